"""A one-line footer of the key bindings, redrawn only when the keys shown change.

Textual's ``Footer`` rebuilds a widget per key on every focus change, which costs a visible
fraction of a second with the editor's many widgets; this footer is a single line of text
with the same content (the keys of the focused widget first, then the app's).
"""

from __future__ import annotations

from rich.text import Text
from textual.binding import Binding
from textual.screen import Screen
from textual.widgets import Static


class KeyBar(Static):
    """The active key bindings (``show=True``), as ``key description`` pairs."""

    DEFAULT_CSS = """
    KeyBar { height: 1; background: $panel; color: $text; }
    """

    def on_mount(self) -> None:
        self._last = ""
        self.screen.bindings_updated_signal.subscribe(self, self._bindings_changed)
        self.call_after_refresh(self.update_keys)

    def on_unmount(self) -> None:
        self.screen.bindings_updated_signal.unsubscribe(self)

    def _bindings_changed(self, screen: Screen) -> None:
        if self.is_attached and screen is self.screen:
            self.call_after_refresh(self.update_keys)

    def keys(self) -> list[tuple[str, str]]:
        """(key as shown, description) of the bindings shown, one per action."""
        seen: set[str] = set()
        local: list[tuple[str, str]] = []
        app: list[tuple[int, str, str]] = []
        order: dict[str, int] = {}
        for i, b in enumerate(Binding.make_bindings(self.app.BINDINGS)):
            order.setdefault(b.action, i)
        for node, binding, enabled, _tooltip in self.screen.active_bindings.values():
            if not binding.show or not enabled or binding.action in seen:
                continue
            seen.add(binding.action)
            shown = (self.app.get_key_display(binding), binding.description)
            if node is self.app:
                app.append((order.get(binding.action, 99), *shown))
            else:
                local.append(shown)
        return local + [(k, d) for _, k, d in sorted(app)]

    def update_keys(self) -> None:
        """Redraw if the keys changed."""
        text = Text(no_wrap=True, overflow="ellipsis")
        for key, description in self.keys():
            text.append(f" {key} ", style="bold #ffa62b")
            text.append(f"{description} ")
        if text.plain != self._last:
            self._last = text.plain
            self.update(text)
