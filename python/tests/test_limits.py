"""limits= (the CLI's --limits FILE): a body-region table of one's own. The example table
(every force and pressure of ISO/TS 15066 Annex A x 0.8) gives the CLI's JSON for the same
input, scales every bare limit speed by exactly 0.8, names the table and the SHA-256 of its
bytes, and a bad table raises ValueError naming file:line:column."""

import hashlib
import pathlib

import pytest

import covopt

ROOT = pathlib.Path(__file__).resolve().parents[2]
COMPANY = str(ROOT / "materials" / "examples" / "company_limits_0.8_iso.toml")
BOTH = "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M"


def _digest(path):
    return hashlib.sha256(pathlib.Path(path).read_bytes()).hexdigest()


def test_body_regions_with_limits_is_the_cli_s_list(cli_json):
    own = covopt.body_regions(limits=COMPANY)
    assert [r.to_dict() for r in own] == cli_json("body-regions", "list", "--limits", COMPANY, "--json")
    iso = covopt.body_regions()
    for a, b in zip(iso, own):
        assert b.quasi_static_force_N == pytest.approx(0.8 * a.quasi_static_force_N, rel=1e-12)
        assert b.stiffness_N_per_m == a.stiffness_N_per_m
        assert b.to_dict()["limit_table"]["sha256"] == _digest(COMPANY)
        assert a.to_dict()["limit_table"]["edition"] == BOTH
    assert covopt.body_region_limits("chest", limits=pathlib.Path(COMPANY)).force_N == pytest.approx(224.0)


def test_speed_limit_with_limits_is_the_cli_s_and_scales_bare_speeds_by_0_8(cli_json):
    scene = covopt.Scene(robot_mass=10.0, covering_thickness=0.0)
    own = covopt.speed_limit(scene, body_region="all", contact_area="1cm2", limits=COMPANY)
    assert own == cli_json("speed-limit", "--body-region", "all", "--robot-mass", "10kg", "--covering-thickness",
                           "0", "--contact-area", "1cm2", "--limits", COMPANY, "--json")
    iso = covopt.speed_limit(scene, body_region="all", contact_area="1cm2")
    for a, b in zip(iso.to_dict()["rows"], own.to_dict()["rows"]):
        if a["region"] == "head":
            continue
        assert b["bare_max_speed_m_per_s"] == pytest.approx(0.8 * a["bare_max_speed_m_per_s"], rel=1e-12)
    table = own.to_dict()["summary"]["limit_tables"][0]
    assert table["source"] == COMPANY
    assert table["sha256"] == _digest(COMPANY)
    assert iso.to_dict()["summary"]["limit_tables"][0]["source"] == "built-in"
    assert iso.to_dict()["summary"]["standards"][0] == BOTH


def test_a_bad_table_raises_value_error_with_file_line_column(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(pathlib.Path(COMPANY).read_text().replace("transient_factor = 2\n", "transient_factor = 12\n", 1))
    with pytest.raises(ValueError, match=rf"^{bad}:\d+:\d+: region 'neck': transient_factor must be a number >= 1"):
        covopt.speed_limit(covopt.Scene(robot_mass=10.0), body_region="neck", limits=str(bad))
    with pytest.raises(ValueError, match=r"limits applies to an ISO/TS 15066 body region"):
        covopt.speed_limit(covopt.Scene(robot_mass=10.0), limits=COMPANY)
    with pytest.raises(ValueError, match=r"limits: expected the path"):
        covopt.body_regions(limits=3)
