// covopt::report's provenance (provenance.hpp): SHA-256 against the FIPS 180-2 vectors, the
// command line read back by a POSIX shell, SOURCE_DATE_EPOCH, and WithProvenance on every
// shape of object the *Json functions print.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "covopt/report/provenance.hpp"

namespace {

using covopt::report::CommandLine;
using covopt::report::InputFile;
using covopt::report::MakeProvenance;
using covopt::report::Provenance;
using covopt::report::Sha256OfBytes;
using covopt::report::Sha256OfFile;
using covopt::report::WithProvenance;
using Json = nlohmann::ordered_json;

/// Sets an environment variable for the scope (unset: nullopt), restoring the old value.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, std::optional<std::string> value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) {
      ::setenv(name, value->c_str(), 1);
    } else {
      ::unsetenv(name);
    }
  }
  ~ScopedEnv() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

std::filesystem::path TempFile(const std::string& name, const std::string& bytes) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("covopt-provenance-" + std::to_string(::getpid()) + "-" + name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

Provenance Sample() {
  Provenance p;
  p.version = "9.8.7";
  p.commit = "0123456789abcdef0123456789abcdef01234567";
  p.command = "covopt simulate --json";
  p.date_utc = "2023-11-14T22:13:20Z";
  p.inputs.push_back({"scene", "a b.toml", std::string(64, 'f'), 12});
  return p;
}

/// What a shell prints for `printf '<%s>' ARGS...` run through CommandLine's quoting.
std::string ThroughShell(const std::vector<std::string>& args) {
  std::vector<const char*> argv{"printf", "<%s>"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  const std::string line = CommandLine(argv);
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(line.c_str(), "r"), &::pclose);  // sh -c LINE
  REQUIRE(pipe);
  std::string out;
  char buffer[256];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe.get())) > 0;) out.append(buffer, n);
  return out;
}

}  // namespace

TEST_CASE("Sha256OfBytes gives the FIPS 180-2 test vectors", "[provenance]") {
  CHECK(Sha256OfBytes("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(Sha256OfBytes("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(Sha256OfBytes("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  // One million 'a' (FIPS 180-2 appendix B.3).
  CHECK(Sha256OfBytes(std::string(1000000, 'a')) ==
        "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("Sha256OfFile hashes the file's bytes across its read buffer", "[provenance]") {
  // 200,003 bytes with zeros and high bytes: more than three 64 KiB reads, binary-safe.
  std::string bytes;
  for (int i = 0; i < 200003; ++i) bytes += static_cast<char>((i * 131 + i / 7) % 256);
  const auto path = TempFile("bytes.bin", bytes);
  CHECK(Sha256OfFile(path) == Sha256OfBytes(bytes));
  const auto million = TempFile("million.txt", std::string(1000000, 'a'));
  CHECK(Sha256OfFile(million) == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  std::filesystem::remove(path);
  std::filesystem::remove(million);
  CHECK_THROWS_WITH(Sha256OfFile("/nonexistent/covopt.toml"),
                    Catch::Contains("/nonexistent/covopt.toml"));
}

TEST_CASE("CommandLine quotes each argument so that sh reads it back", "[provenance]") {
  const std::vector<std::string> args{"plain", "two words", "it's", "\"double\"", "$HOME `x` \\n *",
                                      "ünïcødé 15 N/cm²", "", "--flag=a b", "tab\there", "line\nbreak", "'"};
  std::string expected;
  for (const std::string& a : args) expected += "<" + a + ">";
  CHECK(ThroughShell(args) == expected);
  // Safe arguments stay bare; the program is its file name.
  const std::vector<const char*> argv{"/usr/local/bin/covopt", "optimize", "--material", "PORON XRD 15 pcf",
                                      "--speed=2m/s"};
  CHECK(CommandLine(argv) == "covopt optimize --material 'PORON XRD 15 pcf' --speed=2m/s");
}

TEST_CASE("MakeProvenance: version, commit, the date of SOURCE_DATE_EPOCH, each file hashed once", "[provenance]") {
  const std::string text = "[robot]\nmass = \"10kg\"\n";
  const auto scene = TempFile("scene.toml", text);
  const std::vector<InputFile> files{{"scene", scene}, {"catalog", scene}, {"scene", scene}};
  {
    const ScopedEnv epoch("SOURCE_DATE_EPOCH", "1700000000");
    const Provenance p = MakeProvenance("covopt simulate", files);
    CHECK(p.software == "covopt");
    CHECK(p.version == covopt::report::CovoptVersion());
    CHECK(p.commit == covopt::report::CovoptCommit());
    CHECK(p.command == "covopt simulate");
    CHECK(p.date_utc == "2023-11-14T22:13:20Z");
    REQUIRE(p.inputs.size() == 2);  // the same file in another role is named again
    CHECK(p.inputs[0].role == "scene");
    CHECK(p.inputs[1].role == "catalog");
    CHECK(p.inputs[0].sha256 == Sha256OfBytes(text));
    CHECK(p.inputs[0].size_bytes == static_cast<long long>(text.size()));
    CHECK(p.inputs[0].path == scene.string());
  }
  {
    const ScopedEnv epoch("SOURCE_DATE_EPOCH", std::nullopt);
    const std::string date = MakeProvenance("x", {}).date_utc;  // now: YYYY-MM-DDTHH:MM:SSZ
    CHECK(date.size() == 20);
    CHECK(date[4] == '-');
    CHECK(date[10] == 'T');
    CHECK(date.back() == 'Z');
    CHECK(date >= "2024");
  }
  const std::string commit = covopt::report::CovoptCommit();
  const bool hex = commit.size() >= 40 && commit.find_first_not_of("0123456789abcdef") >= 40;
  CHECK((commit == "unknown" || (hex && (commit.size() == 40 || commit.substr(40) == "-dirty"))));
  std::filesystem::remove(scene);
  CHECK_THROWS_AS(MakeProvenance("x", std::vector<InputFile>{{"urdf", "/nonexistent/robot.urdf"}}), std::runtime_error);
}

TEST_CASE("WithProvenance appends the block as the last key at the object's indent", "[provenance]") {
  const Provenance p = Sample();
  const Json block = Json::parse(covopt::report::ProvenanceJson(p));
  CHECK(block.dump() == R"({"software":"covopt","version":"9.8.7","commit":"0123456789abcdef0123456789abcdef01234567",)"
                        R"("command":"covopt simulate --json","date_utc":"2023-11-14T22:13:20Z","inputs":[{"role":)"
                        R"("scene","path":"a b.toml","sha256":"ffffffffffffffffffffffffffffffffffffffffffffffffffff)"
                        R"(ffffffffffff","size_bytes":12}]})");

  SECTION("an object at indent 2, as the CLI prints it") {
    const Json object{{"a", 1}, {"b", {{"c", Json::array({1, 2})}}}};
    const std::string text = WithProvenance(object.dump(2), p);
    Json expected = object;
    expected["provenance"] = block;
    CHECK(text == expected.dump(2));  // exactly nlohmann's layout of the whole object
  }
  SECTION("an object at indent 4") {
    const Json object{{"a", "x"}};
    Json expected = object;
    expected["provenance"] = block;
    CHECK(WithProvenance(object.dump(4), p) == expected.dump(4));
  }
  SECTION("a one-line object, as Python's bindings read it") {
    const Json object{{"a", 1.5}, {"s", "{ } , \" provenance"}};
    Json expected = object;
    expected["provenance"] = block;
    CHECK(WithProvenance(object.dump(), p) == expected.dump());
  }
  SECTION("an empty object, on one line or two, and text around it kept") {
    Json expected = Json::object();
    expected["provenance"] = block;
    CHECK(WithProvenance("{}", p) == expected.dump());
    CHECK(Json::parse(WithProvenance("{\n}", p)) == expected);
    CHECK(WithProvenance("{}\n", p) == expected.dump() + "\n");
  }
  SECTION("anything but an object is refused") {
    for (const std::string& text : {std::string("[1, 2]"), std::string(""), std::string("  "), std::string("42"),
                                    std::string("\"{}\""), std::string("{\"a\": 1"), std::string("null")}) {
      INFO(text);
      CHECK_THROWS_AS(WithProvenance(text, p), std::invalid_argument);
    }
  }
}
