"""The editor's model and IDA fields are their declared options (frp_assess/dynamics/options.py).

Like tests/dynamics/test_options.py does for the schemas and the command line: each declared
option has a field in the Analysis tab at its key path of the project file, and that field's
help line, default, choices and range text are the declaration's.  The range texts the issue
found hand-written and wrong (step ratio ``> 1``, IDA tolerance ``0-0.1``) are spelled out by
hand here from the declared bounds (docs/model.md §5: s in [1.01, 10], tolerance in
[1e-4, 0.1]).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from textual.widgets import Input, Label, Static, TabbedContent

from frp_assess.config.schema import AnalysisSpec
from frp_assess.dynamics.options import (
    COLLAPSE,
    FREE_VIBRATION_TAIL,
    IDA_CAPACITY,
    IDA_LADDER_RATIO,
    IDA_MAX_MULTIPLIER,
    IDA_OFFSET,
    IDA_OPTIONS,
    IDA_STEP_RATIO,
    IDA_TOLERANCE,
    INTEGRATION_TOLERANCE,
    MODEL_OPTIONS,
    PIVOT,
    RESTITUTION,
    RUPTURE,
    STRAIN_FACTOR,
    VERIFY,
    Option,
)
from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.field_specs import ANALYSIS_FIELDS
from frp_assess.tui.fields import FieldSpec
from frp_assess.tui.option_fields import option_field, option_hint
from tests.tui.conftest import run_async, settle

#: where each declared option lives in a project file (docs/project-file keys)
OPTION_PATHS: list[tuple[tuple[str, ...], Option[Any]]] = [
    (("analysis", "restitution"), RESTITUTION),
    (("analysis", "rupture"), RUPTURE),
    (("analysis", "collapse"), COLLAPSE),
    (("analysis", "pivot"), PIVOT),
    (("analysis", "strain_factor"), STRAIN_FACTOR),
    (("analysis", "free_vibration_tail"), FREE_VIBRATION_TAIL),
    (("analysis", "integration", "tolerance"), INTEGRATION_TOLERANCE),
    (("analysis", "integration", "verify"), VERIFY),
    (("analysis", "ida", "step_ratio"), IDA_STEP_RATIO),
    (("analysis", "ida", "capacity"), IDA_CAPACITY),
    (("analysis", "ida", "ladder_ratio"), IDA_LADDER_RATIO),
    (("analysis", "ida", "offset"), IDA_OFFSET),
    (("analysis", "ida", "tolerance"), IDA_TOLERANCE),
    (("analysis", "ida", "max_multiplier"), IDA_MAX_MULTIPLIER),
]


def field_at(path: tuple[str, ...]) -> FieldSpec:
    found = [f for f in ANALYSIS_FIELDS if f.path == path]
    assert len(found) == 1, f"the Analysis tab has {len(found)} fields for {'.'.join(path)}"
    return found[0]


def test_every_declared_option_is_listed_here() -> None:
    """A new option in dynamics/options.py fails here until it has its path (and field)."""
    declared = {id(o): o.key for o in (*MODEL_OPTIONS.values(), *IDA_OPTIONS.values())}
    declared |= {id(STRAIN_FACTOR): STRAIN_FACTOR.key, id(VERIFY): VERIFY.key}
    listed = {id(o) for _, o in OPTION_PATHS}
    assert not set(declared) - listed, sorted(declared[i] for i in set(declared) - listed)


@pytest.mark.parametrize(
    ("path", "option"), OPTION_PATHS, ids=[".".join(p) for p, _ in OPTION_PATHS]
)
def test_each_option_field_is_its_declaration(path: tuple[str, ...], option: Option[Any]) -> None:
    spec = field_at(path)
    assert spec.help == option.describe()
    assert spec.default == option.default
    if option.numeric:  # typed: a number (or one of the words), empty for the default
        assert spec.kind == "scalar" and spec.optional
        assert option.range_text() in spec.unit and option.unit in spec.unit
        assert spec.unit.startswith("or ") == bool(option.choices)  # the words: in the help
    elif option.is_flag:
        assert spec.kind == "choice" and [v for _, v in spec.choices] == [False, True]
    else:
        assert spec.kind == "choice" and [v for _, v in spec.choices] == list(option.choices)


@pytest.mark.parametrize(
    ("path", "option"), OPTION_PATHS, ids=[".".join(p) for p, _ in OPTION_PATHS]
)
def test_the_field_path_is_the_schema_field_of_the_option(
    path: tuple[str, ...], option: Option[Any]
) -> None:
    """The key path leads to the project schema's field, whose description is the option's."""
    model: Any = AnalysisSpec
    for key in path[1:-1]:
        model = model.model_fields[key].annotation
    assert model.model_fields[path[-1]].description == option.describe()


def test_the_range_texts_the_issue_found_wrong() -> None:
    """Hand-written from docs/model.md §5 and §4: what shows right of the inputs."""
    assert field_at(("analysis", "ida", "step_ratio")).unit == "[1.01, 10] (1.1)"
    assert field_at(("analysis", "ida", "tolerance")).unit == "[0.0001, 0.1] (0.005)"
    assert field_at(("analysis", "ida", "max_multiplier")).unit == "(1, 1000] (100)"
    assert field_at(("analysis", "free_vibration_tail")).unit == "s, [0, 60] (0)"
    assert field_at(("analysis", "restitution")).unit == "or (0, 1] (energy)"


def test_option_hint_and_labels() -> None:
    """Made-up options: unit before the range, ``or`` before a range besides words; a label
    for a value the option does not take is refused."""
    length = Option(
        key="x", flag="", default=2.0, help="A length", unit="m", low=0.0, low_open=True
    )
    ratio = Option(key="r", flag="", default="auto", help="R", choices=("auto",), high=1.0)
    assert option_hint(length) == "m, > 0"
    assert option_hint(ratio) == "or <= 1"
    assert option_field(("a", "x"), "X", length).unit == "m, > 0 (2)"
    word = Option(key="w", flag="", default="a", help="W", choices=("a", "b"))
    spec = option_field(("a", "w"), "W", word, labels={"b": "b (other)"})
    assert spec.choices == (("a", "a"), ("b (other)", "b"))
    with pytest.raises(ValueError, match="c"):
        option_field(("a", "w"), "W", word, labels={"c": "?"})


@pytest.mark.slow
def test_the_analysis_tab_shows_and_checks_the_declared_range(small_project: Path) -> None:
    """Driven with Pilot: the step ratio's row shows the declared range, its help line is the
    declaration's, and 1.005 (below 1.01, above the old hint's ``> 1``) is refused on the field
    while 1.2 is taken into the project."""

    async def body() -> None:
        app = FrpAssessApp(small_project)
        path = ("analysis", "ida", "step_ratio")
        async with app.run_test(size=(100, 30)) as pilot:
            await pilot.pause()
            await pilot.press("f7")
            tabs = app.query_one("#tabs", TabbedContent)
            await settle(pilot, lambda: tabs.active == "tab-analysis")
            row = next(r for r in app.rows if r.spec.path == path)
            assert str(row.query_one(".f-unit", Label).content) == "[1.01, 10] (1.1)"
            box = row.query_one(Input)
            box.focus()
            help_line = app.query_one("#help-line", Static)
            await settle(pilot, lambda: str(help_line.content) == IDA_STEP_RATIO.describe())
            box.value = "1.00"
            box.cursor_position = len(box.value)
            await pilot.press("5")
            await settle(pilot, lambda: row.error is not None)
            assert row.error is not None and "[1.01, 10]" in row.error and "1.005" in row.error
            box.value = "1."
            box.cursor_position = len(box.value)
            await pilot.press("2")
            await settle(pilot, lambda: row.error is None and app.project is not None)
            assert app.project is not None and app.project.analysis.ida.step_ratio == 1.2

    run_async(body)
