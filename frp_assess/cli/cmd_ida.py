"""`frp-assess ida`: incremental dynamic analysis of one wall under a set of records."""

from __future__ import annotations

import argparse
import json
import math

from frp_assess.app.expert import G, IdaSettings, read_record, run_ida
from frp_assess.cli.output import Column, make_console, print_table, user
from frp_assess.cli.wall_args import (
    add_model_arguments,
    add_option_argument,
    add_record_arguments,
    build_model,
)
from frp_assess.dynamics.options import IDA_OPTIONS
from frp_assess.errors import InputError


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "ida",
        help="incremental dynamic analysis under a set of records",
        description="Collapse multiplier C, a_dyn = C·PGA and q = a_dyn/a_RM of "
        "one wall for every record, and their mean, least favourable and design values over "
        "the records, as `run` takes them: a record that does not collapse up to C_max counts "
        "at C_max·PGA (a lower bound); units m, kN/m³, GPa, ‰, g.",
    )
    add_model_arguments(p)
    add_record_arguments(p, many=True)
    ida = p.add_argument_group("IDA search")
    for option in IDA_OPTIONS.values():
        add_option_argument(ida, option)
    p.add_argument("--jobs", type=int, default=None, help="worker threads (default: all cores)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    model = build_model(args)
    try:
        settings = IdaSettings(**{key: getattr(args, key) for key in IDA_OPTIONS})
    except ValueError as exc:
        raise InputError(str(exc)) from None
    if args.jobs is not None and args.jobs < 1:
        raise InputError(f"expected at least 1 job, found {args.jobs}", key="--jobs")
    records = [read_record(path, format=args.format, units=args.units) for path in args.record]
    outcome = run_ida(model, records, settings, jobs=args.jobs)
    results = outcome.results
    rows = []
    for rec, res in zip(records, results, strict=True):
        rows.append(
            {
                "record": rec.name,
                "pga": rec.pga_g,
                "collapse_multiplier": res.collapse_multiplier,
                "a_dyn": None if res.a_dyn is None else res.a_dyn / G,
                "q": res.q,
                # how the wall failed at the first collapse; null without collapse
                "failure_mode": res.failure_mode,
                # the first collapse on the sampling: the paper's convention (docs/model.md §5)
                "first_collapse_multiplier": res.first_collapse,
                # collapse windows below the capacity (docs/model.md §11)
                "windows_below": res.windows_below,
            }
        )
    # one definition with `run`: a record that does not collapse up to C_max counts at
    # C_max·PGA, a lower bound (frp_assess.assess.runner.summarise, through app.expert.run_ida)
    summary = outcome.summary
    n_bound = sum(r["a_dyn"] is None for r in rows)
    out = {
        "alpha": model.wall.alpha,
        "a_rm": model.wall.a_rm_g,
        "records": rows,
        "mean_a_dyn": summary.mean_a_dyn,
        "min_a_dyn": summary.min_a_dyn,
        "mean_q": summary.mean_q,
        "design_a_dyn": summary.design_a_dyn,
        "design_value": outcome.design_value,
        "lower_bound": summary.lower_bound,
        "records_without_collapse": n_bound,
    }
    if args.json:
        print(json.dumps(out))
        return 0
    console = make_console()
    w = model.wall
    console.print(
        f"wall B = {w.thickness:g} m, H = {w.height:g} m, α = {math.degrees(w.alpha):.3f}°, "
        f"a_RM = {w.a_rm_g:.4f} g, {args.mechanism}"
        + (
            ""
            if model.rebars is None
            else f"; rebars {user(model.rebars.position)} ρ = {model.rebars.ratio:g} ‰, "
            f"K = {model.K:.3g}, θ_max = {model.theta_max:.4g} rad"
        )
    )
    cells: list[list[str]] = []
    for r in rows:
        if r["collapse_multiplier"] is None:
            cells.append([str(r["record"]), f"{r['pga']:.4f}", "no collapse ≤ C_max", "—", "—"])
        else:
            cells.append(
                [
                    str(r["record"]),
                    f"{r['pga']:.4f}",
                    f"{r['collapse_multiplier']:.4f}",
                    f"{r['a_dyn']:.4f}",
                    f"{r['q']:.3f}",
                ]
            )
    columns = [
        Column("record", text=True),
        Column("PGA [g]"),
        Column("collapse multiplier C [–]"),
        Column("a_dyn [g]"),
        Column("q [–]"),
    ]
    rule = (
        "effective collapse intensity"
        if settings.capacity == "effective"
        else "first collapse, the paper's convention"
    )
    print_table(console, f"Incremental dynamic analysis: {rule}", columns, cells)
    ge = "≥ " if summary.lower_bound else ""
    console.print(
        f"over the {len(rows)} records: mean a_dyn = {ge}{summary.mean_a_dyn:.4f} g, mean q = "
        f"{ge}{summary.mean_q:.3f}, least favourable a_dyn = {ge}{summary.min_a_dyn:.4f} g; "
        f"design a_dyn ({outcome.design_value}) = {ge}{summary.design_a_dyn:.4f} g"
    )
    if n_bound:
        console.print(
            f"{n_bound} of {len(rows)} records did not collapse up to C_max: they count at "
            "C_max·PGA, so the values above are lower bounds (≥)"
        )
    return 0
