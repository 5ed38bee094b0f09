"""The Results tab's views of issues 15-16: fragility curves (against scipy's lognormal),
bars as built, the pivot check, the code's kinematic checks and the sensitivity table.

The results are those of a real run of a small project; the fields added by issues 15-16
(``as_built``, ``pivot``, ``kinematic_checks``) are computed by their modules for the same
inputs and put on the result with :func:`dataclasses.replace`, as a run that writes them.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import pytest
from rich.console import Console
from scipy import stats
from textual.widgets import DataTable, Static, TabbedContent

from frp_assess.api import prepare_records, run_assessment
from frp_assess.assess.bars_as_built import option_as_built
from frp_assess.assess.from_project import inputs_from_project
from frp_assess.assess.kinematic_checks import IdaSummary, kinematic_checks
from frp_assess.assess.pivot_check import case_pivot
from frp_assess.config import load_project_text
from frp_assess.results.checks import CaseChecks, KinematicChecks
from frp_assess.results.model import AssessmentResult, DesignRow
from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.core.fragility import lognormal_cdf, pga_axis
from frp_assess.tui.main_tabs import MainTabs
from frp_assess.tui.plots import PlotView, render_plot
from frp_assess.tui.ranking_table import RANKING_COLUMNS, RankingTable
from frp_assess.tui.result_views import (
    bars_text,
    floor_spectra_plot,
    fragility_plot,
    kinematic_table,
)
from frp_assess.tui.results_pane import ResultsPane
from tests.report.test_checks_section import CAPACITY, LINEAR, _ls
from tests.report.test_report import raw, typed
from tests.tui.conftest import SMALL, run_async, settle
from tests.tui.test_app import SIZE

#: anchorage data, so that the pull-out cone is checked
ANCHORAGE = "bars: {anchorage: {hole_clearance: 6.0, bond_bar: 9.0, bond_masonry: 0.5}}\n"


def plain(widget: Static) -> str:
    """What a Static shows, as plain text on a wide console (tables unwrapped)."""
    console = Console(width=240, record=True, file=open("/dev/null", "w"))  # noqa: SIM115
    console.print(widget.content)
    return console.export_text()


@dataclass(frozen=True)
class Run:
    plain: AssessmentResult  #: as the run gives it
    full: AssessmentResult  #: with bars as built, pivot checks and kinematic checks


@pytest.fixture(scope="module")
def run(tmp_path_factory: pytest.TempPathFactory) -> Run:
    folder = tmp_path_factory.mktemp("views")
    project = load_project_text(SMALL + ANCHORAGE, "small.yaml", check_files=False).project
    inputs = inputs_from_project(project, folder, "small.yaml")
    results, _ = run_assessment(inputs, folder / "out", pdf=False, jobs=1)
    # the pivot of a weak masonry (0.2 MPa): the CFRP option's compressed zone is too deep
    weak = project.model_copy(
        update={"wall": project.wall.model_copy(update={"compressive_strength": 0.2})}
    )
    weak_inputs = inputs_from_project(weak, folder, "small.yaml")
    options = (None, *inputs.options)
    cases = tuple(
        replace(
            c,
            ratio_asked=None if o is None else o.asked,
            as_built=None if o is None else option_as_built(inputs, o),
            pivot=case_pivot(
                weak_inputs, None if o is None else weak_inputs.options[i - 1]
            ).result(),
        )
        for i, (c, o) in enumerate(zip(results.cases, options, strict=True))
    )
    ida = {c.name: IdaSummary(c.mean_a_dyn, c.min_a_dyn, len(c.records)) for c in results.cases}
    checks = kinematic_checks(inputs, records=prepare_records(inputs).records, ida=ida)
    full = replace(replace(results, cases=cases), kinematic_checks=checks)
    return Run(results, full)


# ------------------------------------------------------------------------------ fragility
def test_lognormal_cdf_is_scipys_lognormal():
    """P(a) = Φ(ln(a/θ)/β) is scipy's lognorm(s=β, scale=θ).cdf."""
    for median, beta in ((0.35, 0.3), (1.2, 0.05), (0.08, 0.9)):
        for a in (0.01, 0.5 * median, median, 1.7 * median, 5.0):
            expected = stats.lognorm(s=beta, scale=median).cdf(a)
            assert lognormal_cdf(a, median, beta) == pytest.approx(expected, abs=1e-12)
    assert lognormal_cdf(0.0, 0.3, 0.2) == 0.0
    with pytest.raises(ValueError):
        lognormal_cdf(0.1, 0.0, 0.2)


def test_the_pga_axis_reaches_past_every_curve_and_the_demand():
    xs = pga_axis([0.2, 0.5], [0.3, 0.1], demand=0.9, n=50)
    assert xs[0] == 0.0 and len(xs) == 50
    assert xs[-1] >= 1.2 * 0.9
    assert all(stats.lognorm(s=b, scale=m).cdf(xs[-1]) > 0.97 for m, b in ((0.2, 0.3), (0.5, 0.1)))


def test_fragility_plot_has_every_fitted_case_and_the_demand(run: Run):
    r = run.plain
    fitted = [c for c in r.cases if c.scatter.fragility is not None]
    assert fitted  # 3 records of a small wall: the fits exist
    series, options = fragility_plot(r)
    assert [s.label for s in series] == [c.name for c in fitted]
    (rule,) = options["rules"]
    # the decision's demand FC·a_g·S (tests/report/data, the small project: FC of LC2)
    demand = r.urm.fc * r.demand.pga
    assert rule.axis == "x" and rule.value == demand and "FC·a_g·S" in rule.label
    for s, c in zip(series, fitted, strict=True):
        fr = c.scatter.fragility
        assert fr is not None
        dist = stats.lognorm(s=fr.beta, scale=fr.median)
        assert list(s.y) == pytest.approx([dist.cdf(x) for x in s.x], abs=1e-12)
        # the probability the run reports at a_g·S lies on the curve drawn
        assert lognormal_cdf(r.demand.pga, fr.median, fr.beta) == pytest.approx(
            fr.p_collapse_at_demand, rel=1e-9, abs=1e-12
        )
    lines = render_plot(series, 80, 16, **options)
    assert "P(collapse)" in lines[0].plain and "PGA [g]" in lines[-1].plain


# ---------------------------------------------------------------------------- in the app
async def _show(pilot: Any, results: AssessmentResult) -> ResultsPane:
    app = pilot.app
    pane = app.query_one(ResultsPane)
    pane.show(results, "out")
    app.show_tab("tab-results")
    await settle(pilot, lambda: pane.results is results)
    return pane


@pytest.mark.slow
def test_the_results_views_are_made_when_first_needed(run: Run, small_project: Path):
    """Opening makes none of the Results tab's views (most sessions show no results); its
    tab shown without results focuses none of them; results given before the views are
    mounted are shown once they are."""

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            pane = app.query_one(ResultsPane)
            assert not pane.built and not app.query(RankingTable)
            await pilot.press("f9")
            await settle(pilot, lambda: pane.ready)
            await pilot.pause()
            assert not app.query_one("#results-tabs").display
            assert not isinstance(app.focused, RankingTable)  # hidden: never focused
            app.show_tab("tab-wall")
            await pilot.pause()

        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            pane = app.query_one(ResultsPane)
            pane.show(run.full, "out")
            assert pane.built and not pane.ready and pane.results is None
            await settle(pilot, lambda: pane.results is run.full)
            assert app.query_one("#results-tabs").display
            assert app.query_one(RankingTable).row_count == len(run.full.cases)

    run_async(body)


@pytest.mark.slow
def test_results_views_show_bars_pivot_checks_and_sensitivity(run: Run, small_project: Path):
    r = run.full

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            await _show(pilot, r)
            q = app.query_one
            tabs = q("#results-tabs", TabbedContent)
            for tab in ("res-fragility", "res-bars", "res-checks"):
                tabs.active = tab
                await settle(pilot, lambda tab=tab: tabs.active == tab)
            # fragility: every case in the table, with its fit
            frag = plain(q("#fragility-table", Static))
            for c in r.cases:
                assert c.name in frag
                fr = c.scatter.fragility
                if fr is not None:
                    assert f"{fr.median:.4f}" in frag and f"{fr.beta:.2f}" in frag
            # bars as built: n × Ød, spacing, installed vs asked, anchorage verdict
            bars = plain(q("#bars-table", Static))
            for c in r.options:
                b = c.as_built
                assert b is not None
                row = next(line for line in bars.splitlines() if c.name in line)
                assert bars_text(b) in row and f"{b.spacing:.2f}" in row
                assert f"{b.ratio_installed:.3f} / {c.ratio_asked:g}" in row
                cone = b.anchorage.cone_ok
                assert cone is not None and ("OK" if cone else "FAILS") in row
            # the base: x/B of every case, and its line (no option is dropped for it any
            # more: docs/model.md §1.1)
            pivot = plain(q("#pivot-table", Static))
            assert not any(c.pivot.dropped for c in r.cases)
            for c in r.cases:
                p = c.pivot
                row = next(line for line in pivot.splitlines() if line.lstrip().startswith(c.name))
                assert f"{p.depth_ratio:.3f}" in row
                assert ("dropped" if p.dropped else "holds") in row
                assert (
                    p.reason.startswith(f"{c.name}: ") and p.reason[len(c.name) + 2 :][:40] in row
                )
            # the code's checks: each case's ζ_E of every check, and its verdict
            checks = plain(q("#kinematic-table", Static))
            kc = r.kinematic_checks
            assert f"FC = {kc.fc:.2f}" in checks
            for cc in kc.cases:
                row = next(
                    line for line in checks.splitlines() if line.lstrip().startswith(cc.case)
                )
                for zeta in (cc.linear.zeta_e, cc.slv.zeta_e, cc.slc.zeta_e, cc.ida.zeta_e):
                    assert f"{zeta:.2f}" in row
                assert ("pass" if cc.passed else "FAIL") in row
            # sensitivity: one row per model convention
            sens = plain(q("#sensitivity-table", Static))
            assert r.sensitivity is not None and len(r.sensitivity.rows) > 1
            for row in r.sensitivity.rows:
                assert row.variant in sens and f"{row.design_a_dyn:.4f}" in sens
            # design mode: the answer's bars as built
            gfrp = r.cases[1]
            row = DesignRow("GFRP", "external", 1.0, gfrp.capacity_demand, 1.0, 2.0, "")
            pane = q(ResultsPane)
            pane.show(replace(r, design=(replace(row, as_built=gfrp.as_built),)), "out")
            design = plain(q("#design-table", Static))
            b = gfrp.as_built
            assert (
                f"{bars_text(b)} at {b.spacing:.2f} m /face, ρ {b.ratio_installed:.3f} ‰" in design
            )
            # the case summary of the Per record tab: its bars and its pivot
            pane.show_case(2)
            summary = plain(q("#case-summary", Static))
            c = r.cases[2]
            assert f"bars: {bars_text(c.as_built)}" in summary
            assert f"pivot: x/B = {c.pivot.depth_ratio:.3f}" in summary

    run_async(body)


@pytest.mark.slow
def test_the_focus_waits_for_the_results_views_to_be_mounted(run: Run, small_project: Path):
    """The Results tab's focus goes to the ranking table, which is mounted a moment after
    the views are made (:meth:`ResultsPane.build`).  A focus asked for in between used to
    look the table up before it existed and crash the app (NoMatches; seen in CI under
    load, 2026-11-26): it now waits for the views, then focuses the table."""

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            tabs = app.query_one("#tabs", MainTabs)
            pane = app.query_one(ResultsPane)
            pane.show(run.plain, "out")  # makes the views; they are not mounted yet
            tabs.active = "tab-results"
            assert not pane.ready and not app.query("#ranking-table")
            tabs.focus_in("tab-results")  # the lookup that crashed
            await settle(pilot, lambda: pane.ready and pane.results is run.plain)
            await settle(pilot, lambda: isinstance(app.focused, RankingTable))

    run_async(body)


@pytest.mark.slow
def test_results_without_the_new_fields_show_nothing_of_them(run: Run, small_project: Path):
    r = run.plain

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            bare = replace(
                r,
                cases=tuple(
                    replace(
                        c, as_built=None, pivot=None, scatter=replace(c.scatter, fragility=None)
                    )
                    for c in r.cases
                ),
                sensitivity=None,
            )
            bare = replace(bare, kinematic_checks=None)
            await _show(pilot, bare)
            q = app.query_one
            assert plain(q("#bars-table", Static)).strip() == "No bar layout in these results."
            assert plain(q("#pivot-table", Static)).strip() == "No pivot check in these results."
            assert "No kinematic checks" in plain(q("#kinematic-table", Static))
            assert "No sensitivity table" in plain(q("#sensitivity-table", Static))
            summary = plain(q("#case-summary", Static))
            assert "bars:" not in summary and "pivot:" not in summary
            # no case has a lognormal fit: no curve, a line saying why
            assert fragility_plot(bare) == ([], {})
            assert "No lognormal fit" in str(q("#fragility-plot", PlotView).render())

    run_async(body)


@dataclass(frozen=True)
class BuildingStandIn:
    """The attribute of ``results.building`` the TUI shows (W15's BuildingResult has more)."""

    shaken_by: str


@dataclass(frozen=True)
class FloorSpectraStandIn:
    """``results.floor_spectra``: 5 % spectra [g] at ``periods`` [s]."""

    periods: tuple[float, ...]
    mean: tuple[float, ...]
    code: tuple[float, ...]
    ground: tuple[float, ...]


@pytest.mark.slow
def test_dropped_options_floor_motion_and_fc_are_shown(run: Run, small_project: Path):
    """A wall above ground: the summary says what shook it, each record's floor PGA and the
    floor spectra show; an option dropped by the pivot check is marked in the ranking; the
    case summary states the FC dividing its capacity/demand."""
    r = run.full
    cases = []
    for i, c in enumerate(r.cases):
        records = tuple(replace(rec, floor_pga=2.0 * rec.pga) for rec in c.records)
        # a results file written when options could be dropped: the last one was
        dropped = i == len(r.cases) - 1
        c = replace(c, pivot=replace(c.pivot, dropped=dropped))
        cases.append(replace(c, records=records, fc=1.35, rank=None if dropped else c.rank))
    floor = FloorSpectraStandIn((0.0, 0.5, 1.0), (0.2, 0.6, 0.3), (0.25, 0.7, 0.2), (0.1, 0.3, 0.1))
    shown = replace(
        replace(r, cases=tuple(cases)),
        building=BuildingStandIn("the wall's base at Z = 9 m of a 3-storey building"),
        floor_spectra=floor,
    )

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            await _show(pilot, shown)
            q = app.query_one
            summary = plain(q("#results-summary", Static))
            assert "Shaken by: the wall's base at Z = 9 m of a 3-storey building" in summary
            table = q(RankingTable)
            ranks = {str(table.get_row_at(i)[1]): str(table.get_row_at(i)[0]) for i in range(3)}
            assert "dropped" in ranks.values()
            for c in shown.cases[1:]:
                assert (ranks[c.name] == "dropped") == c.pivot.dropped
            pane = q(ResultsPane)
            pane.show_case(1)
            case = shown.cases[1]
            assert "with FC = 1.35" in plain(q("#case-summary", Static))
            records = q("#records-table", DataTable)
            first = case.records[0]
            assert str(records.get_row_at(0)[1]) == f"{first.pga:.4f} (floor {2 * first.pga:.4f})"
            plot = q("#floor-plot", PlotView)
            assert plot.display
            labels = [s.label for s in floor_spectra_plot(shown)[0]]
            assert labels == [
                "code floor spectrum",
                "mean of the records' floor motions",
                "ground target",
            ]
            # results of a wall at ground level: no floor plot, no "Shaken by"
            await _show(pilot, r)
            assert not plot.display
            assert "Shaken by" not in plain(q("#results-summary", Static))

    run_async(body)


def test_kinematic_table_does_not_round_a_failing_zeta_to_one():
    """ζ_E = 0.997 fails (ζ_E ≥ 1 passes): the TUI shows "0.997", not "1.00", as the report
    does (tests/report/test_checks_section.py); 1.004 passes and shows "1.00"."""
    case = CaseChecks(
        "w",
        CAPACITY,
        LINEAR,
        _ls("SLV", 0.079, 0.2493, 0.997),
        _ls("SLC", 0.1, 0.251, 1.004),
        None,
        None,
    )
    checks = KinematicChecks("LC1", 1.35, "FC", True, 0.25, None, (case,))
    result = SimpleNamespace(kinematic_checks=checks, case=lambda name: None)
    table = kinematic_table(result)  # type: ignore[arg-type]
    console = Console(width=240, record=True, file=open("/dev/null", "w"))  # noqa: SIM115
    console.print(table)
    row = next(line for line in console.export_text().splitlines() if line.strip().startswith("w "))
    assert row.split()[1:4] == ["0.78", "0.997", "1.00"]


def test_ranking_cd_agrees_with_the_ida_check_and_shows_the_verdict():
    """C/D = 0.997 against a target of 1 does not meet it: the ranking table's C/D cell reads
    "0.997" (not "1.00"), as the CLI and the report (numbers.fmt_against); the verdict,
    governing check and margin are the decision's; a lower bound reads "≥"."""
    case = replace(
        typed(raw()).cases[1],
        capacity_demand=0.997,
        meets_target=False,
        lower_bound=False,
        passes=False,
        governing_check="time history SLV",
        governing_margin=0.22,
    )
    results = typed(raw())
    cells = {header: cell(case, results) for header, _, cell in RANKING_COLUMNS}
    assert cells["C/D"] == "0.997"
    assert cells["verdict"].plain == "fails"
    assert cells["governs"] == "TH SLV" and cells["margin"] == "0.22"
    passing = replace(case, capacity_demand=1.004, meets_target=True, lower_bound=True)
    assert {h: cell(passing, results) for h, _, cell in RANKING_COLUMNS}["C/D"] == "≥ 1.00"
