"""covopt.optimize against `covopt optimize --json` (the same dict apart from wall times:
both come from covopt::report::DesignJson) and its bad input."""

import pytest

import covopt


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
]


@pytest.mark.parametrize("kwargs,flags", CASES)
def test_optimize_returns_the_cli_json_object(cli_json, kwargs, flags):
    ours = covopt.optimize(**kwargs)
    theirs = cli_json("optimize", "--json", *flags)
    assert list(ours) == list(theirs)
    assert without_times(ours) == without_times(theirs)


def test_the_recommendation_is_admissible_and_simulates_as_reported():
    answer = covopt.optimize()
    best = answer["recommendation"]
    assert best is not None
    one = covopt.simulate(material=best["material"], covering_thickness=best["thickness_m"])
    assert one["safe"] and not one["fully_compressed"]


@pytest.mark.parametrize("kwargs,words", [
    ({"materials": ["polystyrene"]}, ["materials: no material 'polystyrene' in the catalog"]),
    ({"families": ["metal"]}, ["families: no family 'metal'"]),
    ({"thickness": 0.0}, ["thickness must be in (0, 1 m]"]),
    ({"max_thickness": 2.0}, ["max_thickness 2"]),
    ({"global_algorithm": "newton"}, ["global_algorithm: expected direct-l, isres or mlsl", "newton"]),
    ({"threads": 0}, ["threads must be a whole number in [1, 256]", "0"]),
    ({"no_builtin": True}, ["no_builtin leaves no catalog"]),
    ({"catalog": "/nonexistent/catalog.toml"}, ["catalog: ", "/nonexistent/catalog.toml"]),
])
def test_bad_input_names_the_keyword(kwargs, words):
    with pytest.raises(ValueError) as error:
        covopt.optimize(**kwargs)
    for word in words:
        assert word in str(error.value)


@pytest.mark.parametrize("keyword", ["covering_thickness", "covering_modulus", "material"])
def test_the_covering_is_not_an_input(keyword):
    with pytest.raises(TypeError):
        covopt.optimize(**{keyword: 0.01})
