"""The report's part for a spectrum given by the site's coordinates (issue 23).

A pure function of the typed results: :func:`site_section` returns the flowables of the
``site`` block of results.json (docs/results-json.md) — coordinates, V_N, C_U, V_R and the
four limit states' T_R, a_g, F0, T_C*, the one the assessment uses highlighted — or nothing
when the spectrum was given by its parameters.  Units: a_g in g, T_C* in s, T_R in years.
"""

from __future__ import annotations

from reportlab.lib.units import mm
from reportlab.platypus import Flowable, KeepTogether

from frp_assess.report.flow import esc, gap, grid, key_value, markup, para
from frp_assess.report.tables import TableData
from frp_assess.results.model import AssessmentResult, SiteResult

#: the heading of the part (the caller numbers it, or not)
TITLE = "Site hazard from coordinates"


def site_rows(site: SiteResult) -> list[list[str]]:
    """'quantity | value' rows: where the site is and its reference period."""
    return [
        ["latitude, longitude", f"{site.latitude:.7g}°, {site.longitude:.7g}°"],
        ["nominal life V_N", f"{site.V_N:g} years"],
        ["use class, coefficient C_U", f"{site.use_class}, {site.C_U:g}"],
        ["reference period V_R", f"{site.V_R:g} years (V_N·C_U, at least 35 years)"],
        ["nearest grid node", f"{site.nearest_node:.1f} km"],
    ]


def limit_state_table(site: SiteResult) -> TableData:
    """One row per limit state: P_VR, T_R (and the clamped one), a_g, F0, T_C*."""
    rows = []
    for name, s in site.limit_states.items():
        tr = f"{s.TR:.0f}" if s.TR_used == s.TR else f"{s.TR:.0f} ({s.TR_used:g} used)"
        used = "used" if name == site.limit_state else ""
        values = [f"{s.ag:.4f}", f"{s.F0:.3f}", f"{s.Tc_star:.3f}"]
        rows.append([name, f"{100 * s.P_VR:g} %", tr, *values, used])
    return TableData(
        ["limit state", "P_VR", "T_R [years]", "a_g [g]", "F0 [-]", "T_C* [s]", ""], rows
    )


def site_section(results: AssessmentResult, heading: Flowable | None = None) -> list[Flowable]:
    """The site's part of the report (``heading`` first when given); [] without a site."""
    site = results.site
    if site is None:
        return []
    table = limit_state_table(site)
    chosen = [i for i, row in enumerate(table.rows) if row[0] == site.limit_state]
    out: list[Flowable] = [heading] if heading is not None else []
    out.append(
        markup(
            f"<b>{esc(TITLE)}.</b> The spectrum's a_g, F0 and T_C* are those of "
            f"{esc(site.limit_state)} at the site, interpolated on the NTC reference grid "
            "(NTC 2018 §3.2; NTC 2008 Allegati A and B): the inverse-distance mean of the "
            "four vertices of the grid cell containing the site (the four nearest nodes when "
            "no complete cell does), log-log between the grid's return periods; "
            "T_R = −V_R/ln(1 − P_VR), within 30–2475 years."
        )
    )
    out.append(key_value(site_rows(site), sub_values=True))
    out.append(gap(4))
    out.append(
        KeepTogether(
            [
                grid(
                    table,
                    [24 * mm, 18 * mm, 34 * mm, 22 * mm, 20 * mm, 22 * mm, 16 * mm],
                    numeric_from=1,
                    highlight_rows=chosen,
                ),
                para(
                    "NTC 2018 Tab. 3.2.I: probability P_VR of exceeding the action in V_R and "
                    "its return period T_R for each limit state.",
                    "caption",
                ),
            ]
        )
    )
    return out
