"""Extract Italy's outline into frp_assess/data/italy_outline.csv.gz (run once).

Usage::

    python3 scripts/extract_italy_outline.py path/to/countries.geojson

The input is a GeoJSON FeatureCollection holding the feature of Italy (name "Italy" or ISO
code ITA) of Natural Earth's Admin-0 countries at 1:10m (public domain), e.g.
``data/countries.geojson`` of github.com/datasets/geo-countries (ODC-PDDL, the 1:10m layer
converted with ogr2ogr, 6 decimals) or an extract of that one feature.  What is written:

- every ring of Italy's polygons (mainland, islands, the hole of San Marino), each vertex
  rounded to 1e-5° (≈ 1 m, far below the data's accuracy; no vertex is removed), with the
  **neighbour across each edge**: ``FR``, ``CH``, ``AT``, ``SI`` along the land border,
  ``SM`` around San Marino, ``VA`` around the Vatican, empty along the coast;
- two stated corrections: the Vatican (Natural Earth's hole there is 0.1 x 0.13 km, a
  quarter of its 0.49 km²) is replaced by a 24-sided polygon of 0.49 km² around its
  published centre, and Campione d'Italia (an Italian exclave in Switzerland, 2.68 km², not
  in Natural Earth at this scale) is added as a 24-sided polygon of that area around its
  published centre (:data:`CORRECTIONS`; the sources are named there).

The land border is the chain of the mainland ring between the vertices where it meets the
coast at Ponte San Ludovico (Ventimiglia/Menton) and at Lazzaretto (Muggia/Koper); it is
split among the four neighbours at the vertices nearest the published tripoints
(:data:`TRIPOINTS`).  The script checks each of these vertices against its published point
before writing (:data:`MAX_ANCHOR_KM`).  Output: comment header, then ``ring,lon,lat,
beyond`` rows (``beyond`` the neighbour across the edge from this vertex to the next of its
ring; rings are closed implicitly), gzip with mtime 0: the same input gives the same bytes.
It prints the SHA-256 of the uncompressed text, the constant ``OUTLINE_SHA256`` of
frp_assess/motions/site/territory.py.
"""

from __future__ import annotations

import gzip
import hashlib
import json
import math
import sys
from pathlib import Path
from typing import Any

OUT = Path(__file__).resolve().parent.parent / "frp_assess" / "data" / "italy_outline.csv.gz"
EARTH_KM_PER_DEG = 6371.0 * math.pi / 180.0

#: where the land border meets the coast (lat, lon [°]); the Natural Earth vertex nearest each
#: is the end of the land-border chain (Ponte San Ludovico crossing, Ventimiglia/Menton; the
#: Lazzaretto crossing, Muggia/Koper: the vertices where the data's border line meets its
#: coastline, found by inspection and checked here)
COAST_ENDS = {"west": (43.7845, 7.5311), "east": (45.5932, 13.7118)}
#: the tripoints (lat, lon [°]) that split the land border, with the neighbour on each side:
#: Mont Dolent FR/CH/IT 45°55′19″N 7°02′46″E (fr.wikipedia "Mont Dolent"); Piz Lad CH/AT/IT,
#: the summit 46°50′54″N 10°28′19″E (de.wikipedia "Piz Lad"; the tripoint is 750 m north of
#: it); Peč (Monte Forno) AT/SI/IT 46°31′23″N 13°42′51″E (de.wikipedia "Dreiländereck (Berg)")
TRIPOINTS = (
    ("Mont Dolent", (45.92194, 7.04611)),
    ("Piz Lad", (46.84833, 10.47194)),
    ("Pec", (46.52306, 13.71417)),
)
#: the neighbours along the chain from the west coast end: France up to Mont Dolent,
#: Switzerland to Piz Lad, Austria to Peč, Slovenia to the east coast end
CHAIN_NEIGHBOURS = ("FR", "CH", "AT", "SI")
#: a chosen vertex farther than this from its published point is an error [km]
MAX_ANCHOR_KM = 2.0
#: the published centre of San Marino's capital (en.wikipedia "City of San Marino",
#: 43°56′4.56″N 12°26′50.28″E): the hole of the data that holds it is San Marino
SAN_MARINO = (43.9346, 12.44730)
#: the stated corrections: name, centre (lat, lon [°]), area [km²], neighbour across its edge,
#: whether it is a hole (foreign land inside Italy) or an extra part of Italy, and the source
CORRECTIONS: tuple[tuple[str, tuple[float, float], float, str, bool, str], ...] = (
    (
        "Vatican City",
        (41.90278, 12.45250),
        0.49,
        "VA",
        True,
        'en.wikipedia "Geography of Vatican City": 41°54′10″N 12°27′9″E, 49 ha',
    ),
    (
        "Campione d'Italia",
        (45.967, 8.967),
        2.68,
        "CH",
        False,
        'en.wikipedia "Campione d\'Italia" (2018): 45°58′N 8°58′E, 2.68 km²',
    ),
)
SIDES = 24


def km(a: tuple[float, float], b: tuple[float, float]) -> float:
    """Distance [km] between two (lat, lon) points, local flat earth (enough below 10 km)."""
    dy = (b[0] - a[0]) * EARTH_KM_PER_DEG
    dx = (b[1] - a[1]) * EARTH_KM_PER_DEG * math.cos(math.radians(0.5 * (a[0] + b[0])))
    return math.hypot(dx, dy)


def italy_polygons(path: Path) -> list[list[list[tuple[float, float]]]]:
    """The polygons (rings of (lat, lon), unclosed) of Italy's feature in the file."""
    data: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
    for feature in data["features"]:
        props = feature.get("properties") or {}
        names = {str(props.get(k)) for k in ("name", "NAME", "ADMIN", "admin")}
        codes = {str(props.get(k)) for k in ("ISO3166-1-Alpha-3", "ISO_A3", "iso_a3")}
        if "Italy" in names or "ITA" in codes:
            geom = feature["geometry"]
            polys = geom["coordinates"] if geom["type"] == "MultiPolygon" else [geom["coordinates"]]
            return [
                [[(float(p[1]), float(p[0])) for p in ring[:-1]] for ring in poly] for poly in polys
            ]
    raise SystemExit(f"{path}: no feature named Italy (or ITA)")


def contains(ring: list[tuple[float, float]], point: tuple[float, float]) -> bool:
    """Even-odd test of ``point`` (lat, lon) against one ring."""
    inside = False
    lat, lon = point
    for (y1, x1), (y2, x2) in zip(ring, ring[1:] + ring[:1], strict=True):
        if (y1 > lat) != (y2 > lat) and lon < x1 + (lat - y1) * (x2 - x1) / (y2 - y1):
            inside = not inside
    return inside


def nearest_vertex(ring: list[tuple[float, float]], point: tuple[float, float], what: str) -> int:
    i = min(range(len(ring)), key=lambda k: km(ring[k], point))
    d = km(ring[i], point)
    if d > MAX_ANCHOR_KM:
        raise SystemExit(f"{what}: nearest vertex {d:.2f} km away (more than {MAX_ANCHOR_KM})")
    print(f"{what}: vertex {i} at {ring[i][0]:.5f} N {ring[i][1]:.5f} E, {d:.2f} km away")
    return i


def label_mainland(ring: list[tuple[float, float]]) -> list[str]:
    """The neighbour across each edge of the mainland ring ("" on the coast)."""
    n = len(ring)
    west = nearest_vertex(ring, COAST_ENDS["west"], "land border, west end (coast)")
    east = nearest_vertex(ring, COAST_ENDS["east"], "land border, east end (coast)")
    splits = [nearest_vertex(ring, p, f"tripoint {name}") for name, p in TRIPOINTS]
    # walk from the west end in the direction that meets the tripoints before the east end
    for step in (1, -1):
        order, k = [], west
        while k != east:
            order.append(k)
            k = (k + step) % n
        if all(s in order for s in splits) and [order.index(s) for s in splits] == sorted(
            order.index(s) for s in splits
        ):
            break
    else:
        raise SystemExit("the tripoints are not in order along the land border")
    labels = [""] * n
    part = 0
    for k in order:
        if part < len(splits) and k == splits[part]:
            part += 1
        # the edge from k to its next vertex along the walk; stored on its first vertex in
        # ring order
        edge_start = k if step == 1 else (k - 1) % n
        labels[edge_start] = CHAIN_NEIGHBOURS[part]
    return labels


def polygon_of_area(
    centre: tuple[float, float], area_km2: float, clockwise: bool
) -> list[tuple[float, float]]:
    """A regular polygon of :data:`SIDES` sides and ``area_km2`` around ``centre``."""
    r = math.sqrt(2.0 * area_km2 / (SIDES * math.sin(2.0 * math.pi / SIDES)))
    lat0, lon0 = centre
    pts = []
    for k in range(SIDES):
        t = 2.0 * math.pi * k / SIDES * (-1 if clockwise else 1)
        pts.append(
            (
                lat0 + r * math.sin(t) / EARTH_KM_PER_DEG,
                lon0 + r * math.cos(t) / (EARTH_KM_PER_DEG * math.cos(math.radians(lat0))),
            )
        )
    return pts


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print(__doc__)
        return 2
    polys = italy_polygons(Path(argv[0]))
    mainland = max(polys, key=lambda p: len(p[0]))
    rings: list[tuple[list[tuple[float, float]], list[str]]] = []
    for poly in polys:
        for j, ring in enumerate(poly):
            if poly is mainland and j == 0:
                rings.append((ring, label_mainland(ring)))
            elif j == 0:
                rings.append((ring, [""] * len(ring)))  # an island: coast all round
            elif contains(ring, SAN_MARINO):
                rings.append((ring, ["SM"] * len(ring)))
            elif max(km(v, CORRECTIONS[0][1]) for v in ring) < 1.0:
                print(f"dropped the data's Vatican hole ({len(ring)} vertices)")
            else:
                raise SystemExit(f"an unexpected hole of {len(ring)} vertices at {ring[0]}")
    for name, centre, area, code, hole, source in CORRECTIONS:
        inside = any(contains(r, centre) for r, _ in rings[:1])
        if inside != hole:
            raise SystemExit(f"{name}: expected {'inside' if hole else 'outside'} the mainland")
        rings.append((polygon_of_area(centre, area, clockwise=hole), [code] * SIDES))
        print(f"added {name}: {area} km2 around {centre} ({source})")
    lines = [
        "# Italy's outline: Natural Earth Admin-0 countries 1:10m (public domain), feature Italy,",
        "# via github.com/datasets/geo-countries data/countries.geojson (ODC-PDDL); written by",
        "# scripts/extract_italy_outline.py: vertices rounded to 1e-5 deg, none removed; the",
        "# Vatican replaced and Campione d'Italia added as 24-gons of their published area",
        "# (sources in the script). Rows: ring, lon, lat [deg], neighbour across the edge from",
        "# this vertex to the next of its ring (FR CH AT SI SM VA; empty: the coast).",
        "ring,lon,lat,beyond",
    ]
    for i, (ring, labels) in enumerate(rings):
        for (lat, lon), beyond in zip(ring, labels, strict=True):
            lines.append(f"{i},{lon:.5f},{lat:.5f},{beyond}")
    text = ("\n".join(lines) + "\n").encode("ascii")
    OUT.write_bytes(gzip.compress(text, compresslevel=9, mtime=0))
    vertices = sum(len(r) for r, _ in rings)
    print(f"wrote {OUT} ({OUT.stat().st_size} bytes, {len(rings)} rings, {vertices} vertices)")
    print(f"OUTLINE_SHA256 = {hashlib.sha256(text).hexdigest()!r}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
