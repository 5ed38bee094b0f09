"""Is a record's acceleration plausible in the units it was read in?

A file in m/s² read as g gives peak ground accelerations near 3 g, and one in g read as cm/s²
near 0.003 g: both then run silently and give nonsense.  :func:`plausibility_warnings` returns
one line per record whose PGA, *before any scaling*, is outside [:data:`PGA_MIN_G`,
:data:`PGA_MAX_G`], with the units that would bring it into a typical range.  Pure: it only
reads the records.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from frp_assess.motions.record import G, Record

#: largest plausible recorded PGA [g] (the largest ever recorded are about 2-4 g)
PGA_MAX_G = 2.0
#: smallest PGA [g] of a record worth an assessment
PGA_MIN_G = 0.001
#: a typical design PGA [g]: the suggested units bring the record closest to it
TYPICAL_PGA_G = 0.2
#: units a suggestion may name -> factor to m/s² (gal is cm/s²)
CANDIDATE_UNITS: dict[str, float] = {"g": G, "m/s2": 1.0, "cm/s2": 0.01}
_LABEL = {"g": "g", "m/s2": "m/s²", "cm/s2": "cm/s²"}


def _canonical(units: str) -> str:
    key = units.strip().lower().replace(" ", "").replace("^", "")
    return "cm/s2" if key == "gal" else key


def likely_units(peak: float, units: str) -> str | None:
    """The units in which a peak ``peak`` (a number of the file) is a plausible PGA.

    Among :data:`CANDIDATE_UNITS` other than ``units``, the one whose PGA is in
    [PGA_MIN_G, PGA_MAX_G] and closest (in ratio) to :data:`TYPICAL_PGA_G`; None if none is.
    """
    current = _canonical(units)
    best: tuple[float, str] | None = None
    for name, factor in CANDIDATE_UNITS.items():
        if name == current:
            continue
        pga_g = peak * factor / G
        if PGA_MIN_G <= pga_g <= PGA_MAX_G:
            distance = abs(math.log(pga_g / TYPICAL_PGA_G))
            if best is None or distance < best[0]:
                best = (distance, name)
    return None if best is None else best[1]


def plausibility_warning(record: Record, units: str | None = None) -> str | None:
    """One line if the record's PGA (as read, before scaling) looks like a units mistake.

    Args:
        record: the record as read [m/s²].
        units: the units its file was read in (default ``record.meta["units"]``, else g).
    """
    units = units or record.meta.get("units", "g")
    pga_g = record.pga_g
    if PGA_MIN_G <= pga_g <= PGA_MAX_G:
        return None
    current = _canonical(units)
    factor = CANDIDATE_UNITS.get(current, G)
    peak = record.pga / factor  # the number written in the file
    label = _LABEL.get(current, units)
    side = f"above {PGA_MAX_G:g} g" if pga_g > PGA_MAX_G else f"below {PGA_MIN_G:g} g"
    head = f"record {record.name!r}: PGA {pga_g:.3g} g as read ({peak:.3g} in {label}) is {side}"
    suggestion = likely_units(peak, units)
    if suggestion is None:
        return f"{head}; check the file and its units"
    return (
        f"{head}: the file looks like {_LABEL[suggestion]} "
        f"({peak * CANDIDATE_UNITS[suggestion] / G:.3g} g): set units: {suggestion}"
    )


def plausibility_warnings(records: Sequence[Record]) -> tuple[str, ...]:
    """The warnings of :func:`plausibility_warning` for every record, in order."""
    return tuple(w for r in records if (w := plausibility_warning(r)) is not None)
