"""Shared pieces of the project file's models: the number types, the bounds each
field's range is written with, the base model and the located cross-check error.
"""

from __future__ import annotations

import datetime as _dt
from typing import Annotated, Any, Literal, get_args

from pydantic import (
    AllowInfNan,
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Strict,
)
from pydantic_core import PydanticCustomError

from frp_assess.motions.record_text import MAX_DT
from frp_assess.rules.geometry import HEIGHT_RANGE as HEIGHT_RANGE  # re-export
from frp_assess.rules.geometry import THICKNESS_RANGE as THICKNESS_RANGE  # re-export

GroundType = Literal["A", "B", "C", "D", "E"]

#: accepted ``format`` of a record file (as frp_assess.motions.record_text.FORMATS)
RecordFormat = Literal["auto", "at2", "esm", "two-column", "one-column"]
RECORD_FORMATS: tuple[str, ...] = get_args(RecordFormat)
#: accepted ``units`` of a record file (as frp_assess.motions.record_text.UNITS)
RecordUnits = Literal["g", "m/s2", "m/s^2", "cm/s2", "cm/s^2", "gal"]
#: the largest bar diameter [mm] and area [mm²] accepted
MAX_BAR_DIAMETER = 50.0
MAX_BAR_AREA = 2000.0
MIN_BAR_DIAMETER = 1.0
#: smallest ratio [‰] of an option: below it the bars carry nothing measurable (the
#: plausibility warning starts at 0.1 ‰)
MIN_RATIO = 0.001
#: smallest spacing between bar axes [m]: two drilled holes need about 20 mm between axes
MIN_SPACING = 0.02
#: exposure of the bars (CNR-DT 200 R1/2013 Table 3.2) and fibres of its η_a
Exposure = Literal["internal", "external", "aggressive"]
Fibre = Literal["glass", "carbon", "aramid", "basalt"]
#: shortest artificial record [s]: the generator's envelope rise (2.5 s) + stationary part
#: (10 s) + 1 s of decay (frp_assess.motions.simqke; a test keeps the two equal)
MIN_ARTIFICIAL_DURATION = 13.5


def located_error(message: str, *loc: str | int) -> PydanticCustomError:
    """A validation error whose ``ctx['loc']`` extends the location pydantic reports."""
    return PydanticCustomError(
        "cross_check", message.replace("{", "(").replace("}", ")"), {"loc": loc}
    )


def _to_text(value: Any) -> Any:
    """Free text: any YAML scalar (number, date) becomes a string; null becomes ``""``."""
    if value is None:
        return ""
    if isinstance(value, bool | int | float | _dt.date):
        return str(value)
    return value


#: every number of the file: strict (no quoted "0.4", no yes/no) and finite (YAML reads 1e400
#: and .inf as infinity, .nan as not-a-number; none of them is a value of any field)
Number = Annotated[float, Strict(), AllowInfNan(False)]
FreeText = Annotated[str, BeforeValidator(_to_text)]
#: an integer of the file (a float such as 7.0 or 1e400 is refused)
WholeNumber = Annotated[int, Strict()]

#: The range of every number below is the range the model is valid for (refused outside, with
#: the file's line); each bound is written once, on its field, with its unit and its reason.
#: Values inside the range but outside the range of practice give a warning instead
#: (frp_assess.config.plausibility).
#: smallest a_g [g] of a code spectrum and smallest largest ordinate of a table [g]: below
#: 0.001 g there is no seismic action to assess, and records scaled to it lose their digits
MIN_SPECTRUM_G = 0.001
#: ranges shared with the command line's wall and bar options (cli/wall_args.py), [low, high]:
#: thickness B [m] (below 50 mm no masonry leaf stands, a brick on edge is 55-60 mm), height H
#: [m] (below 0.5 m the wall is a block, not a rocking panel), E [GPa] and eps_u [-] of a bar
#: (FRP bars: 30-250 GPa, 0.005-0.035; a bar softer than 1 GPa or breaking at 0.01 % is none)
#: (THICKNESS_RANGE and HEIGHT_RANGE are in rules/geometry.py: results.json is read back
#: within them too)
MODULUS_RANGE = (1.0, 1000.0)
STRAIN_RANGE = (1e-4, 0.1)
#: reference period T1 [s] of the compatibility checks (also the records command's --t1): the
#: checks' ranges start at 0.2*T1, below T1 = 0.05 s they leave the spectra's periods (and
#: T1 = 1e-300 never ended)
T1_RANGE = (0.05, 10.0)
#: periods [s] up to which a table's ordinates must reach MIN_SPECTRUM_G
TABLE_BAND = 2.0
#: bounds on the work one project asks for (refused before any computation, see each field)
MAX_OPTIONS = 2000  #: retrofit options after the sweeps are expanded
MAX_RECORD_DURATION = 600.0  #: [s] longest artificial record
MIN_TIME_STEP = 1e-4  #: [s] smallest time step of a record
#: [s] largest time step of a record: the record reader's (its reason there)
MAX_TIME_STEP = MAX_DT
MAX_SEED = 2**32 - 1  #: largest random seed
MAX_TABLE_POINTS = 1000  #: points of a spectrum table
#: longest free texts [characters]
MAX_NAME_CHARS = 200
MAX_NOTES_CHARS = 5000


#: longest record name [characters] (it names the exported ``records/<name>.AT2``)
MAX_RECORD_NAME = 100
#: characters a record name may not contain: path separators and what Windows refuses
_UNSAFE_NAME_CHARS = '/\\:*?"<>|'


def unsafe_name_reason(name: str) -> str | None:
    """Why ``name`` is not safe as a file name (``records/<name>.AT2``), or None if it is.

    Refused: empty, longer than :data:`MAX_RECORD_NAME`, a path separator or one of
    ``: * ? " < > |``, a control character, a leading dot or blank (``..``, hidden files),
    a trailing dot or blank.
    """
    if not name.strip():
        return "it is empty"
    if len(name) > MAX_RECORD_NAME:
        return f"it has {len(name)} characters, more than {MAX_RECORD_NAME}"
    bad = sorted({c for c in name if c in _UNSAFE_NAME_CHARS})
    if bad:
        return f'it contains {" ".join(bad)} (names may not contain / \\ : * ? " < > |)'
    if any(ord(c) < 32 or 0x7F <= ord(c) <= 0x9F for c in name):
        return "it contains control characters"
    if name[0] in ". " or name[-1] in ". ":
        return "it starts or ends with a dot or a blank"
    return None


def format_ratio(ratio: float) -> str:
    """A ratio [‰] without trailing zeros: 1.0 -> ``1``, 1.50 -> ``1.5``."""
    return f"{ratio:.6g}"


def option_name(material: str, position: str, ratio: float) -> str:
    """The generated name of an option, e.g. ``GFRP centred 1‰``."""
    return f"{material} {position} {format_ratio(ratio)}‰"


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
