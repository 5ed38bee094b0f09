"""The "stands again" column of the per-record table: the smallest multiplier above the first
collapse at which the IDA found the wall standing (a resurrection), read from the stored curve."""

from __future__ import annotations

from frp_assess.tui.results import _resurrection


def test_resurrection_is_the_smallest_standing_multiplier_above_the_first_collapse():
    curve = [[1.0, False, 0.2], [1.1, True, 9.0], [1.2, False, 0.8], [1.3, False, 0.9]]
    assert str(_resurrection({"collapse_multiplier": 1.1, "curve": curve})) == "1.2000"
    monotone = [[1.0, False, 0.2], [1.1, True, 9.0], [1.2, True, 9.0]]
    assert _resurrection({"collapse_multiplier": 1.1, "curve": monotone}) == "—"
    assert _resurrection({"collapse_multiplier": None, "curve": curve}) == "—"
