"""Independent checks of a run, for the reasoned judgement NTC 2018 §10.2 asks of results
computed with a program: each compares a figure of the model that ran with one reached by a
route the analysis did not take, with a tolerance, so that each can fail.

* **activation multiplier**: α₀ by the Circolare's hand formula (moment balance of the
  weight about the pivot: α₀ = B/H about the edge; (B − x)/H about the crushing pivot, x =
  W/(0.85·f_d), W = γ·B·H) against the run's a_RM/g (the kernel's base reaction);
* **free rocking period**: the run's wall released from θ₀ = α/2 without losses (velocity
  ratio 1, edge pivot) reaches θ = 0 after T/4, T by Housner's (1963) exact quadrature
  T = 4∫₀^θ₀ dθ / √(2p²[cos(α − θ₀) − cos(α − θ)]);
* **energy at impact**: the same release with the run's mechanism and impact rule: the
  amplitude after the first impact θ₁ follows from the energy balance
  cos(α − θ₁) − cos α = e²·[cos(α − θ₀) − cos α], e the velocity ratio of Housner's
  coefficients (paper Eqs. 13–14) written out here;
* **reference integrator**: the governing record of the assessed case (the recommended
  option, else the closest, else the unreinforced wall; its least favourable record) at the
  time-history check's intensity, re-run by the fixed-step RK4 scheme: the same fate and peak
  rotation θ_max/α within 0.01;
* **tighter tolerance** (when the run repeated its IDAs, ``--verify``): the largest change of
  a collapse multiplier against the IDA's bisection tolerance, no fate changed.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray
from scipy.integrate import quad

from frp_assess.dynamics import ModelOptions, RockingModel
from frp_assess.motions import Record
from frp_assess.results.independent import IndependentCheck
from frp_assess.results.model import CaseResult, NumericalCheckResult
from frp_assess.rules.masonry import STRESS_BLOCK_FACTOR
from frp_assess.rules.wall_loads import uplift_multiplier

#: tolerances [-]: relative for α₀, the period and the rebound amplitude; absolute on
#: θ_max/α for the reference integrator
ALPHA0_TOLERANCE = 0.005
PERIOD_TOLERANCE = 0.001
REBOUND_TOLERANCE = 0.002
REFERENCE_TOLERANCE = 0.01
#: the release of the free-rocking checks, as a fraction of α
RELEASE = 0.5
#: samples per quarter period of the free-rocking checks
SAMPLES_PER_QUARTER = 2000
#: the largest step of the RK4 reference [s]
REFERENCE_STEP = 1e-4


def _check(
    name: str, value: float, reference: float, unit: str, tolerance: float, detail: str,
    *, absolute: bool = False,
) -> IndependentCheck:  # fmt: skip
    diff = abs(value - reference)
    deviation = diff if absolute else diff / abs(reference) if reference != 0.0 else math.inf
    return IndependentCheck(
        name=name,
        value=value,
        reference=reference,
        unit=unit,
        deviation=deviation,
        tolerance=tolerance,
        absolute=absolute,
        passed=bool(deviation <= tolerance),
        detail=detail,
    )


def hand_alpha0(model: RockingModel) -> tuple[float, float | None]:
    """(α₀, x [m] or None about the edge) by the hand formula of the module docstring; with
    loads, the Circolare's eq. C8.7.1.1 as a sum of moments (rules.wall_loads, docs/model.md
    §12), on the side that rocks first."""
    w = model.wall
    weight = w.unit_weight * w.thickness * w.height  # [N/m]
    loads = model.loads
    edge = model.options.pivot != "crushing" or not math.isfinite(w.compressive_strength)
    if not (loads.top or loads.thrusts):
        if edge:
            return w.thickness / w.height, None
        depth = weight / (STRESS_BLOCK_FACTOR * w.compressive_strength)
        return (w.thickness - depth) / w.height, depth
    n0 = weight + sum(p.force for p in loads.top)
    depth = 0.0 if edge else n0 / (STRESS_BLOCK_FACTOR * w.compressive_strength)
    sides = (1,) if model.mechanism == "one-sided" else (1, -1)
    alpha0 = min(
        uplift_multiplier(
            weight, w.thickness, w.height, loads.top, loads.thrusts, s, n0 * depth / 2
        )
        for s in sides
    )
    return alpha0, None if edge else depth


def activation_check(model: RockingModel) -> IndependentCheck:
    alpha0, depth = hand_alpha0(model)
    about = "the edge" if depth is None else f"the crushing pivot (x = {depth * 1000:.1f} mm)"
    run = model.a_rm_g
    return _check(
        "activation multiplier", run, alpha0, "-", ALPHA0_TOLERANCE,
        f"α0 about {about} by hand {alpha0:.5f}, the model's a_RM/g {run:.5f}",
    )  # fmt: skip


def housner_period(alpha: float, p2: float, theta0: float) -> float:
    """Housner's exact free-rocking period [s] (module docstring), by quadrature."""

    # θ = θ0 − v² removes the 1/√(θ0 − θ) singularity (dθ = −2v dv), and
    # cos(α − θ0) − cos(α − θ) = 2·sin(α − (θ0 + θ)/2)·sin(v²/2) keeps it free of cancellation;
    # at v = 0 the integrand is its limit 2/√(2p²·sin(α − θ0))
    def integrand(v: float) -> float:
        if v == 0.0:
            return 2 / math.sqrt(2 * p2 * math.sin(alpha - theta0))
        th = theta0 - v * v
        drop = 2 * math.sin(alpha - 0.5 * (theta0 + th)) * math.sin(0.5 * v * v)
        return 2 * v / math.sqrt(2 * p2 * drop)

    val, _ = quad(integrand, 0.0, math.sqrt(theta0), epsabs=0.0, epsrel=1e-10, limit=200)
    return 4 * val


def _free_release(model: RockingModel, period: float) -> tuple[NDArray[np.float64], float]:
    """θ(t) of ``model`` released from RELEASE·α with no ground motion, over 1.5 periods."""
    dt = period / 4 / SAMPLES_PER_QUARTER
    theta0 = RELEASE * model.wall.alpha
    acc = np.zeros(int(1.5 * period / dt) + 2)
    res = model.run(acc, dt, history=True, theta0=theta0)
    assert res.history is not None  # asked for
    theta = res.history.theta
    return theta[~np.isnan(theta)], dt


def period_check(model: RockingModel) -> IndependentCheck:
    wall = model.wall
    free = RockingModel(wall, "two-sided", options=ModelOptions(restitution=1.0, pivot="edge"))
    period = housner_period(wall.alpha, wall.p2, RELEASE * wall.alpha)
    theta, dt = _free_release(free, period)
    k = int(np.argmax(theta <= 0.0))  # the first sample at or past θ = 0
    quarter = (k - 1 + theta[k - 1] / (theta[k - 1] - theta[k])) * dt if k > 0 else math.nan
    return _check(
        "free rocking period", 4 * quarter, period, "s", PERIOD_TOLERANCE,
        f"free rocking from θ0 = α/2 without losses: the program's period {4 * quarter:.5f} s, "
        f"Housner's closed form {period:.5f} s",
    )  # fmt: skip


def housner_velocity_ratio(model: RockingModel) -> float:
    """The velocity ratio at an impact from Housner's coefficients (paper Eqs. 13–14), for
    the run's mechanism and convention (a number is the ratio itself)."""
    a = model.wall.alpha
    r = (1 - 1.5 * math.sin(a) ** 2) ** 2
    if model.mechanism == "one-sided":
        r = (r * (1 - 1.5 * math.cos(a) ** 2)) ** 2
    rule = model.options.restitution
    if rule == "energy":
        return math.sqrt(r)
    if rule == "velocity":
        return r
    return float(rule)


def _first_rebound(theta: NDArray[np.float64]) -> float:
    """The first local peak of |θ| after the release, refined by a parabola through three
    samples."""
    a = np.abs(theta)
    for k in range(1, a.size - 1):
        if a[k] >= a[k - 1] and a[k] > a[k + 1] and a[k - 1] < a[0]:
            y0, y1, y2 = a[k - 1], a[k], a[k + 1]
            den = y0 - 2 * y1 + y2
            return float(y1 - (y2 - y0) ** 2 / (8 * den)) if den != 0.0 else float(y1)
    return math.nan


def impact_check(model: RockingModel) -> IndependentCheck:
    wall = model.wall
    edge = model.with_options(pivot="edge")
    a = wall.alpha
    theta0 = RELEASE * a
    period = housner_period(a, wall.p2, theta0)
    theta, _ = _free_release(edge, period)
    e = housner_velocity_ratio(model)
    theta1 = a - math.acos(math.cos(a) + e * e * (math.cos(a - theta0) - math.cos(a)))
    run = _first_rebound(theta)
    return _check(
        "energy at impact", run / a, theta1 / a, "-", REBOUND_TOLERANCE,
        f"amplitude after the first impact from θ0 = α/2 ({model.mechanism}, velocity ratio "
        f"{e:.4f}): the program's θ1/α {run / a:.5f}, the energy balance {theta1 / a:.5f}",
    )  # fmt: skip


def governing_record(case: CaseResult) -> int:
    """Index of the case's least favourable record (the smallest a_dyn; a record without
    collapse counts as infinite)."""
    values = [math.inf if r.a_dyn is None else r.a_dyn for r in case.records]
    return min(range(len(values)), key=lambda i: values[i])


def reference_check(
    model: RockingModel, motion: Record, record_name: str, case_name: str, scale: float
) -> IndependentCheck:
    run = model.run(motion.acc, motion.dt, scale)
    ref = model.with_options(fixed_step=min(REFERENCE_STEP, motion.dt / 10)).run(
        motion.acc, motion.dt, scale
    )
    same_fate = run.fate == ref.fate
    value = run.max_rotation_ratio if math.isfinite(run.max_rotation_ratio) else 1.0
    refv = ref.max_rotation_ratio if math.isfinite(ref.max_rotation_ratio) else 1.0
    check = _check(
        "reference integrator", value, refv, "-", REFERENCE_TOLERANCE,
        f"{case_name} under {record_name} at C = {scale:g}: the program (Dormand–Prince, "
        f"tolerance {model.options.tolerance:g}) gives θmax/α {value:.4f} ({run.fate}), the "
        f"fixed-step RK4 reference {refv:.4f} ({ref.fate})",
        absolute=True,
    )  # fmt: skip
    if same_fate:
        return check
    return IndependentCheck(**{**check.__dict__, "passed": False})


def tolerance_check(numerical: NumericalCheckResult, ida_tolerance: float) -> IndependentCheck:
    change = numerical.max_change
    check = _check(
        "tighter tolerance", 0.0 if change is None else change, 0.0, "-", ida_tolerance,
        f"every IDA repeated at tolerance {numerical.check_tolerance:g} instead of "
        f"{numerical.tolerance:g}: largest change of a collapse multiplier "
        + ("—" if change is None else f"{100 * change:.2f} %")
        + f", {numerical.changed_pairs} of {numerical.pairs} beyond the IDA's tolerance"
        + ("; a fate changed" if numerical.fate_changed else ""),
        absolute=True,
    )  # fmt: skip
    if numerical.fate_changed or change is None:
        return IndependentCheck(**{**check.__dict__, "passed": False})
    return check


def independent_checks(
    models: Sequence[RockingModel],
    names: Sequence[str],
    motions: Sequence[Record],
    cases: Sequence[CaseResult],
    assessed: str | None,
    *,
    scale: float,
    ida_tolerance: float,
    numerical: NumericalCheckResult | None = None,
) -> tuple[IndependentCheck, ...]:
    """The checks of the module docstring. ``models``/``names``: the run's case models and
    their names (the unreinforced wall first); ``motions``: each record at the wall's base;
    ``assessed``: the recommended or closest case (None: the unreinforced wall); ``scale``:
    the multiplier of the time-history check (FC when it enters the dynamics, else 1)."""
    urm = models[0]
    out = [activation_check(urm)]
    if not (urm.loads.top or urm.loads.thrusts):  # Housner's closed forms: the bare block
        out += [period_check(urm), impact_check(urm)]
    by_name = {c.name: c for c in cases}
    name = assessed if assessed in names and assessed in by_name else names[0]
    case = by_name.get(name)
    if case is not None and case.records:
        k = governing_record(case)
        out.append(
            reference_check(models[names.index(name)], motions[k], case.records[k].record,
                            name, scale)
        )  # fmt: skip
    if numerical is not None:
        out.append(tolerance_check(numerical, ida_tolerance))
    return tuple(out)


__all__ = ["independent_checks"]
