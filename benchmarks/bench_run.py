"""Time `frp-assess run` on the full-sweep example (targets: ≤ 15 s, rerun ≤ 2 s).

Run: ``PYTHONPATH=. python3 benchmarks/bench_run.py [PROJECT.yaml] [--jobs N] [--pdf]``
(default: projects/facade-laquila.yaml, 19 cases × 7 records
plus its design mode).  The kernels are compiled (or loaded from numba's cache) by a small
warm-up run first; the timed runs start from an empty results directory and then rerun with
nothing changed.  Each phase reports its wall time and the CPU time of the process (user +
system, all threads): on a loaded machine the CPU time is the fairer measure, and CPU well
above wall × jobs means threads burn cores without working.  Not collected by pytest.
"""

from __future__ import annotations

import argparse
import resource
import tempfile
import time
from dataclasses import replace
from pathlib import Path

from frp_assess.api import run_assessment
from frp_assess.assess.from_project import load_inputs
from frp_assess.assess.inputs import ArtificialRecords

DEFAULT = Path(__file__).resolve().parents[1] / "projects" / "facade-laquila.yaml"
TARGET_FIRST_S = 15.0
TARGET_RERUN_S = 2.0


def cpu_s() -> float:
    """CPU time [s] of this process so far, user + system, all threads."""
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("project", nargs="?", default=str(DEFAULT), help="a project file")
    ap.add_argument("--jobs", type=int, default=None, help="threads (default: all cores)")
    ap.add_argument("--pdf", action="store_true", help="also build report.pdf")
    args = ap.parse_args()
    inputs = load_inputs(args.project)
    warm = replace(
        inputs, records=ArtificialRecords(1, 1, 14.0, 0.02), options=inputs.options[:1], design=None
    )
    with tempfile.TemporaryDirectory() as tmp:
        run_assessment(warm, Path(tmp) / "warm", jobs=args.jobs, pdf=False)
        out = Path(tmp) / "out"
        t0, c0 = time.perf_counter(), cpu_s()
        _, first = run_assessment(inputs, out, jobs=args.jobs, pdf=args.pdf)
        t1, c1 = time.perf_counter(), cpu_s()
        _, again = run_assessment(inputs, out, jobs=args.jobs, pdf=args.pdf)
        t2, c2 = time.perf_counter(), cpu_s()
        no_design = replace(inputs, design=None)
        t3, c3 = time.perf_counter(), cpu_s()
        run_assessment(no_design, Path(tmp) / "sweep", jobs=args.jobs, pdf=args.pdf)
        t4, c4 = time.perf_counter(), cpu_s()
    n = 1 + len(inputs.options)
    print(
        f"{Path(args.project).name}: {n} cases, design mode "
        f"{'on' if inputs.design else 'off'}, pdf {'on' if args.pdf else 'off'}\n"
        f"  sweep only ({n} cases): {t4 - t3:.2f} s, CPU {c4 - c3:.2f} s "
        f"(target ≤ {TARGET_FIRST_S:g} s)\n"
        f"  whole run: {t1 - t0:.2f} s, CPU {c1 - c0:.2f} s, {first.computed} IDAs computed\n"
        f"  rerun, nothing changed: {t2 - t1:.2f} s, CPU {c2 - c1:.2f} s, {again.computed} "
        f"computed, {again.reused} reused (target ≤ {TARGET_RERUN_S:g} s)"
    )
    return 0 if (t4 - t3) <= TARGET_FIRST_S and (t2 - t1) <= TARGET_RERUN_S else 1


if __name__ == "__main__":
    raise SystemExit(main())
