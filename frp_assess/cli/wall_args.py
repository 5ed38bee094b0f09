"""Command-line options shared by `simulate` and `ida`: the wall, the bars, the model.

Units on the command line are practitioners' (m, kN/m³, GPa, ‰, g); they are converted to SI
here and validated into one-line :class:`~frp_assess.errors.InputError` messages.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable
from typing import Any

from frp_assess.app.expert import (
    MECHANISMS,
    POSITIONS,
    BarsInput,
    ModelOptions,
    RockingModel,
    WallInput,
    rocking_model,
)
from frp_assess.app.records import FORMATS, UNITS
from frp_assess.cli.arg_types import number_in
from frp_assess.config.schema import (
    HEIGHT_RANGE,
    MAX_RATIO,
    MIN_RATIO,
    MODULUS_RANGE,
    STRAIN_RANGE,
    THICKNESS_RANGE,
)
from frp_assess.dynamics.options import (
    FREE_VIBRATION_TAIL,
    INTEGRATION_TOLERANCE,
    MODEL_OPTIONS,
    RESTITUTION,
    STRAIN_FACTOR,
    Option,
)
from frp_assess.errors import InputError

#: bounds of the command-line wall (those of the project file's schema)
THICKNESS = number_in(*THICKNESS_RANGE, unit="m")
HEIGHT = number_in(*HEIGHT_RANGE, unit="m")
UNIT_WEIGHT = number_in(5, 30, unit="kN/m³")
MODULUS = number_in(*MODULUS_RANGE, unit="GPa")
STRAIN = number_in(*STRAIN_RANGE)
RATIO = number_in(MIN_RATIO, MAX_RATIO, unit="‰")


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
    wall.add_argument("--mechanism", choices=MECHANISMS, required=True)
    bars = parser.add_argument_group("FRP rebars (omit all four for the unreinforced wall)")
    bars.add_argument("--modulus", type=MODULUS, metavar="E", help="elastic modulus E [GPa]")
    bars.add_argument(
        "--ultimate-strain", type=STRAIN, metavar="EPS", help="ultimate strain ε_u [-]"
    )
    bars.add_argument("--position", choices=POSITIONS)
    bars.add_argument("--ratio", type=RATIO, metavar="RHO", help="active bar area ρ [‰ of B·1 m]")
    add_option_argument(bars, STRAIN_FACTOR, metavar="C")
    model = parser.add_argument_group("model options (docs/model.md §3–4)")
    for option in MODEL_OPTIONS.values():
        if option.flag:  # the pivot needs the masonry's strength: project files only
            add_option_argument(model, option, metavar=_METAVARS.get(option.key))


#: the metavar of some options in the help (the others show their choices or the key)
_METAVARS = {
    RESTITUTION.key: "energy|velocity|NUMBER",
    INTEGRATION_TOLERANCE.key: "TOL",
    FREE_VIBRATION_TAIL.key: "SECONDS",
}


def option_dest(option: Option[Any]) -> str:
    """The attribute of the parsed arguments that holds ``option``."""
    return option.flag.removeprefix("--").replace("-", "_")


def option_type(option: Option[Any]) -> Callable[[str], float]:
    """argparse ``type=`` of a numeric option: a finite number in its declared range."""
    return number_in(
        option.low,
        option.high,
        low_open=option.low_open,
        high_open=option.high_open,
        unit=option.unit,
    )


#: the integration tolerance (``run --rtol`` overrides the project file's with it)
TOLERANCE = option_type(INTEGRATION_TOLERANCE)


def add_option_argument(
    group: argparse._ArgumentGroup, option: Option[Any], *, metavar: str | None = None
) -> None:
    """The command-line argument of a declared option (dynamics/options.py): its flag,
    default, accepted values and help.  An option that takes words and a number is read as
    text (checked by :func:`parse_word_or_number`)."""
    kwargs: dict[str, Any] = {"default": option.default, "help": option.describe()}
    if option.numeric and not option.choices:
        kwargs["type"] = option_type(option)
    elif not option.numeric:
        kwargs["choices"] = option.choices
    if metavar is not None:
        kwargs["metavar"] = metavar
    group.add_argument(option.flag, **kwargs)


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


def parse_word_or_number(option: Option[Any], text: str) -> str | float:
    """The argument of an option that takes words and a number (``--restitution``): one of
    the words, or a number in its range; else a one-line :class:`InputError`."""
    if text in option.choices:
        return text
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not option.accepts(value):
        raise InputError(f"expected {option.allowed_text()}, found {text!r}", key=option.flag)
    return value


def model_options(args: argparse.Namespace) -> ModelOptions:
    """The model options of the parsed arguments (every one of dynamics/options.py)."""
    values: dict[str, Any] = {}
    for key, option in MODEL_OPTIONS.items():
        if not option.flag:
            continue  # not on the command line: its default
        value = getattr(args, option_dest(option))
        if option.choices and option.numeric and isinstance(value, str):
            value = parse_word_or_number(option, value)
        values[key] = value
    return ModelOptions(**values)


def build_model(args: argparse.Namespace) -> RockingModel:
    B = _positive(args.thickness, "--thickness", "m")
    H = _positive(args.height, "--height", "m")
    w = _positive(args.unit_weight, "--unit-weight", "kN/m³")
    wall = WallInput(B, H, w)  # no masonry strength on the command line: the edge pivot
    bar_opts = {
        "--modulus": args.modulus,
        "--ultimate-strain": args.ultimate_strain,
        "--position": args.position,
        "--ratio": args.ratio,
    }
    given = [k for k, v in bar_opts.items() if v is not None]
    rebars: BarsInput | None = None
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
        rebars = BarsInput(
            args.modulus, args.ultimate_strain, args.position, args.ratio, args.strain_factor
        )
    if not (math.isfinite(args.tail) and args.tail >= 0.0):
        raise InputError(f"expected a duration >= 0 s, found {args.tail:g}", key="--tail")
    return rocking_model(wall, args.mechanism, rebars, model_options(args), key="--thickness")
