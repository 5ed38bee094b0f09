"""Ranking of retrofit options (issue 4, Deliver 4)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

RANKING_RULE = (
    "Options meeting the target (capacity/demand >= {target:g}) first, cheapest first "
    "(then lightest); then the others by capacity/demand, highest first."
)


@dataclass(frozen=True)
class Rankable:
    """One option as the ranking sees it: capacity/demand [-], cost [currency], mass [kg]."""

    index: int
    capacity_demand: float
    cost: float
    mass: float


def rank_options(options: Sequence[Rankable], target: float) -> list[int]:
    """Indices of ``options`` in ranked order (best first)."""
    meeting = [o for o in options if o.capacity_demand >= target]
    others = [o for o in options if o.capacity_demand < target]
    meeting.sort(key=lambda o: (o.cost, o.mass, o.index))
    others.sort(key=lambda o: (-o.capacity_demand, o.cost, o.index))
    return [o.index for o in meeting + others]
