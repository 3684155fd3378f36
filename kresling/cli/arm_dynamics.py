"""``kresling arm --gravity`` and ``kresling arm --modes``: the arm's weight and its
natural frequencies in every configuration (masses from the thesis's materials)."""

from __future__ import annotations

from kresling.cli._output import cli_names, print_json, print_table


def add_arguments(analysis, parser) -> None:
    """The options of the two analyses (``analysis``: the group of one-at-a-time analyses)."""
    from kresling.arm.gravity import ORIENTATIONS

    analysis.add_argument("--gravity", nargs="?", const="hanging", choices=tuple(ORIENTATIONS),
                          help="the sag of every configuration's markers under the arm's own "
                               "weight, at rest and at step 10 of the section 4.3 protocol, "
                               "tendon lengths held; the orientation (default hanging: the "
                               "thesis's arm hangs from its base and bends in a vertical "
                               "plane; standing; horizontal, tendon 1 on top); with --pulls or "
                               "--reach, that arm carries its own weight instead (its tendon "
                               "lengths held)")
    analysis.add_argument("--modes", type=int, nargs="?", const=6, metavar="K",
                          help="the K lowest natural frequencies (a count, default 6) of "
                               "every configuration, pretensioned")
    parser.add_argument("--measured-mass", action="store_true",
                        help="with --gravity or --modes: scale the cells and guides to the "
                             "thesis's weighed 56.3 g skeleton (per three modules) instead of "
                             "the materials' 44.4 g")


def _modules(args) -> int:
    modules = 3 if args.modules is None else args.modules
    if modules < 1:
        raise ValueError(f"modules = {modules} is invalid: must be an integer >= 1")
    return modules


def _configurations(args):
    from kresling.arm import all_configurations, parse_configuration

    if args.config is not None:
        parse_configuration(args.config, args.modules)   # raises naming the configuration
        return [args.config]
    return all_configurations(_modules(args))


def run_gravity(args, arm_options: dict, pretension: float) -> int:
    from kresling.arm.gravity import gravity_table
    from kresling.manipulator.joint_lengths import read_table5

    rows = gravity_table(orientation=args.gravity, configurations=_configurations(args),
                         measured_skeleton=args.measured_mass, pretension=pretension,
                         **arm_options)
    # Table 5's ranges (a module measured once, min = max, has none).
    ranges = [r["max_mm"] - r["min_mm"] for r in read_table5() if r["max_mm"] > r["min_mm"]]
    worst = max(rows, key=lambda r: r["largest_sag_mm"])
    out = {"orientation": args.gravity, "measured_mass": args.measured_mass,
           "pretension": pretension, "rows": rows,
           "largest_sag_mm": worst["largest_sag_mm"],
           "largest_sag_at": {"config": worst["config"], "k": worst["k"]},
           "table5_range_mm": [min(ranges), max(ranges)],
           "completed": all(r["completed"] for r in rows)}
    if args.json:
        print_json(out)
        return 0 if out["completed"] else 1
    print_table([(r["config"], r["k"], f"{r['mass_g']:.2f}",
                  " ".join(f"{v:.3f}" for v in r["sag_mm"][1:]),
                  " ".join(f"{v:+.3f}" for v in r["module_length_change_mm"]),
                  " ".join(f"{v:.3f}" for v in r["tension_N"])) for r in rows],
                ("config", "k", "mass [g]", "marker sag, base to tip [mm]",
                 "module length change [mm]", "tensions [N]"))
    print(f"\narm {args.gravity}, tendon lengths held, tendons pretensioned to {pretension} N; "
          f"largest marker sag {worst['largest_sag_mm']:.3g} mm ({worst['config']}, step "
          f"{worst['k']}). Table 5's measured module-length ranges span "
          f"{min(ranges):.1f}-{max(ranges):.1f} mm.")
    return 0 if out["completed"] else 1


def run_modes(args, arm_options: dict, pretension: float) -> int:
    from kresling.arm.frequencies import arm_frequencies

    rows = []
    for config in _configurations(args):
        with cli_names({"k": "--modes"}):
            f = arm_frequencies(config, k=args.modes, pretension=pretension,
                                measured_skeleton=args.measured_mass, **arm_options)
        rows.append({"config": config, "mass_g": f.mass * 1e6,
                     "frequencies_hz": f.modes.frequencies_hz.tolist(),
                     "effective_mass_x": f.modes.effective_mass_fraction[:, 0].tolist()})
    lowest = min(r["frequencies_hz"][0] for r in rows)
    for r in rows:
        r["ratio_to_softest"] = r["frequencies_hz"][0] / lowest
    if args.json:
        print_json({"pretension": pretension, "measured_mass": args.measured_mass,
                    "rows": rows, "completed": True})
        return 0
    print_table([(r["config"], f"{r['mass_g']:.2f}",
                  " ".join(f"{v:.4g}" for v in r["frequencies_hz"]),
                  f"{r['ratio_to_softest']:.3g}") for r in rows],
                ("config", "mass [g]", "frequencies [Hz]", "f1 / softest f1"))
    print(f"\nabout the arm pretensioned to {pretension} N per tendon, base fixed")
    return 0
