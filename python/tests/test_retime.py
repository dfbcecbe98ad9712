"""covopt.retime: the dict is the CLI's --json for the same input; the re-timed program written
with output= is safe when audited again and keeps the joints' limits; bad input is ValueError
naming the keyword; audit_many(retime=True) re-times each program on dask and equals the serial
run."""

import csv
import math
import pathlib

import pytest

import covopt
from conftest import without_provenance

ROOT = pathlib.Path(__file__).resolve().parents[2]
FR3 = ROOT / "robot" / "models" / "franka_fr3.urdf"
PICK = ROOT / "robot" / "models" / "franka_fr3_pick.csv"
SCENE = dict(covering_thickness="10mm", covering_modulus="0.5MPa", covering_poisson=0.45)
FLAGS = ["--covering-thickness", "10mm", "--covering-modulus", "0.5MPa", "--covering-poisson", "0.45"]
# A coarse surface: quick.
OPTIONS = dict(contact_area="1cm2", flat_face_radius="20mm", surface_spacing="100mm")
OPTION_FLAGS = ["--contact-area", "1cm2", "--flat-face-radius", "20mm", "--surface-spacing", "100mm"]


def test_retime_returns_the_cli_json_object(cli_json):
    expected = cli_json("retime", "--urdf", str(FR3), "--tip", "fr3_link8", "--trajectory", str(PICK), *FLAGS,
                        *OPTION_FLAGS, "--joint-accel-limit", "10", "--thickness", "5mm,20mm", "--json")
    result = covopt.retime(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), joint_accel_limit=10,
                           thickness=["5mm", "20mm"], **OPTIONS)
    assert isinstance(result, covopt.Retime)
    assert without_provenance(result) == without_provenance(expected)
    assert result.status == "safe"
    assert result.cycle_time_s < result.uniform_cycle_time_s


def test_retime_output_is_safe_when_audited_again_and_keeps_the_joint_limits(tmp_path):
    out = tmp_path / "retimed.csv"
    accel = [10, 10, 10, 10, 12, 12, 12]
    result = covopt.retime(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), joint_accel_limit=accel,
                           joint_speed_limit=2.0, output=out, **OPTIONS)
    assert result.status == "safe"
    again = covopt.audit(FR3, "fr3_link8", out, scene=covopt.Scene(**SCENE), keep_ratio_over_time=False, **OPTIONS)
    assert again.safe_speed_scale >= 1 - 1e-6
    rows = [[float(x) for x in row] for row in csv.reader(out.open()) if row and not row[0].startswith(("#", "t"))]
    assert len(rows) == result.sample_count
    assert rows[-1][0] == pytest.approx(result.cycle_time_s, rel=1e-9)
    for row in rows:
        assert all(abs(v) <= 2.0 * (1 + 1e-6) for v in row[8:15])
    for a, b in zip(rows, rows[1:]):
        for k in range(7):
            assert abs(b[8 + k] - a[8 + k]) / (b[0] - a[0]) <= accel[k] * (1 + 1e-3)


@pytest.mark.parametrize("keywords, match", [
    ({}, "joint_accel_limit"),
    ({"joint_accel_limit": -10}, "joint_accel_limit"),
    ({"joint_accel_limit": math.nan}, "joint_accel_limit"),
    ({"joint_accel_limit": [10, 10]}, "joint_accel_limit"),
    ({"joint_accel_limit": "fast"}, "joint_accel_limit"),
    ({"joint_accel_limit": 10, "joint_speed_limit": 0}, "joint_speed_limit"),
    ({"joint_accel_limit": 10, "thickness": "0..40mm:1"}, "thickness"),
    ({"joint_accel_limit": 10, "materials": ["no such foam"], "thickness": "5mm,10mm"}, "materials"),
    ({"joint_accel_limit": 10, "materials": ["PU foam PORON 4701-30 320"]}, "thickness"),
])
def test_retime_bad_input_is_a_value_error_naming_the_keyword(keywords, match):
    with pytest.raises(ValueError, match=match):
        covopt.retime(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), **OPTIONS, **keywords)


def test_audit_many_retimes_two_programs_as_the_serial_runs(tmp_path):
    pytest.importorskip("dask.distributed")
    slow = tmp_path / "pick_slow.csv"  # the pick move at half its speed
    lines = [line for line in PICK.read_text().splitlines() if line and not line.startswith("#")]
    rows = [lines[0]]
    for line in lines[1:]:
        v = [float(x) for x in line.split(",")]
        rows.append(",".join(repr(x) for x in [2 * v[0], *v[1:8], *[x / 2 for x in v[8:]]]))
    slow.write_text("\n".join(rows) + "\n")
    scene = covopt.Scene(**SCENE)
    results = covopt.audit_many([PICK, slow], FR3, "fr3_link8", scene=scene, retime=True, joint_accel_limit=10,
                                n_workers=2, **OPTIONS)
    assert [type(r) for r in results] == [covopt.Retime, covopt.Retime]
    for program, result in zip([PICK, slow], results):
        serial = covopt.retime(FR3, "fr3_link8", program, scene=scene, joint_accel_limit=10, **OPTIONS)
        assert without_provenance(result) == without_provenance(serial)
    # The same path: the slower program re-times to no shorter a cycle than the fast one's.
    assert results[1].cycle_time_s >= results[0].cycle_time_s * (1 - 1e-9)
    with pytest.raises(ValueError, match="retime"):
        covopt.audit_many([PICK], FR3, "fr3_link8", scene=scene, retime="yes", joint_accel_limit=10)
