"""Small modal dialogs: a path prompt (save as, export) and the quit confirmation."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import ClassVar

from textual import on
from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Horizontal, Vertical
from textual.screen import ModalScreen
from textual.widgets import Button, Input, Label, Static

from frp_assess.tui.fields import OrderedInput
from frp_assess.tui.literal import literal

#: checks a typed path: an error message, or None if it can be used
PathCheck = Callable[[Path], str | None]


class PathPrompt(ModalScreen[Path | None]):
    """Ask for a file or directory path; ``enter`` accepts, ``esc`` cancels.

    The check runs on ``enter``; its message shows under the field and the dialog stays.
    """

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape", "cancel", "Cancel")]

    def __init__(self, title: str, value: str, hint: str, check: PathCheck | None = None):
        super().__init__()
        self.title_text, self.value, self.hint, self.check = title, value, hint, check

    def compose(self) -> ComposeResult:
        with Vertical(classes="dialog"):
            yield Label(self.title_text, classes="dialog-title")
            yield OrderedInput(self.value, id="path-input")
            yield Static(self.hint, classes="hint")
            yield Static("", id="path-error", classes="dialog-error")
            with Horizontal(classes="dialog-buttons"):
                yield Button("OK  enter", id="ok", variant="primary", compact=True)
                yield Button("Cancel  esc", id="cancel", compact=True)

    def on_mount(self) -> None:
        self.query_one("#path-input", Input).focus()

    @on(Input.Submitted)
    @on(Button.Pressed, "#ok")
    def _accept(self) -> None:
        text = self.query_one("#path-input", Input).value.strip()
        error = "expected a path, found nothing" if not text else None
        path = Path(text).expanduser()
        if error is None and self.check is not None:
            error = self.check(path)
        if error:
            self.query_one("#path-error", Static).update(literal(f"✗ {error}", "red"))
            return
        self.dismiss(path)

    @on(Input.Changed)
    def _typed(self, event: Input.Changed) -> None:
        event.stop()
        self.query_one("#path-error", Static).update("")

    @on(Button.Pressed, "#cancel")
    def action_cancel(self) -> None:
        self.dismiss(None)


class ConfirmQuit(ModalScreen[str]):
    """Unsaved changes: ``s`` save and quit, ``d`` quit discarding them, ``esc`` stay."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("s", "choose('save')", "Save and quit"),
        Binding("d", "choose('discard')", "Discard and quit"),
        Binding("escape,c", "choose('cancel')", "Cancel"),
    ]

    def __init__(self, message: str) -> None:
        super().__init__()
        self.message = message

    def compose(self) -> ComposeResult:
        with Vertical(classes="dialog"):
            yield Label("Quit frp-assess?", classes="dialog-title")
            yield Static(self.message)
            with Horizontal(classes="dialog-buttons"):
                yield Button("Save and quit  s", id="save", variant="primary", compact=True)
                yield Button("Discard  d", id="discard", variant="error", compact=True)
                yield Button("Cancel  esc", id="cancel", compact=True)

    @on(Button.Pressed)
    def _pressed(self, event: Button.Pressed) -> None:
        self.dismiss(str(event.button.id))

    def action_choose(self, choice: str) -> None:
        self.dismiss(choice)
