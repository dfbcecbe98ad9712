// The report for the risk-assessment file (covopt/report/html_report.hpp), rendered from real
// results: the --json objects of a SAFE and an UNSAFE run of every report kind and mode, saved
// from the CLI under tests/report/data (make-fixtures.sh), and a simulation made here by the
// library. Checked: the banner's verdict is the JSON's; the governing ratio is the largest
// ratio of the JSON, with its exact number text; every scene/input leaf is in the document
// with its exact JSON text; SAFE and UNSAFE banners differ only in colour; every text is
// escaped; two gnuplot charts' ids are prefixed apart and every <svg> is well-formed XML; no
// script and no external reference; runs without a verdict, non-objects and results without
// provenance are refused.
#include <algorithm>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <covopt/core/impact_model.hpp>
#include <covopt/core/exact.hpp>
#include <covopt/materials/catalog.hpp>
#include <covopt/report/html_report.hpp>
#include <covopt/report/provenance.hpp>
#include <covopt/optim/verdicts.hpp>
#include <covopt/report/simulation_json.hpp>

namespace {

using covopt::report::ReportContent;
using covopt::report::ReportKind;
using Json = nlohmann::ordered_json;

std::string ReadFile(const std::string& name) {
  std::ifstream in(std::string(COVOPT_REPORT_TEST_DATA) + "/" + name, std::ios::binary);
  if (!in) throw std::runtime_error("missing test data " + name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The JSON with the provenance block every command adds.
std::string WithProvenance(const std::string& json) {
  if (Json::parse(json).contains("provenance")) return json;
  return covopt::report::WithProvenance(json, covopt::report::MakeProvenance("covopt test --json", {}));
}

std::string Render(ReportKind kind, const std::string& json, std::vector<covopt::report::SvgChart> charts = {}) {
  ReportContent content;
  content.kind = kind;
  content.result_json = WithProvenance(json);
  content.charts = std::move(charts);
  return covopt::report::HtmlReport(content);
}

std::string Unescape(std::string text) {
  static const std::pair<const char*, const char*> kEntities[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}};
  for (const auto& [entity, plain] : kEntities) {
    for (std::size_t at = text.find(entity); at != std::string::npos; at = text.find(entity, at + 1)) {
      text.replace(at, std::string(entity).size(), plain);
    }
  }
  return text;
}

/// The banner: data-safe and the visible word.
struct Banner {
  std::string data_safe;
  std::string word;
  std::string css_class;
  std::string governing_value;
};

Banner BannerOf(const std::string& html) {
  std::smatch m;
  Banner b;
  REQUIRE(std::regex_search(html, m, std::regex(R"re(<section id="verdict" class="([^"]*)" data-safe="([^"]*)">\s*<div class="word">([^<]*)</div>)re")));
  b.css_class = m[1];
  b.data_safe = m[2];
  b.word = m[3];
  REQUIRE(std::regex_search(html, m, std::regex(R"re(<span id="governing-ratio" data-value="([^"]*)">)re")));
  b.governing_value = Unescape(m[1]);
  return b;
}

/// Every data-key with its data-value.
std::multimap<std::string, std::string> DataKeys(const std::string& html) {
  std::multimap<std::string, std::string> keys;
  static const std::regex kPair(R"re(data-key="([^"]*)" data-value="([^"]*)")re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), kPair); it != std::sregex_iterator(); ++it) {
    keys.emplace(Unescape((*it)[1]), Unescape((*it)[2]));
  }
  return keys;
}

/// The leaves of `value` by dotted path (independent of the report's own flattening).
void Leaves(const Json& value, const std::string& path, std::vector<std::pair<std::string, std::string>>& out) {
  if (value.is_object() && !value.empty()) {
    for (auto it = value.begin(); it != value.end(); ++it) Leaves(it.value(), path + "." + it.key(), out);
  } else if (value.is_array() && !value.empty()) {
    for (std::size_t i = 0; i < value.size(); ++i) Leaves(value[i], path + "." + std::to_string(i), out);
  } else {
    out.emplace_back(path, value.is_string() ? value.get<std::string>() : value.dump());
  }
}

/// The largest number under a key named "ratio", "*_ratio" (not a Poisson ratio) or
/// "worst_ratio" in `value`, with its JSON text.
void MaxRatio(const Json& value, const std::string& key, double& best, std::string& text) {
  if (value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it) MaxRatio(it.value(), it.key(), best, text);
  } else if (value.is_array()) {
    for (const Json& e : value) MaxRatio(e, key, best, text);
  } else if (value.is_number()) {
    const bool ratio = (key == "ratio" || (key.size() > 6 && key.compare(key.size() - 6, 6, "_ratio") == 0)) &&
                       key.find("poisson") == std::string::npos && key != "corner_governing_ratio";
    if (ratio && value.get<double>() > best) {
      best = value.get<double>();
      text = value.dump();
    }
  }
}

std::string MaxRatioText(std::initializer_list<const Json*> parts) {
  double best = -1.0;
  std::string text = "null";
  for (const Json* p : parts) {
    if (p) MaxRatio(*p, "", best, text);
  }
  return text;
}

struct Case {
  const char* file;
  ReportKind kind;
  bool safe;
  /// The parts of the JSON the governing ratio is the largest ratio of.
  std::function<std::string(const Json&)> governing;
  /// The JSON's top-level input objects.
  std::vector<const char*> inputs;
};

const Json* Ptr(const Json& j, const char* key) { return j.contains(key) ? &j[key] : nullptr; }

std::vector<Case> Cases() {
  const auto head_sim = [](const Json& j) {
    return MaxRatioText({Ptr(j, "laceration"), Ptr(j, "contusion"), Ptr(j, "crush"), Ptr(j, "worst_case")});
  };
  const auto regions = [](const Json& j) {
    return MaxRatioText({Ptr(j, "regions"), j["head"].is_null() ? nullptr : &j["head"]["laceration"],
                         j["head"].is_null() ? nullptr : &j["head"]["contusion"]});
  };
  const auto recommendation = [](const Json& j) { return j["recommendation"]["governing_ratio"].dump(); };
  const auto bare = [](const Json& j) { return MaxRatioText({Ptr(j, "bare_robot")}); };
  const auto rows = [](const Json& j) { return MaxRatioText({Ptr(j, "rows")}); };
  const auto samples = [](const Json& j) { return MaxRatioText({Ptr(j, "samples")}); };
  const auto cells = [](const Json& j) { return MaxRatioText({Ptr(j, "cells")}); };
  const auto probability = [](const Json& j) {
    return Json(j["recommendation"]["injury_probability"]["inadmissible"].get<double>() /
                j["max_probability"].get<double>())
        .dump();
  };
  return {
      {"simulate_safe.json", ReportKind::kSimulate, true, head_sim, {"scene"}},
      {"simulate_unsafe.json", ReportKind::kSimulate, false, head_sim, {"scene"}},
      {"simulate_ranges_unsafe.json", ReportKind::kSimulate, false, head_sim, {"scene", "uncertain_inputs"}},
      {"simulate_body_safe.json", ReportKind::kSimulate, true, regions, {"scene", "safety_factor"}},
      {"simulate_body_unsafe.json", ReportKind::kSimulate, false, regions, {"scene", "safety_factor"}},
      {"optimize_safe.json", ReportKind::kOptimize, true, recommendation, {"scene", "limits", "design_space"}},
      {"optimize_unsafe.json", ReportKind::kOptimize, false, bare, {"scene", "limits", "design_space"}},
      {"optimize_robust_safe.json", ReportKind::kOptimize, true, recommendation, {"uncertain_inputs", "limits"}},
      {"optimize_probability_safe.json", ReportKind::kOptimize, true, probability,
       {"uncertain_inputs", "max_probability", "samples", "seed"}},
      {"optimize_body_safe.json", ReportKind::kOptimize, true, recommendation, {"scene", "speed_m_per_s", "safety_factor"}},
      {"optimize_body_unsafe.json", ReportKind::kOptimize, false, bare, {"scene", "speed_m_per_s", "safety_factor"}},
      {"speed_limit_safe.json", ReportKind::kSpeedLimit, true, rows, {"scene", "limits", "search_limit", "solve_for"}},
      {"speed_limit_body_safe.json", ReportKind::kSpeedLimit, true, rows, {"scene", "solve_for"}},
      {"speed_limit_robust_safe.json", ReportKind::kSpeedLimit, true, rows, {"uncertain_inputs", "solve_for"}},
      {"trajectory_safe.json", ReportKind::kTrajectory, true, samples, {"scene", "limits", "joint_names"}},
      {"trajectory_unsafe.json", ReportKind::kTrajectory, false, samples, {"scene", "limits", "joint_names"}},
      {"trajectory_body_safe.json", ReportKind::kTrajectory, true, samples, {"scene", "regions"}},
      {"trajectory_body_unsafe.json", ReportKind::kTrajectory, false, samples, {"scene", "regions"}},
      {"audit_safe.json", ReportKind::kAudit, true, cells, {"robot", "coverings", "contact_area_m2", "surface"}},
      {"audit_unsafe.json", ReportKind::kAudit, false, cells, {"robot", "coverings", "contact_area_m2", "surface"}},
  };
}

/// A small XML well-formedness check of one element's text: tags nest and close, attributes
/// are quoted and not repeated, entities are XML's, nothing follows the root.
void CheckWellFormedXml(const std::string& xml) {
  std::vector<std::string> open;
  std::size_t i = 0;
  bool root_closed = false;
  const auto name_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == ':' || c == '-' || c == '_' || c == '.'; };
  while (i < xml.size()) {
    if (xml[i] == '&') {
      const std::size_t semi = xml.find(';', i);
      REQUIRE(semi != std::string::npos);
      const std::string entity = xml.substr(i + 1, semi - i - 1);
      const bool ok = entity == "lt" || entity == "gt" || entity == "amp" || entity == "quot" || entity == "apos" ||
                      (entity.size() > 1 && entity[0] == '#');
      INFO("entity &" << entity << ";");
      REQUIRE(ok);
      i = semi + 1;
      continue;
    }
    if (xml[i] != '<') {
      if (root_closed) REQUIRE(std::isspace(static_cast<unsigned char>(xml[i])));
      ++i;
      continue;
    }
    REQUIRE_FALSE(root_closed);
    if (xml.compare(i, 4, "<!--") == 0) {
      i = xml.find("-->", i);
      REQUIRE(i != std::string::npos);
      i += 3;
      continue;
    }
    if (xml.compare(i, 9, "<![CDATA[") == 0) {
      i = xml.find("]]>", i);
      REQUIRE(i != std::string::npos);
      i += 3;
      continue;
    }
    const bool closing = xml[i + 1] == '/';
    std::size_t j = i + (closing ? 2 : 1);
    const std::size_t name_begin = j;
    while (j < xml.size() && name_char(xml[j])) ++j;
    const std::string name = xml.substr(name_begin, j - name_begin);
    REQUIRE_FALSE(name.empty());
    std::set<std::string> attributes;
    bool self_closing = false;
    while (true) {
      while (j < xml.size() && std::isspace(static_cast<unsigned char>(xml[j]))) ++j;
      REQUIRE(j < xml.size());
      if (xml[j] == '>') break;
      if (xml.compare(j, 2, "/>") == 0) {
        self_closing = true;
        ++j;
        break;
      }
      REQUIRE_FALSE(closing);
      const std::size_t a = j;
      while (j < xml.size() && name_char(xml[j])) ++j;
      const std::string attribute = xml.substr(a, j - a);
      INFO("<" << name << "> attribute '" << attribute << "'");
      REQUIRE_FALSE(attribute.empty());
      REQUIRE(attributes.insert(attribute).second);
      while (std::isspace(static_cast<unsigned char>(xml[j]))) ++j;
      REQUIRE(xml[j] == '=');
      ++j;
      while (std::isspace(static_cast<unsigned char>(xml[j]))) ++j;
      const char quote = xml[j];
      REQUIRE((quote == '"' || quote == '\''));
      const std::size_t close = xml.find(quote, j + 1);
      REQUIRE(close != std::string::npos);
      REQUIRE(xml.substr(j + 1, close - j - 1).find('<') == std::string::npos);
      j = close + 1;
    }
    if (closing) {
      INFO("closing </" << name << ">");
      REQUIRE_FALSE(open.empty());
      REQUIRE(open.back() == name);
      open.pop_back();
      if (open.empty()) root_closed = true;
    } else if (!self_closing) {
      open.push_back(name);
    } else if (open.empty()) {
      root_closed = true;
    }
    i = j + 1;
  }
  REQUIRE(open.empty());
  REQUIRE(root_closed);
}

std::vector<std::string> SvgBlocks(const std::string& html) {
  std::vector<std::string> blocks;
  for (std::size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) {
    const std::size_t end = html.find("</svg>", at);
    REQUIRE(end != std::string::npos);
    blocks.push_back(html.substr(at, end + 6 - at));
    at = end;
  }
  return blocks;
}

std::vector<std::string> Ids(const std::string& text) {
  std::vector<std::string> ids;
  static const std::regex kId(R"re(\sid=(?:"([^"]*)"|'([^']*)'))re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kId); it != std::sregex_iterator(); ++it) {
    ids.push_back((*it)[1].matched ? (*it)[1].str() : (*it)[2].str());
  }
  return ids;
}

std::vector<covopt::report::SvgChart> TwoGnuplotCharts() {
  return {{"Force over time", "the peak & the limit <F>", ReadFile("gnuplot_points.svg")},
          {"Stress", "second chart", ReadFile("gnuplot_lines.svg")}};
}

}  // namespace

TEST_CASE("The report's banner is the JSON's verdict and the governing ratio its largest ratio, for every kind and mode",
          "[report][html]") {
  for (const Case& c : Cases()) {
    INFO(c.file);
    const std::string json = ReadFile(c.file);
    const Json j = Json::parse(json);
    const std::string html = Render(c.kind, json);
    const Banner banner = BannerOf(html);
    CHECK(banner.data_safe == (c.safe ? "true" : "false"));
    CHECK(banner.word == (c.safe ? "SAFE" : "UNSAFE"));
    CHECK(banner.css_class == (c.safe ? "verdict safe" : "verdict unsafe"));
    CHECK(banner.governing_value == c.governing(j));
    // The fixture says the same as its own verdict field, where it has one.
    if (j.contains("safe") && j["safe"].is_boolean()) CHECK(j["safe"].get<bool>() == c.safe);
    if (j.contains("status")) CHECK((j["status"] == "safe") == c.safe);
  }
}

TEST_CASE("Every input leaf of the JSON is in the report with its dotted path and exact JSON text", "[report][html]") {
  for (const Case& c : Cases()) {
    INFO(c.file);
    const std::string json = ReadFile(c.file);
    const Json j = Json::parse(json);
    const std::multimap<std::string, std::string> keys = DataKeys(Render(c.kind, json));
    std::vector<std::pair<std::string, std::string>> leaves;
    for (const char* input : c.inputs) {
      REQUIRE(j.contains(input));
      Leaves(j[input], input, leaves);
    }
    REQUIRE(leaves.size() >= c.inputs.size());
    for (const auto& [path, text] : leaves) {
      INFO(path << " = " << text);
      const auto range = keys.equal_range(path);
      REQUIRE(std::distance(range.first, range.second) == 1);
      CHECK(range.first->second == text);
    }
  }
}

TEST_CASE("A simulation made by the library renders with its own numbers", "[report][html]") {
  covopt::Scene scene;  // the paper's scene with 15 mm of 27.6 MPa foam: contusion 1.15
  scene.covering = {27.6e6, 0.25, 0.015};
  covopt::report::SimulationReport report;
  report.scene = scene;
  report.result = covopt::SolveExact(covopt::ImpactModel::FromScene(scene));
  for (const double sf : {1.0, 0.5}) {
    report.verdict = covopt::optim::HeadVerdict(report.result.peaks, true, covopt::InjuryLimits{},
                                                covopt::optim::DesignRule{sf, covopt::optim::DesignCriterion::kPaper});
    report.verdict.scope = {"Criteria: no laceration and no contusion (Park et al. 2011's skin limits)."};
    const std::string json = covopt::report::SimulationJson(report);
    const Json j = Json::parse(json);
    const std::string html = Render(ReportKind::kSimulate, json);
    const Banner banner = BannerOf(html);
    const double contusion = j["contusion"]["ratio"].get<double>();
    CHECK(contusion > 1.0);
    // SF 0.5 doubles every derated limit: 1.15 × 0.5 <= 1 is safe.
    CHECK(banner.data_safe == (sf * contusion <= 1.0 ? "true" : "false"));
    CHECK(banner.governing_value == j["contusion"]["ratio"].dump());
    // The margin of the governing criterion, 1 − SF × ratio, in percent with one decimal.
    char margin[32];
    std::snprintf(margin, sizeof margin, "margin %.1f %%", 100.0 * (1.0 - sf * contusion));
    CHECK(html.find(margin) != std::string::npos);
    CHECK(DataKeys(html).find("scene.head.mass_kg")->second == j["scene"]["head"]["mass_kg"].dump());
  }
}

TEST_CASE("SAFE and UNSAFE are equally prominent: the same element and place, only colours differ", "[report][html]") {
  const std::string safe = Render(ReportKind::kSimulate, ReadFile("simulate_safe.json"));
  const std::string unsafe = Render(ReportKind::kSimulate, ReadFile("simulate_unsafe.json"));
  // The banner is the first element of the body after the header, in both.
  const auto banner_position = [](const std::string& html) {
    return html.find("<section id=\"verdict\"") - html.find("</header>");
  };
  CHECK(banner_position(safe) == banner_position(unsafe));
  // The rules of .verdict.safe and .verdict.unsafe set colours only; size and weight are .verdict's.
  for (const char* selector : {".verdict.safe {", ".verdict.unsafe {"}) {
    INFO(selector);
    const std::size_t at = safe.find(selector);
    REQUIRE(at != std::string::npos);
    const std::string rule = safe.substr(at, safe.find('}', at) - at);
    std::vector<std::string> properties;
    static const std::regex kProperty(R"re(([a-z-]+)\s*:)re");
    for (auto it = std::sregex_iterator(rule.begin(), rule.end(), kProperty); it != std::sregex_iterator(); ++it) {
      properties.push_back((*it)[1]);
    }
    CHECK(properties == std::vector<std::string>{"color", "background", "border-color"});
  }
  CHECK(safe.find("<div class=\"word\">SAFE</div>") != std::string::npos);
  CHECK(unsafe.find("<div class=\"word\">UNSAFE</div>") != std::string::npos);
}

TEST_CASE("Every text from the JSON and the charts is escaped: a material named <script> is inert", "[report][html]") {
  Json j = Json::parse(ReadFile("simulate_safe.json"));
  j["scene"]["covering"]["material"] = "<script>alert('x')</script> & \"co\"";
  j["warnings"].push_back("<img src=x onerror=alert(1)>");
  j["unknown_extra"] = {{"<b>key</b>", "</td></tr></table><script>"}};
  std::vector<covopt::report::SvgChart> charts = {{"<script>t</script>", "<i>caption</i>", ReadFile("gnuplot_lines.svg")}};
  const std::string html = Render(ReportKind::kSimulate, j.dump(2), charts);
  CHECK(html.find("<script") == std::string::npos);
  CHECK(html.find("<img") == std::string::npos);
  CHECK(html.find("<b>key</b>") == std::string::npos);
  CHECK(html.find("&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;co&quot;") != std::string::npos);
  CHECK(html.find("&lt;i&gt;caption&lt;/i&gt;") != std::string::npos);
  // The unknown key lands in the appendix, escaped.
  CHECK(html.find("&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;&lt;script&gt;") != std::string::npos);
  // The input's data-value gives the string back exactly.
  CHECK(DataKeys(html).find("scene.covering.material")->second == j["scene"]["covering"]["material"].get<std::string>());
}

TEST_CASE("Two gnuplot charts inline as well-formed SVG with ids prefixed apart and references kept", "[report][html]") {
  const std::vector<covopt::report::SvgChart> charts = TwoGnuplotCharts();
  // The raw charts clash: gnuplot names its ids the same in every file.
  const std::vector<std::string> first = Ids(charts[0].svg);
  const std::vector<std::string> second = Ids(charts[1].svg);
  REQUIRE(std::find(second.begin(), second.end(), "gnuplot_canvas") != second.end());
  REQUIRE(std::find(first.begin(), first.end(), "gnuplot_canvas") != first.end());

  const std::string html = Render(ReportKind::kSimulate, ReadFile("simulate_unsafe.json"), charts);
  CHECK(html.find("<?xml") == std::string::npos);
  CHECK(html.find("<!DOCTYPE svg") == std::string::npos);
  const std::vector<std::string> svgs = SvgBlocks(html);
  REQUIRE(svgs.size() == 2);
  for (const std::string& svg : svgs) CheckWellFormedXml(svg);
  // Every id of the document is unique, and each chart kept all of its own.
  const std::vector<std::string> ids = Ids(html);
  const std::set<std::string> unique(ids.begin(), ids.end());
  CHECK(unique.size() == ids.size());
  CHECK(Ids(svgs[0]).size() == first.size());
  CHECK(Ids(svgs[1]).size() == second.size());
  CHECK(unique.count("chart1-gnuplot_canvas") == 1);
  CHECK(unique.count("chart2-gnuplot_canvas") == 1);
  // Every local reference points at an id of its own chart.
  static const std::regex kReference(R"re((?:href=["']#|url\(#)([^"')]*))re");
  for (std::size_t n = 0; n < svgs.size(); ++n) {
    const std::vector<std::string> own = Ids(svgs[n]);
    std::size_t references = 0;
    for (auto it = std::sregex_iterator(svgs[n].begin(), svgs[n].end(), kReference); it != std::sregex_iterator(); ++it) {
      const std::string target = (*it)[1];
      INFO("chart " << n + 1 << " refers to #" << target);
      CHECK(std::find(own.begin(), own.end(), target) != own.end());
      ++references;
    }
    CHECK(references > 0);
  }
  // Figures with their titles, one per chart.
  std::size_t figures = 0;
  for (std::size_t at = html.find("<figure class=\"chart\""); at != std::string::npos;
       at = html.find("<figure class=\"chart\"", at + 1)) {
    ++figures;
  }
  CHECK(figures == 2);
  CHECK(html.find("the peak &amp; the limit &lt;F&gt;") != std::string::npos);
}

TEST_CASE("The report fetches nothing and runs nothing", "[report][html]") {
  for (const Case& c : Cases()) {
    INFO(c.file);
    const std::string html = Render(c.kind, ReadFile(c.file), TwoGnuplotCharts());
    CHECK(html.find("<script") == std::string::npos);
    CHECK(html.find("<link") == std::string::npos);
    CHECK(html.find("<img") == std::string::npos);
    CHECK(html.find("@import") == std::string::npos);
    CHECK(html.find("src=") == std::string::npos);
    static const std::regex kExternal(R"re((?:href=["'](?!#)|url\((?!#)))re");
    CHECK_FALSE(std::regex_search(html, kExternal));
    CHECK(html.rfind("<!DOCTYPE html>\n<html lang=\"en\">", 0) == 0);
    CHECK(html.find("<meta charset=\"utf-8\">") != std::string::npos);
    CHECK(html.find("default-src 'none'") != std::string::npos);
  }
  // A chart that refers outside itself, or runs a script, is refused or stripped.
  std::string external = ReadFile("gnuplot_lines.svg");
  external.insert(external.find("<g "), "<image href=\"https://example.com/x.png\"/>");
  CHECK_THROWS_WITH(Render(ReportKind::kSimulate, ReadFile("simulate_safe.json"), {{"t", "c", external}}),
                    Catch::Contains("chart 1") && Catch::Contains("external"));
  std::string scripted = ReadFile("gnuplot_lines.svg");
  scripted.insert(scripted.find("<g "), "<script type=\"text/javascript\">alert(1)</script><g onload=\"alert(2)\"></g>");
  const std::string html = Render(ReportKind::kSimulate, ReadFile("simulate_safe.json"), {{"t", "c", scripted}});
  CHECK(html.find("alert") == std::string::npos);
  CheckWellFormedXml(SvgBlocks(html).at(0));
}

TEST_CASE("The report states its sources, margin definition, model assumptions, materials and provenance",
          "[report][html]") {
  const std::string body = Render(ReportKind::kSimulate, ReadFile("simulate_body_unsafe.json"));
  CHECK(body.find("ISO/TS 15066:2016 Annex A, Table A.2, region chest, area sternum (body area no. ") !=
        std::string::npos);
  CHECK(body.find("docs/model.md §13.1") != std::string::npos);
  CHECK(body.find("(§13.8)") != std::string::npos);
  CHECK(body.find("1 − SF × ratio") != std::string::npos);
  CHECK(body.find("Park et al., Designing Optimally Safe Robot Surface Properties") != std::string::npos);
  // The neoprene sponge's datasheet source, from the catalog.
  CHECK(body.find("<h3>neoprene sponge D1056 2C4</h3>") != std::string::npos);
  CHECK(body.find("source (datasheet)") != std::string::npos);
  CHECK(body.find(covopt::materials::Catalog::BuiltIn().Find("neoprene sponge D1056 2C4")->source) != std::string::npos);
  CHECK(body.find("The run used E = ") == std::string::npos);
  // A material of that name with another modulus came from the run's own catalog: said so.
  Json own = Json::parse(ReadFile("simulate_safe.json"));
  own["scene"]["covering"]["youngs_modulus_Pa"] = 1.5e6;
  CHECK(Render(ReportKind::kSimulate, own.dump()).find("The run used E = 1.5 MPa, not the built-in entry") !=
        std::string::npos);
  const std::string audit = Render(ReportKind::kAudit, ReadFile("audit_unsafe.json"));
  CHECK(audit.find("docs/model.md §14.6") != std::string::npos);
  CHECK(audit.find("No catalog material: the covering is given by its modulus") != std::string::npos);
  // Provenance: the version, commit, command and each input file with its SHA-256.
  ReportContent content;
  content.kind = ReportKind::kTrajectory;
  const std::string csv = std::string(COVOPT_REPORT_TEST_DATA) + "/fr3_pick21.csv";
  const std::vector<covopt::report::InputFile> files = {{"trajectory", csv}};
  const covopt::report::Provenance p = covopt::report::MakeProvenance("covopt robot --trajectory 'a b.csv'", files);
  content.result_json = covopt::report::WithProvenance(ReadFile("trajectory_safe.json"), p);
  const std::string html = covopt::report::HtmlReport(content);
  CHECK(html.find(p.inputs.at(0).sha256) != std::string::npos);
  CHECK(p.inputs.at(0).sha256 == covopt::report::Sha256OfFile(csv));
  CHECK(html.find("covopt robot --trajectory &#39;a b.csv&#39;") != std::string::npos);
  CHECK(html.find(p.commit) != std::string::npos);
  CHECK(html.find(p.date_utc) != std::string::npos);
  // The appendix holds every value: each sample's time is there.
  const Json j = Json::parse(ReadFile("trajectory_safe.json"));
  const std::string appendix = html.substr(html.find("Appendix: every value"));
  for (const Json& sample : j["samples"]) {
    CHECK(appendix.find("<td>" + sample["reflected_mass_kg"].dump() + "</td>") != std::string::npos);
  }
}

TEST_CASE("The margin is 1 - SF x ratio with the result's own safety factor", "[report][html]") {
  // A body-region trajectory records its factor in the criterion's words only.
  Json j = Json::parse(ReadFile("trajectory_body_unsafe.json"));
  const std::string criterion = j["criterion"].get<std::string>();
  const std::size_t at = criterion.rfind("safety factor 1 on each");
  REQUIRE(at != std::string::npos);
  double ratio = 0.0;
  for (const Json& sample : j["samples"]) ratio = std::max(ratio, sample["worst_ratio"].get<double>());
  for (const double sf : {1.0, 2.0}) {
    j["criterion"] = sf == 1.0 ? criterion : criterion.substr(0, at) + "safety factor 2 on each";
    char margin[64];
    std::snprintf(margin, sizeof margin, "margin %.1f %% (safety factor %g)", 100.0 * (1.0 - sf * ratio), sf);
    INFO(margin);
    CHECK(Render(ReportKind::kTrajectory, j.dump()).find(margin) != std::string::npos);
  }
}

TEST_CASE("A speed-limit table with a row that has no safe speed is UNSAFE", "[report][html]") {
  // The JSON of a run whose lightest robot were unsafe at every speed searched: its row as
  // speed_limit_json writes one (status no-safe-value, the limit null).
  Json j = Json::parse(ReadFile("speed_limit_safe.json"));
  j["rows"][1]["status"] = "no-safe-value";
  j["rows"][1]["max_safe_speed_m_per_s"] = nullptr;
  const Banner banner = BannerOf(Render(ReportKind::kSpeedLimit, j.dump(2)));
  CHECK(banner.data_safe == "false");
  CHECK(banner.word == "UNSAFE");
}

TEST_CASE("Runs without a verdict, non-objects and results without provenance are refused", "[report][html]") {
  const auto refuse = [](ReportKind kind, const std::string& json, const char* says) {
    ReportContent content;
    content.kind = kind;
    content.result_json = json;
    INFO(json.substr(0, 80));
    CHECK_THROWS_AS(covopt::report::HtmlReport(content), std::invalid_argument);
    CHECK_THROWS_WITH(covopt::report::HtmlReport(content), Catch::Contains(says));
  };
  refuse(ReportKind::kSimulate, "[1, 2]", "must be the JSON object");
  refuse(ReportKind::kSimulate, "not json", "not JSON");
  refuse(ReportKind::kSimulate, ReadFile("simulate_safe.json"), "no \"provenance\"");
  // Each kind refuses a result of the wrong kind, or one whose run failed.
  refuse(ReportKind::kOptimize, WithProvenance(ReadFile("simulate_safe.json")), "without a verdict");
  refuse(ReportKind::kSpeedLimit, WithProvenance(ReadFile("simulate_safe.json")), "without a verdict");
  refuse(ReportKind::kAudit, WithProvenance(ReadFile("simulate_safe.json")), "without a verdict");
  refuse(ReportKind::kSimulate, WithProvenance(ReadFile("speed_limit_safe.json")), "without a verdict");
  Json failed_simulation = Json::parse(ReadFile("simulate_safe.json"));
  failed_simulation["solver"]["status"] = "too-much-work";
  refuse(ReportKind::kSimulate, WithProvenance(failed_simulation.dump()), "solver status 'too-much-work'");
  Json failed = Json::parse(ReadFile("trajectory_safe.json"));
  failed["status"] = "evaluation-failed";
  refuse(ReportKind::kTrajectory, WithProvenance(failed.dump()), "evaluation-failed");
  Json failed_row = Json::parse(ReadFile("speed_limit_safe.json"));
  failed_row["rows"][0]["status"] = "evaluation-failed";
  refuse(ReportKind::kSpeedLimit, WithProvenance(failed_row.dump()), "evaluation failed");
  Json audit = Json::parse(ReadFile("audit_safe.json"));
  audit["status"] = "evaluation-failed";
  refuse(ReportKind::kAudit, WithProvenance(audit.dump()), "evaluation-failed");
  Json provenance_not_object = Json::parse(ReadFile("simulate_safe.json"));
  provenance_not_object["provenance"] = "covopt";
  refuse(ReportKind::kSimulate, provenance_not_object.dump(), "no \"provenance\"");
  // A chart that is not SVG.
  ReportContent content;
  content.kind = ReportKind::kSimulate;
  content.result_json = WithProvenance(ReadFile("simulate_safe.json"));
  content.charts = {{"t", "c", "PNG\x89 not an svg"}};
  CHECK_THROWS_WITH(covopt::report::HtmlReport(content), Catch::Contains("chart 1: no <svg>"));
}
