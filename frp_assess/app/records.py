"""The `records` commands: generate a set of spectrum-compatible accelerograms and check any
set against a code spectrum (EN 1998-1 §3.2.3.1.2, NTC 2018 §3.2.3.6).

:func:`generate_records` writes the set (PEER .AT2 files in g and spectra.csv) as one set:
into a staging folder inside the output folder, moved in file by file, so that a full disk or
an interrupt leaves no half-written set behind.  The spectrum parser, the readers' formats
and units and the envelopes are re-exported for the command line's arguments.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path

from frp_assess.errors import InputError
from frp_assess.io_utils import atomic_write_text
from frp_assess.motions.compliance import DEFAULT_T1, ComplianceReport, check_compliance
from frp_assess.motions.envelopes import ENVELOPES
from frp_assess.motions.pga_plausibility import plausibility_warnings
from frp_assess.motions.readers import read_record
from frp_assess.motions.record import Record
from frp_assess.motions.record_text import FORMATS, UNITS
from frp_assess.motions.simqke import generate_artificial
from frp_assess.motions.spectra import SPECTRUM_HELP, ElasticSpectrum, parse_spectrum
from frp_assess.motions.writers import write_at2

__all__ = [
    "DEFAULT_T1",
    "ENVELOPES",
    "FORMATS",
    "SPECTRUM_HELP",
    "UNITS",
    "ComplianceReport",
    "ElasticSpectrum",
    "GeneratedRecords",
    "check_compliance",
    "generate_records",
    "parse_spectrum",
    "read_records",
    "spectra_csv",
]


@dataclass(frozen=True)
class GeneratedRecords:
    """A generated set, written."""

    records: list[Record]
    report: ComplianceReport  #: the code checks of the set
    set_scale_factor: float  #: the one factor the whole set was scaled by [-]


def generate_records(
    spectrum: ElasticSpectrum,
    out: Path,
    *,
    count: int,
    seed: int,
    duration: float,
    dt: float,
    stationary: float,
    envelope: str,
    t1: float,
) -> GeneratedRecords:
    """Generate ``count`` artificial records compatible with ``spectrum`` (SIMQKE; the same
    seed gives the same records, bit for bit) of ``duration`` [s] at ``dt`` [s] with a
    stationary part of ``stationary`` [s], check them (``t1`` [s]) and write them with
    spectra.csv into ``out``."""
    records = generate_artificial(
        spectrum,
        count=count,
        seed=seed,
        duration=duration,
        dt=dt,
        stationary=stationary,
        envelope=envelope,
        t1=t1,
    )
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise InputError("exists and is not a folder", file=str(out), key="--out")
    report = check_compliance(records, spectrum, t1=t1)
    out.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=".records-staging-", dir=out))
    try:
        for record in records:
            write_at2(record, staging / f"{record.name}.AT2")
        atomic_write_text(staging / "spectra.csv", spectra_csv(report, spectrum))
        for path in sorted(staging.iterdir()):
            os.replace(path, out / path.name)
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    return GeneratedRecords(records, report, float(records[0].meta["set_scale_factor"]))


def read_records(
    files: list[str], *, format: str, units: str, dt: float | None
) -> tuple[list[Record], list[str]]:
    """Read record ``files`` (``format``, ``units``; ``dt`` [s] of one-column files); returns
    them and the warnings of implausible peak accelerations (one line each)."""
    records: list[Record] = [read_record(f, format=format, units=units, dt=dt) for f in files]
    return records, list(plausibility_warnings(records))


def spectra_csv(report: ComplianceReport, spectrum: ElasticSpectrum) -> str:
    """CSV of the target, mean and per-record spectra [g] at the report's periods [s]."""
    names = report.record_names
    lines = [
        f"# target: {spectrum.description}",
        f"# damping {report.damping:g}; pseudo-accelerations in g; T1 = {report.t1:g} s",
        ",".join(
            ["period_s", "target_g", "mean_g", "mean_over_target"] + [f"{n}_g" for n in names]
        ),
    ]
    for k, t in enumerate(report.periods):
        row = [f"{t:.6g}", f"{report.target[k]:.6g}", f"{report.mean[k]:.6g}"]
        row.append(f"{report.mean[k] / report.target[k]:.5f}")
        row += [f"{report.spectra[i, k]:.6g}" for i in range(len(names))]
        lines.append(",".join(row))
    return "\n".join(lines) + "\n"
