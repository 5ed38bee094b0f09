"""One row of a study's summary.csv, typed: the one definition of a study's result row.

:class:`SummaryRow` holds each column as its type (m, °, ‰, g; None where the cell is empty:
the unreinforced wall has no material, position or ratio) and is also read by column name as
the CSV text (``row["mean_q"]``), as the figures and the comparison with the paper group and
pick cases by the written values.
"""

from __future__ import annotations

import csv
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path

#: a row read by column name, as the CSV text (a :class:`SummaryRow`, or one with extra
#: columns the comparison adds to order cases)
Row = Mapping[str, str]


@dataclass(frozen=True)
class SummaryRow(Mapping[str, str]):
    """One case of a study over all its records: a row of summary.csv, its fields in the order
    of :data:`frp_assess.study.run.SUMMARY_COLUMNS`."""

    case: int  #: index of the case in the study's plan
    label: str
    spectrum: str
    mechanism: str
    height_m: float  #: H [m]
    thickness_m: float  #: B [m]
    alpha_deg: float  #: α [°]
    material: str | None  #: None: the unreinforced wall
    position: str | None
    ratio_permille: float | None  #: ρ [‰]
    records: int
    a_rm_g: float  #: a_RM = B/H [g]
    mean_a_dyn_g: float  #: [g]; a lower bound when ``lower_bound``
    min_a_dyn_g: float  #: [g]
    mean_q: float  #: [-]
    lower_bound: bool  #: some record did not collapse up to C_max (counted at C_max·PGA)
    unreinforced_case: int  #: the case of the same wall without bars
    unreinforced_mean_a_dyn_g: float  #: [g]
    improvement: float  #: mean a_dyn over that of the unreinforced wall [-]
    cells: Mapping[str, str] = field(repr=False, compare=False)  #: the CSV text by column

    @classmethod
    def from_cells(cls, cells: Mapping[str, str]) -> SummaryRow:
        """The row of the CSV ``cells`` (column -> text, as :class:`csv.DictReader` reads)."""

        def number(key: str) -> float | None:
            return float(cells[key]) if cells[key] else None

        def text(key: str) -> str | None:
            return cells[key] or None

        def required(key: str) -> float:
            return float(cells[key])

        return cls(
            case=int(cells["case"]),
            label=cells["label"],
            spectrum=cells["spectrum"],
            mechanism=cells["mechanism"],
            height_m=required("height_m"),
            thickness_m=required("thickness_m"),
            alpha_deg=required("alpha_deg"),
            material=text("material"),
            position=text("position"),
            ratio_permille=number("ratio_permille"),
            records=int(cells["records"]),
            a_rm_g=required("a_rm_g"),
            mean_a_dyn_g=required("mean_a_dyn_g"),
            min_a_dyn_g=required("min_a_dyn_g"),
            mean_q=required("mean_q"),
            lower_bound=cells["lower_bound"] == "yes",
            unreinforced_case=int(cells["unreinforced_case"]),
            unreinforced_mean_a_dyn_g=required("unreinforced_mean_a_dyn_g"),
            improvement=required("improvement"),
            cells=dict(cells),
        )

    @property
    def reinforced(self) -> bool:
        """Whether the case has bars."""
        return self.material is not None

    def __getitem__(self, key: str) -> str:
        return self.cells[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self.cells)

    def __len__(self) -> int:
        return len(self.cells)


def read_summary(path: Path) -> list[SummaryRow]:
    """The rows of a summary.csv (for figures, comparison and tests)."""
    with Path(path).open(encoding="utf-8", newline="") as fh:
        return [SummaryRow.from_cells(cells) for cells in csv.DictReader(fh)]
