"""The bundled examples under a shifted and a finer sampling of the effective collapse intensity
(docs/model.md §11; issue 38, "done when").

    PYTHONPATH=. python3 benchmarks/effective_examples.py [PROJECT.yaml ...] [--jobs N]

Each project (default: projects/facade-laquila.yaml and projects/boundary-wall-records.yaml)
is run three times with ``analysis.ida.capacity: effective``, into temporary folders with a
cache of its own: as given; with ``analysis.ida.offset: 0.5`` (the ladder shifted by half a
step); with the sampling twice as fine (ladder ratio √r, bisection tolerance / 2).  Printed per
project: the recommendation of each run, and for every case the largest relative change of its
design a_dyn against the run as given (with its capacity/demand), and the mean and largest
change over the cases.  Not part of the tests (several minutes); the run of 2026-11-28 is
kept beside this file (effective_examples.txt).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from frp_assess.api import run_assessment  # noqa: E402
from frp_assess.assess.from_project import load_inputs  # noqa: E402

DEFAULT = ("facade-laquila.yaml", "boundary-wall-records.yaml")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("projects", nargs="*", default=[str(ROOT / "projects" / p) for p in DEFAULT])
    ap.add_argument("--jobs", type=int, default=None)
    args = ap.parse_args()
    for project in args.projects:
        inputs = load_inputs(project)
        base = replace(inputs.ida, capacity="effective")
        variants = {
            "as given": base,
            "offset 0.5": replace(base, offset=0.5),
            "twice as fine": replace(
                base, ladder_ratio=base.ladder_ratio**0.5, tolerance=base.tolerance / 2
            ),
        }
        runs = {}
        with tempfile.TemporaryDirectory() as tmp:
            for name, settings in variants.items():
                res, _ = run_assessment(
                    replace(inputs, ida=settings), Path(tmp) / name.replace(" ", "-"),
                    jobs=args.jobs, pdf=False,
                )  # fmt: skip
                runs[name] = res
        ref = runs["as given"]
        print(f"{Path(project).name}: {len(ref.cases)} cases")
        for name, res in runs.items():
            print(f"  {name:<14} recommended: {res.recommended}")
        for name, res in runs.items():
            if name == "as given":
                continue
            theirs = {c.name: c for c in res.cases}
            pairs = [(a, theirs[a.name]) for a in ref.cases if a.name in theirs]
            changes = [b.design_a_dyn / a.design_a_dyn - 1.0 for a, b in pairs]
            worst = max(range(len(changes)), key=lambda i: abs(changes[i]))
            a, b = pairs[worst]
            mean = statistics.fmean(changes)
            spread = statistics.fmean(abs(c) for c in changes)
            print(
                f"  {name:<14} design a_dyn of {len(pairs)} cases against as given: mean "
                f"{100 * mean:+.2f} %, mean |change| {100 * spread:.2f} %, largest "
                f"{100 * changes[worst]:+.2f} % ({a.name}, capacity/demand "
                f"{a.capacity_demand:.3f} -> {b.capacity_demand:.3f})"
            )
    return 0


if __name__ == "__main__":
    sys.exit(main())
