"""The Site tab: the elastic spectrum of the site and its live preview."""

from __future__ import annotations

from typing import Any

import numpy as np
from rich.text import Text
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.widgets import Static

from frp_assess.tui.field_specs import NTC_FIELDS, NTC_INPUT, SITE_FIELDS, SITE_TYPE, T1_FIELD
from frp_assess.tui.fields import FieldRow, section_error
from frp_assess.tui.plots import PlotView, Rule, Series

#: the preview's period range [s]
T_MAX = 4.0


def ntc_parameters(spectrum: Any) -> str:
    """The line 'a_g = … g, F0 = …, T_C* = … s' of an NTC 2018 spectrum (derived from the
    coordinates, or as typed), with a newline; "" for another kind of spectrum."""
    p = getattr(spectrum, "parameters", None) or {}
    if getattr(spectrum, "kind", "") != "ntc2018" or not {"ag", "F0", "Tc_star"} <= set(p):
        return ""
    return f"a_g = {p['ag']:.4f} g, F0 = {p['F0']:.3f}, T_C* = {p['Tc_star']:.3f} s\n"


class SitePane(VerticalScroll):
    """The elastic spectrum of the site and its live preview."""

    def compose(self) -> ComposeResult:
        with Horizontal(classes="columns"):
            with Vertical(classes="col-left col-narrow"):
                yield Static("Elastic spectrum (5 % damping)", classes="section-title")
                yield section_error("err-site")
                yield FieldRow(SITE_TYPE)
                for kind, specs in SITE_FIELDS.items():
                    with Vertical(classes="variant", id=f"var-spectrum-{kind}"):
                        if kind == "ntc2018":  # by parameters or by coordinates
                            yield FieldRow(NTC_INPUT)
                            for given_by, ntc_specs in NTC_FIELDS.items():
                                with Vertical(classes="variant", id=f"var-ntc-{given_by}"):
                                    for spec in ntc_specs:
                                        yield FieldRow(spec)
                        for spec in specs:
                            yield FieldRow(spec)
                yield FieldRow(T1_FIELD)
                yield Static("", id="spectrum-info", classes="derived")
            with Vertical(classes="col-right"):
                yield PlotView(id="spectrum-plot")

    def on_mount(self) -> None:
        self.shown: Any = None

    def show_spectrum(self, spectrum: Any, t1: Any, warning: str = "") -> None:
        """Plot the spectrum (Se [g] against T [s]) with the period T1 [s] of the checks;
        ``spectrum`` is a string when it cannot be built (the reason); ``warning`` the site's
        (near Italy's land border), shown under the values."""
        key = (
            spectrum if isinstance(spectrum, str) else (spectrum, spectrum.description, t1, warning)
        )
        if key == self.shown:
            return
        self.shown = key
        plot = self.query_one("#spectrum-plot", PlotView)
        info = self.query_one("#spectrum-info", Static)
        if isinstance(spectrum, str):
            plot.show_message(f"no preview: {spectrum}")
            info.update("")
            return
        periods = np.linspace(0.0, T_MAX, 321)
        sa = spectrum.sa(periods)
        rules = (
            [Rule(float(t1), "x", "yellow", f"T1 = {t1:g} s")]
            if isinstance(t1, int | float) and not isinstance(t1, bool) and 0 < t1 <= T_MAX
            else []
        )
        plot.show(
            [Series(periods.tolist(), sa.tolist(), style="cyan", label="Se(T)")],
            x_range=(0.0, T_MAX),
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
                (ntc_parameters(spectrum), ""),
                (corners, "dim"),
                (f"\nwarning: {warning}" if warning else "", "bold yellow"),
            )
        )
