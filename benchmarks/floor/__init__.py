"""The compiled fixed-step floor of the speed benchmark (benchmarks/bench_floor.py).

:func:`load` compiles ``rk4_floor.c`` with the system's C compiler into a temporary folder and
returns a :class:`Floor` that runs whole IDAs with it; :func:`floor_params` computes the wall's
constants from the equations of docs/model.md, independently of frp_assess.dynamics.
"""

from __future__ import annotations

import ctypes
import math
import shutil
import subprocess
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import brentq

G = 9.80665
SOURCE = Path(__file__).with_name("rk4_floor.c")


class Params(ctypes.Structure):
    """The C struct ``Params`` of rk4_floor.c, field for field."""

    _fields_ = [
        (name, ctypes.c_double)
        for name in (
            "g", "p2", "sin_a", "cos_a", "tan_uplift", "xi", "k_bar", "kappa", "theta_max",
            "theta_cr", "rupture_energy", "e_impact", "barrier_intact", "angle_intact",
            "barrier_broken", "angle_broken", "h", "max_free",
        )
    ] + [("one_sided", ctypes.c_int), ("bar_mode", ctypes.c_int)]  # fmt: skip


@dataclass(frozen=True)
class FloorWall:
    """A wall as the floor sees it (SI): B, H [m], w [N/m³], f_d [Pa] (inf: edge pivot), and
    the bars (E [Pa], ε_max [-], position, ratio [‰]) or None."""

    thickness: float
    height: float
    unit_weight: float
    design_strength: float
    one_sided: bool
    bars: tuple[float, float, str, float] | None = None


def _integral(theta: float, kap: float) -> float:
    """∫₀^θ n(φ)²·cos φ dφ, n = 1 + κ·sin(φ/2) (closed form)."""
    c = math.cos(0.5 * theta)
    return (
        math.sin(theta)
        + 2.0 * kap * (2.0 * c - 4.0 / 3.0 * c**3 - 2.0 / 3.0)
        + 0.5 * kap * kap * (math.sin(theta) - 0.5 * theta - 0.25 * math.sin(2.0 * theta))
    )


def floor_params(wall: FloorWall, step: float) -> tuple[Params, float]:
    """The C parameters of ``wall`` at the fixed step [s], and a_RM [m/s²]."""
    b, h = wall.thickness, wall.height
    alpha = math.atan2(b, h)
    r = 0.5 * math.hypot(b, h)
    p2 = 3.0 * G / (4.0 * r)
    weight = wall.unit_weight * b * h
    x_w = 0.0 if math.isinf(wall.design_strength) else weight / (0.85 * wall.design_strength)
    xi = x_w / (2.0 * r)
    sin2 = math.sin(alpha) ** 2
    one = 1.0 - 1.5 * sin2
    e_impact = abs(one**2 * (1.0 - 1.5 * math.cos(alpha) ** 2)) if wall.one_sided else one
    k_bar = kappa = rupture_energy = 0.0
    theta_max = theta_cr = math.inf
    bar_mode = 0
    if wall.bars is not None:
        modulus, eps_max, position, ratio = wall.bars
        area = ratio * 1e-3 * b
        arm = 0.5 * b if position == "centred" else b
        k_bar = modulus * area * arm**2 / (h * weight * r)
        kappa = 2.0 * arm * modulus * area / (h * weight)
        arg = eps_max * h / (2.0 * arm)
        theta_max = 2.0 * math.asin(arg) if arg < 1.0 else math.inf
        if x_w > 0.0:
            crush = (min(arm, b) / x_w - 1.0) / kappa
            theta_cr = 2.0 * math.asin(max(crush, 0.0)) if crush < 1.0 else math.inf
        if math.isfinite(theta_max):
            inertia = 4.0 / 3.0 * (weight / G) * r * r
            elong = 2.0 * arm * math.sin(0.5 * theta_max)
            rupture_energy = 0.5 * modulus * area / h * elong**2 / inertia
        bar_mode = 1 if position == "centred" else 2

    def potential(theta: float, k: float, kap: float) -> float:
        return p2 * (
            math.cos(alpha - theta) + k * (1.0 - math.cos(theta)) - xi * _integral(theta, kap)
        )

    def moment(theta: float, k: float, kap: float) -> float:
        n = 1.0 + kap * math.sin(0.5 * theta)
        return math.sin(alpha - theta) + k * math.sin(theta) - xi * n * n * math.cos(theta)

    def tipping(k: float, kap: float) -> float:
        if moment(0.5 * math.pi, k, kap) >= 0.0:
            return 0.5 * math.pi
        return float(brentq(moment, 0.0, 0.5 * math.pi, args=(k, kap), xtol=1e-15))

    angle_broken = tipping(0.0, 0.0)
    angle_intact = min(tipping(k_bar, kappa), theta_max, theta_cr)
    prm = Params(
        g=G, p2=p2, sin_a=math.sin(alpha), cos_a=math.cos(alpha), tan_uplift=(b - x_w) / h,
        xi=xi, k_bar=k_bar, kappa=kappa, theta_max=theta_max, theta_cr=theta_cr,
        rupture_energy=rupture_energy, e_impact=e_impact,
        barrier_intact=potential(angle_intact, k_bar, kappa), angle_intact=angle_intact,
        barrier_broken=potential(angle_broken, 0.0, 0.0), angle_broken=angle_broken,
        h=step, max_free=300.0, one_sided=int(wall.one_sided), bar_mode=bar_mode,
    )  # fmt: skip
    return prm, G * (b - x_w) / h


@dataclass(frozen=True)
class FloorIda:
    multiplier: float | None  #: C of the first collapse (None: none up to C_max)
    runs: int
    steps: int


class Floor:
    """The compiled floor: one time history, and whole IDAs with the rule of docs/model.md §5."""

    def __init__(self, library: ctypes.CDLL) -> None:
        self._simulate = library.floor_simulate
        self._simulate.restype = ctypes.c_int
        self._simulate.argtypes = [
            ctypes.POINTER(ctypes.c_double), ctypes.c_long, ctypes.c_double, ctypes.c_double,
            ctypes.POINTER(Params), ctypes.POINTER(ctypes.c_long),
            ctypes.POINTER(ctypes.c_double),
        ]  # fmt: skip

    def run(
        self, acc: NDArray[np.float64], dt: float, scale: float, prm: Params
    ) -> tuple[int, int, float]:
        """(1 collapse / 0 none / -1 undecided, RK4 steps, peak |θ| [rad]) of one time history."""
        steps = ctypes.c_long(0)
        peak = ctypes.c_double(0.0)
        ptr = acc.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
        out = self._simulate(
            ptr, acc.shape[0], dt, scale, ctypes.byref(prm), ctypes.byref(steps),
            ctypes.byref(peak),
        )  # fmt: skip
        return int(out), int(steps.value), float(peak.value)

    def ida(
        self,
        acc: NDArray[np.float64],
        dt: float,
        prm: Params,
        a_rm: float,
        *,
        step_ratio: float = 1.10,
        tolerance: float = 0.005,
        max_multiplier: float = 100.0,
    ) -> FloorIda:
        """Hunt C₀·s^k to the first collapse, then bisect to (C_hi − C_lo) ≤ tol·C_hi."""
        acc = np.ascontiguousarray(acc, dtype=np.float64)
        c0 = a_rm / float(np.max(np.abs(acc)))
        total = [0, 0]

        def collapses(c: float) -> bool:
            out, steps, _ = self.run(acc, dt, c, prm)
            total[0] += 1
            total[1] += steps
            if out < 0:
                raise RuntimeError("floor: fate undecided after the free vibration")
            return out == 1

        c_lo, k = 0.0, 0
        while True:
            c = c0 * step_ratio**k
            if c > max_multiplier * c0 * (1.0 + 1e-12):
                return FloorIda(None, total[0], total[1])
            if collapses(c):
                c_hi = c
                break
            c_lo, k = c, k + 1
        while c_hi - c_lo > tolerance * c_hi:
            mid = 0.5 * (c_lo + c_hi)
            if collapses(mid):
                c_hi = mid
            else:
                c_lo = mid
        return FloorIda(c_hi, total[0], total[1])


def load(say: Callable[[str], None] = print) -> Floor | None:
    """Compile rk4_floor.c with the system's C compiler; None (and a message) without one."""
    cc = shutil.which("cc") or shutil.which("gcc") or shutil.which("clang")
    if cc is None:
        say("no C compiler (cc, gcc or clang) on PATH: the compiled fixed-step floor is skipped")
        return None
    folder = Path(tempfile.mkdtemp(prefix="frp-floor-"))
    lib = folder / "rk4_floor.so"
    cmd = [cc, "-O3", "-march=native", "-shared", "-fPIC", str(SOURCE), "-o", str(lib), "-lm"]
    done = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        say(f"the C compiler failed, the floor is skipped: {done.stderr.strip()[:300]}")
        return None
    return Floor(ctypes.CDLL(str(lib)))
