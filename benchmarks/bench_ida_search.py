"""Per-IDA cost of the compiled search against one Python call per time history, side by side
(not part of the tests).

    python3 benchmarks/bench_ida_search.py [--stride N] [--study projects/paper-study.yaml]

Takes every N-th case of the study (default 40: 52 cases × 7 records of the paper's grid) and
runs each IDA both ways, interleaved, on one thread:

* ``compiled``: :func:`frp_assess.dynamics.ida` on a :class:`RockingModel`: hunt and
  bisection in one compiled call, the record's quiet start skipped
  (:mod:`frp_assess.dynamics.ida_search`);
* ``per run``: the same search rule driven from Python, one ``RockingModel.run`` per time
  history from the record's first sample (the way every IDA ran before).

Prints the CPU time per IDA and per time history of each (``time.process_time``: the fair
measure on a shared machine), and checks that both give equal results (bit for bit).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from frp_assess.dynamics import ida  # noqa: E402
from frp_assess.study import StudyPlan, load_study, study_records  # noqa: E402


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--study", default=str(ROOT / "projects" / "paper-study.yaml"))
    ap.add_argument("--stride", type=int, default=40, help="every N-th case (default 40)")
    args = ap.parse_args()
    plan = StudyPlan(load_study(Path(args.study)))
    records = study_records(plan)
    cases = list(plan.cases(0, len(plan)))[:: args.stride]
    warm = plan.model(cases[0])
    rec0 = records[cases[0].spectrum][0]
    ida(warm, rec0.acc, rec0.dt, plan.ida_settings)  # compile both paths before timing
    ida(warm, rec0.acc, rec0.dt, plan.ida_settings, compiled=False)
    t_compiled = t_per_run = 0.0
    n_ida = n_runs = differ = 0
    for case in cases:
        model = plan.model(case)
        for rec in records[case.spectrum]:
            t0 = time.process_time()
            a = ida(model, rec.acc, rec.dt, plan.ida_settings)
            t1 = time.process_time()
            b = ida(model, rec.acc, rec.dt, plan.ida_settings, compiled=False)
            t2 = time.process_time()
            t_compiled += t1 - t0
            t_per_run += t2 - t1
            n_ida += 1
            n_runs += a.runs
            differ += a != b
    print(
        f"{Path(args.study).name}, every {args.stride}th case: {n_ida} IDAs, "
        f"{n_runs} time histories ({n_runs / n_ida:.1f} per IDA), one thread, CPU time\n"
        f"  compiled search: {1e3 * t_compiled / n_ida:7.2f} ms per IDA, "
        f"{1e6 * t_compiled / n_runs:7.1f} µs per time history\n"
        f"  per run        : {1e3 * t_per_run / n_ida:7.2f} ms per IDA, "
        f"{1e6 * t_per_run / n_runs:7.1f} µs per time history\n"
        f"  ratio {t_per_run / t_compiled:.2f}; results that differ: {differ}"
    )
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
