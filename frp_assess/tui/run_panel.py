"""The Run tab: Run/Cancel, the overall progress bar, one bar per case and a log."""

from __future__ import annotations

import time
from collections.abc import Sequence

from rich.text import Text
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.widgets import Button, Label, ProgressBar, RichLog, Static

from frp_assess.tui.core.progress import CaseCount
from frp_assess.tui.core.session import RunEvent
from frp_assess.tui.literal import literal, safe

STAGES = {
    "records": "generating/reading the records and checking them",
    "ida": "incremental dynamic analyses",
    "design": "design mode (smallest ratio)",
    "writing": "writing the results",
}


class CaseBar(Horizontal):
    """The progress of one case: name, bar, count."""

    def __init__(self, name: str, total: int) -> None:
        super().__init__(classes="case-bar")
        self.case_name = name
        self.total = total
        self.done = 0

    def compose(self) -> ComposeResult:
        yield Label(literal(self.case_name[:30]), classes="case-name")
        yield ProgressBar(total=self.total, show_eta=False, show_percentage=False)
        yield Label(f"0/{self.total}", classes="case-count")

    def set_done(self, done: int) -> None:
        if done == self.done:
            return
        self.done = done
        self.query_one(ProgressBar).update(progress=done)
        self.query_one(".case-count", Label).update(f"{done}/{self.total}")


class RunPanel(Vertical):
    """Controls and progress of a run; the app drives it."""

    def compose(self) -> ComposeResult:
        with Horizontal(id="run-controls"):
            yield Button("▶ Run  ctrl+r", id="run-button", variant="success", compact=True)
            yield Button("■ Cancel  esc", id="cancel-button", variant="error", compact=True)
            yield Static("idle: press ctrl+r to run the assessment", id="run-state")
        with Horizontal(id="overall-row"):
            yield Label("Overall", classes="case-name")
            yield ProgressBar(total=1, id="overall-bar", show_eta=True)
            yield Label("", id="overall-count", classes="case-count")
        yield Static("", id="run-stage")
        yield VerticalScroll(id="case-bars")
        yield RichLog(id="run-log", wrap=True, markup=False, max_lines=500)

    def on_mount(self) -> None:
        self.query_one("#cancel-button", Button).disabled = True
        self._started = 0.0
        self._bars: dict[int, CaseBar] = {}
        self.last_stage = ""
        self._last_event: RunEvent | None = None
        self._elapsed_timer = self.set_interval(1.0, self._show_stage, pause=True)

    def log_line(self, text: str | Text, style: str = "") -> None:
        """Append a line to the run log."""
        stamp = time.strftime("%H:%M:%S ")
        line = Text(stamp, style="dim") + safe(
            text if isinstance(text, Text) else Text(text, style)
        )
        self.query_one("#run-log", RichLog).write(line)

    def start(self, names: Sequence[str], per_case: int, out_dir: str) -> None:
        """A run starts: one bar per case (unreinforced wall first)."""
        self._started = time.monotonic()
        self.query_one("#run-button", Button).disabled = True
        self.query_one("#cancel-button", Button).disabled = False
        self.set_state(Text("running…", style="bold yellow"))
        bars = self.query_one("#case-bars", VerticalScroll)
        bars.remove_children()
        self._bars = {i: CaseBar(n, per_case) for i, n in enumerate(names)}
        if self._bars:
            bars.mount_all(self._bars.values())
        overall = self.query_one("#overall-bar", ProgressBar)
        overall.update(total=1, progress=0)  # not indeterminate: its animation costs CPU
        self.query_one("#overall-count", Label).update("")
        self.query_one("#run-stage", Static).update("")
        self.last_stage = ""
        self._last_event = None
        self._elapsed_timer.resume()
        self.log_line(f"run started: {len(names)} cases; results into {out_dir}/")

    def _show_stage(self) -> None:
        ev = self._last_event
        if ev is None:
            return
        elapsed = time.monotonic() - self._started
        self.query_one("#run-stage", Static).update(
            Text.assemble(
                ("stage: ", "dim"),
                (STAGES.get(ev.stage, ev.stage), "bold"),
                (f"  {ev.done}/{ev.total}", ""),
                (f"   {elapsed:.0f} s elapsed", "dim"),
            )
        )

    def show_event(self, ev: RunEvent) -> None:
        """Show a progress event of the run."""
        self.last_stage = ev.stage
        self._last_event = ev
        self._show_stage()
        if ev.stage == "ida":
            overall = self.query_one("#overall-bar", ProgressBar)
            overall.update(total=ev.total, progress=ev.done)
            self.query_one("#overall-count", Label).update(f"{ev.done}/{ev.total}")
        if ev.cases is not None:
            for i, count in enumerate(ev.cases):
                bar = self._bars.get(i)
                if bar is not None:
                    bar.set_done(count.done)
        if ev.message:
            self.log_line(ev.message)

    def case_counts(self) -> list[CaseCount]:
        """The per-case counts shown (for tests)."""
        out = []
        for bar in self._bars.values():
            pb = bar.query_one(ProgressBar)
            out.append(CaseCount(bar.case_name, int(pb.progress), bar.total))
        return out

    def set_state(self, text: str | Text) -> None:
        self.query_one("#run-state", Static).update(safe(text))

    def finish(self, status: str, message: str) -> None:
        """The run ended: ``done``, ``cancelled`` or ``error`` (message: one line)."""
        self.query_one("#run-button", Button).disabled = False
        self.query_one("#cancel-button", Button).disabled = True
        self._elapsed_timer.pause()
        elapsed = time.monotonic() - self._started
        style = {"done": "bold green", "cancelled": "bold yellow", "error": "bold red"}[status]
        label = {"done": "finished", "cancelled": "cancelled", "error": "failed"}[status]
        self.set_state(Text(f"{label} after {elapsed:.1f} s", style=style))
        self.log_line(Text(f"{label}: {message}", style=style.replace("bold ", "")))
