"""The report names the IDA capacity rule that ran (issue 38 item 2, docs/model.md §11).

Rendered as document models (what the PDF and the DOCX both draw), in English and Italian,
from results that ran each rule: tests/golden/expected/small (``capacity: effective``,
ladder 1.2) and tests/golden/expected/paper-reduced (``capacity: first-collapse``, the
paper's convention). Checked against results.json read
here with ``json`` (not through the report's helpers), in words written into this test:

* the settings row names the rule of ``model.ida.capacity``, and the method section gives
  the run's own ladder ratio, offset and bisection tolerance (effective) or step ratio;
* the per-record table of the wall as it is shows, with ``effective``, the capacity C, the
  first collapse headed as the paper's convention and the windows below C, each equal to
  results.json's ``collapse_multiplier``, ``first_collapse_multiplier``, ``windows_below``;
* no text describes the rule that did not run;
* the sensitivity table's numerical-spread row is explained, and a verdict on a collapse
  window (``robustness.on_collapse_window``) is said where the verdict is stated.
"""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest

from frp_assess.report import build_document
from frp_assess.report.doc_model import Heading, Keep, Para, Table, markup_text
from frp_assess.report.document import load_results
from frp_assess.results.model import AssessmentResult
from frp_assess.results.verdict import NearDemand

ROOT = Path(__file__).resolve().parents[2]
RUNS = {
    "small": ROOT / "tests" / "golden" / "expected" / "small",
    "paper-reduced": ROOT / "tests" / "golden" / "expected" / "paper-reduced",
}
#: the rule's name as the reader finds it, by results.json's model.ida.capacity
RULE_NAME = {
    "effective": {"en": "effective collapse intensity", "it": "intensità di collasso efficace"},
    "first-collapse": {
        "en": "first collapse (paper's convention)",
        "it": "primo collasso (convenzione dell'articolo)",
    },
}
PAPERS = {"en": "paper's convention", "it": "convenzione dell'articolo"}
SETTINGS_ROW = {"en": "capacity of a record", "it": "capacità di un accelerogramma"}
#: words that only the effective rule's description uses
EFFECTIVE_ONLY = {
    "en": (
        "effective collapse intensity",
        "Sampling.",
        "numerical spread",
        "windows below",
        "intensity of the IDA's ladder",
    ),
    "it": (
        "intensità di collasso efficace",
        "Campionamento.",
        "dispersione numerica",
        "finestre di",
        "intensità della scala",
    ),
}
#: words that only describe the first collapse as the capacity (today's paper wording)
FIRST_ONLY = {
    "en": (
        "C is the first collapse",
        "first collapse met by the search",
        "until the first",
        "to the collapse accelerations",
        "at the smallest multiplier",
    ),
    "it": (
        "C è il primo collasso",
        "primo collasso incontrato dalla ricerca",
        "fino al primo",
        "alle accelerazioni di collasso",
        "al moltiplicatore minore",
    ),
}
#: the paper's wording of the IDA, kept for first-collapse runs
PAPER_WORDING = {
    "en": "Each accelerogram is scaled by a growing multiplier C",
    "it": "Ciascun accelerogramma è scalato con un moltiplicatore C crescente",
}
NOT_UNCERTAINTY = {
    "en": "not the uncertainty of the capacity",
    "it": "non l'incertezza della capacità",
}
COLLAPSE_WINDOW = {
    "en": "The verdict sits on a collapse window",
    "it": "L'esito si trova su una finestra di collasso",
}
SPREAD_CAPTION = {
    "en": "It is not the uncertainty of the capacity",
    "it": "Non è l'incertezza della capacità",
}


def raw(name: str) -> dict[str, Any]:
    return json.loads((RUNS[name] / "results.json").read_text(encoding="utf-8"))


def in_language(r: AssessmentResult, code: str) -> AssessmentResult:
    assert r.report is not None
    return replace(r, report=replace(r.report, language=code))


def num(x: float, code: str, decimals: int = 3) -> str:
    text = f"{x:.{decimals}f}"
    return text.replace(".", ",") if code == "it" else text


def gnum(x: float, code: str) -> str:
    text = f"{x:g}"
    return text.replace(".", ",") if code == "it" else text


def model(r: AssessmentResult) -> tuple[list[str], list[Table], list[tuple[str, list[str]]]]:
    """Paragraphs (plain text), tables, and every section's heading with its paragraphs."""
    paras: list[str] = []
    tables: list[Table] = []
    sections: list[tuple[str, list[str]]] = [("", [])]

    def walk(items: Any) -> None:
        for b in items:
            if isinstance(b, Heading):
                sections.append((markup_text(b.text), []))
            elif isinstance(b, Para):
                paras.append(markup_text(b.markup))
                sections[-1][1].append(paras[-1])
            elif isinstance(b, Table):
                tables.append(b)
            elif isinstance(b, Keep):
                walk(b.blocks)

    walk(build_document(r).blocks())
    return paras, tables, sections


def every_text(paras: list[str], tables: list[Table]) -> str:
    cells = [
        markup_text(str(c))
        for t in tables
        for c in (*t.header, *(x for row in t.rows for x in row))
    ]
    return "\n".join([*paras, *cells])


@pytest.fixture(scope="module", params=sorted(RUNS))
def run(request: pytest.FixtureRequest) -> tuple[str, AssessmentResult, dict[str, Any]]:
    return request.param, load_results(RUNS[request.param]), raw(request.param)


@pytest.mark.parametrize("code", ["en", "it"])
def test_the_rule_named_is_the_one_that_ran(run, code: str) -> None:
    name, r0, d = run
    ida = d["model"]["ida"]
    rule = ida["capacity"]
    paras, tables, _ = model(in_language(r0, code))
    text = every_text(paras, tables)
    # the settings row (body; the English annex's "IDA capacity of a record" too)
    named = [row[1] for t in tables if t.kind == "key_value" for row in t.rows
             if isinstance(row[0], str) and row[0].endswith(SETTINGS_ROW[code])]  # fmt: skip
    assert named and all(v == RULE_NAME[rule][code] for v in named), (name, code, named)
    if rule == "effective":
        # the method section's sampling with the run's numbers
        sampling = next(p for p in paras if f"r = {gnum(ida['ladder_ratio'], code)}" in p)
        assert f"offset {gnum(ida['offset'], code)}" in sampling
        assert gnum(ida["tolerance"], code) in sampling
        for words in FIRST_ONLY[code]:
            assert words not in text, (name, code, words)
    else:
        # the paper's wording, the first collapse named as the paper's convention
        assert any(PAPER_WORDING[code] in p for p in paras), (name, code)
        rule_para = next(p for p in paras if FIRST_ONLY[code][1] in p)
        assert PAPERS[code] in rule_para
        assert gnum(ida["step_ratio"], code) in rule_para
        for words in EFFECTIVE_ONLY[code]:
            assert words not in text, (name, code, words)


@pytest.mark.parametrize("code", ["en", "it"])
def test_per_record_table_shows_capacity_and_first_collapse(run, code: str) -> None:
    name, r0, d = run
    rule = d["model"]["ida"]["capacity"]
    urm = d["cases"][0]
    _, tables, _ = model(in_language(r0, code))
    record_tables = [t for t in tables if t.kind == "grid" and "PGA [g]" in t.header
                     and len(t.header) in (5, 7) and "dyn" in str(t.header[3])
                     and len(t.rows) == len(urm["records"])]  # fmt: skip
    assert record_tables, (name, code)
    for t in record_tables:
        heads = [str(h) for h in t.header]
        assert RULE_NAME[rule][code].split(" (")[0] in heads[2], heads
        for row, rec in zip(t.rows, urm["records"], strict=True):
            assert row[0] == rec["record"]
            c = rec["collapse_multiplier"]
            if c is not None:
                assert row[2] == num(c, code)
        if rule == "effective":
            assert len(heads) == 7 and PAPERS[code] in heads[5], heads
            for row, rec in zip(t.rows, urm["records"], strict=True):
                first = rec["first_collapse_multiplier"]
                if first is not None:
                    assert row[5] == num(first, code)
                assert row[6] == str(rec["windows_below"])
        else:
            assert len(heads) == 5 and PAPERS[code] in heads[2], heads


@pytest.mark.parametrize("code", ["en", "it"])
def test_numerical_spread_row_is_explained_and_is_not_the_uncertainty(run, code: str) -> None:
    name, r0, d = run
    rows = (d.get("sensitivity") or {}).get("rows", [])
    spread_rows = [x for x in rows if x["variant"].startswith("numerical")]
    paras, _, _ = model(in_language(r0, code))
    captions = [p for p in paras if SPREAD_CAPTION[code] in p]
    assert bool(captions) == bool(spread_rows), (name, code)
    if spread_rows:
        # the method section says it too, with the case's CoV of a_dyn over the records
        case = next(c for c in d["cases"] if c["name"] == d["sensitivity"]["case"])
        cov = f"{100 * case['scatter']['cov']:.0f} %"
        assert any(cov in p and NOT_UNCERTAINTY[code] in p for p in paras), (name, code, cov)


@pytest.mark.parametrize("code", ["en", "it"])
def test_verdict_on_a_collapse_window_is_stated_with_the_verdict(code: str) -> None:
    r0 = load_results(RUNS["small"])
    assert r0.robustness is not None and not r0.robustness.on_collapse_window
    paras, _, _ = model(in_language(r0, code))
    assert not any(COLLAPSE_WINDOW[code] in p for p in paras)
    near = (NearDemand(0.98, True), NearDemand(1.02, False))
    rob = replace(r0.robustness, on_collapse_window=True, time_history_near_demand=near)
    paras, _, sections = model(in_language(replace(r0, robustness=rob), code))
    stated = [h for h, ps in sections if any(COLLAPSE_WINDOW[code] in p for p in ps)]
    # where the verdict of the wall and of the options is stated, and in the conclusions
    assert len(stated) >= 2, (code, stated)
    line = next(p for p in paras if COLLAPSE_WINDOW[code] in p)
    assert gnum(0.98, code) in line and gnum(1.02, code) in line


@pytest.mark.parametrize("code", ["en", "it"])
def test_the_early_stop_band_is_the_one_results_json_records(code: str) -> None:
    """The sampling paragraph and the IDA settings row give results.json's
    ``model.ida.early_stop_band`` (1.5 in the golden run), and follow it when it differs
    (1.75 here): the report reads the band from the run, not from a constant of its own."""
    d = raw("small")
    r0 = load_results(RUNS["small"])
    assert r0.model.ida.early_stop_band == d["model"]["ida"]["early_stop_band"] == 1.5
    other = replace(r0, model=replace(r0.model, ida=replace(r0.model.ida, early_stop_band=1.75)))
    for r, band in ((r0, gnum(1.5, code)), (other, gnum(1.75, code))):
        paras, tables = model(in_language(r, code))[:2]
        sampling = next(
            p for p in paras if f"r = {gnum(d['model']['ida']['ladder_ratio'], code)}" in p
        )
        assert f"{band} " in sampling, (code, sampling)
        rows = [str(row[1]) for t in tables if t.kind == "key_value" for row in t.rows
                if isinstance(row[1], str) and f"{band}×" in row[1]]  # fmt: skip
        assert rows, (code, band)
