"""The assessment report as a document model, a pure function of the typed results
(:class:`~frp_assess.results.model.AssessmentResult`, docs/results-json.md): the blocks of
the body, the appendix and the annex in order, the title, header and footer.  Free of
reportlab: the PDF (:mod:`frp_assess.report.pdf_document`) and the DOCX
(:mod:`frp_assess.report.render_docx`) are drawn from it.

Public API: :func:`load_results`, :func:`build_document`, :func:`build_docx`.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from frp_assess.errors import InputError
from frp_assess.report import (
    body_analysis,
    body_annex,
    body_checks,
    body_closing,
    body_front,
    body_software,
    loads_section,
)
from frp_assess.report.doc_model import MM, Block, Document, Heading, split_sections
from frp_assess.report.flow import cond_break, page_break
from frp_assess.report.lang import Lang
from frp_assess.report.render_docx import write_docx
from frp_assess.report.wording import engineer_blocks
from frp_assess.results.json_io import from_json
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import plain

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


def _lang(results: AssessmentResult) -> Lang:
    return Lang(results.report.language if results.report is not None else "en")


#: the body, in the order Italian reviewers expect (the same for every language); True: the
#: section starts on a new page
BODY: tuple[tuple[Callable[[AssessmentResult, Lang], list[Block]], bool], ...] = (
    (body_front.introduction, False),
    (body_front.codes, False),
    (body_front.wall, False),
    (loads_section.section, False),  # docs/model.md §12: nothing without loads
    (body_front.category, False),
    (body_front.knowledge_section, False),
    (body_front.materials, False),
    (body_analysis.seismic, True),
    (body_analysis.method, True),
    (body_checks.as_is, True),
    (body_checks.retrofit, True),
    (body_software.section, True),
    (body_closing.conclusions, True),
    (body_closing.appendix, True),
)


def number_headings(blocks: list[Block]) -> list[Block]:
    """Level-1 and level-2 headings numbered 1, 1.1... (a heading whose text starts with a
    capital letter and a dot or space-dash, an appendix, keeps its text)."""
    out: list[Block] = []
    h1_n = h2_n = 0
    for b in blocks:
        if isinstance(b, Heading) and b.level in (1, 2):
            if b.level == 1:
                h1_n, h2_n = h1_n + 1, 0
                b = Heading(f"{h1_n}  {b.text}", 1)
            else:
                h2_n += 1
                b = Heading(f"{h1_n}.{h2_n}  {b.text}", 2)
        out.append(b)
    return out


def build_blocks(results: AssessmentResult) -> list[Block]:
    """The blocks of the report, in order: title, numbered body, appendix A and the annex B
    of calculation details."""
    lang = _lang(results)
    body: list[Block] = []
    for part, new_page in BODY:
        if part is body_closing.appendix:
            break
        blocks = part(results, lang)
        body += [page_break() if new_page else cond_break(40 * MM), *blocks]
    story: list[Block] = body_front.title(results, lang) + number_headings(body[1:])
    story += [page_break(), *_appendix(results, lang)]
    story += [page_break(), *body_annex.annex(results, lang)]
    return engineer_blocks(story, results)


def _appendix(results: AssessmentResult, lang: Lang) -> list[Block]:
    out: list[Block] = []
    n = 0
    for b in body_closing.appendix(results, lang):
        if isinstance(b, Heading) and b.level == 2:
            n += 1
            b = Heading(f"A.{n}  {b.text}", 2)
        out.append(b)
    return out


def build_document(results: AssessmentResult) -> Document:
    """The report as a document model: what both renderers draw."""
    doc = document_head(results)
    doc.sections = split_sections(build_blocks(results))
    return doc


def document_head(results: AssessmentResult) -> Document:
    """The document's title, running header and footer, without its sections."""
    lang = _lang(results)
    p = results.project
    sw = results.software
    return Document(
        title=lang.t("doc.title", name=p.name or lang.t("title.unnamed")),
        header=lang.t("doc.header"),
        footer=lang.t(
            "doc.footer", software=sw.name, version=sw.version, date=lang.date(results.created)
        )
        + (f" · {results.input_file}" if results.input_file else ""),
        page_word=lang.t("doc.page", n="{n}", total="{total}"),
        author=p.engineer or "",
        language=lang.code,
        sections=[],
    )


def build_docx(results: AssessmentResult, out_path: Path | str) -> None:
    """Write the editable Word report to ``out_path`` atomically (byte-identical rebuilds)."""
    template = results.report.template if results.report is not None else None
    write_docx(build_document(results), out_path, created=results.created, template=template)
