"""The report as data: one document model, built from the results by pure functions and drawn
by two renderers (:mod:`frp_assess.report.render_pdf`, :mod:`frp_assess.report.render_docx`).

A :class:`Document` holds :class:`Section` s, each a list of blocks.  Text in a
:class:`Para` is *trusted markup*: the report's own words with the inline tags ``<b>``,
``<i>``, ``<sub>``, ``<sup>`` and ``<br/>``; every piece of user or data text in it was
escaped on the way in (:func:`frp_assess.report.flow.esc`).  Table cells are plain text.
Layout hints (:class:`Break`, :class:`Keep`, :class:`Gap`) serve the PDF; the DOCX renderer
keeps only the page breaks.
"""

from __future__ import annotations

import html
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from frp_assess.text_safety import PDF_MAX_CHARS, pdf

#: points per millimetre (72 pt to the inch; reportlab's value, so that layouts are identical)
MM = 72.0 / 2.54 * 0.1

if TYPE_CHECKING:  # the model holds a chart; only the renderers draw it
    from reportlab.graphics.shapes import Drawing


@dataclass(frozen=True)
class Heading:
    """A section (level 1) or subsection (level 2) title; level 0: the document title."""

    text: str  #: plain text
    level: int


@dataclass(frozen=True)
class Para:
    """A paragraph of trusted markup; ``style`` names a paragraph style (body, small,
    caption, bullet, equation, reference, verdict_ok, verdict_bad, subtitle, title)."""

    markup: str
    style: str = "body"


@dataclass(frozen=True)
class Table:
    """A table of plain-text cells.

    ``kind``: ``grid`` (a header row, then ``rows``) or ``key_value`` (rows of two cells,
    quantity and value, no header).  ``widths``: column widths [pt] (scaled down to the text
    width when larger); ``wrap``: columns whose cells wrap (the others are one line, numeric
    from ``numeric_from`` right-aligned); ``sub_keys``/``sub_values``: ``x_y`` in a label is
    a subscript (not in the rows of ``verbatim_rows``, which hold user text);
    ``highlight_rows``: body rows shaded; ``header`` cells may be :class:`Markup`.
    """

    kind: str
    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    widths: tuple[float, ...]
    wrap: tuple[int, ...] = ()
    small: bool = False
    numeric_from: int = 1
    highlight_rows: tuple[int, ...] = ()
    sub_values: bool = False
    verbatim_rows: tuple[int, ...] = ()
    repeat_header: bool = True


@dataclass(frozen=True)
class Figure:
    """A vector chart (a reportlab Drawing, sized in pt)."""

    drawing: Drawing


@dataclass(frozen=True)
class Break:
    """``page``: a page break; ``cond``: a page break unless ``height`` [pt] is left."""

    kind: str = "page"
    height: float = 0.0


@dataclass(frozen=True)
class Gap:
    """Vertical space [pt]."""

    height: float = 6.0


@dataclass(frozen=True)
class Keep:
    """Blocks kept on one page (a figure and its caption)."""

    blocks: tuple[Block, ...]


Block = Heading | Para | Table | Figure | Break | Gap | Keep


@dataclass
class Section:
    """A numbered part of the report: its heading (None for the title block) and blocks."""

    heading: Heading | None
    blocks: list[Block] = field(default_factory=list)


@dataclass
class Document:
    """The whole report: metadata for the renderers and the sections in order."""

    title: str  #: plain text (PDF title, DOCX core property)
    header: str  #: running header, right side
    footer: str  #: running footer, left side
    page_word: str  #: "page {n} of {total}" in the report's language
    author: str
    language: str
    sections: list[Section]

    def blocks(self) -> list[Block]:
        """Every block in order, section headings included."""
        out: list[Block] = []
        for s in self.sections:
            if s.heading is not None:
                out.append(s.heading)
            out += s.blocks
        return out


def split_sections(blocks: Sequence[Block]) -> list[Section]:
    """Blocks cut into sections at each level-1 heading (what comes before: the title)."""
    sections = [Section(None)]
    for b in blocks:
        if isinstance(b, Heading) and b.level == 1:
            sections.append(Section(b))
        else:
            sections[-1].blocks.append(b)
    return sections


_TAG = re.compile(r"<[^<>]*>")


def markup_text(markup: str) -> str:
    """The plain text of trusted markup (tags dropped, ``<br/>`` a space, entities decoded)."""
    return html.unescape(_TAG.sub("", markup.replace("<br/>", " ")))


_SUB = re.compile(r"(?<![A-Za-z0-9])([A-Za-zα-ω])_([A-Za-z0-9]+)")


def with_subscripts(escaped: str) -> str:
    """``a_dyn`` → a<sub>dyn</sub> in already escaped, trusted label text."""
    return _SUB.sub(r"\1<sub>\2</sub>", escaped)


def cell_markup(t: Table, row: int, col: int, value: str, *, limit: int = PDF_MAX_CHARS) -> str:
    """The markup a renderer shows for cell (``row``, ``col``) of ``t`` (``row`` -1: the
    header): user text escaped; labels of key-value tables (and their values with
    ``sub_values``, but for ``verbatim_rows``) with ``x_y`` as a subscript."""
    text = pdf(value, limit=limit)
    if t.kind == "key_value" and (col == 0 or (t.sub_values and row not in t.verbatim_rows)):
        return with_subscripts(text)
    return text


def plain_texts(doc: Document) -> list[str]:
    """The text of the document in reading order: headings, paragraphs and table cells (one
    string each, whitespace collapsed), what both renderers must show."""
    out: list[str] = []

    def walk(blocks: Sequence[Block]) -> None:
        for b in blocks:
            if isinstance(b, Heading):
                out.append(b.text)
            elif isinstance(b, Para):
                out.append(markup_text(b.markup))
            elif isinstance(b, Table):
                for i, row in enumerate(((b.header,) if b.header else ()) + b.rows):
                    r = i - 1 if b.header else i
                    out.extend(markup_text(cell_markup(b, r, j, c)) for j, c in enumerate(row))
            elif isinstance(b, Keep):
                walk(b.blocks)

    walk(doc.blocks())
    return [" ".join(t.split()) for t in out if t.strip()]
