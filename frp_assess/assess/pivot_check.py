"""The compression at the base of every case of an assessment (docs/model.md §1.1).

Units: forces per metre of wall [kN/m], lengths [m], stresses [MPa].

A record of the largest compression the base carries in the model, N = W + T_u (T_u: the
acting bar at the rupture strain ε_max the model uses, c·ε_u or the design value; N = W for
the unreinforced wall), on the stress block 0.85·f_d: x = N / (0.85·f_d·1 m).  No option is
dropped for it: with ``pivot: crushing`` the dynamics follow x(θ) at every instant and a toe
that crushes is a failure mode of the IDA; with ``pivot: edge`` x is ignored by the model and
the record says whether x/B stays within the edge limit
(:data:`~frp_assess.assess.masonry_strength.DEFAULT_PIVOT_LIMIT`).
"""

from __future__ import annotations

from dataclasses import dataclass

from frp_assess.assess.inputs import UNREINFORCED, AssessmentInputs, RetrofitOption
from frp_assess.assess.masonry_strength import (
    DEFAULT_PIVOT_LIMIT,
    STRESS_BLOCK_FACTOR,
    PivotCheck,
    pivot_check,
)
from frp_assess.dynamics import PivotRule
from frp_assess.dynamics.units import KPA_PER_GPA
from frp_assess.results.pivot import PivotResult
from frp_assess.rules.bars import bar_area, bar_force, lever_arm
from frp_assess.rules.masonry import toe_crushes, wall_weight


@dataclass(frozen=True)
class CasePivot:
    """The pivot of one case.

    Attributes:
        case: the case's name (``Unreinforced`` or the option's).
        rule: ``analysis.pivot``.
        check: W, T_u, N, f_d, x, x/B against the edge limit (:class:`PivotCheck`).
        bar_distance: the acting bar from the compressed edge [m]; ``None`` unreinforced.
        model_pivot: the model the case's IDA runs with: ``crushing`` when the base reaction
            is in the equation (a finite f_d), else ``edge``.
        weight_depth: x_W = W/(0.85·f_d·1 m) [m], the stress block under the weight alone.
        thickness: B [m].
    """

    case: str
    rule: PivotRule
    check: PivotCheck
    bar_distance: float | None
    model_pivot: PivotRule
    weight_depth: float
    thickness: float

    def line(self) -> str:
        """One line for the report: the numbers at the bar's rupture force, then what they
        mean for the model."""
        c = self.check
        head = (
            f"{self.case}: N = {c.force:.0f} kN/m (W {c.weight:.0f} + T_u {c.bar_force:.0f}) on "
            f"{STRESS_BLOCK_FACTOR:g}*f_d = {STRESS_BLOCK_FACTOR * c.f_d:.2f} MPa needs "
            f"x = {c.depth * 1e3:.0f} mm, "
            f"x/B = {c.depth_ratio:.3f}"
        )
        if self.model_pivot == "crushing":
            if self.bar_distance is not None and toe_crushes(
                c.depth, self.thickness, self.bar_distance
            ):
                return (
                    f"{head}: the toe crushes before the bar breaks (x reaches the bar, "
                    f"{self.bar_distance * 1e3:.0f} mm from the corner; pivot: crushing)"
                )
            return f"{head}; the base reaction follows the bar force (pivot: crushing)"
        if c.depth_ratio > c.limit:
            return f"{head} > {c.limit:.2f}: the edge model ignores a compressed zone this deep"
        return f"{head} <= {c.limit:.2f}: the edge pivot holds"

    def result(self) -> PivotResult:
        """The results.json record of this case."""
        c = self.check
        return PivotResult(
            rule=self.rule,
            model_pivot=self.model_pivot,
            weight=c.weight,
            bar_force=c.bar_force,
            force=c.force,
            depth=c.depth,
            depth_ratio=c.depth_ratio,
            # where the reaction acts at rest, x_W/2 from the corner (0 with the edge model):
            # a_RM = g·(B − 2·pivot_shift)/H for every case
            pivot_shift=0.5 * self.weight_depth if self.model_pivot == "crushing" else 0.0,
            bar_distance=self.bar_distance,
            limit=c.limit,
            dropped=False,  # no option is dropped for its base (docs/model.md §1.1)
            reason=self.line(),
        )


def case_pivot(
    inputs: AssessmentInputs, option: RetrofitOption | None, limit: float = DEFAULT_PIVOT_LIMIT
) -> CasePivot:
    """The pivot check of the unreinforced wall (``None``) or of one option."""
    b = inputs.thickness
    weight = wall_weight(inputs.unit_weight, b, inputs.height)  # [kN/m]
    f_d = inputs.masonry_strength.f_d
    rule = inputs.model.pivot
    if option is None or option.material is None or option.position is None:
        force, distance = 0.0, None  # no bars: a tie alone loads the base as the wall does
    else:
        strain = inputs.rupture_strain(option.material)  # ε_max the model uses [-]
        modulus = option.material.elastic_modulus * KPA_PER_GPA  # [kPa]: T in kN/m
        force = bar_force(modulus, bar_area(option.ratio, b), strain)
        distance = lever_arm(option.position, b)
    check = pivot_check(weight, force, b, f_d, limit)
    model = inputs.model_for(option)
    return CasePivot(
        case=UNREINFORCED if option is None else option.name,
        rule=rule,
        check=check,
        bar_distance=distance,
        model_pivot="crushing" if model.base_reaction.weight_depth > 0.0 else "edge",
        weight_depth=pivot_check(weight, 0.0, b, f_d, limit).depth,
        thickness=b,
    )


def pivot_checks(
    inputs: AssessmentInputs, limit: float = DEFAULT_PIVOT_LIMIT
) -> tuple[CasePivot, ...]:
    """The pivot check of every case, in the order of :meth:`AssessmentInputs.case_names`."""
    return (
        case_pivot(inputs, None, limit),
        *(case_pivot(inputs, o, limit) for o in inputs.options),
    )
