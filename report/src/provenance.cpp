#include "covopt/report/provenance.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "append_key.hpp"
#include "covopt/core/sha256.hpp"
#include "covopt_build_info.hpp"  // COVOPT_VERSION_TEXT, COVOPT_GIT_COMMIT: written at build time

namespace covopt::report {
namespace {

using Json = nlohmann::ordered_json;

std::string IsoDateUtc() {
  std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  // SOURCE_DATE_EPOCH (reproducible-builds.org): a fixed date for reproducible documents.
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"); epoch != nullptr && *epoch != '\0') {
    char* end = nullptr;
    const long long seconds = std::strtoll(epoch, &end, 10);
    if (*end == '\0' && seconds >= 0) now = static_cast<std::time_t>(seconds);
  }
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  std::array<char, 32> text{};
  std::strftime(text.data(), text.size(), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text.data();
}

/// An argument as a POSIX shell reads it back: bare when it has only safe characters.
std::string ShellQuoted(std::string_view argument) {
  const bool safe = !argument.empty() && std::all_of(argument.begin(), argument.end(), [](unsigned char c) {
    return std::isalnum(c) != 0 || std::string_view("@%+=:,./-_").find(static_cast<char>(c)) != std::string_view::npos;
  });
  if (safe) return std::string(argument);
  std::string quoted = "'";
  for (const char c : argument) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

Json ToJson(const Provenance& p) {
  Json inputs = Json::array();
  for (const InputFileDigest& f : p.inputs) {
    inputs.push_back({{"role", f.role}, {"path", f.path}, {"sha256", f.sha256}, {"size_bytes", f.size_bytes}});
  }
  return Json{{"software", p.software}, {"version", p.version}, {"commit", p.commit},
              {"command", p.command},   {"date_utc", p.date_utc}, {"inputs", std::move(inputs)}};
}

}  // namespace

std::string CovoptVersion() { return COVOPT_VERSION_TEXT; }

std::string CovoptCommit() { return COVOPT_GIT_COMMIT; }

std::string Sha256OfBytes(std::string_view bytes) { return covopt::Sha256Hex(bytes); }

std::string Sha256OfFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("cannot read '{}' to take its SHA-256", path.string()));
  covopt::Sha256 digest;
  std::array<char, 1 << 16> buffer{};
  while (in) {
    in.read(buffer.data(), buffer.size());
    digest.Add(buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw std::runtime_error(fmt::format("cannot read '{}' to take its SHA-256", path.string()));
  return digest.HexDigest();
}

std::string CommandLine(std::span<const char* const> argv) {
  std::string line;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    if (argv[i] == nullptr) break;
    if (i > 0) line += ' ';
    // The program as its file name: the path it was started from says nothing of the run.
    line += i == 0 ? ShellQuoted(std::filesystem::path(argv[0]).filename().string()) : ShellQuoted(argv[i]);
  }
  return line;
}

Provenance MakeProvenance(std::string command, std::span<const InputFile> input_files) {
  Provenance p;
  p.version = CovoptVersion();
  p.commit = CovoptCommit();
  p.command = std::move(command);
  p.date_utc = IsoDateUtc();
  for (const InputFile& file : input_files) {
    const std::string path = file.path.string();
    const bool seen = std::any_of(p.inputs.begin(), p.inputs.end(),
                                  [&](const InputFileDigest& d) { return d.path == path && d.role == file.role; });
    if (seen) continue;
    std::error_code ec;
    const auto size = std::filesystem::file_size(file.path, ec);
    p.inputs.push_back({file.role, path, Sha256OfFile(file.path), ec ? 0LL : static_cast<long long>(size)});
  }
  return p;
}

std::string ProvenanceJson(const Provenance& provenance, int indent) { return ToJson(provenance).dump(indent); }

std::string WithProvenance(const std::string& json_object, const Provenance& provenance) {
  return internal::AppendKey(json_object, "provenance", ToJson(provenance), "WithProvenance");
}

std::string internal::AppendKey(const std::string& json_object, std::string_view key, const nlohmann::ordered_json& value,
                                std::string_view caller) {
  const std::size_t first = json_object.find_first_not_of(" \t\r\n");
  const std::size_t last = json_object.find_last_not_of(" \t\r\n");
  if (first == std::string::npos || json_object[first] != '{' || json_object[last] != '}') {
    throw std::invalid_argument(fmt::format("{}: the text is not a JSON object", caller));
  }
  // The indent of the object's keys: the spaces after its first line break (none: one line).
  const std::size_t line_break = json_object.find('\n', first);
  const bool one_line = line_break == std::string::npos || line_break > last;
  std::size_t indent = 0;
  if (!one_line) {
    while (line_break + 1 + indent < json_object.size() && json_object[line_break + 1 + indent] == ' ') ++indent;
  }
  const bool empty = json_object.find_first_not_of(" \t\r\n", first + 1) == last;
  std::string block = value.dump(one_line ? -1 : static_cast<int>(indent));
  std::string out = json_object.substr(0, last);
  while (!out.empty() && (out.back() == ' ' || out.back() == '\n' || out.back() == '\r' || out.back() == '\t')) {
    out.pop_back();
  }
  if (one_line) {
    out += fmt::format("{}\"{}\":{}}}", empty ? "" : ",", key, block);
  } else {
    // Re-indent the block's inner lines by the object's indent.
    const std::string pad(indent, ' ');
    std::string indented;
    for (const char c : block) {
      indented += c;
      if (c == '\n') indented += pad;
    }
    out += fmt::format("{}\n{}\"{}\": {}\n}}", empty ? "" : ",", pad, key, indented);
  }
  return out + json_object.substr(last + 1);
}

}  // namespace covopt::report
