"""`code_check.intervention` end to end: the same wall judged as an upgrade and as an
improvement by `frp-assess run`, and the located refusals of the input.

References: NTC 2018 §8.4.2 (an improvement raises ζ_E by at least 0.1, or to 0.6 for use
class III schools and class IV) and §8.4.3 (an upgrade: ζ_E ≥ 1; here the IDA's target 7,
`analysis.target`), read by hand against the numbers of the run's own results.json.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from frp_assess.cli import main

ROOT = Path(__file__).resolve().parents[2]
#: the golden small wall (tests/golden/projects/small.yaml) with the IDA's target raised to
#: 7: its unreinforced ζ_E is 4.31 and the option's 6.07 (tests/golden/expected/small)
PROJECT = (ROOT / "tests" / "golden" / "projects" / "small.yaml").read_text(encoding="utf-8")
TARGET_7 = PROJECT.replace(
    "analysis:\n  ida:", "analysis:\n  target: 7.0\n  ida:"
)  # an upgrade the option cannot reach


def run(tmp_path: Path, name: str, code_check: str) -> dict:
    project = tmp_path / f"{name}.yaml"
    project.write_text(TARGET_7 + code_check, encoding="utf-8")
    out = tmp_path / f"{name}-out"
    assert main(["run", str(project), "--out", str(out), "--no-pdf", "--jobs", "1"]) == 0
    return json.loads((out / "results.json").read_text(encoding="utf-8"))


def test_an_improvement_passes_what_an_upgrade_fails(tmp_path: Path) -> None:
    """As an upgrade (the default) the option's IDA ζ_E 6.07 < 7 fails, and so does the
    wall as it is (4.31 < 7): nothing is recommended.  As an improvement of a class II
    building the option must reach the unreinforced mechanism's ζ_E + 0.1 on every deciding
    check: 4.31 + 0.1 = 4.41 ≤ 6.07 (IDA), ≤ 551 (SLV), ≤ 1249 (SLC): it passes and is
    recommended; the wall as it is still fails (it is judged by the assessment)."""
    up = run(tmp_path, "upgrade", "")
    assert up["intervention"]["category"] == "upgrade"
    assert up["intervention"]["clause"] == "NTC 2018 §8.4.3"
    assert up["cases"][1]["passes"] is False and up["recommended"] is None
    imp = run(tmp_path, "improvement", "code_check: {intervention: improvement, use_class: II}\n")
    block = imp["intervention"]
    urm, option = imp["cases"]
    zetas = [c["margin"] * 7.0 if c["name"] == "IDA capacity/demand" else c["margin"]
             for c in urm["deciding_checks"]]  # fmt: skip
    assert block["as_is_zeta"] == pytest.approx(min(zetas))
    assert block["required_zeta"] == pytest.approx(min(zetas) + 0.1)
    assert block["use_class"] == "II" and block["strict"] is False
    assert urm["passes"] is False and imp["retrofit_required"] is True
    assert option["passes"] is True and imp["recommended"] == option["name"]
    ida = option["deciding_checks"][0]
    assert ida["margin"] == pytest.approx(6.0659 / block["required_zeta"], rel=1e-4)
    assert "§8.4.2" in imp["decision_rule"]


@pytest.mark.parametrize(
    "code_check, key, says",
    [
        ("{intervention: improvement}", "code_check.intervention", "use class"),
        ("{intervention: improvement, use_class: II, school: true}", "code_check.school", "III"),
        ("{intervention: renovation}", "code_check.intervention", "local"),
    ],
)
def test_refused_in_one_line_at_the_key(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], code_check: str, key: str, says: str
) -> None:
    """An improvement without a use class, a school of class II, an unknown category: exit
    2, one line naming the file and the key, nothing written."""
    project = tmp_path / "p.yaml"
    project.write_text(PROJECT + f"code_check: {code_check}\n", encoding="utf-8")
    assert main(["run", str(project), "--no-pdf"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1, err
    assert "p.yaml" in err and key in err and says in err, err
    assert list(tmp_path.iterdir()) == [project]


def test_the_use_class_of_the_site_and_of_code_check_must_agree(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A spectrum by coordinates of class III and code_check.use_class IV: one building,
    one use class: refused at code_check.use_class."""
    text = PROJECT.replace(
        "spectrum: {type: preset, name: A2}",
        "spectrum: {type: ntc2018, site: {latitude: 42.35, longitude: 13.40}, "
        "use_class: III, soil: B}",
    )
    project = tmp_path / "p.yaml"
    project.write_text(
        text + "code_check: {intervention: improvement, use_class: IV}\n", encoding="utf-8"
    )
    assert main(["run", str(project), "--no-pdf"]) == 2
    err = capsys.readouterr().err.strip()
    assert "code_check.use_class" in err and "III" in err and "IV" in err, err


def test_design_mode_searches_the_category_s_target(tmp_path: Path) -> None:
    """Design mode walks the grid up to the first ratio meeting what the category asks: as
    an upgrade the IDA's ζ_E must reach the target 7 (the golden small wall's 1 ‰ gives
    6.07: a larger ratio); as an improvement of class II it must reach 4.31 + 0.1 = 4.41,
    which a smaller ratio does.  Each answer passes the decision; the improvement's is the
    smaller and its ζ_E lies between 4.41 and 7."""
    design = "design: {materials: [GFRP], positions: [external], ratio_range: [0.1, 2.1], "
    design += "resolution: 0.2}\n"
    up = run(tmp_path, "design-upgrade", design)["design"][0]
    imp = run(
        tmp_path, "design-improvement", design + "code_check: {intervention: improvement, "
        "use_class: II}\n"
    )  # fmt: skip
    found = imp["design"][0]
    assert up["ratio"] is not None and up["capacity_demand"] >= 7.0
    assert found["ratio"] is not None and found["ratio"] < up["ratio"]
    required = imp["intervention"]["required_zeta"]
    assert required <= found["capacity_demand"] < 7.0
    case = next(c for c in imp["cases"] if c["name"] == found["case"])
    assert case["passes"] is True
