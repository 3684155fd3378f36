"""The MEMS micro-mirror of examples/micro_mirror: a structure of [[bar]] and [[hinge]]
members 1.4 mm across (beams 0.1 mm wide) whose fold under gravity and whose modes before
and after come out of one problem file, and which folds at 1000 times its size as it does
at its own.

References: the flat structure's modes from an eigen-analysis written here (numpy: the
tangent of a stress-free state is the bars' EA/L and the hinges' k g g^T, g the dihedral
angle's gradient in its textbook closed form), and the similarity of statics (lengths x s,
areas x s^2, hinge stiffnesses x s^3, forces x s^2: displacements x s, angles unchanged).
"""

from __future__ import annotations

import importlib.util
import tomllib
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg

from kresling.simulate import build_problem_model, simulate

MIRROR = Path(__file__).resolve().parents[2] / "examples" / "micro_mirror"


def _make_problem():
    spec = importlib.util.spec_from_file_location("make_problem", MIRROR / "make_problem.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_committed_problem_is_what_make_problem_writes():
    assert _make_problem().problem_text() == (MIRROR / "problem.toml").read_text()


@pytest.fixture(scope="module")
def mirror():
    return simulate(MIRROR / "problem.toml", progress=False)


def _dihedral_gradient(x_i, x_j, x_k, x_l):
    """d theta / d(x_i, x_j, x_k, x_l) for the spring [i, j, k, l] (axis j -> k)."""
    r_ij, r_kj, r_kl = x_i - x_j, x_k - x_j, x_k - x_l
    m, n = np.cross(r_ij, r_kj), np.cross(r_kj, r_kl)
    axis = np.dot(r_kj, r_kj)
    g_i = np.sqrt(axis) / np.dot(m, m) * m
    g_l = -np.sqrt(axis) / np.dot(n, n) * n
    g_j = (np.dot(r_ij, r_kj) / axis - 1) * g_i - np.dot(r_kl, r_kj) / axis * g_l
    g_k = (np.dot(r_kl, r_kj) / axis - 1) * g_l - np.dot(r_ij, r_kj) / axis * g_i
    return np.concatenate([g_i, g_j, g_k, g_l])


def _flat_frequencies(problem_file, count):
    """The lowest ``count`` frequencies [Hz] of the stress-free structure, from the file's
    own numbers (mm, N, t)."""
    data = tomllib.loads(Path(problem_file).read_text())
    X = np.array(data["pattern"]["vertices"], dtype=float)
    n = len(X)
    K = np.zeros((3 * n, 3 * n))
    for entry in data["bar"]:
        for a, b in entry["nodes"]:
            e = X[b] - X[a]
            length = np.linalg.norm(e)
            e /= length
            block = entry["modulus"] * entry["area"] / length * np.outer(e, e)
            for p, q, sign in ((a, a, 1), (b, b, 1), (a, b, -1), (b, a, -1)):
                K[3 * p:3 * p + 3, 3 * q:3 * q + 3] += sign * block
    for entry in data["hinge"]:
        assert entry["convention"] == "simfast"
        for spring in entry["nodes"]:
            g = _dihedral_gradient(*(X[v] for v in spring))
            dofs = np.concatenate([np.arange(3 * v, 3 * v + 3) for v in spring])
            K[np.ix_(dofs, dofs)] += entry["stiffness"] * np.outer(g, g)
    masses = np.zeros(n)
    for entry in data["mass"]:
        masses[entry["node"]] += entry["mass"]
    free = np.ones(3 * n, dtype=bool)
    for entry in data["support"]:
        for node in entry["nodes"]:
            free[3 * node:3 * node + 3] = False
    M = np.repeat(masses, 3)
    eigenvalues = scipy.linalg.eigh(K[np.ix_(free, free)], np.diag(M[free]),
                                    eigvals_only=True, subset_by_index=(0, count - 1))
    return np.sqrt(eigenvalues) / (2 * np.pi)


def test_the_flat_mirrors_modes_are_the_closed_form_eigen_analysis(mirror):
    assert mirror.completed, mirror.message
    runs = dict(mirror.runs)
    flat = runs["flat_modes"].modes.frequencies_hz
    # The same 99-DOF eigenproblem, solved by two solvers in double precision. Its
    # stiffness spans 1e-9 (hinges) to 3e3 N/mm (bars) over node masses down to 5e-14 t,
    # so each solver's eigenvalue carries a rounding error up to ~eps ||M^-1 K|| = 13
    # 1/s^2, 2.6e-6 of the first eigenvalue (5e6 1/s^2): 1e-5 relative in frequency. (A
    # hinge stiffness in the wrong unit, or multiplied by its axis's length, moves them by
    # orders of magnitude.)
    np.testing.assert_allclose(flat, _flat_frequencies(MIRROR / "problem.toml", 3), rtol=1e-5)
    assert 300.0 < flat[0] < 400.0     # the mirror's flapping about its beams


def test_the_mirror_folds_under_gravity_and_its_folded_modes_come_from_the_file(mirror):
    runs = dict(mirror.runs)
    fold = runs["fold"]
    assert fold.completed and fold.path.num_steps == 20
    report = fold.fold_report()
    # Every driven crease folds the way it was told, short of its rest angle where the
    # segments' undriven diagonal creases resist (the file's 10 deg tolerance).
    assert report["creases_driven"] == 10 and report["left_branch"] == 0
    assert report["largest_shortfall_deg"] < 10.0
    flat = runs["flat_modes"].modes.frequencies_hz
    folded = runs["folded_modes"].modes.frequencies_hz
    # About the folded state, with its rest angles and stress: the lowest mode softens.
    assert folded[0] < 0.95 * flat[0]
    assert np.abs(runs["folded_modes"].state).max() > 0.02   # mm: the mirror has risen


def _fold_only(scale, *, si=False):
    """The mirror's fold stage alone, the structure scaled by ``scale`` in similarity, its
    numbers in SI (m, Pa, m^2, N m/rad) rather than mm with ``si``."""
    data = tomllib.loads((MIRROR / "problem.toml").read_text())
    fold = next(stage for stage in data["stage"] if stage["name"] == "fold")
    problem = {key: data[key] for key in ("pattern", "bar", "hinge", "support")}
    length, modulus = (1e-3, 1e6) if si else (1.0, 1.0)
    problem["pattern"] = dict(problem["pattern"], vertices=(
        np.array(problem["pattern"]["vertices"]) * scale * length).tolist())
    problem["bar"] = [dict(b, area=b["area"] * (scale * length) ** 2,
                           modulus=b["modulus"] * modulus) for b in problem["bar"]]
    problem["hinge"] = [dict(h, stiffness=h["stiffness"] * scale**3 * length)
                        for h in problem["hinge"]]
    problem["actuation"] = fold["actuation"]
    problem["load"] = [dict(load, force=[f * scale**2 for f in load["force"]])
                       for load in fold["load"]]
    problem["analysis"] = {"method": "fold", "steps": fold["steps"],
                           "target_tolerance_deg": fold["target_tolerance_deg"]}
    return simulate(problem, progress=False)


def test_the_mirror_folds_at_a_thousand_times_its_size_as_at_its_own():
    small, large = _fold_only(1.0), _fold_only(1000.0)
    assert small.completed and large.completed
    # Newton's test is relative to the structure's size and the hinges' angle is exact at
    # flat: the same path, increment for increment and iteration for iteration.
    np.testing.assert_array_equal(small.path.iterations, large.path.iterations)
    # Displacements scale with the size, to the Newton tolerance (1e-8 of the size).
    np.testing.assert_allclose(large.path.displacement, 1000.0 * small.path.displacement,
                               rtol=0, atol=1e-6 * np.abs(large.path.displacement).max())
    angles = [s.model.element_state(s.path.displacement[-1])["hinge_angle"]
              for s in (small, large)]
    np.testing.assert_allclose(angles[1], angles[0], rtol=0, atol=1e-8)


def test_the_mirrors_members_build_with_their_own_stiffnesses():
    pm = build_problem_model(MIRROR / "problem.toml")
    assert pm.model.num_nodes == 33
    assert set(pm.hinge_family) == {"member"} and set(pm.bar_family) == {"member"}
    # A member hinge's stiffness is its moment per radian: not multiplied by its axis.
    assert np.all(pm.model.hinge_length == 1.0)


def test_the_mirror_in_si_numbers_folds_as_in_mm():
    """The same file written in metres, pascals and N m/rad (forces in N either way)."""
    mm, si = _fold_only(1.0), _fold_only(1.0, si=True)
    assert mm.completed and si.completed
    np.testing.assert_array_equal(mm.path.iterations, si.path.iterations)
    np.testing.assert_allclose(si.path.displacement * 1e3, mm.path.displacement, rtol=0,
                               atol=1e-6 * np.abs(mm.path.displacement).max())


def test_the_chirp_stage_drives_the_folded_mirror_and_balances_its_energy(mirror):
    runs = dict(mirror.runs)
    chirp = runs["chirp"]
    assert chirp.completed and chirp.path.num_steps == 1000
    history = chirp.history
    # Started from the folded state, under its weights: the right beam's creases swing
    # about the rest angles the fold left.
    np.testing.assert_allclose(chirp.path.displacement[0], runs["folded_modes"].state,
                               atol=1e-3)
    balance = (history.kinetic + history.strain + history.dissipated - history.work
               - history.actuation_work)
    # Newmark's average acceleration balances exactly for a linear model; this one is
    # nearly linear at these amplitudes (micrometres on a 1.4 mm structure): 1e-3 of the
    # energy the actuation put in.
    assert np.ptp(balance) < 1e-3 * np.abs(history.actuation_work).max()
    centre = chirp.path.displacement[:, 3 * 28 + 2]
    assert 5e-3 < np.ptp(centre) < 0.1    # mm: the mirror moves, by micrometres

