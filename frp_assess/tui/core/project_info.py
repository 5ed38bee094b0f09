"""Figures about the project being edited, shown next to the fields (no Textual here)."""

from __future__ import annotations

from frp_assess.app.preview import OptionRow, design_value_rule, option_rows
from frp_assess.config.schema import Project

__all__ = ["OptionRow", "option_rows", "record_count", "records_summary", "retrofits_summary"]


def record_count(project: Project) -> int:
    """How many records the run uses (artificial ones or files)."""
    recs = project.seismic.records
    return recs.artificial.count if recs.artificial is not None else len(recs.files or [])


def retrofits_summary(project: Project | None) -> str:
    """The line above the retrofit table: options, cases and IDAs of a run."""
    if project is None:
        return "Retrofit options (FRP mass per metre of wall, both faces if external)"
    n_rec = record_count(project)
    n = len(project.expand_interventions())
    return (
        f"Retrofit options: {n} after expanding sweeps (repeats dropped); with the "
        f"unreinforced wall {n + 1} cases × {n_rec} records = {(n + 1) * n_rec} IDAs"
    )


def records_summary(project: Project) -> tuple[str, str]:
    """What the records are (one sentence) and the design-value rule for their number."""
    recs = project.seismic.records
    n = record_count(project)
    if recs.artificial is not None:
        a = recs.artificial
        text = (
            f"{a.count} artificial records of {a.duration:g} s at dt = {a.dt:g} s "
            f"({int(round(a.duration / a.dt)) + 1} samples), compatible with the site "
            f"spectrum; seed {a.seed}."
        )
    else:
        text = f"{n} record files, " + (
            "scaled together to a_g·S of the spectrum."
            if recs.scale_to_spectrum
            else "used as recorded."
        )
    return text, design_value_rule(n)
