"""The date a run records (results.json ``created``): ``--created`` and SOURCE_DATE_EPOCH."""

from __future__ import annotations

import datetime as dt

import pytest

from frp_assess.api import SOURCE_DATE_EPOCH, run_date
from frp_assess.cli import build_parser
from frp_assess.errors import InputError


def test_source_date_epoch_fixes_the_day_in_utc(monkeypatch: pytest.MonkeyPatch) -> None:
    # 1970-01-01 to 2025-01-01: 55 years of 365 days and 14 leap days (1972-2024) = 20089
    # days of 86400 s; one second earlier is still 2024-12-31 in UTC
    monkeypatch.setenv(SOURCE_DATE_EPOCH, str(20089 * 86400 - 1))
    assert run_date() == "2024-12-31"
    monkeypatch.setenv(SOURCE_DATE_EPOCH, str(20089 * 86400))
    assert run_date() == "2025-01-01"


def test_without_source_date_epoch_the_date_is_today(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(SOURCE_DATE_EPOCH, raising=False)
    before = dt.date.today().isoformat()
    found = run_date()
    assert found in {before, dt.date.today().isoformat()}


def test_bad_source_date_epoch_is_one_line_naming_the_variable(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setenv(SOURCE_DATE_EPOCH, "1e99")
    with pytest.raises(InputError, match=r"^SOURCE_DATE_EPOCH: expected whole seconds"):
        run_date()


def test_hidden_created_option(capsys: pytest.CaptureFixture[str]) -> None:
    parser = build_parser()
    args = parser.parse_args(["run", "p.yaml", "--created", "2025-01-01"])
    assert args.created == "2025-01-01"
    with pytest.raises(SystemExit) as exit_info:
        parser.parse_args(["run", "p.yaml", "--created", "2025-13-01"])
    assert exit_info.value.code == 2
    assert "expected a date YYYY-MM-DD, found '2025-13-01'" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        parser.parse_args(["run", "--help"])
    assert "--created" not in capsys.readouterr().out
