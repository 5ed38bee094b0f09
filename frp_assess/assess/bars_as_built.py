"""The bars of each option as they will be built (docs/model.md §2.1).

From an option's material, position and ratio to whole bars of a catalogue diameter over the
wall (:func:`choose_layout`), and from those bars to the typed record of results.json
(:class:`~frp_assess.results.as_built.AsBuilt`): installed ratio, quantities and cost, the
rupture strain and its factors, the design force per bar and its anchorage.

Diameter rule when an option gives none: of the sizes of its material (the built-in nominal
diameters Ø6–Ø16 with the project's ``bars.catalogue`` added) that keep the spacing within
``bars.min_spacing``–``bars.max_spacing``, the one installing the least ratio; ties go to the
smaller diameter (a more uniform restraint).  A material without catalogue sizes (a new
material not listed under ``bars.catalogue``) takes the nominal diameters Ø6–Ø16.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Protocol

from frp_assess.assess.bar_anchorage import Anchorage, anchorage, bar_rupture_force
from frp_assess.assess.bar_catalogue import (
    BAR_CATALOGUE,
    BarLayout,
    BarSize,
    bar_layout,
    bar_size,
    bar_sizes,
    best_layout,
    nominal_area,
)
from frp_assess.assess.bar_strain import fibre_of
from frp_assess.assess.inputs import AssessmentInputs, BarSettings, Material, RetrofitOption
from frp_assess.assess.masonry_strength import MASONRY_TABLE, masonry_design_values
from frp_assess.dynamics import Position
from frp_assess.errors import InputError
from frp_assess.results.as_built import AsBuilt, BarAnchorage, BarStrain
from frp_assess.rules.bars import FRP_RUPTURE_PARTIAL_FACTOR, MAX_RATIO


class DesignAnswer(Protocol):
    """What :func:`design_as_built` reads of a design-mode answer (the runner's
    ``DesignResult``; a protocol, so that this module does not import the runner)."""

    @property
    def material(self) -> Material: ...
    @property
    def layout(self) -> BarLayout | None: ...
    @property
    def ratio_model(self) -> float | None: ...


#: f_t = this factor × τ0d for the pull-out cone (Turnšek–Čačovič, assess/bar_anchorage.py)
TENSILE_OVER_SHEAR = 1.5

#: the built-in nominal diameters [mm] (those of the catalogue)
NOMINAL_DIAMETERS: tuple[float, ...] = tuple(s.diameter for s in BAR_CATALOGUE["GFRP"])

DIAMETER_GIVEN = "given"
DIAMETER_CHOSEN = "least installed ratio"


def sizes_for(bars: BarSettings, material: str) -> tuple[BarSize, ...]:
    """The bar sizes of ``material``: the catalogue's with the project's added (a project
    size of the same diameter replaces the catalogue's); a material with neither takes the
    nominal diameters Ø6–Ø16 (area π·d²/4)."""
    own = [s for s in bars.catalogue if s.material == material]
    if material not in BAR_CATALOGUE and not own:
        own = [BarSize(material, d, nominal_area(d)) for d in NOMINAL_DIAMETERS]
    return bar_sizes(material, own)


def choose_layout(
    bars: BarSettings,
    thickness: float,
    length: float,
    material: str,
    position: Position,
    ratio: float,
    diameter: float | None = None,
) -> BarLayout:
    """Whole bars installing at least ``ratio`` [‰] over a wall B × L [m] (module docstring).

    Raises:
        InputError: the diameter is not a size of the material (key ``diameter``), or no size
            installs the ratio within the spacing rule (key ``ratio``); the message says what
            can be installed.
    """
    lay = _choose_layout(bars, thickness, length, material, position, ratio, diameter)
    if lay.ratio_installed > MAX_INSTALLED_RATIO:  # the model's range (dynamics.rebars)
        raise InputError(
            f"{ratio:g} ‰ is built as {lay.ratio_installed:.3g} ‰ (the fewest bars "
            f"Ø{lay.diameter:g} within bars.max_spacing = {bars.max_spacing:g} m on a wall "
            f"{thickness:g} m thick), more than the model's {MAX_INSTALLED_RATIO:g} ‰; widen "
            "bars.max_spacing or use smaller bars",
            key="ratio",
        )
    return lay


#: the largest ratio [‰] the rocking model takes
MAX_INSTALLED_RATIO = MAX_RATIO


def _choose_layout(
    bars: BarSettings,
    thickness: float,
    length: float,
    material: str,
    position: Position,
    ratio: float,
    diameter: float | None = None,
) -> BarLayout:
    sizes = sizes_for(bars, material)
    if diameter is not None:
        try:
            size = bar_size(material, diameter, sizes)
        except InputError as exc:
            raise InputError(exc.message, key="diameter") from None
        lay = bar_layout(
            ratio,
            thickness,
            length,
            position,
            size.diameter,
            bars.min_spacing,
            bars.max_spacing,
            bar_area=size.area,
        )
        if not lay.fits:
            raise InputError(
                f"{ratio:g} ‰ needs {lay.bars_per_line} bars Ø{diameter:g} per line at "
                f"{lay.spacing:.3f} m, closer than bars.min_spacing = {bars.min_spacing:g} m; "
                "choose a larger diameter",
                key="diameter",
            )
        return lay
    best = best_layout(
        ratio, thickness, length, position, sizes, bars.min_spacing, bars.max_spacing
    )
    if best is None:
        top = max(sizes, key=lambda s: s.area)
        n_max = math.floor(length / bars.min_spacing * (1.0 + 1e-12))
        most = n_max * top.area / (thickness * length * 1e3)
        raise InputError(
            f"{ratio:g} ‰ cannot be installed: the largest {material} bar (Ø{top.diameter:g}) "
            f"at bars.min_spacing = {bars.min_spacing:g} m gives {most:.3g} ‰; add larger "
            "sizes under bars.catalogue or lower the ratio",
            key="ratio",
        )
    return best


def option_with_layout(inputs: AssessmentInputs, option: RetrofitOption) -> RetrofitOption:
    """``option`` with its layout, ``ratio`` = the ratio the model uses (installed with
    ``bars.whole_bars``) and ``ratio_asked`` = the option's ratio.

    With ``bars.whole_bars`` an option that cannot be built is an InputError (as
    :func:`choose_layout`); without, the model uses the ratio asked anyway (the paper's
    smeared idealisation) and such an option has no layout (``layout`` None).  A tie alone
    has no bars: returned as it is.
    """
    if option.material is None or option.position is None:
        return option
    asked = option.asked
    try:
        lay = choose_layout(
            inputs.bars,
            inputs.thickness,
            inputs.length,
            option.material.name,
            option.position,
            asked,
            option.diameter,
        )
    except InputError:
        if inputs.bars.whole_bars:
            raise
        return replace(option, ratio=asked, ratio_asked=asked, layout=None)
    used = lay.ratio_installed if inputs.bars.whole_bars else asked
    return replace(option, ratio=used, ratio_asked=asked, layout=lay)


#: the fraction by which the ratio installed in whole bars may differ from the ratio asked
#: without a warning.  Whole bars of the least-ratio diameter round the area up by less than
#: one bar: for the ratios of practice (0.5-5 ‰) on a wall a metre or more long that is a few
#: per cent (the golden projects: 0-0.5 %); beyond a quarter the bars are governed by
#: bars.max_spacing or by a given diameter (0.1 ‰ asked, built as Ø16 at 0.67 ‰), and the
#: wall is assessed with a quarter more (or less) restraint than the engineer wrote
AS_BUILT_TOLERANCE = 0.25


def as_built_difference(option: RetrofitOption, *, whole_bars: bool) -> str | None:
    """One warning line when the bars of ``option`` as built install a ratio more than
    :data:`AS_BUILT_TOLERANCE` away from the ratio asked (relative), else None (also for an
    option without a layout)."""
    lay = option.layout
    asked = option.asked
    if lay is None or abs(lay.ratio_installed - asked) <= AS_BUILT_TOLERANCE * asked:
        return None
    used = "the model uses it" if whole_bars else "the model uses the ratio asked"
    why = "bars.max_spacing" if lay.governed_by == "max_spacing" else "the area of whole bars"
    bars = f"{lay.bars_per_line} bar{'' if lay.bars_per_line == 1 else 's'}"
    return (
        f"{option.name}: {asked:g} ‰ is built as {bars} Ø{lay.diameter:g} "
        f"per line at {lay.spacing:.3g} m, {lay.ratio_installed:.3g} ‰ "
        f"({lay.ratio_installed / asked:.3g} times the ratio asked, more than "
        f"{AS_BUILT_TOLERANCE:.0%} off; governed by {why}); {used}: check the ratio, the "
        "diameter and bars.max_spacing"
    )


def largest_installable_ratio(
    bars: BarSettings, thickness: float, length: float, material: str
) -> float:
    """The largest ρ [‰] any size of ``material`` installs at the smallest spacing."""
    n_max = max(1, math.floor(length / bars.min_spacing * (1.0 + 1e-12)))
    top = max(s.area for s in sizes_for(bars, material))
    return n_max * top / (thickness * length * 1e3)


# ---------------------------------------------------------------------------------------------
# The typed record


def bar_strain(inputs: AssessmentInputs, material: Material) -> BarStrain:
    """The rupture strain of ``material`` in the model and its factors."""
    c = inputs.strain_factor
    d = inputs.design_strain(material)
    if d is None:
        return BarStrain(
            design_values=False,
            mean=material.ultimate_strain,
            characteristic=None,
            characteristic_source=None,
            fibre=None,
            exposure=None,
            eta_a=None,
            partial_factor=None,
            cyclic_factor=c,
            rupture_strain=inputs.rupture_strain(material),
            rule="c*eps_u: mean producer value, no design factors (bars.design_values: false)",
        )
    return BarStrain(
        design_values=True,
        mean=material.ultimate_strain,
        characteristic=d.characteristic,
        characteristic_source=material.characteristic_source,
        fibre=fibre_of(material.name, material.fibre),
        exposure=d.exposure,
        eta_a=d.eta_a,
        partial_factor=d.partial_factor,
        cyclic_factor=d.cyclic_factor,
        rupture_strain=inputs.rupture_strain(material),
        rule=(
            "c*eta_a*eps_fk/gamma_f (CNR-DT 200 R1/2013 §3.5: eta_a Table 3.2, "
            f"gamma_f = {FRP_RUPTURE_PARTIAL_FACTOR:g} Table 3.1; c = analysis.strain_factor)"
        ),
    )


def masonry_tensile_strength(inputs: AssessmentInputs) -> float | None:
    """f_t [MPa] for the pull-out cone: ``bars.anchorage.tensile_strength``, else
    1.5·τ0d of ``wall.masonry`` at the knowledge level (Circolare 2019 Tab. C8.5.I, FC),
    else None (no cone check)."""
    a = inputs.bars.anchorage
    if a is not None and a.tensile_strength is not None:
        return a.tensile_strength
    if inputs.masonry is None or inputs.masonry not in MASONRY_TABLE:
        return None
    values = masonry_design_values(inputs.masonry, inputs.code_check.knowledge_level)
    return TENSILE_OVER_SHEAR * values.tau_0d


def bar_anchorage(inputs: AssessmentInputs, material: Material, lay: BarLayout) -> BarAnchorage:
    """The design force per bar at the model's rupture strain and, with ``bars.anchorage``,
    its bond length and pull-out cone (assess/bar_anchorage.py)."""
    force = bar_rupture_force(
        lay.bar_area, material.elastic_modulus, inputs.rupture_strain(material)
    )
    a = inputs.bars.anchorage
    if a is None:
        return BarAnchorage(
            force, force, None, None, None, None, None, None, None, None, None, None,
            f"{force:.1f} kN per bar at rupture (end plate or anchorage); give bars.anchorage "
            "for the bond length and the pull-out cone",
        )  # fmt: skip
    hole = lay.diameter + a.hole_clearance
    f_t = masonry_tensile_strength(inputs)
    anc: Anchorage = anchorage(
        force,
        lay.diameter,
        hole_diameter=hole,
        bond_bar=a.bond_bar,
        bond_masonry=a.bond_masonry,
        tensile_strength=f_t if f_t is not None else 1.0,
        thickness=inputs.thickness,
        spacing=lay.spacing,
        position=lay.position,  # type: ignore[arg-type]
        axis_to_face=0.5 * hole * 1e-3,
    )
    note = f"{force:.1f} kN per bar; bond length {anc.length_required:.3f} m"
    if f_t is None:
        note += "; pull-out cone not checked (give wall.masonry or bars.anchorage.tensile_strength)"
    else:
        verdict = "OK" if anc.cone_ok else "FAILS"
        note += f"; pull-out cone {anc.cone_resistance:.1f} kN {verdict}"
    return BarAnchorage(
        design_force=force,
        end_plate_force=force,
        hole_diameter=hole,
        bond_bar=a.bond_bar,
        bond_masonry=a.bond_masonry,
        length_bar=anc.length_bar,
        length_masonry=anc.length_masonry,
        length_required=anc.length_required,
        cone_area=None if f_t is None else anc.cone_area,
        tensile_strength=f_t,
        cone_resistance=None if f_t is None else anc.cone_resistance,
        cone_ok=None if f_t is None else anc.cone_ok,
        note=note,
    )


def as_built(
    inputs: AssessmentInputs,
    material: Material,
    lay: BarLayout,
    ratio_model: float,
    diameter_rule: str,
) -> AsBuilt:
    """The typed record of one layout (quantities over the bar length, see AsBuilt)."""
    anc = bar_anchorage(inputs, material, lay)
    bar_length = inputs.height + 2.0 * (anc.length_required or 0.0)
    full = bar_layout(
        lay.ratio_asked,
        inputs.thickness,
        inputs.length,
        lay.position,  # type: ignore[arg-type]
        lay.diameter,
        inputs.bars.min_spacing,
        inputs.bars.max_spacing,
        bar_area=lay.bar_area,
        bar_length=bar_length,
        density=material.density,
        price=material.price,
        installation_per_metre=inputs.costs.installation_per_metre,
    )
    assert full.metres is not None and full.mass is not None and full.cost is not None
    return AsBuilt(
        material=material.name,
        position=lay.position,
        diameter=lay.diameter,
        bar_area=lay.bar_area,
        diameter_rule=diameter_rule,
        lines=lay.lines,
        bars_per_line=lay.bars_per_line,
        total_bars=lay.total_bars,
        spacing=lay.spacing,
        min_spacing=inputs.bars.min_spacing,
        max_spacing=inputs.bars.max_spacing,
        governed_by=lay.governed_by,
        ratio_asked=lay.ratio_asked,
        ratio_installed=lay.ratio_installed,
        ratio_model=ratio_model,
        bar_length=bar_length,
        metres=full.metres,
        mass=full.mass,
        cost=full.cost,
        currency=inputs.costs.currency,
        strain=bar_strain(inputs, material),
        anchorage=anc,
        note=lay.note,
    )


def option_as_built(inputs: AssessmentInputs, option: RetrofitOption) -> AsBuilt | None:
    """The as-built record of an option (its layout made here if it has none); None for an
    option that cannot be built, which only ``bars.whole_bars: false`` lets through."""
    if option.layout is None:
        option = option_with_layout(inputs, option)
    if option.layout is None or option.material is None:
        return None  # cannot be built, or a tie alone (no bars)
    rule = DIAMETER_GIVEN if option.diameter is not None else DIAMETER_CHOSEN
    return as_built(inputs, option.material, option.layout, option.ratio, rule)


def design_as_built(inputs: AssessmentInputs, result: DesignAnswer) -> AsBuilt | None:
    """The as-built record of a design-mode answer (None when no ratio met the target)."""
    if result.layout is None or result.ratio_model is None:
        return None
    return as_built(inputs, result.material, result.layout, result.ratio_model, DIAMETER_CHOSEN)
