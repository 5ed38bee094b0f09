"""A ratio shown beside a verdict on it, with enough decimals to read on the verdict's side
(0.997 against a target of 1 is "0.997", never "1.00"): shared by results.csv and, through
:mod:`frp_assess.numbers`, every other output."""

from __future__ import annotations

import math

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
