"""Benchmark of the rocking kernel and of a 19-case × 7-record IDA (not part of the test run).

    python benchmarks/bench_dynamics.py

Prints the kernel throughput in simulated seconds per CPU-second on a 25 s record at
dt = 0.005 s (unreinforced and CFRP-external walls, one-sided, at 90 % of each wall's
collapse multiplier, where the wall rocks for most of the record — the costly regime of an
IDA), and the wall time of the IDA of 19 cases (unreinforced + GFRP/BFRP/CFRP × centred/
external × 1/2/3 ‰) × 7 records on all cores, after the first compile.
"""

from __future__ import annotations

import math
import os
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "scripts"))

from make_example_records import synthetic  # noqa: E402

from frp_assess.dynamics import (  # noqa: E402
    IdaTask,
    Rebars,
    RockingModel,
    Wall,
    default_jobs,
    ida,
    run_batch,
)

MATERIALS = {"GFRP": (46e9, 0.015), "BFRP": (50e9, 0.020), "CFRP": (150e9, 0.013)}


def throughput(model: RockingModel, acc, dt: float, scale: float, repeat: int = 200) -> float:
    model.run(acc, dt, scale)
    t0 = time.process_time()
    for _ in range(repeat):
        model.run(acc, dt, scale)
    cpu = (time.process_time() - t0) / repeat
    return (acc.size - 1) * dt / cpu


def main() -> None:
    wall = Wall.from_slenderness(3.0, math.radians(7.5), 18e3)
    records = [synthetic(seed, pga_g=0.106) for seed in range(1, 8)]
    rec = records[0]
    print(
        f"record: {rec.duration:.0f} s at dt = {rec.dt} s; wall H = 3 m, alpha = 7.5 deg, one-sided"
    )
    for label, bars in [
        ("unreinforced", None),
        ("CFRP external 1 per mille", Rebars(150e9, 0.013, "external", 1.0)),
    ]:
        model = RockingModel(wall, "one-sided", bars)
        c = ida(model, rec.acc, rec.dt).collapse_multiplier
        assert c is not None
        for frac in (0.5, 0.9):
            sps = throughput(model, rec.acc, rec.dt, frac * c)
            print(
                f"  {label:28s} at {frac:.1f}*C = {frac * c:6.2f}: "
                f"{sps:10.0f} simulated s per CPU-s "
                f"({model.substeps(rec.dt)} sub-steps per sample)"
            )
    models = [RockingModel(wall, "one-sided")]
    for E, eps in MATERIALS.values():
        for pos in ("centred", "external"):
            for rho in (1.0, 2.0, 3.0):
                models.append(RockingModel(wall, "one-sided", Rebars(E, eps, pos, rho)))
    tasks = [IdaTask(m, r.acc, r.dt) for m in models for r in records]
    run_batch(tasks[:1], jobs=1)  # compile/cache load
    t0 = time.perf_counter()
    results = run_batch(tasks, jobs=default_jobs())
    wall_time = time.perf_counter() - t0
    runs = sum(r.runs for r in results)
    print(
        f"IDA of {len(models)} cases x {len(records)} records: {wall_time:.2f} s wall time on "
        f"{default_jobs()} threads ({os.cpu_count()} CPUs), {runs} time histories"
    )


if __name__ == "__main__":
    main()
