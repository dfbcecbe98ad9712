#pragma once
/// @file output.hpp
/// What `covopt simulate` prints and writes: the readable table, the JSON object, the
/// history CSV, and an atomic file writer. Physics comes from covopt::core only; this file
/// formats it.

#include <filesystem>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <sys/types.h>

#include <nlohmann/json.hpp>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/time_integration.hpp"
#include "covopt/report/csv.hpp"
#include "covopt/report/scene_headline.hpp"
#include "covopt/report/simulation_json.hpp"

namespace covopt::cli {

/// One finished computation with everything needed to report it (covopt::report's, whose
/// SimulationJson is the --json object).
using report::SimulationReport;

/// The scene in one short line, and its inputs beyond that line (report/scene_headline.hpp).
using report::SceneDetailsBeyondHeadline;
using report::SceneHeadline;

/// The readable report: scene, peaks, verdicts, method and solver, warnings.
void PrintTable(std::ostream& out, const SimulationReport& report);

/// Every resolved scene input in SI; fixed masses are "fixed", a flat radius is "flat"
/// (report::SceneJson, parsed).
nlohmann::ordered_json SceneToJson(const Scene& scene);

/// A number for JSON, or null when it is not finite (JSON has no NaN or Infinity).
nlohmann::ordered_json JsonNumber(double value);

/// The integrator's counters as JSON: steps, rhs_evaluations, root_evaluations,
/// jacobian_evaluations, nonlinear_iterations, error_test_failures, convergence_failures,
/// restarts (report::SolverStatisticsJson, parsed).
nlohmann::ordered_json StatisticsToJson(const SolverStatistics& statistics);

/// The report as one JSON object, values in SI, keys carrying the unit
/// (max_penetration_m, peak_force_N, ...); missing or non-finite values are null.
/// scene.covering.material is the catalog material's name, or null. It is
/// report::SimulationJson parsed (the object Python's covopt.simulate returns).
nlohmann::ordered_json ToJson(const SimulationReport& report);

/// The CSV header of a history file.
inline constexpr std::string_view kHistoryCsvHeader =
    "time_s,penetration_m,penetration_rate_m_per_s,force_N,compressive_stress_Pa,"
    "tensile_stress_Pa,energy_density_J_per_m2";
/// The columns a scene with damping, braking or a neck (docs/model.md §10) adds after
/// kHistoryCsvHeader's: the bodies' speeds, the neck force and the work taken out
/// (HistorySample).
inline constexpr std::string_view kHistoryCsvExtendedColumns =
    ",robot_speed_m_per_s,head_speed_m_per_s,neck_force_N,dissipated_work_J";

/// The history as CSV text: kHistoryCsvHeader (and kHistoryCsvExtendedColumns for a scene
/// beyond the conservative two-mass model), then one row per sample (shortest
/// round-trip decimal numbers; a non-finite value is an empty field). tensile_stress_Pa is
/// σ_t = σ_c (1 - 2ν_t)/3 from the sample's compressive stress
/// (model.TensileFromCompressive), the stress the laceration limit judges.
std::string HistoryCsv(const ImpactModel& model, const std::vector<HistorySample>& history);

/// One CSV field, by covopt's one CSV rule (covopt/report/csv.hpp, RFC 4180).
using report::CsvField;

/// An output file (--history, --csv, a plot, sweep's streamed CSV, ...), written whole or
/// piece by piece. Every file the CLI writes goes through it. What is at the path decides
/// how, and nothing at the path is ever replaced by something of another kind:
///
///   - nothing: a new file is made through a temporary in the same directory, renamed into
///     place by Commit, with the permissions a plain open() gives (0666 & ~umask). A missing
///     directory is an error naming the directory.
///   - a regular file: replaced atomically (temporary + rename; a reader sees the old file
///     or the whole new one), keeping its permission bits. A file the user may not write
///     (access(W_OK) fails), or whose mode grants write to nobody (chmod a-w: refused even
///     for root, who bypasses permissions), is refused and left as it was.
///   - a character device (/dev/null, a terminal) or a FIFO (a named pipe, `>(gzip)`):
///     written straight to, opened O_WRONLY without O_CREAT or O_TRUNC (a FIFO waits for
///     its reader, as a shell's `>` does); write errors (ENOSPC from /dev/full) are errors.
///   - a symbolic link: followed (up to 40 links), and its final target written by these
///     rules: a regular target is replaced atomically in the target's own directory, so the
///     link stays a link pointing at the new file; a dangling link makes its target.
///   - a directory, a block device, a socket: refused.
///
/// The temporary (".NAME.tmp-XXXXXX" beside the file) is removed on every error path and
/// when the object is destroyed uncommitted, and is registered with the SIGINT, SIGTERM and
/// SIGHUP handlers installed on first use, which unlink every live temporary and then die
/// of the signal with its default action: an interrupted write leaves no temporary behind
/// and the previous file as it was. Errors are OutputError (exit 1): "cannot write 'PATH':
/// REASON".
class OutputFile {
 public:
  /// Checks the path and opens the temporary or the device. @throws OutputError.
  explicit OutputFile(const std::filesystem::path& path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// @throws OutputError naming the file and the system's reason.
  void Write(std::string_view text);
  /// Finishes the file: flushes a regular file to disk and renames the temporary over the
  /// target; closes a device or FIFO. @throws OutputError.
  void Commit();
  /// Whether the file is replaced through a temporary (false: written straight to a
  /// device or FIFO).
  bool atomic() const noexcept { return !temp_.empty(); }

 private:
  [[noreturn]] void Fail(const char* step, int error);

  std::string shown_;   // the path as the user gave it, for messages
  std::string target_;  // the file renamed over (a followed link's target)
  std::string temp_;    // the temporary, empty when writing straight to a device
  int fd_ = -1;
  int slot_ = -1;       // the temporary's place in the signal handlers' registry
  mode_t mode_ = 0;     // the permissions the final file gets
  bool committed_ = false;
  std::size_t written_ = 0;       // bytes written so far
  std::size_t written_back_ = 0;  // bytes whose write-back has been started
};

/// Which file a path names, to tell whether two paths of one run are one file: the device
/// and inode of the file its symbolic links lead to (followed as OutputFile follows them), or,
/// for a file that does not exist yet, the device and inode of its directory and its name in
/// it. So `a.csv`, `./a.csv`, `dir/../a.csv`, a symbolic link to it and a hard link to it are
/// one file, whether or not it exists yet.
struct FileIdentity {
  dev_t device = 0;
  ino_t inode = 0;
  std::string name;  ///< the file's name in directory (device, inode) when it does not exist yet
  bool character_device = false;  ///< /dev/null, a terminal: any number of writers may share it
  friend bool operator==(const FileIdentity&, const FileIdentity&) = default;
};

/// The FileIdentity of `path`; nullopt when neither the file nor its directory can be found
/// (its reader or writer reports that), or its links loop.
std::optional<FileIdentity> IdentifyFile(const std::string& path);

/// Writes `content` to `path` by OutputFile's rules (atomically for a regular file).
/// @throws OutputError naming the file and the system's reason.
void WriteFileAtomically(const std::filesystem::path& path, std::string_view content);

/// Registers a temporary file, or a temporary directory (removed after the files, so once
/// its registered files are gone), for removal should SIGINT, SIGTERM or SIGHUP end the
/// process (installing the handlers on first use); returns its slot, or -1 when the fixed registry
/// (16 paths of up to 4095 bytes) is full. Unregister it once it is renamed or removed.
int RegisterTemporaryFile(const std::string& path) noexcept;
void UnregisterTemporaryFile(int slot) noexcept;

}  // namespace covopt::cli
