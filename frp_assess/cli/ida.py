"""`frp-assess ida`: incremental dynamic analysis of one wall under a set of records."""

from __future__ import annotations

import argparse
import json
import math
import sys

from frp_assess.cli.output import Column, make_console, print_table, user
from frp_assess.cli.wall_args import add_model_arguments, add_record_arguments, build_model
from frp_assess.dynamics import IdaSettings, IdaTask, run_batch
from frp_assess.errors import InputError
from frp_assess.motions.readers import read_record
from frp_assess.motions.record import G


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "ida",
        help="incremental dynamic analysis under a set of records",
        description="Collapse multiplier C, a_dyn = C·PGA and q = a_dyn/a_RM of "
        "one wall for every record (MODEL.md §5); units m, kN/m³, GPa, ‰, g.",
    )
    add_model_arguments(p)
    add_record_arguments(p, many=True)
    ida = p.add_argument_group("IDA search")
    ida.add_argument("--step-ratio", type=float, default=1.10, help="hunt ratio s (default 1.10)")
    ida.add_argument("--tolerance", type=float, default=0.005, help="bisection tolerance (0.005)")
    ida.add_argument(
        "--max-multiplier",
        type=float,
        default=100.0,
        help="give up beyond C_max = this × C₀ (default 100)",
    )
    p.add_argument("--jobs", type=int, default=None, help="worker threads (default: all cores)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    model = build_model(args)
    try:
        settings = IdaSettings(args.step_ratio, args.tolerance, args.max_multiplier)
    except ValueError as exc:
        raise InputError(str(exc)) from None
    if args.jobs is not None and args.jobs < 1:
        raise InputError(f"expected at least 1 job, found {args.jobs}", key="--jobs")
    records = [read_record(path, format=args.format, units=args.units) for path in args.record]
    tasks = [IdaTask(model, r.acc, r.dt, settings) for r in records]
    results = run_batch(tasks, jobs=args.jobs)
    rows = []
    for rec, res in zip(records, results, strict=True):
        rows.append(
            {
                "record": rec.name,
                "pga": rec.pga_g,
                "collapse_multiplier": res.collapse_multiplier,
                "a_dyn": None if res.a_dyn is None else res.a_dyn / G,
                "q": res.q,
            }
        )
    collapsed = [r for r in rows if r["a_dyn"] is not None]
    mean_a = sum(r["a_dyn"] for r in collapsed) / len(collapsed) if collapsed else None
    mean_q = sum(r["q"] for r in collapsed) / len(collapsed) if collapsed else None
    out = {
        "alpha": model.wall.alpha,
        "a_rm": model.wall.a_rm_g,
        "records": rows,
        "mean_a_dyn": mean_a,
        "mean_q": mean_q,
        "records_without_collapse": len(rows) - len(collapsed),
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
    cells = []
    for r in rows:
        if r["collapse_multiplier"] is None:
            cells.append([r["record"], f"{r['pga']:.4f}", "no collapse ≤ C_max", "—", "—"])
        else:
            cells.append(
                [
                    r["record"],
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
    print_table(console, "Incremental dynamic analysis", columns, cells)
    if mean_a is not None:
        console.print(
            f"mean a_dyn = {mean_a:.4f} g, mean q = {mean_q:.3f}"
            + (
                f" (over {len(collapsed)} of {len(rows)} records)"
                if len(collapsed) < len(rows)
                else ""
            )
        )
    else:
        print("no record made the wall collapse up to C_max", file=sys.stderr)
    return 0
