"""The help screen (``?`` or F1): keys and how the editor works."""

from __future__ import annotations

from typing import ClassVar

from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Vertical, VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Markdown, Static

HELP_TEXT = """\
# frp-assess tui

Edit a project, run the assessment, read the results. Every value is checked as you
type by the same rules (and messages) as `frp-assess validate`; the message shows under
the field and the tab is marked **✗**. Derived values update as you type.

## Keys everywhere

| key | action |
|---|---|
| `ctrl+s` | save the project (asks for a file name the first time); only what |
|  | changed is rewritten: the file's comments and layout stay |
| `ctrl+r` | run the assessment (in the background; the editor stays usable) |
| `esc` / `ctrl+c` | cancel the run (finished analyses are kept in the cache) |
| `ctrl+e` | export the PDF report and the result files |
| `F2` … `F10` | go to a tab: Wall, Site, Records, Materials, Retrofits, |
|  | Analysis, Run, Results, Time history (also `ctrl+pageup/pagedown`) |
| `tab` / `shift+tab` | next / previous field (the tab bar too: then ←/→) |
| `?` / `F1` | this help (in a free-text field `?` is typed: use F1 there) |
| `ctrl+p` | command palette (save as…, theme, keys) |
| `q` / `ctrl+q` | quit (asks when there are unsaved changes) |

## A building file (`walls:`)

The list of walls is on the left (`ctrl+w` goes to it; `enter` shows the wall
highlighted in the tabs). A wall's own keys (wall, loads, its `building:`, its
options) are saved in its item of `walls:`; the site, records, materials, analysis
and costs are the building's, for every wall. On the list: `a` add, `d` duplicate,
`r` rename, `delete` remove a wall (names unique). Run the building with
`frp-assess run FILE`: its summary is then the Results tab.

## Fields

Numbers are read as in the YAML file (`0.4`, `1e-3`); optional fields show their
default, and an emptied one leaves the key out (the default applies). Lists are
comma-separated (`GFRP, CFRP`). Choices open with `enter`; pick with ↑/↓ and `enter`.
The line at the bottom shows the field's meaning and units.

## Tables (materials, retrofits, record files)

| key | action |
|---|---|
| `a` | add (retrofits: an option) |
| `s` | add a sweep (retrofits) |
| `d` | duplicate the selected row |
| `delete` / `x` | remove the selected row (materials: back to the library) |
| `enter` | edit the selected row in the form below |

## Results

Its views (Ranking, Per record, FRP plot, Fragility, Bars & pivot, Checks, Design,
Compliance): `]` next view, `[` previous view (anywhere in the Results tab); or
`shift+tab` up to the views' tab bar, then ←/→.

*Ranking*: ←/→ pick a column, `s` sorts by it (again: reverse), `enter` shows the IDA
per record of the case; verdict, governing check ("TH SLV": the time history at SLV) and
margin are the decision's, as in the console and results.csv. *FRP plot*: improvement or
capacity/demand against the FRP mass. *Fragility*: P(collapse) against PGA of every
case's lognormal fit, the demand FC·a_g·S (the decision's) marked and P(collapse) stated
there. *Bars & pivot*: per option the bars as built (count × diameter, spacing, ratio
installed / asked, anchorage) and per case the compressed zone at the pivot (x/B,
dropped and why). *Checks*: the code's kinematic checks (ζ_E of the linear, SLV, SLC,
time-history and IDA checks) and the sensitivity of the best option to the model
conventions and to the IDA's hunt step (√s). *Design*: the smallest ratio per material
and position (design mode).
*Compliance*: the code checks of the records and their mean spectrum.

*Time history*: the rocking time history θ/α(t) and bar strain(t) of one case under
one record at one multiplier C of it: pick a case and a record; `c` at collapse, `b`
just below, `1` for C = 1, or type a multiplier and press `enter`.

Runs write `results.json`, `results.csv`, `spectra.csv`, `records/`, `report.pdf` and
`report.docx` (the editable Word report) into `<project>-results/` next to the project
file and keep every finished analysis in its `.cache/`, as `frp-assess run` does.  That
folder only ever holds the results of the file as saved: `ctrl+r` on unsaved edits runs
them in a scratch folder of their own (the run log and the Results tab say where; it is
removed when you quit: `ctrl+e` exports its results before); save,
then `ctrl+r`, to put them next to the project.  `ctrl+e` writes them all (both reports
included) into another folder (proposed: `<project>-export/`).
Opening a project that was run before shows that run's results again (rebuilt from the
cache, nothing recomputed) when they match the project as it is.
"""


class HelpScreen(ModalScreen[None]):
    """Keys and usage; closes with esc, q, ? or F1."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("escape,q,question_mark,f1", "close", "Close help"),
    ]

    def compose(self) -> ComposeResult:
        with Vertical(id="help-box"):
            with VerticalScroll(id="help-scroll"):
                yield Markdown(HELP_TEXT)
            yield Static("↑/↓ scroll · esc close", classes="hint")

    def on_mount(self) -> None:
        self.query_one("#help-scroll").focus()

    def action_close(self) -> None:
        self.dismiss(None)
