"""Ranking of retrofit options (issue 4, Deliver 4; issue 16: the pivot drop rule)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

RANKING_RULE = (
    "Options meeting the target (capacity/demand >= {target:g}) first, cheapest first "
    "(then lightest); then the others by capacity/demand, highest first. Options failing "
    "the pivot check (the masonry at the pivot, docs/model.md §1.1) are dropped: no rank."
)


@dataclass(frozen=True)
class Rankable:
    """One option as the ranking sees it: capacity/demand [-], cost [currency], mass [kg];
    ``dropped``: it fails the pivot check and gets no rank."""

    index: int
    capacity_demand: float
    cost: float
    mass: float
    dropped: bool = False


def rank_options(options: Sequence[Rankable], target: float) -> list[int]:
    """Indices of ``options`` in ranked order (best first); dropped options are left out."""
    kept = [o for o in options if not o.dropped]
    meeting = [o for o in kept if o.capacity_demand >= target]
    others = [o for o in kept if o.capacity_demand < target]
    meeting.sort(key=lambda o: (o.cost, o.mass, o.index))
    others.sort(key=lambda o: (-o.capacity_demand, o.cost, o.index))
    return [o.index for o in meeting + others]
