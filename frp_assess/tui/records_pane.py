"""The Records tab: the accelerograms, artificial ones or record files."""

from __future__ import annotations

from typing import Any

from rich.text import Text
from textual.app import ComposeResult
from textual.containers import Vertical, VerticalScroll
from textual.widgets import Static

from frp_assess.config.schema import Project
from frp_assess.tui.core.project_info import records_summary
from frp_assess.tui.field_specs import ARTIFICIAL_FIELDS, RECORD_SOURCE, SCALE_FIELD
from frp_assess.tui.fields import FieldRow, section_error
from frp_assess.tui.literal import literal
from frp_assess.tui.record_files import RecordFilesEditor


class RecordsPane(VerticalScroll):
    """The accelerograms: artificial ones or record files."""

    def compose(self) -> ComposeResult:
        yield Static("Ground-motion records", classes="section-title")
        yield section_error("err-records")
        yield FieldRow(RECORD_SOURCE)
        with Vertical(classes="variant", id="var-records-artificial"):
            for spec in ARTIFICIAL_FIELDS:
                yield FieldRow(spec)
        with Vertical(classes="variant", id="var-records-files"):
            yield RecordFilesEditor(id="files-editor")
        yield FieldRow(SCALE_FIELD)
        yield Static("", id="records-info", classes="derived")

    def on_mount(self) -> None:
        self.shown: Any = None

    def show_summary(self, project: Project | None) -> None:
        """What the records are and the design-value rule (nothing while invalid)."""
        key = None if project is None else records_summary(project)
        if key == self.shown:
            return
        self.shown = key
        info = self.query_one("#records-info", Static)
        if key is None:
            info.update("")
            return
        text, rule = key
        info.update(Text.assemble(literal(text), ("\nDesign value of a_dyn: ", "dim"), rule))
