"""The Time history tab: θ/α(t) and bar strain(t) of a chosen case and record of the last run.

The multiplier C scales the record as in the IDA; by default it is just below the case's
collapse multiplier for that record (the most demanding motion it survives).  Buttons (or
keys ``c``/``b``/``1`` outside the multiplier field) set it at collapse, just below, or 1.
"""

from __future__ import annotations

from typing import ClassVar

from rich.text import Text
from textual import on, work
from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Horizontal, Vertical
from textual.message import Message
from textual.widgets import Button, Input, Label, Select, Static

from frp_assess.app.history import below_collapse
from frp_assess.dynamics.options import IDA_TOLERANCE
from frp_assess.results.model import AssessmentResult, RecordResult
from frp_assess.tui.core.session import HistoryData, RunOutcome, case_history
from frp_assess.tui.core.text import printable
from frp_assess.tui.fields import OrderedInput
from frp_assess.tui.literal import literal
from frp_assess.tui.plots import PlotView, Rule, Series


class HistoryDone(Message):
    """A time history computed (``data``), or why not (``error``)."""

    def __init__(self, data: HistoryData | None, error: str = "") -> None:
        super().__init__()
        self.data, self.error = data, error


class HistoryPane(Vertical):
    """Controls and the two plots; the history is computed in a worker thread."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("c", "preset('collapse')", "C collapse"),
        Binding("b", "preset('below')", "C below"),
        Binding("1", "preset('one')", "C=1"),
    ]

    def compose(self) -> ComposeResult:
        with Horizontal(classes="control-row"):
            yield Label("Case ", classes="f-label-short")
            yield Select([], id="hist-case", compact=True, prompt="(run first)")
            yield Label(" Record ", classes="f-label-short")
            yield Select([], id="hist-record", compact=True, prompt="(run first)")
        with Horizontal(classes="control-row"):
            yield Label("C ", classes="f-label-short")
            yield OrderedInput(id="hist-multiplier", compact=True, placeholder="multiplier")
            yield Button("at collapse", id="hist-collapse", compact=True)
            yield Button("just below", id="hist-below", compact=True)
            yield Button("C = 1", id="hist-one", compact=True)
            yield Static("", id="hist-error")
        yield Static("Run the assessment first (ctrl+r).", id="hist-info")
        yield PlotView(id="hist-theta")
        yield PlotView(id="hist-strain")

    def on_mount(self) -> None:
        self.outcome: RunOutcome | None = None
        self.results: AssessmentResult | None = None
        #: the IDA's bisection tolerance [-] of the results shown (the declared default before)
        self.tolerance: float = IDA_TOLERANCE.default
        self._needs_update = False

    def set_case(self, case: int) -> None:
        """Follow the case highlighted in the ranking (computed when the tab is shown)."""
        sel = self.query_one("#hist-case", Select)
        if self.results is None or sel.value == case:
            return
        with self.app.prevent(Select.Changed):
            sel.value = case
        self._needs_update = True

    def refresh_if_needed(self) -> None:
        """Compute the history if the case changed while the tab was hidden."""
        if self._needs_update:
            self._needs_update = False
            self.action_preset("below", quiet=True)

    # ------------------------------------------------------------------------ results
    def show_outcome(self, outcome: RunOutcome) -> None:
        """A new run (or the last one, reloaded): offer its cases and records."""
        self.outcome = outcome
        self.show_results(outcome.results)

    def show_results(self, results: AssessmentResult) -> None:
        """Offer the cases and records of ``results`` (of :attr:`outcome`)."""
        self.results = results
        self.tolerance = float(results.model.ida.tolerance)
        cases = self.query_one("#hist-case", Select)
        records = self.query_one("#hist-record", Select)
        with self.app.prevent(Select.Changed):
            cases.set_options([(literal(c.name), i) for i, c in enumerate(results.cases)])
            records.set_options([(literal(r.name), i) for i, r in enumerate(results.records)])
        gov = results.governing
        case, rec = 0, 0
        if gov:
            names = [c.name for c in results.cases]
            recs = [r.name for r in results.records]
            case = names.index(gov.case) if gov.case in names else 0
            rec = recs.index(gov.record) if gov.record in recs else 0
        with self.app.prevent(Select.Changed):
            cases.value = case
            records.value = rec
        self.select(case, rec)

    def select(self, case: int, record: int | None = None) -> None:
        """Show case ``case`` (and record ``record``) just below its collapse."""
        if self.results is None:
            return
        with self.app.prevent(Select.Changed):
            self.query_one("#hist-case", Select).value = case
            if record is not None:
                self.query_one("#hist-record", Select).value = record
        self.action_preset("below", quiet=True)

    def _current(self) -> tuple[int, int] | None:
        if not self.is_attached:
            return None
        c = self.query_one("#hist-case", Select).value
        r = self.query_one("#hist-record", Select).value
        if self.results is None or not isinstance(c, int) or not isinstance(r, int):
            return None
        return c, r

    def _ida_of_record(self) -> RecordResult | None:
        cur = self._current()
        if cur is None or self.results is None:
            return None
        return self.results.cases[cur[0]].records[cur[1]]

    def collapse_multiplier(self) -> float | None:
        rec = self._ida_of_record()
        return None if rec is None else rec.collapse_multiplier

    def action_preset(self, which: str, quiet: bool = False) -> None:
        """Set the multiplier (collapse, just below collapse, or 1) and compute."""
        cur = self._current()
        if cur is None:
            return
        c = self.collapse_multiplier()
        if which == "one" or c is None:
            value = 1.0
            if c is None and which != "one" and not quiet:
                self.app.notify(
                    "no collapse up to C_max for this record: C = 1 shown", markup=False
                )
        elif which == "collapse":
            value = c
        else:
            rec = self._ida_of_record()
            survivor = None if rec is None else rec.survivor_multiplier
            value = below_collapse(c, survivor, self.tolerance)
        inp = self.query_one("#hist-multiplier", Input)
        with self.app.prevent(Input.Changed):
            inp.value = f"{value:.6g}"
        self._request()

    def _request(self) -> None:
        cur = self._current()
        if cur is None:
            return
        text = self.query_one("#hist-multiplier", Input).value.strip()
        err = self.query_one("#hist-error", Static)
        try:
            value = float(text)
            if not value > 0 or value != value or value == float("inf"):
                raise ValueError
        except ValueError:
            err.update(Text(f"✗ expected a number > 0, found {text!r}", "red"))
            return
        err.update("")
        self.query_one("#hist-info", Static).update(Text("computing…", "dim"))
        if self.outcome is not None:
            self.compute(self.outcome, cur[0], cur[1], value)

    @work(thread=True, exclusive=True, group="history", exit_on_error=False)
    def compute(self, outcome: RunOutcome, case: int, record: int, multiplier: float) -> None:
        """The history of case ``case`` under record ``record`` scaled by ``multiplier``
        (in a worker thread; posts HistoryDone)."""
        try:
            data = case_history(outcome, case, record, multiplier)
        except Exception as exc:  # noqa: BLE001 - shown in the History tab
            self.post_message(HistoryDone(None, f"{type(exc).__name__}: {exc}"))
        else:
            self.post_message(HistoryDone(data))

    @on(HistoryDone)
    def _computed(self, message: HistoryDone) -> None:
        if not self.is_attached or self.app.return_code is not None:
            return  # the app is closing
        if message.data is not None:
            self.show_history(message.data)
        else:
            self.show_error(message.error)

    @on(Select.Changed, "#hist-case")
    @on(Select.Changed, "#hist-record")
    def _changed(self, event: Select.Changed) -> None:
        event.stop()
        self.action_preset("below")

    @on(Input.Submitted, "#hist-multiplier")
    def _submitted(self, event: Input.Submitted) -> None:
        event.stop()
        self._request()

    @on(Input.Changed, "#hist-multiplier")
    def _typed(self, event: Input.Changed) -> None:
        event.stop()  # not a project field; computed on enter

    @on(Button.Pressed)
    def _button(self, event: Button.Pressed) -> None:
        event.stop()
        which = {"hist-collapse": "collapse", "hist-below": "below", "hist-one": "one"}
        if event.button.id in which:
            self.action_preset(which[event.button.id])

    # ----------------------------------------------------------------------- display
    def show_history(self, h: HistoryData) -> None:
        """Plot a computed history."""
        info = Text()
        info.append(printable(h.case), "bold")
        info.append(printable(f" under {h.record} × C = {h.multiplier:.5g}: "))
        if h.collapsed:
            info.append("COLLAPSE", "bold red")
            if h.collapse_time is not None:
                info.append(f" at t = {h.collapse_time:.2f} s")
        else:
            info.append("survives", "bold green")
        info.append(f";  peak |θ|/α = {h.peak_ratio:.3f}, {h.impacts} impacts")
        if h.ruptures:
            info.append(", bar rupture at t = " + ", ".join(f"{t:.2f} s" for t in h.ruptures))
        c = self.collapse_multiplier()
        info.append(
            f"\nIDA collapse multiplier of this record: {c:.5g}"
            if c
            else "\nno collapse up to C_max in the IDA",
            "dim",
        )
        info.append("   (keys c, b, 1; or type C + enter)", "dim")
        self.query_one("#hist-info", Static).update(info)
        t = h.time.tolist()
        self.query_one("#hist-theta", PlotView).show(
            [Series(t, h.theta_over_alpha.tolist(), style="cyan", label="θ/α")],
            x_range=(0.0, max(t[-1], 1e-6) if t else 1.0),
            y_range=_sym_range(h.theta_over_alpha.tolist(), 1.0),
            rules=[
                Rule(1.0, "y", "red", "±1 overturning"),
                Rule(-1.0, "y", "red"),
                Rule(0.0, "y", "grey35"),
            ],
            x_label="t [s]",
            y_label="θ/α",
        )
        strain_plot = self.query_one("#hist-strain", PlotView)
        if not h.reinforced:
            strain_plot.show_message("unreinforced wall: no bars, no strain")
            return
        rules = []
        if h.rupture_strain is not None:
            rules.append(Rule(h.rupture_strain, "y", "red", f"ε_max = {h.rupture_strain:.4g}"))
        for tr in h.ruptures:
            rules.append(Rule(tr, "x", "yellow", "rupture"))
        top = max([*h.strain.tolist(), h.rupture_strain or 0.0, 1e-9])
        strain_plot.show(
            [Series(t, h.strain.tolist(), style="magenta", label="bar strain")],
            x_range=(0.0, max(t[-1], 1e-6) if t else 1.0),
            y_range=(0.0, top * 1.1),
            rules=rules,
            x_label="t [s]",
            y_label="ε [-]",
        )

    def show_error(self, message: str) -> None:
        self.query_one("#hist-info", Static).update(literal(f"✗ {message}", "red"))


def _sym_range(values: list[float], at_least: float, at_most: float = 2.0) -> tuple[float, float]:
    """A symmetric range showing ±1 (overturning); after a collapse θ/α grows without bound,
    so the range stops at ``at_most`` (the curve leaves the plot at the top or bottom)."""
    finite = [abs(v) for v in values if v == v]
    top = min(max([*finite, at_least]), at_most) * 1.1
    return -top, top
