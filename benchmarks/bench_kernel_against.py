"""The IDAs of this tree against those of an earlier commit, interleaved IDA by IDA in one
process (not part of the tests).

    python3 benchmarks/bench_kernel_against.py --against REV [--stride N] [--study FILE]

On a shared machine two runs of the same code minutes apart differ by ±10 % or more, so a
change of a few per cent cannot be seen by running the old and the new code one after the
other.  Here both run in one process: the package of commit REV (``git archive``) and this
tree's (uncommitted changes included) are copied into a temporary folder under two other
names (``frp_before``, ``frp_now``, their imports of themselves rewritten), and every IDA of
every N-th case of the study (default 20: 721 IDAs of the paper's grid; FILE default
projects/paper-study.yaml) is run by both, one right after the other, the order alternating
from IDA to IDA, one thread.  The package set up and compiled first runs about 3.4 % faster
(the same code against itself: 1.034 one way, 0.967 the other; memory layout, not the
code), so this is done twice, in two processes, each package first once, and the geometric
mean of the two ratios is the figure.  Printed: the CPU time per IDA (``time.process_time``)
of each in each pass, the ratios, and how many IDAs gave the same results bit for bit
(collapse multiplier, time histories run, every peak of the IDA curve).

REV must have the API used here (``frp_assess.dynamics.ida(model, acc, dt, settings)``,
``frp_assess.study.StudyPlan``; main since 2026-11-25).  Both trees compile into their own
numba caches before timing starts (the warm-up IDA); the temporary folder is removed at the
end.  The figures of docs/paper-study.md of 2026-11-27 ("Taken since") come from here.
"""

from __future__ import annotations

import argparse
import importlib
import json
import math
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

#: The names the two packages are imported under (both copies, renamed alike).
NOW, BEFORE = "frp_now", "frp_before"


def _install(package: Path, into: Path, name: str) -> None:
    """Move the package folder ``package`` to ``into/name``, its imports of itself renamed."""
    target = into / name
    shutil.move(str(package), target)
    word = re.compile(r"\bfrp_assess\b")
    for path in target.rglob("*.py"):
        path.write_text(word.sub(name, path.read_text(encoding="utf-8")), encoding="utf-8")


def extract(rev: str, into: Path, name: str) -> None:
    """The package ``frp_assess`` of commit ``rev`` as ``into/name``."""
    archive = subprocess.run(
        ["git", "-C", str(ROOT), "archive", rev, "frp_assess"], capture_output=True, check=True
    ).stdout
    stage = Path(tempfile.mkdtemp(dir=into))
    subprocess.run(["tar", "-x", "-C", str(stage)], input=archive, check=True)
    _install(stage / "frp_assess", into, name)


def copy_tree(into: Path, name: str) -> None:
    """This tree's package, uncommitted changes included, as ``into/name``."""
    stage = Path(tempfile.mkdtemp(dir=into))
    ignore = shutil.ignore_patterns("__pycache__")
    shutil.copytree(ROOT / "frp_assess", stage / "frp_assess", ignore=ignore)
    _install(stage / "frp_assess", into, name)


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


def one_pass(packages: Path, first: str, study: Path, stride: int) -> dict[str, float]:
    """The interleaved IDAs of both packages in ``packages``, the one named ``first`` imported,
    built and compiled first: CPU time per IDA [s] of each, IDAs compared, IDAs the same."""
    sys.path.insert(0, str(packages))
    order = [NOW, BEFORE] if first == NOW else [BEFORE, NOW]
    sides = []
    for name in order:
        run = importlib.import_module(f"{name}.dynamics").ida
        settings, work = workload(name, study, stride)
        run(work[0][0], work[0][1].acc, work[0][1].dt, settings)  # compile before timing
        sides.append((name, run, settings, work))
    cpu = {NOW: 0.0, BEFORE: 0.0}
    agree = 0
    n = len(sides[0][3])
    for k in range(n):
        results = {}
        for name, run, settings, work in sides if k % 2 == 0 else sides[::-1]:
            model, rec = work[k]
            t0 = time.process_time()
            results[name] = run(model, rec.acc, rec.dt, settings)
            cpu[name] += time.process_time() - t0
        agree += same(results[NOW], results[BEFORE])
    return {NOW: cpu[NOW] / n, BEFORE: cpu[BEFORE] / n, "n": n, "agree": agree}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--against", required=True, metavar="REV", help="the earlier commit")
    ap.add_argument("--study", default=str(ROOT / "projects" / "paper-study.yaml"))
    ap.add_argument("--stride", type=int, default=20, help="every N-th case (default 20)")
    ap.add_argument("--pass", dest="one", nargs=2, metavar=("DIR", "FIRST"), help=argparse.SUPPRESS)
    args = ap.parse_args()
    study = Path(args.study)
    if args.one:  # a child: one pass over packages already extracted
        print(json.dumps(one_pass(Path(args.one[0]), args.one[1], study, args.stride)))
        return 0
    tmp = Path(tempfile.mkdtemp(prefix="frp-against-"))
    try:
        extract(args.against, tmp, BEFORE)
        copy_tree(tmp, NOW)
        passes = []
        for first in (NOW, BEFORE):
            child = subprocess.run(
                [sys.executable, __file__, "--against", args.against, "--study", str(study),
                 "--stride", str(args.stride), "--pass", str(tmp), first],
                capture_output=True, text=True, check=True,
            )  # fmt: skip
            passes.append(json.loads(child.stdout.strip().splitlines()[-1]))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    ratios = [p[BEFORE] / p[NOW] for p in passes]
    n = int(passes[0]["n"])
    print(f"{study.name}, every {args.stride}th case: {n} IDAs, one thread, interleaved")
    for first, p, r in zip((NOW, BEFORE), passes, ratios, strict=True):
        who = "this tree" if first == NOW else args.against
        print(
            f"  {who} set up first: this tree {1e3 * p[NOW]:.2f} ms, {args.against} "
            f"{1e3 * p[BEFORE]:.2f} ms CPU per IDA; ratio {r:.3f}; "
            f"the same results bit for bit: {int(p['agree'])} of {n}"
        )
    print(f"  {args.against} / this tree = {math.sqrt(ratios[0] * ratios[1]):.3f} (geometric mean)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
