"""Small flowable builders shared by the report sections.

Escaping is done here, at one place: every builder takes plain text and escapes it with
:func:`esc` (:func:`frp_assess.text_safety.pdf`); only :class:`~frp_assess.text_safety.Markup`
and :func:`markup` paragraphs, written by the code, carry markup.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from reportlab.platypus import Flowable, Paragraph, Spacer, Table

from frp_assess.report import styles as st
from frp_assess.report.tables import TableData
from frp_assess.text_safety import PDF_MAX_CHARS, pdf, pdf_plain

#: longest plain-text paragraph (notes) [characters]; table cells hold PDF_MAX_CHARS
PARAGRAPH_MAX_CHARS = 8 * PDF_MAX_CHARS


def esc(text: object, *, limit: int = PDF_MAX_CHARS) -> str:
    """User or data text made safe for Paragraph markup: control characters replaced, length
    capped, long words broken, ``<``, ``&``, ``>`` escaped; :class:`Markup` unchanged."""
    return pdf(text, limit=limit)


_SUB = re.compile(r"(?<![A-Za-z0-9])([A-Za-zαεθ])_([A-Za-z0-9]+)")


def with_subscripts(escaped: str) -> str:
    """``a_dyn`` → a<sub>dyn</sub> in already escaped, trusted label text."""
    return _SUB.sub(r"\1<sub>\2</sub>", escaped)


def para(text: object, style: str = "body") -> Paragraph:
    """A paragraph of plain text (escaped)."""
    return Paragraph(esc(text, limit=PARAGRAPH_MAX_CHARS), st.paragraph_styles()[style])


def markup(text: str, style: str = "body") -> Paragraph:
    """A paragraph of trusted markup: every piece of data in it must go through :func:`esc`."""
    return Paragraph(text, st.paragraph_styles()[style])


def gap(h: float = 6) -> Spacer:
    return Spacer(1, h)


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
    s = st.paragraph_styles()

    def val(i: int, v: str) -> str:
        return with_subscripts(esc(v)) if sub_values and i not in verbatim_rows else esc(v)

    data = [
        [Paragraph(with_subscripts(esc(k)), s["cell"]), Paragraph(val(i, v), s["cell"])]
        for i, (k, v) in enumerate(rows)
    ]
    t = Table(data, colWidths=[key_width, st.FRAME_WIDTH - key_width], hAlign="LEFT")
    t.setStyle(st.key_value_table_style(len(data)))
    return t


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
    """A table with a header row. Columns in ``wrap`` hold wrapping (escaped) paragraphs;
    the others plain strings (right-aligned from ``numeric_from``); header cells are plain text
    or :class:`~frp_assess.text_safety.Markup`."""
    s = st.paragraph_styles()
    head = s["head_small"] if small else s["head_center"]
    cell = s["cell_small"] if small else s["cell"]
    body: list[list[Flowable | str]] = [[Paragraph(esc(h), head) for h in data.header]]
    for row in data.rows:
        body.append(
            [Paragraph(esc(v), cell) if j in wrap else pdf_plain(v) for j, v in enumerate(row)]
        )
    total = sum(widths)
    scale = st.FRAME_WIDTH / total if total > st.FRAME_WIDTH else 1.0
    t = Table(
        body,
        colWidths=[w * scale for w in widths],
        repeatRows=1 if repeat_header else 0,
        hAlign="LEFT",
    )
    style = st.grid_table_style(
        len(body),
        font_size=st.SMALL_TABLE_SIZE if small else st.TABLE_SIZE,
        numeric_from=numeric_from,
    )
    for r in highlight_rows:
        style.add("BACKGROUND", (0, r + 1), (-1, r + 1), st.HIGHLIGHT)
    for j in wrap:
        style.add("ALIGN", (j, 1), (j, -1), "LEFT")
    t.setStyle(style)
    return t
