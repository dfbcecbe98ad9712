"""covopt.audit_many keeps every program's result when one fails (an AuditFailure naming the
program and its error; errors="raise" raises AuditManyError holding them all) and runs from a
script without ``if __name__ == "__main__":`` (threads by default; processes=True there is one
clear RuntimeError naming the guard, before any process starts; neither leaks a semaphore).
Also the audit's inputs of issue 33: a bool keyword must be a bool (design="yes" is refused),
payload_inertia takes a symmetric 3 x 3 matrix (np.eye(3)) as well as its six numbers, and a
link-coverings file or dict refuses a negative thickness and a Poisson ratio out of
covering.poisson's range with the place of the value; the guide's example file is read."""

import os
import pathlib
import re
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import covopt
from conftest import covopt_binary, without_provenance

ROOT = pathlib.Path(__file__).resolve().parents[2]
FR3 = ROOT / "robot" / "models" / "franka_fr3.urdf"
PICK = ROOT / "robot" / "models" / "franka_fr3_pick.csv"
SCENE = dict(covering_thickness="10mm", covering_modulus="0.5MPa", covering_poisson=0.45)
# One region and no ratio-over-time matrix: a quick audit.
QUICK = dict(contact_area="1cm2", flat_face_radius="20mm", body_region="chest", keep_ratio_over_time=False)


def test_one_bad_program_keeps_the_others(tmp_path):
    pytest.importorskip("dask.distributed")
    bad = tmp_path / "bad.csv"
    bad.write_text("time_s,q1\n0,nan\n")
    short = {"time_s": [0.0], "positions": [[0.0] * 7], "velocities": [[0.0] * 6]}  # 6 velocities for 7 joints
    scene = covopt.Scene(**SCENE)
    results = covopt.audit_many([PICK, bad, short, PICK], FR3, "fr3_link8", scene=scene, **QUICK)
    assert [r.ok for r in results] == [True, False, False, True]
    serial = covopt.audit(FR3, "fr3_link8", PICK, scene=scene, **QUICK)
    assert isinstance(results[0], covopt.Audit)
    assert without_provenance(results[0]) == without_provenance(serial)
    assert without_provenance(results[3]) == without_provenance(results[0])  # the date is each run's own
    failure = results[1]
    assert isinstance(failure, covopt.AuditFailure)
    assert (failure.index, failure.program, failure.error_type) == (1, str(bad), "ValueError")
    assert isinstance(failure.error, ValueError) and failure.message == str(failure.error)
    assert str(failure).startswith(f"{bad}: ValueError: ")
    with pytest.raises(ValueError):  # the same error as the serial call
        covopt.audit(FR3, "fr3_link8", bad, scene=scene, **QUICK)
    assert (results[2].program, results[2].error_type) == ("trajectories[2]", "ValueError")
    # errors="raise": one exception naming every failed program, holding every result.
    with pytest.raises(covopt.AuditManyError, match=r"2 of 4 programs failed: .*bad\.csv: ValueError: .*"
                                                    r"trajectories\[2\]: ValueError") as raised:
        covopt.audit_many([PICK, bad, short, PICK], FR3, "fr3_link8", scene=scene, errors="raise", **QUICK)
    assert [r.ok for r in raised.value.results] == [True, False, False, True]
    assert raised.value.failures[0].program == str(bad)
    with pytest.raises(ValueError, match="errors"):
        covopt.audit_many([PICK], FR3, "fr3_link8", scene=scene, errors="ignore", **QUICK)


def run_script(tmp_path, body):
    """Runs `body` as a script file in a fresh interpreter; (exit status, stdout, stderr)."""
    script = tmp_path / "programs.py"
    script.write_text(textwrap.dedent(body).format(FR3=str(FR3), PICK=str(PICK), SCENE=SCENE, QUICK=QUICK))
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(pathlib.Path(covopt.__file__).parents[1]),
                                                       os.environ.get("PYTHONPATH", "")]))
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, cwd=tmp_path, env=env,
                          timeout=300, check=False)
    return done.returncode, done.stdout, done.stderr


SCRIPT = """\
import covopt
results = covopt.audit_many([{PICK!r}, {PICK!r}], {FR3!r}, "fr3_link8", scene=covopt.Scene(**{SCENE!r}),
                            **{QUICK!r}{extra})
def same(a, b):  # equal apart from the provenance, whose date is each run's own
    return ({{k: v for k, v in a.to_dict().items() if k != "provenance"}}
            == {{k: v for k, v in b.to_dict().items() if k != "provenance"}})
print([r.ok for r in results], same(results[0], results[1]), results[0].status)
"""


def test_a_script_without_the_main_guard_runs(tmp_path):
    pytest.importorskip("dask.distributed")
    status, out, err = run_script(tmp_path, SCRIPT.replace("{extra}", ""))
    assert status == 0, err
    assert out == f"[True, True] True {covopt.audit(FR3, 'fr3_link8', PICK, scene=covopt.Scene(**SCENE), **QUICK).status}\n"
    assert "leaked semaphore" not in err and "Traceback" not in err


def test_processes_without_the_main_guard_is_one_clear_error(tmp_path):
    pytest.importorskip("dask.distributed")
    status, out, err = run_script(tmp_path, SCRIPT.replace("{extra}", ", processes=True"))
    assert status == 1 and out == ""
    assert "leaked semaphore" not in err
    assert err.count("Traceback") == 1  # the script's own error, no worker's
    last = err.strip().splitlines()[-1]
    assert re.match(r"RuntimeError: audit_many\(processes=True\) is called at .*programs\.py:2 outside "
                    r"'if __name__ == \"__main__\":'", last), last
    assert "processes=False" in last


def test_processes_under_the_main_guard_run(tmp_path):
    pytest.importorskip("dask.distributed")
    guarded = "if __name__ == \"__main__\":\n" + textwrap.indent(SCRIPT.replace("{extra}", ", processes=True"), "    ")
    status, out, err = run_script(tmp_path, guarded)
    assert status == 0, err
    assert out.startswith("[True, True] True ")
    assert "leaked semaphore" not in err


@pytest.mark.parametrize("value", ["yes", "no", 1, 0, [True]])
def test_a_bool_keyword_must_be_a_bool(value):
    with pytest.raises(ValueError, match=r"^design: expected True or False \(got "):
        covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), design=value, **QUICK)
    with pytest.raises(ValueError, match=r"^history: expected True or False"):
        covopt.simulate(covopt.Scene(), history=value)


def test_numpy_bools_are_bools():
    a = covopt.simulate(covopt.Scene(), history=np.False_)
    assert without_provenance(a) == without_provenance(covopt.simulate(covopt.Scene(), history=False))
    assert "history" in covopt.simulate(covopt.Scene(), history=np.True_).to_dict()


FR3_READY = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]


def test_payload_inertia_takes_a_symmetric_3_by_3_matrix():
    six = covopt.reflected_mass(str(FR3), "fr3_link8", FR3_READY, payload_mass=1.0,
                                payload_inertia=(0.01, 0.02, 0.03, 0.001, 0, 0))
    matrix = covopt.reflected_mass(str(FR3), "fr3_link8", FR3_READY, payload_mass=1.0,
                                   payload_inertia=np.array([[0.01, 0.001, 0], [0.001, 0.02, 0], [0, 0, 0.03]]))
    assert without_provenance(matrix) == without_provenance(six)
    # np.eye(3) [kg m²] is a valid inertia (1 kg m² about each axis).
    eye = covopt.reflected_mass(str(FR3), "fr3_link8", FR3_READY, payload_mass=1.0, payload_inertia=np.eye(3))
    assert without_provenance(eye) == without_provenance(covopt.reflected_mass(
        str(FR3), "fr3_link8", FR3_READY, payload_mass=1.0, payload_inertia=(1, 1, 1, 0, 0, 0)))
    audit_eye = covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), payload_mass=1.0,
                             payload_inertia=np.eye(3), **QUICK)
    audit_six = covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), payload_mass=1.0,
                             payload_inertia=[1, 1, 1, 0, 0, 0], **QUICK)
    assert without_provenance(audit_eye) == without_provenance(audit_six)


@pytest.mark.parametrize("inertia, match", [
    (np.eye(2), r"payload_inertia: expected 6 numbers \(ixx, iyy, izz, ixy, ixz, iyz\) or a symmetric 3 x 3 "
                r"matrix, in kg m² about the centre of mass \(got 2 rows\)"),
    ((1, 2, 3), r"payload_inertia: expected 6 numbers .* \(got 3 numbers\)"),
    (np.ones((3, 4)), r"payload_inertia: .* \(got a row payload_inertia\[0\] of 4 numbers\)"),
    ([[1, 0.1, 0], [0, 1, 0], [0, 0, 1]], r"payload_inertia: a 3 x 3 inertia must be symmetric"),
    ("eye", r"payload_inertia: expected 6 numbers"),
    ([[1, 0, 0], [0, 1, 0], [0, 0, "x"]], r"payload_inertia\[2\]\[2\]: expected a number"),
])
def test_payload_inertia_of_another_shape_is_a_value_error_naming_it(inertia, match):
    with pytest.raises(ValueError, match=match):
        covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), payload_mass=1.0,
                     payload_inertia=inertia, **QUICK)
    with pytest.raises(ValueError, match=match):
        covopt.reflected_mass(str(FR3), "fr3_link8", FR3_READY, payload_mass=1.0, payload_inertia=inertia)


@pytest.mark.parametrize("fields, match", [
    ({"modulus": "0.5MPa", "thickness": "-5mm"}, r"thickness must be 0 \(bare\) or in \[0\.1 mm, 1000 mm\] "
                                                r"\(got -5 mm\)"),
    ({"modulus": "0.5MPa", "thickness": "0.01mm"}, r"thickness must be 0 \(bare\)"),
    ({"modulus": "0.5MPa", "poisson": -1, "thickness": "5mm"}, r"poisson must be in \(-1, 0\.5\]"),
    ({"modulus": "0.5MPa", "poisson": 0.6, "thickness": "5mm"}, r"poisson must be in \(-1, 0\.5\]"),
])
def test_link_coverings_values_out_of_range_are_refused(tmp_path, fields, match):
    scene = covopt.Scene(**SCENE)
    with pytest.raises(ValueError, match=r"link_coverings\['fr3_link6'\] " + match):
        covopt.audit(FR3, "fr3_link8", PICK, scene=scene, link_coverings={"fr3_link6": fields}, **QUICK)
    path = tmp_path / "links.toml"
    path.write_text('[[link]]\nname = "fr3_link6"\n' +
                    "".join(f"{k} = {v!r}\n".replace("'", '"') for k, v in fields.items()))
    with pytest.raises(ValueError, match=re.escape(str(path)) + r":\d+:\d+: link 'fr3_link6' " + match):
        covopt.audit(FR3, "fr3_link8", PICK, scene=scene, link_coverings=path, **QUICK)


def test_link_coverings_take_covering_poisson_s_range():
    # -0.5 and 0.5 are good covering.poisson values; the file once refused both.
    scene = covopt.Scene(**SCENE)
    for nu in (-0.5, 0.5):
        result = covopt.audit(FR3, "fr3_link8", PICK, scene=scene, **QUICK,
                              link_coverings={"fr3_link6": {"modulus": "0.5MPa", "poisson": nu, "thickness": "5mm"}})
        [covering] = [c for c in result.to_dict()["coverings"] if c["link"] == "fr3_link6"]
        assert covering["poisson_ratio"] == nu


def test_a_link_name_with_a_newline_is_one_line():
    with pytest.raises(ValueError) as raised:
        covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), **QUICK,
                     link_coverings={"fr3\nlink6": {"thickness": 0}})
    assert "\n" not in str(raised.value)
    assert "a link name has no control characters such as a newline (got 'fr3\\nlink6')" in str(raised.value)


def test_the_guides_link_coverings_example_is_read(tmp_path):
    """docs/guide/audit.md's example file, as the CLI reads it: every material in the catalog."""
    binary = covopt_binary()
    if not binary:
        pytest.fail("no covopt binary")
    guide = (ROOT / "docs" / "guide" / "audit.md").read_text()
    block = guide.split("### Link-covering files", 1)[1].split("\n\n    [[link]]", 1)[1]
    lines = ["[[link]]"]
    for line in block.splitlines():
        if line and not line.startswith("    "):
            break
        lines.append(line[4:])
    example = tmp_path / "links.toml"
    example.write_text("\n".join(lines) + "\n")
    names = re.findall(r'^name = "([^"]+)"', example.read_text(), re.M)
    assert len(names) == 3
    done = subprocess.run([binary, "audit", "--urdf", str(FR3), "--tip", "fr3_link8", "--trajectory", str(PICK),
                           "--link-coverings", str(example), "--body-region", "chest", "--contact-area", "1cm2",
                           "--json"], capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr


@pytest.mark.parametrize("link_coverings, match", [
    ({"fr3_link6": 5}, r"^link_coverings\['fr3_link6'\]: expected a dict of material or modulus"),
    ({"fr3_link6": {"material": 5, "thickness": "5mm"}},
     r"^link_coverings\['fr3_link6'\] material: expected a catalog name \(a string\), got 5"),
    (5, r"^link_coverings: expected a link-covering file \(a path\) or a dict"),
])
def test_link_coverings_of_another_type_is_a_value_error_naming_it(link_coverings, match):
    with pytest.raises(ValueError, match=match):
        covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), link_coverings=link_coverings, **QUICK)
