"""The design value over a set of records, NTC 2018 §7.3.5 (Circolare 2019 §C7.3.5): "with at
least 7 time histories the mean of the responses, with fewer the least favourable"; the 7 is
typed here from the clause, not read back from the module."""

from __future__ import annotations

import pytest

from frp_assess.rules.record_sets import design_statistic, design_value


@pytest.mark.parametrize(
    "n,statistic",
    [(1, "least"), (3, "least"), (6, "least"), (7, "mean"), (8, "mean"), (30, "mean")],
)
def test_seven_records_or_more_take_the_mean(n: int, statistic: str) -> None:
    assert design_statistic(n) == statistic


def test_design_value_picks_without_arithmetic() -> None:
    """The rule chooses, it does not compute: the caller's mean and least come back unchanged
    (bit for bit), so no result moves with where the rule is written."""
    mean, least = 0.1 + 0.2, 0.25
    assert design_value(mean, least, 7) is mean
    assert design_value(mean, least, 6) is least
