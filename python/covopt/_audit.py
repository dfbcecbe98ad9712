"""covopt.audit: the whole robot along its motion (``covopt audit --json``); covopt.retime:
the fastest safe timing of the program (``covopt retime --json``); and covopt.audit_many: a
plant's programs audited (or re-timed) in parallel through dask.distributed
(docs/guide/audit.md, docs/guide/retime.md)."""

import os

from ._inputs import takes_objects
from . import _covopt, _provenance
from ._results import Result

__all__ = ["Audit", "AuditFailure", "AuditManyError", "Retime", "audit", "audit_many", "retime"]


class Audit(Result):
    """covopt.audit's result: the object of ``covopt audit --json`` (``to_dict()`` is it);
    ``ok`` is True (audit_many's AuditFailure has False).

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
    ok = True  # not a JSON key: audit_many's results are Audits or AuditFailures

    def cell(self, link, region):
        """The cell of `link` and `region` (names)."""
        for c in self._data["cells"]:
            if c["link"] == link and c["region"] == region:
                return Result(c, "AuditCell")
        raise KeyError(f"no cell for link {link!r} and region {region!r}")


_KEYWORDS = ("surface_file", "surface_spacing", "box_edge_radius", "flat_face_radius", "link_coverings",
             "body_region", "body_area", "contact", "contact_area", "limits", "allow_full_compression", "allow_crushing",
             "design", "materials", "families", "allow_unknown_strength", "max_thickness", "thickness_step",
             "payload_mass", "payload_com", "payload_inertia", "ignore_joint_limits", "keep_ratio_over_time",
             "keep_travel", "tool_surface", "payload_surface", "exposure")


@takes_objects
@_provenance.stamped
def audit(urdf, tip, trajectory, base=None, *, scene=None, urdf_text=None, surface_file=None,
          surface_spacing=None, box_edge_radius=None, flat_face_radius=None, link_coverings=None,
          body_region=None, body_area=None, contact=None, contact_area=None, limits=None, allow_full_compression=False,
          allow_crushing=False, design=False, materials=None, families=None, allow_unknown_strength=False,
          max_thickness=None, thickness_step=None, payload_mass=None, payload_com=None, payload_inertia=None,
          ignore_joint_limits=False, keep_ratio_over_time=True, keep_travel=False, tool_surface=None,
          payload_surface=None, exposure=None):
    """Every surface point of every link, at every sample of `trajectory`, against every exposed
    body region (audit::Audit), as ``covopt audit --json``; returns an Audit.

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
    contact_area and limits as simulate takes them. design=True: per link the thinnest catalog covering
    (materials=, families=, allow_unknown_strength, max_thickness, thickness_step as optimize).
    keep_ratio_over_time=False: no samples x links matrix (memory independent of the
    trajectory's length). tool_surface, payload_surface: shapes in the flange frame as the
    CLI's --tool-surface specs ("box:center=0,0,0.05;size=0.08,0.2,0.1;edge=10mm"; a string or a
    list), audited as the rows "tool" and "payload". exposure: an exposure file (TOML [[zone]]
    name, min_m, max_m, regions) or a list of dicts with those keys; cells no zone exposes are
    not judged. ValueError on bad input.
    """
    from . import _given, _scene  # the package's helpers (covopt/__init__.py)
    options = dict(surface_file=surface_file, surface_spacing=surface_spacing, box_edge_radius=box_edge_radius,
                   flat_face_radius=flat_face_radius, link_coverings=link_coverings, body_region=body_region,
                   body_area=body_area, contact=contact, contact_area=contact_area, limits=limits,
                   allow_full_compression=_given_flag(allow_full_compression), allow_crushing=_given_flag(allow_crushing),
                   design=_given_flag(design), materials=materials, families=families,
                   allow_unknown_strength=_given_flag(allow_unknown_strength), max_thickness=max_thickness,
                   thickness_step=thickness_step, payload_mass=payload_mass, payload_com=payload_com,
                   payload_inertia=payload_inertia, ignore_joint_limits=_given_flag(ignore_joint_limits),
                   keep_ratio_over_time=None if keep_ratio_over_time is True else keep_ratio_over_time,
                   keep_travel=_given_flag(keep_travel), tool_surface=tool_surface,
                   payload_surface=payload_surface, exposure=exposure)
    return Audit(_covopt.audit(urdf, tip, trajectory, base, urdf_text, _scene(scene), **_given(**options)))


class Retime(Result):
    """covopt.retime's result: the object of ``covopt retime --json`` (``to_dict()`` is it);
    ``ok`` is True (audit_many's AuditFailure has False).

    status ("safe", "at-rest", "infeasible", "not-safe", "evaluation-failed"), message,
    summary, cycle_time_s (None without a safe timing), original_cycle_time_s,
    uniform_cycle_time_s, uniform_speed_scale, max_speed_scale, tolerance, joint_names,
    joint_speed_limits_rad_per_s (None: none), joint_acceleration_limits_rad_per_s2, profile (status, message),
    slowdowns (start_time_s, end_time_s, first_sample, last_sample, min_path_speed, bound,
    link, region), samples (original_time_s, time_s, safe_path_speed, path_speed, bound,
    limiting_link, limiting_region), before (the original program's audit: status, message,
    safe_speed_scale, limiting), after (the re-timed program's audit, as covopt.audit's dict),
    thickness_sweep (designs, thicknesses_m, points: design, thickness_m, status,
    cycle_time_s, uniform_cycle_time_s, safe_speed_scale, message), the audit's inputs
    (criterion, safety_factor, robot, surface, regions, coverings, ...), scope, notes, warnings.
    """
    _report_kind = "retime"
    ok = True


@takes_objects
@_provenance.stamped
def retime(urdf, tip, trajectory, base=None, *, scene=None, urdf_text=None, joint_accel_limit=None,
           joint_speed_limit=None, max_speed_scale=None, output=None, thickness=None, materials=None,
           design=False, design_materials=None, **options):
    """The fastest timing of `trajectory`'s path that is safe at every sample and keeps the
    joints' limits (audit::Retime), re-audited, as ``covopt retime --json``; returns a Retime.

    The robot, trajectory, scene and the audit's keywords as audit() takes them (surface_file,
    surface_spacing, box_edge_radius, flat_face_radius, link_coverings, body_region, contact_area,
    payload_*, ...). joint_accel_limit (required: rad/s², one number for every joint or one per
    joint), joint_speed_limit (rad/s, same; math.inf: none; default the URDF's), max_speed_scale
    (default 1: never faster than programmed), output (a path: the re-timed trajectory CSV,
    written when there is a safe timing). thickness ("0..40mm:9", or a list of lengths): the
    cycle time against the covering's thickness, one line per material of materials (catalog
    names; default the scene's covering), and with design=True the per-link design's point
    (its candidates design_materials=, families=, as audit's materials= and families=).
    ValueError on bad input.
    """
    from . import _given, _scene  # the package's helpers (covopt/__init__.py)
    keywords = dict(joint_accel_limit=joint_accel_limit, joint_speed_limit=joint_speed_limit,
                    max_speed_scale=max_speed_scale, output=None if output is None else os.fspath(output),
                    thickness=thickness, materials=materials, design=_given_flag(design),
                    design_materials=design_materials)
    unknown = sorted(set(options) - set(_KEYWORDS) - {"keep_ratio_over_time"})
    if unknown:
        raise TypeError(f"retime() got an unexpected keyword argument {unknown[0]!r}")
    for flag in ("allow_full_compression", "allow_crushing", "allow_unknown_strength", "ignore_joint_limits",
                 "keep_travel"):
        if flag in options:
            options[flag] = _given_flag(options[flag])
    options.pop("keep_ratio_over_time", None)
    return Retime(_covopt.retime(urdf, tip, trajectory, base, urdf_text, _scene(scene), **_given(**keywords, **options)))


def _given_flag(value):
    """A flag as the extension takes it: None for its default False (not an input given), else
    the value itself, which must be a bool (design="yes" or design=0 is a ValueError there)."""
    return None if value is False else value


def _audit_one(trajectory, urdf, tip, base, urdf_text, scene, options, retime_it=False):
    """One audit (or re-timing) on a worker; the result travels as its dict (the scene pickles
    as its keywords)."""
    call = retime if retime_it else audit
    return call(urdf, tip, trajectory, base, scene=scene, urdf_text=urdf_text, **options).to_dict()


class AuditFailure:
    """audit_many's result for a program whose audit raised: ``ok`` is False (an Audit's is
    True), ``index`` its place in the list, ``program`` the trajectory as given (a path, or
    "trajectories[i]" for a dict), ``error`` the exception (ValueError for bad input, as
    audit() raises it), ``error_type`` its class name and ``message`` its text."""

    ok = False

    def __init__(self, index, program, error):
        self.index = index
        self.program = program
        self.error = error
        self.error_type = type(error).__name__
        self.message = str(error)

    def __str__(self):
        return f"{self.program}: {self.error_type}: {self.message}"

    def __repr__(self):
        return f"AuditFailure(index={self.index}, program={self.program!r}, {self.error_type}: {self.message!r})"


class AuditManyError(Exception):
    """audit_many(errors="raise") when a program failed: the message names every failed program;
    ``results`` holds every program's result (Audits and AuditFailures, in order), ``failures``
    the failed ones; the first failure's exception is the cause."""

    def __init__(self, results):
        self.results = results
        self.failures = [r for r in results if not r.ok]
        super().__init__(f"{len(self.failures)} of {len(results)} programs failed: " +
                         "; ".join(str(f) for f in self.failures))


def audit_many(trajectories, urdf, tip, base=None, *, scene=None, urdf_text=None, client=None,
               scheduler_address=None, n_workers=2, threads_per_worker=1, processes=False, errors="collect",
               retime=False, **options):
    """Audits many trajectories (a plant's programs) in parallel through dask.distributed;
    returns one result per program, in the order given: an Audit equal to audit(trajectory, ...)
    run serially (the same library call on the same input: the results are identical), or an
    AuditFailure (``ok`` False; ``program``, ``error``, ``error_type``, ``message``) where that
    program's audit raised. One bad program never loses the others.

    trajectories: CSV paths (str or os.PathLike; a directory: its *.csv files, sorted) or
    trajectory dicts. The other arguments as audit() takes them. retime=True: each program is
    re-timed instead (covopt.retime, its keywords among the options: joint_accel_limit=, ...),
    and the results are Retimes. errors="collect" (default):
    failures are in the list; errors="raise": AuditManyError naming every failed program once
    all have run (its ``results`` holds them all). Where it runs:
    - client: a dask.distributed Client you made (used as it is, not closed);
    - scheduler_address: "tcp://host:8786" of a running scheduler (``dask scheduler``, with
      ``dask worker tcp://host:8786`` on each machine; covopt importable on every worker, and
      the URDF and trajectory paths readable there);
    - neither: a LocalCluster of n_workers workers, threads_per_worker threads each, closed
      afterwards. processes=False (default): threads in this process (the audit runs without
      the GIL, so they run in parallel), which works from any script. processes=True: worker
      processes, which start by re-running the calling script: its call must be under
      ``if __name__ == "__main__":``, else RuntimeError naming that fix before any process starts.
    """
    try:
        from dask.distributed import Client, LocalCluster, wait
    except ImportError as e:  # pragma: no cover - the dependency is documented
        raise ImportError("audit_many needs dask.distributed (Debian: apt-get install python3-distributed; "
                          "pip: pip install distributed)") from e
    if client is not None and scheduler_address is not None:
        raise ValueError("give client or scheduler_address, not both")
    if errors not in ("collect", "raise"):
        raise ValueError(f"errors: expected \"collect\" or \"raise\" (got {errors!r})")
    if not isinstance(processes, bool):
        raise ValueError(f"processes: expected True or False (got {processes!r})")
    if not isinstance(retime, bool):
        raise ValueError(f"retime: expected True or False (got {retime!r})")
    result_type = Retime if retime else Audit
    items = _expand(trajectories)
    urdf = os.fspath(urdf) if urdf is not None else None
    if client is None and scheduler_address is None and processes:
        _refuse_unguarded_script()
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
                             scene=scene, options=options, retime_it=retime, pure=False)
        wait(futures)
        results = []
        for index, (item, future) in enumerate(zip(items, futures)):
            try:
                results.append(result_type(future.result()))
            except Exception as e:  # the program's error (or its worker's), kept with the program
                program = item if isinstance(item, str) else f"trajectories[{index}]"
                results.append(AuditFailure(index, program, e))
    finally:
        for resource in owned:
            resource.close()
    if errors == "raise" and any(not r.ok for r in results):
        failure = AuditManyError(results)
        raise failure from failure.failures[0].error
    return results


def _refuse_unguarded_script():
    """RuntimeError when audit_many(processes=True) is called from the top level of the script
    being run outside ``if __name__ == "__main__":``: each worker process starts by re-running
    that script (multiprocessing's spawn), which would start workers again, crash, and leak
    their semaphores. Nothing is refused where that cannot be told (an interactive session, no
    source, multiprocessing's fork method)."""
    import ast
    import sys
    try:
        from dask import config
        if config.get("distributed.worker.multiprocessing-method", "spawn") == "fork":
            return
    except ImportError:  # pragma: no cover - dask.distributed brings dask
        pass
    main = sys.modules.get("__main__")
    path = getattr(main, "__file__", None)
    if main is None or not path:
        return
    frame = sys._getframe(1)
    while frame is not None and not (frame.f_globals is vars(main) and frame.f_code.co_name == "<module>"):
        frame = frame.f_back
    if frame is None:  # not run by the script's top level (a thread, a callback)
        return
    try:
        with open(path, encoding="utf-8") as f:
            tree = ast.parse(f.read(), path)
    except (OSError, SyntaxError, ValueError):
        return
    line = frame.f_lineno
    for statement in tree.body:
        if statement.lineno <= line <= (statement.end_lineno or statement.lineno):
            if isinstance(statement, ast.If) and _is_main_test(statement.test) and \
                    any(s.lineno <= line <= (s.end_lineno or s.lineno) for s in statement.body):
                return
            raise RuntimeError(
                f"audit_many(processes=True) is called at {path}:{line} outside "
                "'if __name__ == \"__main__\":'; its worker processes start by re-running the script. "
                "Put the call under 'if __name__ == \"__main__\":', or use processes=False (the default: "
                "threads in this process)")


def _is_main_test(test):
    """Whether `test` is ``__name__ == "__main__"`` (either side)."""
    import ast
    if not (isinstance(test, ast.Compare) and len(test.ops) == 1 and isinstance(test.ops[0], ast.Eq)):
        return False
    sides = [test.left, test.comparators[0]]
    names = [s for s in sides if isinstance(s, ast.Name) and s.id == "__name__"]
    texts = [s for s in sides if isinstance(s, ast.Constant) and s.value == "__main__"]
    return len(names) == 1 and len(texts) == 1


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
