"""covopt.optimize against `covopt optimize --json` (the same dict apart from wall times:
both come from covopt::report::DesignJson) and its bad input."""

import pytest

import covopt
from conftest import same_provenance, without_provenance
from calls import call


def without_times(value):
    """The JSON value with every wall time ("seconds") left out."""
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if k != "seconds"}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


CASES = [
    ({}, []),
    ({"robot_mass": 20.0, "speed": 1.5}, ["--robot-mass", "20kg", "--speed", "1.5m/s"]),
    ({"thickness": 0.01}, ["--thickness", "10mm"]),
    ({"materials": ["polystyrene foam 27.6", "polystyrene foam 48.3"], "safety_factor": 1.5},
     ["--material", "polystyrene foam 27.6", "--material", "polystyrene foam 48.3",
      "--safety-factor", "1.5"]),
    ({"families": "foam", "allow_full_compression": True, "max_thickness": "30mm"},
     ["--family", "foam", "--allow-full-compression", "--max-thickness", "30mm"]),
    ({"materials": "XPS Foamular 250", "allow_crushing": True},
     ["--material", "XPS Foamular 250", "--allow-crushing"]),
    ({"materials": "polystyrene foam 27.6", "allow_unknown_strength": True, "safety_factor": 2},
     ["--material", "polystyrene foam 27.6", "--allow-unknown-strength", "--safety-factor", "2"]),
    ({"materials": ["vinyl-nitrile foam VN600", "elastomer Shore A40"]},
     ["--material", "vinyl-nitrile foam VN600", "--material", "elastomer Shore A40"]),
    ({"materials": "vinyl-nitrile foam VN600", "covering_law": "hertz"},
     ["--material", "vinyl-nitrile foam VN600", "--covering-law", "hertz"]),
    ({"covering_law": "foam", "max_thickness": "30mm"}, ["--covering-law", "foam", "--max-thickness", "30mm"]),
]


@pytest.mark.parametrize("kwargs,flags", CASES)
def test_optimize_returns_the_cli_json_object(cli_json, kwargs, flags):
    ours = call(covopt.optimize, **kwargs)
    theirs = cli_json("optimize", "--json", *flags)
    assert list(ours) == list(theirs)
    assert without_times(without_provenance(ours)) == without_times(without_provenance(theirs))
    assert same_provenance(ours["provenance"], theirs["provenance"])


def test_the_criterion_names_every_part_and_each_design_its_governing_ratio():
    answer = covopt.optimize()
    assert answer.criterion.parts == ["laceration", "contusion", "fracture", "full-compression", "crush",
                                      "law-validity"]
    assert "A.3.2" in answer.scope[1]
    for c in answer.candidates:
        # The covering's travel rule is named for its law: within-curve for a foam layer.
        travel = "within-curve" if c.covering_law == "foam" else "full-compression"
        ratios = {"laceration": c.laceration_ratio, "contusion": c.contusion_ratio, travel: c.compression_ratio,
                  "law-validity": c.validity.ratio}  # how far along its law's validity limits
        if c.crush_ratio is not None:
            ratios["crush"] = c.crush_ratio
        # The governing ratio is the largest that counts; the margin is 1 minus it (SF 1).
        assert c.governing_ratio == max(ratios.values())
        assert ratios[c.governing_criterion] == c.governing_ratio
        assert c.margin == pytest.approx(1 - c.governing_ratio, abs=1e-15)
        if c.crush_behaviour == "crushes":
            assert c.crush_ratio == pytest.approx(c.max_compressive_stress_Pa / c.compressive_strength_Pa,
                                                     rel=1e-15)
    # A material that crushes is never admissible beyond its strength.
    for c in answer.candidates:
        if c.safe and c.crush_ratio is not None:
            assert c.crush_ratio <= 1.0


def test_unknown_strengths_are_refused_unless_allowed_and_then_warned():
    refused = covopt.optimize(materials="polystyrene foam 27.6")
    assert refused.recommendation is None
    allowed = covopt.optimize(materials="polystyrene foam 27.6", allow_unknown_strength=True)
    assert allowed.recommendation.crush_check == "unknown-strength"
    assert any("unverified for crushing" in w for w in allowed.warnings)


def test_a_range_points_to_robust_optimize():
    with pytest.raises(ValueError, match="robust_optimize"):
        covopt.optimize(covopt.Scene(head_mass="3.7kg..5.8kg")).to_dict()


def test_the_recommendation_is_admissible_and_simulates_as_reported():
    answer = covopt.optimize()
    best = answer.recommendation
    assert best is not None
    one = covopt.simulate(covopt.Scene(material=best.material, covering_thickness=best.thickness_m))
    assert one.safe and not one.fully_compressed


@pytest.mark.parametrize("kwargs,words", [
    ({"materials": ["polystyrene"]}, ["materials: no material 'polystyrene' in the catalog"]),
    ({"families": ["metal"]}, ["families: no family 'metal'"]),
    ({"thickness": 0.0}, ["thickness must be in [0.1 mm, 1 m]"]),
    ({"max_thickness": 2.0}, ["max_thickness 2"]),
    ({"global_algorithm": "newton"}, ["global_algorithm: expected direct-l, isres or mlsl", "newton"]),
    ({"threads": -1}, ["threads must be a whole number in [0, 256]", "-1"]),
    ({"no_builtin": True}, ["no_builtin leaves no catalog"]),
    ({"catalog": "/nonexistent/catalog.toml"}, ["catalog: ", "/nonexistent/catalog.toml"]),
])
def test_bad_input_names_the_keyword(kwargs, words):
    with pytest.raises(ValueError) as error:
        call(covopt.optimize, **kwargs)
    for word in words:
        assert word in str(error.value)


@pytest.mark.parametrize("keyword,value", [("covering_thickness", 0.01), ("covering_modulus", 1e6),
                                           ("material", "polystyrene foam 48.3")])
def test_the_covering_is_not_an_input(keyword, value):
    with pytest.raises(ValueError, match="the covering is what optimize designs"):
        covopt.optimize(covopt.Scene(**{keyword: value}))


def test_a_curve_material_is_designed_with_the_foam_law_and_each_row_names_its_law_and_validity():
    foam = covopt.optimize(materials=["vinyl-nitrile foam VN600", "elastomer Shore A40"]).to_dict()
    laws = {c["material"]: c["covering_law"] for c in foam["candidates"]}
    assert laws == {"vinyl-nitrile foam VN600": "foam", "elastomer Shore A40": "hertz"}
    for c in foam["candidates"]:
        assert set(c["validity"]) == {"within", "ratio", "note"}
        assert c["has_compressive_curve"] == (c["covering_law"] == "foam")
    assert foam["continuous_optimum"]["covering_law"] == "hertz"
    hertz = call(covopt.optimize, materials="vinyl-nitrile foam VN600", covering_law="hertz")
    assert hertz["candidates"][0]["covering_law"] == "hertz"
    vn600 = [c for c in foam["candidates"] if c["material"] == "vinyl-nitrile foam VN600"][0]
    assert vn600["laceration_ratio"] != hertz["candidates"][0]["laceration_ratio"]
    with pytest.raises(ValueError, match="material 'elastomer Shore A40' has no compressive_curve"):
        call(covopt.optimize, materials="elastomer Shore A40", covering_law="foam")
