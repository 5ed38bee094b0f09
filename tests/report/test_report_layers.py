"""The document model is free of reportlab (issue 37 step 3c): the model, the text source and
the builder of the document import no renderer; only the PDF renderer (render_pdf,
pdf_document), the charts and the layout helpers that size blocks do."""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import frp_assess.report

REPORT = Path(frp_assess.report.__file__).parent
#: modules that must not import reportlab (outside ``if TYPE_CHECKING:``)
FREE = ("doc_model.py", "document.py", "lang.py", "wording.py", "__init__.py")


def top_level_imports(path: Path) -> set[str]:
    """Modules imported by ``path`` at run time (``if TYPE_CHECKING:`` blocks left out)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out: set[str] = set()

    def visit(nodes: list[ast.stmt]) -> None:
        for node in nodes:
            if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
                continue
            if isinstance(node, ast.Import):
                out.update(a.name for a in node.names)
            elif isinstance(node, ast.ImportFrom) and node.module:
                out.add(node.module)
                out.update(f"{node.module}.{a.name}" for a in node.names)
            for field in ("body", "orelse", "finalbody", "handlers"):
                visit(getattr(node, field, []) or [])

    visit(tree.body)
    return out


def test_the_document_model_and_its_builder_import_no_renderer() -> None:
    for name in FREE:
        imported = top_level_imports(REPORT / name)
        assert not any(m.split(".")[0] == "reportlab" for m in imported), (name, imported)
        assert not any(m.endswith(("render_pdf", "pdf_document")) for m in imported), name


def test_importing_the_model_loads_no_reportlab() -> None:
    code = (
        "import sys\n"
        "import frp_assess.report.doc_model, frp_assess.report.lang\n"
        "print(sorted(m for m in sys.modules if m.split('.')[0] == 'reportlab'))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]", out.stdout
