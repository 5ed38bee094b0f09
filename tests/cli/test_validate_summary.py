"""`validate` states the pivot and the confidence factor, which change every verdict.

References written here: FC = 1.35 / 1.20 / 1.00 for LC1 / LC2 / LC3 (Circolare 2019
Tab. C8.5.IV); the pivot rule is `analysis.pivot` as the project file gives it
(docs/model.md §1.1: paper-case pins `edge`, the others take the default `crushing`).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from frp_assess.cli import main

PROJECTS = Path(__file__).resolve().parents[2] / "projects"


def validate(path: Path, capsys: pytest.CaptureFixture[str]) -> str:
    assert main(["validate", str(path)]) == 0
    return capsys.readouterr().out


def test_paper_case_edge_pivot_lc1(capsys: pytest.CaptureFixture[str]) -> None:
    out = validate(PROJECTS / "paper-case.yaml", capsys)
    assert ", pivot edge," in out
    assert (
        "code check: LC1, FC = 1.35 (in the IDA verdict too), q = 2; "
        "intervention: upgrade (NTC 2018 §8.4.3)"
    ) in out


def test_facade_crushing_pivot_lc2_and_fc_off(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    src = (PROJECTS / "facade-laquila.yaml").read_text(encoding="utf-8")
    out = validate(PROJECTS / "facade-laquila.yaml", capsys)
    assert ", pivot crushing," in out
    assert "code check: LC2, FC = 1.2 (in the IDA verdict too), q = 2" in out
    old = "code_check: {knowledge_level: LC2, behaviour_factor: 2.0}"
    assert old in src
    off = tmp_path / "facade.yaml"
    off.write_text(
        src.replace(
            old, "code_check: {knowledge_level: LC3, behaviour_factor: 1.5, fc_in_ida: false}"
        ),
        encoding="utf-8",
    )
    out = validate(off, capsys)
    assert "code check: LC3, FC = 1 (not in the IDA verdict (fc_in_ida: false)), q = 1.5" in out
