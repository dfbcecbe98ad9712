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


@pytest.fixture(scope="session")
def cli_json(cli):
    """cli_json(*args) -> the parsed JSON the CLI prints (asserting exit 0)."""

    def run(*args):
        code, out, err = cli(*args)
        assert code == 0, err
        return json.loads(out)

    return run
