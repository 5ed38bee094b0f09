"""Masonry at the base of the wall (SI units, per metre of wall length).

NTC 2018 §7.8.2.2.1: the compression at the base is carried by a rectangular stress block of
0.85·f_d, f_d the design compressive strength of the masonry (f_m / FC).
"""

from __future__ import annotations

import math

#: Stress of the rectangular stress block as a fraction of f_d (NTC 2018 §7.8.2.2.1) [-].
STRESS_BLOCK_FACTOR = 0.85


def compressed_zone_depth(normal_force: float, design_strength: float) -> float:
    """Depth x [m] of the stress block that carries ``normal_force`` N [N/m] on 1 m of wall:
    x = N / (0.85·f_d·1 m), f_d [Pa]; 0 when f_d is infinite (the paper's edge pivot)."""
    if math.isinf(design_strength):
        return 0.0
    return normal_force / (STRESS_BLOCK_FACTOR * design_strength)
