"""Shared fixtures of the voronav Python tests (run by CTest as python.pytest, docs/python.md).

An empty collection must fail: pytest would exit with code 5 ("no tests collected"), which CTest
treats as a failure anyway, but the message here says why.
"""

from __future__ import annotations

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(os.environ.get("VORONAV_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
DATA = ROOT / "data"


def pytest_collection_modifyitems(session, config, items):
    if not items:
        raise pytest.UsageError("voronav Python tests: no test was collected (python/tests/test_*.py)")


@pytest.fixture(scope="session")
def data() -> pathlib.Path:
    return DATA


def run_cli(*args: str) -> dict:
    """Runs the voronav CLI with --json and returns its output (skips when the CLI is not built)."""
    cli = os.environ.get("VORONAV_CLI")
    if not cli or not pathlib.Path(cli).exists():
        pytest.skip("VORONAV_CLI is not set (the tests compare with the CLI when CTest runs them)")
    out = subprocess.run([cli, *args, "--json"], capture_output=True, text=True, check=False)
    if out.returncode not in (0, 1):
        raise AssertionError(f"voronav {' '.join(args)} failed ({out.returncode}): {out.stderr}")
    return json.loads(out.stdout)


@pytest.fixture(scope="session")
def cli():
    return run_cli
