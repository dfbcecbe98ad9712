// Benchmarks of the report for the risk-assessment file (covopt/report/html_report.hpp): the
// time HtmlReport adds to a command, which the issue bounds at 50 ms. Each renders the --json
// object of a real run, with its provenance block, and two gnuplot SVG charts:
//   BM_HtmlReport/<kind>      the SAFE fixture of each kind (tests/report/data, made by the CLI:
//                             simulate, optimize, speed-limit, robot --trajectory, audit)
//   BM_HtmlReportAuditFull    the largest result a command prints: the audit of the README, the
//                             FR3's whole surface along its 101-sample pick move against every
//                             transient body region and the head, with the ratio over time
//                             (about 170 kB of JSON); the audit runs once, outside the timing.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <covopt/audit/audit.hpp>
#include <covopt/report/audit_json.hpp>
#include <covopt/report/html_report.hpp>
#include <covopt/report/provenance.hpp>
#include <covopt/robot/surface.hpp>

#include "fr3_pick.hpp"

namespace {

std::string ReadData(const std::string& name) {
  std::ifstream in(std::string(COVOPT_REPORT_TEST_DATA) + "/" + name, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

covopt::report::ReportContent Content(covopt::report::ReportKind kind, const std::string& json) {
  covopt::report::ReportContent content;
  content.kind = kind;
  content.result_json =
      covopt::report::WithProvenance(json, covopt::report::MakeProvenance("covopt bench --report r.html", {}));
  content.charts = {{"points", "a gnuplot chart", ReadData("gnuplot_points.svg")},
                    {"lines", "another gnuplot chart", ReadData("gnuplot_lines.svg")}};
  return content;
}

void Render(benchmark::State& state, const covopt::report::ReportContent& content) {
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string html = covopt::report::HtmlReport(content);
    bytes = html.size();
    benchmark::DoNotOptimize(html.data());
  }
  state.counters["json_kB"] = static_cast<double>(content.result_json.size()) / 1e3;
  state.counters["html_kB"] = static_cast<double>(bytes) / 1e3;
}

void BM_HtmlReport(benchmark::State& state, covopt::report::ReportKind kind, const char* file) {
  Render(state, Content(kind, ReadData(file)));
}

BENCHMARK_CAPTURE(BM_HtmlReport, simulate, covopt::report::ReportKind::kSimulate, "simulate_safe.json")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HtmlReport, simulate_body, covopt::report::ReportKind::kSimulate, "simulate_body_unsafe.json")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HtmlReport, optimize, covopt::report::ReportKind::kOptimize, "optimize_safe.json")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HtmlReport, optimize_body, covopt::report::ReportKind::kOptimize, "optimize_body_safe.json")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HtmlReport, speed_limit, covopt::report::ReportKind::kSpeedLimit, "speed_limit_safe.json")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HtmlReport, trajectory, covopt::report::ReportKind::kTrajectory, "trajectory_safe.json")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HtmlReport, audit, covopt::report::ReportKind::kAudit, "audit_unsafe.json")
    ->Unit(benchmark::kMillisecond);

void BM_HtmlReportAuditFull(benchmark::State& state) {
  static const std::string json = [] {
    const covopt::audit::AuditSetup setup =
        Fr3AuditSetup(covopt::robot::SurfaceFromUrdfFile(kFr3Urdf, Fr3()));
    return covopt::report::AuditJson(setup, covopt::audit::Audit(setup, Pick(), {}));
  }();
  Render(state, Content(covopt::report::ReportKind::kAudit, json));
}
BENCHMARK(BM_HtmlReportAuditFull)->Unit(benchmark::kMillisecond);

}  // namespace
