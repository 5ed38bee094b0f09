"""The objects of results.json that record what the run was given
(:mod:`frp_assess.results.run_inputs`): each material, the wall, the building and the floor
spectra at the wall's base, the seismic input and its spectrum compatibility.  Units as in
results.json (accelerations g, lengths m, periods s).
"""

from __future__ import annotations

import json
import math
from dataclasses import asdict
from typing import Any

from frp_assess.assess.floor_input import FloorSpectra
from frp_assess.assess.inputs import (
    ArtificialRecords,
    AssessmentInputs,
    BuildingSettings,
    Material,
)
from frp_assess.assess.seismic import SeismicInput
from frp_assess.motions.floor import default_period, mode_shape, participation_factor
from frp_assess.results.model import (
    Compliance,
    ComplianceCheck,
)
from frp_assess.results.run_inputs import (
    BuildingResult,
    FloorSpectraResult,
    Generator,
    MaterialResult,
    SeismicResult,
    SpectrumResult,
    WallResult,
)


def material_result(m: Material) -> MaterialResult:
    return MaterialResult(
        elastic_modulus=m.elastic_modulus,
        ultimate_strain=m.ultimate_strain,
        density=m.density,
        price=m.price,
        source=m.source,
    )


def wall_result(inputs: AssessmentInputs) -> WallResult:
    """The wall; ``a_rm`` is that of the unreinforced wall's model, g·tan α_x (g·tan α with
    ``pivot: edge``, g·(B − x_W)/H with ``pivot: crushing``, the same for every option),
    ``alpha`` the geometric slenderness (tan α = B/H)."""
    w = inputs.wall
    return WallResult(
        thickness=inputs.thickness,
        height=inputs.height,
        length=inputs.length,
        masonry=inputs.masonry,
        masonry_description=inputs.masonry_description,
        unit_weight=inputs.unit_weight,
        mechanism=inputs.mechanism,
        alpha=w.alpha,
        alpha_deg=math.degrees(w.alpha),
        R=w.R,
        p=w.p,
        mass=w.mass,
        a_rm=inputs.model_for(None).a_rm_g,
    )


def shaken_by(building: BuildingSettings) -> str:
    """One sentence: the wall was shaken by the floor motion at Z (first mode), and a_dyn and
    capacity/demand are in ground terms (for results.json, the report and the CLI)."""
    gamma1 = participation_factor(building.storeys)
    psi1 = mode_shape(building.wall_base, building.height)
    return (
        f"the wall's base at Z = {building.wall_base:g} m of a {building.storeys}-storey "
        f"building {building.height:g} m tall moved with that floor's absolute acceleration, "
        f"first mode only (γ1 = {gamma1:.3g}, ψ1 = Z/H_b = {psi1:.3g}, "
        f"T1 = {building.period:.3g} s, ξ1 = {building.damping:.3g}; Circolare 2019 §C7.2.3); "
        "the IDA scaled the ground records, so a_dyn and capacity/demand are in "
        "ground-acceleration terms, compared with a_g·S"
    )


def building_result(building: BuildingSettings) -> BuildingResult:
    """The ``building`` object of results.json (docs/results-json.md)."""
    return BuildingResult(
        height=building.height,
        storeys=building.storeys,
        wall_base=building.wall_base,
        z_over_h=building.z_over_h,
        period=building.period,
        period_default=default_period(building.height),
        damping=building.damping,
        gamma1=participation_factor(building.storeys),
        psi1=mode_shape(building.wall_base, building.height),
        shaken_by=shaken_by(building),
    )


def floor_spectra_result(spectra: FloorSpectra) -> FloorSpectraResult:
    """The ``floor_spectra`` object of results.json, accelerations in g, periods in s."""
    return FloorSpectraResult(
        periods=spectra.periods,
        mean=spectra.mean,
        code=spectra.code,
        ground=spectra.ground,
        records=spectra.records,
    )


def seismic_result(inputs: AssessmentInputs, seismic: SeismicInput) -> SeismicResult:
    sp = inputs.spectrum
    rep = seismic.compliance
    gen = None
    if isinstance(inputs.records, ArtificialRecords):
        a = inputs.records
        gen = Generator(method="SIMQKE", count=a.count, seed=a.seed, duration=a.duration, dt=a.dt)
    return SeismicResult(
        spectrum=SpectrumResult(
            type=sp.kind,
            name=sp.name,
            description=sp.description,
            parameters=_jsonable(sp.parameters),
            ag_S=sp.pga_g,
            T_B=sp.T_B,
            T_C=sp.T_C,
            T_D=sp.T_D,
        ),
        t1=inputs.t1,
        records_kind="recorded" if seismic.recorded else "artificial",
        generator=gen,
        scale_factor=seismic.scale_factor,
        periods=tuple(rep.periods.tolist()),
        target_sa=tuple(rep.target.tolist()),
        mean_sa=tuple(rep.mean.tolist()),
    )


def compliance_result(seismic: SeismicInput) -> Compliance:
    """The ``compliance`` object of results.json: the record set's checks, one
    :class:`~frp_assess.results.model.ComplianceCheck` per clause check (same fields)."""
    rep = seismic.compliance
    return Compliance(
        passed=rep.passed, checks=tuple(ComplianceCheck(**asdict(c)) for c in rep.checks)
    )


def _jsonable(obj: Any) -> Any:
    return json.loads(
        json.dumps(obj, default=lambda o: o.tolist() if hasattr(o, "tolist") else str(o))
    )
