"""The build's one step beyond pyproject.toml: the wheel carries the compiled kernel.

After the package's files are copied into the build directory, the kernel is compiled there
once (:func:`frp_assess.dynamics.kernel_cache.warm_up_in_parallel`, in a subprocess on the build's
numba), so numba's cache files (``__pycache__/*.nbi|*.nbc`` next to the sources) are
installed with the package and the first ``frp-assess run`` loads the kernel instead of
compiling it (15-23 CPU-s, docs/compilation.md).  numba's cache is valid where the numba
version, the source's content, the Python bytecode and the processor are the ones it was
compiled with: a wheel built and installed on the same machine (``pip install .``).
Anywhere else numba compiles on the first run, as it would without this step.

Nothing here can make the install fail: if the compile fails (or
``FRP_ASSESS_NO_PRECOMPILE=1``), the wheel is built without the cache and a warning said.
An editable install (``pip install -e .``) keeps the cache in the source tree, as before.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

WARM_UP = "from frp_assess.dynamics.kernel_cache import warm_up_in_parallel as w; w()"


def drop_kernel_cache(root: Path) -> None:
    """Remove numba's cache files under ``root`` (a failed compile leaves no half cache)."""
    for pattern in ("*.nbi", "*.nbc"):
        for path in root.rglob(pattern):
            path.unlink()


def compile_kernel(build_lib: Path) -> None:
    """Compile the kernel into numba's cache next to the sources in ``build_lib``."""
    env = dict(os.environ)
    env.pop("NUMBA_CACHE_DIR", None)  # the cache must land next to the built sources
    env.pop("NUMBA_DISABLE_JIT", None)
    env["PYTHONDONTWRITEBYTECODE"] = "1"  # no .pyc in the wheel: pip writes its own
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(build_lib), env.get("PYTHONPATH")) if p)
    print("frp-assess: compiling the numerical kernel into the wheel (about 20 CPU-s)", flush=True)
    done = subprocess.run([sys.executable, "-c", WARM_UP], env=env, cwd=build_lib, check=False)
    if done.returncode != 0:
        drop_kernel_cache(build_lib)
        print(
            "frp-assess: warning: the kernel could not be compiled at install; the first "
            "run compiles it instead",
            file=sys.stderr,
        )


class BuildPyWithKernel(build_py):
    """``build_py``, then the kernel compiled in the build directory (not when editable)."""

    def run(self) -> None:
        super().run()
        if self.editable_mode or os.environ.get("FRP_ASSESS_NO_PRECOMPILE") == "1":
            return
        compile_kernel(Path(self.build_lib).resolve())


setup(cmdclass={"build_py": BuildPyWithKernel})
