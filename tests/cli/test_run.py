"""`frp-assess run`: a project file end to end, its errors, the cache, the worked examples."""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import pytest

from frp_assess.app.rerun import SIDECAR
from frp_assess.assess.from_project import load_inputs
from frp_assess.assess.inputs import ArtificialRecords, RecordFile
from frp_assess.cli import main
from frp_assess.config import FRP_MATERIALS
from frp_assess.numbers import recommendation_label, recommendation_text
from frp_assess.results.json_io import from_json

ROOT = Path(__file__).resolve().parents[2]
BROKEN = ROOT / "tests" / "config" / "broken"

SMALL = """\
project: {name: "Small <&> wall", engineer: Test}
wall: {thickness: 0.3, height: 3.0, length: 5.0, unit_weight: 18.0, mechanism: one-sided}
seismic:
  spectrum: {type: preset, name: A2}
  records:
    artificial: {count: 3, seed: 7, duration: 14.0, dt: 0.01}
materials:
  GFRP: {price: 9.0}
interventions:
  - {material: GFRP, position: external, ratio: 1.0}
  - {name: my carbon, material: CFRP, position: centred, ratio: 2}
costs: {currency: EUR, installation_per_metre: 100.0}
"""


def test_small_project_end_to_end_and_instant_rerun(tmp_path, capsys):
    """The whole run writes every result file; a rerun computes nothing (all from the cache)
    and gives the same results.json."""
    project = tmp_path / "small.yaml"
    project.write_text(SMALL, encoding="utf-8")
    assert main(["run", str(project), "--no-pdf", "--jobs", "2"]) == 0
    out_dir = tmp_path / "small-results"
    names = {p.name for p in out_dir.iterdir()}
    assert {"results.json", "results.csv", "spectra.csv", "records"} <= names
    assert "report.pdf" not in names and "report.docx" not in names
    first = json.loads((out_dir / "results.json").read_text())
    assert [c["name"] for c in first["cases"]] == ["Unreinforced", "GFRP external 1‰", "my carbon"]
    assert first["demand"]["pga"] == pytest.approx(0.106)
    assert first["project"]["name"] == "Small <&> wall"
    gfrp = first["cases"][1]
    # 1 ‰ of 0.3 m x 5 m = 1500 mm² on each face, built as 30 bars Ø8 (30·16π = 1508 mm²,
    # docs/model.md §2.1), GFRP density 2000 kg/m3, bars 3 m long
    assert gfrp["frp_mass"] == pytest.approx(2 * 30 * 16e-6 * math.pi * 3.0 * 2000.0, rel=1e-9)
    # the unreinforced wall's verdict: every deciding check (the IDA's target among them)
    assert first["retrofit_required"] is (not first["cases"][0]["passes"])
    out = capsys.readouterr().out
    assert "Spectrum compatibility" in out
    said = " ".join(out.split())
    typed = from_json((out_dir / "results.json").read_text(encoding="utf-8"))
    assert f"{recommendation_label(typed)}: {recommendation_text(typed)}" in said
    # this small set (3 short records) fails the code's checks: nothing is "recommended"
    assert first["input_code_compliant"] is first["compliance"]["passed"] is False
    assert "(input not code-compliant): " in said and "Recommended:" not in said
    assert "INPUT NOT CODE-COMPLIANT" in said

    assert main(["run", str(project), "--no-pdf"]) == 0
    assert "unchanged since " in capsys.readouterr().out  # nothing read but results.json
    (out_dir / SIDECAR).unlink()  # without the digest: the run again, from the cache
    assert main(["run", str(project), "--no-pdf"]) == 0
    assert "0 IDAs computed" in capsys.readouterr().out
    second = json.loads((out_dir / "results.json").read_text())
    first.pop("created"), second.pop("created")
    assert first == second


@pytest.mark.parametrize(
    "name", ["unknown-key.yaml", "thickness-ge-height.yaml", "yaml-syntax.yaml"]
)
def test_broken_project_exit_2_one_line_nothing_written(tmp_path, capsys, name):
    project = tmp_path / name
    shutil.copy(BROKEN / name, project)
    assert main(["run", str(project)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and name in err
    assert list(tmp_path.iterdir()) == [project]


def test_interrupted_run_exits_130_without_results(tmp_path, capsys, monkeypatch):
    """Ctrl-C during the IDA: exit 130, a message, no results.json."""
    import frp_assess.app.assessment as assessment

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(assessment, "run_assessment", interrupted)  # cli.cmd_run imports it late
    project = tmp_path / "small.yaml"
    project.write_text(SMALL, encoding="utf-8")
    assert main(["run", str(project), "--no-pdf"]) == 130
    assert "interrupted" in capsys.readouterr().err
    assert not (tmp_path / "small-results" / "results.json").exists()


def test_project_maps_onto_inputs(tmp_path):
    """Every block of the file reaches the assessment: overrides, names, paths, settings."""
    (tmp_path / "recs").mkdir()
    text = (
        SMALL.replace(
            "    artificial: {count: 3, seed: 7, duration: 14.0, dt: 0.01}",
            "    files: [{path: recs/a.txt, format: two-column, units: cm/s2}]\n"
            "    scale_to_spectrum: false",
        )
        + "analysis: {restitution: 0.9, collapse: first-exceedance, strain_factor: 0.4}\n"
    )
    (tmp_path / "recs" / "a.txt").write_text("0 0\n0.01 1\n0.02 0\n")
    project = tmp_path / "p.yaml"
    project.write_text(text, encoding="utf-8")
    inputs = load_inputs(project)
    assert inputs.records == (
        RecordFile(str((tmp_path / "recs" / "a.txt").resolve()), "two-column", "cm/s2"),
    )
    assert inputs.scale_to_spectrum is False
    assert inputs.model.restitution == 0.9 and inputs.model.collapse == "first-exceedance"
    assert inputs.strain_factor == 0.4
    gfrp = inputs.options[0].material
    assert gfrp.price == 9.0 and gfrp.elastic_modulus == FRP_MATERIALS["GFRP"].elastic_modulus
    assert inputs.options[1].name == "my carbon" and inputs.options[1].ratio_asked == 2.0
    assert inputs.costs.installation_per_metre == 100.0
    assert inputs.input_file == "p.yaml"


@pytest.mark.parametrize(
    "name",
    [
        "facade-laquila.yaml",
        "paper-case.yaml",
        "boundary-wall-records.yaml",
        "gable-top-storey.yaml",
    ],
)
def test_worked_examples_load(name):
    inputs = load_inputs(ROOT / "projects" / name)
    assert inputs.options
    if isinstance(inputs.records, ArtificialRecords):
        assert inputs.records.count == 7
    else:
        assert all(Path(r.path).is_file() for r in inputs.records)


def test_ntc_example_spectrum():
    """facade-laquila: NTC 2018 soil C, a_g = 0.261 g, F0 = 2.36 -> S_S = 1.00 <= 1.70 -
    0.60*F0*a_g/g = 1.330 (Tab. 3.2.IV), so a_g*S = 0.3472 g."""
    inputs = load_inputs(ROOT / "projects" / "facade-laquila.yaml")
    assert inputs.spectrum.pga_g == pytest.approx(0.261 * (1.70 - 0.60 * 2.36 * 0.261), rel=1e-9)


def test_run_writes_the_report_and_report_rebuilds_it_identically(tmp_path):
    """`run` writes report.pdf and report.docx from a real run; `frp-assess report DIR`
    rebuilds each from results.json alone, byte for byte (reportlab invariant mode, issue 5;
    the DOCX stamped with the results' date)."""
    project = tmp_path / "small.yaml"
    project.write_text(SMALL, encoding="utf-8")
    assert main(["run", str(project), "--jobs", "2"]) == 0
    out_dir = tmp_path / "small-results"
    pdf = (out_dir / "report.pdf").read_bytes()
    assert pdf.startswith(b"%PDF")
    assert main(["report", str(out_dir), "--out", str(tmp_path / "again.pdf")]) == 0
    assert (tmp_path / "again.pdf").read_bytes() == pdf
    word = (out_dir / "report.docx").read_bytes()
    assert word.startswith(b"PK")
    assert main(["report", str(out_dir), "--out", str(tmp_path / "again.docx")]) == 0
    assert (tmp_path / "again.docx").read_bytes() == word


@pytest.mark.slow
def test_paper_case_just_below_history_survives(tmp_path):
    """Regression: in projects/paper-case.yaml the governing record collapses at C and also at
    C·(1 - tol) (the response is not monotonic in C); the report's "just below" history must
    be one the IDA ran and found standing: its bracket's lower end."""
    from frp_assess.api import run_assessment

    inputs = load_inputs(ROOT / "projects" / "paper-case.yaml")
    results, _ = run_assessment(inputs, tmp_path, pdf=False)
    gov = results.governing
    assert gov is not None
    case = results.case(gov.case)
    assert case is not None
    ida = next(r for r in case.records if r.record == gov.record)
    at, below = gov.runs
    assert at.collapsed is True and below.collapsed is False
    assert below.multiplier == ida.survivor_multiplier < at.multiplier
