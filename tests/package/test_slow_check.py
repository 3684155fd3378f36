"""The check that fails a test not marked slow when it costs too much (tests/slow_check.py),
on small test files run by pytester with a limit of a fraction of a second, in one process
and on two pytest-xdist workers."""

from pathlib import Path

import pytest

import slow_check

# CPU work (BURN) that takes well over LIMIT on any machine, and a test that takes well
# under it.
LIMIT = 0.2
BURN = 0.4
TESTS = """
    import subprocess, sys, time
    import pytest

    def burn(seconds):
        end = time.process_time() + seconds
        while time.process_time() < end:
            pass

    def test_quick():
        pass

    def test_busy():
        burn({burn})

    @pytest.mark.slow
    def test_busy_marked():
        burn({burn})

    def test_busy_in_a_child():
        subprocess.run([sys.executable, "-c",
                        "import time\\nend = time.process_time() + {burn}\\n"
                        "while time.process_time() < end: pass"], check=True)

    def test_waiting():
        time.sleep(4 * {limit})

    def test_busy_and_failing():
        burn({burn})
        assert 1 == 2, "its own failure"

    @pytest.fixture(scope="module")
    def expensive():
        burn({burn})

    def test_first_to_ask_for_the_fixture(expensive):
        pass

    def test_second_to_ask_for_the_fixture(expensive):
        pass
"""
EXPECTED = {
    "test_quick": "passed",
    "test_busy": "failed",                     # its CPU time
    "test_busy_marked": "passed",              # marked slow
    "test_busy_in_a_child": "failed",          # a child process's CPU time counts
    "test_waiting": "failed",                  # time it waited without computing
    "test_busy_and_failing": "failed",         # with its own failure, below
    "test_first_to_ask_for_the_fixture": "failed",  # pays for the fixture's setup
    "test_second_to_ask_for_the_fixture": "passed",
}


def _run(pytester, monkeypatch, limit, *args, files=("test_cases",),
         plugin=("-p", "slow_check")):
    monkeypatch.setenv(slow_check.LIMIT_VARIABLE, str(limit))
    pytester.makeini("[pytest]\nmarkers = slow: over the limit\n")
    pytester.makepyfile(**{name: TESTS.format(limit=LIMIT, burn=BURN) for name in files})
    return pytester.runpytest(*plugin, "-p", "no:cacheprovider", *args)


def _outcomes(result, file="test_cases"):
    return {report.nodeid.split("::")[1]: report.outcome
            for report in result.reprec.getreports("pytest_runtest_logreport")
            if report.when == "call" and report.nodeid.startswith(f"{file}.py::")}


def test_the_limit_is_ten_seconds(monkeypatch):
    assert slow_check.SLOW_SECONDS == 10.0
    monkeypatch.delenv(slow_check.LIMIT_VARIABLE, raising=False)
    assert slow_check.limit() == 10.0


def test_a_test_is_charged_its_cpu_time_and_its_waiting_never_the_machines_load():
    charged = slow_check.charged
    assert charged(cpu=8.0, wall=8.1, stall=0.0) == pytest.approx(8.1)  # alone on a core
    assert charged(cpu=8.0, wall=30.0, stall=25.0) == 8.0     # a busy machine: its CPU time
    assert charged(cpu=0.1, wall=12.0, stall=0.0) == pytest.approx(12.0)  # a sleep
    assert charged(cpu=0.1, wall=12.0, stall=5.0) == pytest.approx(7.0)   # part of it loaded
    assert charged(cpu=16.0, wall=8.0, stall=0.0) == 16.0     # two threads: CPU time
    assert charged(cpu=0.1, wall=12.0, stall=None) == 0.1     # no measure of the pressure


def test_the_cpu_pressure_is_read_or_taken_as_none(tmp_path, monkeypatch):
    pressure = tmp_path / "cpu"
    pressure.write_text("some avg10=1.00 avg60=0.50 avg300=0.10 total=2500000\n"
                        "full avg10=0.00 avg60=0.00 avg300=0.00 total=0\n")
    assert slow_check.stall_seconds(pressure) == 2.5
    assert slow_check.stall_seconds(tmp_path / "missing") is None


def test_an_unmarked_test_over_the_limit_fails_saying_why(pytester, monkeypatch):
    # No CPU pressure in the run it starts, so that test_waiting's sleep is charged whatever
    # the machine's load (this run's own check keeps the file it read).
    quiet = pytester.path / "pressure"
    quiet.write_text("some avg10=0.00 avg60=0.00 avg300=0.00 total=0\n")
    monkeypatch.setattr(slow_check, "PRESSURE", quiet)
    result = _run(pytester, monkeypatch, LIMIT)
    assert _outcomes(result) == EXPECTED
    result.stdout.fnmatch_lines([
        f"*test_busy is not marked slow but cost * s (* s of CPU time, * s of wall time; "
        f"setup and call), over the {LIMIT:g} s*mark it @pytest.mark.slow*"])
    assert "its own failure" in result.stdout.str()


def test_each_xdist_worker_charges_its_own_tests(pytester, monkeypatch):
    # The workers cannot import this folder's module (xdist gives them the sys.path this
    # run started with): the plugin is the run's conftest.py instead. test_waiting's charge
    # depends on the machine's load there (the CPU pressure read is the real one): left out,
    # and so are the tests whose outcome does not depend on the check.
    pytester.makeconftest(Path(slow_check.__file__).read_text())
    files = ("test_cases_a", "test_cases_b")   # one on each worker
    result = _run(pytester, monkeypatch, LIMIT, "-n", "2", "--dist", "loadfile",
                  "-k", "not waiting and not marked and not failing", files=files, plugin=())
    expected = {name: outcome for name, outcome in EXPECTED.items()
                if name not in ("test_waiting", "test_busy_marked", "test_busy_and_failing")}
    for file in files:
        assert _outcomes(result, file) == expected


def test_a_limit_of_zero_turns_the_check_off(pytester, monkeypatch):
    result = _run(pytester, monkeypatch, 0)
    result.assert_outcomes(passed=7, failed=1)   # test_busy_and_failing, on its own
