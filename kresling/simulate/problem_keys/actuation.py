"""``[[actuation]]``: creases driven to fold angles, by edge or by family: in stages one
after another (``method = "fold"``), or in time (``method = "dynamic"``, each entry with its
``time`` as a load's: docs/dynamics.md, 'Creases driven in time')."""

from __future__ import annotations

from dataclasses import dataclass

from kresling.model.crease_kinds import FOLD_FAMILIES
from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_keys.dynamics import OSCILLATING, read_load_time
from kresling.simulate.problem_table import integer, number, raw, string

__all__ = ["KEY", "Actuation", "ACTUATION_FAMILIES"]

#: The families an actuation may name: a fold family, or "fold" for every fold hinge.
ACTUATION_FAMILIES = FOLD_FAMILIES + ("join", "fold")


@dataclass(frozen=True)
class Actuation:
    """A group of creases driven together to a fold angle.

    Attributes
    ----------
    edges : tuple of (int, int), or None
        The creases by their two end vertices (0-based), or None with ``family``.
    family : str or None
        A whole family (:data:`ACTUATION_FAMILIES`).
    fold_angle_deg : float or None
        Target fold angle [deg], FOLD's convention (+ valley, - mountain, 0 flat); None:
        the pattern file's ``edges_foldAngle`` (or, with a harmonic or chirp ``time``, no
        target: the time function's amplitude is the fold angle's swing [deg]).
    stage : int
        Stages fold one after another, 1 first.
    time : LoadTime or None
        ``method = "dynamic"``: the factor in time of the way from the rest angle at the
        start to the target (or, harmonic or chirp, the fold angle's change [deg]); None:
        a step.
    """

    edges: tuple | None
    family: str | None
    fold_angle_deg: float | None
    stage: int = 1
    time: object = None


def read_actuations(entries, context) -> dict:
    """The ``[[actuation]]`` entries."""
    num_vertices = context.pattern.num_vertices
    out = []
    for i, t in enumerate(entries):
        if t.has("edges") == t.has("family"):
            t.fail(None, f"(entry {i}) needs exactly one of 'edges' (creases by their end "
                         "vertices) or 'family' (one of " + ", ".join(ACTUATION_FAMILIES) + ")")
        edges = family = None
        if t.has("edges"):
            value = t.get("edges", raw)
            if not isinstance(value, list) or not value:
                t.fail("edges", f"= {value!r} is invalid: must be a non-empty list of [u, v] "
                                "vertex pairs")
            pairs = []
            for pair in value:
                if not isinstance(pair, list) or len(pair) != 2:
                    t.fail("edges", f"has {pair!r}: each crease is a pair [u, v] of vertices")
                u, v = (integer(t, "edges", x) for x in pair)
                for x in (u, v):
                    if not 0 <= x < num_vertices:
                        t.fail("edges", f"has vertex {x}: out of range, the pattern's vertices "
                                        f"are 0 to {num_vertices - 1}")
                if u == v:
                    t.fail("edges", f"has [{u}, {v}]: a crease joins two different vertices")
                pairs.append((min(u, v), max(u, v)))
            edges = tuple(pairs)
        else:
            family = t.get("family", string, choices=ACTUATION_FAMILIES)
        time = read_load_time(t)
        oscillating = time is not None and time.kind in OSCILLATING
        if oscillating and t.has("fold_angle_deg"):
            t.fail("fold_angle_deg", f"applies only to a time that drives to a target: a "
                                     f"{time.kind} swings the fold angle about its start by "
                                     "its amplitude [deg]")
        if not t.has("fold_angle_deg") and not oscillating:
            t.fail("fold_angle_deg", "is missing: must be a target fold angle in [-180, 180] "
                                     "deg, or \"file\" for the pattern's edges_foldAngle")
        given = t.get("fold_angle_deg", raw, None)
        if given is None or given == "file":
            angle = None
        else:
            if isinstance(given, str):
                t.fail("fold_angle_deg", f"= {given!r} is invalid: must be a number of degrees "
                                         "or \"file\"")
            angle = number(t, "fold_angle_deg", given)
            if not -180.0 <= angle <= 180.0:
                t.fail("fold_angle_deg", f"= {angle!r} is invalid: must be in [-180, 180] deg "
                                         "(+ valley, - mountain)")
        stage = t.get("stage", integer, 1)
        if not 1 <= stage <= 1000:
            t.fail("stage", f"= {stage!r} is invalid: must be an integer in [1, 1000]")
        t.finish()
        out.append(Actuation(edges, family, angle, stage, time))
    return {"actuations": tuple(out)}


def check_actuations(problem):
    """Creases are driven by a method that drives them: a fold in stages, a motion in time
    (implicit) by each entry's time function."""
    if not problem.actuations:
        return
    method = problem.analysis.method
    if not (problem.method.drives_creases or problem.method.in_time):
        raise ValueError(f"{problem.source}: [[actuation]] drives creases only with "
                         f"[analysis] method = 'fold' or 'dynamic' (given: {method!r})")
    for i, entry in enumerate(problem.actuations):
        where = f"{problem.source}: actuation[{i}]"
        if problem.method.drives_creases and entry.time is not None:
            raise ValueError(f"{where} key 'time' applies only with [analysis] method = "
                             f"'dynamic' (given: {method!r}): a fold drives its creases in "
                             "stages")
        if problem.method.in_time and entry.stage != 1:
            raise ValueError(f"{where} key 'stage' = {entry.stage} applies only with "
                             f"[analysis] method = 'fold': in a motion each entry's time "
                             "drives its creases")
    if problem.method.in_time and problem.dynamics is not None and \
            problem.dynamics.scheme == "explicit":
        raise ValueError(f"{problem.source}: [[actuation]] drives creases only with "
                         "[dynamics] scheme = 'newmark' or 'hht' (given: 'explicit')")


KEY = ProblemKey("actuation", rank=80, read=read_actuations, array=True,
                 check=check_actuations)
