"""Benchmark of a study: the paper's Table 1 (2,052 cases × 7 records) or the small slice.

    python benchmarks/bench_study.py            # projects/paper-study-small.yaml
    python benchmarks/bench_study.py --full     # projects/paper-study.yaml (~3 min, 2 cores)

Runs into a fresh temporary directory (cold cache) on all cores and prints the wall time of
the records, of the IDAs and of the figures.  Measured (2 cores, AMD EPYC): full study
181 s of IDA, 3 min 04 s for the whole command (docs/paper-study.md).
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
        stats = run_study(study, out, records=records)
        t2 = time.perf_counter()
        write_study_pdf(out)
        t3 = time.perf_counter()
    print(
        f"{name}: {stats.cases} cases x {stats.records_per_case} records on "
        f"{default_jobs()} cores: records {t1 - t0:.1f} s, IDA {t2 - t1:.1f} s "
        f"({stats.computed} IDAs), figures {t3 - t2:.1f} s"
    )


if __name__ == "__main__":
    main()
