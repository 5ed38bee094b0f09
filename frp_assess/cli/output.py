"""What every CLI printer uses: a console, user text made safe, tables that never cut numbers.

- :func:`make_console`: a rich console without emoji codes (``:smile:`` in a name prints
  literally) and without automatic highlighting;
- :func:`user`: any user string (option, material, record or project name, currency, path)
  before it reaches rich: control characters replaced, markup escaped
  (:func:`frp_assess.text_safety.console`); :func:`plain_line` for ``print``;
- :func:`print_table`: a table whose numbers are never truncated: in a console too narrow for
  it (a narrow terminal, or a log, which rich treats as 80 columns) the rows are printed as
  stacked records, one "header: value" line each;
- :func:`setup_streams`: stdout and stderr print what their encoding can hold (a Windows
  redirect's cp1252, ``PYTHONIOENCODING=ascii``, latin-1): a character it cannot encode is
  written as its ASCII spelling (``≥`` as ``>=``, ``θ`` as ``theta``, ``‰`` as ``per mille``),
  never an exception.
"""

from __future__ import annotations

import codecs
import sys
import unicodedata
from collections.abc import Sequence
from dataclasses import dataclass
from typing import IO, Any

from rich import box
from rich.console import Console
from rich.table import Table
from rich.text import Text

from frp_assess.text_safety import console as _console_text
from frp_assess.text_safety import plain

#: the error handler of the standard streams (:func:`setup_streams`)
STREAM_ERRORS = "frp-assess-ascii"
#: ASCII spellings of the characters the outputs use that NFKD does not reduce to ASCII
_ASCII: dict[str, str] = {
    "≥": ">=", "≤": "<=", "≈": "~", "‰": " per mille", "×": "x", "·": "*", "°": " deg",
    "±": "+/-", "∓": "-/+", "−": "-", "–": "-", "—": "-", "…": "...", "→": "->", "←": "<-",
    "↑": "^", "↓": "v", "√": "sqrt", "∞": "inf", "∂": "d", "∈": " in ", "∫": "int",
    "µ": "u", "§": "par. ", "Ø": "dia ", "ø": "o", "†": "+", "✓": "ok", "✗": "x",
    "‘": "'", "’": "'", "“": '"', "”": '"', "─": "-", "━": "-", "│": "|", "┄": "-",
    "└": "+", "┤": "+", "■": "#", "▲": "^", "▼": "v", "▶": ">", "●": "*", "○": "o",
}  # fmt: skip


def ascii_spelling(char: str) -> str:
    """``char`` in ASCII: its spelling in :data:`_ASCII`, a Greek letter's name (``theta``),
    the ASCII of its compatibility decomposition (``²`` as ``2``, ``à`` as ``a``), else
    ``?``."""
    if char in _ASCII:
        return _ASCII[char]
    name = unicodedata.name(char, "")
    for prefix, case in (("GREEK SMALL LETTER ", str.lower), ("GREEK CAPITAL LETTER ", str.title)):
        if name.startswith(prefix) and " " not in name[len(prefix) :]:
            return case(name[len(prefix) :])
    plain_ascii = unicodedata.normalize("NFKD", char).encode("ascii", "ignore").decode("ascii")
    return plain_ascii or "?"


def _encode_fallback(exc: UnicodeError) -> tuple[str, int]:
    if not isinstance(exc, UnicodeEncodeError):
        raise exc
    return "".join(ascii_spelling(c) for c in exc.object[exc.start : exc.end]), exc.end


codecs.register_error(STREAM_ERRORS, _encode_fallback)


def setup_streams() -> None:
    """Make stdout and stderr write what their encoding cannot hold in ASCII
    (:func:`ascii_spelling`) instead of raising UnicodeEncodeError: the one setup of every
    command's output (:func:`frp_assess.cli.main`)."""
    for stream in (sys.stdout, sys.stderr):
        reconfigure = getattr(stream, "reconfigure", None)
        if reconfigure is None:
            continue
        try:
            reconfigure(errors=STREAM_ERRORS)
        except (OSError, ValueError):  # a closed or detached stream: nothing to set
            pass


class _Console(Console):
    """A rich console that lets a closed pipe reach :func:`frp_assess.cli.main` (rich itself
    exits with status 1) and, on a stream that is not UTF-8, lays out the text it can write
    (:func:`ascii_spelling` before the layout, so that the columns of a table still line up)."""

    def render_str(self, text: str, *args: Any, **kwargs: Any) -> Text:
        encoding = self.encoding
        if not encoding.startswith("utf"):
            try:
                text = text.encode(encoding, STREAM_ERRORS).decode(encoding)
            except LookupError:  # an encoding Python does not know: as it is
                pass
        return super().render_str(text, *args, **kwargs)

    def on_broken_pipe(self) -> None:
        raise BrokenPipeError


def make_console(file: IO[str] | None = None, width: int | None = None) -> Console:
    """The console of the CLI printers (stdout unless ``file``)."""
    return _Console(file=file, width=width, emoji=False, highlight=False)


def user(text: object) -> str:
    """User text for rich output: no control characters, rich markup shown literally."""
    return _console_text(text)


def plain_line(text: object) -> str:
    """User text for ``print``: no control characters (no escape sequence, no line break)."""
    return plain(text)


@dataclass(frozen=True)
class Column:
    """A table column: its header (with units, plain text) and whether it holds text."""

    header: str
    text: bool = False  #: left-aligned, may wrap (names); otherwise numbers, never cut
    #: a text column that may wrap between words (a word longer than the column is folded);
    #: False: its cells are never wrapped (short words: a verdict, a check's short name)
    fold: bool = True


#: width the table layout adds per column (a space separator and one space of padding; no outer
#: rules) and per table [characters]
_PER_COLUMN = 2
_PER_TABLE = 0
#: a header word longer than this may be folded (numbers never are) [characters]
_HEADER_WORD = 12
#: narrowest a text column (names) may be made before the table is stacked [characters]
_MIN_TEXT = 12
#: a text column is at least as wide as its longest word up to this, so that words are wrapped
#: whole ("pseudo-stationary", not "pseudo-stationar / y") [characters]
_WHOLE_WORD = 20


def _longest_word(text: str) -> int:
    return max((len(w) for w in text.split()), default=0)


def _min_widths(columns: Sequence[Column], rows: Sequence[Sequence[str]]) -> list[int]:
    """Narrowest each column may be: numbers whole, header words up to _HEADER_WORD."""
    out = []
    for j, col in enumerate(columns):
        cells = [r[j] for r in rows]
        if col.text and col.fold:
            need = max(min(_MIN_TEXT, max((len(c) for c in cells), default=0)), 1)
            need = max(need, min(_WHOLE_WORD, max((_longest_word(c) for c in cells), default=0)))
        else:
            need = max((len(c) for c in cells), default=1)
        out.append(max(need, min(_longest_word(col.header), _HEADER_WORD)))
    return out


def table_min_width(columns: Sequence[Column], rows: Sequence[Sequence[str]]) -> int:
    """Narrowest the table can be printed without cutting a number [characters]."""
    return sum(_min_widths(columns, rows)) + _PER_COLUMN * len(columns) + _PER_TABLE


def column_widths(
    columns: Sequence[Column], rows: Sequence[Sequence[str]], width: int
) -> list[int]:
    """Widths of the columns in a table ``width`` wide: numbers get their minimum, the text
    columns share the rest in proportion to their longest cell (never below their minimum)."""
    mins = _min_widths(columns, rows)
    widths = list(mins)
    text = [j for j, c in enumerate(columns) if c.text and c.fold]
    natural = {
        j: max(max((len(r[j]) for r in rows), default=1), _longest_word(columns[j].header))
        for j in text
    }
    spare = width - table_min_width(columns, rows)
    want = {j: max(natural[j] - mins[j], 0) for j in text}
    total_want = sum(want.values())
    if total_want and spare > 0:
        for j in text:
            widths[j] += min(want[j], spare * want[j] // total_want)
        left = width - sum(widths) - _PER_COLUMN * len(columns) - _PER_TABLE
        for j in sorted(text, key=lambda j: natural[j] - widths[j]):  # nearly whole first
            extra = min(left, natural[j] - widths[j])
            if extra > 0:
                widths[j] += extra
                left -= extra
    return widths


def print_table(
    con: Console,
    title: str,
    columns: Sequence[Column],
    rows: Sequence[Sequence[str]],
) -> None:
    """Print ``rows`` (plain text, already formatted; user text not yet escaped) under
    ``columns``: as a table when it fits ``con.width``, else as stacked records."""
    if table_min_width(columns, rows) <= con.width:
        t = Table(title=user(title), box=box.SIMPLE_HEAD, padding=(0, 1, 0, 0), show_edge=False)
        widths = column_widths(columns, rows, con.width)
        for col, w in zip(columns, widths, strict=True):
            t.add_column(
                user(col.header),
                justify="left" if col.text else "right",
                overflow="fold",
                width=w,
            )
        for r in rows:
            t.add_row(*(user(c) for c in r))
        con.print(t)
        return
    con.print(user(title), soft_wrap=False)
    width = max(len(plain_line(c.header)) for c in columns)
    labels = [user(plain_line(c.header).ljust(width)) for c in columns]
    # one print for all the records (a print per line cost ~0.4 ms each): the same lines
    lines: list[str] = []
    for r in rows:
        lines.append("")
        lines.extend(f"  {label}  {user(cell)}" for label, cell in zip(labels, r, strict=True))
    if lines:
        con.print("\n".join(lines), overflow="fold")
