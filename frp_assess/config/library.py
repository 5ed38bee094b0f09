"""Built-in libraries: FRP bar materials (docs/model.md §7) and masonry unit weights.

Plain frozen dataclasses, in practitioners' units (GPa, kg/m³, EUR/kg, kN/m³).  A project file
may add or override FRP materials under ``materials:``; masonry types are chosen by key under
``wall.masonry``.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from dataclasses import dataclass


@dataclass(frozen=True)
class FrpMaterial:
    """An FRP bar material.

    Attributes:
        name: library key, e.g. ``GFRP``.
        elastic_modulus: E [GPa].
        ultimate_strain: ε_u [-] (the design rupture strain is strain_factor·ε_u).
        density: [kg/m³].
        price: indicative price of the bars [currency/kg] (EUR in the library).
        source: where the values come from.
        description: one line for reports.
        characteristic_strain: ε_fk [-], the 5 % fractile, when the producer gives it (None:
            derived from ε_u, docs/model.md §2.1).
        fibre: glass, carbon, aramid or basalt, for the environmental factor η_a (None: by
            the name, glass for an unknown one).
    """

    name: str
    elastic_modulus: float
    ultimate_strain: float
    density: float
    price: float
    source: str = ""
    description: str = ""
    characteristic_strain: float | None = None
    fibre: str | None = None


@dataclass(frozen=True)
class Masonry:
    """A masonry type of Circolare 2019 Tab. C8.5.I.

    Attributes:
        key: kebab-case library key, e.g. ``solid-brick-lime-mortar``.
        unit_weight: w [kN/m³] used by default.
        description: the masonry type in words (with the Italian name of the table).
        source: the table cited.
        unit_weight_range: (min, max) [kN/m³] when the table gives a range, else ``None``.
    """

    key: str
    unit_weight: float
    description: str
    source: str = "Circolare 2019 (NTC 2018), Tab. C8.5.I"
    unit_weight_range: tuple[float, float] | None = None


_PRODUCER = "typical producer data"
_PRICE_NOTE = "price indicative (EUR/kg, bars only), replace with a quotation"

#: FRP bar materials of docs/model.md §7, by key.
FRP_MATERIALS: dict[str, FrpMaterial] = {
    m.name: m
    for m in (
        FrpMaterial(
            "GFRP",
            46.0,
            0.015,
            2000.0,
            8.0,
            f"{_PRODUCER}; CNR-DT 203/2006 ranges",
            f"glass FRP bar; {_PRICE_NOTE}",
        ),
        FrpMaterial("BFRP", 50.0, 0.020, 2000.0, 10.0, _PRODUCER, f"basalt FRP bar; {_PRICE_NOTE}"),
        FrpMaterial(
            "CFRP", 150.0, 0.013, 1550.0, 35.0, _PRODUCER, f"carbon FRP bar; {_PRICE_NOTE}"
        ),
    )
}

#: Masonry types of Circolare 2019 Tab. C8.5.I with their unit weights, by key.
MASONRY: dict[str, Masonry] = {
    m.key: m
    for m in (
        Masonry(
            "rubble-stone",
            19.0,
            "rubble stone masonry, irregular stones and pebbles (muratura in pietrame disordinata)",
        ),
        Masonry(
            "roughly-cut-stone",
            20.0,
            "roughly cut stone masonry with leaves of uneven thickness (muratura a conci sbozzati)",
        ),
        Masonry(
            "good-split-stone",
            21.0,
            "split stone masonry with good texture (muratura in pietre a spacco con buona "
            "tessitura)",
        ),
        Masonry(
            "soft-stone",
            16.0,
            "soft stone blocks, tuff, calcarenite (muratura a conci di pietra tenera); the "
            "table gives 13-16 kN/m3, the upper value is used: give unit_weight for a lighter "
            "stone",
            unit_weight_range=(13.0, 16.0),
        ),
        Masonry(
            "squared-blocks",
            22.0,
            "squared stone blocks (muratura a blocchi lapidei squadrati)",
        ),
        Masonry(
            "solid-brick-lime-mortar",
            18.0,
            "solid brick and lime mortar (muratura in mattoni pieni e malta di calce)",
        ),
        Masonry(
            "semi-solid-brick-cement-mortar",
            15.0,
            "semi-solid bricks and cement mortar (muratura in mattoni semipieni con malta "
            "cementizia)",
        ),
    )
}


def did_you_mean(name: str, choices: Iterable[str]) -> str:
    """`` (did you mean 'X'?)`` for the closest of ``choices`` to ``name``, or ``""``.

    Case-insensitive, so that ``gfrp`` suggests ``GFRP``.
    """
    options = list(choices)
    by_lower = {c.lower(): c for c in options}
    close = difflib.get_close_matches(str(name).lower(), list(by_lower), n=1, cutoff=0.6)
    return f" (did you mean {by_lower[close[0]]!r}?)" if close else ""
