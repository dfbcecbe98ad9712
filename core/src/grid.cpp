// Many exact-path impacts on several threads (covopt/core/grid.hpp). The points are handed
// out in fixed chunks by ParallelFor; each point is written only by the thread
// that computed it, so the order of work never changes a result.
#include "covopt/core/grid.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/parallel_for.hpp"

namespace covopt {
namespace {

constexpr std::size_t kChunk = 64;          // points per unit of work
constexpr unsigned kMaxThreads = 4096;

void SolvePoint(const Scene& scene, const ExactOptions& exact, GridPointResult& out) {
  try {
    const ImpactModel model = ImpactModel::FromScene(scene);
    out.result = SolveExact(model, exact);
    out.assessment = Assess(out.result->peaks);
  } catch (const std::invalid_argument& e) {
    out.result.reset();
    out.error = e.what();
  }
}

}  // namespace

std::vector<GridPointResult> SolveExactGrid(std::span<const Scene> scenes,
                                            const GridOptions& options) {
  if (options.threads > kMaxThreads) {
    throw std::invalid_argument("threads must be <= " + std::to_string(kMaxThreads) +
                                " (got " + std::to_string(options.threads) + ")");
  }
  const std::size_t total = scenes.size();
  std::vector<GridPointResult> results(total);
  const std::size_t chunks = (total + kChunk - 1) / kChunk;

  std::atomic<std::size_t> done{0};
  ParallelFor(chunks, options.threads, [&](std::size_t chunk, unsigned worker) {
    const std::size_t begin = chunk * kChunk;
    const std::size_t end = std::min(total, begin + kChunk);
    for (std::size_t i = begin; i < end; ++i) SolvePoint(scenes[i], options.exact, results[i]);
    const std::size_t now = done.fetch_add(end - begin) + (end - begin);
    if (worker == 0 && options.progress && now < total) options.progress(now, total);
  });
  if (options.progress) options.progress(total, total);
  return results;
}

}  // namespace covopt
