"""Bad inputs keep the promise: exit code 2, one located line per problem, no traceback,
nothing written.

One row per bad input: the files it needs, the command line, the expected fragment of the
first stderr line and, for problems inside a file, its line and key.  The CLI runs in-process
(``frp_assess.cli.main``).  Rows are grouped by the class of problem of issue 13: non-finite
numbers, unbounded work, several problems at once, study files, record names, record files,
the YAML level, parser edges and command-line arguments.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import pytest

from frp_assess.cli import main
from tests.config.test_study_file import STUDY  # a valid study file

#: a valid project (line numbers matter: rows point at them)
BASE = """\
project: {name: Bad input}
wall:
  thickness: 0.3
  height: 3.0
  length: 1.0
  masonry: rubble-stone
  mechanism: one-sided
seismic:
  spectrum: {type: preset, name: A2}
  records:
    artificial: {count: 3, seed: 1, duration: 14.0, dt: 0.01}
analysis:
  ida: {step_ratio: 1.1, tolerance: 0.005, max_multiplier: 100}
  target: 1.0
costs: {currency: EUR, installation_per_metre: 0}
"""

#: a building block appended to BASE (lines 16-19; the last line is formatted in)
BUILDING = "building:\n  height: 10.0\n  storeys: 3\n  {}\n"

FILES = """\
    files:
      - {path: r1.txt}
      - {path: r2.txt}
"""
TWO_COLUMN = "".join(f"{0.01 * k:.2f} {0.1 * (-1) ** k:.3f}\n" for k in range(50))
FIFO = "<fifo>"  #: a file content that stands for a named pipe
WALL_ARGS = ("--thickness", "0.3", "--height", "3", "--mechanism", "one-sided")


def sub(old: str, new: str, text: str = BASE) -> str:
    """``text`` with ``old`` replaced (which must be there) by ``new``."""
    assert old in text, old
    return text.replace(old, new, 1)


def with_files(*items: str) -> str:
    """BASE with recorded files instead of artificial records."""
    listing = "    files:\n" + "".join(f"      - {item}\n" for item in items)
    return sub("    artificial: {count: 3, seed: 1, duration: 14.0, dt: 0.01}\n", listing)


@dataclass(frozen=True)
class Row:
    id: str
    args: tuple[str, ...]  #: {p}: the project/study file, {d}: the folder, {out}: output
    expect: str  #: fragment of the first stderr line
    text: str | bytes | None = None  #: content of {p} (p.yaml)
    line: int | None = None  #: line of the first problem in {p}
    key: str | None = None  #: key of the first problem
    problems: int = 1  #: number of stderr lines
    files: tuple[tuple[str, str | bytes], ...] = ()  #: more files in {d}
    path: str = "{p}"  #: the file the first line names (None: not a file's problem)
    sparse: int = 0  #: if > 0, the extra files are this many bytes (sparse, no disk used)


def validate(id: str, text: str | bytes, expect: str, line: int | None, key: str | None,
             problems: int = 1, **kw: object) -> Row:  # fmt: skip
    return Row(id, ("validate", "{p}"), expect, text, line, key, problems, **kw)  # type: ignore[arg-type]


def run(id: str, text: str | bytes, expect: str, line: int | None, key: str | None,
        **kw: object) -> Row:  # fmt: skip
    args = ("run", "{p}", "--out", "{out}", "--no-pdf")
    return Row(id, args, expect, text, line, key, **kw)  # type: ignore[arg-type]


def cli(id: str, *args: str, expect: str, **kw: object) -> Row:
    return Row(id, args, expect, path="", **kw)  # type: ignore[arg-type]


FINITE = "expected a finite number, found"
ROWS: list[Row] = [
    # --- 1. every number finite, in project and study files -------------------------------
    validate(
        "height-1e400", sub("height: 3.0", "height: 1e400"), f"{FINITE} inf", 4, "wall.height"
    ),
    run("height-1e400-run", sub("height: 3.0", "height: 1e400"), f"{FINITE} inf", 4, "wall.height"),
    validate(
        "thickness-nan",
        sub("thickness: 0.3", "thickness: .nan"),
        f"{FINITE} nan",
        3,
        "wall.thickness",
    ),
    validate("length-inf", sub("length: 1.0", "length: .inf"), f"{FINITE} inf", 5, "wall.length"),
    run(
        "length-minus-inf", sub("length: 1.0", "length: -.inf"), f"{FINITE} -inf", 5, "wall.length"
    ),
    validate(
        "target-inf", sub("target: 1.0", "target: .inf"), f"{FINITE} inf", 14, "analysis.target"
    ),
    validate(
        "max-multiplier-inf",
        sub("max_multiplier: 100", "max_multiplier: .Inf"),
        f"{FINITE} inf",
        13,
        "analysis.ida.max_multiplier",
    ),
    validate(
        "installation-inf",
        sub("installation_per_metre: 0", "installation_per_metre: .inf"),
        f"{FINITE} inf",
        15,
        "costs.installation_per_metre",
    ),
    validate(
        "price-inf",
        BASE + "materials:\n  GFRP: {price: .inf}\n",
        f"{FINITE} inf",
        17,
        "materials.GFRP.price",
    ),
    # --- bars as built (docs/model.md §2.1): keys, catalogue, options that cannot be built
    validate(
        "bars-exposure",
        BASE + "bars: {exposure: marine}\n",
        "expected one of internal, external, aggressive, found 'marine'",
        16,
        "bars.exposure",
    ),
    validate(
        "bars-spacing-order",
        BASE + "bars: {min_spacing: 2.0, max_spacing: 1.0}\n",
        "expected min_spacing <= max_spacing = 1 m, found 2",
        16,
        "bars.min_spacing",
    ),
    validate(
        "bars-catalogue-material",
        BASE + "bars:\n  catalogue:\n    - {material: XFRP, diameter: 12, area: 113}\n",
        "unknown material 'XFRP'",
        18,
        "bars.catalogue[0].material",
    ),
    validate(
        "bars-catalogue-twice",
        BASE
        + "bars:\n  catalogue:\n    - {material: GFRP, diameter: 12, area: 113}\n"
        + "    - {material: GFRP, diameter: 12, area: 110}\n",
        "GFRP Ø12 is already catalogue[0]",
        19,
        "bars.catalogue[1].diameter",
    ),
    validate(
        "bars-catalogue-area",
        BASE + "bars:\n  catalogue:\n    - {material: GFRP, diameter: 12, area: -1}\n",
        "expected a number in [0.5, 2000], found -1",
        18,
        "bars.catalogue[0].area",
    ),
    validate(
        "bars-anchorage-incomplete",
        BASE + "bars: {anchorage: {hole_clearance: 4}}\n",
        "missing required key 'bond_bar'",
        16,
        "bars.anchorage",
        problems=2,
    ),
    validate(
        "material-fibre",
        BASE + "materials:\n  GFRP: {fibre: steel}\n",
        "expected one of glass, carbon, aramid, basalt, found 'steel'",
        17,
        "materials.GFRP.fibre",
    ),
    validate(
        "option-diameter-not-in-catalogue",
        BASE + "interventions:\n  - {material: GFRP, position: centred, ratio: 1, diameter: 13}\n",
        "no GFRP bar of diameter 13 mm; available: 6, 8, 10, 12, 14, 16 mm",
        17,
        "interventions[0].diameter",
    ),
    run(
        "option-bars-too-close-run",
        BASE + "interventions:\n  - {material: GFRP, position: external, ratio: 3, diameter: 6}\n",
        "closer than bars.min_spacing = 0.1 m; choose a larger diameter",
        17,
        "interventions[0].diameter",
    ),
    validate(
        "sweep-ratio-not-installable",
        BASE + "interventions:\n  - sweep: {material: [GFRP], position: [centred], ratio: [1,8]}\n",
        "cannot be installed: the largest GFRP bar (Ø16) at bars.min_spacing = 0.1 m gives 6.7 ‰",
        17,
        "interventions[0].sweep.ratio[1]",
    ),
    run(
        "sweep-ratio-not-installable-run",
        BASE + "interventions:\n  - sweep: {material: [GFRP], position: [centred], ratio: [1,8]}\n",
        "cannot be installed",
        17,
        "interventions[0].sweep.ratio[1]",
    ),
    validate(
        "ratio-nan",
        BASE + "interventions:\n  - {material: GFRP, position: centred, ratio: .NaN}\n",
        f"{FINITE} nan",
        17,
        "interventions[0].ratio",
    ),
    validate(
        "spectrum-ag-inf",
        sub("{type: preset, name: A2}", "{type: ec8, ag: 1e999, ground: B}"),
        f"{FINITE} inf",
        9,
        "seismic.spectrum.ag",
    ),
    validate(
        "table-period-inf",
        sub(
            "{type: preset, name: A2}",
            "{type: table, periods: [0, .inf], accelerations: [0.3, 0.3]}",
        ),
        f"{FINITE} inf",
        9,
        "seismic.spectrum.periods[1]",
    ),
    validate(
        "count-inf",
        sub("count: 3", "count: 1e400"),
        "expected a whole number, found inf",
        11,
        "seismic.records.artificial.count",
    ),
    validate(
        "study-height-inf", sub("[3.0]", "[3.0, .inf]", STUDY), f"{FINITE} inf", 2, "height[1]"
    ),
    validate(
        "study-density-nan",
        STUDY + "materials:\n  X: {elastic_modulus: 40, ultimate_strain: 0.01, density: .nan}\n",
        f"{FINITE} nan",
        10,
        "materials.X.density",
    ),
    # --- 2. physically sensible bounds, before any work ------------------------------------
    validate(
        "tolerance-1e-300",
        sub("tolerance: 0.005", "tolerance: 1e-300"),
        "[0.0001, 0.1], found 1e-300",
        13,
        "analysis.ida.tolerance",
    ),
    run(
        "tolerance-1e-300-run",
        sub("tolerance: 0.005", "tolerance: 1e-300"),
        "[0.0001, 0.1], found 1e-300",
        13,
        "analysis.ida.tolerance",
    ),
    validate(
        "step-ratio-1-plus",
        sub("step_ratio: 1.1", "step_ratio: 1.0000000001"),
        "[1.01, 10], found 1.0000000001",
        13,
        "analysis.ida.step_ratio",
    ),
    validate(
        "max-multiplier-huge",
        sub("max_multiplier: 100", "max_multiplier: 1e6"),
        "(1, 1000], found 1000000",
        13,
        "analysis.ida.max_multiplier",
    ),
    validate(
        "dt-1e-9",
        sub("dt: 0.01", "dt: 1e-9"),
        "[0.0001, 0.05], found 1e-09",
        11,
        "seismic.records.artificial.dt",
    ),
    run(
        "dt-denormal",
        sub("dt: 0.01", "dt: 5e-324"),
        "[0.0001, 0.05], found 4.94065645841e-324",
        11,
        "seismic.records.artificial.dt",
    ),
    validate(
        "duration-1e6",
        sub("duration: 14.0", "duration: 1e6"),
        "[13.5, 600], found 1000000",
        11,
        "seismic.records.artificial.duration",
    ),
    validate(
        "count-1e6",
        sub("count: 3", "count: 1000000"),
        "[1, 100], found 1000000",
        11,
        "seismic.records.artificial.count",
    ),
    run(
        "seed-minus-1",
        sub("seed: 1", "seed: -1"),
        "found -1",
        11,
        "seismic.records.artificial.seed",
    ),
    validate(
        "tail-1e9",
        sub("  target: 1.0", "  target: 1.0\n  free_vibration_tail: 1e9"),
        "[0, 60], found 1000000000",
        15,
        "analysis.free_vibration_tail",
    ),
    validate(
        "options-2400",
        BASE
        + "interventions:\n  - sweep: {material: [GFRP, BFRP, CFRP], "
        + "position: [centred, external], ratio: ["
        + ", ".join(f"{0.01 * k:.2f}" for k in range(1, 401))
        + "]}\n",
        "the options expand to 2400, more than 2000",
        17,
        "interventions[0]",
    ),
    validate(
        "name-20000-chars",
        sub("{name: Bad input}", "{name: " + "x" * 20000 + "}"),
        "at most 200 characters, found 20000",
        1,
        "project.name",
    ),
    validate(
        "design-resolution",
        BASE + "design: {materials: [GFRP], resolution: 1e-12}\n",
        "[0.001, 1], found 1e-12",
        16,
        "design.resolution",
    ),
    validate(
        "study-tolerance",
        STUDY + "ida: {tolerance: 1e-300}\n",
        "[0.0001, 0.1], found 1e-300",
        9,
        "ida.tolerance",
    ),
    validate(
        "study-too-many-cases",
        sub(
            "ratio: [1.0]",
            "ratio: [" + ", ".join(f"{0.01 * k:.2f}" for k in range(1, 1001)) + "]",
            sub(
                "height: [3.0]",
                "height: [" + ", ".join(f"{3 + k / 100:.2f}" for k in range(200)) + "]",
                STUDY,
            ),
        ),
        "more than 100,000; split the study",
        1,
        None,
    ),
    # a wall above the ground floor: its base below the top of the building
    validate(
        "building-wall-base-above-the-roof",
        BASE + BUILDING.format("wall_base: 12.0"),
        "expected 0 <= Z < height H_b = 10 m, found 12",
        19,
        "building.wall_base",
    ),
    run(
        "building-wall-base-above-the-roof-run",
        BASE + BUILDING.format("wall_base: 10.0"),
        "expected 0 <= Z < height H_b = 10 m, found 10",
        19,
        "building.wall_base",
    ),
    validate(
        "building-wall-base-negative",
        BASE + BUILDING.format("wall_base: -1.0"),
        "expected a number >= 0, found -1",
        19,
        "building.wall_base",
    ),
    validate(
        "building-storeys-fraction",
        sub("storeys: 3", "storeys: 2.5", BASE + BUILDING.format("wall_base: 9.0")),
        "expected a whole number, found 2.5",
        18,
        "building.storeys",
    ),
    validate(
        "building-period-inf",
        BASE + BUILDING.format("wall_base: 9.0") + "  period: .inf\n",
        f"{FINITE} inf",
        20,
        "building.period",
    ),
    # --- 3. every problem of a file, in file order ------------------------------------------
    validate(
        "three-problems",
        sub(
            "mechanism: one-sided",
            "mechanism: sideways",
            sub("height: 3.0", "height: .inf", sub("thickness: 0.3", "thickness: -1")),
        ),
        "expected a number in [0.05, 5], found -1",
        3,
        "wall.thickness",
        problems=3,
    ),
    validate(
        "misspelt-key-once",
        sub("height: 3.0", "hieght: 3.0", sub("seed: 1", "seed: -2")),
        "unknown key 'hieght' (did you mean 'height'?)",
        4,
        "wall.hieght",
        problems=2,
    ),
    # --- 4. a study file is validated as a study -------------------------------------------
    validate(
        "study-unknown-key",
        sub("height:", "heigth:", STUDY),
        "unknown key 'heigth' (did you mean 'height'?)",
        2,
        "heigth",
    ),
    validate(
        "study-unknown-material",
        sub("[CFRP]", "[KFRP]", STUDY),
        "unknown material 'KFRP'",
        5,
        "material[0]",
    ),
    # --- 5. record names: unique and safe as file names ------------------------------------
    run(
        "name-dot-dot",
        with_files("{path: r1.txt, name: ../../evil}"),
        "not a safe file name: it contains /",
        12,
        "seismic.records.files[0].name",
        files=(("r1.txt", TWO_COLUMN),),
    ),
    validate(
        "name-absolute",
        with_files("{path: r1.txt, name: /tmp/evil}"),
        "not a safe file name",
        12,
        "seismic.records.files[0].name",
    ),
    validate(
        "name-backslash",
        with_files("{path: r1.txt, name: '..\\evil'}"),
        "not a safe file name: it contains \\",
        12,
        "seismic.records.files[0].name",
    ),
    validate(
        "name-hidden",
        with_files("{path: r1.txt, name: .hidden}"),
        "starts or ends with a dot",
        12,
        "seismic.records.files[0].name",
    ),
    validate(
        "name-empty",
        with_files("{path: r1.txt, name: ''}"),
        "it is empty",
        12,
        "seismic.records.files[0].name",
    ),
    run(
        "names-twice",
        with_files("{path: a/r.txt}", "{path: b/r.txt}"),
        "record name 'r' is already the name of files[0]",
        13,
        "seismic.records.files[1].path",
    ),
    validate(
        "names-twice-given",
        with_files("{path: r1.txt, name: Rec}", "{path: r2.txt, name: REC}"),
        "already the name of files[0]",
        13,
        "seismic.records.files[1].name",
    ),
    # --- 6/7. record files: plausible, readable, bounded --------------------------------------
    run(
        "record-fifo",
        with_files("{path: r1.txt}"),
        "is not a regular file",
        12,
        "seismic.records.files[0].path",
        files=(("r1.txt", FIFO),),
    ),
    run(
        "record-folder",
        with_files("{path: sub}"),
        "is a folder",
        12,
        "seismic.records.files[0].path",
        files=(("sub/x.txt", "1"),),
    ),
    run(
        "record-npts-1e400",
        with_files("{path: r.AT2}"),
        "NPTS must be a whole number, found inf",
        4,
        None,
        files=(("r.AT2", "a\nb\nc\nNPTS= 1e400, DT= 0.01 SEC\n0.1 0.2\n"),),
        path="{d}/r.AT2",
    ),
    cli(
        "check-npts-huge",
        "records",
        "check",
        "{d}/r.AT2",
        "--spectrum",
        "A2",
        expect="{d}/r.AT2:4: NPTS=3e+09 is more than 2,000,000 samples",
        files=(("r.AT2", "a\nb\nc\nNPTS= 3e9, DT= 0.01 SEC\n0.1 0.2\n"),),
    ),
    cli(
        "check-dt-tiny",
        "records",
        "check",
        "{d}/r.AT2",
        "--spectrum",
        "A2",
        expect="{d}/r.AT2:4: time step 1e-09 s is below 0.0001 s",
        files=(("r.AT2", "a\nb\nc\nNPTS= 2, DT= 1e-9 SEC\n0.1 0.2\n"),),
    ),
    cli(
        "check-fifo",
        "records",
        "check",
        "{d}/r.txt",
        "--spectrum",
        "A2",
        expect="{d}/r.txt: is not a regular file",
        files=(("r.txt", FIFO),),
    ),
    cli(
        "check-dev-zero",
        "records",
        "check",
        "/dev/zero",
        "--spectrum",
        "A2",
        "--format",
        "two-column",
        expect="/dev/zero: is not a regular file",
    ),
    cli(
        "check-decimal-comma-ambiguous",
        "records",
        "check",
        "{d}/r.txt",
        "--spectrum",
        "A2",
        expect="{d}/r.txt:1: '0,12' may be a decimal comma or two comma-separated columns",
        files=(("r.txt", "0,12\n-0,31\n0,45\n"),),
    ),
    cli(
        "check-mixed-decimal-marks",
        "records",
        "check",
        "{d}/r.csv",
        "--spectrum",
        "A2",
        expect="{d}/r.csv:2: a semicolon-separated table with both decimal points and "
        "decimal commas",
        files=(("r.csv", "t;a\n0.00;0,1\n0.01;0,2\n"),),
    ),
    # --- 7. the YAML level: bounded work, what is not a file, control characters ------------
    validate(
        "alias-bomb",
        "a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n"
        + "".join(
            f"{c}: &{c} [{', '.join([f'*{p}'] * 9)}]\n"
            for p, c in zip("abcdefgh", "bcdefghi", strict=True)
        ),
        "expands to more than 100,000 values",
        None,
        None,
    ),
    run(
        "alias-bomb-run",
        "a: &a [x, x, x, x, x, x, x, x, x, x]\n"
        + "".join(
            f"{c}: &{c} [{', '.join([f'*{p}'] * 10)}]\n"
            for p, c in zip("abcdefgh", "bcdefghi", strict=True)
        ),
        "expands to more than 100,000 values",
        None,
        None,
    ),
    validate(
        "recursive-alias", "wall: &w [*w]\n", "an alias '*name' used inside its own block", 1, None
    ),
    validate(
        "nesting-3000",
        "wall: " + "[" * 3000 + "]" * 3000 + "\n",
        "nesting deeper than 50 levels",
        1,
        None,
    ),
    run(
        "nesting-200-block",
        "".join(f"{' ' * i}k{i}:\n" for i in range(200)) + " " * 200 + "k: 1\n",
        "nesting deeper than 50 levels",
        50,
        None,
    ),
    cli("dev-zero", "validate", "/dev/zero", expect="/dev/zero: is not a regular file"),
    cli(
        "project-fifo",
        "validate",
        "{d}/p.yaml",
        expect="{d}/p.yaml: is not a regular file",
        files=(("p.yaml", FIFO),),
    ),
    cli("project-folder", "validate", "{d}", expect="{d}: is a folder, not a project file"),
    cli("tui-folder", "tui", "{d}", expect="{d}: is a folder, not a project file"),
    cli(
        "simulate-rtol-tiny",
        "simulate",
        *WALL_ARGS,
        "--rtol",
        "1e-20",
        "--record",
        "x",
        expect="argument --rtol: expected a number in [1e-12, 0.001], found 1e-20",
    ),
    cli(
        "simulate-collapse-unknown",
        "simulate",
        *WALL_ARGS,
        "--collapse",
        "overturn",
        "--record",
        "x",
        expect="argument --collapse: invalid choice: 'overturn'",
    ),
    cli(
        "tui-fifo",
        "tui",
        "{d}/p.yaml",
        expect="{d}/p.yaml: is not a regular file",
        files=(("p.yaml", FIFO),),
    ),
    cli(
        "tui-study-file",
        "tui",
        "{d}/s.yaml",
        expect="{d}/s.yaml: is a study file: the terminal UI edits project files",
        files=(("s.yaml", STUDY),),
    ),
    cli(
        "project-missing", "validate", "{d}/nope.yaml", expect="{d}/nope.yaml: no such project file"
    ),
    cli(
        "project-under-a-file",
        "validate",
        "{d}/f.yaml/p.yaml",
        expect="no such project file (a part of the path is a file)",
        files=(("f.yaml", "x: 1\n"),),
    ),
    validate(
        "project-3-mb",
        BASE + "# " + "x" * 3_000_000 + "\n",
        "is 3.0 MB; a project file is at most 2 MB",
        None,
        None,
    ),
    validate(
        "latin-1",
        sub("Bad input", "Caf\xe9").encode("latin-1"),
        "is not UTF-8 text (byte 0xe9)",
        1,
        None,
    ),
    validate(
        "raw-nul",
        sub("rubble-stone", "rubble\x00stone"),
        "control character U+0000 (NUL)",
        6,
        "wall.masonry",
    ),
    validate(
        "raw-esc",
        sub("rubble-stone", "rubble\x1b[31mstone"),
        "control character U+001B (ESC)",
        6,
        "wall.masonry",
    ),
    validate(
        "raw-esc-in-flow",
        sub("Bad input", "Bad \x1b[31minput"),
        "control character U+001B (ESC)",
        1,
        None,
    ),
    run(
        "raw-del",
        sub("rubble-stone", "rubble\x7fstone"),
        "control character U+007F (DEL)",
        6,
        "wall.masonry",
    ),
    validate(
        "escaped-nul",
        sub("{name: Bad input}", '{name: "Bad\\0input"}'),
        "control character U+0000",
        1,
        "project.name",
    ),
    validate(
        "escaped-lone-surrogate",
        sub("{name: Bad input}", '{name: Bad input, notes: "\\ud83d"}'),
        "control character U+D83D (a lone UTF-16 surrogate",
        1,
        "project.notes",
    ),
    validate(
        "bidi-override",
        sub("{name: Bad input}", '{name: "Bad \\u202einput"}'),
        "control character U+202E",
        1,
        "project.name",
    ),
    # --- 8. parser edges -------------------------------------------------------------------
    validate(
        "int-key",
        sub("  length: 1.0\n", "  length: 1.0\n  1: x\n"),
        "the key '1' is read as a number",
        6,
        "wall.1",
    ),
    validate("null-key", BASE + "~: 3\n", "the key '~' is read as null", 16, "~"),
    validate(
        "bool-key",
        sub("  length: 1.0\n", "  length: 1.0\n  yes: x\n"),
        "the key 'yes' is read as true/false",
        6,
        "wall.yes",
    ),
    validate(
        "octal-022",
        sub("count: 3", "count: 022"),
        "022 has a leading zero, which YAML reads as the octal number 18; write 22",
        11,
        "seismic.records.artificial.count",
    ),
    validate(
        "hex",
        sub("seed: 1", "seed: 0x1f"),
        "hexadecimal, binary or base-60",
        11,
        "seismic.records.artificial.seed",
    ),
    validate(
        "base-60",
        sub("duration: 14.0", "duration: 1:30"),
        "base-60",
        11,
        "seismic.records.artificial.duration",
    ),
    validate(
        "duplicate-merge",
        "x: &x {thickness: 0.3}\ny: &y {height: 3.0}\nwall:\n  <<: *x\n  <<: *y\n",
        "duplicate key '<<' (first defined on line 4)",
        5,
        "wall.<<",
    ),
    validate(
        "duplicate-key",
        sub("  length: 1.0\n", "  length: 1.0\n  height: 4\n"),
        "duplicate key 'height' (first defined on line 4)",
        6,
        "wall.height",
    ),
    cli(
        "three-columns-simulate",
        "simulate",
        *WALL_ARGS,
        "--record",
        "{d}/r.txt",
        expect="{d}/r.txt: dt: cannot read this record's time step (dt): it holds 3 numbers a line",
        files=(("r.txt", "0.1 0.2 0.3\n0.4 0.5 0.6\n"),),
    ),
    validate(
        "yaml-syntax-first",
        sub("mechanism: one-sided", "mechanism: [one-sided", sub("count: 3", "count: 022")),
        "YAML syntax error",
        None,
        None,
    ),
    # --- more files the tool reads: empty, wrong shape, other record formats ----------------
    validate("project-empty", "# nothing\n", "the project file is empty", 1, None),
    validate("project-a-list", "- wall\n- seismic\n", "expected a mapping of keys", 1, None),
    validate("study-empty", "", "the project file is empty", 1, None),
    validate(
        "number-yes",
        sub("length: 1.0", "length: yes"),
        "expected a number, found true",
        5,
        "wall.length",
    ),
    validate(
        "number-quoted",
        sub("length: 1.0", 'length: "1.0"'),
        "expected a number, found '1.0'",
        5,
        "wall.length",
    ),
    validate(
        "restitution-nan",
        sub("  target: 1.0", "  target: 1.0\n  restitution: .nan"),
        "expected energy, velocity or a number in (0, 1], found nan",
        15,
        "analysis.restitution",
    ),
    validate(
        "tab-indent", sub("  height: 3.0", "\theight: 3.0"), "indent with spaces, not tabs", 4, None
    ),
    validate(
        "one-column-dt-tiny",
        with_files("{path: r1.txt, format: one-column, dt: 1e-7}"),
        "[0.0001, 0.05], found 1e-07",
        12,
        "seismic.records.files[0].dt",
    ),
    run(
        "record-huge",
        with_files("{path: r1.txt}"),
        "a record file is at most 50 MB",
        None,
        None,
        files=(("r1.txt", b""),),
        path="{d}/r1.txt",
        sparse=50_000_001,
    ),
    run(
        "record-decimal-comma-ambiguous",
        with_files("{path: r1.txt}"),
        "may be a decimal comma",
        1,
        None,
        files=(("r1.txt", "0,1\n0,2\n"),),
        path="{d}/r1.txt",
    ),
    run(
        "record-three-columns",
        with_files("{path: r1.txt}"),
        "it holds 3 numbers a line",
        None,
        None,
        files=(("r1.txt", "1 2 3\n4 5 6\n"),),
        path="{d}/r1.txt",
    ),
    cli(
        "check-esm-dt-tiny",
        "records",
        "check",
        "{d}/r.asc",
        "--spectrum",
        "A2",
        expect="{d}/r.asc:1: time step 1e-09 s is below 0.0001 s",
        files=(("r.asc", "SAMPLING_INTERVAL_S: 1e-9\nUNITS: g\n0.1\n0.2\n"),),
    ),
    cli(
        "check-esm-ndata-huge",
        "records",
        "check",
        "{d}/r.asc",
        "--spectrum",
        "A2",
        expect="{d}/r.asc:2: NDATA is not a whole number: '1e400'",
        files=(("r.asc", "SAMPLING_INTERVAL_S: 0.01\nNDATA: 1e400\n0.1\n0.2\n"),),
    ),
    cli(
        "check-two-column-dt-tiny",
        "records",
        "check",
        "{d}/r.txt",
        "--spectrum",
        "A2",
        expect="{d}/r.txt:2: time step 1e-06 s is below 0.0001 s",
        files=(("r.txt", "0 0.1\n0.000001 0.2\n0.000002 0.1\n"),),
    ),
    cli(
        "check-folder",
        "records",
        "check",
        "{d}",
        "--spectrum",
        "A2",
        "--format",
        "two-column",
        expect="{d}: is a directory, not a record file",
    ),
    validate(
        "validate-reads-records",
        with_files("{path: r.AT2}"),
        "NPTS must be a whole number, found inf",
        4,
        None,
        files=(("r.AT2", "a\nb\nc\nNPTS= 1e400, DT= 0.01 SEC\n0.1 0.2\n"),),
        path="{d}/r.AT2",
    ),
    validate(
        "validate-record-without-dt",
        with_files("{path: r1.txt}"),
        "it holds 3 numbers a line",
        None,
        None,
        files=(("r1.txt", "1 2 3\n4 5 6\n"),),
        path="{d}/r1.txt",
    ),
    # --- 1/2. numeric command-line arguments ----------------------------------------------
    cli(
        "generate-count-1e6",
        "records",
        "generate",
        "--spectrum",
        "A2",
        "--count",
        "1e6",
        "--out",
        "{out}",
        expect="argument --count: expected a whole number, found '1e6'",
    ),
    cli(
        "generate-count-million",
        "records",
        "generate",
        "--spectrum",
        "A2",
        "--count",
        "1000000",
        "--out",
        "{out}",
        expect="argument --count: expected a whole number in [1, 100], found 1000000",
    ),
    cli(
        "generate-dt-1e-9",
        "records",
        "generate",
        "--spectrum",
        "A2",
        "--dt",
        "1e-9",
        "--out",
        "{out}",
        expect="argument --dt: expected a number in [0.0001, 0.05] s, found 1e-9",
    ),
    cli(
        "generate-duration-inf",
        "records",
        "generate",
        "--spectrum",
        "A2",
        "--duration",
        "inf",
        "--out",
        "{out}",
        expect="argument --duration: expected a finite number, found 'inf'",
    ),
    cli(
        "generate-duration-1e6",
        "records",
        "generate",
        "--spectrum",
        "A2",
        "--duration",
        "1e6",
        "--out",
        "{out}",
        expect="argument --duration: expected a number in (0, 600] s, found 1e6",
    ),
    cli(
        "generate-seed-negative",
        "records",
        "generate",
        "--spectrum",
        "A2",
        "--seed",
        "-1",
        "--out",
        "{out}",
        expect="argument --seed: expected a whole number in [0, 4294967295], found -1",
    ),
    cli(
        "generate-stationary-long",
        "records",
        "generate",
        "--spectrum",
        "A2",
        "--stationary",
        "30",
        "--out",
        "{out}",
        expect="--stationary: expected a stationary part shorter than --duration 25 s, found 30 s",
    ),
    cli(
        "simulate-height-1e400",
        "simulate",
        "--thickness",
        "0.3",
        "--height",
        "1e400",
        "--mechanism",
        "one-sided",
        "--record",
        "x",
        expect="argument --height: expected a finite number, found '1e400'",
    ),
    cli(
        "simulate-thickness-nan",
        "simulate",
        "--thickness",
        "nan",
        "--height",
        "3",
        "--mechanism",
        "one-sided",
        "--record",
        "x",
        expect="argument --thickness: expected a finite number, found 'nan'",
    ),
    cli(
        "simulate-tail-1e9",
        "simulate",
        *WALL_ARGS,
        "--record",
        "x",
        "--tail",
        "1e9",
        expect="argument --tail: expected a number in [0, 60] s, found 1e9",
    ),
    cli(
        "ida-ratio-inf",
        "ida",
        *WALL_ARGS,
        "--record",
        "x",
        "--modulus",
        "40",
        "--ultimate-strain",
        "0.01",
        "--position",
        "centred",
        "--ratio",
        "inf",
        expect="argument --ratio: expected a finite number, found 'inf'",
    ),
    cli(
        "ida-unit-weight",
        "ida",
        *WALL_ARGS,
        "--record",
        "x",
        "--unit-weight",
        "1e5",
        expect="argument --unit-weight: expected a number in [5, 30] kN/m³, found 1e5",
    ),
    cli(
        "check-t1-nan",
        "records",
        "check",
        "x",
        "--spectrum",
        "A2",
        "--t1",
        "nan",
        expect="argument --t1: expected a finite number, found 'nan'",
    ),
    cli(
        "check-dt-zero",
        "records",
        "check",
        "x",
        "--spectrum",
        "A2",
        "--dt",
        "0",
        expect="argument --dt: expected a number in [0.0001, 0.05] s, found 0",
    ),
    # --- the masonry at the pivot (issue 16 §1, docs/model.md §1.1) ------------------------
    validate(
        "compressive-strength-zero",
        sub("  masonry: rubble-stone\n", "  masonry: rubble-stone\n  compressive_strength: 0\n"),
        "expected a number in [0.1, 100], found 0",
        7,
        "wall.compressive_strength",
    ),
    run(
        "compressive-strength-inf-run",
        sub("  masonry: rubble-stone\n", "  masonry: rubble-stone\n  compressive_strength: .inf\n"),
        f"{FINITE} inf",
        7,
        "wall.compressive_strength",
    ),
    validate(
        "compressive-strength-with-unit",
        sub(
            "  masonry: rubble-stone\n", "  masonry: rubble-stone\n  compressive_strength: 3 MPa\n"
        ),
        "expected a number, found '3 MPa'",
        7,
        "wall.compressive_strength",
    ),
    run(
        "pivot-unknown",
        sub("analysis:\n", "analysis:\n  pivot: middle\n"),
        "expected one of edge, crushing, found 'middle'",
        13,
        "analysis.pivot",
    ),
]


def snapshot(folder: Path) -> dict[str, tuple[int, int]]:
    """Every file and folder under ``folder`` with its size and modification time."""
    out: dict[str, tuple[int, int]] = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            info = os.lstat(os.path.join(root, name))
            out[os.path.relpath(os.path.join(root, name), folder)] = (
                info.st_size,
                info.st_mtime_ns,
            )
    return out


def test_the_table_is_large_and_covers_every_class() -> None:
    assert len(ROWS) >= 60
    assert len({row.id for row in ROWS}) == len(ROWS)
    commands = {row.args[0] for row in ROWS}
    assert {"validate", "run", "records", "simulate", "ida"} <= commands


@pytest.mark.parametrize("row", ROWS, ids=[row.id for row in ROWS])
def test_bad_input(row: Row, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    work = tmp_path / "work"
    work.mkdir()
    if row.text is not None:
        data = row.text if isinstance(row.text, bytes) else row.text.encode("utf-8")
        (work / "p.yaml").write_bytes(data)
    for name, content in row.files:
        target = work / name
        target.parent.mkdir(parents=True, exist_ok=True)
        if content == FIFO:
            os.mkfifo(target)
        else:
            target.write_bytes(content.encode("utf-8") if isinstance(content, str) else content)
        if row.sparse:
            with open(target, "r+b") as handle:
                handle.truncate(row.sparse)
    out = tmp_path / "out"
    names = {"p": str(work / "p.yaml"), "d": str(work), "out": str(out)}
    args = [a.format(**names) for a in row.args]
    before = snapshot(tmp_path)
    outside = [tmp_path.parent / "evil.AT2", tmp_path / "evil.AT2", Path("/tmp/evil.AT2")]
    existed = [p.exists() for p in outside]

    try:
        code = main(args)
    except SystemExit as exc:  # argparse refuses an argument by exiting
        code = exc.code

    captured = capsys.readouterr()
    err = captured.err.splitlines()
    assert code == 2, captured
    assert "Traceback" not in captured.err
    assert len(err) == row.problems, err
    first = err[0]
    assert row.expect.format(**names) in first, first
    if row.path:
        where = f"frp-assess: error: {row.path.format(**names)}"
        if row.line is not None:
            where += f":{row.line}: "
            assert first.startswith(where + (f"{row.key}: " if row.key else "")), first
        assert first.startswith(where), first
        for line in err:  # every problem names the file (and its line, if it has one)
            assert line.startswith(f"frp-assess: error: {row.path.format(**names)}"), line
    else:
        assert first.startswith("frp-assess"), first
    assert not out.exists(), "an output folder was written"
    assert snapshot(tmp_path) == before, "a file was written or changed"
    assert [p.exists() for p in outside] == existed, "a record was written outside the output"


def test_problems_come_in_file_order(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    text = sub(
        "seed: 1",
        "seed: -1",
        sub("height: 3.0", "height: .inf", sub("thickness: 0.3", "thickness: -1")),
    )
    text = sub("target: 1.0", "target: 0", sub("mechanism: one-sided", "mechanism: x", text))
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    assert main(["validate", str(path)]) == 2
    lines = [int(e.split(":")[3]) for e in capsys.readouterr().err.splitlines()]
    assert lines == [3, 4, 7, 11, 14]
