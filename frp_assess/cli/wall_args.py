"""Command-line options shared by `simulate` and `ida`: the wall, the bars, the model.

Units on the command line are practitioners' (m, kN/m³, GPa, ‰, g); they are converted to SI
here and validated into one-line :class:`~frp_assess.errors.InputError` messages.
"""

from __future__ import annotations

import argparse
import math

from frp_assess.cli.arg_types import number_in
from frp_assess.dynamics import (
    COLLAPSE_RULES,
    DEFAULT_TOLERANCE,
    RUPTURE_RULES,
    ModelOptions,
    Rebars,
    RockingModel,
    Wall,
)
from frp_assess.dynamics.rebars import DEFAULT_STRAIN_FACTOR
from frp_assess.dynamics.restitution import Restitution
from frp_assess.dynamics.rocking import TOLERANCE_RANGE
from frp_assess.errors import InputError
from frp_assess.motions.readers import FORMATS, UNITS

#: bounds of the command-line wall (those of the project file's schema)
THICKNESS = number_in(0, 5, low_open=True, unit="m")
HEIGHT = number_in(0, 50, low_open=True, unit="m")
UNIT_WEIGHT = number_in(5, 30, unit="kN/m³")
MODULUS = number_in(0, 1000, low_open=True, unit="GPa")
STRAIN = number_in(0, 1, low_open=True)
RATIO = number_in(0, 20, low_open=True, unit="‰")
FACTOR = number_in(0, 1, low_open=True)
#: longest free-vibration tail [s] (the schema's analysis.free_vibration_tail)
TAIL = number_in(0, 60, unit="s")
TOLERANCE = number_in(*TOLERANCE_RANGE)


def add_model_arguments(parser: argparse.ArgumentParser) -> None:
    wall = parser.add_argument_group("wall (per metre of length)")
    wall.add_argument(
        "--thickness", type=THICKNESS, required=True, metavar="B", help="thickness B [m]"
    )
    wall.add_argument("--height", type=HEIGHT, required=True, metavar="H", help="height H [m]")
    wall.add_argument(
        "--unit-weight",
        type=UNIT_WEIGHT,
        default=18.0,
        metavar="W",
        help="unit weight [kN/m³] (default 18: solid brick and lime mortar)",
    )
    wall.add_argument("--mechanism", choices=["one-sided", "two-sided"], required=True)
    bars = parser.add_argument_group("FRP rebars (omit all four for the unreinforced wall)")
    bars.add_argument("--modulus", type=MODULUS, metavar="E", help="elastic modulus E [GPa]")
    bars.add_argument(
        "--ultimate-strain", type=STRAIN, metavar="EPS", help="ultimate strain ε_u [-]"
    )
    bars.add_argument("--position", choices=["centred", "external"])
    bars.add_argument("--ratio", type=RATIO, metavar="RHO", help="active bar area ρ [‰ of B·1 m]")
    bars.add_argument(
        "--strain-factor",
        type=FACTOR,
        default=DEFAULT_STRAIN_FACTOR,
        metavar="C",
        help="cyclic reduction c, ε_max = c·ε_u (default 0.5)",
    )
    model = parser.add_argument_group("model options (docs/model.md §3–4)")
    model.add_argument(
        "--restitution",
        default="energy",
        metavar="energy|velocity|NUMBER",
        help="impact rule: energy (|θ'₊| = √r·|θ'₋|, default), velocity (r·|θ'₋|) "
        "or a velocity ratio in (0, 1]",
    )
    model.add_argument("--rupture", choices=RUPTURE_RULES, default="energy-transfer")
    model.add_argument(
        "--collapse",
        choices=COLLAPSE_RULES,
        default="overturning",
        help="overturning: the wall falls (default) | end-of-record: |θ| >= α when the record "
        "ends | first-exceedance: |θ| reaches α",
    )
    model.add_argument(
        "--rtol",
        type=TOLERANCE,
        default=DEFAULT_TOLERANCE,
        metavar="TOL",
        help=f"local error tolerance of the integrator (default {DEFAULT_TOLERANCE:g})",
    )
    model.add_argument(
        "--tail",
        type=TAIL,
        default=0.0,
        metavar="SECONDS",
        help="free vibration appended after the record [s], 0-60",
    )


def add_record_arguments(parser: argparse.ArgumentParser, *, many: bool) -> None:
    rec = parser.add_argument_group("ground motion")
    if many:
        rec.add_argument(
            "--record",
            action="append",
            required=True,
            metavar="FILE",
            help="accelerogram file (.AT2 or two-column t, a); repeat for a set",
        )
    else:
        rec.add_argument(
            "--record",
            required=True,
            metavar="FILE",
            help="accelerogram file (.AT2 or two-column t, a)",
        )
    rec.add_argument(
        "--units",
        default="g",
        choices=sorted(UNITS),
        help="acceleration units of the file (AT2 files are in g)",
    )
    rec.add_argument("--format", default="auto", choices=FORMATS)


def _positive(value: float, option: str, unit: str) -> float:
    if not (math.isfinite(value) and value > 0.0):
        raise InputError(f"expected a number > 0 [{unit}], found {value:g}", key=option)
    return value


def parse_restitution(text: str) -> Restitution:
    if text == "energy":
        return "energy"
    if text == "velocity":
        return "velocity"
    try:
        value = float(text)
    except ValueError:
        raise InputError(
            f"expected energy, velocity or a number in (0, 1], found {text!r}", key="--restitution"
        ) from None
    if not (0.0 < value <= 1.0):
        raise InputError(
            f"expected a velocity ratio in (0, 1], found {value:g}", key="--restitution"
        )
    return value


def build_model(args: argparse.Namespace) -> RockingModel:
    B = _positive(args.thickness, "--thickness", "m")
    H = _positive(args.height, "--height", "m")
    w = _positive(args.unit_weight, "--unit-weight", "kN/m³")
    if B >= H:
        raise InputError(
            f"expected thickness < height for a rocking wall, found B = {B:g} m ≥ H = {H:g} m",
            key="--thickness",
        )
    wall = Wall(thickness=B, height=H, unit_weight=w * 1e3)
    bar_opts = {
        "--modulus": args.modulus,
        "--ultimate-strain": args.ultimate_strain,
        "--position": args.position,
        "--ratio": args.ratio,
    }
    given = [k for k, v in bar_opts.items() if v is not None]
    rebars = None
    if given:
        missing = [k for k, v in bar_opts.items() if v is None]
        if missing:
            raise InputError(
                f"rebars need {', '.join(bar_opts)}; missing {', '.join(missing)}", key=given[0]
            )
        _positive(args.modulus, "--modulus", "GPa")
        if not (0.0 < args.ultimate_strain < 1.0):
            raise InputError(
                f"expected a strain in (0, 1), found {args.ultimate_strain:g}",
                key="--ultimate-strain",
            )
        if not (math.isfinite(args.ratio) and 0.0 < args.ratio <= 20.0):
            raise InputError(f"expected a ratio in (0, 20] ‰, found {args.ratio:g}", key="--ratio")
        if not (0.0 < args.strain_factor <= 1.0):
            raise InputError(
                f"expected a factor in (0, 1], found {args.strain_factor:g}", key="--strain-factor"
            )
        rebars = Rebars(
            args.modulus * 1e9, args.ultimate_strain, args.position, args.ratio, args.strain_factor
        )
    if not (math.isfinite(args.tail) and args.tail >= 0.0):
        raise InputError(f"expected a duration >= 0 s, found {args.tail:g}", key="--tail")
    options = ModelOptions(
        restitution=parse_restitution(args.restitution),
        rupture=args.rupture,
        collapse=args.collapse,
        free_vibration_tail=args.tail,
        tolerance=args.rtol,
    )
    return RockingModel(wall, args.mechanism, rebars, options)
