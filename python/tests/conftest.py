"""Shared fixtures of the covopt Python tests: the covopt binary, to compare with the CLI."""

import json
import os
import pathlib
import shutil
import subprocess

import pytest

import covopt


def covopt_binary():
    """The covopt binary: $COVOPT_CLI (CTest sets it), else the build tree's beside the module
    (build/python/covopt -> build/cli/covopt), else covopt on PATH; None if none is found."""
    if os.environ.get("COVOPT_CLI"):
        return os.environ["COVOPT_CLI"]
    beside = pathlib.Path(covopt.__file__).resolve().parents[2] / "cli" / "covopt"
    if beside.is_file() and os.access(beside, os.X_OK):
        return str(beside)
    return shutil.which("covopt")


@pytest.fixture(scope="session")
def cli():
    """run(*args) -> (exit code, stdout, stderr) of the covopt binary; fails without one."""
    path = covopt_binary()
    if not path:
        pytest.fail("no covopt binary to compare with: set COVOPT_CLI, build the covopt target "
                    "(build/cli/covopt beside build/python) or put covopt on PATH")

    def run(*args):
        done = subprocess.run([path, *args], capture_output=True, text=True, check=False)
        return done.returncode, done.stdout, done.stderr

    return run


def without_provenance(result):
    """A result's dict (or a Result) without its "provenance" block and its "input_sources"
    (the CLI's say "flag --speed" where Python's say "keyword speed")."""
    data = result.to_dict() if hasattr(result, "to_dict") else result
    return {key: value for key, value in data.items() if key not in ("provenance", "input_sources")}


def same_provenance(a, b):
    """Whether two provenance blocks name the same software, version, commit and input files
    (role, SHA-256, size): what two runs of the same input share. The command (the CLI's
    command line or the Python call) and the date are the run's own."""
    def key(p):
        return (p["software"], p["version"], p["commit"],
                [(f["role"], f["sha256"], f["size_bytes"]) for f in p["inputs"]])
    return key(a) == key(b)


def same_result(a, b):
    """Two results' dicts are the same: every key but "provenance" equal, and both with a
    provenance block naming the same version, commit and inputs (same_provenance)."""
    if "provenance" not in a or "provenance" not in b:
        return False
    return without_provenance(a) == without_provenance(b) and same_provenance(a["provenance"], b["provenance"])


class CliJson(dict):
    """The JSON object the CLI printed. ``==`` with a Python result (or its dict) is
    same_result: everything but the provenance block strictly, and of the provenance blocks the
    version, commit and input files (the command and date differ by nature). As a dict
    subclass its ``__eq__`` is tried first, also in ``result == cli_json(...)``."""

    def __eq__(self, other):
        if hasattr(other, "to_dict"):
            other = other.to_dict()
        if not isinstance(other, dict):
            return NotImplemented
        return same_result(self, other)

    def __ne__(self, other):
        equal = self.__eq__(other)
        return equal if equal is NotImplemented else not equal

    __hash__ = None


@pytest.fixture(scope="session")
def build_provenance(cli):
    """The version (`covopt --version`) and commit of the build under test."""
    code, out, err = cli("--version")
    assert code == 0, err
    return {"version": out.split()[-1], "commit": covopt._covopt.provenance("", [])["commit"]}


@pytest.fixture(scope="session")
def cli_json(cli, build_provenance):
    """cli_json(*args) -> the parsed JSON the CLI prints (asserting exit 0). An object must end
    with the provenance block of this build (its version and commit) and comes back as a
    CliJson; an array (materials list) stays a list."""

    def run(*args):
        code, out, err = cli(*args)
        assert code == 0, err
        data = json.loads(out)
        if not isinstance(data, dict):
            return data
        assert list(data)[-1] == "provenance", list(data)
        block = data["provenance"]
        assert list(block) == ["software", "version", "commit", "command", "date_utc", "inputs"]
        assert (block["software"], block["version"], block["commit"]) == (
            "covopt", build_provenance["version"], build_provenance["commit"])
        return CliJson(data)

    return run
