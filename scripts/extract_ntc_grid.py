"""Extract the NTC reference hazard grid into frp_assess/data/ntc2018_grid.csv.gz (run once).

Usage::

    python3 scripts/extract_ntc_grid.py path/to/HazardNTCgrid_IT.mat

The input is a MATLAB file holding ONE array of 10751 rows x 29 columns: longitude and
latitude [°] of each node of the reference grid published with NTC 2008 Allegato B (kept by
NTC 2018), then, for each of the nine return periods 30, 50, 72, 101, 140, 201, 475, 975 and
2475 years, a_g [g/10], F0 [-] and T_C* [s].  A copy of it ships in the wheel of the PyPI
package ``bimquake`` 1.0.0 (``bimquake/hazard_data/HazardNTCgrid_IT.mat``); only the numbers
are taken from it (``pip download --no-deps bimquake==1.0.0`` and unzip the wheel).

The column order is checked here against values known independently (a_g(475) ≈ 0.26 g near
L'Aquila, ≈ 0.05 g in Milano, a_g growing with the return period at every node) before
anything is written.  The output is the numbers as read (shortest round-trip text of each
double; a_g kept in g/10 as published), node order of the source, gzip with mtime 0: the same
input always gives the same bytes.  It prints the SHA-256 of the uncompressed CSV text, the
constant ``GRID_SHA256`` of frp_assess/motions/site/grid.py.
"""

from __future__ import annotations

import gzip
import hashlib
import sys
from pathlib import Path

import numpy as np
import scipy.io

OUT = Path(__file__).resolve().parent.parent / "frp_assess" / "data" / "ntc2018_grid.csv.gz"
RETURN_PERIODS = (30, 50, 72, 101, 140, 201, 475, 975, 2475)
NODES = 10751

HEADER = """\
# NTC reference seismic hazard grid (reticolo di riferimento), 10751 nodes.
# Source: the grid published with NTC 2008 (D.M. 14 gennaio 2008) Allegato B, prepared for the
# Consiglio Superiore dei Lavori Pubblici from the INGV hazard model; kept unchanged by NTC 2018
# (D.M. 17 gennaio 2018). Numbers read from HazardNTCgrid_IT.mat as shipped in the PyPI wheel
# bimquake 1.0.0 by scripts/extract_ntc_grid.py (values unchanged, node order of the source).
# Columns: lon, lat [deg, ED50 as published]; then per return period TR [years]:
# ag_TR [g/10, as in Allegato B], F0_TR [-], Tc_TR [s] (T_C*).
"""


def _distance_km(lat: float, lon: float, grid: np.ndarray) -> np.ndarray:
    lat1, lat2 = np.radians(lat), np.radians(grid[:, 1])
    dlat, dlon = lat2 - lat1, np.radians(grid[:, 0] - lon)
    h = np.sin(dlat / 2) ** 2 + np.cos(lat1) * np.cos(lat2) * np.sin(dlon / 2) ** 2
    return 2 * 6371.0 * np.arcsin(np.sqrt(h))


def check_columns(grid: np.ndarray) -> None:
    """Refuse a file whose columns are not lon, lat, (a_g, F0, T_C*) x 9 as expected."""
    if grid.shape != (NODES, 2 + 3 * len(RETURN_PERIODS)):
        raise SystemExit(f"expected an array of {NODES} x 29, found {grid.shape}")
    if not (6 < grid[:, 0].min() and grid[:, 0].max() < 19):
        raise SystemExit("column 1 is not a longitude of Italy")
    if not (36 < grid[:, 1].min() and grid[:, 1].max() < 48):
        raise SystemExit("column 2 is not a latitude of Italy")
    ag = grid[:, 2::3]
    if not np.all(np.diff(ag, axis=1) > 0):
        raise SystemExit("a_g does not grow with the return period at every node")
    if not (np.all((grid[:, 3::3] > 1.5) & (grid[:, 3::3] < 3.5))):
        raise SystemExit("F0 columns out of 1.5-3.5")
    if not (np.all((grid[:, 4::3] > 0.05) & (grid[:, 4::3] < 0.7))):
        raise SystemExit("T_C* columns out of 0.05-0.7 s")
    i475 = 2 + 3 * RETURN_PERIODS.index(475)
    for name, lat, lon, low, high in (
        ("L'Aquila", 42.35, 13.40, 0.24, 0.28),
        ("Milano", 45.464, 9.19, 0.04, 0.06),
    ):
        node = int(np.argmin(_distance_km(lat, lon, grid)))
        ag475 = grid[node, i475] / 10.0
        if not low <= ag475 <= high:
            raise SystemExit(f"{name}: a_g(475) = {ag475:g} g, expected {low}-{high} g")


def csv_text(grid: np.ndarray) -> str:
    """The grid as CSV text: the provenance header, the column names, one node a line."""
    names = ["lon", "lat"]
    for tr in RETURN_PERIODS:
        names += [f"ag_{tr}", f"F0_{tr}", f"Tc_{tr}"]
    lines = [HEADER.rstrip("\n"), ",".join(names)]
    lines += [",".join(repr(float(v)) for v in row) for row in grid]
    return "\n".join(lines) + "\n"


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print(__doc__.split("\n\n")[1].strip(), file=sys.stderr)
        return 2
    data = scipy.io.loadmat(argv[0])
    arrays = [v for k, v in data.items() if not k.startswith("__")]
    if len(arrays) != 1:
        raise SystemExit(f"expected one array in {argv[0]}, found {len(arrays)}")
    grid = np.asarray(arrays[0], dtype=float)
    check_columns(grid)
    text = csv_text(grid).encode("utf-8")
    OUT.parent.mkdir(parents=True, exist_ok=True)
    with open(OUT, "wb") as raw, gzip.GzipFile("", "wb", 9, raw, mtime=0) as gz:
        gz.write(text)
    print(f"wrote {OUT} ({OUT.stat().st_size} bytes)")
    print(f"SHA-256 of the CSV text: {hashlib.sha256(text).hexdigest()}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
