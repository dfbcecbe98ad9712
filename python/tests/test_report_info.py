"""The report's sign-off fields in Python (to_html and to_pdf's report_info, the CLI's --project
... flags) and where each input came from (the result's "input_sources", as the CLI's --json has
it): the same library calls as the CLI's (covopt/report/report_settings.hpp, input_sources.hpp,
pdf_print.hpp)."""

import shutil
import subprocess

import pytest

import covopt


def test_input_sources_name_the_keywords_the_catalog_and_the_defaults():
    result = covopt.simulate(covopt.Scene(robot_mass=12.0, speed="1.5m/s", safety_factor=1.5,
                                          material="PU foam PORON 4701-30 320"))
    data = result.to_dict()
    assert list(data)[-2:] == ["input_sources", "provenance"]
    sources = data["input_sources"]
    assert sources["scene.robot.mass_kg"] == "keyword robot_mass"
    assert sources["scene.robot.speed_m_per_s"] == "keyword speed"
    assert sources["laceration.safety_factor"] == "keyword safety_factor"
    assert sources["scene.covering.material"] == "keyword material"
    assert sources["scene.covering.youngs_modulus_Pa"] == "catalog"
    assert sources["scene.covering.poisson_ratio"] == "catalog"
    assert sources["scene.head.mass_kg"] == "default"
    assert sources["laceration.limit_Pa"] == "default"
    # Only reportable results carry it.
    assert "input_sources" not in covopt.max_safe_speed().to_dict()


def test_input_sources_agree_with_the_cli_but_for_the_words(cli_json):
    ours = covopt.speed_limit(covopt.Scene(covering_thickness="20mm", safety_factor=2)).to_dict()["input_sources"]
    theirs = cli_json("speed-limit", "--covering-thickness", "20mm", "--safety-factor", "2", "--json")["input_sources"]
    assert list(ours) == list(theirs)
    assert theirs["scene.covering.thickness_m"] == "flag --covering-thickness"
    assert ours["scene.covering.thickness_m"] == "keyword covering_thickness"
    assert theirs["safety_factor"] == "flag --safety-factor"
    assert ours["safety_factor"] == "keyword safety_factor"
    assert all(theirs[key] == ours[key] == "default" for key in ours if ours[key] == "default")


@pytest.mark.parametrize("report_info, message", [
    ({"projet": "x"}, r"report_info: unknown key\(s\) 'projet'; the keys are project, cell"),
    ({"projet": "x", "colour": 1}, r"unknown key\(s\) 'projet', 'colour'"),
    ({"margin_threshold": 10}, r"report_info\['margin_threshold'\]: a bare number is a share in \[0, 1\); write 10%"),
    ({"margin_threshold": "150%"}, r"report_info\['margin_threshold'\]: must be a share in \[0, 1\)"),
    ({"margin_threshold": True}, r"report_info\['margin_threshold'\]: expected a str or a number \(got True\)"),
    ({"appendix": "all"}, r"report_info\['appendix'\]: the appendix must be none, summary or full \(got 'all'\)"),
    ({"project": "x" * 2001}, r"report_info\['project'\]: 2001 characters"),
    ({"cell": "a\x07"}, r"report_info\['cell'\]: a control character"),
    ({"assessor": 3}, r"report_info\['assessor'\]: expected a text, got the number 3"),
    (["project"], r"report_info must be a dict"),
])
def test_bad_report_info_is_a_value_error_naming_it(tmp_path, report_info, message):
    result = covopt.simulate()
    for write, name in ((result.to_html, "r.html"), (result.to_pdf, "r.pdf")):
        with pytest.raises(ValueError, match=message):
            write(tmp_path / name, report_info=report_info)
    assert list(tmp_path.iterdir()) == []


def test_good_report_info_is_taken(tmp_path):
    info = {"project": "Line 4 palletiser", "cell": "C-12", "assessor": "A. Person", "note": "one\ntwo",
            "margin_threshold": "15%", "appendix": "full"}
    path = tmp_path / "r.html"
    assert covopt.simulate().to_html(path, report_info=info) == path
    assert path.read_text(encoding="utf-8").lstrip().lower().startswith("<!doctype html")
    assert covopt.simulate().to_html(tmp_path / "n.html", report_info={"margin_threshold": 0.0, "project": None})


@pytest.mark.parametrize("name", ["x.html", "x", "x.pdf.bak"])
def test_to_pdf_refuses_a_name_that_is_not_pdf(tmp_path, name):
    with pytest.raises(ValueError, match=r"to_pdf: path must be a file name ending in \.pdf"):
        covopt.simulate().to_pdf(tmp_path / name)
    assert list(tmp_path.iterdir()) == []


def test_to_pdf_prints_the_report(tmp_path):
    for tool in ("pdfinfo", "pdftotext"):
        assert shutil.which(tool), f"{tool} (poppler-utils) is needed by this test"
    path = tmp_path / "report.PDF"
    result = covopt.simulate()
    assert result.to_pdf(path, report_info={"project": "Line 4 palletiser"}) == path
    assert path.read_bytes().startswith(b"%PDF")
    info = subprocess.run(["pdfinfo", str(path)], capture_output=True, text=True, check=True).stdout
    pages = int(next(line.split()[1] for line in info.splitlines() if line.startswith("Pages:")))
    assert pages >= 1
    text = subprocess.run(["pdftotext", str(path), "-"], capture_output=True, text=True, check=True).stdout
    assert result.provenance.commit in text.replace("\n", "")
