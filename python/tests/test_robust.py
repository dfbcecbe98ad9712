"""covopt.worst_case, injury_probability, sensitivities and robust_optimize (docs/model.md §11),
cross-checked against the CLI's JSON with the same ranges."""

import pytest

import covopt
from conftest import without_provenance
from calls import call

COVERING = {"covering_thickness": "16mm", "material": "XPS Foamular 250"}
COVERING_FLAGS = ["--covering-thickness", "16mm", "--material", "XPS Foamular 250"]
RANGES = {"head_mass": ("3.7kg", "5.8kg"), "scalp_thickness": "2mm..5mm"}
RANGE_FLAGS = ["--head-mass", "3.7kg..5.8kg", "--scalp-thickness", "2mm..5mm"]


def without_timing(value):
    """The dict without seconds and evaluation counts that may differ between runs."""
    if isinstance(value, dict):
        return {k: without_timing(v) for k, v in value.items() if k not in ("seconds",)}
    if isinstance(value, list):
        return [without_timing(v) for v in value]
    return value


def test_worst_case_is_the_cli_simulate_object(cli_json):
    ours = call(covopt.worst_case, ranges=RANGES, **COVERING)
    theirs = cli_json("simulate", "--json", *RANGE_FLAGS, *COVERING_FLAGS)
    assert without_timing(ours["worst_case"]) == without_timing(theirs["worst_case"])
    assert ours["uncertain_inputs"] == theirs["uncertain_inputs"]
    assert ours["contusion"] == theirs["contusion"]
    assert ours["worst_case"]["inputs"]["head-mass"] == pytest.approx(5.8)
    # XPS Foamular 250 crushes at every point of the box (crush ratio ~19): crush binds, not
    # contusion (issue 34: the worst case counts every criterion).
    assert ours["worst_case"]["binding"] == "crush"
    assert ours["worst_case"]["crush_ratio"] > 15.0
    assert not ours["worst_case"]["admissible"]


def test_injury_probability_is_the_cli_object_for_any_thread_count(cli_json):
    ours = call(covopt.injury_probability, ranges=RANGES, samples=5000, seed=4, threads=1, **COVERING)
    threaded = call(covopt.injury_probability, ranges=RANGES, samples=5000, seed=4, threads=3,
                    **COVERING)
    theirs = cli_json("simulate", "--json", *RANGE_FLAGS, *COVERING_FLAGS, "--samples", "5000",
                      "--seed", "4")
    assert ours["injury_probability"] == theirs["injury_probability"]
    assert threaded["injury_probability"] == ours["injury_probability"]
    p = ours["injury_probability"]
    assert p["ci95"]["contusion"][0] <= p["contusion"] <= p["ci95"]["contusion"][1]
    assert p["any"] >= p["contusion"]
    # Every sample crushes the foam: every sample fails the criterion, not only the bruised ones.
    assert p["crushed"] == 1.0
    assert p["inadmissible"] == 1.0
    assert p["contusion"] < 1.0


def test_distributions_match_the_cli(cli_json):
    ours = call(covopt.injury_probability, ranges={"head_mass": ("3.7kg", "5.8kg")}, samples=3000,
                                     distributions={"head_mass": ("normal", "4.5kg",
                                                                  "0.5kg")}, **COVERING)
    theirs = cli_json("simulate", "--json", "--head-mass", "3.7kg..5.8kg", *COVERING_FLAGS, "--samples",
                      "3000",
                      "--distribution", "head-mass=normal:4.5kg:0.5kg")
    assert ours["injury_probability"] == theirs["injury_probability"]
    assert ours["uncertain_inputs"][0]["distribution"] == "normal"


def test_sensitivities_are_the_cli_object(cli_json):
    ours = call(covopt.sensitivities, **COVERING)
    theirs = cli_json("simulate", "--json", "--sensitivities", *COVERING_FLAGS)["sensitivities"]
    assert without_provenance(ours) == theirs  # the CLI's is the simulate object's
    assert ours["rows"][0]["field"] == "speed"


def test_robust_optimize_is_the_cli_optimize_object(cli_json):
    ours = covopt.robust_optimize(ranges=RANGES)
    theirs = cli_json("optimize", "--json", *RANGE_FLAGS)
    assert without_timing(ours.recommendation.to_dict()) == without_timing(theirs["recommendation"])
    assert without_timing(ours.worst_case.to_dict()) == without_timing(theirs["worst_case"])
    assert ours.verdict == "covering-found"
    assert ours.recommendation.thickness_m > 0.016  # thicker than for the nominal head


def test_probability_design_matches_the_cli(cli_json):
    ours = covopt.robust_optimize(ranges={"head_mass": ("3.7kg", "5.8kg")}, samples=2000, seed=2,
                                  max_injury_probability=0.05)
    theirs = cli_json("optimize", "--json", "--head-mass", "3.7kg..5.8kg", "--samples", "2000",
                      "--seed", "2",
                      "--max-injury-probability", "0.05")
    assert ours.recommendation.material == theirs["recommendation"]["material"]
    assert ours.recommendation.thickness_m == theirs["recommendation"]["thickness_m"]
    assert ours.recommendation.injury_probability == theirs["recommendation"]["injury_probability"]
    assert ours.recommendation.injury_probability.inadmissible <= 0.05


@pytest.mark.parametrize("call, needle", [
    (lambda: covopt.worst_case(ranges={"head_mass": ("5.8kg", "3.7kg")}).to_dict(), "head"),
    (lambda: covopt.worst_case(ranges={"brain_mass": ("1kg", "2kg")}).to_dict(), "unknown input"),
    (lambda: covopt.worst_case(ranges={}).to_dict(), "ranges"),
    (lambda: covopt.worst_case(covopt.Scene(damping="0.2s/m"), ranges={"head_mass": ("3.7kg",
                                                                                     "5.8kg")}).to_dict(), "damping"),
    (lambda: covopt.injury_probability(ranges={"head_mass": ("3.7kg", "5.8kg")}, samples=0).to_dict(),
     "samples"),
    (lambda: covopt.injury_probability(ranges={"head_mass": ("3.7kg", "5.8kg")}, samples=10,
                                       distributions={"speed": ("normal", "2m/s",
                                                                "0.1m/s")}).to_dict(), "no range"),
    (lambda: covopt.robust_optimize(ranges={"head_mass": ("3.7kg", "5.8kg")},
                                    max_injury_probability=0.1).to_dict(),
     "samples"),
])
def test_bad_input_raises_value_error(call, needle):
    with pytest.raises(ValueError, match=needle):
        call()


def test_the_seed_is_any_unsigned_64_bit_value_and_the_message_says_so():
    # Issue 22: the stated maximum was 18000000000000000000 and seeds above it were refused.
    top = 2**64 - 1
    ours = covopt.injury_probability(ranges={"head_mass": ("3.7kg", "5.8kg")}, samples=10, seed=top)
    assert ours.injury_probability.seed == top
    with pytest.raises(ValueError, match=r"seed must be a whole number in \[0, 18446744073709551615\]"):
        covopt.injury_probability(ranges={"head_mass": ("3.7kg", "5.8kg")}, samples=10,
                                  seed=2**64).to_dict()
    with pytest.raises(ValueError, match="18446744073709551615"):
        covopt.injury_probability(ranges={"head_mass": ("3.7kg", "5.8kg")}, samples=10,
                                  seed=-1).to_dict()
    assert "18446744073709551615" in covopt.injury_probability.__doc__


BRAKING = {"reaction_delay": "10ms", "braking": "20m/s2"}
BRAKING_FLAGS = ["--reaction-delay", "10ms", "--braking", "20m/s2"]


def test_braking_robot_with_ranges_is_the_cli_object(cli_json):
    """A braking robot over a box (docs/model.md §11): the time path, screened by the exact path's
    bound; the same objects as the CLI's, and no thicker than without the brake."""
    worst = call(covopt.worst_case, ranges=RANGES, **COVERING, **BRAKING)
    theirs = cli_json("simulate", "--json", *RANGE_FLAGS, *COVERING_FLAGS, *BRAKING_FLAGS)
    assert without_timing(worst["worst_case"]) == without_timing(theirs["worst_case"])
    unbraked = call(covopt.worst_case, ranges=RANGES, **COVERING)
    assert worst["worst_case"]["governing_ratio"] <= unbraked["worst_case"]["governing_ratio"]
    assert worst["worst_case"]["time_path"]["failed"] == 0

    # With a brake the curve materials are left out and the solid elastomers are beyond their law's
    # strain limit on this scene: the compressible Hertz coverings of unknown strength remain.
    padding = {"allow_unknown_strength": True}
    padding_flags = ["--allow-unknown-strength"]
    ours = covopt.robust_optimize(covopt.Scene(**BRAKING), ranges=RANGES, **padding)
    design = cli_json("optimize", "--json", *RANGE_FLAGS, *BRAKING_FLAGS, *padding_flags)
    assert without_timing(ours.recommendation.to_dict()) == without_timing(design["recommendation"])
    assert design["time_path"]["runs"] > 0
    free = cli_json("optimize", "--json", *RANGE_FLAGS, *padding_flags)
    assert (ours.recommendation.to_dict()["min_safe_thickness_m"]
            <= free["recommendation"]["min_safe_thickness_m"] + 1e-6)


def test_robust_optimize_designs_curve_materials_with_the_foam_law_as_the_cli(cli_json):
    ours = covopt.robust_optimize(covopt.Scene(covering_law="foam"), ranges={"head_mass": ("3.7kg", "5.8kg")})
    theirs = cli_json("optimize", "--json", "--head-mass", "3.7kg..5.8kg", "--covering-law", "foam")
    assert without_timing(ours.to_dict()["candidates"]) == without_timing(theirs["candidates"])
    assert theirs["candidates"] and all(c["covering_law"] == "foam" for c in theirs["candidates"])
    assert all(set(c["validity"]) == {"within", "ratio", "note"} for c in theirs["candidates"])
