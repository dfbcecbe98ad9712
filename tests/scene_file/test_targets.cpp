// The one resolver of target names (covopt/scene_file/targets.hpp) and the field spellings
// (spelling.hpp): the behaviour the CLI's --body-region and Python's covopt.Regions share.
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "covopt/materials/body_regions.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/scene_file/integrators.hpp"
#include "covopt/scene_file/scene_inputs.hpp"
#include "covopt/scene_file/spelling.hpp"
#include "covopt/scene_file/targets.hpp"

namespace {

using Catch::Matchers::Contains;
using covopt::ContactType;
using covopt::materials::BodyRegionTable;
using covopt::materials::ContactTargets;
using covopt::scene_file::ResolveTargets;
using covopt::scene_file::TargetRequest;

TargetRequest Names(std::vector<std::string> names) {
  TargetRequest request;
  request.names = std::move(names);
  return request;
}

std::vector<std::string> TargetNames(const ContactTargets& targets) {
  std::vector<std::string> names;
  for (const auto& target : targets.targets) names.push_back(target.Name());
  return names;
}

std::string MessageOf(const TargetRequest& request) {
  try {
    (void)ResolveTargets(request);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("targets: nothing named is no target, and a contact input without a region is refused") {
  CHECK_FALSE(ResolveTargets(TargetRequest{}).has_value());
  TargetRequest contact;
  contact.contact = "clamped";
  CHECK_THAT(MessageOf(contact), Contains("body.contact applies to an ISO/TS 15066 body region"));
}

TEST_CASE("targets: all is the table's areas in order then the head, whatever the case") {
  const std::vector<covopt::materials::BodyLimits> table = BodyRegionTable::BuiltIn().AllLimits(ContactType::kTransient);
  for (const char* all : {"all", "ALL", " All "}) {
    CAPTURE(all);
    const ContactTargets targets = *ResolveTargets(Names({all}));
    REQUIRE(targets.targets.size() == table.size() + 1);
    for (std::size_t i = 0; i < table.size(); ++i) {
      CHECK(targets.targets[i].limits->region == table[i].region);
      CHECK(targets.targets[i].limits->area == table[i].area);
    }
    CHECK(targets.targets.back().is_head());  // the head row last, as in the table order
    CHECK(targets.notes.empty());
  }
  // Clamped: no head (its skin model is a free head), and the skull and face are in.
  TargetRequest clamped = Names({"all"});
  clamped.contact = "Clamped";
  const ContactTargets targets = *ResolveTargets(clamped);
  CHECK_FALSE(targets.has_head());
  CHECK(targets.contact == ContactType::kClamped);
  CHECK(targets.targets.size() == BodyRegionTable::BuiltIn().AllLimits(ContactType::kClamped).size());
}

TEST_CASE("targets: names keep their order, lists split at commas, case ignored") {
  const ContactTargets targets = *ResolveTargets(Names({"Pelvis, HEAD", "chest"}));
  CHECK(TargetNames(targets) == std::vector<std::string>{"pelvis (pelvic-bone)", "head", "chest (sternum)"});
  CHECK(targets.has_head());
  CHECK(targets.IsoLimits().size() == 2);
  CHECK(targets.IsoNames() == "pelvis, chest");
}

TEST_CASE("targets: a target named twice is judged once, with a note") {
  const ContactTargets targets = *ResolveTargets(Names({"chest,Chest", "head", "head"}));
  CHECK(TargetNames(targets) == std::vector<std::string>{"chest (sternum)", "head"});
  REQUIRE(targets.notes.size() == 2);
  CHECK(targets.notes[0] == "body.region: chest (sternum) is named more than once; it is judged once");
  CHECK(targets.notes[1] == "body.region: head is named more than once; it is judged once");
  // A region named besides "all" is in "all": merged without a note, where it was named first.
  const ContactTargets with_all = *ResolveTargets(Names({"pelvis", "all"}));
  CHECK(with_all.targets.front().limits->region->name == "pelvis");
  CHECK(with_all.targets.size() == BodyRegionTable::BuiltIn().AllLimits(ContactType::kTransient).size() + 1);
  CHECK(with_all.notes.empty());
}

TEST_CASE("targets: the area of the one region named") {
  TargetRequest request = Names({"hands-fingers", "head"});
  request.area = "Palm-Dominant";
  const ContactTargets targets = *ResolveTargets(request);
  CHECK(TargetNames(targets) == std::vector<std::string>{"hands-fingers (palm-dominant)", "head"});
  request.names = {"chest,pelvis"};
  CHECK(MessageOf(request) ==
        "body.area 'Palm-Dominant' names an area of one region; give exactly one body.region with it (got 2 regions)");
  request.names = {"all"};
  CHECK_THAT(MessageOf(request), Contains("(got all)"));
  request.names = {"chest"};
  CHECK_THAT(MessageOf(request), Contains("body.area: body area 'Palm-Dominant' is not an area of 'chest'"));
}

TEST_CASE("targets: bad names, contacts and areas name the field and the value") {
  CHECK_THAT(MessageOf(Names({"chset"})),
             Contains("body.region: body region 'chset' is not in ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M; did you mean "
                               "'chest'?"));
  CHECK_THAT(MessageOf(Names({"chset"})), Contains("; or head (Park et al.'s skin model) or all"));
  CHECK_THAT(MessageOf(Names({"chest,,face"})), Contains("body.region: an empty name in 'chest,,face'"));
  CHECK_THAT(MessageOf(Names({"face"})), Contains("use body.contact=clamped"));
  TargetRequest sideways = Names({"chest"});
  sideways.contact = "sideways";
  CHECK(MessageOf(sideways) == "body.contact: expected 'transient' or 'clamped' (got 'sideways')");
  TargetRequest head = Names({"head"});
  head.contact = "clamped";
  CHECK_THAT(MessageOf(head), Contains("body.region=head is judged by Park et al.'s skin model"));
  CHECK_THAT(MessageOf(head), Contains("give head.mass=fixed with a transient body.contact"));
  for (const double area : {0.0, 1e-7, 5.0}) {
    TargetRequest request = Names({"chest"});
    request.contact_area_m2 = area;
    request.contact_area_shown = "typed";
    CHECK(MessageOf(request) ==
          "body.contact_area must be in [1 mm², 1 m²] (a bare number is m²: 1e-06 to 1; 1 cm² is 1e-4) (got 'typed')");
  }
  TargetRequest ok = Names({"chest"});
  ok.contact_area_m2 = 1e-4;
  CHECK(ResolveTargets(ok)->contact_area_m2 == 1e-4);
}

TEST_CASE("targets: the bare robot on an ISO region needs its contact area") {
  covopt::BodyContactScene scene;
  scene.covering.thickness_m = 0.0;
  scene.contact_area_m2 = 0.0;
  const ContactTargets chest = *ResolveTargets(Names({"chest"}));
  try {
    covopt::scene_file::RequireBareRobotContactArea(chest, scene);
    FAIL("a bare robot without its contact area was judged");
  } catch (const std::invalid_argument& e) {
    CHECK_THAT(e.what(), Contains("body.contact_area is needed for the bare robot on chest"));
  }
  CHECK(covopt::scene_file::BarePressureNote(chest).has_value());
  CHECK_NOTHROW(covopt::scene_file::RequireBareRobotContactArea(*ResolveTargets(Names({"head"})), scene));
  scene.contact_area_m2 = 1e-4;
  CHECK_NOTHROW(covopt::scene_file::RequireBareRobotContactArea(chest, scene));
  scene.contact_area_m2 = 0.0;
  scene.covering.thickness_m = 0.01;
  CHECK_NOTHROW(covopt::scene_file::RequireBareRobotContactArea(chest, scene));
}

TEST_CASE("spelling: fields become flags or keywords, with their values") {
  using covopt::scene_file::FieldSpelling;
  using covopt::scene_file::Respell;
  using covopt::scene_file::ValueStyle;
  const FieldSpelling flags[] = {{"body.contact", "--contact"}, {"body.contact_area", "--contact-area"},
                                 {"body.region", "--body-region"}};
  const FieldSpelling keywords[] = {{"body.contact", "contact"}, {"body.contact_area", "contact_area"},
                                    {"body.region", "body_region"}};
  const std::string message = "use body.contact=clamped, or body.region=head. body.contact_area is needed; "
                              "not body.regions";
  CHECK(Respell(message, flags, ValueStyle::kFlag) ==
        "use --contact clamped, or --body-region head. --contact-area is needed; not body.regions");
  CHECK(Respell(message, keywords, ValueStyle::kKeyword) ==
        "use contact='clamped', or body_region='head'. contact_area is needed; not body.regions");
}

TEST_CASE("scene inputs: one resolution, messages naming fields, spelled per front end") {
  using covopt::scene_file::ApplySceneInputs;
  using covopt::scene_file::ResolvedScene;
  using covopt::scene_file::SceneInput;
  using covopt::scene_file::SceneInputSpellings;
  using covopt::scene_file::ValueStyle;
  const covopt::materials::Catalog& catalog = covopt::materials::Catalog::BuiltIn();
  ResolvedScene resolved;
  const std::vector<SceneInput> good{{"robot.mass", std::string("12kg"), ""},
                                     {"robot.radius", 0.04, "0.04"},
                                     {"limits.safety_factor", std::string("2"), ""},
                                     {"model.thresholds", std::string("literal"), ""},
                                     {"covering.material", std::string(catalog.materials().front().name), ""}};
  ApplySceneInputs(good, catalog, resolved);
  CHECK(resolved.scene.robot.mass_kg == 12.0);
  CHECK(resolved.scene.robot.radius_m == 0.04);
  CHECK(resolved.safety_factor == 2.0);
  CHECK(resolved.scene.model.thresholds == covopt::ThresholdReading::kLiteral);
  REQUIRE(resolved.covering_material != nullptr);
  CHECK(resolved.scene.covering.youngs_modulus_Pa == resolved.covering_material->youngs_modulus_Pa);

  const auto message = [&](std::vector<SceneInput> inputs) {
    ResolvedScene r;
    try {
      ApplySceneInputs(inputs, catalog, r, "'");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string bare = message({{"robot.radius", 40.0, "40"}});
  CHECK_THAT(bare, Contains("robot.radius 40: a bare number is in metres"));
  CHECK_THAT(covopt::scene_file::Respell(bare, SceneInputSpellings(ValueStyle::kFlag), ValueStyle::kFlag),
             Contains("--robot-radius 40: a bare number is in metres"));
  CHECK_THAT(covopt::scene_file::Respell(bare, SceneInputSpellings(ValueStyle::kKeyword), ValueStyle::kKeyword),
             Contains("robot_radius 40: a bare number is in metres"));
  // The limits' one range (optimize once allowed laceration only to 1 GPa).
  CHECK(message({{"limits.laceration", std::string("2e13Pa"), ""}}) ==
        "limits.laceration must be in [1000, 1e+13] Pa (got '2e13Pa')");
  CHECK(message({{"limits.laceration", std::string("2GPa"), ""}}).empty());
  CHECK(message({{"limits.safety_factor", 0.5, "0.5"}}) == "limits.safety_factor must be in [1, 100] (got 0.5)");
  CHECK_THAT(message({{"covering.material", std::string("x"), ""}, {"covering.poisson", 0.3, "0.3"}}),
             Contains("give either covering.material or covering.poisson, not both"));
  CHECK_THAT(message({{"model.thresholds", std::string("loose"), ""}}),
             Contains("model.thresholds: expected 'cumulative' or 'literal'"));
}

TEST_CASE("targets: an ISO region reads the robot, the covering and the safety factor only") {
  for (const char* field : {"robot.mass", "robot.speed", "robot.radius", "covering.thickness", "covering.material",
                            "limits.safety_factor", "robot.braking"}) {
    CHECK(covopt::scene_file::BodyRegionReads(field));
  }
  for (const char* field : {"head.mass", "scalp.thickness", "model.damping", "limits.laceration", "robot.modulus"}) {
    CHECK_FALSE(covopt::scene_file::BodyRegionReads(field));
  }
}

TEST_CASE("targets: the body contact takes the scene's robot and covering and the targets' contact") {
  covopt::Scene scene;
  scene.robot.mass_kg = 7.5;
  scene.robot.speed_m_per_s = 0.8;
  scene.robot.radius_m = 0.03;
  scene.robot.reaction_delay_s = 0.02;
  scene.robot.braking_m_per_s2 = 4.0;
  scene.covering.thickness_m = 0.012;
  TargetRequest request = Names({"chest"});
  request.contact = "clamped";
  request.contact_area_m2 = 2e-4;
  const ContactTargets targets = *ResolveTargets(request);
  const covopt::BodyContactScene contact = covopt::scene_file::BodyContactSceneOf(scene, targets);
  CHECK(contact.robot_mass_kg == 7.5);
  CHECK(contact.speed_m_per_s == 0.8);
  CHECK(contact.robot_radius_m == 0.03);
  CHECK(contact.reaction_delay_s == 0.02);
  CHECK(contact.braking_m_per_s2 == 4.0);
  CHECK(contact.covering.thickness_m == 0.012);
  CHECK(contact.contact == ContactType::kClamped);
  CHECK(contact.contact_area_m2 == 2e-4);
}

TEST_CASE("targets: the head alone is named by head in any case, nothing else") {
  for (const char* head : {"head", "HEAD", "Head"}) CHECK(covopt::scene_file::NamesTheHead(head));
  for (const char* other : {"chest", "all", "heads", "hea", "head,chest", ""}) {
    CAPTURE(other);
    CHECK_FALSE(covopt::scene_file::NamesTheHead(other));
  }
}

TEST_CASE("integrators: cvode is CVODE's Adams method, each integrator by its name, exact none") {
  using covopt::ComputationMethod;
  using covopt::scene_file::ParseIntegrator;
  CHECK(ParseIntegrator("cvode") == ComputationMethod::kCvodeAdams);
  for (const ComputationMethod method : covopt::TimeIntegrationMethods()) {
    CAPTURE(covopt::ToString(method));
    CHECK(ParseIntegrator(covopt::ToString(method)) == method);
    CHECK_THAT(covopt::scene_file::IntegratorNames(), Contains(std::string(covopt::ToString(method))));
  }
  CHECK_FALSE(ParseIntegrator("exact").has_value());
  CHECK_FALSE(ParseIntegrator("time-path").has_value());
  CHECK_FALSE(ParseIntegrator("").has_value());
}
