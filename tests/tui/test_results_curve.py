"""The "stands again" column of the per-record table: the smallest multiplier above the first
collapse at which the IDA found the wall standing (a resurrection), read from the stored curve."""

from __future__ import annotations

from frp_assess.results.model import CurvePoint, RecordResult
from frp_assess.tui.results_pane import _resurrection


def record(first: float | None, curve: tuple[CurvePoint, ...]) -> RecordResult:
    return RecordResult("art-01", 0.3, first, None, None, None, curve)


def test_resurrection_is_the_smallest_standing_multiplier_above_the_first_collapse():
    curve = ((1.0, False, 0.2), (1.1, True, 9.0), (1.2, False, 0.8), (1.3, False, 0.9))
    assert str(_resurrection(record(1.1, curve))) == "1.2000"
    monotone = ((1.0, False, 0.2), (1.1, True, 9.0), (1.2, True, 9.0))
    assert _resurrection(record(1.1, monotone)) == "—"
    assert _resurrection(record(None, curve)) == "—"
