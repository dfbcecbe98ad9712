// The report for the risk-assessment file (covopt/report/html_report.hpp), laid out from the
// result's summary (covopt/core/result_summary.hpp, its JSON report/summary_json.hpp). Checked:
// the first page's state word, sentence and colour for each state (SAFE, MARGINAL below the
// report's threshold, UNSAFE, LIMITS); the margin, threshold and governing ratio with their JSON
// texts; the governing case, what was judged, the covering, the robot; the sign-off fields,
// escaped, and two signature lines; the inputs as tables by group with units and sources, the
// SI value kept exactly; the appendix modes and the collapsed JSON; nothing read from prose;
// charts inlined as well-formed SVG with ids prefixed apart; no script and no external
// reference; results without a summary, of another kind, not evaluated or without provenance
// are refused. The fixtures under tests/report/data (make-fixtures.sh) are real results of
// every kind and mode.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <covopt/core/result_summary.hpp>
#include <covopt/core/verdict.hpp>
#include <covopt/report/html_report.hpp>
#include <covopt/report/provenance.hpp>
#include <covopt/report/summary_json.hpp>

namespace {

using covopt::ResultSummary;
using covopt::report::ReportAppendix;
using covopt::report::ReportContent;
using covopt::report::ReportInfo;
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

std::string Render(ReportKind kind, const std::string& json, std::vector<covopt::report::SvgChart> charts = {},
                   const ReportInfo& info = {}) {
  ReportContent content;
  content.kind = kind;
  content.result_json = WithProvenance(json);
  content.charts = std::move(charts);
  content.info = info;
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

/// A verdict of one criterion: value against limit with safety factor `sf`.
covopt::Verdict OneCriterion(const char* name, const char* unit, double value, double limit, double sf = 1.0) {
  covopt::Verdict v;
  v.safety_factor = sf;
  v.Add(name, covopt::CriterionPart::kInjury, unit, value, limit, "Park et al. 2011");
  return v;
}

/// A head verdict whose contusion ratio is `contusion_ratio` (laceration 0.3), finished.
ResultSummary HeadSummary(double contusion_ratio, double sf = 1.0) {
  covopt::Verdict v = OneCriterion("laceration", "Pa", 0.3e6, 1e6, sf);
  v.Add("contusion", covopt::CriterionPart::kInjury, "J/m2", contusion_ratio * 25200.0, 25200.0, "Park et al. 2011");
  ResultSummary s;
  s.command = "simulate";
  s.AddVerdict("head (frontal)", v, "hertz", "within");
  s.scope = {"Criteria: no laceration and no contusion (Park et al. 2011's skin limits)."};
  s.governing_case = "the impact at 2 m/s";
  s.covering = {.present = true, .material = "elastomer Shore A60", .thickness_m = 0.02, .law = "hertz",
                .validity = "within", .validity_ratio = 0.4};
  s.robot = {.model_file = "", .motion = "", .joints = {}, .reflected_mass_kg = 10.0, .payload_kg = 0.0,
             .speed_m_per_s = 2.0};
  s.Finish();
  return s;
}

/// A result JSON holding `summary` and `extra` keys, with its provenance.
std::string ResultJson(const ResultSummary& summary, Json extra = Json::object()) {
  Json j = Json::object();
  j["summary"] = Json::parse(covopt::report::SummaryJson(summary));
  for (const auto& [key, value] : extra.items()) j[key] = value;
  return WithProvenance(j.dump());
}

/// The first page's verdict: state, data-safe, word, sentence, margin and threshold texts.
struct Banner {
  std::string state, safe, word, sentence, margin, threshold, ratio;
};

Banner BannerOf(const std::string& html) {
  std::smatch m;
  Banner b;
  REQUIRE(std::regex_search(html, m, std::regex(R"re(<section id="verdict" class="verdict ([a-z]+)" data-state="([a-z]+)" data-safe="([a-z]+)">\s*<div class="word">([^<]*)</div>\s*<div class="sentence">([^<]*)</div>)re")));
  CHECK(m[1] == m[2]);
  b.state = m[2];
  b.safe = m[3];
  b.word = m[4];
  b.sentence = Unescape(m[5]);
  REQUIRE(std::regex_search(html, m, std::regex(R"re(<span id="margin" data-value="([^"]*)">)re")));
  b.margin = m[1];
  REQUIRE(std::regex_search(html, m, std::regex(R"re(<span id="margin-threshold" data-value="([^"]*)">)re")));
  b.threshold = m[1];
  REQUIRE(std::regex_search(html, m, std::regex(R"re(<span id="governing-ratio" data-value="([^"]*)">)re")));
  b.ratio = m[1];
  return b;
}

/// The text of the element with id `id` up to its section's end.
std::string Section(const std::string& html, const std::string& id) {
  const std::size_t at = html.find("<section id=\"" + id + "\"");
  REQUIRE(at != std::string::npos);
  return html.substr(at, html.find("</section>", at) - at);
}

/// Every inputs table's rows: group, quantity, value text, data-key, data-value, unit, source.
struct InputRow {
  std::string group, quantity, value, key, data_value, unit, source;
};

std::vector<InputRow> InputRows(const std::string& html) {
  std::vector<InputRow> rows;
  static const std::regex kTable(R"re(<table class="inputs" data-group="([a-z]+)">([\s\S]*?)</table>)re");
  static const std::regex kRow(
      R"re(<tr><td>([^<]*)</td><td class="num" data-key="([^"]*)" data-value="([^"]*)">([^<]*)</td><td class="unit">([^<]*)</td><td class="source">([^<]*)</td></tr>)re");
  for (auto t = std::sregex_iterator(html.begin(), html.end(), kTable); t != std::sregex_iterator(); ++t) {
    const std::string body = (*t)[2];
    for (auto r = std::sregex_iterator(body.begin(), body.end(), kRow); r != std::sregex_iterator(); ++r) {
      rows.push_back({(*t)[1], Unescape((*r)[1]), Unescape((*r)[4]), Unescape((*r)[2]), Unescape((*r)[3]),
                      Unescape((*r)[5]), Unescape((*r)[6])});
    }
  }
  return rows;
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

TEST_CASE("SAFE reads SAFE with its margin and the threshold asked, in words and colour", "[report][html]") {
  const ResultSummary s = HeadSummary(0.58);
  const std::string html = Render(ReportKind::kSimulate, ResultJson(s));
  const Banner b = BannerOf(html);
  CHECK(b.state == "safe");
  CHECK(b.safe == "true");
  CHECK(b.word == "SAFE");
  CHECK(b.sentence == "SAFE with a margin of 42.0 % (at least 10 % asked).");
  CHECK(b.margin == Json(s.margin).dump());
  CHECK(b.threshold == "0.1");
  CHECK(b.ratio == Json(0.58 * 25200.0 / 25200.0).dump());
  CHECK(html.find(".verdict.safe { color: #0b5a23") != std::string::npos);
  CHECK(html.find("<title>covopt simulate report: SAFE</title>") != std::string::npos);
}

TEST_CASE("A safe verdict with a margin below the threshold reads MARGINAL, the threshold the report's", "[report][html]") {
  const ResultSummary s = HeadSummary(0.998);
  REQUIRE(s.safe);
  const Banner b = BannerOf(Render(ReportKind::kSimulate, ResultJson(s)));
  CHECK(b.state == "marginal");
  CHECK(b.safe == "true");
  CHECK(b.word == "MARGINAL");
  CHECK(b.sentence == "MARGINAL: safe, but the margin 0.2 % is below the 10 % asked.");
  // The user's threshold restates it: 0.1 % asked makes 0.2 % SAFE, 50 % makes 42 % MARGINAL.
  ReportInfo low;
  low.margin_threshold = 0.001;
  const Banner safe = BannerOf(Render(ReportKind::kSimulate, ResultJson(s), {}, low));
  CHECK(safe.word == "SAFE");
  CHECK(safe.sentence == "SAFE with a margin of 0.2 % (at least 0.1 % asked).");
  CHECK(safe.threshold == "0.001");
  ReportInfo high;
  high.margin_threshold = 0.5;
  const Banner marginal = BannerOf(Render(ReportKind::kSimulate, ResultJson(HeadSummary(0.58)), {}, high));
  CHECK(marginal.word == "MARGINAL");
  CHECK(marginal.sentence == "MARGINAL: safe, but the margin 42.0 % is below the 50 % asked.");
}

TEST_CASE("UNSAFE names what fails, LIMITS and a case without a safe value read as such", "[report][html]") {
  const Banner unsafe = BannerOf(Render(ReportKind::kSimulate, ResultJson(HeadSummary(1.344))));
  CHECK(unsafe.state == "unsafe");
  CHECK(unsafe.safe == "false");
  CHECK(unsafe.word == "UNSAFE");
  CHECK(unsafe.sentence == "UNSAFE: fails head (frontal) contusion (margin -34.4 %).");

  ResultSummary limits;
  limits.kind = ResultSummary::Kind::kLimits;
  limits.command = "speed-limit";
  for (const double mass : {1.0, 5.0}) {
    limits.limits.push_back({.target = "head (frontal), robot mass " + std::to_string(static_cast<int>(mass)) + " kg",
                             .quantity = "max safe speed", .unit = "m/s", .value = 2.0 / mass,
                             .binding_criterion = "contusion", .law = "hertz", .validity = "within", .note = ""});
  }
  limits.Finish();
  const std::string html = Render(ReportKind::kSpeedLimit, ResultJson(limits));
  const Banner b = BannerOf(html);
  CHECK(b.state == "limits");
  CHECK(b.word == "LIMITS");
  CHECK(b.safe == "true");
  CHECK(b.margin == "null");
  CHECK(b.sentence == "LIMITS: a table of the largest safe values, one per case (2); the robot is safe at or below "
                      "each row's value.");
  CHECK(html.find(".verdict.limits { color: #0d3c78") != std::string::npos);
  CHECK(html.find("<td class=\"num\">0.4</td><td class=\"unit\">m/s</td><td>contusion</td>") != std::string::npos);
  limits.limits[1].value = 0.0;
  limits.Finish();
  const Banner none = BannerOf(Render(ReportKind::kSpeedLimit, ResultJson(limits)));
  CHECK(none.word == "UNSAFE");
  CHECK(none.sentence == "UNSAFE: no safe value for head (frontal), robot mass 5 kg.");
}

TEST_CASE("Page one holds, in order, the header, verdict, governing case, what was judged, covering, robot and sign-off",
          "[report][html]") {
  const std::string html = Render(ReportKind::kSimulate, ResultJson(HeadSummary(0.58)));
  const std::size_t page = html.find("<section id=\"page-one\">");
  REQUIRE(page != std::string::npos);
  std::size_t last = page;
  for (const char* part : {"<header>", "<section id=\"verdict\"", "<section id=\"governing-case\">",
                           "<section id=\"judged\">", "<section id=\"covering\">", "<section id=\"robot\">",
                           "<section id=\"sign-off\">"}) {
    INFO(part);
    const std::size_t at = html.find(part);
    CHECK(at > last);
    CHECK(at != std::string::npos);
    last = at;
  }
  CHECK(html.find("<h2>", page) > last);  // the rest of the report follows the first page
  CHECK(Section(html, "governing-case").find("<dd>head (frontal)</dd>") != std::string::npos);
  CHECK(Section(html, "governing-case").find("<dd>contusion</dd>") != std::string::npos);
  CHECK(Section(html, "governing-case").find("<dd>the impact at 2 m/s</dd>") != std::string::npos);
  CHECK(Section(html, "judged").find("<dd>Park et al. 2011</dd>") != std::string::npos);
  CHECK(Section(html, "covering").find("<dd>elastomer Shore A60</dd>") != std::string::npos);
  CHECK(Section(html, "covering").find("<dd>20 mm</dd>") != std::string::npos);
  CHECK(Section(html, "robot").find("<dd>10 kg</dd>") != std::string::npos);
  CHECK(html.find("#page-one { break-after: page;") != std::string::npos);
}

TEST_CASE("The sign-off block prints the fields escaped, the provenance's date, version and digests, and two lines",
          "[report][html]") {
  ReportInfo info;
  info.project = "Cell <7> & \"line\"";
  info.cell = "press 'B'";
  info.assessor = "A. Assessor";
  info.note = "first\nsecond";
  const std::string csv = std::string(COVOPT_REPORT_TEST_DATA) + "/fr3_pick21.csv";
  const std::vector<covopt::report::InputFile> files = {{"trajectory", csv}};
  const covopt::report::Provenance p = covopt::report::MakeProvenance("covopt test", files);
  const std::string json = covopt::report::WithProvenance(ResultJson(HeadSummary(0.5)), p);
  const std::string html = Render(ReportKind::kSimulate, json, {}, info);
  const std::string block = Section(html, "sign-off");
  CHECK(block.find("<dd data-field=\"project\">Cell &lt;7&gt; &amp; &quot;line&quot;</dd>") != std::string::npos);
  CHECK(block.find("<dd data-field=\"cell\">press &#39;B&#39;</dd>") != std::string::npos);
  CHECK(block.find("<dd data-field=\"assessor\">A. Assessor</dd>") != std::string::npos);
  CHECK(block.find("<dd data-field=\"note\">first\nsecond</dd>") != std::string::npos);
  CHECK(block.find("<dd data-field=\"date\">" + p.date_utc + "</dd>") != std::string::npos);
  CHECK(block.find(p.commit) != std::string::npos);
  CHECK(block.find(p.inputs.at(0).sha256) != std::string::npos);
  CHECK(block.find("<div class=\"signature-line\" data-role=\"assessor\">") != std::string::npos);
  CHECK(block.find("<div class=\"signature-line\" data-role=\"approver\">") != std::string::npos);
  CHECK(html.find("Cell <7>") == std::string::npos);
  // Fields not given are blank lines to fill in, never left out.
  const std::string blank = Section(Render(ReportKind::kSimulate, ResultJson(HeadSummary(0.5))), "sign-off");
  CHECK(blank.find("<dd data-field=\"assessor\" class=\"blank\"></dd>") != std::string::npos);
  // A field beyond what ReportInfo allows is refused.
  ReportInfo bad;
  bad.margin_threshold = 1.5;
  CHECK_THROWS_AS(Render(ReportKind::kSimulate, ResultJson(HeadSummary(0.5)), {}, bad), std::invalid_argument);
}

TEST_CASE("The inputs are tables by group with the CLI's units, sources and the exact SI value", "[report][html]") {
  const Json extra = {
      {"scene",
       {{"robot", {{"mass_kg", 5.0}, {"speed_m_per_s", 1.5}}},
        {"covering", {{"material", "elastomer Shore A60"}, {"thickness_m", 0.02}, {"youngs_modulus_Pa", 2.5e6}}},
        {"head", {{"radius_m", 0.08}}},
        {"model", {{"exponent_covering_bone", 1.8}}}}},
      {"limits", {{"contusion_J_per_m2", 25200.0}}},
      {"input_sources", {{"scene.robot.mass_kg", "flag --robot-mass"}, {"scene.covering.thickness_m", "scene file s.toml"},
                         {"scene.covering.material", "catalog"}}}};
  const std::vector<InputRow> rows = InputRows(Render(ReportKind::kSimulate, ResultJson(HeadSummary(0.5), extra)));
  const auto find = [&](const std::string& key) {
    const auto it = std::find_if(rows.begin(), rows.end(), [&](const InputRow& r) { return r.key == key; });
    REQUIRE(it != rows.end());
    return *it;
  };
  const InputRow mass = find("scene.robot.mass_kg");
  CHECK(mass.group == "robot");
  CHECK(mass.quantity == "robot mass");
  CHECK(mass.value == "5");
  CHECK(mass.unit == "kg");
  CHECK(mass.source == "flag --robot-mass");
  const InputRow thickness = find("scene.covering.thickness_m");
  CHECK(thickness.group == "covering");
  CHECK(thickness.value == "20");
  CHECK(thickness.unit == "mm");
  CHECK(thickness.data_value == "0.02");
  CHECK(thickness.source == "scene file s.toml");
  const InputRow material = find("scene.covering.material");
  CHECK(material.unit == "text");
  CHECK(material.source == "catalog");
  const InputRow modulus = find("scene.covering.youngs_modulus_Pa");
  CHECK(modulus.value == "2.5");
  CHECK(modulus.unit == "MPa");
  CHECK(modulus.source == "—");
  CHECK(find("scene.head.radius_m").group == "human");
  CHECK(find("scene.model.exponent_covering_bone").group == "solver");
  CHECK(find("scene.model.exponent_covering_bone").unit == "-");
  CHECK(find("limits.contusion_J_per_m2").group == "criteria");
  CHECK(find("limits.contusion_J_per_m2").unit == "J/cm²");
  CHECK(find("limits.contusion_J_per_m2").value == "2.52");
  CHECK(rows.size() == 8);
  for (const InputRow& r : rows) CHECK_FALSE(r.unit.empty());
}

TEST_CASE("The appendix holds nothing, the summary or every value, the full JSON is always there, collapsed",
          "[report][html]") {
  const Json extra = {{"scene", {{"robot", {{"mass_kg", 5.0}}}}},
                      {"status", "safe"},
                      {"samples", Json::array({{{"t_s", 0.125}, {"nested", {{"deep_value_m", 0.0421}}}}})}};
  const std::string json = ResultJson(HeadSummary(0.5), extra);
  const auto render = [&](ReportAppendix appendix) {
    ReportInfo info;
    info.appendix = appendix;
    return Render(ReportKind::kSimulate, json, {}, info);
  };
  const std::string none = render(ReportAppendix::kNone);
  const std::string summary = render(ReportAppendix::kSummary);
  const std::string full = render(ReportAppendix::kFull);
  CHECK(none.find("<section id=\"appendix\" data-appendix=\"none\">\n</section>") != std::string::npos);
  CHECK(summary.find("<section id=\"appendix\" data-appendix=\"summary\">") != std::string::npos);
  CHECK(full.find("<section id=\"appendix\" data-appendix=\"full\">") != std::string::npos);
  // The summary appendix: the result's scalar values (not the rows the body shows); the full one: every value.
  const std::string summary_part = Section(summary, "appendix");
  CHECK(summary_part.find("<td class=\"key\">status</td><td>safe</td>") != std::string::npos);
  CHECK(summary_part.find("head (frontal)") == std::string::npos);
  CHECK(summary_part.find("0.0421") == std::string::npos);
  CHECK(Section(full, "appendix").find("0.0421") != std::string::npos);
  for (const std::string* html : {&none, &summary, &full}) {
    const std::size_t details = html->find("<details id=\"result-json\">");
    REQUIRE(details != std::string::npos);
    CHECK(html->find("open", details) > html->find(">", details));  // collapsed
    CHECK(html->find("&quot;deep_value_m&quot;: 0.0421", details) != std::string::npos);
  }
  CHECK(none.find("details#result-json { display: none; }") != std::string::npos);  // not printed
}

TEST_CASE("Many rows: the body shows the governing, the failed and the largest, the summary appendix all", "[report][html]") {
  ResultSummary s;
  s.command = "simulate";
  for (int i = 0; i < 30; ++i) {  // region 3 the one failed row
    s.AddVerdict("region " + std::to_string(i), OneCriterion("force", "N", i == 3 ? 1100.0 : 10.0 * i, 1000.0), "hertz",
                 "within");
  }
  s.Finish();
  const std::string html = Render(ReportKind::kSimulate, ResultJson(s));
  const std::string body = html.substr(0, html.find("<section id=\"appendix\""));
  const std::string appendix = Section(html, "appendix");
  CHECK(body.find("24 of 30 rows") != std::string::npos);
  // Page one names six targets and how many more, so it stays one page.
  CHECK(Section(html, "judged").find("region 5 and 24 more (all in the result&#39;s JSON)") != std::string::npos);
  CHECK(body.find("<tr class=\"binding\"><td>region 3</td>") != std::string::npos);
  for (int i = 0; i < 30; ++i) {
    const std::string cell = "<td>region " + std::to_string(i) + "</td>";
    INFO(cell);
    CHECK(appendix.find(cell) != std::string::npos);
    // The smallest ratios (regions 0 to 5 but the failed 3) are left to the appendix.
    CHECK((body.find(cell) == std::string::npos) == (i < 7 && i != 3));
  }
}

TEST_CASE("No renderer reads prose: the safety factor and verdict are the summary's, whatever the text says",
          "[report][html]") {
  // The summary's safety factor 2 doubles every ratio's weight: contusion 0.4 leaves 20 % margin. The
  // result's texts say otherwise; the report prints the summary's.
  const Json extra = {{"criterion", {{"description", "safety factor 1 on each"}}},
                      {"message", "SAFE with a margin of 60 %"},
                      {"safe", false}};
  const std::string html = Render(ReportKind::kSimulate, ResultJson(HeadSummary(0.4, 2.0), extra));
  const Banner b = BannerOf(html);
  CHECK(b.word == "SAFE");
  CHECK(b.sentence == "SAFE with a margin of 20.0 % (at least 10 % asked).");
  CHECK(Section(html, "verdict").find("safety factor 2") != std::string::npos);
  CHECK(Section(html, "judged").find("<dd>2 (each limit derated to limit / SF)</dd>") != std::string::npos);
}

TEST_CASE("The verdict rows carry units, ratios, margins and the governing mark", "[report][html]") {
  const std::string html = Render(ReportKind::kSimulate, ResultJson(HeadSummary(1.344)));
  // contusion 1.344 × 2.52 J/cm² = 3.387 J/cm², limit 2.52, margin -34.4 %, failing and governing.
  CHECK(html.find("<tr class=\"binding\"><td>head (frontal)</td><td>contusion</td><td class=\"num\">3.387</td>"
                  "<td class=\"num\">2.52</td><td class=\"num\">2.52</td><td class=\"unit\">J/cm²</td>"
                  "<td class=\"num\">1.344</td><td class=\"num\">-34.4 %</td><td class=\"bad\">UNSAFE, governs</td>") !=
        std::string::npos);
  CHECK(html.find("<td>laceration</td><td class=\"num\">0.3</td><td class=\"num\">1</td><td class=\"num\">1</td>"
                  "<td class=\"unit\">MPa</td>") != std::string::npos);
}

TEST_CASE("Two gnuplot charts inline as well-formed SVG with ids prefixed apart and references kept", "[report][html]") {
  const std::vector<covopt::report::SvgChart> charts = TwoGnuplotCharts();
  // The raw charts clash: gnuplot names its ids the same in every file.
  const std::vector<std::string> first = Ids(charts[0].svg);
  const std::vector<std::string> second = Ids(charts[1].svg);
  REQUIRE(std::find(second.begin(), second.end(), "gnuplot_canvas") != second.end());
  REQUIRE(std::find(first.begin(), first.end(), "gnuplot_canvas") != first.end());

  const std::string html = Render(ReportKind::kSimulate, ResultJson(HeadSummary(1.2)), charts);
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

TEST_CASE("Every text from the summary, the JSON and the charts is escaped", "[report][html]") {
  ResultSummary s = HeadSummary(0.5);
  s.covering.material = "<script>alert('x')</script> & \"co\"";
  s.rows[0].note = "<img src=x onerror=alert(1)>";
  const Json extra = {{"warnings", {"<img src=y>"}}, {"unknown_extra", {{"<b>key</b>", "</td></tr></table><script>"}}},
                      {"scene", {{"covering", {{"material", "<script>m</script>"}}}}}};
  ReportInfo info;
  info.appendix = ReportAppendix::kFull;
  const std::vector<covopt::report::SvgChart> charts = {{"<script>t</script>", "<i>caption</i>", ReadFile("gnuplot_lines.svg")}};
  const std::string html = Render(ReportKind::kSimulate, ResultJson(s, extra), charts, info);
  CHECK(html.find("<script") == std::string::npos);
  CHECK(html.find("<img") == std::string::npos);
  CHECK(html.find("<b>key</b>") == std::string::npos);
  CHECK(html.find("&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;co&quot;") != std::string::npos);
  CHECK(html.find("&lt;i&gt;caption&lt;/i&gt;") != std::string::npos);
  CHECK(html.find("&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;&lt;script&gt;") != std::string::npos);
  CHECK(DataKeys(html).find("scene.covering.material")->second == "<script>m</script>");
}

TEST_CASE("The report fetches nothing and runs nothing", "[report][html]") {
  {
    const std::string html = Render(ReportKind::kSimulate, ResultJson(HeadSummary(0.5)), TwoGnuplotCharts());
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
  CHECK_THROWS_WITH(Render(ReportKind::kSimulate, ResultJson(HeadSummary(0.5)), {{"t", "c", external}}),
                    Catch::Contains("chart 1") && Catch::Contains("external"));
  std::string scripted = ReadFile("gnuplot_lines.svg");
  scripted.insert(scripted.find("<g "), "<script type=\"text/javascript\">alert(1)</script><g onload=\"alert(2)\"></g>");
  const std::string html = Render(ReportKind::kSimulate, ResultJson(HeadSummary(0.5)), {{"t", "c", scripted}});
  CHECK(html.find("alert") == std::string::npos);
  CheckWellFormedXml(SvgBlocks(html).at(0));
}

TEST_CASE("Results without a summary, of another kind, not evaluated, not objects or without provenance are refused",
          "[report][html]") {
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
  Json no_provenance = Json::parse(ResultJson(HeadSummary(0.5)));
  no_provenance.erase("provenance");
  refuse(ReportKind::kSimulate, no_provenance.dump(), "no \"provenance\"");
  no_provenance["provenance"] = "covopt";
  refuse(ReportKind::kSimulate, no_provenance.dump(), "no \"provenance\"");
  refuse(ReportKind::kSimulate, WithProvenance(R"({"safe": true})"), "has no summary");
  refuse(ReportKind::kOptimize, ResultJson(HeadSummary(0.5)), "the result is of covopt simulate, not of covopt optimize");
  ResultSummary failed = HeadSummary(0.5);
  failed.evaluated = false;
  failed.Finish();
  refuse(ReportKind::kSimulate, ResultJson(failed), "without a verdict");
  ReportContent content;
  content.kind = ReportKind::kSimulate;
  content.result_json = ResultJson(HeadSummary(0.5));
  content.charts = {{"t", "c", "PNG\x89 not an svg"}};
  CHECK_THROWS_WITH(covopt::report::HtmlReport(content), Catch::Contains("chart 1: no <svg>"));
}

namespace {

/// A real result of each kind and mode (make-fixtures.sh) and its input objects.
struct Fixture {
  const char* file;
  ReportKind kind;
  std::vector<const char*> inputs;
};

std::vector<Fixture> Fixtures() {
  const ReportKind sim = ReportKind::kSimulate, opt = ReportKind::kOptimize, lim = ReportKind::kSpeedLimit,
                   traj = ReportKind::kTrajectory, audit = ReportKind::kAudit;
  return {
      {"simulate_safe.json", sim, {"scene"}},
      {"simulate_unsafe.json", sim, {"scene"}},
      {"simulate_ranges_unsafe.json", sim, {"scene", "uncertain_inputs"}},
      {"simulate_body_safe.json", sim, {"scene", "safety_factor"}},
      {"simulate_body_unsafe.json", sim, {"scene", "safety_factor"}},
      {"optimize_safe.json", opt, {"scene", "limits", "design_space"}},
      {"optimize_unsafe.json", opt, {"scene", "limits", "design_space"}},
      {"optimize_robust_safe.json", opt, {"uncertain_inputs", "limits"}},
      {"optimize_probability_safe.json", opt, {"uncertain_inputs", "max_probability", "samples", "seed"}},
      {"optimize_body_safe.json", opt, {"scene", "speed_m_per_s", "safety_factor"}},
      {"optimize_body_unsafe.json", opt, {"scene", "speed_m_per_s", "safety_factor"}},
      {"speed_limit_safe.json", lim, {"scene", "limits", "search_limit", "solve_for"}},
      {"speed_limit_body_safe.json", lim, {"scene", "solve_for"}},
      {"trajectory_safe.json", traj, {"scene", "limits", "joint_names"}},
      {"trajectory_unsafe.json", traj, {"scene", "limits", "joint_names"}},
      {"trajectory_body_safe.json", traj, {"scene", "regions"}},
      {"trajectory_body_unsafe.json", traj, {"scene", "regions"}},
      {"audit_safe.json", audit, {"robot", "coverings", "contact_area_m2", "surface"}},
      {"audit_unsafe.json", audit, {"robot", "coverings", "contact_area_m2", "surface"}},
  };
}

}  // namespace

TEST_CASE("Every real result renders its summary's verdict, governing ratio and every input leaf", "[report][html]") {
  for (const Fixture& f : Fixtures()) {
    INFO(f.file);
    const std::string json = ReadFile(f.file);
    const Json j = Json::parse(json);
    const Json& summary = j.at("summary");
    const std::string html = Render(f.kind, json, TwoGnuplotCharts());
    const Banner b = BannerOf(html);
    CHECK(b.state == summary.at("state").get<std::string>());  // the default threshold is the JSON's
    CHECK(b.safe == summary.at("safe").dump());
    CHECK(b.ratio == summary.at("governing").at("ratio").dump());
    CHECK(b.margin == (summary.at("kind") == "limits" ? "null" : summary.at("margin").dump()));
    // The result's own verdict says the same.
    if (j.contains("safe") && j["safe"].is_boolean()) CHECK(j["safe"] == summary["safe"]);
    if (j.contains("status") && j["status"] != "at-rest") CHECK((j["status"] == "safe") == summary["safe"].get<bool>());
    // Every input leaf, with its exact JSON text, once, in an inputs table with a unit.
    const std::vector<InputRow> rows = InputRows(html);
    std::vector<std::pair<std::string, std::string>> leaves;
    for (const char* input : f.inputs) {
      REQUIRE(j.contains(input));
      Leaves(j[input], input, leaves);
    }
    for (const auto& [path, text] : leaves) {
      INFO(path << " = " << text);
      const auto n = std::count_if(rows.begin(), rows.end(), [&](const InputRow& r) { return r.key == path; });
      REQUIRE(n == 1);
      const InputRow& r = *std::find_if(rows.begin(), rows.end(), [&](const InputRow& r) { return r.key == path; });
      CHECK(r.data_value == text);
      CHECK_FALSE(r.unit.empty());
      CHECK_FALSE(r.source.empty());
    }
    // No script, no external reference, the page-one sections once each.
    CHECK(html.find("<script") == std::string::npos);
    for (const char* id : {"page-one", "verdict", "governing-case", "judged", "covering", "robot", "sign-off", "appendix"}) {
      INFO(id);
      const std::string tag = std::string("<section id=\"") + id + "\"";
      CHECK(html.find(tag) != std::string::npos);
      CHECK(html.find(tag, html.find(tag) + 1) == std::string::npos);
    }
  }
}
