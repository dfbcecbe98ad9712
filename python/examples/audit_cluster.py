"""Audits a folder of robot programs on a dask.distributed cluster (docs/guide/audit.md):
every FR3 program in python/examples/fr3_programs (make_fr3_programs.py writes them) against
every transient ISO/TS 15066 body region and the head, with a 10 mm covering on every link,
and prints per program the safe speed scale and which link and region set it.

    python3 python/examples/audit_cluster.py                         # an in-process LocalCluster
    python3 python/examples/audit_cluster.py tcp://scheduler:8786    # a running cluster

On a real cluster covopt must be importable on every worker, and the URDF and the programs'
paths readable there (a shared file system), or pass the trajectories as dicts.
"""

import pathlib
import sys

import covopt

HERE = pathlib.Path(__file__).resolve().parent
URDF = HERE.parents[1] / "robot" / "models" / "franka_fr3.urdf"
PROGRAMS = HERE / "fr3_programs"

SCENE = covopt.Scene(covering_thickness="10mm", covering_modulus="0.5MPa", covering_poisson=0.45)
OPTIONS = dict(contact_area="1cm2", flat_face_radius="20mm", keep_ratio_over_time=False)


def main(scheduler_address=None, n_workers=2, processes=True, programs=PROGRAMS):
    """The audits of every program, as a list of (file name, covopt.Audit or covopt.AuditFailure)."""
    paths = sorted(pathlib.Path(programs).glob("*.csv"))
    results = covopt.audit_many(paths, URDF, "fr3_link8", scene=SCENE, scheduler_address=scheduler_address,
                                n_workers=n_workers, processes=processes, **OPTIONS)
    return list(zip((p.name for p in paths), results))


if __name__ == "__main__":  # the worker processes re-run this file: start them only from here
    for name, result in main(sys.argv[1] if len(sys.argv) > 1 else None):
        if not result.ok:  # a program that could not be audited (covopt.AuditFailure)
            print(f"{name:<20} failed   {result.error_type}: {result.message}")
            continue
        limiting = result.limiting
        where = f"{limiting.link} against {limiting.region} ({limiting.binding})" if limiting else "-"
        print(f"{name:<20} {result.status:<8} scale {result.safe_speed_scale or float('inf'):.3g}  {where}")
