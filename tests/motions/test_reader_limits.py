"""Record files that would hang, exhaust memory or be misread are refused in one line."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from frp_assess.errors import InputError
from frp_assess.motions.readers import read_record
from frp_assess.motions.record_text import MAX_RECORD_BYTES, RecordFormatError

HEAD = "PEER\nrecord\nunits g\n"


@pytest.mark.parametrize(
    ("header", "fragment"),
    [
        ("NPTS= 1e400, DT= 0.01 SEC", "NPTS must be a whole number, found inf"),
        ("NPTS= 3e9, DT= 0.01 SEC", "more than 2,000,000 samples"),
        ("NPTS= 3, DT= 1e-9 SEC", "below 0.0001 s"),
        ("NPTS= 3, DT= 5e-324 SEC", "below 0.0001 s"),
        ("NPTS= 3, DT= 1e400 SEC", "must be > 0, found inf"),
        # issue 36 item 8: a record of DT = 1 s was accepted; it holds no motion below 2 s
        ("NPTS= 3, DT= 1.0 SEC", "above 0.05 s: the spectrum's periods from 0.15 s"),
        ("NPTS= 3, DT= 0.0501 SEC", "above 0.05 s"),
    ],
)
def test_at2_headers_that_ask_for_unbounded_work(
    tmp_path: Path, header: str, fragment: str
) -> None:
    path = tmp_path / "r.AT2"
    path.write_text(f"{HEAD}{header}\n0.1 0.2 0.3\n", encoding="utf-8")
    with pytest.raises(RecordFormatError) as info:
        read_record(path)
    assert fragment in str(info.value) and info.value.line == 4


@pytest.mark.parametrize("dt", ["0.05", "0.005", "0.0001"])
def test_at2_time_steps_within_the_bounds_are_read(tmp_path: Path, dt: str) -> None:
    """The bounds themselves are time steps (0.05 s: the project file's largest dt)."""
    path = tmp_path / "r.AT2"
    path.write_text(f"{HEAD}NPTS= 3, DT= {dt} SEC\n0.1 0.2 0.3\n", encoding="utf-8")
    assert read_record(path).dt == float(dt)


def test_two_column_time_in_seconds_of_a_second_step_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "r.txt"
    path.write_text("0 0.1\n1 0.2\n2 0.1\n", encoding="utf-8")
    with pytest.raises(RecordFormatError, match="above 0.05 s"):
        read_record(path)


def test_two_column_time_in_milliseconds_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "r.txt"
    path.write_text("0 0.1\n0.00001 0.2\n0.00002 0.1\n", encoding="utf-8")
    with pytest.raises(RecordFormatError, match="below 0.0001 s"):
        read_record(path)


def test_fifo_device_and_size_are_refused_before_reading(tmp_path: Path) -> None:
    fifo = tmp_path / "r.AT2"
    os.mkfifo(fifo)  # opening it for reading would block for ever
    for path in (fifo, Path("/dev/zero")):
        with pytest.raises(RecordFormatError, match="not a regular file"):
            read_record(path, format="two-column")
    big = tmp_path / "big.txt"
    with open(big, "wb") as handle:
        handle.truncate(MAX_RECORD_BYTES + 1)  # sparse: no disk used
    with pytest.raises(RecordFormatError, match="a record file is at most 50 MB"):
        read_record(big)


def test_a_three_column_file_says_what_to_do(tmp_path: Path) -> None:
    path = tmp_path / "r.txt"
    path.write_text("0.1 0.2 0.3\n0.4 0.5 0.6\n", encoding="utf-8")
    with pytest.raises(InputError) as info:
        read_record(path)
    message = str(info.value)
    assert "3 numbers a line" in message and "--dt" in message and "two columns" in message
