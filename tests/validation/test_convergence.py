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

import pytest

from frp_assess.dynamics import IdaSettings, ida
from frp_assess.dynamics.rocking import DEFAULT_TOLERANCE
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
