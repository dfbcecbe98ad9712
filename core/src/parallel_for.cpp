// The library's one thread pool (covopt/core/parallel_for.hpp).
//
// ParallelFor hands out indices through one atomic counter. ParallelForOrdered keeps a ring
// of `slots` slots: threads claim the next index in order, but only when its slot is free
// (index < delivered + slots); the calling thread delivers strictly in order and computes an
// index itself while the one it must deliver next is not ready.
#include "covopt/core/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

namespace covopt {
namespace {

/// The ring of slots shared by the threads of one ParallelForOrdered.
class Ring {
 public:
  Ring(std::size_t count, std::size_t slots) : count_(count), slots_(slots), ready_(slots, kNone) {}

  /// Claims the next index if its slot is free; false when there is none to claim now.
  /// Call with the lock held.
  bool TryClaim(std::size_t& index) {
    if (stop_ || next_ >= count_ || next_ >= delivered_ + slots_) return false;
    index = next_++;
    return true;
  }
  /// No index left to claim, ever.
  bool Exhausted() const { return stop_ || next_ >= count_; }

  std::size_t Slot(std::size_t index) const { return index % slots_; }

  std::mutex mutex;
  std::condition_variable changed;  // an index became ready, a slot free, or stop was set

  void MarkReady(std::size_t index) { ready_[index % slots_] = index; }
  bool Ready(std::size_t index) const { return ready_[index % slots_] == index; }
  void MarkDelivered(std::size_t index) {
    ready_[index % slots_] = kNone;
    delivered_ = index + 1;
  }
  void Stop() { stop_ = true; }
  bool stopped() const { return stop_; }

 private:
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  const std::size_t count_;
  const std::size_t slots_;
  std::size_t next_ = 0;       // the next index to claim
  std::size_t delivered_ = 0;  // indices delivered
  bool stop_ = false;
  std::vector<std::size_t> ready_;  // per slot: the index it holds, computed; or kNone
};

}  // namespace

unsigned ParallelThreads(std::size_t count, unsigned requested) noexcept {
  unsigned threads = requested;
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  return static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(count, 1)));
}

void ParallelFor(std::size_t count, unsigned threads,
                 const std::function<void(std::size_t index, unsigned worker)>& body) {
  const unsigned workers = ParallelThreads(count, threads);
  if (workers == 1) {
    for (std::size_t i = 0; i < count; ++i) body(i, 0);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex error_mutex;
  std::exception_ptr error;
  const auto work = [&](unsigned worker) {
    try {
      while (!stop.load(std::memory_order_relaxed)) {
        const std::size_t i = next.fetch_add(1);
        if (i >= count) return;
        body(i, worker);
      }
    } catch (...) {
      const std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception();
      stop.store(true);
    }
  };
  {
    std::vector<std::jthread> pool;  // joined on leaving the block, however it is left
    pool.reserve(workers - 1);
    try {
      for (unsigned w = 1; w < workers; ++w) pool.emplace_back(work, w);
    } catch (...) {
      stop.store(true);  // a thread could not start: the started ones finish their index
      throw;
    }
    work(0);
  }
  if (error) std::rethrow_exception(error);
}

void ParallelForOrdered(std::size_t count, unsigned threads, std::size_t slots,
                        const std::function<void(std::size_t index, std::size_t slot)>& compute,
                        const std::function<void(std::size_t index, std::size_t slot)>& deliver) {
  const unsigned workers = ParallelThreads(count, threads);
  Ring ring(count, std::max<std::size_t>(slots, 1));
  std::exception_ptr worker_error;

  // A worker thread: claims and computes indices until none is left or the work stops.
  const auto work = [&] {
    std::unique_lock lock(ring.mutex);
    while (true) {
      std::size_t index = 0;
      bool claimed = false;
      ring.changed.wait(lock, [&] {
        claimed = ring.TryClaim(index);
        return claimed || ring.Exhausted();
      });
      if (!claimed) return;
      lock.unlock();
      try {
        compute(index, ring.Slot(index));
      } catch (...) {
        lock.lock();
        if (!worker_error) worker_error = std::current_exception();
        ring.Stop();
        ring.changed.notify_all();
        return;
      }
      lock.lock();
      ring.MarkReady(index);
      ring.changed.notify_all();
    }
  };

  // Stops and joins the workers however the calling thread leaves (an exception from
  // deliver, or from compute on the calling thread, included).
  struct Workers {
    Ring& ring;
    std::vector<std::thread> threads;
    ~Workers() {
      {
        const std::lock_guard lock(ring.mutex);
        ring.Stop();
      }
      ring.changed.notify_all();
      for (std::thread& thread : threads) thread.join();
    }
  } pool{ring, {}};
  pool.threads.reserve(workers - 1);
  for (unsigned t = 1; t < workers; ++t) pool.threads.emplace_back(work);

  for (std::size_t next = 0; next < count; ++next) {
    {
      std::unique_lock lock(ring.mutex);
      while (!ring.Ready(next) && !ring.stopped()) {
        std::size_t index = 0;
        if (ring.TryClaim(index)) {
          lock.unlock();
          compute(index, ring.Slot(index));
          lock.lock();
          ring.MarkReady(index);
          ring.changed.notify_all();
          continue;
        }
        ring.changed.wait(lock);
      }
      if (worker_error) std::rethrow_exception(worker_error);
    }
    // The slot is complete, and no thread writes it again before it is marked delivered.
    deliver(next, ring.Slot(next));
    {
      const std::lock_guard lock(ring.mutex);
      ring.MarkDelivered(next);
    }
    ring.changed.notify_all();
  }
}

}  // namespace covopt
