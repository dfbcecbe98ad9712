// The report's sign-off settings (covopt/report/report_info.hpp, report_settings.hpp): the
// appendix's names, the checks of CheckReportInfo (lengths, characters, the threshold's range),
// the margin threshold's reading ("10%" or 0.1) and ApplyReportSettings (later settings win,
// unknown keys and wrong types refused, nothing changed by a bad setting).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "covopt/report/report_info.hpp"
#include "covopt/report/report_settings.hpp"

namespace {

using covopt::report::ApplyReportSettings;
using covopt::report::CheckReportInfo;
using covopt::report::ParseMarginThreshold;
using covopt::report::ParseReportAppendix;
using covopt::report::ReportAppendix;
using covopt::report::ReportInfo;
using covopt::report::ReportSetting;
using Catch::Matchers::Contains;
using Catch::Matchers::Equals;

/// The message CheckReportInfo gives for `info`; empty when it accepts it.
std::string CheckMessage(const ReportInfo& info) {
  try {
    CheckReportInfo(info);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

ReportInfo WithProject(std::string project) {
  ReportInfo info;
  info.project = std::move(project);
  return info;
}

}  // namespace

TEST_CASE("The report appendix: its three names read back, another name is refused", "[report_info]") {
  for (const ReportAppendix a : {ReportAppendix::kNone, ReportAppendix::kSummary, ReportAppendix::kFull}) {
    CHECK(ParseReportAppendix(covopt::report::ToString(a)) == a);
  }
  CHECK(covopt::report::ToString(ReportAppendix::kSummary) == "summary");
  CHECK(ReportInfo{}.appendix == ReportAppendix::kSummary);
  CHECK_THROWS_WITH(ParseReportAppendix("Full"), Contains("none, summary or full") && Contains("'Full'"));
  CHECK_THROWS_AS(ParseReportAppendix(""), std::invalid_argument);
}

TEST_CASE("CheckReportInfo: texts up to 2000 characters, counted as characters, not bytes", "[report_info]") {
  CHECK(CheckMessage(ReportInfo{}).empty());
  CHECK(CheckMessage(WithProject(std::string(2000, 'a'))).empty());
  std::string umlauts;
  for (int i = 0; i < 2000; ++i) umlauts += "\xC3\xA4";  // ä: 2 bytes, 1 character
  CHECK(CheckMessage(WithProject(umlauts)).empty());
  const std::string too_long = CheckMessage(WithProject(std::string(2001, 'a')));
  CHECK_THAT(too_long, Contains("project") && Contains("2001 characters") && Contains("at most 2000"));
}

TEST_CASE("CheckReportInfo: no control characters, but line breaks in the note", "[report_info]") {
  ReportInfo info;
  info.note = "line one\nline two\r\nline three";
  CHECK(CheckMessage(info).empty());
  CHECK_THAT(CheckMessage(WithProject("cell\n4")), Contains("project") && Contains("control character at character 5"));
  info.note = std::string("bell\a");
  CHECK_THAT(CheckMessage(info), Contains("note") && Contains("\\x07") && Contains("only line breaks"));
  info = {};
  info.assessor = "tab\there";
  CHECK_THAT(CheckMessage(info), Contains("assessor"));
  info = {};
  info.cell = "C1\xC2\x85";  // U+0085, a C1 control character
  CHECK_THAT(CheckMessage(info), Contains("cell") && Contains("control character"));
  CHECK_THAT(CheckMessage(WithProject("\xFF\xFE")), Contains("project") && Contains("not UTF-8"));
  CHECK_THAT(CheckMessage(WithProject("cut \xC3")), Contains("not UTF-8"));
}

TEST_CASE("CheckReportInfo: the margin threshold is a finite share from 0 up to but not including 1", "[report_info]") {
  for (const double good : {0.0, 0.1, 0.999}) {
    ReportInfo info;
    info.margin_threshold = good;
    CHECK(CheckMessage(info).empty());
  }
  for (const double bad : {1.0, -0.01, 50.0, std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()}) {
    ReportInfo info;
    info.margin_threshold = bad;
    CAPTURE(bad);
    CHECK_THAT(CheckMessage(info), Contains("margin_threshold") && Contains("[0, 1)"));
  }
}

TEST_CASE("ParseMarginThreshold: a percentage or a bare share", "[report_info]") {
  CHECK(ParseMarginThreshold("10%", "--margin-threshold") == Approx(0.10));
  CHECK(ParseMarginThreshold(" 2.5 % ", "--margin-threshold") == Approx(0.025));
  CHECK(ParseMarginThreshold("0.2", "--margin-threshold") == Approx(0.2));
  CHECK(ParseMarginThreshold("0", "x") == 0.0);
  CHECK_FALSE(std::signbit(ParseMarginThreshold("-0", "x")));
  CHECK_THROWS_WITH(ParseMarginThreshold("10", "--margin-threshold"),
                    Equals("--margin-threshold: a bare number is a share in [0, 1); write 10% for 10 per cent "
                           "(got '10')"));
  CHECK_THROWS_WITH(ParseMarginThreshold("100%", "--margin-threshold"), Contains("[0, 1)") && Contains("'100%'"));
  CHECK_THROWS_WITH(ParseMarginThreshold("-5%", "t"), Contains("t: must be a share"));
  CHECK_THROWS_WITH(ParseMarginThreshold("ten", "t"), Contains("t: expected a share") && Contains("'ten'"));
  CHECK_THROWS_WITH(ParseMarginThreshold("", "t"), Contains("expected a share"));
  CHECK_THROWS_WITH(ParseMarginThreshold("nan", "t"), Contains("expected a share"));
  CHECK_THROWS_WITH(ParseMarginThreshold("0.1x", "t"), Contains("'0.1x'"));
  CHECK_THROWS_WITH(ParseMarginThreshold("1e400", "t"), Contains("expected a share"));
}

TEST_CASE("ApplyReportSettings: each key read, later settings win", "[report_info]") {
  const std::vector<ReportSetting> settings{
      {"project", std::string("Line 4 palletiser"), "s.toml:2:11: report.project"},
      {"note", std::string("first\nsecond"), "s.toml:3:8: report.note"},
      {"margin_threshold", 0.25, "s.toml:4:20: report.margin_threshold"},
      {"appendix", std::string("full"), "s.toml:5:12: report.appendix"},
      {"project", std::string("Line 5"), "--project"},
      {"margin_threshold", std::string("15%"), "--margin-threshold"},
      {"cell", std::string("C-12"), "--cell"},
      {"assessor", std::string("A. Person"), "--assessor"},
  };
  ReportInfo info;
  ApplyReportSettings(settings, info);
  CHECK(info.project == "Line 5");
  CHECK(info.cell == "C-12");
  CHECK(info.assessor == "A. Person");
  CHECK(info.note == "first\nsecond");
  CHECK(info.margin_threshold == Approx(0.15));
  CHECK(info.appendix == ReportAppendix::kFull);
}

TEST_CASE("ApplyReportSettings: a bad setting is refused by its name and changes nothing", "[report_info]") {
  ReportInfo info;
  info.project = "kept";
  const auto refused = [&](ReportSetting setting) {
    const std::vector<ReportSetting> settings{{"cell", std::string("changed?"), "--cell"}, std::move(setting)};
    try {
      ApplyReportSettings(settings, info);
    } catch (const std::invalid_argument& e) {
      CHECK(info.project == "kept");
      CHECK(info.cell.empty());
      return std::string(e.what());
    }
    FAIL("accepted");
    return std::string();
  };
  CHECK_THAT(refused({"projet", std::string("x"), "report_info['projet']"}),
             Equals("report_info['projet']: unknown key 'projet'; did you mean 'project'?"));
  CHECK_THAT(refused({"colour", std::string("x"), "k"}),
             Contains("the keys are project, cell, assessor, note, margin_threshold, appendix"));
  CHECK_THAT(refused({"assessor", 3.0, "report_info['assessor']"}),
             Contains("report_info['assessor']: expected a text, got the number 3"));
  CHECK_THAT(refused({"appendix", std::string("some"), "--report-appendix"}),
             Contains("--report-appendix: the appendix must be none, summary or full (got 'some')"));
  CHECK_THAT(refused({"margin_threshold", 12.0, "s.toml:2:1: report.margin_threshold"}),
             Contains("s.toml:2:1: report.margin_threshold: a bare number") && Contains("write 12%"));
  CHECK_THAT(refused({"margin_threshold", -0.5, "m"}), Contains("m: must be a share in [0, 1)"));
  CHECK_THAT(refused({"note", std::string(2001, 'n'), "--note"}), Contains("--note: 2001 characters"));
  CHECK_THAT(refused({"project", std::string("a\x1b[31m"), ""}), Contains("control character") && !Contains(": a"));
}
