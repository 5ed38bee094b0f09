"""An independent solver of the rocking wall held by a steel tie (docs/model.md §12).

It extends :mod:`tests.dynamics.loads_reference` (the statics of the turned block, scipy's
DOP853 at 1e-12) with the tie written from its own mechanics, not from the kernel: a bar
anchored on the outer face at height h_t, whose anchor point moves outward by δ = h_t·sin θ
when the wall turns outward about the outer corner (the point u = 0, y = h_t of the turned
block is at X = −h_t·sin θ), pulled back by F = clip(k_t·(δ − δ_p), 0, F_y) acting at the
height Y = h_t·cos θ above the corner: the moment F·h_t·cos θ holds the wall.  The tie's
state changes at scipy's event functions (terminal, with a direction): yield (δ − δ_p =
F_y/k_t, rising), unload while yielding (θ' = 0, falling), slack (δ − δ_p = 0, falling),
re-engage (rising) and the loss of a brittle anchorage (k_t·(δ − δ_p) = F_a, rising); the
integration restarts from each with the new state.  Impacts as in the reference it extends.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from tests.dynamics.loads_reference import LoadedWall

SLACK, ELASTIC, YIELD, LOST = "slack", "elastic", "yield", "lost"


@dataclass(frozen=True)
class RefTie:
    height: float  #: h_t [m]
    stiffness: float  #: k_t [N/m per m]
    yield_force: float  #: F_y [N/m]
    anchorage: float = math.inf  #: F_a [N/m] (inf: never lost)


@dataclass
class TiedResult:
    theta: np.ndarray  #: θ at the requested times (NaN after a fall)
    plastic: float  #: δ_p at the end [m]
    lost: bool
    plastic_work: float  #: Σ F_y·Δδ_p [J/m]
    plastic_by_tie: tuple[float, ...] = ()  #: δ_p of each tie at the end [m]


def _force(tie: RefTie, mode: str, theta: float, dp: float) -> float:
    """The tie's force [N/m] in ``mode`` at θ."""
    if theta <= 0.0 or mode in (SLACK, LOST):
        return 0.0
    if mode == YIELD:
        return tie.yield_force
    return tie.stiffness * (tie.height * math.sin(theta) - dp)


def tied_rocking(
    wall: LoadedWall,
    tie: RefTie | Sequence[RefTie],
    duration: float,
    times: np.ndarray,
    theta0: float = 0.0,
    omega0: float = 0.0,
    ground: Callable[[float], float] = lambda _t: 0.0,
    breaks: Sequence[float] = (),
    side0: int = 1,
) -> TiedResult:
    """θ(t) at ``times`` from (θ0, θ'0) under ü_g = ``ground(t)`` [m/s²] (smooth between the
    instants ``breaks``, where the integration restarts), the wall rocking first on
    ``side0``; two-sided impacts by angular momentum.  ``tie``: one tie, or several (each
    with its own state and δ_p; the result's ``plastic`` is the largest δ_p, ``plastic_by_tie``
    each, ``lost`` whether any was lost)."""
    ties = (tie,) if isinstance(tie, RefTie) else tuple(tie)
    out = np.full(times.shape, np.nan)
    t0, y0 = 0.0, np.array([theta0, omega0])
    side = side0
    modes = [ELASTIC] * len(ties)
    dps = [0.0] * len(ties)
    work = 0.0
    while t0 < duration:

        def rhs(
            t: float, y: np.ndarray, s: int = side, m: tuple = tuple(modes), d: tuple = tuple(dps)
        ) -> list[float]:
            th = float(y[0])
            moment = s * wall.moment(s * th, s, ground(t))
            if s > 0:
                for tj, mj, dj in zip(ties, m, d, strict=True):
                    moment -= _force(tj, mj, th, dj) * tj.height * math.cos(th)
            return [float(y[1]), moment / wall.inertia(s)]

        def cross(_t: float, y: np.ndarray) -> float:
            return float(y[0])

        cross.terminal = True  # type: ignore[attr-defined]
        cross.direction = -side  # type: ignore[attr-defined]

        def fall(_t: float, y: np.ndarray) -> float:
            return abs(float(y[0])) - 0.5 * math.pi

        fall.terminal = True  # type: ignore[attr-defined]
        events = [cross, fall]
        names: list[tuple[str, int]] = [("impact", -1), ("fall", -1)]
        if side > 0:
            for j, (tj, mode, dp) in enumerate(zip(ties, modes, dps, strict=True)):
                h, k = tj.height, tj.stiffness

                def stretch(y: np.ndarray, h: float = h, d: float = dp) -> float:
                    return h * math.sin(float(y[0])) - d

                if mode == SLACK:
                    events.append(_event(lambda _t, y, f=stretch: f(y), +1))
                    names.append(("engage", j))
                elif mode == ELASTIC:
                    fy = tj.yield_force / k
                    events.append(_event(lambda _t, y, f=stretch, fy=fy: f(y) - fy, +1))
                    names.append(("yield", j))
                    if math.isfinite(tj.anchorage):
                        fa = tj.anchorage
                        loss = _event(lambda _t, y, f=stretch, k=k, fa=fa: k * f(y) - fa, +1)
                        events.append(loss)
                        names.append(("loss", j))
                    if dp > 0.0:
                        events.append(_event(lambda _t, y, f=stretch: f(y), -1))
                        names.append(("slack", j))
            if YIELD in modes:
                events.append(_event(lambda _t, y: float(y[1]), -1))
                names.append(("unload", -1))
        t_stop = min([b for b in breaks if b > t0] + [duration])
        sol = solve_ivp(
            rhs, (t0, t_stop), y0, method="DOP853", rtol=1e-12, atol=1e-14,
            events=events, dense_output=True,
        )  # fmt: skip
        t_end = float(sol.t[-1])
        sel = (times >= t0) & (times <= t_end)
        out[sel] = sol.sol(times[sel])[0]
        if sol.status == 0:  # a break (or the end): go on from there in the same state
            y0 = sol.y[:, -1].copy()
            t0 = t_end
            continue
        if sol.status != 1:
            break
        hit = next(i for i, te in enumerate(sol.t_events) if te.size)
        name, which = names[hit]
        th, om = (float(v) for v in sol.y_events[hit][0])
        if name == "fall":
            break
        for j, tj in enumerate(ties):
            if modes[j] == YIELD:  # the plastic elongation reached so far
                new_dp = tj.height * math.sin(th) - tj.yield_force / tj.stiffness
                work += tj.yield_force * (new_dp - dps[j])
                dps[j] = new_dp
        if name == "impact":
            side = -side
            om *= wall.impact_ratio(side)
            th = 0.0
            modes = [
                m if m == LOST else (SLACK if d > 0.0 else ELASTIC)
                for m, d in zip(modes, dps, strict=True)
            ]
        elif name == "engage":
            modes[which] = ELASTIC
        elif name == "yield":
            modes[which] = YIELD
        elif name == "unload":
            modes = [ELASTIC if m == YIELD else m for m in modes]
            om = 0.0
        elif name == "slack":
            modes[which] = SLACK
        elif name == "loss":
            modes[which] = LOST
        y0 = np.array([th, om])
        t0 = t_end
    return TiedResult(out, max(dps), LOST in modes, work, tuple(dps))


def _event(f, direction: int):  # type: ignore[no-untyped-def]
    """A terminal scipy event function with a direction."""

    def event(t: float, y: np.ndarray) -> float:
        return float(f(t, y))

    event.terminal = True  # type: ignore[attr-defined]
    event.direction = direction  # type: ignore[attr-defined]
    return event
