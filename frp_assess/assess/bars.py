"""Bars as they are built: catalogue, layout over the wall, design strain, anchorage.

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

**Design strain** (CNR-DT 200 R1/2013 §3, design values of the FRP): ε_d = c·η_a·ε_fk/γ_f, with
the characteristic rupture strain ε_fk (5 % fractile), the environmental conversion factor η_a
of Table 3.2 (:data:`ENVIRONMENTAL_FACTORS`), the partial factor γ_f = 1.10 for the rupture of
FRP (Table 3.1) and the cyclic reduction c = 0.5 of ``docs/model.md`` §2.  The values of η_a
are those of CNR-DT 200 R1/2013 Table 3.2 (they coincide with the environmental reduction
factors C_E of ACI 440.2R).  Basalt is not in the table: BFRP takes the glass values, the fibre
whose alkali and moisture sensitivity is closest (a conservative choice).

**Anchorage.** The design force per bar at rupture is F = A_b·E·ε (A_b [mm²]·E [GPa]·ε gives
kN).  A bar bonded in a resin-filled hole of diameter d_h needs the bond length

    l_b = max( F / (π·d·τ_b),  F / (π·d_h·τ_m) )

for the bar–resin interface (bond strength τ_b) and the resin–masonry interface (τ_m): the
equilibrium of a uniform bond stress along the bar, the form of the anchorage length of
FRP bars in CNR-DT 203/2006 and ACI 440.1R (l_b = d·f/(4·τ)).  The bond strengths come from
the producer's tests (τ_b) and from pull-out tests on the masonry (τ_m); they are inputs,
no default is assumed.  The masonry pull-out cone is a check: a 45° cone from the end of
the bond length, projected area π·l_b² (TMS 402 anchor bolts in masonry, A_pt = π·l_b²),
clipped by the faces of the wall and shared with the neighbouring bars (its base is limited
to the strip of width s around the bar), with the tensile strength f_t = 1.5·τ0d of the
masonry (the Turnšek–Čačovič relation behind the diagonal-cracking shear strength of
Circolare 2019 §C8.7.1).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Literal

from scipy.integrate import quad

from frp_assess.dynamics import Position
from frp_assess.errors import InputError
from frp_assess.rules import bars as rule
from frp_assess.rules.bars import DEFAULT_STRAIN_FACTOR
from frp_assess.rules.bars import FRP_RUPTURE_PARTIAL_FACTOR as FRP_RUPTURE_PARTIAL_FACTOR
from frp_assess.rules.bars import characteristic_strain as characteristic_strain  # re-export

Exposure = Literal["internal", "external", "aggressive"]
EXPOSURES: tuple[str, ...] = ("internal", "external", "aggressive")

#: Default smallest and largest spacing between the axes of bars in one line [m].
DEFAULT_MIN_SPACING = 0.10
DEFAULT_MAX_SPACING = 1.0

#: Cyclic reduction of the rupture strain, c (``docs/model.md`` §2; the rules' default).
CYCLIC_FACTOR = DEFAULT_STRAIN_FACTOR

#: η_a by fibre and exposure (CNR-DT 200 R1/2013 Table 3.2).
ENVIRONMENTAL_FACTORS: dict[str, dict[str, float]] = {
    "glass": {"internal": 0.75, "external": 0.65, "aggressive": 0.50},
    "carbon": {"internal": 0.95, "external": 0.85, "aggressive": 0.85},
    "aramid": {"internal": 0.85, "external": 0.75, "aggressive": 0.70},
}

#: Fibre of each bar material; basalt is not in Table 3.2 and takes the glass values.
FIBRE_OF_MATERIAL: dict[str, str] = {
    "GFRP": "glass",
    "CFRP": "carbon",
    "AFRP": "aramid",
    "BFRP": "glass",
}


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


# ---------------------------------------------------------------------------------------------
# Design strain


def fibre_of(material: str, fibre: str | None = None) -> str:
    """The fibre whose η_a a bar material takes: ``fibre`` when given (basalt: the glass
    values, module docstring), else by the library key, else glass (the smallest η_a of the
    table: the conservative choice for a fibre not stated)."""
    if fibre is not None:
        return "glass" if fibre == "basalt" else fibre
    return FIBRE_OF_MATERIAL.get(material, "glass")


def environmental_factor(material: str, exposure: str, *, fibre: str | None = None) -> float:
    """η_a of CNR-DT 200 R1/2013 Table 3.2 for a bar material (GFRP, BFRP, CFRP, AFRP), or
    for the ``fibre`` given (glass, carbon, aramid, basalt)."""
    if fibre is not None:
        fibre = fibre_of(material, fibre)
    else:
        fibre = FIBRE_OF_MATERIAL.get(material)
    if fibre is None or fibre not in ENVIRONMENTAL_FACTORS:
        raise InputError(
            f"no environmental factor for {material!r}; known: {', '.join(FIBRE_OF_MATERIAL)}",
            key="materials",
        )
    if exposure not in EXPOSURES:
        raise InputError(
            f"unknown exposure {exposure!r}; choose one of: {', '.join(EXPOSURES)}",
            key="exposure",
        )
    return ENVIRONMENTAL_FACTORS[fibre][exposure]


#: CoV of the rupture strain assumed when the producer gives no characteristic value
#: (an assumption of this tool, on the safe side of the scatter of tension tests on FRP bars)
DEFAULT_STRAIN_COV = 0.10


@dataclass(frozen=True)
class DesignStrain:
    """ε_d = c·η_a·ε_fk/γ_f and its factors.

    Attributes:
        characteristic: ε_fk [-].  eta_a: η_a [-].  partial_factor: γ_f [-].
        cyclic_factor: c [-].  exposure: internal, external or aggressive.
        design: ε_d [-].
    """

    characteristic: float
    eta_a: float
    partial_factor: float
    cyclic_factor: float
    exposure: str
    design: float

    @property
    def fd(self) -> float:
        """ε_fd = η_a·ε_fk/γ_f [-], the design strain before the cyclic reduction c."""
        return rule.fd_strain(self.characteristic, self.eta_a, self.partial_factor)


def design_rupture_strain(
    characteristic: float,
    material: str,
    exposure: str,
    *,
    cyclic_factor: float = CYCLIC_FACTOR,
    partial_factor: float = FRP_RUPTURE_PARTIAL_FACTOR,
    fibre: str | None = None,
) -> DesignStrain:
    """The rupture strain the analysis uses: ε_d = c·η_a·ε_fk/γ_f (module docstring);
    ``fibre`` as :func:`environmental_factor`."""
    if not characteristic > 0:
        raise ValueError(f"characteristic strain must be > 0, got {characteristic}")
    if not (0 < cyclic_factor <= 1 and partial_factor >= 1):
        raise ValueError(f"need 0 < c <= 1 and gamma_f >= 1, got {cyclic_factor}, {partial_factor}")
    eta = environmental_factor(material, exposure, fibre=fibre)
    return DesignStrain(
        characteristic=characteristic,
        eta_a=eta,
        partial_factor=partial_factor,
        cyclic_factor=cyclic_factor,
        exposure=exposure,
        design=rule.design_rupture_strain(characteristic, eta, cyclic_factor, partial_factor),
    )


# ---------------------------------------------------------------------------------------------
# Anchorage


def bar_rupture_force(bar_area: float, elastic_modulus: float, strain: float) -> float:
    """Force in one bar, F = A_b·E·ε [kN] (A_b [mm²], E [GPa]: mm²·GPa = kN)."""
    return rule.bar_force(elastic_modulus, bar_area, strain)


def cone_area(radius: float, face_distances: tuple[float, float], spacing: float) -> float:
    """Projected area [m²] of a cone base of ``radius`` [m] around a bar, clipped to the wall
    (``face_distances`` [m] from the bar's axis to each face) and to the strip of width
    ``spacing`` [m] it shares with its neighbours."""
    if not (radius >= 0 and spacing > 0 and min(face_distances) >= 0):
        raise ValueError("radius, face distances must be >= 0 and spacing > 0")
    a = max(-face_distances[0], -radius)
    b = min(face_distances[1], radius)
    if b <= a:
        return 0.0
    half = 0.5 * spacing

    def width(x: float) -> float:
        return 2.0 * min(math.sqrt(max(radius * radius - x * x, 0.0)), half)

    points = []
    if half < radius:
        x_k = math.sqrt(radius * radius - half * half)
        points = [p for p in (-x_k, x_k) if a < p < b]
    value, _ = quad(width, a, b, points=points or None, limit=200)
    return value


@dataclass(frozen=True)
class Anchorage:
    """Anchorage of one bar in a resin-filled hole, and the masonry pull-out cone check.

    Attributes:
        force: F [kN].
        length_bar: F/(π·d·τ_b) [m].  length_masonry: F/(π·d_h·τ_m) [m].
        length_required: the larger [m].  length: the length provided [m] (the required one
            unless given).
        cone_area: projected area of the 45° cone [m²].
        tensile_strength: f_t [MPa].
        cone_resistance: f_t·area [kN].
        cone_ok: cone_resistance ≥ F.
        length_ok: length ≥ length_required.
    """

    force: float
    length_bar: float
    length_masonry: float
    length_required: float
    length: float
    cone_area: float
    tensile_strength: float
    cone_resistance: float
    cone_ok: bool
    length_ok: bool


def anchorage(
    force: float,
    diameter: float,
    *,
    hole_diameter: float,
    bond_bar: float,
    bond_masonry: float,
    tensile_strength: float,
    thickness: float,
    spacing: float,
    position: Position,
    axis_to_face: float = 0.0,
    length: float | None = None,
) -> Anchorage:
    """Bond length and pull-out cone for a bar force ``force`` [kN] (module docstring).

    Args:
        diameter: d [mm].  hole_diameter: d_h [mm] (≥ d).
        bond_bar: τ_b, bar–resin [MPa].  bond_masonry: τ_m, resin–masonry [MPa].
        tensile_strength: f_t of the masonry [MPa], e.g. 1.5·τ0d.
        thickness: B [m].  spacing: s between bars of the line [m].
        position: ``centred`` (axis at B/2) or ``external`` (axis ``axis_to_face`` [m] from
            its face, e.g. half the groove depth).
        length: bond length provided [m]; the required length when omitted.
    """
    if not (force >= 0 and diameter > 0 and hole_diameter >= diameter):
        raise ValueError("need force >= 0, diameter > 0 and hole_diameter >= diameter")
    if not (bond_bar > 0 and bond_masonry > 0 and tensile_strength > 0):
        raise ValueError("bond strengths and tensile strength must be > 0 MPa")
    newton = force * 1e3
    l_bar = newton / (math.pi * diameter * bond_bar) * 1e-3  # N / (mm·MPa) = mm → m
    l_mas = newton / (math.pi * hole_diameter * bond_masonry) * 1e-3
    required = max(l_bar, l_mas)
    provided = required if length is None else length
    if position == "centred":
        faces = (0.5 * thickness, 0.5 * thickness)
    elif position == "external":
        if not 0 <= axis_to_face <= thickness:
            raise ValueError(f"axis_to_face must be within the wall, got {axis_to_face}")
        faces = (axis_to_face, thickness - axis_to_face)
    else:
        raise ValueError(f"position must be 'centred' or 'external', got {position!r}")
    area = cone_area(provided, faces, spacing)
    resistance = tensile_strength * 1e3 * area  # MPa·m² = MN → kN
    return Anchorage(
        force=force,
        length_bar=l_bar,
        length_masonry=l_mas,
        length_required=required,
        length=provided,
        cone_area=area,
        tensile_strength=tensile_strength,
        cone_resistance=resistance,
        cone_ok=bool(resistance >= force),
        length_ok=bool(provided >= required * (1.0 - 1e-12)),
    )
