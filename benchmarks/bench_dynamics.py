"""Benchmark of the rocking kernel (not part of the test run).

    python3 benchmarks/bench_dynamics.py

Side by side, in one run, on the same seven 25 s broadband records at dt = 0.005 s
(scripts/make_example_records.py) and H = 3 m, α = 7.5°:

1. accuracy: the median relative error of the peak rotation at 0.5·C against a reference at
   tolerance 1e-12, for the adaptive kernel at its default tolerance and for fixed-step RK4 at
   several steps; the RK4 step that reaches the adaptive kernel's accuracy is "converged RK4";
2. speed: simulated seconds per CPU-second of whole IDAs (hunt and bisection, one thread) of
   the unreinforced two-sided wall and of a CFRP external 1 ‰ wall, for the adaptive kernel,
   converged RK4, and the scheme before error control (one RK4 step per sample whenever
   h·p·√(1+K) ≤ 0.2);

and prints the ratios; and the Bogacki–Shampine 3(2) pair at the same tolerance, the
measurement that chose Dormand–Prince 5(4).  Target: adaptive ≥ 2× converged RK4 on the
unreinforced two-sided IDAs; adaptive no slower than the old scheme on the reinforced wall.
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "scripts"))

import numpy as np  # noqa: E402
from make_example_records import synthetic  # noqa: E402

from frp_assess.dynamics import (  # noqa: E402
    DEFAULT_TOLERANCE,
    IdaSettings,
    Rebars,
    RockingModel,
    Wall,
    ida,
)

RK4_STEPS = (2e-3, 1e-3, 5e-4, 2.5e-4)  # [s]
OLD_STEP_FACTOR = 0.2


def old_scheme_step(model: RockingModel, dt: float) -> float:
    """The step of the kernel before error control: h·p·√(1+K) ≤ 0.2, at most dt [s]."""
    return min(dt, OLD_STEP_FACTOR / (model.wall.p * math.sqrt(1.0 + model.K)))


def peak_error(model: RockingModel, ref: RockingModel, records: list, cs: list[float]) -> float:
    """Median over the records of the relative peak-rotation error at 0.5·C (the median: a
    record on which the wall is ill-conditioned there says nothing about the integrator)."""
    errors = []
    for rec, c in zip(records, cs, strict=True):
        a = model.run(rec.acc, rec.dt, 0.5 * c).max_rotation
        b = ref.run(rec.acc, rec.dt, 0.5 * c).max_rotation
        errors.append(abs(a - b) / b)
    return float(np.median(errors))


def ida_throughput(model: RockingModel, records: list) -> tuple[float, int]:
    """Simulated seconds per CPU-second over the IDAs of all records, and the runs."""
    settings = IdaSettings()
    ida(model, records[0].acc, records[0].dt, settings)  # compile / load the cache
    simulated = 0.0
    runs = 0
    t0 = time.process_time()
    for rec in records:
        res = ida(model, rec.acc, rec.dt, settings)
        runs += res.runs
        simulated += res.runs * rec.duration
    return simulated / (time.process_time() - t0), runs


def main() -> int:
    wall = Wall.from_slenderness(3.0, math.radians(7.5), 18e3)
    records = [synthetic(seed, pga_g=0.106) for seed in range(1, 8)]
    print(
        f"7 records of {records[0].duration:.0f} s at dt = {records[0].dt} s; "
        f"wall H = 3 m, alpha = 7.5 deg; default tolerance {DEFAULT_TOLERANCE:g}"
    )
    ok = True
    for label, mechanism, bars in [
        ("unreinforced two-sided", "two-sided", None),
        ("CFRP external 1 per mille one-sided", "one-sided", Rebars(150e9, 0.013, "external", 1.0)),
    ]:
        model = RockingModel(wall, mechanism, bars)
        ref = model.with_options(tolerance=1e-12)
        cs = [ida(model, r.acc, r.dt).collapse_multiplier or 1.0 for r in records]
        err = peak_error(model, ref, records, cs)
        converged = None
        for h in RK4_STEPS:
            e = peak_error(model.with_options(fixed_step=h), ref, records, cs)
            print(f"  {label}: RK4 h = {h * 1e3:g} ms peak error {e:.1e}")
            if e <= max(err, 1e-9) and converged is None:
                converged = h
        converged = converged or RK4_STEPS[-1]
        bs3 = model.with_options(method="bs3")
        bs3_err = peak_error(bs3, ref, records, cs)
        bs3_speed, _ = ida_throughput(bs3, records)
        old = old_scheme_step(model, records[0].dt)
        adaptive, runs = ida_throughput(model, records)
        rk4, _ = ida_throughput(model.with_options(fixed_step=converged), records)
        before, _ = ida_throughput(model.with_options(fixed_step=old), records)
        print(
            f"  {label}: adaptive peak error {err:.1e}; IDA throughput (simulated s per CPU-s, "
            f"{runs} runs): adaptive {adaptive:,.0f}, converged RK4 (h = {converged * 1e3:g} ms) "
            f"{rk4:,.0f}, old scheme (h = {old * 1e3:.3g} ms) {before:,.0f}; "
            f"adaptive/converged RK4 = {adaptive / rk4:.2f}, adaptive/old = {adaptive / before:.2f}"
        )
        print(
            f"  {label}: Bogacki-Shampine 3(2) at the same tolerance: peak error {bs3_err:.1e}, "
            f"{bs3_speed:,.0f} simulated s per CPU-s (Dormand-Prince/BS3 = "
            f"{adaptive / bs3_speed:.2f})"
        )
        if mechanism == "two-sided" and bars is None:
            ok &= adaptive >= 2.0 * rk4
        if bars is not None:
            ok &= adaptive >= before
    print("targets met" if ok else "TARGET MISSED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
