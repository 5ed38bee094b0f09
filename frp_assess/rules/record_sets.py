"""The design value of a response over a set of time histories (records).

NTC 2018 §7.3.5 (Circolare 2019 §C7.3.5; EN 1998-1 §4.3.3.4.3): with at least 7 records the
design value of a response is the mean of the responses to the records, with fewer the least
favourable of them.  For the IDA's a_dyn [g] the least favourable is the smallest.
"""

from __future__ import annotations

from typing import Literal

#: with this many records or more the design value is their mean, with fewer the least
#: favourable one (NTC 2018 §7.3.5) [records]
MEAN_OF_RECORDS_FROM = 7

DesignStatistic = Literal["mean", "least"]


def design_statistic(n_records: int) -> DesignStatistic:
    """How the design value is taken from ``n_records`` records [-] (NTC 2018 §7.3.5):
    ``"mean"`` with ≥ :data:`MEAN_OF_RECORDS_FROM`, else ``"least"`` (the least favourable)."""
    return "mean" if n_records >= MEAN_OF_RECORDS_FROM else "least"


def design_value(mean: float, least: float, n_records: int) -> float:
    """The design value of a response (NTC 2018 §7.3.5): its ``mean`` over the records with
    ≥ 7 of them, else its ``least`` favourable value (the unit of both; ``n_records`` [-])."""
    return mean if design_statistic(n_records) == "mean" else least
