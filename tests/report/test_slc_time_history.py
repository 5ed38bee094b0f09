"""The report shows the time-history check at SLC beside the one at SLV (Circolare 2019
§C8.7.1.2.1.9; docs/model.md, "Displacement-based checks"): both decide, so both are in the
per-case lines and the annex's checks table, in both languages and both renderers (one
document model).

The checks are built here with hand-picked peaks; every value the report must show is worked
out in the test from those inputs (ζ_E = d_limit / mean peak, displacements in mm)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from frp_assess.numbers import check_verdicts
from frp_assess.report.annex_checks import checks_table
from frp_assess.report.body_checks import _checks_lines
from frp_assess.report.doc_model import plain_texts
from frp_assess.report.document import build_document, build_docx
from frp_assess.report.lang import LANGUAGES, Lang
from frp_assess.results.checks import CaseChecks, KinematicChecks, TimeHistoryResult
from frp_assess.results.model import AssessmentResult
from tests.report.test_checks_section import CAPACITY, CHECKS, IDA, LINEAR, _ls
from tests.report.test_document_model import (
    ENGLISH,
    _squash,
    docx_texts,
    pdf_texts,
    results_in,
)

D0 = 0.197479  #: the bare wall's d0 = B/2 [m] (CAPACITY of test_checks_section)
D_SLV = 0.078991  #: 0.40·d0 [m]
D_SLC = 0.118487  #: 0.60·d0 [m]
AG_SLV, AG_SLC = 0.2952, 0.35481  #: a_g·S of each limit state [g] (site known)


def _th(ls: str, d_limit: float, a_g: float, peaks: tuple[float, float]) -> TimeHistoryResult:
    mean, top = sum(peaks) / len(peaks), max(peaks)
    ok = mean <= d_limit and top <= D0
    ratio = d_limit / mean
    return TimeHistoryResult(1.35, peaks, mean, top, D0, d_limit, top <= D0, mean <= d_limit,
                             ratio, ok, ls, min(ratio, D0 / top), a_g)  # fmt: skip


def _case(name: str, slv: tuple[float, float], slc: tuple[float, float]) -> CaseChecks:
    return CaseChecks(
        name,
        CAPACITY,
        LINEAR,
        _ls("SLV", D_SLV, 0.19337, 0.77348),
        _ls("SLC", D_SLC, 0.31157, 1.24628),
        _th("SLV", D_SLV, AG_SLV, slv),
        IDA,
        _th("SLC", D_SLC, AG_SLC, slc),
    )


#: the wall as it is passes both (SLC mean peak 90 mm ≤ 118.5 mm); the option (the fixture's
#: recommended one) passes at SLV and fails at SLC (mean peak 160 mm > 118.5 mm)
URM = _case("Unreinforced", (0.030, 0.050), (0.080, 0.100))
OPTION = _case("GFRP centred 2‰", (0.020, 0.030), (0.150, 0.170))
KC = replace(CHECKS, a_g=AG_SLV, floor=None, cases=(URM, OPTION))

#: ζ_E of each SLC check by hand: d_SLC / mean peak
ZETA_URM_SLC = D_SLC / 0.090  # 1.3165 → 1.32
ZETA_OPT_SLC = D_SLC / 0.160  # 0.7405 → 0.74


def _results(code: str) -> AssessmentResult:
    return replace(results_in(code), kinematic_checks=KC)


def th_rows(checks: KinematicChecks, code: str = "en") -> list[list[str]]:
    """The time-history rows of the annex's checks table of ``checks`` in language ``code``."""
    lang = Lang(code)
    table = checks_table(replace(results_in(code), kinematic_checks=checks), lang)
    assert table is not None
    th = lang.t("ax.chk.th", ls="", at="", what="").split()[0]  # "time", "analisi"
    return [r for r in table.rows if r[1].startswith(th)]


def test_the_checks_table_has_a_row_per_limit_state():
    """English checks table: SLV then SLC, each with its own a_g·S, d_limit and mean peak."""
    rows = th_rows(KC)
    assert [r[1] for r in rows[:2]] == [
        "time history SLV at a_g·S = 0.295 g: d_SLV vs mean peak",
        "time history SLC at a_g·S = 0.355 g: d_SLC vs mean peak",
    ]
    assert rows[1][2:] == [f"{1e3 * D_SLC:.1f} mm", "90.0 mm", f"{ZETA_URM_SLC:.2f}", "pass"]
    assert rows[3][2:] == [f"{1e3 * D_SLC:.1f} mm", "160.0 mm", f"{ZETA_OPT_SLC:.2f}", "FAIL"]
    assert rows[2][4:] == [f"{D_SLV / 0.025:.2f}", "pass"]  # the option passes at SLV


def test_results_without_the_slc_check_keep_one_row():
    """A file written before the SLC check (no time_history_slc, no a_g): one row, at SLV."""
    rows = [r[1] for r in th_rows(CHECKS)]
    assert rows == ["time history SLV: d_SLV vs mean peak"] * 2


@pytest.mark.parametrize(
    ("code", "zeta", "word"),
    [("en", f"{ZETA_OPT_SLC:.2f}", "NOT satisfied"),
     ("it", f"{ZETA_OPT_SLC:.2f}".replace(".", ","), "NON soddisfatta")],
)  # fmt: skip
def test_the_case_lines_name_the_slc_check(code: str, zeta: str, word: str):
    lang = Lang(code)
    line = _checks_lines(OPTION, lang)
    slv, slc = lang.t("check.th", ls="SLV"), lang.t("check.th", ls="SLC")
    assert slv != slc and slv.endswith("SLV") and slc.endswith("SLC")
    assert f"{slc}: ζ<sub>E</sub> = {zeta} ({word})" in line
    assert line.index(slv) < line.index(slc) < line.index("IDA")


@pytest.mark.parametrize("code", LANGUAGES)
def test_the_annex_table_has_an_slc_row(code: str):
    """The annex's checks table, in both languages: the SLV then the SLC time history of
    each case, ζ_E and the verdict worked out above."""
    lang = Lang(code)
    num = lang.num
    rows = th_rows(KC, code)
    assert [("SLV" in r[1], "SLC" in r[1]) for r in rows] == [(True, False), (False, True)] * 2
    assert rows[1][4:] == [num(ZETA_URM_SLC, 2), lang.t("ax.pass")]
    assert rows[3][4:] == [num(ZETA_OPT_SLC, 2), lang.t("ax.fail")]
    assert rows[2][4:] == [num(D_SLV / 0.025, 2), lang.t("ax.pass")]


def test_the_annex_table_of_an_older_file_has_no_slc_row():
    rows = th_rows(CHECKS, "it")
    assert len(rows) == len(CHECKS.cases) and not any("SLC" in r[1] for r in rows)


@pytest.mark.parametrize("code", LANGUAGES)
def test_both_renderers_show_the_slc_check(code: str, tmp_path: Path):
    """The whole report: the SLC check in the document model, the PDF and the DOCX alike."""
    results = _results(code)
    model = [_squash(t) for t in plain_texts(build_document(results))]
    out = tmp_path / "report.docx"
    build_docx(results, out)
    assert docx_texts(out) == model
    assert pdf_texts(results) == model
    text = "\n".join(model)
    slc = Lang(code).t("check.th", ls="SLC")
    zeta = Lang(code).num(ZETA_OPT_SLC, 2)
    assert f"{slc}: ζE = {zeta}" in text  # the recommended option's line
    assert f"{slc}: ζE = {Lang(code).num(ZETA_URM_SLC, 2)}" in text  # the wall as it is
    if code == "en":
        assert "time history SLC at a_g·S = 0.355 g: d_SLC vs mean peak" in text
    else:
        assert not ENGLISH.search(slc + Lang(code).t("ax.chk.lead"))


def test_the_short_check_names_tell_the_two_time_histories_apart():
    """The report's "passes …; fails …" lines: SLV and SLC named when both were run."""
    assert check_verdicts(OPTION)[3:] == [
        ("time history SLV", True),
        ("time history SLC", False),
        ("IDA", True),
    ]
    assert ("time history", False) in check_verdicts(CHECKS.cases[0])  # an older file


#: an option whose SLC mean peak is within d_SLC (110 mm ≤ 118.5 mm) but one record passes
#: d0 (210 mm > 197.5 mm): it fails, and its ζ_E is d0/largest = 0.9404, not d_SLC/mean =
#: 1.077 (a ζ_E above 1 beside "FAIL" is what the report printed before)
D0_GOVERNS = _case("CFRP external 1‰", (0.020, 0.030), (0.010, 0.210))
ZETA_D0 = D0 / 0.210  # 0.9404 → 0.94


@pytest.mark.parametrize("code", LANGUAGES)
def test_a_record_beyond_d0_gives_the_zeta_that_decides(code: str):
    """Circolare 2019 §C8.7.1.2.1.9 asks for both conditions; ζ_E = min(d_SLC/mean peak,
    d0/largest peak) worked out by hand above.  The checks table names the governing pair, the
    case line and the annex cell print ζ_E < 1 with the failure."""
    th = D0_GOVERNS.time_history_slc
    assert th is not None and not th.passed and th.ratio > 1.0
    rows = th_rows(replace(KC, cases=(D0_GOVERNS,)))
    row = next(r for r in rows if r[1].startswith("time history SLC"))
    assert row[1] == "time history SLC at a_g·S = 0.355 g: d0 vs largest peak"
    assert row[2:] == [f"{1e3 * D0:.1f} mm", "210.0 mm", f"{ZETA_D0:.2f}", "FAIL (d0 exceeded)"]
    lang = Lang(code)
    zeta = lang.num(ZETA_D0, 2)
    assert f"{lang.t('check.th', ls='SLC')}: ζ<sub>E</sub> = {zeta} (" in _checks_lines(
        D0_GOVERNS, lang
    )
    rows = th_rows(replace(KC, cases=(URM, D0_GOVERNS)), code)
    assert rows[3][4:] == [zeta, lang.t("ax.fail") + lang.t("ax.chk.d0_exceeded")]
