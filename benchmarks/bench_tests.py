"""Benchmark of the whole test run (not part of the test run itself).

    python3 benchmarks/bench_tests.py [--warm] [--repeat N] [--against REV] [-- PYTEST ARGS...]

Runs the README's ``python3 -m pytest`` (every test, pytest-xdist on all cores as configured
in pyproject.toml) from the repository root, by default with the numba cache cold as CI has
it (every ``*.nbi``/``*.nbc`` under frp_assess/ deleted first; ``--warm`` keeps it), and
prints for each run: the wall time [s], the CPU time of pytest and all its workers and
subprocesses (user + system) [s], the load average before and after, and the core count.

On a shared machine the wall time depends on the other load; the CPU time much less so:
``CPU / cores`` is the wall time the run would take on idle cores with perfect balance.
Target (issue 21): the full run under half of the wall time of the day the issue was filed
(2026-11-25, 200 s on that day's machine; the last commit before the work on it is bfa8f79).
Machines differ by 2x, so the two are compared side by side on the same machine:
``--against bfa8f79`` checks that commit out into a temporary git worktree, installs it into a
temporary virtual environment (``--system-site-packages``, the package itself only), and runs
its test command (``python3 -m pytest`` then too, one process) before each run of this tree,
both with a cold numba cache; it prints both times and their ratio.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
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


def run_once(
    pytest_args: list[str],
    *,
    cold: bool,
    root: Path = ROOT,
    python: str = sys.executable,
    env: dict[str, str] | None = None,
) -> dict[str, float]:
    """One full test run of the tree at ``root`` with ``python``; returns wall [s], cpu [s],
    load before/after [-], exit code."""
    if cold:
        clear_numba_cache(root)
    load_before = os.getloadavg()[0]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    with tempfile.TemporaryFile("w+", encoding="utf-8") as log:
        code = subprocess.call(
            [python, "-m", "pytest", "-q", "-p", "no:cacheprovider", *pytest_args],
            cwd=root,
            stdout=log,
            stderr=subprocess.STDOUT,
            env=env,
        )
        wall = time.perf_counter() - t0
        if code != 0:  # a failed run is no measurement: say what failed
            log.seek(0)
            lines = log.read().splitlines()
            failed = [ln for ln in lines if ln.startswith(("FAILED", "ERROR"))]
            print("\n".join(failed or lines[-30:]), file=sys.stderr)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {
        "wall": wall,
        "cpu": cpu,
        "load_before": load_before,
        "load_after": os.getloadavg()[0],
        "code": float(code),
    }


def install_revision(rev: str, folder: Path) -> tuple[Path, str, dict[str, str]]:
    """Commit ``rev`` of this repository as a git worktree in ``folder``/tree, installed
    (editable, no dependencies: the ones installed here serve) into a virtual environment in
    ``folder``/venv; returns (its root, its Python, the environment to run its tests in: the
    venv's bin first on PATH and the worktree on PYTHONPATH, so that every process of its
    tests imports that commit's package)."""
    tree = folder / "tree"
    venv = folder / "venv"
    subprocess.run(
        ["git", "-C", str(ROOT), "worktree", "add", "--detach", str(tree), rev],
        check=True,
        stdout=subprocess.DEVNULL,
    )
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    python = str(venv / "bin" / "python")
    subprocess.run(
        [python, "-m", "pip", "install", "-q", "--no-deps", "-e", str(tree)],
        check=True,
        stdout=subprocess.DEVNULL,
    )
    # PYTHONPATH too: a copy of the package installed in the system's site-packages (which
    # the venv sees) would otherwise come before the editable install's finder
    env = dict(
        os.environ,
        PATH=f"{venv / 'bin'}{os.pathsep}{os.environ.get('PATH', '')}",
        PYTHONPATH=str(tree),
    )
    return tree, python, env


def remove_revision(folder: Path) -> None:
    """Undo :func:`install_revision` (the worktree is unregistered from git too)."""
    subprocess.run(
        ["git", "-C", str(ROOT), "worktree", "remove", "--force", str(folder / "tree")],
        check=False,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    shutil.rmtree(folder, ignore_errors=True)


def describe(label: str, r: dict[str, float], cores: int) -> str:
    return (
        f"{label}: wall {r['wall']:.1f} s, CPU {r['cpu']:.1f} s "
        f"(CPU/cores {r['cpu'] / cores:.1f} s), load average {r['load_before']:.1f} "
        f"-> {r['load_after']:.1f}, exit code {int(r['code'])}"
    )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--warm", action="store_true", help="keep the numba cache")
    parser.add_argument("--repeat", type=int, default=1, help="runs (default 1)")
    parser.add_argument(
        "--against",
        metavar="REV",
        help="before each run, run the tests of commit REV (installed apart) the same way",
    )
    parser.add_argument("pytest_args", nargs="*", help="extra pytest arguments (after --)")
    args = parser.parse_args(argv)
    cores = os.cpu_count() or 1
    print(f"{cores} cores; numba cache {'warm' if args.warm else 'cold'}")
    if not args.against:
        for i in range(args.repeat):
            r = run_once(args.pytest_args, cold=not args.warm)
            print(describe(f"run {i + 1}", r, cores))
        return 0
    folder = Path(tempfile.mkdtemp(prefix="bench-tests-"))
    try:
        tree, python, env = install_revision(args.against, folder)
        for i in range(args.repeat):
            base = run_once([], cold=not args.warm, root=tree, python=python, env=env)
            print(describe(f"run {i + 1}, {args.against}", base, cores))
            now = run_once(args.pytest_args, cold=not args.warm)
            print(describe(f"run {i + 1}, this tree", now, cores))
            print(f"run {i + 1}: this tree / {args.against} = {now['wall'] / base['wall']:.3f}")
    finally:
        remove_revision(folder)
    return 0


if __name__ == "__main__":
    sys.exit(main())
