"""Reading accelerograms from files: PEER NGA ``.AT2`` and two-column (t, a) text.

Every malformed file raises :class:`RecordFormatError`, whose message is one line naming the
file and the line.  Accelerations are converted to m/s².
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np

from frp_assess.errors import InputError
from frp_assess.motions.record import G, Record

#: accepted unit names -> factor to m/s²
UNITS: dict[str, float] = {
    "g": G,
    "m/s2": 1.0,
    "m/s^2": 1.0,
    "cm/s2": 0.01,
    "cm/s^2": 0.01,
    "gal": 0.01,
}
FORMATS = ("auto", "at2", "two-column")

_NPTS_DT = re.compile(r"NPTS\s*=\s*([0-9]+)\s*,?\s*DT\s*=\s*([0-9.eE+-]+)", re.IGNORECASE)


class RecordFormatError(InputError):
    """A record file that cannot be read as asked."""


def unit_factor(units: str) -> float:
    """Factor from ``units`` to m/s²."""
    key = units.strip().lower().replace(" ", "")
    if key not in UNITS:
        raise InputError(f"unknown acceleration units {units!r}; expected one of g, m/s2, cm/s2")
    return UNITS[key]


def _floats(tokens: list[str], path: Path, lineno: int) -> list[float]:
    out = []
    for tok in tokens:
        try:
            value = float(tok)
        except ValueError:
            raise RecordFormatError(
                f"expected a number, found {tok!r}", file=str(path), line=lineno
            ) from None
        if not math.isfinite(value):
            raise RecordFormatError(f"value {tok!r} is not finite", file=str(path), line=lineno)
        out.append(value)
    return out


def _read_lines(path: Path) -> list[str]:
    try:
        return path.read_text(encoding="utf-8", errors="replace").splitlines()
    except FileNotFoundError:
        raise RecordFormatError("record file not found", file=str(path)) from None
    except OSError as exc:
        raise RecordFormatError(
            f"cannot read record file ({exc.strerror})", file=str(path)
        ) from None


def read_at2(path: Path, *, units: str = "g", name: str | None = None) -> Record:
    """PEER NGA ``.AT2``: 3 free header lines, then ``NPTS= n, DT= dt`` (new style) or the
    numbers ``n dt`` first on line 4 (old style), then the samples in g (5 a line)."""
    lines = _read_lines(path)
    if len(lines) < 5:
        raise RecordFormatError(
            "too short for a PEER .AT2 file (needs 4 header lines)", file=str(path)
        )
    header = lines[3]
    m = _NPTS_DT.search(header)
    if m:
        npts, dt = int(m.group(1)), float(m.group(2))
    else:
        nums = re.findall(r"[-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?", header)
        if len(nums) < 2:
            raise RecordFormatError(
                "expected 'NPTS= n, DT= dt' or 'n dt' on the 4th line", file=str(path), line=4
            )
        npts, dt = int(float(nums[0])), float(nums[1])
    if not (dt > 0 and math.isfinite(dt)):
        raise RecordFormatError(f"DT must be > 0, found {dt}", file=str(path), line=4)
    values: list[float] = []
    for k, line in enumerate(lines[4:], start=5):
        if line.strip():
            values.extend(_floats(line.split(), path, k))
    if len(values) != npts:
        raise RecordFormatError(
            f"header says NPTS={npts} but the file holds {len(values)} values",
            file=str(path),
            line=4,
        )
    return _make(path, name, dt, np.asarray(values) * unit_factor(units), "PEER AT2")


def read_two_column(path: Path, *, units: str = "g", name: str | None = None) -> Record:
    """Two columns (time [s], acceleration); leading header lines that are not numbers are
    skipped; the time step must be uniform."""
    lines = _read_lines(path)
    t: list[float] = []
    a: list[float] = []
    started = False
    for k, line in enumerate(lines, start=1):
        text = line.strip()
        if not text or text.startswith("#"):
            continue
        tokens = text.replace(",", " ").split()
        if not started:
            try:
                [float(x) for x in tokens]
            except ValueError:
                continue  # a header line
            started = True
        if len(tokens) != 2:
            raise RecordFormatError(
                f"expected 2 columns (time, acceleration), found {len(tokens)}",
                file=str(path),
                line=k,
            )
        tt, aa = _floats(tokens, path, k)
        if t and not tt > t[-1]:
            raise RecordFormatError(f"time {tt} does not increase", file=str(path), line=k)
        t.append(tt)
        a.append(aa)
    if len(t) < 2:
        raise RecordFormatError("the record is empty (fewer than 2 samples)", file=str(path))
    time = np.asarray(t)
    steps = np.diff(time)
    dt = float(np.mean(steps))
    bad = np.nonzero(np.abs(steps - dt) > 1e-6 * max(dt, 1e-12) + 1e-9)[0]
    if bad.size:
        raise RecordFormatError(
            f"non-uniform time step ({steps[bad[0]]:.6g} s vs {dt:.6g} s)", file=str(path)
        )
    if abs(time[0]) > 1e-9:
        raise RecordFormatError(f"the first time must be 0, found {time[0]}", file=str(path))
    return _make(path, name, dt, np.asarray(a) * unit_factor(units), "two-column")


def read_record(
    path: str | Path, *, format: str = "auto", units: str = "g", name: str | None = None
) -> Record:
    """Read one accelerogram; ``format``: ``auto`` (by extension), ``at2``, ``two-column``."""
    path = Path(path)
    fmt = format.lower()
    if fmt not in FORMATS:
        raise InputError(f"unknown record format {format!r}; expected one of {', '.join(FORMATS)}")
    if fmt == "auto":
        fmt = "at2" if path.suffix.lower() == ".at2" else "two-column"
    unit_factor(units)  # validate early
    if fmt == "at2":
        return read_at2(path, units=units, name=name)
    return read_two_column(path, units=units, name=name)


def _make(path: Path, name: str | None, dt: float, acc: np.ndarray, kind: str) -> Record:
    if acc.size < 2:
        raise RecordFormatError("the record is empty (fewer than 2 samples)", file=str(path))
    if not np.any(acc):
        raise RecordFormatError("the record holds only zeros", file=str(path))
    return Record(name=name or path.stem, dt=dt, acc=acc, source=f"{kind} file {path.name}")
