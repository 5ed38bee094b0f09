"""The text of a record file, whatever its format: the accepted units and formats, the limits
on size, samples, time step and peak, the one-line :class:`RecordFormatError`, and the
low-level reading of lines and numbers every format of :mod:`frp_assess.motions.readers`
shares.  Accelerations in m/s² once converted (:func:`unit_factor`).
"""

from __future__ import annotations

import math
import os
import re
import stat
from pathlib import Path

from frp_assess.errors import InputError
from frp_assess.motions.record import G

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
NUMBER_RE = re.compile(_NUMBER)
NPTS_RE = re.compile(r"NPTS\s*=\s*(" + _NUMBER + ")", re.IGNORECASE)
DT_RE = re.compile(r"\bDT\s*=\s*(" + _NUMBER + ")", re.IGNORECASE)
ESM_KEY_RE = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*:\s*(.*?)\s*$")
ESM_MARKERS = ("NDATA", "SAMPLING_INTERVAL_S", "EVENT_NAME", "NETWORK", "STATION_CODE")

#: relative tolerance on the uniformity of the time column of a two-column file
TIME_TOLERANCE = 1e-6
#: largest record file [bytes] (a 600 s record at 200 Hz in text is about 2 MB)
MAX_RECORD_BYTES = 50_000_000
#: most samples of one record (a header's NPTS above it is refused before reading on)
MAX_SAMPLES = 2_000_000
#: smallest time step [s] (as the project file's; a smaller one is a unit or header mistake)
MIN_DT = 1e-4
#: largest time step [s] of a record (the project file's dt has the same bound).  The
#: spectrum-compatibility checks compare spectra from 0.15 s (NTC 2018 §3.2.3.6; EC8's from
#: 0.2·T1) and a record holds no motion faster than its Nyquist period 2·dt: at dt = 0.05 s a
#: 0.15 s oscillation still has 3 samples a cycle; a record of dt = 1 s holds nothing below
#: 2 s, and its spectrum over the checks' periods would be an artefact of the sampling
MAX_DT = 0.05
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


def read_lines(path: Path) -> list[str]:
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


def table_lines(path: Path) -> tuple[list[str], str | None]:
    """The lines of a table (one- or two-column file) with its separators made standard.

    A table with semicolons between the columns (``0.01;0.0012``) or with decimal commas
    (``0,01;0,0012``, ``0,01<tab>0,0012``) is read as what it is: the returned lines use
    blanks and decimal points, and the second item says what was converted.  A table that is
    ambiguous (one ``a,b`` a line without any decimal point: decimal comma or two columns?)
    is refused with how to convert it.
    """
    lines = read_lines(path)
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


def to_float(token: str) -> float:
    """A number of a record file; Fortran exponents (``1.5D-03``) accepted."""
    return float(token.replace("D", "E").replace("d", "e"))


def parse_floats(tokens: list[str], path: Path, lineno: int) -> list[float]:
    """Parse tokens as finite numbers; run-together fixed-width fields are split."""
    out: list[float] = []
    for tok in tokens:
        try:
            values = [to_float(tok)]
        except ValueError:
            parts = NUMBER_RE.findall(tok)
            if len(parts) < 2 or "".join(parts) != tok:
                raise RecordFormatError(
                    f"expected a number, found {tok!r}", file=str(path), line=lineno
                ) from None
            values = [to_float(p) for p in parts]
        for value in values:
            if not math.isfinite(value):
                raise RecordFormatError(f"value {tok!r} is not finite", file=str(path), line=lineno)
        out.extend(values)
    return out


def is_numeric_line(text: str) -> bool:
    """Every blank- or comma-separated token of ``text`` is a number (and there is one)."""
    tokens = text.replace(",", " ").split()
    if not tokens:
        return False
    try:
        for tok in tokens:
            to_float(tok)
    except ValueError:
        return False
    return True


def check_dt(dt: float, path: Path, line: int | None) -> float:
    """``dt`` [s] if it is a usable time step (finite, :data:`MIN_DT` to :data:`MAX_DT`),
    else a :class:`RecordFormatError` at ``path``:``line``."""
    if not (math.isfinite(dt) and dt > 0.0):
        raise RecordFormatError(f"time step must be > 0, found {dt}", file=str(path), line=line)
    if dt < MIN_DT:
        raise RecordFormatError(
            f"time step {dt:g} s is below {MIN_DT:g} s (check the header or the time column's "
            "units: seconds)",
            file=str(path),
            line=line,
        )
    if dt > MAX_DT:
        raise RecordFormatError(
            f"time step {dt:g} s is above {MAX_DT:g} s: the spectrum's periods from 0.15 s "
            f"need samples at most {MAX_DT:g} s apart (check the header or the time column's "
            "units: seconds)",
            file=str(path),
            line=line,
        )
    return dt
