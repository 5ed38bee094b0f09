"""argparse ``type=`` functions for numbers: finite, in a stated range, with the unit.

A bad value is refused by argparse itself as one line (``argument --tail: expected a number in
[0, 60] s, found 1e9``), exit code 2, before any work: ``inf``, ``nan`` and ``1e400`` are never
accepted.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable


def _number(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, found {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"expected a finite number, found {text!r}")
    return value


def finite_float(text: str) -> float:
    """argparse ``type=``: a finite number (``inf``, ``nan``, ``1e400`` are refused)."""
    return _number(text)


def number_in(
    low: float | None = None,
    high: float | None = None,
    *,
    low_open: bool = False,
    high_open: bool = False,
    unit: str = "",
) -> Callable[[str], float]:
    """argparse ``type=``: a finite number in [low, high] (``(low, high]`` if ``low_open``,
    ``[low, high)`` if ``high_open``).

    The message states the range and the unit: ``expected a number in (0, 60] s, found 1e9``.
    """
    left = "(" if low_open else "["
    right = ")" if high_open else "]"
    lo = "" if low is None else f"{low:g}"
    hi = "" if high is None else f"{high:g}"
    if low is not None and high is not None:
        wanted = f"a number in {left}{lo}, {hi}{right}"
    elif low is not None:
        wanted = f"a number {'>' if low_open else '>='} {lo}"
    else:
        wanted = f"a number {'<' if high_open else '<='} {hi}"
    suffix = f" {unit}" if unit else ""

    def convert(text: str) -> float:
        value = _number(text)
        too_low = low is not None and (value <= low if low_open else value < low)
        too_high = high is not None and (value >= high if high_open else value > high)
        if too_low or too_high:
            raise argparse.ArgumentTypeError(f"expected {wanted}{suffix}, found {text}")
        return value

    convert.__name__ = "number"  # argparse names the type in its own messages
    return convert


def whole_number_in(low: int, high: int) -> Callable[[str], int]:
    """argparse ``type=``: a whole number in [low, high] (``1e6`` is refused: not whole)."""

    def convert(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected a whole number, found {text!r}") from None
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(
                f"expected a whole number in [{low}, {high}], found {value}"
            )
        return value

    convert.__name__ = "whole number"
    return convert
