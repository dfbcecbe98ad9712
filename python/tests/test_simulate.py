"""covopt.simulate against the CLI and the physics.

The dict must be the CLI's `simulate --json` object on the same inputs, key for key and
number for number (both come from covopt::report::SimulationJson; shortest round-trip
doubles survive json.loads exactly). History arrays have one entry per sample and agree
with the peaks; a fixed body behaves as an infinitely heavy one; bad input is a ValueError
naming the keyword, a failed computation a ComputationError with its status.
"""

import math
import threading

import numpy as np
import pytest

import covopt
from conftest import without_provenance
from calls import call

# (keyword arguments, the same scene as CLI flags)
SCENES = [
    ({}, []),
    ({"robot_mass": 10.0, "speed": 1.5, "covering_thickness": 0.02, "covering_modulus": 5e6},
     ["--robot-mass", "10kg", "--speed", "1.5m/s", "--covering-thickness", "20mm",
      "--covering-modulus", "5MPa"]),
    ({"robot_mass": math.inf, "speed": 2.2}, ["--robot-mass", "fixed", "--speed", "2.2m/s"]),
    ({"head_mass": "fixed", "robot_radius": "flat"}, ["--head-mass", "fixed", "--robot-radius", "flat"]),
    ({"covering_thickness": 0.0}, ["--covering-thickness", "0"]),
    ({"covering_thickness": 0.004, "thresholds": "literal"},
     ["--covering-thickness", "4mm", "--thresholds", "literal"]),
    ({"material": "polystyrene foam 48.3"}, ["--material", "polystyrene foam 48.3"]),
    ({"covering_modulus": 70e9, "covering_poisson": 0.3, "covering_thickness": 0.015},
     ["--covering-modulus", "70GPa", "--covering-poisson", "0.3", "--covering-thickness", "15mm"]),
    ({"laceration_limit": 2e6, "contusion_limit": "3J/cm2"},
     ["--laceration-limit", "2MPa", "--contusion-limit", "3J/cm2"]),
    ({"method": "cvode", "rtol": 1e-9}, ["--method", "cvode", "--rtol", "1e-9"]),
    ({"method": "arkode-erk54", "speed": 3.0}, ["--method", "arkode-erk54", "--speed", "3m/s"]),
    ({"robot_mass": 5.145, "robot_radius": "60mm", "speed": 2.3, "covering_thickness": 0.0, "head_area": "nasal"},
     ["--robot-mass", "5.145kg", "--robot-radius", "60mm", "--speed", "2.3m/s", "--covering-thickness", "0",
      "--head-area", "nasal"]),
    ({"covering_law": "hertz"}, ["--covering-law", "hertz"]),
]


@pytest.mark.parametrize("kwargs,flags", SCENES)
def test_simulate_returns_the_cli_json_object(cli_json, kwargs, flags):
    assert call(covopt.simulate, **kwargs) == cli_json("simulate", "--json", *flags)


def test_the_keys_come_in_the_cli_order(cli_json):
    assert list(covopt.simulate().to_dict()) == list(cli_json("simulate", "--json"))


def test_a_safety_factor_derates_the_limits_as_the_cli_does(cli_json):
    ours = covopt.simulate(covopt.Scene(safety_factor=2.0)).to_dict()
    theirs = cli_json("simulate", "--json", "--safety-factor", "2")
    # The CLI adds a warning on its input (the factor and the derated limits); all else agrees.
    for key in ("laceration", "contusion", "safe", "max_tensile_stress_Pa", "scene", "solver"):
        assert ours[key] == theirs[key]
    assert ours["laceration"]["derated_limit_Pa"] == 0.5e6
    assert ours["laceration"]["ratio"] == covopt.simulate().laceration.ratio


def test_an_implausible_number_is_accepted_with_an_explicit_unit():
    assert covopt.simulate(covopt.Scene(robot_radius="40m")).scene.robot.radius_m == 40.0


def test_values_with_units_equal_si_floats():
    assert without_provenance(covopt.simulate(covopt.Scene(robot_mass="10kg", speed="250mm/s",
                                                           covering_thickness="18mm"))) == \
        without_provenance(covopt.simulate(covopt.Scene(robot_mass=10.0, speed=0.25, covering_thickness=0.018)))


def test_fixed_and_flat_are_math_inf():
    fixed = without_provenance(covopt.simulate(covopt.Scene(robot_mass="fixed", robot_radius="flat")))
    assert fixed == without_provenance(covopt.simulate(covopt.Scene(robot_mass=math.inf, robot_radius=math.inf)))
    assert fixed["scene"]["robot"]["mass_kg"] == "fixed"
    assert fixed["scene"]["robot"]["radius_m"] == "flat"


def test_a_fixed_robot_is_the_limit_of_a_heavy_one():
    fixed = covopt.simulate(covopt.Scene(robot_mass=math.inf)).to_dict()
    heavy = covopt.simulate(covopt.Scene(robot_mass="1e6kg")).to_dict()  # beyond the plausible range of a bare number
    light = covopt.simulate(covopt.Scene(robot_mass=1.0)).to_dict()
    for key in ("max_penetration_m", "peak_force_N", "max_energy_density_J_per_m2"):
        assert heavy[key] == pytest.approx(fixed[key], rel=1e-5)
        assert light[key] < fixed[key]


def test_history_arrays_have_one_entry_per_sample_and_agree_with_the_peaks():
    result = covopt.simulate(history=True)
    history = result.history.to_dict()
    columns = ["time_s", "penetration_m", "penetration_rate_m_per_s", "force_N",
               "compressive_stress_Pa", "tensile_stress_Pa", "energy_density_J_per_m2"]
    assert list(history) == columns
    samples = result.solver.history_samples
    assert samples >= 400
    for name in columns:
        assert isinstance(history[name], np.ndarray)
        assert history[name].shape == (samples,)
        assert history[name].dtype == np.float64
    assert np.all(np.diff(history["time_s"]) >= 0)
    assert history["penetration_m"].max() == pytest.approx(result.max_penetration_m, rel=1e-6)
    assert history["force_N"].max() == pytest.approx(result.peak_force_N, rel=1e-6)
    # σ_t = σ_c (1 - 2 ν_t) / 3 at every sample.
    nu_t = result.scene.model.tensile_poisson_ratio
    np.testing.assert_allclose(history["tensile_stress_Pa"],
                               history["compressive_stress_Pa"] * (1 - 2 * nu_t) / 3, rtol=1e-12)
    assert "history" not in covopt.simulate().to_dict()


def test_history_matches_the_cli_history_csv(cli, tmp_path):
    csv = tmp_path / "history.csv"
    code, _, err = cli("simulate", "--history", str(csv))
    assert code == 0, err
    table = np.genfromtxt(csv, delimiter=",", names=True)
    history = covopt.simulate(history=True).history.to_dict()
    for name in history:
        np.testing.assert_array_equal(history[name], table[name])


def test_bad_input_is_a_value_error_with_the_clis_message(cli):
    with pytest.raises(ValueError) as error:
        covopt.simulate(covopt.Scene(robot_mass=-10.0)).to_dict()
    code, out, err = cli("simulate", "--robot-mass", "-10kg")
    assert code == 2 and out == ""
    library_part = str(error.value).split(" (robot.mass is")[0]
    assert library_part in err
    assert "robot_mass=-10.0" in str(error.value)


@pytest.mark.parametrize("kwargs,words", [
    ({"robot_radius": "40"}, ["robot_radius 40", "a bare number is in metres", "40mm"]),
    ({"robot_radius": 40.0}, ["robot_radius 40", "a bare number is in metres", "'40mm' or '40m'"]),
    ({"covering_modulus": 27.6}, ["covering_modulus 27.6", "Pa", "'27.6MPa'"]),
    ({"robot_mass": 5000}, ["robot_mass 5000", "kg"]),
    ({"speed": "2kg"}, ["speed", "'kg' is not a speed"]),
    ({"robot_mass": math.nan}, ["robot_mass must be finite", "nan"]),
    ({"speed": math.inf}, ["speed must be finite", "inf"]),
    ({"head_mass": -math.inf}, ["head_mass must be finite", "fixed"]),
    ({"covering_thickness": [1]}, ["covering_thickness: expected a number"]),
    ({"thresholds": "paper"}, ["thresholds", "'cumulative' or 'literal'", "paper"]),
    ({"safety_factor": 0.5}, ["safety_factor must be in [1, 100]", "0.5"]),
    ({"head_area": "cheek"}, ["head_area must be one of frontal, temporo-parietal, nasal", '"cheek"']),
    ({"head_area": 3}, ["head_area must be one of frontal", '(got "3")']),
    ({"covering_law": "soft"}, ["covering_law: expected 'auto', 'foam' or 'hertz'", "soft"]),
    ({"method": "euler"}, ["method: expected exact, cvode or one of", "euler"]),
    ({"method": "exact", "history": True}, ["method='exact' computes no time history"]),
    ({"rtol": 1e-6}, ["rtol applies to the time path only"]),
    ({"material": "polystyrene", "covering_modulus": 1e6}, ["give either material or covering_modulus"]),
    ({"method": "cvode", "rtol": 1.0}, ["rtol must be in [1e-14, 1e-2]", "got 1"]),
    ({"robot_mass": 10**400}, ["robot_mass: 10000000000000000000... (401 digits) is beyond a double"]),
    ({"speed": -(10**400)}, ["speed: ", "is beyond a double", "m/s"]),
])
def test_bad_input_names_the_keyword_and_the_value(kwargs, words):
    with pytest.raises(ValueError) as error:
        call(covopt.simulate, **kwargs)
    for word in words:
        assert word in str(error.value)


def test_the_head_area_sets_the_fracture_verdict():
    # The 2.8 kN bare hit: below the forehead's 3114 N, over the nose's 450 N.
    trial = dict(robot_mass=5.145, robot_radius="60mm", speed=2.3, covering_thickness=0.0)
    forehead = covopt.simulate(covopt.Scene(**trial)).to_dict()
    nose = covopt.simulate(covopt.Scene(head_area="nasal", **trial)).to_dict()
    assert forehead["fracture"]["area"] == "frontal" and forehead["fracture"]["safe"]
    assert forehead["safe"]
    assert nose["fracture"]["limit_N"] == 450.0
    assert nose["fracture"]["value_N"] == forehead["fracture"]["value_N"] > 2700.0
    assert not nose["fracture"]["safe"] and not nose["safe"]
    assert nose["laceration"]["safe"] and nose["contusion"]["safe"]


def test_an_unknown_keyword_is_a_type_error():
    with pytest.raises(TypeError):
        covopt.simulate(robot_masss=10.0).to_dict()


def test_a_failed_computation_raises_computation_error_with_its_status(cli):
    with pytest.raises(covopt.ComputationError) as error:
        covopt.simulate(method="cvode", max_steps=10).to_dict()
    assert error.value.status == "step-limit"
    assert isinstance(error.value, RuntimeError)
    code, out, err = cli("simulate", "--method", "cvode", "--max-steps", "10")
    assert code == 1 and out == ""
    assert str(error.value) in err


def test_threads_get_the_same_results_as_one_call():
    expected = covopt.simulate(covopt.Scene(speed=3.0), history=True).max_penetration_m
    results = []

    def work():
        for _ in range(5):
            results.append(covopt.simulate(covopt.Scene(speed=3.0), history=True).max_penetration_m)

    threads = [threading.Thread(target=work) for _ in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert results == [expected] * 20


# Issue 22: the warnings the CLI adds about its inputs, the same list in Python. Where the CLI
# names a flag as a value's source ("from --safety-factor '2'"), Python names the keyword
# ("from safety_factor='2'"); everything else is word for word.
WARNING_SCENES = [
    ({"material": "XPS Foamular 250"}, ["--material", "XPS Foamular 250"]),
    ({"material": "XPS Foamular 250", "covering_thickness": 0.0},
     ["--material", "XPS Foamular 250", "--covering-thickness", "0"]),
    ({"covering_thickness": 0.0, "covering_modulus": "5MPa", "covering_poisson": "0.3"},
     ["--covering-thickness", "0", "--covering-modulus", "5MPa", "--covering-poisson", "0.3"]),
    ({"safety_factor": "2"}, ["--safety-factor", "2"]),
    ({"safety_factor": "1.5", "material": "XPS Foamular 250"},
     ["--safety-factor", "1.5", "--material", "XPS Foamular 250"]),
]


def as_keywords(warnings):
    """The CLI's warnings with each source flag spelled as Python's keyword:
    "--covering-modulus '5MPa'" -> "covering_modulus='5MPa'"."""
    import re
    return [re.sub(r"--([a-z-]+) '([^']*)'", lambda m: m[1].replace("-", "_") + "='" + m[2] + "'", w)
            for w in warnings]


@pytest.mark.parametrize("kwargs,flags", WARNING_SCENES)
def test_simulate_returns_the_warnings_the_cli_prints(cli_json, kwargs, flags):
    ours = call(covopt.simulate, **kwargs)["warnings"]
    theirs = cli_json("simulate", "--json", *flags)["warnings"]
    assert ours, "the scene has an input warning"
    assert ours == as_keywords(theirs)


def test_an_unknown_poisson_ratio_is_warned_word_for_word(cli_json):
    ours = covopt.simulate(covopt.Scene(material="XPS Foamular 250")).warnings
    assert ours == cli_json("simulate", "--json", "--material", "XPS Foamular 250")["warnings"]
    assert any("ν unknown, 0.25 assumed" in w for w in ours)
