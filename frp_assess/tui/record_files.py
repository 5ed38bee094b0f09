"""Recorded accelerogram files (``seismic.records.files``): a table and a form.

Paths are relative to the project file, as in YAML; a file that does not exist is reported
next to its path with the loader's message.
"""

from __future__ import annotations

from typing import Any, ClassVar

from frp_assess.config.schema import RecordFileSpec
from frp_assess.tui.core.editor_state import format_value
from frp_assess.tui.fields import choice, num, schema_default, text
from frp_assess.tui.item_editor import ItemEditor

#: the defaults of a record file's format and units (the schema's)
FORMAT, UNITS = schema_default(RecordFileSpec, "format"), schema_default(RecordFileSpec, "units")


class RecordFilesEditor(ItemEditor):
    """The ``files`` list of the records."""

    ROOT = ("seismic", "records", "files")
    BUTTONS = (("+ add", "add"), ("duplicate", "duplicate"), ("remove", "remove"))
    FORMS: ClassVar[dict[str, Any]] = {
        "file": (
            text(("path",), "Path", RecordFileSpec, width=44),
            choice(("format",), "Format", None, RecordFileSpec, width=16),
            choice(("units",), "Units", None, RecordFileSpec, width=12),
            num(("dt",), "dt", "s (one-column files)", RecordFileSpec, optional=True),
            text(
                ("name",),
                "Name",
                RecordFileSpec,
                optional=True,
                width=24,
                placeholder="(file name)",
            ),
        )
    }

    def columns(self) -> list[str]:
        return ["#", "path", "format", "units", "dt [s]", "name"]

    def new_item(self, action: str) -> Any:
        return {"path": "records/record.AT2", "format": FORMAT, "units": UNITS}

    def row_cells(self, index: int, item: Any) -> list[Any]:
        get = item.get if isinstance(item, dict) else (lambda _k, _d=None: None)
        return [
            index + 1,
            format_value(get("path"))[:40],
            format_value(get("format", FORMAT)),
            format_value(get("units", UNITS)),
            format_value(get("dt")),
            format_value(get("name")),
        ]
