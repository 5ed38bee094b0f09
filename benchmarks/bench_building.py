"""A building of 30 walls run on local threads and on Dask, side by side (issue 41 item 6).

    PYTHONPATH=. python3 benchmarks/bench_building.py [--walls N] [--rounds N]

The building is generated from the bundled example's four walls
(projects/building-camerino.yaml: a ground-floor façade, a top-storey façade, a gable and a
boundary wall, with their floors and options): N walls (default 30) cycle through them, the
k-th with its height and thickness scaled by 0.85 + 0.3·(k mod 7)/6 and 0.9 + 0.2·(k mod 5)/4
(an upper-floor wall kept inside its building); the example's records (3 × 25 s, the fewest
the code accepts) are shared.  After a warm-up of each executor (numba's cache filled, a
LocalCluster started once), ``frp-assess run BUILDING --no-pdf`` (local threads, ``--jobs 2``)
and ``... --executor dask --jobs 2`` (a LocalCluster of 2 worker processes, started by the
command and counted in its time) run alternately, N rounds (default 1), each into a fresh
``--out`` folder (every wall's IDA cache empty).  Printed: each run's wall time and CPU time
(user + system of the command and its worker processes), the IDAs computed, the ratio of
the medians, the load average before and after; every wall's results.json of the two runs is
compared byte for byte.  Not collected by pytest.
"""

from __future__ import annotations

import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from ruamel.yaml import YAML

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "projects" / "building-camerino.yaml"
RUNS = {"local": ["--jobs", "2"], "dask": ["--executor", "dask", "--jobs", "2"]}


def building(n_walls: int, folder: Path) -> Path:
    """The example's file with ``n_walls`` walls varied from its four (the module's rule)."""
    yaml = YAML()
    data = yaml.load(EXAMPLE.read_text(encoding="utf-8"))
    base = list(data["walls"])
    walls = []
    for k in range(n_walls):
        wall = dict(base[k % len(base)])
        wall["name"] = f"{wall['name']} {k + 1}"
        height = round(float(wall["height"]) * (0.85 + 0.3 * (k % 7) / 6), 2)
        if "building" in wall:  # the wall's top stays inside its building
            b = wall["building"]
            height = min(height, float(b["height"]) - float(b["wall_base"]))
        wall["height"] = height
        wall["thickness"] = round(float(wall["thickness"]) * (0.9 + 0.2 * (k % 5) / 4), 3)
        walls.append(wall)
    data["walls"] = walls
    data["project"]["name"] = f"{n_walls} walls from the Camerino example"
    out = folder / f"building-{n_walls}.yaml"
    with out.open("w", encoding="utf-8") as f:
        yaml.dump(data, f)
    return out


def children_cpu() -> float:
    """CPU time [s] of the finished child processes (and theirs) so far, user + system."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run(project: Path, out: Path, extra: list[str]) -> tuple[float, float, int]:
    """(wall time [s], CPU time [s], IDAs computed) of one ``frp-assess run``."""
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    cmd = [sys.executable, "-m", "frp_assess", "run", str(project), "--out", str(out)]
    cmd += ["--no-pdf", "--created", "2026-01-01", *extra]
    t0, c0 = time.perf_counter(), children_cpu()
    done = subprocess.run(cmd, check=True, env=env, capture_output=True, text=True)
    seconds, cpu = time.perf_counter() - t0, children_cpu() - c0
    found = re.search(r"(\d+) IDAs computed", done.stdout)
    if found is None:
        raise SystemExit(f"no 'IDAs computed' in the output of {' '.join(cmd)}")
    return seconds, cpu, int(found.group(1))


def same_walls(a: Path, b: Path) -> bool:
    """Every wall's results.json of two runs equal byte for byte."""
    names = sorted(p.name for p in (a / "walls").iterdir())
    return names == sorted(p.name for p in (b / "walls").iterdir()) and all(
        (a / "walls" / n / "results.json").read_bytes()
        == (b / "walls" / n / "results.json").read_bytes()
        for n in names
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--walls", type=int, default=30)
    parser.add_argument("--rounds", type=int, default=1)
    args = parser.parse_args()
    print(f"load before: {os.getloadavg()[0]:.1f} (1-min average, {os.cpu_count()} cores)")
    times: dict[str, list[tuple[float, float, int]]] = {k: [] for k in RUNS}
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        project = building(args.walls, folder)
        (folder / "warm").mkdir()
        small = building(2, folder / "warm")
        for kind, extra in RUNS.items():  # numba's cache, and the workers' first start
            run(small, folder / f"warm-{kind}", extra)
        for r in range(args.rounds):
            outs = {}
            for kind, extra in RUNS.items():
                outs[kind] = folder / f"{kind}-{r}"
                times[kind].append(run(project, outs[kind], extra))
                s, c, n = times[kind][-1]
                print(f"round {r + 1} {kind:5}: {s:6.1f} s wall, {c:6.1f} s CPU, {n} IDAs")
            print(f"  every wall's results.json equal: {same_walls(outs['local'], outs['dask'])}")
    med = {k: statistics.median(t[0] for t in v) for k, v in times.items()}
    print(
        f"{args.walls} walls: local {med['local']:.1f} s, Dask LocalCluster (2 workers) "
        f"{med['dask']:.1f} s: Dask/local {med['dask'] / med['local']:.2f}"
    )
    print(f"load after: {os.getloadavg()[0]:.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
