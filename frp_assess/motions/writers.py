"""Writing accelerograms (atomic: a temporary file renamed into place)."""

from __future__ import annotations

from pathlib import Path

from frp_assess.io_utils import atomic_write_text
from frp_assess.motions.record import G, Record


def write_at2(record: Record, path: str | Path, description: str = "") -> None:
    """PEER NGA ``.AT2`` (new-style header), accelerations in g."""
    acc = record.acc / G
    lines = [
        "PEER NGA STRONG MOTION DATABASE RECORD (format)",
        (description or record.source or record.name)[:200],
        "ACCELERATION TIME SERIES IN UNITS OF G",
        f"NPTS= {record.npts:7d}, DT= {record.dt:.6f} SEC",
    ]
    for k in range(0, acc.size, 5):
        lines.append("".join(f"{v:15.7E}" for v in acc[k : k + 5]))
    atomic_write_text(Path(path), "\n".join(lines) + "\n")


def write_two_column(record: Record, path: str | Path, units: str = "g") -> None:
    """Two columns: time [s], acceleration [g] (or m/s2)."""
    factor = G if units == "g" else 1.0
    rows = [f"# {record.name}: {record.source}", f"# time [s], acceleration [{units}]"]
    rows += [f"{t:.6f} {a / factor:.8e}" for t, a in zip(record.time, record.acc, strict=True)]
    atomic_write_text(Path(path), "\n".join(rows) + "\n")
