"""Record readers: PEER .AT2 (new and old header) and two-column text; one-line errors."""

from __future__ import annotations

import numpy as np
import pytest

from frp_assess.motions.readers import RecordFormatError, read_record
from frp_assess.motions.record import G, Record
from frp_assess.motions.writers import write_at2, write_two_column


def test_at2_round_trip(tmp_path):
    rec = Record("x", 0.01, np.sin(np.arange(23)) * 0.3 * G)
    write_at2(rec, tmp_path / "x.AT2")
    back = read_record(tmp_path / "x.AT2")
    assert back.dt == pytest.approx(0.01) and back.npts == 23
    assert back.acc == pytest.approx(rec.acc, rel=1e-6)


def test_at2_old_header(tmp_path):
    p = tmp_path / "old.at2"
    p.write_text("h1\nh2\nh3\n4   0.02   NPTS, DT\n0.1 0.2\n-0.3 0.0\n")
    rec = read_record(p)
    assert rec.dt == 0.02 and rec.acc == pytest.approx(np.array([0.1, 0.2, -0.3, 0.0]) * G)


def test_two_column_units(tmp_path):
    rec = Record("y", 0.005, np.cos(np.arange(10)) * 2.0)
    write_two_column(rec, tmp_path / "y.txt", units="m/s2")
    back = read_record(tmp_path / "y.txt", units="m/s2")
    assert back.acc == pytest.approx(rec.acc, rel=1e-7)
    cm = read_record(tmp_path / "y.txt", units="cm/s2")
    assert cm.acc == pytest.approx(rec.acc / 100, rel=1e-7)


@pytest.mark.parametrize(
    "name,text,fragment,line",
    [
        ("npts.AT2", "a\nb\nc\nNPTS= 5, DT= 0.01 SEC\n0.1 0.2 0.3\n", "NPTS=5", 4),
        ("text.AT2", "a\nb\nc\nNPTS= 3, DT= 0.01 SEC\n0.1 abc 0.3\n", "'abc'", 5),
        ("nan.AT2", "a\nb\nc\nNPTS= 3, DT= 0.01 SEC\n0.1 nan 0.3\n", "not finite", 5),
        ("uneven.txt", "t a\n0 0.1\n0.01 0.2\n0.03 0.1\n", "non-uniform", None),
        ("empty.txt", "time acc\n", "empty", None),
    ],
)
def test_malformed_files(tmp_path, name, text, fragment, line):
    p = tmp_path / name
    p.write_text(text)
    with pytest.raises(RecordFormatError) as err:
        read_record(p)
    msg = str(err.value)
    assert fragment in msg and str(p) in msg and "\n" not in msg
    if line is not None:
        assert f"{p}:{line}:" in msg
