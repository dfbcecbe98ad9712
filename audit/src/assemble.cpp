// The one assembly of an audit from its inputs (assemble.hpp): what `covopt audit`'s Resolve
// and covopt.audit() each did on their own.
#include "covopt/audit/assemble.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <covopt/core/number_format.hpp>
#include <covopt/optim/design.hpp>

#include "covopt/audit/tool_surface.hpp"

namespace covopt::audit {
namespace {

[[noreturn]] void Refuse(const std::string& field, const std::string& message) {
  throw std::invalid_argument(field + ": " + message);
}

/// The robot's mass, speed and radius are each surface point's and sample's.
void RefuseRobotInputs(const AuditInputs& in) {
  const AuditFieldNames& n = in.names;
  for (const auto& [field, name, what] :
       {std::tuple{"robot.mass", &n.robot_mass, "reflected mass (the robot model's)"},
        std::tuple{"robot.speed", &n.speed, "speed (the trajectory's)"},
        std::tuple{"robot.radius", &n.robot_radius, "radius (the surface's)"}}) {
    if (const auto given = in.given_robot_inputs.find(field); given != in.given_robot_inputs.end()) {
      throw std::invalid_argument(*name + " '" + given->second + "': not used by audit (each surface point brings its own " +
                                  what + "); drop " + *name);
    }
  }
}

/// The design's inputs apply with the design only.
void RefuseDesignInputsWithoutDesign(const AuditInputs& in) {
  if (in.design) return;
  const AuditFieldNames& n = in.names;
  const std::string* field = !in.families.empty()         ? &n.families
                             : !in.design_materials.empty() ? &n.design_materials
                             : in.allow_unknown_strength    ? &n.allow_unknown_strength
                             : in.max_thickness_m           ? &n.max_thickness
                             : in.thickness_step_m          ? &n.thickness_step
                                                            : nullptr;
  if (field) {
    throw std::invalid_argument(*field + " applies with " + n.design + " (the per-link covering design)");
  }
}

robot::RobotSurface ReadSurface(const AuditInputs& in) {
  const AuditFieldNames& n = in.names;
  robot::RobotSurface surface;
  try {
    surface = in.urdf_text ? robot::SurfaceFromUrdfString(*in.urdf_text, in.chain, in.surface, n.urdf_text)
                           : robot::SurfaceFromUrdfFile(in.urdf_file, in.chain, in.surface);
  } catch (const std::invalid_argument& e) {
    Refuse(in.surface.surface_file ? n.surface_file : in.urdf_text ? n.urdf_text : n.urdf, e.what());
  }
  const std::string tip = in.chain.tip_link();
  for (const auto& [name, specs, field] : {std::tuple{"tool", &in.tool_surface, &n.tool_surface},
                                           std::tuple{"payload", &in.payload_surface, &n.payload_surface}}) {
    std::vector<robot::SurfaceShape> shapes;
    for (const std::string& spec : *specs) shapes.push_back(ParseTipShape(spec, *field));
    try {
      robot::AddTipSurface(surface, in.chain, name, shapes);
    } catch (const std::invalid_argument& e) {
      Refuse(*field, e.what());
    }
  }
  if (surface.links.empty()) {
    const std::string urdf = in.urdf_text ? n.urdf_text : n.urdf + " '" + in.urdf_file + "'";
    Refuse(urdf, "no link of the chain " + in.chain.base_link() + " -> " + in.chain.tip_link() +
                     " has collision geometry; give " + n.surface_file + " FILE.toml");
  }
  return surface;
}

robot::JointTrajectory ReadTrajectory(const AuditInputs& in) {
  if (const auto* samples = std::get_if<robot::JointTrajectory>(&in.trajectory)) return *samples;
  const std::string& path = std::get<std::string>(in.trajectory);
  if (path.empty()) Refuse(in.names.trajectory, "empty file name");
  try {
    return robot::ReadJointTrajectory(path, in.chain.joint_count());
  } catch (const std::invalid_argument& e) {
    Refuse(in.names.trajectory, e.what());
  }
}

/// The exposure zones: read from the file (its title and source kept), or as given.
void SetExposure(const AuditInputs& in, AssembledAudit& audit) {
  if (const auto* zones = std::get_if<std::vector<ExposureZone>>(&*in.exposure)) {
    audit.setup.exposure_zones = *zones;
    return;
  }
  const std::string& path = std::get<std::string>(*in.exposure);
  if (path.empty()) Refuse(in.names.exposure, "empty file name");
  scene_file::ExposureFile file;
  try {
    file = scene_file::ReadExposureFile(path);
  } catch (const std::invalid_argument& e) {
    Refuse(in.names.exposure, e.what());
  }
  audit.exposure_title = file.title;
  audit.exposure_source = file.source;
  for (const scene_file::ExposureZoneEntry& z : file.zones) {
    audit.setup.exposure_zones.push_back(ExposureZone{.name = z.name,
                                                      .min_m = Eigen::Vector3d(z.min_m[0], z.min_m[1], z.min_m[2]),
                                                      .max_m = Eigen::Vector3d(z.max_m[0], z.max_m[1], z.max_m[2]),
                                                      .regions = z.regions,
                                                      .origin = z.where});
  }
}

/// "--link-coverings robot.toml:3:1", or Python's "link_coverings['fr3_link7']" as it is.
std::string EntryWhere(const AuditFieldNames& n, const scene_file::LinkCoveringEntry& entry) {
  return entry.where.rfind(n.link_coverings, 0) == 0 ? entry.where : n.link_coverings + " " + entry.where;
}

/// Each entry's covering on its link; an assumed Poisson ratio of a material into `warnings`.
void AddLinkCoverings(const AuditInputs& in, const materials::Catalog& catalog, AuditSetup& setup,
                      std::vector<std::string>& warnings) {
  const AuditFieldNames& n = in.names;
  std::vector<scene_file::LinkCoveringEntry> entries;
  if (const auto* file = std::get_if<std::string>(&*in.link_coverings)) {
    if (file->empty()) Refuse(n.link_coverings, "empty file name");
    try {
      entries = scene_file::ReadLinkCoverings(*file);
    } catch (const std::invalid_argument& e) {
      Refuse(n.link_coverings, e.what());
    }
  } else {
    entries = std::get<std::vector<scene_file::LinkCoveringEntry>>(*in.link_coverings);
  }
  for (const scene_file::LinkCoveringEntry& entry : entries) {
    const bool on_surface = std::any_of(setup.surface.links.begin(), setup.surface.links.end(),
                                        [&](const robot::LinkSurface& l) { return l.link == entry.link; });
    if (!on_surface) {
      std::string names;
      for (const robot::LinkSurface& l : setup.surface.links) names += (names.empty() ? "" : ", ") + l.link;
      Refuse(EntryWhere(n, entry), "link '" + entry.link + "' is not a link of the audited surface (" + names + ")");
    }
    AuditCovering covering;
    covering.covering.thickness_m = entry.thickness_m;
    if (entry.material) {
      optim::CandidateMaterial material;
      try {
        const std::vector<std::string> names{*entry.material};
        material = optim::SelectCandidates(catalog, names).front();
      } catch (const std::invalid_argument& e) {
        Refuse(EntryWhere(n, entry), e.what());
      }
      // The material's curve comes along: under auto, a material with one takes the foam law.
      covering.covering = optim::CoveringOf(material, entry.thickness_m, CoveringLaw::kAuto);
      if (material.poisson_assumed && entry.thickness_m > 0.0) {
        warnings.push_back("link '" + entry.link + "': " + material.name + " has no Poisson ratio in the catalog; " +
                           FormatSignificant(material.poisson_ratio) + " assumed");
      }
      covering.material = std::move(material);
    } else if (entry.modulus_Pa) {
      covering.covering.youngs_modulus_Pa = *entry.modulus_Pa;
      covering.covering.poisson_ratio = entry.poisson_ratio.value_or(0.25);
    }
    setup.link_coverings.insert_or_assign(entry.link, std::move(covering));
  }
}

/// The per-link design's materials, thickness range and rule.
void SetDesign(const AuditInputs& in, const materials::Catalog& catalog, AssembledAudit& audit) {
  AuditDesignOptions& design = audit.options.design;
  try {
    design.materials = optim::SelectCandidates(catalog, in.design_materials, in.families);
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    Refuse(what.rfind("no family", 0) == 0 ? in.names.families : in.names.design_materials, what);
  }
  // The design's rule is optimize's: unknown strengths only when allowed (the audit alone
  // judges a covering of unknown strength without the crush check, as robot does).
  audit.setup.rule.unknown_strength_allowed = in.allow_unknown_strength;
  if (in.max_thickness_m) design.max_thickness_m = *in.max_thickness_m;
  if (in.thickness_step_m) design.thickness_step_m = *in.thickness_step_m;
}

}  // namespace

AssembledAudit AssembleAudit(const AuditInputs& in) {
  RefuseRobotInputs(in);
  if (in.contact != ContactType::kTransient) {
    Refuse(in.names.contact + " '" + std::string(ToString(in.contact)) + "'",
           "an audit judges the free (transient) impacts of a motion; drop " + in.names.contact);
  }
  RefuseDesignInputsWithoutDesign(in);
  AssembledAudit audit{AuditSetup(in.chain, ReadSurface(in))};
  AuditSetup& setup = audit.setup;
  setup.covering = AuditCovering{in.scene.covering, in.judge.material};
  setup.regions = in.regions;
  setup.SetReactionAndHead(in.scene, in.head);
  setup.contact_area_m2 = in.contact_area_m2;
  setup.flat_face_radius_m = in.flat_face_radius_m;
  setup.rule = in.judge.rule;
  setup.motion.reflected_mass = in.reflected_mass;
  audit.trajectory = ReadTrajectory(in);
  audit.options.keep_ratio_over_time = in.keep_ratio_over_time;

  const materials::Catalog& catalog = in.catalog ? *in.catalog : materials::Catalog::BuiltIn();
  if (in.link_coverings) AddLinkCoverings(in, catalog, setup, audit.input_warnings);
  if (in.design) SetDesign(in, catalog, audit);
  if (in.exposure) SetExposure(in, audit);
  audit.input_warnings.insert(audit.input_warnings.end(), in.scene_warnings.begin(), in.scene_warnings.end());
  return audit;
}

}  // namespace covopt::audit
