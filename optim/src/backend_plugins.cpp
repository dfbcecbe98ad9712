// SolveWithNlopt and SolveWithIpopt: the solvers live in plugin modules (libcovopt_nlopt.so,
// libcovopt_ipopt.so), opened the first time a solve needs one. Ipopt brings MUMPS, scotch,
// BLAS/LAPACK and gfortran (about 15 shared objects): loaded at start-up they were most of
// the start-up time of every covopt program, optimising or not (docs/performance.md).
//
// Where a plugin is looked for: in the run path of the executable or shared module that holds
// this code (the covopt executable, the Python module, a user's program), with $ORIGIN expanded,
// then LD_LIBRARY_PATH and the system directories: the dynamic loader's own search list for
// that object (dlinfo RTLD_DI_SERINFO). dlopen() with a bare name would search the same list,
// but only of its direct caller, which under AddressSanitizer is the sanitizer's interceptor.
// The build sets that run path: the build tree's lib/covopt for every binary built there;
// installed, $ORIGIN-relative for the covopt executable and the Python module, and an absolute
// -rpath that covopt::optim adds to a package consumer's link.
#include <dlfcn.h>
#include <link.h>

#include <chrono>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend_plugins.hpp"
#include "evaluation_guard.hpp"

namespace covopt::optim {
namespace internal {
namespace {

/// The directories the dynamic loader searches for the object that holds this function.
std::vector<std::string> SearchDirectories(std::string& object_name) {
  std::vector<std::string> directories;
  Dl_info info{};
  link_map* holder = nullptr;
  if (dladdr1(reinterpret_cast<void*>(&SearchDirectories), &info, reinterpret_cast<void**>(&holder),
              RTLD_DL_LINKMAP) == 0 ||
      holder == nullptr) {
    return directories;
  }
  // The main program's link map has an empty name; dlopen(nullptr) is its handle.
  const bool in_main_program = holder->l_name == nullptr || holder->l_name[0] == '\0';
  object_name = in_main_program ? "the program" : holder->l_name;
  void* handle = dlopen(in_main_program ? nullptr : holder->l_name, RTLD_LAZY | RTLD_NOLOAD);
  if (handle == nullptr) return directories;
  Dl_serinfo size{};
  if (dlinfo(handle, RTLD_DI_SERINFOSIZE, &size) == 0 && size.dls_size > 0) {
    std::vector<std::max_align_t> storage(size.dls_size / sizeof(std::max_align_t) + 1);
    auto* list = reinterpret_cast<Dl_serinfo*>(storage.data());
    list->dls_size = size.dls_size;
    list->dls_cnt = size.dls_cnt;
    if (dlinfo(handle, RTLD_DI_SERINFOSIZE, list) == 0 && dlinfo(handle, RTLD_DI_SERINFO, list) == 0) {
      for (unsigned i = 0; i < list->dls_cnt; ++i) directories.emplace_back(list->dls_serpath[i].dls_name);
    }
  }
  dlclose(handle);
  return directories;
}

/// Opens libcovopt_<name>.so and returns its entry point `symbol`; throws std::runtime_error
/// naming the directories searched when it is not there.
void* LoadPlugin(const std::string& name, const char* symbol) {
  const std::string file = "libcovopt_" + name + ".so";
  std::string object_name = "this program";
  const std::vector<std::string> directories = SearchDirectories(object_name);
  std::string searched;
  for (const std::string& directory : directories) {
    const std::filesystem::path path = std::filesystem::path(directory.empty() ? "." : directory) / file;
    searched += (searched.empty() ? "" : ", ") + path.parent_path().string();
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) continue;
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      throw std::runtime_error("cannot load the " + name + " solver plugin " + path.string() + ": " +
                               (why != nullptr ? why : "unknown error"));
    }
    void* entry = dlsym(handle, symbol);
    if (entry == nullptr) {
      throw std::runtime_error("the " + name + " solver plugin " + path.string() + " has no entry " +
                               symbol + " (a plugin from another covopt version?)");
    }
    return entry;
  }
  throw std::runtime_error("the " + name + " solver plugin " + file + " was not found on the run path of " +
                           object_name + " (searched: " + searched + "); it is built with covopt and installed in " +
                           COVOPT_PLUGIN_INSTALL_DIR + " of covopt's prefix, or add its directory to LD_LIBRARY_PATH");
}

/// The entry point of a plugin, loaded once per process (thread-safe); a failed load is retried
/// (and reported) at the next call.
template <typename Entry>
Entry* PluginEntry(const std::string& name, const char* symbol) {
  static std::mutex mutex;
  static Entry* entry = nullptr;
  const std::lock_guard<std::mutex> lock(mutex);
  if (entry == nullptr) entry = reinterpret_cast<Entry*>(LoadPlugin(name, symbol));
  return entry;
}

/// Runs a plugin's solve and finishes its result as every backend does.
template <typename Entry, typename Options>
SolveResult Solve(const std::string& name, const char* symbol, std::string backend, const Problem& problem,
                  std::span<const double> x0, const Options& options) {
  const auto started = std::chrono::steady_clock::now();
  Entry* solve = PluginEntry<Entry>(name, symbol);
  SolveResult result;
  result.report.backend = std::move(backend);
  if (!solve(problem, x0, options, result)) return result;
  FinishResult(problem, result);
  result.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace
}  // namespace internal

std::string_view ToString(NloptAlgorithm algorithm) noexcept {
  switch (algorithm) {
    case NloptAlgorithm::kDirectL: return "GN_DIRECT_L";
    case NloptAlgorithm::kIsres: return "GN_ISRES";
    case NloptAlgorithm::kMlsl: return "G_MLSL_LDS+LD_LBFGS";
    case NloptAlgorithm::kCobyla: return "LN_COBYLA";
    case NloptAlgorithm::kSlsqp: return "LD_SLSQP";
    case NloptAlgorithm::kLbfgs: return "LD_LBFGS";
  }
  return "unknown";
}

SolveResult SolveWithNlopt(const Problem& problem, std::span<const double> x0, const NloptOptions& options) {
  return internal::Solve<internal::NloptEntry>("nlopt", internal::kNloptEntryName,
                                               std::string("nlopt:").append(ToString(options.algorithm)), problem, x0,
                                               options);
}

SolveResult SolveWithIpopt(const Problem& problem, std::span<const double> x0, const IpoptOptions& options) {
  return internal::Solve<internal::IpoptEntry>("ipopt", internal::kIpoptEntryName, "ipopt", problem, x0,
                                               options);
}

}  // namespace covopt::optim
