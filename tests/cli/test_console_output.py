"""What the CLI prints: user text is shown literally, numbers are never cut, the number shown
agrees with the verdict."""

from __future__ import annotations

import copy
import io
from typing import Any

import pytest

from frp_assess.cli.output import Column, make_console, print_table, user
from frp_assess.cli.ranking import print_ranking, ranking_rows
from frp_assess.numbers import fmt_against
from frp_assess.text_safety import PLACEHOLDER, plain
from tests.report.test_report import raw, typed
from tests.results.decided import decided


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
        for cell in row[2:]:
            # a lower bound is "≥ 11.53": the number whole, after its sign
            assert cell.split()[-1] in tokens, (cell, width)
    # headers carry units, the title the demand in g
    flat = " ".join(out.split())
    assert "kg" in flat and "FC·a_g·S" in flat and " g" in flat


@pytest.mark.parametrize("width", [60, 80])
def test_hostile_names_print_literally(results: dict[str, Any], width: int) -> None:
    r = copy.deepcopy(results)
    r["costs"]["currency"] = "[/x]"
    for i, name in ((1, "[b]G[/x]\x1b[2J"), (2, ":smile:\x1b]0;\x07")):
        old, r["cases"][i]["name"] = r["cases"][i]["name"], name
        for key in ("recommended", "closest"):  # a case's name, read back (read_checks)
            r[key] = name if r[key] == old else r[key]
    out = printed(width, print_ranking, typed(r))
    assert "\x1b" not in out and "\x07" not in out
    tokens = out.split()
    assert f"[b]G[/x]{PLACEHOLDER}[2J" in tokens
    assert f":smile:{PLACEHOLDER}]0;{PLACEHOLDER}" in tokens
    assert "[/x]," in tokens  # the currency, in the legend


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


def test_text_columns_wrap_whole_words_at_80_columns() -> None:
    """The spectrum-compatibility table at 80 columns: a word is never cut in two
    ("pseudo-stationar / y" was), each cell's words are printed whole."""
    from frp_assess.cli.cmd_run import COMPLIANCE_COLUMNS

    rows = [
        ["NTC 2018", "§3.2.3.6", "pseudo-stationary part ≥ 10 s", "shortest 10 s", "+0 s", "pass"],
        [
            "EN 1998-1",
            "§3.2.3.1.2(4)c",
            "mean spectrum ≥ 90% of target",
            "min 96.4%",
            "+6.4%",
            "pass",
        ],
    ]
    out = printed(80, lambda con: print_table(con, "t", COMPLIANCE_COLUMNS, rows))
    assert max(len(line) for line in out.splitlines()) <= 80
    assert "┃" not in out and "─" in out  # a table, not stacked records
    tokens = set(out.split())
    for row in rows:
        for cell in row:
            assert set(cell.split()) <= tokens, cell


def test_the_ranking_is_one_table_of_80_columns_with_the_decision(
    results: dict[str, Any],
) -> None:
    """18 options at 80 columns: one line each (not 18 stacked blocks), with the decision's
    verdict, governing check and margin on the option's line; a legend says what they mean."""
    r = typed(decided(results))
    out = printed(80, print_ranking, r)
    lines = out.splitlines()
    assert max(len(line) for line in lines) <= 80
    for c in r.cases:
        line = next(line for line in lines if f" {c.name} " in line)
        word = "recommended" if c.recommended else ("passes" if c.passes else "fails")
        assert word in line.split() and "TH" in line.split(), line
        if c.governing_margin == 0.0:
            assert "falls" in line.split()
    assert len(lines) < 2 * len(r.cases)
    assert "TH SLV, TH SLC: time-history check" in " ".join(out.split())


def test_no_option_is_recommended_when_the_wall_needs_no_retrofit(
    results: dict[str, Any],
) -> None:
    """results.json says no retrofit is required (the unreinforced wall passes) and names the
    cheapest passing option: the console calls it "passes", never "recommended", and says
    that no retrofit is needed (Norcia printed "(recommended)" beside "no retrofit needed")."""
    raw_r = decided(results)
    raw_r["cases"][0].update(passes=True, governing_margin=1.5)
    raw_r["retrofit_required"] = False
    r = typed(raw_r)
    out = printed(80, print_ranking, r)
    assert "recommended" not in out.replace("no option is recommended", "")
    assert "no retrofit needed" in " ".join(out.split())
