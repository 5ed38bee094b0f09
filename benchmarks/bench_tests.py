"""Benchmark of the whole test run (not part of the test run itself).

    python3 benchmarks/bench_tests.py [--warm] [--repeat N] [-- PYTEST ARGS...]

Runs the README's ``python3 -m pytest`` (every test, pytest-xdist on all cores as configured
in pyproject.toml) from the repository root, by default with the numba cache cold as CI has
it (every ``*.nbi``/``*.nbc`` under frp_assess/ deleted first; ``--warm`` keeps it), and
prints for each run: the wall time [s], the CPU time of pytest and all its workers and
subprocesses (user + system) [s], the load average before and after, and the core count.

On a shared machine the wall time depends on the other load; the CPU time much less so:
``CPU / cores`` is the wall time the run would take on idle cores with perfect balance.
Target (issue 21): the full run under 100 s wall on 2 cores.
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def clear_numba_cache(root: Path = ROOT) -> int:
    """Delete numba's on-disk cache under frp_assess/; returns the files deleted."""
    package = root / "frp_assess"
    files = [*package.rglob("*.nbi"), *package.rglob("*.nbc")]
    for f in files:
        f.unlink()
    return len(files)


def run_once(pytest_args: list[str], *, cold: bool) -> dict[str, float]:
    """One full test run; returns wall [s], cpu [s], load before/after [-], exit code."""
    if cold:
        clear_numba_cache()
    load_before = os.getloadavg()[0]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    code = subprocess.call(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", *pytest_args],
        cwd=ROOT,
        stdout=subprocess.DEVNULL,
    )
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {
        "wall": wall,
        "cpu": cpu,
        "load_before": load_before,
        "load_after": os.getloadavg()[0],
        "code": float(code),
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--warm", action="store_true", help="keep the numba cache")
    parser.add_argument("--repeat", type=int, default=1, help="runs (default 1)")
    parser.add_argument("pytest_args", nargs="*", help="extra pytest arguments (after --)")
    args = parser.parse_args(argv)
    cores = os.cpu_count() or 1
    print(f"{cores} cores; numba cache {'warm' if args.warm else 'cold'}")
    for i in range(args.repeat):
        r = run_once(args.pytest_args, cold=not args.warm)
        print(
            f"run {i + 1}: wall {r['wall']:.1f} s, CPU {r['cpu']:.1f} s "
            f"(CPU/cores {r['cpu'] / cores:.1f} s), load average {r['load_before']:.1f} "
            f"-> {r['load_after']:.1f}, exit code {int(r['code'])}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
