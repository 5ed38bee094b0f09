"""Bars as they are built: the catalogue of bar sizes and the layout of whole bars over the
wall.

Units: diameters [mm], bar areas [mm²], lengths and spacings [m], ratios [‰], forces [kN],
stresses [MPa], E [GPa], density [kg/m³], price [currency/kg].

**Catalogue.** :data:`BAR_CATALOGUE` lists nominal diameters Ø6–Ø16 for GFRP, BFRP and CFRP
bars with the nominal area π·d²/4 of the nominal diameter (the convention of CNR-DT 203/2006
§3.2.1 and of producers' data sheets; sand-coated or ribbed bars are sold by nominal
diameter).  The diameters are those commonly offered by producers, not a particular
catalogue: a project adds or replaces sizes with :func:`bar_sizes` (``extra``).

**Layout.** The ratio ρ is an area per metre of wall for each line of bars (one line centred,
one per face external, ``docs/model.md`` §2).  Over a wall of length L one line needs the
area ρ·B·L; the number of bars is rounded *up* to whole bars, and raised further if the
spacing L/n would exceed the largest spacing.  Bars sit at equal spacing s = L/n with s/2 to
each end.  Spacing rule (stated, not taken from a code clause for this technique):

- largest spacing 1.0 m by default.  The model smears the bars into a uniform restraint per
  metre of wall; bars much further apart than that leave the masonry between them to rock
  on its own.  For new reinforced masonry NTC 2018 §7.8.6.1 allows vertical bars up to 4 m
  apart, far too loose for a smeared restraint; 1 m is an assumption of this tool, to be
  set by the designer.
- smallest spacing 0.10 m by default: at closer spacing the drilled holes (or grooves) weaken
  the masonry between them and the pull-out cones overlap.  EN 1996-1-1 §8.2.6 asks for a
  clear distance of at least the bar diameter and 10 mm between bars in mortar; 0.10 m
  between axes is a practical minimum for drilled masonry, an assumption of this tool.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

from frp_assess.dynamics import Position
from frp_assess.errors import InputError
from frp_assess.rules import bars as rule

#: Default smallest and largest spacing between the axes of bars in one line [m].
DEFAULT_MIN_SPACING = 0.10
DEFAULT_MAX_SPACING = 1.0


# ---------------------------------------------------------------------------------------------
# Catalogue


@dataclass(frozen=True)
class BarSize:
    """A bar size: material, nominal diameter d [mm], nominal area [mm²], where it is from."""

    material: str
    diameter: float
    area: float
    source: str = "nominal diameter, area pi*d^2/4 (CNR-DT 203/2006 §3.2.1)"


def nominal_area(diameter: float) -> float:
    """π·d²/4 [mm²] of the nominal diameter d [mm]."""
    return math.pi * diameter**2 / 4.0


_DIAMETERS = (6.0, 8.0, 10.0, 12.0, 14.0, 16.0)

#: Bar sizes by material key (nominal diameters commonly offered by producers).
BAR_CATALOGUE: dict[str, tuple[BarSize, ...]] = {
    m: tuple(BarSize(m, d, nominal_area(d)) for d in _DIAMETERS) for m in ("GFRP", "BFRP", "CFRP")
}


def bar_sizes(material: str, extra: Iterable[BarSize] = ()) -> tuple[BarSize, ...]:
    """The sizes of ``material``, with a project's ``extra`` sizes added (a size with the
    same diameter replaces the catalogue's), sorted by diameter."""
    by_d = {s.diameter: s for s in BAR_CATALOGUE.get(material, ())}
    for s in extra:
        if s.material == material:
            by_d[s.diameter] = s
    if not by_d:
        raise InputError(
            f"no bar sizes for material {material!r}: add them to the project "
            f"(catalogue has {', '.join(BAR_CATALOGUE)})",
            key="bars",
        )
    return tuple(by_d[d] for d in sorted(by_d))


def bar_size(material: str, diameter: float, extra: Iterable[BarSize] = ()) -> BarSize:
    """The size Ø``diameter`` of ``material``; an unknown diameter is an :class:`InputError`."""
    sizes = bar_sizes(material, extra)
    for s in sizes:
        if math.isclose(s.diameter, diameter):
            return s
    listed = ", ".join(f"{s.diameter:g}" for s in sizes)
    raise InputError(
        f"no {material} bar of diameter {diameter:g} mm; available: {listed} mm",
        key="bars.diameter",
    )


# ---------------------------------------------------------------------------------------------
# Layout


@dataclass(frozen=True)
class BarLayout:
    """Bars over the wall for one option.

    Attributes:
        diameter: d [mm].  bar_area: A_b [mm²].  position: centred or external.
        lines: 1 centred, 2 external (one line per face).
        bars_per_line: n, whole bars over the length L.
        spacing: s = L/n between axes [m]; the end bars sit s/2 from the wall's ends.
        ratio_asked: ρ asked [‰].  ratio_installed: n·A_b/(B·L) [‰] (per line).
        governed_by: ``ratio`` (area rounded up) or ``max_spacing``.
        fits: s ≥ the smallest spacing.
        total_bars: n·lines.
        bar_length: length of one bar [m] (None when not given).
        metres: total length of bar [m].  mass: [kg].  cost: bars + installation [currency]
            (None when the inputs they need were not given).
        note: one line for a report.
    """

    diameter: float
    bar_area: float
    position: str
    lines: int
    bars_per_line: int
    spacing: float
    ratio_asked: float
    ratio_installed: float
    governed_by: str
    fits: bool
    total_bars: int
    bar_length: float | None
    metres: float | None
    mass: float | None
    cost: float | None
    note: str


def bar_layout(
    ratio: float,
    thickness: float,
    length: float,
    position: Position,
    diameter: float,
    min_spacing: float = DEFAULT_MIN_SPACING,
    max_spacing: float = DEFAULT_MAX_SPACING,
    *,
    bar_area: float | None = None,
    bar_length: float | None = None,
    density: float | None = None,
    price: float | None = None,
    installation_per_metre: float = 0.0,
) -> BarLayout:
    """Whole bars of Ø``diameter`` installing at least ``ratio`` over the wall.

    Args:
        ratio: ρ asked [‰] per line.  thickness: B [m].  length: L [m].
        position: ``centred`` (one line) or ``external`` (one line per face).
        diameter: d [mm]; ``bar_area`` [mm²] defaults to π·d²/4.
        min_spacing, max_spacing: the spacing rule [m] (module docstring).
        bar_length: length of one bar [m] (the free length H plus the two anchorages).
        density: [kg/m³].  price: [currency/kg].
        installation_per_metre: per metre of wall and line, as in ``assess.quantities``.
    """
    if not ratio > 0:
        raise ValueError(f"ratio must be > 0 ‰, got {ratio}")
    if not (thickness > 0 and length > 0 and diameter > 0):
        raise ValueError("thickness, length and diameter must be > 0")
    if not 0 < min_spacing <= max_spacing:
        raise ValueError(f"need 0 < min_spacing <= max_spacing, got {min_spacing}, {max_spacing}")
    lines = rule.faces(position)
    a_b = nominal_area(diameter) if bar_area is None else bar_area
    if not a_b > 0:
        raise ValueError(f"bar_area must be > 0 mm², got {a_b}")
    needed = ratio * thickness * length * 1e3  # [mm²] per line: ρ‰·B·L
    # round up to whole bars; the relative tolerance keeps an exact fit from gaining a bar
    n_ratio = math.ceil(needed / a_b * (1.0 - 1e-12))
    n_spacing = math.ceil(length / max_spacing * (1.0 - 1e-12))
    n = max(n_ratio, n_spacing, 1)
    governed = "ratio" if n_ratio >= n_spacing else "max_spacing"
    s = length / n
    fits = s >= min_spacing * (1.0 - 1e-12)
    installed = n * a_b / (thickness * length * 1e3)
    total = n * lines
    metres = None if bar_length is None else total * bar_length
    mass = None if metres is None or density is None else metres * a_b * 1e-6 * density
    cost = (
        None
        if mass is None or price is None
        else (mass * price + installation_per_metre * length * lines)
    )
    per = "per face" if lines == 2 else "one line"
    note = (
        f"{n} x Ø{diameter:g} {per} at {s:.3f} m, installed {installed:.3f} ‰ for "
        f"{ratio:.3f} ‰ asked ({governed.replace('_', ' ')})"
    )
    if not fits:
        note += f"; spacing below {min_spacing:g} m: choose a larger diameter"
    return BarLayout(
        diameter=diameter,
        bar_area=a_b,
        position=position,
        lines=lines,
        bars_per_line=n,
        spacing=s,
        ratio_asked=ratio,
        ratio_installed=installed,
        governed_by=governed,
        fits=fits,
        total_bars=total,
        bar_length=bar_length,
        metres=metres,
        mass=mass,
        cost=cost,
        note=note,
    )


def best_layout(
    ratio: float,
    thickness: float,
    length: float,
    position: Position,
    sizes: Iterable[BarSize],
    min_spacing: float = DEFAULT_MIN_SPACING,
    max_spacing: float = DEFAULT_MAX_SPACING,
) -> BarLayout | None:
    """Of the sizes that fit the spacing rule, the one installing the least ratio (ties: the
    smaller diameter, the more uniform restraint); ``None`` if no size fits."""
    layouts = [
        bar_layout(
            ratio,
            thickness,
            length,
            position,
            s.diameter,
            min_spacing,
            max_spacing,
            bar_area=s.area,
        )
        for s in sizes
    ]
    fitting = [lay for lay in layouts if lay.fits]
    if not fitting:
        return None
    return min(fitting, key=lambda lay: (round(lay.ratio_installed, 12), lay.diameter))
