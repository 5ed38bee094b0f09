"""Symbolic links inside the results folder (issue 25, class 5): the tool never writes,
replaces or deletes anything outside ``--out`` through a link it did not make.

A folder holding a link named like one of the tool's own entries is refused before any work
(exit 2, one line naming the link), and the link's target is left as it was.  The IDA cache,
used by library callers without the CLI's check, replaces such a link itself (never its
target).
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from frp_assess.assess.cache import IdaCache
from frp_assess.cli import main
from frp_assess.errors import InputError
from frp_assess.output_set import FolderLock, check_out_dir
from tests.cli.outputs_helpers import tiny_project, tree

REPORT_DATA = Path(__file__).resolve().parents[1] / "report" / "data" / "results.json"

#: every name the tool makes in a results folder, and whether it is a folder
NAMES: list[tuple[str, bool]] = [
    (".lock", False),
    (".cache", True),
    ("records", True),
    ("results.csv", False),
    ("results.json", False),
    ("spectra.csv", False),
    ("report.pdf", False),
    (".staging-4242-0a1b2c3d", True),  # a staging folder
    (".results.json.k3j4.tmp", False),  # a temporary file of an atomic write
]


def _outside(tmp: Path, is_dir: bool) -> Path:
    """A target outside the results folder, holding something the test checks afterwards."""
    target = tmp / "outside"
    target.mkdir()
    if is_dir:
        (target / "keep.txt").write_text("keep\n", encoding="utf-8")
        return target
    victim = target / "victim.txt"
    victim.write_text("precious\n", encoding="utf-8")
    return victim


@pytest.mark.parametrize(("name", "is_dir"), NAMES, ids=[n for n, _ in NAMES])
def test_run_refuses_a_link_named_like_its_own_entries(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], name: str, is_dir: bool
) -> None:
    project = tiny_project(tmp_path)
    out = tmp_path / "res"
    out.mkdir()
    target = _outside(tmp_path, is_dir)
    (out / name).symlink_to(target)
    before = tree(tmp_path / "outside")
    code = main(["run", str(project), "--out", str(out), "--no-pdf"])
    err = capsys.readouterr().err
    assert code == 2
    assert err.count("\n") == 1 and "Traceback" not in err
    assert f"{out / name} is a symbolic link" in err
    assert tree(tmp_path / "outside") == before
    assert (out / name).is_symlink()  # the user's link is not removed either


@pytest.mark.parametrize("name", ["report.pdf", ".lock"])
def test_report_refuses_a_link_in_the_results_folder(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], name: str
) -> None:
    res = tmp_path / "res"
    res.mkdir()
    shutil.copy(REPORT_DATA, res / "results.json")
    victim = _outside(tmp_path, is_dir=False)
    (res / name).symlink_to(victim)
    code = main(["report", str(res)])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1
    assert "symbolic link" in err
    assert victim.read_text(encoding="utf-8") == "precious\n"


def test_records_generate_refuses_a_linked_spectra_csv(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "recs"
    out.mkdir()
    victim = _outside(tmp_path, is_dir=False)
    (out / "spectra.csv").symlink_to(victim)
    code = main(["records", "generate", "--spectrum", "A2", "--count", "1", "--out", str(out)])
    assert code == 2 and "symbolic link" in capsys.readouterr().err
    assert victim.read_text(encoding="utf-8") == "precious\n"


def test_lock_refuses_a_link_made_after_the_check(tmp_path: Path) -> None:
    """check_out_dir passes, then a link appears: the lock still refuses it."""
    out = tmp_path / "res"
    out.mkdir()
    check_out_dir(out)
    victim = _outside(tmp_path, is_dir=False)
    (out / ".lock").symlink_to(victim)
    with pytest.raises(InputError, match="symbolic link"), FolderLock(out):
        pass
    assert victim.read_text(encoding="utf-8") == "precious\n"


def test_a_linked_cache_is_replaced_not_followed(tmp_path: Path) -> None:
    target = _outside(tmp_path, is_dir=True)
    cache_dir = tmp_path / "res" / ".cache"
    cache_dir.parent.mkdir()
    cache_dir.symlink_to(target, target_is_directory=True)
    warnings: list[str] = []
    IdaCache(cache_dir, warn=warnings.append)
    assert not cache_dir.is_symlink() and cache_dir.is_dir()
    assert [p.name for p in target.iterdir()] == ["keep.txt"]
    assert len(warnings) == 1 and "symbolic link" in warnings[0]


def test_a_link_with_another_name_is_left_alone(tmp_path: Path) -> None:
    """Links the tool never writes through (a user's own notes) do not block a run."""
    out = tmp_path / "res"
    out.mkdir()
    (out / "my-notes.txt").symlink_to(_outside(tmp_path, is_dir=False))
    assert check_out_dir(out) == out
