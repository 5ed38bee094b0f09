"""The editor fields of the declared model and IDA options (``dynamics/options.py``).

Each :class:`~frp_assess.dynamics.options.Option` gives its field whole: the help line is
:meth:`Option.describe` (what the schema and ``--help`` say), the text right of the input its
unit and accepted range with the default, the choices its words (``yes``/``no`` options: a
choice of the two).  Only the label, the width and the words shown for each value are the
editor's.  ``tests/tui/test_option_fields.py`` checks every declared option's field.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from frp_assess.config.messages import Loc
from frp_assess.dynamics.options import Option
from frp_assess.tui.core.editor_state import format_value
from frp_assess.tui.fields import FieldSpec


def option_hint(option: Option[Any]) -> str:
    """The short text right of a number's input: unit and accepted range (``s, [0, 60]``);
    an option that also takes words says ``or`` before the range (``or (0, 1]``)."""
    hint = ", ".join(p for p in (option.unit, option.range_text()) if p)
    return f"or {hint}" if option.choices else hint


def option_field(
    path: Loc,
    label: str,
    option: Option[Any],
    *,
    labels: Mapping[Any, str] | None = None,
    width: int | None = None,
) -> FieldSpec:
    """The field editing ``option`` at ``path`` of the project file.

    A number (with or without words besides) is an optional input whose unit text is
    :func:`option_hint` and the default (``[1.01, 10] (1.1)``); a word option is a choice of
    its words, a yes/no option a choice of ``False``/``True``; ``labels`` names a value in the
    list (the value itself otherwise).  ``width`` of the input: a number's 10 cells (its range
    text needs the room right of it), a choice's 22.
    """
    help_text = option.describe()
    if option.numeric:
        unit = f"{option_hint(option)} ({format_value(option.default)})".strip()
        return FieldSpec(
            path,
            label,
            "scalar",
            unit=unit,
            help=help_text,
            optional=True,
            width=width or 10,
            default=option.default,
        )
    values: tuple[Any, ...] = (False, True) if option.is_flag else option.choices
    names = labels or {}
    unknown = set(names) - set(values)
    if unknown:
        raise ValueError(
            f"{option.key}: labels for values it does not take: {sorted(map(repr, unknown))}"
        )
    pairs = tuple((names.get(v, str(v)), v) for v in values)
    return FieldSpec(
        path,
        label,
        "choice",
        choices=pairs,
        help=help_text,
        default=option.default,
        width=width or 22,
    )
