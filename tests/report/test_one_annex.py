"""One annex for every language (issue 37 step 3b): the annex B of the English and of the
Italian report is built by one code path (report/body_annex.py) whose words come from the
catalogue, so both hold the same sections and the same tables with the same columns; the
only difference is the design mode's note, the run's English prose, which an English report
shows in a last column (report/formats.run_text)."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pytest

from frp_assess.report.doc_model import Block, Heading, Keep, Table
from frp_assess.report.document import build_document
from frp_assess.report.lang import Lang
from frp_assess.results.json_io import from_json
from frp_assess.results.model import ReportSettings
from tests.report.test_document_model import results_in

ROOT = Path(__file__).resolve().parents[2]
#: real runs' results (the golden projects): bars as built, loads, a wall above ground
RUNS = sorted((ROOT / "tests" / "golden" / "expected").glob("*/results.json"))


def annex_shape(code: str, path: Path | None = None) -> list[tuple[str, int, int]]:
    """The annex as (kind, size, rows) in order: ("h", level, 0) for a heading, ("t", columns,
    rows) for a table (the design table's note column left out), ("f", 0, 0) a figure."""
    if path is None:
        results = results_in(code)
    else:
        run = from_json(path.read_text(encoding="utf-8"), file=str(path))
        results = replace(run, report=ReportSettings(language=code))
    blocks = build_document(results).blocks()
    annex_title = Lang(code).t("h.annex")
    start = next(
        i for i, b in enumerate(blocks) if isinstance(b, Heading) and b.text == annex_title
    )
    note = Lang(code).t("annex.col.note")
    out: list[tuple[str, int, int]] = []

    def walk(items: list[Block]) -> None:
        for b in items:
            if isinstance(b, Heading):
                out.append(("h", b.level, 0))
            elif isinstance(b, Table):
                notes = sum(1 for h in b.header if str(h) == note)
                out.append(("t", len(b.widths) - notes, len(b.rows)))
            elif isinstance(b, Keep):
                walk(list(b.blocks))
            elif type(b).__name__ == "Figure":
                out.append(("f", 0, 0))

    walk(list(blocks[start:]))
    return out


def test_both_languages_have_the_same_annex() -> None:
    en, it = annex_shape("en"), annex_shape("it")
    assert len([k for k in en if k[0] == "h"]) >= 20  # B.1 ... B.7 and their subsections
    assert en == it


@pytest.mark.parametrize("path", RUNS, ids=lambda p: p.parent.name)
def test_both_languages_have_the_same_annex_for_a_real_run(path: Path) -> None:
    assert annex_shape("en", path) == annex_shape("it", path)


def test_the_design_note_is_the_one_english_only_column() -> None:
    """The design mode's note is the run's English prose: in the English annex only."""
    data = json.loads((ROOT / "tests" / "report" / "data" / "results.json").read_text())
    assert data["design"], "the fixture has design-mode answers"
    en, it = Lang("en"), Lang("it")
    en_heads = [
        [str(h) for h in b.header]
        for b in build_document(results_in("en")).blocks()
        if isinstance(b, Table)
    ]
    it_heads = [
        [str(h) for h in b.header]
        for b in build_document(results_in("it")).blocks()
        if isinstance(b, Table)
    ]
    assert sum(en.t("annex.col.note") in h for h in en_heads) == 1
    assert sum(it.t("annex.col.note") in h for h in it_heads) == 0
