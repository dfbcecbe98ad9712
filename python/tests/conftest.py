"""Shared fixtures of the covopt Python tests: the built CLI (COVOPT_CLI, set by CTest)."""

import json
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    """run(*args) -> (exit code, stdout, stderr) of the built covopt binary."""
    path = os.environ.get("COVOPT_CLI")
    if not path:
        pytest.skip("COVOPT_CLI (the built covopt binary) is not set; CTest sets it")

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
