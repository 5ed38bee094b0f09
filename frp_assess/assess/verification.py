"""The numerical check of an assessment (docs/model.md §4.5, `analysis.integration.verify`).

Every IDA of the run is repeated at a 10× tighter integration tolerance, through the same
cached runner, and the largest change of a first-collapse multiplier is reported: a number
the engineer can quote for how much the result depends on the integrator.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from frp_assess.assess.runner import IdaRunner
from frp_assess.dynamics import IdaResult, RockingModel

#: The check's tolerance is the run's divided by this.
TIGHTER = 10.0


@dataclass(frozen=True)
class NumericalCheck:
    """Outcome of the verification run."""

    tolerance: float  #: the run's integration tolerance [-]
    check_tolerance: float  #: the verification's [-]
    max_change: float  #: largest |C_check − C| / C over every (case, record) [-]; inf if a
    #: record collapsed in one run and not in the other
    case: int  #: index of the case where it happened (0: unreinforced)
    record: int  #: index of the record where it happened
    changed: int  #: (case, record) pairs whose C moved by more than the IDA tolerance
    pairs: int  #: (case, record) pairs compared


def _change(a: float | None, b: float | None) -> float:
    if a is None or b is None:
        return 0.0 if a is b else math.inf
    return abs(b - a) / a


def verify(
    runner: IdaRunner,
    models: Sequence[RockingModel],
    results: Sequence[Sequence[IdaResult]],
    ida_tolerance: float,
    progress: Callable[[int, int], None] | None = None,
) -> NumericalCheck:
    """Repeat the IDAs of ``models`` (whose results are ``results``) at a tighter tolerance."""
    tol = models[0].options.tolerance
    tight = [m.with_options(tolerance=tol / TIGHTER) for m in models]
    checked = runner.run(tight, progress=progress)
    worst, where, changed, pairs = 0.0, (0, 0), 0, 0
    for i, (base, other) in enumerate(zip(results, checked, strict=True)):
        for k, (a, b) in enumerate(zip(base, other, strict=True)):
            change = _change(a.collapse_multiplier, b.collapse_multiplier)
            pairs += 1
            changed += change > ida_tolerance
            if change > worst:
                worst, where = change, (i, k)
    return NumericalCheck(tol, tol / TIGHTER, worst, where[0], where[1], changed, pairs)
