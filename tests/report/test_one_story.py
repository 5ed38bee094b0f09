"""One story in every report (issue 39): the report says what results.json's decision says.

The bundled examples (projects/facade-laquila.yaml: 4 of 19 options pass, the verdict is not
robust; projects/facade-norcia-coordinates.yaml: Italian, the wall as it is passes while the
Circolare's static checks fail) and a project where nothing passes (data/nothing-passes.yaml)
are run (``frp-assess run --no-pdf``) and their reports built as document models, in English
and in Italian. Checked against the decision fields, never against the report's own helpers:

* every option's verdict cell, in the body's ranking and in the annex, is the decision's
  ``passes`` (the last turn's tests compared the cell with ``meets_target``, the IDA's target
  alone, and so certified "meets target: yes" for all 18 options while 4 passed);
* the wall as it is and the recommended (or closest) option are said to pass or not as the
  decision says, naming the governing check;
* whenever ``robustness.survives`` is false the robustness statement is there, and the
  sensitivity row of every convention under which the verdict flips reads FAIL;
* every probability of collapse is stated at FC·a_g·S, and the intensity written beside it is
  results.json's ``robustness.design_intensity`` (the console's).
"""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

import pytest

from frp_assess.cli import main
from frp_assess.numbers import recommendation_label, recommendation_text
from frp_assess.report import build_document
from frp_assess.report.doc_model import Keep, Para, Table, markup_text
from frp_assess.report.document import load_results
from frp_assess.report.lang import Lang
from frp_assess.results.model import AssessmentResult

ROOT = Path(__file__).resolve().parents[2]
PROJECTS = {
    "laquila": ROOT / "projects" / "facade-laquila.yaml",
    "norcia": ROOT / "projects" / "facade-norcia-coordinates.yaml",
    "nothing-passes": Path(__file__).with_name("data") / "nothing-passes.yaml",
}
#: the words of the verdict cells and sentences, as a reader finds them (en, it)
PASS_CELL = {"en": "pass", "it": "superate"}
FAIL_CELL = {"en": "FAIL", "it": "NON superate"}
PASSES = {"en": "passes every deciding check", "it": "supera tutte le verifiche determinanti"}
FAILS = {
    "en": "does NOT pass every deciding check",
    "it": "NON supera tutte le verifiche determinanti",
}
NOT_ROBUST = {
    "en": ("The verdict is NOT robust", "The verdict that no option passes"),
    "it": ("L'esito NON è robusto", "L'esito che nessuna soluzione supera"),
}
VERDICT_COLUMN = {
    "en": ("deciding checks", "deciding<br/>checks"),
    "it": ("verifiche determinanti", "verifiche<br/>determinanti"),
}
#: the last column of the sensitivity table (its verdict column is the one before)
GOVERNING_MARGIN = ("governing margin", "margine che governa")
#: how FC·a_g·S reads in a paragraph (markup) and in the English annex's plain text
FC_AGS = ("FC·ag·S", "FC·a_g·S")


def run(project: Path, out: Path) -> AssessmentResult:
    assert (
        main(["run", str(project), "--out", str(out), "--no-pdf", "--created", "2025-01-01"]) == 0
    )
    return load_results(out)


@pytest.fixture(scope="module", params=sorted(PROJECTS))
def results(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory):
    return request.param, run(PROJECTS[request.param], tmp_path_factory.mktemp(request.param))


def in_language(r: AssessmentResult, code: str) -> AssessmentResult:
    assert r.report is not None
    return replace(r, report=replace(r.report, language=code))


def blocks(r: AssessmentResult) -> tuple[list[str], list[Table]]:
    """The paragraphs (plain text) and the tables of the report's document model."""
    paras: list[str] = []
    tables: list[Table] = []

    def walk(items) -> None:
        for b in items:
            if isinstance(b, Para):
                paras.append(markup_text(b.markup))
            elif isinstance(b, Table):
                tables.append(b)
            elif isinstance(b, Keep):
                walk(b.blocks)

    walk(build_document(r).blocks())
    return paras, tables


def verdict_tables(tables: list[Table], code: str) -> list[tuple[Table, int]]:
    """(table, column) of every grid with a verdict column, one row per case (not the
    sensitivity table's, one row per model convention)."""
    out = []
    for t in tables:
        heads = [str(h) for h in t.header]
        if not heads or heads[-1] in GOVERNING_MARGIN:
            continue
        for i, h in enumerate(heads):
            if h in VERDICT_COLUMN[code] and t.kind == "grid":
                out.append((t, i))
    return out


@pytest.mark.parametrize("code", ["en", "it"])
def test_every_verdict_word_is_the_decision(results, code: str) -> None:
    name, r0 = results
    r = in_language(r0, code)
    paras, tables = blocks(r)
    text = "\n".join(paras)
    by_rank = {c.rank: c for c in r.options if c.rank is not None}
    found = verdict_tables(tables, code)
    assert found, f"{name}/{code}: no table with a verdict column"
    checked = 0
    for t, col in found:
        for row in t.rows:
            # the body's ranking and the Italian annex start with the rank; the English
            # annex's ranking with the rank, then the case's name
            case = r.case(row[1]) or by_rank.get(int(row[0]) if row[0].isdigit() else None)
            if row[1] == Lang(code).t("annex.urm"):  # the annex's name of the wall as it is
                case = r.urm
            if row[0] in ("—", "-") and case is None:
                case = r.urm
            assert case is not None, (name, code, row)
            assert case.passes is not None
            want = PASS_CELL[code] if case.passes else FAIL_CELL[code]
            assert row[col] == want, (name, code, case.name, row[col])
            checked += 1
    assert checked >= len(r.options)
    # the wall as it is: said to pass or not as decided, with its governing check
    urm_word = PASSES[code] if r.urm.passes else FAILS[code]
    assert urm_word in text
    # the recommended option passes; when nothing passes the closest is named and fails
    rec = r.case(r.recommended)
    if rec is not None:
        assert rec.passes
    else:
        closest = r.case(r.closest)
        assert closest is not None and not closest.passes
        assert not any(c.passes for c in r.options)
    # "margin 0.00 (≥ 1 passes)" read as a pass: every margin stated says on which side of 1
    for m in re.finditer(r"(margin|margine) (≥ )?(\d+[.,]\d\d)(?! [≥<] 1)", text):
        raise AssertionError(f"{name}/{code}: a margin without its comparison: {m.group(0)}")


@pytest.mark.parametrize("code", ["en", "it"])
def test_robustness_and_probability_of_collapse(results, code: str) -> None:
    name, r0 = results
    r = in_language(r0, code)
    paras, tables = blocks(r)
    text = "\n".join(paras)
    rob = r.robustness
    assert rob is not None
    if not rob.survives:
        assert any(p in text for p in NOT_ROBUST[code]), f"{name}/{code}: no robustness statement"
        flipped = [c.variant for c in rob.conventions if c.passes != rob.conventions[0].passes]
        sens = [t for t in tables if t.header and str(t.header[-1]) in GOVERNING_MARGIN]
        for t in sens:
            col = len(t.header) - 2
            for row, conv in zip(t.rows, rob.conventions, strict=True):
                want = PASS_CELL[code] if conv.passes else FAIL_CELL[code]
                assert row[col] == want, (name, code, conv.variant, row)
        if flipped:
            assert sens, f"{name}/{code}: the flip {flipped} is in no sensitivity table"
    # every probability of collapse at FC·a_g·S, the number beside it the decision's
    fc_ags = FC_AGS[0]
    word = "P(collapse)" if code == "en" else "P(collasso)"
    stated = [m.start() for m in re.finditer(re.escape(word), text)]
    assert stated, f"{name}/{code}: no probability of collapse stated"
    for i in stated:
        near = text[i : i + 130]
        assert any(f in near for f in FC_AGS), (name, code, near)
    x = f"{rob.design_intensity:.3f}"
    x = x.replace(".", ",") if code == "it" else x
    assert f"{fc_ags} = {x} g" in text
    for t in tables:
        for h in t.header:
            if word in markup_text(str(h)):
                assert any(f in markup_text(str(h)) for f in FC_AGS), (name, code, h)
    assert "at the demand a_g·S" not in text and "alla domanda ag·S" not in text


def test_robustness_sentence_and_console_line_say_what_the_decision_says(results) -> None:
    """results.json's ``robustness.summary`` and the console's decision line (``run``:
    ``recommendation_label: recommendation_text``) name an option as recommended only when
    the decision does (``recommended`` of a wall with ``retrofit_required``): Norcia's wall
    passes as it is, so its cheapest passing option is extra margin; when nothing passes the
    line does not start "Recommended"."""
    name, r = results
    rob = r.robustness
    assert rob is not None
    line = f"{recommendation_label(r)}: {recommendation_text(r)}"
    if not r.retrofit_required:
        assert "stays recommended" not in rob.summary, (name, rob.summary)
        assert rob.summary.startswith("no retrofit needed"), (name, rob.summary)
        assert line.startswith("Decision: no retrofit needed"), (name, line)
    elif r.recommended is None:
        assert line.startswith("Decision: none of the options passes"), (name, line)
        assert "recommended" not in rob.summary, (name, rob.summary)
    else:
        assert line.startswith(f"Recommended: {r.recommended}"), (name, line)
        assert rob.summary.count(r.recommended) >= 1, (name, rob.summary)
    if name == "norcia":  # the example this was seen on (issue 39)
        assert not r.retrofit_required and r.recommended is not None
    if name == "nothing-passes":
        assert r.recommended is None and r.retrofit_required


@pytest.mark.parametrize("code", ["en", "it"])
def test_optional_margin_is_not_called_the_verdict(results, code: str) -> None:
    """A wall that passes as it is (Norcia): the robust option is extra margin, and the
    report says so rather than that it "keeps" the verdict."""
    name, r0 = results
    r = in_language(r0, code)
    text = "\n".join(blocks(r)[0])
    rob = r.robustness
    assert rob is not None
    optional = {"en": "the cheapest option for extra margin", "it": "per un margine maggiore"}
    keeps = {"en": f"{rob.case} keeps it", "it": f"{rob.case} lo mantiene"}
    if rob.survives and not r.retrofit_required:
        assert optional[code] in text, (name, code)
        assert keeps[code] not in text, (name, code)
    elif rob.survives:
        assert keeps[code] in text, (name, code)
    if name == "norcia":  # the example this was seen on
        assert rob.survives and not r.retrofit_required


@pytest.mark.parametrize("code", ["en", "it"])
def test_the_ranking_caption_names_the_highlighted_row_as_the_decision_does(
    results, code: str
) -> None:
    """The annex's ranking table highlights results.json's `recommended` row; its caption
    names it as the decision does: the recommended option when a retrofit is required, the
    cheapest option for extra margin when the wall passes as it is (Norcia: it read
    "the recommended option" under "no retrofit is needed"), the best ranked when the input
    is not code-compliant."""
    name, r0 = results
    r = in_language(r0, code)
    text = "\n".join(blocks(r)[0])
    said = {
        "recommended": {
            "en": "Highlighted: the recommended option.",
            "it": "Evidenziata: la soluzione raccomandata.",
        },
        "optional": {
            "en": "Highlighted: the cheapest option for extra margin",
            "it": "Evidenziata: la soluzione più economica per un margine maggiore",
        },
    }
    if r.input_code_compliant and r.retrofit_required:
        assert said["recommended"][code] in text, (name, code)
    elif r.input_code_compliant:
        assert said["optional"][code] in text, (name, code)
        assert said["recommended"][code] not in text, (name, code)
    if name == "norcia":  # the example this was seen on
        assert not r.retrofit_required
