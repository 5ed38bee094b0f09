"""The ``analysis`` block (model options, time integration, the IDA rule, the target) and
the ``code_check`` block (the linear kinematic check of Circolare 2019 §C8.7.1).
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import (
    BeforeValidator,
    Field,
    WithJsonSchema,
    model_validator,
)
from pydantic_core import PydanticCustomError

from frp_assess.config.schema.spec_base import (
    Number,
    _Model,
    located_error,
)
from frp_assess.dynamics.base_reaction import PivotRule
from frp_assess.dynamics.ida import IdaSettings
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
    CapacityRule,
    CollapseRule,
    Option,
    RuptureRule,
)
from frp_assess.dynamics.rocking import ModelOptions
from frp_assess.rules.intervention import CATEGORY_CLAUSE, Category
from frp_assess.rules.masonry import CONFIDENCE_FACTORS, confidence_factor

#: "1.35 (LC1), 1.20 (LC2), 1.00 (LC3)": the confidence factors of Tab. C8.5.IV, for the help
_FC_BY_LEVEL = ", ".join(f"{fc:.2f} ({level})" for level, fc in CONFIDENCE_FACTORS.items())


# ------------------------------------------------------------------------------- analysis
def option_field(option: Option[Any]) -> Any:
    """The pydantic field of a declared option: its default, range and description."""
    bounds: dict[str, float] = {}
    if option.numeric and not option.choices:
        if option.low is not None:
            bounds["gt" if option.low_open else "ge"] = option.low
        if option.high is not None:
            bounds["lt" if option.high_open else "le"] = option.high
    return Field(option.default, description=option.describe(), **bounds)  # type: ignore[call-overload]


def _restitution(value: Any) -> Any:
    if isinstance(value, str) and RESTITUTION.accepts(value):
        return value
    if isinstance(value, int | float) and RESTITUTION.accepts(value):
        return float(value)
    raise PydanticCustomError(
        "restitution", f"expected {RESTITUTION.allowed_text()}, found {value!r}"
    )


Restitution = Annotated[
    Literal["energy", "velocity"] | float,
    BeforeValidator(_restitution),
    WithJsonSchema(
        {
            "anyOf": [
                {"enum": list(RESTITUTION.choices), "type": "string"},
                {
                    "type": "number",
                    "exclusiveMinimum": RESTITUTION.low,
                    "maximum": RESTITUTION.high,
                },
            ]
        }
    ),
]


class IdaSpec(_Model):
    """The incremental dynamic analysis rule (docs/model.md §5 and §11)."""

    step_ratio: Number = option_field(IDA_STEP_RATIO)
    tolerance: Number = option_field(IDA_TOLERANCE)
    max_multiplier: Number = option_field(IDA_MAX_MULTIPLIER)
    capacity: CapacityRule = option_field(IDA_CAPACITY)
    ladder_ratio: Number = option_field(IDA_LADDER_RATIO)
    offset: Number = option_field(IDA_OFFSET)

    def settings(self) -> IdaSettings:
        """The search rule these fields give."""
        return IdaSettings(**{key: getattr(self, key) for key in IDA_OPTIONS})


class IntegrationSpec(_Model):
    """Error control of the time integration (docs/model.md §4)."""

    tolerance: Number = option_field(INTEGRATION_TOLERANCE)
    verify: bool = option_field(VERIFY)


class ModelOptionsSpec(_Model):
    """The model options of docs/model.md §2–4 a project and a study file share."""

    restitution: Restitution = option_field(RESTITUTION)
    rupture: RuptureRule = option_field(RUPTURE)
    collapse: CollapseRule = option_field(COLLAPSE)
    strain_factor: Number = option_field(STRAIN_FACTOR)
    free_vibration_tail: Number = option_field(FREE_VIBRATION_TAIL)
    pivot: PivotRule = option_field(PIVOT)

    def model_options(self, tolerance: float) -> ModelOptions:
        """The model options these fields give, integrated at ``tolerance`` [-] (a project
        file holds it under ``integration``, a study file as ``integration_tolerance``)."""
        given = {key: getattr(self, key) for key in MODEL_OPTIONS if key != "tolerance"}
        return ModelOptions(**given, tolerance=tolerance)


class AnalysisSpec(ModelOptionsSpec):
    """Model options and the IDA settings (docs/model.md §3–5)."""

    integration: IntegrationSpec = Field(
        default_factory=IntegrationSpec, description="Time integration."
    )
    ida: IdaSpec = Field(default_factory=IdaSpec, description="IDA rule.")
    # a required capacity/demand below 0.01 accepts any wall
    target: Number = Field(
        1.0,
        ge=0.01,
        le=10,
        description="Required mean capacity/demand, mean a_dyn/(a_g*S), 0.01-10 (1.0).",
    )


class CodeCheckSpec(_Model):
    """Linear kinematic check of Circolare 2019 §C8.7.1 beside the IDA."""

    knowledge_level: Literal["LC1", "LC2", "LC3"] = Field(
        "LC1", description=f"Knowledge level: FC = {_FC_BY_LEVEL}."
    )
    behaviour_factor: Number = Field(2.0, ge=1, le=4, description="Behaviour factor q (2.0).")
    fc_in_ida: bool = Field(
        True,
        description="Divide the IDA capacity by FC too: capacity/demand = a_dyn/(FC*a_g*S) "
        "(true; Circolare 2019 C8.7.1.2.1.3: a rigid block uses LC1's "
        f"FC = {confidence_factor('LC1'):.2f}).",
    )

    intervention: Category = Field(
        "upgrade",
        description="Category of the intervention, what an option must reach: local "
        f"({CATEGORY_CLAUSE['local']}: the mechanism's zeta_E rises, no check worse) | "
        f"improvement ({CATEGORY_CLAUSE['improvement']}: zeta_E +0.1, or >= 0.6 for class "
        f"III schools and class IV) | upgrade ({CATEGORY_CLAUSE['upgrade']}: zeta_E >= 1; "
        "the default).",
    )
    use_class: Literal["I", "II", "III", "IV"] | None = Field(
        None,
        description="Use class I-IV of the building (NTC 2018 §2.4.2), for an improvement; "
        "default: seismic.spectrum.use_class.",
    )
    school: bool = Field(
        False, description="A class III building used as a school (false; NTC 2018 §8.4.2)."
    )

    @model_validator(mode="after")
    def _school_of_class_iii(self) -> CodeCheckSpec:
        if self.school and self.use_class not in (None, "III"):
            raise located_error(
                f"school: true applies to use class III (NTC 2018 §8.4.2), found use_class "
                f"{self.use_class}",
                "school",
            )
        return self

    @property
    def confidence_factor(self) -> float:
        """FC [-] of the knowledge level."""
        return confidence_factor(self.knowledge_level)
