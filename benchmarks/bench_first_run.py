"""The first run after a fresh install, compilation included (issue 42, goal 1; not a test).

    python3 benchmarks/bench_first_run.py [--cache] [--keep DIR]

Default (``--venv``): the README's first command on a fresh machine, as far as one machine
can give one.  Two copies of this tree side by side, each into a new virtual environment
(``python3 -m venv``, no site-packages: every dependency installed by pip as a user's would
be), interleaved step by step:

* ``precompiled``: ``pip install .`` as the README says (the wheel's build compiles the kernel:
  setup.py, docs/compilation.md);
* ``compile at run``: the same with ``FRP_ASSESS_NO_PRECOMPILE=1`` (the build does not
  compile: the first run does, as every install did before).

For each: ``pip install .`` timed, then ``frp-assess run projects/facade-laquila.yaml`` from
the copy's root (the first run: cold or warm as the install left numba's cache), then the
same into a fresh folder (a warm run, the yardstick of goal 1).  Goal 1: the first run within
15 s of wall time, or within 1.5x the warm run, whichever is larger.

``--cache``: quicker, in this tree (no install): the bundled example with numba's cache
empty (``NUMBA_CACHE_DIR`` a new folder: a first run that compiles) against the same run
with that cache warm, interleaved, three pairs; what a source checkout or an editable
install gets, and the compile's cost.

Wall time and the child's CPU time (user + system: the fair measure on a shared machine)
are reported, with the machine's load (``/proc/loadavg``) before each step.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PROJECT = "projects/facade-laquila.yaml"
FIRST_RUN_TARGET_S = 15.0  #: issue 42, goal 1: ≤ 15 s wall ...
FIRST_RUN_TARGET_RATIO = 1.5  #: ... or ≤ 1.5x a warm run, whichever is larger
IGNORED = shutil.ignore_patterns(
    ".git", "__pycache__", "*.egg-info", "build", "dist", "*-results", ".venv", ".*_cache"
)


def load() -> str:
    """The machine's load averages (1, 5, 15 min)."""
    return " ".join(Path("/proc/loadavg").read_text(encoding="ascii").split()[:3])


def timed(argv: list[str], cwd: Path, env: dict[str, str]) -> tuple[float, float]:
    """(wall [s], child CPU [s]) of ``argv``; exits with its output if it fails."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run(argv, cwd=cwd, env=env, capture_output=True, text=True, check=False)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(argv)} exited with {proc.returncode}:\n{proc.stderr}")
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def clean_env(**extra: str) -> dict[str, str]:
    """The environment a new user has: no PYTHONPATH to a tree, numba's defaults."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "NUMBA_CACHE_DIR")}
    return {**env, **extra}


def verdict(first: float, warm: float) -> str:
    """Goal 1 for a first run of ``first`` s against a warm run of ``warm`` s."""
    limit = max(FIRST_RUN_TARGET_S, FIRST_RUN_TARGET_RATIO * warm)
    return f"{'meets' if first <= limit else 'misses'} ≤ {limit:.1f} s"


def venv_mode(keep: Path | None) -> int:
    """The README's first command in two fresh venvs, side by side."""
    variants = {"precompiled": {}, "compile at run": {"FRP_ASSESS_NO_PRECOMPILE": "1"}}
    with tempfile.TemporaryDirectory(prefix="frp-first-") as tmp:
        base = keep if keep is not None else Path(tmp)
        trees: dict[str, Path] = {}
        for i, name in enumerate(variants):
            tree = base / f"tree{i}"
            shutil.copytree(ROOT, tree, ignore=IGNORED)
            subprocess.run([sys.executable, "-m", "venv", str(tree / ".venv")], check=True)
            trees[name] = tree
        env = {
            name: clean_env(
                **extra, PATH=f"{trees[name] / '.venv' / 'bin'}{os.pathsep}{os.environ['PATH']}"
            )
            for name, extra in variants.items()
        }
        steps = {
            "pip install .": ["python3", "-m", "pip", "install", "-q", "."],
            "first run": ["frp-assess", "run", PROJECT],
            "warm run": ["frp-assess", "run", PROJECT, "--out", "warm-results"],
        }
        got: dict[tuple[str, str], tuple[float, float]] = {}
        for step, argv in steps.items():
            for name in variants:
                print(f"[load {load()}] {name}: {step} ...", flush=True)
                got[name, step] = timed(argv, trees[name], env[name])
                print(f"  {got[name, step][0]:.1f} s wall, {got[name, step][1]:.1f} s CPU")
    print(f"\nThe README's first command in a fresh venv, side by side (load now {load()}):")
    for name in variants:
        first, warm = got[name, "first run"][0], got[name, "warm run"][0]
        parts = [
            f"{step} {got[name, step][0]:.1f} s ({got[name, step][1]:.1f} CPU-s)" for step in steps
        ]
        print(f"  {name:<15} " + ", ".join(parts))
        print(
            f"  {'':<15} first run / warm run = {first / warm:.2f}; "
            f"first run {first:.1f} s: {verdict(first, warm)} (goal 1)"
        )
    return 0


def cache_mode(pairs: int) -> int:
    """A run with numba's cache empty against one with it warm, in this tree."""
    firsts: list[float] = []
    warms: list[float] = []
    cpu_first: list[float] = []
    cpu_warm: list[float] = []
    with tempfile.TemporaryDirectory(prefix="frp-cold-") as tmp:
        warm_cache = Path(tmp) / "warm-cache"
        env = clean_env(PYTHONPATH=str(ROOT))
        argv = [sys.executable, "-m", "frp_assess", "run", PROJECT, "--out"]
        # the warm cache filled once, untimed
        timed([*argv, str(Path(tmp) / "fill")], ROOT, {**env, "NUMBA_CACHE_DIR": str(warm_cache)})
        for k in range(pairs):
            cold = {**env, "NUMBA_CACHE_DIR": str(Path(tmp) / f"cold-{k}")}
            warm = {**env, "NUMBA_CACHE_DIR": str(warm_cache)}
            print(f"[load {load()}] pair {k + 1}: cold cache, then warm", flush=True)
            w, c = timed([*argv, str(Path(tmp) / f"c{k}")], ROOT, cold)
            firsts.append(w)
            cpu_first.append(c)
            w, c = timed([*argv, str(Path(tmp) / f"w{k}")], ROOT, warm)
            warms.append(w)
            cpu_warm.append(c)
            print(
                f"  cold {firsts[-1]:.1f} s ({cpu_first[-1]:.1f} CPU-s), warm {w:.1f} s ({c:.1f})"
            )
    first, warm = statistics.median(firsts), statistics.median(warms)
    print(
        f"\nfrp-assess run {PROJECT} in this tree, {pairs} pairs (load now {load()}):\n"
        f"  cold cache: median {first:.1f} s wall, {statistics.median(cpu_first):.1f} s CPU\n"
        f"  warm cache: median {warm:.1f} s wall, {statistics.median(cpu_warm):.1f} s CPU\n"
        f"  cold / warm = {first / warm:.2f}; compile ≈ {first - warm:.1f} s wall, "
        f"{statistics.median(cpu_first) - statistics.median(cpu_warm):.1f} CPU-s; "
        f"cold first run {first:.1f} s: {verdict(first, warm)} (goal 1, without the "
        "install's compile)"
    )
    return 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cache", action="store_true", help="cold against warm cache, this tree")
    ap.add_argument("--pairs", type=int, default=3, help="--cache: pairs timed (default 3)")
    ap.add_argument("--keep", type=Path, help="venv mode: build the copies in DIR (kept)")
    args = ap.parse_args()
    return cache_mode(args.pairs) if args.cache else venv_mode(args.keep)


if __name__ == "__main__":
    sys.exit(main())
