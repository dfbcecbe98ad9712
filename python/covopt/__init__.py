"""covopt: safe soft coverings for collaborative robots (multi-layer Hertz head-impact model).

The C++ library behind the ``covopt`` command, as Python calls. A ``covopt.Scene`` holds the
impact scene, its injury limits and safety factor, read once from keywords named as the
CLI's scene flags with underscores (``--robot-mass`` is ``robot_mass``); every call takes one
(default: the paper's scene) and its own options::

    scene = covopt.Scene(robot_mass=10.0, speed=1.5, covering_thickness="20mm")
    result = covopt.simulate(scene)
    result.laceration.ratio, result.safe, result.to_dict()

Values are SI floats in and out; a scene value may also be a string with a unit (``"15mm"``).
The judging rule and the targets may be given as objects, ``rule=covopt.Rule(...)`` and
``regions=covopt.Regions(...)`` (covopt/_inputs.py), instead of their keywords.
Results are read-only objects whose attributes are the keys of the CLI's ``--json`` output
(``to_dict()`` gives that object). Bad input raises ``ValueError`` with the library's (the
CLI's) message naming the keyword; a computation that fails raises
``covopt.ComputationError``, whose ``status`` is the library's status name. Long calls
release the GIL.
"""

from . import _body_regions, _covopt, _provenance
from ._body_regions import (BodyContact, BodyRegionDesign, BodyRegionSpeedLimitTable, BodyRegionSweep,
                            BodyRegionTrajectoryCheck)
from ._audit import Audit, AuditFailure, AuditManyError, Retime, audit, audit_many, retime
from ._catalog import Catalog
from ._errors import ComputationError
from ._inputs import Regions, Rule, takes_objects as _takes_objects
from ._results import (ContactMotion, Design, Material, ReflectedMass, Result, RobustDesign,
                       RobustSimulation, Sensitivities, Simulation, SpeedLimit, SpeedLimitTable,
                       Sweep, TrajectoryCheck)

Scene = _covopt.Scene
for _public in (Scene, ComputationError):
    _public.__module__ = __name__  # shown as covopt.Scene, covopt.ComputationError

__all__ = ["Scene", "Rule", "Regions", "Result", "simulate", "sweep", "optimize", "materials", "material", "Catalog",
           "ComputationError", "max_safe_speed", "max_safe_mass", "speed_limit", "reflected_mass", "iso_robot_mass",
           "contact_motion", "check_trajectory", "worst_case", "injury_probability",
           "sensitivities", "robust_optimize", "load_scene", "BodyContact", "BodyRegionSpeedLimitTable",
           "BodyRegionDesign", "BodyRegionTrajectoryCheck", "BodyRegionSweep", "Audit", "AuditFailure", "AuditManyError",
           "audit", "audit_many", "Retime", "retime"]


def _scene(scene, ranged=False):
    if scene is None:
        return Scene()
    if not isinstance(scene, Scene):
        raise TypeError(f"scene: expected a covopt.Scene (got {type(scene).__name__}); "
                        "write covopt.Scene(**keywords)")
    if scene.ranges and not ranged:
        raise ValueError(f"the scene has ranges ({', '.join(scene.ranges)}): a population, not one "
                         "scene; give it to covopt.worst_case, injury_probability or robust_optimize")
    return scene


def _given(**options):
    return {name: value for name, value in options.items() if value is not None}


@_takes_objects
@_provenance.stamped
def simulate(scene=None, *, method=None, rtol=None, atol=None, max_steps=None, history=False,
             body_region=None, body_area=None, contact=None, contact_area=None, keep_travel=False, limits=None):
    """One impact: its peaks and the injury verdicts, as ``covopt simulate --json``.

    scene: a covopt.Scene (default the paper's scene). A damped scene reports
    coefficient_of_restitution.
    method: None (auto: the exact path where the scene has an energy integral, conservative
    or damped; the default integrator for braking, a neck or history=True), "exact" (refused
    with braking or a neck), "cvode" or an integrator name ("arkode-erk54", "cvode-bdf",
    ...); rtol, atol [-] and max_steps apply to the time path only.
    history: also give ``result.history``, 1-D numpy arrays of equal length
    (time_s, penetration_m, penetration_rate_m_per_s, force_N, compressive_stress_Pa,
    tensile_stress_Pa, energy_density_J_per_m2: the columns of ``--history``; with damping,
    braking or a neck also robot_speed_m_per_s, head_speed_m_per_s [m/s] along the impact
    axis, the head starting at rest, neck_force_N [N] and dissipated_work_J [J], the work of
    the dampers, the brake and a fixed robot's support so far).

    The result's warnings are those of ``covopt simulate --json`` for the same input, including
    the ones about the input itself (the default covering when none is given; a catalog
    material's unknown Poisson ratio, "ν unknown, 0.25 assumed"; a safety factor; covering
    inputs a zero thickness makes moot), which name
    the keyword (``safety_factor='2'``) where the CLI names the flag (``--safety-factor '2'``).

    body_region: an ISO/TS 15066 region ("chest", "hands-fingers", ...; "head" is the skin
    model above), with body_area, contact ("transient" or "clamped") and contact_area (the
    bare robot's contact area: m², or a string with its unit, "1cm2"; needed for a bare robot,
    whose pressure is its force over it): returns a BodyContact (covopt/_body_regions.py), the
    object of ``covopt simulate --body-region --json``; method None or "exact" is the exact
    path, "time-path" or an integrator also runs the time path (``result.time_path``, its
    peaks; the verdict is the exact path's), history=True too (``result.history``).

    keep_travel: the covering's travel rule as a limit (``--keep-travel``): not fully compressed
    (Hertz) or within its measured curve (foam), the safety factor as a reserve. Default
    False: the travel is reported, not a limit (a foam used up is within its law, its stop
    modelled); the law's validity ("law-validity") counts always.

    Returns a Simulation. ``result.safe`` is the CLI's verdict, made by the same library call:
    the injury criteria (laceration, contusion, fracture) and the covering's design rules (within
    its law's validity; not crushed, for a material of known strength; with keep_travel within
    its travel) all hold; ``result.verdict``
    holds each criterion (value, limit, derated_limit, ratio, counted, passed), the governing one
    and the margin. Raises ValueError on bad input, ComputationError when the computation fails.
    """
    if _body_regions.is_region(body_region, body_area=body_area, contact=contact, contact_area=contact_area,
                               limits=limits):
        return _body_regions.simulate(_scene(scene), **_given(**{k: v for k, v in locals().items() if k != "scene"}))
    return Simulation(_covopt.simulate(_scene(scene), **_given(
        method=method, rtol=rtol, atol=atol, max_steps=max_steps, history=history, keep_travel=keep_travel)))


@_takes_objects
@_provenance.stamped
def sweep(x, y=None, *, scene=None, threads=None, body_region=None, body_area=None, contact=None,
          contact_area=None, keep_travel=False, limits=None):
    """A grid of impacts, as ``covopt sweep``: one or two scene quantities over lists of
    values, everything else from the scene. Each point takes the exact path where its scene
    has an energy integral, the time path (ARKODE ERK 5(4), rtol 1e-8) with braking or a neck.

    x, y: ``(quantity, values)``; the quantity is a scene keyword or CLI flag name
    ("speed", "robot_mass" or "robot-mass", "covering_thickness", ...), the values SI
    numbers (a list or numpy array; math.inf, "fixed" or "flat" where a body may be fixed
    or the robot flat); at most 100000 values per axis and 1000000 points in all, as ``covopt
    sweep`` (a ValueError before anything is allocated; an iterator is read up to the cap).
    threads: worker threads, None or 0 = all cores; results are the same for any number.

    Returns a Sweep: ``x`` (and ``y``) as numpy arrays with ``x_quantity`` (``y_quantity``);
    one numpy array per result, ``a[i, j]`` at ``x[i]``, ``y[j]`` (``a[i]`` with one axis):
    the peaks (max_penetration_m, peak_force_N, contact_duration_s,
    time_of_max_compression_s, max_compressive_stress_Pa, max_tensile_stress_Pa,
    max_energy_density_J_per_m2, rebound_speed_m_per_s, phase_at_max), laceration_ratio,
    contusion_ratio, worst_ratio, compression_ratio (δ_max / t2, above 1 fully compressed),
    and the flags valid, scalp_fully_compressed, fully_compressed, safe, admissible (safe
    and not fully compressed). A point outside the model's input range is not valid: NaN
    in every number, False in every flag. Also status, message and brief_report (the
    library's summary line).

    body_region: one ISO/TS 15066 region, with body_area, contact and contact_area as
    simulate takes them: its verdict per point, as ``covopt sweep --body-region --csv``, over
    robot_mass, speed, robot_radius or the covering; returns a BodyRegionSweep
    (covopt/_body_regions.py), where an invalid point carries its error. Each point is judged on
    force, pressure, the law's validity and crushing; keep_travel=True (``--keep-travel``) also
    counts the covering's travel rule (the head's sweep refuses it: its own columns report the travel).

    Raises ValueError on bad input (an unknown quantity, no values, ...), ComputationError
    when no point is a valid scene.
    """
    if _body_regions.is_region(body_region, body_area=body_area, contact=contact, contact_area=contact_area,
                               limits=limits):
        return _body_regions.sweep(x, y, _scene(scene), **_given(
            threads=threads, body_region=body_region, body_area=body_area, contact=contact,
            contact_area=contact_area, keep_travel=keep_travel or None, limits=limits))
    if keep_travel:
        raise ValueError("keep_travel applies with body_region: the head's sweep reports the covering's travel in its "
                         "own columns (fully_compressed, admissible); drop it")
    return Sweep(_covopt.sweep(x, y, _scene(scene), threads))


@_takes_objects
@_provenance.stamped
def optimize(scene=None, *, materials=None, families=None, catalog=None, no_builtin=False,
             thickness=None, max_thickness=None, min_modulus=None, max_modulus=None,
             covering_poisson=None, thickness_step=None, allow_full_compression=False,
             allow_crushing=False, allow_unknown_strength=False, global_algorithm=None, seed=None,
             threads=None, oracle=None, method=None, rtol=None, max_steps=None, body_region=None,
             body_area=None, contact=None, contact_area=None, limits=None):
    """Which covering, how thick, with what margin, as ``covopt optimize --json``.

    scene: a covopt.Scene without a covering (it is what is designed); damping, braking and a
    neck included.
    Problem (a), the default: the thinnest admissible covering, continuous and for every
    candidate material. Admissible: safety_factor times every ratio that counts is <= 1: the
    laceration and contusion ratios; unless allow_full_compression, the covering's travel
    used (not fully compressed, with the reserve the factor leaves); unless allow_crushing (a
    sacrificial liner), the crush ratio (peak compressive stress / the material's compressive
    strength). Materials of unknown strength are recommended only with
    allow_unknown_strength (then with a warning). result["criterion"] names every part,
    result["scope"] says what the verdict covers (and ISO/TS 15066's word on the head), and
    each design carries crush_ratio, governing_criterion and governing_ratio; margin is
    1 - safety_factor x governing_ratio. Problem (b), with thickness [m]: the least injury at that
    thickness. materials: catalog names (default: every material), families: catalog
    families, catalog: TOML catalog files added to the built-in one (no_builtin: only
    them). Design space: max_thickness [m] (0.05), min_modulus and max_modulus [Pa]
    (0.1e6, 1e9), covering_poisson [-] of the continuous design (0.25), thickness_step [m]
    the recommendation is rounded up to (0.5e-3). Solver: global_algorithm "direct-l"
    (default), "isres" or "mlsl"; seed; threads of the catalog snap (0..256, 0 = all cores). Oracle:
    oracle "auto" (default: the exact path where the scene has an energy integral, else the
    time path), "exact" or "time-path"; method: the time path's integrator (default
    "arkode-erk54"; "exact" means oracle="exact"); rtol: its relative tolerance (1e-8);
    max_steps: its step limit per impact (an int >= 10; default 200000).
    result["solver"]["oracle"] says which ran and why.

    body_region: ISO/TS 15066 regions (a name, a list, "all"; "head" among them is judged by
    Park et al.'s model), with body_area, contact, contact_area: the thinnest catalog covering
    (materials, families, max_thickness, thickness_step, allow_*) that keeps every region
    named safe at the scene's speed; returns a BodyRegionDesign (covopt/_body_regions.py).

    Returns a Design: ``covopt optimize --json`` (without the CLI's warnings about its own
    input). Raises ValueError on bad input, ComputationError when the search fails.
    """
    if _body_regions.is_region(body_region, body_area=body_area, contact=contact, contact_area=contact_area,
                               limits=limits):
        return _body_regions.design(_scene(scene), **_given(**{k: v for k, v in locals().items() if k != "scene"}))
    return Design(_covopt.optimize(_scene(scene), **_given(
        materials=materials, families=families, catalog=catalog, no_builtin=no_builtin,
        thickness=thickness, max_thickness=max_thickness, min_modulus=min_modulus,
        max_modulus=max_modulus, covering_poisson=covering_poisson, thickness_step=thickness_step,
        allow_full_compression=allow_full_compression, allow_crushing=allow_crushing,
        allow_unknown_strength=allow_unknown_strength, global_algorithm=global_algorithm,
        seed=seed, threads=threads, oracle=oracle, method=method, rtol=rtol,
        max_steps=max_steps)))


def materials():
    """Every built-in catalog material, as ``covopt materials list --json``: a list of Materials
    (name, family, youngs_modulus_Pa, poisson_ratio, density_kg_per_m3, modulus_basis,
    source, note, defined_at; None where the catalog gives nothing)."""
    return [Material(row) for row in _covopt.materials()]


@_provenance.stamped
def material(name):
    """One built-in catalog material by name (ignoring case), as ``covopt materials show NAME
    --json``. An unknown name raises ValueError: "no material 'X' in the catalog; did you
    mean ...?"."""
    return Material(_covopt.material(name))


from ._results import BodyLimits, BodyRegion  # beside the functions that use them

__all__ += ["body_regions", "body_region_limits"]


def body_regions(limits=None):
    """The body regions of ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M (Tables A.2 and
    A.3), or of the table file `limits` (docs/guide/limits.md), as ``covopt body-regions list
    [--limits FILE] --json``: a list of BodyRegions (12 for the standard), in SI units named in the keys (name, title,
    quasi_static_force_N, transient_permitted, transient_factor and transient_force_N (None
    where A.3.2 forbids transient contact: the skull/forehead and the face), transient_rule,
    stiffness_N_per_m, effective_mass_kg, default_area, areas (name, title, number,
    quasi_static_pressure_Pa, transient_pressure_Pa), sources, limit_table (title, edition,
    source: "built-in" or the path, sha256 of the file's bytes)). A bad table raises ValueError
    naming file:line:column and the key."""
    return [BodyRegion(row) for row in _covopt.body_regions(**({"limits": limits} if limits is not None else {}))]


def body_region_limits(region, area=None, contact="transient", limits=None):
    """The limits ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M (or the table file
    `limits`) sets for one area of one body region.

    region: a region's name ("chest", "hands-fingers"; ignoring case, "_", "/" and " " read
    as "-"). area: one of its areas ("sternum"); None: the area with the lowest pressure.
    contact: "transient" (the region recoils: twice the quasi-static limits) or "clamped"
    (also "quasi-static": held against a fixed object, the quasi-static limits, and
    effective_mass_kg = math.inf).

    Returns a BodyLimits: region, area, area_number, contact, force_N [N], pressure_Pa [Pa],
    stiffness_N_per_m [N/m], effective_mass_kg [kg] and describe, who sets the limits
    ("ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M, transient (2× quasi-static), chest
    (sternum): 280 N, 240 N/cm²") and edition, the table's. Raises ValueError for an unknown region or area (naming the choices) and for
    transient contact with the skull/forehead or the face (naming A.3.2).
    """
    return BodyLimits(_covopt.body_region_limits(region, area, contact,
                                                 **({"limits": limits} if limits is not None else {})))


@_takes_objects
@_provenance.stamped
def max_safe_speed(scene=None, *, allow_full_compression=False, allow_crushing=False, keep_travel=False, oracle=None,
                   method=None, rtol=None, max_steps=None):
    """The largest impact speed [m/s] such that every speed up to it is safe: the injury
    ratios <= 1/safety_factor and the covering within its law's validity (a Hertz covering not
    fully compressed, unless allow_full_compression); with keep_travel also within its travel
    (not fully compressed / within its curve) with the travel the factor reserves; a catalog material of known
    compressive strength also must not crush (safety_factor x peak compressive stress <= its
    strength) unless allow_crushing (optim::MaxSafeSpeed). The result's warnings say when
    crushing is not checked (no covering given, a covering given by its modulus, a material
    of unknown strength). The scene (damping,
    braking and a neck included) gives no speed (it is what is computed). oracle, method,
    rtol, max_steps: as optimize's (a scene without an energy integral is bracketed on the
    time path).

    Returns a SpeedLimit: max_safe_speed_m_per_s (None when not even 1e-6 m/s is safe; 100 when
    safe up to the model's ceiling), limited_by ("laceration", "contusion", "fracture",
    "full-compression", "law-validity", "crush", "none" at the ceiling), covering_law,
    within_law, validity {within, note}, covering_used_up_m_per_s (the speed at which the
    covering is used up, None bare or above 100 m/s), laceration_ratio, contusion_ratio,
    compression_ratio (of the impact at the limit), status ("limited",
    "safe-up-to-search-limit", "no-safe-value"), robot_mass_kg, material, message,
    brief_report. Raises ValueError on bad input, ComputationError (status
    "evaluation-failed") when the time path fails on an impact of the search: a failed
    search is no limit.
    """
    return SpeedLimit(_covopt.max_safe_speed(_scene(scene), **_given(
        allow_full_compression=allow_full_compression, allow_crushing=allow_crushing, keep_travel=keep_travel,
        oracle=oracle, method=method, rtol=rtol, max_steps=max_steps)))


@_takes_objects
@_provenance.stamped
def max_safe_mass(scene=None, *, allow_full_compression=False, allow_crushing=False, keep_travel=False, oracle=None,
                  method=None, rtol=None, max_steps=None):
    """The largest reflected robot mass [kg] that is safe, with every lighter robot, at the
    scene's speed (optim::MaxSafeMass); as max_safe_speed, the scene without robot_mass.

    Returns a SpeedLimit like max_safe_speed's with max_safe_mass_kg ("fixed" when even a
    fixed robot is safe) and speed_m_per_s. Raises ValueError on bad input,
    ComputationError as max_safe_speed.
    """
    return SpeedLimit(_covopt.max_safe_mass(_scene(scene), **_given(
        allow_full_compression=allow_full_compression, allow_crushing=allow_crushing, keep_travel=keep_travel,
        oracle=oracle, method=method, rtol=rtol, max_steps=max_steps)))


@_takes_objects
@_provenance.stamped
def speed_limit(scene=None, *, solve_for="speed", values=None, materials=None,
                allow_full_compression=False, allow_crushing=False, oracle=None, method=None,
                rtol=None, max_steps=None, body_region=None, body_area=None, contact=None,
                contact_area=None, keep_travel=False, limits=None):
    """A table of limits, as ``covopt speed-limit --json``: solve_for="speed" gives the max
    safe speed for each robot mass in values [kg] (math.inf or "fixed" for a fixed robot;
    default the scene's), solve_for="mass" the max safe reflected mass for each speed in
    values [m/s] (default the scene's; at most 100000, as the CLI's lists). materials: a catalog
    name or a list of names, one block of rows each (default the scene's covering).

    oracle, method, rtol, max_steps: as optimize's.

    body_region: ISO/TS 15066 regions (a name, a list, "all"), with body_area, contact,
    contact_area: the max safe speed for each robot mass in values (default the scene's) per
    area, bare and with the scene's covering, and which limit binds; "all" with a transient
    contact adds the head's row (Park et al.'s skin model, max_safe_speed). A bare scene
    needs contact_area; with a covering and none, the bare column is the force's alone (the
    warnings say so). Returns a BodyRegionSpeedLimitTable (covopt/_body_regions.py), the
    object of ``covopt speed-limit --body-region --json``.

    Returns a SpeedLimitTable (solve_for, criterion, safety_factor, limits, search_limit,
    oracle, rows, scene, warnings: the CLI's, the input's included (a safety factor, an assumed
    covering or ν), naming the keywords). Raises
    ValueError on bad input, ComputationError (status "evaluation-failed") when the time path
    fails on an impact of a row's search.
    """
    if _body_regions.is_region(body_region, body_area=body_area, contact=contact, contact_area=contact_area,
                               limits=limits):
        return _body_regions.speed_limit(_scene(scene), **_given(**{k: v for k, v in locals().items() if k != "scene"}))
    return SpeedLimitTable(_covopt.speed_limit(_scene(scene), **_given(
        solve_for=solve_for, values=values, materials=materials,
        allow_full_compression=allow_full_compression, allow_crushing=allow_crushing, keep_travel=keep_travel,
        oracle=oracle, method=method, rtol=rtol, max_steps=max_steps)))


@_provenance.stamped
def reflected_mass(urdf, tip, joints, base=None, point=(0.0, 0.0, 0.0), direction=None, *,
                   urdf_text=None, ignore_joint_limits=False, payload_mass=None, payload_com=None,
                   payload_inertia=None):
    """The reflected mass of a robot at a contact point, as ``covopt robot --json``.

    urdf: the robot model's file (str or path; None with urdf_text=, the URDF itself);
    tip: the link that hits; base: the chain's base link (default the URDF's root);
    joints: the movable joints' positions in chain order [rad, m for prismatic joints];
    point: the contact point in the tip link's frame [m]; direction: the impact direction
    in the base frame (any length; None: only the extremes). Joint positions must lie within a
    full turn (|q| <= 2 pi rad: radians, not degrees; |q| <= 10 m) and within the URDF's
    <limit>s; ignore_joint_limits=True skips the URDF's limits and adds a warning saying so.

    A tool or payload on the tip link (a gripper with its part) counts in the mass:
    payload_mass [kg] (None or 0: none), payload_com its centre of mass (x, y, z) in the tip
    link's frame [m] (default its origin), payload_inertia (ixx, iyy, izz, ixy, ixz, iyz) about
    the centre of mass in the tip link's axes [kg m²] (URDF's order; default a point mass), as
    ``--payload-mass/--payload-com/--payload-inertia``.

    Returns a ReflectedMass: reflected_mass_kg (None without a direction), direction,
    max_reflected_mass_kg, max_direction, min_reflected_mass_kg, min_direction,
    contact_point_m (base frame), joint_names, payload (None without one, else mass_kg,
    center_of_mass_m, inertia_kg_m2 (3 x 3) and without_payload: the three masses on the bare
    chain), status, message, warnings. A mass the robot cannot move is the string "fixed"
    (infinite), with a warning.

    Raises ValueError on bad input (missing or malformed URDF, unknown links, a joint
    count that does not match, non-finite numbers, a zero direction, a position beyond a full
    turn or the URDF's limits, a URDF with a cycle, implausible masses, inertias or origins,
    a non-physical payload: a negative mass, an inertia with a negative principal moment or one
    above the sum of the other two, naming the keyword and the value).
    """
    return ReflectedMass(_covopt.reflected_mass(urdf, tip, joints, base=base, point=point,
                                                direction=direction, urdf_text=urdf_text,
                                                ignore_joint_limits=ignore_joint_limits,
                                                payload_mass=payload_mass, payload_com=payload_com,
                                                payload_inertia=payload_inertia))


def iso_robot_mass(moving_mass, payload_mass=None):
    """ISO/TS 15066:2016 Annex A's estimate of the robot's effective mass without a robot
    model, m_R = M/2 + m_L [kg]: moving_mass M the total mass of the robot's moving parts [kg],
    payload_mass m_L the payload with tooling and workpiece [kg] (None: 0). As ``--robot-moving-mass
    M --payload-mass m_L`` on the CLI: give it as the scene's robot_mass,
    ``Scene(robot_mass=covopt.iso_robot_mass(30, 2.5))``. Not a reflected mass: it ignores the
    pose and the impact's direction; reflected_mass() gives that where a URDF exists. Raises
    ValueError unless 0 < M <= 1e6 kg and 0 <= m_L <= 1e4 kg.
    """
    return _covopt.iso_robot_mass(moving_mass, payload_mass)


@_provenance.stamped
def contact_motion(urdf, tip, trajectory, base=None, point=(0.0, 0.0, 0.0), *, urdf_text=None,
                   ignore_joint_limits=False, payload_mass=None, payload_com=None, payload_inertia=None):
    """The contact point's motion along a joint trajectory.

    trajectory: a CSV file (an optional header line; time [s], the n joint positions, the n
    joint velocities per line, in chain order; a first line of numbers only is a sample, with a
    warning; at most 64 MiB and 10**6 samples) or a dict with exactly the keys time_s (N),
    positions (N x n) and velocities (N x n). Positions and velocities are checked against
    the URDF's limits (ignore_joint_limits=True: not, with a warning). Other arguments, the
    payload's included, as reflected_mass.

    Returns a ContactMotion: samples (time_s, speed_m_per_s, moving, direction (None at rest),
    velocity_m_per_s, contact_point_m, reflected_mass_kg along the motion; at rest the
    largest over all directions), joint_names, status, message, warnings.
    """
    return ContactMotion(_covopt.contact_motion(urdf, tip, trajectory, base=base, point=point,
                                                urdf_text=urdf_text,
                                                ignore_joint_limits=ignore_joint_limits,
                                                payload_mass=payload_mass, payload_com=payload_com,
                                                payload_inertia=payload_inertia))


@_takes_objects
@_provenance.stamped
def check_trajectory(urdf, tip, trajectory, base=None, point=(0.0, 0.0, 0.0), *, scene=None,
                     urdf_text=None, allow_full_compression=False, allow_crushing=False, keep_travel=False,
                     ignore_joint_limits=False, body_region=None, body_area=None, contact=None,
                     contact_area=None, payload_mass=None, payload_com=None, payload_inertia=None, limits=None):
    """Is a robot motion safe with this covering, and by how much may it be sped up or must
    it be slowed down? As ``covopt robot --trajectory --json``.

    The robot and trajectory as contact_motion takes them (a payload on the tip too); the covering, head and limits from
    the scene (no robot_mass or speed: each sample brings its reflected mass
    along the motion and the contact point's speed). Per sample: the injury ratios of an
    impact at that speed and mass, and the largest safe speed at that mass
    (optim::CheckTrajectory). safe_speed_scale = min over moving samples of max safe speed /
    speed: running the whole trajectory k times faster is safe exactly when k <= it.

    Returns a TrajectoryCheck: status ("safe", "unsafe", "at-rest"), message, safe_speed_scale (None
    when at rest throughout), worst_sample (index and the sample's keys; None at rest),
    sample_count, unsafe_sample_count, criterion, safety_factor, limits, search_limit, scene,
    joint_names, samples (time_s, speed_m_per_s, reflected_mass_kg ("fixed" if infinite),
    moving, max_safe_speed_m_per_s (None when no speed is safe), speed_scale, limited_by,
    laceration_ratio, contusion_ratio, compression_ratio, safe), warnings (the CLI's: the
    input's, e.g. an assumed covering or ν, the robot's and the check's). Raises ValueError on bad input,
    ComputationError (status "evaluation-failed") when the time path (a scene with braking or
    a neck) fails at a sample: the trajectory then has no verdict.

    body_region: ISO/TS 15066 regions (a name, a list, "all"; "head" among them is judged by
    the check above), with body_area, contact and contact_area as simulate takes them: every
    sample against every region named (optim::CheckTrajectoryForBodyRegions); returns a
    BodyRegionTrajectoryCheck (covopt/_body_regions.py), the object of ``covopt robot
    --trajectory --body-region --json``.
    """
    payload = (payload_mass, payload_com, payload_inertia)
    if _body_regions.is_region(body_region, body_area=body_area, contact=contact, contact_area=contact_area,
                               limits=limits):
        return _body_regions.check_trajectory(
            urdf, tip, trajectory, base, point, urdf_text, ignore_joint_limits, payload, _scene(scene), **_given(
                allow_full_compression=allow_full_compression or None, allow_crushing=allow_crushing or None,
                keep_travel=keep_travel or None,
                body_region=body_region, body_area=body_area, contact=contact, contact_area=contact_area,
                limits=limits))
    return TrajectoryCheck(_covopt.check_trajectory(
        urdf, tip, trajectory, base, point, urdf_text, ignore_joint_limits, payload, _scene(scene),
        allow_full_compression=allow_full_compression, allow_crushing=allow_crushing, keep_travel=keep_travel))


# Robust design over a population (docs/model.md §11). `ranges` maps scene inputs (keyword
# names, head_mass or head-mass) to (low, high) or "LO..HI", values with units as elsewhere
# (default the scene's ranges, Scene(ranges=...) or a scene file's); the scene gives the rest
# (the exact path only: no damping, braking or neck).

@_provenance.stamped
def worst_case(scene=None, *, ranges=None):
    """The worst impact over the box (optim::FindWorstCase: corners, a Halton sample, DIRECT-L,
    COBYLA). Returns as a RobustSimulation the dict ``covopt simulate --json`` prints with the same ranges: the impact
    at the worst case (peaks, verdicts, scene) plus uncertain_inputs and worst_case {inputs,
    units, laceration_ratio, contusion_ratio, compression_ratio, governing_ratio, binding,
    admissible, corner_governing_ratio, found_by, evaluations, seconds}. ValueError on bad input.
    """
    scene = _scene(scene, ranged=True)
    return RobustSimulation(_covopt.worst_case(scene, ranges=ranges or scene.ranges))


@_provenance.stamped
def injury_probability(scene=None, *, ranges=None, samples, seed=1, threads=0, distributions=None):
    """Monte Carlo over the box: as worst_case, plus injury_probability {samples, seed,
    laceration, contusion, any, fully_compressed, inadmissible, ci95: {name: [low, high]},
    counts}, the dict ``covopt simulate --json --samples N --seed S`` prints. distributions maps
    an input to ("normal" or "lognormal", mean, sd) (of the value, with units; truncated to the
    range); uniform otherwise. samples is a whole number in [1, 10000000000]; seed any whole
    number in [0, 18446744073709551615] (2**64 - 1, as --seed); threads in [0, 4096]. Identical
    for any threads (0 = all cores)."""
    scene = _scene(scene, ranged=True)
    return RobustSimulation(_covopt.injury_probability(scene, **_given(
        ranges=ranges or scene.ranges, samples=samples, seed=seed, threads=threads, distributions=distributions)))


@_provenance.stamped
def sensitivities(scene=None):
    """The elasticities d ln r / d ln x of the laceration, contusion and compression ratios to
    every scene input at this scene (optim::ComputeElasticities), the ``sensitivities`` object
    of ``covopt simulate --json --sensitivities``: {laceration_ratio, contusion_ratio,
    compression_ratio, evaluations, rows: [{field, unit, value, laceration, contusion,
    compression, method, reliable, discrepancy}]} in tornado order."""
    return Sensitivities(_covopt.sensitivities(_scene(scene)))


@_takes_objects
@_provenance.stamped
def robust_optimize(scene=None, *, ranges=None, samples=None, seed=1, threads=0, distributions=None,
                    max_injury_probability=None, allow_full_compression=False, allow_crushing=False,
                    allow_unknown_strength=False):
    """The thinnest built-in catalog covering admissible for every value in the box
    (optim::FindRobustThinnestCovering), the dict ``covopt optimize --json`` prints with the
    same ranges (worst_case: the input values that set the design). With samples, the
    recommendation's injury_probability too; with max_injury_probability (and samples), the
    thinnest covering whose probability of failing the criterion is shown to be at most that
    (the upper end of its 95 % interval, not the estimate alone; optim::FindProbabilityDesign),
    as ``covopt optimize --max-injury-probability P``. The criterion is optimize's: crushing
    counts unless allow_crushing, unknown strengths are refused unless allow_unknown_strength.
    seed is any whole number in [0, 18446744073709551615] (2**64 - 1); threads 0 = all cores."""
    scene = _scene(scene, ranged=True)
    return RobustDesign(_covopt.robust_optimize(scene, **_given(
        ranges=ranges or scene.ranges, samples=samples, seed=seed, threads=threads, distributions=distributions,
        max_injury_probability=max_injury_probability,
        allow_full_compression=allow_full_compression, allow_crushing=allow_crushing,
        allow_unknown_strength=allow_unknown_strength)))


def load_scene(path):
    """A scene file (TOML, the format of ``covopt simulate --scene``; see cli/examples/paper_scene.toml),
    read by the library's reader with the CLI's checks and messages, as a covopt.Scene holding
    what the file sets (its repr shows the keywords); ranges the file writes ("3.7kg..5.8kg")
    are the Scene's ``ranges`` ({"head_mass": (low, high)} in SI), which worst_case,
    injury_probability and robust_optimize take. So ``covopt.simulate(covopt.load_scene(path))``
    is ``covopt simulate --scene path``.

    Raises ValueError naming file:line:column, the key and what is allowed, as the CLI does.
    """
    return Scene(**_covopt.load_scene(str(path)))



class Measurement(Result):
    """covopt.predict_measurement's result, the object of ``covopt measure --json``
    (``to_dict()``): scene, safety_factor, device (name, spring_N_per_m, pad_shore_a,
    pad_modulus_Pa and its source, pad_thickness_m, pad_thickness_assumed, reduced_mass_kg,
    peak_force_N: what the device shows, stiff_pad_force_N: the spring alone, an upper bound,
    peak_pressure_Pa: what a pressure film on the pad shows, pad and covering layers, validity,
    force and pressure against the region's limits, admissible), body_model (the body model's
    verdict, as covopt.simulate(body_region=...)'s), comparison (force_difference_N,
    force_ratio, pressure_difference_Pa, pressure_ratio: device against body model), safe,
    scope, summary, warnings.
    """
    _report_kind = "measure"


@_takes_objects
@_provenance.stamped
def predict_measurement(scene=None, *, body_region, body_area=None, contact=None, contact_area=None,
                        keep_travel=False, device=None, device_spring=None, device_pad=None,
                        device_pad_thickness=None):
    """What a biofidelic force-measuring device would read when the scene's robot strikes it,
    beside the body model's prediction for the same region: ``covopt measure --json``
    (docs/guide/limits.md, docs/model.md §13.11).

    The device is a spring on a fixed base under a pad of Shore A hardness (its modulus from
    the Ruess correlation): the robot's whole reflected mass strikes it, and its pad and the
    robot's covering form one Hertz contact. body_region, body_area, contact, contact_area and
    keep_travel: as covopt.simulate's (one ISO region). The device: device, a spring and pad
    pair ("25+70", N/mm + Shore A, DGUV FB HM-080) or the region it stands for ("chest"), with
    device_pad_thickness (m, or "7mm"; default 7 mm, assumed and said so); or device_spring (N/m,
    or "25N/mm") with device_pad ("70ShA,7mm": hardness and thickness); or neither: the region's
    own pair. Returns a Measurement. Raises ValueError on bad input, naming the keyword.
    """
    return Measurement(_covopt.predict_measurement(_scene(scene), **_given(
        body_region=body_region, body_area=body_area, contact=contact, contact_area=contact_area,
        keep_travel=keep_travel, device=device, device_spring=device_spring, device_pad=device_pad,
        device_pad_thickness=device_pad_thickness)))


__all__ += ["predict_measurement", "Measurement"]
