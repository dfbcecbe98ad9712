#pragma once
/// @file result_summary.hpp
/// The summary of a result: made once, by the library, from the result (never from its text),
/// and printed by every front end as it is: the JSON's "summary" object, the CLI's text, Python's
/// repr and the report's first page. No renderer parses prose or re-derives a verdict: each reads
/// these rows.
///
/// A summary is of one of two kinds:
///   - a verdict (simulate, optimize, robot --trajectory, audit, every body-region mode): the
///     verdict rows of every target judged (a target's Verdict, core/verdict.hpp, row by row),
///     the governing row, the margin and its state (SAFE, MARGINAL, UNSAFE);
///   - limits (speed-limit): a table of largest safe values (a speed or a mass per case), each
///     with the criterion that binds it; the state is kLimits, or kUnsafe when a case has no
///     safe value at all.

#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/compressive_curve.hpp"
#include "covopt/core/head_area.hpp"
#include "covopt/core/verdict.hpp"

namespace covopt {

/// The three states of a verdict, and the two that are not one.
enum class VerdictState {
  kSafe,          ///< safe, with a margin >= the margin threshold
  kMarginal,      ///< safe, with a margin below the margin threshold
  kUnsafe,        ///< not safe (an injury criterion or a design rule fails), or a case without a safe value
  kLimits,        ///< a table of limits (speed-limit): safe at or below each row's value
  kNotEvaluated,  ///< the result could not be computed: no answer (never reported as one)
};
/// "safe", "marginal", "unsafe", "limits", "not-evaluated".
std::string_view ToString(VerdictState state) noexcept;
/// The word a reader sees: "SAFE", "MARGINAL", "UNSAFE", "LIMITS", "NOT EVALUATED".
std::string_view StateWord(VerdictState state) noexcept;

/// The default margin threshold [-]: a SAFE verdict with less margin than 10 % is MARGINAL.
inline constexpr double kDefaultMarginThreshold = 0.10;

/// The state of a verdict: not evaluated; unsafe; safe with margin >= threshold (SAFE); else
/// MARGINAL. `margin` [-] is 1 − SF × governing ratio; `threshold` [-] in [0, 1).
VerdictState VerdictStateOf(bool evaluated, bool safe, double margin, double threshold) noexcept;

/// One verdict row: one criterion of one target.
struct SummaryRow {
  std::string target;     ///< what is judged: "head (frontal)", "chest (sternum)", "fr3_link7 × hand"
  std::string criterion;  ///< Criterion::name: "contusion", "force", "law-validity", ...
  CriterionPart part = CriterionPart::kInjury;
  std::string unit;       ///< the SI unit of value and limits: "Pa", "J/m2", "N", "1"
  double value = 0.0;          ///< [unit]
  double limit = 0.0;          ///< [unit]; NaN when unknown
  double derated_limit = 0.0;  ///< limit / SF [unit]
  double ratio = 0.0;          ///< value / limit [-]
  double margin = 0.0;         ///< 1 − SF × ratio [-]
  bool counted = true;         ///< counts in the verdict (else reported only)
  bool passed = true;
  bool binding = false;        ///< the governing row of the whole summary
  std::string law;        ///< the covering's law: "foam", "hertz", "bare" (no covering)
  std::string validity;   ///< "within", or why not ("beyond the curve's last point"); "" for no covering
  std::string source;     ///< whose limit: "Park et al. 2011", "ISO/TS 15066:2016 Table A.2", ...
  std::string note;       ///< why not counted, or what else a reader must know; "" else
};

/// One row of a limits summary (speed-limit): the largest safe value of one case.
struct LimitRow {
  std::string target;     ///< the case: "head (frontal), robot mass 5 kg", "chest (sternum)"
  std::string quantity;   ///< "max safe speed", "max safe mass"
  std::string unit;       ///< "m/s", "kg"
  double value = 0.0;     ///< [unit]; 0 when no value is safe; +inf when no limit was found below the search limit
  std::string binding_criterion;  ///< the criterion that binds at the value ("contusion", "force", ...)
  std::string law;
  std::string validity;
  std::string note;       ///< e.g. "no safe value", "not limited below the search limit 10 m/s"
};

/// The covering the verdict is about (absent for a bare robot).
struct CoveringSummary {
  bool present = false;
  std::string material;   ///< the catalog name, or "" when given by its modulus
  double thickness_m = 0.0;
  std::string law;        ///< "foam", "hertz"
  std::string validity;   ///< "within" or why not
  double validity_ratio = 0.0;  ///< CoveringValidity::ratio [-] (1 at the edge of the law)
};

/// The robot the verdict is about, as far as the result knows it.
struct RobotSummary {
  std::string model_file;      ///< the URDF's file name; "" for a reflected mass given directly
  std::string motion;          ///< "configuration q = [...]", "program pick.csv (412 samples)", "" for none
  std::vector<std::string> joints;  ///< the joint names, when from a URDF
  double reflected_mass_kg = 0.0;   ///< the (governing case's) reflected mass [kg]; NaN when not one value
  double payload_kg = 0.0;          ///< [kg]
  double speed_m_per_s = 0.0;       ///< the (governing case's) speed [m/s]; NaN when not one value
};

/// A body-region limit table a verdict was judged on (covopt::materials::LimitTableInfo).
struct LimitTableSummary {
  std::string title;
  std::string edition;  ///< "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M"
  std::string source;   ///< "built-in" or the file's path as given
  std::string sha256;   ///< of the table's bytes, lower-case hex
};

/// The summary of one result.
struct ResultSummary {
  enum class Kind { kVerdict, kLimits };
  Kind kind = Kind::kVerdict;
  std::string command;        ///< "simulate", "optimize", "speed-limit", "robot --trajectory", "audit"
  bool evaluated = true;
  bool safe = false;
  double safety_factor = 1.0;  ///< [-]
  double margin = 0.0;         ///< the governing row's margin [-]; -inf when not evaluated
  double margin_threshold = kDefaultMarginThreshold;  ///< [-]
  VerdictState state = VerdictState::kUnsafe;

  /// The governing case: the binding row's target and criterion and its ratio, and one sentence
  /// saying where it happens ("sample 41 at t = 1.23 s, link fr3_link7 against the hand").
  std::string governing_target;
  std::string governing_criterion;
  double governing_ratio = 0.0;  ///< [-]
  std::string governing_case;

  std::vector<std::string> targets;    ///< every target judged, once each
  std::vector<std::string> criteria;   ///< every criterion applied (counted), once each
  std::vector<std::string> standards;  ///< with their editions: "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M", "Park et al. 2011"
  std::vector<LimitTableSummary> limit_tables;  ///< the body-region tables judged on (none for the head alone)
  std::vector<std::string> scope;      ///< what the verdict covers and does not, one sentence each

  CoveringSummary covering;
  RobotSummary robot;
  std::vector<SummaryRow> rows;   ///< kVerdict: every row of every target (the binding one marked)
  std::vector<LimitRow> limits;   ///< kLimits: one row per case

  /// Adds `table` to limit_tables (once: same source and digest) and its edition to standards
  /// (once).
  void AddLimitTable(const LimitTableSummary& table);
  /// Appends one row per criterion of `verdict` for `target`, with the covering's law and
  /// validity, and adds the target, its counted criteria and their sources to the lists.
  void AddVerdict(std::string_view target, const Verdict& verdict, std::string_view law,
                  std::string_view validity);
  /// Marks the binding row (the counted row with the largest ratio; the first on a tie), sets
  /// governing_*, margin, safe (evaluated and every counted row passed) and state from the rows
  /// (kVerdict), or safe and state from the limit rows (kLimits: unsafe when a row's value is 0;
  /// the case with the lowest value governs: governing_target, _criterion and _case).
  /// Call once after the rows are in (a builder may then narrow `safe`, e.g. optimize without a
  /// recommendation, and must then set `state` again with VerdictStateOf).
  void Finish();
};

// ---- The pieces every builder shares, and the impact's (simulate's) summary -----------------
// The builders of the other results live beside them: optim/summaries.hpp, audit/summary.hpp.

struct Scene;
struct ImpactResult;
struct CoveringValidity;

/// The head as a target: "head (frontal)".
std::string HeadTarget(HeadArea area);
/// The law's word in a row: "bare" without a covering, else ToString(law) ("foam", "hertz").
std::string LawWord(bool covered, CoveringLaw law);
/// The validity's words in a row: "" without a covering, "within", else the validity's note.
std::string ValidityWords(bool covered, const CoveringValidity& validity);
/// The covering of a verdict: absent when `thickness_m` is 0; `material` "" when given by its modulus.
CoveringSummary SummarizeCovering(double thickness_m, std::string_view material, CoveringLaw law,
                                  const CoveringValidity& validity);

/// The summary of one head impact (`simulate`): the head's rows at the scene's robot mass and
/// speed, with the covering of the scene (its catalog `material`, "" if none).
ResultSummary SummarizeImpact(const Scene& scene, const ImpactResult& result, const Verdict& verdict,
                              std::string_view material);

}  // namespace covopt
