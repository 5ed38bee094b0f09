"""Units that look wrong are said, with the likely units; semicolon/decimal-comma tables."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from frp_assess.cli import main
from frp_assess.motions.pga_plausibility import (
    PGA_MAX_G,
    PGA_MIN_G,
    likely_units,
    plausibility_warning,
    plausibility_warnings,
)
from frp_assess.motions.readers import read_record
from frp_assess.motions.record import G, Record
from frp_assess.motions.record_text import UNITS, RecordFormatError

SHAPE = np.sin(np.linspace(0.0, 20.0, 400)) * np.exp(-np.linspace(0.0, 3.0, 400))


def as_read(true_pga_g: float, file_units: str, read_units: str) -> Record:
    """A record of true PGA ``true_pga_g`` written in ``file_units``, read in ``read_units``."""
    numbers = SHAPE / np.max(np.abs(SHAPE)) * true_pga_g * G / UNITS[file_units]
    return Record("r", 0.01, numbers * UNITS[read_units], meta={"units": read_units})


@pytest.mark.parametrize("pga", [0.05, 0.35, 1.2])
@pytest.mark.parametrize(
    ("file_units", "read_units"),
    [("m/s2", "g"), ("cm/s2", "g"), ("cm/s2", "m/s2"), ("g", "cm/s2"), ("gal", "g")],
)
def test_a_units_mistake_is_named_with_the_right_units(
    pga: float, file_units: str, read_units: str
) -> None:
    record = as_read(pga, file_units, read_units)
    if PGA_MIN_G <= record.pga_g <= PGA_MAX_G:
        assert plausibility_warning(record) is None  # nothing to say: plausible as read
        return
    warning = plausibility_warning(record)
    assert warning is not None and warning.startswith("record 'r': PGA ")
    expected = "cm/s2" if file_units == "gal" else file_units
    assert warning.endswith(f"set units: {expected}"), warning


@pytest.mark.parametrize("units", sorted(UNITS))
@pytest.mark.parametrize("pga", [0.002, 0.1, 0.5, 1.9])
def test_plausible_records_give_no_warning(units: str, pga: float) -> None:
    assert plausibility_warnings([as_read(pga, units, units)]) == ()


def test_an_implausible_record_without_a_better_unit_says_check() -> None:
    record = Record("big", 0.01, SHAPE / np.max(np.abs(SHAPE)) * 1e7, meta={"units": "cm/s2"})
    assert likely_units(1e9, "cm/s2") is None
    warning = plausibility_warning(record)
    assert warning is not None and warning.endswith("check the file and its units")


def test_records_check_prints_the_warning(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "ms2.txt"
    t = np.arange(SHAPE.size) * 0.01
    acc = SHAPE / np.max(np.abs(SHAPE)) * 3.4  # m/s²
    path.write_text("".join(f"{a:.4f} {b:.6f}\n" for a, b in zip(t, acc, strict=True)))
    main(["records", "check", str(path), "--spectrum", "A2", "--recorded"])
    err = capsys.readouterr().err.splitlines()
    assert (
        len(err) == 1 and "set units: m/s2" in err[0] and err[0].startswith("frp-assess: warning:")
    )


TABLE = [(0.0, 0.0012), (0.01, -0.0031), (0.02, 0.0045), (0.03, -0.002)]


@pytest.mark.parametrize(
    ("text", "read_as"),
    [
        ("time;acc\n" + "".join(f"{t:.2f};{a}\n" for t, a in TABLE), "semicolon-separated"),
        (
            "time;acc\n" + "".join(f"{t:.2f};{a}\n".replace(".", ",") for t, a in TABLE),
            "semicolon-separated, decimal commas",
        ),
        (
            "".join(f"{t:.2f}\t{a}\n".replace(".", ",") for t, a in TABLE),
            "blank-separated, decimal commas",
        ),
    ],
)
def test_semicolon_and_decimal_comma_tables_are_read_correctly(
    tmp_path: Path, text: str, read_as: str
) -> None:
    path = tmp_path / "r.csv"
    path.write_text(text, encoding="utf-8")
    record = read_record(path)
    assert record.dt == pytest.approx(0.01) and record.meta["read_as"] == read_as
    assert record.acc / G == pytest.approx([a for _, a in TABLE])


@pytest.mark.parametrize(
    ("text", "fragment", "line"),
    [
        ("0,0012\n-0,0031\n0,0045\n", "decimal comma or two comma-separated columns", 1),
        ("head\n0.00;0,0012\n0.01;0,0031\n", "both decimal points and decimal commas", 2),
    ],
)
def test_ambiguous_tables_are_refused_with_how_to_convert(
    tmp_path: Path, text: str, fragment: str, line: int
) -> None:
    path = tmp_path / "r.csv"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(RecordFormatError) as info:
        read_record(path)
    assert fragment in str(info.value) and info.value.line == line


def test_validate_reads_the_records_and_warns(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    t = np.arange(SHAPE.size) * 0.01
    acc = SHAPE / np.max(np.abs(SHAPE)) * 3.4  # m/s², read as g
    (tmp_path / "ms2.txt").write_text(
        "".join(f"{a:.4f} {b:.6f}\n" for a, b in zip(t, acc, strict=True)), encoding="utf-8"
    )
    project = tmp_path / "p.yaml"
    project.write_text(
        "wall: {thickness: 0.3, height: 3, masonry: rubble-stone, mechanism: one-sided}\n"
        "seismic:\n  spectrum: {type: preset, name: A2}\n  records:\n"
        "    files: [{path: ms2.txt}]\n",
        encoding="utf-8",
    )
    assert main(["validate", str(project)]) == 0
    (warning,) = capsys.readouterr().err.splitlines()
    assert warning.startswith("frp-assess: warning: record 'ms2': PGA 3.4 g")
    assert warning.endswith("set units: m/s2")
