"""The result summary: every reportable result carries "summary" (the library's, as the CLI's
--json has it), its verdict is the result's own, and repr prints its first line, made by the
library (covopt._covopt.summary_headline), so the rule is written once."""

import pathlib

import pytest

import covopt
from covopt import _covopt

ROOT = pathlib.Path(__file__).resolve().parents[2]
FR3 = ROOT / "robot" / "models" / "franka_fr3.urdf"
PICK = ROOT / "robot" / "models" / "franka_fr3_pick.csv"


@pytest.mark.parametrize("speed", [0.5, 1.8, 3.0])
def test_simulate_summary_is_its_verdict(speed):
    r = covopt.simulate(covopt.Scene(speed=speed))
    s = r.to_dict()["summary"]
    assert s["safe"] == r.safe
    assert s["governing"]["ratio"] == r.verdict.governing_ratio
    assert s["margin"] == r.verdict.margin
    word = "UNSAFE" if not r.safe else "SAFE" if r.verdict.margin >= 0.10 else "MARGINAL"
    assert s["state"] == word.lower()
    assert repr(r).startswith(f"Simulation({word}, margin ")
    assert "head (frontal)" in repr(r)


def test_optimize_summary_is_the_recommended_designs_verdict():
    d = covopt.optimize(covopt.Scene(speed=1.5))
    s = d.to_dict()["summary"]
    assert s["safe"] == d.recommendation.safe
    assert s["margin"] == pytest.approx(d.recommendation.margin, rel=1e-12)
    assert s["covering"]["material"] == d.recommendation.material
    assert repr(d).startswith("Design(SAFE, margin ") or repr(d).startswith("Design(MARGINAL, margin ")
    # The one-sentence answer is "message".
    assert d.message.startswith("Recommended: ")


def test_speed_limit_summary_is_a_table_of_limits():
    t = covopt.speed_limit(covopt.Scene(), values=[2, 20])
    s = t.to_dict()["summary"]
    assert s["kind"] == "limits"
    assert [row["value"] for row in s["limits"]] == [row.max_safe_speed_m_per_s for row in t.rows]
    assert repr(t).startswith("SpeedLimitTable(LIMITS: ")


def test_trajectory_and_audit_summaries_are_their_verdicts():
    c = covopt.check_trajectory(FR3, "fr3_link8", PICK)
    s = c.to_dict()["summary"]
    assert s["safe"] == (c.status == "safe")
    assert s["robot"]["speed_m_per_s"] == c.worst_sample.speed_m_per_s
    a = covopt.audit(FR3, "fr3_link8", PICK, contact_area="1cm2",
                     scene=covopt.Scene(covering_thickness="10mm", covering_modulus="0.5MPa", covering_poisson=0.45))
    s = a.to_dict()["summary"]
    assert s["safe"] == (a.status == "safe")
    assert s["governing"]["ratio"] == a.limiting.governing_ratio


def test_summary_text_is_the_clis_and_names_a_missing_summary():
    r = covopt.simulate(covopt.Scene(speed=1.0))
    import json
    text = _covopt.summary_text(json.dumps(r.to_dict()))
    assert text.splitlines()[0] == _covopt.summary_headline(json.dumps(r.to_dict()))
    assert "head (frontal) contusion: " in text
    with pytest.raises(ValueError, match="summary"):
        _covopt.summary_text('{"safe": true}')
