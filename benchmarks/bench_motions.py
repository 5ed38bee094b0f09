"""Benchmark of the ground-motion module (not part of the test run).

    python benchmarks/bench_motions.py

Generates 7 artificial records of 25 s at dt = 0.005 s against the paper's spectrum A2
(SIMQKE, default iterations) and checks them (EN 1998-1 and NTC 2018), after a first call
that compiles the numba kernels; prints the wall times (target: generate + check <= 3 s).
"""

from __future__ import annotations

import time

import numpy as np

from frp_assess.motions.compliance import check_compliance
from frp_assess.motions.response import response_spectrum
from frp_assess.motions.simqke import generate_artificial
from frp_assess.motions.spectra import preset_spectrum


def main() -> None:
    spectrum = preset_spectrum("A2")
    t0 = time.perf_counter()
    warm = generate_artificial(spectrum, count=1, seed=99, duration=15.0)
    check_compliance(warm, spectrum)
    print(f"first call (numba compile or cache load): {time.perf_counter() - t0:.2f} s")

    acc = warm[0].acc
    periods = np.geomspace(0.02, 4.0, 100)
    t0 = time.perf_counter()
    for _ in range(20):
        response_spectrum(acc, 0.005, periods)
    per = (time.perf_counter() - t0) / 20
    print(f"response spectrum, {acc.size} samples x 100 periods: {per * 1e3:.2f} ms")

    best = []
    for repeat in range(3):
        t0 = time.perf_counter()
        records = generate_artificial(spectrum, count=7, seed=1 + repeat, duration=25.0, dt=0.005)
        t_gen = time.perf_counter() - t0
        report = check_compliance(records, spectrum)
        t_all = time.perf_counter() - t0
        best.append(t_all)
        print(
            f"run {repeat + 1}: generate 7 x 25 s @ 0.005 s: {t_gen:.2f} s, "
            f"+ check: {t_all:.2f} s total; passed={report.passed}"
        )
    print(f"best generate + check: {min(best):.2f} s (target <= 3 s)")


if __name__ == "__main__":
    main()
