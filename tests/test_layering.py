"""Import rules as one table: what each package of frp_assess may import (docs/architecture.md).

Checked on the source (import statements of every module, sub-packages included, those under
``if TYPE_CHECKING:`` too), not on ``sys.modules``: numba itself imports PyYAML.  Dependencies
point one way: the numerical core (``dynamics``, ``motions``) knows nothing of files, schemas
or screens; ``config`` turns files into checked values; ``assess`` runs them; ``app`` is the
application service, the one door of the interfaces: ``cli`` and ``tui`` import ``app`` and a
few leaves (:data:`INTERFACE_LEAVES`), nothing else of the package.
"""

from __future__ import annotations

import ast
import os
import subprocess
import sys
from pathlib import Path

import pytest

import frp_assess

PACKAGE = Path(frp_assess.__file__).parent

#: What the interfaces (cli, tui) may import besides ``app`` and each other: the typed results
#: and small leaves, each with why.  Nothing of the numerics, the loader, the assessment or the
#: study runner: they go through ``app``.  A dotted name allows that module only (not its
#: package), so ``config.schema`` does not open ``config.loader``.
INTERFACE_LEAVES: dict[str, str] = {
    "": "frp_assess.__version__ (the --version flag)",
    "results": "the typed results (frozen dataclasses) the screens and tables show",
    "errors": "InputError, Cancelled: what every command catches",
    "numbers": "the number formats and result sentences every output shares",
    "text_safety": "escaping of user text on the terminal",
    "io_utils": "atomic writes of a file the user names (`new`, `simulate --out`)",
    "output_set": "checking an output folder or file before anything runs",
    "config.schema": "form metadata: the project file's blocks, fields, bounds and help",
    "dynamics.options": "option metadata: default, range, unit and help of each model option",
    "rules": "the code's clauses and constants (pure functions of numbers), which every layer "
    "may call so that each is written once (docs/architecture.md)",
    # justified beyond the brief's list:
    "config.library": "the FRP and masonry catalogues (pure data) the forms offer by name",
    "config.messages": "Loc, a field's key path, and the loader's wording of a problem, so "
    "that a form field shows its problem in the words `validate` prints (pydantic only)",
}

#: package -> the frp_assess packages it may import ("" is frp_assess itself, for __version__;
#: "a.b" is the module a.b only)
# fmt: off
INTERNAL: dict[str, set[str]] = {
    "errors": set(),
    # the code's clauses and material rules: a leaf, nothing of frp_assess below them, and
    # every layer may import it (each rule written once)
    "rules": set(),
    "results": {"errors", "rules"},  # the typed results (stdlib dataclasses): no numerics
    "numbers": {"results", "rules"},
    "text_safety": set(),
    "libm": set(),  # elementwise C-library functions of arrays (the same bits on every CPU)
    "io_utils": {"errors"},
    "output_record": {"errors", "io_utils"},  # what the tool wrote in a results folder
    "output_set": {"errors", "io_utils", "output_record"},
    "dynamics": {"errors", "libm", "motions", "rules"},
    "motions": {"errors", "io_utils", "libm", "rules"},
    "config": {"errors", "io_utils", "rules", "dynamics", "motions"},
    "assess": {
        "", "errors", "io_utils", "libm", "numbers", "text_safety", "rules", "dynamics",
        "motions", "config", "results",
    },
    "report": {"errors", "io_utils", "numbers", "text_safety", "results", "rules"},
    "study": {
        "", "errors", "io_utils", "dynamics", "motions", "config", "assess", "report", "results",
        "rules",
    },
    # the application service: everything below it, and nothing imports it but the interfaces
    "app": {
        "", "errors", "io_utils", "output_record", "output_set", "text_safety", "dynamics",
        "motions", "config", "assess", "report", "study", "results", "rules",
    },
    "api": {"app"},  # the former application API: a re-export of app, kept for old imports
    # the interfaces: the one door (app) and the leaves above, nothing else
    "tui": {"app", *INTERFACE_LEAVES},
    "cli": {"app", "tui", *INTERFACE_LEAVES},  # `frp-assess tui` starts the TUI
    "__main__": {"cli"},
    "__init__": set(),
}
# fmt: on
#: (report reads nothing but results.json: tests/report/test_report.py checks it further)
#: third-party libraries that only some packages may use
RESTRICTED = {
    "textual": {"tui"},
    "rich": {"cli", "tui", "text_safety"},
    "reportlab": {"report", "study"},
    "pydantic": {"config", "study", "tui"},
    "pydantic_core": {"config", "tui"},
    "yaml": {"config", "study"},
    "ruamel": {"config"},
    "dask": {"study"},
}


def imported_modules(path: Path) -> set[str]:
    """Every module ``path`` imports, absolute: relative imports resolved, and
    ``from frp_assess import x`` counted as ``frp_assess.x`` (``__version__``: frp_assess)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            module = node.module or ""
            if node.level:
                here = ["frp_assess", *path.relative_to(PACKAGE).with_suffix("").parts]
                base = here[: len(here) - node.level]
                module = ".".join([*base, module] if module else base)
            if module == "frp_assess":
                names.update(
                    module if a.name == "__version__" else f"{module}.{a.name}" for a in node.names
                )
            elif module:
                names.add(module)
    return names


def package_of(path: Path) -> str:
    parts = path.relative_to(PACKAGE).parts
    return parts[0].removesuffix(".py")


MODULES = sorted(PACKAGE.rglob("*.py"))


def allowed(own: str, name: str) -> bool:
    """May package ``own`` import the frp_assess module ``name``?"""
    target = name.removeprefix("frp_assess").removeprefix(".")
    if target.split(".")[0] == own:
        return True
    return any(target == rule or (rule and target.startswith(f"{rule}.")) for rule in INTERNAL[own])


def import_problems(path: Path) -> list[str]:
    """The imports of ``path`` that break the table, sorted."""
    own = package_of(path)
    bad = []
    for name in imported_modules(path):
        top = name.split(".")[0]
        if top == "frp_assess":
            if not allowed(own, name):
                bad.append(name)
        elif top in RESTRICTED and own not in RESTRICTED[top]:
            bad.append(name)
    return sorted(bad)


def test_every_package_has_a_rule() -> None:
    assert {package_of(p) for p in MODULES} <= set(INTERNAL)


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_imports_follow_the_table(path: Path) -> None:
    bad = import_problems(path)
    assert not bad, f"{package_of(path)} may not import {bad}"


@pytest.mark.parametrize(
    "line",
    [
        "from frp_assess.assess.inputs import AssessmentInputs",
        "from frp_assess.config import Project",
        "from frp_assess.config.loader import parse_yaml",
        "import frp_assess.dynamics.units",
        "from frp_assess import api",
        "from frp_assess.api import run_assessment",
        "from frp_assess.study.plan import StudyPlan",
        "from {up}motions.readers import read_record",  # relative: resolved first
    ],
)
@pytest.mark.parametrize("interface", ["cli", "tui/core"])
def test_an_internal_import_in_an_interface_is_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, interface: str, line: str
) -> None:
    """The rule bites: an interface module that imports an internal fails the table, while
    the same module with the allowed imports passes."""
    fake_package = tmp_path / "frp_assess"
    module = fake_package / interface / "probe.py"
    module.parent.mkdir(parents=True)
    monkeypatch.setitem(globals(), "PACKAGE", fake_package)
    ok = "from frp_assess.app import project\nfrom frp_assess.config.schema import Project\n"
    module.write_text(ok, encoding="utf-8")
    assert import_problems(module) == []
    up = "." * (interface.count("/") + 2)  # from the probe's package up to frp_assess
    module.write_text(ok + line.format(up=up) + "\n", encoding="utf-8")
    assert import_problems(module) != []


# --- the layout by role (issue 21): no cycle, names that say what they hold, small modules ----

#: the longest module [lines] (docs/architecture.md); the project file's schema is split by
#: block, each module shorter still
MAX_MODULE_LINES = 500
MAX_SCHEMA_MODULE_LINES = 400
#: modules allowed over MAX_MODULE_LINES, each with why (none today)
LONG_MODULES: dict[str, str] = {}
#: basenames allowed in two places (besides __init__.py and __main__.py), each with why
SHARED_BASENAMES: dict[str, str] = {}
#: class names allowed at the top level of two modules, each with why (none today)
SHARED_CLASS_NAMES: dict[str, str] = {}


def module_name(path: Path) -> str:
    """``frp_assess.a.b`` of ``frp_assess/a/b.py`` (a package: of its ``__init__.py``)."""
    parts = ["frp_assess", *path.relative_to(PACKAGE).with_suffix("").parts]
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def top_level_imports(path: Path, modules: set[str]) -> set[str]:
    """The frp_assess modules ``path`` imports when it is imported: its module-level import
    statements (not those in functions, nor under ``if TYPE_CHECKING:``); ``from a import b``
    counts as module ``a.b`` when that is a module, else as ``a``."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    here = module_name(path)
    package = here if path.name == "__init__.py" else here.rpartition(".")[0]
    found: set[str] = set()
    statements: list[ast.stmt] = list(tree.body)
    while statements:
        node = statements.pop()
        if isinstance(node, ast.If):
            if "TYPE_CHECKING" not in ast.unparse(node.test):
                statements += node.body + node.orelse
        elif isinstance(node, ast.Try):
            statements += node.body + node.orelse + node.finalbody
            statements += [s for h in node.handlers for s in h.body]
        elif isinstance(node, ast.Import):
            found.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                up = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                base = ".".join([*up, base] if base else up)
            found.update(
                f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base for a in node.names
            )
    return {m for m in found if m in modules and m != here}


def import_cycle(graph: dict[str, set[str]]) -> list[str]:
    """One cycle of ``graph`` (a list of modules, the first repeated at the end), or []."""
    state: dict[str, int] = {}  # 1: on the current path, 2: done
    path: list[str] = []

    def visit(node: str) -> list[str]:
        state[node] = 1
        path.append(node)
        for nxt in sorted(graph[node]):
            if state.get(nxt) == 1:
                return [*path[path.index(nxt) :], nxt]
            if nxt not in state and (cycle := visit(nxt)):
                return cycle
        state[node] = 2
        path.pop()
        return []

    for start in sorted(graph):
        if start not in state and (cycle := visit(start)):
            return cycle
    return []


def test_import_cycle_finder_finds_one() -> None:
    """The finder bites: a → b → c → a is found, a → b, a → c is not."""
    assert import_cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert import_cycle({"a": {"b", "c"}, "b": {"c"}, "c": set()}) == []


def test_no_import_cycle() -> None:
    """No module imports, through any chain of module-level imports, a module that imports it
    (docs/architecture.md): each layer can be read, and imported, on its own."""
    modules = {module_name(p): p for p in MODULES}
    graph = {name: top_level_imports(path, set(modules)) for name, path in modules.items()}
    cycle = import_cycle(graph)
    assert not cycle, "import cycle: " + " -> ".join(cycle)


def test_no_two_modules_share_a_name() -> None:
    """A module's file name says what it holds, once in the package: ``cli/cmd_run.py`` is the
    command, ``study/run.py`` the study runner (docs/architecture.md, "Names")."""
    seen: dict[str, list[str]] = {}
    for path in MODULES:
        if path.name not in ("__init__.py", "__main__.py"):
            seen.setdefault(path.name, []).append(str(path.relative_to(PACKAGE)))
    shared = {n: p for n, p in seen.items() if len(p) > 1 and n not in SHARED_BASENAMES}
    assert not shared, f"modules sharing a name: {shared}"


def test_no_two_classes_share_a_name() -> None:
    """A class name means one thing: the project file's model ends in ``Spec``, the typed input
    of an assessment in ``Settings`` (or names its object), the recorded copy in results.json in
    ``Result`` where an input of the same name exists (docs/architecture.md, "Names")."""
    seen: dict[str, list[str]] = {}
    for path in MODULES:
        for node in ast.parse(path.read_text(encoding="utf-8")).body:
            if isinstance(node, ast.ClassDef):
                seen.setdefault(node.name, []).append(str(path.relative_to(PACKAGE)))
    shared = {n: p for n, p in seen.items() if len(p) > 1 and n not in SHARED_CLASS_NAMES}
    assert not shared, f"classes defined in two modules: {shared}"


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_modules_are_small(path: Path) -> None:
    """No module over 500 lines; a module of the project file's schema under 400 (one block)."""
    relative = str(path.relative_to(PACKAGE))
    if relative in LONG_MODULES:
        pytest.skip(LONG_MODULES[relative])
    limit = MAX_SCHEMA_MODULE_LINES if relative.startswith("config/schema/") else MAX_MODULE_LINES
    lines = len(path.read_text(encoding="utf-8").splitlines())
    assert lines <= limit, f"{relative} has {lines} lines, more than {limit}: split it by role"


#: what the service's run (app/assessment.py) takes from assess/: the inputs and records it is
#: given, the cache it places, the runner it hands over and the one function that does the
#: engineering (issue 37: the service orchestrates, assess/ decides)
SERVICE_RUN_IMPORTS = {
    "frp_assess.assess.assessment_run",
    "frp_assess.assess.cache",
    "frp_assess.assess.from_project",
    "frp_assess.assess.inputs",
    "frp_assess.assess.runner",
    "frp_assess.assess.seismic",
}


def test_the_service_run_takes_no_engineering_from_assess() -> None:
    """app/assessment.py decides nothing (no FC, check, spectrum or material of its own):
    what it imports of assess/ is the table above, and nothing of rules/."""
    names = imported_modules(PACKAGE / "app" / "assessment.py")
    engineering = {n for n in names if n.startswith(("frp_assess.assess.", "frp_assess.rules"))}
    assert engineering <= SERVICE_RUN_IMPORTS, engineering - SERVICE_RUN_IMPORTS


# --- the core loads no UI library (issue 37) ---------------------------------------------------

#: the packages of the core: what a program that assesses a wall without a screen or a report
#: imports (the leaves included)
CORE = (
    "app", "assess", "config", "dynamics", "motions", "results", "rules", "study",
    "errors", "io_utils", "libm", "numbers", "output_set", "text_safety",
)  # fmt: skip
#: modules of the core that draw an output themselves, each with why
CORE_OUTPUT_MODULES: dict[str, str] = {
    "frp_assess.study.figures": "the study's figures, drawn with reportlab (RESTRICTED allows "
    "study); the study runner imports it only when it draws them",
}
UI_LIBRARIES = ("textual", "rich", "reportlab", "docx")


def core_modules() -> list[str]:
    """Every module of :data:`CORE` but :data:`CORE_OUTPUT_MODULES`, by dotted name."""
    names = []
    for path in MODULES:
        name = module_name(path)
        parts = name.split(".")
        if len(parts) > 1 and parts[1] in CORE and name not in CORE_OUTPUT_MODULES:
            names.append(name)
    return sorted(names)


def test_the_core_loads_no_ui_library() -> None:
    """Importing every module of the core (frp_assess.app, assess, dynamics, rules, ...) in a
    fresh interpreter loads none of textual, rich, reportlab, python-docx: the engineering
    runs without a screen or a document (docs/architecture.md)."""
    script = (
        "import importlib, sys\n"
        f"for name in {core_modules()!r}:\n"
        "    importlib.import_module(name)\n"
        f"print(sorted({{m.split('.')[0] for m in sys.modules}} & set({UI_LIBRARIES!r})))\n"
    )
    env = {**os.environ, "PYTHONPATH": str(PACKAGE.parent)}
    done = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, env=env, check=False
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]", f"the core loads {done.stdout.strip()}"


def test_the_ui_check_bites() -> None:
    """The same probe sees a UI library that a module loads (rich here)."""
    script = "import sys, rich.markup\nprint('rich' in sys.modules)\n"
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert done.stdout.strip() == "True"
