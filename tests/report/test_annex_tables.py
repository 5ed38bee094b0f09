"""The annex tables of the design mode, of the model conventions and of the anchorage, in
the report's language (frp_assess.report.annex_design_tables), through the document model
that both renderers (PDF, DOCX) draw."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path
from typing import Any

import pytest

from frp_assess.report.annex_design_tables import (
    anchorage_table,
    design_table,
    sensitivity_table,
    variant_words,
)
from frp_assess.report.doc_model import Heading, Table
from frp_assess.report.document import build_document
from frp_assess.report.lang import Lang
from frp_assess.results.json_io import from_data
from frp_assess.results.model import AssessmentResult, ReportSettings
from tests.report.test_report import DATA

ROOT = Path(__file__).resolve().parents[2]
#: a real run's results (the golden project "small"): options with their bars as built
SMALL = ROOT / "tests" / "golden" / "expected" / "small" / "results.json"
IT, EN = Lang("it"), Lang("en")


def _typed(data: dict[str, Any], language: str) -> AssessmentResult:
    result = from_data(AssessmentResult, data)
    assert isinstance(result, AssessmentResult)
    return dataclasses.replace(result, report=ReportSettings(language, None))


def _fixture(language: str = "it") -> AssessmentResult:
    return _typed(json.loads(DATA.read_text(encoding="utf-8")), language)


@pytest.mark.parametrize(
    ("variant", "italian"),
    [
        ("as assessed", "come valutato"),
        ("restitution: velocity", "restituzione: convenzione sulle velocità"),
        ("restitution: energy", "restituzione: convenzione energetica"),
        ("collapse: end-of-record", "collasso: rotazione oltre α al termine dell'accelerogramma"),
        (
            "collapse: first-exceedance",
            "collasso: rotazione che raggiunge α in un istante qualsiasi",
        ),
        ("collapse: overturning", "collasso: ribaltamento"),
        ("rupture: velocity-continuous", "rottura delle barre: velocità continua"),
        ("rupture: energy-transfer", "rottura delle barre: trasferimento di energia"),
        ("strain factor c = 0.5", "fattore di deformazione c = 0,5"),
        ("E -10% (41.4 GPa)", "E delle barre -10 % (41,4 GPa)"),
        ("E +10% (165 GPa)", "E delle barre +10 % (165 GPa)"),
        ("something new 2.5", "something new 2,5"),  # an unknown label: as written, numbers
    ],
)
def test_every_convention_label_in_italian(variant: str, italian: str) -> None:
    assert variant_words(variant, IT) == italian


def test_the_design_table_rows_and_a_material_without_answer() -> None:
    data = json.loads(DATA.read_text(encoding="utf-8"))
    data["design"][0].update(ratio=None, capacity_demand=None, frp_mass=None, frp_cost=None)
    table = design_table(_typed(data, "it"), IT)
    assert table is not None
    # the fixture's first two answers (GFRP and BFRP, centred): ρ 1.579 and 1.391 ‰,
    # capacity/demand 1.004, FRP 20.03 kg, cost 1140.4 EUR
    assert table.rows[0] == ["GFRP", "in mezzeria", "nessuno nell'intervallo", "—", "—", "—"]
    assert table.rows[1] == ["BFRP", "in mezzeria", "1,39", "1,00", "20,0", "1.140"]
    assert len(table.rows) == len(data["design"])
    data["design"] = None
    assert design_table(_typed(data, "it"), IT) is None


def test_the_sensitivity_table_changes_from_the_case_as_assessed() -> None:
    results = _fixture()
    table = sensitivity_table(results, IT)
    assert table is not None and results.sensitivity is not None
    rows = results.sensitivity.rows
    # velocity convention: 0.30882/0.33207 − 1 = −7.0 % (by hand from the fixture)
    assert table.rows[0][:3] == ["come valutato", "0,332", "+0,0"]
    assert table.rows[1][1:3] == ["0,309", "-7,0"]
    assert len(table.rows) == len(rows)


def test_the_anchorage_table_of_a_real_run() -> None:
    results = _typed(json.loads(SMALL.read_text(encoding="utf-8")), "it")
    table = anchorage_table(results, IT)
    built = [c for c in results.options if c.as_built is not None]
    assert table is not None and len(table.rows) == len(built)
    first = built[0].as_built
    assert first is not None
    # no bars.anchorage in the project: the force only, the other columns not checked
    assert table.rows[0][1] == IT.num(first.anchorage.design_force, 1)
    assert table.rows[0][2:] == ["—", "—", "—"]
    assert anchorage_table(_fixture(), IT) is None  # the fixture's options have no bars


def test_the_italian_annex_holds_the_three_tables_numbered_in_order() -> None:
    """The annex's sections B.1, B.2, ... in order, each subsection B.n.1, B.n.2, ... under
    its section (B.6, the retrofit as built, is left out when there is nothing to show)."""
    doc = build_document(_fixture("it"))
    heads = [b.text for b in doc.blocks() if isinstance(b, Heading) and b.text.startswith("B.")]
    numbers = [tuple(int(n) for n in h.split("  ")[0][2:].split(".")) for h in heads]
    sections = [n[0] for n in numbers if len(n) == 1]
    assert sections == sorted(set(sections)) and sections[:5] == [1, 2, 3, 4, 5]
    for prev, cur in zip(numbers, numbers[1:], strict=False):
        if len(cur) == 2:  # a subsection: the next of its section, or its first
            assert cur[0] == prev[0] and cur[1] == (prev[1] + 1 if len(prev) == 2 else 1), heads
    assert any("Modalità di progetto" in h for h in heads)
    assert any("convenzioni del modello" in h for h in heads)
    small = build_document(_typed(json.loads(SMALL.read_text(encoding="utf-8")), "it"))
    assert any(
        isinstance(b, Heading) and b.text.endswith("Ancoraggio delle barre") for b in small.blocks()
    )
    tables = [b for b in small.blocks() if isinstance(b, Table)]
    assert any("lunghezza di ancoraggio [m]" in b.header for b in tables)


def test_every_failure_mode_has_words_in_both_languages() -> None:
    """The conclusions name the wall's failure mode; "overturning" was printed in English
    in the Italian report."""
    from frp_assess.dynamics.rocking import FAILURE_MODES

    for mode in FAILURE_MODES:
        assert IT.has(f"failure:{mode}") and EN.has(f"failure:{mode}"), mode
    assert IT.t("failure:overturning") == "ribaltamento"
    data = json.loads(DATA.read_text(encoding="utf-8"))
    data["cases"][0]["failure_mode"] = "overturning"  # the wall as it is
    doc = build_document(_typed(data, "it"))
    text = " ".join(b.markup for b in doc.blocks() if hasattr(b, "markup"))
    assert "Modo di collasso della parete nello stato di fatto: ribaltamento." in text
