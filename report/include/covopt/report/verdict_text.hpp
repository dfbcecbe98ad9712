#pragma once
/// @file verdict_text.hpp
/// The one text and JSON form of a covopt::Verdict (core/verdict.hpp), for every command that
/// prints a verdict (the CLI's text and --json, Python's dicts): the injury verdict, then the
/// covering's design rules, then the overall verdict with the governing criterion and margin.

#include <string>
#include <vector>

#include <covopt/core/verdict.hpp>

namespace covopt::report {

/// One criterion in words, e.g. "contusion UNSAFE 3.1 J/cm² against 2.52 J/cm² (derated 2.1
/// J/cm² at SF 1.2), ratio 1.23 EXCEEDED": the value, the standard's limit, the derated limit
/// (shown when SF != 1), the ratio, and EXCEEDED when SF × ratio > 1 (or the covering bottomed
/// out); "not counted: <why>" for a criterion that is reported only.
std::string CriterionText(const Criterion& criterion, double safety_factor);

/// The ratio in words with the limit it is judged against: "ratio 0.837" when within it,
/// "ratio 0.837 EXCEEDED (limit 280 N, derated 233.3 N at SF 1.2)" when SF × ratio > 1 (the
/// derated limit is shown at SF 1 too, equal to the limit).
std::string RatioText(const Criterion& criterion, double safety_factor);

/// The one-line overall verdict: "SAFE (governing contusion, ratio 0.412, margin 58.8 %,
/// safety factor 1)"; "no verdict (not evaluated)" when the contact was not computed.
std::string VerdictSummary(const Verdict& verdict);

/// The verdict block every command prints, one line each (no trailing newline): a heading per
/// part ("injury", "design rules") with its SAFE/UNSAFE, each criterion (CriterionText), and
/// "overall" with VerdictSummary. `indent` spaces start every line.
std::vector<std::string> VerdictLines(const Verdict& verdict, int indent = 2);

/// The verdict as one JSON object: safe, injury_safe, design_rules_met, evaluated, governing,
/// governing_ratio, margin, margin_percent, safety_factor, criteria (name, part, unit, value,
/// limit, derated_limit, ratio, counted, passed, source, note; non-finite numbers null) and
/// scope. `indent` as nlohmann's dump.
std::string VerdictJson(const Verdict& verdict, int indent = 2);

}  // namespace covopt::report
