"""The expert commands `simulate` and `ida`: one wall, no project file.

:func:`simulate` runs one time history, :func:`run_ida` the IDA of one wall under a set of
records through the cached runner of `run` (so `ida` and `run` take the mean the same way).
The wall and its bars are built from practitioners' units by the one model builder,
:func:`~frp_assess.assess.wall_model.rocking_model`, re-exported here with the model types the
command line needs, so that the interfaces import only this package.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from frp_assess.assess.cache import IdaCache
from frp_assess.assess.runner import CaseSummary, IdaRunner, design_value_rule, summarise
from frp_assess.assess.wall_model import BarsInput, WallInput, rocking_model
from frp_assess.dynamics import (
    MECHANISMS,
    POSITIONS,
    IdaResult,
    IdaSettings,
    ModelOptions,
    RockingModel,
    RockingResult,
)
from frp_assess.motions import G, Record, read_record

__all__ = [
    "G",
    "MECHANISMS",
    "POSITIONS",
    "IdaOutcome",
    "IdaSettings",
    "ModelOptions",
    "Record",
    "RockingModel",
    "BarsInput",
    "WallInput",
    "read_record",
    "rocking_model",
    "run_ida",
    "simulate",
]


def simulate(
    model: RockingModel, record: Record, scale: float = 1.0, *, history: bool = False
) -> RockingResult:
    """One time history of ``model`` under ``record`` scaled by ``scale`` [-] (``history``:
    keep θ(t), θ'(t) and the bar strain at the record's samples)."""
    if not (math.isfinite(scale) and scale > 0.0):
        raise ValueError(f"the record multiplier must be > 0, got {scale!r}")
    return model.run(record.acc, record.dt, scale, history=history)


@dataclass(frozen=True)
class IdaOutcome:
    """The IDA of one wall under a set of records, summarised as `run` summarises a case."""

    records: tuple[Record, ...]
    results: tuple[IdaResult, ...]  #: one per record, in order
    summary: CaseSummary  #: mean/least favourable/design a_dyn [g], the lower-bound rule
    design_value: str  #: how the design a_dyn is taken from the records (results.json wording)
    computed: int  #: IDAs computed (the others came from the cache)


def run_ida(
    model: RockingModel,
    records: Sequence[Record],
    settings: IdaSettings,
    *,
    jobs: int | None = None,
    cache_dir: Path | None = None,
    progress: Callable[[int, int], None] | None = None,
    cancel: threading.Event | None = None,
) -> IdaOutcome:
    """IDA of ``model`` under every record, through the cached runner of `run`
    (:class:`~frp_assess.assess.runner.IdaRunner`; ``cache_dir`` None: no cache), summarised
    by the one definition of the mean (a record without collapse up to C_max counts at
    C_max·PGA, a lower bound: :func:`~frp_assess.assess.runner.summarise`)."""
    runner = IdaRunner(
        records, None, IdaCache(cache_dir), jobs=jobs, cancel=cancel, settings=settings
    )
    results = runner.run([model], progress)[0]
    return IdaOutcome(
        tuple(records),
        tuple(results),
        summarise(results, settings.max_multiplier, model.a_rm_g),
        design_value_rule(len(results)),
        runner.computed,
    )
