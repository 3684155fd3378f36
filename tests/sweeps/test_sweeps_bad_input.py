"""Bad input to the sweeps: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""

import sys
import time

import pytest



def _process_running(pid: int) -> bool:
    """Whether the OS still runs ``pid`` (a zombie, dead but not yet reaped, counts as ended).

    Asked of the OS rather than of ``Process.is_alive()``: the pool's own manager thread reaps
    its workers too, and a ``join`` that loses that race returns at once with the process's
    exit code still unset, so ``is_alive()`` would say True for a process that has ended."""
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().rsplit(")", 1)[1].split()[0] != "Z"
    except (FileNotFoundError, ProcessLookupError):  # reaped, or reaped while being read
        return False


# 8. A damaged sweep directory: errors that named neither file nor line.
@pytest.mark.parametrize("damage, message", [
    (lambda lines: lines[:2] + [b"\xff\xfe\x00binary"] + lines[3:], r"line 3: not UTF-8"),
    (lambda lines: lines[:2] + [b",".join([b"garbage"] * lines[1].count(b",")) + b",x"]
     + lines[3:], r"line 3: column 'n' = 'garbage' is not a int"),
])
def test_damaged_results_name_file_and_line(tmp_path, damage, message):
    from kresling.sweeps import design_grid, sweep
    out = tmp_path / "sweep"
    sweep(design_grid((4,), 2), ["psi_ratio"], out=out, progress=False, workers=1)
    results = out / "results.csv"
    lines = results.read_bytes().split(b"\n")
    results.write_bytes(b"\n".join(damage(lines)))
    (out / "manifest.json").write_text(
        (out / "manifest.json").read_text().replace('"complete": true', '"complete": false'))
    with pytest.raises(ValueError, match=r"results.csv, " + message):
        sweep(design_grid((4,), 2), ["psi_ratio"], out=out, progress=False, workers=1)


def test_damaged_table_names_file_and_line(tmp_path):
    from kresling.sweeps import SweepTable
    path = tmp_path / "table.csv"
    path.write_text("n,Lc,lam,R\n4,15.0,0.7,30.0\n4,oops,0.7,30.0\n")
    with pytest.raises(ValueError, match=r"table.csv, line 3: column 'Lc' = 'oops' is not a "
                                         r"float"):
        SweepTable.read_csv(path)
    path.write_text("")
    with pytest.raises(ValueError, match=r"table.csv is empty"):
        SweepTable.read_csv(path)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")
def test_a_killed_process_sweep_leaves_no_workers(tmp_path):
    from kresling.sweeps.executors import make_executor
    handle = make_executor("processes", 2)
    futures = [handle.executor.submit(time.sleep, 30) for _ in range(2)]
    deadline = time.perf_counter() + 60  # spawned workers take a moment to start
    while not all(f.running() for f in futures) and time.perf_counter() < deadline:
        time.sleep(0.05)
    time.sleep(0.5)
    pids = [p.pid for p in handle.executor._processes.values()]
    assert pids and all(_process_running(pid) for pid in pids)
    start = time.perf_counter()
    handle.shutdown(interrupted=True)
    # The workers sleep for 30 s: ended within 5 s means they were stopped, not waited for.
    while any(_process_running(pid) for pid in pids) and time.perf_counter() - start < 5:
        time.sleep(0.05)
    assert not any(_process_running(pid) for pid in pids)
    del futures


def test_sweep_sizes_are_checked():
    from kresling.sweeps import design_grid, sweep
    with pytest.raises(ValueError, match=r"^size = 100000 is invalid"):
        design_grid((4,), 100_000)
    with pytest.raises(ValueError, match=r"^size = \(5000, 5000\) is invalid with 4 n: the grid "
                                         r"would hold 100000000 designs"):
        design_grid((4, 6, 8, 10), (5000, 5000))
    with pytest.raises(ValueError, match=r"^chunk_size = -2 is invalid"):
        sweep(design_grid((4,), 2), ["psi_ratio"], chunk_size=-2, progress=False)
    with pytest.raises(ValueError, match=r"^workers = 100000 is invalid for threads"):
        sweep(design_grid((4,), 2), ["psi_ratio"], workers=100_000, progress=False)


def test_an_index_beyond_64_bits_names_the_file_and_line(tmp_path):
    # (found by the fuzz target at scale 50: an OverflowError from numpy)
    from kresling.sweeps.table import SweepTable

    path = tmp_path / "results.csv"
    path.write_text("index,Lc\n" + "9" * 40 + ",15.0\n")
    with pytest.raises(ValueError, match=r"results.csv, line 2: column 'index'"):
        SweepTable.read_csv(path)
