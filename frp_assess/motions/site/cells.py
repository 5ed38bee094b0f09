"""The elementary cells of the NTC reference grid and the cell that contains a site.

NTC 2008 Allegato A (kept by NTC 2018) takes the value at a site as the mean of the values
"nei quattro vertici della maglia elementare del reticolo di riferimento contenente il punto
in esame", weighted by the inverse of the distances of the site from the four vertices.

The packaged grid lists the nodes by longitude (columns of the lattice), not by the official
node ID, so the lattice is rebuilt here from the coordinates: every node has its lattice
neighbours 5.53-5.56 km away (the diagonal ones ≈ 7.85 km), the lattice being square but
turned by the meridian convergence of its projection (-3.4° in the west to +4.7° in the
east).  Starting from one node, each neighbour closer than :data:`NEIGHBOUR_KM` takes the
lattice index (column ``i`` eastwards, row ``j`` northwards) of the step it is in — east,
west, north or south, whichever component of the step is the larger — and the construction
checks that no node gets two indices and no index two nodes.  A cell is four nodes
(i, j), (i+1, j), (i+1, j+1), (i, j+1) that all exist.

The cell containing a site is found among the cells that have one of the site's nearest
nodes as a vertex, by the point-in-quadrilateral test in the plane tangent to the sphere at
the site.  A site on the edge shared by two cells belongs to the cell on the north or east
side of it (a cell holds its west and south edges, like the half-open square [i, i+1) x
[j, j+1)); a site on a node takes the node's values whatever the cell.
"""

from __future__ import annotations

import functools
import math
from collections import deque
from dataclasses import dataclass

import numpy as np

from frp_assess import libm
from frp_assess.motions.site.grid import load_grid, unit_vectors

#: two nodes closer than this [km] are lattice neighbours (the step is 5.53-5.56 km, the
#: diagonal 7.84-7.86 km)
NEIGHBOUR_KM = 6.5
#: a site this close [km] to a cell's edge line counts as on it (1 mm: far below the
#: 5-digit rounding of the coordinates, ≈ 1 m)
EDGE_TOLERANCE_KM = 1e-6
#: how many of the site's nearest nodes give the candidate cells (each is a vertex of up to
#: four cells); the nearest node to a point inside a cell is always a vertex of that cell on
#: a near-square lattice, four leave room for the lattice's small irregularity
CANDIDATE_NODES = 4


@dataclass(frozen=True)
class Lattice:
    """The grid's topology: ``i``, ``j`` the lattice column (eastwards) and row (northwards)
    of each node (shape (n,)); ``node_at`` the node of each (i, j)."""

    i: np.ndarray
    j: np.ndarray
    node_at: dict[tuple[int, int], int]

    def cell(self, i: int, j: int) -> tuple[int, int, int, int] | None:
        """The nodes of the cell whose south-west vertex is (i, j), counter-clockwise from
        it; None when one of the four is missing (the grid's border)."""
        corners = ((i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1))
        nodes = tuple(self.node_at.get(c, -1) for c in corners)
        if min(nodes) < 0:
            return None
        return nodes[0], nodes[1], nodes[2], nodes[3]


@functools.cache
def lattice() -> Lattice:
    """The grid's lattice, rebuilt once from the node coordinates (RuntimeError if the
    coordinates do not make one consistent square lattice)."""
    from scipy.spatial import cKDTree

    g = load_grid()
    n = g.lat.size
    xyz = unit_vectors(g.lat, g.lon) * 6371.0
    dist, near = cKDTree(xyz).query(xyz, k=9)
    unset = np.iinfo(np.int64).min
    ii = np.full(n, unset, dtype=np.int64)
    jj = np.full(n, unset, dtype=np.int64)
    ii[0] = jj[0] = 0
    queue = deque([0])
    while queue:
        a = queue.popleft()
        for d, b in zip(dist[a, 1:], near[a, 1:], strict=True):
            if d > NEIGHBOUR_KM:
                break
            east = (g.lon[b] - g.lon[a]) * libm.cos(np.radians(0.5 * (g.lat[a] + g.lat[b])))
            north = g.lat[b] - g.lat[a]
            if abs(east) > abs(north):
                step = (1 if east > 0 else -1, 0)
            else:
                step = (0, 1 if north > 0 else -1)
            target = (int(ii[a]) + step[0], int(jj[a]) + step[1])
            if ii[b] == unset:
                ii[b], jj[b] = target
                queue.append(int(b))
            elif (int(ii[b]), int(jj[b])) != target:
                raise RuntimeError(f"grid node {b} has two lattice positions")
    if np.any(ii == unset):
        raise RuntimeError("the grid's nodes are not one connected lattice")
    node_at = {(int(x), int(y)): k for k, (x, y) in enumerate(zip(ii, jj, strict=True))}
    if len(node_at) != n:
        raise RuntimeError("two grid nodes share one lattice position")
    ii.setflags(write=False)
    jj.setflags(write=False)
    return Lattice(ii, jj, node_at)


def _tangent_plane(latitude: float, longitude: float, nodes: np.ndarray) -> np.ndarray:
    """East, north coordinates [km] of the grid ``nodes`` in the plane tangent to the
    sphere at the site (gnomonic: straight lines on the sphere stay straight)."""
    g = load_grid()
    site = unit_vectors(np.array(latitude), np.array(longitude))
    lam = np.radians(longitude)
    east = np.array([-math.sin(lam), math.cos(lam), 0.0])
    north = np.cross(site, east)
    v = unit_vectors(g.lat[nodes], g.lon[nodes])
    scale = 6371.0 / _dot(v, site)
    return np.stack([_dot(v, east) * scale, _dot(v, north) * scale], axis=-1)


def _dot(v: np.ndarray, w: np.ndarray) -> np.ndarray:
    """v·w of each row of ``v`` (shape (n, 3)) with the 3-vector ``w``, in plain arithmetic
    (a BLAS product may round by the processor's kernel)."""
    return v[:, 0] * w[0] + v[:, 1] * w[1] + v[:, 2] * w[2]


def _holds(corners: np.ndarray) -> bool:
    """Whether the origin is inside the quadrilateral ``corners`` (4 x 2, km, counter-
    clockwise from the south-west vertex), its west and south edges included and its east
    and north edges excluded."""
    for k in range(4):
        a, b = corners[k], corners[(k + 1) % 4]
        edge = b - a
        # signed distance of the origin from the edge line, > 0 on the inner side
        side = (edge[0] * (-a[1]) - edge[1] * (-a[0])) / float(np.hypot(*edge))
        if k in (0, 3):  # south and west edges: the cell holds them
            if side < -EDGE_TOLERANCE_KM:
                return False
        elif side <= EDGE_TOLERANCE_KM:  # east and north edges: the next cell holds them
            return False
    return True


def containing_cell(
    latitude: float, longitude: float, nearest: tuple[int, ...]
) -> tuple[int, int, int, int] | None:
    """The four nodes (grid rows, counter-clockwise from the south-west one) of the cell
    that contains the site [°], searched around the ``nearest`` nodes (nearest first);
    None when no complete cell does (a site on the grid's border or beyond it)."""
    lat_ = lattice()
    seen: set[tuple[int, int]] = set()
    for node in nearest[:CANDIDATE_NODES]:
        i0, j0 = int(lat_.i[node]), int(lat_.j[node])
        for sw in ((i0, j0), (i0 - 1, j0), (i0 - 1, j0 - 1), (i0, j0 - 1)):
            if sw in seen:
                continue
            seen.add(sw)
            cell = lat_.cell(*sw)
            if cell is not None and _holds(_tangent_plane(latitude, longitude, np.array(cell))):
                return cell
    return None
