"""The kernel against a compiled fixed-step floor, side by side in one run (not part of the tests).

    python3 benchmarks/bench_floor.py [--records N] [--no-scipy]

Two walls, H = 3 m, α = 7.5°, w = 18 kN/m³, f_d = 2.0 MPa (the default `crushing` model of
docs/model.md: the base reaction follows the bars): the unreinforced two-sided wall, and a CFRP
external 1 ‰ one-sided wall (the stiff case, K ≈ 1.7), under seven 25 s broadband records at
dt = 0.005 s (scripts/make_example_records.py).

1. The floor: a plain fixed-step RK4 of the same equations written in C
   (benchmarks/floor/rk4_floor.c), compiled now with the system's C compiler (skipped with a
   message where there is none), run at the largest step of 2, 1, 0.5, 0.25 ms whose collapse
   multipliers agree within 1 % with the kernel at a 100× tighter tolerance on every
   well-conditioned record (a record is ill-conditioned when the kernel's own C moves by more
   than 0.2 % between its default, a 100× and a 10⁴× tighter tolerance: the fractal boundary
   of rocking collapse, where no solver's answer is meaningful to 1 %).
2. Whole IDAs (hunt and bisection, one thread), simulated seconds per CPU-second, kernel and
   floor, and their ratio; and scipy's solve_ivp with event location on single time histories
   of the unreinforced wall.
Target: kernel ≥ 2× the converged floor on both walls.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "scripts"))
sys.path.insert(0, str(HERE))

from floor import Floor, FloorWall, floor_params, load  # noqa: E402
from floor.scipy_events import run_unreinforced  # noqa: E402
from make_example_records import synthetic  # noqa: E402

from frp_assess.dynamics import IdaSettings, Rebars, RockingModel, Wall, ida  # noqa: E402
from frp_assess.motions import Record  # noqa: E402

H = 3.0
B = H * math.tan(math.radians(7.5))
W = 18e3  # N/m³
F_D = 2.0e6  # Pa
STEPS = (2e-3, 1e-3, 5e-4, 2.5e-4)  # [s]
C_GATE = 0.01  #: the issue's accuracy gate on collapse multipliers
C_BAR = 2e-3  #: docs/model.md §4: C within 0.2 % at a 100x tighter tolerance
PEAK_BAR = 1e-3  #: docs/model.md §4: peaks within 0.1 %
PERTURBATION = 1e-6  #: relative change of the record that tests a result's conditioning


def walls(f_d: float) -> list[tuple[str, RockingModel, FloorWall]]:
    """The two walls, as the kernel's models and as the floor's, at f_d [Pa]."""
    wall = Wall(B, H, W, f_d)
    cfrp = Rebars(150e9, 0.013, "external", 1.0)
    return [
        ("unreinforced two-sided", RockingModel(wall, "two-sided"), FloorWall(B, H, W, f_d, False)),
        (
            "CFRP external 1 per mille one-sided",
            RockingModel(wall, "one-sided", cfrp),
            FloorWall(B, H, W, f_d, True, (150e9, cfrp.rupture_strain, "external", 1.0)),
        ),
    ]


def floor_speed(
    floor: Floor, fwall: FloorWall, h: float, records: list[Record]
) -> tuple[float, list[float | None], list[float]]:
    """(simulated s per CPU-s of the floor's IDAs, their C, a timing-free list) at step h."""
    prm, a_rm = floor_params(fwall, h)
    t0 = time.process_time()
    runs = [floor.ida(r.acc, r.dt, prm, a_rm) for r in records]
    cpu = time.process_time() - t0
    simulated = sum(f.runs * r.duration for f, r in zip(runs, records, strict=True))
    return simulated / cpu, [f.multiplier for f in runs], []


def rel(a: float | None, b: float | None) -> float:
    """Relative difference of two results (inf when one is missing)."""
    if a is None or b is None:
        return 0.0 if a is b else math.inf
    return abs(a - b) / abs(b)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--records", type=int, default=7, help="records of the set (default 7)")
    ap.add_argument(
        "--fd", type=float, default=F_D / 1e6, help="f_d [MPa] (default 2.0; inf: edge pivot)"
    )
    ap.add_argument("--dt", type=float, default=0.005, help="sample interval [s] (default 0.005)")
    ap.add_argument(
        "--rtol", type=float, default=None, help="the kernel's tolerance (default: its default)"
    )
    ap.add_argument("--no-scipy", action="store_true", help="skip the solve_ivp measurement")
    args = ap.parse_args()
    floor = load()
    records = [synthetic(seed, dt=args.dt, pga_g=0.106) for seed in range(1, args.records + 1)]
    print(f"{len(records)} records of {records[0].duration:.0f} s at dt = {records[0].dt} s")
    settings = IdaSettings()
    ok = True
    for label, model, fwall in walls(args.fd * 1e6):
        if args.rtol is not None:
            model = model.with_options(tolerance=args.rtol)
        ida(model, records[0].acc, records[0].dt, settings)  # compile / load numba's cache
        t0 = time.process_time()
        kernel = [ida(model, r.acc, r.dt, settings) for r in records]
        speed_k = sum(k.runs * r.duration for k, r in zip(kernel, records, strict=True)) / (
            time.process_time() - t0
        )
        tight = model.with_options(tolerance=model.options.tolerance / 100.0)
        ref = [ida(tight, r.acc, r.dt, settings).collapse_multiplier for r in records]
        tighter = model.with_options(tolerance=model.options.tolerance / 1e4)
        ref2 = [ida(tighter, r.acc, r.dt, settings).collapse_multiplier for r in records]
        # C is judged where the kernel's own answer does not move with its tolerance: the
        # same at the default, 100x and 10^4x tighter (two of them can agree by chance, as the
        # IDA's multipliers are a discrete grid: the unreinforced wall's C agreed at 1e-6 and
        # 1e-8 on records where 1e-10 moved it by 9 % to 30 %)
        good = [
            i
            for i, k in enumerate(kernel)
            if rel(k.collapse_multiplier, ref[i]) <= C_BAR and rel(ref[i], ref2[i]) <= C_BAR
        ]
        half = [0.5 * (c or kernel[i].c0 * 100.0) for i, c in enumerate(ref)]
        peak_ref = [
            tight.run(r.acc, r.dt, c).max_rotation for r, c in zip(records, half, strict=True)
        ]
        # a peak is judged where a change of the record by one part in a million
        # (far below any accelerogram's precision) does not move it: rocking near its
        # collapse boundary can be chaotic, and there no solver's peak means anything
        nudged = [
            tight.run(r.acc, r.dt, c * (1.0 + PERTURBATION)).max_rotation
            for r, c in zip(records, half, strict=True)
        ]
        stable = [i for i in range(len(records)) if rel(nudged[i], peak_ref[i]) <= PEAK_BAR / 10]
        peak_k = [
            model.run(r.acc, r.dt, c).max_rotation for r, c in zip(records, half, strict=True)
        ]
        err_k = max((rel(peak_k[i], peak_ref[i]) for i in stable), default=0.0)
        print(
            f"{label}: kernel {speed_k:,.0f} simulated s per CPU-s "
            f"({sum(k.runs for k in kernel)} runs); C well-conditioned on {len(good)}/"
            f"{len(records)} records, the peak at C/2 on {len(stable)}; largest peak error "
            f"there {err_k:.1e}"
        )
        if floor is None:
            continue
        converged = None
        for h in STEPS:
            speed_f, cs, _ = floor_speed(floor, fwall, h, records)
            prm, _ = floor_params(fwall, h)
            peaks = [floor.run(r.acc, r.dt, c, prm)[2] for r, c in zip(records, half, strict=True)]
            err_f = max((rel(peaks[i], peak_ref[i]) for i in stable), default=0.0)
            c_ok = all(rel(cs[i], ref[i]) <= C_GATE for i in good)
            fine = c_ok and err_f <= PEAK_BAR
            print(
                f"  floor RK4 h = {h * 1e3:g} ms: {speed_f:,.0f} simulated s per CPU-s; C within "
                f"{C_GATE:.0%}: {'yes' if c_ok else 'no'}; largest peak error at C/2 "
                f"{err_f:.1e}; kernel/floor = {speed_k / speed_f:.2f}"
            )
            if fine and converged is None:
                converged = (h, speed_f)
        if converged is None:
            print(f"  the floor did not converge at {STEPS[-1] * 1e3:g} ms")
            ok = False
            continue
        ratio = speed_k / converged[1]
        print(
            f"  => kernel / converged floor (h = {converged[0] * 1e3:g} ms) = {ratio:.2f} "
            f"({'meets' if ratio >= 2.0 else 'MISSES'} the 2x target)"
        )
        ok &= ratio >= 2.0
    if not args.no_scipy:
        rec = records[0]
        c = 0.5 * ida(RockingModel(Wall(B, H, W), "two-sided"), rec.acc, rec.dt).c0 * 4.0
        t0 = time.process_time()
        run_unreinforced(rec.acc, rec.dt, c, B, H, one_sided=False)
        cpu = time.process_time() - t0
        edge = RockingModel(Wall(B, H, W), "two-sided")
        t0 = time.process_time()
        for _ in range(20):
            edge.run(rec.acc, rec.dt, c)
        cpu_k = (time.process_time() - t0) / 20
        print(
            f"solve_ivp (RK45, rtol 1e-8, events), unreinforced two-sided, one time history at "
            f"C = {c:.2f}: {rec.duration / cpu:,.0f} simulated s per CPU-s; "
            f"kernel/solve_ivp = {cpu / cpu_k:,.0f}"
        )
    print("targets met" if ok else "TARGET MISSED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
