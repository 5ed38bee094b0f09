"""Each user option is declared once (frp_assess/dynamics/options.py); the dataclasses, the
project and study schemas and the command line are checked against that declaration here.

The expected values are the declaration's own numbers (what each layer must agree with) and,
for :class:`Option` itself, hand-picked values on either side of each bound.
"""

from __future__ import annotations

import argparse
import math
from dataclasses import fields
from typing import Any, get_args

import pytest
from pydantic import BaseModel, ValidationError

from frp_assess.cli import build_parser
from frp_assess.config.schema import AnalysisSpec, IdaSpec, IntegrationSpec, ModelOptionsSpec
from frp_assess.dynamics import IdaSettings, ModelOptions, Rebars
from frp_assess.dynamics.options import (
    IDA_OPTIONS,
    INTEGRATION_TOLERANCE,
    MODEL_OPTIONS,
    RESTITUTION,
    STRAIN_FACTOR,
    VERIFY,
    Option,
)
from frp_assess.study.schema import ModelSpec, StudyFile

#: fields of ModelOptions that are not user options (the tests' and benchmarks' integrators)
INTERNAL_MODEL_FIELDS = {"fixed_step", "method"}

#: (option, pydantic model, field name) of every option a schema holds
SCHEMA_FIELDS: list[tuple[Option[Any], type[BaseModel], str]] = [
    *(
        (o, ModelOptionsSpec, o.key)
        for o in MODEL_OPTIONS.values()
        if o is not INTEGRATION_TOLERANCE
    ),
    (STRAIN_FACTOR, ModelOptionsSpec, "strain_factor"),
    (INTEGRATION_TOLERANCE, IntegrationSpec, "tolerance"),
    (VERIFY, IntegrationSpec, "verify"),
    (INTEGRATION_TOLERANCE, ModelSpec, "integration_tolerance"),
    *((o, IdaSpec, o.key) for o in IDA_OPTIONS.values()),
]


def test_every_model_option_is_declared_with_its_default() -> None:
    user_fields = {f.name: f for f in fields(ModelOptions)}
    missing = set(user_fields) - INTERNAL_MODEL_FIELDS - set(MODEL_OPTIONS)
    assert not missing, f"declare {sorted(missing)} in dynamics/options.py"
    for key, option in MODEL_OPTIONS.items():
        assert user_fields[key].default == option.default, key


def test_every_model_option_has_its_schema_field() -> None:
    """A new option in MODEL_OPTIONS needs a field in ModelOptionsSpec (shared by the project
    and study files), the integration tolerance aside."""
    missing = set(MODEL_OPTIONS) - {INTEGRATION_TOLERANCE.key} - set(ModelOptionsSpec.model_fields)
    assert not missing, f"add {sorted(missing)} to config/schema/analysis_spec.py ModelOptionsSpec"


def test_the_schemas_give_the_dataclasses() -> None:
    spec = ModelOptionsSpec.model_validate(
        {"restitution": 0.7, "rupture": "velocity-continuous", "free_vibration_tail": 2.0}
    )
    assert spec.model_options(1e-9) == ModelOptions(
        restitution=0.7, rupture="velocity-continuous", free_vibration_tail=2.0, tolerance=1e-9
    )
    assert ModelOptionsSpec().model_options(INTEGRATION_TOLERANCE.default) == ModelOptions()
    ida = IdaSpec.model_validate({"step_ratio": 1.2, "max_multiplier": 50.0})
    assert ida.settings() == IdaSettings(step_ratio=1.2, max_multiplier=50.0)


def test_the_ida_settings_are_the_declared_ones() -> None:
    assert {f.name: f.default for f in fields(IdaSettings)} == {
        k: o.default for k, o in IDA_OPTIONS.items()
    }


def test_the_bars_take_the_declared_strain_factor() -> None:
    bars = Rebars(40e9, 0.02, "centred", 1.0)
    assert bars.strain_factor == STRAIN_FACTOR.default


def _nudge(x: float, up: bool) -> float:
    return x + (1 if up else -1) * max(abs(x), 1e-12) * 1e-6


@pytest.mark.parametrize(
    "option,model,name", SCHEMA_FIELDS, ids=lambda v: getattr(v, "__name__", getattr(v, "key", v))
)
def test_the_schemas_are_derived_from_the_declaration(
    option: Option[Any], model: type[BaseModel], name: str
) -> None:
    field = model.model_fields[name]
    assert field.default == option.default
    assert field.description == option.describe()
    if option.choices and not option.numeric:
        assert get_args(field.annotation) == option.choices

    def accepted(value: object) -> bool:
        try:
            model.model_validate({name: value})
        except ValidationError:
            return False
        return True

    for word in option.choices:
        assert accepted(word)
    assert not accepted("no-such-rule")
    if option.low is not None:
        assert accepted(option.low) is not option.low_open
        assert not accepted(_nudge(option.low, up=False))
        assert accepted(_nudge(option.low, up=True))
    if option.high is not None:
        assert accepted(option.high) is not option.high_open
        assert not accepted(_nudge(option.high, up=True))


def test_the_study_file_reuses_the_project_models() -> None:
    assert issubclass(ModelSpec, ModelOptionsSpec)
    assert StudyFile.model_fields["ida"].annotation is IdaSpec
    assert set(ModelSpec.model_fields) == set(ModelOptionsSpec.model_fields) | {
        "integration_tolerance"
    }
    assert set(AnalysisSpec.model_fields) >= set(ModelOptionsSpec.model_fields)


def _subparser(name: str) -> argparse.ArgumentParser:
    parser = build_parser()
    for action in parser._actions:  # noqa: SLF001 - argparse keeps its subparsers here
        if isinstance(action, argparse._SubParsersAction):  # noqa: SLF001
            return action.choices[name]  # type: ignore[no-any-return]
    raise AssertionError("no subcommands")


WALL = ["--thickness", "0.4", "--height", "3", "--mechanism", "one-sided", "--record", "r"]
#: the options on the command line (the pivot, which needs the masonry's strength, is not)
CLI_MODEL_OPTIONS = [o for o in MODEL_OPTIONS.values() if o.flag]
CLI_OPTIONS = [
    *(("simulate", o) for o in (*CLI_MODEL_OPTIONS, STRAIN_FACTOR)),
    *(("ida", o) for o in (*CLI_MODEL_OPTIONS, STRAIN_FACTOR, *IDA_OPTIONS.values())),
]


@pytest.mark.parametrize("command,option", CLI_OPTIONS, ids=lambda v: getattr(v, "flag", v))
def test_the_command_line_is_derived_from_the_declaration(
    command: str, option: Option[Any]
) -> None:
    parser = _subparser(command)
    defaults = parser.parse_args(WALL)
    assert getattr(defaults, option.flag[2:].replace("-", "_")) == option.default

    def accepted(text: str) -> bool:
        try:
            parser.parse_args([*WALL, option.flag, text])
        except SystemExit:
            return False
        return True

    for word in option.choices:
        assert accepted(word)
    if option.numeric and not option.choices:  # restitution's number is checked by build_model
        assert option.low is not None and option.high is not None
        assert accepted(repr(option.low)) is not option.low_open
        assert not accepted(repr(_nudge(option.low, up=False)))
        assert accepted(repr(option.high)) is not option.high_open
        assert not accepted(repr(_nudge(option.high, up=True)))
        assert not accepted("nan")


@pytest.mark.parametrize(
    "value,ok",
    [
        ("energy", True),
        ("velocity", True),
        ("bouncy", False),
        (1.0, True),
        (1, True),
        (0.5, True),
        (0.0, False),
        (1.0000001, False),
        (True, False),
        (math.nan, False),
        (math.inf, False),
    ],
)
def test_restitution_takes_a_word_or_a_ratio_in_0_1(value: object, ok: bool) -> None:
    assert RESTITUTION.accepts(value) is ok
    if not ok:
        with pytest.raises(ValueError, match="restitution must be energy, velocity or a number"):
            RESTITUTION.check(value)


def test_descriptions_state_range_unit_and_default() -> None:
    from frp_assess.dynamics.options import FREE_VIBRATION_TAIL, IDA_MAX_MULTIPLIER

    assert FREE_VIBRATION_TAIL.describe().endswith(": a number in [0, 60] s (default 0).")
    assert IDA_MAX_MULTIPLIER.range_text() == "(1, 1000]"
    assert VERIFY.describe().endswith("(default no).")


def test_the_template_shows_the_declared_defaults() -> None:
    """`frp-assess new` writes the analysis block with its defaults: they are the declared ones."""
    from frp_assess.api import template_text
    from frp_assess.config import load_project_text

    analysis = load_project_text(template_text(), "t.yaml").project.analysis
    for key, option in MODEL_OPTIONS.items():
        if option is not INTEGRATION_TOLERANCE:
            assert getattr(analysis, key) == option.default, key
    assert analysis.strain_factor == STRAIN_FACTOR.default
    assert analysis.integration.tolerance == INTEGRATION_TOLERANCE.default
    assert analysis.integration.verify == VERIFY.default
    for key, option in IDA_OPTIONS.items():
        assert getattr(analysis.ida, key) == option.default, key
