"""One `frp-assess run` of a small project with a tie option, a bars option and both
(docs/model.md §12.2): results.json records each option's kind and tie with its steel and
cost by hand, the tie option's α₀ is eq. C8.7.1.1's with the tie by hand, the ranking follows
the decision's rule on the option's whole cost, and the console, results.csv and the report
(English and Italian) show the tie.

The wall: B = 0.4 m, H = 6 m, L = 6 m, w = 18 kN/m³, one-sided, the edge pivot (x₀ = 0), no
loads: W = 43.2 kN/m, W·B/2 = 8.64, W·H/2 = 129.6 kNm/m.  The tie: Ø20 (A_s = 314.159 mm²),
S235, every 3 m, 8 m long, at 5.5 m, no anchorage given: F_y = 314.159e-6·235e6/3 =
24.6091 kN/m, L_i = 24.6091·5.5 = 135.350 kNm/m, so α₀ = (8.64 + 135.350)/129.6 = 1.111036
against B/H = 0.0667 for the wall.  Steel 7850·314.159e-6·8 = 19.7292 kg per tie, 6.5764
kg/m, 39.458 kg over 6 m; one tie costs 19.7292·2 + 2·50 + 250 = 389.458, the wall 6/3 of
that, 778.917 EUR.
"""

from __future__ import annotations

import contextlib
import csv
import io
from collections.abc import Iterable
from dataclasses import replace
from pathlib import Path

import pytest

from frp_assess.cli import main
from frp_assess.report import build_document
from frp_assess.report.doc_model import Keep, Para, markup_text
from frp_assess.report.document import load_results
from frp_assess.results.model import AssessmentResult
from frp_assess.results.run_inputs import TiePricesResult

PROJECT = """\
project: {name: Tie option run}
wall: {thickness: 0.4, height: 6.0, length: 6.0, unit_weight: 18, mechanism: one-sided}
seismic:
  spectrum: {type: preset, name: A2}
  records: {artificial: {count: 1, seed: 1, duration: 13.5, dt: 0.02}}
interventions:
  - {type: tie, height: 5.5, diameter: 20, spacing: 3.0, length: 8.0}
  - {material: GFRP, position: external, ratio: 1}
  - {material: GFRP, position: external, ratio: 1,
     tie: {height: 5.5, diameter: 20, spacing: 3.0, length: 8.0}}
analysis: {pivot: edge}
costs: {tie_steel_per_kg: 2.0, tie_plate: 50, tie_installation: 250}
"""
TIE = "Tie Ø20 @ 3.0 m at 5.5 m"
BOTH = "GFRP external 1‰ + tie Ø20 @ 3.0 m at 5.5 m"


def _paragraphs(results: AssessmentResult) -> str:
    """The report's paragraphs (plain text), in its language."""
    out: list[str] = []

    def walk(items: Iterable[object]) -> None:
        for b in items:
            if isinstance(b, Para):
                out.append(markup_text(b.markup))
            elif isinstance(b, Keep):
                walk(b.blocks)

    walk(build_document(results).blocks())
    return "\n".join(out)


@pytest.fixture(scope="module")
def run(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, str]:
    folder = tmp_path_factory.mktemp("tie-run")
    path = folder / "p.yaml"
    path.write_text(PROJECT, encoding="utf-8")
    out = folder / "out"
    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        code = main(["run", str(path), "--out", str(out), "--no-pdf", "--jobs", "1"])
    assert code == 0
    return out, buffer.getvalue()


def test_results_record_the_tie_options_by_hand(run: tuple[Path, str]) -> None:
    out, _ = run
    r = load_results(out)
    urm, tie, bars, both = r.cases
    assert (tie.name, both.name) == (TIE, BOTH)
    assert (urm.kind, tie.kind, bars.kind, both.kind) == (None, "tie", None, "bars+tie")
    assert tie.material is None and tie.frp_cost == 0.0 and not tie.is_unreinforced
    assert tie.tie is not None and both.tie is not None and bars.tie is None
    q = tie.tie
    assert q.tie.yield_force == pytest.approx(24.6091, abs=5e-5)
    assert q.tie.capacity == q.tie.yield_force and q.tie.ductile
    assert q.steel_mass_per_m == pytest.approx(6.5764, abs=5e-5)
    assert q.steel_mass == pytest.approx(39.458, abs=5e-4)
    assert q.cost_per_tie == pytest.approx(389.458, abs=5e-4)
    assert q.cost == pytest.approx(778.917, abs=5e-4) and q.prices_given
    assert replace(both.tie, tie=replace(both.tie.tie, name=q.tie.name)) == q
    assert both.frp_cost == pytest.approx(bars.frp_cost) and both.frp_mass == bars.frp_mass
    assert both.option_cost == pytest.approx(bars.frp_cost + 778.917, abs=5e-4)
    assert r.costs.ties == TiePricesResult(2.0, 0.0, 50.0, 250.0)
    # the static α₀ of eq. C8.7.1.1, the tie at its capacity (module docstring)
    assert r.kinematic_checks is not None
    alpha0 = {c.case: c.linear.alpha0 for c in r.kinematic_checks.cases}
    assert alpha0[TIE] == pytest.approx(1.111036, abs=5e-7)
    assert alpha0[BOTH] == pytest.approx(1.111036, abs=5e-7)
    assert alpha0["Unreinforced"] == pytest.approx(0.4 / 6.0, rel=1e-9)


def test_the_ranking_is_the_decisions_rule_on_the_whole_cost(run: tuple[Path, str]) -> None:
    """Passing options first by cost (bars + tie), then the others by governing margin."""
    out, _ = run
    r = load_results(out)
    ranked = sorted(r.options, key=lambda c: c.rank or 0)
    passing = [c for c in ranked if c.passes]
    assert [c.option_cost for c in passing] == sorted(c.option_cost for c in passing)
    assert all(c.passes for c in ranked[: len(passing)])
    others = [c for c in ranked if not c.passes]
    margins = [c.governing_margin or 0.0 for c in others]
    assert margins == sorted(margins, reverse=True)
    if r.recommended is not None:
        assert r.recommended == passing[0].name


def test_console_csv_and_report_show_the_tie(run: tuple[Path, str]) -> None:
    out, console = run
    assert "tie options: cost = the bars + the ties" in " ".join(console.split())
    assert TIE in " ".join(console.split())
    rows = list(csv.DictReader(io.StringIO((out / "results.csv").read_text("utf-8-sig"))))
    by_case = {row["case"]: row for row in rows}
    assert by_case[TIE]["case_kind"] == "tie" and by_case[TIE]["case_tie_cost"] == "779"
    assert by_case[TIE]["case_option_cost"] == "779"
    assert by_case["Unreinforced"]["case_kind"] == "" and by_case[BOTH]["case_kind"] == "bars+tie"
    r = load_results(out)
    assert r.report is not None
    en = _paragraphs(r)
    assert "An option with tie-rods is the wall as it is" in en
    assert f"{TIE}: steel tie-rods Ø20 mm every 3 m at 5.5 m" in en
    assert "α0 = 1.1110 with the tie, against 0.0667 without it" in en
    it = _paragraphs(replace(r, report=replace(r.report, language="it")))
    assert "Una soluzione con catene è la parete allo stato di fatto" in it
    assert "catene in acciaio Ø20 mm ogni 3 m a quota 5,5 m" in it


def test_a_building_summary_counts_the_tie_in_the_proposed_retrofits_cost(
    run: tuple[Path, str],
) -> None:
    """The building summary's cost of a wall is its proposed option's, bars and tie-rods
    (docs/results-json.md, building files): with the bars-and-tie option proposed, the tie's
    778.917 EUR by hand (module docstring) is added to the bars' cost, and its 39.458 kg of
    steel are counted beside the FRP."""
    from frp_assess.results.building_summary import wall_summary

    out, _ = run
    results = load_results(out)
    proposed = replace(results, recommended=BOTH, retrofit_required=True)
    row = wall_summary("w", "walls/w", proposed)
    both = results.case(BOTH)
    assert row.frp_cost == both.frp_cost
    assert row.cost == pytest.approx(both.frp_cost + 778.917, abs=1e-3)
    assert row.tie_steel_mass == pytest.approx(39.458, abs=1e-3)
