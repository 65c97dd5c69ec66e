"""Shared fixtures: the repository's example files, and the demoplan binary to compare
the Python command line with."""

from __future__ import annotations

import os
import pathlib

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples" / "cubes"


@pytest.fixture
def cube_domain() -> pathlib.Path:
    return EXAMPLES / "domain.pddl"


@pytest.fixture
def cube_problem() -> pathlib.Path:
    return EXAMPLES / "tower-3.pddl"


@pytest.fixture
def demoplan_binary() -> pathlib.Path:
    """The Rust binary: $DEMOPLAN_BINARY, or the workspace's debug build. A missing one
    is a failure, never a skip: .ci/run builds it before the Python tests."""
    path = pathlib.Path(os.environ.get("DEMOPLAN_BINARY", REPO / "target" / "debug" / "demoplan"))
    assert path.is_file(), f"no demoplan binary at {path}: run `cargo build -p demoplan-cli` or set DEMOPLAN_BINARY"
    return path
