"""The NTC reference hazard grid shipped as package data, and the nodes around a site.

``frp_assess/data/ntc2018_grid.csv.gz`` holds the 10,751 nodes of the grid published with
NTC 2008 Allegato B (kept by NTC 2018): longitude, latitude [°] and, for each of the nine
return periods 30-2475 years, a_g [g/10 as published], F0 [-], T_C* [s].  It is read once;
its uncompressed text must have the SHA-256 :data:`GRID_SHA256` (written by
``scripts/extract_ntc_grid.py``), otherwise loading fails with a clear error.  Provenance:
``frp_assess/data/README.md`` and docs/site-hazard.md.
"""

from __future__ import annotations

import functools
import gzip
import hashlib
import io
from dataclasses import dataclass
from importlib import resources

import numpy as np

from frp_assess import libm
from frp_assess.errors import InputError
from frp_assess.motions.site.formulas import EARTH_RADIUS_KM, GRID_RETURN_PERIODS

GRID_FILE = "ntc2018_grid.csv.gz"
#: SHA-256 of the uncompressed CSV text of :data:`GRID_FILE`
GRID_SHA256 = "43c1b7d44cbae44e01cfea4e9f48b7df22fbabbd9459d4ec8e7317bd512820dd"
GRID_NODES = 10751
#: a site farther than this from every node is outside the grid [km]: a little more than the
#: grid step (≈ 5.5 km); inside the grid no point is farther than half a cell's diagonal
#: (≈ 3.9 km) from a node
MAX_NODE_DISTANCE_KM = 6.0
#: how many nodes the spatial interpolation uses (NTC 2008 Allegato A: a cell's vertices)
NODES_PER_SITE = 4


class GridDataError(RuntimeError):
    """The packaged grid is missing or not the file this version was built with."""


class OutsideGridError(InputError):
    """The site is not covered by the reference grid (sea, abroad, a small island)."""


@dataclass(frozen=True)
class HazardGrid:
    """The grid: ``lon``, ``lat`` [°] of each node (shape (n,)); ``ag`` [g], ``F0`` [-],
    ``Tc_star`` [s] at each node and grid return period (shape (n, 9), columns in the order
    of :data:`~frp_assess.motions.site.formulas.GRID_RETURN_PERIODS`)."""

    lon: np.ndarray
    lat: np.ndarray
    ag: np.ndarray
    F0: np.ndarray
    Tc_star: np.ndarray


@dataclass(frozen=True)
class NearNode:
    """A grid node near a site: its row in the grid (0-based, source order), coordinates [°]
    and great-circle distance [km] from the site."""

    index: int
    lat: float
    lon: float
    distance: float


def packaged_text(file: str, what: str, sha256: str) -> bytes:
    """The packaged data file ``frp_assess/data/<file>`` (gzip), decompressed and checked
    against its SHA-256; ``what`` names it in the one-line :class:`GridDataError` a missing,
    corrupt or changed file gives."""
    try:
        raw = resources.files("frp_assess").joinpath("data", file).read_bytes()
    except OSError as exc:
        raise GridDataError(
            f"{what} frp_assess/data/{file} is missing ({exc}); reinstall frp-assess"
        ) from None
    text = gzip.decompress(raw)
    digest = hashlib.sha256(text).hexdigest()
    if digest != sha256:
        raise GridDataError(
            f"{what} frp_assess/data/{file} is corrupt or was changed: SHA-256 {digest}, "
            f"expected {sha256}; reinstall frp-assess"
        )
    return text


@functools.cache
def load_grid() -> HazardGrid:
    """The packaged grid, read and checked once (:class:`GridDataError` if it is not the
    file of this version)."""
    table = np.loadtxt(
        io.BytesIO(packaged_text(GRID_FILE, "the NTC hazard grid", GRID_SHA256)),
        delimiter=",",
        comments="#",
        skiprows=8,
    )
    if table.shape != (GRID_NODES, 2 + 3 * len(GRID_RETURN_PERIODS)):
        raise GridDataError(f"the NTC hazard grid has shape {table.shape}")  # pragma: no cover
    table.setflags(write=False)
    return HazardGrid(
        lon=table[:, 0],
        lat=table[:, 1],
        ag=table[:, 2::3] / 10.0,  # published in g/10
        F0=table[:, 3::3],
        Tc_star=table[:, 4::3],
    )


def unit_vectors(lat: np.ndarray, lon: np.ndarray) -> np.ndarray:
    """Unit vectors (shape (..., 3)) of points given by latitude and longitude [°]."""
    phi, lam = np.radians(lat), np.radians(lon)
    return np.stack(
        [libm.cos(phi) * libm.cos(lam), libm.cos(phi) * libm.sin(lam), libm.sin(phi)], axis=-1
    )


@functools.cache
def _node_vectors() -> np.ndarray:
    g = load_grid()
    return unit_vectors(g.lat, g.lon)


def check_coordinates(latitude: float, longitude: float) -> None:
    """Refuse coordinates that are not a latitude/longitude in degrees (InputError)."""
    if not (np.isfinite(latitude) and -90.0 <= latitude <= 90.0):
        raise InputError(f"expected a latitude in degrees, -90 to 90, found {latitude!r}")
    if not (np.isfinite(longitude) and -180.0 <= longitude <= 180.0):
        raise InputError(f"expected a longitude in degrees, -180 to 180, found {longitude!r}")


def near_nodes(latitude: float, longitude: float, indices: np.ndarray) -> tuple[NearNode, ...]:
    """The grid nodes of rows ``indices`` with their great-circle distances [km] from the
    site [°]: 2R·asin(c/2), c the chord between unit vectors (exact, stable near zero)."""
    g = load_grid()
    site = unit_vectors(np.array(latitude), np.array(longitude))
    chord = np.linalg.norm(_node_vectors()[indices] - site, axis=1)
    dist = 2.0 * EARTH_RADIUS_KM * libm.arcsin(np.minimum(chord / 2.0, 1.0))
    return tuple(
        NearNode(int(i), float(g.lat[i]), float(g.lon[i]), float(d))
        for i, d in zip(indices, dist, strict=True)
    )


def nearest_nodes(latitude: float, longitude: float) -> tuple[NearNode, ...]:
    """The :data:`NODES_PER_SITE` nodes nearest to the site [°], nearest first.

    Nodes are ranked by the chord between unit vectors (the same order as the great-circle
    distance), distances are great-circle [km] on a sphere of radius 6371 km.  Raises
    :class:`OutsideGridError` when the nearest node is farther than
    :data:`MAX_NODE_DISTANCE_KM`: the site is at sea, abroad, or on an island whose values
    NTC 2008 Allegato B gives separately (Tab. 1).
    """
    check_coordinates(latitude, longitude)
    site = unit_vectors(np.array(latitude), np.array(longitude))
    chord = np.linalg.norm(_node_vectors() - site, axis=1)
    nodes = near_nodes(latitude, longitude, np.argsort(chord, kind="stable")[:NODES_PER_SITE])
    if nodes[0].distance > MAX_NODE_DISTANCE_KM:
        raise OutsideGridError(
            f"latitude {latitude:g}, longitude {longitude:g} is outside the NTC reference grid "
            f"(nearest node {nodes[0].distance:.1f} km away, more than "
            f"{MAX_NODE_DISTANCE_KM:g} km): at sea, abroad, or on an island other than "
            "Sicily, Ischia, Procida and Capri, whose a_g, F0, T_C* NTC 2008 Allegato B "
            "Tab. 1 gives per island; give ag, F0 and Tc_star instead"
        )
    return nodes
