"""The annex tables of the design mode, of the model conventions (sensitivity) and of the
anchorage of the bars, in the report's language (the Italian annex; the English report has
them in its detailed sections).  Words from the catalogue, numbers from the results; the
English free text the run writes (the design mode's note, a convention's label) is not
copied: the words are rebuilt from the values."""

from __future__ import annotations

import re

from frp_assess.report.body_annex import case_label
from frp_assess.report.body_front import position_words
from frp_assess.report.formats import TableData
from frp_assess.report.lang import Lang, short
from frp_assess.results.as_built import AsBuilt
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import Markup

Results = AssessmentResult

_CONVENTION = re.compile(r"^(restitution|collapse|rupture): ([a-z-]+)$")
_STRAIN = re.compile(r"^strain factor c = ([0-9.]+)$")
_MODULUS = re.compile(r"^E ([+-][0-9.]+)% \(([0-9.]+) GPa\)$")
_HUNT_STEP = re.compile(r"^IDA step ratio s = ([0-9.]+)$")
_SPREAD = re.compile(r"^numerical spread: .*\(offset ([0-9.]+)\)$")


def variant_words(variant: str, lang: Lang) -> str:
    """A model convention of the sensitivity table in the report's language: the run's label
    (``"as assessed"``, ``"collapse: end-of-record"``, ``"E -10% (41.4 GPa)"`` ...) read back
    into its parts; a label of another form is shown as written, numbers re-formatted."""
    if variant == "as assessed":
        return lang.t("sens.as_assessed")
    m = _CONVENTION.match(variant)
    if m and lang.has(f"sens.value.{m.group(2)}"):
        return lang.t(f"sens.{m.group(1)}", value=lang.t(f"sens.value.{m.group(2)}"))
    m = _STRAIN.match(variant)
    if m:
        return lang.t("sens.strain", c=lang.gnum(float(m.group(1))))
    m = _MODULUS.match(variant)
    if m:
        return lang.t(
            "sens.modulus", change=lang.numbers_in(m.group(1)), e=lang.gnum(float(m.group(2)))
        )
    m = _HUNT_STEP.match(variant)
    if m:
        return lang.t("sens.hunt_step", s=lang.gnum(float(m.group(1))))
    m = _SPREAD.match(variant)
    if m:
        return lang.t("sens.numerical_spread", offset=lang.gnum(float(m.group(1))))
    return lang.numbers_in(variant)


def design_table(results: Results, lang: Lang) -> TableData | None:
    """Design mode, one row per (material, position): the smallest ratio ρ [‰] that passes
    every deciding check, its capacity/demand, FRP mass [kg] and cost; None when the design
    mode was not run."""
    if not results.design:
        return None
    n = lang.num
    header = [
        lang.t("annex.col.material"),
        lang.t("annex.col.position"),
        lang.t("annex.col.smallest"),
        lang.t("col.cd"),
        lang.t("col.mass"),
        lang.t("col.cost", currency=short(results.costs.currency)),
    ]
    rows = [
        [
            d.material,
            position_words(d.position, lang, short=True),
            lang.t("annex.design.none") if d.ratio is None else n(d.ratio, 2),
            n(d.capacity_demand, 2),
            n(d.frp_mass, 1),
            n(d.frp_cost, 0, grouping=True),
        ]
        for d in results.design
    ]
    return TableData(header, rows)


def sensitivity_table(results: Results, lang: Lang) -> TableData | None:
    """The assessed case under each model convention: design a_dyn [g], its change from the
    case as assessed [%], capacity/demand [-]; None when not computed."""
    sens = results.sensitivity
    if sens is None or not sens.rows:
        return None
    n = lang.num
    base = sens.rows[0].design_a_dyn
    header = [
        lang.t("annex.col.variant"),
        Markup("a<sub>dyn,d</sub> [g]"),
        lang.t("annex.col.change"),
        lang.t("col.cd"),
    ]
    rows = []
    for r in sens.rows:
        ge = "≥ " if r.lower_bound else ""
        change = 100.0 * (r.design_a_dyn / base - 1.0)
        rows.append([
            variant_words(r.variant, lang),
            ge + n(r.design_a_dyn, 3),
            ("+" if change >= 0 else "") + n(change, 1),
            ge + n(r.capacity_demand, 2),
        ])  # fmt: skip
    return TableData(header, rows)


def built(results: Results, lang: Lang) -> list[tuple[str, AsBuilt]]:
    """(label, bars as built) of every option with bars, then of every design-mode answer."""
    out = [(case_label(c, lang), c.as_built) for c in results.options if c.as_built is not None]
    for d in results.design or ():
        if d.as_built is not None:
            pos = position_words(d.position, lang, short=True)
            out.append((lang.t("annex.design.label", material=d.material, position=pos),
                        d.as_built))  # fmt: skip
    return out


def anchorage_table(results: Results, lang: Lang) -> TableData | None:
    """Per option and design answer: the design force per bar [kN], its bond length [m],
    the masonry pull-out cone [kN] and its verdict (a dash: not checked); None without bars."""
    items = built(results, lang)
    if not items:
        return None
    n = lang.num
    header = [
        lang.t("annex.col.option"),
        lang.t("annex.col.force"),
        lang.t("annex.col.bond"),
        lang.t("annex.col.cone"),
        lang.t("annex.col.cone_ok"),
    ]
    rows = []
    for label, b in items:
        a = b.anchorage
        ok = "—" if a.cone_ok is None else lang.t("annex.ok" if a.cone_ok else "annex.ko")
        rows.append([label, n(a.design_force, 1), n(a.length_required, 3),
                     n(a.cone_resistance, 1), ok])  # fmt: skip
    return TableData(header, rows)
