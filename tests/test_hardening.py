"""Reproducers of the defects a fuzzing audit found (each must stay fixed): bad input is a
ValueError naming the parameter, the value and what is allowed (the command line: one line
on stderr, exit 2), never another exception, a hang or a silent NaN. The C++ side of several
is in cpp/tests/test_hardening.cpp."""

import _thread
import json
import math
import signal
import sys
import threading
import time

import numpy as np
import pytest

from kresling import Design, _core
from kresling.cli import main
from kresling.model import Model
from kresling.model.kresling_specimen import kresling_specimen
from kresling.solvers import (condensed_stiffness, solve_displacement_control,
                              solve_force_control, solve_mgdcm)


def run_cli(capsys, *argv):
    """``kresling ARGV`` in this process: (exit status, stdout, stderr)."""
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def assert_one_line_error(status, err, command, *fragments):
    assert status == 2, err
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"kresling {command}: error: "), err
    for fragment in fragments:
        assert fragment in lines[0], lines[0]


def driven_cell(n=4, lam=0.7, Lc=30.0):
    """One cell, bottom polygon fixed, top polygon driven down 5 mm; (model, prescribed)."""
    specimen = kresling_specimen(Design(n, lam, Lc), [1])
    fixed = np.zeros((specimen.model.num_nodes, 3), dtype=bool)
    fixed[specimen.level_nodes(0)] = True
    model = specimen.model.replace(fixed=fixed)
    prescribed = np.zeros((model.num_nodes, 3))
    prescribed[specimen.level_nodes(1), 2] = -5.0
    return model, prescribed


# 1. A subnormal bad value: std::stod threw out_of_range (an IndexError) in the message.
def test_subnormal_bad_value_is_a_value_error():
    with pytest.raises(ValueError, match=r"^Lc = -1e-310 is invalid: must be >= 0$"):
        Design(10, 0.8, -1e-310)


def test_subnormal_bad_value_on_the_command_line(capsys):
    status, _, err = run_cli(capsys, "design", "--n", "10", "--lam", "0.8", "--Lc=-1e-310")
    assert_one_line_error(status, err, "design", "Lc = -1e-310 is invalid")


# 2. max_bisections >= 31 was undefined behaviour (1 << 31 and beyond).
@pytest.mark.parametrize("bisections", [31, 32, 47, -1])
def test_bisections_beyond_30_are_refused(bisections):
    model, prescribed = driven_cell()
    with pytest.raises(ValueError, match=rf"max_bisections = {bisections} is invalid: must be an "
                                         r"integer"):
        solve_displacement_control(model, prescribed, 2, max_bisections=bisections)


def test_thirty_bisections_run():
    model, prescribed = driven_cell()
    assert solve_displacement_control(model, prescribed, 2, max_bisections=30).completed


# 3. shift unchecked: 1e9, inf or -1e9 "converged" in one iteration with a wrong answer.
@pytest.mark.parametrize("shift", [1e9, math.inf, -1e9, math.nan, None, "1e-8"])
@pytest.mark.parametrize("solver", ["displacement", "force", "mgdcm"])
def test_shift_out_of_range_is_refused(shift, solver):
    model, prescribed = driven_cell()
    with pytest.raises(ValueError, match=r"^shift = .* is invalid: must be"):
        if solver == "displacement":
            solve_displacement_control(model, prescribed, 2, shift=shift)
        elif solver == "force":
            solve_force_control(model, -0.01 * np.sign(prescribed), 2, shift=shift)
        else:
            solve_mgdcm(model, -0.01 * np.sign(prescribed), max_increments=2, shift=shift)


def test_largest_shift_gives_the_same_path():
    model, prescribed = driven_cell()
    reference = solve_displacement_control(model, prescribed, 4)
    shifted = solve_displacement_control(model, prescribed, 4, shift=_core.solvers.MAX_SHIFT)
    assert shifted.completed
    np.testing.assert_allclose(shifted.constraint_force, reference.constraint_force,
                               rtol=1e-6, atol=1e-8)


# 4. Lc = 0: snap forces of 4.9e13 N (a parabola through a -3.9e14 N sample at the flat
# state) and bending errors that did not say why.
def test_snap_through_at_lc_zero_names_lc(capsys):
    from kresling.analyses import snap_through
    with pytest.raises(ValueError, match=r"^Lc = 0 is invalid: must be > 0 for the snap-through"):
        snap_through(Design(4, 0.6, 0.0))
    status, out, err = run_cli(capsys, "snap", "--n", "4", "--lam", "0.6", "--Lc", "0")
    assert_one_line_error(status, err, "snap", "Lc = 0 is invalid")
    assert out == ""


@pytest.mark.parametrize("extra", [[], ["--deflection-rad", "0.001"]])
def test_bend_at_lc_zero_names_lc(capsys, extra):
    status, _, err = run_cli(capsys, "bend", "--n", "10", "--lam", "0.8", "--Lc", "0", *extra)
    assert_one_line_error(status, err, "bend", "Lc = 0 is invalid: must be > 0 for the bending "
                                               "test in the contracted state")


def test_linear_bending_at_lc_zero_names_lc():
    from kresling.analyses import linear_bending_stiffness
    with pytest.raises(ValueError, match=r"^Lc = 0 is invalid"):
        linear_bending_stiffness(Design(8, 0.8, 0.0), "contracted")
    assert math.isfinite(linear_bending_stiffness(Design(8, 0.8, 0.0), "extended"))


def test_nearly_flat_cells_are_refused_by_the_tests():
    # Psi below 1e-6 rad is not resolved by the model's hinge angles (MERLIN2's arccosine):
    # its forces there were noise of any size (a 2.5e12 N "snap force" at Lc = 2e-311).
    from kresling.analyses import bending_test, snap_through
    for design, name in ((Design(4, 0.6, 1e-300), "Lc"), (Design(4, 0.6, 1e-6), "Lc"),
                         (Design(3, 0.5 + 2**-52, 2.2e-311, 67.0), "Lc")):
        with pytest.raises(ValueError, match=rf"^{name} = .* is invalid: must be > 0 for the "
                                             r"snap-through test, and large enough that the "
                                             r"contracted cell is not flat"):
            snap_through(design)
    with pytest.raises(ValueError, match=r"^lam = 0.5000000000000002\d* is invalid: must be further "
                                         r"from 0.5 for the bending test in the extended state"):
        bending_test(Design(4, 0.5 + 2**-52, 0.0), "extended")
    assert math.isfinite(snap_through(Design(4, 0.6, 1e-3)).force[-1])


def test_a_path_driven_flat_stops_before_the_flat_state():
    # The enhanced linear law is infinite at a hinge folded flat: the path keeps only finite
    # steps and says why it stopped (it ended "completed" on a -3.9e14 N force).
    design = Design(4, 0.6, 0.0)
    specimen = kresling_specimen(design, [1])
    fixed = np.zeros((specimen.model.num_nodes, 3), dtype=bool)
    fixed[specimen.level_nodes(0)] = True
    prescribed = np.zeros(fixed.shape)
    prescribed[specimen.level_nodes(1), 2] = -design.Le
    path = solve_displacement_control(specimen.model.replace(fixed=fixed), prescribed, 100,
                                      extrapolation=2)
    assert not path.completed and "not finite" in path.message
    assert np.isfinite(path.constraint_force).all()
    assert np.abs(path.constraint_force).max() < 1e6


def test_random_designs_never_report_absurd_snap_forces():
    from kresling.analyses import snap_through
    rng = np.random.default_rng(7)
    for _ in range(20):
        d = Design(int(rng.integers(3, 13)), rng.uniform(0.51, 0.99),
                   float(rng.choice([1e-9, rng.uniform(0, 1), rng.uniform(0, 100)])),
                   float(10 ** rng.uniform(-1, 3)))
        try:
            r = snap_through(d)
        except ValueError as error:
            assert str(error).startswith(("Lc = ", "lam = ")), error
            continue
        assert np.isfinite(r.force).all()
        assert math.isnan(r.snap_force) or abs(r.snap_force) < 1e6, d


# 5. kresling manipulator --config 111 crashed printing a table with no rows.
def test_manipulator_with_every_module_rigid(capsys):
    status, out, err = run_cli(capsys, "manipulator", "--config", "111")
    assert status == 0 and err == ""
    assert "every module is extended" in out
    status, out, _ = run_cli(capsys, "manipulator", "--config", "111", "--json")
    assert status == 0 and json.loads(out)["config"] == "111"


# 6. Large integers: TypeErrors from numpy and from pybind11's int conversion.
def test_large_integers_are_value_errors(capsys):
    with pytest.raises(ValueError, match=r"^n = 100000000000000000000 is invalid: must be an "
                                         r"integer >= 3 and <= 2147483647"):
        Design(10**20, 0.8, 20)
    model, prescribed = driven_cell()
    with pytest.raises(ValueError, match=r"^steps = 2147483648 is invalid"):
        solve_displacement_control(model, prescribed, 2**31)
    with pytest.raises(ValueError, match=r"^steps = 100001 is invalid: must be an integer in "
                                         r"\[1, 100000\]"):
        solve_displacement_control(model, prescribed, 100001)
    with pytest.raises(ValueError, match=r"^max_iterations = 2147483648 is invalid"):
        solve_displacement_control(model, prescribed, 2, max_iterations=2**31)
    status, _, err = run_cli(capsys, "design", "--n", str(10**20), "--lam", "0.8", "--Lc", "1")
    assert_one_line_error(status, err, "design", "n = 100000000000000000000 is invalid")
    status, _, err = run_cli(capsys, "snap", "--n", "4", "--lam", "0.8", "--Lc", "1", "--steps",
                             str(10**20))
    assert_one_line_error(status, err, "snap", "steps = 100000000000000000000 is invalid")


# 7. A record or marker file with a line over 128 KiB raised _csv.Error.
def test_csv_line_over_csvs_limit_names_file_and_line(tmp_path, capsys):
    from kresling.fits.records import read_machine_record
    from kresling.manipulator.markers import read_markers
    record = tmp_path / "record.csv"
    record.write_text("displacement (mm),force (N)\n0,0\n1," + "2" * 200_000 + "\n2,4\n")
    with pytest.raises(ValueError, match=r"record.csv, line 3: not a CSV line \(field larger"):
        read_machine_record(record)
    assert len(read_machine_record(record, on_invalid="skip")) == 2
    markers = tmp_path / "markers.csv"
    markers.write_text("config,step,marker,x,y\n101,0,1,0," + "1" * 200_000 + "\n")
    with pytest.raises(ValueError, match=r"markers.csv, line 2: not a CSV line"):
        read_markers(markers)
    status, _, err = run_cli(capsys, "fit", "bending", str(record), "--state", "extended",
                             "--module-length", "60")
    assert_one_line_error(status, err, "fit", "line 3")


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


def test_truncated_manifest_names_the_file(tmp_path, capsys):
    from kresling.sweeps import design_grid, sweep
    out = tmp_path / "sweep"
    sweep(design_grid((4,), 2), ["psi_ratio"], out=out, progress=False, workers=1)
    manifest = out / "manifest.json"
    manifest.write_bytes(manifest.read_bytes()[:40])
    with pytest.raises(ValueError, match=r"manifest.json is damaged \(not JSON"):
        sweep(design_grid((4,), 2), ["psi_ratio"], out=out, progress=False, workers=1)
    status, _, err = run_cli(capsys, "sweep", "--n", "4", "--grid", "2", "--metrics",
                             "psi_ratio", "--out", str(out), "--no-progress")
    assert_one_line_error(status, err, "sweep", "manifest.json is damaged")


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


# 9. Non-integers silently truncated.
def test_non_integers_are_never_truncated():
    from kresling.analyses import (BendingTester, LinearBendingTester, SnapThroughTester)
    nodes = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    with pytest.raises(ValueError, match=r"^bars\[0, 1\] = 1.7 is invalid: must be an integer"):
        Model(nodes, [[0, 1.7]], [], bar_modulus=1.0, hinge_stiffness=1.0)
    with pytest.raises(ValueError, match=r"^bars has dtype bool: must be integers"):
        Model(nodes, [[False, True]], [], bar_modulus=1.0, hinge_stiffness=1.0)
    with pytest.raises(ValueError, match=r"^steps = 2.7 is invalid"):
        BendingTester(8, steps=2.7)
    with pytest.raises(ValueError, match=r"^cells = 4.9 is invalid"):
        BendingTester(8, cells=4.9)
    with pytest.raises(ValueError, match=r"^cells = 4.9 is invalid"):
        LinearBendingTester(8, cells=4.9)
    with pytest.raises(ValueError, match=r"^n = 8.9 is invalid"):
        SnapThroughTester(8.9)
    model, _ = driven_cell()
    with pytest.raises(ValueError, match=r"^node = 1.5 is invalid"):
        model.dof(1.5, "x")
    with pytest.raises(ValueError, match=r"^axis = True is invalid"):
        model.dof(1, True)
    assert model.dof(1.0, "y") == 4


# 10. Long C++ runs ignored Ctrl-C and had no bound.
@pytest.fixture
def sigint_raises():
    """Ctrl-C as an interactive Python has it (KeyboardInterrupt), whatever the test run
    inherited: a background job (``make test &``, ``nohup``) starts with SIGINT ignored, and
    then neither Python's handler nor ``_thread.interrupt_main`` is there to test."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


def _default_sigint():  # runs in a child before exec: Python installs its handler again
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def test_a_long_solve_stops_on_ctrl_c(sigint_raises):
    model, prescribed = driven_cell(n=40)  # 100000 increments: about 10 s or more of C++
    timer = threading.Timer(0.5, _thread.interrupt_main)
    start = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            solve_displacement_control(model, prescribed, 100_000)
    finally:
        timer.cancel()
    assert time.perf_counter() - start < 5.0


def test_step_counts_are_bounded():
    model, prescribed = driven_cell()
    with pytest.raises(ValueError, match=r"^steps = 1000000000 is invalid: must be an integer "
                                         r"in \[1, 100000\]"):
        solve_displacement_control(model, prescribed, 10**9)
    with pytest.raises(ValueError, match=r"^max_increments = 1000000000 is invalid"):
        solve_mgdcm(model, -0.01 * np.sign(prescribed), max_increments=10**9)


# 11. Silent NaN on accepted input.
def test_element_state_of_nan_displacements_is_refused():
    model, _ = driven_cell()
    with pytest.raises(ValueError, match=r"u contains NaN or inf"):
        model.element_state(np.full(model.num_dofs, np.nan))
    with pytest.raises(ValueError, match=r"u has 3 entries"):
        model.element_state([0.0, 0.0, 0.0])


@pytest.mark.parametrize("solver", ["displacement", "displacement_merlin2", "force", "mgdcm"])
def test_a_huge_initial_state_never_completes_with_nan(solver):
    model, prescribed = driven_cell()
    initial = np.zeros(model.num_dofs)
    initial[-1] = 1e300
    forces = -0.01 * np.sign(prescribed)
    if solver.startswith("displacement"):
        r = solve_displacement_control(model, prescribed, 2, initial=initial,
                                       merlin2_steps=solver.endswith("merlin2"))
    elif solver == "force":
        r = solve_force_control(model, forces, 2, initial=initial)
    else:
        r = solve_mgdcm(model, forces, max_increments=3, initial=initial)
    assert np.isfinite(r.constraint_force).all() and np.isfinite(r.energy).all()
    assert r.completed or r.message


def test_psi_ratio_overflow_is_documented_inf():
    # Psi_con = 1.6e-312 rad: the ratio exceeds the largest float (documented: inf).
    d = Design(70, 0.8, 2.4e-306, 825111)
    assert d.psi_con > 0 and d.psi_ratio == math.inf
    assert "exceeds the largest float" in type(d).psi_ratio.__doc__


# 12. A valid design raised RuntimeError: near-flat hinges read with an arccosine.
def test_facet_angle_of_a_nearly_flat_extended_cell():
    from kresling.analyses import facet_angle, facet_angles
    d = Design(15, 0.5000000000000001, 0.0)
    assert np.ptp(facet_angles(d, 1)) <= 1e-12 * max(d.psi_ext, 1e-300) + 1e-15
    assert facet_angle(d, 1) == pytest.approx(d.psi_ext, rel=1e-9)


# 13. Fabrication without a size limit: 198 784 paths, a 41k x 181k px PNG.
def test_fabrication_has_a_size_limit(tmp_path):
    from kresling.fabrication import cut_sheet, write_pattern
    with pytest.raises(ValueError, match=r"spans .* mm: a cut sheet must be at most 5000 mm"):
        cut_sheet(Design(17, 0.82, 10000, 1621), "paper")
    with pytest.raises(ValueError, match=r"the sheet would hold \d+ cut paths: at most 50000; "
                                         r"lengthen the dashes \(dash_length = 0.001 mm"):
        cut_sheet(Design(10, 0.9, 15), "paper", dash_length=1e-3, tie_length=1e-3)
    with pytest.raises(ValueError, match=r"^dpi = 100000 is invalid for a .* sheet: the PNG "
                                         r"would have .* pixels; must be at most"):
        write_pattern(tmp_path / "big.png", Design(10, 0.9, 15), dpi=100_000)


# 14. The property test's flaky example: alpha_e was exactly 0 at lam = 1 - 2^-52.
def test_alpha_e_is_positive_for_every_lambda_below_one():
    d = Design(28, 0.9999999999999998, 0, 1)
    assert 0.0 < d.alpha_e <= d.alpha0 < math.pi
    assert d.alpha_e == pytest.approx(math.pi - d.alpha0 - 2 * d.phi, abs=1e-15)


# 15. The smaller ones.
def test_analyses_given_a_non_design():
    from kresling.analyses import (bending_test, facet_angle, linear_bending_stiffness,
                                   snap_through)
    for call in (lambda: snap_through("x"), lambda: bending_test((8, 0.8, 30), 1),
                 lambda: linear_bending_stiffness(None, 1), lambda: facet_angle(8, 1)):
        with pytest.raises(ValueError, match=r"^design = .* is invalid: must be a "
                                             r"kresling.Design"):
            call()


def test_none_and_wrong_types_are_value_errors(tmp_path):
    from kresling.manipulator.markers import read_markers
    from kresling.sweeps import design_grid, sweep
    nodes = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.1]]
    with pytest.raises(ValueError, match=r"^hinge_law = None is invalid: must be one of"):
        Model(nodes, [[0, 1]], [[1, 2, 0, 3]], bar_modulus=1.0, hinge_stiffness=1.0,
              hinge_law=None)
    markers = tmp_path / "m.csv"
    markers.write_text("config,step,marker,x,y\n")
    with pytest.raises(ValueError, match=r"^modules = None is invalid"):
        read_markers(markers, None)
    with pytest.raises(ValueError, match=r"^metrics = None is invalid"):
        sweep(design_grid((4,), 2), None, progress=False)
    model, _ = driven_cell()
    with pytest.raises(ValueError, match=r"^dofs = 3 is invalid: must be a sequence"):
        condensed_stiffness(model, 3)
    with pytest.raises(ValueError, match=r"^dofs\[0\] = 1.5 is invalid"):
        condensed_stiffness(model, [1.5])


@pytest.mark.parametrize("fixed", [np.nan, 0.5, 2, "yes"])
def test_fixed_flags_are_booleans(fixed):
    nodes = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    mask = np.zeros((3, 3), dtype=object)
    mask[0, 0] = fixed
    with pytest.raises(ValueError, match=r"^fixed is invalid: must be booleans"):
        Model(nodes, [[0, 1]], [], bar_modulus=1.0, hinge_stiffness=1.0, fixed=mask)


def test_a_run_list_cannot_point_outside_its_folder(tmp_path):
    from kresling.fits.crease_files import read_crease_runs
    secret = tmp_path / "secret.csv"
    secret.write_text("displacement (mm),force (N)\n0,0\n1,1\n")
    folder = tmp_path / "runs"
    folder.mkdir()
    header = ("sample,run,record,Lp_mm,W_mm,vertex_x1_px,vertex_y1_px,upper_x1_px,upper_y1_px,"
              "lower_x1_px,lower_y1_px,vertex_x2_px,vertex_y2_px,upper_x2_px,upper_y2_px,"
              "lower_x2_px,lower_y2_px\n")
    for record in ("../secret.csv", str(secret)):
        (folder / "runs.csv").write_text(header + f"1,1,{record},10,20" + ",1" * 12 + "\n")
        with pytest.raises(ValueError, match=r"column 'record': .* is invalid: must be a file "
                                             r"in the list's folder"):
            read_crease_runs(folder / "runs.csv")


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


# Found by the fuzz suite (tests/fuzz): each a reproducer.
def test_fold_coordinates_beyond_the_float_range(tmp_path):
    from kresling.io import read_fold
    path = tmp_path / "big.fold"
    path.write_text('{"vertices_coords": [[0, 0], [1, 0], [' + "9" * 400 + ', 1]], '
                    '"faces_vertices": [[0, 1, 2]]}')
    with pytest.raises(ValueError, match=r"big.fold: key 'vertices_coords'\[2\]"):
        read_fold(path)


def test_supports_and_loads_must_be_arrays_of_tables():
    from kresling.simulate import load_problem
    problem = {"pattern": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "panels": [[0, 1, 2]]},
               "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0},
               "support": None, "load": [{"node": 2, "force": [0.0, 1.0, 0.0]}],
               "analysis": {"method": "force_control", "steps": 2}}
    with pytest.raises(ValueError, match=r"^problem: .*'support' = None is invalid: must be an "
                                         r"array of tables"):
        load_problem(problem)


def test_element_states_that_overflow_are_refused():
    from kresling.assembly import assemble
    model, _ = driven_cell()
    u = np.zeros(model.num_dofs)
    u[-1] = 1e100  # a stretch of 1e100: the Ogden law's s^4 overflows
    with pytest.raises(ValueError, match=r"^u is invalid: the element states are not finite"):
        model.element_state(u)
    with pytest.raises(ValueError, match=r"^u is invalid: the energy or the internal force"):
        assemble(model, u)


def test_arcs_of_extreme_tendons():
    from kresling.manipulator import arc_from_tendons
    # (a^2 + b^2) / scale^2 overflowed to inf / inf = NaN, passed the check and gave s = NaN
    assert np.isfinite(arc_from_tendons([0.0, 0.0, 1.34078079299426e154], 4.5e153)).all()
    with pytest.raises(ValueError, match=r"sqrt\(Q\) / \(3 N d\)"):
        arc_from_tendons([0.0, 0.0, 1.34078079299426e154], 4e153)
    # the mean of subnormal lengths underflowed to 0: kappa was inf
    assert np.isfinite(arc_from_tendons([0.0, 0.0, 5e-324])).all()
    with pytest.raises(ValueError, match=r"^d = 1e-310 is invalid: must be large enough"):
        arc_from_tendons([0.0, 0.0, 1e-310], 1e-310)  # kappa = 2e310


def test_a_long_arm_does_not_list_every_configuration():
    from kresling.manipulator import Manipulator, inverse_kinematics
    with pytest.raises(ValueError, match=r"^modules = 52 is invalid for listing every "
                                         r"configuration \(2\*\*52 of them\)"):
        inverse_kinematics(Manipulator(modules=52), [0.0, 0.0, 0.0])
    far = inverse_kinematics(Manipulator(), [0.0, 0.0, 1.34e154])
    assert not far.reachable and np.isfinite(far.distance)


def test_a_nearly_flat_specimen_builds():
    # 2 pi - 1e-17 rounded to 2 pi, a rest angle the model refuses
    specimen = kresling_specimen(Design(3, 0.75, 5.960464477539063e-08), [0])
    assert (specimen.model.hinge_rest_angle < 2 * math.pi).all()


def test_a_zero_poisson_ratio_names_it():
    from kresling.model import SheetMaterial, build_pattern_model
    square = (np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float), [[0, 1, 2, 3]])
    with pytest.raises(ValueError, match=r"^poisson_ratio = 0 is invalid for this pattern: it "
                                         r"gives bar \d+ .* a calibrated area of 0"):
        build_pattern_model(square, material=SheetMaterial(1.0, 0.0, 1.0))


def test_fits_that_overflow_name_the_file(tmp_path):
    from kresling.fits import fit_bending_files
    record = tmp_path / "huge.csv"
    record.write_text("# state: extended\n# module_length: 110 mm\ndisplacement (mm),force (N)\n"
                      "0,0\n1,1e308\n2,1e308\n")
    with pytest.raises(ValueError, match=r"huge.csv: the fitted K_B = .* is not finite"):
        fit_bending_files([record])


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


def test_ctrl_c_stops_a_long_command(tmp_path):
    import subprocess
    import sys
    # About 13 s of C++ (100000 increments of a 60-gon); it ignored Ctrl-C to the end. The
    # child gets the default disposition of SIGINT (a user's terminal), not this run's.
    process = subprocess.Popen([sys.executable, "-m", "kresling", "snap", "--n", "60", "--lam",
                                "0.8", "--Lc", "30", "--steps", "100000"], cwd=tmp_path,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               preexec_fn=_default_sigint)
    time.sleep(3.0)  # past the imports, inside the C++ drive
    process.send_signal(signal.SIGINT)
    signalled = time.perf_counter()
    try:
        _, err = process.communicate(timeout=30)
    finally:
        process.kill()
    assert process.returncode == 130, err
    assert err.strip() == "kresling snap: interrupted"
    assert time.perf_counter() - signalled < 5.0


def test_a_model_the_problem_cannot_build_names_the_problem_key():
    from kresling.simulate import simulate
    problem = {"pattern": {"vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],
                           "panels": [[0, 1, 2, 3]]},
               "material": {"calibration": "auto", "E": 1000.0, "nu": 0.0, "thickness": 0.25},
               "support": [{"nodes": [0, 1], "fix": "xyz"}, {"node": 3, "fix": "z"}],
               "load": [{"node": 2, "force": [0.0, 0.0, 0.01]}],
               "analysis": {"method": "force_control", "steps": 2}}
    with pytest.raises(ValueError, match=r"^problem: \[material\] key 'nu': poisson_ratio = 0 is "
                                         r"invalid"):
        simulate(problem)


def test_linear_bending_never_returns_a_bare_nan():
    # Lc / R = 1e6: the condensed stiffness is rounding noise (-9.5e-9); it was a bare NaN.
    from kresling.analyses import linear_bending_stiffness
    with pytest.raises(ValueError, match=r"^design = Design\(n=8, .* has no linearised K_B in "
                                         r"the contracted state: the condensed stiffness is "):
        linear_bending_stiffness(Design(8, 0.584, 1000, 0.001), 0)


def test_arm_and_view_inputs_are_value_errors(tmp_path):
    from kresling.arm import build_arm, pull_until_snap
    from kresling.view import view_model, view_path, write_html
    with pytest.raises(ValueError, match=r"^direction = \{\} is invalid"):
        pull_until_snap(build_arm("111"), {})
    model, prescribed = driven_cell()
    with pytest.raises(ValueError, match=r"^field = \[\] is invalid"):
        view_model(model, field=[])
    with pytest.raises(ValueError, match=r"^u = <object"):
        view_model(model, object())
    figure = view_path(model, solve_displacement_control(model, prescribed, 3))
    for frame in (math.nan, "", [], math.inf):
        with pytest.raises(ValueError, match=r"^initial_frame = "):
            write_html(figure, tmp_path / "page.html", initial_frame=frame)


def test_a_degenerate_panel_is_named():
    # a self-intersecting pentagon: its N5B8 centre landed on a corner and the model refused
    # "bar 0 (nodes 6, 0): rest length = 0"
    from kresling.model import SheetMaterial, build_pattern_model
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0]], float)
    with pytest.raises(ValueError, match=r"^panel 0: two of its sides cross or touch"):
        build_pattern_model((vertices, [[0, 1, 2, 3, 4]]), material=SheetMaterial(1e3, 0.3, 0.25))
