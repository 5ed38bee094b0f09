"""Running the IDAs of an assessment through the cache, and the design-mode search."""

from __future__ import annotations

import math
import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from frp_assess.assess.bar_catalogue import BarLayout
from frp_assess.assess.bars_as_built import choose_layout, largest_installable_ratio
from frp_assess.assess.cache import IdaCache, record_digest, task_key
from frp_assess.assess.floor_input import floor_record, in_ground_terms
from frp_assess.assess.inputs import AssessmentInputs, BuildingSettings, Material
from frp_assess.dynamics import (
    IdaResult,
    IdaSettings,
    IdaTask,
    Position,
    RockingModel,
    run_batch,
)
from frp_assess.motions import G, Record
from frp_assess.rules.record_sets import MEAN_OF_RECORDS_FROM, design_statistic, design_value

#: progress(stage, done, total)
Progress = Callable[[str, int, int], None]


@dataclass(frozen=True)
class CaseSummary:
    """IDA results of one case over the record set, accelerations in g."""

    results: tuple[IdaResult, ...]
    a_dyn: tuple[float | None, ...]  #: per record [g]; None = no collapse up to C_max
    a_dyn_bound: tuple[float, ...]  #: a_dyn, or C_max·PGA (a lower bound) where None [g]
    mean_a_dyn: float  #: [g]
    min_a_dyn: float  #: [g]
    mean_q: float
    design_a_dyn: float  #: mean with ≥ 7 records, else the least favourable [g]
    lower_bound: bool  #: some record did not collapse up to C_max: values are lower bounds


def design_value_rule(n_records: int) -> str:
    """How the design a_dyn is taken from ``n_records`` records (results.json wording)."""
    if design_statistic(n_records) == "mean":
        return "mean of the records"
    return f"least favourable record (fewer than {MEAN_OF_RECORDS_FROM} records)"


def summarise(results: Sequence[IdaResult], settings_max: float, a_rm_g: float) -> CaseSummary:
    """The case's IDA over the record set; ``a_rm_g`` [g] is the a_RM of the case's own model
    (:attr:`RockingModel.a_rm_g`, about its pivot: the edge, or moved inward by x/2 with
    ``pivot: crushing``), so that mean q = mean a_dyn / a_RM is the IDA's q."""
    a_dyn = tuple(None if r.a_dyn is None else r.a_dyn / G for r in results)
    # without a capacity: its lower bound, C_max (the first collapse) or the effective
    # intensity counted up to C_max (docs/model.md §11)
    bound = tuple(
        a
        if a is not None
        else (settings_max * r.c0 if r.bound_multiplier is None else r.bound_multiplier) * r.pga / G
        for a, r in zip(a_dyn, results, strict=True)
    )
    mean = sum(bound) / len(bound)
    low = min(bound)
    design = design_value(mean, low, len(bound))
    return CaseSummary(
        tuple(results),
        a_dyn,
        bound,
        mean,
        low,
        mean / a_rm_g,
        design,
        any(a is None for a in a_dyn),
    )


#: runs IDA tasks in order, as :func:`~frp_assess.dynamics.run_batch` (its signature)
BatchRunner = Callable[..., list[IdaResult]]


class IdaRunner:
    """Runs (models × records) IDAs, reusing and filling the cache.

    ``inputs`` gives the IDA settings and the building (or ``settings`` and ``building``, for a
    runner without an assessment: the study); ``batch`` computes the missing ones (default
    :func:`run_batch` on local threads; the study passes its executor's).

    The one place where a wall above the ground floor gets its floor motion: the IDA of each
    (model, record) pair runs on ``motions[i]`` (the floor motion at Z of ``records[i]``, or
    the record itself at ground level) and its result is restated in terms of the ground
    record (:func:`~frp_assess.assess.floor_input.in_ground_terms`: a_dyn = C·PGA_ground).
    """

    def __init__(
        self,
        records: Sequence[Record],
        inputs: AssessmentInputs | None,
        cache: IdaCache,
        *,
        jobs: int | None = None,
        cancel: threading.Event | None = None,
        settings: IdaSettings | None = None,
        building: BuildingSettings | None = None,
        batch: BatchRunner = run_batch,
    ) -> None:
        self.records = list(records)
        if settings is None:
            if inputs is None:
                raise ValueError("IdaRunner needs the assessment inputs or the IDA settings")
            settings = inputs.ida
        if inputs is not None:
            if building is not None and building != inputs.building:
                raise ValueError("IdaRunner: give the building through inputs or alone, not both")
            building = inputs.building
        self.settings = settings
        self.building = building
        self.batch = batch
        self.cache = cache
        self.jobs = jobs
        self.cancel = cancel
        #: the motion at the wall's base under each record (the floor's, for a building)
        self.motions = [floor_record(r, building) for r in self.records]
        self._hashes = [record_digest(r.acc, r.dt) for r in self.records]
        self.computed = 0
        self.reused = 0

    def run(
        self,
        models: Sequence[RockingModel],
        progress: Callable[[int, int], None] | None = None,
        on_pair: Callable[[int, int], None] | None = None,
        settings: IdaSettings | None = None,
    ) -> list[list[IdaResult]]:
        """IDA of every (model, record) pair, from the cache where possible.

        ``progress(done, total)`` counts finished pairs; ``on_pair(model_index, record_index)``
        is called once per pair as it finishes (cache hits first, then fresh results from the
        worker threads, each before the matching ``progress`` call).  ``settings``: the IDA
        search of these pairs, when not the runner's (the sensitivity's hunt step).
        """
        settings = self.settings if settings is None else settings
        n_rec = len(self.records)
        total = len(models) * n_rec
        out: list[IdaResult | None] = [None] * total
        keys: list[str] = []
        tasks: list[IdaTask] = []
        slots: list[int] = []
        for m_i, model in enumerate(models):
            for r_i in range(n_rec):
                key = task_key(model, self._hashes[r_i], settings, self.building)
                hit = self.cache.get(key)
                if hit is not None:
                    out[m_i * n_rec + r_i] = hit
                else:
                    motion = self.motions[r_i]
                    keys.append(key)
                    tasks.append(IdaTask(model, motion.acc, motion.dt, settings))
                    slots.append(m_i * n_rec + r_i)
        hits = total - len(tasks)
        self.reused += hits
        if on_pair is not None:
            fresh_slots = set(slots)
            for slot in range(total):
                if slot not in fresh_slots:
                    on_pair(*divmod(slot, n_rec))
        if progress is not None:
            progress(hits, total)

        def ground_terms(i: int, res: IdaResult) -> IdaResult:
            if self.building is None:
                return res
            return in_ground_terms(res, self.records[slots[i] % n_rec].pga)

        def on_result(i: int, res: IdaResult) -> None:
            self.cache.put(keys[i], ground_terms(i, res))
            if on_pair is not None:
                on_pair(*divmod(slots[i], n_rec))

        fresh = self.batch(
            tasks,
            jobs=self.jobs,
            on_result=on_result,
            cancel=self.cancel,
            progress=None if progress is None else (lambda d, n: progress(hits + d, total)),
        )
        self.computed += len(tasks)
        for i, (slot, res) in enumerate(zip(slots, fresh, strict=True)):
            out[slot] = ground_terms(i, res)
        results = [r for r in out if r is not None]
        return [results[i * n_rec : (i + 1) * n_rec] for i in range(len(models))]


@dataclass(frozen=True)
class DesignResult:
    material: Material
    position: Position
    ratio: float | None  #: smallest ratio meeting the target [‰], None if none in range
    summary: CaseSummary | None
    capacity_demand: float | None
    message: str
    #: the bars that build ``ratio`` (installed ratio ≥ ratio), None if no ratio was found
    layout: BarLayout | None = None
    #: the ratio the model used for ``ratio`` [‰]: installed, or ``ratio`` with
    #: ``bars.whole_bars: false``
    ratio_model: float | None = None


def bisect_boundary(lo: int, hi: int, on_lo_side: Callable[[int], bool]) -> tuple[int, int]:
    """Narrow the grid indices ``lo`` < ``hi`` (``lo`` on one side of a monotone predicate,
    ``hi`` on the other) to neighbours ``(lo, hi)``, halving: ``on_lo_side(mid)`` says which
    end ``mid`` replaces.  The design search uses it for the pivot cap only (the installed
    ratio is monotone along the grid; capacity is not, so the target is not bisected)."""
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if on_lo_side(mid):
            lo = mid
        else:
            hi = mid
    return lo, hi


def design_search(
    runner: IdaRunner,
    inputs: AssessmentInputs,
    material: Material,
    position: Position,
    demand_g: float,
    screen: Callable[[RockingModel], bool] | None = None,
    *,
    target: float | None = None,
    strict: bool = False,
) -> DesignResult:
    """Smallest ρ on the grid of ``resolution`` within ``ratio_range`` that passes every
    deciding check: ``screen(model)`` (the time-history checks,
    :func:`frp_assess.assess.verdict_pipeline.time_history_screen`; None: none) and the IDA's design
    capacity/demand ≥ the target (``demand_g`` = FC·a_g·S [g]; ``target`` [-] the ζ_E the
    category of the intervention asks of the IDA, above it when ``strict``; None: the
    assessment's ``inputs.target``).  Capacity is not assumed to
    grow with ρ (it does not: a stiffer bar can break sooner, a heavier one move the pivot):
    the grid is walked from the bottom up and the first ratio that passes is the answer, so
    every smaller grid ratio was checked and failed.

    Each grid ratio is built in whole bars (:func:`~frp_assess.assess.bars_as_built.choose_layout`,
    the diameter chosen by the least installed ratio) and the model runs with the installed
    ratio (with ``bars.whole_bars``), so the answer's layout installs at least the ratio found
    and capacity/demand is that of the bars as built.  The installed ratio never decreases
    along the grid (each size's rounding is monotone, and a size that stops fitting the
    spacing rule never comes back).  Grid ratios beyond the largest installable one are left
    out of the search; the message says so.  (No ratio is left out for the masonry at the
    base: a toe that crushes is the IDA's failure mode, docs/model.md §1.1.)
    """
    assert inputs.design is not None
    goal = inputs.target if target is None else target
    lo_r, hi_r = inputs.design.ratio_range
    res = inputs.design.resolution
    grid_lo = math.ceil(lo_r / res - 1e-9)
    grid_hi = math.floor(hi_r / res + 1e-9)
    top_ratio = largest_installable_ratio(
        inputs.bars, inputs.thickness, inputs.length, material.name
    )
    capped = grid_hi * res > top_ratio * (1.0 + 1e-12)
    if capped:
        grid_hi = math.floor(top_ratio / res + 1e-9)
    hi_shown = grid_hi * res if capped else hi_r
    cap_note = (
        f" (the search stops at {grid_hi * res:g} ‰: the largest {material.name} bar at "
        f"bars.min_spacing installs {top_ratio:.3g} ‰)"
        if capped
        else ""
    )
    cache: dict[int, CaseSummary] = {}

    def layout(k: int) -> BarLayout:
        return choose_layout(
            inputs.bars, inputs.thickness, inputs.length, material.name, position, k * res
        )

    def model_ratio(k: int) -> float:
        return layout(k).ratio_installed if inputs.bars.whole_bars else k * res

    def model(k: int) -> RockingModel:
        return inputs.model_of(material, position, model_ratio(k))

    def evaluate(k: int) -> CaseSummary:
        if k not in cache:
            m = model(k)
            cache[k] = summarise(runner.run([m])[0], inputs.ida.max_multiplier, m.a_rm_g)
        return cache[k]

    # the grid from the bottom up, no assumption that capacity grows with the ratio: the
    # first grid ratio that passes is the smallest (the cheap time-history screen first, the
    # IDA only where it passes)
    best: tuple[float, int] | None = None  # (largest IDA capacity/demand seen, its k)
    screened_out = 0
    found: int | None = None
    for k in range(grid_lo, grid_hi + 1):
        if screen is not None and not screen(model(k)):
            screened_out += 1
            continue
        cd_k = evaluate(k).design_a_dyn / demand_g
        if best is None or cd_k > best[0]:
            best = (cd_k, k)
        if cd_k > goal if strict else cd_k >= goal:
            found = k
            break
    if found is None:
        n = max(grid_hi - grid_lo + 1, 0)
        reach = ""
        if best is not None:
            reach = f" (the IDA reaches at most {best[0]:.2f}, at {best[1] * res:g} ‰)"
        screen_note = (
            f"; the time-history check fails at {screened_out} of the {n} grid ratios"
            if screen is not None and screened_out
            else ""
        )
        return DesignResult(
            material,
            position,
            None,
            None if best is None else evaluate(best[1]),
            None if best is None else best[0],
            f"no ratio up to {hi_shown:g} ‰ passes every deciding check (IDA target "
            f"{goal:g}{', time history SLV and SLC' if screen is not None else ''})"
            + reach
            + screen_note
            + cap_note,
        )
    k = found
    s = evaluate(k)
    ratio = round(k * res, 6)
    if k == grid_lo:
        message = (
            f"ρ = {ratio:g} ‰, the lower end of ratio_range, already passes every deciding "
            f"check (a smaller ratio may too: lower ratio_range to find the smallest)"
        )
    else:
        message = (
            f"ρ = {ratio:g} ‰ is the smallest ratio on the grid (every {res:g} ‰, each one "
            "checked) passing every deciding check"
        )
    lay = layout(k)
    message += f"; built as {lay.note}"
    return DesignResult(
        material,
        position,
        ratio,
        s,
        s.design_a_dyn / demand_g,
        message + cap_note,
        layout=lay,
        ratio_model=model_ratio(k),
    )
