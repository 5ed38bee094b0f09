"""How much the first-collapse multiplier depends on the hunt's step ratio (docs/model.md §5.1).

    python3 scripts/hunt_resolution.py [--stride N] [--study FILE] [--ratio R ...]
                                       [--tolerance TOL ...]

The IDA's result is the *first* collapse that the search meets: the hunt tries C₀·s^k and
bisects below the first k that collapses.  A rocking wall often collapses in a narrow window
of C and stands again above it, so a hunt with a finer step can meet a window that a coarser
one steps over.  This script runs the IDAs of every N-th case of a study (default 10: 206 cases
× 7 records of the paper's grid) with the study's step ratio s and with the nested grids s^½
(every point of the s grid and one between each pair) and s² (every other point), everything
else unchanged, interleaved on one thread, and prints against s:

* per IDA: how many a_dyn = C·PGA move by more than 1 % (down / up), the median and the
  extremes of the relative change;
* per case (the mean over its records, the figure every verdict uses): how many move by more
  than 1 % and 5 %, the extremes and the mean change;
* the same for the grid s·(1 + 4·10⁻¹⁶), a few units in the last place away: the nested grids
  share their points only up to rounding, and this control shows how much of the change is
  the ill-conditioned time histories (docs/model.md §4.5) rather than the step;
* with ``--ratio R``: the same for a hunt of step ratio R (1.1^(1/4) = 1.0241: is the first
  collapse converging as the step shrinks?);
* with ``--tolerance TOL``: the same for the grid of s with that integration tolerance;
* how many IDAs found no collapse up to C_max (their a_dyn: C_max·PGA, as in the means);
* the CPU time per IDA (``time.process_time``) and the time histories per IDA.

Not part of the tests (about two minutes at the default stride, half a minute more per
``--tolerance``).  It reads the study
file only; nothing is written.
"""

from __future__ import annotations

import argparse
import copy
import dataclasses
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from frp_assess.dynamics import ida  # noqa: E402
from frp_assess.study import StudyPlan, load_study, study_records  # noqa: E402


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--study", default=str(ROOT / "projects" / "paper-study.yaml"))
    ap.add_argument("--stride", type=int, default=10, help="every N-th case (default 10)")
    ap.add_argument(
        "--ratio",
        type=float,
        action="append",
        default=[],
        help="also run a hunt with this step ratio (repeatable; e.g. 1.0241 = 1.1^(1/4))",
    )
    ap.add_argument(
        "--tolerance",
        type=float,
        action="append",
        default=[],
        help="also run the study's step with this integration tolerance (repeatable)",
    )
    args = ap.parse_args()
    study = load_study(Path(args.study))
    plan = StudyPlan(study)
    records = study_records(plan)
    s = plan.ida_settings.step_ratio
    grids = {
        f"s = {s:g}": s,
        f"s^1/2 = {s**0.5:.4f}": s**0.5,
        f"s^2 = {s * s:.4f}": s * s,
        # the control: the same grid moved by a few units in the last place (nested grids
        # are nested only up to rounding); what moves here is ill-conditioning, not the step
        "s·(1 + 4e-16)": s * (1.0 + 4e-16),
    }
    for r in args.ratio:
        grids[f"s = {r:g}"] = r
    # name -> (the IDA's settings, the plan that builds the models)
    variants = {
        name: (dataclasses.replace(plan.ida_settings, step_ratio=r), plan)
        for name, r in grids.items()
    }
    for tol in args.tolerance:
        other = copy.copy(plan)
        other.options = study.model.model_options(tol)
        variants[f"s, tolerance {tol:g}"] = (plan.ida_settings, other)
    a_dyn: dict[str, list[float]] = {name: [] for name in variants}
    cpu = dict.fromkeys(variants, 0.0)
    runs = dict.fromkeys(variants, 0)
    no_collapse = dict.fromkeys(variants, 0)
    case_of: list[int] = []
    cases = list(plan.cases(0, len(plan)))[:: args.stride]
    first = records[cases[0].spectrum][0]
    for st, pl in variants.values():  # compile before timing
        ida(pl.model(cases[0]), first.acc, first.dt, st)
    for n_case, case in enumerate(cases):
        models = {name: pl.model(case) for name, (_, pl) in variants.items()}
        for rec in records[case.spectrum]:
            for name, (st, _) in variants.items():
                t0 = time.process_time()
                res = ida(models[name], rec.acc, rec.dt, st)
                cpu[name] += time.process_time() - t0
                runs[name] += res.runs
                c = res.collapse_multiplier
                # no collapse up to C_max: C_max·PGA, a lower bound, as in every mean (§5.2)
                a_dyn[name].append(res.pga * (st.max_multiplier * res.c0 if c is None else c))
                no_collapse[name] += c is None
            case_of.append(n_case)
    owner = np.array(case_of)
    base = np.array(a_dyn[next(iter(variants))])
    n_ida = base.size
    print(
        f"{Path(args.study).name}, every {args.stride}th case: {len(cases)} cases, {n_ida} IDAs; "
        f"a_dyn of the first collapse against s = {s:g} (C_max·PGA where none up to C_max)"
    )
    base_mean = np.array([base[owner == k].mean() for k in range(len(cases))])
    for name in variants:
        val = np.array(a_dyn[name])
        rel = val / base - 1.0
        mean = np.array([val[owner == k].mean() for k in range(len(cases))])
        mrel = mean / base_mean - 1.0
        print(
            f"  {name:<20} {1e3 * cpu[name] / n_ida:6.2f} ms/IDA, {runs[name] / n_ida:5.1f} time "
            f"histories/IDA | IDAs lower by > 1 %: {int(np.sum(rel < -0.01))}, higher by > 1 %: "
            f"{int(np.sum(rel > 0.01))}, median |change| {np.median(np.abs(rel)):.2g}, "
            f"extremes {rel.min():+.3f} / {rel.max():+.3f}; no collapse up to C_max: "
            f"{no_collapse[name]} | case means moved by > 1 %: "
            f"{int(np.sum(np.abs(mrel) > 0.01))}, > 5 %: {int(np.sum(np.abs(mrel) > 0.05))}, "
            f"extremes {mrel.min():+.3f} / {mrel.max():+.3f}, mean {mrel.mean():+.4f}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
