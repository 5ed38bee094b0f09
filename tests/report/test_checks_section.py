"""The annex's section of the code's kinematic checks (frp_assess.report.annex_checks)."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace
from typing import Any

from reportlab.platypus import Paragraph, SimpleDocTemplate

from frp_assess.report import annex_checks
from frp_assess.report.formats import TableData
from frp_assess.report.lang import Lang
from frp_assess.report.render_pdf import flowables
from frp_assess.results.checks import (
    CapacitySummary,
    CaseChecks,
    FloorBasis,
    IdaCheck,
    KinematicChecks,
    LimitStateResult,
    LinearCheck,
    TimeHistoryResult,
)

CAPACITY = CapacitySummary(1.0, 2174.8, 0.9563, 0.9563, 0.197479, 0.0, None, None)
LINEAR = LinearCheck(0.09752, 0.125, 2.0, 0.7802, False)


def _ls(name: str, d: float, capacity: float, zeta: float) -> LimitStateResult:
    return LimitStateResult(
        name, d, 0.57, 1.9636, 0.08, 0.102125, 0.25, 0.0975, capacity, zeta, zeta >= 1.0
    )


def _case(name: str, th: TimeHistoryResult | None, ida: IdaCheck | None) -> CaseChecks:
    return CaseChecks(
        name,
        CAPACITY,
        LINEAR,
        _ls("SLV", 0.078991, 0.19337, 0.77348),
        _ls("SLC", 0.118487, 0.31157, 1.24628),
        th,
        ida,
    )


FELL = TimeHistoryResult(
    1.35, (0.01, None, 0.3), None, None, 0.197479, 0.078991, False, False, 0.0, False
)
QUIET = TimeHistoryResult(1.35, (0.0, 0.0), 0.0, 0.0, 0.197479, 0.078991, True, True, None, True)
IDA = IdaCheck(1.35, 0.25, 1.2, 0.9, "mean", 1.2, True)
CHECKS = KinematicChecks(
    "LC1",
    1.35,
    "FC = 1.35 (knowledge level LC1; a rigid block uses the FC of LC1).",
    True,
    0.25,
    FloorBasis(2 / 3, 3, 0.2598, 0.05, 2.15),
    (_case("Unreinforced", FELL, IDA), _case("CFRP <external> & 1‰", QUIET, None)),
)


EN = Lang("en")


def _results(checks: KinematicChecks) -> Any:
    """Results holding only ``checks`` (no case of results.json: cases named as checked)."""
    return SimpleNamespace(kinematic_checks=checks, cases=())


def checks_table(checks: KinematicChecks) -> TableData:
    table = annex_checks.checks_table(_results(checks), EN)
    assert table is not None
    return table


def curves_table(checks: KinematicChecks) -> TableData:
    table = annex_checks.curves_table(_results(checks), EN)
    assert table is not None
    return table


def checks_section(checks: KinematicChecks) -> list[Any]:
    return annex_checks.checks_section(_results(checks), EN)


def _text(flowables: list[object]) -> str:
    return " ".join(f.getPlainText() for f in flowables if isinstance(f, Paragraph))


def test_table_has_every_check_of_every_case():
    """Rows: linear, SLV, SLC, time history, IDA mean and least for the first case (6); no
    IDA line for the second (4).  ζ_E = capacity/demand as stored; a fall is stated."""
    data = checks_table(CHECKS)
    assert data.header == ["case", "check", "capacity", "demand", "ζ<sub>E</sub>", "verdict"]
    assert len(data.rows) == 10
    first = data.rows[:6]
    assert first[0] == [
        "Unreinforced",
        "linear: a0* vs demand/q",
        "0.098 g",
        "0.125 g",
        "0.78",
        "FAIL",
    ]
    assert first[1][2:] == ["0.193 g", "0.250 g", "0.77", "FAIL"]
    assert first[2][2:] == ["0.312 g", "0.250 g", "1.25", "pass"]
    assert first[3][2:] == ["79.0 mm", "fell", "0.00", "FAIL (d0 exceeded)"]
    # IDA capacity a_dyn/FC = ζ_E·a_g·S: 1.2·0.25 = 0.300 g, 0.9·0.25 = 0.225 g
    assert first[4][2:] == ["0.300 g", "0.250 g", "1.20", "pass"]
    assert first[5][2:] == ["0.225 g", "0.250 g", "0.90", "FAIL (not deciding)"]
    assert all(r[0] == "" for r in data.rows[1:6])
    assert data.rows[6][0] == "CFRP <external> & 1‰"
    assert data.rows[9][2:] == ["79.0 mm", "0.0 mm", "—", "pass"]


def test_tiny_displacements_and_large_ratios_stay_readable():
    """A mean peak of 0.039 mm is not shown as 0.0 mm, and d_SLV/mean = 2027 as "> 100"."""
    tiny = TimeHistoryResult(
        1.35, (3.9e-5,), 3.9e-5, 3.9e-5, 0.197479, 0.078991, True, True, 2025.4, True
    )
    checks = KinematicChecks("LC1", 1.35, "FC", True, 0.25, None, (_case("w", tiny, None),))
    row = checks_table(checks).rows[3]
    assert row[2:] == ["79.0 mm", "0.039 mm", "> 100", "pass"]


def test_zeta_just_below_one_is_not_rounded_to_a_pass():
    """ζ_E = 0.997 fails (ζ_E ≥ 1 passes): shown "0.997" beside FAIL, not "1.00" (2 decimals
    would round it across 1); 1.004 passes and stays "1.00"."""
    case = CaseChecks(
        "w",
        CAPACITY,
        LINEAR,
        _ls("SLV", 0.078991, 0.2493, 0.997),
        _ls("SLC", 0.1, 0.251, 1.004),
        None,
        None,
    )
    rows = checks_table(KinematicChecks("LC1", 1.35, "FC", True, 0.25, None, (case,))).rows
    assert rows[1][4:] == ["0.997", "FAIL"]
    assert rows[2][4:] == ["1.00", "pass"]


def test_curves_table_in_mm_and_seconds():
    data = curves_table(CHECKS)
    assert data.rows[0][:5] == ["Unreinforced", "0", "197.5", "79.0", "1.964"]


def test_section_states_fc_and_the_floor_and_renders(tmp_path: Path):
    story = flowables(checks_section(CHECKS))
    text = _text(story)
    assert "FC = 1.35 (knowledge level LC1" in text
    assert "Z/H = 0.67 of a 3-storey building" in text
    assert "Some code checks fail" in text
    out = tmp_path / "checks.pdf"
    SimpleDocTemplate(str(out)).build(story)
    data = out.read_bytes()
    assert data.startswith(b"%PDF") and len(data) > 2000
