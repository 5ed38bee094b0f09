"""One story in every output (issue 39): for every case of the bundled examples (L'Aquila,
Norcia by its coordinates, Italian) and of a project where nothing passes, the verdict the
console prints (an 80-column terminal), the one in results.csv and the one in the TUI's
ranking equal results.json's decision; every demand a probability or a margin is stated at
is the decision's, FC·a_g·S; the robustness statement is printed whenever the verdict is not
robust.

Reference: results.json of the same run, read as plain JSON (not through the code that
writes the outputs): a case passes when ``passes`` is true; it is "recommended" only when it
is ``recommended`` for a wall with ``retrofit_required`` and code-compliant records
(docs/results-json.md, "The decision"), else it "passes"; it "fails" otherwise.
"""

from __future__ import annotations

import csv
import io
import json
import os
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from frp_assess.results.json_io import from_json
from frp_assess.results.model import AssessmentResult
from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.ranking_table import RANKING_COLUMNS, RankingTable
from frp_assess.tui.results_pane import ResultsPane
from tests.tui.conftest import run_async, settle

ROOT = Path(__file__).resolve().parents[2]

#: a wall no option saves: L'Aquila's spectrum, the two weakest options of the example
NOTHING_PASSES = """\
project: {name: Nothing passes}
wall: {thickness: 0.25, height: 4.5, length: 5.0, masonry: solid-brick-lime-mortar,
       mechanism: one-sided}
seismic:
  spectrum: {type: ntc2018, ag: 0.261, F0: 2.36, Tc_star: 0.347, soil: C, topography: T1}
  records:
    artificial: {count: 3, seed: 7, duration: 25.0, dt: 0.01}
  t1: 1.0
interventions:
  - {material: GFRP, position: centred, ratio: 1.0}
  - {material: BFRP, position: centred, ratio: 1.0}
costs: {currency: EUR, installation_per_metre: 100.0}
"""

#: the governing checks' short names in the console's and the TUI's ranking
SHORT = {"IDA capacity/demand": "IDA", "time history SLV": "TH SLV", "time history SLC": "TH SLC"}


@dataclass(frozen=True)
class Run:
    data: dict[str, Any]  #: results.json as plain JSON
    results: AssessmentResult
    console: str  #: what `frp-assess run` printed at 80 columns
    csv_text: str


#: results.csv's words when the report is Italian (docs/results-json.md, "results.csv")
ITALIAN_CSV = {
    "recommended": "proposta",
    "passes": "supera",
    "fails": "non supera",
    "IDA capacity/demand": "capacità/domanda IDA",
    "time history SLV": "verifica dinamica non lineare SLV",
    "time history SLC": "verifica dinamica non lineare SLC",
    "pivot check": "verifica alla cerniera",
}


def expected(data: dict[str, Any], case: dict[str, Any]) -> str:
    """The decision's word for ``case`` (the module docstring's reference)."""
    if not case["passes"]:
        return "fails"
    chosen = (
        case["name"] == data["recommended"]
        and data["retrofit_required"]
        and data["input_code_compliant"]
    )
    return "recommended" if chosen else "passes"


def run_cli(project: Path, out: Path) -> Run:
    """``frp-assess run`` as a user runs it, in an 80-column terminal."""
    env = {**os.environ, "COLUMNS": "80", "PYTHONPATH": str(ROOT)}
    cmd = [sys.executable, "-m", "frp_assess", "run", str(project), "--out", str(out)]
    done = subprocess.run([*cmd, "--no-pdf"], env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    text = (out / "results.json").read_text(encoding="utf-8")
    csv_text = (out / "results.csv").read_text(encoding="utf-8")
    return Run(json.loads(text), from_json(text), done.stdout, csv_text)


@pytest.fixture(scope="module")
def runs(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Run]:
    work = tmp_path_factory.mktemp("one-verdict")
    nothing = work / "nothing-passes.yaml"
    nothing.write_text(NOTHING_PASSES, encoding="utf-8")
    projects = {
        "laquila": ROOT / "projects" / "facade-laquila.yaml",
        "norcia": ROOT / "projects" / "facade-norcia-coordinates.yaml",
        "nothing": nothing,
    }
    return {name: run_cli(path, work / f"{name}-results") for name, path in projects.items()}


NAMES = ["laquila", "norcia", "nothing"]


def ranking_line(console: str, name: str) -> list[str]:
    """The words after the option's name on its line of the console's ranking table."""
    for line in console.splitlines():
        m = re.match(r"\s*(\d+|—)\s+(.*)$", line)
        if m and m.group(2).startswith(name + " "):
            return m.group(2)[len(name) :].split()
    raise AssertionError(f"{name} not in the ranking table")


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES)
def test_console_verdicts_are_the_decisions(runs: dict[str, Run], name: str) -> None:
    run = runs[name]
    data, out = run.data, run.console
    assert max(len(line) for line in out.splitlines()) <= 80
    for case in data["cases"]:
        words = ranking_line(out, case["name"])
        assert words[0] == expected(data, case), (case["name"], words)
        assert " ".join(words[1:]).startswith(SHORT[case["governing_check"]])
    # the decision's demand, named where margins and probabilities are stated
    fc_ags = data["cases"][0]["fc"] * data["demand"]["pga"]
    flat = " ".join(out.split())
    assert f"Retrofit options at FC·a_g·S = {fc_ags:.3f} g" in flat
    rob = data["robustness"]
    if rob["p_collapse"] is not None:
        assert f"at FC·a_g·S = {rob['design_intensity']:.3f} g is" in flat
        assert rob["design_intensity"] == pytest.approx(fc_ags)
    for said in re.findall(r"P\(collapse\)[^=]*?at ([^=]+?) =", flat):
        assert said.split()[-1] == "FC·a_g·S", said
    if not rob["survives"]:
        assert "Robustness: " in out and " ".join(rob["summary"].split()) in flat
    if not data["retrofit_required"]:  # Norcia: no option is called recommended
        assert "no retrofit needed" in flat and "(recommended)" not in flat
    if data["recommended"] is None:
        assert data["closest"] and f"the closest is {data['closest']}" in flat


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES)
def test_csv_verdicts_are_the_decisions(runs: dict[str, Run], name: str) -> None:
    run = runs[name]
    data = run.data
    italian = data["report"]["language"] == "it"
    assert run.csv_text.startswith("\ufeff")
    rows = list(csv.DictReader(io.StringIO(run.csv_text[1:]), delimiter=";" if italian else ","))
    by_name = {c["name"]: c for c in data["cases"]}
    assert {r["case"] for r in rows} == set(by_name)
    # an Italian report's words, as docs/results-json.md ("results.csv") lists them
    word = (lambda w: ITALIAN_CSV[w]) if italian else (lambda w: w)
    for row in rows:
        case = by_name[row["case"]]
        assert row["case_verdict"] == word(expected(data, case))
        assert row["case_governing_check"] == word(case["governing_check"])
        margin = float(row["case_governing_margin"].replace(",", "."))
        assert margin == pytest.approx(case["governing_margin"], abs=0.006)
        assert (margin >= 1.0) == (case["governing_margin"] >= 1.0)


@pytest.mark.slow
def test_tui_ranking_verdicts_are_the_decisions(runs: dict[str, Run]) -> None:
    verdict = [h for h, _, _ in RANKING_COLUMNS].index("verdict")
    option = [h for h, _, _ in RANKING_COLUMNS].index("option")
    governs = [h for h, _, _ in RANKING_COLUMNS].index("governs")

    async def body() -> None:
        app = FrpAssessApp(ROOT / "projects" / "facade-laquila.yaml")
        async with app.run_test(size=(120, 40)) as pilot:
            await pilot.pause()
            pane = app.query_one(ResultsPane)
            app.show_tab("tab-results")
            pane.show(runs[NAMES[0]].results, "out")
            await settle(pilot, lambda: bool(app.query(RankingTable)))
            table = app.query_one(RankingTable)
            for name in NAMES:
                run = runs[name]
                pane.show(run.results, "out")
                await settle(pilot, lambda r=run: pane.results is r.results)
                await settle(pilot, lambda r=run: table.row_count == len(r.data["cases"]))
                by_name = {c["name"]: c for c in run.data["cases"]}
                for i in range(table.row_count):
                    row = table.get_row_at(i)
                    case = by_name[str(row[option])]
                    assert str(row[verdict]) == expected(run.data, case), (name, case["name"])
                    assert str(row[governs]) == SHORT[case["governing_check"]]

    run_async(body)
