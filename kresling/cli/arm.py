"""``kresling arm``: the manipulator as one structure (modules, guides, tendons).

Without options it builds the arm of a configuration and reports its tip; ``--tip-load``
carries a tip force (tendons pretensioned first), ``--pull-all`` shortens all three tendons
together until the first module snaps, ``--capacity`` finds the largest tip loads along four
directions.
"""

from __future__ import annotations

import sys

from kresling.arm.structure import THESIS_DESIGN
from kresling.cli import arm_creases
from kresling.cli import arm_dynamics
from kresling.cli._output import check_output_file, print_json, print_table
from kresling.cli.design import add_design_arguments


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "arm",
        help="the tendon-driven arm as a structure: tip loads, pull-to-snap, load capacity",
        description="Build the manipulator as one bar-and-hinge structure (modules of two "
                    "Kresling cells, stiff guides, three sliding tendons from the fixed base "
                    "to the tip) and report its tip; optionally under a tip load, pulling "
                    "all tendons until a module snaps, or its load capacity. Lengths in mm, "
                    "forces in N.",
    )
    design = parser.add_argument_group("the cell (default: the thesis's optimum)")
    add_design_arguments(design, defaults=THESIS_DESIGN, chirality=False)
    arm = parser.add_argument_group("the arm")
    arm.add_argument("--modules", type=int, help="number of modules (default: the "
                     "configuration's length, or 3)")
    arm.add_argument("--config", help="module states from the base, 0 contracted / 1 extended "
                     "(default: all extended)")
    arm.add_argument("--tendon-radius", type=float, default=32.0,
                     help="radius d of the tendon holes [mm] (default 32)")
    arm.add_argument("--tendon-stiffness", type=float, default=500.0,
                     help="axial rigidity EA of each tendon [N] (default 500, an assumption)")
    arm.add_argument("--guide-radius", type=float, default=40.0,
                     help="circumradius of the guide plates [mm] (default 40, an assumption)")
    arm.add_argument("--contact", type=float, default=0.0, metavar="D_HAT",
                     help="keep the panels off each other, within and between modules: the "
                     "barrier's distance d_hat [mm] (default 0: no contact; below 0.595, the "
                     "nearest panels of a contracted module as built)")
    arm.add_argument("--contact-stiffness", type=float, default=485.0,
                     help="the barrier's stiffness kappa [N/mm^3] (default 485: at d_hat / 2 "
                     "= 0.15 mm as stiff as the three-module arm's mean diagonal stiffness)")
    analysis = parser.add_argument_group("analysis (one at most)")
    analysis.add_argument("--tip-load", type=float, nargs=3, metavar=("FX", "FY", "FZ"),
                          help="tip force [N] on the tip guide's centre")
    analysis.add_argument("--reach", type=float, nargs=3, metavar=("X", "Y", "Z"),
                          help="the configuration and the tendon pulls (after the pretension; "
                               "what --pulls takes) that bring the tip guide's centre to this "
                               "point [mm], on the structural model (every configuration of "
                               "--modules, or --config alone); exit 1 when out of reach, with "
                               "the nearest point reached")
    analysis.add_argument("--pull-all", action="store_true",
                          help="shorten all three tendons together until the first module snaps")
    analysis.add_argument("--pull-tendon", type=int, choices=(1, 2, 3),
                          help="shorten one tendon alone until the first module snaps")
    analysis.add_argument("--capacity", action="store_true",
                          help="largest tip load along -z, +x, -x, +y before a module snaps "
                               "or a tendon goes slack")
    analysis.add_argument("--table", action="store_true",
                          help="the load-capacity table of all 2^m configurations (stiffness, "
                               "length, largest tip loads)")
    analysis.add_argument("--protocol", action="store_true",
                          help="the section 4.3 protocol (tendon 1 in by 2k, tendons 2 and 3 "
                               "out by k per contracted module, k = 0..10) on the structure, "
                               "step by step beside the constant-curvature model")
    analysis.add_argument("--table5", action="store_true",
                          help="module lengths under the protocol for all 8 configurations of "
                               "the three-module arm beside Table 5's measured ranges")
    analysis.add_argument("--switching", action="store_true",
                          help="pull all tendons, or one, from every configuration until a "
                               "module snaps: which configurations the pulls reach")
    arm_creases.add_arguments(parser, analysis)
    arm_dynamics.add_arguments(analysis, parser)
    parser.add_argument("--plot", metavar="FILE.png",
                        help="with --table: write the load-capacity figure; with --protocol: "
                             "the markers of both models")
    parser.add_argument("--pretension", type=float,
                        help="tension of each tendon before a tip load, --pulls, the "
                             "capacity and the protocol [N] (default 1, an assumption; the "
                             "built arm's tendons are just taut, and the pull-to-snap "
                             "analyses start from there)")
    parser.add_argument("--pulls", type=float, nargs=3, metavar=("P1", "P2", "P3"),
                        help="shorten the tendons by these amounts [mm, >= 0] (with or without "
                             "--tip-load)")
    parser.add_argument("--max-pull", type=float,
                        help="largest pull for --pull-all/--pull-tendon [mm]")
    parser.add_argument("--closed-loop", action="store_true",
                        help="with --reach: move an arm that differs from the model (crease "
                             "stiffness, cell height and tendon radius drawn by --seed), measure "
                             "its tip with 0.2 mm of camera error and correct the pulls on the "
                             "model's tip Jacobian, five times; print each step's error")
    parser.add_argument("--view", metavar="FILE.html",
                        help="with --reach: write an interactive page of the arm moving from "
                             "its pretensioned state to the pulls found, beside the tip's "
                             "distance from the target")
    parser.add_argument("--seed", type=int, default=0,
                        help="with --closed-loop: the draw of the true arm and the camera, an "
                             "integer index (default 0)")
    parser.add_argument("--prefer", choices=("travel", "stiffness", "switches"),
                        help="with --reach, among the configurations that reach the target: "
                             "the smallest tendon travel (default), the stiffest tip, or "
                             "(with --from) the fewest module switches; with --from, travel "
                             "and stiffness take the fewest switches among the configurations "
                             "within 20 %% of the best")
    parser.add_argument("--from", dest="start", metavar="CONFIG",
                        help="with --reach: the configuration the arm rests in (0 contracted / "
                             "1 extended per module from the base); print the plan: the module "
                             "switches (tendon pulls, or crease actuation where the tendons "
                             "cannot), each checked on the model, then the move")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.set_defaults(func=run_reporting)


def _configuration(args) -> str:
    from kresling.arm import parse_configuration

    if args.modules is not None and args.modules < 1:
        raise ValueError(f"modules = {args.modules} is invalid: must be an integer >= 1")
    if args.config is None:
        return "1" * (3 if args.modules is None else args.modules)
    parse_configuration(args.config, args.modules)  # raises naming the configuration
    return args.config


def run_reporting(args) -> int:
    """:func:`run`, with a solve that does not reach its equilibrium told in one line (exit
    1, as for a run that stopped early): valid input the arm cannot follow is not bad input
    (exit 2)."""
    from kresling.arm import EquilibriumNotReached

    try:
        return run(args)
    except EquilibriumNotReached as error:
        print(f"kresling arm: stopped: {error}", file=sys.stderr)
        return 1


def run(args) -> int:
    from kresling.arm import (CAPACITY_DIRECTIONS, DEFAULT_PRETENSION, ArmSolver, arm_summary,
                              build_arm, load_capacity, pull_until_snap, tip_load)
    from kresling.manipulator import TendonDrive

    # With --reach or --pulls, --gravity weighs that arm instead of tabulating every one.
    weighed = args.gravity is not None and (args.reach is not None or args.pulls is not None)
    chosen = [name for name, on in (("--reach", args.reach is not None),
                                    ("--tip-load", args.tip_load is not None),
                                    ("--pull-all", args.pull_all),
                                    ("--pull-tendon", args.pull_tendon is not None),
                                    ("--capacity", args.capacity),
                                    ("--table", args.table), ("--protocol", args.protocol),
                                    ("--table5", args.table5), ("--switching", args.switching),
                                    ("--crease-switch", args.crease_switch is not None),
                                    ("--gravity", args.gravity is not None and not weighed),
                                    ("--modes", args.modes is not None))
              if on]
    if len(chosen) > 1:
        raise ValueError(f"{' and '.join(chosen)}: give one analysis at a time")
    if args.start is not None and args.reach is None:
        raise ValueError("from: --from CONFIG plans the way to a target from where the arm "
                         "rests; add --reach X Y Z")
    if args.plot and not (args.table or args.protocol):
        raise ValueError("plot: --plot draws the load-capacity table or the protocol; add "
                         "--table or --protocol")
    if args.plot:
        check_output_file("--plot", args.plot)   # before the analysis, not after
    if args.measured_mass and args.gravity is None and args.modes is None:
        raise ValueError("measured-mass: --measured-mass weighs the arm for --gravity or "
                         "--modes; add one of them")
    if args.gravity is not None and not weighed:
        return arm_dynamics.run_gravity(args, _arm_options(args), _pretension(args))
    if args.modes is not None:
        return arm_dynamics.run_modes(args, _arm_options(args), _pretension(args))
    if args.reach is not None:
        return _run_reach(args)
    if args.table:
        return _run_table(args)
    if args.table5:
        return _run_table5(args)
    if args.switching:
        return _run_switching(args)
    if args.protocol:
        return _run_protocol(args)
    configuration = _configuration(args)
    parameters = _parameters(args)
    arm = build_arm(configuration, n=args.n, lam=args.lam, Lc=args.Lc, R=args.R,
                    parameters=parameters)
    if args.crease_switch is not None:
        return arm_creases.run(args, arm)
    solver = ArmSolver(arm)
    out = {"design": {"n": args.n, "lam": args.lam, "Lc": args.Lc, "R": args.R},
           "modules": arm.modules}
    completed, message = True, ""
    if args.pulls is not None and (args.pull_all or args.pull_tendon or args.capacity):
        raise ValueError("pulls: --pulls goes with a tip load or alone, not with the pull or "
                         "capacity analyses")
    if args.tip_load is not None or args.pulls is not None:
        pretension = DEFAULT_PRETENSION if args.pretension is None else args.pretension
        load = [0.0, 0.0, 0.0] if args.tip_load is None else args.tip_load
        r = tip_load(arm, load, pulls=args.pulls, pretension=pretension, solver=solver)
        state = r.state
        if args.gravity is not None:
            if args.tip_load is not None:
                raise ValueError("gravity: --gravity weighs the arm under --pulls or --reach; "
                                 "leave --tip-load out")
            state, weighed_ok, weighed_message = _weigh(args, arm, solver, r.state)
            out.update(gravity=args.gravity, measured_mass=args.measured_mass,
                       tip_position_without_gravity=r.state.tip_position.tolist())
        out.update(arm_summary(arm, state))
        out.update(tip_load=list(load), pretension=pretension,
                   tip_displacement=r.tip_displacement.tolist(),
                   tip_position_unloaded=r.unloaded.tip_position.tolist(),
                   tip_compliance=r.compliance.tolist(), load_factor=r.load_factor,
                   lost_between=list(r.lost_between) if r.lost_between else None,
                   snapped_module=r.snapped_module if r.lost_between else None)
        completed, message = r.completed, r.message
        if args.gravity is not None and completed and not weighed_ok:
            completed, message = False, f"the arm does not carry its weight: {weighed_message}"
    elif args.pull_all or args.pull_tendon:
        if args.pretension is not None:
            raise ValueError("pretension: pulling starts from the built arm (its tendons just "
                             "taut); leave --pretension out")
        direction = (1.0, 1.0, 1.0) if args.pull_all else \
            tuple(float(t == args.pull_tendon) for t in (1, 2, 3))
        r = pull_until_snap(arm, direction, max_pull=args.max_pull, solver=solver)
        last = r.states[-1]
        out.update(arm_summary(arm, last))
        counts = TendonDrive()
        out.update(snapped=r.snapped, snap_tendon_force=r.tension_sum if r.snapped else None,
                   snapped_module=r.snapped_module if r.snapped else None,
                   snap_pull=r.pull if r.snapped else None,
                   snap_tension=r.tension.tolist() if r.snapped else None,
                   snap_motor_counts=(counts.sign * counts.counts_per_mm * r.pulls).tolist()
                   if r.snapped else None,
                   configuration_after=r.configuration_after,
                   tip_position_after=r.after.tip_position.tolist() if r.after else None)
        completed, message = r.snapped, r.message
    elif args.capacity:
        pretension = DEFAULT_PRETENSION if args.pretension is None else args.pretension
        start = solver.pretension(pretension)
        out.update(arm_summary(arm, start))
        out.update(pretension=pretension, tip_compliance=solver.tip_compliance(start).tolist())
        rows = {}
        for name, direction in CAPACITY_DIRECTIONS.items():
            c = load_capacity(arm, direction, pretension=pretension, solver=solver,
                              pretensioned=start)
            rows[name] = {"load": c.load, "limit": c.limit,
                          "tendon": c.tendon + 1 if c.tendon >= 0 else None,
                          "module": c.module if c.module >= 0 else None,
                          "tip_displacement": c.tip_displacement.tolist()}
        out["capacity"] = rows
    else:
        state = solver.built() if args.pretension is None else solver.pretension(args.pretension)
        out.update(arm_summary(arm, state))
        out["pretension"] = args.pretension or 0.0
    out["completed"] = bool(completed)
    if message:
        out["message"] = message
    if args.json:
        print_json(out)
    else:
        _print_text(out)
    if not completed:
        print(f"kresling arm: warning: {message}", file=sys.stderr)
        return 1
    return 0


def _weigh(args, arm, solver, state):
    """``state`` of ``arm`` with the arm's own weight added, tendon lengths held:
    ``(state, completed, message)``."""
    from kresling.arm.gravity import gravity_sag
    from kresling.arm.masses import arm_masses

    sag = gravity_sag(arm, args.gravity, start=state, solver=solver,
                      masses=arm_masses(arm, measured_skeleton=args.measured_mass))
    return solver.state_at(sag.displacement, state.pulls), sag.completed, sag.message


def _run_table(args) -> int:
    from kresling.arm import DEFAULT_PRETENSION
    from kresling.arm.capacity import capacity_rows, load_capacity_table

    if args.config is not None:
        raise ValueError("config: --table runs every configuration; give --modules instead")
    modules = 3 if args.modules is None else args.modules
    if modules < 1:
        raise ValueError(f"modules = {modules} is invalid: must be an integer >= 1")
    pretension = DEFAULT_PRETENSION if args.pretension is None else args.pretension
    parameters = _parameters(args)
    table = load_capacity_table(modules, pretension=pretension, n=args.n, lam=args.lam,
                                Lc=args.Lc, R=args.R, parameters=parameters)
    rows = capacity_rows(table)
    if args.json:
        print_json({"modules": modules, "pretension": pretension, "rows": rows,
                    "completed": True})
    else:
        directions = list(table[0].capacity)
        print_table([(r["configuration"], f"{r['tip_height_mm']:.1f}",
                      f"{r['sideways_stiffness_N_per_mm']:.4g}", f"{r['C_zz_mm_per_N']:.3g}",
                      *(f"{r[f'load_{d}_N']:.3g} ({r[f'limit_{d}']})" for d in directions))
                     for r in rows],
                    ("config", "length [mm]", "1/C_xx [N/mm]", "C_zz [mm/N]",
                     *(f"load {d} [N]" for d in directions)))
        print(f"\ntendons pretensioned to {pretension} N each; limits: a taut tendon goes "
              "slack, or a module snaps")
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")  # files only: never open a window
        from kresling.arm.plots import plot_load_capacity

        plot_load_capacity(table).savefig(args.plot, dpi=150)
        print(f"wrote {args.plot} (load-capacity figure)",
              file=sys.stderr if args.json else sys.stdout)
    return 0


def _run_reach(args) -> int:
    from kresling.arm.reach import reach

    if args.prefer == "switches" and args.start is None:
        raise ValueError("prefer: --prefer switches counts the switches from where the arm "
                         "rests; add --from CONFIG")
    if args.gravity is not None and (args.closed_loop or args.view):
        raise ValueError("gravity: --closed-loop and --view run the arm without its weight; "
                         "leave --gravity out")
    if args.start is not None:
        return _run_plan(args)
    prefer = args.prefer or "travel"
    if args.pulls is not None:
        raise ValueError("pulls: --reach finds the pulls; leave --pulls out")
    if args.view:
        if args.closed_loop:
            raise ValueError("view: --view draws the planned reach; leave --closed-loop out")
        from kresling.view import check_writable

        check_writable(args.view)   # before the planning, not after
    configurations = None if args.config is None else [_configuration(args)]
    modules = 3 if args.modules is None else args.modules
    if args.closed_loop:
        return _run_closed_loop(args, configurations)
    r = reach(args.reach, configurations=configurations, prefer=prefer,
              pretension=_pretension(args), modules=modules, gravity=args.gravity,
              measured_mass=args.measured_mass, **_arm_options(args))
    out = _reach_summary(args, r, prefer)
    if args.view:
        _write_reach_view(args, r)
        print(f"wrote {args.view} (interactive page)", file=sys.stderr if args.json
              else sys.stdout)
    if args.json:
        print_json(out)
    else:
        print_table([("configuration", r.configuration, ""),
                     *((f"pull {t + 1}", p, "mm") for t, p in enumerate(r.tendon_displacements)),
                     *((f"tip {a}", v, "mm") for a, v in zip("xyz", r.tip_position)),
                     ("error", r.error, "mm")], ("quantity", "value", "unit"))
        _print_reach(args, r)
    return 0 if r.reached else 1


def _reach_summary(args, r, prefer) -> dict:
    """The JSON fields of a reach (their meaning is the same with and without a plan)."""
    return {"target": r.target.tolist(), "configuration": r.configuration,
            "tendon_displacements": r.tendon_displacements.tolist(),
            "tip_position": r.tip_position.tolist(), "error": r.error, "reached": r.reached,
            "prefer": prefer, "pretension": _pretension(args), "gravity": args.gravity,
            "candidates": {c: (dict(zip(("error", "travel", "compliance"), v))
                               if isinstance(v, tuple) else {"failed": v})
                           for c, v in r.candidates.items()},
            "message": r.message}


def _print_reach(args, r) -> None:
    print_table([("configuration", r.configuration, ""),
                 *((f"pull {t + 1}", p, "mm") for t, p in enumerate(r.tendon_displacements)),
                 *((f"tip {a}", v, "mm") for a, v in zip("xyz", r.tip_position)),
                 ("error", r.error, "mm")], ("quantity", "value", "unit"))
    weight = "" if args.gravity is None else f" --gravity {args.gravity}" + \
        (" --measured-mass" if args.measured_mass else "")
    print(f"\n{'reached' if r.reached else r.message}; check: kresling arm --config "
          f"{r.configuration} --pulls " + " ".join(f"{p:.9g}" for p in r.tendon_displacements)
          + weight)


def _run_plan(args) -> int:
    """--reach with --from: the switches from the arm's configuration, then the move."""
    from kresling.arm.plan import plan_reach

    if args.closed_loop:
        raise ValueError("from: --from plans the switches and the move; leave --closed-loop "
                         "out")
    if args.view:
        from kresling.view import check_writable

        check_writable(args.view)   # before the planning, not after
    if args.pulls is not None:
        raise ValueError("pulls: --reach finds the pulls; leave --pulls out")
    start = args.start
    if not (isinstance(start, str) and start and set(start) <= {"0", "1"}):
        raise ValueError(f"from = {start!r} is invalid: must be the configuration the arm "
                         "rests in, one 0 (contracted) or 1 (extended) per module from the "
                         "base, e.g. 000")
    if args.modules is not None and args.modules != len(start):
        raise ValueError(f"from = {start!r} is invalid: has {len(start)} modules, --modules "
                         f"{args.modules}")
    configurations = None
    if args.config is not None:
        if len(args.config) != len(start):
            raise ValueError(f"config = {args.config!r} is invalid: --from {start} has "
                             f"{len(start)} modules")
        configurations = [_configuration(args)]
    prefer = args.prefer or "switches"
    plan = plan_reach(args.reach, start, prefer=prefer, configurations=configurations,
                      pretension=_pretension(args), gravity=args.gravity,
                      measured_mass=args.measured_mass, **_arm_options(args))
    r = plan.reach
    out = _reach_summary(args, r, prefer)
    out.update(start_configuration=start, switches=plan.switches,
               plan=[_step_summary(s) for s in plan.steps],
               passed_over=plan.passed_over)
    if args.view:
        _write_reach_view(args, r, plan)
        print(f"wrote {args.view} (interactive page)", file=sys.stderr if args.json
              else sys.stdout)
    if args.json:
        print_json(out)
        return 0 if r.reached else 1
    rows = []
    for k, s in enumerate(out["plan"], 1):
        if s["kind"] == "switch":
            how = (f"pull all tendons {len(s['tendon_pulls'])}x, to "
                   + ", ".join(f"{max(p):.3g}" for p in s["tendon_pulls"]) + " mm"
                   if s["means"] == "tendon" else
                   f"{s['crease_group']} creases by {s['crease_change_deg']:.4g} deg")
            rows.append((k, f"switch module {s['module']} to {s['to']}", s["means"], how,
                         s["configuration_after"]))
        else:
            rows.append((k, "move", "tendon",
                         "pulls " + _fmt(s["tendon_displacements"]) + " mm",
                         s["configuration"]))
    print(f"from {start}, {plan.switches} switch{'es' if plan.switches != 1 else ''}:")
    print_table(rows, ("step", "what", "means", "actuation", "configuration after"))
    print()
    _print_reach(args, r)
    return 0 if r.reached else 1


def _step_summary(step) -> dict:
    """One plan step as JSON."""
    from kresling.arm.plan import SwitchStep

    if not isinstance(step, SwitchStep):
        return {"kind": "move", "configuration": step.configuration,
                "tendon_displacements": step.tendon_displacements.tolist(),
                "tip_position": step.tip_position.tolist()}
    out = {"kind": "switch", "module": step.module, "to": step.to, "means": step.means,
           "configuration_before": step.configuration_before,
           "configuration_after": step.configuration_after,
           "module_length": step.module_length.tolist(),
           "tip_position": step.tip_position.tolist(), "attempts": list(step.attempts)}
    a = step.actuation
    if step.means == "tendon":
        out.update(tendon_pulls=a["pulls"], tension_sums=a["tension_sums"])
    else:
        out.update(crease_group=a["group"], creases=a["creases"],
                   crease_change_deg=a["change_deg"], crease_moment=a["moment"],
                   crease_work=a["work"])
    return out


def _write_reach_view(args, result, plan=None) -> None:
    """The arm pulled from its pretensioned state to ``result``'s pulls in 20 increments,
    beside the tip's distance from the target; with a ``plan``, first where the arm rests
    in its start configuration and after each switch."""
    from types import SimpleNamespace

    import numpy as np

    from kresling.arm import ArmSolver, build_arm
    from kresling.view import view_path, write_html

    arm = build_arm(result.configuration, **_arm_options(args))
    solver = ArmSolver(arm, steps=20, max_bisections=0)
    base = solver.pretension(_pretension(args))
    states, _, _ = solver.ramp(base, base.pulls + result.tendon_displacements)
    # Every configuration's arm has the same nodes: a state of another is drawn on this
    # one's by its positions.
    rests = []
    if plan is not None:
        start = build_arm(plan.start_configuration, **_arm_options(args))
        rests = [start.model.nodes.ravel()]
        rests += [step.positions.ravel() for step in plan.steps[:-1]]
    moving = [base, *states]
    displacement = [x - arm.model.nodes.ravel() for x in rests] + \
        [s.displacement for s in moving]
    tips = [x.reshape(-1, 3)[arm.tip_node] for x in rests] + [s.tip_position for s in moving]
    fraction = np.concatenate([np.arange(-len(rests), 0.0),
                               np.linspace(0.0, 1.0, len(moving))])
    miss = [float(np.linalg.norm(t - result.target)) for t in tips]
    path = SimpleNamespace(displacement=np.array(displacement), load_factor=fraction,
                           completed=True, message="")
    steps = "" if plan is None else \
        f"from {plan.start_configuration} by {plan.switches} switches, then "
    page = view_path(arm, path, curve=(fraction, miss, "switches (< 0), then fraction of "
                                       "the pulls" if rests else "fraction of the pulls",
                                       "tip's distance from the target [mm]"),
                     title=f"{steps}configuration {result.configuration} reaching "
                           f"{np.round(result.target, 2).tolist()} mm "
                           f"(pulls {np.round(result.tendon_displacements, 3).tolist()} mm)")
    write_html(page, args.view)


def _run_closed_loop(args, configurations) -> int:
    from kresling.arm.closed_loop import closed_loop

    if args.modules not in (None, 3) or args.tendon_radius != 32.0 or args.contact > 0:
        raise ValueError("closed-loop: the closed loop runs on the thesis's three-module arm; "
                         "leave --modules, --tendon-radius and --contact at their defaults")
    r = closed_loop(args.reach, seed=args.seed, configurations=configurations,
                    pretension=_pretension(args))
    out = {"target": r.target.tolist(), "configuration": r.configuration, "seed": args.seed,
           "arm_length": r.arm_length,
           "open_loop_kinematic": None if r.open_loop_kinematic != r.open_loop_kinematic
           else r.open_loop_kinematic,
           "open_loop_structural": r.open_loop_structural,
           "closed_loop": r.closed_loop.tolist(), "tendon_displacements": r.pulls.tolist()}
    if args.json:
        print_json(out)
    else:
        rows = [("open loop, constant curvature", r.open_loop_kinematic),
                ("open loop, structural model", r.open_loop_structural),
                *((f"closed loop, correction {k + 1}", e) for k, e in enumerate(r.closed_loop))]
        print_table([(name, e, 100 * e / r.arm_length) for name, e in rows],
                    ("tip error", "mm", "% of the arm's length"))
    return 0


def _pretension(args) -> float:
    from kresling.arm import DEFAULT_PRETENSION

    return DEFAULT_PRETENSION if args.pretension is None else args.pretension


def _arm_options(args) -> dict:
    return {"n": args.n, "lam": args.lam, "Lc": args.Lc, "R": args.R,
            "parameters": _parameters(args)}


def _parameters(args):
    """The arm's parameters from the command line (tendons, guides, panel contact)."""
    from kresling.arm import ArmParameters

    return ArmParameters(tendon_radius=args.tendon_radius, guide_radius=args.guide_radius,
                         tendon_stiffness=args.tendon_stiffness, contact_distance=args.contact,
                         contact_stiffness=args.contact_stiffness if args.contact > 0 else 0.0)


def _run_protocol(args) -> int:
    import math

    from kresling.arm import build_arm
    from kresling.arm.actuation import pseudo_linkage_run

    configuration = _configuration(args)
    arm = build_arm(configuration, **_arm_options(args))
    run = pseudo_linkage_run(arm, pretension=_pretension(args))
    steps = []
    for k in range(len(run.changes)):
        done = k < len(run.states)
        steps.append({
            "k": k, "tendon_change": run.changes[k].tolist(),
            "motor_counts": run.motor_counts[k].tolist(),
            "tip_position": run.markers[k, -1].tolist() if done else None,
            "kinematic_tip_position": run.kinematic_markers[k, -1].tolist(),
            "tip_error": float(run.tip_error[k]) if done else None,
            "marker_error": run.marker_error[k].tolist() if done else None,
            "bend_angles": run.bend_angles[k].tolist() if done else None,
            "kinematic_bend_angles": run.kinematic_bend_angles[k].tolist(),
            "bend_direction": _finite(run.bend_direction[k]),
            "kinematic_bend_direction": _finite(run.kinematic_bend_direction[k]),
            "tension": run.tension[k].tolist() if done else None,
            "module_length": run.module_lengths[k].tolist() if done else None})
    out = {"configuration": configuration, "pretension": _pretension(args), "steps": steps,
           "completed": run.completed}
    if run.message:
        out["message"] = run.message
    if args.json:
        print_json(out)
    else:
        print_table([(s["k"], _fmt(s["tendon_change"]), _fmt(s["tip_position"] or [math.nan] * 3),
                      _fmt(s["kinematic_tip_position"]), s["tip_error"],
                      _fmt([math.degrees(a) for a in s["bend_angles"] or [math.nan]]),
                      _fmt([math.degrees(a) for a in s["kinematic_bend_angles"]]))
                     for s in steps],
                    ("k", "tendon change [mm]", "tip, structure [mm]", "tip, kinematic [mm]",
                     "tip error [mm]", "bends [deg]", "kinematic bends [deg]"))
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")  # files only: never open a window
        from kresling.arm.plots import plot_actuation

        plot_actuation(run).savefig(args.plot, dpi=150)
        print(f"wrote {args.plot} (markers of both models)",
              file=sys.stderr if args.json else sys.stdout)
    if not run.completed:
        print(f"kresling arm: warning: {run.message}", file=sys.stderr)
        return 1
    return 0


def _run_table5(args) -> int:
    from kresling.arm.actuation import table5_comparison

    if args.config is not None or args.modules not in (None, 3):
        raise ValueError("config: --table5 runs Table 5's eight configurations of three modules")
    rows = table5_comparison(pretension=_pretension(args), **_arm_options(args))
    if args.json:
        print_json({"pretension": _pretension(args), "rows": rows,
                    "completed": all(r["completed"] for r in rows)})
    else:
        print_table([(r["config"], r["joint"], r["state"], f"[{r['min_mm']}, {r['max_mm']}]",
                      f"{r['kinematic_min_mm']:.2f}",
                      f"[{r['predicted_min_mm']:.2f}, {r['predicted_max_mm']:.2f}]",
                      f"{r['outside_by_mm']:.2f}") for r in rows],
                    ("config", "module", "state", "Table 5 [mm]", "kinematic [mm]",
                     "structure [mm]", "outside by [mm]"))
    return 0


def _run_switching(args) -> int:
    from kresling.arm.switching import switching_map

    if args.config is not None:
        raise ValueError("config: --switching runs every configuration; give --modules instead")
    modules = 3 if args.modules is None else args.modules
    switches = switching_map(modules, **_arm_options(args))
    rows = [{"start": s.start, "pull": s.pull, "snapped": s.snapped,
             "snapped_module": s.snapped_module if s.snapped else None, "end": s.end,
             "pull_mm": _finite(s.pull_mm), "tension_sum": _finite(s.tension_sum),
             "motor_counts": s.motor_counts.tolist() if s.snapped else None} for s in switches]
    if args.json:
        print_json({"modules": modules, "rows": rows, "completed": True})
    else:
        print_table([(r["start"], r["pull"], r["end"], r["snapped_module"], r["pull_mm"],
                      r["tension_sum"]) for r in rows],
                    ("from", "pull", "to", "snapped module", "pull [mm]", "tension sum [N]"))
    return 0


def _finite(value):
    import math

    return float(value) if math.isfinite(value) else None


def _print_text(out: dict) -> None:
    rows = [("configuration", out["configuration"], "", "module states from the base"),
            ("tip_position", _fmt(out["tip_position"]), "mm", "tip guide's centre"),
            ("tip_height_built", out["tip_height_built"], "mm", "sum of the modules' heights"),
            ("tension", _fmt(out["tension"]), "N", "tendons 1, 2, 3"),
            ("module_length", _fmt(out["module_length"]), "mm", "guide centre to guide centre")]
    for key, unit, meaning in (("gravity", "", "the arm carries its own weight, tendon lengths "
                                "held"),
                               ("tip_position_without_gravity", "mm", "the tip before"),
                               ("tip_displacement", "mm", "caused by the tip load"),
                               ("snap_tendon_force", "N", "sum of the tensions at the snap"),
                               ("snapped_module", "", "0-based from the base"),
                               ("snap_pull", "mm", "tendon pull at the snap"),
                               ("configuration_after", "", "where the released arm rests")):
        if out.get(key) is not None:
            value = out[key]
            rows.append((key, _fmt(value) if isinstance(value, list) else value, unit, meaning))
    print_table(rows, ("quantity", "value", "unit", "meaning"))
    if "capacity" in out:
        print()
        print_table([(d, r["load"], r["limit"], r["tendon"] or "", _fmt(r["tip_displacement"]))
                     for d, r in out["capacity"].items()],
                    ("direction", "load [N]", "limit", "slack tendon", "tip displacement [mm]"))
    if "tip_compliance" in out:
        print("\ntip compliance [mm/N]:")
        for row in out["tip_compliance"]:
            print("  " + "  ".join(f"{v:12.6g}" for v in row))


def _fmt(values) -> str:
    return "(" + ", ".join(f"{v:.6g}" for v in values) + ")"
