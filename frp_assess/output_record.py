"""The record of what frp-assess wrote in a results folder, so that it never replaces or
deletes anything else (:mod:`frp_assess.output_set` states the rule).

:data:`MANIFEST_NAME` holds the size and SHA-256 of every member of the output set the tool
wrote (``records/`` file by file), and for each report the results.json it was made from.
A member on no record, or changed since (a project's own ``records/`` when ``--out`` is the
project's folder, a report signed or edited since, a user's ``results.csv``), is *foreign*:
:func:`refuse_foreign` says so in one line.  Standard library only, small files only.
"""

from __future__ import annotations

import hashlib
import json
import os
import stat
from collections.abc import Iterator
from pathlib import Path

from frp_assess.errors import InputError
from frp_assess.io_utils import atomic_write_text, read_regular

#: the members of a run's output set, ``results.json`` (the one that validates the set) last
SET_NAMES: tuple[str, ...] = (
    "results.csv",
    "spectra.csv",
    "records",
    "report.pdf",
    "report.docx",
    "results.json",
)
#: the members made from results.json alone (frp-assess report makes them again)
REPORT_NAMES: tuple[str, ...] = ("report.pdf", "report.docx")
#: the record of the members the tool wrote: {"files": {"records/a.AT2": ["<size>:<sha256>"]},
#: "reports_of": {"report.pdf": "<size>:<sha256> of the results.json it was made from"}}
MANIFEST_NAME = ".frp-assess-files.json"
#: the inputs sidecar of a run (as frp_assess.app.rerun.SIDECAR): "results" is the SHA-256
#: of the results.json it belongs to, how a folder of an older version is known
SIDECAR_NAME = ".inputs-digest.json"
#: the largest manifest or sidecar read back [bytes]
_MAX_RECORD_BYTES = 4_000_000
#: a member larger than this is nobody's output of this tool: not hashed, foreign [bytes]
_MAX_MEMBER_BYTES = 1 << 30


def _digest(path: Path, size: int) -> str:
    """``"<size>:<sha256>"`` of a regular file of ``size`` bytes."""
    h = hashlib.sha256()
    with os.fdopen(os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_NOFOLLOW), "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            h.update(block)
    return f"{size}:{h.hexdigest()}"


def _walk_members(
    directory: Path, names: tuple[str, ...] = SET_NAMES
) -> Iterator[tuple[str, os.stat_result]]:
    """Every entry of the set members ``names`` in ``directory`` (``records/`` file by file,
    its folders too), as (path relative to ``directory``, ``lstat``); never follows a link."""
    for name in names:
        try:
            st = os.lstat(directory / name)
        except OSError:
            continue
        yield name, st
        if stat.S_ISDIR(st.st_mode):
            for root, dirs, files in os.walk(directory / name):
                dirs.sort()
                for entry in sorted(dirs + files):
                    p = Path(root) / entry
                    yield p.relative_to(directory).as_posix(), os.lstat(p)


def member_digests(directory: Path) -> dict[str, str]:
    """The digests of the regular files of the set members in ``directory``."""
    return {
        rel: _digest(directory / rel, st.st_size)
        for rel, st in _walk_members(directory)
        if stat.S_ISREG(st.st_mode) and st.st_size <= _MAX_MEMBER_BYTES
    }


def _read_json(path: Path) -> object:
    """The JSON value of a small regular file the tool wrote; None if there is none or it
    cannot be read as one."""
    try:
        return json.loads(read_regular(path, "file of frp-assess", _MAX_RECORD_BYTES))
    except (InputError, ValueError):
        return None


def known_members(directory: Path) -> dict[str, list[str]] | None:
    """The members the tool wrote in ``directory``: its record (:data:`MANIFEST_NAME`); for
    a folder of an older version without one, the members as they are when its sidecar
    holds the SHA-256 of its results.json; ``{}`` for a folder without members; None when
    the members are on no record."""
    data = _read_json(directory / MANIFEST_NAME)
    if os.path.lexists(directory / MANIFEST_NAME):
        files = data.get("files") if isinstance(data, dict) else None
        if not isinstance(files, dict):
            return None
        return {str(k): [str(d) for d in v] for k, v in files.items() if isinstance(v, list)}
    if not any(os.path.lexists(directory / n) for n in SET_NAMES):
        return {}
    sidecar = _read_json(directory / SIDECAR_NAME)
    digests = member_digests(directory) if isinstance(sidecar, dict) else {}
    stored = digests.get("results.json", "").partition(":")[2]  # what an older version wrote
    if stored and isinstance(sidecar, dict) and stored == sidecar.get("results"):
        return {rel: [d] for rel, d in digests.items()}
    return None


def _foreign(
    directory: Path, known: dict[str, list[str]], names: tuple[str, ...] = SET_NAMES
) -> str | None:
    """The first member in ``directory`` (relative path) that is not on ``known``: a file
    not recorded or changed since, anything but a file or a folder (a link, a FIFO)."""
    for rel, st in _walk_members(directory, names):
        if stat.S_ISDIR(st.st_mode) and rel.split("/")[0] == "records":
            continue
        if not stat.S_ISREG(st.st_mode) or st.st_size > _MAX_MEMBER_BYTES:
            return rel
        allowed = known.get(rel, [])
        if not any(d.startswith(f"{st.st_size}:") for d in allowed):
            return rel
        if _digest(directory / rel, st.st_size) not in allowed:
            return rel
    return None


def refuse_foreign(directory: Path, key: str = "--out", names: tuple[str, ...] = SET_NAMES) -> None:
    """One :class:`InputError` line if one of the set members ``names`` in ``directory`` is
    not one the tool wrote, which a run would replace or delete (see the module docstring);
    nothing for a folder that does not exist or holds no member."""
    foreign = _foreign(Path(directory), known_members(Path(directory)) or {}, names)
    if foreign is not None:
        raise InputError(
            f"{Path(directory) / foreign} is not a file frp-assess wrote there (none on "
            "record, or changed since); frp-assess never replaces or deletes a file it did "
            "not write: move it away or choose another folder for the results",
            key=key,
        )


def _reports_of(directory: Path) -> dict[str, str]:
    data = _read_json(directory / MANIFEST_NAME)
    made = data.get("reports_of") if isinstance(data, dict) else None
    return {str(k): str(v) for k, v in made.items()} if isinstance(made, dict) else {}


def report_belongs(directory: Path, name: str) -> bool:
    """Whether the report ``name`` in ``directory`` is, on the tool's record, made from the
    results.json now beside it (and not changed since); False when nothing says so."""
    directory = Path(directory)
    known = known_members(directory)
    results = (known or {}).get("results.json", [])
    if known is None or len(results) != 1 or _reports_of(directory).get(name) != results[0]:
        return False
    return _foreign(directory, known, ("results.json", name)) is None


def set_on_record(directory: Path, reports: tuple[str, ...] = ()) -> bool:
    """Whether every member in ``directory`` is as the tool wrote it and each of ``reports``
    is made from the results.json beside it (the latter unknowable, and not asked, in a
    folder of an older version)."""
    directory = Path(directory)
    known = known_members(directory)
    if known is None or _foreign(directory, known) is not None:
        return False
    if not os.path.lexists(directory / MANIFEST_NAME):
        return True
    return all(report_belongs(directory, name) for name in reports)


def record_report(directory: Path, name: str) -> None:
    """Put the report ``name`` in ``directory`` as it is now on the tool's record, made from
    the results.json beside it (``frp-assess report``, under the folder's lock)."""
    directory = Path(directory)
    known = known_members(directory) or {}
    now = member_digests(directory)
    known = {**known, name: [now[name]]} if name in now else known
    made_from = {**_reports_of(directory), name: now.get("results.json", "")}
    write_record(directory, known, made_from)


def write_record(directory: Path, files: dict[str, list[str]], made_from: dict[str, str]) -> None:
    data = {
        "files": {rel: files[rel] for rel in sorted(files)},
        "reports_of": {n: made_from[n] for n in sorted(made_from)},
    }
    atomic_write_text(directory / MANIFEST_NAME, json.dumps(data, indent=1) + "\n")
