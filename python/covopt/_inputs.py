"""covopt.Rule and covopt.Regions: the judging rule and the targets as objects, taken by every
call that judges (``rule=``, ``regions=``) instead of the same keywords in each signature.

    rule = covopt.Rule(safety_factor=1.5, allow_crushing=False)
    regions = covopt.Regions(["chest", "head"], contact="transient", contact_area="1cm2")
    covopt.speed_limit(scene, regions=regions, rule=rule)

The names are resolved by the library (covopt::scene_file::ResolveTargets), as the CLI's
--body-region: case-insensitive, "all" (every region/area the contact permits, then the head
when transient), "head" (Park et al.'s skin model), lists, a target named twice judged once
(with a warning). The older keywords (body_region=, allow_crushing=, ...) still work; giving
one both ways is refused.
"""

import functools
import inspect

from . import _covopt

__all__ = ["Rule", "Regions"]

_CRITERIA = ("no-full-compression", "paper")


class _Frozen:
    __slots__ = ()

    def __setattr__(self, name, value):
        raise AttributeError(f"{type(self).__name__} is immutable; make a new one")

    def __eq__(self, other):
        return type(self) is type(other) and all(getattr(self, k) == getattr(other, k) for k in self.__slots__)

    def __hash__(self):
        return hash(tuple(repr(getattr(self, k)) for k in self.__slots__))

    def __repr__(self):
        fields = ", ".join(f"{k}={getattr(self, k)!r}" for k in self.__slots__)
        return f"covopt.{type(self).__name__}({fields})"

    def _set(self, **fields):
        for name, value in fields.items():
            object.__setattr__(self, name, value)


class Rule(_Frozen):
    """How a verdict is judged (optim::DesignRule), as the CLI's rule flags.

    safety_factor: None (the scene's) or in [1, 100]: each limit is divided by it (the CLI's
    --safety-factor); a scene with another safety factor is refused.
    criterion: "no-full-compression" (default: the covering must keep travel, the CLI's
    default) or "paper" (the paper's injury criteria alone: --allow-full-compression).
    allow_crushing: a crushed covering may still be safe (--allow-crushing).
    allow_unknown_strength: materials of unknown compressive strength are candidates, with a
    warning (--allow-unknown-strength; optimize and robust_optimize).
    """
    __slots__ = ("safety_factor", "criterion", "allow_crushing", "allow_unknown_strength")

    def __init__(self, *, safety_factor=None, criterion="no-full-compression", allow_crushing=False,
                 allow_unknown_strength=False):
        if criterion not in _CRITERIA:
            raise ValueError(f"criterion: expected 'no-full-compression' or 'paper' (got {criterion!r})")
        for name, value in (("allow_crushing", allow_crushing), ("allow_unknown_strength", allow_unknown_strength)):
            if not isinstance(value, bool):
                raise ValueError(f"{name}: expected True or False (got {value!r})")
        self._set(safety_factor=safety_factor, criterion=criterion, allow_crushing=allow_crushing,
                  allow_unknown_strength=allow_unknown_strength)

    def _keywords(self):
        return {"allow_full_compression": self.criterion == "paper", "allow_crushing": self.allow_crushing,
                "allow_unknown_strength": self.allow_unknown_strength}


class Regions(_Frozen):
    """What a verdict is about: ISO/TS 15066 body regions and/or the head, as the CLI's
    --body-region, --body-area, --contact, --contact-area and --limits.

    names: a region name, a comma-separated list, a list of names, "all" or "head".
    area: the area of the one region named (default: its lowest pressure limit).
    contact: "transient" (default) or "clamped".
    contact_area: the bare robot's contact area (m², or a string with its unit, "1cm2"); the
    bare robot's own verdict on an ISO region needs it.
    limits: a body-region table file of one's own (--limits; default the built-in table).
    """
    __slots__ = ("names", "area", "contact", "contact_area", "limits")

    def __init__(self, names, *, area=None, contact=None, contact_area=None, limits=None):
        if isinstance(names, (list, tuple)):
            names = tuple(names)
        elif not isinstance(names, str):
            raise ValueError(f"names: expected a region name or a list of names (got {names!r})")
        self._set(names=names, area=area, contact=contact, contact_area=contact_area, limits=limits)

    def _keywords(self):
        names = list(self.names) if isinstance(self.names, tuple) else self.names
        return {"body_region": names, "body_area": self.area, "contact": self.contact,
                "contact_area": self.contact_area, "limits": self.limits}


def _merge(call, parameters, kwargs, keywords, source):
    """kwargs with `keywords` (from a Rule or Regions) added; one given both ways is refused."""
    for name, value in keywords.items():
        if name not in parameters:
            if value:
                raise ValueError(f"{source}: {name} does not apply to {call}")
            continue
        if name in kwargs and kwargs[name] != parameters[name].default:
            raise ValueError(f"{name}: give it in {source}= or as a keyword, not both")
        if value is not None:
            kwargs[name] = value
    return kwargs


def takes_objects(function):
    """`function` also taking regions= (a Regions) and rule= (a Rule)."""
    signature = inspect.signature(function)
    parameters = signature.parameters

    @functools.wraps(function)
    def call(*args, regions=None, rule=None, **kwargs):
        if regions is not None:
            if not isinstance(regions, Regions):
                raise TypeError(f"regions: expected a covopt.Regions (got {type(regions).__name__})")
            kwargs = _merge(function.__name__, parameters, kwargs, regions._keywords(), "regions")
        if rule is not None:
            if not isinstance(rule, Rule):
                raise TypeError(f"rule: expected a covopt.Rule (got {type(rule).__name__})")
            kwargs = _merge(function.__name__, parameters, kwargs, rule._keywords(), "rule")
            if rule.safety_factor is not None:
                bound = signature.bind(*args, **kwargs)
                scene = bound.arguments.get("scene") or _covopt.Scene()
                if "safety_factor" in scene.__getstate__() and scene.safety_factor != rule.safety_factor:
                    raise ValueError(f"safety_factor: the scene has {scene.safety_factor:g} and the rule "
                                     f"{rule.safety_factor!r}; give it once")
                bound.arguments["scene"] = scene.replace(safety_factor=rule.safety_factor)
                args, kwargs = bound.args, bound.kwargs
        return function(*args, **kwargs)

    extra = [inspect.Parameter("regions", inspect.Parameter.KEYWORD_ONLY, default=None),
             inspect.Parameter("rule", inspect.Parameter.KEYWORD_ONLY, default=None)]
    params = list(parameters.values())
    tail = [p for p in params if p.kind is inspect.Parameter.VAR_KEYWORD]
    call.__signature__ = signature.replace(parameters=[p for p in params if p not in tail] + extra + tail)
    return call
