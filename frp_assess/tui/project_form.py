"""The project as edited: every field and table of the tabs, validated as it is typed.

:class:`ProjectForm` is the editing state of the app: it fills the fields from the project
data, collects them back into the dict the YAML loader would produce, validates it with the
loader's models (:mod:`frp_assess.tui.core.editor_state`), shows each problem next to its field,
and hands the derived values to the panes that show them.
"""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

from textual.dom import DOMNode
from textual.widgets import Input, Select, Static

from frp_assess.config.messages import Loc, format_path
from frp_assess.config.schema import Project
from frp_assess.tui.core.editor_state import (
    Problem,
    get_path,
    material_table,
    record_file_problem,
    set_path,
    spectrum_preview,
    spectrum_site_warning,
    validate_edit,
    wall_derived,
    without_paths,
)
from frp_assess.tui.core.tabs import tab_of
from frp_assess.tui.field_specs import (
    ARTIFICIAL_DEFAULTS,
    BUILDING_DEFAULTS,
    DESIGN_DEFAULTS,
    NTC_SITE_DEFAULTS,
    SECTIONS,
    SPECTRUM_DEFAULTS,
)
from frp_assess.tui.fields import FieldRow
from frp_assess.tui.item_editor import ItemEditor
from frp_assess.tui.literal import literal
from frp_assess.tui.loads_editors import LOAD_EDITORS, LOADS, loads_data
from frp_assess.tui.main_tabs import MainTabs
from frp_assess.tui.materials_pane import MaterialsPane
from frp_assess.tui.record_files import RecordFilesEditor
from frp_assess.tui.records_pane import RecordsPane
from frp_assess.tui.retrofits_pane import RetrofitsPane
from frp_assess.tui.site_pane import SitePane
from frp_assess.tui.wall_pane import WallPane

#: the variant groups: which fields are part of the data (spectrum type, record source...)
VARIANT_GROUPS = ("spectrum", "ntc", "records", "design", "building")
#: a variant group shown only inside a variant of another (NTC 2018 by parameters or by
#: coordinates, inside the NTC 2018 spectrum)
VARIANT_PARENTS: dict[str, tuple[str, str]] = {"ntc": ("spectrum", "ntc2018")}
#: the blocks of the file each variant group stands for: left out of what is carried over
#: from the file when the variant chosen is not the file's (another spectrum type...)
VARIANT_BLOCKS: dict[str, tuple[Loc, ...]] = {
    "spectrum": (("seismic", "spectrum"),),
    "ntc": (),  # its keys are all the fields' (an emptied ``site`` goes with them)
    "records": (("seismic", "records", "artificial"), ("seismic", "records", "files")),
    "design": (("design",),),
    "building": (("building",),),
}
#: the blocks the tables edit as a whole
TABLE_BLOCKS: tuple[Loc, ...] = (
    ("seismic", "records", "files"),
    ("materials",),
    ("interventions",),
    LOADS,
)


def variant_of(data: Any, group: str) -> str:
    """The variant of ``group`` the project data uses (``ntc2018``, ``files``, ``on``...)."""
    if group == "spectrum":
        t = get_path(data, ("seismic", "spectrum", "type"))
        return t if t in SPECTRUM_DEFAULTS else "ntc2018"
    if group == "ntc":
        spectrum = get_path(data, ("seismic", "spectrum"), {})
        return "coordinates" if isinstance(spectrum, dict) and "site" in spectrum else "parameters"
    if group == "records":
        recs = get_path(data, ("seismic", "records"), {})
        return "files" if isinstance(recs, dict) and "files" in recs else "artificial"
    if group == "building":
        return "on" if isinstance(data, dict) and data.get("building") is not None else "off"
    return "on" if isinstance(data, dict) and data.get("design") is not None else "off"


def variant_defaults(group: str, value: str) -> dict[str, Any]:
    """The data shown by the fields of a variant the project does not use."""
    if group == "spectrum":
        return {"seismic": {"spectrum": SPECTRUM_DEFAULTS[value]}}
    if group == "ntc":
        default = NTC_SITE_DEFAULTS if value == "coordinates" else SPECTRUM_DEFAULTS["ntc2018"]
        return {"seismic": {"spectrum": default}}
    if group == "records":
        return {"seismic": {"records": {"artificial": ARTIFICIAL_DEFAULTS}}}
    if group == "building":
        return {"building": BUILDING_DEFAULTS}
    return {"design": DESIGN_DEFAULTS}


def row_for(rows: list[FieldRow], target: Loc) -> FieldRow | None:
    """The field whose key path is the longest prefix of ``target``."""
    best = None
    for r in rows:
        n = len(r.spec.path)
        if target[:n] == r.spec.path and (best is None or n > len(best.spec.path)):
            best = r
    return best


def section_for(target: Loc) -> str:
    """The section (its error line's id) of a key path that is no field's."""
    for n in range(len(target), 0, -1):
        sid = SECTIONS.get(tuple(str(t) for t in target[:n]))
        if sid:
            return sid
    return "err-wall"


class ProjectForm:
    """The fields and tables of the project, under the DOM node ``root`` (the app)."""

    def __init__(self, root: DOMNode) -> None:
        self.root = root
        self.variants: dict[str, str] = {"spectrum": "ntc2018", "records": "artificial"}
        self.variants["design"] = "off"
        self.variants["building"] = "off"
        self.variants["ntc"] = "parameters"
        #: the project data as opened, and its variants: what no field or table edits (the
        #: ``bars:`` block, say) is carried from it into the data unchanged
        self.opened_data: dict[str, Any] = {}
        self.opened_variants: dict[str, str] = dict(self.variants)
        self.problems: list[Problem] = []
        self.project: Project | None = None
        self.saved_data: Any = None  #: the data as last opened or saved (None: never saved)
        self.last_data: Any = None  #: the data last validated
        self.field_rows: list[FieldRow] | None = None
        self.section_shown: dict[str, str | None] = {}

    # ------------------------------------------------------------------------ widgets
    @property
    def rows(self) -> list[FieldRow]:
        """The fields of the project (not those of the tables' forms)."""
        if self.field_rows is None:
            self.field_rows = [
                r
                for r in self.root.query(FieldRow)
                if not any(isinstance(a, ItemEditor) for a in r.ancestors)
            ]
        return self.field_rows

    def editors(self) -> list[tuple[Loc, ItemEditor]]:
        """The table editors and the key path of the block each edits."""
        q = self.root.query_one
        return [
            (("seismic", "records", "files"), q(RecordFilesEditor)),
            (("materials",), q(MaterialsPane).editor),
            (("interventions",), q(RetrofitsPane).editor),
            *((e.ROOT, q(e)) for e in LOAD_EDITORS),
        ]

    # -------------------------------------------------------------------- data <-> UI
    def populate(self, data: Any) -> None:
        """Show ``data`` (the project as the YAML loader reads it) in every field."""
        data = copy.deepcopy(data)
        self.variants = {g: variant_of(data, g) for g in VARIANT_GROUPS}
        self.opened_data = copy.deepcopy(data) if isinstance(data, dict) else {}
        self.opened_variants = dict(self.variants)
        with self.root.prevent(Input.Changed, Select.Changed):
            for row in self.rows:
                spec = row.spec
                if spec.selects is not None:
                    row.set_value(self.variants[spec.selects])
                    continue
                source = data
                if spec.variant is not None and not self.variant_on(spec.variant):
                    source = variant_defaults(*spec.variant)
                row.set_value(get_path(source, spec.path))
        files = get_path(data, ("seismic", "records", "files"), [])
        self.root.query_one(RecordFilesEditor).load(list(files) if isinstance(files, list) else [])
        self.root.query_one(MaterialsPane).load(data)
        self.root.query_one(RetrofitsPane).load(data)
        for editor in LOAD_EDITORS:
            found = get_path(data, editor.ROOT, [])
            self.root.query_one(editor).load(list(found) if isinstance(found, list) else [])
        self.apply_variants()

    def apply_variants(self) -> None:
        """Show the fields of the chosen spectrum type, record source and design mode."""
        for container in self.root.query(".variant"):
            _, group, value = str(container.id).split("-", 2)
            container.display = self.variants.get(group) == value

    def choose_variant(self, row: FieldRow) -> None:
        """A variant selector (spectrum type, record source, design mode) changed."""
        if row.spec.selects is None or any(isinstance(a, ItemEditor) for a in row.ancestors):
            return
        value = row.control.value  # the event may be older than the value shown
        if isinstance(value, str) and value != self.variants.get(row.spec.selects):
            self.variants[row.spec.selects] = value
            self.apply_variants()

    def carried(self) -> dict[str, Any]:
        """What the file opened holds that no field or table edits (``bars:``, a key added
        to the schema after the editor...): kept as it was, so that a run uses it and a save
        writes it back.  A variant block (the spectrum, the design block...) goes when
        another variant is chosen."""
        owned: list[Loc] = [r.spec.path for r in self.rows if not r.spec.virtual]
        owned += TABLE_BLOCKS
        for group, blocks in VARIANT_BLOCKS.items():
            if self.variants[group] != self.opened_variants.get(group):
                owned += blocks
        return without_paths(self.opened_data, owned)

    def collect(self) -> dict[str, Any]:
        """The project data as typed (the dict the YAML loader would produce): the fields
        and tables over what the file held that they do not edit (:meth:`carried`)."""
        data = self.carried()
        for row in self.rows:
            spec = row.spec
            if spec.virtual:
                continue
            if spec.variant is not None and not self.variant_on(spec.variant):
                continue
            set_path(data, spec.path, row.data_value())
        if self.variants["records"] == "files":
            files = copy.deepcopy(self.root.query_one(RecordFilesEditor).items)
            set_path(data, ("seismic", "records", "files"), files)
        data["materials"] = copy.deepcopy(self.root.query_one(MaterialsPane).data())
        data["interventions"] = copy.deepcopy(self.root.query_one(RetrofitsPane).items())
        lists = {str(e.ROOT[-1]): copy.deepcopy(self.root.query_one(e).items) for e in LOAD_EDITORS}
        if (block := loads_data(lists)) is not None:
            set_path(data, LOADS, block)
        return data

    def modified(self, data: dict[str, Any] | None = None) -> bool:
        """Whether the fields differ from the file as last opened or saved."""
        return self.saved_data is None or (data or self.collect()) != self.saved_data

    # ------------------------------------------------------------------- validation
    def revalidate(self, base_dir: Path, force: bool = False) -> dict[str, Any] | None:
        """Validate what is typed (record files read from ``base_dir``); show problems,
        derived values and preview.  Returns the data, or None when it did not change
        (``force``: redo anyway, e.g. after a save, when record paths change folder)."""
        data = self.collect()
        if not force and data == self.last_data:
            return None
        self.last_data = copy.deepcopy(data)
        project, problems = validate_edit(data)
        if project is not None:
            missing = record_file_problem(project, base_dir)
            if missing is not None:
                problems = [missing]
        self.problems = problems
        self.project = project
        self.show_problems(problems)
        self.show_derived(data, project)
        return data

    def active(self, row: FieldRow) -> bool:
        """Whether the row is part of the data (its variant is the one chosen)."""
        return self.variant_on(row.spec.variant)

    def variant_on(self, variant: tuple[str, str] | None) -> bool:
        """Whether ``variant`` (group, value) is chosen, and so is its parent's, if any."""
        if variant is None:
            return True
        group, value = variant
        if self.variants.get(group) != value:
            return False
        return self.variant_on(VARIANT_PARENTS.get(group))

    def show_problems(self, problems: list[Problem]) -> None:
        """Each problem under its field, in its table, or in its section; ✗ on the tabs."""
        rows = [r for r in self.rows if not r.spec.virtual and self.active(r)]
        messages: dict[int, str] = {}
        sections: dict[str, str] = {}
        editors = self.editors()
        for p in problems:
            if any(p.target[: len(root)] == root for root, _ in editors):
                continue
            row = row_for(rows, p.target)
            if row is not None:
                rest = p.target[len(row.spec.path) :]
                msg = f"{format_path(rest)}: {p.message}" if rest else p.message
                messages.setdefault(id(row), msg)
                continue
            sections.setdefault(section_for(p.target), str(p))
        for r in self.rows:
            r.show_error(messages.get(id(r)))
        for sid in sorted(set(SECTIONS.values())):
            text = sections.get(sid)
            if self.section_shown.get(sid, "") == text:
                continue
            self.section_shown[sid] = text
            for w in self.root.query(f"#{sid}"):
                if isinstance(w, Static):
                    w.update(literal(f"✗ {text}", "red") if text else "")
                    w.display = bool(text)
        for _, editor in editors:
            editor.show_problems(problems)
        self.root.query_one(MainTabs).mark_problems({tab_of(p.target) for p in problems})

    def show_derived(self, data: dict[str, Any], project: Project | None) -> None:
        """Derived wall values, spectrum preview, FRP quantities and record summary."""
        wall = wall_derived(data.get("wall"), data.get("analysis"), data.get("code_check"))
        spectrum_data = get_path(data, ("seismic", "spectrum"))
        spectrum = spectrum_preview(spectrum_data)
        pga = None if isinstance(spectrum, str) else spectrum.pga_g
        n_options = None if project is None else len(project.expand_interventions())
        q = self.root.query_one
        q(WallPane).show_derived(wall, pga, n_options)
        q(SitePane).show_spectrum(
            spectrum, get_path(data, ("seismic", "t1"), 1.0), spectrum_site_warning(spectrum_data)
        )
        table = material_table(data.get("materials"))
        q(RetrofitsPane).show_project(project, wall, data.get("wall"), table)
        q(MaterialsPane).refresh_view()
        q(RecordsPane).show_summary(project)
