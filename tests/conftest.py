"""Shared fixtures, and the order in which pytest-xdist hands out the test files."""

from collections import Counter
from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parent

#: slow_check: a test not marked slow that takes over 10 s fails (tests/slow_check.py);
#: pytester: for the test of that check.
pytest_plugins = ["slow_check", "pytester"]


def pytest_itemcollected(item):
    """The tests that drive a headless browser (files ``*_browser.py``) and the fuzz suite's
    (``tests/fuzz``) are marked ``browser`` and ``fuzz``: part of ``make test``, left out of
    ``make test-fast``."""
    if item.path.name.endswith("_browser.py"):
        item.add_marker(pytest.mark.browser)
    if item.path.parent.name == "fuzz":
        item.add_marker(pytest.mark.fuzz)


def pytest_collection_modifyitems(config, items):
    """On pytest-xdist's workers (``make test``: ``-n N --dist loadfile
    --no-loadscope-reorder``), the files with the most tests marked slow first, then those
    with the most tests, each file's tests in their own order: the workers take the long
    files while the others are still queued, and finish on short ones together (a long
    file handed out last would run on one worker while the others wait)."""
    if not hasattr(config, "workerinput"):
        return
    slow = Counter(item.path for item in items if item.get_closest_marker("slow"))
    count = Counter(item.path for item in items)
    items.sort(key=lambda item: (-slow[item.path], -count[item.path]))  # stable


@pytest.fixture(scope="session")
def golden_dir() -> Path:
    """MERLIN2's element data and solver states of the n=4, Lc=30, lambda=0.7 extended model."""
    return TESTS / "data" / "golden_n4_Lc30_lam0.7_extended"
