"""covopt.audit(tool_surface=, payload_surface=, exposure=): the dict is the CLI's --json for the
same tool and zone file; zones as dicts judge as the file; bad input is ValueError naming the
keyword or the zone."""

import pathlib

import pytest

import covopt
from conftest import without_provenance

ROOT = pathlib.Path(__file__).resolve().parents[2]
FR3 = ROOT / "robot" / "models" / "franka_fr3.urdf"
PICK = ROOT / "robot" / "models" / "franka_fr3_pick.csv"
ZONES = ROOT / "robot" / "models" / "exposure_table_cell.toml"
SCENE = dict(covering_thickness="10mm", covering_modulus="0.5MPa", covering_poisson=0.45)
FLAGS = ["--covering-thickness", "10mm", "--covering-modulus", "0.5MPa", "--covering-poisson", "0.45",
         "--contact-area", "1cm2", "--flat-face-radius", "20mm", "--surface-spacing", "80mm"]
GRIPPER = "box:center=0,0,0.045;size=0.08,0.2,0.09;edge=10mm;rpy=0,0,-0.7854"


def run(**kwargs):
    return covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), contact_area="1cm2",
                        flat_face_radius="20mm", surface_spacing="80mm", **kwargs)


def test_tool_and_zones_are_the_cli_json(cli_json):
    expected = cli_json("audit", "--urdf", str(FR3), "--tip", "fr3_link8", "--trajectory", str(PICK), *FLAGS,
                        "--tool-surface", GRIPPER, "--exposure", str(ZONES), "--json")
    got = run(tool_surface=[GRIPPER], exposure=ZONES).to_dict()
    assert without_provenance(got) == without_provenance(expected)
    assert got["surface"]["links"][-1]["name"] == "tool"
    assert got["not_judged_cells"] > 0


def test_zones_as_dicts_judge_as_a_file(tmp_path):
    path = tmp_path / "zones.toml"
    path.write_text('[[zone]]\nname = "cell"\nmin_m = [-2, -2, 0.3]\nmax_m = [2, 2, 2]\nregions = ["chest", "head"]\n')
    from_file = run(exposure=path).to_dict()
    from_dicts = run(exposure=[{"name": "cell", "min_m": [-2, -2, 0.3], "max_m": [2, 2, 2],
                                "regions": ["chest", "head"]}]).to_dict()
    assert [c["governing_ratio"] for c in from_file["cells"]] == [c["governing_ratio"] for c in from_dicts["cells"]]
    for cell in from_dicts["cells"]:
        if not (cell["region"].startswith("chest") or cell["region"].startswith("head")):
            assert cell["not_judged"] == "no exposure zone exposes the region"


@pytest.mark.parametrize("kwargs, words", [
    ({"tool_surface": "sphere:center=0,0,0.1"}, "tool_surface 'sphere:center=0,0,0.1': radius: missing"),
    ({"payload_surface": ["cone:center=0,0,0"]}, "payload_surface"),
    ({"exposure": [{"name": "z", "min_m": [0, 0, 1], "max_m": [1, 1, 0], "regions": ["all"]}]},
     "exposure[0]: exposure_zones[0] 'z': min_m [0, 0, 1] lies above max_m [1, 1, 0]"),
    ({"exposure": [{"name": "z", "min_m": [0, 0, 0], "max_m": [1, 1, 1], "regions": ["elbow"]}]}, "'elbow'"),
    ({"exposure": [{"name": "z", "min": [0, 0, 0]}]}, "exposure[0]: unknown key 'min'"),
])
def test_bad_tool_or_zone_is_a_value_error(kwargs, words):
    with pytest.raises(ValueError) as error:
        run(**kwargs)
    assert words in str(error.value)
