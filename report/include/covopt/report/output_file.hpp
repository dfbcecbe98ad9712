#pragma once
/// @file output_file.hpp
/// The one file writer of covopt's outputs (the CLI's --history, --csv, --plot, --report, ...):
/// atomic replacement, devices and FIFOs written straight to, symbolic links followed, and no
/// temporary left behind by an interrupted write; and OutputError, what an output file or an
/// external tool (gnuplot, a PDF browser) that failed throws.

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <sys/types.h>

namespace covopt::report {

/// An output file or an external tool failed. The message names the file or the tool.
/// `details`: what the tool itself printed (a PDF browser's last lines), which a front end shows
/// under the one-line message, each line prefixed with `tool` (the CLI: "  <tool>: ").
class OutputError : public std::runtime_error {
 public:
  explicit OutputError(const std::string& message, std::string tool = {}, std::vector<std::string> details = {})
      : std::runtime_error(message), tool_(std::move(tool)), details_(std::move(details)) {}
  const std::string& tool() const noexcept { return tool_; }
  const std::vector<std::string>& details() const noexcept { return details_; }

 private:
  std::string tool_;
  std::vector<std::string> details_;
};

/// An output file (--history, --csv, a plot, sweep's streamed CSV, ...), written whole or
/// piece by piece. Every file the CLI writes goes through it (cli/output.hpp). What is at the path decides
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

}  // namespace covopt::report
