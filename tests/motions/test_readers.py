"""Record readers and writers (frp_assess.motions.readers / writers; issue 3 item 5).

PEER .AT2 (new and old header), ESM ASCII, two-column and one-column text; units g, m/s²,
cm/s²; malformed files give one-line errors naming the file and the line.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from frp_assess.errors import InputError
from frp_assess.motions.readers import detect_format, read_record
from frp_assess.motions.record import G, Record
from frp_assess.motions.record_text import UNITS, RecordFormatError, unit_factor
from frp_assess.motions.writers import write_at2, write_two_column

DATA = Path(__file__).parent / "data"


def test_at2_round_trip(tmp_path):
    rec = Record("x", 0.01, np.sin(np.arange(23)) * 0.3 * G)
    write_at2(rec, tmp_path / "x.AT2")
    back = read_record(tmp_path / "x.AT2")
    assert back.dt == pytest.approx(0.01) and back.npts == 23
    assert back.acc == pytest.approx(rec.acc, rel=1e-7)
    assert not list(tmp_path.glob(".*.tmp"))  # atomic write leaves no temp file


def test_at2_round_trip_awkward_dt(tmp_path):
    rec = Record("x", 1 / 300, np.cos(np.arange(11)))
    write_at2(rec, tmp_path / "x.at2")
    assert read_record(tmp_path / "x.at2").dt == pytest.approx(1 / 300, rel=1e-9)


def test_at2_old_header(tmp_path):
    p = tmp_path / "old.at2"
    p.write_text("h1\nh2\nh3\n4   0.02   NPTS, DT\n0.1 0.2\n-0.3 0.0\n")
    rec = read_record(p)
    assert rec.dt == 0.02 and rec.acc == pytest.approx(np.array([0.1, 0.2, -0.3, 0.0]) * G)


def test_at2_header_keys_in_other_order(tmp_path):
    p = tmp_path / "rev.at2"
    p.write_text("h1\nh2\nh3\nDT= 0.005 SEC, NPTS= 3\n0.1 0.2 0.3\n")
    rec = read_record(p)
    assert rec.dt == 0.005 and rec.npts == 3


def test_peer_sample_files():
    """Stored samples: new style with leading-dot numbers; old style with run-together fields."""
    new = read_record(DATA / "peer_new.AT2")
    assert new.dt == 0.005 and new.npts == 7
    assert new.acc[:5] / G == pytest.approx([0.01, -0.02, 0.03, -0.04, 0.05])
    old = read_record(DATA / "peer_old.at2")
    assert old.dt == 0.01 and old.npts == 7
    assert old.acc[:5] / G == pytest.approx([-0.001, -0.002, 0.003, -0.004, 0.005])


def test_esm_sample_units_override():
    """ESM: UNITS cm/s^2 in the header wins over the (default) units argument."""
    rec = read_record(DATA / "esm_sample.ASC")
    assert detect_format(DATA / "esm_sample.ASC") == "esm"
    assert rec.dt == 0.01 and rec.npts == 8
    assert rec.acc[3] == pytest.approx(0.5)  # 50 cm/s² -> 0.5 m/s²
    assert rec.meta["event_id"] == "TEST-0001"


def test_esm_ndata_mismatch(tmp_path):
    text = (DATA / "esm_sample.ASC").read_text().replace("NDATA: 8", "NDATA: 9")
    p = tmp_path / "bad.asc"
    p.write_text(text)
    with pytest.raises(RecordFormatError, match="NDATA=9") as err:
        read_record(p)
    assert f"{p}:9:" in str(err.value)


def test_two_column_units(tmp_path):
    rec = Record("y", 0.005, np.cos(np.arange(10)) * 2.0)
    write_two_column(rec, tmp_path / "y.txt", units="m/s2")
    back = read_record(tmp_path / "y.txt", units="m/s2")
    assert back.acc == pytest.approx(rec.acc, rel=1e-8)
    cm = read_record(tmp_path / "y.txt", units="cm/s2")
    assert cm.acc == pytest.approx(rec.acc / 100, rel=1e-8)


@pytest.mark.parametrize("units", ["g", "cm/s^2", "gal", "m/s^2"])
def test_two_column_round_trip_in_units(tmp_path, units):
    rec = Record("y", 0.02, np.sin(np.arange(50) * 0.3) * 3.0)
    write_two_column(rec, tmp_path / "y.dat", units=units)
    back = read_record(tmp_path / "y.dat", format="two-column", units=units)
    assert back.dt == pytest.approx(0.02, rel=1e-9)
    assert back.acc == pytest.approx(rec.acc, rel=1e-8)


def test_two_column_header_lines_and_offset_start(tmp_path):
    p = tmp_path / "t.csv"
    p.write_text("Station X\ntime,acc\n0.01,0.1\n0.02,0.2\n0.03,-0.1\n")
    rec = read_record(p)
    assert rec.dt == pytest.approx(0.01) and rec.npts == 3 and rec.meta["t0_s"] == "0.01"


def test_one_column_needs_dt(tmp_path):
    p = tmp_path / "one.txt"
    p.write_text("acceleration in g\n0.1\n0.2\n-0.1\n0.05\n")
    assert detect_format(p) == "one-column"
    with pytest.raises(InputError, match="dt"):
        read_record(p)
    rec = read_record(p, dt=0.02)
    assert rec.dt == 0.02 and rec.acc == pytest.approx(np.array([0.1, 0.2, -0.1, 0.05]) * G)


def test_dt_disagreeing_with_file(tmp_path):
    rec = Record("x", 0.01, np.sin(np.arange(23)))
    write_at2(rec, tmp_path / "x.AT2")
    with pytest.raises(RecordFormatError, match="differs"):
        read_record(tmp_path / "x.AT2", dt=0.02)


@pytest.mark.parametrize("alias", sorted(UNITS))
def test_unit_aliases(alias):
    assert unit_factor(alias.upper() if alias == "gal" else alias) == UNITS[alias]


def test_unknown_units_and_format(tmp_path):
    with pytest.raises(InputError, match="units"):
        read_record(DATA / "peer_new.AT2", units="ft/s2")
    with pytest.raises(InputError, match="format"):
        read_record(DATA / "peer_new.AT2", format="sac")


@pytest.mark.parametrize(
    "name,text,fragment,line",
    [
        ("npts.AT2", "a\nb\nc\nNPTS= 5, DT= 0.01 SEC\n0.1 0.2 0.3\n", "NPTS=5", 4),
        ("text.AT2", "a\nb\nc\nNPTS= 3, DT= 0.01 SEC\n0.1 abc 0.3\n", "'abc'", 5),
        ("nan.AT2", "a\nb\nc\nNPTS= 3, DT= 0.01 SEC\n0.1 nan 0.3\n", "not finite", 5),
        ("inf.txt", "t a\n0 0.1\n0.01 inf\n0.02 0.1\n", "not finite", 3),
        ("hdr.AT2", "a\nb\nc\nno numbers here\n0.1 0.2\n", "4th line", 4),
        ("dt0.AT2", "a\nb\nc\nNPTS= 2, DT= 0 SEC\n0.1 0.2\n", "> 0", 4),
        ("uneven.txt", "t a\n0 0.1\n0.01 0.2\n0.03 0.1\n", "non-uniform", 4),
        ("back.txt", "t a\n0 0.1\n0.01 0.2\n0.005 0.1\n", "does not increase", 4),
        ("cols.txt", "t a\n0 0.1\n0.01 0.2 0.3\n", "2 columns", 3),
        ("empty.txt", "time acc\n", "no numeric data", None),
        ("empty.AT2", "a\nb\nc\nNPTS= 0, DT= 0.01\n", "empty", None),
        ("short.AT2", "a\nb\n", "too short", None),
        ("nodt.asc", "NDATA: 2\nUNITS: g\n0.1\n0.2\n", "SAMPLING_INTERVAL_S", None),
        ("unit.asc", "SAMPLING_INTERVAL_S: 0.01\nUNITS: furlong\n0.1\n0.2\n", "UNITS", 2),
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


def test_unreadable_files(tmp_path):
    with pytest.raises(RecordFormatError, match="not found"):
        read_record(tmp_path / "missing.AT2")
    with pytest.raises(RecordFormatError, match="directory"):
        read_record(tmp_path, format="two-column")
    p = tmp_path / "bin.dat"
    p.write_bytes(b"\x00\x01\x02")
    with pytest.raises(RecordFormatError, match="binary"):
        read_record(p)
