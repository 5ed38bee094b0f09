"""Design mode makes no monotonicity assumption (frp_assess.assess.runner.design_search).

Reference: the smallest passing grid ratio found by a plain scan of the same predicate,
written out in each test.  The runner is a stand-in whose a_dyn is a set function of the
model's ratio (a window of capacity, as the ranking of a real run showed: CFRP external
1 and 2 ‰ passing while 2.5 ‰ reached 0.13).
"""

from __future__ import annotations

from dataclasses import replace

import pytest

from frp_assess.assess.inputs import DesignRequest
from frp_assess.assess.runner import design_search
from frp_assess.dynamics import IdaResult, RockingModel
from frp_assess.motions import G
from tests.assess.test_as_built import inputs_of


class WindowRunner:
    """a_dyn = 0.3 g for a model ratio in [0.8, 1.6] ‰, else 0.1 g; records every ratio."""

    def __init__(self) -> None:
        self.ratios: list[float] = []

    def run(self, models: list[RockingModel]) -> list[list[IdaResult]]:
        out = []
        for m in models:
            assert m.rebars is not None
            r = m.rebars.ratio
            self.ratios.append(r)
            a = (0.3 if 0.8 <= r <= 1.6 else 0.1) * G
            out.append([IdaResult(G, 1.0, a / G, a, 1.0, 1, None)])
        return out


def _inputs(resolution: float = 0.1):
    inputs = inputs_of("  []", b=0.4, length=1.0)
    return replace(
        inputs,
        design=DesignRequest((), ("centred",), (0.2, 3.0), resolution),
        compressive_strength=50.0,  # the pivot cap stays above the range
    )


def _gfrp():
    return inputs_of("  - {material: GFRP, position: centred, ratio: 1}").options[0].material


def test_a_capacity_window_is_found_where_bisection_would_miss_it():
    """Demand 0.2 g: only model ratios in [0.8, 1.6] ‰ pass, the top of the range (3 ‰)
    fails.  A bisection assuming capacity grows with ρ checks 3 ‰ first and answers "no
    ratio"; the grid walk answers the first grid ratio whose installed ratio is ≥ 0.8 ‰."""
    inputs = _inputs()
    runner = WindowRunner()
    res = design_search(runner, inputs, _gfrp(), "centred", 0.2)  # type: ignore[arg-type]
    assert res.ratio is not None and res.ratio_model is not None
    assert 0.8 <= res.ratio_model <= 1.6
    # plain scan of the same grid: every ratio before the answer ran and failed
    before = [r for r in runner.ratios if r != res.ratio_model]
    assert before and all(r < 0.8 for r in before)
    assert res.capacity_demand == pytest.approx(0.3 / 0.2)


def test_the_screen_skips_the_ida_and_moves_the_answer_up():
    """A time-history screen that fails below 1.2 ‰ (model ratio): the IDA is not run there,
    and the answer is the first grid ratio ≥ 1.2 ‰ inside the window."""
    inputs = _inputs()
    runner = WindowRunner()
    screened: list[float] = []

    def screen(m: RockingModel) -> bool:
        assert m.rebars is not None
        screened.append(m.rebars.ratio)
        return m.rebars.ratio >= 1.2

    res = design_search(runner, inputs, _gfrp(), "centred", 0.2, screen)  # type: ignore[arg-type]
    assert res.ratio_model is not None and 1.2 <= res.ratio_model <= 1.6
    assert runner.ratios == [res.ratio_model]  # the IDA ran only where the screen passed
    assert all(r < 1.2 for r in screened[:-1])


def test_no_ratio_passes_says_how_close_it_came():
    inputs = _inputs(resolution=0.5)
    runner = WindowRunner()
    res = design_search(runner, inputs, _gfrp(), "centred", 1.0)  # type: ignore[arg-type]
    assert res.ratio is None
    assert "passes every deciding check" in res.message
    assert "the IDA reaches at most 0.30" in res.message
