"""CPU time of the first IDA and of the first time history with a history, in a fresh process
(not part of the tests): on a cold numba cache, the kernel's compilation.

    find frp_assess/dynamics -name __pycache__ -type d -exec rm -rf {} +
    python3 benchmarks/bench_first_compile.py [--study FILE]

Builds the first case of the study (default projects/paper-study.yaml), runs its IDA under
the first record, then ``RockingModel.run(..., history=True)`` at half the multiplier, and
prints the CPU time (``time.process_time``) of each.  On a shared machine compare two trees
side by side (run both at the same time, several pairs): the figures of docs/model.md §4.6
come from there.
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
    args = ap.parse_args()
    plan = StudyPlan(load_study(Path(args.study)))
    case = next(iter(plan.cases(0, 1)))
    model = plan.model(case)
    rec = study_records(plan)[case.spectrum][0]
    c0 = time.process_time()
    res = ida(model, rec.acc, rec.dt, plan.ida_settings)
    c1 = time.process_time()
    model.run(rec.acc, rec.dt, 0.5 * res.collapse_multiplier, history=True)
    c2 = time.process_time()
    print(f"first IDA {c1 - c0:.2f} CPU-s, first run with a history {c2 - c1:.2f} CPU-s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
