"""Shared fixtures: the repository, the isolab executable the module is compared with."""

import json
import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture
def repo():
    return REPO


@pytest.fixture
def isolab_cli():
    """Runs the isolab executable (ctest names it in ISOLAB_BINARY) and returns its result."""
    binary = os.environ.get("ISOLAB_BINARY", str(REPO / "build" / "isolab"))
    assert os.path.exists(binary), f"no isolab executable at {binary} (set ISOLAB_BINARY)"

    def run(*args, expect=0):
        done = subprocess.run([binary, *map(str, args)], capture_output=True, text=True,
                              cwd=REPO)
        assert done.returncode == expect, done.stdout + done.stderr
        return done

    def run_json(*args):
        return json.loads(run(*args, "--json").stdout)

    run.json = run_json
    return run
