#include "measure.hpp"

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "covopt/core/measuring_device.hpp"
#include "covopt/optim/measurement.hpp"
#include "covopt/report/measurement_json.hpp"
#include "body_region_options.hpp"
#include "body_region_output.hpp"
#include "errors.hpp"
#include "output_options.hpp"
#include "quantity.hpp"
#include "report_option.hpp"
#include "rule_options.hpp"

namespace covopt::cli {
namespace {

/// A library message about the device, its keywords (device_spring, ...) spelled as flags.
std::string DeviceFlags(std::string message) {
  // Longest first; a name inside a longer one (device in device_pad) is left to that one.
  for (const auto& [field, flag] : {std::pair{"device_pad_thickness", "--device-pad-thickness"},
                                    {"device_spring", "--device-spring"}, {"device_pad", "--device-pad"},
                                    {"device", "--device"}}) {
    const std::string_view name(field);
    for (std::size_t at = message.find(name); at != std::string::npos; at = message.find(name, at + 1)) {
      const char before = at > 0 ? message[at - 1] : ' ';
      const char after = at + name.size() < message.size() ? message[at + name.size()] : ' ';
      if (before == '-' || before == '_' || after == '_' || after == '-') continue;
      message.replace(at, name.size(), flag);
    }
  }
  return message;
}

/// The device the flags name: the library's ResolveDevice, its messages naming the flags.
MeasuringDevice ResolveDeviceFlags(const MeasureOptions& o, const materials::BodyLimits& limits) {
  DeviceChoice choice{.preset = o.device, .spring_N_per_m = std::nullopt, .pad = o.device_pad, .pad_thickness_m = std::nullopt};
  if (o.device_spring) choice.spring_N_per_m = ParseQuantity(*o.device_spring, kDeviceSpringSpec, "--device-spring");
  if (o.device_pad_thickness) {
    choice.pad_thickness_m = ParseQuantity(*o.device_pad_thickness, kPadThicknessSpec, "--device-pad-thickness");
  }
  try {
    return ResolveDevice(choice, limits.region->name);
  } catch (const std::invalid_argument& e) {
    throw InputError(DeviceFlags(e.what()));
  }
}

}  // namespace

void SetupMeasure(CLI::App* sub, MeasureOptions& options) {
  sub->footer(
      "The device is fixed: the robot's whole reflected mass strikes it. Its pad and the robot's covering\n"
      "are one Hertz contact (the pad's modulus from its Shore A hardness, Ruess correlation) on its spring.\n"
      "Presets (N/mm+ShoreA, DGUV FB HM-080): 10+10 abdomen, 25+70 chest, 30+30 upper-arms-elbows,\n"
      "35+30 back-shoulders, 40+70 lower-arms-wrists, 50+30 thighs-knees, 60+30 lower-legs, 75+70\n"
      "hands-fingers. Without --device the region's pair. Exit codes: 0 done; 1 an output failed; 2 bad input.");
  SimulateOptions& s = options.scene;
  AddSceneOptions(*sub, s);
  AddRuleOptions(*sub, {.safety_factor = &s.safety_factor, .keep_travel = &s.keep_travel});
  AddBodyRegionOptions(*sub, s.body);
  sub->add_option("--device", options.device, "a spring and pad pair (25+70) or the region it stands for (chest)")
      ->type_name("PAIR|REGION")->group("Device");
  sub->add_option("--device-spring", options.device_spring, "the device's spring, e.g. 25N/mm")
      ->type_name("STIFFNESS")->group("Device");
  sub->add_option("--device-pad", options.device_pad, "the pad's Shore A hardness and thickness, e.g. 70ShA,7mm")
      ->type_name("HARDNESS[,THICKNESS]")->group("Device");
  sub->add_option("--device-pad-thickness", options.device_pad_thickness,
                  "the pad's thickness with --device (default 7 mm, assumed)")
      ->type_name("LENGTH")->group("Device");
  AddJsonFlag(*sub, s.json);
  AddReportOption(*sub, s.report);
}

int RunMeasure(const MeasureOptions& options, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "measure");
  if (options.scene.body.regions.empty()) return errors.BadInput("--body-region: give the one region the device stands for, e.g. chest");
  return RunWithBodyRegions(options.scene.body, errors, [&](const BodyRegionPlan& regions) {
    SimulationPlan plan;
    MeasuringDevice device;
    const std::vector<materials::BodyLimits> limits = regions.IsoLimits();
    try {
      if (limits.size() != 1 || regions.has_head()) {
        throw InputError("--body-region: measure compares one ISO/TS 15066 region (not the head) with the device");
      }
      plan = ResolveSimulation(options.scene);
      CheckBodyRegionScene(regions, plan);
      device = ResolveDeviceFlags(options, limits.front());
    } catch (const InputError& e) {
      return errors.BadInput(e.what());
    }
    const BodyContactScene scene = BodyContactSceneOf(plan.scene, regions);
    optim::MeasurementPrediction prediction;
    try {
      prediction = optim::PredictMeasurement(scene, limits.front(), device, BodyRegionOptionsOf(plan, false, false));
    } catch (const std::invalid_argument& e) {
      return errors.BadInput(AttributeError(DeviceFlags(e.what()), plan));
    }
    std::vector<std::string> warnings = InputWarnings(plan);
    warnings.insert(warnings.end(), regions.notes.begin(), regions.notes.end());
    if (const auto note = ContactAreaNote(regions, plan.scene, false)) warnings.push_back(*note);
    warnings.insert(warnings.end(), prediction.warnings.begin(), prediction.warnings.end());
    if (plan.json || options.scene.report.file) {
      try {
        PrintAndReport(out, plan.json,
                       report::MeasurementJson(scene, body_text::MaterialName(plan), prediction, plan.safety_factor, warnings),
                       options.run, options.scene.report, plan.inputs, report::ReportKind::kMeasure,
                       [] { return std::vector<chart::GnuplotChart>{}; });
      } catch (const OutputError& e) {
        return errors.Failed(e);
      }
    }
    if (!plan.json) out << report::MeasurementText(scene, prediction, warnings);
    out.flush();
    if (!out) return errors.Failed("cannot write the results to standard output");
    return 0;
  });
}

}  // namespace covopt::cli
