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
    "rules": set(),  # pure engineering formulas: nothing of frp_assess below them
    "results": {"errors"},  # the typed results (stdlib dataclasses): no numerics, no files
    "numbers": {"results"},
    "text_safety": set(),
    "io_utils": {"errors"},
    "output_set": {"errors", "io_utils"},
    "dynamics": {"errors", "motions", "rules"},
    "motions": {"errors", "io_utils"},
    "config": {"errors", "io_utils", "rules", "dynamics", "motions"},
    "assess": {
        "", "errors", "io_utils", "numbers", "text_safety", "rules", "dynamics", "motions",
        "config", "results",
    },
    "report": {"errors", "io_utils", "numbers", "text_safety", "results"},
    "study": {
        "", "errors", "io_utils", "dynamics", "motions", "config", "assess", "report", "results",
    },
    # the application service: everything below it, and nothing imports it but the interfaces
    "app": {
        "", "errors", "io_utils", "output_set", "text_safety", "dynamics", "motions", "config",
        "assess", "report", "study", "results",
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
