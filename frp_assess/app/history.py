"""Time histories of a finished run: one case under one of its records at a multiplier,
as the IDA ran it (the TUI's history viewer), and the multiplier just below collapse the
viewer offers (:func:`~frp_assess.assess.results.below_collapse`, the one the results use)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from frp_assess.app.expert import simulate
from frp_assess.assess.floor_input import floor_record
from frp_assess.assess.inputs import AssessmentInputs
from frp_assess.assess.results import below_collapse
from frp_assess.dynamics import RockingModel, RockingResult
from frp_assess.motions import Record

if TYPE_CHECKING:
    from frp_assess.app.assessment import RunOutcome

__all__ = ["HistoryData", "TimeHistory", "below_collapse", "case_history", "time_history"]


@dataclass(frozen=True)
class TimeHistory:
    """One case of a run under one of its records at one multiplier."""

    model: RockingModel  #: the case's wall, bars and options
    record: Record
    multiplier: float  #: C [-]
    result: RockingResult  #: with its history


def time_history(
    inputs: AssessmentInputs,
    records: Sequence[Record],
    case_index: int,
    record_index: int,
    multiplier: float,
) -> TimeHistory:
    """The time history of case ``case_index`` of a run (0: the unreinforced wall, then each
    option) under its record ``record_index`` scaled by ``multiplier``, as the IDA ran it (on
    the floor motion at Z for a wall above the ground floor)."""
    model = inputs.case_models()[case_index]
    rec = floor_record(records[record_index], inputs.building)
    res = simulate(model, rec, float(multiplier), history=True)
    return TimeHistory(model, rec, float(multiplier), res)


@dataclass(frozen=True)
class HistoryData:
    """θ/α(t) and bar strain(t) of one case under one record at one multiplier."""

    case: str
    record: str
    multiplier: float
    time: np.ndarray  #: [s]
    theta_over_alpha: np.ndarray  #: [-]
    strain: np.ndarray  #: acting bar [-]
    collapsed: bool
    collapse_time: float | None  #: [s]
    peak_ratio: float  #: max |θ|/α [-]
    impacts: int
    ruptures: tuple[float, ...]  #: times of bar ruptures [s]
    rupture_strain: float | None  #: ε_max = c·ε_u, None when unreinforced
    reinforced: bool


def case_history(
    outcome: RunOutcome, case_index: int, record_index: int, multiplier: float
) -> HistoryData:
    """The time history of case ``case_index`` (0 = unreinforced) under record
    ``record_index`` of the run, scaled by ``multiplier`` (as the IDA does)."""
    run = time_history(
        outcome.inputs, outcome.seismic.records, case_index, record_index, multiplier
    )
    model, rec, res = run.model, run.record, run.result
    h = res.history
    assert h is not None
    n = h.computed
    bars = model.rebars
    return HistoryData(
        case=outcome.results.cases[case_index].name,
        record=rec.name,
        multiplier=float(multiplier),
        time=h.time[:n],
        theta_over_alpha=h.theta[:n] / model.alpha,  # α_x, as peak_ratio (docs/model.md §1.1)
        strain=h.strain[:n],
        collapsed=res.collapsed,
        collapse_time=res.collapse_time,
        peak_ratio=res.max_rotation_ratio,
        impacts=res.impacts,
        ruptures=tuple(r.time for r in res.ruptures),
        rupture_strain=None if bars is None else bars.rupture_strain,
        reinforced=bars is not None,
    )
