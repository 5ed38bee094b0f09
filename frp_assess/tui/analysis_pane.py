"""The Analysis tab: model options, IDA settings, code check, costs and design mode."""

from __future__ import annotations

from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.widgets import Static

from frp_assess.tui.field_specs import (
    ANALYSIS_FIELDS,
    CODE_FIELDS,
    COST_FIELDS,
    DESIGN_FIELDS,
    DESIGN_MODE,
)
from frp_assess.tui.fields import FieldRow, section_error


class AnalysisPane(VerticalScroll):
    """Model options, IDA settings, code check, costs and design mode."""

    def compose(self) -> ComposeResult:
        yield section_error("err-analysis")
        with Horizontal(classes="columns"):
            with Vertical(classes="col-half"):
                yield Static("Model and IDA", classes="section-title")
                for spec in ANALYSIS_FIELDS:
                    yield FieldRow(spec)
            with Vertical(classes="col-half"):
                yield Static("Code kinematic check (§C8.7.1)", classes="section-title")
                for spec in CODE_FIELDS:
                    yield FieldRow(spec)
                yield Static("Costs (indicative)", classes="section-title")
                for spec in COST_FIELDS:
                    yield FieldRow(spec)
                yield Static("Design mode", classes="section-title")
                yield FieldRow(DESIGN_MODE)
                with Vertical(classes="variant", id="var-design-on"):
                    for spec in DESIGN_FIELDS:
                        yield FieldRow(spec)
