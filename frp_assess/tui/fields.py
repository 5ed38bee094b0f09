"""One labelled field of the editor: label, input (or choice), unit, and its error below.

A :class:`FieldRow` is bound to a key path of the project data (``("wall", "thickness")``);
the editor reads :meth:`FieldRow.data_value` from every active row to build the data the
loader validates, and shows each problem with :meth:`FieldRow.show_error`.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any, ClassVar, Literal, get_args, get_origin

from pydantic import BaseModel
from pydantic_core import PydanticUndefined
from rich.text import Text
from textual import events
from textual.widget import Widget
from textual.widgets import Input, Label, Select, Static

from frp_assess.config.messages import Loc
from frp_assess.tui.core.editor_state import MISSING, format_value, parse_list, parse_scalar
from frp_assess.tui.core.text import printable
from frp_assess.tui.literal import literal

Kind = Literal["scalar", "text", "choice", "list"]


class OrderedInput(Input):
    """An Input that edits with backspace, delete and the cursor keys in typing order.

    Textual runs these keys through bindings, which are checked only after the key has
    bubbled up to the app, while printable keys are inserted at once: keys that arrive
    together (a fast typist, a paste of keys, ``tmux send-keys``) then apply out of order
    (``BSpace 5`` gives ``0.3`` -> ``0.35`` -> ``0.3``).  Here they act immediately.
    """

    #: key -> Input action, applied as the key arrives
    EDIT_KEYS: ClassVar[dict[str, str]] = {
        "backspace": "delete_left",
        "delete": "delete_right",
        "left": "cursor_left",
        "right": "cursor_right",
        "home": "home",
        "end": "end",
        "ctrl+u": "delete_left_all",
        "ctrl+k": "delete_right_all",
        "ctrl+w": "delete_left_word",
    }

    #: ``?`` opens the help instead of typing (fields where ``?`` is never valid)
    help_key = False

    def on_key(self, event: events.Key) -> None:
        """Apply an editing key at once (before ``Input``'s own key handler, which still
        runs for these keys: it restarts the cursor blink and inserts only printable keys)."""
        if self.help_key and event.key == "question_mark":
            event.stop()
            event.prevent_default()  # not typed into the field
            self.app.action_help()  # type: ignore[attr-defined]
            return
        action = self.EDIT_KEYS.get(event.key)
        if action is not None:
            event.stop()  # never reaches the (later) bindings
            getattr(self, f"action_{action}")()


@dataclass(frozen=True)
class FieldSpec:
    """What a field edits and how.

    Attributes:
        path: key path in the project data.
        label: shown left of the input.
        kind: ``scalar`` (read as a YAML scalar: numbers, ``energy``...), ``text`` (kept as
            typed), ``choice`` (one of ``choices``), ``list`` (comma-separated values).
        unit: shown right of the input, e.g. ``m`` or ``kN/m³``.
        help: one line shown in the help bar while the field has focus (units, range).
        choices: (label, value) pairs of a choice.
        optional: an empty field leaves the key out (the default applies).
        width: of the input, in cells.
        variant: (group, value): the row is part of the data only while the editor's
            variant ``group`` is ``value`` (the spectrum type, the record source...).
        placeholder: shown in an empty input.
        default: shown by a choice when the data has no value (the schema's default).
        virtual: not a data key (a selector of the editor only).
        selects: the variant group this field's value chooses (``spectrum`` for the type).
    """

    path: Loc
    label: str
    kind: Kind = "scalar"
    unit: str = ""
    help: str = ""
    choices: tuple[tuple[str, Any], ...] = ()
    optional: bool = False
    width: int = 14
    variant: tuple[str, str] | None = None
    placeholder: str = ""
    default: Any = MISSING
    virtual: bool = False
    selects: str | None = None

    @property
    def dom_id(self) -> str:
        """A DOM id derived from the path: ``f-wall-thickness``."""
        tail = f"-{self.variant[1]}" if self.variant else ""
        return ("f-" + "-".join(str(p) for p in self.path) + tail).replace("_", "-")


# ---------------------------------------------------------------- fields from the schema
# Each field takes its help line, its default and (for a choice) its values from the pydantic
# model of the block it edits, by the last key of its path: the schema stays the one source.


def field_help(model: type[BaseModel], name: str) -> str:
    """The schema's description of a field (units, range): the help line of its input."""
    return str(model.model_fields[name].description or "")


def schema_default(model: type[BaseModel], name: str) -> Any:
    """The schema's default of a field (shown when the file leaves the key out)."""
    value = model.model_fields[name].get_default(call_default_factory=True)
    return MISSING if value is PydanticUndefined or value is None else value


def literal_values(model: type[BaseModel], name: str) -> tuple[Any, ...]:
    """The values a ``Literal[...]`` field accepts (``Optional`` allowed)."""
    annotation = model.model_fields[name].annotation
    for candidate in (annotation, *get_args(annotation)):
        if get_origin(candidate) is Literal:
            return get_args(candidate)
    raise TypeError(f"{model.__name__}.{name} is not a Literal field")


def num(path: Loc, label: str, unit: str, model: type[BaseModel], **kw: Any) -> FieldSpec:
    """A number (or YAML scalar) field; an optional one shows the schema's default after its
    unit, e.g. ``s (25)``."""
    kw.setdefault("default", schema_default(model, str(path[-1])))
    if kw.get("optional") and kw["default"] is not MISSING:
        unit = f"{unit} ({format_value(kw['default'])})".strip()
    return FieldSpec(path, label, "scalar", unit=unit, help=field_help(model, str(path[-1])), **kw)


def choice(
    path: Loc,
    label: str,
    values: Sequence[Any] | None,
    model: type[BaseModel],
    **kw: Any,
) -> FieldSpec:
    """A choice among ``values`` (plain values, or (label, value) pairs); None: the values of
    the schema's ``Literal``."""
    name = str(path[-1])
    if values is None:
        values = literal_values(model, name)
    pairs = tuple(v if isinstance(v, tuple) else (str(v), v) for v in values)
    kw.setdefault("help", field_help(model, name))
    kw.setdefault("default", schema_default(model, name))
    return FieldSpec(path, label, "choice", choices=pairs, **kw)


def text(path: Loc, label: str, model: type[BaseModel], **kw: Any) -> FieldSpec:
    """A free-text field (kept as typed)."""
    kw.setdefault("width", 44)
    kw.setdefault("default", schema_default(model, str(path[-1])))
    return FieldSpec(path, label, "text", help=field_help(model, str(path[-1])), **kw)


def items(path: Loc, label: str, model: type[BaseModel], **kw: Any) -> FieldSpec:
    """A list typed as comma-separated values (``GFRP, CFRP`` or ``1, 2, 3``)."""
    return FieldSpec(path, label, "list", help=field_help(model, str(path[-1])), **kw)


def choice_options(choices: Sequence[tuple[str, Any]]) -> list[tuple[Text, Any]]:
    """The options of a Select: labels as plain text (a name is never read as markup)."""
    return [(literal(label), value) for label, value in choices]


class FieldRow(Widget):
    """A label, an input or a select, a unit, and the validation message under them.

    Laid out as a grid of three cells (label, control, unit) over the message, which is
    mounted only when the field first has one.

    The widgets of a row are made when it is first shown (:meth:`realize`: its tab is shown,
    or its control is asked for): until then the row keeps what its control would hold (the
    text of an input, the value and options of a choice) and its message, and answers
    :meth:`data_value` from them exactly as the control would.  The editor holds about
    ninety rows over nine tabs, and every widget costs its styling and layout: an app that
    makes only the rows of the tab shown opens in about half the time.
    """

    DEFAULT_CSS = """
    FieldRow {
        layout: grid;
        grid-size: 3;
        grid-rows: 1 auto;
        height: auto;
    }
    FieldRow .f-label { width: 18; color: $text-muted; }
    FieldRow .f-unit { width: 1fr; color: $text-muted; padding-left: 1; }
    FieldRow .f-error { color: $error; padding-left: 18; display: none; column-span: 3; }
    FieldRow.-error .f-error { display: block; }
    FieldRow.-error .f-label { color: $error; }
    """

    def __init__(self, spec: FieldSpec, *, id: str | None = None) -> None:
        super().__init__(id=id or spec.dom_id)
        self.spec = spec
        self.error: str | None = None
        #: (text shown, text read) of a value whose control characters are shown visibly
        self.shown_text: tuple[str, str] | None = None
        self.styles.grid_columns = f"18 {spec.width} 1fr"
        self.realized = False  #: the widgets are made (:meth:`realize`)
        self.live = False  #: the control is mounted: it holds the value from then on
        # what the control holds until it is live (a Select without a value shows its first
        # option unless it may be blank)
        self.text = ""
        self.placeholder = spec.placeholder
        self.options = choice_options(spec.choices)
        first = spec.choices[0][1] if spec.choices and not spec.optional else Select.NULL
        self.choice: Any = first

    def realize(self) -> None:
        """Make the widgets of the row (once) with the value and message kept so far.

        No change event is posted: the value shown is the one the row already had.  The
        control is live once mounted; what is set meanwhile is kept and then applied.
        """
        if self.realized:
            return
        self.realized = True
        # made and mounted with no change event (the widgets' own, at creation and mount)
        with self.app.prevent(Input.Changed, Select.Changed):
            self.mount(*self.make_widgets())
        self.call_next(self.go_live, self.options)  # after the mount (queued before it)

    def make_widgets(self) -> list[Widget]:
        """The label, the control holding the value kept, the unit, and the message if any."""
        s = self.spec
        control: Widget
        if s.kind == "choice":
            control = Select(
                self.options,
                allow_blank=s.optional,
                value=self.choice,
                compact=True,
                prompt="(none)",
                id=f"{s.dom_id}-control",
                tooltip=s.help or None,
            )
        else:
            inp = OrderedInput(
                self.text,
                compact=True,
                placeholder=self.placeholder,
                id=f"{s.dom_id}-control",
                tooltip=s.help or None,
                select_on_focus=False,
            )
            inp.help_key = s.kind != "text"
            control = inp
        control.styles.width = s.width
        widgets: list[Widget] = [
            Label(s.label, classes="f-label"),
            control,
            Label(s.unit, classes="f-unit"),
        ]
        if self.error is not None:
            widgets.append(Static(literal(f"✗ {self.error}"), classes="f-error"))
        return widgets

    def go_live(self, built_options: list[tuple[Text, Any]]) -> None:
        """The control is mounted: apply what was set since it was made (its options were
        ``built_options``)."""
        made = self.query(f"#{self.spec.dom_id}-control")
        if not made:
            return  # removed, or the app closing: the row keeps its value itself
        self.live = True
        c = made.first()
        with self.app.prevent(Input.Changed, Select.Changed):
            if isinstance(c, Select):
                if self.options is not built_options:
                    c.set_options(self.options)
                if c.value != self.choice:
                    self.set_choice(self.choice)
            elif isinstance(c, Input):
                if c.placeholder != self.placeholder:
                    c.placeholder = self.placeholder
                if c.value != self.text:
                    c.value = self.text

    @property
    def control(self) -> Input | Select[Any]:
        """The input or select of the row (made now if it is not yet)."""
        self.realize()
        return self.query_one(f"#{self.spec.dom_id}-control")  # type: ignore[return-value]

    def data_value(self) -> Any:
        """The value for the data: parsed as the YAML loader would, ``MISSING`` if empty."""
        if self.spec.kind == "choice":
            value = self.control.value if self.live else self.choice
            return MISSING if value is Select.NULL else value
        text = str(self.control.value) if self.live else self.text
        if self.shown_text is not None and text == self.shown_text[0]:
            text = self.shown_text[1]  # unchanged: the value as read, with its control characters
        if self.spec.kind == "text":
            return MISSING if self.spec.optional and not text.strip() else text
        if self.spec.kind == "list":
            return parse_list(text)
        return parse_scalar(text)

    def set_value(self, value: Any) -> None:
        """Show a data value (``MISSING``/None: empty)."""
        if value is MISSING or value is None:
            value = self.spec.default
        if self.spec.kind == "choice":
            if value is MISSING or value is None:
                if self.spec.optional:
                    self.set_choice(Select.NULL)
                return
            if value not in [v for _, v in self.spec.choices]:
                # keep what the file says, so that its error shows
                unknown = (literal(f"{value} (?)"), value)
                self.set_choice_options([*choice_options(self.spec.choices), unknown])
            self.set_choice(value)
        else:
            text = format_value(value)
            shown = printable(text)
            self.shown_text = (shown, text) if shown != text else None
            if self.live:
                self.control.value = shown
            else:
                self.text = shown

    def set_choice(self, value: Any) -> None:
        """Choose ``value`` (one of the options, or ``Select.NULL``)."""
        if not self.live:
            self.choice = value
        elif value is Select.NULL:
            self.control.clear()  # type: ignore[union-attr]
        else:
            self.control.value = value

    def set_choice_options(self, options: list[tuple[Text, Any]]) -> None:
        """Replace the options of the choice (as ``Select.set_options``: blank if it may be,
        else the first option)."""
        if self.live:
            self.control.set_options(options)  # type: ignore[union-attr]
        else:
            self.options = options
            self.choice = options[0][1] if options and not self.spec.optional else Select.NULL

    def set_placeholder(self, text: str) -> None:
        """What an empty input shows."""
        self.placeholder = text
        if self.live and isinstance(c := self.control, Input):
            c.placeholder = text

    def set_choices(self, choices: Sequence[tuple[str, Any]]) -> None:
        """Replace the options of a choice, keeping the value (no change event is posted)."""
        if self.spec.kind != "choice" or tuple(choices) == self.spec.choices:
            return
        current = self.control.value if self.live else self.choice
        self.spec = replace(self.spec, choices=tuple(choices))
        values = [v for _, v in choices]
        with self.app.prevent(Select.Changed):
            if current is not Select.NULL and current not in values:
                self.set_choice_options(
                    [*choice_options(choices), (literal(f"{current} (?)"), current)]
                )
            else:
                self.set_choice_options(choice_options(choices))
            if current is not Select.NULL:
                self.set_choice(current)

    def show_error(self, message: str | None) -> None:
        """Show (or clear) the validation message under the field."""
        if message == self.error:
            return
        self.error = message
        self.set_class(message is not None, "-error")
        if not self.realized:
            return  # shown when the row is made
        text = "" if message is None else literal(f"✗ {message}")
        lines = self.query(".f-error")
        if lines:
            lines.first(Static).update(text)
        elif message is not None:
            self.mount(Static(text, classes="f-error"))  # the first message of the field


def section_error(section_id: str) -> Static:
    """Where a problem of a section that is not one field's is shown (hidden when none)."""
    return Static("", id=section_id, classes="section-error")
