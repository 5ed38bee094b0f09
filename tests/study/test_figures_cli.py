"""Figures, the study PDF and the `frp-assess study` command."""

from __future__ import annotations

import pytest
import yaml

from frp_assess.cli import main
from frp_assess.study import StudyPlan, parse_study, read_summary, run_study
from frp_assess.study.figures import FIGURES, figure_series, write_study_pdf
from tests.study.conftest import TINY


def test_figures_and_pdf(tmp_path, tiny_study, records):
    run_study(tiny_study, tmp_path, jobs=2, records=records)
    rows = read_summary(tmp_path / "summary.csv")
    spec = next(f for f in FIGURES if f.name == "fig11-q-rebars-ratio")
    series = figure_series(rows, spec)
    assert set(series) == {"ρ = 1 ‰", "ρ = 2 ‰"}
    assert [h for h, _ in series["ρ = 1 ‰"]] == [3.0, 4.0]
    write_study_pdf(tmp_path)
    assert (tmp_path / "study.pdf").read_bytes().startswith(b"%PDF")
    assert (tmp_path / "figures" / "fig11-q-rebars-ratio.svg").stat().st_size > 1000


def test_cli_study_runs_and_reports_errors(tmp_path, capsys, monkeypatch):
    import frp_assess.study.run as run_mod
    from tests.study.conftest import tiny_records

    monkeypatch.setattr(run_mod, "study_records", lambda plan: tiny_records())
    import frp_assess.study as pkg

    monkeypatch.setattr(pkg, "study_records", lambda plan: tiny_records())
    f = tmp_path / "tiny.yaml"
    f.write_text(yaml.safe_dump(TINY), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["study", str(f), "--out", str(out), "--jobs", "2"]) == 0
    assert len(read_summary(out / "summary.csv")) == len(StudyPlan(parse_study(TINY)))
    assert (out / "study.pdf").exists()
    capsys.readouterr()
    assert main(["study", str(f), "--out", str(out), "--no-figures"]) == 0
    assert "0 IDAs computed" in capsys.readouterr().out
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: x\nheight: [3]\nalpha_deg: [7.5]\nspectrum: [A2]\ncolour: red\n")
    assert main(["study", str(bad)]) == 2
    err = capsys.readouterr().err
    assert "bad.yaml:5: colour: unknown key" in err and len(err.strip().splitlines()) == 1


@pytest.mark.slow
def test_dask_and_local_give_identical_numbers(tmp_path, tiny_study, records):
    pytest.importorskip("dask")
    pytest.importorskip("distributed")
    from frp_assess.study.executors import DaskExecutor

    run_study(tiny_study, tmp_path / "local", jobs=2, records=records)
    ex = DaskExecutor(n_workers=2)
    try:
        stats = run_study(tiny_study, tmp_path / "dask", executor=ex, records=records)
    finally:
        ex.close()
    assert stats.computed == 18 and stats.executor.startswith("Dask")
    for name in ("long.csv", "summary.csv"):
        assert (tmp_path / "dask" / name).read_text() == (tmp_path / "local" / name).read_text()


def test_a_full_disk_leaves_the_previous_study_pdf(tmp_path, tiny_study, records, monkeypatch):
    """Issue 36 item 8: a full disk while study.pdf was written left a 0-byte study.pdf.  The
    PDF (and each figure) is written beside it and renamed when complete (io_utils.atomic_path,
    as run's outputs): the disk filling up (ENOSPC after the file was opened, as reportlab
    opens it) leaves the previous study.pdf byte for byte, no temporary file, and an error
    naming study.pdf."""
    import errno

    import frp_assess.study.figures as figures

    run_study(tiny_study, tmp_path, jobs=2, records=records)
    write_study_pdf(tmp_path)
    before = (tmp_path / "study.pdf").read_bytes()

    class FullDisk:
        def __init__(self, filename: str, **kwargs: object) -> None:
            self.filename = filename

        def build(self, story: object) -> None:
            open(self.filename, "wb").close()  # opened (truncated), then nothing fits
            raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(figures, "SimpleDocTemplate", FullDisk)
    with pytest.raises(OSError) as info:
        write_study_pdf(tmp_path)
    assert "study.pdf" in str(info.value) and "No space left" in str(info.value)
    assert (tmp_path / "study.pdf").read_bytes() == before
    assert not [p.name for p in tmp_path.iterdir() if p.name.endswith(".tmp")]
