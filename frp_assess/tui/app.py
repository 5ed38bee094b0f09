"""`frp-assess tui`: the Textual application.

The app composes the panes (one per tab, each in its own module), binds the keys and routes
the messages between them.  The editing state is :class:`~frp_assess.tui.project_form.
ProjectForm`; the long operations (assessment, last results, export) run in worker threads
(:mod:`frp_assess.tui.jobs`) through the headless session (:mod:`frp_assess.tui.core`).
"""

from __future__ import annotations

import threading
from functools import partial
from pathlib import Path
from typing import Any, ClassVar

from rich.text import Text
from textual import on
from textual.app import ComposeResult, SystemCommand
from textual.binding import Binding, BindingType
from textual.screen import Screen
from textual.widget import Widget
from textual.widgets import Button, Input, Select, TabbedContent, TabPane

from frp_assess.app.assessment import UNREINFORCED, default_out_dir
from frp_assess.app.rerun import project_changed
from frp_assess.config.schema import Project
from frp_assess.errors import InputError
from frp_assess.numbers import numerical_check_text, recommendation_text
from frp_assess.tui import run_folders as folders
from frp_assess.tui.analysis_pane import AnalysisPane
from frp_assess.tui.core.editor_state import Problem
from frp_assess.tui.core.opening import opening_data
from frp_assess.tui.core.project_info import record_count
from frp_assess.tui.core.session import RunOutcome, save_project, yaml_path_problem
from frp_assess.tui.core.tabs import TABS, tab_of, tab_title
from frp_assess.tui.core.text import printable
from frp_assess.tui.dialogs import ConfirmQuit, PathPrompt
from frp_assess.tui.fields import FieldRow
from frp_assess.tui.help import HelpScreen
from frp_assess.tui.help_line import HelpLine
from frp_assess.tui.history_pane import HistoryPane
from frp_assess.tui.item_editor import ItemEditor
from frp_assess.tui.jobs import export_job, previous_results_job, run_assessment_job
from frp_assess.tui.keybar import KeyBar
from frp_assess.tui.main_tabs import MainTabs
from frp_assess.tui.materials_pane import MaterialsPane
from frp_assess.tui.pane_lookup import PaneLookupApp
from frp_assess.tui.project_form import ProjectForm
from frp_assess.tui.ranking_table import RankingTable
from frp_assess.tui.records_pane import RecordsPane
from frp_assess.tui.results_pane import STALE_TITLE, ResultsPane
from frp_assess.tui.retrofits_pane import RetrofitsPane
from frp_assess.tui.run_panel import RunPanel
from frp_assess.tui.site_pane import SitePane
from frp_assess.tui.status_bar import StatusBar
from frp_assess.tui.wall_pane import WallPane
from frp_assess.tui.worker_messages import ExportDone, PreviousLoaded, RunDone, RunProgress


class FrpAssessApp(PaneLookupApp):
    """Edit, run and read an FRP retrofit assessment."""

    CSS_PATH = "app.tcss"
    TITLE = "frp-assess"
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("ctrl+s", "save", "Save", priority=True),
        Binding("ctrl+r", "run", "Run", priority=True),
        Binding("escape", "cancel_run", "Cancel"),
        Binding("ctrl+c", "cancel_run", "Cancel run", show=False, priority=True),
        Binding("ctrl+e", "export", "Export", priority=True),
        Binding("f1,question_mark", "help", "Help", key_display="?/F1"),
        Binding("f2", "tab(0)", "Tabs", key_display="F2…F10", priority=True),
        *[Binding(f"f{i + 2}", f"tab({i})", show=False, priority=True) for i in range(1, 9)],
        *[Binding(f"alt+{i + 1}", f"tab({i})", show=False, priority=True) for i in range(9)],
        Binding("ctrl+pagedown", "next_tab(1)", show=False, priority=True),
        Binding("ctrl+pageup", "next_tab(-1)", show=False, priority=True),
        Binding("q", "quit_app", "Quit", show=False),
        Binding("ctrl+q", "quit_app", "Quit", priority=True),
    ]

    def __init__(
        self,
        path: Path | None = None,
        *,
        text: str | None = None,
        jobs: int | None = None,
    ) -> None:
        """Open ``path`` (a project file), or a new project from ``text`` (the template).

        ``path`` may name a file that does not exist yet: the template is then saved there.
        """
        super().__init__()
        self.path = None if path is None else Path(path).absolute()
        self.jobs = jobs
        self.base_dir = (self.path.parent if self.path else Path.cwd()).resolve()
        self.initial_text = text
        self.form = ProjectForm(self)
        self.outcome: RunOutcome | None = None
        self.cancel_event: threading.Event | None = None
        self.running = False
        self.pending_run = False  #: run once the new project is saved
        self.quitting = False
        self.previous_cancel = threading.Event()  #: stops rebuilding the last results
        self.scratch: Path | None = None  #: where unsaved edits run (tui/run_folders.py)

    # ------------------------------------------------------------------------ layout
    def compose(self) -> ComposeResult:
        panes: tuple[Widget, ...] = (
            WallPane(),
            SitePane(),
            RecordsPane(),
            MaterialsPane(classes="pane"),
            RetrofitsPane(classes="pane"),
            AnalysisPane(),
            RunPanel(id="run-panel"),
            ResultsPane(id="results-pane"),
            HistoryPane(id="history-pane"),
        )
        with MainTabs(id="tabs"):
            for (tab_id, title), pane in zip(TABS, panes, strict=True):
                with TabPane(title, id=tab_id):
                    yield pane
        yield HelpLine("", id="help-line")
        yield StatusBar("", id="status")
        yield KeyBar(id="keybar")

    def get_system_commands(self, screen: Screen) -> Any:
        yield from super().get_system_commands(screen)
        yield SystemCommand("Save as…", "Save the project to another file", self.action_save_as)
        yield SystemCommand("Run", "Run the assessment (ctrl+r)", self.action_run)
        yield SystemCommand("Export", "Export the PDF report and results", self.action_export)
        yield SystemCommand("Help", "Keys and usage (?)", self.action_help)

    def notify(self, message: str, *, title: str = "", **kw: Any) -> None:
        """A notification; its text is shown as plain text (names may hold markup or
        control characters), never as markup."""
        kw["markup"] = False
        super().notify(printable(message, newlines=True), title=printable(title), **kw)

    # ------------------------------------------------------------- the project edited
    @property
    def project(self) -> Project | None:
        """The project as typed, if valid."""
        return self.form.project

    @property
    def problems(self) -> list[Problem]:
        """What is wrong with the project as typed (empty: valid)."""
        return self.form.problems

    @property
    def rows(self) -> list[FieldRow]:
        """The fields of the project (not those of the tables' forms)."""
        return self.form.rows

    def modified(self) -> bool:
        """Whether the fields differ from the file as last opened or saved."""
        return self.form.modified()

    def revalidate(self, force: bool = False) -> None:
        """Validate what is typed and show the outcome (nothing redone if unchanged)."""
        data = self.form.revalidate(self.base_dir, force)
        if data is not None:
            self.update_status(data)

    def update_status(self, data: dict[str, Any] | None = None) -> None:
        """The status line, and whether the results shown are of the project as it is."""
        modified = self.form.modified(data)
        self.query_one(StatusBar).show_state(self.path, modified, self.problems, self.running)
        if self.outcome is not None:
            stale = self.project is None or self.project != self.outcome.project
            self.query_one(ResultsPane).mark_stale(stale, self.file_changed(self.outcome))

    def file_changed(self, outcome: RunOutcome) -> bool:
        """The project file (or a record file) changed since the run shown: its digest is not
        the results' (frp_assess/app/rerun.py)."""
        digest = outcome.results.inputs_digest
        changed = project_changed(self.path, outcome.project, digest)
        tab = self.query_one("#tabs", TabbedContent).get_tab("tab-results")
        tab.label = STALE_TITLE if changed else tab_title("tab-results")
        return changed

    # ---------------------------------------------------------------------- opening
    def on_mount(self) -> None:
        data, message = opening_data(self.path, self.initial_text, self.base_dir)
        self.form.populate(data)
        self.form.saved_data = self.form.collect()
        if self.path is not None and not self.path.exists():
            self.form.saved_data = None  # a new file: not saved yet
        self.revalidate()
        if message:
            self.notify(message, severity="warning", timeout=8)
        self.query_one(MainTabs).start()  # the fields of the other tabs: when first shown
        self.query_one("#f-wall-thickness-control", Input).focus()
        if self.path is not None and self.project is not None and not self.problems:
            out_dir = default_out_dir(self.path)
            if (out_dir / "results.json").is_file():
                job = partial(
                    previous_results_job,
                    self.post_message,
                    self.project,
                    self.base_dir,
                    self.path,  # the project is this file's content: it was just read
                    out_dir,
                    self.previous_cancel,
                    self.jobs,
                )
                self.run_worker(
                    job, thread=True, exclusive=True, group="previous", exit_on_error=False
                )

    @on(PreviousLoaded)
    def _previous_loaded(self, message: PreviousLoaded) -> None:
        panel = self.pane(RunPanel)
        if self.running or self.outcome is not None or self.path is None or panel is None:
            return
        out_dir = default_out_dir(self.path)
        o = message.outcome
        if o is None:
            why = f" ({message.error})" if message.error else ""
            panel.log_line(
                f"the results in {out_dir}/ are not those of the project as it is{why}: "
                "ctrl+r runs it"
            )
            return
        panel.log_line(
            f"results of the run of {o.results.created} shown ({out_dir}/); "
            f"recommended: {recommendation_text(o.results)}"
        )
        self.show_outcome(o)

    def show_outcome(self, outcome: RunOutcome) -> None:
        """Show the results of a run in the Results and Time history tabs (once its views exist)."""
        pane = self.query_one(ResultsPane)
        if not pane.when_ready(partial(self.show_outcome, outcome)):
            return
        self.outcome = outcome
        stale = self.project != outcome.project
        changed = self.file_changed(outcome)
        pane.show(outcome.results, str(outcome.out_dir), stale, changed, self.is_scratch(outcome))
        self.query_one(HistoryPane).show_outcome(outcome)
        self.update_status()

    # ----------------------------------------------------------------------- editing
    @on(Input.Changed)
    @on(Select.Changed)
    def _field_changed(self, event: Input.Changed | Select.Changed) -> None:
        row = next((a for a in event.control.ancestors if isinstance(a, FieldRow)), None)
        if row is not None and not self.closing:
            self.form.choose_variant(row)
            self.revalidate()

    @on(ItemEditor.Edited)
    def _items_edited(self, event: ItemEditor.Edited) -> None:
        if not self.closing:
            self.revalidate()

    def on_descendant_focus(self, event: Any) -> None:
        if (line := self.pane(HelpLine)) is not None:
            line.show_for(event.widget)

    # ------------------------------------------------------------------------ tabs
    def action_tab(self, index: int) -> None:
        if 0 <= index < len(TABS):
            self.show_tab(TABS[index][0])

    def action_next_tab(self, step: int) -> None:
        self.query_one(MainTabs).step(step)

    def show_tab(self, tab_id: str) -> None:
        """Show a tab and put the focus on its first field (never on a hidden one)."""
        self.query_one(MainTabs).show(tab_id)

    @on(TabbedContent.TabActivated, "#tabs")
    def _tab_activated(self, event: TabbedContent.TabActivated) -> None:
        if event.pane.id == "tab-history" and (history := self.pane(HistoryPane)) is not None:
            history.refresh_if_needed()

    @on(RankingTable.CaseChosen)
    def _case_chosen(self, message: RankingTable.CaseChosen) -> None:
        if (history := self.pane(HistoryPane)) is not None:
            history.set_case(message.index)

    def action_help(self) -> None:
        if not isinstance(self.screen, HelpScreen):
            self.push_screen(HelpScreen())

    # ------------------------------------------------------------------------- save
    def action_save(self) -> None:
        if self.path is None:
            self.action_save_as()
            return
        self.save_to(self.path)

    def action_save_as(self, then_run: bool = False) -> None:
        default = str(self.path) if self.path else str(Path.cwd() / "wall.yaml")

        def done(path: Path | None) -> None:
            if path is None:
                self.pending_run = False
                return
            if self.save_to(path) and self.pending_run:
                self.pending_run = False
                self.action_run()

        self.pending_run = then_run
        self.push_screen(
            PathPrompt(
                "Save the project as",
                default,
                "a .yaml file; relative record paths are read from its folder",
                yaml_path_problem,
            ),
            done,
        )

    def save_to(self, path: Path) -> bool:
        """Save the project to ``path`` (keeping the comments of the file opened)."""
        if self.project is None:
            first = self.problems[0] if self.problems else None
            self.notify(
                f"cannot save: {first}" if first else "cannot save: the project is not valid",
                title="Not saved",
                severity="error",
            )
            return False
        opened = self.path if self.path is not None and self.path.is_file() else None
        try:
            kept = save_project(self.project, path, opened_from=opened)
        except InputError as exc:
            self.notify(str(exc), title="Not saved", severity="error")
            return False
        self.path = Path(path).absolute()
        self.base_dir = self.path.parent  # relative record paths are read from there now
        self.form.saved_data = self.form.collect()
        self.revalidate(force=True)
        how = "only the changes; its comments kept" if kept else "the whole project"
        self.notify(f"saved {path} ({how})", title="Saved")
        return True

    # -------------------------------------------------------------------------- run
    def is_scratch(self, outcome: RunOutcome) -> bool:
        """The run was of unsaved edits, in the scratch folder (tui/run_folders.py)."""
        return self.scratch is not None and Path(outcome.out_dir) == self.scratch

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        return self.running if action == "cancel_run" else True

    def action_run(self) -> None:
        panel = self.query_one(RunPanel)
        if self.running:
            self.notify("a run is already in progress (esc cancels it)")
            return
        self.show_tab("tab-run")
        if self.problems or self.project is None:
            p = self.problems[0] if self.problems else "the project is not valid"
            tab = tab_title(tab_of(p.target)) if isinstance(p, Problem) else ""
            panel.log_line(f"cannot run: {p} (fix it in the {tab} tab)", "red")
            panel.set_state(Text("cannot run: fix the problems first", style="bold red"))
            return
        if self.path is None:
            panel.log_line("save the project first: the results go next to it")
            self.action_save_as(then_run=True)
            return
        project = self.project
        out_dir = default_out_dir(self.path)
        names = [UNREINFORCED, *(str(o.name) for o in project.expand_interventions())]
        saved = None if self.modified() else self.path  # the digest: only of what the file holds
        if saved is None:  # the saved file's results folder holds only the saved file's results
            self.scratch = out_dir = self.scratch or folders.scratch_folder()
            panel.log_line(folders.unsaved_note(out_dir, self.path), "yellow")
        panel.start(names, record_count(project), str(out_dir))
        self.cancel_event = threading.Event()
        self.running = True
        self.update_status()
        job = partial(
            run_assessment_job,
            self.post_message,
            project,
            self.base_dir,
            self.path.name,
            out_dir,
            self.cancel_event,
            self.jobs,
            saved,
        )
        self.run_worker(job, thread=True, exclusive=True, group="run", exit_on_error=False)

    @on(RunProgress)
    def _run_progress(self, message: RunProgress) -> None:
        if (panel := self.pane(RunPanel)) is not None:
            panel.show_event(message.event)

    @on(RunDone)
    def _run_done(self, message: RunDone) -> None:
        self.running = False
        self.cancel_event = None
        if (panel := self.pane(RunPanel)) is None:
            return
        if message.status == "done" and message.outcome is not None:
            o = message.outcome
            panel.finish(
                "done",
                f"{o.stats.computed} IDAs computed, {o.stats.reused} reused from the cache; "
                f"recommended: {recommendation_text(o.results)}; results, report.pdf and "
                f"report.docx in {o.out_dir}/"
                + (f"\n{check}" if (check := numerical_check_text(o.results)) else ""),
            )
            self.show_outcome(o)
            self.notify("run finished: see the Results tab (F9)", title="Done")
        else:
            panel.finish(message.status, message.message)
            if message.status == "error":
                self.notify(message.message, title="Run failed", severity="error")
        self.update_status()
        self.refresh_bindings()

    def action_cancel_run(self) -> None:
        if self.running and self.cancel_event is not None:
            self.cancel_event.set()
            self.query_one(RunPanel).set_state(Text("cancelling…", style="bold yellow"))

    @on(Button.Pressed, "#run-button")
    def _run_pressed(self) -> None:
        self.action_run()

    @on(Button.Pressed, "#cancel-button")
    def _cancel_pressed(self) -> None:
        self.action_cancel_run()

    # ----------------------------------------------------------------------- export
    def action_export(self) -> None:
        if self.outcome is None:
            self.notify(
                "nothing to export yet: run the assessment first (ctrl+r)", severity="warning"
            )
            return
        outcome, scratch = self.outcome, self.is_scratch(self.outcome)

        def done(path: Path | None) -> None:
            if path is not None:
                self.notify(f"exporting into {path}/ …")
                job = partial(export_job, self.post_message, outcome, path)
                self.run_worker(
                    job, thread=True, exclusive=True, group="export", exit_on_error=False
                )

        self.push_screen(folders.export_prompt(self.path, outcome.out_dir, scratch), done)

    @on(ExportDone)
    def _export_done(self, message: ExportDone) -> None:
        if (panel := self.pane(RunPanel)) is None:
            return
        if message.error:
            self.notify(message.error, title="Export failed", severity="error")
            panel.log_line(f"export failed: {message.error}", "red")
            return
        names, where = folders.exported(message.files)
        self.notify(f"wrote {names} into {where}/", title="Exported")
        panel.log_line(f"exported into {where}/: {names}")

    # ------------------------------------------------------------------------- quit
    def action_quit_app(self) -> None:
        if not self.modified():
            self.quit_now()
            return
        what = (
            "The project has unsaved changes." if self.path else "The new project was never saved."
        )

        def done(choice: str | None) -> None:
            if choice == "save":
                if self.path is None:
                    self.action_save_as()
                elif self.save_to(self.path):
                    self.quit_now()
            elif choice == "discard":
                self.quit_now()

        self.push_screen(ConfirmQuit(what), done)

    def quit_now(self) -> None:
        """Stop the workers, remove the scratch folder (unless a run writes there), leave."""
        self.quitting = True
        self.previous_cancel.set()
        if self.cancel_event is not None:
            self.cancel_event.set()
        if self.scratch is not None and not self.running:
            folders.remove_scratch(self.scratch)
        self.exit()


__all__ = ["FrpAssessApp"]
