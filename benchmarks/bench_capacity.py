"""Warm `frp-assess run` of the bundled example with each capacity rule, side by side
(issue 42 goal 2: `capacity: effective` within 1.2x of `capacity: first-collapse`).

    PYTHONPATH=. python3 benchmarks/bench_capacity.py [PROJECT.yaml] [--rounds N]

The project (default projects/facade-laquila.yaml: 19 cases x 7 records and its design mode)
is copied twice into a temporary folder with ``analysis.ida.capacity`` set to each rule; after
one run of each to compile the kernels (numba's cache), the two are run alternately, N rounds
(default 2), each time by the command line into a fresh ``--out`` folder (its IDA cache empty).
Printed: every wall and CPU time (user + system of the run's process), the medians, their
ratios and the load average before and after.
Not collected by pytest; the run of 2026-11-28 is kept beside this file (bench_capacity.txt).
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from ruamel.yaml import YAML

ROOT = Path(__file__).resolve().parents[1]
DEFAULT = ROOT / "projects" / "facade-laquila.yaml"
RULES = ("first-collapse", "effective")


def project_with(src: Path, rule: str, folder: Path) -> Path:
    yaml = YAML()
    data = yaml.load(src.read_text(encoding="utf-8"))
    analysis = data.setdefault("analysis", {})
    analysis.setdefault("ida", {})["capacity"] = rule
    out = folder / f"{src.stem}-{rule}.yaml"
    with out.open("w", encoding="utf-8") as f:
        yaml.dump(data, f)
    return out


def children_cpu() -> float:
    """CPU time [s] of the finished child processes so far, user + system."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run(project: Path, out: Path) -> tuple[float, float]:
    """(wall time, CPU time) [s] of one run by the command line."""
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    cmd = [sys.executable, "-m", "frp_assess", "run", str(project), "--out", str(out), "--no-pdf"]
    t0, c0 = time.perf_counter(), children_cpu()
    subprocess.run(cmd, check=True, env=env, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0, children_cpu() - c0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("project", nargs="?", default=str(DEFAULT))
    ap.add_argument("--rounds", type=int, default=2)
    args = ap.parse_args()
    print(f"load before: {os.getloadavg()}")
    times: dict[str, list[float]] = {r: [] for r in RULES}
    cpus: dict[str, list[float]] = {r: [] for r in RULES}
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        projects = {r: project_with(Path(args.project), r, folder) for r in RULES}
        for r in RULES:  # compile (numba's cache) and warm the files
            run(projects[r], folder / f"warm-{r}")
        for k in range(args.rounds):
            for r in RULES:
                t, c = run(projects[r], folder / f"out-{r}-{k}")
                times[r].append(t)
                cpus[r].append(c)
                print(
                    f"round {k + 1}: {r:<15} {t:7.2f} s wall, {c:7.2f} s CPU "
                    f"(load {os.getloadavg()[0]:.1f})"
                )
    for label, values in (("wall", times), ("CPU", cpus)):
        med = {r: statistics.median(v) for r, v in values.items()}
        print(
            f"median {label}: first-collapse {med['first-collapse']:.2f} s, effective "
            f"{med['effective']:.2f} s, ratio {med['effective'] / med['first-collapse']:.2f}"
        )
    print(f"load after: {os.getloadavg()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
