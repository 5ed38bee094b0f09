"""The study: cross product, shared unreinforced walls, outputs, resume, schema errors."""

from __future__ import annotations

import csv
import threading
from pathlib import Path

import pytest

from frp_assess.assess.cache import IdaCache, record_digest, task_key
from frp_assess.assess.runner import IdaRunner
from frp_assess.dynamics import ida
from frp_assess.errors import Cancelled, InputError
from frp_assess.study import StudyPlan, load_study, parse_study, read_summary, run_study
from frp_assess.study.comparison import compare
from frp_assess.study.run import LocalExecutor
from tests.study.conftest import TINY


def _rows(path: Path) -> list[dict[str, str]]:
    with path.open(encoding="utf-8", newline="") as fh:
        return list(csv.DictReader(fh))


def test_cross_product_counts_and_shared_unreinforced():
    study = parse_study(
        dict(
            TINY,
            height=[3.0, 4.0, 5.0],
            alpha_deg=[5.0, 7.5],
            ratio=[1.0, 2.0, 3.0],
            material=["GFRP", "CFRP"],
            position=["centred", "external"],
            mechanism=["one-sided", "two-sided"],
            spectrum=["A1", "A2"],
        )
    )
    plan = StudyPlan(study)
    walls = 3 * 2 * 2 * 2  # H × α × mechanism × spectrum
    assert plan.n_unreinforced == walls
    assert plan.n_reinforced == walls * 2 * 2 * 3
    assert len(plan) == walls * (1 + 12)
    cases = list(plan.cases())
    keys = {
        (c.spectrum, c.mechanism, c.height, c.alpha_deg, c.material, c.position, c.ratio)
        for c in cases
    }
    assert len(keys) == len(cases)  # no duplicates
    for c in cases:
        u = plan.case(c.unreinforced_index)
        assert u.material is None and u.unreinforced_index == u.index <= c.index
        assert (u.spectrum, u.mechanism, u.height, u.alpha_deg) == (
            c.spectrum,
            c.mechanism,
            c.height,
            c.alpha_deg,
        )


def test_paper_table_1_has_2052_cases():
    plan = StudyPlan(load_study(Path(__file__).parents[2] / "projects" / "paper-study.yaml"))
    assert (len(plan), plan.n_unreinforced) == (2052, 108)


def test_summary_is_consistent_with_long_csv(tmp_path, tiny_study, records):
    stats = run_study(tiny_study, tmp_path, jobs=2, records=records)
    assert stats.cases == 2 * (1 + 2) and stats.computed == stats.cases * 3
    long = _rows(tmp_path / "long.csv")
    summary = read_summary(tmp_path / "summary.csv")
    assert len(long) == 6 * 3 and len(summary) == 6
    for s in summary:
        mine = [r for r in long if r["case"] == s["case"]]
        assert len(mine) == 3 and s["lower_bound"] == "no"
        mean = sum(float(r["a_dyn_g"]) for r in mine) / 3
        assert float(s["mean_a_dyn_g"]) == pytest.approx(mean, rel=1e-12)
        assert float(s["mean_q"]) == pytest.approx(mean / float(s["a_rm_g"]), rel=1e-12)
        base = next(u for u in summary if u["case"] == s["unreinforced_case"])
        assert base["material"] == "" and base["height_m"] == s["height_m"]
        assert float(s["improvement"]) == pytest.approx(
            float(s["mean_a_dyn_g"]) / float(base["mean_a_dyn_g"]), rel=1e-12
        )
    # the improvement of the restrained wall is > 1
    rf = {
        (s["height_m"], s["ratio_permille"]): float(s["improvement"])
        for s in summary
        if s["material"]
    }
    assert all(v > 1.0 for v in rf.values())
    # with the paper's edge model it grows with ρ (with the study's default masonry, the
    # lowest f_m of Tab. C8.5.I, the toe of the CFRP 2 ‰ wall may crush first: docs/model.md
    # §1.1, capacity can fall with more bar only through crushing)
    edge_dir = tmp_path / "edge"
    run_study(parse_study({**TINY, "model": {"pivot": "edge"}}), edge_dir, jobs=2, records=records)
    edge = {
        (s["height_m"], s["ratio_permille"]): float(s["improvement"])
        for s in read_summary(edge_dir / "summary.csv")
        if s["material"]
    }
    for h in ("3.0", "4.0"):
        assert 1.0 < edge[(h, "1.0")] < edge[(h, "2.0")]


def test_one_row_equals_a_direct_ida(tmp_path, tiny_study, records):
    run_study(tiny_study, tmp_path, jobs=1, records=records)
    plan = StudyPlan(tiny_study)
    case = plan.case(2)  # H = 3 m, CFRP external 2 ‰
    rec = records["A2"][1]
    direct = ida(plan.model(case), rec.acc, rec.dt, plan.ida_settings)
    row = next(
        r for r in _rows(tmp_path / "long.csv") if r["case"] == "2" and r["record"] == rec.name
    )
    assert float(row["collapse_multiplier"]) == direct.collapse_multiplier
    assert int(row["runs"]) == direct.runs


def test_resume_after_interruption_computes_nothing_twice(tmp_path, tiny_study, records):
    total = 6 * 3
    cancel = threading.Event()
    seen: list[int] = []

    def progress(done: int, n: int) -> None:
        seen.append(done)
        if done >= 7:  # mid-way through the second chunk
            cancel.set()

    with pytest.raises(Cancelled):
        run_study(tiny_study, tmp_path, jobs=1, records=records, progress=progress, cancel=cancel)
    assert not (tmp_path / "summary.csv").exists()
    cached = len(list((tmp_path / ".cache").glob("*.json")))
    assert 7 <= cached < total
    second = run_study(tiny_study, tmp_path, jobs=2, records=records)
    assert second.computed == total - cached
    assert second.chunks_skipped >= 1
    assert second.computed + cached == total
    third = run_study(tiny_study, tmp_path, jobs=2, records=records)
    assert third.computed == 0 and third.chunks_skipped == third.chunks
    # and the results equal those of an uninterrupted run
    fresh = tmp_path / "fresh"
    run_study(tiny_study, fresh, jobs=2, records=records)
    assert (fresh / "long.csv").read_text() == (tmp_path / "long.csv").read_text()
    assert (fresh / "summary.csv").read_text() == (tmp_path / "summary.csv").read_text()


def test_same_cache_keys_as_the_assessment_runner(tmp_path, tiny_study, records):
    run_study(tiny_study, tmp_path, jobs=2, records=records)
    plan = StudyPlan(tiny_study)
    cache = IdaCache(tmp_path / ".cache")
    rec = records["A2"][0]
    key = task_key(plan.model(plan.case(0)), record_digest(rec.acc, rec.dt), plan.ida_settings)
    assert cache.get(key) is not None


def test_schema_rejects_unknown_keys_with_key_and_line(tmp_path):
    f = tmp_path / "s.yaml"
    f.write_text(
        "name: x\nheight: [3.0]\nalpha_deg: [7.5]\nspectrum: [A2]\n"
        "records:\n  count: 3\n  sed: 2\n",
        encoding="utf-8",
    )
    with pytest.raises(InputError) as err:
        load_study(f)
    msg = str(err.value)
    assert msg.startswith(f"{f}:7: records.sed: unknown key")
    assert "seed" in msg  # lists the allowed keys
    with pytest.raises(InputError, match="heights: unknown key"):
        parse_study(dict(TINY, heights=[3.0]))


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"thickness": [0.3]}, "exactly one of alpha_deg"),
        ({"material": ["KFRP"]}, "unknown material 'KFRP'"),
        ({"ratio": [1.0, 1.0]}, "repeated"),
        ({"alpha_deg": [50.0]}, "α < 45°"),
        ({"model": {"restitution": "elastic"}}, "model.restitution"),
    ],
)
def test_schema_errors_are_clear(change, message):
    with pytest.raises(InputError, match=message):
        StudyPlan(parse_study(dict(TINY, **change)))


def test_comparison_on_the_tiny_study(tmp_path, records):
    # the paper's claims, on the paper's model (pivot: edge; with the default masonry the toe
    # of the CFRP 2 ‰ wall crushes first, docs/model.md §1.1)
    run_study(parse_study({**TINY, "model": {"pivot": "edge"}}), tmp_path, jobs=2, records=records)
    table = {r.claim: r for r in compare(read_summary(tmp_path / "summary.csv"))}
    assert table["improvement grows with ρ"].verdict == "agrees"
    assert table["q of the unreinforced wall grows with α"].verdict == "not tested"
    head = table["headline: CFRP, ρ = 1 ‰ (one-sided, external, H = 3 m, α = 7.5°, A2)"]
    assert head.verdict in ("agrees", "differs") and head.deviation.endswith("%")


def test_the_study_runs_through_the_assessment_runner_on_its_executor(
    tmp_path, tiny_study, records
):
    """Every IDA of the study goes once through the executor given; the cache it fills is
    the one `frp-assess run` reads: the assessment's IdaRunner finds every pair there and
    gives the numbers of long.csv."""

    class Counting(LocalExecutor):
        tasks = 0

        def run(self, tasks, on_result, progress, cancel):
            Counting.tasks += len(tasks)
            super().run(tasks, on_result, progress, cancel)

    out = tmp_path / "study"
    stats = run_study(tiny_study, out, executor=Counting(1), records=records)
    assert Counting.tasks == stats.computed == 6 * 3 and stats.reused == 0

    def must_not_compute(tasks, **_):
        assert not tasks, f"{len(tasks)} IDAs not in the cache"
        return []

    plan = StudyPlan(tiny_study)
    runner = IdaRunner(
        records["A2"],
        None,
        IdaCache(out / ".cache"),
        settings=plan.ida_settings,
        batch=must_not_compute,
    )
    found = runner.run([plan.model(c) for c in plan.cases()])
    assert runner.computed == 0 and runner.reused == 6 * 3
    written = [r["collapse_multiplier"] for r in _rows(out / "long.csv")]
    assert written == [
        "" if r.collapse_multiplier is None else repr(r.collapse_multiplier)
        for case in found
        for r in case
    ]


def test_a_runner_needs_inputs_or_settings(records):
    with pytest.raises(ValueError, match="inputs or the IDA settings"):
        IdaRunner(records["A2"], None, IdaCache(None))


def test_a_chunk_found_in_the_cache_does_not_call_the_executor():
    from frp_assess.study.run import executor_batch

    class Refusing(LocalExecutor):
        def run(self, tasks, on_result, progress, cancel):
            raise AssertionError("the executor was called with nothing to do")

    assert executor_batch(Refusing(1))([]) == []
