"""Recorded accelerogram files (``seismic.records.files``): a table and a form.

Paths are relative to the project file, as in YAML; a file that does not exist is reported
next to its path with the loader's message.
"""

from __future__ import annotations

from typing import Any, ClassVar

from frp_assess.config.schema import RECORD_FORMATS, RecordFile
from frp_assess.tui.fields import FieldSpec, field_help
from frp_assess.tui.item_editor import ItemEditor
from frp_assess.tui.model import format_value

UNITS = ("g", "m/s2", "cm/s2", "gal", "m/s^2", "cm/s^2")


class RecordFilesEditor(ItemEditor):
    """The ``files`` list of the records."""

    ROOT = ("seismic", "records", "files")
    BUTTONS = (("+ add", "add"), ("duplicate", "duplicate"), ("remove", "remove"))
    FORMS: ClassVar[dict[str, Any]] = {
        "file": (
            FieldSpec(("path",), "Path", "text", width=44, help=field_help(RecordFile, "path")),
            FieldSpec(
                ("format",),
                "Format",
                "choice",
                choices=tuple((f, f) for f in RECORD_FORMATS),
                width=16,
                default="auto",
                help=field_help(RecordFile, "format"),
            ),
            FieldSpec(
                ("units",),
                "Units",
                "choice",
                choices=tuple((u, u) for u in UNITS),
                width=12,
                default="g",
                help=field_help(RecordFile, "units"),
            ),
            FieldSpec(
                ("dt",),
                "dt",
                unit="s (one-column files)",
                optional=True,
                help=field_help(RecordFile, "dt"),
            ),
            FieldSpec(
                ("name",),
                "Name",
                "text",
                optional=True,
                width=24,
                placeholder="(file name)",
                help=field_help(RecordFile, "name"),
            ),
        )
    }

    def columns(self) -> list[str]:
        return ["#", "path", "format", "units", "dt [s]", "name"]

    def new_item(self, action: str) -> Any:
        return {"path": "records/record.AT2", "format": "auto", "units": "g"}

    def row_cells(self, index: int, item: Any) -> list[Any]:
        get = item.get if isinstance(item, dict) else (lambda _k, _d=None: None)
        return [
            index + 1,
            format_value(get("path"))[:40],
            format_value(get("format", "auto")),
            format_value(get("units", "g")),
            format_value(get("dt")),
            format_value(get("name")),
        ]
