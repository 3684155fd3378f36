"""Shared fixtures."""

from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parent

#: slow_check: a test not marked slow that takes over 10 s fails (tests/slow_check.py);
#: pytester: for the test of that check.
pytest_plugins = ["slow_check", "pytester"]


@pytest.fixture(scope="session")
def golden_dir() -> Path:
    """MERLIN2's element data and solver states of the n=4, Lc=30, lambda=0.7 extended model."""
    return TESTS / "data" / "golden_n4_Lc30_lam0.7_extended"
