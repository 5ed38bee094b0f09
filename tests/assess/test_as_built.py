"""Bars as they are built, wired into the assessment (docs/model.md §2.1).

Every expected number is a hand calculation written in the test.  Environmental conversion
factors typed from CNR-DT 200 R1/2013 Table 3.2 (η_a internal / external / aggressive):
glass 0.75 / 0.65 / 0.50, carbon 0.95 / 0.85 / 0.85; γ_f = 1.10 for FRP rupture (Table 3.1).
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest

from frp_assess.assess.bar_catalogue import BarSize
from frp_assess.assess.bars_as_built import (
    choose_layout,
    design_as_built,
    largest_installable_ratio,
    option_as_built,
)
from frp_assess.assess.cache import task_key
from frp_assess.assess.from_project import inputs_from_project
from frp_assess.assess.inputs import AnchorageSettings, BarSettings, DesignRequest
from frp_assess.assess.quantities import option_quantity
from frp_assess.assess.runner import CaseSummary, design_search
from frp_assess.config import load_project_text
from frp_assess.dynamics import IdaResult, IdaSettings, RockingModel, ida
from frp_assess.errors import InputError
from tests.conftest import synthetic_record

BASE = """\
wall: {{thickness: {b}, height: 3.0, length: {length}, masonry: solid-brick-lime-mortar,
       mechanism: two-sided}}
seismic:
  spectrum: {{type: preset, name: A2}}
  records: {{artificial: {{count: 1, seed: 1, duration: 14.0, dt: 0.01}}}}
interventions:
{options}
{extra}
"""


def inputs_of(options: str, *, b: float = 0.2, length: float = 1.0, extra: str = "") -> Any:
    text = BASE.format(b=b, length=length, options=options, extra=extra)
    loaded = load_project_text(text, "p.yaml", base_dir=Path("."))
    return inputs_from_project(loaded.project, Path("."), "p.yaml", lines=loaded.lines)


# ------------------------------------------------------------------------------ layout


def test_layout_chooses_least_installed_ratio_and_the_smaller_diameter_on_a_tie():
    # ρ = 1 ‰, B = 0.25 m, L = 5 m: 1250 mm² per line.  Bars (round up), installed ratio:
    #   Ø6  28.27 mm²: 45 → 1272.3 mm² (1.0179 ‰)    Ø8  50.27: 25 → 1256.6 (1.0053 ‰)
    #   Ø10 78.54 mm²: 16 → 1256.6 mm² (1.0053 ‰)    Ø12 113.1: 12 → 1357.2 (1.0857 ‰)
    #   Ø14 153.9 mm²:  9 → 1385.4 mm² (1.1084 ‰)    Ø16 201.1:  7 → 1407.4 (1.1259 ‰)
    # Ø8 and Ø10 tie (25·π·16 = 16·π·25 = 400π mm²): the smaller diameter, Ø8 at 0.20 m.
    lay = choose_layout(BarSettings(), 0.25, 5.0, "GFRP", "centred", 1.0)
    assert lay.diameter == 8.0 and lay.bars_per_line == 25
    assert lay.spacing == pytest.approx(0.20)
    assert lay.ratio_installed == pytest.approx(400 * math.pi / 1250)
    external = choose_layout(BarSettings(), 0.25, 5.0, "GFRP", "external", 1.0)
    assert external.lines == 2 and external.total_bars == 50  # 25 per face


def test_layout_with_a_given_diameter_and_a_project_size():
    # Ø12 given: 1250/113.097 = 11.05 → 12 bars at 5/12 m
    lay = choose_layout(BarSettings(), 0.25, 5.0, "GFRP", "centred", 1.0, 12.0)
    assert lay.bars_per_line == 12 and lay.spacing == pytest.approx(5 / 12)
    # a producer's Ø12.7 of 126.7 mm²: 1250/126.7 = 9.87 → 10 bars, 1267 mm² (1.0136 ‰),
    # less than Ø8's 1.0053 ‰? no: 1.0136 > 1.0053, so the automatic choice stays Ø8
    own = BarSettings(catalogue=(BarSize("GFRP", 12.7, 126.7),))
    lay = choose_layout(own, 0.25, 5.0, "GFRP", "centred", 1.0, 12.7)
    assert lay.bars_per_line == 10 and lay.ratio_installed == pytest.approx(1267 / 1250)
    assert choose_layout(own, 0.25, 5.0, "GFRP", "centred", 1.0).diameter == 8.0


def test_layout_problems_are_input_errors():
    with pytest.raises(InputError, match="available: 6, 8, 10, 12, 14, 16") as exc:
        choose_layout(BarSettings(), 0.25, 5.0, "GFRP", "centred", 1.0, 13.0)
    assert exc.value.key == "diameter"
    # Ø6 at 3 ‰ on B = 0.4 m, L = 1 m: 1200/28.27 → 43 bars at 23 mm < 0.10 m
    with pytest.raises(InputError, match="closer than bars.min_spacing") as exc:
        choose_layout(BarSettings(), 0.4, 1.0, "GFRP", "centred", 3.0, 6.0)
    assert exc.value.key == "diameter"
    # largest installable: 10 bars Ø16 per metre at 0.10 m = 2010.6 mm² on B = 0.4: 5.03 ‰
    assert largest_installable_ratio(BarSettings(), 0.4, 1.0, "GFRP") == pytest.approx(
        10 * math.pi * 64 / 400
    )
    with pytest.raises(InputError, match="gives 5.03 ‰") as exc:
        choose_layout(BarSettings(), 0.4, 1.0, "GFRP", "centred", 6.0)
    assert exc.value.key == "ratio"


def test_a_new_material_takes_the_nominal_diameters():
    lay = choose_layout(BarSettings(), 0.25, 5.0, "MyBar", "centred", 1.0)
    assert lay.diameter == 8.0 and lay.bars_per_line == 25


# ------------------------------------------------------------------------- the project


def test_options_are_laid_out_and_keep_the_ratio_asked():
    # B = 0.2 m, L = 1 m, 1 ‰ with Ø12 given: 200 mm² → 2 bars = 226.19 mm² = 1.1310 ‰
    inputs = inputs_of("  - {material: GFRP, position: centred, ratio: 1.0, diameter: 12}")
    (o,) = inputs.options
    assert o.name == "GFRP centred 1‰ Ø12"
    assert o.ratio_asked == 1.0 and o.diameter == 12.0
    assert o.ratio == pytest.approx(2 * math.pi * 36 / 200)
    assert o.layout is not None and o.layout.bars_per_line == 2


def test_the_model_uses_the_installed_ratio():
    """An option asked at 1.0 ‰ that installs 1.131 ‰ is the model of an option asked at
    1.131 ‰: same bars, same cache key, same collapse multiplier on a record."""
    installed = 2 * math.pi * 36 / 200  # 1.1310 ‰, by hand as above
    inputs = inputs_of(
        "  - {material: GFRP, position: centred, ratio: 1.0, diameter: 12}\n"
        f"  - {{material: GFRP, position: centred, ratio: {installed!r}, diameter: 12}}"
    )
    m1, m2 = (inputs.model_for(o) for o in inputs.options)
    assert m1.rebars is not None and m1.rebars.ratio == pytest.approx(installed)
    settings = IdaSettings(tolerance=0.01)
    assert task_key(m1, "r", settings) == task_key(m2, "r", settings)
    acc = synthetic_record(3, duration=6.0, pga_g=0.3)
    r1, r2 = ida(m1, acc, 0.01, settings), ida(m2, acc, 0.01, settings)
    assert r1.collapse_multiplier == r2.collapse_multiplier
    # the ratio asked, smeared, is another model (whole_bars: false)
    smeared = inputs_of(
        "  - {material: GFRP, position: centred, ratio: 1.0, diameter: 12}",
        extra="bars: {whole_bars: false}",
    )
    (o,) = smeared.options
    assert o.ratio == 1.0 and o.layout is not None and o.layout.ratio_installed > 1.13
    assert task_key(smeared.model_for(o), "r", settings) != task_key(m1, "r", settings)


def test_design_strain_against_cnr_dt_200():
    # GFRP (library ε_u = 0.015, no producer ε_fk): ε_fk = 0.015·(1 − 1.645·0.10) = 0.0125325
    # exposure internal, glass: η_a = 0.75; γ_f = 1.10; c = 0.5 (analysis.strain_factor)
    # ε_d = 0.5·0.75·0.0125325/1.10 = 0.00427244
    inputs = inputs_of(
        "  - {material: GFRP, position: centred, ratio: 1.0}",
        extra="bars: {exposure: internal}",
    )
    (o,) = inputs.options
    e_d = 0.5 * 0.75 * 0.015 * (1 - 1.645 * 0.10) / 1.10
    assert inputs.rupture_strain(o.material) == pytest.approx(e_d)
    bars = inputs.model_for(o).rebars
    assert bars is not None  # c is applied once: c·(η_a·ε_fk/γ_f)
    assert bars.strain_factor * bars.ultimate_strain == pytest.approx(e_d)
    built = option_as_built(inputs, o)
    assert built is not None
    assert built.strain.eta_a == 0.75 and built.strain.partial_factor == 1.10
    assert built.strain.cyclic_factor == 0.5 and built.strain.fibre == "glass"
    # CFRP with the producer's ε_fk = 0.012, aggressive: η_a = 0.85 → 0.5·0.85·0.012/1.1
    carbon = inputs_of(
        "  - {material: CFRP, position: external, ratio: 1.0}",
        extra="bars: {exposure: aggressive}\nmaterials: {CFRP: {characteristic_strain: 0.012}}",
    )
    assert carbon.rupture_strain(carbon.options[0].material) == pytest.approx(
        0.5 * 0.85 * 0.012 / 1.10
    )
    # BFRP takes the glass values; a new material without fibre too (external: 0.65)
    basalt = inputs_of("  - {material: BFRP, position: centred, ratio: 1.0}")
    assert basalt.rupture_strain(basalt.options[0].material) == pytest.approx(
        0.5 * 0.65 * 0.020 * (1 - 0.1645) / 1.10
    )
    # design values off: c·ε_u, the mean producer value, as the paper
    mean = inputs_of(
        "  - {material: GFRP, position: centred, ratio: 1.0}", extra="bars: {design_values: false}"
    )
    assert mean.rupture_strain(mean.options[0].material) == pytest.approx(0.5 * 0.015)
    built = option_as_built(mean, mean.options[0])
    assert built is not None and built.strain.eta_a is None


def test_as_built_quantities_and_anchorage_by_hand():
    # B = 0.25 m, H = 3 m, L = 5 m, GFRP centred 1 ‰: 25 × Ø8 at 0.20 m (first test)
    # ε_d (external, default) = 0.5·0.65·0.0125325/1.1 = 0.00370278
    # F = 50.265 mm² · 46 GPa · ε_d = 8.5618 kN
    # d_h = 8 + 4 = 12 mm; l_bar = F/(π·8·8 MPa) = 0.042583 m; l_mas = F/(π·12·0.5) = 0.45422 m
    # bar length 3 + 2·0.45422 m; mass = 25 · 3.90844 m · 50.265e-6 m² · 2000 kg/m³
    # f_t = 1.5·τ0d: solid brick LC1 τ0 = 0.05 MPa (Tab. C8.5.I minimum), FC 1.35
    # cone: radius 0.454 m clipped to B/2 = 0.125 each side and to s/2 = 0.10: B·s = 0.05 m²
    inputs = inputs_of(
        "  - {material: GFRP, position: centred, ratio: 1.0}",
        b=0.25,
        length=5.0,
        extra="bars: {anchorage: {hole_clearance: 4, bond_bar: 8.0, bond_masonry: 0.5}}\n"
        "costs: {installation_per_metre: 100}",
    )
    (o,) = inputs.options
    built = option_as_built(inputs, o)
    assert built is not None
    e_d = 0.5 * 0.65 * 0.015 * (1 - 0.1645) / 1.10
    a_b = math.pi * 16
    force = a_b * 46 * e_d
    assert built.anchorage.design_force == pytest.approx(force)
    assert built.anchorage.end_plate_force == pytest.approx(force)
    assert built.anchorage.length_bar == pytest.approx(force / (math.pi * 8 * 8))
    l_mas = force / (math.pi * 12 * 0.5)
    assert built.anchorage.length_required == pytest.approx(l_mas)
    assert built.bar_length == pytest.approx(3 + 2 * l_mas)
    assert built.metres == pytest.approx(25 * (3 + 2 * l_mas))
    mass = 25 * (3 + 2 * l_mas) * a_b * 1e-6 * 2000
    assert built.mass == pytest.approx(mass)
    assert built.cost == pytest.approx(mass * 8.0 + 100 * 5.0)
    assert built.anchorage.tensile_strength == pytest.approx(1.5 * 0.05 / 1.35)
    assert built.anchorage.cone_area == pytest.approx(0.25 * 0.20)
    assert built.anchorage.cone_resistance == pytest.approx(1.5 * 0.05 / 1.35 * 1e3 * 0.05)
    assert built.anchorage.cone_ok is False  # 2.78 kN < 8.56 kN
    assert (built.ratio_asked, built.bars_per_line, built.diameter) == (1.0, 25, 8.0)
    assert option_quantity(inputs, o).mass == pytest.approx(mass)
    # without bars.anchorage: the bars over H only, no bond length
    plain = replace(inputs, bars=replace(inputs.bars, anchorage=None))
    bare = option_as_built(plain, o)
    assert bare is not None and bare.mass == pytest.approx(25 * 3 * a_b * 1e-6 * 2000)
    assert bare.anchorage.length_required is None


def test_anchorage_tensile_strength_given():
    inputs = inputs_of(
        "  - {material: GFRP, position: external, ratio: 1.0}",
        extra="bars: {anchorage: {hole_clearance: 4, bond_bar: 8.0, bond_masonry: 0.5,"
        " tensile_strength: 0.3}}",
    )
    built = option_as_built(inputs, inputs.options[0])
    assert built is not None
    assert built.anchorage.tensile_strength == 0.3 and built.anchorage.cone_ok is not None


def test_smeared_ratios_let_an_option_that_cannot_be_built_through():
    # B = 0.2 m, L = 1 m: at most 10 × Ø16 = 2010.6 mm² = 10.05 ‰; 12 ‰ cannot be built
    text = "  - {material: GFRP, position: centred, ratio: 12}"
    with pytest.raises(InputError, match="cannot be installed"):
        inputs_of(text)
    smeared = inputs_of(text, extra="bars: {whole_bars: false}")
    (o,) = smeared.options
    assert o.ratio == 12.0 and o.layout is None
    assert option_as_built(smeared, o) is None
    # the quantity falls back on the smeared estimate: 12 ‰ · 0.2 m · 3 m · 1 m · 2000 kg/m³
    assert option_quantity(smeared, o).mass == pytest.approx(0.012 * 0.2 * 3.0 * 2000.0)


# --------------------------------------------------------------------------- design mode


class RatioRunner:
    """A stand-in for IdaRunner: capacity grows with the model's ratio, a_dyn = 0.1 g·(1 + ρ),
    and it records every ratio it was asked to run."""

    def __init__(self) -> None:
        self.ratios: list[float] = []

    def run(self, models: list[RockingModel]) -> list[list[IdaResult]]:
        out = []
        for m in models:
            assert m.rebars is not None
            self.ratios.append(m.rebars.ratio)
            a = 0.1 * 9.81 * (1 + m.rebars.ratio)
            out.append([IdaResult(9.81, 1.0, a / 9.81, a, 1.0, 1, None)])
        return out


def test_design_mode_answers_with_a_layout_installing_at_least_the_ratio_found():
    inputs = inputs_of("  []", b=0.25, length=5.0)
    inputs = replace(inputs, design=DesignRequest((), ("centred",), (0.1, 3.0), 0.05))
    gfrp = inputs_of("  - {material: GFRP, position: centred, ratio: 1}").options[0].material
    runner = RatioRunner()
    # demand 0.2 g: 0.1·(1 + ρ_model) ≥ 0.2 ⇔ ρ_model ≥ 1 ‰; the grid ratio 0.95 ‰ installs
    # 1250·0.95 = 1187.5 mm² → Ø8: 24 bars = 1206.4 mm² (0.9651 ‰) < 1, fails; 1.0 ‰ installs
    # 1.0053 ‰ (25 Ø8): passes.  Answer 1.0 ‰, 25 × Ø8, installed 1.0053 ‰ ≥ 1.0.
    res = design_search(runner, inputs, gfrp, "centred", 0.2)  # type: ignore[arg-type]
    assert res.ratio == pytest.approx(1.0)
    assert res.layout is not None and res.layout.bars_per_line == 25 and res.layout.diameter == 8
    assert res.layout.ratio_installed >= res.ratio
    assert res.ratio_model == pytest.approx(400 * math.pi / 1250)
    # every model run had an installed ratio: that of a whole number of some catalogue bar
    for r in runner.ratios:
        assert any(
            math.isclose(r * 1250 / (math.pi * d * d / 4), round(r * 1250 / (math.pi * d * d / 4)))
            for d in (6, 8, 10, 12, 14, 16)
        )
    assert any(math.isclose(r, res.ratio_model) for r in runner.ratios)
    built = design_as_built(inputs, res)
    assert built is not None and built.bars_per_line == 25 and built.ratio_asked == 1.0
    assert isinstance(res.summary, CaseSummary)


def test_design_mode_stops_at_the_largest_installable_ratio():
    # B = 0.4, L = 1: at most 10 × Ø16 = 5.03 ‰; range up to 8 ‰ and a target never met
    # (a strong masonry, f_m 50 MPa: the pivot check's own cap stays above 8 ‰)
    inputs = inputs_of("  []", b=0.4, length=1.0)
    inputs = replace(
        inputs,
        design=DesignRequest((), ("centred",), (1.0, 8.0), 0.5),
        compressive_strength=50.0,
    )
    gfrp = inputs_of("  - {material: GFRP, position: centred, ratio: 1}").options[0].material
    runner = RatioRunner()
    res = design_search(runner, inputs, gfrp, "centred", 10.0)  # type: ignore[arg-type]
    assert res.ratio is None and res.layout is None
    assert "stops at 5 ‰" in res.message
    assert max(runner.ratios) <= 10 * math.pi * 64 / 400 + 1e-12


def test_bar_settings_of_anchorage():
    inputs = inputs_of(
        "  []", extra="bars: {anchorage: {hole_clearance: 6, bond_bar: 9, bond_masonry: 0.4}}"
    )
    assert inputs.bars.anchorage == AnchorageSettings(6.0, 9.0, 0.4, None)
