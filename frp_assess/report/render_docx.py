"""The DOCX renderer: the document model (:mod:`frp_assess.report.doc_model`) as an editable
Word file (python-docx), optionally on a firm's own template (its styles, page and header).

Styles used (Word's built-in names, present in python-docx's default template and in any
template made with Word): Title, Subtitle, Heading 1, Heading 2, Normal, Caption,
List Bullet, Table Grid; a style missing from a template falls back to Normal.
Same results → same bytes: the core properties carry the results' date and the zip entries a
fixed time stamp.
"""

from __future__ import annotations

import datetime as _dt
import html
import io
import re
import zipfile
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import docx
from docx.enum.style import WD_STYLE_TYPE
from docx.enum.table import WD_TABLE_ALIGNMENT
from docx.enum.text import WD_ALIGN_PARAGRAPH
from docx.oxml import OxmlElement
from docx.oxml.ns import qn
from docx.shared import Pt, RGBColor

from frp_assess.errors import InputError
from frp_assess.io_utils import atomic_path
from frp_assess.report.doc_model import (
    Block,
    Break,
    Document,
    Figure,
    Heading,
    Keep,
    Para,
    Table,
    cell_markup,
)
from frp_assess.report.render_png import drawing_png
from frp_assess.text_safety import pdf_plain

#: Word style of a paragraph style of the model
PARA_STYLE = {
    "title": "Title",
    "subtitle": "Subtitle",
    "caption": "Caption",
    "bullet": "List Bullet",
}
#: font size [pt] of the model's small styles
SMALL_PT = {"small": 9.0, "caption": 8.5, "reference": 9.0}
HEADING_STYLE = {0: "Title", 1: "Heading 1", 2: "Heading 2"}
#: width of the text on the page when the template says nothing [pt] (A4, 18 mm margins)
TEXT_WIDTH_PT = 493.0
_TOKEN = re.compile(r"(<br/>|</?(?:b|i|sub|sup)>)")


def _style(doc: Any, name: str) -> str:
    try:
        doc.styles[name]  # noqa: B018 (lookup raises KeyError when missing)
    except KeyError:
        return "Normal"
    return name


class _ParagraphStyles:
    """The paragraph style ids of one document, each looked up once.  python-docx finds a
    style by name with an XPath search of the styles part at every
    ``add_paragraph(style=name)``: two searches per paragraph were half of a report's DOCX
    time.  :meth:`add` gives the same XML (the style id, none for the default style)."""

    def __init__(self, doc: Any) -> None:
        self._doc = doc
        self._ids: dict[str, str | None] = {}

    def add(self, name: str) -> Any:
        """A new paragraph at the end of the body, in style ``name`` (Normal when the
        document has no such style)."""
        if name not in self._ids:
            self._ids[name] = self._doc.part.get_style_id(
                _style(self._doc, name), WD_STYLE_TYPE.PARAGRAPH
            )
        p = self._doc.add_paragraph()
        p._p.style = self._ids[name]  # as python-docx: an empty w:pPr for the default style
        return p


def add_markup(paragraph: Any, markup: str, *, size: float | None = None) -> None:
    """Runs of ``paragraph`` from trusted markup: bold, italic, sub- and superscript, line
    breaks; entities decoded."""
    state = {"b": False, "i": False, "sub": False, "sup": False}
    for token in _TOKEN.split(markup):
        if not token:
            continue
        if token == "<br/>":
            paragraph.add_run().add_break()
        elif _TOKEN.fullmatch(token):
            closing = token.startswith("</")
            state[token.strip("</>")] = not closing
        else:
            run = paragraph.add_run(html.unescape(re.sub(r"<[^<>]*>", "", token)))
            run.bold = state["b"] or None
            run.italic = state["i"] or None
            if state["sub"]:
                run.font.subscript = True
            if state["sup"]:
                run.font.superscript = True
            if size is not None:
                run.font.size = Pt(size)


def _heading(styles: _ParagraphStyles, b: Heading) -> None:
    p = styles.add(HEADING_STYLE.get(b.level, "Heading 2"))
    p.add_run(pdf_plain(b.text))


def _para(styles: _ParagraphStyles, b: Para) -> None:
    text = b.markup
    if b.style == "bullet" and text.startswith("• "):
        text = text[2:]
    p = styles.add(PARA_STYLE.get(b.style, "Normal"))
    if b.style == "equation":
        p.paragraph_format.left_indent = Pt(18)
    add_markup(p, text, size=SMALL_PT.get(b.style))
    if b.style in ("verdict_ok", "verdict_bad"):
        for run in p.runs:
            run.bold = True
            ok = b.style == "verdict_ok"
            run.font.color.rgb = RGBColor(0x1B, 0x6E, 0x3A) if ok else RGBColor(0xB0, 0x1E, 0x1E)


def _repeat_header(row: Any) -> None:
    tr_pr = row._tr.get_or_add_trPr()
    el = OxmlElement("w:tblHeader")
    el.set(qn("w:val"), "true")
    tr_pr.append(el)


def _cell(cell: Any, markup: str, *, size: float, bold: bool = False, right: bool = False) -> None:
    p = cell.paragraphs[0]
    add_markup(p, markup, size=size)
    if bold:
        for run in p.runs:
            run.bold = True
    if right:
        p.alignment = WD_ALIGN_PARAGRAPH.RIGHT


def _table(doc: Any, b: Table, text_width: float) -> None:
    size = 7.5 if b.small else 8.5
    n_cols = len(b.header) if b.kind == "grid" else 2
    rows: list[Sequence[str]] = [b.header] if b.kind == "grid" else []
    rows += list(b.rows)
    if not rows or n_cols == 0:
        return
    t = doc.add_table(rows=len(rows), cols=n_cols)
    t.style = _style(doc, "Table Grid")
    t.alignment = WD_TABLE_ALIGNMENT.LEFT
    t.autofit = False
    total = sum(b.widths) or 1.0
    scale = min(1.0, text_width / total)
    widths = [Pt(w * scale) for w in b.widths]
    for i, row in enumerate(rows):
        cells = t.rows[i].cells
        for j in range(n_cols):
            value = row[j] if j < len(row) else ""
            if j < len(widths):
                cells[j].width = widths[j]
            row_index = i if b.kind == "key_value" else i - 1
            text = cell_markup(b, row_index, j, value)
            if b.kind == "key_value":
                _cell(cells[j], text, size=size)
            elif i == 0:
                _cell(cells[j], text, size=size, bold=True)
            else:
                body_row = i - 1
                _cell(cells[j], text, size=size, right=j >= b.numeric_from)
                if body_row in b.highlight_rows:
                    shade = OxmlElement("w:shd")
                    shade.set(qn("w:val"), "clear")
                    shade.set(qn("w:fill"), "FFF4CC")
                    cells[j]._tc.get_or_add_tcPr().append(shade)
    if b.kind == "grid" and b.repeat_header:
        _repeat_header(t.rows[0])
    doc.add_paragraph()


def _figure(doc: Any, b: Figure, text_width: float) -> None:
    width = min(float(b.drawing.width), text_width)
    doc.add_picture(io.BytesIO(drawing_png(b.drawing)), width=Pt(width))


def _blocks(
    doc: Any, blocks: Sequence[Block], text_width: float, styles: _ParagraphStyles | None = None
) -> None:
    styles = styles or _ParagraphStyles(doc)
    for b in blocks:
        if isinstance(b, Heading):
            _heading(styles, b)
        elif isinstance(b, Para):
            _para(styles, b)
        elif isinstance(b, Table):
            _table(doc, b, text_width)
        elif isinstance(b, Figure):
            _figure(doc, b, text_width)
        elif isinstance(b, Keep):
            _blocks(doc, b.blocks, text_width, styles)
        elif isinstance(b, Break) and b.kind == "page":
            doc.add_page_break()


def _page_field(paragraph: Any) -> None:
    run = paragraph.add_run()
    field = OxmlElement("w:fldSimple")
    field.set(qn("w:instr"), "PAGE")
    run._r.append(field)


def _open(template: str | Path | None) -> Any:
    if template is None:
        return docx.Document()
    path = Path(template)
    try:
        doc = docx.Document(str(path))
    except Exception as exc:  # noqa: BLE001 - any failure of a user's file is one line
        raise InputError(
            f"cannot open the Word template (a .docx file is expected): {exc}",
            file=str(path),
            key="report.template",
        ) from None
    body = doc.element.body
    for child in list(body):
        if child.tag != qn("w:sectPr"):
            body.remove(child)
    return doc


def docx_bytes(document: Document, *, created: str, template: str | Path | None = None) -> bytes:
    """The DOCX of ``document``; ``created``: the results' date (ISO), stamped into the file."""
    doc = _open(template)
    sec = doc.sections[0]
    text_width = TEXT_WIDTH_PT
    if sec.page_width is not None and sec.left_margin is not None and sec.right_margin is not None:
        text_width = (sec.page_width - sec.left_margin - sec.right_margin) / 12700
    if template is None:
        head = sec.header.paragraphs[0]
        head.text = pdf_plain(document.header)
        foot = sec.footer.paragraphs[0]
        foot.text = pdf_plain(document.footer) + " · "
        _page_field(foot)
    _blocks(doc, document.blocks(), text_width)
    props = doc.core_properties
    props.title = pdf_plain(document.title)
    props.author = pdf_plain(document.author)
    props.language = document.language
    when = _when(created)
    props.created = props.modified = props.last_printed = when
    props.revision = 1
    raw = io.BytesIO()
    doc.save(raw)
    return _fixed_zip(raw.getvalue(), when)


def _when(created: str) -> _dt.datetime:
    try:
        when = _dt.datetime.fromisoformat(str(created))
    except ValueError:
        when = _dt.datetime(2000, 1, 1)
    return when.replace(tzinfo=None)


def _fixed_zip(data: bytes, when: _dt.datetime) -> bytes:
    """The same zip with every entry stamped ``when`` (a rebuild is byte-identical)."""
    stamp = (max(when.year, 1980), when.month, when.day, when.hour, when.minute, when.second)
    out = io.BytesIO()
    with zipfile.ZipFile(io.BytesIO(data)) as src, zipfile.ZipFile(out, "w") as dst:
        for info in src.infolist():
            fixed = zipfile.ZipInfo(info.filename, date_time=stamp)
            fixed.compress_type = zipfile.ZIP_DEFLATED
            fixed.external_attr = 0o644 << 16
            dst.writestr(fixed, src.read(info.filename))
    return out.getvalue()


def write_docx(
    document: Document, out_path: Path | str, *, created: str, template: str | Path | None = None
) -> None:
    """Write the DOCX atomically (temp file in the same directory, then rename)."""
    data = docx_bytes(document, created=created, template=template)
    out_path = Path(out_path)
    out_path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(out_path) as tmp:
        Path(tmp).write_bytes(data)
