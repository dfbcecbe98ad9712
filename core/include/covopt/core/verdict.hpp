#pragma once
/// @file verdict.hpp
/// The one verdict every command gives on one contact target (the head or an ISO/TS 15066 body
/// region), whatever computed it: its criteria, each with its value, the standard's limit, the
/// derated limit (limit / SF), the ratio and whether it counts and passed; the governing
/// criterion, the margin, the safety factor and the scope (docs/model.md §6, §12, §13).
///
/// A verdict has two parts, judged and printed apart:
///   - the injury verdict (kInjury): laceration and contusion (Park et al. 2011's head), the
///     force and pressure (ISO/TS 15066 Table A.2's body regions), [fracture];
///   - the covering's design rules (kDesignRule): "law-validity" (the covering's law describes
///     the contact: CoveringValidity::within; it counts always), "within its working range"
///     (the covering not fully compressed, where the travel rule is kept) and "not crushed" (a
///     material of known compressive strength).
/// safe() needs both: a bottomed-out or crushed covering is not SAFE even with every injury
/// ratio below its limit. A criterion that does not count (the paper's criterion; crushing
/// allowed; a strength that is unknown and allowed to be) is reported and never binds.
///
/// Builders (one per model) live beside the results they read: optim::HeadVerdict
/// (optim/verdicts.hpp) and the body-region judgement (optim::JudgeBodyContact).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace covopt {

/// Which part of the verdict a criterion belongs to.
enum class CriterionPart {
  kInjury,      ///< the injury verdict: the person is not hurt
  kDesignRule,  ///< the covering's design rules: it stays within its working range, uncrushed
};
/// "injury", "design-rule".
std::string_view ToString(CriterionPart part) noexcept;

/// One criterion of a verdict: value against limit. Its texts are static (string literals),
/// so a verdict is cheap to build inside the design scans.
struct Criterion {
  /// "laceration", "contusion", "fracture", "force", "pressure", "law-validity",
  /// "full-compression", "within-curve", "crush".
  std::string_view name;
  CriterionPart part = CriterionPart::kInjury;
  /// The value's and the limits' unit in SI: "Pa", "J/m2", "N", "1" (a share of the travel).
  std::string_view unit;
  double value = 0.0;          ///< the model's peak [unit]
  double limit = 0.0;          ///< the standard's (or the material's) limit [unit]; NaN: unknown
  double derated_limit = 0.0;  ///< limit / safety factor [unit]
  double ratio = 0.0;          ///< value / limit [-] (unscaled; SF × ratio <= 1 passes)
  /// The criterion counts in safe() (else it is reported only).
  bool counted = true;
  /// SF × ratio <= 1 (and for full compression: the covering not bottomed out). A criterion
  /// that does not count still says whether it would pass.
  bool passed = true;
  /// Whose limit: "Park et al. 2011", "ISO/TS 15066:2016 Table A.2", "the material's compressive
  /// strength", "the covering's travel".
  std::string_view source;
  /// Why the criterion is not counted or has no limit (e.g. "strength unknown"); empty else.
  std::string_view note;
};

/// The verdict on one contact.
struct Verdict {
  std::vector<Criterion> criteria;
  double safety_factor = 1.0;  ///< SF [-], in [1, 100]
  /// What the verdict covers, one sentence each (criteria applied, standards named).
  std::vector<std::string> scope;
  /// False when the contact could not be computed (a failed time-path run): no answer, never
  /// safe; the ratios are then +inf.
  bool evaluated = true;

  /// Adds a criterion with limit [unit] and value [unit]: ratio = value / limit, derated
  /// limit = limit / safety_factor, passed = SF × ratio <= 1 and !forced_fail. Returns it.
  Criterion& Add(std::string_view name, CriterionPart part, std::string_view unit, double value, double limit,
                 std::string_view source, bool counted = true, bool forced_fail = false);
  /// The criterion named `name`, or nullptr.
  const Criterion* Find(std::string_view name) const noexcept;
  /// The counted criterion with the largest ratio (the first on a tie); nullptr when none
  /// counts. A criterion without a ratio (an unknown limit, e.g. a strength that is not known)
  /// never governs: the margin is the ratios', and such a criterion, counted, fails safe() alone.
  const Criterion* governing() const noexcept;
  /// The governing ratio (unscaled) [-]; 0 when none counts, +inf when not evaluated.
  double governing_ratio() const noexcept;
  /// The governing criterion's name, "none" when none counts.
  std::string_view governing_name() const noexcept;
  /// 1 − SF × governing ratio [-]: the share of the derated limit left on the binding
  /// criterion (>= 0 when safe); -inf when not evaluated.
  double margin() const noexcept;
  /// Every counted injury criterion passed.
  bool injury_safe() const noexcept;
  /// Every counted design rule of the covering held (within its working range, not crushed).
  bool design_rules_met() const noexcept;
  /// Evaluated, injury_safe() and design_rules_met().
  bool safe() const noexcept { return evaluated && injury_safe() && design_rules_met(); }
  /// The names of the counted criteria, in order ("laceration", "contusion", ...).
  std::vector<std::string> CountedNames() const;
};

/// The design rule that the covering's law describes the contact (CoveringValidity::within,
/// core/impact_result.hpp): a result out of its law's validity is never SAFE.
inline constexpr std::string_view kLawValidityRule = "law-validity";

/// Appends "law-validity" to `verdict`: a design rule that always counts, unit "1", value how far
/// the covering went along its law's validity limits (CoveringValidity::ratio, 1 at the edge)
/// against a limit of 1. The validity limit is the model's, not the standard's: the safety factor
/// does not derate it, so its derated limit is 1 and its ratio value / (SF × limit) (SF × ratio =
/// the validity ratio, comparable with the derated criteria). Out of the validity (`within`
/// false) the criterion fails whatever the safety factor (the validity's note says why).
Criterion& AddLawValidity(Verdict& verdict, bool within, double validity_ratio);
/// AddLawValidity(verdict, within, within ? 0 : 1): a yes/no where no ratio is known.
Criterion& AddLawValidity(Verdict& verdict, bool within);

/// A share as a percentage with one decimal, as every margin is printed: "58.8 %" for 0.588,
/// "-34.4 %"; "none" when not finite.
std::string FormatPercent(double fraction);

/// "SAFE" or "UNSAFE".
std::string_view SafeWord(bool safe) noexcept;

}  // namespace covopt
