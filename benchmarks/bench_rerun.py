"""Time an unchanged rerun of `frp-assess run` (issue 24, goal 3: ≤ 0.5 s).

Run: ``python3 benchmarks/bench_rerun.py [PROJECT.yaml] [--repeats N] [--no-pdf]``
(default: projects/facade-laquila.yaml).  The project is copied into a temporary folder, run
once (the first run, timed), then run again with nothing changed ``--repeats`` times, each as
a fresh subprocess ``python3 -m frp_assess run ...`` from the repository root.  Reported:
the median wall time and the median CPU time of the child (``resource.getrusage``, user +
system: on a loaded machine the CPU time is the fairer measure), and for scale the same of a
bare interpreter start (``python3 -c pass``: site-packages' .pth files included, which the
product does not control).  Not collected by pytest.
"""

from __future__ import annotations

import argparse
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DEFAULT = ROOT / "projects" / "facade-laquila.yaml"
TARGET_RERUN_S = 0.5


def timed(argv: list[str]) -> tuple[float, float, str]:
    """(wall [s], child CPU [s], stdout) of one subprocess run of ``argv``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run(argv, cwd=ROOT, capture_output=True, text=True, check=False)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(argv)} exited with {proc.returncode}:\n{proc.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, proc.stdout


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("project", nargs="?", default=str(DEFAULT), help="a project file")
    ap.add_argument("--repeats", type=int, default=7, help="unchanged reruns timed (default 7)")
    ap.add_argument("--no-pdf", action="store_true", help="run without report.pdf")
    args = ap.parse_args()
    source = Path(args.project).resolve()
    with tempfile.TemporaryDirectory() as tmp:
        project = Path(tmp) / source.name
        shutil.copy(source, project)
        for sub in ("records",):  # the example's record files, if it references any
            if (source.parent / sub).is_dir():
                shutil.copytree(source.parent / sub, Path(tmp) / sub)
        argv = [sys.executable, "-m", "frp_assess", "run", str(project)]
        argv += ["--no-pdf"] if args.no_pdf else []
        first_wall, first_cpu, _ = timed(argv)
        walls, cpus = [], []
        for _ in range(args.repeats):
            wall, cpu, out = timed(argv)
            if "nothing to recompute" not in out:
                raise SystemExit("the rerun recomputed: the fast path was not taken")
            walls.append(wall)
            cpus.append(cpu)
        bare = [timed([sys.executable, "-c", "pass"]) for _ in range(args.repeats)]
    wall_med, cpu_med = statistics.median(walls), statistics.median(cpus)
    bare_wall = statistics.median(b[0] for b in bare)
    bare_cpu = statistics.median(b[1] for b in bare)
    print(
        f"{source.name}, pdf {'off' if args.no_pdf else 'on'}\n"
        f"  first run: wall {first_wall:.2f} s, CPU {first_cpu:.2f} s\n"
        f"  unchanged rerun ({args.repeats} runs): median wall {wall_med:.3f} s "
        f"(min {min(walls):.3f}, max {max(walls):.3f}), median CPU {cpu_med:.3f} s "
        f"(target ≤ {TARGET_RERUN_S:g} s)\n"
        f"  bare interpreter start ({args.repeats} runs): median wall {bare_wall:.3f} s, "
        f"median CPU {bare_cpu:.3f} s"
    )
    return 0 if min(wall_med, cpu_med) <= TARGET_RERUN_S else 1


if __name__ == "__main__":
    sys.exit(main())
