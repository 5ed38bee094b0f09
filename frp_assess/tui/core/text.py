"""User text made safe to show on a terminal.

Names, currencies and messages come from the project file and may hold anything a YAML
string can: Rich markup (``[bold]``, ``[/x]``) and terminal control characters
(``"\\e[2J"``).  The widgets show such text as plain text (never as markup), after
:func:`printable` has replaced every control character by a visible one.
"""

from __future__ import annotations

#: C0 controls -> their Unicode "control pictures" (ESC -> ␛), DEL -> ␡, C1 controls ->
#: U+FFFD; one character for one, so styles spanning the text stay in place
_PICTURES: dict[int, int] = {c: 0x2400 + c for c in range(0x20)}
_PICTURES[0x7F] = 0x2421
_PICTURES.update({c: 0xFFFD for c in range(0x80, 0xA0)})
_PICTURES_KEEP_NEWLINES = {c: p for c, p in _PICTURES.items() if c != 0x0A}


def printable(text: str, *, newlines: bool = False) -> str:
    """``text`` with every C0/C1 control character and DEL replaced by a visible
    character of its own (the same length); ``newlines``: keep line feeds."""
    return text.translate(_PICTURES_KEEP_NEWLINES if newlines else _PICTURES)


def has_controls(text: str) -> bool:
    """Whether ``text`` holds a character :func:`printable` would replace."""
    return printable(text, newlines=True) != text
