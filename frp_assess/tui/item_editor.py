"""A table of items (options, materials, record files) with a form for the selected one.

The table shows every item and marks the invalid ones; the form below edits the selected
item in place.  Keys while the table has focus: ``a`` add, ``d`` duplicate, ``delete``/``x``
remove, ``enter`` edit (focus the form).  Subclasses say what an item is.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, ClassVar

from rich.text import Text
from textual import on
from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Horizontal, Vertical
from textual.coordinate import Coordinate
from textual.message import Message
from textual.widgets import Button, DataTable, Input, Select, Static

from frp_assess.config.messages import Loc, format_path
from frp_assess.tui.core.editor_state import Problem, get_path, set_path
from frp_assess.tui.fields import FieldRow, FieldSpec
from frp_assess.tui.literal import literal, safe


class ItemEditor(Vertical):
    """Base class: a DataTable of ``items``, buttons, and one form per item kind."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("a", "add", "Add"),
        Binding("d", "duplicate", "Dup"),
        Binding("delete,x", "remove", "Remove", key_display="del"),
    ]

    DEFAULT_CSS = """
    ItemEditor { height: auto; }
    ItemEditor > DataTable { height: auto; max-height: 12; }
    ItemEditor > .ie-buttons { height: 1; margin: 0 0 1 0; }
    ItemEditor > .ie-buttons Button { margin-right: 1; min-width: 8; }
    ItemEditor .ie-form { height: auto; border-top: solid $primary 40%; }
    ItemEditor .ie-title { color: $text-muted; }
    ItemEditor .ie-problem { color: $error; }
    """

    #: the data key of the items (``interventions``, ``materials``...), for messages
    ROOT: ClassVar[Loc] = ()
    #: (kind, [field specs with paths relative to the item])
    FORMS: ClassVar[dict[str, Sequence[FieldSpec]]] = {}
    #: (label, action) buttons
    BUTTONS: ClassVar[Sequence[tuple[str, str]]] = (
        ("+ add", "add"),
        ("duplicate", "duplicate"),
        ("remove", "remove"),
    )

    class Edited(Message):
        """The items changed (the app revalidates)."""

    def __init__(self, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.items: list[Any] = []
        self.problems: list[Problem] = []
        self.context: dict[str, Any] = {}
        self._filled: int | None = None
        self._form_rows: dict[str, list[FieldRow]] = {}
        self._shown: list[list[str]] = []
        self._problem_text = ""

    # ---------------------------------------------------------------- subclass interface
    def columns(self) -> list[str]:
        raise NotImplementedError

    def row_cells(self, index: int, item: Any) -> list[Any]:
        raise NotImplementedError

    def kind_of(self, item: Any) -> str:
        return next(iter(self.FORMS))

    def new_item(self, action: str) -> Any:
        raise NotImplementedError

    def item_path(self, index: int) -> Loc:
        """Key path of item ``index`` in the project data."""
        return (*self.ROOT, index)

    def item_label(self, index: int) -> str:
        return f"#{index + 1}"

    # ---------------------------------------------------------------------- composition
    def compose(self) -> ComposeResult:
        table: DataTable[Any] = DataTable(cursor_type="row", zebra_stripes=True)
        table.add_columns(*(Text(c) for c in self.columns()), Text(""))
        yield table
        with Horizontal(classes="ie-buttons"):
            for label, action in self.BUTTONS:
                yield Button(label, compact=True, name=action)
            yield Static("", classes="ie-problem")
        for kind, specs in self.FORMS.items():
            with Vertical(classes=f"ie-form ie-form-{kind}"):
                yield Static("", classes="ie-title")
                for spec in specs:
                    yield FieldRow(spec, id=f"{self.id}-{kind}-{spec.dom_id}")

    @property
    def table(self) -> DataTable[Any]:
        return self.query_one(DataTable)

    @property
    def selected(self) -> int | None:
        if not self.items:
            return None
        return min(max(self.table.cursor_row, 0), len(self.items) - 1)

    def form_rows(self, kind: str) -> list[FieldRow]:
        rows = self._form_rows.get(kind)
        if rows is None:
            rows = self._form_rows[kind] = list(self.query_one(f".ie-form-{kind}").query(FieldRow))
        return rows

    # ---------------------------------------------------------------------------- data
    def load(self, items: list[Any]) -> None:
        """Replace the items (a file was opened)."""
        self.items = items
        self.refresh_table()
        self.table.move_cursor(row=0)
        self.fill_form()

    def refresh_table(self) -> None:
        """Redraw the rows (values, derived quantities, problem marks)."""
        table = self.table
        bad = {p.path[len(self.ROOT)] for p in self.problems if len(p.path) > len(self.ROOT)}
        rows: list[list[Text]] = []
        for i, item in enumerate(self.items):
            cells = [
                safe(c) if isinstance(c, Text) else literal(c) for c in self.row_cells(i, item)
            ]
            cells.append(Text("✗", style="bold red") if self._key_of(i) in bad else Text(""))
            rows.append(cells)
        keys = [[t.markup for t in r] for r in rows]
        if keys == self._shown and table.row_count == len(rows):
            return  # nothing changed: no redraw (this runs on every key typed)
        if len(keys) == len(self._shown) == table.row_count:
            for i, (new, old) in enumerate(zip(keys, self._shown, strict=True)):
                for j, (a, b) in enumerate(zip(new, old, strict=True)):
                    if a != b:
                        table.update_cell_at(Coordinate(i, j), rows[i][j], update_width=True)
        else:
            row = table.cursor_row
            table.clear()
            for cells in rows:
                table.add_row(*cells)
            if self.items:
                table.move_cursor(row=min(max(row, 0), len(self.items) - 1), animate=False)
        self._shown = keys

    def _key_of(self, index: int) -> Any:
        return self.item_path(index)[len(self.ROOT)]

    def fill_form(self) -> None:
        """Show the selected item in its form (the other forms are hidden)."""
        i = self.selected
        self._filled = i
        kind = self.kind_of(self.items[i]) if i is not None else None
        for k in self.FORMS:
            form = self.query_one(f".ie-form-{k}")
            form.display = k == kind
        if i is None or kind is None:
            return
        with self.app.prevent(Input.Changed, Select.Changed):
            for row in self.form_rows(kind):
                row.set_value(self.item_value(i, row.spec.path))
            self.form_filled(i)
        self.show_form_problems()

    def item_value(self, index: int, path: Loc) -> Any:
        """The value of a form field of item ``index`` (``MISSING`` if absent)."""
        return get_path(self.items[index], path)

    def form_filled(self, index: int) -> None:
        """Hook after the form shows item ``index``."""

    def show_problems(self, problems: list[Problem]) -> None:
        """Mark the items with problems and show those of the selected item in its form."""
        n = len(self.ROOT)
        self.problems = [p for p in problems if p.path[:n] == self.ROOT and len(p.path) > n]
        own = [p for p in problems if p.path[:n] == self.ROOT]
        text = ""
        if own:
            more = f" (+{len(own) - 1})" if len(own) > 1 else ""
            text = f"✗ {own[0].key}{more} (row marked ✗)" if self.problems else f"✗ {own[0]}"
        self.refresh_table()
        if text != self._problem_text:
            self._problem_text = text
            self.query_one(".ie-problem", Static).update(literal(text))
        self.show_form_problems()

    def show_form_problems(self) -> None:
        i = self.selected
        if i is None:
            return
        base = self.item_path(i)
        kind = self.kind_of(self.items[i])
        mine = [p for p in self.problems if p.target[: len(base)] == base]
        for row in self.form_rows(kind):
            full = (*base, *row.spec.path)
            msg = None
            for p in mine:
                if p.target[: len(full)] == full:
                    rest = p.target[len(full) :]
                    msg = f"{format_path(rest)}: {p.message}" if rest else p.message
                    break
            row.show_error(msg)
        title = self.query_one(f".ie-form-{kind} .ie-title", Static)
        general = [p for p in mine if p.target == base]
        text = f"Selected: {self.item_label(i)}"
        title.update(
            literal(text) + (literal(f"  ✗ {general[0].message}", "red") if general else Text(""))
        )

    # ------------------------------------------------------------------------- events
    @on(DataTable.RowHighlighted)
    def _row_changed(self, event: DataTable.RowHighlighted) -> None:
        event.stop()
        if event.cursor_row != self._filled:  # not a redraw of the same selection
            self.fill_form()

    @on(DataTable.RowSelected)
    def _row_selected(self, event: DataTable.RowSelected) -> None:
        event.stop()
        self.action_edit()

    @on(Input.Changed)
    @on(Select.Changed)
    def _form_changed(self, event: Input.Changed | Select.Changed) -> None:
        row = next((a for a in event.control.ancestors if isinstance(a, FieldRow)), None)
        i = self.selected
        if row is None or i is None:
            return
        self.apply_field(i, row.spec.path, row.data_value())
        self.refresh_table()

    def apply_field(self, index: int, path: Loc, value: Any) -> None:
        """Store a form value into item ``index``."""
        set_path(self.items[index], path, value)

    @on(Button.Pressed)
    def _button(self, event: Button.Pressed) -> None:
        event.stop()
        if event.button.name:
            getattr(self, f"action_{event.button.name}")()

    def changed(self) -> None:
        """After a structural change: redraw, refill and tell the app."""
        self.refresh_table()
        self.fill_form()
        self.post_message(self.Edited())

    def action_add(self) -> None:
        self.items.append(self.new_item("add"))
        self.refresh_table()
        self.table.move_cursor(row=len(self.items) - 1)
        self.changed()

    def action_duplicate(self) -> None:
        import copy

        i = self.selected
        if i is None:
            return
        self.items.insert(i + 1, copy.deepcopy(self.items[i]))
        self.refresh_table()
        self.table.move_cursor(row=i + 1)
        self.changed()

    def action_remove(self) -> None:
        i = self.selected
        if i is None:
            return
        del self.items[i]
        self.refresh_table()
        self.changed()

    def action_edit(self) -> None:
        i = self.selected
        if i is None:
            return
        rows = self.form_rows(self.kind_of(self.items[i]))
        if rows:
            rows[0].control.focus()
