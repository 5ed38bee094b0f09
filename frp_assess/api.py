"""The former application API, kept so that existing imports keep working.

The application service is :mod:`frp_assess.app` (docs/architecture.md); this module only
re-exports its names (``run_study`` answers its old pair).  New code imports
``frp_assess.app.<module>``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from frp_assess.app import study as _study
from frp_assess.app.assessment import (
    CACHE_DIR,
    SOURCE_DATE_EPOCH,
    PairDone,
    Progress,
    RunStats,
    default_out_dir,
    governing_histories,
    missing_idas,
    prepare_records,
    run_assessment,
    run_date,
)
from frp_assess.app.expert import IdaOutcome, run_ida, simulate
from frp_assess.app.history import TimeHistory, time_history
from frp_assess.app.project import (
    TEMPLATE_NAME,
    new_project_text,
    project_name_from_path,
    template_text,
)
from frp_assess.app.report import build_pdf, write_outputs
from frp_assess.app.study import StudyStats


def run_study(*args: Any, **kwargs: Any) -> tuple[StudyStats, list[Path]]:
    """:func:`frp_assess.app.study.run_study`, answered as before: (counts, figure files)."""
    outcome = _study.run_study(*args, **kwargs)
    return outcome.stats, list(outcome.figures)


__all__ = [
    "CACHE_DIR",
    "SOURCE_DATE_EPOCH",
    "TEMPLATE_NAME",
    "IdaOutcome",
    "PairDone",
    "Progress",
    "RunStats",
    "TimeHistory",
    "build_pdf",
    "default_out_dir",
    "governing_histories",
    "missing_idas",
    "new_project_text",
    "prepare_records",
    "project_name_from_path",
    "run_assessment",
    "run_date",
    "run_ida",
    "run_study",
    "simulate",
    "template_text",
    "time_history",
    "write_outputs",
]
