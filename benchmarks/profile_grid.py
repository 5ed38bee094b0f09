"""Where a time history of the paper's grid spends its work (not part of the tests).

    python3 benchmarks/profile_grid.py [--stride N] [--study projects/paper-study.yaml]

Runs the IDAs of every N-th case of the study (default 40) the way the compiled search does
(the same multipliers, the record's quiet start skipped), one kernel call per time history
from Python so that each call's outcome and CPU time (``time.process_time_ns``) can be kept,
and prints per time history: accepted and rejected steps, impacts, the samples integrated
after the quiet start, steps per integrated sample, the share that collapse and how early,
and the CPU time, overall and by the bar's stiffness K; then the CPU time split by least
squares into a cost per accepted step and a cost per impact.  The figures of docs/paper-study.md
("Where the time goes") come from here.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from frp_assess.dynamics.ida_search import (  # noqa: E402
    next_multiplier,
    quiet_intervals,
    running_max_abs,
)
from frp_assess.dynamics.kernel import Buffers, Ground, simulate  # noqa: E402
from frp_assess.dynamics.kernel import params as kp  # noqa: E402
from frp_assess.study import StudyPlan, load_study, study_records  # noqa: E402

_COLLAPSE = (kp.FATE_FELL, kp.FATE_EXCEEDED, kp.FATE_CRUSHED)
#: columns of one row per time history
_COLS = ("k_bar", "one_sided", "start", "n_input", "integrated", "steps", "rejected",
         "impacts", "collapsed", "cpu_us")  # fmt: skip


def profile(study: Path, stride: int) -> dict[str, np.ndarray]:
    """One row per time history of the sampled IDAs (see ``_COLS``)."""
    plan = StudyPlan(load_study(study))
    records = study_records(plan)
    settings = plan.ida_settings
    h = np.empty(1)
    buf = Buffers(h, h, h, np.zeros(2), np.zeros(2, dtype=np.int64))
    rows: list[tuple[float, ...]] = []
    warm = True
    for case in list(plan.cases(0, len(plan)))[::stride]:
        model = plan.model(case)
        prm = model.params
        for rec in records[case.spectrum]:
            acc = kp.kernel_record(rec.acc)  # as the product passes it
            c0 = model.a_rm / float(np.max(np.abs(acc)))
            hunt: list[float] = []
            while (c := c0 * settings.step_ratio ** len(hunt)) <= settings.max_multiplier * c0 * (
                1.0 + 1e-12
            ):
                hunt.append(c)
            peak_so_far = running_max_abs(acc)
            n_tail = model.tail_samples(rec.dt)
            n, c_lo, c_hi = 0, 0.0, math.nan
            while not math.isnan(
                c := next_multiplier(np.array(hunt), settings.tolerance, n, c_lo, c_hi)
            ):
                start = quiet_intervals(peak_so_far, c, prm)
                a = acc[start:]
                args = (Ground(a, rec.dt, c, n_tail), prm, model.tie_params, 0.0, 0.0, False, buf)
                if warm:  # compile before timing
                    simulate(*args)
                    warm = False
                t0 = time.process_time_ns()
                out = simulate(*args)
                cpu = time.process_time_ns() - t0
                collapsed = out.fate in _COLLAPSE
                rows.append((prm.k_bar, float(prm.one_sided), start, a.size + n_tail - 1,
                             out.decided_time / rec.dt, out.steps, out.rejected, out.impacts,
                             float(collapsed), 1e-3 * cpu))  # fmt: skip
                n += 1
                c_hi, c_lo = (c, c_lo) if collapsed else (c_hi, c)
    table = np.array(rows)
    return {name: table[:, j] for j, name in enumerate(_COLS)}


def report(t: dict[str, np.ndarray]) -> str:
    """The figures, as text."""
    n = t["steps"].size
    lines = [f"{n} time histories, {t['cpu_us'].sum() / 1e6:.2f} CPU-s in the kernel"]

    def block(name: str, m: np.ndarray) -> str:
        integ = t["integrated"][m].sum()
        coll = m & (t["collapsed"] > 0)
        return (
            f"{name:<22} {m.sum():6d} TH ({t['cpu_us'][m].sum() / t['cpu_us'].sum():5.1%} of CPU): "
            f"{t['cpu_us'][m].mean():6.0f} µs/TH, {t['steps'][m].mean():6.0f} steps "
            f"({t['rejected'][m].mean():.2f} rejected), {t['impacts'][m].mean():5.0f} impacts, "
            f"{t['steps'][m].sum() / integ:.2f} steps/sample, "
            f"{1e3 * t['cpu_us'][m].sum() / t['steps'][m].sum():4.0f} ns/step, "
            f"collapse {coll.sum() / max(m.sum(), 1):.0%}"
        )

    everything = np.ones(n, dtype=bool)
    lines.append(block("all", everything))
    for lo, hi in ((0.0, 1e-9), (1e-9, 3.0), (3.0, 10.0), (10.0, math.inf)):
        m = (t["k_bar"] >= lo) & (t["k_bar"] < hi)
        if m.any():
            lines.append(block(f"K in [{lo:g}, {hi:g})", m))
    for side in (1.0, 0.0):
        lines.append(block("one-sided" if side else "two-sided", t["one_sided"] == side))
    coll = t["collapsed"] > 0
    lines.append(
        f"samples: {t['n_input'].mean() + t['start'].mean():.0f} per record, "
        f"{t['start'].mean():.0f} skipped as the quiet start, {t['integrated'].mean():.0f} "
        f"integrated (collapsing histories {t['integrated'][coll].mean():.0f}, the others "
        f"{t['integrated'][~coll].mean():.0f}); impacts "
        f"{t['impacts'].sum() / t['steps'].sum():.3f} per accepted step"
    )
    lines.append(cost_split(t))
    return "\n".join(lines)


def cost_split(t: dict[str, np.ndarray]) -> str:
    """The CPU time of a time history fitted (least squares over all of them) as
    a·(accepted steps) + b·impacts + c: what one more step and one more impact cost, and
    their shares of the kernel's time.  c is what the two counts do not capture: the Python
    call of each time history (this script's, ≈ 9 µs; the compiled search has none) and the
    samples at rest (≈ 15 ns each); it is left out of the shares."""
    x = np.column_stack([t["steps"], t["impacts"], np.ones_like(t["steps"])])
    (a, b, c), *_ = np.linalg.lstsq(x, t["cpu_us"], rcond=None)
    per_step = a * t["steps"].sum()
    per_impact = b * t["impacts"].sum()
    kernel = per_step + per_impact
    return (
        f"cost split (least squares): {1e3 * a:.0f} ns per accepted step, "
        f"{1e3 * b:.0f} ns per impact (the located step, the search on the cubic, the "
        f"restart), {c:.0f} µs per call and rest; steps {per_step / kernel:.0%} and impacts "
        f"{per_impact / kernel:.0%} of the kernel's time"
    )


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--study", default=str(ROOT / "projects" / "paper-study.yaml"))
    ap.add_argument("--stride", type=int, default=40, help="every N-th case (default 40)")
    args = ap.parse_args()
    print(report(profile(Path(args.study), args.stride)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
