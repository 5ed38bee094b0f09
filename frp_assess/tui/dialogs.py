"""Small modal dialogs: a path prompt (save as, export), a name prompt (a building's walls)
and the quit confirmation."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import ClassVar, Generic, TypeVar

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
#: what a prompt gives
T = TypeVar("T")


class Prompt(ModalScreen[T | None], Generic[T]):
    """Ask for one line of text; ``enter`` accepts, ``esc`` cancels.

    :meth:`read` turns the text into the answer or a message, which shows under the field
    while the dialog stays.
    """

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape", "cancel", "Cancel")]

    def __init__(self, title: str, value: str, hint: str) -> None:
        super().__init__()
        self.title_text, self.value, self.hint = title, value, hint

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

    def read(self, text: str) -> tuple[T | None, str | None]:  # pragma: no cover - abstract
        """The answer of the text typed (stripped), or None and the message of a problem."""
        raise NotImplementedError

    @on(Input.Submitted)
    @on(Button.Pressed, "#ok")
    def _accept(self) -> None:
        answer, error = self.read(self.query_one("#path-input", Input).value.strip())
        if error or answer is None:
            self.query_one("#path-error", Static).update(literal(f"✗ {error}", "red"))
            return
        self.dismiss(answer)

    @on(Input.Changed)
    def _typed(self, event: Input.Changed) -> None:
        event.stop()
        self.query_one("#path-error", Static).update("")

    @on(Button.Pressed, "#cancel")
    def action_cancel(self) -> None:
        self.dismiss(None)


class PathPrompt(Prompt[Path]):
    """Ask for a file or directory path; the check runs on ``enter``."""

    def __init__(self, title: str, value: str, hint: str, check: PathCheck | None = None):
        super().__init__(title, value, hint)
        self.check = check

    def read(self, text: str) -> tuple[Path | None, str | None]:
        if not text:
            return None, "expected a path, found nothing"
        path = Path(text).expanduser()
        error = self.check(path) if self.check is not None else None
        return (None, error) if error else (path, None)


class NamePrompt(Prompt[str]):
    """Ask for a name; ``check`` gives the problem of a name ("" when it can be used)."""

    def __init__(self, title: str, value: str, hint: str, check: Callable[[str], str]):
        super().__init__(title, value, hint)
        self.check = check

    def read(self, text: str) -> tuple[str | None, str | None]:
        error = self.check(text)
        return (None, error) if error else (text, None)


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
