// SHA-256 through OpenSSL's EVP interface, libcrypto opened at the first digest (sha256.hpp).
#include "covopt/core/sha256.hpp"

#include <array>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <dlfcn.h>

#include <openssl/evp.h>
#include <openssl/opensslv.h>

#define COVOPT_SHA256_TEXT(x) #x
#define COVOPT_SHA256_MACRO_TEXT(x) COVOPT_SHA256_TEXT(x)

namespace covopt {
namespace {

/// OpenSSL's digest functions, from libcrypto opened the first time something is hashed. The
/// library is OpenSSL's (libcrypto.so.<OPENSSL_SHLIB_VERSION>) whose headers built this.
struct Crypto {
  decltype(&EVP_MD_CTX_new) md_ctx_new;
  decltype(&EVP_MD_CTX_free) md_ctx_free;
  decltype(&EVP_sha256) sha256;
  decltype(&EVP_DigestInit_ex) digest_init;
  decltype(&EVP_DigestUpdate) digest_update;
  decltype(&EVP_DigestFinal_ex) digest_final;
};

const Crypto& OpenCrypto() {
  static const Crypto crypto = [] {
    const std::string library = std::string("libcrypto.so.") + COVOPT_SHA256_MACRO_TEXT(OPENSSL_SHLIB_VERSION);
    void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      throw std::runtime_error("SHA-256: cannot load OpenSSL's " + library + ": " + (why ? why : "?"));
    }
    const auto symbol = [handle, &library]<class F>(F& function, const char* name) {
      function = reinterpret_cast<F>(dlsym(handle, name));
      if (function == nullptr) throw std::runtime_error("SHA-256: " + library + " has no " + name);
    };
    Crypto c{};
    symbol(c.md_ctx_new, "EVP_MD_CTX_new");
    symbol(c.md_ctx_free, "EVP_MD_CTX_free");
    symbol(c.sha256, "EVP_sha256");
    symbol(c.digest_init, "EVP_DigestInit_ex");
    symbol(c.digest_update, "EVP_DigestUpdate");
    symbol(c.digest_final, "EVP_DigestFinal_ex");
    return c;  // the handle stays open for the process
  }();
  return crypto;
}

}  // namespace

struct Sha256::Context {
  const Crypto& crypto = OpenCrypto();
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> md{crypto.md_ctx_new(), crypto.md_ctx_free};
};

Sha256::Sha256() : context_(std::make_unique<Context>()) {
  if (!context_->md || context_->crypto.digest_init(context_->md.get(), context_->crypto.sha256(), nullptr) != 1) {
    throw std::runtime_error("SHA-256: OpenSSL could not start a digest");
  }
}

Sha256::~Sha256() = default;

void Sha256::Add(const void* data, std::size_t size) {
  if (context_->crypto.digest_update(context_->md.get(), data, size) != 1) {
    throw std::runtime_error("SHA-256: OpenSSL digest failed");
  }
}

std::string Sha256::HexDigest() {
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  if (context_->crypto.digest_final(context_->md.get(), digest.data(), &length) != 1) {
    throw std::runtime_error("SHA-256: OpenSSL digest failed");
  }
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) {
    std::array<char, 3> pair{};
    std::snprintf(pair.data(), pair.size(), "%02x", digest[i]);
    hex += pair.data();
  }
  return hex;
}

std::string Sha256Hex(std::string_view bytes) {
  Sha256 digest;
  digest.Add(bytes.data(), bytes.size());
  return digest.HexDigest();
}

}  // namespace covopt
