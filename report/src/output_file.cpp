#include "covopt/report/output_file.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <random>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

// After the project headers: <csignal> defines macros that clash with theirs.
#include <csignal>

namespace covopt::report {

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
  // Then the registered directories, empty now (gnuplot's scratch directory, covopt/chart/charts.hpp).
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

}  // namespace covopt::report
