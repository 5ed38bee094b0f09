"""The compiled kernel against an independent high-accuracy solution of docs/model.md §3.

Reference: tests/validation/reference.py — scipy DOP853 at rtol 1e-11, integrated one sample
interval at a time with scipy's own event location (a different integrator, different event
logic, the model written out again).  Tolerances: peak rotation 0.5 %, collapse multiplier
1 % (the acceptance criteria of issue 2); the kernel is typically within 1e-5.

The reference applies the `end-of-record` rule; the kernel's default `overturning` rule is
compared with the reference following 10 s of free vibration after the record (where every
wall here has fallen or settled), collapse meaning |θ| reached π/2.
"""

from __future__ import annotations

import numpy as np
import pytest

from frp_assess.dynamics import IdaSettings, RockingModel, ida
from frp_assess.dynamics.kernel import Buffers, Ground, simulate
from frp_assess.dynamics.kernel.params import kernel_record
from tests.conftest import synthetic_record
from tests.validation.configs import CASES, model_for
from tests.validation.reference import RefSystem, reference_run

DT = 0.01
RULES = ["end-of-record", "overturning"]
FREE = np.zeros(int(10.0 / DT))


def ref_record(acc: np.ndarray, rule: str) -> np.ndarray:
    """The record the reference integrates: followed by free vibration for `overturning`."""
    return np.concatenate([acc, FREE]) if rule == "overturning" else acc


def ref_system(name: str, **kw) -> RefSystem:
    mechanism, bars = CASES[name]
    args = dict(B=0.4, H=3.0, w=18e3, one_sided=mechanism == "one-sided", **kw)
    if bars:
        args.update(
            E=bars["elastic_modulus"],
            eps_u=bars["ultimate_strain"],
            position=bars["position"],
            rho=bars["ratio"],
        )
    return RefSystem(**args)


@pytest.mark.parametrize("rule", RULES)
@pytest.mark.parametrize("name", list(CASES))
def test_peak_rotation_matches_reference(name, rule):
    acc = synthetic_record(seed=21, duration=6.0, dt=DT)
    model = model_for(name, collapse=rule)
    c = ida(model, acc, DT, IdaSettings(tolerance=0.01)).collapse_multiplier
    for frac in (0.4, 0.7):
        ours = model.run(acc, DT, frac * c)
        tail = len(acc) if rule == "overturning" else None  # the free vibration appended
        ref = reference_run(ref_system(name), ref_record(acc, rule), DT, frac * c, tail_from=tail)
        assert ours.collapsed == ref["collapsed"]
        assert ours.max_rotation == pytest.approx(ref["peak"], rel=5e-3)
        if rule == "end-of-record":  # `overturning` stops counting once the fate is certain
            # every impact, the bounces that surely die out included (docs/model.md §3.3)
            assert impacts_of_every_bounce(model, acc, frac * c) == ref["impacts"]
            assert ours.impacts <= ref["impacts"]


def impacts_of_every_bounce(model: RockingModel, acc: np.ndarray, c: float) -> int:
    """The impacts of the kernel following every bounce to its rest velocity (the rule of
    docs/model.md §3.3 off), as the reference does."""
    prm = model.params._replace(settle_chatter=False)
    h = np.empty(1)
    rec = kernel_record(acc)
    buf = Buffers(h, h, h, np.zeros(2), np.zeros(2, np.int64))
    out = simulate(
        Ground(rec, DT, c, model.tail_samples(DT)), prm, model.tie_params, 0.0, 0.0, False, buf
    )
    return int(out.impacts)


#: the acceptance bar of the collapse multiplier (issue 2): 1 %
C_BAR = 1e-2
#: the kernel's hunt steps at or above this fraction of its C are confirmed on the reference
HUNT_CHECKED_FROM = 0.7


@pytest.mark.slow
@pytest.mark.parametrize("rule", ["overturning"])
@pytest.mark.parametrize(
    "name", ["URM one-sided", "CFRP external one-sided", "GFRP external two-sided"]
)
def test_collapse_multiplier_matches_reference(name, rule):
    """The kernel's first collapse C (IDA, tolerance 0.5 %) confirmed on the reference where
    it is decided, rather than by a whole second search on a solver ~1000x slower:

    - the reference stands at C/(1 + 1 %) and falls at C/(1 − 1 %): it changes from standing
      to falling within 1 % of C (the bar of issue 2).  A kernel C more than 1 % too high
      fails the first check, one more than 1 % too low the second;
    - it stands at every multiplier from 0.7·C to C/(1 + 1 %) that the kernel ran and found
      standing (its last hunt steps C₀·s^k and bisection survivors): no earlier collapse the
      kernel missed where one is most likely (below, test_peak_rotation_matches_reference
      compares the two solvers' peaks on another record at 0.4·C and 0.7·C).

    Before, the test ran the kernel's whole search (every hunt step from C₀, then the
    bisection) on the reference: ~30-40 reference runs per wall instead of ~6.
    """
    acc = synthetic_record(seed=22, duration=5.0, dt=DT)
    model = model_for(name, collapse=rule)
    ref_acc = ref_record(acc, rule)
    ours = ida(model, acc, DT, IdaSettings(tolerance=0.005, capacity="first-collapse"))
    c = ours.collapse_multiplier
    assert c is not None and ours.survivor_multiplier is not None

    def ref_collapsed(multiplier: float) -> bool:
        return reference_run(ref_system(name), ref_acc, DT, multiplier, tail_from=len(acc))[
            "collapsed"
        ]

    assert not ref_collapsed(c / (1 + C_BAR)), "the reference stands 1 % below the kernel's C"
    assert ref_collapsed(c / (1 - C_BAR)), "the reference falls 1 % above the kernel's C"
    hunt = [p.multiplier for p in ours.curve if not p.collapsed]
    checked = [m for m in hunt if HUNT_CHECKED_FROM * c <= m < c / (1 + C_BAR)]
    assert checked, "no hunt step checked"
    for m in checked:
        assert not ref_collapsed(m), f"the reference falls at C = {m:.4g} < {c:.4g}"
