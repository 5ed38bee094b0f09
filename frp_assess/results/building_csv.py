"""A building's results.csv: one row per wall and case (the unreinforced wall and every
option), in the conventions of a wall's results.csv (:mod:`frp_assess.results.csv_files`: a
byte-order mark, the report's rounding, the Italian separators when the report is Italian)."""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence

from frp_assess.results.building_summary import CHECK_COLUMNS, case_zeta
from frp_assess.results.csv_files import BOM, CSV_FIELDS, case_columns, csv_style
from frp_assess.results.model import AssessmentResult

#: the columns: the wall, the case, ζ_E of every check, then a wall's results.csv's case_*
#: columns (design a_dyn, capacity/demand, verdict, governing check and margin, rank...)
BUILDING_CSV_FIELDS: list[str] = [
    "wall",
    "wall_folder",
    "case",
    "material",
    "position",
    "ratio_permille",
    "as_built",
    "proposed",
    *(f"zeta_e_{key}" for key, _ in CHECK_COLUMNS),
    *(name for name in CSV_FIELDS if name.startswith("case_")),
]


def building_csv(walls: Sequence[tuple[str, str, AssessmentResult]]) -> str:
    """One row per (wall, case) of the walls' (name, folder, results), in file order; the
    style (language) of the first wall's report."""
    st = csv_style(walls[0][2])
    buf = io.StringIO()
    w = csv.writer(buf, delimiter=st.delimiter, lineterminator="\n")
    w.writerow(BUILDING_CSV_FIELDS)
    for name, folder, results in walls:
        cells = case_columns(results, st)
        proposed = results.recommended if results.retrofit_required else None
        for c in results.cases:
            z = case_zeta(results, c)
            zetas = [getattr(z, key) for key, _ in CHECK_COLUMNS]
            w.writerow(
                [
                    name,
                    folder,
                    c.name,
                    c.material or "",
                    c.position or "",
                    st.number(c.ratio, 2),
                    "" if c.as_built is None else c.as_built.note,
                    st.flag(c.name == proposed),
                    *(st.number(x, 3) for x in zetas),
                    *cells(c),
                ]
            )
    return BOM + buf.getvalue()
