"""The annex B of the report, the calculation details, in the report's language (one code
path for every language): B.1 the summary, B.2 the inputs, B.3 the seismic input, B.4 the
wall as it is and the code's checks of every case, B.5 the retrofit options, B.6 the retrofit
as built and the masonry at the base, B.7 the governing time history.  Words from the
catalogue, numbers from the results; the parts are in the ``annex_*`` modules."""

from __future__ import annotations

from collections.abc import Callable

from frp_assess.report import annex_as_built, annex_inputs, annex_results, annex_summary
from frp_assess.report.doc_model import Block, Heading
from frp_assess.report.flow import h1, markup
from frp_assess.report.lang import Lang
from frp_assess.results.model import AssessmentResult

#: the parts of the annex, in order (each numbers its own headings 1, 1.1, ...)
PARTS: tuple[Callable[[AssessmentResult, Lang], list[Block]], ...] = (
    annex_summary.summary,
    annex_inputs.inputs,
    annex_inputs.seismic,
    annex_results.unreinforced,
    annex_results.options,
    annex_as_built.section,
    annex_results.governing,
)


def annex(results: AssessmentResult, lang: Lang, letter: str = "B") -> list[Block]:
    """The annex: its heading, the lead and its parts, their headings prefixed ``B.``."""
    out: list[Block] = [h1(lang.t("h.annex")), markup(lang.t("annex.lead"))]
    for part in PARTS:
        for b in part(results, lang):
            if isinstance(b, Heading) and b.level in (1, 2):
                b = Heading(f"{letter}.{b.text}", b.level)
            out.append(b)
    return out
