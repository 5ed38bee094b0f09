"""The masonry at the pivot in results.json (docs/results-json.md, docs/model.md §1.1).

Plain frozen dataclasses (standard library only): the field names are the JSON keys, written
by :mod:`frp_assess.results.json_io`.  Forces are per metre of wall length.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class MasonryResult:
    """The masonry strength behind the pivot (results.json ``masonry_strength``).

    Attributes:
        masonry: type of Circolare 2019 Tab. C8.5.I, or null when the project gives none.
        knowledge_level: ``LC1`` | ``LC2`` | ``LC3`` (``code_check.knowledge_level``).
        f_m: compressive strength taken [MPa] (LC1: minimum of the table's range, LC2/LC3:
            mean; a project value wins).
        confidence_factor: FC [-] (Tab. C8.5.IV).
        f_d: design compressive strength f_m / FC [MPa].
        stress_block_factor: the stress block's fraction of f_d [-] (0.85).
        source: where f_m comes from, one line.
    """

    masonry: str | None
    knowledge_level: str
    f_m: float
    confidence_factor: float
    f_d: float
    stress_block_factor: float
    source: str


@dataclass(frozen=True)
class PivotResult:
    """The compression at the pivot of one case (results.json ``cases[i].pivot``).

    Attributes:
        rule: ``analysis.pivot`` of the project: ``edge`` | ``crushing``.
        model_pivot: the model the IDA of this case ran with: ``crushing`` (the base reaction
            of docs/model.md §1.1) or ``edge`` (x = 0: ``pivot: edge``, or no f_d).
        weight: W = w·B·H [kN/m].
        bar_force: T_u = E·A·ε_max, the acting bar at its design rupture strain [kN/m]
            (0 unreinforced).
        force: N = W + T_u, the largest compression at the pivot [kN/m].
        depth: x = N / (0.85·f_d·1 m), depth of the compressed zone [m].
        depth_ratio: x/B [-].
        pivot_shift: where the base reaction acts at rest, x_W/2 from the corner [m] (x_W of
            the weight alone; 0 with the edge model): a_RM = g·(B − 2·pivot_shift)/H for
            every case.  The wall turns about its corner in both models.
        bar_distance: distance of the acting bar from the compressed edge [m] (B/2 centred,
            B external); null unreinforced.
        limit: largest x/B accepted with the edge pivot [-] (0.10).
        dropped: always false: no option is dropped for its base any more (a toe that
            crushes is the IDA's failure mode; kept for older readers).
        reason: one line: the numbers and what they mean for the model.
    """

    rule: str
    model_pivot: str
    weight: float
    bar_force: float
    force: float
    depth: float
    depth_ratio: float
    pivot_shift: float
    bar_distance: float | None
    limit: float
    dropped: bool
    reason: str
