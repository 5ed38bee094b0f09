"""Writing accelerograms, readable back by :mod:`frp_assess.motions.readers`.

Every file is written atomically (a temporary file in the same folder, then ``os.replace``),
so a reader never sees half a record.
"""

from __future__ import annotations

from pathlib import Path

from frp_assess.io_utils import atomic_write_text
from frp_assess.motions.record import G, Record
from frp_assess.motions.record_text import unit_factor


def write_at2(record: Record, path: str | Path, description: str = "") -> None:
    """PEER NGA ``.AT2`` with the new-style header; samples in g, 5 a line (``E16.8``).

    Args:
        record: the accelerogram (m/s²).
        path: destination file.
        description: free text of header line 2 (default: the record's source or name).
    """
    acc = record.acc / G
    text = (description or record.source or record.name).replace("\n", " ")[:200]
    lines = [
        f"PEER NGA STRONG MOTION DATABASE RECORD (written by frp-assess): {record.name}",
        text,
        "ACCELERATION TIME SERIES IN UNITS OF G",
        f"NPTS= {record.npts:7d}, DT= {record.dt:.10g} SEC",
    ]
    for k in range(0, acc.size, 5):
        lines.append("".join(f"{v:16.8E}" for v in acc[k : k + 5]))
    atomic_write_text(Path(path), "\n".join(lines) + "\n")


def write_two_column(record: Record, path: str | Path, units: str = "g") -> None:
    """Two columns: time [s] and acceleration in ``units`` (``g``, ``m/s2``, ``cm/s2``).

    The header lines start with ``#``; the time is written with 9 decimals, so the step is
    uniform to far better than the reader's 1e-6 relative tolerance.
    """
    factor = unit_factor(units)
    rows = [
        f"# {record.name}: {record.source}".replace("\n", " "),
        f"# time [s], acceleration [{units}]",
    ]
    acc = record.acc / factor
    rows += [f"{k * record.dt:.9f} {a:.9e}" for k, a in enumerate(acc)]
    atomic_write_text(Path(path), "\n".join(rows) + "\n")
