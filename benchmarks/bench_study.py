"""Benchmark of a study: the paper's Table 1 (2,052 cases × 7 records) or the small slice.

    python benchmarks/bench_study.py            # projects/paper-study-small.yaml
    python benchmarks/bench_study.py --full     # projects/paper-study.yaml

Runs into a fresh temporary directory (IDA cache cold; numba's cache as it is: for the
"compilation included" figure delete frp_assess/**/*.nb[ic] first, or use
benchmarks/run_all.py) on all cores and prints the wall time of the records, of the IDAs and
of the figures, the process's CPU time of the IDAs (all threads; the fair measure on a shared
machine) and the cost per IDA.  Measured figures: docs/paper-study.md, "Time".
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

from frp_assess.dynamics import default_jobs
from frp_assess.study import StudyPlan, load_study, run_study, study_records
from frp_assess.study.figures import write_study_pdf

ROOT = Path(__file__).resolve().parent.parent


def main() -> None:
    name = "paper-study.yaml" if "--full" in sys.argv else "paper-study-small.yaml"
    study = load_study(ROOT / "projects" / name)
    plan = StudyPlan(study)
    t0 = time.perf_counter()
    records = study_records(plan)
    t1 = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)
        c1 = time.process_time()
        stats = run_study(study, out, records=records)
        c2 = time.process_time()
        t2 = time.perf_counter()
        write_study_pdf(out)
        t3 = time.perf_counter()
    print(
        f"{name}: {stats.cases} cases x {stats.records_per_case} records on "
        f"{default_jobs()} cores: records {t1 - t0:.1f} s, IDA {t2 - t1:.1f} s "
        f"({stats.computed} IDAs), figures {t3 - t2:.1f} s\n"
        f"IDA CPU time {c2 - c1:.1f} s ({100 * (c2 - c1) / (t2 - t1):.0f} % of one core); "
        f"per IDA {1e3 * (t2 - t1) / stats.computed:.2f} ms wall, "
        f"{1e3 * (c2 - c1) / stats.computed:.2f} ms CPU"
    )


if __name__ == "__main__":
    main()
