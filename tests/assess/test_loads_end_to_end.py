"""A façade with a floor, a restrained roof, a thrust and a tie, assessed end to end
(tests/fixtures/facade-loads.yaml; docs/model.md §12).

The IDA's activation multiplier (a_RM/g of the kernel, from its per-side bracket) equals α₀
without ties of the code checks (the Circolare's eq. C8.7.1.1 summed term by term in
assess/loaded_capacity.py from rules/wall_loads.py) and the §10.2 hand check; the record's
capacity is a multiple of that a_RM; the tie is in the time histories (no warning says
otherwise).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from frp_assess.cli import main

FIXTURE = Path(__file__).resolve().parents[1] / "fixtures" / "facade-loads.yaml"


@pytest.mark.slow
def test_a_loaded_facade_runs_with_the_loads_in_the_time_histories(tmp_path: Path) -> None:
    out = tmp_path / "out"
    assert main(["run", str(FIXTURE), "--out", str(out), "--no-pdf", "--jobs", "1"]) == 0
    data = json.loads((out / "results.json").read_text(encoding="utf-8"))
    alpha0 = data["loads"]["overturning"]["alpha0_without_ties"]
    # hand: (43.2·0.2 − N₀·x₀/2 + 10·0.3 + 4·0.2 − 1·5.5)/(43.2·3 + 10·6) with the stress block
    assert 0.0 < alpha0 < 0.4 / 6.0
    checks = {c["name"]: c for c in data["independent_checks"]}
    activation = checks["activation multiplier"]
    assert activation["passed"]
    assert activation["value"] == pytest.approx(alpha0, rel=1e-9)
    assert activation["reference"] == pytest.approx(alpha0, rel=1e-9)
    # Housner's closed forms are for the bare block: not claimed for a loaded wall
    assert "free rocking period" not in checks and "energy at impact" not in checks
    (record,) = data["cases"][0]["records"]
    assert record["q"] == pytest.approx(record["a_dyn"] / alpha0, rel=1e-9)  # both in g
    assert not any("tie" in w for w in data["input_warnings"])


def test_thrusts_that_tip_the_wall_about_the_crushing_pivot_are_one_line(tmp_path: Path) -> None:
    """The schema refuses thrusts that tip the wall about its edge; with the stress block the
    pivot is x₀/2 inside the wall (docs/model.md §12): f_m = 0.5 MPa, LC1 (FC 1.35), N₀ = 43.2
    + 10 = 53.2 kN/m, x₀ = 53.2/(0.85·370) = 0.169 m, N₀·x₀/2 = 4.50 kNm/m; the moments that
    hold it, 8.64 + 3.0 − 4.50 = 7.14 kNm/m, fall below the thrust's 2·5.5 = 11 kNm/m:
    `validate` and `run` say so in one located line (exit 2), and nothing is written."""
    project = tmp_path / "tip.yaml"
    project.write_text(
        "project: {name: Tip}\n"
        "wall: {thickness: 0.4, height: 6.0, unit_weight: 18, compressive_strength: 0.5,\n"
        "       mechanism: one-sided,\n"
        "       loads: {top: [{load: 10.0, distance: 0.3}], thrust: [{force: 2.0, height: 5.5}]}}\n"
        "seismic:\n"
        "  spectrum: {type: preset, name: A2}\n"
        "  records: {artificial: {count: 1, seed: 1, duration: 13.5, dt: 0.05}}\n"
        "interventions:\n"
        "  - {material: GFRP, position: centred, ratio: 1}\n",
        encoding="utf-8",
    )
    assert main(["validate", str(project)]) == 2
    out = tmp_path / "out"
    assert main(["run", str(project), "--out", str(out), "--no-pdf"]) == 2
    assert not out.exists()


def test_the_tui_preview_shows_the_a_rm_the_run_computes_with_the_loads() -> None:
    """The derived values shown while the project is typed (app/preview.py) come from the
    model the run builds: with loads, a_RM of §12, not the bare wall's (B − x_W)/H."""
    from frp_assess.app.preview import wall_derived
    from frp_assess.app.project import load_project
    from frp_assess.assess.from_project import load_inputs

    project = load_project(FIXTURE).project
    shown = wall_derived(project.wall, project.analysis.pivot, project.code_check.knowledge_level)
    run = load_inputs(FIXTURE, warn=None).model_for(None).a_rm_g
    assert shown.a_rm == pytest.approx(run, rel=1e-12)
    bare = wall_derived(
        project.wall.model_copy(update={"loads": None}),
        project.analysis.pivot,
        project.code_check.knowledge_level,
    )
    assert bare.a_rm > 2 * shown.a_rm  # the floor's inertia and the thrust lower it
