"""Parametric studies: the cross product of wall, retrofit, mechanism and spectrum axes
(the paper's Table 1 and larger), run chunked and resumable through the IDA cache."""

from __future__ import annotations

from frp_assess.study.plan import Case, StudyMaterial, StudyPlan
from frp_assess.study.rows import SummaryRow, read_summary
from frp_assess.study.run import (
    LocalExecutor,
    StudyStats,
    run_study,
    study_records,
)
from frp_assess.study.schema import StudyFile, load_study, parse_study

__all__ = [
    "Case",
    "LocalExecutor",
    "StudyFile",
    "StudyMaterial",
    "StudyPlan",
    "StudyStats",
    "SummaryRow",
    "load_study",
    "parse_study",
    "read_summary",
    "run_study",
    "study_records",
]
