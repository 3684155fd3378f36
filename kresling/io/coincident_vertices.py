"""Coincident vertices of a flat crease pattern read from a file: a copy merged, a cut kept.

Two vertices of an unfolded pattern at one point (closer than
:data:`~kresling.io.cuts.DUPLICATE_TOLERANCE` of its size) are one of three things:

- **a cut**, which stays: both lie on edges the file assigns ``C`` (FOLD 1.2's cut), or every
  pair of edges that merging them would lay on top of each other is assigned ``B`` or ``C`` by
  the file on both sides (a slit drawn as two boundaries, as FOLD 1.1 files and Origami
  Simulator's exports draw one);
- **a copy**, which is merged into the lower-numbered vertex with a warning: a vertex written
  twice, so that the faces round it are parted along edges that the file does not call
  boundaries (a crease the file assigns, or a side it does not list). Merged, the faces round
  the point are joined along those edges into one fan, each edge between at most two faces
  turning opposite ways, as in any sheet; the copy is removed and the vertices after it are
  numbered one lower;
- **a mistake**, refused naming both vertices and the file: merging would join the faces at
  the point only (no edge between them), lay three faces on one edge, join two faces turning
  the same way, or give one face the point twice.

Folded patterns are not looked at: folding, and folding flat, bring vertices together.
"""

from __future__ import annotations

import logging

import numpy as np

from kresling.io.cuts import DUPLICATE_TOLERANCE, coincident_twins

__all__ = ["merge_coincident_vertices"]

logger = logging.getLogger(__name__)

#: Pairs a warning lists by name before summing up the rest.
_LISTED = 5


def _sides(face):
    return list(zip(face, face[1:] + face[:1]))


def _key(u, v):
    return (u, v) if u < v else (v, u)


def merge_coincident_vertices(vertices, faces, edges, assignments, angles, frames, fail, *,
                              declared: int, source: str = "", first: int = 0):
    """Merge the copies among a flat pattern's coincident vertices (see the module's text).

    Parameters
    ----------
    vertices : ndarray, shape (N, 3)
        Coordinates [mm].
    faces : tuple of tuple of int
    edges : ndarray of int, shape (E, 2)
        Every side of every face among them (:func:`~kresling.io.pattern.complete_edges`).
    assignments : tuple of str, length E
    angles : ndarray, shape (E,)
        Fold angles [degrees], NaN where unknown.
    frames : sequence of ndarray, each of shape (N, 3)
        Further configurations of the vertices [mm].
    fail : callable
        ``fail(message)`` returns the exception to raise.
    declared : int
        How many of the leading edges have an assignment the file states (the others'
        were derived: ``B`` on one face, ``U`` between two).
    source : str
        The file, named in the warning.
    first : int
        The number the file gives its first vertex (1 for OBJ), for the messages.

    Returns
    -------
    tuple
        ``(vertices, faces, edges, assignments, angles, frames)``: the arguments themselves
        if nothing is merged; else without the copies, every index renumbered, the edges
        laid on top of each other made one (with the assignment and fold angle the file
        gives it, a crease rather than a boundary).

    Raises
    ------
    ValueError
        From ``fail``, for coincident vertices that are neither a cut nor a copy, naming
        both and why.
    """
    twins = coincident_twins(vertices, faces, DUPLICATE_TOLERANCE)
    if not twins:
        return vertices, faces, edges, assignments, angles, frames
    letter = {}
    for k, (u, v) in enumerate(np.asarray(edges).tolist()):
        letter[_key(u, v)] = (assignments[k], k < declared)
    on_cut = {v for (u, w), (a, _) in letter.items() if a == "C" for v in (u, w)}
    into = {}
    for one, other, gap in twins:
        if not (one in on_cut and other in on_cut):
            into[other] = (one, gap)
    if not into:
        return vertices, faces, edges, assignments, angles, frames

    # A pair whose every seam the file calls a boundary on both sides is a cut: kept apart
    # (decided on the merge of every pair, then checked again without the cuts).
    seams = _seams(faces, into)
    for other in sorted(into):
        one = into[other][0]
        at = [originals for pair, originals in seams.items() if one in pair]
        if at and all(_stated(edge, letter, "BC") for originals in at for edge in originals):
            del into[other]
    if not into:
        return vertices, faces, edges, assignments, angles, frames

    def target(v):
        return into[v][0] if v in into else v

    _check_merge(faces, into, target, _seams(faces, into), fail, first)
    return _merged(vertices, faces, edges, assignments, angles, frames, into, target, letter,
                   fail, source, first, declared)


def _stated(edge, letter, kinds) -> bool:
    """The file states the assignment of ``edge`` (a vertex pair), one of ``kinds``."""
    kind, stated = letter[_key(*edge)]
    return stated and kind in kinds


def _seams(faces, into) -> dict:
    """The edges merging ``into`` would join two faces along, each with the original edges
    laid on it (two or more: the faces were parted there)."""
    def target(v):
        return into[v][0] if v in into else v

    sides = {}
    for face in faces:
        for u, v in _sides(face):
            sides.setdefault(_key(target(u), target(v)), set()).add(_key(u, v))
    faces_on = {}
    for face in faces:
        for u, v in _sides([target(w) for w in face]):
            faces_on[_key(u, v)] = faces_on.get(_key(u, v), 0) + 1
    return {pair: sorted(originals) for pair, originals in sides.items()
            if len(originals) > 1 and faces_on[pair] >= 2}


def _check_merge(faces, into, target, seams, fail, first):
    """Refuse a merge that would not leave one fan of faces round each merged point."""
    merged_at = {one for one, _ in into.values()}
    for other, (one, gap) in sorted(into.items()):
        names = f"vertices {one + first} and {other + first}"
        if not any(one in pair for pair in seams):
            raise fail(f"{names} coincide ({gap:.3g} mm apart) and their faces share no "
                       "edge there: the panels would meet at that point only. Use one vertex "
                       "for both if the sheet is joined there, or move them apart (for a "
                       "slit, assign the edges along it 'C')")
    directions = {}
    for f, face in enumerate(faces):
        mapped = [target(v) for v in face]
        if len(set(mapped)) < len(mapped):
            twice = next(v for v in mapped if mapped.count(v) > 1)
            raise fail(f"face {f} has two corners at vertex {twice + first} and its copy: "
                       "merging coincident vertices would pinch the face; move them apart")
        for u, v in _sides(mapped):
            directions.setdefault(_key(u, v), []).append((f, u < v))
    for (u, v), uses in directions.items():
        if not (u in merged_at or v in merged_at):
            continue
        where = f"edge {u + first}-{v + first}"
        if len(uses) > 2:
            raise fail(f"merging coincident vertices would put faces "
                       f"{', '.join(str(f) for f, _ in uses)} on one {where}: a sheet has at "
                       "most two faces on an edge; move the vertices apart or assign the "
                       "edges 'C'")
        if len(uses) == 2 and uses[0][1] == uses[1][1]:
            raise fail(f"merging coincident vertices would join faces {uses[0][0]} and "
                       f"{uses[1][0]} along {where} turning the same way (one folded over "
                       "the other); move the vertices apart or assign the edges 'C'")


def _merged(vertices, faces, edges, assignments, angles, frames, into, target, letter, fail,
            source, first, declared):
    """The pattern's arrays with the copies ``into`` merged and the vertices renumbered."""
    keep = np.ones(len(vertices), dtype=bool)
    keep[list(into)] = False
    number = np.cumsum(keep) - 1                     # new index of every kept vertex

    def renumbered(v):
        return int(number[target(v)])

    new_faces = tuple(tuple(renumbered(v) for v in face) for face in faces)
    faces_on = {}
    for face in new_faces:
        for u, v in _sides(face):
            faces_on[_key(u, v)] = faces_on.get(_key(u, v), 0) + 1
    edges = np.asarray(edges).tolist()
    groups = {}                                      # merged pair -> its original edges
    for k, (u, v) in enumerate(edges):
        groups.setdefault(_key(renumbered(u), renumbered(v)), []).append(k)
    new_edges, new_assignments, new_angles = [], [], []
    for pair, members in groups.items():
        u, v = edges[members[0]]
        new_edges.append((renumbered(u), renumbered(v)))
        if len(members) == 1 or faces_on.get(pair, 0) < 2:
            # Not between two faces: the edge the file states, if it states one.
            stated = [k for k in members if k < declared] or members
            new_assignments.append(assignments[stated[0]])
            new_angles.append(float(angles[stated[0]]))
            continue
        # Laid on top of each other: one edge between two faces, with the crease (or cut)
        # the file gives it (a side was a boundary only because of the copy); unassigned if
        # the file gives none.
        creases = [k for k in members if _stated(edges[k], letter, "C")] or [
            k for k in members if _stated(edges[k], letter, "MVFUJ")]
        kinds = {assignments[k] for k in creases}
        if len(kinds) > 1:
            raise fail(f"merging coincident vertices would make edges "
                       f"{' and '.join(str(k) for k in creases)} one, but the file assigns "
                       f"them {' and '.join(sorted(kinds))}; move the vertices apart or "
                       "assign the edges alike")
        new_assignments.append(assignments[creases[0]] if creases else "U")
        new_angles.append(float(angles[creases[0]]) if creases else float("nan"))
    pairs = sorted(into.items())
    listed = ", ".join(f"{other + first} into {one + first} ({gap:.2g} mm apart)"
                       for other, (one, gap) in pairs[:_LISTED])
    more = f" and {len(pairs) - _LISTED} more" if len(pairs) > _LISTED else ""
    logger.warning("%s: %d coincident %s merged (a vertex written twice parts the faces "
                   "round it): %s%s; the faces are joined along the edges between them, and "
                   "the vertices after each copy are numbered one lower (%d vertices left)",
                   source or "pattern", len(pairs), "vertex" if len(pairs) == 1 else "vertices",
                   listed, more, int(keep.sum()))
    return (np.asarray(vertices)[keep], new_faces,
            np.array(new_edges, dtype=np.int64).reshape(-1, 2), tuple(new_assignments),
            np.array(new_angles, dtype=float), tuple(np.asarray(f)[keep] for f in frames))

