"""``kresling arm --crease-switch MODULE``: switch one module by its creases, beside the
tendons."""

from __future__ import annotations

import math

from kresling.cli._output import print_json, print_table

#: Where the creases start from: the built arm, the module resting contracted (built
#: extended), or where pulling all tendons leaves the arm.
STARTS = ("built", "contracted", "pulled")


def add_arguments(parser, analysis) -> None:
    """The option on ``kresling arm`` and its settings."""
    analysis.add_argument("--crease-switch", type=int, metavar="MODULE",
                          help="switch the module of this index (0-based from the base) by "
                               "driving its "
                               "creases' rest angles instead of pulling the tendons (which "
                               "are let out), towards its other state; reports the change and "
                               "moment at the snap and where the released arm rests, beside "
                               "pulling all tendons")
    parser.add_argument("--crease-group", default="fold",
                        choices=("fold", "valley", "mountain", "polygon"),
                        help="with --crease-switch: the creases driven (default: all folds)")
    parser.add_argument("--crease-start", default="built", choices=STARTS,
                        help="with --crease-switch: start from the built arm, from the module "
                             "resting contracted though built extended (the creases then "
                             "extend it, which tendons cannot), or from where pulling all "
                             "tendons leaves the arm (default: built)")


def _finite(value):
    return float(value) if isinstance(value, float) and math.isfinite(value) else None


def _summary(r) -> dict:
    out = {"module": r.module, "group": r.group, "to": r.to, "creases": r.creases,
           "switched": r.switched, "configuration_before": r.configuration_before,
           "configuration_after": r.configuration_after,
           "snap_change_deg": _finite(r.snap_change_deg), "moment": _finite(r.moment),
           "max_crease_moment": _finite(r.max_crease_moment), "work": _finite(r.work),
           "let_out": r.let_out, "start_cell_height": r.start.cell_height.tolist(),
           "start_tip_position": r.start.tip_position.tolist(),
           "after_cell_height": r.after.cell_height.tolist() if r.after else None,
           "after_tip_position": r.after.tip_position.tolist() if r.after else None,
           "message": r.message}
    t = r.tendons
    out["tendons"] = None if t is None else {
        "snapped": t.snapped, "snapped_module": t.snapped_module if t.snapped else None,
        "tension_sum": _finite(t.tension_sum), "pull": _finite(t.pull),
        "configuration_after": t.configuration_after,
        "after_tip_position": t.after.tip_position.tolist() if t.after else None}
    return out


def run(args, arm) -> int:
    from kresling.arm import pull_until_snap
    from kresling.arm.creases import crease_switch, resting_state

    if args.pulls is not None or args.pretension is not None:
        raise ValueError("crease-switch: the tendons are let out; leave --pulls and "
                         "--pretension out")
    module = args.crease_switch
    if not 0 <= module < arm.modules:
        raise ValueError(f"crease-switch = {module} is invalid: must be a module in "
                         f"[0, {arm.modules - 1}] (0: the base)")
    start = None
    if args.crease_start == "contracted":
        start = resting_state(arm, module, 0)
    elif args.crease_start == "pulled":
        start = pull_until_snap(arm).after
        if start is None:
            raise ValueError("crease-start = 'pulled' is invalid here: pulling all tendons "
                             "snaps no module of this arm")
    r = crease_switch(arm, module, group=args.crease_group, start=start)
    out = _summary(r)
    if args.json:
        print_json({**out, "completed": True})
        return 0
    print(f"module {module} driven {r.to} by its {r.group} creases ({r.creases}), tendons let "
          f"out by {r.let_out:.3g} mm: {r.message}")
    rows = [("configuration", r.configuration_before, r.configuration_after, ""),
            ("cell heights", _fmt(r.start.cell_height),
             _fmt(r.after.cell_height) if r.after else "-", "mm"),
            ("tip position", _fmt(r.start.tip_position),
             _fmt(r.after.tip_position) if r.after else "-", "mm")]
    print_table(rows, ("", "start", "released", "unit"))
    if not math.isnan(r.snap_change):
        print(f"rest-angle change {'at the snap' if r.switched else 'where the scan ended'}: "
              f"{r.snap_change_deg:.5f} deg; summed crease moment {r.moment:.5g} N*mm "
              f"(largest {r.max_crease_moment:.4g}); work {r.work:.5g} N*mm")
    t = r.tendons
    if t is not None:
        print(f"pulling all tendons instead: {t.message}; lands at "
              f"{t.configuration_after}" + (f", tip {_fmt(t.after.tip_position)} mm"
                                             if t.after else ""))
    elif r.to == "extended":
        print("tendons only pull: they cannot extend a module")
    return 0


def _fmt(values) -> str:
    return "(" + ", ".join(f"{v:.6g}" for v in values) + ")"
