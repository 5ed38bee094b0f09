"""The seismic action and the method of analysis (both languages, words from the catalogue).

A spectrum given by the site's coordinates (results.json ``site``: coordinates, V_N, C_U, V_R,
the limit states) is stated first (:func:`site_blocks`).
"""

from __future__ import annotations

from reportlab.lib.units import mm

from frp_assess.report import charts, ida_words
from frp_assess.report.charts import localize_drawing
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import cond_break, esc, figure, grid, h1, h2, keep, key_value, markup
from frp_assess.report.formats import TableData
from frp_assess.report.lang import Lang
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import Markup

Results = AssessmentResult

#: the spectrum parameters of results.json in the symbols of the code
PARAM_SYMBOL = {
    "ag": "a_g",
    "F0": "F_0",
    "Tc_star": "T_C*",
    "soil": "spectrum.soil",
    "topography": "spectrum.topography",
    "damping": "spectrum.damping",
    "eta": "spectrum.eta",
    "SS": "S_S",
    "CC": "C_C",
    "ST": "S_T",
}


def site_blocks(results: Results, lang: Lang) -> list[Block]:
    """The site of a spectrum given by coordinates: where, nominal life V_N, class of use and
    C_U, reference period V_R and each limit state's P_VR, T_R, a_g, F0, T_C* (the one used
    highlighted); [] when the results hold no ``site`` block (a spectrum by parameters, or a
    file written before it).  Read by attribute: the block is the site helper's."""
    site = getattr(results, "site", None)
    if site is None:
        return []
    n = lang.num
    years = lang.t("site.years")
    rows = [
        [lang.t("site.latlon"), f"{lang.gnum(site.latitude)}°, {lang.gnum(site.longitude)}°"],
        [lang.t("site.V_N"), f"{lang.gnum(site.V_N)} {years}"],
        [lang.t("site.C_U"), f"{esc(site.use_class)}, C_U = {lang.gnum(site.C_U)}"],
        [lang.t("site.V_R"), f"{lang.gnum(site.V_R)} {years}"],
        [lang.t("site.node"), f"{n(site.nearest_node, 1)} km"],
        [lang.t("site.interp"), lang.t(f"site.interp.{getattr(site, 'interpolation', 'cell')}")],
    ]
    header: list[str] = [
        lang.t("site.col.ls"),
        Markup("P<sub>VR</sub>"),
        Markup(f"T<sub>R</sub> [{years}]"),
        Markup("a<sub>g</sub> [g]"),
        Markup("F<sub>0</sub> [-]"),
        Markup("T<sub>C</sub>* [s]"),
        "",
    ]
    body, chosen = [], []
    for i, (name, ls) in enumerate(site.limit_states.items()):
        tr = n(ls.TR, 0)
        if ls.TR_used != ls.TR:
            tr += " " + lang.t("site.tr_used", tr=lang.gnum(ls.TR_used))
        used = lang.t("site.used") if name == site.limit_state else ""
        if used:
            chosen.append(i)
        body.append([name, f"{lang.gnum(100 * ls.P_VR)} %", tr, n(ls.ag, 4), n(ls.F0, 3),
                     n(ls.Tc_star, 3), used])  # fmt: skip
    return [
        markup(lang.t("site.lead", state=esc(site.limit_state))),
        key_value(rows, sub_values=True),
        grid(
            TableData(header, body),
            [x * mm for x in (22, 18, 34, 22, 20, 22, 26)],
            numeric_from=1,
            highlight_rows=chosen,
        ),  # fmt: skip
    ]


#: decimals of each spectrum parameter: one rounding per quantity, as in the site's table
#: (a_g 4, F0 and T_C* 3) and the derived factors (3)
PARAM_DECIMALS = {"ag": 4, "F0": 3, "Tc_star": 3, "SS": 3, "CC": 3, "ST": 3, "eta": 3}


def _param(key: str, value: object, lang: Lang) -> list[str]:
    symbol = PARAM_SYMBOL.get(key, key)
    label = lang.t(symbol) if symbol.startswith("spectrum.") else symbol
    if isinstance(value, float | int) and not isinstance(value, bool):
        unit = {"ag": " g", "Tc_star": " s"}.get(key, "")
        places = PARAM_DECIMALS.get(key)
        shown = lang.gnum(float(value)) if places is None else lang.num(float(value), places)
        if places is not None and float(value) == round(float(value)):
            shown = lang.gnum(float(value))  # S_T = 1, η = 1: no trailing zeros
        return [label, shown + unit]
    return [label, str(value)]


def seismic(results: Results, lang: Lang) -> list[Block]:
    s = results.seismic
    sp = s.spectrum
    n = lang.num
    out: list[Block] = [h1(lang.t("h.seismic"))]
    out += site_blocks(results, lang)
    key = f"spectrum.type.{sp.type}"
    spectrum = lang.t(key) if lang.has(key) else esc(sp.name or sp.type)
    out.append(markup(lang.t("seismic.lead", spectrum=spectrum)))
    rows = [_param(k, v, lang) for k, v in (sp.parameters or {}).items()]
    rows.append([lang.t("seismic.agS"), f"{n(sp.ag_S, 3)} g"])
    for sym, v in (("T_B", sp.T_B), ("T_C", sp.T_C), ("T_D", sp.T_D)):
        if v is not None:
            rows.append([sym, f"{n(v, 3)} s"])
    rows.append([lang.t("seismic.demand"), f"{n(results.demand.pga, 3)} g"])
    out.append(key_value(rows, sub_values=True))
    out.append(h2(lang.t("h.seismic.records")))
    gen = s.generator
    if s.records_kind == "artificial" and gen is not None:
        out.append(
            markup(
                lang.t(
                    "seismic.artificial",
                    n=gen.count,
                    seed=gen.seed,
                    duration=lang.gnum(gen.duration),
                    dt=lang.gnum(gen.dt),
                )
            )
        )
    else:
        out.append(markup(lang.t("seismic.recorded", n=len(results.records))))
    header = [lang.t("col.record"), "PGA [g]", lang.t("col.duration"), "dt [s]"]
    body = [[r.name, n(r.pga, 3), n(r.duration, 2), lang.gnum(r.dt)] for r in results.records]
    out.append(grid(TableData(header, body), [60 * mm, 30 * mm, 30 * mm, 30 * mm], wrap=(0,)))
    ok = results.compliance.passed
    out.append(
        markup(
            lang.t("seismic.compliance_ok" if ok else "seismic.compliance_bad"),
            "verdict_ok" if ok else "verdict_bad",
        )
    )
    by_clause: dict[str, bool] = {}
    for c in results.compliance.checks:  # one line per clause (a clause may hold several)
        where = f"{c.code} {c.clause}"
        by_clause[where] = by_clause.get(where, True) and bool(c.passed)
    for where, passed in by_clause.items():
        state = lang.t("word.pass" if passed else "word.fail")
        out.append(markup("• " + esc(where) + f": {state}", "bullet"))
    out.append(cond_break(90 * mm))
    out.append(
        keep(
            [
                figure(localize_drawing(charts.spectra_chart(results), lang)),
                markup(lang.t("fig.spectra"), "caption"),
            ]
        )
    )
    return out


def method(results: Results, lang: Lang) -> list[Block]:
    out: list[Block] = [h1(lang.t("h.method"))]
    for key in ("method.local", "method.rocking"):
        out.append(markup(lang.t(key)))
    out += [markup(text) for text in ida_words.method_paragraphs(results, lang)]
    out.append(h2(lang.t("h.method.equations")))
    for i in range(1, 7):
        out.append(markup(f"<b>{lang.t(f'eq.{i}.title')}.</b>"))
        out.append(markup(lang.t(ida_words.rule_key(results, lang, f"eq.{i}.body")), "equation"))
    out.append(markup(lang.t("method.symbols"), "small"))
    m = results.model
    rows = [
        [lang.t("model.restitution"), _restitution(results, lang)],
        [lang.t("model.rupture"), lang.t(f"model.rupture.{m.rupture}")
         if lang.has(f"model.rupture.{m.rupture}") else esc(m.rupture)],
        [lang.t("model.collapse"), lang.t(f"model.collapse.{m.collapse}")
         if lang.has(f"model.collapse.{m.collapse}") else esc(m.collapse)],
        [lang.t("model.strain_factor"), lang.gnum(m.strain_factor)],
        [lang.t("model.tail"),
         lang.t("model.tail.value", tail=lang.gnum(m.free_vibration_tail))
         if m.collapse == "overturning" else f"{lang.gnum(m.free_vibration_tail)} s"],
        [lang.t("model.tolerance"), f"{m.integration.tolerance:.0e}".replace("e-0", "e-")],
        [lang.t("model.ida.capacity"), lang.t(f"ida.capacity.{m.ida.capacity}")
         if lang.has(f"ida.capacity.{m.ida.capacity}") else esc(m.ida.capacity)],
        [lang.t("model.ida"), ida_words.settings_value(results, lang)],
        [lang.t("model.target"), lang.gnum(m.target)],
        [lang.t("model.design_value"),
         lang.t("model.design.mean" if results.design_is_mean else "model.design.least")],
    ]  # fmt: skip
    out.append(h2(lang.t("h.method.settings")))
    out.append(key_value(rows, sub_values=True))
    return out


def _restitution(results: Results, lang: Lang) -> str:
    m = results.model
    ratio = lang.num(m.restitution_ratio, 3)
    if isinstance(m.restitution, str) and lang.has(f"model.restitution.{m.restitution}"):
        return lang.t(f"model.restitution.{m.restitution}", ratio=ratio)
    return lang.t("model.restitution.value", value=esc(m.restitution), ratio=ratio)
