"""The PDF assessment report: a pure function of the typed results
(:class:`~frp_assess.results.model.AssessmentResult`, docs/results-json.md).

Public API: :func:`load_results`, :func:`build_story`, :func:`build_report`.
"""

from __future__ import annotations

import datetime as _dt
from pathlib import Path
from typing import Any

from reportlab.lib.units import mm
from reportlab.pdfbase.pdfmetrics import stringWidth
from reportlab.pdfgen.canvas import Canvas
from reportlab.platypus import BaseDocTemplate, Flowable, Frame, PageTemplate, Paragraph

from frp_assess.errors import InputError
from frp_assess.io_utils import atomic_path
from frp_assess.report import as_built_section, render_pdf, sections
from frp_assess.report import styles as st
from frp_assess.report.doc_model import Block, Document, split_sections
from frp_assess.report.render_docx import write_docx
from frp_assess.results.json_io import from_json
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import pdf_plain, plain

#: largest results.json read [bytes] (a run with time histories writes well under 10 MB)
MAX_RESULTS_BYTES = 64 * 1024 * 1024


def load_results(results_dir: str | Path) -> AssessmentResult:
    """Read ``results_dir/results.json`` (:func:`frp_assess.results.json_io.from_json`);
    anything missing or malformed is an InputError naming the file and the key.

    Checked here: size, JSON syntax (NaN and Infinity are not JSON), nesting depth, the
    schema version, and every key and type of the contract (docs/results-json.md).
    """
    d = Path(results_dir)
    if not d.is_dir():
        raise InputError("not a results directory (does not exist)", file=str(d))
    path = d / "results.json"
    if not path.is_file():
        raise InputError("no results.json here; run `frp-assess run` first", file=str(d))
    try:
        if path.stat().st_size > MAX_RESULTS_BYTES:
            raise InputError(
                f"{path.stat().st_size} bytes, more than the {MAX_RESULTS_BYTES} a results "
                "file can have",
                file=str(path),
            )
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"cannot read: {exc}", file=str(path)) from None
    results = from_json(text, file=str(path))
    if not results.cases:
        raise InputError("no cases", file=str(path), key="cases")
    return results


def contract_error(exc: Exception, path: Path | str) -> InputError:
    """The one line said when a results file passed :func:`load_results` (every key and type
    is checked there) but a value breaks the report (docs/results-json.md): out of range,
    an empty list where one is needed."""
    if isinstance(exc, KeyError):
        what = f"missing key {exc.args[0]!r}" if exc.args else "a key is missing"
    else:
        what = f"a value of the wrong type or range ({plain(str(exc))[:160]})"
    return InputError(
        f"does not follow the results contract (docs/results-json.md): {what}", file=str(path)
    )


#: what building the report from results that break the contract (a value out of range) raises
CONTRACT_ERRORS = (KeyError, TypeError, ValueError, AttributeError, IndexError, ZeroDivisionError)


def build_blocks(results: AssessmentResult) -> list[Block]:
    """The blocks of the sections, in order."""
    story: list[Block] = []
    for part in (
        sections.summary,
        sections.inputs,
        sections.seismic,
        sections.unreinforced,
        sections.options,
        as_built_section.section,
        sections.governing,
        sections.method,
    ):
        story += part(results)
    return story


def build_document(results: AssessmentResult) -> Document:
    """The report as a document model: what both renderers draw."""
    p = results.project
    sw = results.software
    return Document(
        title=f"Seismic assessment – {p.name or 'wall'}",
        header="Seismic assessment · vertical FRP rebars",
        footer=f"{sw.name} {sw.version} · results of {results.created} · "
        f"{results.input_file or ''}",
        page_word="page {n} of {total}",
        author=p.engineer or "",
        language="en",
        sections=split_sections(build_blocks(results)),
    )


def build_docx(results: AssessmentResult, out_path: Path | str) -> None:
    """Write the editable Word report to ``out_path`` atomically (byte-identical rebuilds)."""
    write_docx(build_document(results), out_path, created=results.created)


def build_story(results: AssessmentResult) -> list[Flowable]:
    """The PDF flowables of the report, in order."""
    st.register_fonts()
    return render_pdf.flowables(build_blocks(results))


def _fit(text: str, font: str, size: float, width: float) -> str:
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

    def _draw_page_number(self, total: int) -> None:
        self.setFont(st.FONT, 7.5)
        self.setFillColor(st.MUTED)
        self.drawRightString(
            st.PAGE_SIZE[0] - st.MARGIN_X, 10 * mm, f"page {self._pageNumber} of {total}"
        )


class ReportTemplate(BaseDocTemplate):
    """A4 portrait, one frame, header and footer, PDF outline from the section headings."""

    def __init__(self, filename: str, results: AssessmentResult) -> None:
        p = results.project
        super().__init__(
            filename,
            pagesize=st.PAGE_SIZE,
            leftMargin=st.MARGIN_X,
            rightMargin=st.MARGIN_X,
            topMargin=st.MARGIN_TOP,
            bottomMargin=st.MARGIN_BOTTOM,
            title=pdf_plain(f"Seismic assessment – {p.name or 'wall'}"),
            author=pdf_plain(p.engineer or ""),
            subject="Rocking masonry wall retrofitted with vertical FRP rebars",
            creator=pdf_plain(f"frp-assess {results.software.version}"),
            invariant=1,
            initialFontName=st.FONT,
            initialFontSize=st.BODY_SIZE,
        )
        self.results = results
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
        right = "Seismic assessment · vertical FRP rebars"
        right_w = stringWidth(right, st.FONT, 8)
        name = _fit(
            str(p.name or "Unnamed project"), st.FONT_BOLD, 8, st.FRAME_WIDTH - right_w - 12
        )
        canv.drawString(st.MARGIN_X, top, name)
        canv.setFont(st.FONT, 8)
        canv.setFillColor(st.MUTED)
        canv.drawRightString(w - st.MARGIN_X, top, right)
        canv.line(st.MARGIN_X, 13.5 * mm, w - st.MARGIN_X, 13.5 * mm)
        canv.setFont(st.FONT, 7.5)
        sw = r.software
        foot = f"{sw.name} {sw.version} · results of {r.created} · {r.input_file or ''}"
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

    def canvas(*args: Any, **kwargs: Any) -> NumberedCanvas:
        c = NumberedCanvas(*args, **kwargs)
        c.setDateFormatter(lambda *_: date)
        return c

    with atomic_path(out_path) as tmp:
        doc = ReportTemplate(str(tmp), results)
        doc.build(story, canvasmaker=canvas)
