"""covopt.audit: the whole robot along its motion (``covopt audit --json``), and
covopt.audit_many: a plant's programs audited in parallel through dask.distributed
(docs/guide/audit.md)."""

import os

from . import _covopt, _provenance
from ._results import Result

__all__ = ["Audit", "audit", "audit_many"]


class Audit(Result):
    """covopt.audit's result: the object of ``covopt audit --json`` (``to_dict()`` is it).

    status ("safe", "unsafe", "at-rest"), message, safe_speed_scale (None: at rest
    throughout), limiting (the cell that sets the scale: link, region, binding, time_s,
    governing_ratio; None at rest), criterion, safety_factor, contact_area_m2,
    reaction_delay_s, braking_m_per_s2, robot (name, base_link, tip_link, joint_names,
    payload), surface (spacing_m, links: name, point_count), sample_count, regions (names,
    the head last), scope, coverings (per link: material, modulus_Pa, poisson_ratio,
    thickness_m, from), cells (links x regions: link, region, governing_ratio, binding,
    sample, time_s, point, point_in_link_m, point_in_base_m, speed_m_per_s,
    reflected_mass_kg, max_safe_speed_m_per_s, speed_scale), ratio_over_time (time_s, links,
    ratio[sample][link]; None when not kept), link_designs (link, material, thickness_m,
    governing_ratio, message), warnings.
    """
    _report_kind = "audit"

    def cell(self, link, region):
        """The cell of `link` and `region` (names)."""
        for c in self._data["cells"]:
            if c["link"] == link and c["region"] == region:
                return Result(c, "AuditCell")
        raise KeyError(f"no cell for link {link!r} and region {region!r}")


_KEYWORDS = ("surface_file", "surface_spacing", "box_edge_radius", "flat_face_radius", "link_coverings",
             "body_region", "body_area", "contact", "contact_area", "allow_full_compression", "allow_crushing",
             "design", "materials", "families", "allow_unknown_strength", "max_thickness", "thickness_step",
             "payload_mass", "payload_com", "payload_inertia", "ignore_joint_limits", "keep_ratio_over_time")


@_provenance.stamped
def audit(urdf, tip, trajectory, base=None, *, scene=None, urdf_text=None, surface_file=None,
          surface_spacing=None, box_edge_radius=None, flat_face_radius=None, link_coverings=None,
          body_region=None, body_area=None, contact=None, contact_area=None, allow_full_compression=False,
          allow_crushing=False, design=False, materials=None, families=None, allow_unknown_strength=False,
          max_thickness=None, thickness_step=None, payload_mass=None, payload_com=None, payload_inertia=None,
          ignore_joint_limits=False, keep_ratio_over_time=True):
    """Every surface point of every link, at every sample of `trajectory`, against every exposed
    body region (optim::Audit), as ``covopt audit --json``; returns an Audit.

    The robot (urdf or urdf_text, tip, base) and trajectory (a CSV path, or a dict time_s,
    positions, velocities) as check_trajectory takes them; payload_mass (kg), payload_com
    (x, y, z in the tip frame, m) and payload_inertia (ixx, iyy, izz, ixy, ixz, iyz, kg m2)
    as the CLI's --payload-*. The surface: the URDF's collision geometry, surface_file (TOML)
    for mesh links, surface_spacing (default 0.05 m), box_edge_radius, flat_face_radius (a
    covering judged on a flat face). The scene gives the covering of every link (covering_*
    or material), the head's model, braking (reaction_delay, braking) and safety_factor; no
    robot_mass, speed or robot_radius (every point brings its own). link_coverings: a
    link-covering file (TOML [[link]] name, material or modulus and poisson, thickness) or a
    dict {link: {"material": name or "modulus": E, "poisson": nu, "thickness": t}}.
    body_region (default "all": every transient region and the head), body_area,
    contact_area as simulate takes them. design=True: per link the thinnest catalog covering
    (materials=, families=, allow_unknown_strength, max_thickness, thickness_step as optimize).
    keep_ratio_over_time=False: no samples x links matrix (memory independent of the
    trajectory's length). ValueError on bad input.
    """
    from . import _given, _scene  # the package's helpers (covopt/__init__.py)
    options = dict(surface_file=surface_file, surface_spacing=surface_spacing, box_edge_radius=box_edge_radius,
                   flat_face_radius=flat_face_radius, link_coverings=link_coverings, body_region=body_region,
                   body_area=body_area, contact=contact, contact_area=contact_area,
                   allow_full_compression=allow_full_compression or None, allow_crushing=allow_crushing or None,
                   design=design or None, materials=materials, families=families,
                   allow_unknown_strength=allow_unknown_strength or None, max_thickness=max_thickness,
                   thickness_step=thickness_step, payload_mass=payload_mass, payload_com=payload_com,
                   payload_inertia=payload_inertia, ignore_joint_limits=ignore_joint_limits or None,
                   keep_ratio_over_time=None if keep_ratio_over_time else False)
    return Audit(_covopt.audit(urdf, tip, trajectory, base, urdf_text, _scene(scene), **_given(**options)))


def _audit_one(trajectory, urdf, tip, base, urdf_text, scene, options):
    """One audit on a worker; the result travels as its dict (the scene pickles as its
    keywords)."""
    return audit(urdf, tip, trajectory, base, scene=scene, urdf_text=urdf_text, **options).to_dict()


def audit_many(trajectories, urdf, tip, base=None, *, scene=None, urdf_text=None, client=None,
               scheduler_address=None, n_workers=2, threads_per_worker=1, processes=True, **options):
    """Audits many trajectories (a plant's programs) in parallel through dask.distributed;
    returns a list of Audits in the order given, each equal to audit(trajectory, ...) run
    serially (the same library call on the same input: the results are identical).

    trajectories: CSV paths (str or os.PathLike; a directory: its *.csv files, sorted) or
    trajectory dicts. The other arguments as audit() takes them. Where it runs:
    - client: a dask.distributed Client you made (used as it is, not closed);
    - scheduler_address: "tcp://host:8786" of a running scheduler (``dask scheduler``, with
      ``dask worker tcp://host:8786`` on each machine; covopt importable on every worker, and
      the URDF and trajectory paths readable there);
    - neither: an in-process LocalCluster of n_workers workers, threads_per_worker threads
      each (processes=False: threads in this process), closed afterwards.
    """
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError as e:  # pragma: no cover - the dependency is documented
        raise ImportError("audit_many needs dask.distributed (Debian: apt-get install python3-distributed; "
                          "pip: pip install distributed)") from e
    if client is not None and scheduler_address is not None:
        raise ValueError("give client or scheduler_address, not both")
    items = _expand(trajectories)
    urdf = os.fspath(urdf) if urdf is not None else None
    owned = []
    try:
        if client is None:
            if scheduler_address is not None:
                client = Client(scheduler_address)
            else:
                cluster = LocalCluster(n_workers=n_workers, threads_per_worker=threads_per_worker,
                                       processes=processes, dashboard_address=None)
                owned.append(cluster)
                client = Client(cluster)
            owned.insert(0, client)
        futures = client.map(_audit_one, items, urdf=urdf, tip=tip, base=base, urdf_text=urdf_text,
                             scene=scene, options=options, pure=False)
        return [Audit(result) for result in client.gather(futures)]
    finally:
        for resource in owned:
            resource.close()


def _expand(trajectories):
    """Paths (a directory: its *.csv, sorted) and dicts, as a list."""
    if isinstance(trajectories, (str, os.PathLike)):
        trajectories = [trajectories]
    items = []
    for t in trajectories:
        if isinstance(t, (str, os.PathLike)) and os.path.isdir(t):
            items.extend(sorted(os.path.join(os.fspath(t), name) for name in os.listdir(t) if name.endswith(".csv")))
        elif isinstance(t, (str, os.PathLike)):
            items.append(os.fspath(t))
        else:
            items.append(t)
    if not items:
        raise ValueError("trajectories: no trajectory given (an empty list, or a directory without *.csv files)")
    return items
