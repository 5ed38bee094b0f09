"""The geometry of frp_assess/motions/site/territory.py: the point-in-polygon test, the distance
to the outline's edges, and the packaged outline's integrity.

References: the even-odd test against an independent winding-number count written here (the
sum of the angles the edges subtend at the point: 2π inside a ring, 0 outside), on a square,
an L-shaped (concave) ring, a ring with a hole and a separate ring inside the hole; distances
against hand values (a meridian segment 0.01° of longitude away at latitude 45°:
0.01·π/180·6371·cos 45° = 0.7862 km; the end of a segment: Pythagoras).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.motions.site import territory
from frp_assess.motions.site.grid import GridDataError
from frp_assess.motions.site.territory import inside_rings, load_outline, segment_distances

Ring = list[tuple[float, float]]  # (lat, lon) vertices, unclosed

SQUARE: Ring = [(0.0, 0.0), (0.0, 1.0), (1.0, 1.0), (1.0, 0.0)]
L_SHAPE: Ring = [(0, 0), (0, 2), (1, 2), (1, 1), (2, 1), (2, 0)]
HOLE: Ring = [(0.25, 0.25), (0.75, 0.25), (0.75, 0.75), (0.25, 0.75)]
ISLAND: Ring = [(0.4, 0.4), (0.4, 0.6), (0.6, 0.6), (0.6, 0.4)]


def _edges(*rings: Ring) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    a = [v for r in rings for v in r]
    b = [v for r in rings for v in r[1:] + r[:1]]
    return (
        np.array([p[0] for p in a], float),
        np.array([p[1] for p in a], float),
        np.array([p[0] for p in b], float),
        np.array([p[1] for p in b], float),
    )


def _winding_inside(lat: float, lon: float, *rings: Ring) -> bool:
    """Independent reference: the parity of the rings whose winding number about the point
    is not zero (angles summed edge by edge)."""
    count = 0
    for ring in rings:
        total = 0.0
        for (y1, x1), (y2, x2) in zip(ring, ring[1:] + ring[:1], strict=True):
            a1 = math.atan2(y1 - lat, x1 - lon)
            a2 = math.atan2(y2 - lat, x2 - lon)
            d = a2 - a1
            while d > math.pi:
                d -= 2 * math.pi
            while d < -math.pi:
                d += 2 * math.pi
            total += d
        count += abs(total) > math.pi
    return count % 2 == 1


@pytest.mark.parametrize(
    "rings",
    [(SQUARE,), (L_SHAPE,), (SQUARE, HOLE), (SQUARE, HOLE, ISLAND)],
    ids=["square", "L-shaped", "square with a hole", "hole with an island"],
)
def test_even_odd_agrees_with_the_winding_number(rings: tuple[Ring, ...]) -> None:
    rng = np.random.default_rng(7)
    edges = _edges(*rings)
    points = rng.uniform(-0.5, 2.5, size=(2000, 2))
    for lat, lon in points:
        assert inside_rings(lat, lon, *edges) == _winding_inside(lat, lon, *rings)


def test_hand_points() -> None:
    square_with_hole = _edges(SQUARE, HOLE)
    assert inside_rings(0.1, 0.1, *square_with_hole)
    assert not inside_rings(0.5, 0.5, *square_with_hole)  # in the hole (an enclave)
    assert inside_rings(0.5, 0.5, *_edges(SQUARE, HOLE, ISLAND))  # an exclave in the hole
    assert not inside_rings(1.5, 1.5, *_edges(L_SHAPE))  # the notch of the L
    assert inside_rings(0.5, 1.5, *_edges(L_SHAPE))


def test_distances_by_hand() -> None:
    lat1, lon1 = np.array([44.9, 45.0]), np.array([10.01, 10.0])
    lat2, lon2 = np.array([45.1, 45.0]), np.array([10.01, 10.02])
    d = segment_distances(45.0, 10.0, lat1, lon1, lat2, lon2)
    km_per_deg = math.pi / 180 * 6371
    assert d[0] == pytest.approx(0.01 * km_per_deg * math.cos(math.radians(45)), rel=1e-9)
    assert d[1] == 0.0  # the site is the segment's end
    far = segment_distances(45.0, 10.0, np.array([45.03]), np.array([10.04]), np.array([45.05]),
                            np.array([10.04]))  # fmt: skip
    dx, dy = 0.04 * km_per_deg * math.cos(math.radians(45)), 0.03 * km_per_deg
    assert far[0] == pytest.approx(math.hypot(dx, dy), rel=1e-9)  # the nearer end


def test_the_outline_has_the_land_border_neighbours() -> None:
    o = load_outline()
    assert set(o.beyond) == {"", "FR", "CH", "AT", "SI", "SM", "VA"}
    assert o.lat1.size == 3372  # the rows of the file (scripts/extract_italy_outline.py)
    # every edge ends where the next of its ring starts: rings closed, no stray vertex
    assert np.all(np.isin(o.lat2, o.lat1))


def test_a_changed_outline_file_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    load_outline.cache_clear()
    monkeypatch.setattr(territory, "OUTLINE_SHA256", "0" * 64)
    try:
        with pytest.raises(GridDataError, match="corrupt or was changed"):
            load_outline()
    finally:
        load_outline.cache_clear()
