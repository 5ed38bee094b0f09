"""Small file helpers: every output is written atomically (temp file, then rename), and every
file the tool reads back is checked before it is read (:func:`read_regular`).

Temporary files are created next to the target (same file system, so the rename is atomic)
and get the permissions an ordinary ``open`` would give (0666 minus the umask), not the
0600 of :func:`tempfile.mkstemp`.
"""

from __future__ import annotations

import datetime as _dt
import os
import stat
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TextIO

from frp_assess.errors import InputError


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


@contextmanager
def atomic_path(path: str | Path) -> Iterator[Path]:
    """Yield a temporary path next to ``path``; on success it replaces ``path``.

    If the block raises (or is interrupted), the temporary file is removed and ``path`` is
    left as it was; an ``OSError`` that names no file (a full disk, a write refused) is raised
    again naming ``path``, so that its one-line message says where.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, name = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(fd)
    tmp = Path(name)
    try:
        yield tmp
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        if exc.filename is None and exc.errno is not None:  # a full disk says no file name
            raise OSError(exc.errno, exc.strerror, str(path)) from exc
        raise
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


@contextmanager
def atomic_open(path: str | Path, newline: str | None = None) -> Iterator[TextIO]:
    """Open a UTF-8 text file for writing that appears at ``path`` only when complete."""
    with atomic_path(path) as tmp, tmp.open("w", encoding="utf-8", newline=newline) as fh:
        yield fh


def atomic_write_text(path: str | Path, text: str) -> None:
    """Write ``text`` to ``path`` so that readers never see a half-written file."""
    with atomic_open(path) as fh:
        fh.write(text)


def file_kind(mode: int) -> str:
    """What a file of ``mode`` (``st_mode``) that is not a regular file is, in words."""
    if stat.S_ISDIR(mode):
        return "a folder"
    if stat.S_ISFIFO(mode):
        return "a pipe (FIFO)"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


def read_regular(path: str | Path, what: str, max_bytes: int) -> bytes:
    """The bytes of ``path`` if it is a regular file of at most ``max_bytes``, else one
    :class:`~frp_assess.errors.InputError` naming the file (``what`` says what it is for).

    The file is opened without blocking (``O_NONBLOCK``: opening a FIFO does not wait for a
    writer) and checked on the open descriptor (``fstat``), so that a FIFO, a device
    (``/dev/zero``), a folder or a file too large is refused before a byte is read, and a file
    swapped between a check and the read cannot slip through.  At most ``max_bytes + 1``
    bytes are ever read (a file growing while read).
    """
    name = str(path)
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_NOCTTY)
    except FileNotFoundError:
        raise InputError(f"no such {what}", file=name) from None
    except OSError as exc:
        raise InputError(f"cannot read the {what}: {exc.strerror or exc}", file=name) from None
    with os.fdopen(fd, "rb") as handle:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            raise InputError(f"is {file_kind(info.st_mode)}, not a {what}", file=name)
        if info.st_size > max_bytes:
            raise InputError(
                f"is {info.st_size} bytes; a {what} is at most {max_bytes} bytes", file=name
            )
        try:
            raw = handle.read(max_bytes + 1)
        except OSError as exc:
            raise InputError(f"cannot read the {what}: {exc.strerror or exc}", file=name) from None
    if len(raw) > max_bytes:  # grew since it was opened
        raise InputError(f"is more than the {max_bytes} bytes a {what} can have", file=name)
    return raw


#: the largest results.json read back (as frp_assess.report.document's limit) [bytes]
MAX_RESULTS_BYTES = 64 * 1024 * 1024


def read_results_text(path: str | Path) -> str:
    """The UTF-8 text of a stored results.json (:func:`read_regular`: a FIFO, a device, a
    folder or a file over :data:`MAX_RESULTS_BYTES` is one InputError naming it)."""
    raw = read_regular(path, "results file", MAX_RESULTS_BYTES)
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(f"is not UTF-8 text (byte {exc.start})", file=str(path)) from None


#: seconds since 1970-01-01 UTC that fix the date of a run (reproducible-builds.org)
SOURCE_DATE_EPOCH = "SOURCE_DATE_EPOCH"


def source_date() -> str | None:
    """The ISO date (UTC) of ``SOURCE_DATE_EPOCH``, None when it is not set; one
    :class:`~frp_assess.errors.InputError` when it is not whole seconds a date can have.
    Checked by every command before it imports anything (a library may read the variable
    too) and by the run that stamps the date (:func:`frp_assess.app.assessment.run_date`)."""
    epoch = os.environ.get(SOURCE_DATE_EPOCH, "")
    if not epoch:
        return None
    try:
        if len(epoch) > 20:  # int() of thousands of digits is slow, and no date anyway
            raise ValueError(epoch)
        return _dt.datetime.fromtimestamp(int(epoch), tz=_dt.UTC).date().isoformat()
    except (ValueError, OverflowError, OSError):
        shown = epoch if len(epoch) <= 40 else f"{epoch[:40]}..."
        raise InputError(
            f"expected whole seconds since 1970-01-01 UTC, found {shown!r}",
            key=SOURCE_DATE_EPOCH,
        ) from None
