// The one assembly of an audit (audit/assemble.hpp) that `covopt audit` and covopt.audit call:
// what it reads and sets, the audit's rules it applies, and that every message names the input
// by the caller's spelling.
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/audit/assemble.hpp>
#include <covopt/core/number_format.hpp>
#include <covopt/materials/body_regions.hpp>

namespace {

namespace ca = covopt::audit;
namespace rb = covopt::robot;
using covopt::ContactType;

const std::string kModels = COVOPT_ROBOT_MODELS_DIR;
const std::string kFr3 = kModels + "/franka_fr3.urdf";
const std::string kPick = kModels + "/franka_fr3_pick.csv";

/// The FR3 pick move with 10 mm of a 0.5 MPa foam on every link, the chest and the head.
ca::AuditInputs Fr3Inputs() {
  ca::AuditInputs in(rb::KinematicChain::FromUrdfFile(kFr3, {"", "fr3_link8"}), kFr3);
  in.surface.spacing_m = 0.08;
  in.trajectory = kPick;
  in.scene.covering = covopt::CoveringSpec{0.5e6, 0.45, 0.01};
  in.regions = {covopt::materials::BodyRegionTable::BuiltIn().Limits("chest", "", ContactType::kTransient)};
  in.head = true;
  in.flat_face_radius_m = 0.02;
  return in;
}

std::string MessageOf(const ca::AuditInputs& in) {
  try {
    (void)ca::AssembleAudit(in);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  FAIL("AssembleAudit took the inputs");
  return {};
}

struct TempFile {
  explicit TempFile(const std::string& name, const std::string& text)
      : path(std::filesystem::temp_directory_path() / ("covopt_assemble_" + name)) {
    std::ofstream(path) << text;
  }
  ~TempFile() { std::filesystem::remove(path); }
  std::filesystem::path path;
};

}  // namespace

TEST_CASE("AssembleAudit reads the surface and the trajectory and sets the setup from the inputs", "[audit][assemble]") {
  ca::AuditInputs in = Fr3Inputs();
  in.scene.robot.reaction_delay_s = 0.01;
  in.scene.robot.braking_m_per_s2 = 50.0;
  in.contact_area_m2 = 1e-4;
  in.scene_warnings = {"a scene warning"};
  const ca::AssembledAudit a = ca::AssembleAudit(in);
  CHECK(a.setup.surface.links.size() == 8);  // fr3_link0 .. fr3_link7 and the hand
  CHECK(a.setup.surface.spacing_m == 0.08);
  CHECK(a.trajectory.size() == 101);
  CHECK(a.setup.covering.covering.youngs_modulus_Pa == 0.5e6);
  CHECK(a.setup.covering.covering.thickness_m == 0.01);
  CHECK_FALSE(a.setup.covering.material);
  CHECK(a.setup.regions.size() == 1);
  REQUIRE(a.setup.head);
  // The braking is the setup's, for every region; the head's scene does not brake itself.
  CHECK(a.setup.reaction_delay_s == 0.01);
  CHECK(a.setup.braking_m_per_s2 == 50.0);
  CHECK(a.setup.head->robot.braking_m_per_s2 == 0.0);
  CHECK(a.setup.contact_area_m2 == 1e-4);
  CHECK(a.setup.flat_face_radius_m == 0.02);
  CHECK(a.options.design.materials.empty());
  CHECK(a.input_warnings == std::vector<std::string>{"a scene warning"});
  CHECK(ca::AuditRegionNames(a.setup) == std::vector<std::string>{"chest (sternum)", "head (Park et al. 2011)"});
  // Samples instead of a file: taken as they are.
  in.trajectory = a.trajectory;
  CHECK(ca::AssembleAudit(in).trajectory.time_s == a.trajectory.time_s);
}

TEST_CASE("AssembleAudit: link coverings from a file or entries, materials from the catalog", "[audit][assemble]") {
  ca::AuditInputs in = Fr3Inputs();
  const TempFile file("links.toml", "[[link]]\nname = \"fr3_link6\"\nmaterial = \"PU foam PORON 4701-30 320\"\n"
                                    "thickness = \"20mm\"\n\n[[link]]\nname = \"fr3_link1\"\nmodulus = \"2MPa\"\n"
                                    "thickness = \"5mm\"\n");
  in.link_coverings = file.path.string();
  in.scene_warnings = {"a scene warning"};
  const ca::AssembledAudit a = ca::AssembleAudit(in);
  REQUIRE(a.setup.link_coverings.size() == 2);
  const ca::AuditCovering& poron = a.setup.link_coverings.at("fr3_link6");
  REQUIRE(poron.material);
  CHECK(poron.material->name == "PU foam PORON 4701-30 320");
  CHECK(poron.covering.thickness_m == Approx(0.02));
  CHECK(poron.covering.youngs_modulus_Pa == poron.material->youngs_modulus_Pa);
  const ca::AuditCovering& plain = a.setup.link_coverings.at("fr3_link1");
  CHECK_FALSE(plain.material);
  CHECK(plain.covering.youngs_modulus_Pa == 2e6);
  CHECK(plain.covering.poisson_ratio == 0.25);  // the file's default without poisson
  // The catalog has no Poisson ratio for PORON: said first, then the scene's warnings.
  REQUIRE(a.input_warnings.size() == 2);
  CHECK(a.input_warnings[0] == "link 'fr3_link6': PU foam PORON 4701-30 320 has no Poisson ratio in the catalog; " +
                                   covopt::FormatSignificant(poron.covering.poisson_ratio) + " assumed");
  CHECK(a.input_warnings[1] == "a scene warning");

  // Entries as a front end read them (Python's dict) give the same setup.
  covopt::scene_file::LinkCoveringEntry entry;
  entry.link = "fr3_link1";
  entry.modulus_Pa = 2e6;
  entry.thickness_m = 0.005;
  entry.where = "link_coverings['fr3_link1']";
  in.link_coverings = std::vector{entry};
  CHECK(ca::AssembleAudit(in).setup.link_coverings.at("fr3_link1").covering.youngs_modulus_Pa == 2e6);

  // A link not on the surface, and a material not in the catalog: named with where they are.
  entry.link = "fr3_hand_tcp";
  in.link_coverings = std::vector{entry};
  CHECK(MessageOf(in).rfind("link_coverings['fr3_link1']: link 'fr3_hand_tcp' is not a link of the audited surface "
                            "(fr3_link0, ",
                            0) == 0);
  const TempFile unknown("unknown.toml", "[[link]]\nname = \"fr3_link6\"\nmaterial = \"no such foam\"\n"
                                         "thickness = \"20mm\"\n");
  in.link_coverings = unknown.path.string();
  in.names.link_coverings = "--link-coverings";
  const std::string message = MessageOf(in);
  CHECK(message.rfind("--link-coverings " + unknown.path.string() + ":", 0) == 0);
  CHECK(message.find("no such foam") != std::string::npos);
}

TEST_CASE("AssembleAudit: the design's materials, range and rule", "[audit][assemble]") {
  ca::AuditInputs in = Fr3Inputs();
  in.design = true;
  in.families = {"foam"};
  in.allow_unknown_strength = true;
  in.max_thickness_m = 0.03;
  in.thickness_step_m = 0.001;
  const ca::AssembledAudit a = ca::AssembleAudit(in);
  REQUIRE_FALSE(a.options.design.materials.empty());
  for (const auto& m : a.options.design.materials) CHECK(m.family == "foam");
  CHECK(a.options.design.max_thickness_m == 0.03);
  CHECK(a.options.design.thickness_step_m == 0.001);
  CHECK(a.setup.rule.unknown_strength_allowed);
  // Without allow_unknown_strength the design keeps the rule's refusal (as optimize's).
  in.allow_unknown_strength = false;
  CHECK_FALSE(ca::AssembleAudit(in).setup.rule.unknown_strength_allowed);
}

TEST_CASE("AssembleAudit refuses what an audit does not take, naming the input by the caller's spelling",
          "[audit][assemble]") {
  ca::AuditInputs in = Fr3Inputs();
  SECTION("the robot's mass, speed or radius: each surface point and sample brings its own") {
    in.given_robot_inputs = {{"robot.speed", "1.5m/s"}};
    CHECK(MessageOf(in) == "speed '1.5m/s': not used by audit (each surface point brings its own speed (the "
                           "trajectory's)); drop speed");
    in.given_robot_inputs = {{"robot.mass", "10kg"}};
    in.names.robot_mass = "--robot-mass";
    CHECK(MessageOf(in) == "--robot-mass '10kg': not used by audit (each surface point brings its own reflected mass "
                           "(the robot model's)); drop --robot-mass");
  }
  SECTION("a clamped contact") {
    in.contact = ContactType::kClamped;
    CHECK(MessageOf(in) == "contact 'clamped': an audit judges the free (transient) impacts of a motion; drop contact");
    in.names.contact = "--contact";
    CHECK(MessageOf(in) ==
          "--contact 'clamped': an audit judges the free (transient) impacts of a motion; drop --contact");
  }
  SECTION("a design input without the design") {
    in.families = {"foam"};
    CHECK(MessageOf(in) == "families applies with design (the per-link covering design)");
    in.names.families = "--family";
    in.names.design = "--design";
    CHECK(MessageOf(in) == "--family applies with --design (the per-link covering design)");
    in.families.clear();
    in.thickness_step_m = 0.001;
    CHECK(MessageOf(in) == "thickness_step applies with --design (the per-link covering design)");
  }
  SECTION("a design material or family not in the catalog") {
    in.design = true;
    in.design_materials = {"no such foam"};
    CHECK(MessageOf(in).rfind("materials: ", 0) == 0);
    in.design_materials.clear();
    in.families = {"no such family"};
    in.names.families = "--family";
    CHECK(MessageOf(in).rfind("--family: no family", 0) == 0);
  }
  SECTION("a trajectory file that cannot be read") {
    in.trajectory = std::string(kModels + "/no_such.csv");
    in.names.trajectory = "--trajectory";
    CHECK(MessageOf(in).rfind("--trajectory: ", 0) == 0);
    in.trajectory = std::string();
    CHECK(MessageOf(in) == "--trajectory: empty file name");
  }
  SECTION("a chain without collision geometry") {
    const std::string urdf =
        "<robot name='lever'><link name='base'/><joint name='j' type='continuous'><parent link='base'/>"
        "<child link='lever'/><axis xyz='0 0 1'/></joint><link name='lever'><inertial><origin xyz='0.5 0 0'/>"
        "<mass value='2'/><inertia ixx='0' ixy='0' ixz='0' iyy='0' iyz='0' izz='0'/></inertial></link></robot>";
    ca::AuditInputs bare(rb::KinematicChain::FromUrdfString(urdf, {"", "lever"}), "");
    bare.urdf_text = urdf;
    bare.trajectory = rb::JointTrajectory{};
    CHECK(MessageOf(bare) ==
          "urdf_text: no link of the chain base -> lever has collision geometry; give surface_file FILE.toml");
  }
}
