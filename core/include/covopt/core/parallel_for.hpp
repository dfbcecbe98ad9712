#pragma once
/// @file parallel_for.hpp
/// The library's one thread pool: a loop over indices spread over worker threads, the calling
/// thread among them. Sweeps, exact-path grids, the catalog snaps and the Monte Carlo counts
/// all run on it.
///
///     std::vector<double> out(n);
///     covopt::ParallelFor(n, 0, [&](std::size_t i, unsigned) { out[i] = Solve(i); });
///
/// Indices are handed out in increasing order to whichever thread is free, so which thread
/// runs an index varies from run to run: a body that writes only its index's own slot (or its
/// worker's, summed afterwards in worker order for integers) gives results that do not depend
/// on the number of threads.

#include <cstddef>
#include <functional>

namespace covopt {

/// The threads ParallelFor(count, requested, ...) runs on, counting the calling thread:
/// `requested`, or std::thread::hardware_concurrency() (1 if unknown) when it is 0; never
/// more than `count`, never fewer than 1.
unsigned ParallelThreads(std::size_t count, unsigned requested) noexcept;

/// Calls body(index, worker) once for every index in [0, count), on ParallelThreads(count,
/// threads) threads; `worker` is 0 on the calling thread and 1, 2, ... on the others, so a
/// body may keep per-worker state in a vector of that many slots. With one thread every index
/// runs on the calling thread, in order. The first exception a body throws stops the handing
/// out of indices (the indices already started finish); it is rethrown on the calling thread
/// once every thread has finished.
void ParallelFor(std::size_t count, unsigned threads,
                 const std::function<void(std::size_t index, unsigned worker)>& body);

/// ParallelFor whose results are consumed in index order while later ones are computed:
/// compute(index, slot) runs on any of ParallelThreads(count, threads) threads, and
/// deliver(index, slot) on the calling thread for index 0, 1, 2, ... in turn, each after its
/// compute has finished. slot = index % slots: at most `slots` (>= 1) indices are computed and
/// not yet delivered, so a caller holding one buffer per slot uses bounded memory however
/// large `count` is, and the buffer of a slot is the computing thread's alone until it is
/// delivered. The calling thread computes too while the next index to deliver is not ready.
/// An exception thrown by compute or deliver stops the work; it is rethrown on the calling
/// thread once every thread has finished.
void ParallelForOrdered(std::size_t count, unsigned threads, std::size_t slots,
                        const std::function<void(std::size_t index, std::size_t slot)>& compute,
                        const std::function<void(std::size_t index, std::size_t slot)>& deliver);

}  // namespace covopt
