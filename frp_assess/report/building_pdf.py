"""A building's report drawn as PDF and as Word: the document model of
:mod:`frp_assess.report.building_document` on A4 pages with the running header and footer and
"page n of N" of a wall's report (:mod:`frp_assess.report.pdf_document`), dates from the
results so that a rebuild is byte-identical."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from reportlab.lib.units import mm
from reportlab.pdfgen.canvas import Canvas
from reportlab.platypus import BaseDocTemplate

from frp_assess.io_utils import atomic_path
from frp_assess.report import render_pdf
from frp_assess.report import styles as st
from frp_assess.report.building_document import building_document, words
from frp_assess.report.doc_model import Document
from frp_assess.report.pdf_document import A4Template, NumberedCanvas, pdf_date
from frp_assess.report.render_docx import write_docx
from frp_assess.report.render_pdf import fit
from frp_assess.results.building_summary import BuildingResults

__all__ = ["build_building_docx", "build_building_pdf"]


class _BuildingTemplate(A4Template):
    """A4 portrait, one frame, the document's header (its title, left; the report's kind,
    right) and footer."""

    def __init__(self, filename: str, document: Document, subject: str, creator: str) -> None:
        self.document = document
        super().__init__(
            filename, title=document.title, author=document.author, subject=subject, creator=creator
        )

    def _decorate(self, canv: Canvas, doc: BaseDocTemplate) -> None:
        w, h = st.PAGE_SIZE
        canv.saveState()
        canv.setStrokeColor(st.RULE)
        canv.setLineWidth(0.5)
        top = h - 12 * mm
        canv.line(st.MARGIN_X, top - 2.5, w - st.MARGIN_X, top - 2.5)
        right = self.document.header
        canv.setFont(st.FONT_BOLD, 8)
        canv.setFillColor(st.INK)
        width = st.FRAME_WIDTH - canv.stringWidth(right, st.FONT, 8) - 12
        canv.drawString(st.MARGIN_X, top, fit(self.document.title, st.FONT_BOLD, 8, width))
        canv.setFont(st.FONT, 8)
        canv.setFillColor(st.MUTED)
        canv.drawRightString(w - st.MARGIN_X, top, right)
        canv.line(st.MARGIN_X, 13.5 * mm, w - st.MARGIN_X, 13.5 * mm)
        canv.setFont(st.FONT, 7.5)
        foot = fit(self.document.footer, st.FONT, 7.5, st.FRAME_WIDTH - 80)
        canv.drawString(st.MARGIN_X, 10 * mm, foot)
        canv.restoreState()


def build_building_pdf(b: BuildingResults, out_path: Path | str, language: str) -> None:
    """Write the building's PDF report to ``out_path`` atomically."""
    st.register_fonts()
    document = building_document(b, language)
    story = render_pdf.flowables(document.blocks())
    date = pdf_date(b.created)

    def canvas(*args: Any, **kwargs: Any) -> NumberedCanvas:
        c = NumberedCanvas(*args, **kwargs)
        c.setDateFormatter(lambda *_: date)
        c.page_word = document.page_word
        return c

    subject = words(document.language)["doc.subject"]
    out_path = Path(out_path)
    with atomic_path(out_path) as tmp:
        template = _BuildingTemplate(
            str(tmp), document, subject, f"frp-assess {b.software.version}"
        )
        template.build(story, canvasmaker=canvas)


def build_building_docx(
    b: BuildingResults, out_path: Path | str, language: str, template: str | None = None
) -> None:
    """Write the building's Word report (the PDF's document) to ``out_path`` atomically."""
    write_docx(building_document(b, language), out_path, created=b.created, template=template)
