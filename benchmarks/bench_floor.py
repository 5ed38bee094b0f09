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
   than 1 % between its default and the tighter tolerance: the fractal boundary of rocking
   collapse, where no solver's answer is meaningful to 1 %).
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

from floor import FloorWall, floor_params, load  # noqa: E402
from floor.scipy_events import run_unreinforced  # noqa: E402
from make_example_records import synthetic  # noqa: E402

from frp_assess.dynamics import IdaSettings, Rebars, RockingModel, Wall, ida  # noqa: E402

H = 3.0
B = H * math.tan(math.radians(7.5))
W = 18e3  # N/m³
F_D = 2.0e6  # Pa
STEPS = (2e-3, 1e-3, 5e-4, 2.5e-4)  # [s]
AGREE = 0.01


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


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--records", type=int, default=7, help="records of the set (default 7)")
    ap.add_argument(
        "--fd", type=float, default=F_D / 1e6, help="f_d [MPa] (default 2.0; inf: edge pivot)"
    )
    ap.add_argument("--no-scipy", action="store_true", help="skip the solve_ivp measurement")
    args = ap.parse_args()
    floor = load()
    records = [synthetic(seed, pga_g=0.106) for seed in range(1, args.records + 1)]
    print(f"{len(records)} records of {records[0].duration:.0f} s at dt = {records[0].dt} s")
    settings = IdaSettings()
    ok = True
    for label, model, fwall in walls(args.fd * 1e6):
        ida(model, records[0].acc, records[0].dt, settings)  # compile / load numba's cache
        t0 = time.process_time()
        kernel = [ida(model, r.acc, r.dt, settings) for r in records]
        cpu = time.process_time() - t0
        simulated = sum(k.runs * r.duration for k, r in zip(kernel, records, strict=True))
        speed_k = simulated / cpu
        tight = model.with_options(tolerance=model.options.tolerance / 100.0)
        ref = [ida(tight, r.acc, r.dt, settings).collapse_multiplier for r in records]
        good = [
            i
            for i, (k, c) in enumerate(zip(kernel, ref, strict=True))
            if k.collapse_multiplier and c and abs(k.collapse_multiplier - c) <= AGREE * c
        ]
        print(
            f"{label}: kernel {speed_k:,.0f} simulated s per CPU-s ({sum(k.runs for k in kernel)} "
            f"runs); well-conditioned records {len(good)}/{len(records)}"
        )
        if floor is None:
            continue
        converged = None
        for h in STEPS:
            prm, a_rm = floor_params(fwall, h)
            t0 = time.process_time()
            runs = [floor.ida(r.acc, r.dt, prm, a_rm) for r in records]
            cpu_f = time.process_time() - t0
            speed_f = sum(f.runs * r.duration for f, r in zip(runs, records, strict=True)) / cpu_f
            agree = all(
                runs[i].multiplier is not None
                and abs(runs[i].multiplier - ref[i]) <= AGREE * ref[i]  # type: ignore[operator]
                for i in good
            )
            print(
                f"  floor RK4 h = {h * 1e3:g} ms: {speed_f:,.0f} simulated s per CPU-s, "
                f"C within 1 % on the well-conditioned records: {'yes' if agree else 'no'}; "
                f"kernel/floor = {speed_k / speed_f:.2f}"
            )
            if agree and converged is None:
                converged = (h, speed_f)
        if converged is None:
            print("  the floor did not converge at 0.25 ms")
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
