"""The effective collapse intensity of docs/model.md §11 on stand-in models whose collapse set
S(C) is prescribed, so that the integral a_c = C₀·exp(∫ S d ln C) is known in closed form:
a_c = C₀·exp(ln(C_max/C₀) − Σ ln(hi/lo) over the collapse windows within [C₀, C_max])
(docs/model.md §11.1, the rule; hand calculations written in each test)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.dynamics import IdaSettings, RockingModel, Wall, ida
from frp_assess.dynamics.effective import effective_capacity, ladder
from tests.conftest import synthetic_record
from tests.dynamics.test_ida import ACC, StubModel
from tests.validation.corpus import ROOT

C0 = Wall(thickness=0.4, height=3.0, unit_weight=18e3).a_rm / 2.0  # ACC's PGA is 2 m/s²
EFFECTIVE = IdaSettings(capacity="effective")


def exact(bands: list[tuple[float, float]], c_max: float) -> float:
    """The closed form of the module docstring (windows clipped to [C₀, C_max])."""
    fallen = sum(
        math.log(min(hi, c_max) / max(lo, C0)) for lo, hi in bands if min(hi, c_max) > max(lo, C0)
    )
    return C0 * math.exp(math.log(c_max / C0) - fallen)


def test_monotone_record_gives_the_first_collapse() -> None:
    """S = 1 below λ*, 0 above: a_c = λ*, the first collapse of §5, up to the bisection
    tolerance (0.5 %): both bracket the same threshold."""
    for star in (1.0, 1.37, 3.3, 20.0):
        bands = [(star * C0, math.inf)]
        eff = ida(StubModel(bands), ACC, 0.01, EFFECTIVE)
        first = ida(StubModel(bands), ACC, 0.01, IdaSettings(capacity="first-collapse"))
        assert eff.collapse_multiplier == pytest.approx(star * C0, rel=0.005)
        assert eff.collapse_multiplier == pytest.approx(first.collapse_multiplier, rel=0.005)
        assert eff.first_collapse == pytest.approx(first.collapse_multiplier, rel=0.005)
        assert eff.windows_below == 0
        assert eff.capacity == "effective"
        assert eff.q == pytest.approx(eff.collapse_multiplier / C0)


#: A point of the coarse ladder of the default sampling, C₀·r^8k (r = 1.0125, k = 7: 2.005·C₀).
COARSE_POINT = C0 * 1.0125**56


def test_a_narrow_window_moves_the_capacity_by_its_width() -> None:
    """A window 2 % wide below the threshold 5·C₀: a_c = 5·C₀/1.02 (the window's width in ln C
    removed from the standing part), while the first collapse drops to the window.  The
    default sampling sees the window either where the coarse ladder (1.0125^8) lands in it or
    inside the fine band (from 1.35 below the coarse ladder's first collapse, 5.42·C₀/1.35 =
    4.0·C₀).  Its lower edge and the threshold follow standing runs: bisected to 0.5 %; its
    upper edge takes the midpoint rule: within half a fine step (0.62 %), so 1.2 % in all."""
    for lo in (COARSE_POINT / 1.01, 4.2 * C0):
        bands = [(lo, lo * 1.02), (5.0 * C0, math.inf)]
        res = ida(StubModel(bands), ACC, 0.01, EFFECTIVE)
        assert res.collapse_multiplier == pytest.approx(5.0 * C0 / 1.02, rel=0.012)
        assert res.first_collapse == pytest.approx(lo, rel=0.005)
        assert res.windows_below == 1


def test_a_window_between_coarse_points_far_below_is_not_seen() -> None:
    """The price of the coarse ladder (docs/model.md §11.2): a 2 % window between two coarse
    points (2.005·C₀ and 2.214·C₀) more than 1.35 below the threshold 5·C₀ is never run; a_c
    is the threshold, as for a monotone record."""
    lo = COARSE_POINT * 1.05
    res = ida(StubModel([(lo, lo * 1.02), (5.0 * C0, math.inf)]), ACC, 0.01, EFFECTIVE)
    assert res.collapse_multiplier == pytest.approx(5.0 * C0, rel=0.005)
    assert res.windows_below == 0


def test_no_collapse_is_a_lower_bound() -> None:
    """Standing at C_max: no capacity, its lower bound is C_max less the windows below (a
    window the coarse ladder lands in; its upper edge within 0.62 %, as above)."""
    res = ida(StubModel([]), ACC, 0.01, EFFECTIVE)
    assert res.collapse_multiplier is None and res.a_dyn is None and res.q is None
    assert res.bound_multiplier == pytest.approx(100.0 * C0)
    lo = COARSE_POINT / 1.01
    res = ida(StubModel([(lo, lo * 1.02)]), ACC, 0.01, EFFECTIVE)
    assert res.collapse_multiplier is None
    assert res.bound_multiplier == pytest.approx(100.0 * C0 / 1.02, rel=0.012)
    assert res.capacity_multiplier == res.bound_multiplier


def chaotic_bands(seed: int) -> list[tuple[float, float]]:
    """Narrow windows between 2·C₀ and 4·C₀ (widths 1–5 %, gaps 2–15 %: about eight, as
    the fine scans of the bundled example find, docs/model.md §11.2), then collapse for good
    above 4·C₀: the resurrection of a chaotic record in intensity."""
    rng = np.random.default_rng(seed)
    bands = []
    c = 2.0 * C0
    while c < 4.0 * C0:
        w = rng.uniform(0.01, 0.05)
        bands.append((c, c * (1.0 + w)))
        c *= (1.0 + w) * (1.0 + rng.uniform(0.02, 0.15))
    return bands + [(4.0 * C0, math.inf)]


def _case_means(bands: list[list[tuple[float, float]]], ratio: float, coarse: int) -> list[float]:
    """The case mean of a_c/C₀ over the stand-ins at the eight offsets k/8."""
    means = []
    for k in range(8):
        st = IdaSettings(ladder_ratio=ratio, capacity="effective", offset=k / 8)
        caps = [ida(StubModel(b), ACC, 0.01, st, coarse=coarse).capacity_multiplier for b in bands]
        means.append(float(np.mean(caps)))
    return means


def test_shift_and_refinement_converge_to_the_integral() -> None:
    """Over 12 stand-in records with about eight windows each (module docstring for the exact
    integral): as the ladder is refined the case mean over eight offsets approaches the exact
    integral's mean and its scatter over the offsets shrinks.  The plain ladder (coarse = 1;
    r = 1.05, 1.05^½, 1.05^¼): at 1.05^¼ = 1.0123 both within 1 %.  The default sampling (fine
    ladder r, coarse r^8; r = 1.05 … 1.05^⅛): it skips the windows more than 1.35 below the
    coarse ladder's first collapse, which these stand-ins spread over a factor 2 below their
    threshold (measured: +4.3 % at 1.0123, docs/model.md §11.2), so within 1 % only at
    1.05^⅛ = 1.0061.  The first collapse of §5 stays 25 % below, whatever the step: not a
    limit."""
    bands = [chaotic_bands(seed) for seed in range(12)]
    truth = np.mean([exact(b, 100.0 * C0) for b in bands])
    for coarse, ratios in ((1, (1.05, 1.05**0.5, 1.05**0.25)), (8, (1.05**0.25, 1.05**0.125))):
        errors, scatters = [], []
        for ratio in ratios:
            means = _case_means(bands, ratio, coarse)
            errors.append(abs(np.mean(means) / truth - 1.0))
            scatters.append(np.std(means) / np.mean(means))
        assert errors == sorted(errors, reverse=True)
        assert scatters == sorted(scatters, reverse=True)
        assert errors[-1] < 0.01 and scatters[-1] < 0.01
    first = np.mean(
        [
            ida(StubModel(b), ACC, 0.01, IdaSettings(capacity="first-collapse")).collapse_multiplier
            for b in bands
        ]
    )
    assert first < 0.8 * truth


def test_offset_shifts_the_ladder() -> None:
    """C₀·s^(k+offset) up to C_max."""
    lad = ladder(1.0, 2.0, 1.1, 0.5)
    assert lad == pytest.approx([1.1 ** (k + 0.5) for k in range(7)])
    assert ladder(1.0, 2.0, 1.1, 0.0)[0] == 1.0  # offset 0 starts at C₀
    with pytest.raises(ValueError, match="offset"):
        IdaSettings(offset=1.0)
    with pytest.raises(ValueError, match="capacity"):
        IdaSettings(capacity="median")  # type: ignore[arg-type]


def test_integral_by_hand() -> None:
    """By hand.  Samples (C, fell) 1 S, 2 S, 4 C, 8 C on [1, 16]: standing from ln 1 to the
    midpoint of ln 2 and ln 4 (ln √8), fallen above (the last sample fell): a_c = √8, no
    window below it.  1 S, 2 C, 4 S on [1, 4]: standing ln √2 (up to the midpoint of ln 1 and
    ln 2) and ln 4 − ln √8 (from the midpoint of ln 2 and ln 4): ln 2, a_c = 2, and standing
    at the last sample: a lower bound; its window begins at 2 = a_c."""
    r = effective_capacity([(1, False), (2, False), (4, True), (8, True)], 1.0, 16.0)
    assert r.multiplier == pytest.approx(math.sqrt(8))
    assert not r.lower_bound and r.first_collapse == 4 and r.windows_below == 0
    r = effective_capacity([(1, False), (2, True), (4, False)], 1.0, 4.0)
    assert r.multiplier == pytest.approx(2.0)
    assert r.lower_bound and r.first_collapse == 2


def test_compiled_sampling_is_the_python_one() -> None:
    """The compiled sampling (ida_search.sample) runs the same time histories as the
    Python driver of the same rule (next_sample), on a real wall."""
    model = RockingModel(Wall(thickness=0.25, height=3.0, unit_weight=18e3), "two-sided")
    acc, dt = synthetic_record(seed=3), 0.01
    st = IdaSettings(capacity="effective", offset=0.25)
    a = ida(model, acc, dt, st)
    b = ida(model, acc, dt, st, compiled=False)
    assert [(p.multiplier, p.collapsed) for p in a.curve] == [
        (p.multiplier, p.collapsed) for p in b.curve
    ]
    assert a.collapse_multiplier == b.collapse_multiplier


def test_the_project_file_sets_every_ida_field(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """analysis.ida.capacity, ladder_ratio and offset reach the run's IdaSettings."""
    from frp_assess.assess.from_project import load_inputs

    text = (ROOT / "projects" / "paper-case.yaml").read_text(encoding="utf-8")
    text = text.replace(
        "    capacity: first-collapse",
        "    capacity: first-collapse\n    ladder_ratio: 1.2\n    offset: 0.25",
    )
    (tmp_path / "p.yaml").write_text(text, encoding="utf-8")
    ida_settings = load_inputs(tmp_path / "p.yaml").ida
    assert ida_settings.capacity == "first-collapse"
    assert ida_settings.ladder_ratio == 1.2 and ida_settings.offset == 0.25
    assert load_inputs(ROOT / "projects" / "facade-laquila.yaml").ida.capacity == "effective"


def test_the_samples_of_a_monotone_record_by_hand() -> None:
    """The default sampling's time histories (docs/model.md §11.2, design (e); r = 1.0125,
    offset 0, tolerance 0.5 %, band 1.5), enumerated by hand for a threshold between fine
    points 100 and 101 (λ* = C₀·r^100.5).  Coarse ladder 0, 8, …, 104 (104 is the first to
    fall); the fine walk from 104 − ⌈ln 1.35/ln r⌉ = 79 to 103; the collapsed run goes on with
    a step doubling after each three agreeing points (105, 106, 107 | 109, 111, 113 | 117,
    121, 125 | 133, 141) and stops at 141, 40 ≥ ⌈ln 1.5/ln r⌉ = 33 fine steps above the run's
    start 101 (133 is 32 above); the change 100 → 101 follows a long standing run: bisected
    twice (a gap of 1.25 %, then 0.62 %, then 0.31 % ≤ 0.5 %)."""
    r = 1.0125
    star = C0 * r**100.5
    res = ida(StubModel([(star, math.inf)]), ACC, 0.01, EFFECTIVE)
    on_grid = {round(math.log(p.multiplier / C0) / math.log(r), 6): p for p in res.curve}
    ladder_points = sorted(int(k) for k in on_grid if k == int(k))
    expected = sorted(
        set(range(0, 105, 8))
        | set(range(79, 104))
        | {105, 106, 107, 109, 111, 113, 117, 121, 125, 133, 141}
    )
    assert ladder_points == expected
    between = sorted(p.multiplier for p in res.curve if C0 * r**100 < p.multiplier < C0 * r**101)
    assert len(between) == 2 and res.runs == len(expected) + 2
    assert all(p.collapsed == (p.multiplier >= star) for p in res.curve)
