"""One document model, two renderers: the PDF and the DOCX show the same text, in English and
Italian; the catalogues agree; the report speaks to the engineer (no developer names)."""

from __future__ import annotations

import json
import re
import string
from dataclasses import replace
from importlib import resources
from pathlib import Path

import docx
import pytest
from reportlab.platypus import KeepTogether, Paragraph, Table

from frp_assess.report.doc_model import Document, markup_text, plain_texts
from frp_assess.report.document import build_document, build_docx
from frp_assess.report.lang import LANGUAGES, Lang
from frp_assess.report.pdf_document import build_report, build_story
from frp_assess.results.json_io import from_json
from frp_assess.results.model import AssessmentResult, ReportSettings
from tests.report.test_report import DATA


def results_in(code: str) -> AssessmentResult:
    base = from_json(DATA.read_text(encoding="utf-8"), file=str(DATA))
    return replace(base, report=ReportSettings(language=code))


def _squash(text: str) -> str:
    """Whitespace collapsed; a leading bullet dropped (Word draws it from the list style)."""
    return " ".join(text.split()).removeprefix("• ")


def pdf_texts(results: AssessmentResult) -> list[str]:
    """The text of the PDF story in order: paragraphs (headings included) and table cells, as
    the flowables hold it (``getPlainText`` would drop a line break between two words)."""
    out: list[str] = []

    def walk(flowables: list[object]) -> None:
        for f in flowables:
            if isinstance(f, Paragraph):
                out.append(markup_text(f.text))
            elif isinstance(f, Table):
                for row in f._cellvalues:
                    for cell in row:
                        out.append(markup_text(cell.text) if isinstance(cell, Paragraph) else cell)
            elif isinstance(f, KeepTogether):
                walk(f._content)

    walk(build_story(results))
    return [_squash(t) for t in out if str(t).strip()]


def _run_text(element: object) -> str:
    tag = str(getattr(element, "tag", ""))
    if tag.endswith("}t"):
        return str(getattr(element, "text", "") or "")
    return " " if tag.endswith("}br") else ""


def docx_texts(path: Path) -> list[str]:
    """The text of the Word file in body order: paragraphs and table cells."""
    d = docx.Document(str(path))
    out: list[str] = []
    for child in d.element.body.iterchildren():
        tag = child.tag.rsplit("}", 1)[-1]
        if tag == "p":
            out.append("".join(_run_text(t) for t in child.iter()))
        elif tag == "tbl":
            for tc in child.iter():
                if tc.tag.endswith("}tc"):
                    out.append("".join(_run_text(t) for t in tc.iter()))
    return [_squash(t) for t in out if t.strip()]


def renderers_agree(results: AssessmentResult, tmp_path: Path) -> list[str]:
    """The texts of the document model, asserted equal to the Word file's and the PDF's."""
    model = [_squash(t) for t in plain_texts(build_document(results))]
    out = tmp_path / "report.docx"
    build_docx(results, out)
    assert docx_texts(out) == model
    assert pdf_texts(results) == model
    return model


@pytest.mark.parametrize("code", LANGUAGES)
def test_pdf_and_docx_show_the_same_text(code: str, tmp_path: Path) -> None:
    renderers_agree(results_in(code), tmp_path)


def test_catalogues_have_the_same_keys_and_placeholders() -> None:
    cats = {}
    for code in LANGUAGES:
        path = resources.files("frp_assess.report").joinpath("catalogue", f"{code}.json")
        cats[code] = {
            k: v
            for k, v in json.loads(path.read_text(encoding="utf-8")).items()
            if not k.startswith("//")
        }
    en = cats["en"]
    fmt = string.Formatter()
    for code, cat in cats.items():
        assert set(cat) == set(en), code
        for key, text in cat.items():
            names = sorted(f[1] for f in fmt.parse(text) if f[1] is not None)
            assert names == sorted(f[1] for f in fmt.parse(en[key]) if f[1] is not None), key
            assert text.count("<b>") == text.count("</b>"), key
            assert text.count("<sub>") == text.count("</sub>"), key


def test_every_key_the_report_asks_for_is_in_both_catalogues() -> None:
    """Building both reports asks only for keys that exist (a KeyError would fail here)."""
    for code in LANGUAGES:
        assert plain_texts(build_document(results_in(code)))


def test_italian_numbers_have_the_decimal_comma() -> None:
    it, en = Lang("it"), Lang("en")
    assert (it.num(1234.5, 2, grouping=True), en.num(1234.5, 2, grouping=True)) == (
        "1.234,50",
        "1,234.50",
    )
    assert it.num(0.25) == "0,25" and it.gnum(1.35) == "1,35" and it.num(None) == "—"
    assert (
        it.numbers_in("0.2 and 1,000 but v1.2.3 and art-01")
        == "0,2 and 1.000 but v1.2.3 and art-01"
    )
    text = "\n".join(plain_texts(build_document(results_in("it"))))
    r = results_in("it")
    assert f"{r.wall.thickness:.2f} m".replace(".", ",") in text
    assert f"{r.wall.thickness:.2f} m" not in text


#: common English words that must not be left in the Italian report
ENGLISH = re.compile(r"\b(the|of the|and|with|wall|records?|which|is not|page)\b")


def test_the_italian_report_has_no_english_left() -> None:
    r = results_in("it")
    texts = plain_texts(build_document(r))
    user = {r.project.name, r.project.notes, r.project.location, r.project.engineer}
    user |= {rec.name for rec in r.records} | set(r.materials)
    names = re.compile(r"«[^»]*»")  # the worked cases are named as shipped
    left = [t for t in texts if t not in user and ENGLISH.search(names.sub("", t))]
    # user text (project name and notes) may be in any language; references keep their titles
    left = [t for t in left if not t.startswith("[") and r.project.notes not in t]
    assert left == []
    head = build_document(r)
    assert head.header.startswith("Verifica sismica") and "pagina" in head.page_word


#: what an engineer does not want to read: documentation files, keys of the project file,
#: library keys, snake_case words
DEVELOPER = re.compile(
    r"docs/|\.md\b|\b(analysis|bars|code_check|costs|wall|seismic|report|design)\.[a-z_]+"
    r"|[A-Za-z]{2,}_[A-Za-z]{2,}|\(ratio\)|\bpivot: |solid-brick|rubble-stone"
)


#: results of real runs: the golden projects' (tests/golden), written by `frp-assess run`
RUNS = sorted(Path(__file__).parents[1].glob("golden/expected/*/results.json"))


@pytest.mark.parametrize("code", LANGUAGES)
def test_no_developer_names_in_the_report(code: str) -> None:
    r = results_in(code)
    assert r.wall.masonry == "solid-brick-lime-mortar"  # the library key is in the results
    hits = [t for t in plain_texts(build_document(r)) if DEVELOPER.search(t)]
    assert hits == []


@pytest.mark.parametrize("path", RUNS, ids=lambda p: p.parent.name)
@pytest.mark.parametrize("code", LANGUAGES)
def test_no_developer_names_in_the_report_of_a_real_run(code: str, path: Path) -> None:
    """The prose that reaches the report from a run (layout notes, pivot reasons, ranking
    rule, the masonry's source) is put in words too."""
    run = from_json(path.read_text(encoding="utf-8"), file=str(path))
    r = replace(run, report=ReportSettings(language=code))
    texts = plain_texts(build_document(r))
    hits = [t for t in texts if DEVELOPER.search(t) and r.project.notes not in t]
    assert hits == []


def test_long_user_text_wraps_or_is_shortened_never_crashes(tmp_path: Path) -> None:
    """Text is data: a 600-character material name and a 200-character currency fit their
    cells (capped with an ellipsis or wrapped) in both renderers; results.json keeps all."""
    base = results_in("it")
    name = "Barra-" + "x" * 594
    currency = "EUR " * 50
    mats = {name if k == "GFRP" else k: v for k, v in base.materials.items()}
    cases = tuple(replace(c, material=name) if c.material == "GFRP" else c for c in base.cases)
    r = replace(base, materials=mats, cases=cases, costs=replace(base.costs, currency=currency))
    build_report(r, tmp_path / "long.pdf")
    build_docx(r, tmp_path / "long.docx")
    assert (tmp_path / "long.pdf").stat().st_size > 10_000
    for text in docx_texts(tmp_path / "long.docx"):
        assert len(text) <= 5000
    assert len(r.materials) == len(base.materials) and name in r.materials


def test_docx_rebuilds_byte_identical_and_takes_a_template(tmp_path: Path) -> None:
    r = results_in("en")
    build_docx(r, tmp_path / "a.docx")
    build_docx(r, tmp_path / "b.docx")
    assert (tmp_path / "a.docx").read_bytes() == (tmp_path / "b.docx").read_bytes()
    firm = docx.Document()
    firm.sections[0].header.paragraphs[0].text = "Studio Rossi – letterhead"
    firm.add_paragraph("template body, replaced by the report")
    firm.save(str(tmp_path / "firm.docx"))
    build_docx(
        replace(r, report=ReportSettings("it", str(tmp_path / "firm.docx"))), tmp_path / "t.docx"
    )
    out = docx.Document(str(tmp_path / "t.docx"))
    assert out.sections[0].header.paragraphs[0].text == "Studio Rossi – letterhead"
    body = [p.text for p in out.paragraphs]
    assert "template body, replaced by the report" not in body
    assert any(t.startswith("1  Premessa e oggetto") for t in body)


def test_a_template_that_is_not_a_word_file_is_one_line(tmp_path: Path) -> None:
    from frp_assess.errors import InputError

    bad = tmp_path / "firm.docx"
    bad.write_text("not a zip", encoding="utf-8")
    r = replace(results_in("en"), report=ReportSettings("en", str(bad)))
    with pytest.raises(InputError, match="Word template"):
        build_docx(r, tmp_path / "out.docx")
    assert not (tmp_path / "out.docx").exists()


def test_the_document_is_sections_of_blocks() -> None:
    doc = build_document(results_in("en"))
    assert isinstance(doc, Document)
    titles = [s.heading.text for s in doc.sections if s.heading is not None]
    assert titles[:3] == ["1  Introduction and scope", "2  Codes and standards",
                          "3  Description of the wall"]  # fmt: skip
    assert "11  Analyses and checks made with a computer program" in titles
    assert "Appendix A – Assumptions and references" in titles
    assert titles.index("Annex B – Calculation details") < titles.index("B.1  Summary")


def test_a_site_by_coordinates_is_stated_in_both_languages() -> None:
    """The site block of the results (V_N = 50 years, class II: C_U = 1, V_R = 50 years;
    SLV: P_VR = 10 %, T_R = −50/ln 0.9 = 474.6 years) opens the seismic action."""
    from types import SimpleNamespace

    slv = SimpleNamespace(P_VR=0.10, TR=474.56, TR_used=474.56, ag=0.261, F0=2.36, Tc_star=0.347)
    slc = SimpleNamespace(P_VR=0.05, TR=974.79, TR_used=974.79, ag=0.33, F0=2.4, Tc_star=0.36)
    site = SimpleNamespace(
        latitude=42.35, longitude=13.4, V_N=50.0, use_class="II", C_U=1.0, V_R=50.0,
        limit_states={"SLV": slv, "SLC": slc}, limit_state="SLV", nearest_node=1.23,
    )  # fmt: skip
    said = {
        "en": ("nominal life VN 50 years", "SLV 10 % 475"),
        "it": ("vita nominale VN 50 anni", "SLV 10 % 475"),
    }
    for code, (life, slv_row) in said.items():
        r = results_in(code)
        object.__setattr__(r, "site", site)  # the site helper's block, by attribute
        text = " ".join(plain_texts(build_document(r)))
        assert life in text and slv_row in text
    assert "0,2610 2,360 0,347 adottato" in text


@pytest.mark.parametrize(("code", "shown"), [("en", "2026-11-25"), ("it", "25/11/2026")])
def test_the_date_of_the_results_is_written_as_the_language_writes_it(code: str, shown: str):
    """The results' ISO date on the title, in the footer and in the closing note: ISO in
    English, DD/MM/YYYY in an Italian relazione (the date as the reviewer reads it)."""
    results = replace(results_in(code), created="2026-11-25")
    doc = build_document(results)
    texts = plain_texts(doc)
    assert shown in doc.footer
    assert sum(shown in t for t in texts) >= 2  # the subtitle and the closing note
    other = "25/11/2026" if code == "en" else "2026-11-25"
    assert not any(other in t for t in texts) and other not in doc.footer
    assert Lang(code).date("not a date") == "not a date"
