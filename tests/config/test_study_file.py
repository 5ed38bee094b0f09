"""`validate` recognises a study file and checks it with the study schema."""

from __future__ import annotations

from pathlib import Path

import pytest

import frp_assess
from frp_assess.cli import main
from frp_assess.config.yaml_source import parse_yaml
from frp_assess.study.schema import MAX_CASES, load_study, looks_like_study

PROJECTS = Path(frp_assess.__file__).parent.parent / "projects"
STUDY = """\
name: tiny
height: [3.0]
alpha_deg: [7.5]
ratio: [1.0]
material: [CFRP]
position: [external]
spectrum: [A2]
records: {count: 3, seed: 1, duration: 14.0}
"""


@pytest.mark.parametrize("path", sorted(PROJECTS.glob("*.yaml")), ids=lambda p: p.stem)
def test_every_shipped_file_validates(path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["validate", str(path)]) == 0
    out = capsys.readouterr().out
    assert out.startswith(f"{path}: OK")
    text = path.read_text(encoding="utf-8")
    assert ("cases" in out.splitlines()[0]) == looks_like_study(parse_yaml(text, "x")[0])


def test_study_problems_are_all_reported_on_their_lines(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = STUDY.replace("[3.0]", "[3.0, .inf]").replace("seed: 1", "seed: -1")
    bad = bad.replace("[CFRP]", "[KFRP]").replace("[A2]", "[A2, 'ec8:type=3,ground=B,ag=0.2']")
    path = tmp_path / "s.yaml"
    path.write_text(bad, encoding="utf-8")
    assert main(["validate", str(path)]) == 2
    err = capsys.readouterr().err.splitlines()
    assert [line.split(": ")[2] for line in err] == [f"{path}:2", f"{path}:8"]
    # the schema's problems stop there; once they are fixed, materials and spectra are checked
    path.write_text(bad.replace(", .inf", "").replace("seed: -1", "seed: 1"), encoding="utf-8")
    assert main(["validate", str(path)]) == 2
    err = capsys.readouterr().err.splitlines()
    assert err[0].startswith(f"frp-assess: error: {path}:5: material[0]: unknown material 'KFRP'")
    assert err[1].startswith(f"frp-assess: error: {path}:7: spectrum[1]: EC8 type must be 1 or 2")
    assert "unknown key 'name'" not in "\n".join(err)


def test_study_size_is_bounded(tmp_path: Path) -> None:
    path = tmp_path / "big.yaml"
    heights = ", ".join(str(3 + k / 100) for k in range(400))
    ratios = ", ".join(str(1 + k / 100) for k in range(300))
    path.write_text(
        STUDY.replace("[3.0]", f"[{heights}]").replace("ratio: [1.0]", f"ratio: [{ratios}]"),
        encoding="utf-8",
    )
    with pytest.raises(frp_assess.errors.InputError) as info:
        load_study(path)
    assert f"more than {MAX_CASES:,}" in str(info.value) and info.value.line == 1
