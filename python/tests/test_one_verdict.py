"""One target, one verdict (issue 34): covopt.simulate judges with the CLI's library call, so a
bottomed-out or crushed covering is not safe in Python either, and its verdict is the CLI's."""
import json
import os
import subprocess

import covopt


def _cli_json(*args):
    cli = os.environ.get("COVOPT_CLI")
    if not cli:
        return None
    return json.loads(subprocess.run([cli, "simulate", *args, "--json"], check=True, capture_output=True,
                                     text=True).stdout)


def test_a_bottomed_out_covering_is_not_safe():
    result = covopt.simulate(covopt.Scene(covering_thickness="3mm", covering_modulus="1MPa"))
    assert result.fully_compressed
    assert result.safe is False
    verdict = result.to_dict()["verdict"]
    assert verdict["design_rules_met"] is False
    assert result.verdict.design_rules_met is False
    criteria = {c["name"]: c for c in verdict["criteria"]}
    assert criteria["full-compression"]["part"] == "design-rule"
    assert criteria["full-compression"]["passed"] is False
    cli = _cli_json("--covering-thickness", "3mm", "--covering-modulus", "1MPa")
    if cli is not None:
        assert cli["verdict"] == verdict


def test_a_crushed_covering_is_not_safe_and_crush_governs():
    result = covopt.simulate(covopt.Scene(covering_thickness="16mm", material="XPS Foamular 250"))
    assert result.safe is False
    verdict = result.to_dict()["verdict"]
    assert verdict["governing"] == "crush"
    assert result.to_dict()["crush"]["ratio"] > 10
    cli = _cli_json("--covering-thickness", "16mm", "--material", "XPS Foamular 250")
    if cli is not None:
        assert cli["verdict"] == verdict


def test_the_derated_limits_are_given_for_every_criterion():
    verdict = covopt.simulate(covopt.Scene(safety_factor=1.2)).to_dict()["verdict"]
    assert [c["name"] for c in verdict["criteria"]] == ["laceration", "contusion", "fracture", "full-compression",
                                                         "law-validity"]
    for c in verdict["criteria"]:
        if c["name"] == "law-validity":  # the model's range: not derated by the safety factor
            assert c["derated_limit"] == c["limit"] == 1.0
            continue
        assert abs(c["derated_limit"] - c["limit"] / 1.2) <= 1e-12 * c["limit"]
    assert verdict["safety_factor"] == 1.2
    assert verdict["margin_percent"] == verdict["margin"] * 100
