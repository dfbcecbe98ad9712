"""The provenance block of every result: covopt's version and git commit, the call that made
it, the date and the SHA-256 of every input file, made by the C++ library
(covopt/report/provenance.hpp) as for the CLI's ``--json``; ``result.provenance`` is the last
key of ``to_dict()``. The command is the Python call, ``covopt.optimize(materials=['PORON XRD
15 pcf'])``: the function's name and every argument given, by name, as its repr (a repr longer
than 200 characters, a trajectory given as arrays say, is shown as ``<dict>``).

A result that has a report also carries ``input_sources`` (before ``provenance``), as the CLI's
``--json`` does: where each input came from, "keyword robot_mass" for a keyword given (to the
call or to its covopt.Scene), "catalog" for the covering's modulus and Poisson ratio of a
``material``, else "default"; made by the library (covopt/report/input_sources.hpp)."""

import functools
import inspect
import json
import os

from . import _covopt

# The arguments that name input files, and their roles (the CLI's: --urdf, --trajectory, ...).
_FILE_ROLES = {"urdf": "urdf", "trajectory": "trajectory", "catalog": "catalog",
               "surface_file": "surface", "link_coverings": "link-coverings", "exposure": "exposure",
               "limits": "limits"}
_LONGEST_REPR = 200


def _shown(value):
    if isinstance(value, _covopt.Scene):
        return f"covopt.{value!r}"
    text = repr(value)
    if not isinstance(value, str):
        text = " ".join(text.split())  # a numpy array's repr spans lines
    return text if len(text) <= _LONGEST_REPR else f"<{type(value).__name__}>"


def _paths(value):
    """The file paths an argument names: a path, or a list of paths (catalog); none for data
    given in memory (a trajectory dict, a link-coverings dict, urdf_text)."""
    if isinstance(value, (str, os.PathLike)):
        return [os.fspath(value)]
    if isinstance(value, (list, tuple)) and all(isinstance(v, (str, os.PathLike)) for v in value):
        return [os.fspath(v) for v in value]
    return []


def provenance(name, arguments):
    """The provenance block of the call covopt.<name>(**arguments) (the arguments given)."""
    command = f"covopt.{name}({', '.join(f'{key}={_shown(value)}' for key, value in arguments.items())})"
    inputs = [(_FILE_ROLES[key], path) for key, value in arguments.items() if key in _FILE_ROLES
              for path in _paths(value)]
    return _covopt.provenance(command, inputs)


def input_sources(data, arguments):
    """The "input_sources" of a result's data made by a call with `arguments`: the keywords given
    to the call and to its covopt.Scene (its ranges' too)."""
    keywords = list(arguments)
    scene = arguments.get("scene")
    if isinstance(scene, _covopt.Scene):
        given = scene.__getstate__()
        keywords += [key for key in given if key != "ranges"] + list(given.get("ranges") or {})
    text = json.dumps({key: value for key, value in data.items() if key != "history"}, default=lambda _: None)
    return _covopt.input_sources(text, keywords)


def stamped(function):
    """The public function `function`, its result carrying the provenance of the call."""
    signature = inspect.signature(function)

    @functools.wraps(function)
    def call(*args, **kwargs):
        result = function(*args, **kwargs)
        arguments = {}
        for key, value in signature.bind(*args, **kwargs).arguments.items():
            if signature.parameters[key].kind is inspect.Parameter.VAR_KEYWORD:
                arguments.update(value)
            else:
                arguments[key] = value
        if getattr(result, "_report_kind", None) is not None:
            result._data["input_sources"] = input_sources(result._data, arguments)
        result._data["provenance"] = provenance(function.__name__, arguments)
        return result

    return call
