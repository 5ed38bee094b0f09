"""The report's fixture (tests/report/data/results.json, written before the decision: no
verdicts) with a decision set by hand, for the tests of what the outputs say of it."""

from __future__ import annotations

import copy
from typing import Any


def decided(results: dict[str, Any]) -> dict[str, Any]:
    """The fixture with a decision (it has none): the first two options by rank pass, the
    others fail on the time-history check (the 3rd by a fall), the unreinforced wall fails."""
    r = copy.deepcopy(results)
    by_rank = sorted(r["cases"][1:], key=lambda c: c["rank"])
    for i, c in enumerate([r["cases"][0], *by_rank]):
        passes = i in (1, 2)
        margin = 1.2 if passes else (0.0 if i == 3 else 0.5)
        c.update(
            passes=passes,
            governing_check="time history SLV",
            governing_margin=margin,
            governing_lower_bound=False,
            recommended=i == 1,
        )
    r["recommended"] = by_rank[0]["name"]
    r["retrofit_required"] = True
    return r
