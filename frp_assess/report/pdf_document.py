"""The PDF report: the document model of :mod:`frp_assess.report.document` drawn by
reportlab on A4 pages with a running header, footer and "page n of N", the PDF outline from
the headings, and dates from the results so that a rebuild is byte-identical.  With
:mod:`frp_assess.report.render_pdf` (the blocks as flowables) the only modules of the report
that draw with reportlab's page machinery.

Public API: :func:`build_story`, :func:`build_report`, :func:`pdf_date`.
"""

from __future__ import annotations

import datetime as _dt
from pathlib import Path
from typing import Any

from reportlab.lib.units import mm
from reportlab.pdfbase.pdfmetrics import stringWidth
from reportlab.pdfgen.canvas import Canvas
from reportlab.platypus import BaseDocTemplate, Flowable, Frame, PageTemplate, Paragraph

from frp_assess.io_utils import atomic_path
from frp_assess.report import render_pdf
from frp_assess.report import styles as st
from frp_assess.report.document import _lang, build_blocks, document_head
from frp_assess.report.render_pdf import fit as _fit
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import pdf_plain


def build_story(results: AssessmentResult) -> list[Flowable]:
    """The PDF flowables of the report, in order."""
    st.register_fonts()
    return render_pdf.flowables(build_blocks(results))


def pdf_date(created: object) -> str:
    """The PDF date (``D:YYYYMMDDhhmmss+00'00'``) of the results' ``created`` field
    (``YYYY-MM-DD`` or an ISO date-time), so that CreationDate and ModDate say when the
    results were computed and a rebuild from the same results is byte-identical.
    An unreadable value gives 2000-01-01."""
    try:
        when = _dt.datetime.fromisoformat(str(created))
    except ValueError:
        when = _dt.datetime(2000, 1, 1)
    if when.tzinfo is not None:
        when = when.astimezone(_dt.UTC)
    return when.strftime("D:%Y%m%d%H%M%S+00'00'")


class NumberedCanvas(Canvas):
    """Canvas that writes 'page n of N' once the number of pages is known."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._saved: list[dict[str, Any]] = []

    def showPage(self) -> None:  # noqa: N802 (reportlab API)
        self._saved.append(dict(self.__dict__))
        self._startPage()

    def save(self) -> None:
        total = len(self._saved)
        for state in self._saved:
            self.__dict__.update(state)
            self._draw_page_number(total)
            super().showPage()
        super().save()

    #: "page {n} of {total}" in the report's language
    page_word = "page {n} of {total}"

    def _draw_page_number(self, total: int) -> None:
        self.setFont(st.FONT, 7.5)
        self.setFillColor(st.MUTED)
        text = self.page_word.format(n=self._pageNumber, total=total)
        self.drawRightString(st.PAGE_SIZE[0] - st.MARGIN_X, 10 * mm, text)


class A4Template(BaseDocTemplate):
    """A4 portrait, one body frame within the report's margins, the PDF's metadata as plain
    text and invariant (a rebuild is byte-identical); a subclass draws each page's header
    and footer in :meth:`_decorate`."""

    def __init__(
        self, filename: str, *, title: str, author: str, subject: str, creator: str
    ) -> None:
        super().__init__(
            filename,
            pagesize=st.PAGE_SIZE,
            leftMargin=st.MARGIN_X,
            rightMargin=st.MARGIN_X,
            topMargin=st.MARGIN_TOP,
            bottomMargin=st.MARGIN_BOTTOM,
            title=pdf_plain(title),
            author=pdf_plain(author),
            subject=subject,
            creator=pdf_plain(creator),
            invariant=1,
            initialFontName=st.FONT,
            initialFontSize=st.BODY_SIZE,
        )
        frame = Frame(
            self.leftMargin,
            self.bottomMargin,
            self.width,
            self.height,
            id="body",
            leftPadding=0,
            rightPadding=0,
            topPadding=0,
            bottomPadding=0,
        )
        self.addPageTemplates([PageTemplate(id="page", frames=[frame], onPage=self._decorate)])

    def _decorate(self, canv: Canvas, doc: BaseDocTemplate) -> None:
        raise NotImplementedError


class ReportTemplate(A4Template):
    """A4 portrait, one frame, header and footer, PDF outline from the section headings."""

    def __init__(self, filename: str, results: AssessmentResult) -> None:
        self.document = document_head(results)
        super().__init__(
            filename,
            title=self.document.title,
            author=results.project.engineer or "",
            subject=_lang(results).t("doc.subject"),
            creator=f"frp-assess {results.software.version}",
        )
        self.results = results
        self._outline = 0

    def _decorate(self, canv: Canvas, doc: BaseDocTemplate) -> None:
        r = self.results
        p = r.project
        w, h = st.PAGE_SIZE
        canv.saveState()
        canv.setStrokeColor(st.RULE)
        canv.setLineWidth(0.5)
        top = h - 12 * mm
        canv.line(st.MARGIN_X, top - 2.5, w - st.MARGIN_X, top - 2.5)
        canv.setFont(st.FONT_BOLD, 8)
        canv.setFillColor(st.INK)
        right = self.document.header
        right_w = stringWidth(right, st.FONT, 8)
        name = _fit(
            str(p.name or _lang(r).t("title.unnamed")),
            st.FONT_BOLD,
            8,
            st.FRAME_WIDTH - right_w - 12,
        )
        canv.drawString(st.MARGIN_X, top, name)
        canv.setFont(st.FONT, 8)
        canv.setFillColor(st.MUTED)
        canv.drawRightString(w - st.MARGIN_X, top, right)
        canv.line(st.MARGIN_X, 13.5 * mm, w - st.MARGIN_X, 13.5 * mm)
        canv.setFont(st.FONT, 7.5)
        foot = self.document.footer
        canv.drawString(st.MARGIN_X, 10 * mm, _fit(foot, st.FONT, 7.5, st.FRAME_WIDTH - 80))
        canv.restoreState()

    def afterFlowable(self, flowable: Flowable) -> None:  # noqa: N802 (reportlab API)
        if isinstance(flowable, Paragraph) and flowable.style.name in ("h1", "h2"):
            key = f"s{self._outline}"
            self._outline += 1
            self.canv.bookmarkPage(key)
            level = 0 if flowable.style.name == "h1" else 1
            self.canv.addOutlineEntry(flowable.getPlainText(), key, level=level, closed=True)


def build_report(
    results: AssessmentResult, out_path: Path | str, *, story: list[Flowable] | None = None
) -> None:
    """Write the PDF to ``out_path`` atomically (temp file in the same directory, then rename).

    Two builds from the same results give byte-identical files: the PDF's CreationDate and
    ModDate are the results' date (:func:`pdf_date`), not the time of the build.
    ``story``: the flowables of :func:`build_story` if already built.
    """
    out_path = Path(out_path)
    out_path.parent.mkdir(parents=True, exist_ok=True)
    if story is None:
        story = build_story(results)
    date = pdf_date(results.created)
    page_word = document_head(results).page_word

    def canvas(*args: Any, **kwargs: Any) -> NumberedCanvas:
        c = NumberedCanvas(*args, **kwargs)
        c.setDateFormatter(lambda *_: date)
        c.page_word = page_word
        return c

    with atomic_path(out_path) as tmp:
        doc = ReportTemplate(str(tmp), results)
        doc.build(story, canvasmaker=canvas)
