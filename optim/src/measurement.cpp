// What a measuring device reads beside the body model (measurement.hpp).
#include "covopt/optim/measurement.hpp"

#include <cmath>
#include <string>

#include <covopt/core/number_format.hpp>

#include "covopt/optim/summaries.hpp"
#include "covopt/optim/verdicts.hpp"

namespace covopt::optim {

namespace {

std::string DeviceWords(const MeasuringDevice& d) {
  return "device " + d.name + " (spring " + FormatSignificant(d.spring_N_per_m / 1e3, 4) + " N/mm, pad " +
         FormatSignificant(d.pad_shore_a, 3) + " Shore A, " + FormatSignificant(d.pad_thickness_m * 1e3, 3) + " mm" +
         (d.pad_thickness_assumed ? " assumed" : "") + ")";
}

std::string DeviceTarget(const materials::BodyLimits& limits, const MeasuringDevice& d) {
  return RegionTarget(limits) + ", device " + d.name;
}

}  // namespace

MeasurementPrediction PredictMeasurement(const BodyContactScene& scene, const materials::BodyLimits& limits,
                                         const MeasuringDevice& device, const BodyRegionOptions& options) {
  MeasurementPrediction p;
  p.body = JudgeBodyContact(scene, limits, options);
  p.device = PredictDeviceReading(scene, device);
  const BodyContactResult& dc = p.device.contact;
  const BodyContactResult& bc = p.body.contact;
  // Force and pressure against the region's limits, and the two layers' law.
  p.device_verdict = BodyRegionVerdict(dc, limits, false, options.rule, {});
  AddLawValidity(p.device_verdict, p.device.validity.within, p.device.validity.ratio);
  p.device_force_ratio = dc.peak_force_N / limits.force_N;
  if (dc.peak_pressure_Pa) p.device_pressure_ratio = *dc.peak_pressure_Pa / limits.pressure_Pa;
  p.force_difference_N = dc.peak_force_N - bc.peak_force_N;
  p.force_ratio = dc.peak_force_N / bc.peak_force_N;
  if (dc.peak_pressure_Pa && bc.peak_pressure_Pa) {
    p.pressure_difference_Pa = *dc.peak_pressure_Pa - *bc.peak_pressure_Pa;
    p.pressure_ratio = *dc.peak_pressure_Pa / *bc.peak_pressure_Pa;
  }
  p.warnings = p.device.warnings;
  const double k_H = limits.stiffness_N_per_m();
  if (std::abs(device.spring_N_per_m - k_H) > 1e-9 * k_H) {
    p.warnings.push_back("the device's spring " + FormatSignificant(device.spring_N_per_m / 1e3, 4) +
                         " N/mm is not the region's k_H " + FormatSignificant(k_H / 1e3, 4) +
                         " N/mm (ISO/TS 15066 Table A.3)");
  }
  p.scope = limits.Describe() + "; " + DeviceWords(device) +
            ", fixed (reduced mass = the robot's), against the body model (" + std::string(ToString(limits.contact)) +
            ", k_H and m_H of Table A.3)";
  p.device_verdict.scope = {p.scope};
  return p;
}

ResultSummary SummarizeMeasurement(const BodyContactScene& scene, std::string_view material,
                                   const MeasurementPrediction& p) {
  ResultSummary s;
  s.command = "measure";
  const BodyContactResult& bc = p.body.contact;
  const bool covered = bc.covering_law.has_value();
  s.AddVerdict(RegionTarget(p.body.limits) + ", body model", p.body.verdict,
               LawWord(covered, bc.covering_law.value_or(CoveringLaw::kHertz)), ValidityWords(covered, bc.validity));
  s.AddVerdict(DeviceTarget(p.body.limits, p.device.device), p.device_verdict, "hertz",
               ValidityWords(true, p.device.validity));
  s.scope = {p.body.scope, p.scope};
  s.Finish();
  s.governing_case = "one contact of the robot at " + FormatSignificant(scene.speed_m_per_s, 4) + " m/s with the " +
                     s.governing_target;
  s.covering = SummarizeCovering(scene.covering.thickness_m, material, bc.covering_law.value_or(CoveringLaw::kHertz),
                                 bc.validity);
  s.robot = RobotSummary{.model_file = "",
                         .motion = "",
                         .joints = {},
                         .reflected_mass_kg = scene.robot_mass_kg,
                         .payload_kg = 0.0,
                         .speed_m_per_s = scene.speed_m_per_s};
  return s;
}

}  // namespace covopt::optim
