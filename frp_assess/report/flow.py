"""Small block builders shared by the report sections (:mod:`frp_assess.report.doc_model`).

Escaping is done here, at one place: every builder takes plain text and escapes it with
:func:`esc` (:func:`frp_assess.text_safety.pdf`); only :class:`~frp_assess.text_safety.Markup`
and :func:`markup` paragraphs, written by the code, carry markup.
"""

from __future__ import annotations

from collections.abc import Sequence

from reportlab.graphics.shapes import Drawing

from frp_assess.report import styles as st
from frp_assess.report.doc_model import (
    Block,
    Break,
    Figure,
    Gap,
    Heading,
    Keep,
    Para,
    Table,
)
from frp_assess.report.formats import TableData
from frp_assess.text_safety import PDF_MAX_CHARS, pdf

#: longest plain-text paragraph (notes) [characters]; table cells hold PDF_MAX_CHARS
PARAGRAPH_MAX_CHARS = 8 * PDF_MAX_CHARS


def esc(text: object, *, limit: int = PDF_MAX_CHARS) -> str:
    """User or data text made safe for Paragraph markup: control characters replaced, length
    capped, long words broken, ``<``, ``&``, ``>`` escaped; :class:`Markup` unchanged."""
    return pdf(text, limit=limit)


def para(text: object, style: str = "body") -> Para:
    """A paragraph of plain text (escaped)."""
    return Para(esc(text, limit=PARAGRAPH_MAX_CHARS), style)


def markup(text: str, style: str = "body") -> Para:
    """A paragraph of trusted markup: every piece of data in it must go through :func:`esc`."""
    return Para(text, style)


def h1(text: str) -> Heading:
    return Heading(text, 1)


def h2(text: str) -> Heading:
    return Heading(text, 2)


def gap(h: float = 6) -> Gap:
    return Gap(h)


def page_break() -> Break:
    return Break("page")


def cond_break(height: float) -> Break:
    """A page break unless ``height`` [pt] is left on the page."""
    return Break("cond", height)


def keep(blocks: Sequence[Block]) -> Keep:
    return Keep(tuple(blocks))


def figure(drawing: Drawing) -> Figure:
    return Figure(drawing)


def key_value(
    rows: Sequence[Sequence[str]],
    key_width: float = 68 * 2.8346,
    *,
    sub_values: bool = False,
    verbatim_rows: Sequence[int] = (),
) -> Table:
    """'quantity | value' table; both columns wrap. Keys are labels written by the report
    (``x_y`` shown as a subscript); values are shown as typed unless ``sub_values`` (then
    except the rows in ``verbatim_rows``, which hold user text)."""
    return Table(
        "key_value",
        (),
        tuple((str(k), str(v)) for k, v in rows),
        (key_width, st.FRAME_WIDTH - key_width),
        wrap=(0, 1),
        sub_values=sub_values,
        verbatim_rows=tuple(verbatim_rows),
    )


def grid(
    data: TableData,
    widths: Sequence[float],
    *,
    wrap: Sequence[int] = (),
    small: bool = False,
    numeric_from: int = 1,
    highlight_rows: Sequence[int] = (),
    repeat_header: bool = True,
) -> Table:
    """A table with a header row. Columns in ``wrap`` hold wrapping paragraphs; the others
    one line (right-aligned from ``numeric_from``); header cells are plain text or
    :class:`~frp_assess.text_safety.Markup`."""
    return Table(
        "grid",
        tuple(data.header),
        tuple(tuple(r) for r in data.rows),
        tuple(widths),
        wrap=tuple(wrap),
        small=small,
        numeric_from=numeric_from,
        highlight_rows=tuple(highlight_rows),
        repeat_header=repeat_header,
    )
