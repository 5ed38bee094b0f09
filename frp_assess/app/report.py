"""The output set of a run, the PDF report and the export of a run to another folder.

:func:`write_outputs` writes results.json, results.csv, spectra.csv, records/*.AT2,
report.pdf and report.docx as one set (:mod:`frp_assess.output_set`);
:func:`rebuild_report` makes the PDF (or the DOCX) again from a stored results.json
(`frp-assess report`); :func:`export_run` writes a finished run into a folder the user
picks (the TUI's export).
"""

from __future__ import annotations

import shutil
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from frp_assess.errors import InputError
from frp_assess.io_utils import atomic_write_text
from frp_assess.motions import write_at2
from frp_assess.output_record import record_report, refuse_foreign, report_belongs
from frp_assess.output_set import FolderLock, check_out_dir, check_out_file, staged_set
from frp_assess.results.csv_files import results_csv, spectra_csv
from frp_assess.results.json_io import to_json
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import plain

if TYPE_CHECKING:
    from frp_assess.app.assessment import RunOutcome
    from frp_assess.assess.seismic import SeismicInput

__all__ = [
    "REPORT_FILES",
    "build_pdf",
    "build_word",
    "export_folder_problem",
    "export_run",
    "rebuild_report",
    "write_outputs",
]

#: the reports a run writes beside its results (unless ``pdf=False``, ``--no-pdf``)
REPORT_FILES: tuple[str, ...] = ("report.pdf", "report.docx")


def write_outputs(
    results: AssessmentResult, seismic: SeismicInput, out_dir: Path, *, pdf: bool
) -> None:
    """Write the output set — results.json, results.csv, spectra.csv, records/*.AT2 (and
    records/SLC/*.AT2 for a limit state with its own set of records) and (if ``pdf`` and
    available) the reports report.pdf and report.docx, the same document — as one set
    (:mod:`frp_assess.output_set`).

    The folder is locked for the duration, the set is written into a fresh staging folder
    inside ``out_dir`` and swapped in only once complete: any failure (disk full, an error in
    the PDF, an interrupt) leaves the previous set as it was; a report that cannot be laid out
    is left out with a warning (:func:`build_pdf`, :func:`build_word`).  When results.json
    is byte for byte the stored one, the stored reports are kept, not rebuilt.  A record
    name that is not a plain file name is refused (:class:`~frp_assess.errors.InputError`)
    before anything is written.
    """
    for rec in seismic.records:
        if not _is_plain_file_name(rec.name):
            raise InputError(
                f"record name {rec.name!r} cannot be a file name (no '/', '\\', '..', "
                "leading dot or control characters)",
                key="records",
            )
    with FolderLock(out_dir), staged_set(out_dir) as staging:
        for rec in seismic.records:
            write_at2(rec, staging / "records" / f"{rec.name}.AT2", f"{rec.name}: {rec.source}")
        for state, recs in seismic.state_records.items():  # a limit state's own set
            for rec in recs:
                path = staging / "records" / state / f"{rec.name}.AT2"
                write_at2(rec, path, f"{rec.name} ({state} spectrum): {rec.source}")
        atomic_write_text(staging / "spectra.csv", spectra_csv(results))
        atomic_write_text(staging / "results.csv", results_csv(results))
        text = to_json(results)
        atomic_write_text(staging / "results.json", text)
        if pdf:
            for name, build in (("report.pdf", build_pdf), ("report.docx", build_word)):
                if not _keep_report(out_dir, text, name, staging / name):
                    build(results, staging / name)


def _keep_report(out_dir: Path, results_json: str, name: str, target: Path) -> bool:
    """Put the stored report ``name`` at ``target`` when the stored results.json is
    ``results_json`` byte for byte and the report is, on the tool's record, made from it
    (:func:`~frp_assess.output_record.report_belongs`: a report is made from results.json
    alone, nothing to rebuild); returns whether it did."""
    old = out_dir / name
    try:
        if not report_belongs(out_dir, name):
            return False
        same = (out_dir / "results.json").read_bytes() == results_json.encode("utf-8")
        if not same or not old.is_file() or old.is_symlink():
            return False
        shutil.copyfile(old, target)
    except OSError:
        return False
    return True


def _is_plain_file_name(name: str) -> bool:
    return (
        bool(name)
        and not name.startswith(".")
        and "/" not in name
        and "\\" not in name
        and "\x00" not in name
        and name == plain(name)
        and len(name.encode("utf-8")) <= 200
    )


def build_pdf(results: AssessmentResult, path: Path) -> bool:
    """Build the PDF report if the report package is installed; returns whether it did.

    A report that cannot be laid out (a table too wide for the page: 100 records, a name of
    hundreds of characters) does not throw the analysis away: one warning line, no
    report.pdf, and the rest of the set is written (issue 25).
    """
    try:
        from frp_assess.report.pdf_document import build_report
    except ImportError:
        return False
    try:
        build_report(results, path)
    except (OSError, MemoryError):  # a full disk is not the report's fault: the set fails
        raise
    except Exception as exc:  # reportlab's LayoutError, a table's negative width, ...
        print(
            f"frp-assess: warning: report.pdf not written: the report could not be laid out "
            f"({_first_line(exc)}); the other results are complete",
            file=sys.stderr,
        )
        return False
    _font_warning(results)
    return True


def _font_warning(results: AssessmentResult) -> None:
    """One warning line naming the characters of the results the PDF cannot show as written
    (:func:`~frp_assess.report.font_coverage.font_gaps`)."""
    from frp_assess.report.font_coverage import font_gaps

    gaps = font_gaps(results)
    if gaps is not None:
        print(f"frp-assess: warning: {gaps}", file=sys.stderr)


def _first_line(exc: BaseException) -> str:
    """The first line of ``exc`` (its type when it has no text), plain, at most 160 chars."""
    return plain(str(exc).splitlines()[0] if str(exc) else type(exc).__name__)[:160]


def build_word(results: AssessmentResult, path: Path) -> bool:
    """Build the editable Word report (the PDF's document, in its language and with the
    project's Word template); returns whether it did.  As for the PDF, a report that cannot
    be made (python-docx missing, a template Word cannot read) is one warning line and no
    report.docx; the rest of the set is written."""
    try:
        from frp_assess.report.document import build_docx
    except ImportError as exc:
        report_warning("report.docx", f"python-docx is not installed: {exc}")
        return False
    try:
        build_docx(results, path)
    except (OSError, MemoryError):  # a full disk is not the report's fault: the set fails
        raise
    except Exception as exc:  # a template python-docx cannot read, ...
        report_warning("report.docx", str(exc).splitlines()[0] if str(exc) else type(exc).__name__)
        return False
    return True


def report_warning(name: str, reason: str) -> None:
    print(
        f"frp-assess: warning: {name} not written: {plain(reason)[:160]}; the other results "
        "are complete",
        file=sys.stderr,
    )


def export_folder_problem(directory: Path) -> str | None:
    """Why ``directory`` cannot receive an export (None: it can): the checks of
    ``frp-assess run --out`` (:func:`~frp_assess.output_set.check_out_dir`): a file or a
    device, a path under a file, not writable, a missing parent folder (only the export
    folder itself is created), a link named like one of the tool's files."""
    try:
        check_out_dir(Path(directory), key="export")
    except InputError as exc:
        return exc.message
    return None


def export_run(outcome: RunOutcome, directory: Path) -> list[Path]:
    """Write report.pdf, report.docx, results.json/.csv, spectra.csv and records/ of a
    finished run into ``directory``; returns the files and folders written.  ``directory`` is
    checked as ``run --out`` is (:func:`export_folder_problem`): it may be new, the folder
    that holds it must exist."""
    directory = Path(directory)
    check_out_dir(directory, key="export")  # the rules of `run --out`, missing parent included
    try:
        write_outputs(outcome.results, outcome.seismic, directory, pdf=True)
    except OSError as exc:
        raise InputError(f"cannot write into {directory}: {exc.strerror or exc}") from None
    names = [*REPORT_FILES, "results.json", "results.csv", "spectra.csv", "records"]
    return [directory / n for n in names if (directory / n).exists()]


def rebuild_report(results_dir: Path, out: Path | None = None, *, docx: bool = False) -> Path:
    """The PDF report of the stored run in ``results_dir`` (its results.json; no analysis is
    rerun), written to ``out`` (default ``results_dir/report.pdf``); returns the file.
    ``docx``: the editable Word report instead (default ``results_dir/report.docx``), in the
    same language (results.json ``report.language``).

    A results.json that breaks the report's contract is one located
    :class:`~frp_assess.errors.InputError` and nothing is written.  A report written into
    the results folder (report.pdf and report.docx are members of the run's output set) is
    made under the folder's lock, as `run` writes it: never beside results it was not made
    from, never over a report the tool did not write (:mod:`frp_assess.output_record`).
    """
    from frp_assess.report.document import load_results

    results_dir = Path(results_dir)
    if not results_dir.is_dir():
        load_results(results_dir)  # the one line of a folder that is not there, first
    default = results_dir / ("report.docx" if docx else "report.pdf")
    out = check_out_file(Path(out) if out is not None else default)
    other = ".pdf" if docx else ".docx"
    if out.suffix.lower() == other:  # a Word file named r.pdf opens nowhere
        raise InputError(
            f"a {'Word' if docx else 'PDF'} report cannot be named {out.name!r}; give a name "
            f"ending in {'.docx' if docx else '.pdf'}",
            key="--out",
        )
    if out.parent.resolve() != results_dir.resolve():
        return _build_report(results_dir, out, docx=docx)
    # into the results folder: under its lock, as `run` writes it, from the results.json read
    # under that lock (never a report older than the results beside it); a member of the
    # output set never over a file the tool did not write, and put on its record
    with FolderLock(results_dir, key="RESULTS_DIR"):
        if out.name in REPORT_FILES:
            refuse_foreign(results_dir, key="RESULTS_DIR", names=(out.name,))
        _build_report(results_dir, out, docx=docx)
        if out.name in REPORT_FILES:
            record_report(results_dir, out.name)
    return out


def _build_report(results_dir: Path, out: Path, *, docx: bool) -> Path:
    from frp_assess.report.document import (
        CONTRACT_ERRORS,
        build_docx,
        contract_error,
        load_results,
    )
    from frp_assess.report.pdf_document import build_report, build_story

    results = load_results(results_dir)  # InputError -> one line, exit 2
    try:
        if docx:
            build_docx(results, out)  # atomic: nothing written on an error
        else:
            build_report(results, out, story=build_story(results))
    except CONTRACT_ERRORS as exc:  # nothing written: both write atomically
        raise contract_error(exc, results_dir / "results.json") from None
    except (OSError, MemoryError, InputError):
        raise
    except Exception as exc:  # reportlab's LayoutError (a 100,000-character currency), ...
        raise InputError(
            f"{out.name} not written: the report could not be laid out ({_first_line(exc)}); "
            "a value of results.json is far from what a run writes",
            file=str(results_dir / "results.json"),
        ) from None
    if not docx:
        _font_warning(results)
    return out
