"""The retrofit section's part for the options with tie-rods (docs/model.md §12, both
languages): each tie as the loads section states one (its per-metre stiffness, yield and
anchorage forces), its steel and cost, and α₀ of Circolare 2019 eq. C8.7.1.1 with and without
it, so that a reviewer recomputes both by hand.  Nothing when no option has a tie.
"""

from __future__ import annotations

from frp_assess.report.body_front import tie_words
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import esc, h2, markup
from frp_assess.report.lang import Lang
from frp_assess.report.loads_section import tie_paragraph
from frp_assess.results.model import AssessmentResult, CaseResult


def _alpha0(results: AssessmentResult, case: CaseResult) -> float | None:
    """α₀ of the case's linear check (None: no code checks in the file)."""
    kc = results.kinematic_checks
    if kc is None:
        return None
    return next((c.linear.alpha0 for c in kc.cases if c.case == case.name), None)


def section(results: AssessmentResult, lang: Lang) -> list[Block]:
    """'Tie-rods among the options': the rule, then each tie option; nothing without one."""
    ties = [c for c in results.options if c.tie is not None]
    if not ties:
        return []
    n = lang.num
    bare = _alpha0(results, results.urm)
    out: list[Block] = [h2(lang.t("h.retrofit.ties")), markup(lang.t("retrofit.ties.lead"))]
    for c in ties:
        assert c.tie is not None
        q = c.tie
        alpha0 = _alpha0(results, c)
        out.append(
            markup(
                lang.t(
                    "retrofit.tie.row",
                    name=esc(c.name),
                    tie=tie_words(q.tie, lang),
                    m=n(q.steel_mass_per_m, 2),
                    mass=n(q.steel_mass, 1),
                    per_tie=n(q.cost_per_tie, 0, grouping=True),
                    per_m=n(q.cost_per_m, 0, grouping=True),
                    cost=n(q.cost, 0, grouping=True),
                    currency=esc(results.costs.currency),
                    alpha0="—" if alpha0 is None else n(alpha0, 4),
                    bare="—" if bare is None else n(bare, 4),
                )
            )
        )
        out.append(tie_paragraph(q.tie, lang))
    if not all(c.tie.prices_given for c in ties if c.tie is not None):
        out.append(markup(lang.t("retrofit.tie.no_prices")))
    return out
