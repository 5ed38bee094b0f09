"""Is the Dormand–Prince step waiting on its own chain of operations? (not part of the tests)

    python3 benchmarks/step_pair.py [--steps N]

Times N steps of :func:`frp_assess.dynamics.kernel.steppers.dopri5` (one sample, 5 ms, on
the unreinforced wall's equation, θ kept within its rocking range) two ways, compiled, one
thread, three rounds: one history at a time (each step needs the last), and two independent
histories advanced step by step in the same loop.  If a step were bound by the latency of
its stages, the processor would run the second history in the gaps and the pair would cost
little more than one; a ratio near 1 says the step is bound by its arithmetic instead, so
overlapping histories (two multipliers of a hunt, say) would not pay (docs/paper-study.md,
"Steps across samples, tried").
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

from numba import njit

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from frp_assess.dynamics.kernel import params as kp  # noqa: E402
from frp_assess.dynamics.kernel.steppers import dopri5  # noqa: E402

ALPHA = 0.13  #: [rad]
P2 = 5.0  #: p² [1/s²]
DT = 0.005  #: [s]


def wall() -> kp.KernelParams:
    """An unreinforced two-sided wall, edge pivot (the paper's Eq. 10)."""
    sa, ca = math.sin(ALPHA), math.cos(ALPHA)
    return kp.KernelParams(
        g=9.81, p2=P2, p=math.sqrt(P2), alpha=ALPHA, sin_a=math.sin(ALPHA),
        cos_a=math.cos(ALPHA), one_sided=False, bar_mode=kp.BAR_NONE, k_bar=0.0,
        theta_max=math.inf, rupture_energy=0.0, e_impact=0.9,
        rupture_mode=kp.RUPTURE_ENERGY_TRANSFER, collapse_mode=kp.COLLAPSE_OVERTURNING,
        method=kp.METHOD_DOPRI5, tolerance=1e-6, fixed_step=math.inf, xi=0.0,
        kappa_per_k=0.0, theta_cr=math.inf, alpha_x=ALPHA, tan_ax=math.tan(ALPHA),
        tip_bar=math.nan, loaded=False, p2_pos=P2, p2_neg=P2, a0_pos=sa, a0_neg=-sa,
        a1_pos=ca, a1_neg=ca, b0_pos=-ca, b0_neg=-ca, b1_pos=sa, b1_neg=-sa,
        tan_pos=math.tan(ALPHA), tan_neg=math.tan(ALPHA), e_to_pos=0.9, e_to_neg=0.9,
        alpha_x_neg=ALPHA, tip_bar_neg=math.nan,
    )  # fmt: skip


@njit(cache=False)
def _bounded(theta: float, omega: float) -> tuple[float, float]:
    """Keep a history inside the rocking range (restart it when it leaves)."""
    if abs(theta) < 0.1 and abs(omega) < 1.0:
        return theta, omega
    return 0.001, 0.0


@njit(cache=False)
def one_history(n: int, prm: kp.KernelParams) -> float:
    theta, omega, a1, total = 0.01, 0.0, 0.0, 0.0
    for i in range(n):
        u0 = 0.1 * math.sin(0.01 * i)
        theta, omega, a1, err = dopri5(theta, omega, DT, u0, 0.01, 1.0, 0.0, a1, prm)
        theta, omega = _bounded(theta, omega)
        total += err
    return theta + total


@njit(cache=False)
def two_histories(n: int, prm: kp.KernelParams) -> float:
    ta, wa, aa = 0.01, 0.0, 0.0
    tb, wb, ab = 0.011, 0.001, 0.0
    total = 0.0
    for i in range(n // 2):
        u0 = 0.1 * math.sin(0.01 * i)
        ta, wa, aa, ea = dopri5(ta, wa, DT, u0, 0.01, 1.0, 0.0, aa, prm)
        tb, wb, ab, eb = dopri5(tb, wb, DT, 1.1 * u0, 0.01, 1.0, 0.0, ab, prm)
        ta, wa = _bounded(ta, wa)
        tb, wb = _bounded(tb, wb)
        total += ea + eb
    return ta + tb + total


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=2_000_000)
    args = ap.parse_args()
    prm = wall()
    one_history(10, prm)
    two_histories(10, prm)
    for _ in range(3):
        t0 = time.process_time()
        one_history(args.steps, prm)
        t1 = time.process_time()
        two_histories(args.steps, prm)
        t2 = time.process_time()
        print(
            f"one history {1e9 * (t1 - t0) / args.steps:5.1f} ns a step, two interleaved "
            f"{1e9 * (t2 - t1) / args.steps:5.1f} ns a step: ratio {(t1 - t0) / (t2 - t1):.2f}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
