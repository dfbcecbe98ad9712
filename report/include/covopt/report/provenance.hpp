#pragma once
/// @file provenance.hpp
/// What produced a result, for the risk-assessment file: covopt's version and git commit, the
/// command (the CLI's command line, or the Python call), the SHA-256 of every input file, and
/// the date. One definition, shared by every JSON object the CLI prints, every Python result
/// and every report (`"provenance"`, always the last key).

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace covopt::report {

/// One input file a result depends on (URDF, trajectory, scene, catalog, ...).
struct InputFileDigest {
  std::string role;    ///< what it is: "urdf", "trajectory", "scene", "catalog", ...
  std::string path;    ///< as the user gave it
  std::string sha256;  ///< lower-case hex digest of its bytes
  long long size_bytes = 0;  ///< [bytes]
};

/// A file to hash: its role and its path.
struct InputFile {
  std::string role;
  std::filesystem::path path;
};

struct Provenance {
  std::string software = "covopt";
  std::string version;   ///< the project version, "0.1.0"
  std::string commit;    ///< git commit of the build ("<sha>" or "<sha>-dirty"), "unknown" outside a git checkout
  std::string command;   ///< the command line (arguments quoted for a POSIX shell) or the Python call
  std::string date_utc;  ///< ISO 8601, e.g. 2026-11-26T23:40:12Z; SOURCE_DATE_EPOCH when set (reproducible output)
  std::vector<InputFileDigest> inputs;
};

/// covopt's version, e.g. "0.1.0".
std::string CovoptVersion();

/// The git commit covopt was built from, fixed when CMake configured the build: the full hash,
/// with "-dirty" when tracked files differed from it; "unknown" when built outside a checkout.
std::string CovoptCommit();

/// The SHA-256 of a file's bytes, lower-case hex (OpenSSL's EVP interface).
/// @throws std::runtime_error naming the file when it cannot be read.
std::string Sha256OfFile(const std::filesystem::path& path);

/// The SHA-256 of bytes, lower-case hex.
std::string Sha256OfBytes(std::string_view bytes);

/// The command line of argv, each argument quoted for a POSIX shell where it needs it, so that it
/// can be pasted back: `covopt optimize --material 'PORON XRD 15 pcf'`.
std::string CommandLine(std::span<const char* const> argv);

/// The provenance of a run now: version, commit, `command`, the date (UTC, or SOURCE_DATE_EPOCH)
/// and the digest of every input file, in the order given (a file named twice is hashed once).
/// @throws std::runtime_error when an input file cannot be read.
Provenance MakeProvenance(std::string command, std::span<const InputFile> input_files);

/// The provenance as a JSON object: {software, version, commit, command, date_utc,
/// inputs: [{role, path, sha256, size_bytes}]}. `indent` as nlohmann's dump (-1: one line).
std::string ProvenanceJson(const Provenance& provenance, int indent = 2);

/// `json_object` (the text of one JSON object, as the *Json functions print it, at any indent)
/// with "provenance" appended as its last key, at the same indent.
/// @throws std::invalid_argument when json_object is not a JSON object.
std::string WithProvenance(const std::string& json_object, const Provenance& provenance);

}  // namespace covopt::report
