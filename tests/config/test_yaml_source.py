"""The YAML level of every input file: bounded work, names as keys, every problem reported."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
import yaml

from frp_assess.config import load_project, load_project_text
from frp_assess.config.problems import InputErrors, problems_of
from frp_assess.config.yaml_source import (
    LOADERS,
    MAX_DEPTH,
    MAX_FILE_BYTES,
    MAX_VALUES,
    FastProjectYamlLoader,
    ProjectYamlLoader,
    parse_yaml,
)
from frp_assess.errors import InputError

GOOD = """\
wall:
  thickness: 0.3
  height: 3
  masonry: rubble-stone
  mechanism: one-sided
seismic:
  spectrum: {type: preset, name: A1}
"""

#: the classic "billion laughs": 9 levels of 9 aliases, a few hundred bytes
BOMB = "a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n" + "".join(
    f"{c}: &{c} [{', '.join([f'*{p}'] * 9)}]\n" for p, c in zip("abcdefgh", "bcdefghi", strict=True)
)


def problems(text: str) -> list[InputError]:
    with pytest.raises(InputError) as info:
        load_project_text(text, "p.yaml", check_files=False)
    return list(problems_of(info.value))


def test_every_schema_problem_is_reported_in_file_order() -> None:
    text = GOOD.replace("thickness: 0.3", "thickness: -0.3").replace(
        "mechanism: one-sided", "mechanism: sideways"
    )
    text = text.replace("height: 3", "hieght: 3") + "  t1: 0\n"
    found = problems(text)
    assert [(p.line, p.key) for p in found] == [
        (2, "wall.thickness"),
        (3, "wall.hieght"),  # the "missing height" it causes is not repeated
        (5, "wall.mechanism"),
        (8, "seismic.t1"),
    ]
    assert all(str(p).startswith(f"p.yaml:{p.line}: {p.key}: ") for p in found)


def test_several_problems_behave_as_the_first() -> None:
    with pytest.raises(InputErrors) as info:
        load_project_text(GOOD.replace("0.3", "-1").replace("3\n", "-3\n"), "p.yaml")
    first = info.value.problems[0]
    assert str(info.value) == str(first) and info.value.line == first.line == 2


def test_alias_bomb_is_refused_quickly() -> None:
    assert len(BOMB.encode()) < 400
    found = problems(BOMB)  # the full expansion is 10^9 values: without the limit, no end
    assert len(found) == 1 and f"{MAX_VALUES:,} values" in found[0].message


def test_recursive_alias_is_refused() -> None:
    (found,) = problems("wall: &w [*w]\n")
    assert "without end" in found.message


@pytest.mark.parametrize("depth", [MAX_DEPTH + 1, 3000])
def test_deep_nesting_is_refused(depth: int) -> None:
    (found,) = problems("wall: " + "[" * depth + "]" * depth + "\n")
    assert f"deeper than {MAX_DEPTH} levels" in found.message and found.line == 1


@pytest.mark.parametrize(
    ("line", "value", "fragment"),
    [
        ("  t1: 022", "022", "octal number 18; write 22"),
        ("  t1: -017", "-017", "octal number -15; write -17"),
        ("  t1: 0x1f", "0x1f", "hexadecimal"),
        ("  t1: 1:30", "1:30", "base-60"),
        ("  t1: 1:30.5", "1:30.5", "base-60"),
    ],
)
def test_integers_in_another_base_are_refused(line: str, value: str, fragment: str) -> None:
    (found,) = problems(GOOD + line + "\n")
    assert found.line == 8 and found.key == "seismic.t1" and fragment in found.message


@pytest.mark.parametrize(
    ("key", "kind"), [("1", "a number"), ("~", "null"), ("yes", "true/false"), ("2.5", "a number")]
)
def test_keys_that_are_not_names_are_refused_on_their_line(key: str, kind: str) -> None:
    (found,) = problems(GOOD.replace("  height: 3\n", f"  height: 3\n  {key}: x\n"))
    assert found.line == 4 and found.key == f"wall.{key}" and kind in found.message


def test_duplicate_merge_keys_are_refused() -> None:
    text = "x: &x {thickness: 0.3}\ny: &y {height: 3}\nwall:\n  <<: *x\n  <<: *y\n"
    (found,) = problems(text)
    assert found.line == 5 and "duplicate key '<<'" in found.message


@pytest.mark.parametrize(
    ("char", "name"), [("\x00", "NUL"), ("\x1b", "ESC"), ("\x7f", "DEL"), ("\x9b", "U+009B")]
)
def test_raw_control_characters_are_refused_with_key_and_line(char: str, name: str) -> None:
    (found,) = problems(GOOD.replace("rubble-stone", f"rubble{char}stone"))
    assert (found.line, found.key) == (4, "wall.masonry") and name in found.message


@pytest.mark.parametrize("escape", ["\\x00", "\\e", "\\x7f", "\\ud83d", "\\u202e"])
def test_escaped_control_characters_are_refused(escape: str) -> None:
    (found,) = problems(GOOD + f'project: {{notes: "a{escape}b"}}\n')
    assert (found.line, found.key) == (8, "project.notes") and "control character" in found.message


def test_syntax_error_comes_alone() -> None:
    (found,) = problems(GOOD.replace("thickness: 0.3", "thickness: [0.3") + "  t1: 022\n")
    assert "YAML syntax error" in found.message


def test_folder_fifo_device_and_size(tmp_path: Path) -> None:
    cases: dict[Path, str] = {tmp_path: "is a folder", Path("/dev/zero"): "not a regular file"}
    fifo = tmp_path / "fifo.yaml"
    os.mkfifo(fifo)
    cases[fifo] = "not a regular file"  # reading it would block
    big = tmp_path / "big.yaml"
    big.write_bytes(b"# " + b"x" * MAX_FILE_BYTES + b"\n")
    cases[big] = "a project file is at most 2 MB"
    latin = tmp_path / "latin.yaml"
    latin.write_bytes(GOOD.encode() + b"project: {name: caf\xe9}\n")
    cases[latin] = "not UTF-8"
    for path, fragment in cases.items():
        with pytest.raises(InputError) as info:
            load_project(path)
        assert fragment in str(info.value) and str(info.value).startswith(str(path)), path


def test_good_text_parses_with_lines() -> None:
    data, lines = parse_yaml(GOOD, "p.yaml")
    assert data["wall"]["height"] == 3 and lines[("wall", "mechanism")] == 5


SHIPPED = sorted((Path(__file__).parents[2] / "projects").glob("*.yaml")) + [
    Path(__file__).parents[2] / "frp_assess" / "templates" / "wall.yaml"
]


@pytest.mark.parametrize("path", SHIPPED, ids=lambda p: p.name)
def test_libyaml_and_pure_python_read_the_same(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    pure = ProjectYamlLoader(text)
    assert parse_yaml(text, "x") == (pure.load(), pure.lines)


def test_json_escaped_emoji_is_one_character() -> None:
    data, _ = parse_yaml('project: {notes: "wall \\ud83d\\ude00"}\n', "p.yaml")
    assert data["project"]["notes"] == "wall \U0001f600"


@pytest.mark.skipif(not yaml.__with_libyaml__, reason="PyYAML without libyaml")
def test_libyaml_parses_when_it_is_installed() -> None:
    # pure-Python PyYAML takes about 15 s on a 300 kB flow list; libyaml about 1 s
    assert LOADERS[0] is FastProjectYamlLoader
    text = "a: [" + ", ".join(["-1"] * 1000) + "]\n"
    assert len(parse_yaml(text, "p.yaml")[0]["a"]) == 1000


def test_at_most_50_problems_are_listed_then_how_many_more() -> None:
    found = problems("wall:\n" + "".join(f"  k: {i}\n" for i in range(61)))
    assert len(found) == 51 and all("duplicate key 'k'" in p.message for p in found[:50])
    assert found[50].message == "10 more problem(s) not shown; fix these first"
