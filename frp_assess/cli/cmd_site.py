"""`frp-assess site`: the NTC 2018 seismic parameters of a site from its coordinates.

For each limit state (SLO, SLD, SLV, SLC): the return period T_R and a_g [g], F0, T_C* [s]
interpolated on the NTC reference grid (docs/site-hazard.md).  ``--json`` prints them as one
JSON object keyed by limit state.  A site the grid does not cover, or abroad, is refused with
one line; a site near Italy's land border is computed with a warning on stderr.
"""

from __future__ import annotations

import argparse
import json
import sys

from frp_assess.app.site import LIMIT_STATES, P_VR, USE_CLASSES, SiteHazard, site_hazard
from frp_assess.cli.arg_types import number_in

#: the longest nominal life accepted [years] (NTC 2018 Tab. 2.4.I: 10, 50, 100 or more)
MAX_NOMINAL_LIFE = 1000.0


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "site",
        help="NTC 2018 seismic parameters of a site from its coordinates",
        description="Print, for each limit state SLO, SLD, SLV, SLC, the return period T_R "
        "and a_g [g], F0, T_C* [s] of the site (NTC 2018 §3.2: V_R = V_N*C_U, "
        "T_R = -V_R/ln(1-P_VR); values interpolated on the reference grid of NTC 2008 "
        "Allegato B: inverse-distance mean of the 4 vertices of the grid cell containing the "
        "site, log-log in T_R).",
    )
    p.add_argument("--lat", required=True, type=number_in(-90, 90, unit="°"),
                   help="latitude [°], decimal, e.g. 42.35")  # fmt: skip
    p.add_argument("--lon", required=True, type=number_in(-180, 180, unit="°"),
                   help="longitude [°], decimal, e.g. 13.40")  # fmt: skip
    p.add_argument(
        "--nominal-life",
        type=number_in(0, MAX_NOMINAL_LIFE, low_open=True, unit="years"),
        default=50.0,
        help="nominal life V_N [years] (NTC 2018 Tab. 2.4.I; default 50)",
    )
    p.add_argument(
        "--use-class",
        choices=USE_CLASSES,
        default="II",
        help="use class I-IV (C_U = 0.7, 1.0, 1.5, 2.0; default II)",
    )
    p.add_argument("--json", action="store_true", help="print JSON instead of a table")
    p.set_defaults(handler=run)


def as_json(hazard: SiteHazard) -> dict[str, dict[str, float]]:
    """The ``--json`` object: per limit state TR [years], ag [g], F0 [-], Tc_star [s]."""
    return {
        s: {
            "TR": hazard[s].TR,
            "ag": hazard[s].ag,
            "F0": hazard[s].F0,
            "Tc_star": hazard[s].Tc_star,
        }
        for s in LIMIT_STATES
    }


def as_table(hazard: SiteHazard) -> str:
    """The text output: the site, V_R, one line per limit state."""
    h = hazard
    lines = [
        f"Site: latitude {h.latitude:g}°, longitude {h.longitude:g}° (nearest grid node "
        f"{h.nodes[0].distance:.1f} km away)",
        "Values from "
        + (
            "the 4 vertices of the grid cell that contains the site"
            if h.interpolation == "cell"
            else "the 4 nearest nodes: no complete grid cell contains the site"
        ),
        f"V_N = {h.V_N:g} years, use class {h.use_class} (C_U = {h.C_U:g}), V_R = {h.V_R:g} years",
        "",
        f"{'state':<6}{'P_VR':>6}{'T_R [years]':>13}{'a_g [g]':>10}{'F0 [-]':>9}{'T_C* [s]':>10}",
    ]
    for s in LIMIT_STATES:
        v = h[s]
        clamp = "" if v.TR_used == v.TR else f"  (T_R outside 30-2475: {v.TR_used:g} used)"
        lines.append(
            f"{s:<6}{P_VR[s]:>6.0%}{v.TR:>13.0f}{v.ag:>10.4f}{v.F0:>9.3f}{v.Tc_star:>10.3f}" + clamp
        )
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    hazard = site_hazard(args.lat, args.lon, args.nominal_life, args.use_class)
    if hazard.border_warning:
        print(f"frp-assess: warning: --lat/--lon: {hazard.border_warning}", file=sys.stderr)
    if args.json:
        print(json.dumps(as_json(hazard), indent=1))
    else:
        print(as_table(hazard))
    return 0
