"""`frp-assess simulate`: one time history of one wall under one scaled record."""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np

from frp_assess.app.expert import G, read_record, simulate
from frp_assess.cli.arg_types import number_in
from frp_assess.cli.output import plain_line
from frp_assess.cli.wall_args import add_model_arguments, add_record_arguments, build_model
from frp_assess.errors import InputError
from frp_assess.io_utils import atomic_write_text
from frp_assess.output_set import check_out_file


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "simulate",
        help="time history of a wall under one record",
        description="Integrate the rocking wall (paper Eq. 10) under one record "
        "scaled by C; units m, kN/m³, GPa, ‰, g.",
    )
    add_model_arguments(p)
    add_record_arguments(p, many=False)
    p.add_argument(
        "--scale",
        type=number_in(0, 1e6, low_open=True),
        default=1.0,
        metavar="C",
        help="record multiplier C",
    )
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.add_argument("--out", metavar="CSV", help="write θ(t), θ'(t), strain(t) to this CSV file")
    p.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    model = build_model(args)
    if not (math.isfinite(args.scale) and args.scale > 0):
        raise InputError(f"expected a multiplier > 0, found {args.scale:g}", key="--scale")
    if args.out:
        check_out_file(Path(args.out))
    record = read_record(args.record, format=args.format, units=args.units)
    res = simulate(model, record, args.scale, history=args.out is not None)
    out = {
        "collapsed": res.collapsed,
        "fate": res.fate,
        # how the wall failed (docs/model.md §1.1); null when it did not collapse
        "failure_mode": res.failure_mode,
        "decided_time": res.decided_time,
        "collapse_time": res.collapse_time,
        "max_rotation": res.max_rotation,
        "max_rotation_ratio": res.max_rotation_ratio,
        "peak_strain": res.peak_strain,
        "rupture_strain": res.rupture_strain,
        "impacts": res.impacts,
        "ruptures": [{"time": r.time, "side": r.side} for r in res.ruptures],
        "collapse_rule": model.options.collapse,
        "tolerance": model.options.tolerance,
    }
    if args.out:
        h = res.history
        assert h is not None
        acc = np.zeros_like(h.time)
        acc[: record.npts] = record.acc[: h.time.size] * args.scale / G
        rows = ["time_s,theta_rad,theta_over_alpha,omega_rad_s,bar_strain,ground_acc_g"]
        alpha = model.wall.alpha
        for t, th, om, st, ag in zip(h.time, h.theta, h.omega, h.strain, acc, strict=True):
            if math.isnan(th):
                break
            rows.append(f"{t:.6f},{th:.9e},{th / alpha:.9e},{om:.9e},{st:.9e},{ag:.9e}")
        atomic_write_text(args.out, "\n".join(rows) + "\n")
    if args.json:
        print(json.dumps(out))
    else:
        w = model.wall
        print(
            f"wall B = {w.thickness:g} m, H = {w.height:g} m, α = {math.degrees(w.alpha):.3f}°, "
            f"a_RM = {w.a_rm_g:.4f} g; record {plain_line(record.name)} (PGA {record.pga_g:.4f} g)"
            f" × {args.scale:g}"
        )
        verdict = "COLLAPSE" if res.collapsed else "no collapse"
        when = f" at t = {res.collapse_time:.3f} s" if res.collapse_time is not None else ""
        print(
            f"{verdict}{when} ({model.options.collapse} rule: {res.fate}, decided at "
            f"t = {res.decided_time:.3f} s); peak |θ| = {res.max_rotation:.6g} rad "
            f"= {res.max_rotation_ratio:.4f} α; "
            f"{res.impacts} impacts; {len(res.ruptures)} bar ruptures"
        )
        if res.rupture_strain is not None:
            print(
                f"peak strain of an intact acting bar {res.peak_strain * 1e3:.3f} ‰ "
                f"(rupture at {res.rupture_strain * 1e3:.3f} ‰)"
            )
        for r in res.ruptures:
            print(f"  rupture at t = {r.time:.4f} s, side {r.side:+d}")
        if args.out:
            print(f"history written to {plain_line(args.out)}")
    return 0
