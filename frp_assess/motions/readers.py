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
import os
import re
import stat
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike

from frp_assess.errors import InputError
from frp_assess.motions.record import G, Record

#: accepted unit names (lower case, no blanks) -> factor to m/s²
UNITS: dict[str, float] = {
    "g": G,
    "m/s2": 1.0,
    "m/s^2": 1.0,
    "cm/s2": 0.01,
    "cm/s^2": 0.01,
    "gal": 0.01,
}
#: accepted values of ``format=``
FORMATS: tuple[str, ...] = ("auto", "at2", "esm", "two-column", "one-column")

_NUMBER = r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eEdD][-+]?[0-9]+)?"
_NUMBER_RE = re.compile(_NUMBER)
_NPTS_RE = re.compile(r"NPTS\s*=\s*(" + _NUMBER + ")", re.IGNORECASE)
_DT_RE = re.compile(r"\bDT\s*=\s*(" + _NUMBER + ")", re.IGNORECASE)
_ESM_KEY_RE = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*:\s*(.*?)\s*$")
_ESM_MARKERS = ("NDATA", "SAMPLING_INTERVAL_S", "EVENT_NAME", "NETWORK", "STATION_CODE")

#: relative tolerance on the uniformity of the time column of a two-column file
TIME_TOLERANCE = 1e-6
#: largest record file [bytes] (a 600 s record at 200 Hz in text is about 2 MB)
MAX_RECORD_BYTES = 50_000_000
#: most samples of one record (a header's NPTS above it is refused before reading on)
MAX_SAMPLES = 2_000_000
#: smallest time step [s] (as the project file's; a smaller one is a unit or header mistake)
MIN_DT = 1e-4
#: smallest and largest peak [g] of a record that is read at all.  Outside them no units
#: make sense of the file (a PGA of 1e-6 g is below any instrument's noise; 1e4 g is 10⁴ times
#: any recorded earthquake, even a file in cm/s² read as g stays below it) and scaling such a
#: record loses its digits; inside, a peak outside the range of practice is a warning
#: (frp_assess.motions.pga_plausibility).
MIN_PEAK_G = 1e-6
MAX_PEAK_G = 1e4
#: a data line of a table: digits, signs, exponents, points, commas, semicolons, blanks
_DATA_LINE_RE = re.compile(r"^[\s0-9.,;eEdD+-]*[0-9][\s0-9.,;eEdD+-]*$")
_DECIMAL_COMMA_RE = re.compile(r"[0-9],[0-9]")


class RecordFormatError(InputError):
    """A record file that cannot be read as asked (one line: ``file:line: message``)."""


def unit_factor(units: str) -> float:
    """Factor [m/s² per unit] from an acceleration unit name (see :data:`UNITS`)."""
    key = str(units).strip().lower().replace(" ", "")
    if key not in UNITS:
        raise InputError(
            f"unknown acceleration units {units!r}; expected g, m/s2 or cm/s2 (or m/s^2, "
            "cm/s^2, gal)",
            key="units",
        )
    return UNITS[key]


# --- low-level helpers ------------------------------------------------------------------------


def _read_lines(path: Path) -> list[str]:
    """The lines of a regular text file of at most :data:`MAX_RECORD_BYTES`.

    The file is checked before it is opened: a FIFO (reading blocks) or a device such as
    ``/dev/zero`` (reading never ends) is refused.
    """
    try:
        info = os.stat(path)
    except FileNotFoundError:
        raise RecordFormatError("record file not found", file=str(path)) from None
    except OSError as exc:
        raise RecordFormatError(
            f"cannot read record file ({exc.strerror or exc})", file=str(path)
        ) from None
    if stat.S_ISDIR(info.st_mode):
        raise RecordFormatError("is a directory, not a record file", file=str(path))
    if not stat.S_ISREG(info.st_mode):
        raise RecordFormatError(
            "is not a regular file (a device, pipe or socket), not a record file", file=str(path)
        )
    if info.st_size > MAX_RECORD_BYTES:
        raise RecordFormatError(
            f"is {info.st_size / 1e6:.1f} MB; a record file is at most "
            f"{MAX_RECORD_BYTES / 1e6:g} MB",
            file=str(path),
        )
    try:
        with open(path, "rb") as handle:
            raw = handle.read(MAX_RECORD_BYTES + 1)
    except OSError as exc:
        raise RecordFormatError(
            f"cannot read record file ({exc.strerror or exc})", file=str(path)
        ) from None
    if len(raw) > MAX_RECORD_BYTES:
        raise RecordFormatError(
            f"is larger than {MAX_RECORD_BYTES / 1e6:g} MB, the limit of a record file",
            file=str(path),
        )
    if b"\x00" in raw[:4096]:
        raise RecordFormatError("not a text file (binary content)", file=str(path))
    return raw.decode("utf-8", errors="replace").splitlines()


def _table_lines(path: Path) -> tuple[list[str], str | None]:
    """The lines of a table (one- or two-column file) with its separators made standard.

    A table with semicolons between the columns (``0.01;0.0012``) or with decimal commas
    (``0,01;0,0012``, ``0,01<tab>0,0012``) is read as what it is: the returned lines use
    blanks and decimal points, and the second item says what was converted.  A table that is
    ambiguous (one ``a,b`` a line without any decimal point: decimal comma or two columns?)
    is refused with how to convert it.
    """
    lines = _read_lines(path)
    data = [
        (k, line)
        for k, line in enumerate(lines, start=1)
        if not line.lstrip().startswith("#") and _DATA_LINE_RE.match(line)
    ]
    if not data:
        return lines, None
    semicolons = any(";" in line for _, line in data)
    points = any("." in line for _, line in data)
    commas = any(_DECIMAL_COMMA_RE.search(line) for _, line in data)
    if semicolons and commas and points:
        k = next(k for k, line in data if "." in line)
        raise RecordFormatError(
            "a semicolon-separated table with both decimal points and decimal commas; use one "
            "decimal mark (e.g. replace ',' by '.')",
            file=str(path),
            line=k,
        )
    if not semicolons and not (commas and not points):
        return lines, None
    if not semicolons:
        several = any(len(line.split()) > 1 for _, line in data)
        if not several:
            k = data[0][0]
            raise RecordFormatError(
                f"{data[0][1].strip()!r} may be a decimal comma or two comma-separated "
                "columns; write decimal points (e.g. 0.0012) and ',' or blanks between columns",
                file=str(path),
                line=k,
            )
    converted = dict(data)
    out = [
        converted[k].replace(";", " ").replace(",", "." if commas else " ")
        if k in converted
        else line
        for k, line in enumerate(lines, start=1)
    ]
    what = "semicolon-separated" if semicolons else "blank-separated"
    return out, what + (", decimal commas" if commas else "")


def _to_float(token: str) -> float:
    return float(token.replace("D", "E").replace("d", "e"))


def _floats(tokens: list[str], path: Path, lineno: int) -> list[float]:
    """Parse tokens as finite numbers; run-together fixed-width fields are split."""
    out: list[float] = []
    for tok in tokens:
        try:
            values = [_to_float(tok)]
        except ValueError:
            parts = _NUMBER_RE.findall(tok)
            if len(parts) < 2 or "".join(parts) != tok:
                raise RecordFormatError(
                    f"expected a number, found {tok!r}", file=str(path), line=lineno
                ) from None
            values = [_to_float(p) for p in parts]
        for value in values:
            if not math.isfinite(value):
                raise RecordFormatError(f"value {tok!r} is not finite", file=str(path), line=lineno)
        out.extend(values)
    return out


def _is_numeric_line(text: str) -> bool:
    tokens = text.replace(",", " ").split()
    if not tokens:
        return False
    try:
        for tok in tokens:
            _to_float(tok)
    except ValueError:
        return False
    return True


def _check_dt(dt: float, path: Path, line: int | None) -> float:
    if not (math.isfinite(dt) and dt > 0.0):
        raise RecordFormatError(f"time step must be > 0, found {dt}", file=str(path), line=line)
    if dt < MIN_DT:
        raise RecordFormatError(
            f"time step {dt:g} s is below {MIN_DT:g} s (check the header or the time column's "
            "units: seconds)",
            file=str(path),
            line=line,
        )
    return dt


# --- the formats -----------------------------------------------------------------------------


def _at2_header(header: str, path: Path) -> tuple[int, float]:
    npts_m, dt_m = _NPTS_RE.search(header), _DT_RE.search(header)
    if npts_m and dt_m:
        npts_f, dt = _to_float(npts_m.group(1)), _to_float(dt_m.group(1))
    else:
        nums = _NUMBER_RE.findall(header)
        if len(nums) < 2:
            raise RecordFormatError(
                "expected 'NPTS= n, DT= dt' or the numbers 'n dt' on the 4th line",
                file=str(path),
                line=4,
            )
        first, second = _to_float(nums[0]), _to_float(nums[1])
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
    return int(npts_f), _check_dt(dt, path, 4)


def read_at2(path: str | Path, *, units: str = "g", name: str | None = None) -> Record:
    """PEER NGA ``.AT2`` (new- or old-style line 4, see the module docstring).

    Args:
        path: the file.
        units: units of the samples (PEER files are in g).
        name: record name; default the file stem.
    """
    path = Path(path)
    factor = unit_factor(units)
    lines = _read_lines(path)
    if len(lines) < 4:
        raise RecordFormatError(
            "too short for a PEER .AT2 file (needs 4 header lines)", file=str(path)
        )
    npts, dt = _at2_header(lines[3], path)
    values: list[float] = []
    for k, line in enumerate(lines[4:], start=5):
        if line.strip():
            values.extend(_floats(line.replace(",", " ").split(), path, k))
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
    lines = _read_lines(path)
    header: dict[str, tuple[str, int]] = {}
    start = len(lines)
    for k, line in enumerate(lines, start=1):
        text = line.strip()
        if not text:
            continue
        m = _ESM_KEY_RE.match(text)
        if m and not _is_numeric_line(text):
            header[m.group(1).upper()] = (m.group(2), k)
            continue
        start = k - 1
        break
    if "SAMPLING_INTERVAL_S" not in header:
        raise RecordFormatError("ESM header lacks SAMPLING_INTERVAL_S", file=str(path))
    dt_text, dt_line = header["SAMPLING_INTERVAL_S"]
    try:
        dt = _to_float(dt_text)
    except ValueError:
        raise RecordFormatError(
            f"SAMPLING_INTERVAL_S is not a number: {dt_text!r}", file=str(path), line=dt_line
        ) from None
    _check_dt(dt, path, dt_line)
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
            values.extend(_floats(line.replace(",", " ").split(), path, k))
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
            if not _is_numeric_line(text):
                continue  # a header line
            first = k
        rows.append((k, text.replace(",", " ").split()))
    return rows, first


def read_two_column(path: str | Path, *, units: str = "g", name: str | None = None) -> Record:
    """Two columns: time [s], acceleration; uniform time step (1e-6 relative)."""
    path = Path(path)
    factor = unit_factor(units)
    lines, dialect = _table_lines(path)
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
        tt, aa = _floats(tokens, path, k)
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
        _check_dt(float(dt), path, lines_of[1]),
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
    lines, dialect = _table_lines(path)
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
    _check_dt(dt, path, None)
    values: list[float] = []
    for k, tokens in rows:
        values.extend(_floats(tokens, path, k))
    meta = {"units": units}
    if dialect:
        meta["read_as"] = dialect
    return _make(path, name, float(dt), _in_si(values, factor, path), "one-column", meta)


def detect_format(path: str | Path) -> str:
    """The format ``"auto"`` resolves to (see the module docstring)."""
    path = Path(path)
    if path.suffix.lower() == ".at2":
        return "at2"
    lines = _read_lines(path)
    head = lines[:80]
    keys = {m.group(1).upper() for line in head if (m := _ESM_KEY_RE.match(line))}
    if keys & set(_ESM_MARKERS):
        return "esm"
    if len(lines) >= 4 and _NPTS_RE.search(lines[3]):
        return "at2"
    lines, _ = _table_lines(path)
    for line in lines:
        text = line.strip()
        if text and not text.startswith("#") and _is_numeric_line(text):
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
