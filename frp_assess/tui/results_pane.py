"""The Results tab: ranking (sortable), IDA per record, FRP plot, fragility curves, bars as
built and pivot check, code checks and sensitivity, design mode, spectrum compliance.

Everything is read from the typed results of the run (:mod:`frp_assess.results.model`), as the PDF
report does.  The ranking (:mod:`frp_assess.tui.ranking_table`): the highlighted row is the
case shown in "Per record" and in the Time history tab.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial
from typing import Any, ClassVar

from rich import box
from rich.table import Table
from rich.text import Text
from textual import on
from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.widgets import DataTable, Label, Select, Static, TabbedContent, TabPane, Tabs

from frp_assess.results.model import AssessmentResult, CaseResult, RecordResult
from frp_assess.tui.core.fragility import lognormal_cdf
from frp_assess.tui.core.text import printable
from frp_assess.tui.literal import literal
from frp_assess.tui.plots import PlotView, Rule, Series
from frp_assess.tui.ranking_table import RankingTable
from frp_assess.tui.result_views import (
    bars_table,
    case_details,
    design_bars,
    floor_spectra_plot,
    fragility_plot,
    fragility_table,
    kinematic_table,
    pivot_table,
    sensitivity_table,
    summary_text,
)
from frp_assess.tui.tabbed import Tabbed

MATERIAL_STYLES = ("green", "yellow", "magenta", "cyan", "bright_blue", "red", "white")
POSITION_MARKERS = {"external": "●", "centred": "▲"}


def _num(value: Any, fmt: str) -> str:
    return "—" if value is None else format(value, fmt)


def _resurrection(rec: RecordResult) -> Text | str:
    """The smallest multiplier above the first collapse at which the wall stood again in the
    IDA (the curve shows it; the first collapse stays the result), or "—"."""
    first = rec.collapse_multiplier
    if first is None:
        return "—"
    again = [c for c, collapsed, _ in rec.curve if c > first and not collapsed]
    return Text(f"{min(again):.4f}", "yellow") if again else "—"


#: before the note of the Results tab and in its title when the project file changed since
#: the run shown (its digest is not the results', frp_assess/app/rerun.py)
STALE_NOTE = "stale: the project changed since this run.  "
STALE_TITLE = "Results (stale)"  #: short: the tab bar holds every tab at 100 columns
#: the note of the Results tab for a run of unsaved edits (tui/run_folders.py)
SCRATCH_NOTE = (
    "Results of unsaved edits (not the project file's: save, then ctrl+r, to keep them next "
    "to it), in a scratch folder: "
)


class ResultsPane(Vertical):
    """The results of the last run; ``[`` and ``]`` show the previous and next view.

    Its views (eight tabs of tables and plots) are made the first time they are needed: its
    tab shown, or results to show (:meth:`build`); results given before they are mounted
    are shown once they are (:meth:`when_ready`).  Most sessions never show results: an
    app that does not make them opens faster.
    """

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("left_square_bracket", "view(-1)", "◀ View"),
        Binding("right_square_bracket", "view(1)", "View ▶"),
    ]

    def action_view(self, step: int) -> None:
        """Show the previous (``step`` -1) or next (1) view of the results, cyclically, and
        put the focus on their tab bar (←/→ go on from there)."""
        if not self.ready or self.results is None:
            return
        tabs = self.query_one("#results-tabs", TabbedContent)
        ids = [pane.id for pane in tabs.query_children(TabPane) if pane.id]
        ids = ids or [pane.id for pane in tabs.query(TabPane) if pane.id]
        if tabs.active in ids:
            tabs.active = ids[(ids.index(tabs.active) + step) % len(ids)]
            tabs.query_one(Tabs).focus()

    def compose(self) -> ComposeResult:
        yield Static("No results yet: press ctrl+r to run the assessment.", id="results-note")

    def on_mount(self) -> None:
        self.results: AssessmentResult | None = None
        self.built = False  #: the views are made (mounted once ``ready``)
        self.ready = False
        self.waiting: list[Callable[[], object]] = []  #: called once the views are mounted

    def build(self) -> None:
        """Make the views (once)."""
        if self.built:
            return
        self.built = True
        self.mount_compose(self.views())
        self.call_next(self.views_made)  # after the mount (queued before it)

    def when_ready(self, callback: Callable[[], object]) -> bool:
        """True if the views are mounted; else ``callback`` is called once they are (they
        are made now if they are not yet)."""
        if not self.ready:
            self.waiting.append(callback)
            self.build()
        return self.ready

    def views(self) -> ComposeResult:
        """The views of the results, under the note."""
        tabs = Tabbed(id="results-tabs")
        tabs.display = False  # until there are results (never focused while hidden)
        with tabs:
            with TabPane("Ranking", id="res-ranking"):
                yield Static("", id="results-summary")
                yield RankingTable(id="ranking-table")
            with TabPane("Per record", id="res-records"):
                with Horizontal(classes="control-row"):
                    yield Label("Case ", classes="f-label-short")
                    yield Select(
                        [], id="case-select", compact=True, allow_blank=True, prompt="(run first)"
                    )
                yield Static("", id="case-summary")
                yield DataTable(id="records-table", zebra_stripes=True, cursor_type="row")
            with TabPane("FRP plot", id="res-plot"):
                with Horizontal(classes="control-row"):
                    yield Label("Plot ", classes="f-label-short")
                    yield Select(
                        [
                            ("improvement vs FRP mass", "improvement"),
                            ("capacity/demand vs FRP mass", "capacity_demand"),
                            ("capacity/demand vs cost", "capacity_demand_cost"),
                        ],
                        id="plot-metric",
                        value="improvement",
                        allow_blank=False,
                        compact=True,
                    )
                yield PlotView(id="frp-plot")
            with TabPane("Fragility", id="res-fragility"):
                with VerticalScroll(id="fragility-scroll"):
                    yield PlotView(id="fragility-plot")
                    yield Static("", id="fragility-table")
            with TabPane("Bars & pivot", id="res-bars"):
                with VerticalScroll(id="bars-scroll"):
                    yield Static("", id="bars-table")
                    yield Static("", id="pivot-table")
            with TabPane("Checks", id="res-checks"):
                with VerticalScroll(id="checks-scroll"):
                    yield Static("", id="kinematic-table")
                    yield Static("", id="sensitivity-table")
            with TabPane("Design", id="res-design"):
                with VerticalScroll(id="design-scroll"):
                    yield Static("", id="design-table")
            with TabPane("Compliance", id="res-compliance"):
                with VerticalScroll(id="compliance-scroll"):
                    yield Static("", id="compliance-summary")
                    yield Static("", id="compliance-table")
                    yield PlotView(id="compliance-plot")
                    yield PlotView(id="floor-plot")

    def views_made(self) -> None:
        """The views are mounted: their columns, and the results given meanwhile."""
        tables = self.query("#records-table")
        if not tables:
            return  # the app closing
        tables.first(DataTable).add_columns(
            *map(
                Text,
                (
                    "record",
                    "PGA [g]",
                    "C collapse",
                    "a_dyn [g]",
                    "q = a_dyn/a_RM",
                    "IDA runs",
                    "stands again at C",
                ),
            )
        )
        self.ready = True
        for callback in self.waiting:
            callback()
        self.waiting.clear()

    # ------------------------------------------------------------------------- display
    def show(
        self,
        results: AssessmentResult,
        out_dir: str,
        stale: bool = False,
        changed: bool = False,
        scratch: bool = False,
    ) -> None:
        """Show a run's results (``changed``: the project file changed since the run;
        ``scratch``: a run of unsaved edits, in a scratch folder)."""
        if not self.when_ready(partial(self.show, results, out_dir, stale, changed, scratch)):
            return
        self.results = results
        self._out_dir = out_dir
        self._scratch = scratch
        self.mark_stale(stale, changed)
        self.query_one("#results-tabs").display = True
        self._summary(results)
        self.query_one(RankingTable).show(results)
        sel = self.query_one("#case-select", Select)
        with self.app.prevent(Select.Changed):
            sel.set_options([(literal(c.name), i) for i, c in enumerate(results.cases)])
            sel.value = 0
        self.show_case(0)
        self.draw_plot()
        self._compliance(results)
        self._design(results)
        self._issue_views(results)
        self._floor_spectra(results)

    def _issue_views(self, r: AssessmentResult) -> None:
        """Fragility curves, bars as built, pivot check, code checks and sensitivity."""
        q = self.query_one
        series, options = fragility_plot(r)
        plot = q("#fragility-plot", PlotView)
        if series:
            plot.show(series, **options)
        else:
            plot.show_message("No lognormal fit: fewer than 2 distinct collapse values.")
        q("#fragility-table", Static).update(fragility_table(r))
        q("#bars-table", Static).update(bars_table(r))
        q("#pivot-table", Static).update(pivot_table(r))
        q("#kinematic-table", Static).update(kinematic_table(r))
        q("#sensitivity-table", Static).update(sensitivity_table(r))

    def mark_stale(self, stale: bool, changed: bool = False) -> None:
        """Say whether the project was edited after the run shown (``stale``: in the form;
        ``changed``: the project file's digest is not the results')."""
        if self.results is None:
            return
        self.query_one("#results-note", Static).update(
            Text.assemble(
                (STALE_NOTE if changed else "", "bold yellow"),
                (SCRATCH_NOTE, "bold yellow")
                if self._scratch
                else ("Results of the last run, in ", "dim"),
                (printable(f"{self._out_dir}/"), ""),
                ("  (edited since: ctrl+r to rerun)" if stale else "", "yellow"),
            )
        )

    def _summary(self, r: AssessmentResult) -> None:
        self.query_one("#results-summary", Static).update(summary_text(r))

    def show_case(self, index: int) -> None:
        """The IDA result per record of case ``index``."""
        r = self.results
        if r is None or not 0 <= index < len(r.cases):
            return
        c = r.cases[index]
        sel = self.query_one("#case-select", Select)
        if sel.value != index:
            with self.app.prevent(Select.Changed):
                sel.value = index
        table = self.query_one("#records-table", DataTable)
        table.clear()
        for rec in c.records:
            floor = rec.floor_pga
            table.add_row(
                literal(rec.record),
                f"{rec.pga:.4f}" + ("" if floor is None else f" (floor {floor:.4f})"),
                _num(rec.collapse_multiplier, ".4f")
                if rec.collapse_multiplier
                else Text("no collapse", "yellow"),
                _num(rec.a_dyn, ".4f"),
                _num(rec.q, ".3f"),
                str(len(rec.curve)) if rec.curve else "—",
                _resurrection(rec),
            )
        t = Text()
        t.append(printable(f"{c.name}: "), "bold")
        t.append(
            f"mean a_dyn = {c.mean_a_dyn:.4f} g, min = {c.min_a_dyn:.4f} g, "
            f"design a_dyn = {c.design_a_dyn:.4f} g, mean q = {c.mean_q:.2f}\n"
            f"capacity/demand = {c.capacity_demand:.3f}, improvement = "
            f"{c.improvement:.3f}, FRP {c.frp_mass:.1f} kg ({c.frp_mass_per_m:.2f} kg/m)"
        )
        if c.fc != 1.0:
            t.append(f"\ncapacity/demand = design a_dyn / (FC·a_g·S) with FC = {c.fc:.2f}")
        if c.lower_bound:
            t.append("\nsome record did not collapse up to C_max: lower bounds", "yellow")
        sc = c.scatter
        if sc:
            t.append(
                f"\nscatter over the records: median {sc.median_a_dyn:.4f} g, CoV "
                f"{sc.cov:.2f}, least favourable {c.min_a_dyn:.4f} g ("
            )
            t.append(printable(sc.least_favourable_record))
            t.append(")")
            fr = sc.fragility
            if fr:
                demand = c.fc * r.demand.pga  # the decision's demand, FC·a_g·S
                p = lognormal_cdf(demand, fr.median, fr.beta)
                shown = "< 0.1 %" if p < 1e-3 else f"{p:.1%}"
                t.append(
                    f"\nfragility (lognormal): median {fr.median:.4f} g, β = {fr.beta:.2f}; "
                    f"P(collapse) at FC·a_g·S = {demand:.3f} g: {shown}",
                    "yellow" if p >= 0.1 else "",
                )
        t.append_text(case_details(c))
        self.query_one("#case-summary", Static).update(t)

    @on(Select.Changed, "#case-select")
    def _case_selected(self, event: Select.Changed) -> None:
        event.stop()
        value = event.select.value  # the event may be older than the value shown
        if isinstance(value, int):
            self.show_case(value)

    @on(RankingTable.CaseChosen)
    def _case_chosen(self, event: RankingTable.CaseChosen) -> None:
        self.show_case(event.index)

    @on(Select.Changed, "#plot-metric")
    def _metric(self, event: Select.Changed) -> None:
        event.stop()
        self.draw_plot()

    def draw_plot(self) -> None:
        """Improvement or capacity/demand of every case against its FRP quantity."""
        r = self.results
        if r is None:
            return
        plot = self.query_one("#frp-plot", PlotView)
        metric = self.query_one("#plot-metric", Select).value
        by_cost = metric == "capacity_demand_cost"
        field = "capacity_demand" if by_cost else str(metric)
        xkey = "option_cost" if by_cost else "frp_mass"  # the cost: bars and tie
        groups: dict[tuple[str, str], list[CaseResult]] = {}
        for c in r.cases[1:]:
            kind = "tie" if c.tie is not None and c.material is None else ""
            groups.setdefault((c.material or kind, c.position or ""), []).append(c)
        materials = list(dict.fromkeys(m for m, _ in groups))
        series: list[Series] = []
        for (mat, pos), cases in groups.items():
            cases = sorted(cases, key=lambda c: getattr(c, xkey))
            style = MATERIAL_STYLES[materials.index(mat) % len(MATERIAL_STYLES)]
            xs = [getattr(c, xkey) for c in cases]
            ys = [getattr(c, field) for c in cases]
            if len(cases) > 1:
                series.append(Series(xs, ys, style=style))
            series.append(
                Series(
                    xs,
                    ys,
                    style=style,
                    kind="points",
                    label=f"{mat} {pos}",
                    marker=POSITION_MARKERS.get(pos, "■"),
                )
            )
        urm = r.cases[0]
        series.append(
            Series(
                [0.0],
                [getattr(urm, field)],
                style="white",
                kind="points",
                label="unreinforced",
                marker="○",
            )
        )
        rules = []
        if field == "capacity_demand":
            rules.append(Rule(r.model.target, "y", "red", "target"))
        ys_all = [y for s in series for y in s.y if y is not None]
        top = max([*ys_all, *(x.value for x in rules)]) if ys_all else 1.0
        xs_all = [x for s in series for x in s.x if x is not None]
        cur = r.costs.currency
        plot.show(
            series,
            x_range=(0.0, max(xs_all) * 1.05 if xs_all and max(xs_all) > 0 else 1.0),
            y_range=(0.0, top * 1.08),
            rules=rules,
            x_label=f"FRP cost [{cur}]" if by_cost else "FRP mass [kg]",
            y_label="capacity/demand" if field == "capacity_demand" else "improvement",
        )

    def _design(self, r: AssessmentResult) -> None:
        """Design mode: the smallest ratio meeting the target per material and position."""
        out = self.query_one("#design-table", Static)
        found = r.design
        if not found:
            out.update(Text("Design mode was off for this run (Analysis tab: Design mode).", "dim"))
            return
        cur = r.costs.currency
        table = Table(
            title=Text(f"Smallest ratio meeting the target C/D ≥ {r.model.target:g}", "bold"),
            title_justify="left",
            box=box.SIMPLE_HEAD,
            expand=True,
        )
        table.add_column(Text("material"), no_wrap=True)
        table.add_column(Text("position"), no_wrap=True)
        table.add_column(Text("ρ [‰]"), justify="right", no_wrap=True)
        table.add_column(Text("C/D"), justify="right", no_wrap=True)
        table.add_column(Text("FRP [kg]"), justify="right", no_wrap=True)
        table.add_column(literal(f"cost [{cur}]"), justify="right", no_wrap=True)
        built = [d.as_built for d in found]
        if any(b is not None for b in built):
            table.add_column(Text("bars as built"), no_wrap=True)
        table.add_column(Text("note"), ratio=1)
        for d, b in zip(found, built, strict=True):
            bars: list[Text] = []
            if any(x is not None for x in built):
                bars = [Text("—", "dim") if b is None else design_bars(b)]
            table.add_row(
                literal(d.material),
                literal(d.position),
                Text(_num(d.ratio, "g")),
                Text(_num(d.capacity_demand, ".2f")),
                Text(_num(d.frp_mass, ".1f")),
                Text(_num(d.frp_cost, ".0f")),
                *bars,
                literal(d.message, "dim"),
            )
        out.update(table)

    def _floor_spectra(self, r: AssessmentResult) -> None:
        """The records' mean floor spectrum next to the code's (a wall above ground)."""
        plot = self.query_one("#floor-plot", PlotView)
        series, options = floor_spectra_plot(r)
        plot.display = bool(series)
        if series:
            plot.show(series, **options)

    def _compliance(self, r: AssessmentResult) -> None:
        comp = r.compliance
        table = Table(box=box.SIMPLE_HEAD, expand=True, padding=(0, 1))
        table.add_column("", width=1, no_wrap=True)
        table.add_column("clause", ratio=3)
        table.add_column("requirement", ratio=4)
        table.add_column("found", ratio=4)
        table.add_column("margin", justify="right", no_wrap=True)
        for c in comp.checks:
            margin = f"{c.margin:+.1%}" if c.unit == "" else f"{c.margin:+g} {c.unit}"
            code = "EC8" if "1998" in c.code else "NTC" if "NTC" in c.code else c.code
            table.add_row(
                Text("✓", "green") if c.passed else Text("✗", "bold red"),
                literal(f"{code} {c.clause}"),
                literal(c.requirement),
                literal(c.found),
                Text(margin, "green" if c.passed else "red"),
            )
        self.query_one("#compliance-table", Static).update(table)
        s = r.seismic
        self.query_one("#compliance-summary", Static).update(
            Text.assemble(
                ("Spectrum compatibility of the records ", "bold"),
                (printable(f"({s.records_kind}, T1 = {s.t1:g} s): "), ""),
                ("all checks passed", "green") if comp.passed else ("some checks FAIL", "red"),
            )
        )
        self.query_one("#compliance-plot", PlotView).show(
            [
                Series(s.periods, s.target_sa, style="white", label="target"),
                Series(s.periods, s.mean_sa, style="cyan", label="mean of records"),
                Series(
                    s.periods,
                    [0.9 * v for v in s.target_sa],
                    style="grey50",
                    label="90 % target",
                ),
            ],
            x_range=(0.0, max(s.periods)),
            y_range=(0.0, 1.1 * max([*s.target_sa, *s.mean_sa])),
            x_label="T [s]",
            y_label="Se [g]",
        )
