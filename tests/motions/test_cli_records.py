"""`frp-assess records generate|check` (frp_assess.cli.cmd_records; issue 3 item 6)."""

from __future__ import annotations

import numpy as np

from frp_assess.cli import main
from frp_assess.motions.readers import read_record
from frp_assess.motions.simqke import generate_artificial
from frp_assess.motions.spectra import parse_spectrum


def test_generate_writes_records_csv_and_passes(tmp_path, capsys):
    out = tmp_path / "recs"
    rc = main(
        [
            "records",
            "generate",
            "--spectrum",
            "A1",
            "--count",
            "3",
            "--seed",
            "4",
            "--out",
            str(out),
        ]
    )
    assert rc == 0
    files = sorted(out.glob("art-*.AT2"))
    assert [f.name for f in files] == ["art-01.AT2", "art-02.AT2", "art-03.AT2"]
    # the files hold the generator's records (to the 9 digits written)
    direct = generate_artificial(parse_spectrum("A1"), count=3, seed=4)
    for f, rec in zip(files, direct, strict=True):
        back = read_record(f)
        np.testing.assert_allclose(back.acc, rec.acc, rtol=1e-7, atol=1e-9 * rec.pga)
    csv = (out / "spectra.csv").read_text().splitlines()
    header = next(line for line in csv if not line.startswith("#"))
    assert header.startswith("period_s,target_g,mean_g,mean_over_target,art-01_g")
    text = capsys.readouterr().out
    assert "§3.2.3.1.2" in text and "§3.2.3.6" in text and "all checks pass" in text

    rc = main(["records", "check", *map(str, files), "--spectrum", "A1"])
    assert rc == 0


def test_check_reports_failure_with_exit_1(tmp_path, capsys):
    out = tmp_path / "r"
    main(["records", "generate", "--spectrum", "A1", "--count", "3", "--out", str(out)])
    capsys.readouterr()
    # the same records against a spectrum three times stronger fail
    rc = main(
        [
            "records",
            "check",
            *map(str, sorted(out.glob("*.AT2"))),
            "--spectrum",
            "ec8:type=1,ground=D,ag=0.3",
            "--recorded",
        ]
    )
    assert rc == 1 and "FAIL" in capsys.readouterr().out


def test_bad_spectrum_is_one_line_exit_2(tmp_path, capsys):
    rc = main(["records", "generate", "--spectrum", "ntc:ag=0.2,soil=B", "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert rc == 2 and err.count("\n") == 1 and "F0" in err


def test_bad_file_is_one_line_exit_2(tmp_path, capsys):
    bad = tmp_path / "bad.AT2"
    bad.write_text("a\nb\nc\nNPTS= 3, DT= 0.01\n0.1 x 0.2\n")
    rc = main(["records", "check", str(bad), "--spectrum", "A2"])
    err = capsys.readouterr().err
    assert rc == 2 and f"{bad}:5:" in err and err.count("\n") == 1
