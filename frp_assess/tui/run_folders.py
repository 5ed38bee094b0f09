"""Where the TUI writes results: the results on disk next to a project file always belong to
that file as saved.

- A run of the project as saved writes into ``<stem>-results/`` next to it, as
  ``frp-assess run`` does.
- A run of unsaved edits writes into a scratch folder of its own (a new temporary folder,
  one per session, so that its cache serves the next run of edits; removed at quit), never
  into
  ``<stem>-results/``: the report there would describe a wall the file does not hold (after
  "Discard", report.pdf said B = 0.30 m while the file said 0.25 m).  The run log and the
  Results tab say so.
- The export dialog proposes ``<stem>-export/`` next to the project file, never a results
  folder itself (exporting a run into its own folder rewrites the same files), and refuses the
  saved project's results folder for the results of unsaved edits.
"""

from __future__ import annotations

import shutil
import tempfile
from functools import partial
from pathlib import Path

from frp_assess.app.assessment import default_out_dir
from frp_assess.app.report import export_folder_problem
from frp_assess.tui.dialogs import PathPrompt

#: the name of a scratch folder starts so (:func:`remove_scratch` removes no other folder)
SCRATCH_PREFIX = "frp-assess-unsaved-edits-"


def scratch_folder() -> Path:
    """A new folder for the runs of unsaved edits (under the system's temporary folder)."""
    return Path(tempfile.mkdtemp(prefix=SCRATCH_PREFIX))


def remove_scratch(folder: Path) -> None:
    """Remove a scratch folder of :func:`scratch_folder` (at quit: its results were of
    edits never saved; ``ctrl+e`` exports them before)."""
    if folder.name.startswith(SCRATCH_PREFIX):
        shutil.rmtree(folder, ignore_errors=True)


def unsaved_note(scratch: Path, project_file: Path) -> str:
    """The run log's line when unsaved edits run (in ``scratch``)."""
    return (
        f"the project has unsaved edits: they run in the scratch folder {scratch}/, not in "
        f"{default_out_dir(project_file)}/ (which keeps the results of the file as saved; "
        "save with ctrl+s and run again to put them there)"
    )


def export_default(project_file: Path | None, out_dir: Path) -> Path:
    """The folder the export dialog proposes: ``<stem>-export/`` next to the project file
    (next to the results folder without one), never the results folder itself."""
    if project_file is not None:
        return project_file.with_name(f"{project_file.stem}-export")
    return out_dir.with_name(f"{out_dir.name}-export")


def export_problem(directory: Path, project_file: Path | None, scratch: bool) -> str | None:
    """Why ``directory`` cannot receive this export (None: it can): the checks of
    ``run --out`` (:func:`~frp_assess.app.report.export_folder_problem`), and, for results
    of unsaved edits (``scratch``), not the saved project's results folder."""
    if scratch and project_file is not None:
        saved = default_out_dir(project_file).resolve()
        if Path(directory).expanduser().resolve() == saved:
            return (
                f"{saved} holds the results of the project file as saved; these are of "
                "unsaved edits: choose another folder"
            )
    return export_folder_problem(directory)


def export_prompt(project_file: Path | None, out_dir: Path, scratch: bool) -> PathPrompt:
    """The export dialog of the run shown (its results in ``out_dir``; ``scratch``: a run of
    unsaved edits): :func:`export_default` proposed, :func:`export_problem` checked."""
    return PathPrompt(
        "Export the reports (PDF and Word) and the results into the folder",
        str(export_default(project_file, out_dir)),
        "report.pdf, report.docx, results.json, results.csv, spectra.csv, records/",
        partial(export_problem, project_file=project_file, scratch=scratch),
    )


def exported(files: list[Path]) -> tuple[str, str]:
    """(the names of the files exported, the folder they are in) for the run log."""
    pdf = next((f for f in files if f.name == "report.pdf"), None)
    where = pdf.parent if pdf else (files[0].parent if files else "")
    return ", ".join(f.name for f in files), str(where)
