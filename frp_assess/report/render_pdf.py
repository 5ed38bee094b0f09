"""The PDF renderer: blocks of the document model (:mod:`frp_assess.report.doc_model`) as
reportlab flowables, in the report's look (:mod:`frp_assess.report.styles`)."""

from __future__ import annotations

from collections.abc import Sequence

from reportlab.pdfbase.pdfmetrics import stringWidth
from reportlab.platypus import (
    CondPageBreak,
    Flowable,
    KeepTogether,
    PageBreak,
    Paragraph,
    Spacer,
)
from reportlab.platypus import Table as RlTable

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
    cell_markup,
)
from frp_assess.report.flow import esc
from frp_assess.text_safety import pdf_plain

#: paragraph style of a heading by level
HEADING_STYLE = {0: "title", 1: "h1", 2: "h2"}


def fit(text: str, font: str, size: float, width: float) -> str:
    """``text`` (plain, any length) shortened with an ellipsis to fit ``width`` [pt].

    Bisection on the length, so a very long name costs a few width measurements."""
    text = pdf_plain(text)
    if stringWidth(text, font, size) <= width:
        return text
    lo, hi = 0, len(text)  # text[:lo] + "…" fits; text[:hi] + "…" does not
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if stringWidth(text[:mid] + "…", font, size) <= width:
            lo = mid
        else:
            hi = mid
    return text[:lo] + "…"


#: most lines a wrapping table cell shows; longer text is shortened with an ellipsis
MAX_CELL_LINES = 6


def cell_limit(width: float, size: float) -> int:
    """The characters a wrapping cell ``width`` [pt] wide shows in :data:`MAX_CELL_LINES`
    lines of font ``size`` [pt] (a character is about half the font size wide)."""
    return max(24, int(MAX_CELL_LINES * width / (0.55 * size)))


#: tables of at most this many body rows are kept on one page
KEEP_WHOLE_ROWS = 12


def flowables(blocks: Sequence[Block]) -> list[Flowable]:
    """The flowables of ``blocks``, in order."""
    return [_one(b) for b in blocks]


def _one(b: Block) -> Flowable:
    styles = st.paragraph_styles()
    if isinstance(b, Heading):
        return Paragraph(esc(b.text), styles[HEADING_STYLE.get(b.level, "h2")])
    if isinstance(b, Para):
        return Paragraph(b.markup, styles[b.style])
    if isinstance(b, Table):
        table = key_value_table(b) if b.kind == "key_value" else grid_table(b)
        # a short table is never split (a page holding its last two rows): it moves whole
        return KeepTogether([table]) if len(b.rows) <= KEEP_WHOLE_ROWS else table
    if isinstance(b, Figure):
        return b.drawing
    if isinstance(b, Break):
        return PageBreak() if b.kind == "page" else CondPageBreak(b.height)
    if isinstance(b, Gap):
        return Spacer(1, b.height)
    if isinstance(b, Keep):
        return KeepTogether(flowables(b.blocks))
    raise TypeError(f"not a block: {b!r}")


def key_value_table(t: Table) -> RlTable:
    """'quantity | value', both columns wrapping paragraphs."""
    s = st.paragraph_styles()

    data = [
        [Paragraph(cell_markup(t, i, j, v), s["cell"]) for j, v in enumerate(row)]
        for i, row in enumerate(t.rows)
    ]
    table = RlTable(data, colWidths=list(t.widths), hAlign="LEFT")
    table.setStyle(st.key_value_table_style(len(data)))
    return table


def grid_table(t: Table) -> RlTable:
    """A header row, then the body; wrapping columns as paragraphs, the others one line."""
    s = st.paragraph_styles()
    head = s["head_small"] if t.small else s["head_center"]
    cell = s["cell_small"] if t.small else s["cell"]
    total = sum(t.widths)
    scale = st.FRAME_WIDTH / total if total > st.FRAME_WIDTH else 1.0
    size = st.SMALL_TABLE_SIZE if t.small else st.TABLE_SIZE
    widths = [w * scale for w in t.widths]

    def one(i: int, j: int, v: str) -> Flowable | str:
        room = widths[j] if j < len(widths) else st.FRAME_WIDTH  # padding may take some
        if j in t.wrap:
            return Paragraph(cell_markup(t, i, j, v, limit=cell_limit(room, size)), cell)
        return fit(v, st.FONT, size, room)

    body: list[list[Flowable | str]] = [[Paragraph(esc(h), head) for h in t.header]]
    for i, row in enumerate(t.rows):
        body.append([one(i, j, v) for j, v in enumerate(row)])
    table = RlTable(
        body,
        colWidths=widths,
        repeatRows=1 if t.repeat_header else 0,
        hAlign="LEFT",
    )
    style = st.grid_table_style(
        len(body),
        font_size=size,
        numeric_from=t.numeric_from,
    )
    for r in t.highlight_rows:
        style.add("BACKGROUND", (0, r + 1), (-1, r + 1), st.HIGHLIGHT)
    for j in t.wrap:
        style.add("ALIGN", (j, 1), (j, -1), "LEFT")
    table.setStyle(style)
    return table
