"""How long the kernel's steps could be if they were allowed to cross record samples (an
analysis, not part of the tests).

    python3 benchmarks/step_room.py [--stride N] [--study projects/paper-study.yaml]

Today every step ends at the next record sample (docs/model.md §4.2): across a sample the
input's slope jumps and a Runge–Kutta step would lose its order (docs/paper-study.md, "Where
the time goes, and what is left to take"). This asks how much room the error control leaves
on the other side of that limit, i.e. what a step that handled the kinks exactly could gain
at most.

For every N-th case of the study (default 80) and one of its records, the IDA's collapse
multiplier C is found, and the time histories at C/1.1, C/1.1⁴ and C/1.1¹⁰ (the hunt's range)
are run with their history. From the kernel's state at every sample where the wall rocks on
one side with its bar intact up to the next sample, one Dormand–Prince step of length dt is
taken and its error estimate err (in units of the tolerance, docs/model.md §4.2) kept. The
error of a step of m samples grows as m⁵, so a step may span m samples where err·m⁵ ≤ 1
(``bound``) or, with the controller's safety factor, m ≤ 0.9·err^(−1/5) (``controller``);
capped at 8 samples.  Printed per group of walls (bar stiffness K ≥ 10, the others): the
share of samples with room for 2, 3 and 4 samples, and the mean samples per step (the
harmonic mean of m: steps = Σ 1/m over the samples).
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from frp_assess.dynamics import ida  # noqa: E402
from frp_assess.dynamics.kernel import params as kp  # noqa: E402
from frp_assess.dynamics.kernel.steppers import acceleration, step  # noqa: E402
from frp_assess.study import StudyPlan, load_study, study_records  # noqa: E402

#: The largest step considered [samples].
CAP = 8
#: Below the collapse multiplier: C/1.1^j for these j (the hunt climbs by 1.1).
BELOW = (1, 4, 10)


def sample_errors(study: Path, stride: int) -> dict[str, np.ndarray]:
    """Error estimates of one step of length dt from the kernel's state at the samples
    (see the module's docstring), by group of walls: ``stiff`` (K ≥ 10) and ``other``."""
    plan = StudyPlan(load_study(study))
    records = study_records(plan)
    found: dict[str, list[float]] = {"stiff": [], "other": []}
    for case in list(plan.cases(0, len(plan)))[::stride]:
        model = plan.model(case)
        prm = model.params
        recs = records[case.spectrum]
        rec = recs[case.index % len(recs)]
        acc = kp.kernel_record(rec.acc)
        c_collapse = ida(model, acc, rec.dt, plan.ida_settings).collapse_multiplier
        if c_collapse is None:
            continue
        group = found["stiff" if prm.k_bar >= 10.0 else "other"]
        for j in BELOW:
            c = c_collapse / 1.1**j
            run = model.run(acc, rec.dt, c, history=True)
            assert run.history is not None
            th, om = run.history.theta, run.history.omega
            t_rupture = run.ruptures[0].time if run.ruptures else math.inf
            u = acc * (c / prm.g)
            for i in range(min(th.size, acc.size) - 1):
                if (i + 1) * rec.dt >= t_rupture:
                    break
                if th[i] == 0.0 or th[i] * th[i + 1] <= 0.0:
                    continue  # at rest, or an impact before the next sample
                s = 1.0 if th[i] > 0.0 else -1.0
                a1 = acceleration(th[i], s, u[i], prm.k_bar, prm)
                slope = (u[i + 1] - u[i]) / rec.dt
                err = step(th[i], om[i], rec.dt, u[i], slope, s, prm.k_bar, a1, prm)[3]
                group.append(err)
    return {k: np.asarray(v) for k, v in found.items()}


def room(err: np.ndarray, safety: float) -> np.ndarray:
    """Samples a step could span: the largest m ≤ CAP with m ≤ safety·err^(−1/5)."""
    m = np.floor(safety * np.maximum(err, 1e-300) ** -0.2)
    return np.clip(m, 1, CAP)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--study", default=str(ROOT / "projects" / "paper-study.yaml"))
    ap.add_argument("--stride", type=int, default=80, help="every N-th case (default 80)")
    args = ap.parse_args()
    for name, err in sample_errors(Path(args.study), args.stride).items():
        if err.size == 0:
            continue
        bound = room(err, 1.0)
        ctrl = room(err, 0.9)
        print(
            f"{name:<6} {err.size:7d} samples, median err {np.median(err):.2e}; room for "
            f"2/3/4 samples: {np.mean(bound >= 2):.0%}/{np.mean(bound >= 3):.0%}/"
            f"{np.mean(bound >= 4):.0%}; samples per step (cap {CAP}): bound "
            f"{1.0 / np.mean(1.0 / bound):.2f}, controller {1.0 / np.mean(1.0 / ctrl):.2f}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
