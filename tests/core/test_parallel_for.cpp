// ParallelFor and ParallelForOrdered (covopt/core/parallel_for.hpp): every index once, the
// same results on 1 and N threads, exceptions rethrown on the calling thread.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <stdexcept>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

#include "covopt/core/parallel_for.hpp"

namespace {

double Work(std::size_t i) {
  double x = static_cast<double>(i) + 0.5;
  for (int k = 0; k < 50; ++k) x = x * 1.0000001 + 1.0 / x;
  return x;
}

}  // namespace

TEST_CASE("ParallelThreads resolves 0 to the hardware and never exceeds the count", "[parallel]") {
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  CHECK(covopt::ParallelThreads(1000, 0) == std::min(1000u, hardware));
  CHECK(covopt::ParallelThreads(1000, 7) == 7u);
  CHECK(covopt::ParallelThreads(3, 8) == 3u);
  CHECK(covopt::ParallelThreads(0, 8) == 1u);
}

TEST_CASE("ParallelFor runs every index once and gives the same results on 1 and N threads", "[parallel]") {
  constexpr std::size_t kCount = 10007;
  std::vector<double> serial(kCount);
  covopt::ParallelFor(kCount, 1, [&](std::size_t i, unsigned worker) {
    CHECK(worker == 0u);
    serial[i] = Work(i);
  });
  for (unsigned threads : {2u, 3u, 8u, 0u}) {
    std::vector<std::atomic<int>> runs(kCount);
    std::vector<double> parallel(kCount);
    std::vector<std::size_t> per_worker(covopt::ParallelThreads(kCount, threads), 0);
    covopt::ParallelFor(kCount, threads, [&](std::size_t i, unsigned worker) {
      runs[i].fetch_add(1);
      ++per_worker.at(worker);
      parallel[i] = Work(i);
    });
    std::size_t total = 0;
    for (std::size_t n : per_worker) total += n;
    CHECK(total == kCount);
    bool each_once = true;
    for (const std::atomic<int>& r : runs) each_once = each_once && r.load() == 1;
    CHECK(each_once);
    CHECK(parallel == serial);
  }
  covopt::ParallelFor(0, 4, [](std::size_t, unsigned) { FAIL("no index to run"); });
}

TEST_CASE("ParallelFor rethrows a body's exception on the calling thread and stops handing out indices",
          "[parallel]") {
  for (unsigned threads : {1u, 4u}) {
    std::atomic<std::size_t> started{0};
    CHECK_THROWS_AS(covopt::ParallelFor(100000, threads,
                                        [&](std::size_t i, unsigned) {
                                          started.fetch_add(1);
                                          if (i == 10) throw std::runtime_error("index 10");
                                          // Each other index takes a while, so that running all
                                          // of them (~0.7 s) cannot happen while the throwing
                                          // thread is merely descheduled on a loaded machine.
                                          std::this_thread::sleep_for(std::chrono::microseconds(20));
                                        }),
                    std::runtime_error);
    CHECK(started.load() < 100000u);
  }
}

TEST_CASE("ParallelForOrdered delivers every index once, in order, on the calling thread", "[parallel]") {
  constexpr std::size_t kCount = 2003;
  const std::thread::id caller = std::this_thread::get_id();
  for (unsigned threads : {1u, 2u, 4u}) {
    const std::size_t slots = 2 * covopt::ParallelThreads(kCount, threads);
    std::vector<double> buffer(slots);
    std::vector<double> delivered;
    covopt::ParallelForOrdered(
        kCount, threads, slots, [&](std::size_t i, std::size_t slot) { buffer[slot] = Work(i); },
        [&](std::size_t i, std::size_t slot) {
          CHECK(std::this_thread::get_id() == caller);
          CHECK(i == delivered.size());
          delivered.push_back(buffer[slot]);
        });
    REQUIRE(delivered.size() == kCount);
    bool same = true;
    for (std::size_t i = 0; i < kCount; ++i) same = same && delivered[i] == Work(i);
    CHECK(same);
  }
}

TEST_CASE("ParallelForOrdered rethrows an exception from compute or deliver", "[parallel]") {
  for (unsigned threads : {1u, 3u}) {
    CHECK_THROWS_AS(covopt::ParallelForOrdered(
                        1000, threads, 4,
                        [](std::size_t i, std::size_t) {
                          if (i == 500) throw std::runtime_error("compute");
                        },
                        [](std::size_t, std::size_t) {}),
                    std::runtime_error);
    std::size_t delivered = 0;
    CHECK_THROWS_AS(covopt::ParallelForOrdered(
                        1000, threads, 4, [](std::size_t, std::size_t) {},
                        [&](std::size_t i, std::size_t) {
                          if (i == 7) throw std::invalid_argument("deliver");
                          ++delivered;
                        }),
                    std::invalid_argument);
    CHECK(delivered == 7u);
  }
}
