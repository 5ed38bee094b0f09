"""What the CLI prints: user text is shown literally, numbers are never cut, the number shown
agrees with the verdict."""

from __future__ import annotations

import copy
import io
from typing import Any

import pytest

from frp_assess.cli.cmd_run import print_ranking, ranking_rows
from frp_assess.cli.output import Column, make_console, print_table, user
from frp_assess.numbers import fmt_against
from frp_assess.text_safety import PLACEHOLDER, plain
from tests.report.test_report import raw, typed


@pytest.fixture
def results() -> dict[str, Any]:
    """The report's fixture as plain JSON values (tests edit a copy and read it typed)."""
    return raw()


def printed(width: int, fn: Any, *args: Any) -> str:
    buf = io.StringIO()
    fn(make_console(file=buf, width=width), *args)
    return buf.getvalue()


@pytest.mark.parametrize("width", [60, 80, 120])
def test_ranking_never_cuts_a_number(results: dict[str, Any], width: int) -> None:
    out = printed(width, print_ranking, typed(results))
    assert "…" not in out
    assert max(len(line) for line in out.splitlines()) <= width
    tokens = set(out.split())
    for row in ranking_rows(typed(results)):
        for cell in row[2:8]:
            # a lower bound is "≥ 11.53": the number whole, after its sign
            assert cell.split()[-1] in tokens, (cell, width)
    # headers carry units
    flat = " ".join(out.split())
    assert "[kg]" in flat and "[g]" in flat


@pytest.mark.parametrize("width", [60, 80])
def test_hostile_names_print_literally(results: dict[str, Any], width: int) -> None:
    r = copy.deepcopy(results)
    r["costs"]["currency"] = "[/x]"
    r["cases"][1]["name"] = "[b]G[/x]\x1b[2J"
    r["cases"][2]["name"] = ":smile:\x1b]0;\x07"
    out = printed(width, print_ranking, typed(r))
    assert "\x1b" not in out and "\x07" not in out
    tokens = out.split()
    assert f"[b]G[/x]{PLACEHOLDER}[2J" in tokens
    assert f":smile:{PLACEHOLDER}]0;{PLACEHOLDER}" in tokens
    assert "[[/x]]" in tokens


def test_stacked_layout_when_too_narrow() -> None:
    cols = [Column("name", text=True), Column("value [kN]"), Column("other quantity [m]")]
    rows = [["a", "123456.789", "0.000123"], ["b", "1.5", "2.25"]]
    out = printed(30, lambda con: print_table(con, "t", cols, rows))
    assert "value [kN]" in out and "┃" not in out and "│" not in out  # stacked, not a table
    for cell in ("123456.789", "0.000123", "1.5", "2.25"):
        assert cell in out.split()


def test_stacked_records_print_as_one_line_per_cell() -> None:
    """The stacked records come out of one print: the same text as one print per line (an
    empty line before each record, a cell longer than the console folded, markup shown)."""
    cols = [Column("name", text=True), Column("value [kN]"), Column("other quantity [m]")]
    rows = [["a" * 50, "123456.789", "0.000123"], ["[b]x[/b]", "1.5", "2.25"]]
    out = printed(30, lambda con: print_table(con, "t", cols, rows))
    buf = io.StringIO()
    con = make_console(file=buf, width=30)
    con.print("t", soft_wrap=False)
    for r in rows:
        con.print("")
        labels = ("name", "value [kN]", "other quantity [m]")
        for label, cell in zip((user(x.ljust(18)) for x in labels), r, strict=True):
            con.print(f"  {label}  {user(cell)}", overflow="fold")
    assert out == buf.getvalue()
    assert "[b]x[/b]" in out and max(len(line) for line in out.splitlines()) <= 30


def test_user_and_plain_remove_every_control() -> None:
    every = "".join(chr(c) for c in [*range(0x20), *range(0x7F, 0xA0)])
    assert plain(every) == PLACEHOLDER * len(every)
    assert user("[/x]") == "\\[/x]"
    assert plain("a\nb", keep_newlines=True) == "a\nb"


@pytest.mark.parametrize(
    ("value", "target", "meets", "shown"),
    [
        (0.997, 1.0, False, "0.997"),
        (0.9999, 1.0, False, "0.9999"),
        (1.0, 1.0, True, "1.00"),
        (1.004, 1.0, True, "1.00"),
        (0.994, 1.0, False, "0.99"),
        (1.2049, 1.205, False, "1.20"),
        (1.19995, 1.2, False, "1.19995"),
        (2.5, 1.0, None, "2.50"),
    ],
)
def test_shown_capacity_agrees_with_the_verdict(
    value: float, target: float, meets: bool | None, shown: str
) -> None:
    assert fmt_against(value, target, meets) == shown
    if meets is not None:
        assert (float(shown) >= target) == meets
