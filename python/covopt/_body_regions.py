"""The ISO/TS 15066 body regions (docs/model.md §13): covopt.simulate, speed_limit, optimize,
check_trajectory and sweep with ``body_region=``, and their typed results.

The keywords are the CLI's flags: ``body_region`` (``--body-region``: a region of Table A.2,
"head" for Park et al.'s skin model, "all", or a list), ``body_area`` (``--body-area``; default
the region's lowest pressure limit), ``contact`` (``--contact``: "transient" or "clamped")
and ``contact_area`` [m²] (``--contact-area``: the bare robot's contact area, for its
pressure; a number in m², or a string with its unit, "1cm2"; the bare robot's own verdict
needs it) and ``limits`` (``--limits``: a body-region table file of one's own, the built-in
table's format; default the built-in ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M). The robot (robot_mass, speed, robot_radius), its covering and the safety factor
come from the covopt.Scene; the region's spring k_H and mass m_H from Table A.3. The results
are the CLI's ``--json`` objects for the same input (``to_dict()``), their warnings naming the
keywords where the CLI names its flags.
"""

import numpy as np

from . import _covopt
from ._results import Result

__all__ = ["BodyContact", "BodyRegionSpeedLimitTable", "BodyRegionDesign", "BodyRegionTrajectoryCheck",
           "BodyRegionSweep"]

_CONTACT_KEYWORDS = ("body_area", "contact", "contact_area", "limits")


class BodyContact(Result):
    """covopt.simulate(..., body_region=...)'s result: one contact with one area of one region,
    as ``covopt simulate --body-region R --json`` (``to_dict()`` is that object).

    scene (robot_mass_kg, speed_m_per_s, robot_radius_m, covering (None bare), contact,
    contact_area_m2, and for a braking robot braking (reaction_delay_s, braking_m_per_s2)),
    safety_factor, regions (one verdict), head (None), safe, warnings; and, when the time path
    ran (method="time-path", an integrator, or history=True), time_path (its peaks: method,
    peak_force_N, max_approach_m, contact_duration_s, ...; the verdict is the exact path's, or
    for a braking robot, reaction_delay= and braking= in the scene, the time path's: the only
    one that answers it) and with history=True history (numpy arrays time_s, approach_m,
    approach_rate_m_per_s, force_N, robot_speed_m_per_s, braking_work_J).

    The verdict's keys are attributes too (``r.peak_force_N`` is ``r.regions[0].peak_force_N``):
    region, area, area_title, contact, criteria (whose: "ISO/TS 15066:2016 ..."), scope,
    method, reduced_mass_kg, energy_transferred_J, peak_force_N, peak_pressure_Pa (None for a
    bare robot without contact_area), contact_radius_m, covering_deflection_m,
    body_deflection_m, compression_ratio (δ_c / 0.8 b_c, 0 bare), fully_compressed, force
    (value_N, limit_N, ratio), pressure (value_Pa, limit_Pa, ratio, evaluated), crush (check,
    ratio), governing ("force", "pressure", "full-compression", "crush"), governing_ratio,
    admissible, margin.
    """
    _report_kind = "simulate"

    def __getattr__(self, key):
        data = object.__getattribute__(self, "_data")
        if key not in data and data.get("regions") and key in data["regions"][0]:
            return Result.__getattr__(Result(data["regions"][0], "BodyContact"), key)
        return Result.__getattr__(self, key)

    def __dir__(self):
        return list(self._data) + list(self._data["regions"][0])


class BodyRegionSpeedLimitTable(Result):
    """covopt.speed_limit(..., body_region=...)'s result, as ``covopt speed-limit --body-region
    --json``: one row per area of every region named per robot mass (``for row in table``,
    ``len(table)``, ``table[i]``).

    Each row: material, robot_mass_kg, region, area (None for the head), contact,
    force_limit_N, pressure_limit_Pa [Pa] (None for the head), bare_max_speed_m_per_s,
    bare_limited_by, covered_max_speed_m_per_s, covered_limited_by (None without a
    covering), gain (covered / bare speed), criteria (whose), bare_status, covered_status.
    With body_region="all" and a transient contact each mass's last row is the head's,
    judged by Park et al.'s skin model (limited_by "laceration", "contusion" or
    "full-compression"). Also solve_for, scene, criterion, safety_factor, warnings.
    """
    _report_kind = "speed-limit"

    def __iter__(self):
        return iter(self.rows)

    def __len__(self):
        return len(self._data["rows"])

    def __getitem__(self, index):
        return self.rows[index]


class BodyRegionDesign(Result):
    """covopt.optimize(..., body_region=[...])'s result, as ``covopt optimize --body-region
    --json``: the covering (catalog material and thickness) that lets the robot reach the
    scene's speed for every region named.

    message, speed_m_per_s, scene, safety_factor, criterion, recommendation (the
    recommended candidate, or None), bare_robot (safe, regions (verdicts, keys as
    BodyContact's), head), candidates (material, youngs_modulus_Pa, poisson_ratio,
    thickness_m (None when no thickness is admissible), admissible, governing_ratio,
    governing_where, regions, head (laceration_ratio, contusion_ratio, compression_ratio,
    criteria)), scope, warnings.
    """
    _report_kind = "optimize"


class BodyRegionTrajectoryCheck(Result):
    """covopt.check_trajectory(..., body_region=...)'s result, as ``covopt robot --trajectory
    --body-region --json``.

    status ("safe", "unsafe", "at-rest"), message, safe_speed_scale (min over the moving
    samples and the regions of max safe speed / speed; None at rest throughout), worst_sample
    (its index, or None), unsafe_sample_count, criterion, scene, regions (region, area,
    contact, scope), head (status, safe_speed_scale, message of the head's own check, or
    None), samples (time_s, speed_m_per_s, reflected_mass_kg, moving, worst_ratio, binding,
    worst_region, safe, max_safe_speed_m_per_s, limiting_region (indices into regions),
    limited_by, speed_scale), warnings.
    """
    _report_kind = "robot --trajectory"


class BodyRegionSweep(Result):
    """covopt.sweep(..., body_region=...)'s result: one region's verdict over the grid, the
    columns of ``covopt sweep --body-region --csv``, as numpy arrays ``a[i, j]`` at ``x[i]``,
    ``y[j]`` (``a[i]`` with one axis).

    x (and y) with x_quantity (y_quantity); peak_force_N, peak_pressure_Pa (NaN where not
    evaluated), covering_deflection_m, force_ratio, pressure_ratio, compression_ratio,
    crush_ratio (NaN where not checked), governing_ratio (floats); fully_compressed,
    admissible, valid (bools); governing (str: "force", ...; "" where invalid) and error (str:
    the library's message where the point is outside the model's range, else ""). An invalid
    point is NaN in every number and False in every flag. Also region, area, contact, scope
    (whose limits) and message (a summary line).
    """


def is_region(body_region, **contact):
    """True when body_region names ISO/TS 15066 regions (not the head alone): the call takes
    this module's path. False for None (then no contact keyword may be given) and "head" (the
    skin model; then only contact="transient")."""
    if body_region is None:
        named = [k for k, v in contact.items() if v is not None]
        if named:
            raise ValueError(f"{named[0]} applies to an ISO/TS 15066 body region; give body_region= "
                             "(e.g. body_region='chest')")
        return False
    if isinstance(body_region, str) and _covopt.names_the_head(body_region):
        named = [k for k, v in contact.items()
                 if v is not None and not (k == "contact" and v == "transient")]
        if named:
            raise ValueError(f"{named[0]}: body_region='head' is judged by Park et al.'s skin model "
                             "(a transient impact on the scalp), not by ISO/TS 15066's areas; drop it")
        return False
    return True


def _refuse(call, options, allowed):
    """Refuses the call's options that do not apply with body_region (given, not default)."""
    defaults = {"no_builtin": False, "solve_for": "speed", "history": False}
    for name, value in options.items():
        if name not in allowed and value != defaults.get(name, False):
            raise ValueError(f"{name} does not apply to {call} with body_region")
    return {name: value for name, value in options.items() if name in allowed}


_REGION = ("body_region", "body_area", "contact", "contact_area", "limits")
_RULE = ("allow_full_compression", "allow_crushing")
_TRAVEL = ("keep_travel",)  # the judging calls' --keep-travel (not optimize's: its rule keeps the travel)


def simulate(scene, **options):
    """covopt.simulate with body_region (not "head")."""
    options = _refuse("simulate", options, _REGION + _TRAVEL + ("method", "rtol", "atol", "max_steps", "history"))
    return BodyContact(_covopt.simulate_body_region(scene, **options))


def speed_limit(scene, **options):
    """covopt.speed_limit with body_region: the table (values: robot masses [kg])."""
    options = _refuse("speed_limit", options, _REGION + _RULE + _TRAVEL + ("values",))
    return BodyRegionSpeedLimitTable(_covopt.body_region_speed_limit(scene, **options))


def design(scene, **options):
    """covopt.optimize with body_region."""
    options = _refuse("optimize", options, _REGION + _RULE + (
        "allow_unknown_strength", "materials", "families", "max_thickness", "thickness_step"))
    return BodyRegionDesign(_covopt.design_for_body_regions(scene, **options))


def check_trajectory(urdf, tip, trajectory, base, point, urdf_text, ignore_joint_limits, payload, scene,
                     **options):
    """covopt.check_trajectory with body_region; payload: (payload_mass, payload_com, payload_inertia)."""
    options = _refuse("check_trajectory", options, _REGION + _RULE + _TRAVEL)
    return BodyRegionTrajectoryCheck(_covopt.check_trajectory_body_region(
        urdf, tip, trajectory, base, point, urdf_text, ignore_joint_limits, payload, scene, **options))


def sweep(x, y, scene, **options):
    """covopt.sweep with body_region (one ISO region)."""
    options = _refuse("sweep", options, _REGION + _TRAVEL)
    data = _covopt.sweep_body_region(x, y, scene, **options)
    shape = data["admissible"].shape
    for key in ("governing", "error"):
        data[key] = np.array(data[key], dtype=str).reshape(shape)
    return BodyRegionSweep(data)
