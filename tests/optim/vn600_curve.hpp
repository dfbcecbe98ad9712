#pragma once
/// @file vn600_curve.hpp
/// The optim tests' VN600 foam curve: the 11 rounded points of NIST's vinyl-nitrile VN600
/// record the design notes give (docs/model.md §15.7), as one shared CompressiveCurve.

#include <memory>
#include <vector>

#include <covopt/core/compressive_curve.hpp>

namespace covopt::testing {

inline std::shared_ptr<const CompressiveCurve> Vn600Curve() {
  const std::vector<StrainStressPoint> points{
      {0.02, 14.3e3}, {0.05, 22.0e3}, {0.10, 30.2e3}, {0.15, 37.4e3}, {0.20, 45.9e3}, {0.25, 57.3e3},
      {0.30, 72.2e3}, {0.35, 91.6e3}, {0.40, 118.0e3}, {0.45, 153.2e3}, {0.49, 189.5e3}};
  return std::make_shared<const CompressiveCurve>(CompressiveCurve::FromPoints(points));
}

}  // namespace covopt::testing
