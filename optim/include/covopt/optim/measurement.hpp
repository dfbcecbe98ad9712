#pragma once
/// @file measurement.hpp
/// `covopt measure` and covopt.predict_measurement: what a biofidelic force-measuring device
/// would read (covopt/core/measuring_device.hpp) beside what the body-region model predicts for
/// the same robot, speed, covering and region (body_region_check.hpp), each against the
/// region's limits (docs/model.md §13.11, docs/guide/limits.md).
///
/// The assessor compares the device's reading with the limit; covopt's body model predicts the
/// real contact. They differ because the device is fixed (mu = m_R, where the body model's
/// transient region recoils: mu = m_R m_H/(m_R + m_H)), because its pad is a solid elastomer of
/// a given hardness (not the region's tissue, which the body model does not separate from k_H),
/// and because its spring k_D may not be the region's k_H. Both are judged against the same
/// limits: the difference is what the measurement adds to, or takes from, the prediction.

#include <optional>
#include <string>
#include <vector>

#include <covopt/core/body_contact.hpp>
#include <covopt/core/measuring_device.hpp>
#include <covopt/core/result_summary.hpp>
#include <covopt/core/verdict.hpp>
#include <covopt/materials/body_regions.hpp>

#include "covopt/optim/body_region_check.hpp"

namespace covopt::optim {

/// The device and the body model side by side.
struct MeasurementPrediction {
  /// The body model's verdict of the contact (its peaks in body.contact).
  BodyRegionJudgement body;
  /// What the device shows.
  DeviceReading device;
  /// The device's reading judged against the same limits: force and pressure (the Hertz
  /// pressure a pressure film on the pad shows), and "law-validity" (the pad's and the
  /// covering's Hertz limits). Its scope names the limits and the device.
  Verdict device_verdict;
  /// F_device / F_lim and p_device / p_lim [-].
  double device_force_ratio = 0.0;
  std::optional<double> device_pressure_ratio;
  /// Device less body model [N], and their ratio device/body [-].
  double force_difference_N = 0.0;
  double force_ratio = 0.0;
  /// The same for the peak pressure [Pa], [-]; empty where the body model has no pressure
  /// (a bare robot without a contact area).
  std::optional<double> pressure_difference_Pa;
  std::optional<double> pressure_ratio;
  /// The device's warnings (DeviceReading::warnings), and a device whose spring is not the
  /// region's k_H.
  std::vector<std::string> warnings;
  /// What is compared, in words: the limits (their Describe()), the device, the body model.
  std::string scope;
};

/// Predicts the device's reading and the body model's for `scene`'s robot, speed and covering
/// against `limits` (the region's k_H, m_H and contact type taken from it, as
/// JudgeBodyContact does), under `options`.
/// @throws std::invalid_argument naming the field for a bad scene, device or options.
MeasurementPrediction PredictMeasurement(const BodyContactScene& scene, const materials::BodyLimits& limits,
                                         const MeasuringDevice& device, const BodyRegionOptions& options = {});

/// The result summary of a prediction (`measure`): the body model's rows and the device's,
/// each as its own target ("chest (sternum), body model" and "chest (sternum), device 25+70"),
/// with the covering's `material` ("" when given by its modulus).
ResultSummary SummarizeMeasurement(const BodyContactScene& scene, std::string_view material,
                                   const MeasurementPrediction& prediction);

}  // namespace covopt::optim
