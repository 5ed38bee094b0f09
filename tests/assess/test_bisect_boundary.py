"""The design search's bisection (frp_assess.assess.runner.bisect_boundary).

Reference: the boundary of a threshold predicate found by a plain scan over the grid.
"""

from __future__ import annotations

import pytest

from frp_assess.assess.runner import bisect_boundary


@pytest.mark.parametrize("threshold", [1, 2, 7, 13, 20])
def test_neighbours_straddle_the_threshold(threshold: int) -> None:
    def below(k: int) -> bool:
        return k < threshold

    lo, hi = bisect_boundary(0, 20, below)
    last_below = max(k for k in range(0, 21) if below(k))  # plain scan
    assert (lo, hi) == (last_below, last_below + 1)


def test_adjacent_ends_are_returned_without_a_call() -> None:
    calls: list[int] = []
    assert bisect_boundary(4, 5, lambda k: calls.append(k) is None) == (4, 5)
    assert calls == []
