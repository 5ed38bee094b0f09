"""Rewrite the golden files: every file under tests/golden/expected/, from the golden projects.

    python3 scripts/update_golden.py

The only way the expected files change.  It runs each golden project and study through the
same code path as tests/golden/test_golden.py (tests/golden/golden.py: the real command line,
in process) once with one worker and once with two, each into a new folder; it refuses to
write anything if the two differ (the outputs would not be reproducible), then replaces
tests/golden/expected/ as a whole (files of items no longer in the golden set are removed).
Run it only for a change of results on purpose, and say why in the commit.

The kernel is compiled afresh into a temporary numba cache: numba's ``cache=True`` does not
notice that a function it inlined from another file has changed, so a developer's cache can
hold machine code of an older kernel (it once put peaks 3e-5 off in the golden files).
"""

from __future__ import annotations

import os
import shutil
import sys
import tempfile
from pathlib import Path

# before numba is imported: a cache of this run only (see the docstring)
os.environ["NUMBA_CACHE_DIR"] = tempfile.mkdtemp(prefix="frp-golden-numba-")
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from tests.golden.golden import EXPECTED, first_difference, producers  # noqa: E402


def produce_all(work: Path) -> dict[str, bytes]:
    """Every golden file, checked to be the same with one and two workers."""
    files: dict[str, bytes] = {}
    for name, produce in producers().items():
        one = produce(work / name / "jobs1", 1)
        two = produce(work / name / "jobs2", 2)
        for key, data in one.items():
            if two[key] != data:
                raise SystemExit(
                    f"update_golden: {key} differs between --jobs 1 and --jobs 2 at "
                    f"{first_difference(data, two[key])}; nothing written"
                )
        files.update(one)
    return files


def main() -> int:
    with tempfile.TemporaryDirectory(prefix="frp-golden-") as tmp:
        files = produce_all(Path(tmp))
    old = {p for p in EXPECTED.rglob("*") if p.is_file()} if EXPECTED.is_dir() else set()
    changed = 0
    for key, data in sorted(files.items()):
        path = EXPECTED / key
        if not path.is_file() or path.read_bytes() != data:
            changed += 1
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(data)
            print(f"written  tests/golden/expected/{key}")
        old.discard(path)
    for path in sorted(old):
        path.unlink()
        print(f"removed  {path.relative_to(EXPECTED.parents[2]).as_posix()}")
    for folder in sorted((p for p in EXPECTED.rglob("*") if p.is_dir()), reverse=True):
        if not any(folder.iterdir()):
            shutil.rmtree(folder)
    print(f"update_golden: {len(files)} files, {changed} changed, {len(old)} removed")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
