"""Sensitivity of a study's results to the model conventions the paper leaves open.

Runs the same study once per variant of :data:`VARIANTS` (restitution convention, collapse
criterion, rupture rule; docs/model.md §3), each in its own sub-directory of ``out_dir`` sharing
one IDA cache, and returns the improvement of every reinforced case per variant.
"""

from __future__ import annotations

import threading
from pathlib import Path

from frp_assess.study.rows import SummaryRow, read_summary
from frp_assess.study.run import StudyProgress, run_study
from frp_assess.study.schema import StudyFile

#: variant name -> model options changed from the study's own
VARIANTS: dict[str, dict[str, str]] = {
    "paper (energy, end-of-record, energy-transfer)": {},
    "restitution: velocity": {"restitution": "velocity"},
    "collapse: overturning": {"collapse": "overturning"},
    "collapse: first-exceedance": {"collapse": "first-exceedance"},
    "rupture: velocity-continuous": {"rupture": "velocity-continuous"},
}


def run_sensitivity(
    study: StudyFile,
    out_dir: Path,
    *,
    jobs: int | None = None,
    progress: StudyProgress | None = None,
    cancel: threading.Event | None = None,
) -> dict[str, dict[str, SummaryRow]]:
    """{variant: {case label: summary row}} for every variant of :data:`VARIANTS`."""
    out: dict[str, dict[str, SummaryRow]] = {}
    for i, (name, change) in enumerate(VARIANTS.items()):
        variant = study.model_copy(update={"model": study.model.model_copy(update=change)})
        sub = out_dir / f"variant-{i}"
        run_study(
            variant, sub, jobs=jobs, progress=progress, cancel=cancel, cache_dir=out_dir / ".cache"
        )
        out[name] = {r["label"]: r for r in read_summary(sub / "summary.csv")}
    return out
