"""A pytest plugin (loaded by conftest.py): a test that is not marked ``@pytest.mark.slow``
fails when it costs more than :data:`SLOW_SECONDS`, so that ``make test-fast``
(``pytest -m "not slow"``) stays fast as tests are added.

A test's cost is measured from the start of its setup to the end of its call (the first test
that asks for an expensive module-scoped fixture pays for building it: ``-m "not slow"``
builds it as long as one unmarked test asks for it). It is the sum of

- the CPU time of the test's process and of the child processes it waited for
  (``os.times()``: a test that runs ``kresling`` or a browser as a subprocess is charged for
  them). Each pytest-xdist worker is a process of its own, so a worker is charged only for
  its own tests;
- the time it waited without computing (a sleep, a child process it does not wait for): the
  wall time less that CPU time and less the time some task on the machine waited for a CPU
  (Linux's pressure stall information, ``/proc/pressure/cpu``), so that a test is never
  charged for a busy machine: on a loaded machine (``pytest -n`` runs a worker per core, and
  CI machines are shared) wall time grows with the load, the CPU a test needs does not.
  Where the kernel does not report CPU pressure (not Linux, or Linux before 4.20), this part
  is not counted.

``KRESLING_SLOW_LIMIT`` (seconds) overrides the limit; ``0`` turns the check off (``make fuzz``
and ``make sanitize``, which run tests at many times their usual cost). The cost of each test
is kept in its ``user_properties`` (``cpu_seconds``, ``charged_seconds``; ``--junitxml``
writes them out).
"""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest

#: A test not marked slow may cost this much [s] (setup and call).
SLOW_SECONDS = 10.0
#: The environment variable that overrides SLOW_SECONDS (0: no check).
LIMIT_VARIABLE = "KRESLING_SLOW_LIMIT"
#: Tests under these folders are run by another test in a process of their own (the fuzz
#: targets, by test_fuzz.py) and are charged there.
EXEMPT_FOLDERS = ("fuzz",)
#: Cumulative time [us] during which at least one runnable task waited for a CPU.
PRESSURE = Path("/proc/pressure/cpu")

TESTS = Path(__file__).resolve().parent
_START = pytest.StashKey[tuple]()
_LIMIT = pytest.StashKey[float]()
_PRESSURE = pytest.StashKey[Path]()


def cpu_seconds() -> float:
    """CPU time of this process and of the children it has waited for [s]."""
    times = os.times()
    return times.user + times.system + times.children_user + times.children_system


def stall_seconds(pressure: Path) -> float | None:
    """Total time some task on the machine waited for a CPU since boot [s], from the file
    ``pressure`` (/proc/pressure/cpu); None where the kernel does not say."""
    try:
        line = pressure.read_text().splitlines()[0]        # some avg10=... total=<us>
        return int(line.rsplit("total=", 1)[1]) * 1e-6
    except (OSError, IndexError, ValueError):
        return None


def charged(cpu: float, wall: float, stall: float | None) -> float:
    """A test's cost [s]: its ``cpu`` time, and of its ``wall`` time what neither that CPU
    time nor the machine's CPU pressure (``stall``, time a task waited for a CPU) explains.
    The pressure is an upper bound of the time the test and its children waited for a core
    (they wait one after the other), so what remains is time the test waited on its own.
    Without a measure of the pressure (``stall`` None), its CPU time alone."""
    if stall is None:
        return cpu
    return cpu + max(0.0, wall - cpu - max(0.0, stall))


def limit() -> float:
    text = os.environ.get(LIMIT_VARIABLE, "")
    return float(text) if text.strip() else SLOW_SECONDS


def _exempt(path: Path) -> bool:
    return any(path.is_relative_to(TESTS / folder) for folder in EXEMPT_FOLDERS)


def _now(config) -> tuple:
    return cpu_seconds(), time.perf_counter(), stall_seconds(config.stash[_PRESSURE])


def pytest_configure(config):
    # Read once per run: a test that changes them changes only the runs it starts.
    config.stash[_LIMIT] = limit()
    config.stash[_PRESSURE] = PRESSURE


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_setup(item):
    item.stash[_START] = _now(item.config)
    yield


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    report = outcome.get_result()
    if call.when != "call" or _START not in item.stash:
        return
    (cpu0, wall0, stall0), (cpu1, wall1, stall1) = item.stash[_START], _now(item.config)
    cpu, wall = cpu1 - cpu0, wall1 - wall0
    cost = charged(cpu, wall, None if stall0 is None or stall1 is None else stall1 - stall0)
    item.user_properties += [("cpu_seconds", round(cpu, 3)), ("charged_seconds", round(cost, 3))]
    seconds = item.config.stash[_LIMIT]
    if (seconds <= 0 or cost <= seconds or not report.passed
            or item.get_closest_marker("slow") is not None or _exempt(item.path)):
        return
    report.outcome = "failed"
    report.longrepr = (
        f"{item.nodeid} is not marked slow but cost {cost:.1f} s ({cpu:.1f} s of CPU time, "
        f"{wall:.1f} s of wall time; setup and call), over the {seconds:g} s a test not "
        f"marked slow may take: make it cheaper, or mark it @pytest.mark.slow (then "
        f"`make test-fast` leaves it out).")
