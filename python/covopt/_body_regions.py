"""The ISO/TS 15066 body regions (docs/model.md §13): covopt.simulate, speed_limit and optimize
with ``body_region=``, and their typed results.

The keywords are the CLI's flags: ``body_region`` (``--body-region``: a region of Table A.2,
"head" for Park et al.'s skin model, "all", or a list), ``body_area`` (``--body-area``; default
the region's lowest pressure limit), ``contact`` (``--contact``: "transient" or "clamped")
and ``contact_area`` [m²] (``--contact-area``: the bare robot's contact area, for its
pressure). The robot (robot_mass, speed, robot_radius), its covering and the safety factor
come from the covopt.Scene; the region's spring k_H and mass m_H from Table A.3.
"""

from . import _covopt
from ._results import Result

__all__ = ["BodyContact", "BodyRegionSpeedLimitTable", "BodyRegionDesign"]

_CONTACT_KEYWORDS = ("body_area", "contact", "contact_area")


class BodyContact(Result):
    """covopt.simulate(..., body_region=...)'s result: one contact with one area of one region.

    region, area, contact, force_limit_N, pressure_limit_Pa [Pa], stiffness_N_per_m,
    effective_mass_kg ("fixed" when clamped); the peaks: peak_force_N, peak_pressure_Pa (None
    for a bare robot without contact_area), compression_ratio (δ_c / 0.8 b_c, 0 bare),
    fully_compressed, energy_transferred_J (½ μ v²), body_energy_J, covering_energy_J,
    reduced_mass_kg, contact_radius_m, covering_deflection_m, body_deflection_m,
    max_approach_m, contact_duration_s (None with a covering on the exact path),
    rebound_speed_m_per_s, method; the verdict: ratios (force, pressure, compression, crush;
    None where not evaluated), crush_check, governing ("force", "pressure",
    "full-compression", "crush"), governing_ratio, admissible, margin, scope (whose criteria:
    "ISO/TS 15066:2016 ..."); scene, warnings; history with history=True.
    """


class BodyRegionSpeedLimitTable(Result):
    """covopt.speed_limit(..., body_region=...)'s result: one row per area of every region
    named (``for row in table``, ``len(table)``, ``table[i]``).

    Each row: region, area, contact, force_limit_N, pressure_limit_Pa (None for the head),
    scope, bare and covered (max_safe_speed_m_per_s, limited_by, status, message; covered is
    None without a covering), gain (covered / bare speed). With body_region="all" and a
    transient contact the last row is the head's, judged by Park et al.'s skin model (its
    limited_by is "laceration", "contusion" or "full-compression"). Also contact,
    safety_factor, criteria (the limits counted), scene, warnings.
    """

    def __iter__(self):
        return iter(self.rows)

    def __len__(self):
        return len(self._data["rows"])

    def __getitem__(self, index):
        return self.rows[index]


class BodyRegionDesign(Result):
    """covopt.optimize(..., body_region=[...])'s result: the covering (catalog material and
    thickness) that lets the robot reach the scene's speed for every region named.

    message, speed_m_per_s, bare_robot (one judgement per region, keys as BodyContact's),
    bare_head, bare_robot_safe, candidates (material, family, thickness_m (None when no
    thickness is admissible), admissible, governing_ratio, governing_where, regions, head),
    recommendation (the recommended candidate, or None), scope, warnings, safety_factor.
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
    if isinstance(body_region, str) and body_region.lower() == "head":
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


_REGION = ("body_region", "body_area", "contact", "contact_area")
_RULE = ("allow_full_compression", "allow_crushing")


def simulate(scene, **options):
    """covopt.simulate with body_region (not "head")."""
    options = _refuse("simulate", options, _REGION + ("method", "rtol", "atol", "max_steps", "history"))
    return BodyContact(_covopt.simulate_body_region(scene, **options))


def speed_limit(scene, head_speed_limit, **options):
    """covopt.speed_limit with body_region: the table; the head's row (Park et al.) from
    head_speed_limit(scene, allow_full_compression=, allow_crushing=) -> SpeedLimit
    (covopt.max_safe_speed)."""
    options = _refuse("speed_limit", options, _REGION + _RULE)
    table = _covopt.body_region_speed_limit(scene, **options)
    if table.pop("head"):
        rule = {k: v for k, v in options.items() if k in _RULE}
        table["rows"].append(_head_row(scene, table, lambda s: head_speed_limit(s, **rule)))
    table["warnings"] = []
    return BodyRegionSpeedLimitTable(table)


def _head_row(scene, table, head_speed_limit):
    covered = table["scene"]["covering"]["thickness_m"] > 0
    bare_scene = scene.replace(covering_thickness=0, material=None, covering_modulus=None,
                               covering_poisson=None)

    def limit(s):
        r = head_speed_limit(s)
        return {"max_safe_speed_m_per_s": r.max_safe_speed_m_per_s, "limited_by": r.limited_by,
                "status": r.status, "message": r.message}

    bare = limit(bare_scene)
    cover = limit(scene) if covered else None
    gain = (cover["max_safe_speed_m_per_s"] / bare["max_safe_speed_m_per_s"]
            if cover and cover["max_safe_speed_m_per_s"] and bare["max_safe_speed_m_per_s"] else None)
    return {"region": "head", "region_title": "Head (skin model)", "area": None, "area_title": None,
            "contact": "transient", "force_limit_N": None, "pressure_limit_Pa": None,
            "stiffness_N_per_m": None, "effective_mass_kg": scene.head_mass,
            "scope": "skin injury, Park et al. 2011", "bare": bare, "covered": cover, "gain": gain}


def design(scene, **options):
    """covopt.optimize with body_region."""
    options = _refuse("optimize", options, _REGION + _RULE + (
        "allow_unknown_strength", "materials", "families", "max_thickness", "thickness_step"))
    return BodyRegionDesign(_covopt.design_for_body_regions(scene, **options))
