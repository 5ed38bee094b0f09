"""The annex's tables of the inputs (wall, materials, model settings, software, spectrum,
records, compliance) as pure functions of the typed results, in the report's language: words
from the catalogue (keys ``ax.*``), numbers by :class:`~frp_assess.report.lang.Lang`.  Plain
text, but for headers that are :class:`~frp_assess.text_safety.Markup`."""

from __future__ import annotations

from frp_assess.report.body_analysis import PARAM_SYMBOL
from frp_assess.report.body_front import masonry_words
from frp_assess.report.formats import (
    DASH,
    TableData,
    crushing_shift,
    run_text,
    run_words,
    rupture_strain_words,
    shows_run_prose,
    source_text,
)
from frp_assess.report.ida_words import settings_value
from frp_assess.report.lang import Lang
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import Markup, pdf

Results = AssessmentResult


def mechanism_text(mechanism: str, lang: Lang) -> str:
    """The wall's mechanism in words (``one-sided``, ``two-sided``; another as written)."""
    key = f"ax.mechanism.{mechanism}"
    return lang.t(key) if lang.has(key) else mechanism


def masonry_text(results: Results, lang: Lang) -> str:
    """The masonry as the run described it (English), or by its type in the catalogue."""
    w = results.wall
    if shows_run_prose(lang):
        return w.masonry_description or w.masonry or DASH
    return masonry_words(results, lang)


def wall_rows(results: Results, lang: Lang) -> list[list[str]]:
    w = results.wall
    n = lang.num
    return [
        [lang.t("ax.wall.thickness"), f"{n(w.thickness, 3)} m"],
        [lang.t("ax.wall.height"), f"{n(w.height, 3)} m"],
        [lang.t("ax.wall.length"), f"{n(w.length, 3)} m"],
        [lang.t("ax.wall.masonry"), masonry_text(results, lang)],
        [lang.t("ax.wall.unit_weight"), f"{lang.gnum(w.unit_weight)} kN/m³"],
        [lang.t("ax.wall.mechanism"), mechanism_text(w.mechanism, lang)],
    ]


def wall_property_rows(results: Results, lang: Lang) -> list[list[str]]:
    w = results.wall
    n = lang.num
    return [
        [lang.t("ax.wall.alpha"), f"{n(w.alpha, 4)} rad = {n(w.alpha_deg, 2)}°"],
        [lang.t("ax.wall.R"), f"{n(w.R, 3)} m"],
        [lang.t("ax.wall.p"), f"{n(w.p, 3)} rad/s"],
        [lang.t("ax.wall.mass"), f"{n(w.mass, 1)} kg/m"],
        [activation_label(results, lang), f"{n(w.a_rm, 3)} g"],
    ]


def activation_label(results: Results, lang: Lang) -> str:
    """The label of a_RM with the formula of the model's pivot: g·tan α about the edge,
    g·(B − x)/H about the crushing pivot (docs/model.md §1.1, §5.1)."""
    x = crushing_shift(results)
    if x is None:
        return lang.t("ax.wall.a_rm")
    return lang.t("ax.wall.a_rm.crushing", x=lang.num(x * 1000, 0))


def materials_table(results: Results, lang: Lang) -> TableData:
    cur = pdf(results.costs.currency)
    header = [
        lang.t("ax.col.material"),
        "E [GPa]",
        Markup("ε<sub>u</sub> [–]"),
        lang.t("ax.col.density"),
        Markup(lang.t("ax.col.price", cur=cur)),
        lang.t("ax.col.source"),
    ]
    rows = [
        [
            name,
            lang.gnum(m.elastic_modulus),
            lang.gnum(m.ultimate_strain),
            lang.gnum(m.density),
            lang.num(m.price, 2),
            source_text(m.source, lang),
        ]
        for name, m in sorted(results.materials.items())
    ]
    return TableData(header, rows)


def collapse_words(collapse: str, lang: Lang) -> str:
    """The collapse rule in words (docs/model.md §3.5)."""
    key = f"ax.collapse.{collapse}"
    return lang.t(key) if lang.has(key) else collapse


def model_rows(results: Results, lang: Lang) -> list[list[str]]:
    m = results.model
    ida = m.ida
    cur = pdf(results.costs.currency)
    restitution = lang.t(f"ax.model.restitution.{m.restitution}") if lang.has(
        f"ax.model.restitution.{m.restitution}") else m.restitution  # fmt: skip
    rupture = lang.t(f"ax.model.rupture.{m.rupture}") if lang.has(
        f"ax.model.rupture.{m.rupture}") else m.rupture  # fmt: skip
    tail = lang.t("ax.model.tail.overturning") if m.collapse == "overturning" else ""
    rows = [
        [
            lang.t("ax.model.restitution"),
            lang.t(
                "ax.model.restitution.value",
                rule=restitution,
                ratio=lang.num(m.restitution_ratio, 3),
            ),
        ],  # fmt: skip
        [lang.t("ax.model.rupture"), rupture],
        [lang.t("ax.model.collapse"), collapse_words(m.collapse, lang)],
        [
            lang.t("ax.model.strain_factor", rule=rupture_strain_words(results)),
            lang.gnum(m.strain_factor),
        ],
        [lang.t("ax.model.tail"), f"{lang.gnum(m.free_vibration_tail)} s{tail}"],
        [lang.t("ax.model.target"), f"≥ {lang.gnum(m.target)}"],
    ]
    integ = m.integration
    if integ:
        rows.append(
            [
                lang.t("ax.model.integration"),
                lang.t("ax.model.integration.value", tol=lang.gnum(integ.tolerance)),
            ]
        )
    if m.design_value:
        stat = (
            "ax.model.design_value.mean"
            if results.design_is_mean
            else "ax.model.design_value.least"
        )
        value = run_words(m.design_value, lang) or lang.t(stat)
        rows.append([lang.t("ax.model.design_value"), value])
    capacity = f"ax.model.capacity.{ida.capacity}"
    rows += [
        [lang.t("ax.model.capacity"), lang.t(capacity) if lang.has(capacity) else ida.capacity],
        [lang.t("ax.model.sampling"), settings_value(results, lang)],
        [
            lang.t("ax.model.installation"),
            lang.t(
                "ax.model.installation.value",
                cost=lang.num(results.costs.installation_per_metre, 0, grouping=True),
                cur=cur,
            ),
        ],
    ]
    return rows


def software_rows(results: Results, lang: Lang) -> list[list[str]]:
    p = results.project
    sw = results.software
    return [
        [lang.t("ax.sw.project"), p.name or DASH],
        [lang.t("ax.sw.location"), p.location or DASH],
        [lang.t("ax.sw.engineer"), p.engineer or DASH],
        [lang.t("ax.sw.notes"), p.notes or DASH],
        [lang.t("ax.sw.file"), results.input_file or DASH],
        [lang.t("ax.sw.date"), lang.date(results.created) if results.created else DASH],
        [lang.t("ax.sw.software"), f"{sw.name} {sw.version}"],
        [lang.t("ax.sw.schema"), str(results.schema_version)],
    ]


def param_name(key: str, lang: Lang) -> str:
    """A spectrum parameter of results.json by its name (``soil``, ``damping``...) in an
    English report, by the body's words for it in another language."""
    symbol = PARAM_SYMBOL.get(key, key)
    if shows_run_prose(lang) or not symbol.startswith("spectrum."):
        return key
    return lang.t(symbol)


def spectrum_rows(results: Results, lang: Lang) -> list[list[str]]:
    s = results.seismic
    sp = s.spectrum
    n = lang.num
    params = ", ".join(
        f"{param_name(k, lang)} = {lang.numbers_in(f'{v:.4g}') if isinstance(v, float) else v}"
        for k, v in (sp.parameters or {}).items()
    )
    rows = [
        [lang.t("ax.spectrum.name"), sp.name or sp.type or DASH],
        [lang.t("ax.spectrum.description"), run_text(sp.description, lang)],
        [lang.t("ax.spectrum.parameters"), params or DASH],
        [lang.t("ax.spectrum.agS"), f"{n(sp.ag_S, 3)} g"],
    ]
    corners = [
        f"{k} = {n(v, 3)} s"
        for k, v in (("T_B", sp.T_B), ("T_C", sp.T_C), ("T_D", sp.T_D))
        if v is not None
    ]
    if corners:
        rows.append([lang.t("ax.spectrum.corners"), ", ".join(corners)])
    rows.append([lang.t("ax.spectrum.demand"), f"{n(results.demand.pga, 3)} g"])
    rows.append([lang.t("ax.spectrum.t1"), f"{lang.gnum(s.t1)} s"])
    gen = s.generator
    if s.records_kind == "artificial" and gen:
        rows.append(
            [
                lang.t("ax.spectrum.records"),
                lang.t("ax.spectrum.artificial", n=gen.count, method=gen.method, seed=gen.seed,
                       duration=lang.gnum(gen.duration), dt=lang.gnum(gen.dt)),
            ]
        )  # fmt: skip
    else:
        rows.append(
            [lang.t("ax.spectrum.records"), lang.t("ax.spectrum.recorded", n=len(results.records))]
        )
    return rows


def records_table(results: Results, lang: Lang) -> TableData:
    n = lang.num
    header = [
        lang.t("ax.col.record"),
        lang.t("ax.col.source_seed"),
        "PGA [g]",
        lang.t("col.duration"),
        "dt [s]",
        lang.t("ax.col.scale"),
    ]
    rows = [
        [r.name, r.source or DASH, n(r.pga, 3), n(r.duration, 2), lang.gnum(r.dt),
         n(r.scale_factor, 3)]
        for r in results.records
    ]  # fmt: skip
    return TableData(header, rows)


def fmt_margin(margin: float | None, unit: str | None, lang: Lang) -> str:
    if margin is None:
        return DASH
    if not unit:
        return lang.numbers_in(f"{margin:+.1%}")
    key = f"ax.unit.{unit}"
    return lang.numbers_in(f"{margin:+g} {lang.t(key) if lang.has(key) else unit}")


def compliance_table(results: Results, lang: Lang) -> TableData:
    """The spectrum-compatibility checks: code, clause, the requirement and what was found
    (the run's English words: in another language a dash), margin and result."""
    header = [lang.t(f"ax.col.{k}") for k in ("code", "clause", "requirement", "found")]
    header += [lang.t("ax.col.margin"), lang.t("ax.col.result")]
    rows = [
        [c.code, c.clause, run_text(c.requirement, lang), run_text(c.found, lang),
         fmt_margin(c.margin, c.unit, lang), pass_fail(c.passed, lang)]
        for c in results.compliance.checks
    ]  # fmt: skip
    return TableData(header, rows)


def pass_fail(x: bool | None, lang: Lang) -> str:
    """The verdict of one check (pass or FAIL), a dash for None."""
    return DASH if x is None else lang.t("ax.pass" if x else "ax.fail")
