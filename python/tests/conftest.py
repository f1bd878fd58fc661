"""Shared fixtures: the repository paths and the `carry` CLI binary the agreement tests
compare against (``CARRY_CLI``, else ``target/release/carry`` of the repository)."""

import os
import pathlib
import shutil

import pytest

PYTHON_DIR = pathlib.Path(__file__).resolve().parents[1]
REPO = PYTHON_DIR.parent
SHARED = pathlib.Path(os.environ.get("CARRY_SHARED", REPO.parent / "shared"))


@pytest.fixture(scope="session")
def cli() -> str:
    """Path of the `carry` binary (build it with `cargo build --release -p carry-cli`)."""
    given = os.environ.get("CARRY_CLI")
    candidates = [given] if given else [str(REPO / "target" / "release" / "carry"), shutil.which("carry")]
    for c in candidates:
        if c and os.access(c, os.X_OK):
            return c
    pytest.skip(
        "the carry CLI binary was not found: set CARRY_CLI to its path or run "
        "`cargo build --release -p carry-cli` at the repository root"
    )


@pytest.fixture(scope="session")
def golden_dir() -> pathlib.Path:
    return REPO / "tests" / "golden"


@pytest.fixture(scope="session")
def shared_data() -> pathlib.Path:
    d = SHARED / "data"
    if not d.is_dir():
        pytest.skip(f"measured data not found at {d} (set CARRY_SHARED to ../shared)")
    return d
