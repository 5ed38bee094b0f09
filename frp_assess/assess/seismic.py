"""The records of an assessment: generated or read, scaled, and checked against the code."""

from __future__ import annotations

from dataclasses import dataclass, field

from frp_assess.assess.inputs import ArtificialRecords, AssessmentInputs
from frp_assess.motions import (
    ComplianceReport,
    Record,
    check_compliance,
    generate_artificial,
    read_record,
    scale_to_pga,
)
from frp_assess.motions.pga_plausibility import plausibility_warnings


@dataclass(frozen=True)
class SeismicInput:
    records: list[Record]
    compliance: ComplianceReport
    recorded: bool
    scale_factor: float  #: common factor applied to recorded files (1 for artificial)
    #: one line per record whose PGA as read (before scaling) looks like a units mistake
    #: (:func:`frp_assess.motions.pga_plausibility.plausibility_warnings`); empty for artificial
    warnings: tuple[str, ...] = field(default=())


def build_records(inputs: AssessmentInputs) -> SeismicInput:
    """Generate (SIMQKE) or read the records, scale recorded ones to a_g·S, check them."""
    spec = inputs.records
    if isinstance(spec, ArtificialRecords):
        records = generate_artificial(
            inputs.spectrum,
            count=spec.count,
            seed=spec.seed,
            duration=spec.duration,
            dt=spec.dt,
            t1=inputs.t1,
        )
        recorded, factor = False, 1.0
        warnings: tuple[str, ...] = ()
    else:
        records = [
            read_record(f.path, format=f.format, units=f.units, dt=f.dt, name=f.name) for f in spec
        ]
        recorded, factor = True, 1.0
        warnings = plausibility_warnings(records)
        if inputs.scale_to_spectrum:
            before = sum(r.pga_g for r in records) / len(records)
            records = scale_to_pga(records, inputs.spectrum.pga_g)
            factor = inputs.spectrum.pga_g / before
    report = check_compliance(records, inputs.spectrum, t1=inputs.t1, recorded=recorded)
    return SeismicInput(records, report, recorded, factor, warnings)
