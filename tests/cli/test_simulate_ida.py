"""The `simulate` and `ida` commands: JSON contract, one-line errors, exit codes."""

from __future__ import annotations

import json

import numpy as np
import pytest

from frp_assess.cli import main
from frp_assess.dynamics import ModelOptions, Rebars, RockingModel, Wall, ida
from frp_assess.dynamics.rocking import DEFAULT_TOLERANCE
from frp_assess.motions.record import G, Record
from frp_assess.motions.writers import write_at2
from tests.conftest import synthetic_record

WALL_ARGS = ["--thickness", "0.4", "--height", "3", "--mechanism", "one-sided"]
BAR_ARGS = [
    "--modulus",
    "46",
    "--ultimate-strain",
    "0.015",
    "--position",
    "external",
    "--ratio",
    "1",
]


@pytest.fixture
def record_file(tmp_path):
    rec = Record("r1", 0.01, synthetic_record(3, duration=6.0, pga_g=0.3))
    write_at2(rec, tmp_path / "r1.AT2")
    return tmp_path / "r1.AT2"


def test_simulate_json_matches_api(record_file, capsys):
    assert (
        main(
            [
                "simulate",
                *WALL_ARGS,
                *BAR_ARGS,
                "--record",
                str(record_file),
                "--scale",
                "3",
                "--json",
            ]
        )
        == 0
    )
    out = json.loads(capsys.readouterr().out)
    from frp_assess.motions.readers import read_record

    rec = read_record(record_file)
    model = RockingModel(
        Wall(0.4, 3.0, 18e3), "one-sided", Rebars(46e9, 0.015, "external", 1.0), ModelOptions()
    )
    res = model.run(rec.acc, rec.dt, 3.0)
    assert out["max_rotation"] == res.max_rotation
    assert out["max_rotation_ratio"] == pytest.approx(res.max_rotation / model.wall.alpha)
    assert out["collapsed"] == res.collapsed and out["impacts"] == res.impacts
    assert out["fate"] == res.fate and out["decided_time"] == res.decided_time
    assert out["peak_strain"] == res.peak_strain
    assert out["rupture_strain"] == pytest.approx(0.5 * 0.015)
    assert out["collapse_rule"] == "overturning" and out["tolerance"] == DEFAULT_TOLERANCE
    assert not res.collapsed and out["failure_mode"] is None  # at rest: no failure mode
    assert set(out) == {
        "collapsed",
        "fate",
        "failure_mode",
        "decided_time",
        "collapse_time",
        "max_rotation",
        "max_rotation_ratio",
        "peak_strain",
        "rupture_strain",
        "impacts",
        "ruptures",
        "collapse_rule",
        "tolerance",
    }


def test_simulate_json_names_the_failure_mode(record_file, capsys):
    """A run that collapses says how (docs/model.md §1.1): at 12 × the record the GFRP bars
    of this wall rupture and the wall then falls, "rupture then overturning"; the mode is
    derived here from the JSON's own fate and ruptures, not from the kernel's property."""
    argv = ["simulate", *WALL_ARGS, *BAR_ARGS, "--record", str(record_file), "--json"]
    assert main([*argv, "--scale", "12"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["fate"] == "fell" and len(out["ruptures"]) >= 1
    assert out["failure_mode"] == "rupture then overturning"


def test_simulate_history_csv(record_file, tmp_path, capsys):
    out = tmp_path / "h.csv"
    assert (
        main(
            [
                "simulate",
                *WALL_ARGS,
                "--record",
                str(record_file),
                "--scale",
                "2",
                "--out",
                str(out),
            ]
        )
        == 0
    )
    data = np.loadtxt(out, delimiter=",", skiprows=1)
    assert data.shape[1] == 6 and data[1, 0] == pytest.approx(0.01)


def test_ida_json(record_file, capsys):
    assert (
        main(
            [
                "ida",
                *WALL_ARGS,
                "--record",
                str(record_file),
                "--record",
                str(record_file),
                "--json",
            ]
        )
        == 0
    )
    out = json.loads(capsys.readouterr().out)
    from frp_assess.motions.readers import read_record

    rec = read_record(record_file)
    model = RockingModel(Wall(0.4, 3.0, 18e3), "one-sided")
    ref = ida(model, rec.acc, rec.dt)
    assert out["alpha"] == pytest.approx(model.wall.alpha)
    assert out["a_rm"] == pytest.approx(0.4 / 3.0)
    assert len(out["records"]) == 2
    r0 = out["records"][0]
    assert r0["collapse_multiplier"] == ref.collapse_multiplier
    assert r0["a_dyn"] == pytest.approx(ref.a_dyn / G) and r0["q"] == pytest.approx(ref.q)
    assert r0["pga"] == pytest.approx(rec.pga_g)
    # the first collapse on the sampling (the paper's convention) and the windows below the
    # effective capacity (docs/model.md §11): nothing collapsed below the first collapse, so
    # the capacity is at least the first collapse less half its bisection bracket
    assert r0["first_collapse_multiplier"] == ref.first_collapse
    assert r0["windows_below"] == ref.windows_below
    assert r0["first_collapse_multiplier"] <= r0["collapse_multiplier"] * 1.005
    assert out["mean_q"] == pytest.approx(ref.q)
    # the unreinforced wall has no bars to rupture: it overturns
    assert ref.failure_mode == "overturning"
    assert [r["failure_mode"] for r in out["records"]] == ["overturning", "overturning"]


def test_ida_json_failure_mode_of_a_reinforced_wall(record_file, capsys):
    """With GFRP bars the first collapse of this record comes after a bar ruptures: each
    record's row carries "rupture then overturning" (ida's IdaResult.failure_mode)."""
    argv = ["ida", *WALL_ARGS, *BAR_ARGS, "--record", str(record_file), "--json"]
    assert main(argv) == 0
    out = json.loads(capsys.readouterr().out)
    (row,) = out["records"]
    assert row["collapse_multiplier"] is not None
    assert row["failure_mode"] == "rupture then overturning"


@pytest.mark.parametrize(
    "argv,fragment",
    [
        (["--thickness", "-0.4", "--height", "3", "--mechanism", "one-sided"], "--thickness"),
        (["--thickness", "3", "--height", "0.6", "--mechanism", "one-sided"], "thickness < height"),
        ([*WALL_ARGS, *BAR_ARGS[:-1], "25"], "--ratio"),
        ([*WALL_ARGS, "--modulus", "46"], "missing"),
        ([*WALL_ARGS, "--restitution", "bouncy"], "--restitution"),
        ([*WALL_ARGS, "--mechanism", "sideways"], "invalid choice"),
    ],
)
def test_bad_arguments_one_line_exit_2(argv, fragment, record_file, capsys):
    with pytest.raises(SystemExit) as exit_info:
        code = main(["simulate", *argv, "--record", str(record_file)])
        raise SystemExit(code)
    assert exit_info.value.code == 2
    err = capsys.readouterr().err.strip()
    assert fragment in err and "\n" not in err and "Traceback" not in err


@pytest.mark.parametrize("content", ["", "a\nb\nc\nNPTS= 2, DT= 0.01\nnan 0.1\n"])
def test_unreadable_records(tmp_path, content, capsys):
    p = tmp_path / "bad.AT2"
    p.write_text(content)
    assert main(["ida", *WALL_ARGS, "--record", str(p)]) == 2
    err = capsys.readouterr().err.strip()
    assert str(p) in err and "\n" not in err


def test_ida_means_count_records_without_collapse_like_run(tmp_path, capsys):
    """One definition with `run`: a record that does not collapse up to C_max counts at
    C_max·PGA (a lower bound), it is not left out of the mean."""
    strong = tmp_path / "strong.AT2"
    write_at2(Record("strong", 0.01, synthetic_record(3, duration=6.0, pga_g=0.6)), strong)
    weak = tmp_path / "weak.AT2"
    write_at2(Record("weak", 0.01, synthetic_record(4, duration=6.0, pga_g=0.02)), weak)
    argv = ["ida", *WALL_ARGS, "--record", str(strong), "--record", str(weak)]
    assert main([*argv, "--max-multiplier", "3", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    rows = out["records"]
    assert out["records_without_collapse"] == sum(r["a_dyn"] is None for r in rows) >= 1
    bounds = [
        r["a_dyn"] if r["a_dyn"] is not None else 3 * out["a_rm"]  # C_max·PGA = 3·C0·PGA
        for r in rows
    ]
    assert out["lower_bound"] is True
    assert out["mean_a_dyn"] == pytest.approx(sum(bounds) / len(bounds))
    assert out["min_a_dyn"] == pytest.approx(min(bounds))
    assert out["design_a_dyn"] == pytest.approx(min(bounds))  # fewer than 7 records
    assert out["mean_q"] == pytest.approx(out["mean_a_dyn"] / out["a_rm"])
    assert main([*argv, "--max-multiplier", "3"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "lower bounds" in text and f"mean a_dyn = ≥ {out['mean_a_dyn']:.4f} g" in text


def test_ida_multipliers_do_not_depend_on_the_tail(tmp_path, capsys):
    """The issue's wall (0.40 × 5.5 m, two-sided, GFRP centred 1.5 ‰, K ≥ cos α) under the
    default collapse rule: `--tail 0`, `5` and `30` give the same multipliers."""
    from tests.conftest import synthetic_record

    path = tmp_path / "rec.txt"
    acc = synthetic_record(seed=4, duration=10.0, dt=0.01) / 9.80665
    path.write_text("".join(f"{i * 0.01:.2f} {a:.8e}\n" for i, a in enumerate(acc)))
    args = [
        "ida", "--thickness", "0.40", "--height", "5.5", "--mechanism", "two-sided",
        "--modulus", "46", "--ultimate-strain", "0.015", "--position", "centred",
        "--ratio", "1.5", "--record", str(path), "--json",
    ]  # fmt: skip
    got = []
    for tail in ("0", "5", "30"):
        assert main([*args, "--tail", tail]) == 0
        out = json.loads(capsys.readouterr().out)
        got.append([r["collapse_multiplier"] for r in out["records"]])
    assert got[0][0] is not None
    assert got[0] == got[1] == got[2]


def test_a_numerical_failure_is_one_line_and_exit_1(record_file, capsys, monkeypatch):
    """An integrator failure is not the input's fault: one line, exit code 1, no traceback."""
    from frp_assess.errors import NumericalError

    def fail(self, *args, **kwargs):
        raise NumericalError("time history at multiplier C = 3: the wall's fate was not certain")

    monkeypatch.setattr(RockingModel, "run", fail)
    code = main(["simulate", *WALL_ARGS, "--record", str(record_file), "--scale", "3"])
    err = capsys.readouterr().err
    assert code == 1
    assert err.count("\n") == 1 and err.startswith("frp-assess: numerical error: time history")
    assert "Traceback" not in err
