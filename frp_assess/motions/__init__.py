"""Seismic input: records, code spectra, response spectra, artificial accelerograms."""

from __future__ import annotations

from frp_assess.motions.record import G, Record

__all__ = ["G", "Record"]

# --- added by issue 3: the public API of the ground-motion module ----------------------------
from frp_assess.motions.compliance import (  # noqa: E402
    DEFAULT_T1,
    ClauseCheck,
    ComplianceReport,
    check_compliance,
    scale_records,
    scale_to_ntc_band,
    scale_to_pga,
)
from frp_assess.motions.readers import read_record
from frp_assess.motions.record_text import RecordFormatError
from frp_assess.motions.response import response_spectrum  # noqa: E402
from frp_assess.motions.simqke import generate_artificial  # noqa: E402
from frp_assess.motions.spectra import (  # noqa: E402
    ElasticSpectrum,
    ec8_spectrum,
    ntc2018_spectrum,
    parse_spectrum,
    preset_spectrum,
    table_spectrum,
)
from frp_assess.motions.writers import write_at2, write_two_column  # noqa: E402

__all__ += [
    "DEFAULT_T1",
    "ClauseCheck",
    "ComplianceReport",
    "ElasticSpectrum",
    "RecordFormatError",
    "check_compliance",
    "ec8_spectrum",
    "generate_artificial",
    "ntc2018_spectrum",
    "parse_spectrum",
    "preset_spectrum",
    "read_record",
    "response_spectrum",
    "scale_records",
    "scale_to_ntc_band",
    "scale_to_pga",
    "table_spectrum",
    "write_at2",
    "write_two_column",
]
