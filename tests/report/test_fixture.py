"""The report's fixture follows the typed results model: it is what make_fixture.py writes
today through :func:`frp_assess.results.json_io.to_json`, and it reads back unchanged."""

from __future__ import annotations

import importlib.util
from pathlib import Path

from frp_assess.results.json_io import from_json, to_json

DATA = Path(__file__).with_name("data")


def test_the_committed_fixture_is_what_the_script_writes() -> None:
    spec = importlib.util.spec_from_file_location("make_fixture", DATA / "make_fixture.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    committed = (DATA / "results.json").read_text(encoding="utf-8")
    assert module.fixture_text() == committed, (
        "tests/report/data/results.json is stale: run "
        "`PYTHONPATH=. python3 tests/report/data/make_fixture.py`"
    )


def test_the_fixture_reads_and_writes_back_byte_identical() -> None:
    text = (DATA / "results.json").read_text(encoding="utf-8")
    assert to_json(from_json(text, file="results.json")) == text
