"""Byte-exact regression of the outputs (tests/golden/golden.py says what and how).

Every golden project and study is run four ways through the real command line: one worker
and two, each with a cold cache (a new results folder) and a warm one (a rerun into the
other run's folder, reusing its .cache).  All four must give the bytes committed under
tests/golden/expected/.  A refactoring must leave them unchanged; a change of the results
on purpose rewrites them with ``python3 scripts/update_golden.py`` (and says why in its
commit).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.golden.golden import (
    EXPECTED,
    UPDATE_COMMAND,
    expected_files,
    first_difference,
    producers,
)

ITEMS = producers()


def _check(expected: dict[str, bytes], found: dict[str, bytes], variant: str) -> None:
    for key, data in found.items():
        if key not in expected:
            pytest.fail(
                f"{variant}: no golden file tests/golden/expected/{key}; "
                f"create it with {UPDATE_COMMAND}"
            )
        if data != expected[key]:
            pytest.fail(
                f"{variant}: tests/golden/expected/{key} differs at "
                f"{first_difference(expected[key], data)}\n"
                f"If this change of results is intended, regenerate with {UPDATE_COMMAND} "
                "and say why in the commit."
            )


@pytest.mark.parametrize("name", sorted(ITEMS))
def test_golden_bytes_cold_and_warm_one_and_two_workers(name: str, tmp_path: Path) -> None:
    expected = expected_files()
    produce = ITEMS[name]
    one, two = tmp_path / "jobs1", tmp_path / "jobs2"
    for out, jobs, variant in (
        (one, 1, "cold cache, --jobs 1"),
        (two, 2, "cold cache, --jobs 2"),
        (two, 1, "warm cache (the --jobs 2 folder), --jobs 1"),
        (one, 2, "warm cache (the --jobs 1 folder), --jobs 2"),
    ):
        found = produce(out, jobs)
        _check(expected, found, f"{name} ({variant})")
    assert any(k.startswith(f"{name}/") for k in expected)


def test_no_stale_golden_files() -> None:
    """Every file under expected/ belongs to a golden item (update_golden.py removes the rest)."""
    names = {key.split("/", 1)[0] for key in expected_files()}
    assert names == set(ITEMS), (
        f"tests/golden/expected/ holds {sorted(names)}, the golden items are {sorted(ITEMS)}; "
        f"run {UPDATE_COMMAND}"
    )
    assert EXPECTED.is_dir()
