"""Save an edited project into its existing YAML file, keeping the file's comments and layout.

A project file written by hand (or by ``frp-assess new``) documents every key in comments.
:func:`update_project_text` changes only what the edit changed: a value that differs is
rewritten in place, a key the new project no longer has is removed, a key the file did not
have (it held the default) is appended to its block; everything else, comments included, is
kept as it was.  Lists (interventions, record files, sweep axes) are updated item by item.
End-of-line comments of changed values are kept (they mostly give units), except that of a
changed ``type`` (it describes the old kind of spectrum).  The result is checked by loading it
again: if it does not give exactly the new project, None is returned and the caller writes a
plain dump (:func:`~frp_assess.config.dump_project`).

Round-trip parsing uses ruamel.yaml, the maintained round-trip YAML library for Python.
"""

from __future__ import annotations

import io
from collections.abc import Mapping
from typing import Any

from frp_assess.config.loader import load_project_text, project_data
from frp_assess.config.schema import Project
from frp_assess.errors import InputError

_MISSING = object()


def _is_scalar(value: Any) -> bool:
    return not isinstance(value, dict | list)


def _to_node(value: Any) -> Any:
    """A new value as ruamel.yaml objects, in the style of the templates: flow style for a
    mapping or list of scalars (``{material: GFRP, ratio: 1.0}``, ``[1, 2, 3]``)."""
    from ruamel.yaml.comments import CommentedMap, CommentedSeq

    if isinstance(value, dict):
        node = CommentedMap((k, _to_node(v)) for k, v in value.items())
        if all(_is_scalar(v) for v in value.values()):
            node.fa.set_flow_style()
        return node
    if isinstance(value, list):
        seq = CommentedSeq(_to_node(v) for v in value)
        if all(_is_scalar(v) for v in value):
            seq.fa.set_flow_style()
        return seq
    return value


def _drop_eol_comment(node: Any, key: Any) -> None:
    """Remove the end-of-line comment of ``key`` (the lines of comments after it stay)."""
    entry = node.ca.items.get(key)
    token = entry[2] if entry and len(entry) > 2 else None
    if token is not None and token.value.startswith("#"):
        token.value = "\n" + token.value.partition("\n")[2]


def _update(node: Any, key: Any, before: Any, value: Any) -> None:
    """Make ``node[key]`` (which holds ``before``) hold ``value``, in place where possible."""
    from ruamel.yaml.comments import CommentedMap, CommentedSeq

    current = node[key]
    if isinstance(current, CommentedMap) and isinstance(value, dict):
        _merge(current, before if isinstance(before, dict) else {}, value)
    elif isinstance(current, CommentedSeq) and isinstance(value, list):
        _merge_seq(current, before if isinstance(before, list) else [], value)
    elif before != value:
        node[key] = _to_node(value)
        if key == "type":  # the comment described the old kind (of spectrum, say)
            _drop_eol_comment(node, key)


def _merge(node: Any, old: Mapping[str, Any], new: Mapping[str, Any]) -> None:
    """Update the round-trip mapping ``node`` (holding ``old``) so that it holds ``new``."""
    for key in [k for k in node if k not in new]:
        del node[key]
    for key, value in new.items():
        before = old.get(key, _MISSING)
        if key in node:
            _update(node, key, before, value)
        elif before != value:  # the file left it to the default, which changed
            node[key] = _to_node(value)


def _merge_seq(node: Any, old: list[Any], new: list[Any]) -> None:
    """Update the round-trip list ``node`` (holding ``old``) item by item to hold ``new``."""
    for i, value in enumerate(new):
        if i < len(node):
            _update(node, i, old[i] if i < len(old) else _MISSING, value)
        else:
            node.append(_to_node(value))
    del node[len(new) :]


def update_data_text(
    original_text: str, old: Mapping[str, Any], new: Mapping[str, Any]
) -> str | None:
    """``original_text`` (whose YAML reads as the mapping ``old``) changed where ``new``
    differs from ``old``, comments and layout kept; None when the text is not a YAML mapping.
    The caller checks the result (by loading it again)."""
    from ruamel.yaml import YAML
    from ruamel.yaml.comments import CommentedMap
    from ruamel.yaml.error import YAMLError

    yaml = YAML(typ="rt")
    yaml.preserve_quotes = True
    yaml.width = 4096  # never re-wrap long lines (notes, lists)
    yaml.indent(mapping=2, sequence=4, offset=2)  # the layout of templates/wall.yaml
    try:
        doc = yaml.load(original_text)
    except YAMLError:
        return None
    if not isinstance(doc, CommentedMap):
        return None
    _merge(doc, old, new)
    buf = io.StringIO()
    yaml.dump(doc, buf)
    return buf.getvalue()


def update_project_text(
    original_text: str, original: Project, project: Project, name: str = "<project>"
) -> str | None:
    """``original_text`` (which loads as ``original``) changed so that it loads as ``project``.

    None when the text cannot be updated in place (not a mapping, or the check by loading
    the result fails): then write :func:`~frp_assess.config.dump_project` instead.
    """
    if project == original:
        return original_text
    text = update_data_text(original_text, project_data(original), project_data(project))
    if text is None:
        return None
    try:
        again = load_project_text(text, name, check_files=False).project
    except InputError:
        return None
    return text if again == project else None
