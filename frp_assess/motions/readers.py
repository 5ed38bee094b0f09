"""Reading accelerograms from files.

Formats (``format=``):

* ``"at2"`` -- PEER NGA ``.AT2``: three free header lines, then on line 4 either
  ``NPTS=  5590, DT=   .0050 SEC`` (new style, the two keys in either order) or the bare
  numbers ``5590  .0050`` possibly followed by words such as ``NPTS, DT`` (old style); then the
  samples, several a line.  Fixed-width fields run together (``-1.2E-03-4.5E-04``) are split.
* ``"esm"`` -- ESM / ITACA ASCII: ``KEY: value`` header lines (``NDATA``,
  ``SAMPLING_INTERVAL_S``, ``UNITS`` -- which overrides the ``units`` argument), then the
  samples.
* ``"two-column"`` -- time [s] and acceleration, leading non-numeric header lines (and ``#``
  comments) skipped; the time step must be uniform within 1e-6 relative.  A first time
  t0 != 0 is accepted: the record is taken to start at its first sample (t0 kept in ``meta``).
* ``"one-column"`` -- one or more samples a line, leading non-numeric lines skipped; needs
  ``dt``.
* ``"auto"`` -- ``.at2`` extension -> at2; otherwise by content: ESM keys in the header ->
  esm; a ``NPTS`` on line 4 -> at2; two numbers on the first data line -> two-column; one
  number -> one-column.

Units (``units=``): ``g``, ``m/s2`` (``m/s^2``), ``cm/s2`` (``cm/s^2``, ``gal``); the record is
returned in m/s².  Every malformed file raises :class:`RecordFormatError`, whose ``str()`` is
one line naming the file and, where it applies, the line.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike

from frp_assess.errors import InputError
from frp_assess.motions.record import G, Record
from frp_assess.motions.record_text import (
    DT_RE,
    ESM_KEY_RE,
    ESM_MARKERS,
    FORMATS,
    MAX_PEAK_G,
    MAX_SAMPLES,
    MIN_PEAK_G,
    NPTS_RE,
    NUMBER_RE,
    TIME_TOLERANCE,
    RecordFormatError,
    check_dt,
    is_numeric_line,
    parse_floats,
    read_lines,
    table_lines,
    to_float,
    unit_factor,
)

# --- the formats -----------------------------------------------------------------------------


def _at2_header(header: str, path: Path) -> tuple[int, float]:
    npts_m, dt_m = NPTS_RE.search(header), DT_RE.search(header)
    if npts_m and dt_m:
        npts_f, dt = to_float(npts_m.group(1)), to_float(dt_m.group(1))
    else:
        nums = NUMBER_RE.findall(header)
        if len(nums) < 2:
            raise RecordFormatError(
                "expected 'NPTS= n, DT= dt' or the numbers 'n dt' on the 4th line",
                file=str(path),
                line=4,
            )
        first, second = to_float(nums[0]), to_float(nums[1])
        upper = header.upper()
        dt_first = "DT" in upper and "NPTS" in upper and upper.index("DT") < upper.index("NPTS")
        npts_f, dt = (second, first) if dt_first else (first, second)
    if not math.isfinite(npts_f) or npts_f != int(npts_f) or npts_f < 0:
        raise RecordFormatError(
            f"NPTS must be a whole number, found {npts_f:g}", file=str(path), line=4
        )
    if npts_f > MAX_SAMPLES:
        raise RecordFormatError(
            f"NPTS={npts_f:g} is more than {MAX_SAMPLES:,} samples, the limit of a record",
            file=str(path),
            line=4,
        )
    return int(npts_f), check_dt(dt, path, 4)


def read_at2(path: str | Path, *, units: str = "g", name: str | None = None) -> Record:
    """PEER NGA ``.AT2`` (new- or old-style line 4, see the module docstring).

    Args:
        path: the file.
        units: units of the samples (PEER files are in g).
        name: record name; default the file stem.
    """
    path = Path(path)
    factor = unit_factor(units)
    lines = read_lines(path)
    if len(lines) < 4:
        raise RecordFormatError(
            "too short for a PEER .AT2 file (needs 4 header lines)", file=str(path)
        )
    npts, dt = _at2_header(lines[3], path)
    values: list[float] = []
    for k, line in enumerate(lines[4:], start=5):
        if line.strip():
            values.extend(parse_floats(line.replace(",", " ").split(), path, k))
    if len(values) != npts:
        raise RecordFormatError(
            f"header says NPTS={npts} but the file holds {len(values)} values",
            file=str(path),
            line=4,
        )
    return _make(path, name, dt, _in_si(values, factor, path), "PEER AT2", {"units": units})


def read_esm(path: str | Path, *, units: str = "g", name: str | None = None) -> Record:
    """ESM / ITACA ASCII: ``KEY: value`` header then the samples.

    ``SAMPLING_INTERVAL_S`` [s] is required; ``NDATA``, if present, must match the number of
    samples; ``UNITS`` (e.g. ``cm/s^2``), if present, overrides ``units``.
    """
    path = Path(path)
    lines = read_lines(path)
    header: dict[str, tuple[str, int]] = {}
    start = len(lines)
    for k, line in enumerate(lines, start=1):
        text = line.strip()
        if not text:
            continue
        m = ESM_KEY_RE.match(text)
        if m and not is_numeric_line(text):
            header[m.group(1).upper()] = (m.group(2), k)
            continue
        start = k - 1
        break
    if "SAMPLING_INTERVAL_S" not in header:
        raise RecordFormatError("ESM header lacks SAMPLING_INTERVAL_S", file=str(path))
    dt_text, dt_line = header["SAMPLING_INTERVAL_S"]
    try:
        dt = to_float(dt_text)
    except ValueError:
        raise RecordFormatError(
            f"SAMPLING_INTERVAL_S is not a number: {dt_text!r}", file=str(path), line=dt_line
        ) from None
    check_dt(dt, path, dt_line)
    used_units = units
    if "UNITS" in header and header["UNITS"][0]:
        used_units, unit_line = header["UNITS"]
        try:
            unit_factor(used_units)
        except InputError:
            raise RecordFormatError(
                f"unknown UNITS {used_units!r}", file=str(path), line=unit_line
            ) from None
    values: list[float] = []
    for k, line in enumerate(lines[start:], start=start + 1):
        if line.strip():
            values.extend(parse_floats(line.replace(",", " ").split(), path, k))
    if "NDATA" in header:
        nd_text, nd_line = header["NDATA"]
        try:
            ndata = int(nd_text)
        except (ValueError, OverflowError):
            raise RecordFormatError(
                f"NDATA is not a whole number: {nd_text!r}", file=str(path), line=nd_line
            ) from None
        if ndata != len(values):
            raise RecordFormatError(
                f"header says NDATA={ndata} but the file holds {len(values)} values",
                file=str(path),
                line=nd_line,
            )
    meta = {"units": used_units}
    for key in ("EVENT_NAME", "EVENT_ID", "STATION_CODE", "STREAM"):
        if header.get(key, ("", 0))[0]:
            meta[key.lower()] = header[key][0]
    acc = _in_si(values, unit_factor(used_units), path)
    return _make(path, name, dt, acc, "ESM ASCII", meta)


def _data_rows(lines: list[str], path: Path) -> tuple[list[tuple[int, list[str]]], int | None]:
    """Rows of tokens after the leading non-numeric header lines (comments ``#`` skipped)."""
    rows: list[tuple[int, list[str]]] = []
    first: int | None = None
    for k, line in enumerate(lines, start=1):
        text = line.strip()
        if not text or text.startswith("#"):
            continue
        if first is None:
            if not is_numeric_line(text):
                continue  # a header line
            first = k
        rows.append((k, text.replace(",", " ").split()))
    return rows, first


def read_two_column(path: str | Path, *, units: str = "g", name: str | None = None) -> Record:
    """Two columns: time [s], acceleration; uniform time step (1e-6 relative)."""
    path = Path(path)
    factor = unit_factor(units)
    lines, dialect = table_lines(path)
    rows, _ = _data_rows(lines, path)
    t: list[float] = []
    a: list[float] = []
    lines_of: list[int] = []
    for k, tokens in rows:
        if len(tokens) != 2:
            raise RecordFormatError(
                f"expected 2 columns (time, acceleration), found {len(tokens)}",
                file=str(path),
                line=k,
            )
        tt, aa = parse_floats(tokens, path, k)
        if t and not tt > t[-1]:
            raise RecordFormatError(f"time {tt:g} does not increase", file=str(path), line=k)
        t.append(tt)
        a.append(aa)
        lines_of.append(k)
    if len(t) < 2:
        raise RecordFormatError("the record is empty (fewer than 2 samples)", file=str(path))
    time = np.asarray(t)
    dt = (time[-1] - time[0]) / (time.size - 1)
    steps = np.diff(time)
    bad = np.nonzero(np.abs(steps - steps[0]) > TIME_TOLERANCE * steps[0])[0]
    if bad.size:
        i = int(bad[0])
        raise RecordFormatError(
            f"non-uniform time step ({steps[i]:.6g} s where the first is {steps[0]:.6g} s)",
            file=str(path),
            line=lines_of[i + 1],
        )
    meta = {"units": units}
    if time[0] != 0.0:
        meta["t0_s"] = f"{time[0]:g}"
    if dialect:
        meta["read_as"] = dialect
    return _make(
        path,
        name,
        check_dt(float(dt), path, lines_of[1]),
        _in_si(a, factor, path),
        "two-column",
        meta,
    )


def read_one_column(
    path: str | Path, *, dt: float | None, units: str = "g", name: str | None = None
) -> Record:
    """Samples only (one or more a line, leading non-numeric lines skipped), step ``dt`` [s]."""
    path = Path(path)
    factor = unit_factor(units)
    lines, dialect = table_lines(path)
    rows, _ = _data_rows(lines, path)
    if dt is None:
        width = len(rows[0][1]) if rows else 1
        shape = (
            f"it holds {width} numbers a line and no time column or header with the time step"
            if width > 2
            else "it holds samples only, without their time step"
        )
        raise InputError(
            f"cannot read this record's time step (dt): {shape}. Give dt [s] -- in a project "
            "file 'dt:' of this file with 'format: one-column', in 'records check' --dt -- or "
            "convert it to two columns 'time acceleration' (simulate and ida read .AT2 and "
            "two-column files)",
            file=str(path),
            key="dt",
        )
    if not (math.isfinite(dt) and dt > 0):
        raise InputError(f"dt must be > 0, got {dt}", key="dt")
    check_dt(dt, path, None)
    values: list[float] = []
    for k, tokens in rows:
        values.extend(parse_floats(tokens, path, k))
    meta = {"units": units}
    if dialect:
        meta["read_as"] = dialect
    return _make(path, name, float(dt), _in_si(values, factor, path), "one-column", meta)


def detect_format(path: str | Path) -> str:
    """The format ``"auto"`` resolves to (see the module docstring)."""
    path = Path(path)
    if path.suffix.lower() == ".at2":
        return "at2"
    lines = read_lines(path)
    head = lines[:80]
    keys = {m.group(1).upper() for line in head if (m := ESM_KEY_RE.match(line))}
    if keys & set(ESM_MARKERS):
        return "esm"
    if len(lines) >= 4 and NPTS_RE.search(lines[3]):
        return "at2"
    lines, _ = table_lines(path)
    for line in lines:
        text = line.strip()
        if text and not text.startswith("#") and is_numeric_line(text):
            return "two-column" if len(text.replace(",", " ").split()) == 2 else "one-column"
    raise RecordFormatError("cannot tell the record format (no numeric data found)", file=str(path))


def read_record(
    path: str | Path,
    *,
    format: str = "auto",
    units: str = "g",
    dt: float | None = None,
    name: str | None = None,
) -> Record:
    """Read one accelerogram [returns m/s²].

    Args:
        path: the record file.
        format: ``auto``, ``at2``, ``esm``, ``two-column`` or ``one-column``.
        units: units of the file's samples (``g``, ``m/s2``, ``cm/s2``); an ESM ``UNITS``
            header line overrides it.
        dt: time step [s]; required for ``one-column``; for the other formats, if given, it
            must agree (1e-6 relative) with the file's own.
        name: record name; default the file stem.
    """
    path = Path(path)
    fmt = str(format).strip().lower()
    if fmt not in FORMATS:
        raise InputError(
            f"unknown record format {format!r}; expected one of {', '.join(FORMATS)}",
            key="format",
        )
    unit_factor(units)  # validate early
    if fmt == "auto":
        fmt = detect_format(path)
    if fmt == "one-column":
        return read_one_column(path, dt=dt, units=units, name=name)
    reader = {"at2": read_at2, "esm": read_esm, "two-column": read_two_column}[fmt]
    record = reader(path, units=units, name=name)
    if dt is not None and abs(record.dt - dt) > TIME_TOLERANCE * record.dt:
        raise RecordFormatError(
            f"the file's time step {record.dt:g} s differs from the given dt = {dt:g} s",
            file=str(path),
        )
    return record


def _in_si(values: ArrayLike, factor: float, path: Path) -> np.ndarray:
    """The samples as read times the units' factor [m/s²]; a peak beyond :data:`MAX_PEAK_G`
    is refused before the product can overflow (1e308 in g is not a finite m/s²)."""
    raw = np.asarray(values, dtype=float)
    peak = float(np.max(np.abs(raw))) if raw.size else 0.0
    peak_g = peak * factor / G  # a Python float: inf on overflow, never a warning
    if peak_g > MAX_PEAK_G:
        raise RecordFormatError(
            f"expected a peak acceleration between {MIN_PEAK_G:g} g and {MAX_PEAK_G:g} g, "
            f"found {peak_g:.3g} g (check the file and its units)",
            file=str(path),
        )
    return raw * factor


def _make(
    path: Path, name: str | None, dt: float, acc: np.ndarray, kind: str, meta: dict[str, str]
) -> Record:
    if acc.size < 2:
        raise RecordFormatError("the record is empty (fewer than 2 samples)", file=str(path))
    if not np.all(np.isfinite(acc)):
        raise RecordFormatError("the record holds non-finite values", file=str(path))
    if not np.any(acc):
        raise RecordFormatError("the record holds only zeros", file=str(path))
    peak_g = float(np.max(np.abs(acc))) / G
    if not MIN_PEAK_G <= peak_g <= MAX_PEAK_G:
        raise RecordFormatError(
            f"expected a peak acceleration between {MIN_PEAK_G:g} g and {MAX_PEAK_G:g} g, "
            f"found {peak_g:.3g} g (check the file and its units)",
            file=str(path),
        )
    meta = {"format": kind, **meta}
    return Record(
        name=name or path.stem, dt=dt, acc=acc, source=f"{kind} file {path.name}", meta=meta
    )
