"""Fuzz: the readers of laboratory and run files (machine records, bending trials, crease
run lists, marker CSVs) and of sweep results (tables and directories), on random bytes and
mutated valid files. A bad file is a ValueError naming the file (and line) or an OSError."""

import shutil
import tempfile
from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st

from _fuzz import finite, fuzz, mutated
from kresling import data
from kresling.fits import (fit_bending_files, fit_crease_file, read_bending_trial,
                           read_machine_record)
from kresling.manipulator import read_markers
from kresling.sweeps import SweepTable, design_grid, sweep

EXAMPLES = Path(data.path("examples/synthetic_crease/runs.csv")).parents[1]
BENDING = EXAMPLES / "synthetic_bending" / "extended_1.csv"
CREASE = EXAMPLES / "synthetic_crease"
MARKERS = Path(data.path("synthetic_manipulator_markers.csv"))
WORDS = [b"", b",", b";", b"\t", b"\"", b"\n", b"\r", b"\x00", b"\xff\xfe", b"nan", b"inf",
         b"-1e999", b"1e308", b"#", b"# state: sideways\n", b"# module_length: -3 mm\n",
         b"9" * 300, b"x" * 140_000, b"force (lbf)", b"displacement (furlong)", b"\xc3(",
         b"101,0,1,0", b"../secret.csv", b"/etc/passwd", b"2,2,2,2,2,2,2"]


mutations = st.tuples(
    st.lists(st.tuples(st.integers(0, 10**5), st.integers(1, 60)), max_size=3),
    st.lists(st.tuples(st.integers(0, 10**5), st.sampled_from(WORDS)), max_size=3))


def named_file(call, name: str):
    """``call()``, or None when it raised a ValueError naming ``name`` or an OSError."""
    try:
        return call()
    except OSError:
        return None
    except ValueError as error:
        assert name in str(error), f"the message does not name {name}: {error}"
        return None


@fuzz(100)
@given(st.one_of(st.binary(max_size=300), mutations.map(
    lambda m: mutated(BENDING.read_bytes(), *m))), st.sampled_from(["raise", "skip"]))
def test_machine_record_and_bending_trial(data, on_invalid):
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / "fuzzed.csv"
        path.write_bytes(data)
        table = named_file(lambda: read_machine_record(path, on_invalid=on_invalid), "fuzzed.csv")
        if table is not None:
            finite(table.columns["displacement"], table.columns["force"])
        read = named_file(lambda: read_bending_trial(path, on_invalid=on_invalid), "fuzzed.csv")
        if read is not None:
            trial, _ = read
            finite(trial.displacement, trial.force, trial.module_length)
        fit = named_file(lambda: fit_bending_files([path], on_invalid=on_invalid), "fuzzed.csv")
        if fit is not None:
            for fits in fit.fits.values():
                for f in fits:
                    finite(f.K)


@fuzz(60)
@given(st.sampled_from(["runs.csv", "s1_r1.csv"]), mutations)
def test_crease_run_list(which, mutation):
    with tempfile.TemporaryDirectory() as directory:
        folder = Path(directory) / "runs"
        shutil.copytree(CREASE, folder)
        target = folder / which
        target.write_bytes(mutated(target.read_bytes(), *mutation))
        result = named_file(lambda: fit_crease_file(folder / "runs.csv"), which)
        if result is not None:
            finite(result.overall.mean)


@fuzz(80)
@given(st.one_of(st.binary(max_size=300), mutations.map(
    lambda m: mutated(MARKERS.read_bytes()[:3000], *m))),
       st.one_of(st.integers(1, 4), st.sampled_from([0, None, 2.5, 10**20])))
def test_markers(data, modules):
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / "fuzzed.csv"
        path.write_bytes(data)
        markers = named_file(lambda: read_markers(path, modules), "fuzzed.csv") \
            if isinstance(modules, int) and 1 <= modules <= 4 else None
        if markers is not None:
            finite(markers.xy)
        if not (isinstance(modules, int) and 1 <= modules <= 4):
            try:
                read_markers(path, modules)
            except ValueError as error:
                assert "modules" in str(error) or "fuzzed.csv" in str(error)
            except OSError:
                pass


_SWEEP = {}


def finished_sweep() -> Path:
    """A small finished sweep directory (made once)."""
    if "path" not in _SWEEP:
        root = Path(tempfile.mkdtemp(prefix="kresling-fuzz-"))
        sweep(design_grid((4,), 2), ["psi_ratio"], out=root / "sweep", progress=False, workers=1)
        _SWEEP["path"] = root / "sweep"
    return _SWEEP["path"]


@fuzz(60)
@given(st.sampled_from(["results.csv", "manifest.json"]), mutations)
def test_damaged_sweep_directory(which, mutation):
    with tempfile.TemporaryDirectory() as directory:
        out = Path(directory) / "sweep"
        shutil.copytree(finished_sweep(), out)
        target = out / which
        target.write_bytes(mutated(target.read_bytes(), *mutation))
        table = named_file(lambda: sweep(design_grid((4,), 2), ["psi_ratio"], out=out,
                                         progress=False, workers=1), str(out))
        if table is not None:
            assert len(table) == 4
        read = named_file(lambda: SweepTable.read_csv(out / "results.csv"), "results.csv")
        if read is not None:
            assert len(read.columns) > 0
