"""Convergence under a tighter tolerance (docs/model.md §4): a 100× tighter tolerance, and an
independent fixed-step RK4 at h = 0.1 ms, change collapse multipliers by < 0.2 % and peak
rotations by < 0.1 %.

A fast subset of the convergence corpus (the whole corpus: scripts/validate_accuracy.py):
seeded synthetic band-limited noise (tests/conftest.py), 10 s at dt = 0.01 s, on the six
walls of tests/validation/configs.py.  These records are well-conditioned for these walls
(a 1e-6 change of the record does not move the answers); near-collapse chaos is the subject
of the validation script.
"""

from __future__ import annotations

import math
from dataclasses import replace
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from frp_assess.app.assessment import prepare_run
from frp_assess.assess.floor_input import floor_record
from frp_assess.config.loader import load_project
from frp_assess.dynamics import IdaSettings, RockingModel, Wall, ida
from frp_assess.dynamics.rocking import DEFAULT_TOLERANCE
from frp_assess.motions import Record
from tests.conftest import synthetic_record
from tests.validation.configs import CASES, model_for

DT = 0.01
FINE_IDA = IdaSettings(tolerance=1e-4)
REFERENCES = {
    "100x tighter": {"tolerance": DEFAULT_TOLERANCE / 100},
    "RK4 0.1 ms": {"fixed_step": 1e-4},
}


@pytest.mark.parametrize("ref", list(REFERENCES))
@pytest.mark.parametrize("name", list(CASES))
def test_peak_rotation_converges(name: str, ref: str) -> None:
    acc = synthetic_record(seed=11, duration=10.0, dt=DT)
    base = model_for(name)
    other = base.with_options(**REFERENCES[ref])
    c = ida(base, acc, DT, IdaSettings(tolerance=0.01)).collapse_multiplier
    assert c is not None
    scale = 0.6 * c  # rocking hard without falling
    a = base.run(acc, DT, scale)
    b = other.run(acc, DT, scale)
    assert a.max_rotation > 0.05 * base.wall.alpha
    assert not a.collapsed and not b.collapsed
    assert abs(a.max_rotation - b.max_rotation) <= 1e-3 * b.max_rotation


@pytest.mark.parametrize("ref", list(REFERENCES))
@pytest.mark.parametrize("name", list(CASES))
def test_collapse_multiplier_converges(name: str, ref: str) -> None:
    acc = synthetic_record(seed=12, duration=10.0, dt=DT)
    base = model_for(name)
    ca = ida(base, acc, DT, FINE_IDA).collapse_multiplier
    cb = ida(base.with_options(**REFERENCES[ref]), acc, DT, FINE_IDA).collapse_multiplier
    assert ca is not None and cb is not None
    assert abs(ca - cb) <= 2e-3 * cb


def test_step_count_follows_the_tolerance() -> None:
    """The error control is live: a tighter tolerance takes more steps (and the default one
    is not one step per sample, the old fixed scheme)."""
    acc = synthetic_record(seed=11, duration=10.0, dt=DT)
    base = model_for("GFRP external two-sided")
    c = ida(base, acc, DT, IdaSettings(tolerance=0.01)).collapse_multiplier
    assert c is not None
    steps = [
        base.with_options(tolerance=t).run(acc, DT, 0.6 * c).steps for t in (1e-6, 1e-8, 1e-10)
    ]
    assert steps[0] < steps[1] < steps[2]


def test_impact_sequence_then_rocking_agrees_with_rk4() -> None:
    """The reproducer of the one corpus miss (docs/model.md §4.3): the ground acceleration
    passes the uplift threshold, recedes to 0.93 of it (the wall rocks at ~1e-8 rad through a
    sequence of a hundred impacts at |θ'| down to 1e-7 rad/s), passes it again and then
    shakes the wall to ~0.5·α.  Every impact instant carries into the phase of what follows,
    so the peak agrees with RK4 only when those instants are located in time (with a bound
    on θ alone the two were 8e-4 apart; the same history, well-conditioned, agrees to 1e-10
    with the instants located)."""
    wall = Wall.from_slenderness(6.0, math.radians(5.0), 18e3)
    base = RockingModel(wall, "two-sided")
    t = np.arange(0.0, 8.0 + DT / 2, DT)
    u = np.interp(t, [0.0, 0.10, 0.13, 0.16, 0.30], [0.0, -1.01, -0.93, -0.93, -1.05])
    grow = 1.0 + 0.5 * np.minimum(1.0, t - 0.3)
    shake = -1.05 * np.cos(2.0 * np.pi * 0.8 * (t - 0.3)) * np.exp(-0.2 * (t - 0.3)) * grow
    acc = np.where(t > 0.3, shake, u) * base.params.tan_ax * base.params.g
    a = base.run(acc, DT)
    b = base.with_options(**REFERENCES["RK4 0.1 ms"]).run(acc, DT)
    assert a.impacts > 100 and not a.collapsed and a.max_rotation > 0.3 * wall.alpha
    assert abs(a.max_rotation - b.max_rotation) <= 1e-6 * b.max_rotation


STIFF_PROJECT = (
    Path(__file__).resolve().parents[1] / "golden" / "projects" / "building-crushing.yaml"
)
STIFF_CASE = 2  #: its CFRP external 1 ‰ option: K ≈ 240, crushing pivot, floor motion at Z = 9 m
PEAK_BAR = 1e-3  #: relative agreement of peak rotations (docs/model.md §4.5)
SMALL_ROCKING = 0.02  #: peak |θ|/α_x below which a curve point is "small rocking" [-]


@cache
def stiff_wall() -> tuple[RockingModel, tuple[Record, ...], IdaSettings]:
    """The very stiff wall of docs/model.md §4.5: the golden project building-crushing's CFRP
    external option, as `run` builds it (its records as the floor motion at the wall's base),
    at the default tolerance, and the project's IDA settings."""
    loaded = load_project(STIFF_PROJECT)
    prepared = prepare_run(loaded.project, loaded.base_dir, STIFF_PROJECT.name)
    model = prepared.inputs.case_models()[STIFF_CASE].with_options(tolerance=DEFAULT_TOLERANCE)
    recs = tuple(floor_record(r, prepared.inputs.building) for r in prepared.seismic.records)
    return model, recs, prepared.inputs.ida


def rel(a: float, b: float) -> float:
    return abs(a - b) / max(abs(a), abs(b))


def small_rocking_points(model: RockingModel, rec: Record, settings: IdaSettings) -> list[float]:
    """The multipliers of the IDA curve where the wall rocks without falling, below
    SMALL_ROCKING·α_x: on the plain ladder 1.2 (``coarse=1``, every point run; the project's
    ladder before 2026-11-28, the points this test was written on), since the default sampling
    (docs/model.md §11.2) runs only the coarse ladder below the first collapse and so hardly
    any small-rocking point."""
    plain = replace(settings, ladder_ratio=1.2)
    curve = ida(model, rec.acc, rec.dt, plain, coarse=1).curve
    return [p.multiplier for p in curve if not p.collapsed and 0 < p.peak_ratio < SMALL_ROCKING]


def against_tighter(model: RockingModel, rec: Record, c: float) -> tuple[float, float]:
    """(how far the peak at C is from a 100× tighter tolerance and from RK4 at 0.1 ms, the
    larger, how far a change of the record by ± 1e-6 moves it at the tight tolerance),
    relative; the second only where the first misses the peak bar (0 otherwise), as
    scripts/validate_accuracy.py judges the curve."""
    tight = model.with_options(tolerance=model.options.tolerance / 100)
    ref = tight.run(rec.acc, rec.dt, c).max_rotation
    rk4 = model.with_options(**REFERENCES["RK4 0.1 ms"]).run(rec.acc, rec.dt, c).max_rotation
    peak = model.run(rec.acc, rec.dt, c).max_rotation
    off = max(rel(peak, ref), rel(peak, rk4))
    if off <= PEAK_BAR:
        return off, 0.0
    return off, max(
        rel(tight.run(rec.acc * (1.0 + s * 1e-6), rec.dt, c).max_rotation, ref) for s in (1, -1)
    )


@cache
def stiff_points(record: int) -> tuple[tuple[float, float, float], ...]:
    """(C, :func:`against_tighter`) at the small-rocking points of the stiff wall under its
    record ``record`` (0: art-01, 1: art-02)."""
    model, recs, settings = stiff_wall()
    rec = recs[record]
    return tuple(
        (c, *against_tighter(model, rec, c)) for c in small_rocking_points(model, rec, settings)
    )


@pytest.mark.parametrize("record", [0, 1])
def test_stiff_wall_small_rocking_converges(record: int) -> None:
    """A number depends on the wall and the record, not on the tolerance: the small rocking
    (peaks of 0.1–2 % of α_x, 600–1400 impacts in 14 s) of a very stiff wall (K ≈ 240) is at
    the default within the peak bar of docs/model.md §4.5 (0.1 %) of a 100× tighter tolerance
    and of RK4 at h = 0.1 ms at every IDA-curve point below 2 % of α_x where the peak is
    well-conditioned.  Where they disagree, a change of the record by one part in a million
    (far below the precision of any accelerogram) moves the peak by more than the bar too:
    the number is not determined by the data there (the "ill-conditioned" numbers of §4.5),
    and no tolerance changes that.  At least three points per record agree, so the
    comparison is not vacuous.  (These well-conditioned peaks are easy: they agree within
    6e-4 even at a tolerance of 1e-3 or one step per sample; the test guards the statement,
    the error control's own tests are above.)"""
    agree = 0
    for c, off, data in stiff_points(record):
        assert off <= PEAK_BAR or data > PEAK_BAR, (c, off, data)
        agree += off <= PEAK_BAR
    assert agree >= 3


def test_stiff_wall_known_limit_is_ill_conditioned() -> None:
    """Why no tolerance fixes the "known limit" first reported in docs/model.md §4.5 (the
    same wall under art-01, where the default and a 100× tighter tolerance disagreed by up to
    35 % at small-rocking points): there the peak is ill-conditioned, not under-resolved.  A
    change of the record by one part in a million moves it by more than 10 %, as much as the
    tolerance does: the wall rocks at ~1e-3·α_x about an equilibrium just off θ = 0, with an
    impact every half cycle, and the low-velocity (grazing) impacts amplify any difference."""
    worst = max(stiff_points(0), key=lambda point: point[1])
    assert worst[1] > 0.1 and worst[2] > 0.1, worst
