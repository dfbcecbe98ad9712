"""The oracle keywords of covopt.optimize and the speed-limit calls: the same dict as
`covopt optimize --oracle ... --json`, the time path's optimum and speed limit agreeing with the
exact path's to its tolerance, and bad input as ValueError naming the keyword."""

import math

import pytest

import covopt

from test_optimize import without_times


def test_optimize_on_the_time_path_returns_the_cli_json_object(cli_json):
    ours = covopt.optimize(oracle="time-path", rtol=1e-7, materials=["XPS Foamular 250"])
    theirs = cli_json("optimize", "--json", "--oracle", "time-path", "--rtol", "1e-7",
                      "--material", "XPS Foamular 250")
    assert without_times(ours) == without_times(theirs)
    oracle = ours["solver"]["oracle"]
    assert oracle["name"] == "time-path"
    assert oracle["method"] == "arkode-erk54"
    assert oracle["gradient"] == "cvodes-forward-sensitivities"
    exact = covopt.optimize(materials=["XPS Foamular 250"])
    assert exact["solver"]["oracle"]["name"] == "exact"
    b_time = ours["continuous_optimum"]["thickness_m"]
    b_exact = exact["continuous_optimum"]["thickness_m"]
    assert abs(b_time / b_exact - 1) <= 100 * 1e-7


def test_the_speed_limit_on_the_time_path_matches_the_exact_one():
    exact = covopt.max_safe_speed()
    time = covopt.max_safe_speed(oracle="time-path", rtol=1e-10)
    assert math.isclose(time["max_safe_speed_m_per_s"], exact["max_safe_speed_m_per_s"], rel_tol=1e-7)
    table = covopt.speed_limit(oracle="time-path", method="cvode", rtol=1e-9)
    assert table["oracle"]["name"] == "time-path"
    assert table["oracle"]["method"] == "cvode-adams"
    assert table["oracle"]["search"] == "bracketed-bisection"


@pytest.mark.parametrize("kwargs,message", [
    ({"oracle": "foo"}, "oracle: expected 'auto', 'exact' or 'time-path' (got 'foo')"),
    ({"oracle": "time-path", "method": "exact"}, "contradicts oracle='time-path'"),
    ({"oracle": "time-path", "rtol": 0}, "rtol must be in [1e-14, 1e-2]"),
    ({"oracle": "exact", "rtol": 1e-6}, "rtol applies to the time path"),
    ({"method": "rk4"}, "method: expected exact, cvode or one of"),
])
def test_bad_oracle_keywords_raise_value_error(kwargs, message):
    with pytest.raises(ValueError, match=None) as error:
        covopt.optimize(**kwargs)
    assert message in str(error.value)
