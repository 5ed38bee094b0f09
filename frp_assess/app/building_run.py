"""Assess a building: every wall of a building file (``walls:``) as a one-wall project.

Each wall is run by :func:`~frp_assess.app.assessment.run_assessment` into its own results
folder ``OUT/walls/<slug>/`` (its results.json, CSV, records and report, exactly as a one-wall
project of that wall writes them) with its own IDA cache ``OUT/walls/<slug>/.cache``: the
cache key is the wall's model and the record, so an edit of one wall recomputes that wall's
IDAs only.  The records are prepared once and shared by the walls (the ``seismic`` block is
the building's).  The walls run one after the other, each with the parallel IDA runner (which
fills every core), or, given an executor (``run --executor dask``), with each wall's IDAs on
that executor (the study's: :class:`~frp_assess.study.executors.DaskExecutor`), the same
numbers on the same inputs.  Then ``OUT/`` receives the building's output set, written by the rules
of :mod:`frp_assess.output_set` (checked first, locked, staged and swapped in, never over a
file the tool did not write): results.json (:class:`~frp_assess.results.building_summary.
BuildingResults`), results.csv (one row per wall and case) and the building report
report.pdf / report.docx, which opens with the summary.
"""

from __future__ import annotations

import hashlib
import json
import os
import sys
import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from frp_assess import __version__
from frp_assess.app.assessment import Progress, RunStats, run_assessment, run_date
from frp_assess.app.rerun import file_hash, referenced_paths, unchanged_folder, write_sidecar
from frp_assess.assess.from_project import as_built_warnings, inputs_of_loaded
from frp_assess.assess.inputs import AssessmentInputs
from frp_assess.assess.seismic import SeismicInput, build_records
from frp_assess.config.loader import project_data
from frp_assess.config.problems import problems_of, raise_all
from frp_assess.config.walls_file import LoadedBuilding, LoadedWall, load_building
from frp_assess.errors import InputError
from frp_assess.io_utils import atomic_write_text, read_results_text
from frp_assess.output_set import (
    FolderLock,
    check_out_dir,
    refuse_inputs_inside,
    staged_set,
)
from frp_assess.results.building_csv import building_csv
from frp_assess.results.building_summary import BuildingResults, building_results
from frp_assess.results.json_io import from_json, to_json
from frp_assess.results.model import AssessmentResult
from frp_assess.results.run_inputs import ProjectInfo
from frp_assess.study.run import Executor, executor_batch

__all__ = [
    "WALLS_DIR",
    "BuildingInputs",
    "BuildingRun",
    "WallInputs",
    "WallOutcome",
    "check_building_out",
    "load_building_inputs",
    "run_building",
]

#: the folder of the walls' results inside a building's results folder
WALLS_DIR = "walls"


def _print_warning(line: str) -> None:
    print(f"frp-assess: warning: {line}", file=sys.stderr)


@dataclass(frozen=True)
class WallInputs:
    """A wall of the building and its assessment inputs (those of its one-wall project)."""

    wall: LoadedWall
    inputs: AssessmentInputs

    @property
    def name(self) -> str:
        return self.wall.name

    @property
    def folder(self) -> str:
        """Its results folder, relative to the building's: ``walls/<slug>``."""
        return f"{WALLS_DIR}/{self.wall.entry.slug}"


@dataclass(frozen=True)
class BuildingInputs:
    """A validated building file and the inputs of the walls to run (all, or ``--wall``)."""

    building: LoadedBuilding
    walls: tuple[WallInputs, ...]
    complete: bool  #: every wall of the file is to be run (no ``--wall``)


def load_building_inputs(
    path: str | Path,
    *,
    only: str | None = None,
    warn: Callable[[str], None] | None = _print_warning,
) -> BuildingInputs:
    """Load and validate a building file and map each wall to its inputs (as
    :func:`~frp_assess.assess.from_project.load_inputs` maps a one-wall file); every problem of
    every wall is one line located in the file (``walls[2].height``).  ``only``: the name of
    the one wall to run (an unknown name is one line listing the names)."""
    loaded = load_building(path)
    chosen = loaded.walls if only is None else (loaded.wall(only),)
    problems: list[InputError] = []
    walls: list[WallInputs] = []
    warnings: list[str] = list(loaded.warnings)
    for wall in chosen:
        try:
            inputs = inputs_of_loaded(wall.loaded, warn=None)
        except InputError as exc:
            problems += [wall.entry.relocated(p) for p in problems_of(exc)]
            continue
        warnings += [str(wall.entry.relocated(e)) for e in as_built_warnings(wall.loaded, inputs)]
        walls.append(WallInputs(wall, inputs))
    raise_all(list({str(p): p for p in problems}.values()))  # a shared block's problem once
    if warn is not None:
        for line in dict.fromkeys(warnings):
            warn(line)
    return BuildingInputs(loaded, tuple(walls), only is None)


def check_building_out(out_dir: Path, building: BuildingInputs, inputs: Sequence[Path]) -> Path:
    """``out_dir`` and each wall's folder in it, checked as ``run --out`` checks a results
    folder (:func:`~frp_assess.output_set.check_out_dir`; nothing of the user's replaced),
    before any work; ``inputs``: the project file and its record files, which must not lie in
    a folder a run replaces."""
    out_dir = check_out_dir(Path(out_dir))
    refuse_inputs_inside(out_dir, inputs)
    walls = out_dir / WALLS_DIR
    if os.path.lexists(walls) and (walls.is_symlink() or not walls.is_dir()):
        raise InputError(
            f"{walls} is not a folder frp-assess made (a file or a link); the walls' results go "
            "there: remove it or choose another folder",
            key="--out",
        )
    if walls.is_dir():
        for w in building.walls:
            check_out_dir(out_dir / w.folder)
            refuse_inputs_inside(out_dir / w.folder, inputs)
    return out_dir


#: wall_started(index, count, wall): a wall's run begins (index 0-based)
WallStarted = Callable[[int, int, WallInputs], None]


@dataclass(frozen=True)
class WallOutcome:
    """One wall's finished run."""

    wall: WallInputs
    results: AssessmentResult
    stats: RunStats
    #: the wall's folder held the results of its inputs as they are: read, nothing run
    unchanged: bool = False


@dataclass(frozen=True)
class BuildingRun:
    """A finished building run: every wall's outcome and (every wall run) the building's
    results."""

    walls: tuple[WallOutcome, ...]
    building: BuildingResults | None  #: None when one wall was run (``--wall``)
    records: SeismicInput  #: the records the walls shared
    out_dir: Path

    @property
    def computed(self) -> int:
        """(case, record) IDAs computed, over the walls."""
        return sum(w.stats.computed for w in self.walls)

    @property
    def reused(self) -> int:
        """(case, record) IDAs read from the walls' caches."""
        return sum(w.stats.reused for w in self.walls)


def _records_key(inputs: AssessmentInputs) -> str:
    """What a wall's records are made from (equal keys: the same records)."""
    return repr((inputs.records, inputs.spectrum, inputs.t1, inputs.scale_to_spectrum, inputs.site))


def shared_records() -> Callable[[AssessmentInputs], SeismicInput]:
    """The records of a wall, prepared once for every wall with the same seismic input."""
    made: dict[str, SeismicInput] = {}

    def records_of(inputs: AssessmentInputs) -> SeismicInput:
        key = _records_key(inputs)
        if key not in made:
            made[key] = build_records(inputs)
        return made[key]

    return records_of


def wall_digest(wall: WallInputs, input_file: str) -> str:
    """``"sha256:<hex>"`` of what a wall's results depend on (as
    :func:`~frp_assess.app.rerun.inputs_digest` for a one-wall file): its one-wall project
    (every value), the bytes of the files it references, the building file's name, the
    frp-assess version and the integration options of its inputs (``--rtol``, ``--verify``)."""
    loaded = wall.wall.loaded
    content = {
        "frp_assess": __version__,
        "input_file": input_file,
        "project": project_data(loaded.project),
        "files": [[f, file_hash(loaded.base_dir / f)] for f in referenced_paths(loaded.project)],
        "options": {"rtol": wall.inputs.model.tolerance, "verify": wall.inputs.verify},
    }
    text = json.dumps(content, sort_keys=True, ensure_ascii=True, separators=(",", ":"))
    return "sha256:" + hashlib.sha256(text.encode("ascii")).hexdigest()


def _stored(wall: WallInputs, folder: Path, digest: str, pdf: bool) -> AssessmentResult | None:
    """The wall's stored results when its folder holds the run of its inputs as they are
    (:func:`~frp_assess.app.rerun.unchanged_folder`), else None."""
    if unchanged_folder(folder, digest, pdf=pdf) is None:
        return None
    stored = folder / "results.json"
    try:
        return from_json(read_results_text(stored), file=str(stored))
    except InputError:
        return None


def run_building(
    building: BuildingInputs,
    out_dir: Path,
    *,
    jobs: int | None = None,
    progress: Progress | None = None,
    wall_started: WallStarted | None = None,
    records_ready: Callable[[SeismicInput], None] | None = None,
    cancel: threading.Event | None = None,
    created: str | None = None,
    pdf: bool = True,
    reuse: bool = True,
    executor: Executor | None = None,
) -> BuildingRun:
    """Run every wall of ``building`` into ``out_dir/walls/<slug>/`` and, when every wall of
    the file was run, write the building's output set in ``out_dir``.  ``progress`` is each
    wall's (:func:`~frp_assess.app.assessment.run_assessment`), ``wall_started`` says which
    wall it is about; ``records_ready`` receives the shared records once they are made.

    ``reuse``: a wall whose folder holds the complete run of its inputs as they are now (the
    digest of :func:`wall_digest` in its sidecar, as an unchanged one-wall ``run``) is read,
    not run again; a changed wall runs with its IDA cache.

    ``executor``: where the walls' missing IDAs run (a :class:`~frp_assess.study.executors.
    DaskExecutor`; default the local threads of ``jobs``); the caller closes it."""
    created = created or run_date()
    out_dir = Path(out_dir)
    records_of = shared_records()
    outcomes: list[WallOutcome] = []
    records: SeismicInput | None = None
    batch = None if executor is None else executor_batch(executor)
    with FolderLock(out_dir):
        (out_dir / WALLS_DIR).mkdir(exist_ok=True)
        for i, wall in enumerate(building.walls):
            seismic = records_of(wall.inputs)
            if records is None:
                records = seismic
                if records_ready is not None:
                    records_ready(seismic)
            if wall_started is not None:
                wall_started(i, len(building.walls), wall)
            folder = out_dir / wall.folder
            digest = wall_digest(wall, building.building.path.name)
            stored = _stored(wall, folder, digest, pdf) if reuse else None
            if stored is not None:
                outcomes.append(WallOutcome(wall, stored, RunStats(0, 0, folder), True))
                continue
            results, stats = run_assessment(
                wall.inputs,
                folder,
                jobs=jobs,
                progress=progress,
                cancel=cancel,
                seismic=seismic,
                created=created,
                pdf=pdf,
                inputs_digest=digest,
                batch=batch,
            )
            files = referenced_paths(wall.wall.loaded.project)
            write_sidecar(folder, digest, results.created, files, pdf=pdf)
            outcomes.append(WallOutcome(wall, results, stats))
        summary = None
        if building.complete:
            summary = building_results(
                _building_info(building.building, outcomes[0].results),
                building.building.path.name,
                [(o.wall.name, o.wall.folder, o.results) for o in outcomes],
                created=created,
            )
            write_building_outputs(summary, outcomes, out_dir, pdf=pdf)
    assert records is not None  # a building has at least one wall
    return BuildingRun(tuple(outcomes), summary, records, out_dir)


def _building_info(building: LoadedBuilding, first: AssessmentResult) -> ProjectInfo:
    """The building's identification: its name, and the shared project block's other texts."""
    p = first.project
    return ProjectInfo(name=building.name, location=p.location, engineer=p.engineer, notes=p.notes)


def write_building_outputs(
    summary: BuildingResults, walls: Sequence[WallOutcome], out_dir: Path, *, pdf: bool
) -> None:
    """The building's results.json, results.csv and (``pdf``) report.pdf and report.docx,
    as one set (:func:`~frp_assess.output_set.staged_set`, under the folder's lock)."""
    from frp_assess.app.building_report import build_building_docx, build_building_pdf

    rows = [(w.wall.name, w.wall.folder, w.results) for w in walls]
    with FolderLock(out_dir), staged_set(out_dir) as staging:
        atomic_write_text(staging / "results.csv", building_csv(rows))
        atomic_write_text(staging / "results.json", to_json(summary))
        if pdf:
            report = walls[0].results.report
            language = report.language if report is not None else "en"
            template = report.template if report is not None else None
            build_building_pdf(summary, staging / "report.pdf", language)
            build_building_docx(summary, staging / "report.docx", language, template)
