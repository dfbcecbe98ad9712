"""One resolver of target names for the CLI and Python (covopt::scene_file::ResolveTargets):
"all", "head", case, lists, duplicates and the bare-robot contact-area policy give the same
targets, in the same order, with the same warnings; and covopt.Regions / covopt.Rule are the
keywords they replace."""

import pytest

import covopt
from conftest import without_provenance

Scene = covopt.Scene
BARE = {"covering_thickness": 0}
MASS = ["--robot-mass", "10kg", "--covering-thickness", "0", "--contact-area", "1cm2"]


def row_targets(table):
    return [(row["region"], row["area"]) for row in table["rows"]]


@pytest.mark.parametrize("typed, python", [
    ("ALL", "ALL"),
    ("all", ["all"]),
    ("Head,chest", ["Head", "chest"]),
    ("chest,head,pelvis", "chest, head , pelvis"),
    ("chest,CHEST,head,head", ["chest", "CHEST", "head", "head"]),
    ("pelvis,all", ["pelvis", "all"]),
])
def test_speed_limit_targets_agree_with_the_cli(cli_json, typed, python):
    data = cli_json("speed-limit", "--body-region", typed, *MASS, "--json")
    table = covopt.speed_limit(Scene(robot_mass=10, **BARE), body_region=python, contact_area="1cm2")
    assert row_targets(table.to_dict()) == row_targets(data)
    assert table.to_dict()["rows"] == data["rows"]
    # The warnings differ only in how the inputs are named (flags / keywords).
    spelled = [w.replace("--body-region", "body_region") for w in data["warnings"]]
    assert table.warnings == spelled


def test_all_is_the_table_s_order_with_the_head_last():
    table = covopt.speed_limit(Scene(robot_mass=10, **BARE), body_region="All", contact_area="1cm2")
    # Every area of every region that permits transient contact, in Table A.2's order, then the head.
    expected = [(r.name, a["name"]) for r in covopt.body_regions() if r.transient_permitted for a in r.to_dict()["areas"]]
    assert [(row.region, row.area) for row in table] == expected + [("head", None)]


def test_a_duplicate_is_judged_once_with_a_warning(cli_json):
    table = covopt.speed_limit(Scene(robot_mass=10, **BARE), body_region="chest,Chest", contact_area="1cm2")
    assert [row.region for row in table] == ["chest"]
    assert "body_region: chest (sternum) is named more than once; it is judged once" in table.warnings
    data = cli_json("speed-limit", "--body-region", "chest,Chest", *MASS, "--json")
    assert "--body-region: chest (sternum) is named more than once; it is judged once" in data["warnings"]


@pytest.mark.parametrize("args, call, flag_text, keyword_text", [
    (["simulate", "--body-region", "chest", "--covering-thickness", "0"],
     lambda: covopt.simulate(Scene(**BARE), body_region="chest"),
     "--contact-area is needed for the bare robot on chest", "contact_area is needed for the bare robot on chest"),
    (["simulate", "--body-region", "face"], lambda: covopt.simulate(Scene(), body_region="face"),
     "use --contact clamped, or judge the head with Park et al.'s skin model (--body-region head)",
     "use contact='clamped', or judge the head with Park et al.'s skin model (body_region='head')"),
    (["speed-limit", "--body-region", "head", "--contact", "clamped"],
     lambda: covopt.speed_limit(Scene(), body_region=["head", "chest"], contact="clamped"),
     "--body-region head is judged by Park et al.'s skin model", "body_region='head' is judged by Park et al.'s"),
    (["speed-limit", "--body-region", "chest,pelvis", "--body-area", "sternum"],
     lambda: covopt.speed_limit(Scene(), body_region="chest,pelvis", body_area="sternum"),
     "--body-area 'sternum' names an area of one region", "body_area 'sternum' names an area of one region"),
    (["simulate", "--body-region", "chest", "--contact-area", "5m2"],
     lambda: covopt.simulate(Scene(), body_region="chest", contact_area="5m2"),
     "--contact-area must be in [1 mm², 1 m²]", "contact_area must be in [1 mm², 1 m²]"),
    (["simulate", "--body-region", "chest", "--contact", "Sideways"],
     lambda: covopt.simulate(Scene(), body_region="chest", contact="Sideways"),
     "--contact: expected 'transient' or 'clamped' (got 'Sideways')",
     "contact: expected 'transient' or 'clamped' (got 'Sideways')"),
])
def test_the_same_refusal_named_as_flag_or_keyword(cli, args, call, flag_text, keyword_text):
    code, _, err = cli(*args)
    assert code == 2 and flag_text in err, err
    with pytest.raises(ValueError) as error:
        call()
    assert keyword_text in str(error.value)


def test_regions_and_rule_are_the_keywords():
    scene = Scene(robot_mass=10, **BARE)
    by_keywords = covopt.speed_limit(scene, body_region=["chest", "head"], contact_area="1cm2",
                                     allow_full_compression=True, allow_crushing=True)
    by_objects = covopt.speed_limit(scene, regions=covopt.Regions(["chest", "head"], contact_area="1cm2"),
                                    rule=covopt.Rule(criterion="paper", allow_crushing=True))
    assert without_provenance(by_objects) == without_provenance(by_keywords)
    derated = covopt.speed_limit(scene, regions=covopt.Regions("chest", contact_area="1cm2"),
                                 rule=covopt.Rule(safety_factor=2.0))
    plain = covopt.speed_limit(Scene(robot_mass=10, safety_factor=2.0, **BARE), body_region="chest",
                               contact_area="1cm2")
    assert derated.rows[0].bare_max_speed_m_per_s == pytest.approx(plain.rows[0].bare_max_speed_m_per_s, rel=1e-15)
    full = covopt.speed_limit(scene, regions=covopt.Regions("chest", contact_area="1cm2"))
    assert derated.rows[0].bare_max_speed_m_per_s == pytest.approx(full.rows[0].bare_max_speed_m_per_s / 2, rel=1e-12)


def test_regions_and_rule_refuse_what_is_given_twice_or_does_not_apply():
    with pytest.raises(ValueError, match="body_region: give it in regions= or as a keyword, not both"):
        covopt.simulate(Scene(), body_region="chest", regions=covopt.Regions("face"))
    with pytest.raises(ValueError, match="safety_factor: the scene has 2 and the rule 3"):
        covopt.max_safe_speed(Scene(safety_factor=2), rule=covopt.Rule(safety_factor=3.0))
    with pytest.raises(ValueError, match="rule: allow_unknown_strength does not apply to max_safe_speed"):
        covopt.max_safe_speed(Scene(), rule=covopt.Rule(allow_unknown_strength=True))
    with pytest.raises(ValueError, match="criterion: expected 'no-full-compression' or 'paper'"):
        covopt.Rule(criterion="lenient")
    with pytest.raises(TypeError, match="regions: expected a covopt.Regions"):
        covopt.simulate(Scene(), regions="chest")
    with pytest.raises(AttributeError):
        covopt.Rule().allow_crushing = True
    assert covopt.Regions(["chest"], contact="clamped") == covopt.Regions(("chest",), contact="clamped")


def test_the_default_covering_is_warned_by_simulate_in_both_front_ends(cli_json):
    text = "no covering given: the default is assumed"
    assert any(text in w for w in covopt.simulate(Scene()).warnings)
    assert any(text in w for w in cli_json("simulate", "--json")["warnings"])
    assert not any(text in w for w in covopt.simulate(Scene(covering_thickness="10mm")).warnings)
    assert not any(text in w for w in covopt.simulate(Scene(covering_thickness=0)).warnings)


@pytest.mark.parametrize("keyword, typed, allowed", [
    ("laceration_limit", "2e13Pa", "[1000, 1e+13] Pa"),
    ("contusion_limit", "2e13J/m2", "[1, 1e+13] J/m2"),
])
def test_the_injury_limits_have_one_range(cli, keyword, typed, allowed):
    flag = "--" + keyword.replace("_", "-")
    for command in ("simulate", "optimize", "speed-limit"):  # optimize once had [1 kPa, 1 GPa]
        code, _, err = cli(command, flag, typed)
        assert code == 2 and f"{flag} must be in {allowed}" in err, (command, err)
    with pytest.raises(ValueError) as error:
        covopt.Scene(**{keyword: typed})
    assert f"{keyword} must be in {allowed}" in str(error.value)
