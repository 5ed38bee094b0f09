"""Whether a site is in Italy: the packaged outline of Italy's territory and its land border.

The NTC reference grid reaches across the land borders (Lugano, Koper, Menton lie in complete
grid cells < 2 km from a node), so the grid alone cannot tell a site abroad from an Italian
one.  ``frp_assess/data/italy_outline.csv.gz`` holds Italy's outline (Natural Earth Admin-0
1:10m, public domain, with two stated corrections: the Vatican and Campione d'Italia;
``scripts/extract_italy_outline.py``, frp_assess/data/README.md): every ring with, for each
edge, the neighbour across it (France, Switzerland, Austria, Slovenia, San Marino, Vatican
City; none on the coast).  Its SHA-256 is checked on loading, like the grid's.

:func:`check_in_italy` decides, from the site's distance to the land border d_b and to the
coast d_c (km, on the local tangent plane) and whether the outline holds the site:

- outside the outline, the land border nearer than the coast (d_b <= d_c) and farther than
  :data:`BORDER_BAND_KM`: abroad, refused (:class:`OutsideItalyError`);
- d_b <= :data:`BORDER_BAND_KM`, inside or outside: accepted with a warning (the border is
  within the outline's accuracy: the values assume the site is in Italy);
- otherwise accepted silently: inside, or outside on the coast's side (a coastal site the
  1:10m coastline leaves at sea, a small island the outline lacks): the grid decides, as
  before (:func:`~frp_assess.motions.site.grid.nearest_nodes`).

The neighbour is named only when the land border is within :data:`NAME_WITHIN_KM`: farther,
the nearest border may not be the country the site is in (Monaco, Croatia).
"""

from __future__ import annotations

import functools
import io
import math
from dataclasses import dataclass

import numpy as np

from frp_assess import libm
from frp_assess.errors import InputError
from frp_assess.motions.site.formulas import EARTH_RADIUS_KM
from frp_assess.motions.site.grid import packaged_text

OUTLINE_FILE = "italy_outline.csv.gz"
#: SHA-256 of the uncompressed text of :data:`OUTLINE_FILE` (printed by the script)
OUTLINE_SHA256 = "eb0b9c50a214d055b2d09d5deda8fc8dba7974d9f27269b3838d7b2ca24423a7"
#: the band [km] on both sides of the land border where a site is warned, not refused: the
#: outline lies 0.4-1.2 km from seven border points with published coordinates (three
#: tripoints, four passes and squares: docs/site-hazard.md), its straight edges up to 10 km
#: long; 2 km covers the largest offset measured with a margin
BORDER_BAND_KM = 2.0
#: the neighbour across the border is named only within this distance [km] of it
NAME_WITHIN_KM = 5.0
#: the neighbours' codes in the outline file and their names
NEIGHBOURS: dict[str, str] = {
    "FR": "France",
    "CH": "Switzerland",
    "AT": "Austria",
    "SI": "Slovenia",
    "SM": "San Marino",
    "VA": "Vatican City",
}


class OutsideItalyError(InputError):
    """The site lies outside Italy (abroad): the NTC grid's values do not apply there."""


@dataclass(frozen=True)
class Outline:
    """The outline's edges, from (lat1, lon1) to (lat2, lon2) [°] (each shape (n,)), and the
    neighbour across each (a :data:`NEIGHBOURS` code, "" on the coast)."""

    lat1: np.ndarray
    lon1: np.ndarray
    lat2: np.ndarray
    lon2: np.ndarray
    beyond: tuple[str, ...]

    @property
    def land(self) -> np.ndarray:
        """Which edges are land border (a neighbour across them)."""
        return np.array([b != "" for b in self.beyond])


@dataclass(frozen=True)
class Placement:
    """Where a site is with respect to Italy: ``inside`` the outline; ``border_km`` and
    ``coast_km`` its distances [km] to the land border and to the coast; ``neighbour`` the
    country across the nearest land border (its :data:`NEIGHBOURS` name)."""

    inside: bool
    border_km: float
    coast_km: float
    neighbour: str


@functools.cache
def load_outline() -> Outline:
    """The packaged outline, read and checked once (:class:`GridDataError` if it is not the
    file of this version)."""
    rows = [
        line.split(",")
        for line in io.StringIO(
            packaged_text(OUTLINE_FILE, "Italy's outline", OUTLINE_SHA256).decode("ascii")
        )
        if line.strip() and not line.startswith("#")
    ][1:]  # the column names
    ring = np.array([int(r[0]) for r in rows])
    lon = np.array([float(r[1]) for r in rows])
    lat = np.array([float(r[2]) for r in rows])
    beyond = tuple(r[3].strip() for r in rows)
    # the next vertex of each one's ring (rings are stored unclosed)
    nxt = np.arange(1, ring.size + 1)
    last = np.flatnonzero(np.append(ring[1:] != ring[:-1], True))
    first = np.concatenate([[0], last[:-1] + 1])
    nxt[last] = first
    return Outline(lat, lon, lat[nxt], lon[nxt], beyond)


def inside_rings(
    lat: float, lon: float, lat1: np.ndarray, lon1: np.ndarray, lat2: np.ndarray, lon2: np.ndarray
) -> bool:
    """Whether (lat, lon) is inside the polygon made of the edges (lat1, lon1)-(lat2, lon2)
    by the even-odd rule (ray casting eastwards): holes and extra rings count by parity, so
    an enclave inside Italy is outside and an exclave is inside.  A point exactly on an edge
    may fall on either side."""
    crosses = (lat1 > lat) != (lat2 > lat)
    with np.errstate(divide="ignore", invalid="ignore"):
        x_at = lon1 + (lat - lat1) * (lon2 - lon1) / (lat2 - lat1)
    return bool(np.count_nonzero(crosses & (lon < x_at)) % 2)


def segment_distances(
    lat: float, lon: float, lat1: np.ndarray, lon1: np.ndarray, lat2: np.ndarray, lon2: np.ndarray
) -> np.ndarray:
    """Distances [km] from (lat, lon) to the segments (lat1, lon1)-(lat2, lon2), on the plane
    tangent at the site (equirectangular about it: within 0.5 % below 100 km)."""
    ky = math.radians(1.0) * EARTH_RADIUS_KM
    kx = ky * float(libm.cos(np.radians(lat)))
    ax, ay = (lon1 - lon) * kx, (lat1 - lat) * ky
    ex, ey = (lon2 - lon1) * kx, (lat2 - lat1) * ky
    length2 = ex * ex + ey * ey
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(length2 > 0, -(ax * ex + ay * ey) / length2, 0.0)
    t = np.clip(t, 0.0, 1.0)
    return np.asarray(np.hypot(ax + t * ex, ay + t * ey))


def placement(latitude: float, longitude: float) -> Placement:
    """Where the site [°] is with respect to Italy's outline and land border."""
    o = load_outline()
    edges = (o.lat1, o.lon1, o.lat2, o.lon2)
    inside = inside_rings(latitude, longitude, *edges)
    d = segment_distances(latitude, longitude, *edges)
    land = o.land
    k_land = int(np.argmin(np.where(land, d, np.inf)))
    coast = float(np.min(d[~land])) if np.any(~land) else math.inf
    return Placement(inside, float(d[k_land]), coast, NEIGHBOURS[o.beyond[k_land]])


def _where(latitude: float, longitude: float) -> str:
    ns = "N" if latitude >= 0 else "S"
    ew = "E" if longitude >= 0 else "W"
    return f"{abs(latitude):.4f} {ns} {abs(longitude):.4f} {ew}"


def check_in_italy(latitude: float, longitude: float) -> str | None:
    """Refuse a site abroad (:class:`OutsideItalyError`); for a site within
    :data:`BORDER_BAND_KM` of the land border return the warning to show (one line), else
    None.  The rule: this module's docstring."""
    p = placement(latitude, longitude)
    named = f" ({p.neighbour}?)" if p.border_km <= NAME_WITHIN_KM else ""
    if not p.inside and p.border_km > BORDER_BAND_KM and p.border_km <= p.coast_km:
        raise OutsideItalyError(
            f"{_where(latitude, longitude)} lies outside Italy{named}, {p.border_km:.1f} km "
            "beyond its border: the NTC 2018 reference grid applies to sites in Italy; check "
            "the coordinates (decimal degrees, latitude first), or for a site abroad give ag, "
            "F0 and Tc_star instead"
        )
    if p.border_km > BORDER_BAND_KM:
        return None
    side = "inside Italy's outline" if p.inside else f"outside Italy's outline ({p.neighbour}?)"
    return (
        f"{_where(latitude, longitude)} is {p.border_km:.1f} km from Italy's border with "
        f"{p.neighbour}, {side}: the outline is accurate to about {BORDER_BAND_KM:g} km, "
        "so the site may be abroad; the NTC values assume it is in Italy: check the "
        "coordinates"
    )
