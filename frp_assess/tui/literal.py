"""Text for the widgets that never reads user strings as markup or control sequences."""

from __future__ import annotations

from rich.style import StyleType
from rich.text import Text

from frp_assess.tui.core.text import printable


def literal(value: object, style: StyleType = "", *, newlines: bool = False) -> Text:
    """``value`` as plain text (no markup), control characters made visible."""
    return Text(printable(str(value), newlines=newlines), style=style)


def safe(content: str | Text, *, newlines: bool = True) -> Text:
    """A Text (or a str, taken as plain text, never markup) with its control characters
    made visible; styles are kept (the replacement keeps every character's position)."""
    if isinstance(content, str):
        return literal(content, newlines=newlines)
    out = content.copy()
    out.plain = printable(content.plain, newlines=newlines)
    return out
