"""The building summary's two tables as rows of text: the checks' ζ_E per wall, then the
verdicts and proposed retrofits with the building's totals.  Shared by the console
(``frp-assess run BUILDING.yaml``) and the terminal UI's building summary view, so that both
show the same cells."""

from __future__ import annotations

from frp_assess.results.building_summary import CHECK_COLUMNS, BuildingResults, WallSummary
from frp_assess.results.verdict_words import governing_short

#: the console's short names of the checks (as the report's columns)
CHECK_HEADERS = {
    "linear": "lin.",
    "nonlinear_slv": "NL SLV",
    "nonlinear_slc": "NL SLC",
    "time_history_slv": "TH SLV",
    "time_history_slc": "TH SLC",
    "ida": "IDA",
}


def _zeta(x: float | None) -> str:
    return "—" if x is None else f"{x:.2f}"


def check_rows(b: BuildingResults) -> list[list[str]]:
    """The first summary table: per wall α₀, a₀* [g], ζ_E of every check and the
    governing check (of the wall as it is)."""
    return [
        [
            w.name,
            f"{w.alpha0:.3f}",
            f"{w.a0_star:.3f}",
            *(_zeta(getattr(w.unreinforced, key)) for key, _ in CHECK_COLUMNS),
            governing_short(w.unreinforced.governing_check),
        ]
        for w in b.walls
    ]


def _proposed(w: WallSummary) -> str:
    if not w.retrofit_required:
        return "none needed"
    if w.proposed is None:
        return "none passes" + (f" (closest: {w.closest})" if w.closest else "")
    return w.proposed + (f": {w.as_built}" if w.as_built else "")


def retrofit_rows(b: BuildingResults) -> list[list[str]]:
    """The second summary table: per wall the verdicts before and after the
    proposed retrofit, the retrofit with its bars as built, FRP mass [kg] and cost; then
    the building's totals."""
    rows = [
        [
            w.name,
            w.verdict_before,
            _proposed(w),
            w.verdict_after,
            "—" if w.frp_mass is None else f"{w.frp_mass:.1f}",
            "—" if w.cost is None else f"{w.cost:,.0f}",
        ]
        for w in b.walls
    ]
    t = b.totals
    rows.append(["building", "", "", "", f"{t.frp_mass:.1f}", f"{t.cost:,.0f}"])
    return rows


__all__ = ["CHECK_HEADERS", "check_rows", "retrofit_rows"]
