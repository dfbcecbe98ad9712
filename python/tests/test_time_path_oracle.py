"""The oracle keywords of covopt.optimize and the speed-limit calls: the same dict as
`covopt optimize --oracle ... --json`, the time path's optimum and speed limit agreeing with the
exact path's to its tolerance, and bad input as ValueError naming the keyword."""

import math

import pytest

import covopt
from conftest import same_provenance, without_provenance
from calls import call

from test_optimize import without_times


def test_optimize_on_the_time_path_returns_the_cli_json_object(cli_json):
    ours = covopt.optimize(oracle="time-path", rtol=1e-7, materials=["XPS Foamular 250"]).to_dict()
    theirs = cli_json("optimize", "--json", "--oracle", "time-path", "--rtol", "1e-7",
                      "--material", "XPS Foamular 250")
    assert without_times(without_provenance(ours)) == without_times(without_provenance(theirs))
    assert same_provenance(ours["provenance"], theirs["provenance"])
    oracle = ours["solver"]["oracle"]
    assert oracle["name"] == "time-path"
    assert oracle["method"] == "arkode-erk54"
    assert oracle["gradient"] == "cvodes-forward-sensitivities"
    exact = covopt.optimize(materials=["XPS Foamular 250"])
    assert exact.solver.oracle.name == "exact"
    b_time = ours["continuous_optimum"]["thickness_m"]
    b_exact = exact.continuous_optimum.thickness_m
    assert abs(b_time / b_exact - 1) <= 100 * 1e-7


def test_the_speed_limit_on_the_time_path_matches_the_exact_one():
    exact = covopt.max_safe_speed()
    time = covopt.max_safe_speed(oracle="time-path", rtol=1e-10)
    assert math.isclose(time.max_safe_speed_m_per_s, exact.max_safe_speed_m_per_s, rel_tol=1e-7)
    table = covopt.speed_limit(oracle="time-path", method="cvode", rtol=1e-9)
    assert table.oracle.name == "time-path"
    assert table.oracle.method == "cvode-adams"
    assert table.oracle.search == "bracketed-bisection"


@pytest.mark.parametrize("kwargs,message", [
    ({"oracle": "foo"}, "oracle: expected 'auto', 'exact' or 'time-path' (got 'foo')"),
    ({"oracle": "time-path", "method": "exact"}, "contradicts oracle='time-path'"),
    ({"oracle": "time-path", "rtol": 0}, "rtol must be in [1e-14, 1e-2]"),
    ({"oracle": "exact", "rtol": 1e-6}, "rtol applies to the time path"),
    ({"method": "rk4"}, "method: expected exact, cvode or one of"),
])
def test_bad_oracle_keywords_raise_value_error(kwargs, message):
    with pytest.raises(ValueError, match=None) as error:
        call(covopt.optimize, **kwargs)
    assert message in str(error.value)


def test_a_failed_time_path_raises_computation_error_never_a_limit():
    # 10 steps (max_steps' smallest value) cannot carry a braked contact to separation.
    for call in (covopt.max_safe_speed, covopt.max_safe_mass, covopt.speed_limit):
        with pytest.raises(covopt.ComputationError) as error:
            call(covopt.Scene(braking="200m/s2"), max_steps=10)
        assert error.value.status == "evaluation-failed"
        assert "the oracle failed at" in str(error.value) and "step-limit" in str(error.value)
    answered = covopt.max_safe_speed(covopt.Scene(braking="200m/s2"),
                                     max_steps=200000)  # the failure was the step limit's
    assert answered.status == "limited"
    with pytest.raises(covopt.ComputationError) as error:
        covopt.optimize(covopt.Scene(braking="50m/s2"), max_steps=10,
                        materials=["polystyrene foam 27.6"]).to_dict()
    assert error.value.status == "oracle-failed"


@pytest.mark.parametrize("kwargs,message", [
    ({"oracle": "time-path", "max_steps": 5}, "max_steps must be >= 10 (got 5)"),
    ({"oracle": "time-path", "max_steps": 1e4}, "max_steps: expected an integer"),
    ({"oracle": "exact", "max_steps": 1000}, "max_steps applies to the time path"),
])
def test_bad_max_steps_raise_value_error(kwargs, message):
    for call in (covopt.optimize, covopt.max_safe_speed):
        with pytest.raises(ValueError) as error:
            call(**kwargs)
        assert message in str(error.value)
