#include "output.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <atomic>
#include <mutex>
#include <random>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include "errors.hpp"
#include "quantity.hpp"
#include "scene_fields.hpp"

// After the project headers: <csignal> defines macros (si_value) that clash with their
// parameter names.
#include <csignal>

namespace covopt::cli {
namespace {

using Json = nlohmann::ordered_json;

/// A number, or null when it is not finite (JSON has no NaN or Infinity).
Json Number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

std::string_view YesNo(bool b) { return b ? "yes" : "no"; }
std::string_view SafeWord(bool safe) { return safe ? "SAFE" : "UNSAFE"; }

std::string Mass(double kg) { return FormatQuantity(kg, QuantityKind::kMass); }
std::string Length(double m) { return FormatQuantity(m, QuantityKind::kLength); }
std::string Modulus(double pa) { return FormatQuantity(pa, QuantityKind::kModulus); }

/// One "label   value unit" row; only the ASCII label is padded.
void Row(std::ostream& out, std::string_view label, std::string_view value) {
  fmt::print(out, "  {:<24} {}\n", label, value);
}

/// The verdicts: laceration, contusion, fracture (with its source), crush, overall.
void PrintVerdicts(std::ostream& out, const SimulationReport& report) {
  const InjuryVerdict& lac = report.assessment.laceration;
  const InjuryVerdict& con = report.assessment.contusion;
  fmt::print(out, "\nVerdicts\n");
  fmt::print(out, "  {:<12} {:<7} tensile stress {:.6g} MPa, limit {:g} MPa, ratio {:.4g}\n",
             "laceration", SafeWord(lac.safe), lac.value / 1e6, lac.limit / 1e6, lac.ratio);
  fmt::print(out, "  {:<12} {:<7} energy density {:.6g} J/cm², limit {:g} J/cm², ratio {:.4g}\n",
             "contusion", SafeWord(con.safe), con.value / 1e4, con.limit / 1e4, con.ratio);
  const InjuryVerdict& fracture = report.assessment.fracture;
  const FractureForce& bone = FractureForceOf(report.assessment.area);
  const bool published = fracture.limit == bone.force_N;
  fmt::print(out, "  {:<12} {:<7} peak force {:.6g} N, limit {:g} N ({}: {}{}), ratio {:.4g}\n  {:<20} source: {}\n",
             "fracture", SafeWord(fracture.safe), fracture.value, fracture.limit, bone.name,
             published ? "the lowest published fracture force" : "the given fracture force",
             report.safety_factor != 1.0
                 ? fmt::format("; derated {:.4g} N at safety factor {:g}", fracture.limit / report.safety_factor,
                               report.safety_factor)
                 : std::string(),
             fracture.ratio, "", published ? bone.source : std::string_view("given"));
  if (report.crush) {
    fmt::print(out, "  {:<12} {:<7} compressive stress {:.6g} MPa, strength {:.6g} MPa, ratio {:.4g}\n", "crush",
               SafeWord(report.crush->safe), report.crush->value / 1e6, report.crush->limit / 1e6, report.crush->ratio);
  }
  fmt::print(out, "  {:<12} {}\n", "overall", SafeWord(report.safe()));
}

}  // namespace

void PrintTable(std::ostream& out, const SimulationReport& report) {
  const Scene& s = report.scene;
  const ImpactResult& r = report.result;
  const ImpactPeaks& p = r.peaks;

  // Scene: two lines.
  const std::string covering =
      s.covering.thickness_m > 0.0
          ? fmt::format("covering {}{}, E {}, ν {:g}{}", Length(s.covering.thickness_m),
                        report.covering_material
                            ? fmt::format(" '{}'", *report.covering_material)
                            : std::string(),
                        Modulus(s.covering.youngs_modulus_Pa), s.covering.poisson_ratio,
                        report.covering_poisson_assumed ? " (assumed)" : "")
          : std::string("no covering");
  // The speed belongs to the body that moves: a fixed robot has the head dropped onto it.
  const bool robot_fixed = std::isinf(s.robot.mass_kg);
  const bool head_fixed = std::isinf(s.head.mass_kg);
  const std::string robot =
      robot_fixed ? std::string("fixed robot")
                  : fmt::format("robot {} at {:g} m/s", Mass(s.robot.mass_kg), s.robot.speed_m_per_s);
  const std::string head =
      head_fixed    ? std::string(robot_fixed ? "head fixed" : "head fixed (hit by the robot)")
      : robot_fixed ? fmt::format("head {} dropped onto the robot at {:g} m/s", Mass(s.head.mass_kg),
                                  s.robot.speed_m_per_s)
                    : fmt::format("head {}", Mass(s.head.mass_kg));
  fmt::print(out, "Scene   {}, R {}, E {}, ν {:g}; {}\n", robot, Length(s.robot.radius_m),
             Modulus(s.robot.youngs_modulus_Pa), s.robot.poisson_ratio, covering);
  fmt::print(out,
             "        {}, R {}; scalp {}, E {}, ν {:g}; skull E {}, ν {:g}; {} thresholds\n",
             head, Length(s.head.radius_m), Length(s.scalp.thickness_m),
             Modulus(s.scalp.youngs_modulus_Pa), s.scalp.poisson_ratio,
             Modulus(s.skull.youngs_modulus_Pa), s.skull.poisson_ratio,
             ThresholdsName(s.model.thresholds));
  // The inputs beyond the paper's conservative two-mass scene (docs/model.md §10), when set.
  std::vector<std::string> extended;
  if (s.is_damped()) {
    extended.push_back(fmt::format(
        "contact damping {}", FormatQuantity(s.model.damping_s_per_m, QuantityKind::kDampingCoefficient)));
  }
  if (s.robot_brakes()) {
    extended.push_back(fmt::format(
        "the robot brakes at {} from {} after first contact",
        FormatQuantity(s.robot.braking_m_per_s2, QuantityKind::kAcceleration),
        FormatQuantity(s.robot.reaction_delay_s, QuantityKind::kTime)));
  } else if (s.robot.reaction_delay_s > 0.0) {
    extended.push_back(fmt::format("reaction delay {} (no braking)",
                                   FormatQuantity(s.robot.reaction_delay_s, QuantityKind::kTime)));
  }
  if (s.head.has_neck()) {
    extended.push_back(fmt::format(
        "neck to a torso {}: stiffness {}, damping {}",
        std::isinf(s.head.torso_mass_kg) ? std::string("held fixed") : Mass(s.head.torso_mass_kg),
        FormatQuantity(s.head.neck_stiffness_N_per_m, QuantityKind::kStiffness),
        FormatQuantity(s.head.neck_damping_N_s_per_m, QuantityKind::kViscousDamping)));
  }
  if (!extended.empty()) fmt::print(out, "        {}\n", fmt::join(extended, "; "));

  fmt::print(out, "\nPeaks\n");
  Row(out, "max penetration", fmt::format("{:.6g} mm", p.max_penetration_m * 1e3));
  Row(out, "peak force", fmt::format("{:.6g} N", p.peak_force_N));
  if (r.contact_duration_s) {
    Row(out, "contact duration", fmt::format("{:.6g} ms", *r.contact_duration_s * 1e3));
  }
  if (r.time_of_max_compression_s) {
    Row(out, "time of max compression",
        fmt::format("{:.6g} ms", *r.time_of_max_compression_s * 1e3));
  }
  Row(out, "max compressive stress", fmt::format("{:.6g} MPa", p.max_compressive_stress_Pa / 1e6));
  Row(out, "max tensile stress", fmt::format("{:.6g} MPa", p.max_tensile_stress_Pa / 1e6));
  Row(out, "max energy density",
      fmt::format("{:.6g} J/cm²", p.max_energy_density_J_per_m2 / 1e4));
  if (r.rebound_speed_m_per_s) {
    // The coefficient of restitution is 1 in the conservative model; it is shown where
    // damping, braking or a neck make it differ.
    const bool restitution = r.coefficient_of_restitution && !s.is_conservative_two_mass();
    Row(out, "rebound speed",
        fmt::format("{:.6g} m/s{}", *r.rebound_speed_m_per_s,
                    restitution ? fmt::format(" (coefficient of restitution {:.6g})",
                                              *r.coefficient_of_restitution)
                                : std::string()));
  }
  Row(out, "phase at max",
      fmt::format("{} ({})", PhaseNumber(p.phase_at_max), ToString(p.phase_at_max)));
  Row(out, "scalp fully compressed", YesNo(p.scalp_fully_compressed));
  Row(out, "fully compressed", YesNo(p.fully_compressed));

  PrintVerdicts(out, report);

  fmt::print(out, "\nMethod  {}", ToString(r.method));
  if (report.time_options) {
    const TimeIntegrationOptions& o = *report.time_options;
    fmt::print(out, ", rtol {:g}, atol {:g}", o.relative_tolerance,
               o.absolute_tolerance > 0.0 ? o.absolute_tolerance : o.relative_tolerance);
    const SolverStatistics& st = r.statistics;
    fmt::print(out, "\nSolver  {}: {} steps, {} rhs evaluations, {} root evaluations, "
                    "{} Jacobian evaluations,\n        {} nonlinear iterations, "
                    "{} error-test failures, {} convergence failures, {} restarts",
               ToString(r.status), st.steps, st.rhs_evaluations, st.root_evaluations,
               st.jacobian_evaluations, st.nonlinear_iterations, st.error_test_failures,
               st.convergence_failures, st.restarts);
    if (r.energy_residual) fmt::print(out, ";\n        energy residual {:.2g} (self-check)", *r.energy_residual);
    if (!r.history.empty()) fmt::print(out, "; {} history samples", r.history.size());
  } else {
    fmt::print(out, " (energy balance and quadrature, no time integration)");
  }
  fmt::print(out, "\n");

  if (!report.scope.empty()) {
    fmt::print(out, "\nScope\n");
    for (const std::string& line : report.scope) fmt::print(out, "  {}\n", line);
  }
  if (r.warnings.empty() && report.input_warnings.empty()) {
    fmt::print(out, "\nWarnings: none\n");
  } else {
    fmt::print(out, "\nWarnings\n");
    for (const ValidityWarning& warning : r.warnings) fmt::print(out, "  - {}\n", warning.message);
    for (const std::string& warning : report.input_warnings) fmt::print(out, "  - {}\n", warning);
  }
}

Json SceneToJson(const Scene& s) { return Json::parse(report::SceneJson(s)); }

Json JsonNumber(double value) { return Number(value); }

Json StatisticsToJson(const SolverStatistics& st) {
  return Json::parse(report::SolverStatisticsJson(st));
}

Json ToJson(const SimulationReport& report) {
  return Json::parse(report::SimulationJson(report));
}

std::string HistoryCsv(const ImpactModel& model, const std::vector<HistorySample>& history) {
  const auto field = [](double v) { return std::isfinite(v) ? fmt::format("{}", v) : std::string(); };
  const bool extended = !model.scene().is_conservative_two_mass();
  std::string csv(kHistoryCsvHeader);
  if (extended) csv += kHistoryCsvExtendedColumns;
  csv += '\n';
  for (const HistorySample& h : history) {
    csv += fmt::format("{},{},{},{},{},{},{}", field(h.time_s), field(h.penetration_m),
                       field(h.penetration_rate_m_per_s), field(h.force_N),
                       field(h.compressive_stress_Pa),
                       field(model.TensileFromCompressive(h.compressive_stress_Pa)),
                       field(h.energy_density_J_per_m2));
    if (extended) {
      csv += fmt::format(",{},{},{},{}", field(h.robot_speed_m_per_s), field(h.head_speed_m_per_s),
                         field(h.neck_force_N), field(h.dissipated_work_J));
    }
    csv += '\n';
  }
  return csv;
}

namespace {

// The signal handlers' registry of live temporaries: fixed storage, so the handler touches
// no heap and calls only unlink, rmdir, sigaction and raise (async-signal-safe).
constexpr int kTemporarySlots = 16;
constexpr std::size_t kTemporaryPathBytes = 4096;
struct TemporarySlot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 live
  char path[kTemporaryPathBytes];
};
// constinit: zero in .bss, not written by a static initialiser (which touched its 16 pages at
// every start-up, docs/performance.md).
constinit TemporarySlot g_temporaries[kTemporarySlots]{};

extern "C" void RemoveTemporariesAndDie(int signal_number) {
  for (TemporarySlot& slot : g_temporaries) {
    if (slot.state.load() == 2) ::unlink(slot.path);
  }
  // Then the registered directories, empty now (gnuplot's scratch directory, report/charts.hpp).
  for (TemporarySlot& slot : g_temporaries) {
    if (slot.state.load() == 2) ::rmdir(slot.path);
  }
  // SA_RESETHAND restored the default action; the signal is blocked in the handler, so it
  // is delivered (and ends the process) as the handler returns.
  ::raise(signal_number);
}

void InstallSignalHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction current {};
      if (::sigaction(signal_number, nullptr, &current) != 0) continue;
      // Keep an ignored signal ignored (nohup, a background job) and someone else's handler.
      if ((current.sa_flags & SA_SIGINFO) != 0 || current.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = RemoveTemporariesAndDie;
      sigemptyset(&action.sa_mask);
      action.sa_flags = SA_RESETHAND;
      ::sigaction(signal_number, &action, nullptr);
    }
  });
}

std::string Reason(int error) { return std::strerror(error); }

/// The directory a path's file lives in ("." for a bare name).
std::string DirectoryOf(const std::string& path) {
  const std::filesystem::path p(path);
  return p.has_parent_path() ? p.parent_path().string() : std::string(".");
}

/// `path` with every symbolic link along the last component followed (relative link
/// targets are read from the link's directory), up to 40 links; the result need not exist.
std::string FollowLinks(const std::string& shown, std::string path) {
  for (int links = 0;; ++links) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return path;
    if (links == 40) {
      throw OutputError(fmt::format("cannot write '{}': {}", shown, Reason(ELOOP)));
    }
    std::string target(kTemporaryPathBytes, '\0');
    const ssize_t n = ::readlink(path.c_str(), target.data(), target.size());
    if (n < 0 || static_cast<std::size_t>(n) >= target.size()) {
      throw OutputError(fmt::format("cannot write '{}': cannot read the symbolic link: {}", shown,
                                    Reason(n < 0 ? errno : ENAMETOOLONG)));
    }
    target.resize(static_cast<std::size_t>(n));
    path = target.front() == '/' ? target
                                 : (std::filesystem::path(DirectoryOf(path)) / target).string();
  }
}

}  // namespace

std::optional<FileIdentity> IdentifyFile(const std::string& path) {
  std::string followed;
  try {
    followed = FollowLinks(path, path);
  } catch (const OutputError&) {
    return std::nullopt;  // a loop of links: the writer or reader reports it
  }
  struct stat st {};
  if (::stat(followed.c_str(), &st) == 0) {
    return FileIdentity{st.st_dev, st.st_ino, {}, S_ISCHR(st.st_mode)};
  }
  if (errno != ENOENT) return std::nullopt;
  const std::string name = std::filesystem::path(followed).filename().string();
  if (name.empty() || name == "." || name == ".." || ::stat(DirectoryOf(followed).c_str(), &st) != 0) {
    return std::nullopt;
  }
  return FileIdentity{st.st_dev, st.st_ino, name, false};
}

int RegisterTemporaryFile(const std::string& path) noexcept {
  if (path.size() >= kTemporaryPathBytes) return -1;
  InstallSignalHandlers();
  for (int i = 0; i < kTemporarySlots; ++i) {
    int expected = 0;
    if (g_temporaries[i].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(g_temporaries[i].path, path.c_str(), path.size() + 1);
      g_temporaries[i].state.store(2);
      return i;
    }
  }
  return -1;
}

void UnregisterTemporaryFile(int slot) noexcept {
  if (slot >= 0 && slot < kTemporarySlots) g_temporaries[slot].state.store(0);
}

OutputFile::OutputFile(const std::filesystem::path& path) : shown_(path.string()) {
  if (shown_.empty() || !path.has_filename()) {
    throw OutputError(fmt::format("cannot write '{}': not a file name", shown_));
  }
  // A device or FIFO, reached directly or through links (also /dev/fd/N's "pipe:[...]"
  // links, which only stat can follow), is written straight to.
  struct stat st {};
  if (::stat(shown_.c_str(), &st) == 0 && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))) {
    fd_ = ::open(shown_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    if (fd_ < 0) throw OutputError(fmt::format("cannot write '{}': {}", shown_, Reason(errno)));
    return;
  }
  target_ = FollowLinks(shown_, shown_);
  const std::string directory = DirectoryOf(target_);
  const std::string named = target_ == shown_ ? std::string()
                                              : fmt::format(" (the link's target '{}')", target_);
  if (::stat(target_.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) {
      throw OutputError(fmt::format("cannot write '{}'{}: it is a directory", shown_, named));
    }
    if (!S_ISREG(st.st_mode)) {
      throw OutputError(fmt::format(
          "cannot write '{}'{}: not a regular file, character device or FIFO", shown_, named));
    }
    if (::access(target_.c_str(), W_OK) != 0) {
      throw OutputError(fmt::format("cannot write '{}'{}: {}; it is left as it was", shown_,
                                    named, Reason(errno)));
    }
    if ((st.st_mode & 0222) == 0) {
      throw OutputError(fmt::format(
          "cannot write '{}'{}: the file is read-only (mode {:03o}); it is left as it was",
          shown_, named, st.st_mode & 0777));
    }
    mode_ = st.st_mode & 07777;
  } else {
    const int error = errno;
    struct stat dir {};
    if (error == ENOENT && ::stat(directory.c_str(), &dir) != 0) {
      throw OutputError(fmt::format("cannot write '{}': the directory '{}' does not exist",
                                    shown_, directory));
    }
    if (error == ENOENT && !S_ISDIR(dir.st_mode)) {
      throw OutputError(
          fmt::format("cannot write '{}': '{}' is not a directory", shown_, directory));
    }
    if (error != ENOENT) throw OutputError(fmt::format("cannot write '{}': {}", shown_, Reason(error)));
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode_ = 0666 & ~mask;
  }

  // The temporary: a fresh name, registered before it exists (so a signal between open and
  // registration cannot leave it), made with the final permissions.
  std::random_device random;
  const std::string stem =
      (std::filesystem::path(directory) /
       fmt::format(".{}.tmp-", std::filesystem::path(target_).filename().string()))
          .string();
  constexpr std::string_view kLetters =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
    std::string name = stem;
    for (int i = 0; i < 6; ++i) name += kLetters[random() % kLetters.size()];
    slot_ = RegisterTemporaryFile(name);
    fd_ = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode_);
    if (fd_ >= 0) {
      temp_ = name;
      break;
    }
    const int error = errno;
    UnregisterTemporaryFile(slot_);
    slot_ = -1;
    if (error != EEXIST) {
      throw OutputError(fmt::format("cannot write '{}': cannot create a file in '{}': {}", shown_,
                                    directory, Reason(error)));
    }
  }
  if (fd_ < 0) {
    throw OutputError(fmt::format("cannot write '{}': no free temporary name in '{}'", shown_, directory));
  }
  // open() applied the umask; an existing file's bits are kept exactly.
  if (::fchmod(fd_, mode_) != 0) Fail("chmod", errno);
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!temp_.empty() && !committed_) ::unlink(temp_.c_str());
  UnregisterTemporaryFile(slot_);
}

void OutputFile::Fail(const char* step, int error) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temp_.empty()) ::unlink(temp_.c_str());
  UnregisterTemporaryFile(slot_);
  slot_ = -1;
  temp_.clear();
  throw OutputError(fmt::format("cannot write '{}': {}: {}", shown_, step, Reason(error)));
}

void OutputFile::Write(std::string_view text) {
  if (fd_ < 0) throw OutputError(fmt::format("cannot write '{}': the file is closed", shown_));
  const char* data = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      Fail("write", errno);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  written_ += text.size();
#ifdef __linux__
  // On Linux the write-back of every 16 MiB written is started at once, so the disk works
  // while a sweep computes and Commit's fsync waits only for the tail. Only a hint.
  constexpr std::size_t kWriteBackBytes = std::size_t{16} << 20;
  if (atomic() && written_ - written_back_ >= kWriteBackBytes) {
    ::sync_file_range(fd_, static_cast<off_t>(written_back_),
                      static_cast<off_t>(written_ - written_back_), SYNC_FILE_RANGE_WRITE);
    written_back_ = written_;
  }
#endif
}

void OutputFile::Commit() {
  if (fd_ < 0) throw OutputError(fmt::format("cannot write '{}': the file is closed", shown_));
  if (atomic() && ::fsync(fd_) != 0) Fail("fsync", errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) Fail("close", errno);
  if (atomic()) {
    if (::rename(temp_.c_str(), target_.c_str()) != 0) Fail("rename", errno);
    UnregisterTemporaryFile(slot_);
    slot_ = -1;
  }
  committed_ = true;
}

void WriteFileAtomically(const std::filesystem::path& path, std::string_view content) {
  OutputFile file(path);
  file.Write(content);
  file.Commit();
}

}  // namespace covopt::cli
