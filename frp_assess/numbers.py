"""Number formats and result sentences shared by the CLI, the TUI and the PDF report.

:func:`fmt_against` shows a ratio next to a verdict on it (capacity/demand against the target)
with enough digits that the number shown agrees with the verdict: 0.997 against a target of 1
is "0.997", never "1.00 … meets: no".
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

#: most decimals :func:`fmt_against` shows before giving up on separating value and threshold
MAX_DECIMALS = 6


def fmt_against(value: float, threshold: float, meets: bool | None, decimals: int = 2) -> str:
    """``value`` with ``decimals`` decimals, or more when that rounding would contradict the
    verdict ``meets`` (``value ≥ threshold``): the shown number then reads on the verdict's
    side of ``threshold``.  ``meets`` None (no verdict) keeps ``decimals``."""
    if not math.isfinite(value):
        return f"{value}"
    text = f"{value:.{decimals}f}"
    if meets is None:
        return text
    for d in range(decimals, MAX_DECIMALS + 1):
        text = f"{value:.{d}f}"
        if (float(text) >= threshold) == bool(meets):
            return text
    return text


def numerical_check_text(results: Mapping[str, Any]) -> str | None:
    """The verification run in one sentence, or None when it was not asked for."""
    nc = results.get("numerical_check")
    if not nc:
        return None
    head = (
        f"Numerical check: every IDA was repeated at a 10× tighter integration tolerance "
        f"({nc['check_tolerance']:g} instead of {nc['tolerance']:g}). "
    )
    if nc["fate_changed"]:
        return head + (
            f"For {nc['case']} under {nc['record']} a record collapsed in one run and not in "
            f"the other: that result is ill-conditioned (sensitive to the integrator's "
            f"round-off); {nc['changed_pairs']} of {nc['pairs']} multipliers moved by more "
            "than the IDA tolerance."
        )
    return head + (
        f"The largest change of a collapse multiplier was {nc['max_change']:.2%} "
        f"({nc['case']}, {nc['record']}); {nc['changed_pairs']} of {nc['pairs']} "
        "multipliers moved by more than the IDA tolerance."
    )
