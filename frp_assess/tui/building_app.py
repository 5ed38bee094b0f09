"""The TUI of a building file (``walls:``): the list of its walls beside the tabs.

Selecting a wall shows it in today's tabs as the one-wall project the run builds for it;
what is typed goes back into the building's data where the key comes from
(:class:`~frp_assess.app.building_edit.BuildingDoc`): the wall's own keys into its item of
``walls:``, the shared blocks into the file's top level, for every wall.  ``ctrl+s`` saves
the building file, comments kept, rewriting only what changed.  ``ctrl+w`` goes to the list
of walls; on it ``a`` adds a wall, ``d`` duplicates the one highlighted, ``r`` renames it,
``delete`` removes it (names unique: the file's validation's rule and message).  The
Results tab opens on the building summary of the last ``frp-assess run``.  A one-wall
project opens in :class:`~frp_assess.tui.app.FrpAssessApp` as before.
"""

from __future__ import annotations

import copy
from collections.abc import Callable
from pathlib import Path
from typing import Any, ClassVar

from textual import on
from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.events import Mount
from textual.widgets import Input, OptionList

from frp_assess.app.assessment import default_out_dir
from frp_assess.app.building_edit import BuildingDoc, is_building
from frp_assess.app.building_summary_file import load_building_summary
from frp_assess.app.project import parse_yaml
from frp_assess.errors import InputError
from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.building_summary_view import BuildingSummaryView
from frp_assess.tui.core.session import yaml_path_problem
from frp_assess.tui.dialogs import NamePrompt
from frp_assess.tui.main_tabs import MainTabs
from frp_assess.tui.results_pane import ResultsPane
from frp_assess.tui.status_bar import StatusBar


class WallList(OptionList):
    """The building's walls by name; ``enter`` (or a click) shows the one highlighted."""

    DEFAULT_CSS = """
    WallList {
        dock: left;
        width: 28;
        height: 1fr;
        border: round $primary;
        border-title-align: left;
    }
    """
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("a", "app.add_wall", "Add wall"),
        Binding("d", "app.duplicate_wall", "Duplicate"),
        Binding("r", "app.rename_wall", "Rename"),
        Binding("delete", "app.remove_wall", "Remove"),
    ]

    def on_mount(self) -> None:
        self.border_title = "Walls"
        self.border_subtitle = "a d r del"


class BuildingApp(FrpAssessApp):
    """:class:`FrpAssessApp` editing a building file wall by wall; ``ctrl+w`` goes to the
    list of walls."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("ctrl+w", "focus_walls", "Walls", priority=True)
    ]

    def __init__(self, path: Path, text: str, *, jobs: int | None = None) -> None:
        super().__init__(path, jobs=jobs)
        self.file_text = text  #: the file's text as last opened or saved
        self.doc = BuildingDoc.from_text(text, str(path))

    def compose(self) -> ComposeResult:
        yield WallList(*self.doc.names(), id="wall-list")
        yield from super().compose()

    def on_mount(self, event: Mount | None = None) -> None:
        if event is not None:
            event.prevent_default()  # not FrpAssessApp.on_mount: it opens a one-wall project
        self.show_wall(0)
        self.show_summary()
        self.query_one(MainTabs).start()
        self.query_one("#f-wall-thickness-control", Input).focus()

    def show_summary(self) -> None:
        """The building summary of the last run of every wall (``OUT/results.json``) as the
        first view of the Results tab."""
        pane = self.query_one(ResultsPane)
        pane.query_one("#results-note").display = False  # "press ctrl+r": not for a building
        out_dir = default_out_dir(self.path) if self.path is not None else None
        summary, note = None, ""
        try:
            summary = load_building_summary(out_dir) if out_dir is not None else None
        except InputError as exc:
            note = str(exc)
        if summary is None and not note:
            note = f"No results yet: run the building with `frp-assess run {self.path}`."
        view = BuildingSummaryView(id="building-summary-view")
        pane.mount(view, before=0)
        view.call_after_refresh(view.show, summary, note)

    # --------------------------------------------------------------------- the walls
    @property
    def wall_list(self) -> WallList:
        return self.query_one(WallList)

    def show_wall(self, index: int) -> None:
        """Keep what is typed for the wall shown, then show wall ``index`` in the tabs."""
        if self.doc.shown:
            self.doc.store(self.form.collect())
        data, problem = self.doc.show(index, self.base_dir)
        self.form.populate(data)
        self.doc.shown = self.form.collect()  # the edits: what differs from this
        self.form.saved_data = copy.deepcopy(self.doc.shown)
        names = self.doc.names()
        self.wall_list.clear_options()
        self.wall_list.add_options(names)
        self.wall_list.highlighted = index
        self.sub_title = names[index]
        self.revalidate(force=True)
        if problem:
            self.notify(problem, severity="warning", timeout=8)

    @on(OptionList.OptionSelected, "#wall-list")
    def _wall_selected(self, event: OptionList.OptionSelected) -> None:
        if event.option_index != self.doc.current:
            self.show_wall(event.option_index)

    def action_focus_walls(self) -> None:
        self.wall_list.focus()

    def highlighted(self) -> int:
        index = self.wall_list.highlighted
        return self.doc.current if index is None else index

    def ask_name(self, title: str, value: str, change: Callable[[BuildingDoc, str], str]) -> None:
        """Ask for a wall's name and make ``change`` with it (its check: ``change`` on a
        copy of the building); then show the wall it names."""

        def check(name: str) -> str:
            return change(copy.deepcopy(self.doc), name)

        def done(name: str | None) -> None:
            if name is not None:
                self.doc.store(self.form.collect())
                change(self.doc, name)
                self.show_wall(self.doc.names().index(name))

        hint = "unique in the building (it names its results folder walls/NAME/)"
        self.push_screen(NamePrompt(title, value, hint, check), done)

    def action_add_wall(self) -> None:
        self.ask_name("Add a wall (a copy of this one's wall block)", "", BuildingDoc.add)

    def action_duplicate_wall(self) -> None:
        i = self.highlighted()
        name = self.doc.names()[i]
        self.ask_name(
            f"Duplicate {name!r} as",
            f"{name} (2)",
            lambda doc, new: doc.duplicate(i, new),
        )

    def action_rename_wall(self) -> None:
        i = self.highlighted()
        name = self.doc.names()[i]
        self.ask_name(f"Rename {name!r}", name, lambda doc, new: doc.rename(i, new))

    def action_remove_wall(self) -> None:
        i = self.highlighted()
        self.doc.store(self.form.collect())
        name = self.doc.names()[i]
        problem = self.doc.remove(i)
        if problem:
            self.notify(problem, title="Not removed", severity="error")
            return
        self.doc.shown = {}  # its edits are gone with it
        self.show_wall(min(i, len(self.doc.names()) - 1))
        self.notify(f"removed {name!r} (not saved yet)", title="Removed")

    # ------------------------------------------------------------- state and saving
    def modified(self) -> bool:
        return self.doc.modified(self.form.collect())

    def update_status(self, data: dict[str, Any] | None = None) -> None:
        status = self.query_one(StatusBar)
        status.show_state(self.path, self.modified(), self.problems, self.running)

    def save_to(self, path: Path) -> bool:
        """Save the building (every wall, as edited) to ``path``, comments kept."""
        problem = yaml_path_problem(Path(path))
        if self.project is None or problem:
            first = problem or (self.problems[0] if self.problems else "not valid")
            self.notify(f"cannot save: {first}", title="Not saved", severity="error")
            return False
        self.doc.store(self.form.collect())
        try:
            text = self.doc.save(Path(path), self.file_text)
        except InputError as exc:
            self.notify(f"cannot save: {exc}", title="Not saved", severity="error")
            return False
        self.file_text = text
        self.path = Path(path).absolute()
        self.base_dir = self.path.parent
        self.revalidate(force=True)
        self.update_status()
        self.notify(f"saved {path} (only the changes; its comments kept)", title="Saved")
        return True

    def action_run(self) -> None:
        self.notify(
            f"run the building with `frp-assess run {self.path}` (every wall; one wall: "
            "--wall NAME); its summary then shows in the Results tab",
            title="Run",
            severity="warning",
            timeout=8,
        )


def open_app(path: Path | None, *, jobs: int | None = None) -> FrpAssessApp:
    """The app for ``path``: :class:`BuildingApp` for a building file, else the one-wall
    :class:`FrpAssessApp`."""
    if path is not None and path.is_file():
        text = path.read_text(encoding="utf-8")
        try:
            data, _ = parse_yaml(text, str(path))
        except InputError:
            data = None
        if is_building(data):
            return BuildingApp(path, text, jobs=jobs)
    return FrpAssessApp(path, jobs=jobs)


def run_tui(path: Path | None = None, *, jobs: int | None = None) -> int:
    """Run the application for ``path`` (:func:`open_app`), blocking; the exit code."""
    open_app(path, jobs=jobs).run()
    return 0


__all__ = ["BuildingApp", "FrpAssessApp", "WallList", "open_app", "run_tui"]
