"""The digest of a run's inputs, and the unchanged rerun that recomputes nothing.

A run's results depend on the project file's bytes, the bytes of every file it references
(the record files), the version of frp-assess and the run options that change results
(``--rtol``, ``--verify``).  :func:`inputs_digest` hashes exactly those: relative paths as
written in the project file, never an absolute path or a date, so that the same inputs give
the same digest on every machine (results.json's ``inputs_digest``, docs/results-json.md).

Beside results.json a run writes the small sidecar :data:`SIDECAR` (the digest, the date of
the run and the referenced paths), so that ``frp-assess run`` can tell an unchanged rerun
(:func:`unchanged_run`) by reading a few hundred bytes and hashing the inputs, without
importing the numerics, the schema or the PDF renderer.  Standard library only.
"""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from frp_assess import __version__
from frp_assess.errors import InputError
from frp_assess.io_utils import read_regular
from frp_assess.output_record import REPORT_NAMES, SIDECAR_NAME, set_on_record

if TYPE_CHECKING:
    from frp_assess.config.schema import Project

__all__ = [
    "SIDECAR",
    "Unchanged",
    "inputs_digest",
    "project_changed",
    "project_digest",
    "file_hash",
    "unchanged_folder",
    "referenced_paths",
    "unchanged_run",
    "write_sidecar",
]

#: the sidecar file in the output folder: {"digest", "created", "files", "pdf", "results"}
#: ("results": the SHA-256 of the results.json it belongs to)
SIDECAR = SIDECAR_NAME
#: the members of a complete output set (report.pdf and report.docx besides, unless
#: --no-pdf)
_SET_FILES = ("results.json", "results.csv", "spectra.csv")
#: the largest file hashed (a record file is at most 50 MB, a project file 2 MB) [bytes]
_MAX_HASHED_BYTES = 64_000_000
#: the largest sidecar read [bytes]
_MAX_SIDECAR_BYTES = 4_000_000


def file_hash(path: Path) -> str:
    """SHA-256 of a regular file; ``"missing"`` for anything that cannot be read as one (a
    FIFO, a device, a folder, a file too large is never read: :func:`read_regular`)."""
    try:
        return hashlib.sha256(read_regular(path, "file", _MAX_HASHED_BYTES)).hexdigest()
    except InputError:
        return "missing"


def inputs_digest(
    project_file: Path,
    files: Sequence[str],
    *,
    rtol: float | None = None,
    verify: bool = False,
) -> str:
    """``"sha256:<hex>"`` of what a run's results depend on: the bytes of ``project_file``
    and of each referenced file (``files``: paths as written in the project, relative to its
    folder), the frp-assess version and the options ``rtol`` (None: the file's own
    tolerance) and ``verify``.  A file that cannot be read counts as ``"missing"``."""
    project_file = Path(project_file)
    base = project_file.parent
    content = {
        "frp_assess": __version__,
        "project": file_hash(project_file),
        "files": [[f, file_hash(base / f)] for f in files],
        "options": {"rtol": rtol, "verify": bool(verify)},
    }
    text = json.dumps(content, sort_keys=True, ensure_ascii=True, separators=(",", ":"))
    return "sha256:" + hashlib.sha256(text.encode("ascii")).hexdigest()


def referenced_paths(project: Project) -> list[str]:
    """The files ``project`` references, as written in it (relative to its folder): the
    record files, in file order, then the report's Word template if one is given."""
    files = [f.path for f in project.seismic.records.files or []]
    if project.report.template is not None:
        files.append(str(project.report.template))
    return files


def project_digest(
    project_file: Path, project: Project, *, rtol: float | None = None, verify: bool = False
) -> str:
    """:func:`inputs_digest` of ``project`` as read from ``project_file``."""
    return inputs_digest(project_file, referenced_paths(project), rtol=rtol, verify=verify)


def write_sidecar(
    out_dir: Path, digest: str, created: str, files: Sequence[str], *, pdf: bool
) -> None:
    """Write :data:`SIDECAR` into ``out_dir`` (after the output set is complete), tied to its
    results.json by that file's SHA-256 (a sidecar left beside another results.json, by a
    run stopped between the two writes or a file replaced by hand, is not believed)."""
    from frp_assess.io_utils import atomic_write_text

    results = file_hash(Path(out_dir) / "results.json")
    data = {
        "digest": digest,
        "created": created,
        "files": list(files),
        "pdf": pdf,
        "results": results,
    }
    atomic_write_text(Path(out_dir) / SIDECAR, json.dumps(data, indent=1) + "\n")


@dataclass(frozen=True)
class Unchanged:
    """An output folder whose results are those of the inputs as they are now."""

    out_dir: Path
    digest: str
    created: str  #: ISO date of the stored run


def unchanged_run(
    project_file: Path,
    out_dir: Path,
    *,
    rtol: float | None = None,
    verify: bool = False,
    pdf: bool = True,
) -> Unchanged | None:
    """The stored run in ``out_dir`` when it is complete (results.json, results.csv,
    spectra.csv, records/ and, if ``pdf``, report.pdf and report.docx) and its digest is
    that of the inputs now; else None (then the run happens as usual).  Never raises for a
    missing or broken sidecar: that is simply "not unchanged"."""
    return _unchanged(
        Path(out_dir),
        pdf,
        lambda files: inputs_digest(project_file, files, rtol=rtol, verify=verify),
    )


def unchanged_folder(out_dir: Path, digest: str, *, pdf: bool = True) -> Unchanged | None:
    """:func:`unchanged_run` for inputs whose digest is known (a wall of a building:
    :func:`frp_assess.app.building_run.wall_digest`)."""
    return _unchanged(Path(out_dir), pdf, lambda files: digest)


def _unchanged(out_dir: Path, pdf: bool, expected: Callable[[list[str]], str]) -> Unchanged | None:
    """The stored run in ``out_dir`` if complete and its sidecar's digest is ``expected`` of
    the files it lists (see :func:`unchanged_run`)."""
    try:
        data = json.loads(read_regular(out_dir / SIDECAR, "sidecar", _MAX_SIDECAR_BYTES))
        digest, created, files = data["digest"], data["created"], data["files"]
        ok = isinstance(digest, str) and isinstance(created, str) and isinstance(files, list)
        if not ok or not all(isinstance(f, str) for f in files):
            return None
    except (InputError, ValueError, KeyError, TypeError):
        return None
    needed = [*_SET_FILES, *(("report.pdf", "report.docx") if pdf else ())]
    if not all(os.path.isfile(out_dir / n) for n in needed) or not (out_dir / "records").is_dir():
        return None
    if expected(files) != digest:
        return None
    if file_hash(out_dir / "results.json") != data.get("results"):
        return None
    if not set_on_record(out_dir, REPORT_NAMES if pdf else ()):
        return None  # a member changed by hand, a report not made from these results
    return Unchanged(out_dir, digest, created)


def project_changed(project_file: Path | None, project: Project, digest: str | None) -> bool:
    """Whether the project file (or a file it references) changed since the run whose
    results carry ``digest`` (False when either is unknown: no file, no digest)."""
    if project_file is None or not digest:
        return False
    return project_digest(Path(project_file), project) != digest
