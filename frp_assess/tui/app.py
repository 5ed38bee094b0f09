"""`frp-assess tui`: the Textual application.

The app owns the editing state: it builds the project data from the fields and tables,
validates it with the loader's models (:mod:`frp_assess.tui.core.model`), shows each problem next
to its field, updates derived values and the spectrum preview, and runs the long operations
(assessment, time histories, export) in worker threads through :mod:`frp_assess.tui.core.session`.
"""

from __future__ import annotations

import copy
import threading
import time
from pathlib import Path
from typing import Any, ClassVar

from rich.table import Table
from rich.text import Text
from textual import on, work
from textual.app import App, ComposeResult, SystemCommand
from textual.binding import Binding, BindingType
from textual.containers import ScrollableContainer, Vertical
from textual.message import Message
from textual.screen import Screen
from textual.widget import Widget
from textual.widgets import (
    Button,
    DataTable,
    Input,
    Select,
    Static,
    TabbedContent,
    TabPane,
    Tabs,
)

from frp_assess.api import default_out_dir
from frp_assess.assess.inputs import UNREINFORCED
from frp_assess.assess.results import recommendation_text
from frp_assess.config import Project, load_project_text, project_data
from frp_assess.config.loader import parse_yaml
from frp_assess.config.messages import Loc, format_path
from frp_assess.errors import Cancelled, InputError
from frp_assess.tui.core.model import (
    Problem,
    get_path,
    material_table,
    record_file_problem,
    set_path,
    spectrum_preview,
    validate_edit,
    wall_derived,
)
from frp_assess.tui.core.new_project import new_project_text
from frp_assess.tui.core.project_info import (
    option_rows,
    record_count,
    records_summary,
    retrofits_summary,
)
from frp_assess.tui.core.session import (
    HistoryData,
    RunEvent,
    RunOutcome,
    case_history,
    execute_run,
    export_outputs,
    load_previous,
    save_project,
    yaml_path_problem,
)
from frp_assess.tui.core.tabs import TABS, tab_of, tab_title
from frp_assess.tui.core.text import printable
from frp_assess.tui.dialogs import ConfirmQuit, PathPrompt
from frp_assess.tui.editor import (
    ARTIFICIAL_DEFAULTS,
    DESIGN_DEFAULTS,
    SECTIONS,
    SPECTRUM_DEFAULTS,
    AnalysisPane,
    RecordsPane,
    SitePane,
    WallPane,
    derived_wall_table,
)
from frp_assess.tui.fields import FieldRow
from frp_assess.tui.help import HelpScreen
from frp_assess.tui.history import HistoryPane
from frp_assess.tui.interventions import InterventionsEditor
from frp_assess.tui.item_editor import ItemEditor
from frp_assess.tui.keybar import KeyBar
from frp_assess.tui.literal import literal, safe
from frp_assess.tui.materials import MaterialsEditor
from frp_assess.tui.plots import Rule, Series
from frp_assess.tui.record_files import RecordFilesEditor
from frp_assess.tui.results import RankingTable, ResultsPane, Tabbed
from frp_assess.tui.run_panel import RunPanel

#: the widget that gets the focus when a tab is shown
FIRST_FOCUS = {
    "tab-wall": "#f-wall-thickness-control",
    "tab-site": "#f-seismic-spectrum-type-control",
    "tab-records": "#f-seismic-records-source-control",
    "tab-materials": "#materials-editor DataTable",
    "tab-retrofits": "#interventions-editor DataTable",
    "tab-analysis": "#f-analysis-restitution-control",
    "tab-run": "#run-button",
    "tab-results": "#ranking-table",
    "tab-history": "#hist-case",
}
EDITORS: tuple[tuple[Loc, str], ...] = (
    (("seismic", "records", "files"), "#files-editor"),
    (("materials",), "#materials-editor"),
    (("interventions",), "#interventions-editor"),
)


class RunProgress(Message):
    """A progress event of the run (posted from the worker thread)."""

    def __init__(self, event: RunEvent) -> None:
        super().__init__()
        self.event = event


class RunDone(Message):
    """The run ended: status ``done`` | ``cancelled`` | ``error``."""

    def __init__(self, status: str, outcome: RunOutcome | None, message: str) -> None:
        super().__init__()
        self.status, self.outcome, self.message = status, outcome, message


class PreviousLoaded(Message):
    """The results of the last run, rebuilt from the cache at start (None: none match)."""

    def __init__(self, outcome: RunOutcome | None, error: str = "") -> None:
        super().__init__()
        self.outcome, self.error = outcome, error


class HistoryDone(Message):
    def __init__(self, data: HistoryData | None, error: str = "") -> None:
        super().__init__()
        self.data, self.error = data, error


class ExportDone(Message):
    def __init__(self, files: list[Path], error: str = "") -> None:
        super().__init__()
        self.files, self.error = files, error


class FrpAssessApp(App[None]):
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
        self.variants: dict[str, str] = {"spectrum": "ntc2018", "records": "artificial"}
        self.variants["design"] = "off"
        self.problems: list[Problem] = []
        self.project: Project | None = None
        self.saved_data: Any = None
        self.outcome: RunOutcome | None = None
        self.cancel_event: threading.Event | None = None
        self.running = False
        self.load_message = ""
        self._pending_run = False
        self._field_rows: list[FieldRow] | None = None
        self._widget_cache: dict[str, Any] = {}
        self._shown: dict[str, Any] = {}
        self._quitting = False
        self._last_data: Any = None
        self._previous_event = threading.Event()  #: cancels rebuilding the last run's results

    # ------------------------------------------------------------------------ layout
    def compose(self) -> ComposeResult:
        with Tabbed(id="tabs"):
            with TabPane("Wall", id="tab-wall"):
                yield WallPane()
            with TabPane("Site", id="tab-site"):
                yield SitePane()
            with TabPane("Records", id="tab-records"):
                yield RecordsPane()
            with TabPane("Materials", id="tab-materials"):
                with Vertical(classes="pane"):
                    yield Static(
                        "FRP bar materials (library and the project's)", classes="section-title"
                    )
                    yield MaterialsEditor(id="materials-editor")
            with TabPane("Retrofits", id="tab-retrofits"):
                with Vertical(classes="pane"):
                    yield Static("", id="retrofits-info", classes="section-title")
                    yield InterventionsEditor(id="interventions-editor")
                    yield Static("", id="expanded-options")
            with TabPane("Analysis", id="tab-analysis"):
                yield AnalysisPane()
            with TabPane("Run", id="tab-run"):
                yield RunPanel(id="run-panel")
            with TabPane("Results", id="tab-results"):
                yield ResultsPane(id="results-pane")
            with TabPane("History", id="tab-history"):
                yield HistoryPane(id="history-pane")
        yield Static("", id="help-line")
        yield Static("", id="status")
        yield KeyBar(id="keybar")

    def notify(self, message: str, *, title: str = "", **kw: Any) -> None:
        """A notification; its text is shown as plain text (names may hold markup or
        control characters), never as markup."""
        kw["markup"] = False
        super().notify(printable(message, newlines=True), title=printable(title), **kw)

    def get_system_commands(self, screen: Screen) -> Any:
        yield from super().get_system_commands(screen)
        yield SystemCommand("Save as…", "Save the project to another file", self.action_save_as)
        yield SystemCommand("Run", "Run the assessment (ctrl+r)", self.action_run)
        yield SystemCommand("Export", "Export the PDF report and results", self.action_export)
        yield SystemCommand("Help", "Keys and usage (?)", self.action_help)

    # ---------------------------------------------------------------------- opening
    def on_mount(self) -> None:
        data = self._initial_data()
        self.populate(data)
        self.saved_data = self.collect()
        if self.path is not None and not self.path.exists():
            self.saved_data = None  # a new file: not saved yet
        self.revalidate()
        if self.load_message:
            self.notify(self.load_message, severity="warning", timeout=8, markup=False)
        self.query_one("#f-wall-thickness-control", Input).focus()
        if self.path is not None and self.project is not None and not self.problems:
            if (default_out_dir(self.path) / "results.json").is_file():
                self._previous_worker(self.project, self.path.name, default_out_dir(self.path))

    @work(thread=True, exclusive=True, group="previous", exit_on_error=False)
    def _previous_worker(self, project: Project, input_file: str, out_dir: Path) -> None:
        try:
            outcome = load_previous(
                project,
                self.base_dir,
                input_file,
                out_dir,
                cancel=self._previous_event,
                jobs=self.jobs,
            )
        except Cancelled:
            return
        except Exception as exc:  # noqa: BLE001 - a note in the run log, never a crash
            self.post_message(PreviousLoaded(None, f"{type(exc).__name__}: {exc}"))
        else:
            self.post_message(PreviousLoaded(outcome))

    @on(PreviousLoaded)
    def _previous_loaded(self, message: PreviousLoaded) -> None:
        if self._quitting or self.running or self.outcome is not None or self.path is None:
            return
        panel = self.w("#run-panel")
        out_dir = default_out_dir(self.path)
        o = message.outcome
        if o is None:
            why = f" ({message.error})" if message.error else ""
            panel.log_line(
                f"the results in {out_dir}/ are not those of the project as it is{why}: "
                "ctrl+r runs it"
            )
            return
        self.outcome = o
        panel.log_line(
            f"results of the run of {o.results.get('created')} shown (rebuilt from the cache in "
            f"{out_dir}/); recommended: {recommendation_text(o.results)}"
        )
        self.w("#results-pane").show(o.results, str(o.out_dir), self.project != o.project)
        self.w("#history-pane").show_results(o.results)
        self._update_status()

    def _initial_data(self) -> Any:
        if self.path is not None and self.path.exists():
            text = self.path.read_text(encoding="utf-8")
            name = str(self.path)
        else:
            text = new_project_text(self.path, self.initial_text)
            name = str(self.path) if self.path else "new project"
        try:
            data, _ = parse_yaml(text, name)
        except InputError as exc:  # the CLI reports this before starting; here just say it
            self.load_message = str(exc)
            return {}
        try:
            loaded = load_project_text(text, name, base_dir=self.base_dir, check_files=False)
        except InputError as exc:
            self.load_message = f"{exc}"
            return data if isinstance(data, dict) else {}
        return project_data(loaded.project)

    # -------------------------------------------------------------------- data <-> UI
    @property
    def rows(self) -> list[FieldRow]:
        """The fields of the project (not those of the tables' forms)."""
        if self._field_rows is None:
            self._field_rows = [
                r
                for r in self.query(FieldRow)
                if not any(isinstance(a, ItemEditor) for a in r.ancestors)
            ]
        return self._field_rows

    def set_content(self, selector: str, key: Any, content: Any) -> None:
        """Update a Static only when what it shows changed (``key``): typing stays cheap."""
        if self._shown.get(selector) != key:
            self._shown[selector] = key
            self.w(selector).update(safe(content) if isinstance(content, str | Text) else content)

    def w(self, selector: str) -> Any:
        """``query_one`` with a cache: the layout never changes after mounting."""
        widget = self._widget_cache.get(selector)
        if widget is None:
            widget = self._widget_cache[selector] = self.query_one(selector)
        return widget

    def _variant_of(self, data: Any, group: str) -> str:
        if group == "spectrum":
            t = get_path(data, ("seismic", "spectrum", "type"))
            return t if t in SPECTRUM_DEFAULTS else "ntc2018"
        if group == "records":
            recs = get_path(data, ("seismic", "records"), {})
            return "files" if isinstance(recs, dict) and "files" in recs else "artificial"
        return "on" if isinstance(data, dict) and data.get("design") is not None else "off"

    def _defaults(self, group: str, value: str) -> dict[str, Any]:
        if group == "spectrum":
            return {"seismic": {"spectrum": SPECTRUM_DEFAULTS[value]}}
        if group == "records":
            return {"seismic": {"records": {"artificial": ARTIFICIAL_DEFAULTS}}}
        return {"design": DESIGN_DEFAULTS}

    def populate(self, data: Any) -> None:
        """Show ``data`` (the project as the YAML loader reads it) in every field."""
        data = copy.deepcopy(data)
        self.variants = {g: self._variant_of(data, g) for g in ("spectrum", "records", "design")}
        with self.prevent(Input.Changed, Select.Changed):
            for row in self.rows:
                spec = row.spec
                if spec.selects is not None:
                    row.set_value(self.variants[spec.selects])
                    continue
                source = data
                if spec.variant is not None and self.variants[spec.variant[0]] != spec.variant[1]:
                    source = self._defaults(*spec.variant)
                row.set_value(get_path(source, spec.path))
        files = get_path(data, ("seismic", "records", "files"), [])
        self.query_one(RecordFilesEditor).load(list(files) if isinstance(files, list) else [])
        self.query_one(MaterialsEditor).load_entries(data.get("materials") or {})
        items = data.get("interventions") or []
        self.query_one(InterventionsEditor).load(list(items) if isinstance(items, list) else [])
        self.apply_variants()

    def apply_variants(self) -> None:
        """Show the fields of the chosen spectrum type, record source and design mode."""
        for container in self.query(".variant"):
            _, group, value = str(container.id).split("-", 2)
            container.display = self.variants.get(group) == value

    def collect(self) -> dict[str, Any]:
        """The project data as typed (the dict the YAML loader would produce)."""
        data: dict[str, Any] = {}
        for row in self.rows:
            spec = row.spec
            if spec.virtual:
                continue
            if spec.variant is not None and self.variants[spec.variant[0]] != spec.variant[1]:
                continue
            set_path(data, spec.path, row.data_value())
        if self.variants["records"] == "files":
            files = copy.deepcopy(self.w("#files-editor").items)
            set_path(data, ("seismic", "records", "files"), files)
        data["materials"] = copy.deepcopy(self.w("#materials-editor").data())
        data["interventions"] = copy.deepcopy(self.w("#interventions-editor").items)
        return data

    # ------------------------------------------------------------------- validation
    def revalidate(self, force: bool = False) -> None:
        """Validate what is typed; show problems, derived values, preview and status.

        Nothing is redone when the data did not change (``force``: redo anyway, e.g. after a
        save, when record paths are read from another folder).
        """
        data = self.collect()
        if not force and data == self._last_data:
            return
        self._last_data = copy.deepcopy(data)
        project, problems = validate_edit(data)
        if project is not None:
            missing = record_file_problem(project, self.base_dir)
            if missing is not None:
                problems = [missing]
        self.problems = problems
        self.project = project
        self._show_problems(problems)
        self._show_derived(data, project)
        self._update_status(data)

    def _show_problems(self, problems: list[Problem]) -> None:
        rows = [r for r in self.rows if not r.spec.virtual and self._active(r)]
        messages: dict[int, str] = {}
        sections: dict[str, str] = {}
        editors = [(root, self.w(sel)) for root, sel in EDITORS]
        for p in problems:
            if any(p.target[: len(root)] == root for root, _ in editors):
                continue
            row = self._row_for(rows, p.target)
            if row is not None:
                rest = p.target[len(row.spec.path) :]
                msg = f"{format_path(rest)}: {p.message}" if rest else p.message
                messages.setdefault(id(row), msg)
                continue
            section = self._section_for(p.target)
            sections.setdefault(section, str(p))
        for r in self.rows:
            r.show_error(messages.get(id(r)))
        for sid in sorted(set(SECTIONS.values())):
            cached = self._widget_cache.get(sid)
            found = self.query(f"#{sid}") if cached is None else [cached]
            for w in found:
                self._widget_cache.setdefault(sid, w)
                text = sections.get(sid)
                if isinstance(w, Static) and self._shown.get(sid) != text:
                    self._shown[sid] = text
                    w.update(literal(f"✗ {text}", "red") if text else "")
                    w.display = bool(text)
        for _, editor in editors:
            editor.show_problems(problems)
        bad_tabs = {tab_of(p.target) for p in problems}
        tabs = self.w("#tabs")
        for tab_id, title in TABS:
            label = f"{title} ✗" if tab_id in bad_tabs else title
            tab = tabs.get_tab(tab_id)
            if str(tab.label) != label:
                tab.label = Text(label, style="bold red") if tab_id in bad_tabs else label

    def _active(self, row: FieldRow) -> bool:
        v = row.spec.variant
        return v is None or self.variants[v[0]] == v[1]

    @staticmethod
    def _row_for(rows: list[FieldRow], target: Loc) -> FieldRow | None:
        best = None
        for r in rows:
            n = len(r.spec.path)
            if target[:n] == r.spec.path and (best is None or n > len(best.spec.path)):
                best = r
        return best

    @staticmethod
    def _section_for(target: Loc) -> str:
        for n in range(len(target), 0, -1):
            sid = SECTIONS.get(tuple(str(t) for t in target[:n]))
            if sid:
                return sid
        return "err-wall"

    def _show_derived(self, data: dict[str, Any], project: Project | None) -> None:
        wall = wall_derived(data.get("wall"))
        spectrum = spectrum_preview(get_path(data, ("seismic", "spectrum")))
        pga = None if isinstance(spectrum, str) else spectrum.pga_g
        n_options = None if project is None else len(project.expand_interventions())
        self.set_content(
            "#derived-wall", (wall, pga, n_options), derived_wall_table(wall, pga, n_options)
        )
        self._show_spectrum(spectrum, data)
        table = material_table(data.get("materials"))
        for editor in (self.w("#interventions-editor"),):
            editor.context = {"wall": wall, "wall_data": data.get("wall"), "materials": table}
            editor.set_materials(list(table))
            editor.refresh_table()
        self.w("#materials-editor").refresh_table()
        text = retrofits_summary(project)
        self.set_content("#retrofits-info", text, text)
        self._expanded_options(project, wall)
        self._records_info(project)

    def _expanded_options(self, project: Project | None, wall: Any) -> None:
        """The options the run will compare, with their FRP quantities and costs."""
        if project is None or isinstance(wall, str):
            self.set_content("#expanded-options", None, "")
            return
        rows = option_rows(project)
        currency, length = str(project.costs.currency), project.wall.length
        t = Table(
            title=Text(f"Options compared (wall length L = {length:g} m)", "bold"),
            title_justify="left",
            min_width=60,
            box=None,
            padding=(0, 2, 0, 0),
        )
        t.add_column(Text("option"))
        t.add_column(Text("FRP [kg/m]"), justify="right")
        t.add_column(Text("FRP [kg]"), justify="right")
        t.add_column(literal(f"cost [{currency}]"), justify="right")
        for r in rows:
            t.add_row(literal(r.name), f"{r.mass_per_m:.2f}", f"{r.mass:.1f}", f"{r.cost:.0f}")
        self.set_content("#expanded-options", (tuple(rows), currency, length), t)

    def _records_info(self, project: Project | None) -> None:
        if project is None:
            self.set_content("#records-info", "", "")
            return
        text, rule = records_summary(project)
        self.set_content(
            "#records-info",
            (text, rule),
            Text.assemble(text, ("\nDesign value of a_dyn: ", "dim"), rule),
        )

    def _show_spectrum(self, spectrum: Any, data: dict[str, Any]) -> None:
        plot = self.w("#spectrum-plot")
        t1 = get_path(data, ("seismic", "t1"), 1.0)
        key = spectrum if isinstance(spectrum, str) else (spectrum, spectrum.description, t1)
        if self._shown.get("#spectrum-plot") == key:
            return
        self._shown["#spectrum-plot"] = key
        info = self.w("#spectrum-info")
        if isinstance(spectrum, str):
            plot.show_message(f"no preview: {spectrum}")
            info.update("")
            return
        import numpy as np

        t_max = 4.0
        periods = np.linspace(0.0, t_max, 321)
        sa = spectrum.sa(periods)
        rules = (
            [Rule(float(t1), "x", "yellow", f"T1 = {t1:g} s")]
            if isinstance(t1, int | float) and not isinstance(t1, bool) and 0 < t1 <= t_max
            else []
        )
        plot.show(
            [Series(periods.tolist(), sa.tolist(), style="cyan", label="Se(T)")],
            x_range=(0.0, t_max),
            y_range=(0.0, float(max(sa)) * 1.1 or 1.0),
            rules=rules,
            x_label="T [s]",
            y_label="Se [g]",
        )
        corners = ", ".join(
            f"{k} = {v:.3g} s"
            for k, v in (("T_B", spectrum.T_B), ("T_C", spectrum.T_C), ("T_D", spectrum.T_D))
            if v is not None
        )
        info.update(
            Text.assemble(
                ("a_g·S = ", "bold cyan"),
                (f"{spectrum.pga_g:.4f} g", "bold"),
                (f"   plateau {spectrum.plateau_g:.4f} g\n", ""),
                (corners, "dim"),
            )
        )

    def modified(self, data: dict[str, Any] | None = None) -> bool:
        """Whether the fields differ from the file as last opened or saved."""
        return self.saved_data is None or (data or self.collect()) != self.saved_data

    def _update_status(self, data: dict[str, Any] | None = None) -> None:
        where = self.path.name if self.path else "new project (not saved)"
        t = Text(f" {where}", style="bold")
        if self.path is not None and self.modified(data):
            t.append("  ● modified", "yellow")
        t.append("  │ ")
        if not self.problems:
            t.append("✓ valid", "green")
        else:
            p = self.problems[0]
            more = f" (+{len(self.problems) - 1} more)" if len(self.problems) > 1 else ""
            tab = tab_title(tab_of(p.target))
            t.append(f"✗ {p}{more} [{tab}]", "red")
        if self.running:
            t.append("  │ running…", "yellow")
        t.truncate(max(self.size.width, 20) - 1, overflow="ellipsis")
        self.set_content("#status", t.markup, t)
        if self.outcome is not None:
            stale = self.project is None or self.project != self.outcome.project
            self.w("#results-pane").mark_stale(stale)

    # ----------------------------------------------------------------------- events
    @on(Input.Changed)
    @on(Select.Changed)
    def _field_changed(self, event: Input.Changed | Select.Changed) -> None:
        row = next((a for a in event.control.ancestors if isinstance(a, FieldRow)), None)
        if row is None:
            return
        if row.spec.selects is not None and not any(
            isinstance(a, ItemEditor) for a in row.ancestors
        ):
            value = row.control.value  # the event may be older than the value shown
            if isinstance(value, str) and value != self.variants.get(row.spec.selects):
                self.variants[row.spec.selects] = value
                self.apply_variants()
        self.revalidate()

    @on(ItemEditor.Edited)
    def _items_edited(self, event: ItemEditor.Edited) -> None:
        self.revalidate()

    def on_descendant_focus(self, event: Any) -> None:
        widget: Widget = event.widget
        line = self.w("#help-line")
        row = next((a for a in widget.ancestors_with_self if isinstance(a, FieldRow)), None)
        if row is not None:
            line.update(Text(row.spec.help or row.spec.label, style="italic"))
        elif isinstance(widget, DataTable):
            hint = {
                "ranking-table": "←/→ column · s sort · enter: per-record IDA of the case",
            }.get(str(widget.id), "↑/↓ select · a add · d duplicate · del remove · enter edit")
            line.update(Text(hint, style="italic"))
        elif isinstance(widget, Tabs):
            line.update(Text("←/→ switch tab · tab: into the tab · F2…F10: main tabs", "italic"))
        else:
            line.update(Text("tab: next field · ?/F1: help", style="italic dim"))

    # ------------------------------------------------------------------------ tabs
    def action_tab(self, index: int) -> None:
        if 0 <= index < len(TABS):
            self.show_tab(TABS[index][0])

    def action_next_tab(self, step: int) -> None:
        tabs = self.w("#tabs")
        ids = [t for t, _ in TABS]
        i = ids.index(tabs.active) if tabs.active in ids else 0
        self.show_tab(ids[(i + step) % len(ids)])

    def show_tab(self, tab_id: str) -> None:
        """Show a tab and put the focus on its first field (never on a hidden one)."""
        tabs = self.w("#tabs")
        tabs.active = tab_id
        self.call_after_refresh(self._focus_in, tab_id)

    def _focus_in(self, tab_id: str) -> None:
        if self.w("#tabs").active != tab_id:
            return  # the user has moved on
        pane = self.query_one(f"#{tab_id}", TabPane)
        focused = self.focused
        if focused is not None and pane in focused.ancestors:
            return
        chain = self.screen.focus_chain  # only widgets that are shown
        first = FIRST_FOCUS.get(tab_id)
        if first is not None:
            target = self.query_one(first)
            if target in chain:
                target.focus(scroll_visible=False)  # the pane starts at its top
                return
        for widget in chain:
            if pane in widget.ancestors and not isinstance(widget, ScrollableContainer | Tabs):
                widget.focus()
                return
        self.screen.set_focus(None)  # nothing to focus here: never type into a hidden tab

    def action_help(self) -> None:
        if not isinstance(self.screen, HelpScreen):
            self.push_screen(HelpScreen())

    # ------------------------------------------------------------------------- save
    def action_save(self) -> None:
        if self.path is None:
            self.action_save_as()
            return
        self._save_to(self.path)

    def action_save_as(self, then_run: bool = False) -> None:
        default = str(self.path) if self.path else str(Path.cwd() / "wall.yaml")

        def done(path: Path | None) -> None:
            if path is None:
                self._pending_run = False
                return
            if self._save_to(path) and self._pending_run:
                self._pending_run = False
                self.action_run()

        self._pending_run = then_run
        self.push_screen(
            PathPrompt(
                "Save the project as",
                default,
                "a .yaml file; relative record paths are read from its folder",
                yaml_path_problem,
            ),
            done,
        )

    def _save_to(self, path: Path) -> bool:
        if self.project is None:
            first = self.problems[0] if self.problems else None
            self.notify(
                f"cannot save: {first}" if first else "cannot save: the project is not valid",
                title="Not saved",
                severity="error",
                markup=False,
            )
            return False
        opened = self.path if self.path is not None and self.path.is_file() else None
        try:
            kept = save_project(self.project, path, opened_from=opened)
        except InputError as exc:
            self.notify(str(exc), title="Not saved", severity="error", markup=False)
            return False
        self.path = Path(path).absolute()
        self.base_dir = self.path.parent  # relative record paths are read from there now
        self.saved_data = self.collect()
        self.revalidate(force=True)
        how = "only the changes; its comments kept" if kept else "the whole project"
        self.notify(f"saved {path} ({how})", title="Saved", markup=False)
        return True

    # -------------------------------------------------------------------------- run
    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        if action == "cancel_run":
            return self.running
        return True

    def action_run(self) -> None:
        panel = self.w("#run-panel")
        if self.running:
            self.notify("a run is already in progress (esc cancels it)", markup=False)
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
        if self.modified():
            panel.log_line("note: running the project as edited (not saved yet)", "yellow")
        panel.start(names, record_count(project), str(out_dir))
        self.cancel_event = threading.Event()
        self.running = True
        self._update_status()
        self._run_worker(project, self.path.name, out_dir, self.cancel_event)

    @work(thread=True, exclusive=True, group="run", exit_on_error=False)
    def _run_worker(
        self, project: Project, input_file: str, out_dir: Path, cancel: threading.Event
    ) -> None:
        last: dict[str, float] = {}

        def emit(ev: RunEvent) -> None:
            # at most ~10 updates a second: the UI thread shares the GIL with the run
            now = time.monotonic()
            if ev.message or ev.done in (0, ev.total) or now - last.get(ev.stage, 0.0) >= 0.1:
                last[ev.stage] = now
                self.post_message(RunProgress(ev))

        try:
            outcome = execute_run(
                project,
                self.base_dir,
                input_file,
                out_dir,
                cancel=cancel,
                emit=emit,
                jobs=self.jobs,
            )
        except Cancelled:
            self.post_message(RunDone("cancelled", None, "finished analyses are kept in the cache"))
        except InputError as exc:
            self.post_message(RunDone("error", None, str(exc)))
        except Exception as exc:  # noqa: BLE001 - shown in the run panel, never a crash
            self.post_message(RunDone("error", None, f"{type(exc).__name__}: {exc}"))
        else:
            self.post_message(RunDone("done", outcome, ""))

    @on(RunProgress)
    def _run_progress(self, message: RunProgress) -> None:
        if not self._quitting and self.w("#run-panel").is_attached:
            self.w("#run-panel").show_event(message.event)

    @on(RunDone)
    def _run_done(self, message: RunDone) -> None:
        self.running = False
        self.cancel_event = None
        if self._quitting or not self.w("#run-panel").is_attached:
            return
        panel = self.w("#run-panel")
        if message.status == "done" and message.outcome is not None:
            o = message.outcome
            self.outcome = o
            rec = recommendation_text(o.results)
            panel.finish(
                "done",
                f"{o.stats.computed} IDAs computed, {o.stats.reused} reused from the cache; "
                f"recommended: {rec}; results and report.pdf in {o.out_dir}/",
            )
            stale = self.project != o.project
            self.w("#results-pane").show(o.results, str(o.out_dir), stale)
            self.w("#history-pane").show_results(o.results)
            self.notify("run finished: see the Results tab (F9)", title="Done", markup=False)
        else:
            panel.finish(message.status, message.message)
            if message.status == "error":
                self.notify(message.message, title="Run failed", severity="error", markup=False)
        self._update_status()
        self.refresh_bindings()

    def action_cancel_run(self) -> None:
        if self.running and self.cancel_event is not None:
            self.cancel_event.set()
            self.w("#run-panel").set_state(Text("cancelling…", style="bold yellow"))

    @on(Button.Pressed, "#run-button")
    def _run_pressed(self) -> None:
        self.action_run()

    @on(Button.Pressed, "#cancel-button")
    def _cancel_pressed(self) -> None:
        self.action_cancel_run()

    # --------------------------------------------------------------- results & history
    @on(RankingTable.CaseChosen)
    def _case_chosen(self, message: RankingTable.CaseChosen) -> None:
        self.w("#history-pane").set_case(message.index)

    @on(TabbedContent.TabActivated, "#tabs")
    def _tab_activated(self, event: TabbedContent.TabActivated) -> None:
        focused = self.focused
        if focused is None or (
            not isinstance(focused, Tabs) and event.pane not in focused.ancestors
        ):
            self.call_after_refresh(self._focus_in, str(event.pane.id))
        if event.pane.id == "tab-history":
            self.w("#history-pane").refresh_if_needed()

    @on(HistoryPane.Requested)
    def _history_requested(self, message: HistoryPane.Requested) -> None:
        if self.outcome is None:
            return
        self._history_worker(self.outcome, message.case, message.record, message.multiplier)

    @work(thread=True, exclusive=True, group="history", exit_on_error=False)
    def _history_worker(
        self, outcome: RunOutcome, case: int, record: int, multiplier: float
    ) -> None:
        try:
            data = case_history(outcome, case, record, multiplier)
        except Exception as exc:  # noqa: BLE001 - shown in the History tab
            self.post_message(HistoryDone(None, f"{type(exc).__name__}: {exc}"))
        else:
            self.post_message(HistoryDone(data))

    @on(HistoryDone)
    def _history_done(self, message: HistoryDone) -> None:
        pane = self.w("#history-pane")
        if not pane.is_attached or self._quitting:
            return  # the app is closing
        if message.data is not None:
            pane.show_history(message.data)
        else:
            pane.show_error(message.error)

    # ----------------------------------------------------------------------- export
    def action_export(self) -> None:
        if self.outcome is None:
            self.notify(
                "nothing to export yet: run the assessment first (ctrl+r)",
                severity="warning",
                markup=False,
            )
            return
        outcome = self.outcome

        def check(path: Path) -> str | None:
            if path.exists() and not path.is_dir():
                return f"{path} is a file, not a directory"
            return None

        def done(path: Path | None) -> None:
            if path is not None:
                self.notify(f"exporting into {path}/ …", markup=False)
                self._export_worker(outcome, path)

        self.push_screen(
            PathPrompt(
                "Export the PDF report and the results into the folder",
                str(outcome.out_dir),
                "report.pdf, results.json, results.csv, spectra.csv, records/",
                check,
            ),
            done,
        )

    @work(thread=True, exclusive=True, group="export", exit_on_error=False)
    def _export_worker(self, outcome: RunOutcome, directory: Path) -> None:
        try:
            files = export_outputs(outcome, directory)
        except InputError as exc:
            self.post_message(ExportDone([], str(exc)))
        except Exception as exc:  # noqa: BLE001 - reported, never a crash
            self.post_message(ExportDone([], f"{type(exc).__name__}: {exc}"))
        else:
            self.post_message(ExportDone(files))

    @on(ExportDone)
    def _export_done(self, message: ExportDone) -> None:
        panel = self.w("#run-panel")
        if self._quitting or not panel.is_attached:
            return
        if message.error:
            self.notify(message.error, title="Export failed", severity="error", markup=False)
            panel.log_line(f"export failed: {message.error}", "red")
            return
        pdf = next((f for f in message.files if f.name == "report.pdf"), None)
        where = pdf.parent if pdf else (message.files[0].parent if message.files else "")
        self.notify(
            f"wrote {', '.join(f.name for f in message.files)} into {where}/",
            title="Exported",
            markup=False,
        )
        panel.log_line(f"exported into {where}/: " + ", ".join(f.name for f in message.files))

    # ------------------------------------------------------------------------- quit
    def action_quit_app(self) -> None:
        if self.modified():
            what = (
                "The project has unsaved changes."
                if self.path
                else ("The new project was never saved.")
            )

            def done(choice: str | None) -> None:
                if choice == "save":
                    if self.path is None:
                        self.action_save_as()
                        return
                    if not self._save_to(self.path):
                        return
                    self._quit_now()
                elif choice == "discard":
                    self._quit_now()

            self.push_screen(ConfirmQuit(what), done)
            return
        self._quit_now()

    def _quit_now(self) -> None:
        self._quitting = True
        self._previous_event.set()
        if self.cancel_event is not None:
            self.cancel_event.set()
        self.exit()


def run_tui(path: Path | None = None, *, jobs: int | None = None) -> int:
    """Run the application (blocking); returns the exit code."""
    FrpAssessApp(path, jobs=jobs).run()
    return 0


__all__ = ["FrpAssessApp", "run_tui"]
