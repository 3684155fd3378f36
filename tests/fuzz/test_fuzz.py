"""The fuzz suite: every public entry point and command-line subcommand under hypothesis
(tests/fuzz/fuzz_*.py; what each checks is in tests/fuzz/_fuzz.py).

Each file runs in its own Python process, so that a crash in the C++ core (a segfault, an
abort) fails that file with its traceback (faulthandler) instead of taking the test session
down, with a memory limit (a runaway allocation is a failure, not a swapping machine) and a
watchdog (a hang is a failure, with the stack of every thread where it hung).

In the normal suite each target runs its own small number of examples, derandomized: the same
examples on every run, a few seconds per file. ``make fuzz`` sets ``KRESLING_FUZZ_SCALE``
(each target runs that many times as many examples, from random seeds) and runs the same
files.
"""

import os
import subprocess
import sys
from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parents[1]
ROOT = TESTS.parent
TARGETS = sorted((TESTS / "fuzz").glob("fuzz_*.py"))
SCALE = float(os.environ.get("KRESLING_FUZZ_SCALE", "1"))
#: Targets that take over 10 s of CPU time at scale 1 (tests/slow_check.py).
SLOW_TARGETS = {"fuzz_cli"}
#: A file that runs longer than this has hung (its slowest file takes ~10 s at scale 1).
WATCHDOG = 120 + 60 * SCALE
#: Address space of a fuzz process [bytes]: far above what any target needs (~1 GB).
MEMORY = 8 * 2**30


def _limit_memory():  # runs in the child before exec
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (MEMORY, MEMORY))


def test_every_target_file_is_found():
    names = {path.stem for path in TARGETS}
    assert {"fuzz_geometry", "fuzz_model", "fuzz_solvers", "fuzz_analyses", "fuzz_io",
            "fuzz_simulate", "fuzz_files", "fuzz_manipulator", "fuzz_fabrication",
            "fuzz_sweeps", "fuzz_cli", "fuzz_arm_view"} <= names


@pytest.mark.parametrize("path", [
    pytest.param(path, marks=pytest.mark.slow) if path.stem in SLOW_TARGETS else path
    for path in TARGETS], ids=lambda path: path.stem)
def test_fuzz(path):
    # --show-capture=no: a failure's report is its traceback and falsifying example, not the
    # thousands of log lines a long run captures (they would crowd it out of the tail kept).
    command = [sys.executable, "-X", "faulthandler", "-m", "pytest", "-q", "-p",
               "no:cacheprovider", "--no-header", "--show-capture=no", "-o",
               f"faulthandler_timeout={WATCHDOG - 15}", str(path)]
    try:
        done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True,
                              timeout=WATCHDOG, preexec_fn=_limit_memory,
                              env=dict(os.environ, PYTHONFAULTHANDLER="1"))
    except subprocess.TimeoutExpired as hung:
        output = (hung.stdout or b"").decode(errors="replace")[-6000:] if isinstance(
            hung.stdout, bytes) else (hung.stdout or "")[-6000:]
        pytest.fail(f"{path.name} hung (over {WATCHDOG:.0f} s):\n{output}")
    report = (done.stdout + done.stderr)[-12000:]
    assert done.returncode == 0, (f"{path.name} failed (exit {done.returncode}; a negative "
                                  f"exit is the signal that killed it):\n{report}")
