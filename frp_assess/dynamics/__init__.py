"""The rocking wall and its incremental dynamic analysis: pure numerics.

No I/O, no pydantic, yaml or UI imports here (a test checks it).
"""

from __future__ import annotations

from frp_assess.dynamics.base_reaction import PIVOT_RULES, BaseReaction, PivotRule
from frp_assess.dynamics.batch import IdaTask, default_jobs, run_batch
from frp_assess.dynamics.ida import IdaPoint, IdaResult, IdaSettings, ida
from frp_assess.dynamics.rebars import POSITIONS, Position, Rebars
from frp_assess.dynamics.restitution import housner_two_sided, one_sided, velocity_ratio
from frp_assess.dynamics.rocking import (
    COLLAPSE_RULES,
    DEFAULT_TOLERANCE,
    FAILURE_MODES,
    RUPTURE_RULES,
    CollapseRule,
    FailureMode,
    Fate,
    History,
    ModelOptions,
    RockingModel,
    RockingResult,
    Rupture,
)
from frp_assess.dynamics.wall import MECHANISMS, Mechanism, Wall

__all__ = [
    "COLLAPSE_RULES",
    "DEFAULT_TOLERANCE",
    "FAILURE_MODES",
    "MECHANISMS",
    "PIVOT_RULES",
    "RUPTURE_RULES",
    "BaseReaction",
    "CollapseRule",
    "FailureMode",
    "Fate",
    "IdaPoint",
    "POSITIONS",
    "History",
    "IdaResult",
    "IdaSettings",
    "IdaTask",
    "Mechanism",
    "ModelOptions",
    "PivotRule",
    "Position",
    "Rebars",
    "RockingModel",
    "RockingResult",
    "Rupture",
    "Wall",
    "default_jobs",
    "housner_two_sided",
    "ida",
    "one_sided",
    "run_batch",
    "velocity_ratio",
]
