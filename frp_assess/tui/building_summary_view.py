"""The building summary in the Results tab of a building file: ζ_E of every check per wall,
then the verdicts before and after the proposed retrofit, the totals and the governing wall,
the same cells as the console's tables (:mod:`frp_assess.results.building_rows`)."""

from __future__ import annotations

from rich import box
from rich.console import Group
from rich.table import Table
from rich.text import Text
from textual.app import ComposeResult
from textual.containers import VerticalScroll
from textual.widgets import Static

from frp_assess.results.building_rows import CHECK_HEADERS, check_rows, retrofit_rows
from frp_assess.results.building_summary import CHECK_COLUMNS, BuildingResults
from frp_assess.tui.core.text import printable


def _table(title: str, headers: list[str], rows: list[list[str]], text_columns: int) -> Table:
    t = Table(title=title, box=box.SIMPLE_HEAD, padding=(0, 1, 0, 0), show_edge=False)
    for i, h in enumerate(headers):
        t.add_column(h, justify="left" if i < text_columns else "right", overflow="fold")
    for r in rows:
        t.add_row(*(Text(printable(c)) for c in r))
    return t


def summary_renderable(b: BuildingResults) -> Group:
    """The two tables of the building summary and its closing lines."""
    checks = _table(
        "ζ_E of every check (the walls as they are)",
        ["wall", "α0", "a0* [g]", *(CHECK_HEADERS[k] for k, _ in CHECK_COLUMNS), "governing"],
        check_rows(b),
        1,
    )
    retrofits = _table(
        "Verdicts and proposed retrofits",
        [
            "wall",
            "as it is",
            "proposed retrofit (bars as built)",
            "retrofitted",
            "FRP [kg]",
            f"cost [{b.totals.currency}]",
        ],  # fmt: skip
        retrofit_rows(b),
        4,
    )
    t = b.totals
    margin = "unbounded" if t.governing_margin is None else f"ζ_E = {t.governing_margin:.2f}"
    lines = Text(
        printable(
            f"{t.walls} walls, {t.walls_failing} failing as they are; retrofit proposed for "
            f"{t.walls_retrofitted}: FRP {t.frp_mass:.1f} kg, {t.cost:,.0f} {t.currency} "
            f"(indicative)\ngoverning mechanism: {t.governing_wall} "
            f"({t.governing_check or '—'}, {margin})",
            newlines=True,
        )
    )
    head = Text(printable(f"Building summary: {b.project.name} (run of {b.created})"), "bold")
    return Group(head, checks, retrofits, lines)


class BuildingSummaryView(VerticalScroll):
    """The building summary (the first view of a building's results)."""

    DEFAULT_CSS = "BuildingSummaryView { height: 1fr; }"

    def compose(self) -> ComposeResult:
        yield Static("", id="building-summary")

    def show(self, b: BuildingResults | None, note: str) -> None:
        """Show the summary ``b``, or ``note`` (why there is none)."""
        self.query_one("#building-summary", Static).update(
            summary_renderable(b) if b is not None else Text(printable(note))
        )
