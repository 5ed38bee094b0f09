"""The options a user may set on the model and on the IDA, each declared once.

Every option has one :class:`Option` here: its key (the field of :class:`ModelOptions` /
:class:`IdaSettings` / :class:`Rebars` and the key of the project and study files), default,
allowed values or range, unit and a one-line help.  The dataclasses take their defaults from
it; the pydantic schemas (``config/schema/``, reused by ``study/schema.py``) and the
command-line arguments (``cli/wall_args.py``, ``cli/cmd_ida.py``) are derived from it, and
``tests/dynamics/test_options.py`` checks each of them against it.

To add an option: declare it here, add the field to its dataclass with ``default=X.default``,
and add it to :data:`MODEL_OPTIONS` (or :data:`IDA_OPTIONS`); the test lists what is missing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Generic, Literal, TypeVar, get_args

from frp_assess.dynamics.base_reaction import PIVOT_RULES, PivotRule
from frp_assess.dynamics.rebars import DEFAULT_STRAIN_FACTOR
from frp_assess.dynamics.restitution import Restitution
from frp_assess.rules.masonry import STRESS_BLOCK_FACTOR

RuptureRule = Literal["energy-transfer", "velocity-continuous"]
CollapseRule = Literal["overturning", "end-of-record", "first-exceedance"]
CapacityRule = Literal["effective", "first-collapse"]
RUPTURE_RULES: tuple[RuptureRule, ...] = get_args(RuptureRule)
COLLAPSE_RULES: tuple[CollapseRule, ...] = get_args(CollapseRule)
CAPACITY_RULES: tuple[CapacityRule, ...] = get_args(CapacityRule)

Value = str | float | bool
#: the type of an option's value
T = TypeVar("T", bound=Value)


@dataclass(frozen=True)
class Option(Generic[T]):
    """One user option.

    Attributes:
        key: field name in its dataclass and key in the project/study file.
        flag: the command-line option (``--rtol``); ``""`` when the command line has none.
        default: the value when the option is not given.
        help: one line saying what it does (no unit, range or default: they are added).
        unit: of the number (``"s"``); ``""`` when dimensionless.
        choices: accepted words (a word option, or the words besides a number).
        low, high: accepted range of a number (``None``: no number accepted / unbounded).
        low_open, high_open: whether the bound itself is excluded.
    """

    key: str
    flag: str
    default: T
    help: str
    unit: str = ""
    choices: tuple[str, ...] = ()
    low: float | None = None
    high: float | None = None
    low_open: bool = False
    high_open: bool = False

    @property
    def numeric(self) -> bool:
        """Whether a number is accepted."""
        return self.low is not None or self.high is not None

    @property
    def is_flag(self) -> bool:
        """A yes/no option."""
        return isinstance(self.default, bool)

    @property
    def bounds(self) -> tuple[float, float]:
        """(low, high) of a number bounded on both sides."""
        if self.low is None or self.high is None:
            raise ValueError(f"{self.key} is not bounded on both sides")
        return (self.low, self.high)

    def range_text(self) -> str:
        """The accepted numbers, e.g. ``(0, 1]``, ``>= 0`` (``""``: none)."""
        lo, hi = self.low, self.high
        if lo is not None and hi is not None:
            left, right = "(" if self.low_open else "[", ")" if self.high_open else "]"
            return f"{left}{lo:g}, {hi:g}{right}"
        if lo is not None:
            return f"{'>' if self.low_open else '>='} {lo:g}"
        if hi is not None:
            return f"{'<' if self.high_open else '<='} {hi:g}"
        return ""

    def allowed_text(self) -> str:
        """What is accepted, in words: ``energy, velocity or a number in (0, 1]``."""
        words = ", ".join(self.choices)
        if not self.numeric:
            return words
        rng = self.range_text()
        number = f"a number in {rng}" if rng[0] in "([" else f"a number {rng}"
        number += f" {self.unit}" if self.unit else ""
        return f"{words} or {number}" if words else number

    def default_text(self) -> str:
        d = self.default
        if isinstance(d, bool):
            return "yes" if d else "no"
        return f"{d:g}" if isinstance(d, float) else str(d)

    def describe(self) -> str:
        """The one-line description of the schemas and the command line's help."""
        if not self.numeric:  # the help names the words
            return f"{self.help} (default {self.default_text()})."
        return f"{self.help}: {self.allowed_text()} (default {self.default_text()})."

    def accepts(self, value: object) -> bool:
        """Whether ``value`` is one of the choices or a finite number in the range."""
        if self.is_flag:
            return isinstance(value, bool)
        if isinstance(value, str):
            return value in self.choices
        if not self.numeric or isinstance(value, bool) or not isinstance(value, int | float):
            return False
        v = float(value)
        if not math.isfinite(v):
            return False
        if self.low is not None and (v <= self.low if self.low_open else v < self.low):
            return False
        return not (self.high is not None and (v >= self.high if self.high_open else v > self.high))

    def check(self, value: object) -> None:
        """:class:`ValueError` naming the option unless :meth:`accepts` ``value``."""
        if not self.accepts(value):
            raise ValueError(
                f"{self.key.replace('_', ' ')} must be {self.allowed_text()}, got {value!r}"
            )


# ------------------------------------------------------------------ model (docs/model.md §2–4)
RESTITUTION: Option[Restitution] = Option(
    key="restitution",
    flag="--restitution",
    default="energy",
    help="Impact rule, the velocity ratio at an impact: energy (sqrt(r) of Eqs. 13-14), "
    "velocity (r itself) or the ratio itself",
    choices=("energy", "velocity"),
    low=0.0,
    high=1.0,
    low_open=True,
)
RUPTURE: Option[RuptureRule] = Option(
    key="rupture",
    flag="--rupture",
    default="energy-transfer",
    help="Bar rupture rule: energy-transfer (Eq. 12) or velocity-continuous",
    choices=RUPTURE_RULES,
)
COLLAPSE: Option[CollapseRule] = Option(
    key="collapse",
    flag="--collapse",
    default="overturning",
    help="Collapse: overturning (the wall falls; followed after the record until its fate is "
    "certain), end-of-record (|theta| >= alpha when the record ends, the paper's convention) "
    "or first-exceedance (|theta| reaches alpha at any time)",
    choices=COLLAPSE_RULES,
)
FREE_VIBRATION_TAIL: Option[float] = Option(
    key="free_vibration_tail",
    flag="--tail",
    default=0.0,
    help="Zero ground motion appended to each record",
    unit="s",
    low=0.0,
    high=60.0,
)
PIVOT: Option[PivotRule] = Option(
    key="pivot",
    flag="",
    default="crushing",
    help="The masonry at the base: crushing (the weight and the bar force N act at x/2 from "
    f"the corner, x = N/({STRESS_BLOCK_FACTOR:g}*f_d), and the toe crushes when x reaches "
    "the bar; needs the masonry's strength, without it the edge model is used) or edge "
    "(x = 0, the paper's model)",
    choices=PIVOT_RULES,
)
#: Default local error tolerance of the Dormand–Prince pair [-].  Measured on the whole
#: convergence corpus (scripts/validate_accuracy.py; a subset in
#: tests/validation/test_convergence.py): at 1e-6 a 100× tighter tolerance and RK4 at 0.1 ms
#: move no well-conditioned first-collapse multiplier by more than 0.2 % and one peak rotation
#: of 743 by more than 0.1 % (a time history that 1e-8 misses too: docs/model.md §4.5).  It
#: was 1e-8; 1e-6 halves the steps of the stiff reinforced walls.
INTEGRATION_TOLERANCE: Option[float] = Option(
    key="tolerance",
    flag="--rtol",
    default=1e-6,
    help="Local error tolerance of the Dormand-Prince 5(4) integrator",
    low=1e-12,
    high=1e-3,
)
STRAIN_FACTOR: Option[float] = Option(
    key="strain_factor",
    flag="--strain-factor",
    default=DEFAULT_STRAIN_FACTOR,
    help="Cyclic reduction c of the bars' ultimate strain, eps_max = c*eps_u",
    # below 0.01 the bars break at the first rocking (the unreinforced wall, and a strain
    # limit that underflows); in practice 0.5-1
    low=0.01,
    high=1.0,
)
VERIFY: Option[bool] = Option(
    key="verify",
    flag="",
    default=False,
    help="Repeat every IDA at a 10x tighter integration tolerance and report the largest "
    "change of a collapse multiplier",
)

# ------------------------------------------------------------------------ IDA (docs/model.md §5)
IDA_STEP_RATIO: Option[float] = Option(
    key="step_ratio",
    flag="--step-ratio",
    default=1.10,
    help="Step ratio s of the first-collapse hunt, C = C0*s^k (closer to 1 only multiplies "
    "the runs)",
    low=1.01,
    high=10.0,
)
IDA_TOLERANCE: Option[float] = Option(
    key="tolerance",
    flag="--tolerance",
    default=0.005,
    help="Relative bisection tolerance (finer is below the accuracy of the integration)",
    low=1e-4,
    high=0.1,
)
IDA_MAX_MULTIPLIER: Option[float] = Option(
    key="max_multiplier",
    flag="--max-multiplier",
    default=100.0,
    help="Give up ('no collapse') beyond C_max = this multiple of C0",
    low=1.0,
    high=1000.0,
    low_open=True,
)

IDA_CAPACITY: Option[CapacityRule] = Option(
    key="capacity",
    flag="--capacity",
    default="effective",
    help="The capacity of a record: effective (the effective collapse intensity, every "
    "collapse window counted by its width, docs/model.md §11) or first-collapse (the first "
    "collapse the hunt meets, the paper's convention, §5)",
    choices=CAPACITY_RULES,
)
#: The fine ladder of the effective collapse intensity's sampling, design (e) of
#: benchmarks/effective_sampling_designs.py (docs/model.md §11.2): the coarse ladder is its 8th
#: power (1.104), the fine one runs from 1.35 below the first collapse; over the seven cases of
#: §11.2 the case means move by ≤ 1.31 % (one standard deviation) over eight shifts.
IDA_LADDER_RATIO: Option[float] = Option(
    key="ladder_ratio",
    flag="--ladder-ratio",
    default=1.0125,
    help="Ratio r of the fine ladder of the effective capacity, C = C0*r^(k+offset): the "
    "coarse ladder r^8 runs up to the first collapse, the fine one from a band below it, each "
    "isolated change of outcome bisected to the tolerance (closer to 1: less numerical "
    "spread, more runs)",
    low=1.001,
    high=1.5,
)
IDA_OFFSET: Option[float] = Option(
    key="offset",
    flag="--offset",
    default=0.0,
    help="Expert: shift of the ladder of the effective capacity, C = C0*s^(k+offset), as a "
    "fraction of a step (the numerical spread is measured with it)",
    low=0.0,
    high=1.0,
    high_open=True,
)

#: the user options of :class:`~frp_assess.dynamics.rocking.ModelOptions`, by field name
MODEL_OPTIONS: dict[str, Option[Any]] = {
    o.key: o
    for o in (RESTITUTION, RUPTURE, COLLAPSE, FREE_VIBRATION_TAIL, INTEGRATION_TOLERANCE, PIVOT)
}
#: the fields of :class:`~frp_assess.dynamics.ida.IdaSettings`, by name
IDA_OPTIONS: dict[str, Option[Any]] = {
    o.key: o
    for o in (
        IDA_STEP_RATIO,
        IDA_TOLERANCE,
        IDA_MAX_MULTIPLIER,
        IDA_CAPACITY,
        IDA_LADDER_RATIO,
        IDA_OFFSET,
    )
}
