"""The IDAs of this tree against those of an earlier commit, interleaved IDA by IDA in one
process (not part of the tests).

    python3 benchmarks/bench_kernel_against.py --against REV [--stride N] [--study FILE]

On a shared machine two runs of the same code minutes apart differ by ±10 % or more, so a
change of a few per cent cannot be seen by running the old and the new code one after the
other.  Here both run in one process: the package of commit REV is taken out of git
(``git archive``) into a temporary folder under another name (``frp_before``, its own
imports rewritten to it), and every IDA of every N-th case of the study (default 20: 721 IDAs
of the paper's grid; FILE default projects/paper-study.yaml) is run by both, one right after
the other, the order alternating from IDA to IDA, one thread.  Printed: the CPU time per IDA
(``time.process_time``) of each, their ratio, and how many IDAs gave the same results bit for
bit (collapse multiplier, time histories run, every peak of the IDA curve).

REV must have the API used here (``frp_assess.dynamics.ida(model, acc, dt, settings)``,
``frp_assess.study.StudyPlan``; main since 2026-11-25).  Both trees compile into their own
numba caches before timing starts (the warm-up IDA); the temporary folder is removed at the
end.  The figures of docs/paper-study.md of 2026-11-27 ("Taken since") come from here.
"""

from __future__ import annotations

import argparse
import importlib
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from types import ModuleType
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

#: The name the earlier commit's package is imported under.
BEFORE = "frp_before"


def extract(rev: str, into: Path) -> None:
    """The package ``frp_assess`` of commit ``rev`` as ``into/BEFORE``, its imports of
    itself rewritten to that name."""
    archive = subprocess.run(
        ["git", "-C", str(ROOT), "archive", rev, "frp_assess"], capture_output=True, check=True
    ).stdout
    subprocess.run(["tar", "-x", "-C", str(into)], input=archive, check=True)
    (into / "frp_assess").rename(into / BEFORE)
    word = re.compile(r"\bfrp_assess\b")
    for path in (into / BEFORE).rglob("*.py"):
        path.write_text(word.sub(BEFORE, path.read_text(encoding="utf-8")), encoding="utf-8")


def workload(package: str, study: Path, stride: int) -> tuple[Any, list[tuple[Any, Any]]]:
    """(the IDA settings, [(model, record)]) of every ``stride``-th case of ``study``, built
    by ``package``."""
    mod: ModuleType = importlib.import_module(f"{package}.study")
    plan = mod.StudyPlan(mod.load_study(study))
    records = mod.study_records(plan)
    work: list[tuple[Any, Any]] = []
    for case in list(plan.cases(0, len(plan)))[::stride]:
        model = plan.model(case)
        work.extend((model, rec) for rec in records[case.spectrum])
    return plan.ida_settings, work


def same(a: Any, b: Any) -> bool:
    """Whether two IDA results agree bit for bit on what the search found."""
    return bool(
        a.collapse_multiplier == b.collapse_multiplier
        and a.runs == b.runs
        and [(p.multiplier, p.peak_ratio) for p in a.curve]
        == [(p.multiplier, p.peak_ratio) for p in b.curve]
    )


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--against", required=True, metavar="REV", help="the earlier commit")
    ap.add_argument("--study", default=str(ROOT / "projects" / "paper-study.yaml"))
    ap.add_argument("--stride", type=int, default=20, help="every N-th case (default 20)")
    args = ap.parse_args()
    tmp = Path(tempfile.mkdtemp(prefix="frp-against-"))
    try:
        extract(args.against, tmp)
        sys.path.insert(0, str(tmp))
        run_now = importlib.import_module("frp_assess.dynamics").ida
        run_before = importlib.import_module(f"{BEFORE}.dynamics").ida
        s_now, now = workload("frp_assess", Path(args.study), args.stride)
        s_before, before = workload(BEFORE, Path(args.study), args.stride)
        sides = [("now", run_now, s_now, now), ("before", run_before, s_before, before)]
        for _, run, settings, work in sides:
            run(work[0][0], work[0][1].acc, work[0][1].dt, settings)  # compile before timing
        cpu = {"now": 0.0, "before": 0.0}
        agree = 0
        for k in range(len(now)):
            results = {}
            for name, run, settings, work in sides if k % 2 == 0 else sides[::-1]:
                model, rec = work[k]
                t0 = time.process_time()
                results[name] = run(model, rec.acc, rec.dt, settings)
                cpu[name] += time.process_time() - t0
            agree += same(results["now"], results["before"])
        t_now, t_before = cpu["now"], cpu["before"]
        n = len(now)
        print(
            f"{Path(args.study).name}, every {args.stride}th case: {n} IDAs, one thread, "
            f"interleaved\n  this tree : {1e3 * t_now / n:7.2f} ms CPU per IDA\n"
            f"  {args.against:<10}: {1e3 * t_before / n:7.2f} ms CPU per IDA\n"
            f"  {args.against} / this tree = {t_before / t_now:.3f}; "
            f"the same results bit for bit: {agree} of {n} IDAs"
        )
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
