"""User text made safe for each output it reaches: the terminal (rich) and the PDF (reportlab).

Every string that comes from a user (project name, location, engineer, notes, option,
material and record names, the currency, file names, error messages quoting them) passes
through one of these functions before it is printed or laid out:

- :func:`plain` (any output): C0 and C1 control characters and DEL (which includes ESC, so
  terminal escape sequences) become a visible placeholder, so nothing the user typed can move
  the cursor, recolour the terminal or break a one-line message over several lines;
- :func:`console` (rich): :func:`plain`, then rich markup (``[bold]``, ``[/x]``) escaped so
  it prints literally;
- :func:`pdf` (reportlab Paragraph markup): :func:`plain`, very long text capped and very
  long words broken, then XML-escaped (``<img …>``, ``<b>``, ``&`` print literally).

Text written by the code itself as markup is wrapped in :class:`Markup` and passes through
unchanged; everything else is treated as plain text.
"""

from __future__ import annotations

import re

#: shown in place of a control character (ESC, NUL, BEL, newline in a name, C1 controls, DEL)
PLACEHOLDER = "\N{REPLACEMENT CHARACTER}"

_CONTROL = re.compile("[\x00-\x1f\x7f-\x9f]")
_CONTROL_KEEP_NEWLINES = re.compile("[\x00-\x09\x0b-\x1f\x7f-\x9f]")

#: longest user string laid out in the PDF [characters]; the rest is cut with a note
PDF_MAX_CHARS = 600
#: longest unbroken word in the PDF [characters]; longer ones get break opportunities
PDF_MAX_WORD = 80
_LONG_WORD = re.compile(rf"\S{{{PDF_MAX_WORD + 1},}}")


def _xml_escape(text: str) -> str:
    """``&``, ``<`` and ``>`` as XML entities, in that order: what
    ``xml.sax.saxutils.escape`` does, without its import (it pulls in urllib.request,
    http.client, ssl and email, ~50 ms at the start of every command)."""
    return text.replace("&", "&amp;").replace(">", "&gt;").replace("<", "&lt;")


class Markup(str):
    """Markup written by the code (not by a user): :func:`pdf` leaves it unchanged."""

    __slots__ = ()


def plain(text: object, *, keep_newlines: bool = False) -> str:
    """``text`` as a string without control characters (each becomes :data:`PLACEHOLDER`).

    ``keep_newlines`` keeps ``\\n`` (multi-line notes); tabs, ESC, NUL, CR and the C1 range
    are always replaced.
    """
    pattern = _CONTROL_KEEP_NEWLINES if keep_newlines else _CONTROL
    return pattern.sub(PLACEHOLDER, str(text))


def console(text: object) -> str:
    """User text for a rich console or table cell: no control characters, markup literal.

    rich is imported here, when a console needs it, so that the core (assess, app, ...),
    which imports this module for :func:`plain`, loads no UI library
    (tests/test_layering.py)."""
    from rich.markup import escape

    return escape(plain(text))


def cap(text: str, limit: int = PDF_MAX_CHARS) -> str:
    """``text`` cut to ``limit`` characters, saying how much was left out."""
    if len(text) <= limit:
        return text
    return f"{text[:limit]}… ({len(text) - limit} more characters)"


def _break_word(match: re.Match[str]) -> str:
    word = match.group(0)
    return " ".join(word[i : i + PDF_MAX_WORD] for i in range(0, len(word), PDF_MAX_WORD))


def break_long_words(text: str) -> str:
    """Words longer than :data:`PDF_MAX_WORD` characters split into pieces of that length
    (separated by a space), so a layout engine never has to hunt for a break inside them."""
    return _LONG_WORD.sub(_break_word, text)


def pdf(text: object, *, limit: int = PDF_MAX_CHARS) -> str:
    """Plain text → reportlab Paragraph markup that shows it literally.

    :class:`Markup` (written by the code) is returned unchanged.
    """
    if isinstance(text, Markup):
        return str(text)
    return _xml_escape(break_long_words(cap(plain(text), limit)))


def pdf_plain(text: object, *, limit: int = PDF_MAX_CHARS) -> str:
    """User text for places that draw plain strings, not markup (canvas strings, chart
    labels, PDF metadata): no control characters, capped length."""
    return cap(plain(text), limit)
