"""Walls the dynamics tests share: one wall, two sets of bars, and six configurations of
them that between them take every branch of the kernel's events (mechanism, bars acting on
one or both sides, pivot, collapse rule, rupture rule)."""

from __future__ import annotations

from typing import Any

from frp_assess.dynamics import Rebars, Wall

WALL = Wall(thickness=0.4, height=3.0, unit_weight=18e3, compressive_strength=2.0e6)
CFRP = Rebars(150e9, 0.013, "external", 1.0, strain_factor=0.5)
GFRP_CENTRED = Rebars(46e9, 0.015, "centred", 2.0, strain_factor=0.5)

#: (mechanism, bars, model options)
SIX_WALLS: list[tuple[str, Rebars | None, dict[str, Any]]] = [
    ("one-sided", None, {"pivot": "edge", "collapse": "end-of-record"}),
    ("two-sided", None, {}),
    ("one-sided", CFRP, {"pivot": "edge", "collapse": "end-of-record"}),
    ("two-sided", CFRP, {"collapse": "overturning"}),
    ("two-sided", GFRP_CENTRED, {"collapse": "first-exceedance"}),
    ("one-sided", GFRP_CENTRED, {"rupture": "velocity-continuous"}),
]
