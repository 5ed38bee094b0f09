"""Every speed figure of issues 24 and 42 in one run, with summary tables (not part of the tests).

    python3 benchmarks/run_all.py [--small] [--warm] [--jobs N] [--skip first,floor,grid,rerun]

1. ``benchmarks/bench_first_run.py``: the README's first command in two fresh venvs side by
   side, the kernel compiled by the install against compiled by the first run (issue 42,
   goal 1; several minutes: ``pip install .`` twice);
2. ``benchmarks/bench_floor.py``: the kernel against the compiled fixed-step floor on both
   walls, and against scipy's ``solve_ivp``;
3. the paper grid: ``python3 -m frp_assess study projects/paper-study.yaml --out <fresh dir>
   --jobs 2`` (``--small``: projects/paper-study-small.yaml), with numba's cache of this tree
   deleted first (cold cache, compilation included; ``--warm`` keeps it);
4. ``benchmarks/bench_rerun.py``: an unchanged rerun of ``frp-assess run``.

Each runs as a child process from the repository root, this tree first on its PYTHONPATH
(never an installed copy of frp_assess; the first-run benchmark installs copies of this tree
into venvs of its own); its own output is shown as it comes, then the tables: every figure,
and issue 42's four, each against its goal.  Wall time [s] and the child's CPU time (user +
system, the fair measure on a shared machine) are both reported; the per-IDA cost is the
grid's time over its IDAs.  Exit status 0 when every benchmark ran (the targets are
reported, not enforced).
"""

from __future__ import annotations

import argparse
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
GRID_TARGET_S = 90.0  #: issue 24: the paper grid in ≤ 90 s on 2 cores, cold cache
RERUN_TARGET_S = 0.5  #: issue 24: an unchanged rerun in ≤ 0.5 s
CAPACITY_TARGET = 1.2  #: issue 42 goal 2: effective within 1.2x of first-collapse (warm run)
FLOOR_TARGET = 2.0  #: issue 24 (kept by issue 42): kernel ≥ 2× the converged floor
STEPS = ("first", "floor", "grid", "capacity", "rerun")


@dataclass
class Ran:
    """One child process: its wall and CPU time [s], exit status and output."""

    wall: float
    cpu: float
    status: int
    out: str
    rows: list[tuple[str, str]] = field(default_factory=list)


def run(argv: list[str]) -> Ran:
    """Run ``argv`` from the repository root, echoing its output as it comes."""
    print(f"\n$ {' '.join(argv)}", flush=True)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    # this tree first on the children's path (not an installed copy of frp_assess)
    path = os.pathsep.join(p for p in (str(ROOT), os.environ.get("PYTHONPATH", "")) if p)
    proc = subprocess.Popen(
        argv,
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        env={**os.environ, "PYTHONPATH": path},
    )
    lines = []
    assert proc.stdout is not None
    for line in proc.stdout:
        print(f"  {line}", end="", flush=True)
        lines.append(line)
    status = proc.wait()
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return Ran(wall, cpu, status, "".join(lines))


def floor_rows(ran: Ran) -> list[tuple[str, str]]:
    """The kernel/floor ratio of each wall and the kernel/solve_ivp ratio, from
    bench_floor.py's lines (its whole output is shown above the table)."""
    rows: list[tuple[str, str]] = []
    wall = None
    for line in ran.out.splitlines():
        m = re.match(r"^(\S.*?): kernel ([\d,]+) simulated s per CPU-s", line)
        if m:
            wall = m.group(1)
            rows.append((f"kernel, {wall}", f"{m.group(2)} simulated s per CPU-s"))
        m = re.search(r"=> kernel / converged floor \(h = ([^)]*)\) = ([\d.]+)", line)
        if m and wall is not None:
            rows.append((f"  kernel / converged floor (h = {m.group(1)})", m.group(2)))
        if "did not converge" in line and wall is not None:
            rows.append(("  kernel / converged floor", line.strip()))
        m = re.search(r"kernel/solve_ivp = ([\d,]+)", line)
        if m:
            rows.append(("kernel / solve_ivp (one time history)", m.group(1)))
    if not rows:
        rows.append(("bench_floor.py", "no figures found in its output (see above)"))
    return rows


def grid(project: str, jobs: int, cold: bool) -> Ran:
    """The study of ``project`` into a fresh directory, timed (cold numba cache if asked)."""
    if cold:
        for f in (ROOT / "frp_assess").rglob("*.nb[ic]"):
            f.unlink()
    with tempfile.TemporaryDirectory(prefix="frp-grid-") as tmp:
        out = Path(tmp) / "out"
        argv = [sys.executable, "-m", "frp_assess", "study", project, "--out", str(out)]
        ran = run([*argv, "--jobs", str(jobs)])
        manifest = out / "study.json"
        if ran.status != 0 or not manifest.is_file():
            ran.rows = [("grid", f"failed (exit {ran.status})")]
            return ran
        data = json.loads(manifest.read_text(encoding="utf-8"))
    n = int(data["cases"]) * int(data["records_per_case"])
    computed = int(data["run"]["computed"])
    seconds = float(data["run"]["seconds"])
    verdict = "meets" if ran.wall <= GRID_TARGET_S else "misses"
    ran.rows = [
        (
            f"grid {Path(project).name} ({n:,} IDAs, {jobs} jobs, "
            f"{'cold' if cold else 'warm'} cache)",
            f"{ran.wall:.1f} s wall ({verdict} ≤ {GRID_TARGET_S:g} s), "
            f"{ran.cpu:.1f} s CPU ({100 * ran.cpu / ran.wall:.0f} %)",
        ),
        ("  of which the IDAs (study.json)", f"{seconds:.1f} s, {computed:,} computed"),
        (
            "  per IDA",
            f"{1e3 * ran.wall / n:.2f} ms wall, {1e3 * ran.cpu / n:.2f} ms CPU",
        ),
    ]
    return ran


def rerun_rows(ran: Ran) -> list[tuple[str, str]]:
    """The unchanged rerun's median wall and CPU time, from bench_rerun.py's lines."""
    m = re.search(r"median wall ([\d.]+) s.*?median CPU ([\d.]+) s", ran.out, re.S)
    if m is None:
        return [("unchanged rerun", f"no figures found (exit {ran.status})")]
    return [
        (
            "unchanged rerun (frp-assess run)",
            f"median {m.group(1)} s wall, {m.group(2)} s CPU (target ≤ {RERUN_TARGET_S:g} s)",
        )
    ]


def first_run_rows(ran: Ran) -> list[tuple[str, str]]:
    """Goal 1 of issue 42 for each install, from bench_first_run.py's summary lines."""
    rows = []
    for m in re.finditer(
        r"^  (\S.*?)\s+pip install \. ([\d.]+) s.*?first run ([\d.]+) s.*?warm run ([\d.]+) s"
        r".*?\n.*?first run / warm run = ([\d.]+); first run [\d.]+ s: (.*)$",
        ran.out,
        re.M,
    ):
        name, install, first, warm, ratio, verdict = m.groups()
        rows.append(
            (
                f"first run after pip install . ({name})",
                f"{first} s wall, {ratio}x a warm run ({warm} s): {verdict}; "
                f"pip install . {install} s",
            )
        )
    return rows or [("first run after pip install .", f"no figures found (exit {ran.status})")]


def capacity_rows(ran: Ran) -> list[tuple[str, str]]:
    """Goal 2 of issue 42 from bench_capacity.py's medians: the warm run of the bundled example
    with ``capacity: effective`` against ``first-collapse`` (wall and CPU ratios)."""
    rows: list[tuple[str, str]] = []
    for line in ran.out.splitlines():
        m = re.match(r"^median (wall|CPU): first-collapse ([\d.]+) s, effective ([\d.]+) s, "
                     r"ratio ([\d.]+)", line)  # fmt: skip
        if m:
            kind, first, eff, ratio = m.groups()
            ok = float(ratio) <= CAPACITY_TARGET
            rows.append(
                (
                    f"capacity effective / first-collapse, warm run ({kind})",
                    f"{eff} s / {first} s = {ratio} ({'meets' if ok else 'misses'} "
                    f"≤ {CAPACITY_TARGET:g})",
                )
            )
    return rows or [("capacity effective / first-collapse", f"no figures (exit {ran.status})")]


def issue42_rows(rows: list[tuple[str, str]]) -> list[tuple[str, str]]:
    """Issue 42's four figures, each against its goal, picked from the rows above."""
    picked = [r for r in rows if r[0].startswith("first run after")]
    picked += [r for r in rows if r[0].startswith("capacity effective")]
    ratios = [(k, v) for k, v in rows if "kernel / converged floor" in k]
    for k, v in ratios:
        try:
            ok = float(v) >= FLOOR_TARGET
        except ValueError:
            ok = False
        picked.append((k.strip(), f"{v} ({'meets' if ok else 'misses'} ≥ {FLOOR_TARGET:g})"))
    for k, v in rows:
        m = re.match(r"median ([\d.]+) s wall, ([\d.]+) s CPU", v)
        if k.startswith("unchanged rerun") and m:
            wall, cpu = (float(x) for x in m.groups())
            said = [
                f"{w} {'meets' if t <= RERUN_TARGET_S else 'misses'}"
                for w, t in (("wall", wall), ("CPU", cpu))
            ]
            picked.append(
                (k, f"{v.split(' (target')[0]}: {', '.join(said)} ≤ {RERUN_TARGET_S:g} s")
            )
    return picked


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--small", action="store_true", help="the grid of paper-study-small.yaml")
    ap.add_argument("--warm", action="store_true", help="keep numba's cache for the grid")
    ap.add_argument("--jobs", type=int, default=2, help="the grid's worker threads (default 2)")
    ap.add_argument("--skip", default="", help=f"comma-separated: {', '.join(STEPS)}")
    args = ap.parse_args()
    skip = {s.strip() for s in args.skip.split(",") if s.strip()}
    unknown = skip - set(STEPS)
    if unknown:
        ap.error(f"--skip: unknown {', '.join(sorted(unknown))}; expected {', '.join(STEPS)}")
    py = sys.executable
    rows: list[tuple[str, str]] = []
    failed = []
    if "first" not in skip:
        ran = run([py, "benchmarks/bench_first_run.py"])
        rows += first_run_rows(ran)
        if ran.status != 0:
            failed.append("first")
    if "floor" not in skip:
        ran = run([py, "benchmarks/bench_floor.py"])
        rows += floor_rows(ran)
        if ran.status not in (0, 1):  # 1: a target missed, reported in the table
            failed.append("floor")
    if "grid" not in skip:
        name = "paper-study-small.yaml" if args.small else "paper-study.yaml"
        ran = grid(f"projects/{name}", args.jobs, cold=not args.warm)
        rows += ran.rows
        if ran.status != 0:
            failed.append("grid")
    if "capacity" not in skip:
        ran = run([py, "benchmarks/bench_capacity.py", "--rounds", "2"])
        rows += capacity_rows(ran)
        if ran.status != 0:
            failed.append("capacity")
    if "rerun" not in skip:
        ran = run([py, "benchmarks/bench_rerun.py"])
        rows += rerun_rows(ran)
        if ran.status not in (0, 1):
            failed.append("rerun")
    command = " ".join(["python3 benchmarks/run_all.py", *sys.argv[1:]])
    load = " ".join(Path("/proc/loadavg").read_text(encoding="ascii").split()[:3])
    head = subprocess.run(
        ["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True
    ).stdout.strip()
    print(f"\nSummary, {time.strftime('%Y-%m-%d %H:%M')}, load {load}, {head}: {command}")
    print_rows(rows)
    print("Issue 42, each figure against its goal:")
    print_rows(issue42_rows(rows))
    if failed:
        print(f"failed: {', '.join(failed)}")
    return 1 if failed else 0


def print_rows(rows: list[tuple[str, str]]) -> None:
    """``rows`` as an aligned two-column table."""
    width = max((len(k) for k, _ in rows), default=0)
    for k, v in rows:
        print(f"  {k:<{width}}  {v}")


if __name__ == "__main__":
    sys.exit(main())
