"""The retrofit as it will be built, per option and per design-mode answer (results.json).

Stdlib only.  Field names are the JSON keys, in the order written; units are in each
docstring (docs/model.md §2.1 gives the rules behind the numbers).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class BarStrain:
    """The rupture strain the model uses and the factors that give it.

    Attributes:
        design_values: True: ``rupture_strain`` = c·η_a·ε_fk/γ_f; False: c·ε_u (mean values).
        mean: ε_u, the producer's mean rupture strain [-].
        characteristic: ε_fk, 5 % fractile [-] (None without design values).
        characteristic_source: where ε_fk comes from (given, or derived from ε_u with a CoV).
        fibre: the fibre whose η_a is taken (glass, carbon, aramid), None without design values.
        exposure: internal | external | aggressive (None without design values).
        eta_a: environmental conversion factor η_a [-] (CNR-DT 200 R1/2013 Table 3.2).
        partial_factor: γ_f [-] (CNR-DT 200 R1/2013 Table 3.1, rupture of FRP).
        cyclic_factor: c [-] (``analysis.strain_factor``).
        rupture_strain: the strain at which the model breaks the bar [-].
        rule: the formula in words.
    """

    design_values: bool
    mean: float
    characteristic: float | None
    characteristic_source: str | None
    fibre: str | None
    exposure: str | None
    eta_a: float | None
    partial_factor: float | None
    cyclic_factor: float
    rupture_strain: float
    rule: str


@dataclass(frozen=True)
class BarAnchorage:
    """What one bar's ends must carry, and the bond and pull-out checks when they can be made.

    Attributes:
        design_force: force in one bar at the model's rupture strain, A_b·E·ε [kN].
        end_plate_force: force an end plate (or any mechanical anchorage) must carry [kN]
            (equal to ``design_force``).
        hole_diameter: d_h [mm] (None: no ``bars.anchorage``).
        bond_bar: τ_b [MPa].  bond_masonry: τ_m [MPa].
        length_bar: F/(π·d·τ_b) [m].  length_masonry: F/(π·d_h·τ_m) [m].
        length_required: the larger, the bond length needed at each end [m].
        cone_area: projected area of the 45° pull-out cone, clipped by the faces and by the
            neighbouring bars [m²].
        tensile_strength: f_t of the masonry [MPa].
        cone_resistance: f_t·cone_area [kN].
        cone_ok: cone_resistance ≥ design_force (None: not checked).
        note: one line for the report.
    """

    design_force: float
    end_plate_force: float
    hole_diameter: float | None
    bond_bar: float | None
    bond_masonry: float | None
    length_bar: float | None
    length_masonry: float | None
    length_required: float | None
    cone_area: float | None
    tensile_strength: float | None
    cone_resistance: float | None
    cone_ok: bool | None
    note: str


@dataclass(frozen=True)
class AsBuilt:
    """The bars of one option over the whole wall.

    Attributes:
        material: bar material key.  position: centred | external.
        diameter: d [mm].  bar_area: nominal area A_b [mm²].
        diameter_rule: ``given`` (the option's ``diameter``) or ``least installed ratio``.
        lines: lines of bars, 1 centred, 2 external (one per face).
        bars_per_line: whole bars in each line.  total_bars: bars_per_line·lines.
        spacing: between bar axes in each line [m] (per face when external); the end bars
            sit spacing/2 from the wall's ends.
        min_spacing, max_spacing: the spacing rule [m].
        governed_by: ``ratio`` (area rounded up) or ``max_spacing``.
        ratio_asked: ρ asked [‰].  ratio_installed: n·A_b/(B·L) [‰] per line.
        ratio_model: the ρ the model uses [‰] (installed, or asked with
            ``bars.whole_bars: false``).
        bar_length: one bar: H + 2·bond length when known, else H [m].
        metres: total length of bar [m].  mass: [kg].  cost: bars + installation [currency].
        currency: of ``cost``.
        strain: the rupture strain and its factors.
        anchorage: the bar force and its anchorage.
        note: one line for the report.
    """

    material: str
    position: str
    diameter: float
    bar_area: float
    diameter_rule: str
    lines: int
    bars_per_line: int
    total_bars: int
    spacing: float
    min_spacing: float
    max_spacing: float
    governed_by: str
    ratio_asked: float
    ratio_installed: float
    ratio_model: float
    bar_length: float
    metres: float
    mass: float
    cost: float
    currency: str
    strain: BarStrain
    anchorage: BarAnchorage
    note: str
