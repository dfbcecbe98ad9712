"""Every Python result ends with the provenance block the CLI's --json has, made by the same
library call (covopt/report/provenance.hpp): this build's version and commit, the Python call,
the date (SOURCE_DATE_EPOCH when set) and the SHA-256 of every input file."""

import hashlib
import os
import pathlib
import re

import pytest

import covopt
from conftest import same_provenance

MODELS = pathlib.Path(__file__).resolve().parents[2] / "robot" / "models"
FR3 = MODELS / "franka_fr3.urdf"
PICK = MODELS / "franka_fr3_pick.csv"
PAPER = pathlib.Path(__file__).resolve().parents[2] / "cli" / "examples" / "paper_scene.toml"


def sha256(path):
    return hashlib.sha256(pathlib.Path(path).read_bytes()).hexdigest()


def check_block(result, build_provenance, command, inputs=()):
    data = result.to_dict()
    assert list(data)[-1] == "provenance"
    block = data["provenance"]
    assert list(block) == ["software", "version", "commit", "command", "date_utc", "inputs"]
    assert (block["software"], block["version"], block["commit"]) == (
        "covopt", build_provenance["version"], build_provenance["commit"])
    assert block["command"] == command
    assert [(f["role"], f["path"]) for f in block["inputs"]] == [(role, str(path)) for role, path in inputs]
    for f in block["inputs"]:
        assert f["sha256"] == sha256(f["path"])  # OpenSSL's digest is hashlib's
        assert f["size_bytes"] == os.path.getsize(f["path"])
    return block


def test_simulate_optimize_and_speed_limit_name_the_call(build_provenance):
    check_block(covopt.simulate(method="exact"), build_provenance, "covopt.simulate(method='exact')")
    scene = covopt.Scene(robot_mass=10.0, speed="1.5m/s")
    check_block(covopt.simulate(scene), build_provenance, f"covopt.simulate(scene=covopt.{scene!r})")
    check_block(covopt.optimize(materials=["PU foam PORON 4701-30 320"]), build_provenance,
                "covopt.optimize(materials=['PU foam PORON 4701-30 320'])")
    check_block(covopt.max_safe_speed(), build_provenance, "covopt.max_safe_speed()")
    check_block(covopt.speed_limit(values=[5.0, 10.0]), build_provenance, "covopt.speed_limit(values=[5.0, 10.0])")
    check_block(covopt.simulate(scene, body_region="chest"), build_provenance,
                f"covopt.simulate(scene=covopt.{scene!r}, body_region='chest')")


def test_robot_inputs_are_hashed_as_hashlib_does(build_provenance):
    check_block(covopt.reflected_mass(FR3, "fr3_link8", [0, 0, 0, -1.5, 0, 1.5, 0.8]), build_provenance,
                f"covopt.reflected_mass(urdf={FR3!r}, tip='fr3_link8', joints=[0, 0, 0, -1.5, 0, 1.5, 0.8])",
                [("urdf", FR3)])
    check = covopt.check_trajectory(str(FR3), "fr3_link8", str(PICK))
    check_block(check, build_provenance,
                f"covopt.check_trajectory(urdf={str(FR3)!r}, tip='fr3_link8', trajectory={str(PICK)!r})",
                [("urdf", FR3), ("trajectory", PICK)])


def test_a_catalog_file_is_an_input(tmp_path, build_provenance):
    catalog = tmp_path / "my catalog.toml"
    catalog.write_text('[[material]]\nname = "Test foam"\nfamily = "foam"\nyoungs_modulus_Pa = 5e5\n'
                       'modulus_basis = "hardness"\nsource = "a test"\n')
    design = covopt.optimize(catalog=[str(catalog)], materials=["Test foam"], allow_unknown_strength=True)
    check_block(design, build_provenance,
                f"covopt.optimize(materials=['Test foam'], catalog=[{str(catalog)!r}], allow_unknown_strength=True)",
                [("catalog", catalog)])


def test_data_given_in_memory_is_no_input_and_long_reprs_are_cut(build_provenance):
    text = FR3.read_text()
    result = covopt.reflected_mass(None, "fr3_link8", [0, 0, 0, -1.5, 0, 1.5, 0.8], urdf_text=text)
    block = check_block(result, build_provenance,
                        "covopt.reflected_mass(urdf=None, tip='fr3_link8', joints=[0, 0, 0, -1.5, 0, 1.5, 0.8], "
                        "urdf_text=<str>)")
    assert block["inputs"] == []


def test_source_date_epoch_fixes_the_date(monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    assert covopt.simulate().provenance.date_utc == "2023-11-14T22:13:20Z"
    monkeypatch.delenv("SOURCE_DATE_EPOCH")
    assert covopt.simulate().provenance.date_utc >= "2024"


def test_the_same_block_as_the_cli(cli_json):
    ours = covopt.check_trajectory(str(FR3), "fr3_link8", str(PICK))
    theirs = cli_json("robot", "--urdf", str(FR3), "--tip", "fr3_link8", "--trajectory", str(PICK), "--json")
    assert ours == theirs
    assert same_provenance(ours.provenance.to_dict(), theirs["provenance"])
    assert theirs["provenance"]["command"].endswith(f"--trajectory {PICK} --json")
    assert ours.provenance.command != theirs["provenance"]["command"]


def test_to_html_writes_the_report(tmp_path):
    path = tmp_path / "report.html"
    assert covopt.simulate().to_html(path) == path
    html = path.read_text(encoding="utf-8")
    assert html.lstrip().lower().startswith("<!doctype html")
    assert covopt.simulate().provenance.commit in html
    for result in (covopt.optimize(materials=["PU foam PORON 4701-30 320"]), covopt.speed_limit(),
                   covopt.check_trajectory(str(FR3), "fr3_link8", str(PICK)), covopt.simulate(history=True)):
        out = tmp_path / f"{type(result).__name__}.html"
        result.to_html(out)
        assert out.stat().st_size > 0
    with pytest.raises(TypeError, match="no report"):
        covopt.max_safe_speed().to_html(tmp_path / "x.html")


@pytest.mark.parametrize("name", ["x.pdf", "x.PDF", "x.txt", "x", "report.html.bak"])
def test_to_html_refuses_a_name_that_is_not_html(tmp_path, name):
    """to_html writes HTML: a .pdf (or any other) name is refused, naming the argument and the
    value, and nothing is written (issue 33)."""
    with pytest.raises(ValueError, match=r"to_html: path must be a file name ending in \.html or \.htm "
                                         r"\(got .*" + re.escape(name) + r"'\)"):
        covopt.simulate().to_html(tmp_path / name)
    assert list(tmp_path.iterdir()) == []
    for accepted in ("y.HTML", "y.htm"):
        assert covopt.simulate().to_html(str(tmp_path / accepted)) == str(tmp_path / accepted)


def _figures(html):
    """The report's chart figures, as HTML text."""
    return re.findall(r'<figure class="chart".*?</figure>', html, flags=re.S)


@pytest.mark.parametrize("python_call, cli_args", [
    (lambda: covopt.simulate(), ["simulate"]),
    (lambda: covopt.optimize(materials=["PU foam PORON 4701-30 320"]),
     ["optimize", "--material", "PU foam PORON 4701-30 320"]),
    (lambda: covopt.speed_limit(), ["speed-limit"]),
    (lambda: covopt.check_trajectory(str(FR3), "fr3_link8", str(PICK)),
     ["robot", "--urdf", str(FR3), "--tip", "fr3_link8", "--trajectory", str(PICK)]),
    (lambda: covopt.audit(str(FR3), "fr3_link8", str(PICK), contact_area="1cm2", flat_face_radius="20mm",
                          scene=covopt.Scene(covering_thickness=0.02, covering_modulus=0.5e6, covering_poisson=0.45)),
     ["audit", "--urdf", str(FR3), "--tip", "fr3_link8", "--trajectory", str(PICK), "--covering-thickness", "20mm",
      "--covering-modulus", "0.5MPa", "--covering-poisson", "0.45", "--contact-area", "1cm2",
      "--flat-face-radius", "20mm"]),
    (lambda: covopt.simulate(covopt.Scene(robot_mass=10, speed=0.5), body_region="chest", contact_area="1cm2"),
     ["simulate", "--robot-mass", "10kg", "--speed", "0.5m/s", "--body-region", "chest", "--contact-area", "1cm2"]),
    (lambda: covopt.speed_limit(covopt.Scene(robot_mass=10), body_region="all", contact_area="1cm2"),
     ["speed-limit", "--robot-mass", "10kg", "--body-region", "all", "--contact-area", "1cm2"]),
], ids=["simulate", "optimize", "speed-limit", "trajectory", "audit", "simulate-region", "speed-limit-regions"])
def test_to_html_draws_the_cli_reports_charts(tmp_path, cli, python_call, cli_args):
    """result.to_html() has the charts of the CLI's --report for the same inputs, the same SVG
    (one library function draws both), and the chart maker never shows in to_dict()."""
    result = python_call()
    assert "_report_charts" not in result.to_dict()
    python_html = pathlib.Path(result.to_html(tmp_path / "python.html")).read_text(encoding="utf-8")
    cli_file = tmp_path / "cli.html"
    code, _, err = cli(*cli_args, "--report", str(cli_file))
    assert code == 0, err
    cli_figures = _figures(cli_file.read_text(encoding="utf-8"))
    python_figures = _figures(python_html)
    # One chart each; the audit's two: the link x region map and the ratio over time.
    assert len(cli_figures) == (2 if cli_args[0] == "audit" else 1)
    assert all("<svg" in figure for figure in cli_figures)
    assert python_figures == cli_figures
