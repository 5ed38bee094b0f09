"""The annex's sections on the inputs (B.2 the project, the wall, the materials and the model;
B.3 the seismic input) in the report's language: words from the catalogue, tables from
:mod:`~frp_assess.report.annex_input_tables`."""

from __future__ import annotations

from reportlab.lib.units import mm

from frp_assess.report import annex_input_tables as ti
from frp_assess.report import charts
from frp_assess.report.annex_floor import floor_motion_part
from frp_assess.report.charts import localize_drawing
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import (
    cond_break,
    esc,
    figure,
    gap,
    grid,
    h1,
    h2,
    keep,
    key_value,
    markup,
    page_break,
)
from frp_assess.report.formats import design_strain, run_words, rupture_strain_words
from frp_assess.report.lang import Lang
from frp_assess.results.model import AssessmentResult

Results = AssessmentResult


def inputs(results: Results, lang: Lang) -> list[Block]:
    """B.2: the project and software, the wall, the FRP materials, the model's options."""
    out: list[Block] = [h1("2  " + lang.t("ax.h.inputs")), h2("2.1  " + lang.t("ax.h.software"))]
    out.append(key_value(ti.software_rows(results, lang)))
    out.append(h2("2.2  " + lang.t("ax.h.wall")))
    out.append(key_value(ti.wall_rows(results, lang)))
    out.append(h2("2.3  " + lang.t("ax.h.materials")))
    widths = [18 * mm, 16 * mm, 14 * mm, 22 * mm, 22 * mm, 82 * mm]
    out.append(grid(ti.materials_table(results, lang), widths, wrap=(5,)))
    values = lang.t("ax.materials.design" if design_strain(results) else "ax.materials.mean")
    out.append(markup(lang.t("ax.materials.caption", rule=rupture_strain_words(results),
                             c=lang.gnum(results.model.strain_factor), values=values),
                      "caption"))  # fmt: skip
    out.append(h2("2.4  " + lang.t("ax.h.model")))
    out.append(key_value(ti.model_rows(results, lang), sub_values=True))
    return out


def seismic(results: Results, lang: Lang) -> list[Block]:
    """B.3: the target spectrum, the records, their spectra and the code's compliance checks
    (and the floor motion of a wall above ground)."""
    out: list[Block] = [page_break(), h1("3  " + lang.t("ax.h.seismic"))]
    out.append(h2("3.1  " + lang.t("ax.h.spectrum")))
    out.append(key_value(ti.spectrum_rows(results, lang), sub_values=True, verbatim_rows=(0, 1)))
    out.append(h2("3.2  " + lang.t("ax.h.records")))
    widths = [26 * mm, 58 * mm, 20 * mm, 22 * mm, 18 * mm, 22 * mm]
    out.append(grid(ti.records_table(results, lang), widths, wrap=(0, 1), numeric_from=2))
    for warning in results.input_warnings or []:
        said = run_words(str(warning), lang)
        if said is not None:
            out.append(markup(lang.t("ax.warning", text=esc(said)), "small"))
    out.append(gap(6))
    chart = localize_drawing(charts.spectra_chart(results), lang)
    out.append(keep([figure(chart), markup(lang.t("ax.fig.spectra"), "caption")]))
    out.append(cond_break(60 * mm))
    out.append(h2("3.3  " + lang.t("ax.h.compliance")))
    # the Italian words held whole: "soddisfatta", "+4 accelerogrammi" (2026-11-28)
    widths = [18 * mm, 24 * mm, 44 * mm, 38 * mm, 26 * mm, 20 * mm]
    out.append(grid(ti.compliance_table(results, lang), widths, wrap=(0, 1, 2, 3, 4, 5),
                    numeric_from=4))  # fmt: skip
    ok = bool(results.compliance.passed)
    out.append(markup(lang.t("ax.compliance.ok" if ok else "ax.compliance.bad"),
                      "verdict_ok" if ok else "verdict_bad"))  # fmt: skip
    out += floor_motion_part(results, lang)
    return out
