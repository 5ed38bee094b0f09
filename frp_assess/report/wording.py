"""The report speaks to the engineer: developer references in prose that reaches it from the
results (notes of the layout, the ranking rule, the pivot check, the masonry's source) are
put in words — no documentation file names, no keys of the project file, no library keys.

Applied once, to every paragraph and table cell of the document (:func:`engineer_blocks`).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import replace

from frp_assess.report.doc_model import Block, Keep, Para, Table
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import Markup

#: (pattern, words), applied in order
RULES: tuple[tuple[re.Pattern[str], str | Callable[[re.Match[str]], str]], ...] = (
    (re.compile(r",?\s*\(?\s*docs/[\w./-]+\.md(?:\s*,?\s*§\s*\d+(?:\.\d+)*)?\s*\)?"), ""),
    (re.compile(r"code_check\.fc_in_ida:\s*false"), "the designer's choice not to divide by FC"),
    (re.compile(r"code_check\.fc_in_ida"), "the choice of FC in the dynamic analysis"),
    (re.compile(r"code_check\.knowledge_level"), "the knowledge level"),
    (re.compile(r"bars\.design_values:\s*false"), "mean values"),
    (re.compile(r"bars\.design_values"), "design values of the bars"),
    (re.compile(r"bars\.whole_bars:\s*false"), "bars not rounded to whole bars"),
    (re.compile(r"bars\.whole_bars"), "whole bars"),
    (re.compile(r"bars\.anchorage"), "anchorage data"),
    (re.compile(r"bars\.catalogue"), "the catalogue of bar sizes"),
    (re.compile(r"bars\.exposure"), "the exposure of the bars"),
    (re.compile(r"analysis\.strain_factor"), "the cyclic strain factor"),
    (re.compile(r"analysis\.pivot"), "the pivot rule"),
    (re.compile(r"wall\.unit_weight|\bunit_weight\b"), "unit weight"),
    (re.compile(r"\(?pivot:\s*crushing\)?"), "(crushing pivot)"),
    (re.compile(r"\(?pivot:\s*edge\)?"), "(edge pivot)"),
    (re.compile(r"\basked \(ratio\)"), "asked (governed by the ratio)"),
    (re.compile(r"\(max_spacing\)"), "(governed by the largest spacing)"),
    (re.compile(r"\bmax_spacing\b"), "largest spacing"),
    (re.compile(r"\bTc_star\b"), "T_C*"),
    (re.compile(r"wall\.compressive_strength"), "the compressive strength given for the wall"),
    (re.compile(r"wall\.masonry"), "the masonry type"),
    (re.compile(r"bars\.min_spacing"), "the smallest spacing"),
    (re.compile(r"bars\.bar_force"), "the bar force"),
    (re.compile(r"costs\.installation_per_metre"), "the installation cost"),
    (re.compile(r"costs\.currency"), "the currency"),
    # any other key of the project file: its last part in words
    (
        re.compile(
            r"\b(?:wall|bars|analysis|code_check|costs|seismic|design|building|report|"
            r"project|interventions|materials)\.(?:[a-z_]+\.)*([a-z_]+)\b"
        ),
        lambda m: m.group(1).replace("_", " "),
    ),
    (re.compile(r"\(\s*\)"), ""),
    # one spacing of the percent sign (SI, NTC): "5 %", never "5%", kept on one line
    (re.compile(r"(\d)%"), "\\1\u00a0%"),
)


def engineer_text(text: str, results: AssessmentResult) -> str:
    """``text`` with the developer references of :data:`RULES` and the masonry's library
    key put in words."""
    out = text
    for pattern, words in RULES:
        out = pattern.sub(words, out)
    key = results.wall.masonry
    if key and key in out:
        desc = results.wall.masonry_description or ""
        out = out.replace(key, desc.split(" (")[0] if desc else "masonry of the table")
    return Markup(out) if isinstance(text, Markup) else out


def engineer_blocks(blocks: Sequence[Block], results: AssessmentResult) -> list[Block]:
    """``blocks`` with :func:`engineer_text` applied to every paragraph and table cell."""
    out: list[Block] = []
    for b in blocks:
        if isinstance(b, Para):
            b = Para(engineer_text(b.markup, results), b.style)
        elif isinstance(b, Table):
            b = replace(
                b,
                header=tuple(engineer_text(c, results) for c in b.header),
                rows=tuple(tuple(engineer_text(c, results) for c in row) for row in b.rows),
            )
        elif isinstance(b, Keep):
            b = Keep(tuple(engineer_blocks(b.blocks, results)))
        out.append(b)
    return out
