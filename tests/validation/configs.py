"""The five walls every cross-check runs: unreinforced and the four mechanism × position cases."""

from __future__ import annotations

from frp_assess.dynamics import Rebars, RockingModel, Wall

WALL = Wall(thickness=0.4, height=3.0, unit_weight=18e3)

CASES: dict[str, tuple[str, dict | None]] = {
    "URM one-sided": ("one-sided", None),
    "URM two-sided": ("two-sided", None),
    "GFRP centred one-sided": (
        "one-sided",
        dict(elastic_modulus=46e9, ultimate_strain=0.015, position="centred", ratio=2.0),
    ),
    "CFRP external one-sided": (
        "one-sided",
        dict(elastic_modulus=150e9, ultimate_strain=0.013, position="external", ratio=1.0),
    ),
    "BFRP centred two-sided": (
        "two-sided",
        dict(elastic_modulus=50e9, ultimate_strain=0.020, position="centred", ratio=1.0),
    ),
    "GFRP external two-sided": (
        "two-sided",
        dict(elastic_modulus=46e9, ultimate_strain=0.015, position="external", ratio=3.0),
    ),
}


def model_for(name: str, **options) -> RockingModel:
    from frp_assess.dynamics import ModelOptions

    mechanism, bars = CASES[name]
    return RockingModel(WALL, mechanism, Rebars(**bars) if bars else None, ModelOptions(**options))
