"""``kresling pattern --check FILE``: build a crease pattern's model as ``kresling simulate``
would fold it, and say what it repaired or would refuse, before anything runs."""

from __future__ import annotations

import logging
import sys

from kresling.cli._output import print_json, print_table


class _Repairs(logging.Handler):
    """Collects the readers' and builders' warnings: what they changed in the pattern."""

    def __init__(self):
        super().__init__(logging.WARNING)
        self.messages = []

    def emit(self, record):
        self.messages.append(record.getMessage())


def examine(file, *, split="N5B8", snap_tolerance=None, unit=None, scale=None,
            frame=0) -> tuple:
    """Read ``file`` and build its model as ``kresling simulate`` would fold it (the
    problem a new user writes: the pattern, its creases driven to the file's fold angles).

    Returns
    -------
    summary : dict
        The file and split; the counts read and built, as far as it got.
    repairs : list of str
        The readers' and builders' warnings: what they changed in the pattern.
    refusal : str or None
        Why ``simulate`` would refuse it (its own message), or None.
    """
    from kresling.simulate import build_problem_model, load_problem
    from kresling.simulate.fold_plan import fold_plan

    pattern_keys = {"file": str(file), "split": split}
    for key, value in (("snap_tolerance", snap_tolerance), ("unit", unit), ("scale", scale)):
        if value is not None:
            pattern_keys[key] = value
    if frame:
        pattern_keys["frame"] = frame
    problem = {"pattern": pattern_keys,
               "actuation": [{"family": "fold", "fold_angle_deg": "file"}],
               "analysis": {"method": "fold"}}
    repairs = _Repairs()
    logger = logging.getLogger("kresling")
    logger.addHandler(repairs)
    refusal, summary = None, {"file": str(file), "split": split}
    try:
        loaded = load_problem(problem)
        pattern = loaded.pattern
        summary.update(vertices=pattern.num_vertices, faces=pattern.num_faces,
                       edges=pattern.num_edges)
        pm = build_problem_model(loaded)
        summary.update(nodes=pm.model.num_nodes, bars=len(pm.model.bars),
                       hinges=len(pm.model.hinges))
        try:
            plan = fold_plan(loaded, pm)
            summary["creases_with_targets"] = int(plan.hinges.size)
            if plan.closure is not None:
                tolerance = loaded.analysis.target_tolerance_deg
                summary["rigid_closure"] = plan.closure.report(tolerance)
                words = plan.closure.words(tolerance, "whose creases all have one")
                if words:
                    summary["note"] = (f"the file's fold angles are {words}: a fold to them "
                                       "bends or stretches its panels, or falls short")
        except ValueError as error:   # no fold angles: it builds, but folds nothing as is
            summary["creases_with_targets"] = 0
            summary["note"] = str(error)
    except ValueError as error:
        refusal = str(error)
    finally:
        logger.removeHandler(repairs)
    return summary, repairs.messages, refusal


def refuse(refusal: str) -> int:
    """Say why ``simulate`` would refuse the pattern; the exit status (1)."""
    print(f"kresling pattern: simulate would refuse it: {refusal}", file=sys.stderr)
    return 1


def check(args) -> int:
    """``--check``: :func:`examine` ``args.check``, print what it found; exit 0 if
    ``simulate`` would take it, 1 (with the reason) if it would refuse it."""
    summary, repairs, refusal = examine(args.check, split=args.split,
                                        snap_tolerance=args.snap_tolerance)
    summary["repairs"] = repairs
    summary["refused"] = refusal
    if args.json:
        print_json(summary)
    else:
        rows = [(key, summary[key]) for key in ("file", "split", "vertices", "faces", "edges",
                                                "nodes", "bars", "hinges",
                                                "creases_with_targets") if key in summary]
        print_table(rows, ("quantity", "value"))
        for message in repairs:
            print(f"repaired: {message}")
        if "note" in summary:
            print(f"note: {summary['note']}")
    return 0 if refusal is None else refuse(refusal)
