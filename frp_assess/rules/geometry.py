"""The rectangular rocking block (SI units: m, rad; docs/model.md §1, paper Eqs. 2–5).

A wall of thickness B and height H rocks about a base corner only if it is a block at all
(finite sizes > 0) and taller than thick (B < H: slenderness α < 45°).
"""

from __future__ import annotations

import math

#: the wall's thickness B [m] and height H [m] the model is valid for, [low, high]: below 50 mm
#: no masonry leaf stands (a brick on edge is 55-60 mm); below H = 0.5 m the wall is a block,
#: not a rocking panel.  The project file's (config.schema), the command line's
#: (cli/wall_args.py) and results.json's (results/read_checks.py) range.
THICKNESS_RANGE = (0.05, 5.0)
HEIGHT_RANGE = (0.5, 50.0)


def size_problem(value: float, what: str = "size", unit: str = "m") -> str | None:
    """Why a size ``value`` [``unit``, m by default] is not a finite number > 0 (one line),
    ``None`` when it is (a block has sizes, docs/model.md §1)."""
    if isinstance(value, bool) or not (math.isfinite(value) and value > 0.0):
        return f"expected {what} > 0 {unit}, found {value!r}"
    return None


def is_rocking_block(thickness: float, height: float) -> bool:
    """Whether B [m] and H [m] make a rocking wall: both finite and > 0, and B < H
    (docs/model.md §1: slenderness α < 45°)."""
    return size_problem(thickness) is None and size_problem(height) is None and thickness < height


def slenderness_problem(thickness: float, height: float) -> str | None:
    """Why B [m] ≥ H [m] is no rocking wall (one line), ``None`` when B < H (docs/model.md
    §1)."""
    if thickness < height:
        return None
    return (
        f"expected thickness < height for a rocking wall, found B = {thickness:g} m "
        f">= H = {height:g} m"
    )


def slenderness(thickness: float, height: float) -> float:
    """Slenderness α [rad], tan α = B/H, of a wall B [m] thick and H [m] tall (paper Eq. 2)."""
    return math.atan2(thickness, height)


def thickness_of(height: float, alpha: float) -> float:
    """B = H·tan α [m] of the wall of height H [m] and slenderness α [rad] (paper Eq. 2)."""
    return height * math.tan(alpha)


def half_diagonal(thickness: float, height: float) -> float:
    """R = ½·√(B² + H²) [m], centre of mass to a base corner, B and H [m] (paper Eq. 2)."""
    return 0.5 * math.hypot(thickness, height)
