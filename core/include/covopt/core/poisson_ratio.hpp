#pragma once
/// @file poisson_ratio.hpp
/// The Poisson ratios the model takes, one check for every reader: a Scene's (covering.poisson,
/// --covering-poisson, ImpactModel::FromScene), an audit's coverings (audit::Audit) and a
/// link-coverings file's poisson (scene_file::ReadLinkCoverings).

#include <string_view>

namespace covopt {

/// Whether `poisson_ratio` [-] is one the model takes: in (-1, 0.5] (kPoissonRatioRange).
/// False for NaN.
constexpr bool IsPoissonRatio(double poisson_ratio) noexcept {
  return poisson_ratio > -1.0 && poisson_ratio <= 0.5;
}

/// The Poisson ratios IsPoissonRatio takes, as messages show them.
inline constexpr std::string_view kPoissonRatioRange = "(-1, 0.5]";

}  // namespace covopt
