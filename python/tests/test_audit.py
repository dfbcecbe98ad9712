"""covopt.audit and covopt.audit_many: the dict is the CLI's --json for the same input; the
dask.distributed run of a folder of programs (the example) equals the serial run exactly;
bad input is ValueError naming the keyword."""

import importlib.util
import pathlib

import pytest

import covopt
from conftest import same_provenance, without_provenance

ROOT = pathlib.Path(__file__).resolve().parents[2]
FR3 = ROOT / "robot" / "models" / "franka_fr3.urdf"
PICK = ROOT / "robot" / "models" / "franka_fr3_pick.csv"
EXAMPLES = ROOT / "python" / "examples"

SCENE = dict(covering_thickness="10mm", covering_modulus="0.5MPa", covering_poisson=0.45)
FLAGS = ["--covering-thickness", "10mm", "--covering-modulus", "0.5MPa", "--covering-poisson", "0.45"]


@pytest.mark.parametrize("kwargs, flags", [
    ({}, []),
    ({"body_region": ["chest", "head"]}, ["--body-region", "chest,head"]),
    ({"safety_factor": 1.5, "payload_mass": 1.2, "payload_com": (0, 0, 0.05)},
     ["--safety-factor", "1.5", "--payload-mass", "1.2", "--payload-com", "0,0,0.05"]),
    ({"body_region": ["chest", "head"], "reaction_delay": "5ms", "braking": 100},
     ["--body-region", "chest,head", "--reaction-delay", "5ms", "--braking", "100"]),
    ({"link_coverings": {"fr3_link6": {"modulus": "0.2MPa", "poisson": 0.45, "thickness": "30mm"}}}, None),
])
def test_audit_returns_the_cli_json_object(cli_json, tmp_path, kwargs, flags):
    kwargs = dict(kwargs)
    scene_keys = {k: kwargs.pop(k) for k in ("safety_factor", "reaction_delay", "braking") if k in kwargs}
    if flags is None:  # the same coverings as a file for the CLI
        path = tmp_path / "links.toml"
        path.write_text('[[link]]\nname = "fr3_link6"\nmodulus = "0.2MPa"\npoisson = 0.45\nthickness = "30mm"\n')
        flags = ["--link-coverings", str(path)]
    expected = cli_json("audit", "--urdf", str(FR3), "--tip", "fr3_link8", "--trajectory", str(PICK), *FLAGS,
                        "--contact-area", "1cm2", "--flat-face-radius", "20mm", *flags, "--json")
    result = covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE, **scene_keys), contact_area="1cm2",
                          flat_face_radius="20mm", **kwargs)
    assert isinstance(result, covopt.Audit)
    got = result.to_dict()
    if "link_coverings" in kwargs:  # a file for the CLI, a dict here: all but the provenance's inputs agree
        got, expected = without_provenance(got), without_provenance(expected)
    if scene_keys:  # the input warnings name the keyword (safety_factor=1.5) where the CLI names its flag
        assert [w.split(" (from ")[0] for w in got.pop("warnings")] == \
            [w.split(" (from ")[0] for w in expected.pop("warnings")]
    else:
        assert got == expected
    assert got == expected
    # Typed access: the limiting cell, and a cell by link and region.
    limiting = result.limiting
    assert result.cell(limiting.link, limiting.region).speed_scale == result.safe_speed_scale


def test_audit_scale_is_the_minimum_over_links_and_regions():
    result = covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), contact_area="1cm2",
                          flat_face_radius="20mm")
    scales = [c.speed_scale for c in result.cells if c.speed_scale is not None]
    assert result.safe_speed_scale == min(scales)
    for c in result.cells:
        if c.link == "fr3_link0":
            assert c.governing_ratio == 0.0 and c.sample is None  # the base never moves


def test_audit_bad_input_names_the_keyword():
    with pytest.raises(ValueError, match="robot_mass"):
        covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(robot_mass=5, **SCENE), contact_area="1cm2")
    with pytest.raises(ValueError, match="payload"):
        covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), contact_area="1cm2",
                     flat_face_radius="20mm", payload_mass=1.0, payload_inertia=(1, 1, 5, 0, 0, 0))
    with pytest.raises(ValueError, match="fr3_hand"):
        covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), contact_area="1cm2",
                     flat_face_radius="20mm", link_coverings={"fr3_hand": {"thickness": 0}})
    with pytest.raises(ValueError, match="clamped"):
        covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(**SCENE), body_region="chest", contact="clamped")


@pytest.mark.parametrize("keywords, flags, spellings", [
    # A link-covering file naming a link that is not on the surface.
    ({"link_coverings": "LINKS"}, ["--link-coverings", "LINKS"], [("link_coverings", "--link-coverings")]),
    # The robot's mass, which every surface point brings.
    ({"robot_mass": 5}, ["--robot-mass", "5"], [("robot_mass", "--robot-mass")] * 2),
    # A design input without the design.
    ({"families": "foam"}, ["--family", "foam"], [("families", "--family"), ("with design", "with --design")]),
    # A material of the design not in the catalog.
    ({"design": True, "materials": "no such foam"}, ["--design", "--design-material", "no such foam"],
     [("materials", "--design-material")]),
])
def test_audit_and_the_cli_assemble_the_audit_by_one_library_call(cli, tmp_path, keywords, flags, spellings):
    """Both shells hand their inputs to covopt::audit::AssembleAudit: the same bad input gets the
    same message word for word, each input named by the shell's own spelling."""
    links = tmp_path / "links.toml"
    links.write_text('[[link]]\nname = "fr3_hand"\nthickness = 0\n')
    keywords = {k: str(links) if v == "LINKS" else v for k, v in keywords.items()}
    flags = [str(links) if f == "LINKS" else f for f in flags]
    code, out, err = cli("audit", "--urdf", str(FR3), "--tip", "fr3_link8", "--trajectory", str(PICK), *FLAGS,
                         "--contact-area", "1cm2", "--flat-face-radius", "20mm", *flags)
    assert code == 2, (out, err)
    scene = covopt.Scene(**SCENE, **{k: keywords.pop(k) for k in ("robot_mass",) if k in keywords})
    with pytest.raises(ValueError) as raised:
        covopt.audit(FR3, "fr3_link8", PICK, scene=scene, contact_area="1cm2", flat_face_radius="20mm", **keywords)
    message = str(raised.value)
    for keyword, flag in spellings:  # Python's spelling -> the CLI's, once each
        assert keyword in message, message
        message = message.replace(keyword, flag, 1)
    assert err.count(message) == 1, (message, err)


def test_scene_pickles_as_its_keywords():
    import pickle
    scene = covopt.Scene(**SCENE, safety_factor=1.5)
    again = pickle.loads(pickle.dumps(scene))
    assert repr(again) == repr(scene) and again.to_dict() == scene.to_dict()


def test_the_cluster_example_equals_the_serial_run(tmp_path):
    pytest.importorskip("dask.distributed")
    spec = importlib.util.spec_from_file_location("make_fr3_programs", EXAMPLES / "make_fr3_programs.py")
    make = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(make)
    paths = make.main(tmp_path)
    spec = importlib.util.spec_from_file_location("audit_cluster", EXAMPLES / "audit_cluster.py")
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    # Two workers in this process (threads): quick to start, and the same library call.
    parallel = example.main(n_workers=2, processes=False, programs=tmp_path)
    assert [name for name, _ in parallel] == sorted(p.name for p in paths)
    for name, result in parallel:
        serial = covopt.audit(example.URDF, "fr3_link8", tmp_path / name, scene=example.SCENE, **example.OPTIONS)
        assert without_provenance(result) == without_provenance(serial)  # the calls differ
        assert same_provenance(result.provenance.to_dict(), serial.provenance.to_dict())
    # The slower program is never less safe than the pick move it stretches; turning the whole
    # move about the vertical first joint changes no speed and no reflected mass.
    scale = {name: result.safe_speed_scale for name, result in parallel}
    assert scale["pick_slow.csv"] >= scale["pick.csv"]
    assert scale["pick_left.csv"] == pytest.approx(scale["pick.csv"], rel=1e-9)
    assert scale["pick_right.csv"] == pytest.approx(scale["pick.csv"], rel=1e-9)


def test_audit_many_on_a_scheduler_address_equals_the_serial_run():
    distributed = pytest.importorskip("dask.distributed")
    scene = covopt.Scene(**SCENE)
    options = dict(contact_area="1cm2", flat_face_radius="20mm", body_region="chest")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster:
        [result] = covopt.audit_many([PICK], FR3, "fr3_link8", scene=scene,
                                     scheduler_address=cluster.scheduler_address, **options)
    serial = covopt.audit(FR3, "fr3_link8", PICK, scene=scene, **options)
    assert without_provenance(result) == without_provenance(serial)
    assert same_provenance(result.provenance.to_dict(), serial.provenance.to_dict())
    with pytest.raises(ValueError, match="no trajectory"):
        covopt.audit_many([], FR3, "fr3_link8", scene=scene, **options)
