"""Tiny and extreme legal numbers (issue 25, class 1): every numeric key has the range the
model is valid for; outside it the usual located line (exit 2), inside it a result.

Each row is a value that used to end in a traceback (or a hang): 1e-300 for a length, a
period or a factor, a record of subnormal numbers.  The last tests run a project at the low
and at the high end of every range and check that it computes.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from frp_assess.cli import main

BASE = """\
project: {name: Ranges}
wall: {thickness: 0.3, height: 3.0, masonry: rubble-stone, mechanism: one-sided}
seismic:
  spectrum: {type: preset, name: A2}
  records:
    artificial: {count: 1, seed: 1, duration: 13.5, dt: 0.05}
interventions:
  - {material: GFRP, position: centred, ratio: 1}
"""


def _sub(old: str, new: str) -> str:
    assert old in BASE, old
    return BASE.replace(old, new, 1)


#: (id, project text, expected fragment of the one line, its line number, its key)
REFUSED: list[tuple[str, str, str, int, str]] = [
    (
        "strain-factor-1e-300",
        BASE + "analysis: {strain_factor: 1.0e-300}\n",
        "expected a number in [0.01, 1], found 1e-300",
        9,
        "analysis.strain_factor",
    ),
    (
        "spacing-1e-300",
        BASE + "bars: {min_spacing: 1.0e-300, max_spacing: 1.0e-300}\n",
        "expected a number in [0.02, 10], found 1e-300",
        9,
        "bars.min_spacing",
    ),
    (
        "building-period-1e-300",
        BASE + "building: {height: 10, storeys: 3, wall_base: 3, period: 1.0e-300}\n",
        "expected a number in [0.02, 5], found 1e-300",
        9,
        "building.period",
    ),
    (
        "t1-1e-300",  # used to hang: check periods of 2e-301 s
        _sub("  records:", "  t1: 1.0e-300\n  records:"),
        "expected a number in [0.05, 10], found 1e-300",
        5,
        "seismic.t1",
    ),
    (
        "thickness-1e-300",
        _sub("thickness: 0.3", "thickness: 1.0e-300"),
        "expected a number in [0.05, 5], found 1e-300",
        2,
        "wall.thickness",
    ),
    (
        "ag-1e-300",
        _sub("{type: preset, name: A2}", "{type: ec8, ag: 1.0e-300, ground: A}"),
        "expected a number in [0.001, 1.5], found 1e-300",
        4,
        "seismic.spectrum.ag",
    ),
    (
        "table-1e-300",
        _sub(
            "{type: preset, name: A2}",
            "{type: table, periods: [0, 1.0e-300], accelerations: [0.3, 1.0e-300]}",
        ),
        "expected Se >= 0.001 g at the first period and at every period up to 2 s",
        4,
        "seismic.spectrum.accelerations[1]",
    ),
    (
        "design-range-off-grid",  # used to search the ratio 0
        BASE + "design: {materials: [GFRP], ratio_range: [0.0011, 0.0019], resolution: 0.001}\n",
        "expected a range holding a multiple of the resolution 0.001",
        9,
        "design.ratio_range",
    ),
    (
        "anchorage-bond-1e-300",
        BASE + "bars: {anchorage: {hole_clearance: 2, bond_bar: 1.0e-300, bond_masonry: 1}}\n",
        "expected a number in [0.01, 50], found 1e-300",
        9,
        "bars.anchorage.bond_bar",
    ),
    (
        "modulus-1e-300",
        BASE + "materials: {GFRP: {elastic_modulus: 1.0e-300}}\n",
        "expected a number in [1, 1000], found 1e-300",
        9,
        "materials.GFRP.elastic_modulus",
    ),
]


@pytest.mark.parametrize(
    ("text", "expect", "line", "key"),
    [row[1:] for row in REFUSED],
    ids=[row[0] for row in REFUSED],
)
def test_a_value_outside_the_models_range_is_one_located_line(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    text: str,
    expect: str,
    line: int,
    key: str,
) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out), "--no-pdf"]) == 2
    err = capsys.readouterr().err
    first = err.splitlines()[0]
    assert "Traceback" not in err
    assert first.startswith(f"frp-assess: error: {path}:{line}: {key}: "), first
    assert expect in first
    assert not out.exists()


def test_a_record_of_subnormal_numbers_is_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Samples of 5e-320 read as g: scaling to the spectrum needed a factor of 1e318 (inf)."""
    rec = tmp_path / "sub.txt"
    rec.write_text("".join(f"{0.01 * k:.2f} {5e-320 * (-1) ** k}\n" for k in range(200)))
    path = tmp_path / "p.yaml"
    path.write_text(
        BASE.replace(
            "    artificial: {count: 1, seed: 1, duration: 13.5, dt: 0.05}\n",
            "    files:\n      - {path: sub.txt}\n",
        ),
        encoding="utf-8",
    )
    assert main(["validate", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"{rec}: expected a peak acceleration between" in err


def test_an_option_built_beyond_the_models_ratio_is_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """0.001 ‰ on a 50 mm wall with bars at most 20 mm apart installs 28 ‰ in Ø6 bars:
    n·A_b/(B·L) = 50 · 28.27 mm² / (50 mm · 1000 mm) = 28.3 ‰ > 20 ‰ (it used to end in
    the model's ValueError)."""
    path = tmp_path / "p.yaml"
    text = _sub("thickness: 0.3", "thickness: 0.05").replace("ratio: 1}", "ratio: 0.001}")
    path.write_text(text + "bars: {min_spacing: 0.02, max_spacing: 0.02}\n", encoding="utf-8")
    assert main(["run", str(path), "--out", str(tmp_path / "o"), "--no-pdf"]) == 2
    errors = [e for e in capsys.readouterr().err.splitlines() if "warning" not in e]
    assert len(errors) == 1  # (and warnings: a 50 mm wall is outside the range of practice)
    assert "interventions[0].ratio" in errors[0] and "is built as 28.3 ‰" in errors[0]


LOW = (
    _sub(
        "thickness: 0.3, height: 3.0",
        "thickness: 0.05, height: 0.5, length: 0.1, compressive_strength: 0.1",
    )
    .replace("ratio: 1}", "ratio: 0.001}")
    .replace(
        "{type: preset, name: A2}", "{type: ntc2018, ag: 0.001, F0: 1, Tc_star: 0.05, soil: E}"
    )
    .replace("  records:", "  t1: 0.05\n  records:")
    + "bars: {min_spacing: 0.02, max_spacing: 10}\n"
    + "building: {height: 2, storeys: 1, wall_base: 1, period: 0.02, damping: 0.005}\n"
    + "analysis: {target: 0.01, strain_factor: 0.01}\n"
)
HIGH = (
    _sub(
        "thickness: 0.3, height: 3.0",
        "thickness: 5, height: 50, length: 1000, compressive_strength: 100",
    ).replace("ratio: 1}", "ratio: 2}")
    + "bars: {min_spacing: 0.02, max_spacing: 10}\n"
    + "building: {height: 200, storeys: 60, wall_base: 199, period: 5, damping: 0.3}\n"
)


@pytest.mark.parametrize("text", [LOW, HIGH], ids=["low-ends", "high-ends"])
def test_the_ends_of_the_ranges_compute(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], text: str
) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    code = main(["run", str(path), "--out", str(out), "--no-pdf"])
    err = capsys.readouterr().err
    assert code in (0, 1), err  # 1: the records fail the compliance checks (short, one)
    assert "Traceback" not in err
    assert (out / "results.json").is_file()


@pytest.mark.parametrize(
    ("args", "expect"),
    [
        (["records", "check", "{rec}", "--spectrum", "A2", "--t1", "1e-300"], "--t1"),
        (
            ["records", "generate", "--spectrum", "ec8:type=1,ground=B,ag=1e-300"],
            "expected a spectrum with a_g*S >= 0.001 g",
        ),
    ],
    ids=["records-t1-1e-300", "records-ag-1e-300"],
)
def test_the_records_command_shares_the_ranges(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], args: list[str], expect: str
) -> None:
    """--t1 1e-300 never ended (check periods of 2e-301 s); a_g = 1e-300 made zero records."""
    rec = tmp_path / "r.txt"
    rec.write_text("".join(f"{0.01 * k:.2f} {0.1 * (-1) ** k}\n" for k in range(300)))
    out = tmp_path / "out"
    full = [a.replace("{rec}", str(rec)) for a in args]
    if full[1] == "generate":
        full += ["--count", "1", "--out", str(out)]
    try:
        code = main(full)
    except SystemExit as exc:  # argparse's own refusal of a bad argument
        code = int(str(exc.code))
    assert code == 2
    err = capsys.readouterr().err
    assert expect in err and "Traceback" not in err
    assert not out.exists()
