"""Sizes checked before work: every array, list or count Python hands to covopt is refused
over its documented cap before it is allocated or iterated to the end, and a surface too
large to sample is refused from its estimate. Each case runs in a child Python under
RLIMIT_AS = 1 GiB and RLIMIT_CPU = 10 s and must end in a ValueError naming the argument
(the kernel enforces the limits; nothing is timed here). Before: a surface file's segment
999 m long of radius 999 m hung covopt.audit; covopt.sweep and speed_limit read any
iterable to its end (itertools.count() never ends) and allocated the grid unchecked."""

import os
import pathlib
import resource
import subprocess
import sys
import textwrap

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
FR3 = ROOT / "robot" / "models" / "franka_fr3.urdf"
PICK = ROOT / "robot" / "models" / "franka_fr3_pick.csv"

ONE_GIB = 1 << 30
CPU_SECONDS = 10


def _limit():
    resource.setrlimit(resource.RLIMIT_AS, (ONE_GIB, ONE_GIB))
    resource.setrlimit(resource.RLIMIT_CPU, (CPU_SECONDS, CPU_SECONDS))


def refused(code, *needles):
    """Runs `code` (which calls covopt) in a child Python under the limits; it must raise a
    ValueError whose message holds every needle."""
    body = textwrap.indent(textwrap.dedent(code).strip(), "    ")
    program = "\n".join([
        "import itertools, sys",
        "import numpy as np",
        "import covopt",
        f"FR3, PICK = {str(FR3)!r}, {str(PICK)!r}",
        "try:",
        body,
        "except ValueError as e:",
        "    print(e)",
        "    sys.exit(2)",
        "sys.exit(0)",
    ])
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    # A wall-clock bound only so that a hang cannot stall the suite; the CPU limit is the test.
    done = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True, env=env,
                          preexec_fn=_limit, timeout=300, check=False)
    assert done.returncode == 2, f"exit {done.returncode}; stdout {done.stdout!r}; stderr {done.stderr[-2000:]!r}"
    for needle in needles:
        assert needle in done.stdout, done.stdout
    return done.stdout


def test_audit_refuses_a_huge_surface_file_segment(tmp_path):
    surface = tmp_path / "huge.toml"
    surface.write_text('[[link]]\nname = "fr3_link3"\n'
                       'segments = [ { from_m = [0, 0, 0], to_m = [999, 0, 0], radius_m = 999 } ]\n')
    refused(f"""
        covopt.audit(FR3, "fr3_link8", PICK, scene=covopt.Scene(covering_thickness=0), contact_area="1cm2",
                     flat_face_radius="20mm", surface_file={str(surface)!r})
        """, "huge.toml:3:", "a capsule of radius 999 m and length 999 m", "more than the 1000000 allowed")


def test_audit_refuses_a_huge_urdf_sphere_and_a_denormal_one():
    urdf = FR3.read_text()
    big = urdf
    link = '<link name="fr3_link3">'
    assert link in big
    sphere = '<collision><geometry><sphere radius="{}"/></geometry></collision>'
    refused(f"""
        covopt.audit(None, "fr3_link8", PICK, urdf_text={big.replace(link, link + sphere.format(100), 1)!r},
                     scene=covopt.Scene(covering_thickness=0), contact_area="1cm2", flat_face_radius="20mm",
                     surface_spacing="1mm")
        """, "link 'fr3_link3', a sphere of radius 100 m", "more than the 1000000 allowed", "surface_spacing")
    refused(f"""
        covopt.audit(None, "fr3_link8", PICK, urdf_text={big.replace(link, link + sphere.format("4.9e-324"), 1)!r},
                     scene=covopt.Scene(covering_thickness=0), contact_area="1cm2", flat_face_radius="20mm")
        """, "link 'fr3_link3' <collision> 1: <sphere radius> = ", "[0.0001, 1000] m")


@pytest.mark.parametrize("call, needles", [
    # An iterator without end: read to the cap, then refused.
    ("covopt.sweep(('speed', itertools.count(1)))", ["x (speed): more than 100000 values", "at most 100000"]),
    ("covopt.sweep(('speed', np.ones(100001)))", ["x (speed): 100001 values is not allowed (at most 100000)"]),
    # A grid over the cap: refused before its arrays (18 of them) are allocated.
    ("covopt.sweep(('speed', np.linspace(1, 2, 1001)), ('head_mass', np.linspace(3, 6, 1000)))",
     ["the grid has 1001 x 1000 = 1001000 points; at most 1000000 are allowed"]),
    ("covopt.sweep(('robot_mass', np.linspace(1, 2, 2000)), ('speed', np.linspace(1, 2, 2000)), body_region='chest',"
     " contact_area='1cm2')", ["at most 1000000 are allowed"]),
    ("covopt.speed_limit(values=itertools.repeat(10.0))", ["values: more than 100000 values"]),
    ("covopt.speed_limit(values=np.full(100001, 10.0))", ["values: 100001 values is not allowed (at most 100000)"]),
    ("covopt.speed_limit(values=[10], materials=itertools.repeat('polystyrene foam 27.6'))",
     ["materials: more than 100000 values"]),
    ("covopt.contact_motion(FR3, 'fr3_link8', PICK, point=itertools.count())", ["point: more than 10000 values"]),
    ("covopt.contact_motion(FR3, 'fr3_link8', {'time_s': np.zeros(1000001), 'positions': [], 'velocities': []})",
     ["trajectory['time_s']: 1000001 values is not allowed (at most 1000000)"]),
    ("covopt.contact_motion(FR3, 'fr3_link8', {'time_s': [0, 0.1], 'positions': itertools.repeat([0.0] * 7),"
     " 'velocities': [[0.0] * 7] * 2})", ["trajectory['positions']: more than 1000000 values"]),
])
def test_arrays_and_lists_over_their_caps_are_value_errors(call, needles):
    refused(call, *needles)
