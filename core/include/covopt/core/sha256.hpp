#pragma once
/// @file sha256.hpp
/// SHA-256 digests, lower-case hex, by OpenSSL's libcrypto (its EVP interface), which is opened
/// (dlopen) at the first digest: a run that hashes nothing never loads it (its load and symbol
/// bindings cost 0.44 of a hello-world process, docs/performance.md, start-up). The provenance
/// of every output (covopt/report/provenance.hpp) and the digest of a body-region limit table
/// (covopt/materials/body_regions.hpp) use it.

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace covopt {

/// One digest, fed in pieces.
class Sha256 {
 public:
  /// @throws std::runtime_error when libcrypto cannot be loaded or the digest cannot start.
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;
  /// Adds `size` bytes at `data`.
  void Add(const void* data, std::size_t size);
  /// The digest of the bytes added, lower-case hex (64 characters); call once.
  std::string HexDigest();

 private:
  struct Context;
  std::unique_ptr<Context> context_;
};

/// The SHA-256 of `bytes`, lower-case hex.
std::string Sha256Hex(std::string_view bytes);

}  // namespace covopt
