"""The ranking of the options (Results tab): ←/→ choose a column, ``s`` sorts by it (again:
reverse), enter shows the per-record IDA of the highlighted case."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any, ClassVar

from rich.text import Text
from textual.binding import Binding, BindingType
from textual.message import Message
from textual.widgets import DataTable, TabbedContent

from frp_assess.numbers import fmt_capacity, margin_text
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.results.verdict_words import FAILS, UNDECIDED, governing_short, verdict_word
from frp_assess.tui.core.text import printable
from frp_assess.tui.literal import literal, safe


def _text(value: Any) -> Text:
    """A table cell as plain text (a str cell would be read as Rich markup)."""
    return safe(value) if isinstance(value, Text) else literal(value)


def rank_cell(case: CaseResult) -> Any:
    """The rank, or ``dropped`` for an option that fails the pivot check (``case.pivot``;
    results without it show "—")."""
    if case.rank:
        return case.rank
    return Text("dropped", "red") if case.pivot is not None and case.pivot.dropped else "—"


#: (header, sort key, cell) of the ranking table; the cell takes the case and the results it
#: belongs to (C/D with "≥" before a lower bound, :func:`~frp_assess.numbers.fmt_capacity`
#: against the target; the verdict, governing check and margin of the decision,
#: :mod:`frp_assess.results.verdict_words`, the words of the console and results.csv)
RANKING_COLUMNS: list[
    tuple[str, Callable[[CaseResult], Any], Callable[[CaseResult, AssessmentResult], Any]]
] = [
    ("rank", lambda c: (c.rank is None, c.rank or 0), lambda c, _: rank_cell(c)),
    ("option", lambda c: c.name, lambda c, _: c.name),
    ("kg/m", lambda c: c.frp_mass_per_m, lambda c, _: f"{c.frp_mass_per_m:.2f}"),
    ("FRP kg", lambda c: c.frp_mass, lambda c, _: f"{c.frp_mass:.1f}"),
    ("cost", lambda c: c.option_cost, lambda c, _: f"{c.option_cost:.0f}"),
    ("a_dyn [g]", lambda c: c.design_a_dyn, lambda c, _: f"{c.design_a_dyn:.3f}"),
    ("q", lambda c: c.mean_q, lambda c, _: f"{c.mean_q:.2f}"),
    ("impr.", lambda c: c.improvement, lambda c, _: f"{c.improvement:.2f}"),
    ("C/D", lambda c: c.capacity_demand, lambda c, r: fmt_capacity(c, float(r.model.target))),
    ("verdict", lambda c: (c.passes is not True,), lambda c, r: verdict_cell(r, c)),
    (
        "governs",
        lambda c: c.governing_check or "",
        lambda c, _: governing_short(c.governing_check),
    ),
    (
        "margin",
        lambda c: -1.0 if c.governing_margin is None else c.governing_margin,
        lambda c, _: margin_text(c),
    ),
]


def verdict_cell(results: AssessmentResult, case: CaseResult) -> Any:
    """The decision's word (:func:`~frp_assess.results.verdict_words.verdict_word`):
    "recommended" or "passes" in green, "fails" in red, "—" for a case not decided (an
    older results file)."""
    word = verdict_word(results, case)
    if word == UNDECIDED:
        return word
    return Text(word, "red" if word == FAILS else "green")


def sorted_order(cases: Sequence[CaseResult], column: int, reverse: bool) -> list[int]:
    """Indices of the cases ordered by a ranking column (stable; ``rank`` puts the
    unreinforced wall last)."""
    key = RANKING_COLUMNS[column][1]
    return sorted(range(len(cases)), key=lambda i: key(cases[i]), reverse=reverse)


class RankingTable(DataTable[Any]):
    """The options, ranked; ``s`` sorts by the column under the cursor."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("s", "sort", "Sort"),
        Binding("enter", "show_case", "Per record", show=False),
    ]

    class CaseChosen(Message):
        """A case was highlighted (index in results.cases)."""

        def __init__(self, index: int) -> None:
            super().__init__()
            self.index = index

    def __init__(self, **kw: Any) -> None:
        super().__init__(cursor_type="cell", zebra_stripes=True, **kw)
        self.cases: Sequence[CaseResult] = []
        self.results: AssessmentResult | None = None
        self.order: list[int] = []
        self.sort_column = 0
        self.sort_reverse = False

    def show(self, results: AssessmentResult) -> None:
        """Show the cases of ``results`` with the decision on each."""
        self.results = results
        self.cases = results.cases
        self._fill()

    def _fill(self) -> None:
        row, col = self.cursor_coordinate
        self.clear(columns=True)
        for i, (header, _, _) in enumerate(RANKING_COLUMNS):
            if header == "cost" and self.results is not None:
                header = f"cost [{printable(self.results.costs.currency)}]"
            mark = (" ▼" if self.sort_reverse else " ▲") if i == self.sort_column else ""
            self.add_column(Text(header + mark))
        self.order = sorted_order(self.cases, self.sort_column, self.sort_reverse)
        results = self.results
        for i in self.order if results is not None else ():
            assert results is not None
            self.add_row(*[_text(cell(self.cases[i], results)) for _, _, cell in RANKING_COLUMNS])
        if self.cases:
            self.move_cursor(row=min(row, len(self.cases) - 1), column=col, animate=False)

    def sort_by(self, column: int) -> None:
        """Sort by ``column``; the same column again reverses the order."""
        if column == self.sort_column:
            self.sort_reverse = not self.sort_reverse
        else:
            self.sort_column, self.sort_reverse = column, False
        self._fill()

    def action_sort(self) -> None:
        self.sort_by(self.cursor_coordinate.column)

    def on_data_table_header_selected(self, event: DataTable.HeaderSelected) -> None:
        event.stop()
        self.sort_by(event.column_index)

    def selected_case(self) -> int | None:
        if not self.order:
            return None
        return self.order[min(self.cursor_coordinate.row, len(self.order) - 1)]

    def on_data_table_cell_highlighted(self, event: DataTable.CellHighlighted) -> None:
        i = self.selected_case()
        if i is not None:
            self.post_message(self.CaseChosen(i))

    def action_show_case(self) -> None:
        i = self.selected_case()
        if i is not None:
            self.post_message(self.CaseChosen(i))
            self.app.query_one("#results-tabs", TabbedContent).active = "res-records"
            self.app.call_after_refresh(self.app.query_one("#records-table").focus)
