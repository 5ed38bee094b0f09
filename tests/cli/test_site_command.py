"""`frp-assess site`: the NTC parameters of a site from its coordinates, as text and JSON.

References: T_R of V_N = 50 years, class II: −50/ln(1 − P_VR) = 30.1, 50.3, 474.6, 974.8
years (NTC 2018 Tab. 3.2.I: 30, 50, 475, 975); L'Aquila's a_g(SLV) = 0.2607 g is the hand
calculation of tests/motions/test_site_hazard.py.
"""

from __future__ import annotations

import json
import math

import pytest

from frp_assess.cli import main


def test_json_has_the_four_limit_states(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["site", "--lat", "42.35", "--lon", "13.40", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert list(data) == ["SLO", "SLD", "SLV", "SLC"]
    for state, p in {"SLO": 0.81, "SLD": 0.63, "SLV": 0.10, "SLC": 0.05}.items():
        assert set(data[state]) >= {"TR", "ag", "F0", "Tc_star"}
        assert data[state]["TR"] == pytest.approx(-50 / math.log(1 - p))
    assert data["SLV"]["ag"] == pytest.approx(0.2606566, rel=2e-6)


def test_use_class_iv_and_nominal_life_100(capsys: pytest.CaptureFixture[str]) -> None:
    args = ["site", "--lat", "42.35", "--lon", "13.40", "--json"]
    assert main([*args, "--nominal-life", "100", "--use-class", "IV"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["SLV"]["TR"] == pytest.approx(-200 / math.log(0.9))  # V_R = 100·2.0


def test_table_output(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["site", "--lat", "42.35", "--lon", "13.40"]) == 0
    out = capsys.readouterr().out
    assert "V_R = 50 years" in out
    lines = {line.split()[0]: line.split() for line in out.splitlines() if line[:2] == "SL"}
    assert [lines[s][2] for s in ("SLO", "SLD", "SLV", "SLC")] == ["30", "50", "475", "975"]
    assert lines["SLV"][3] == "0.2607"
    assert "Values from the 4 vertices of the grid cell that contains the site" in out
    # at sea south of Ischia, in no complete cell: the fallback is said
    assert main(["site", "--lat", "40.63", "--lon", "13.86"]) == 0
    assert "the 4 nearest nodes: no complete grid cell" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("args", "expected"),
    [
        (["--lat", "39.22", "--lon", "9.11"], "outside the NTC reference grid"),
        (["--lat", "91", "--lon", "9"], "--lat: expected a number in [-90, 90]"),
        (["--lat", "45", "--lon", "9", "--use-class", "V"], "invalid choice: 'V'"),
        (["--lat", "45", "--lon", "9", "--nominal-life", "0"], "--nominal-life"),
        (["--lat", "45"], "required: --lon"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(
    args: list[str], expected: str, capsys: pytest.CaptureFixture[str]
) -> None:
    try:  # argparse refuses by SystemExit, the command itself by its return code
        code = main(["site", *args])
    except SystemExit as exc:
        code = exc.code
    assert code == 2
    err = capsys.readouterr().err
    assert expected in err
    assert err.count("\n") == 1
