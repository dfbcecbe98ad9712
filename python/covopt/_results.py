"""covopt's results: the JSON objects of the CLI's ``--json`` as read-only attribute objects."""

import copy


class Result:
    """A result: every key of the CLI's ``--json`` object is an attribute (``r.peak_force_N``,
    ``r.laceration.ratio``); nested objects are Results, lists stay lists, and an object whose
    keys are not names (``worst_case.inputs``, keyed by scene field) stays a dict.
    ``to_dict()`` is the JSON structure itself (numpy arrays where a history or sweep has them).
    """

    __slots__ = ("_data", "_name")

    def __init__(self, data, name=None):
        object.__setattr__(self, "_data", data)
        object.__setattr__(self, "_name", name or type(self).__name__)

    def __getattr__(self, key):
        try:
            return _wrap(self._data[key], key)
        except KeyError:
            raise AttributeError(f"{self._name} has no attribute {key!r}; it has: "
                                 f"{', '.join(self._data)}") from None

    def __setattr__(self, key, value):
        raise AttributeError(f"{self._name} is read-only")

    def __dir__(self):
        return list(self._data)

    def __eq__(self, other):
        """Equal to a Result with the same data, or to its JSON object (a dict)."""
        return self._data == (other._data if isinstance(other, Result) else other)

    __hash__ = None

    def to_dict(self):
        """The result as the CLI's ``--json`` object (a deep copy: dicts, lists, numbers)."""
        return copy.deepcopy(self._data)

    def __repr__(self):
        def brief(value):
            if isinstance(value, dict):
                return "{...}" if value else "{}"
            if isinstance(value, list):
                return f"[{len(value)} items]" if value else "[]"
            if hasattr(value, "shape"):
                return f"array(shape={value.shape})"
            return repr(value)
        fields = ", ".join(f"{key}={brief(value)}" for key, value in self._data.items())
        return f"{self._name}({fields})"


def _wrap(value, key=None):
    if isinstance(value, dict) and all(isinstance(k, str) and k.isidentifier() for k in value):
        return Result(value, "".join(part.capitalize() for part in str(key).split("_")) if key else None)
    if isinstance(value, dict):
        return {k: _wrap(v, k) for k, v in value.items()}
    if isinstance(value, list):
        return [_wrap(v, key[:-1] if key and key.endswith("s") else key) for v in value]  # rows: Row
    return value


class Simulation(Result):
    """covopt.simulate's result: ``covopt simulate --json`` (and ``history``)."""


class Sweep(Result):
    """covopt.sweep's result: numpy arrays ``a[i, j]`` at ``x[i]``, ``y[j]``."""


class Design(Result):
    """covopt.optimize's result: ``covopt optimize --json``."""


class SpeedLimit(Result):
    """covopt.max_safe_speed / max_safe_mass: one row of ``covopt speed-limit --json``."""


class SpeedLimitTable(Result):
    """covopt.speed_limit's result: ``covopt speed-limit --json``."""


class Material(Result):
    """A catalog material: ``covopt materials show NAME --json``."""


class ReflectedMass(Result):
    """covopt.reflected_mass's result: ``covopt robot --json``."""


class ContactMotion(Result):
    """covopt.contact_motion's result: the contact point's motion."""


class TrajectoryCheck(Result):
    """covopt.check_trajectory's result: ``covopt robot --trajectory --json``."""


class RobustSimulation(Result):
    """covopt.worst_case / injury_probability: ``covopt simulate --json`` with ranges."""


class Sensitivities(Result):
    """covopt.sensitivities' result: the ``sensitivities`` object of ``covopt simulate --json``."""


class RobustDesign(Result):
    """covopt.robust_optimize's result: ``covopt optimize --json`` with ranges."""


class BodyRegion(Result):
    """An ISO/TS 15066 body region: ``covopt body-regions show NAME --json``."""


class BodyLimits(Result):
    """covopt.body_region_limits' result: the limits of one body area under one contact."""
