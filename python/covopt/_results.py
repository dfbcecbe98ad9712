"""covopt's results: the JSON objects of the CLI's ``--json`` as read-only attribute objects."""

import copy
import json
import pathlib


class Result:
    """A result: every key of the CLI's ``--json`` object is an attribute (``r.peak_force_N``,
    ``r.laceration.ratio``); nested objects are Results, lists stay lists, and an object whose
    keys are not names (``worst_case.inputs``, keyed by scene field) stays a dict.
    ``to_dict()`` is the JSON structure itself (numpy arrays where a history or sweep has them).
    """

    __slots__ = ("_data", "_name", "_charts")
    _report_kind = None  # report::ToString(ReportKind) of the results that have a report

    def __init__(self, data, name=None):
        # The report's charts (the extension's _ReportCharts): kept beside the data, never in it.
        charts = data.pop("_report_charts", None) if isinstance(data, dict) else None
        object.__setattr__(self, "_charts", charts)
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

    def to_html(self, path):
        """Writes the report for the risk-assessment file to `path` (UTF-8) and returns `path`:
        one self-contained HTML document (inline CSS and SVG, no script, nothing fetched when
        viewed) with the verdicts, criteria and sources, inputs, assumptions, warnings and the
        provenance, made by the library from ``to_dict()`` (without ``history``) exactly as the
        CLI's ``--report`` makes it from its ``--json``. Results of simulate, worst_case,
        injury_probability, optimize, robust_optimize, speed_limit, check_trajectory and audit
        have one; others raise TypeError. `path` must end in .html or .htm (any case), else
        ValueError: there is no to_pdf (a PDF is printed by a browser, which the CLI's
        ``--report FILE.pdf`` runs; docs/guide/python.md shows how)."""
        try:
            suffix = pathlib.PurePath(path).suffix.lower()
        except TypeError:  # not a str or os.PathLike
            suffix = None
        if suffix not in (".html", ".htm"):
            raise ValueError(f"to_html: path must be a file name ending in .html or .htm (got {path!r}); "
                             "for a PDF, print the HTML with a browser or run the CLI with --report FILE.pdf "
                             "(docs/guide/python.md)")
        if self._report_kind is None:
            raise TypeError(f"{self._name} has no report (simulate, optimize, speed_limit, check_trajectory "
                            "and audit results have one)")
        from . import _covopt  # the extension, imported by the package before this runs
        data = {key: value for key, value in self._data.items() if key != "history"}
        html = _covopt.html_report(self._report_kind, json.dumps(data, allow_nan=False), self._charts)
        pathlib.Path(path).write_text(html, encoding="utf-8")
        return path

    def __repr__(self):
        summary = self._data.get("summary") if isinstance(self._data, dict) else None
        if isinstance(summary, dict):
            # The library's one line (report::SummaryHeadline), then the rest of the fields briefly.
            from . import _covopt  # the extension, imported by the package before this runs
            head = _covopt.summary_headline(json.dumps({"summary": summary}, allow_nan=False))
            return f"{self._name}({head})"
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
    _report_kind = "simulate"


class Sweep(Result):
    """covopt.sweep's result: numpy arrays ``a[i, j]`` at ``x[i]``, ``y[j]``."""


class Design(Result):
    """covopt.optimize's result: ``covopt optimize --json``."""
    _report_kind = "optimize"


class SpeedLimit(Result):
    """covopt.max_safe_speed / max_safe_mass: one row of ``covopt speed-limit --json``."""


class SpeedLimitTable(Result):
    """covopt.speed_limit's result: ``covopt speed-limit --json``."""
    _report_kind = "speed-limit"


class Material(Result):
    """A catalog material: ``covopt materials show NAME --json``. Its compressive curve
    (None without one): ``compressive_curve``, a list of (strain, stress_Pa) tuples through an
    implied origin; ``stress_at_25_Pa``; ``curve_source``; ``curve_rate`` ("quasi-static",
    "unknown" or a rate such as "20 1/s"); ``recovers``; ``rate_factor`` and
    ``stress_at_25_band_Pa`` as (low, high) tuples; ``curve_shape`` (the assumed shape of a band)."""

    @property
    def compressive_curve(self):
        points = self._data.get("compressive_curve")
        return None if points is None else [tuple(point) for point in points]

    @property
    def rate_factor(self):
        bounds = self._data.get("rate_factor")
        return None if bounds is None else tuple(bounds)

    @property
    def stress_at_25_band_Pa(self):
        bounds = self._data.get("stress_at_25_band_Pa")
        return None if bounds is None else tuple(bounds)


class ReflectedMass(Result):
    """covopt.reflected_mass's result: ``covopt robot --json``."""


class ContactMotion(Result):
    """covopt.contact_motion's result: the contact point's motion."""


class TrajectoryCheck(Result):
    """covopt.check_trajectory's result: ``covopt robot --trajectory --json``."""
    _report_kind = "robot --trajectory"


class RobustSimulation(Result):
    """covopt.worst_case / injury_probability: ``covopt simulate --json`` with ranges."""
    _report_kind = "simulate"


class Sensitivities(Result):
    """covopt.sensitivities' result: the ``sensitivities`` object of ``covopt simulate --json``."""


class RobustDesign(Result):
    """covopt.robust_optimize's result: ``covopt optimize --json`` with ranges."""
    _report_kind = "optimize"


class BodyRegion(Result):
    """An ISO/TS 15066 body region: ``covopt body-regions show NAME --json``."""


class BodyLimits(Result):
    """covopt.body_region_limits' result: the limits of one body area under one contact."""
