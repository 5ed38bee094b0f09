"""The results folder of a run: checked before any work, locked while a run uses it, and its
output files replaced as one set.

A results folder holds the output set of one run — ``results.json``, ``results.csv``,
``spectra.csv``, ``records/``, ``report.pdf`` and ``report.docx`` (:data:`SET_NAMES`) — and
the IDA cache ``.cache/``.  The rules:

- **Checked first** (:func:`check_out_dir`): a folder that is a file, lies under a file, is a
  device (``/dev/null``) or cannot be written is refused with one line before any work.
- **Missing parent folder** (the rule of every command with an output path): the output
  itself, the results folder or the file, may be new and is created; the folder that holds
  it must exist.  ``--out a/b/res`` with no ``a/b`` is refused with one line naming ``a/b``
  (a typing mistake is not silently turned into a tree of new folders).
- **No links followed** (:func:`refuse_links`): a symbolic link in the folder named like
  one of the tool's own entries (:data:`OWN_NAMES`, a staging folder, a temporary file) is
  refused with one line before any work: writing through it would write, replace or delete
  outside the folder.  The ``.lock`` file is opened with ``O_NOFOLLOW`` as well.
- **Locked** (:class:`FolderLock`): writing a set takes an exclusive ``flock`` on ``.lock``
  in the folder (the file holds the pid of the holder); ``frp-assess run`` holds it from
  before the IDA until its set is written.
  A second run into the same folder refuses at once (:class:`~frp_assess.errors.InputError`,
  exit 2) and names the pid; the lock dies with its process, so ``kill -9`` leaves no stale
  lock.  ``frp-assess report`` takes the same lock to replace ``report.pdf``.
- **Staged, then swapped in** (:func:`staged_set`): the whole set is written into a fresh
  ``.staging-<pid>-<random>/`` folder inside the results folder (same file system).  Only when
  every file is complete is it moved into place: first the old ``results.json`` is removed
  (from then on the folder holds no valid set), then every member is renamed over the old one
  (members the new run does not produce, e.g. the reports with ``--no-pdf``, are removed),
  ``results.json`` last.  ``results.json`` therefore only ever sits beside the files of its
  own run: a failure while writing (disk full, an exception in the PDF) leaves the old set
  untouched, and a kill during the swap leaves no ``results.json`` (no set) until the next run.
- **Only its own files replaced** (:func:`refuse_foreign`): the tool records in
  :data:`MANIFEST_NAME` the size and SHA-256 of every member it wrote (``records/`` file by
  file).  A member in the folder that is not on that record (a project's own ``records/``
  with the user's record files when ``--out`` is the project's folder, a report.pdf signed or
  edited since, a ``results.csv`` of the user's) is never replaced nor deleted: the run, the
  export or ``report`` is refused with one line before any work, and again under the lock
  just before the swap.  A folder of an older version (no record, but the inputs sidecar
  that holds the SHA-256 of its results.json) is taken as the tool's once.  During the
  swap the record holds the old and the new members, so a kill at any moment leaves nothing
  the next run would refuse.
- **Stale leftovers** of a killed run (staging folders, temporary ``.*.tmp`` files of an
  atomic write) are removed by the next run once it holds the lock.
"""

from __future__ import annotations

import errno
import fcntl
import os
import secrets
import shutil
import stat
import threading
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from types import TracebackType

from frp_assess.errors import InputError
from frp_assess.io_utils import file_kind
from frp_assess.output_record import (
    MANIFEST_NAME,
    REPORT_NAMES,
    SET_NAMES,
    SIDECAR_NAME,
    known_members,
    member_digests,
    refuse_foreign,
    write_record,
)

__all__ = [
    "CACHE_NAME",
    "LOCK_NAME",
    "OWN_NAMES",
    "SET_NAMES",
    "FolderLock",
    "check_out_dir",
    "check_out_file",
    "refuse_foreign",
    "refuse_inputs_inside",
    "refuse_links",
    "staged_set",
]

LOCK_NAME = ".lock"
STAGING_PREFIX = ".staging-"
#: the IDA cache folder inside a results folder (as frp_assess.api.CACHE_DIR)
CACHE_NAME = ".cache"
#: every entry the tool makes in a results folder (beside staging folders and temporary files)
OWN_NAMES: tuple[str, ...] = (LOCK_NAME, CACHE_NAME, MANIFEST_NAME, SIDECAR_NAME, *SET_NAMES)
#: folders locked by this process -> the thread holding the lock (re-entrant in that thread)
_held: dict[Path, int] = {}
_held_guard = threading.Lock()


def _nearest_existing(path: Path) -> Path:
    p = path
    while not os.path.lexists(p):
        if p.parent == p:
            break
        p = p.parent
    return p


def _writable(directory: Path) -> bool:
    """Whether new entries can be made in ``directory`` (permissions, read-only mounts)."""
    if not os.access(directory, os.W_OK | os.X_OK):
        return False
    try:
        return not os.statvfs(directory).f_flag & os.ST_RDONLY
    except OSError:
        return False


def _is_own_name(name: str) -> bool:
    """Whether ``name`` is an entry the tool makes in a results folder: one of
    :data:`OWN_NAMES`, a staging folder or a temporary file of an atomic write."""
    if name in OWN_NAMES or name.startswith(STAGING_PREFIX):
        return True
    return name.startswith(".") and name.endswith(".tmp")


def refuse_links(directory: Path, key: str = "--out") -> None:
    """One :class:`InputError` line if ``directory`` holds a symbolic link named like one of
    the tool's own entries (:func:`_is_own_name`); nothing if it does not exist yet.

    The tool never writes, replaces or deletes through a link it did not make: such a folder
    is refused before any work, and the user removes the link (or chooses another folder).
    """
    try:
        entries = sorted(os.scandir(directory), key=lambda e: e.name)
    except OSError:
        return
    for entry in entries:
        if _is_own_name(entry.name) and entry.is_symlink():
            raise InputError(
                f"{Path(directory) / entry.name} is a symbolic link; frp-assess writes its own "
                f"{entry.name} there and never follows a link it did not make: remove the link "
                "or choose another folder",
                key=key,
            )


def missing_parent(path: Path) -> Path | None:
    """The missing folder that should hold ``path`` (the parent of the output), or None if
    it exists (or lies under a file, which the callers say in their own words)."""
    parent = Path(path).parent
    if os.path.lexists(parent):
        return None
    existing = _nearest_existing(parent)
    return parent if existing.is_dir() else None


def check_parent(path: Path, key: str = "--out") -> None:
    """One :class:`InputError` line if the folder that should hold ``path`` does not exist
    (the rule of every command with an output path: see the module docstring)."""
    parent = missing_parent(path)
    if parent is not None:
        raise InputError(
            f"the folder {parent} does not exist; create it first (frp-assess creates only "
            f"{Path(path).name}, not the folders above it)",
            key=key,
        )


def check_out_dir(path: Path, key: str = "--out") -> Path:
    """``path`` if it can hold a results folder, else one :class:`InputError` line saying why.

    Nothing is created: a folder that does not exist yet is fine if its parent is a writable
    folder (a missing parent is refused, :func:`check_parent`).  An existing folder holding a
    symbolic link named like one of the tool's entries is refused (:func:`refuse_links`).
    """
    path = Path(path)
    shown = str(path)
    if os.path.lexists(path) and not path.is_dir():
        st = os.stat(path) if path.exists() else os.lstat(path)
        kind = (
            "a device"
            if stat.S_ISCHR(st.st_mode) or stat.S_ISBLK(st.st_mode)
            else "a file, not a folder"
        )
        raise InputError(f"{shown} is {kind}; give a folder for the results", key=key)
    existing = _nearest_existing(path)
    if not existing.is_dir():
        raise InputError(f"{shown} lies under {existing}, which is a file, not a folder", key=key)
    if not _writable(existing):
        where = "" if existing == path else f" (its parent {existing})"
        raise InputError(f"{shown}{where} is not writable", key=key)
    check_parent(path, key)
    refuse_links(path, key)
    refuse_foreign(path, key)
    return path


class FolderLock:
    """Exclusive lock of a results folder (see the module docstring); re-entrant within one
    process.  Creates the folder if needed, and removes it again on leaving when nothing but
    its ``.lock`` was written there (a run that failed before writing leaves no folder)."""

    def __init__(self, directory: Path, key: str = "--out") -> None:
        self.directory = Path(directory)
        self.key = key
        self._fd: int | None = None
        self._created = False  #: the lock made the folder (then it removes it if left empty)

    def __enter__(self) -> FolderLock:
        d = self.directory
        real = Path(os.path.realpath(d))
        with _held_guard:
            owner = _held.get(real)
        if owner == threading.get_ident():
            return self
        if owner is not None:
            raise InputError(
                f"another run of this process (pid {os.getpid()}) is writing {d}; wait for it "
                "to finish or choose another folder",
                key=self.key,
            )
        refuse_links(d, self.key)
        created = not os.path.lexists(d)
        for _ in range(3):
            fd = self._open_locked(d)
            try:  # the lock file a holder removed on leaving (an empty folder): lock again
                same = os.path.samestat(os.fstat(fd), os.lstat(d / LOCK_NAME))
            except OSError:
                same = False
            if same:
                break
            os.close(fd)
        else:
            raise InputError(f"cannot lock {d}: its lock file keeps being removed", key=self.key)
        self._created = created
        os.ftruncate(fd, 0)
        os.write(fd, f"{os.getpid()}\n".encode())
        self._fd = fd
        with _held_guard:
            _held[real] = threading.get_ident()
        try:
            refuse_links(d, self.key)  # a link made between the check and the lock
        except InputError:
            self.__exit__(None, None, None)
            raise
        remove_leftovers(d)
        return self

    def _open_locked(self, d: Path) -> int:
        """The descriptor of ``d/.lock`` (a regular file, created if needed) with the
        exclusive lock taken; one InputError line if it cannot be (another holder, ...)."""
        try:
            d.mkdir(parents=True, exist_ok=True)
            flags = os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_NOCTTY
            fd = os.open(d / LOCK_NAME, flags, 0o644)
        except OSError as exc:
            raise InputError(
                f"cannot use {d} as the results folder: {exc.strerror}", key=self.key
            ) from None
        mode = os.fstat(fd).st_mode
        if not stat.S_ISREG(mode):  # a FIFO or a device: flock would fail with EINVAL
            os.close(fd)
            raise InputError(
                f"{d / LOCK_NAME} is {file_kind(mode)}, not the lock file frp-assess makes "
                "there; remove it or choose another folder",
                key=self.key,
            )
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as exc:
            holder = os.read(fd, 32).decode("ascii", "replace").strip() or "?"
            os.close(fd)
            if exc.errno in (errno.EWOULDBLOCK, errno.EACCES, errno.EAGAIN):
                raise InputError(
                    f"another frp-assess process (pid {holder}) is writing {d}; wait for it "
                    "to finish or choose another folder",
                    key=self.key,
                ) from None
            raise
        return fd

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        if self._fd is None:
            return
        with _held_guard:
            _held.pop(Path(os.path.realpath(self.directory)), None)
        if self._created:  # a folder this lock made and nothing else wrote into: not left
            try:
                if os.listdir(self.directory) == [LOCK_NAME]:
                    os.unlink(self.directory / LOCK_NAME)
                    os.rmdir(self.directory)
            except OSError:
                pass
        fcntl.flock(self._fd, fcntl.LOCK_UN)
        os.close(self._fd)
        self._fd = None


def remove_leftovers(directory: Path) -> list[Path]:
    """Remove what a killed run left in ``directory`` (call with the lock held): staging
    folders and the temporary files of atomic writes of set members. Returns them."""
    gone: list[Path] = []
    try:
        entries = list(Path(directory).iterdir())
    except OSError:
        return gone
    for p in entries:
        stale_tmp = p.name.endswith(".tmp") and any(
            p.name.startswith(f".{name}.") for name in SET_NAMES
        )
        if p.name.startswith(STAGING_PREFIX) or stale_tmp:
            _remove(p)
            gone.append(p)
    return gone


def _remove(p: Path) -> None:
    if p.is_dir() and not p.is_symlink():
        shutil.rmtree(p, ignore_errors=True)
    else:
        p.unlink(missing_ok=True)


@contextmanager
def staged_set(out_dir: Path) -> Iterator[Path]:
    """Yield a fresh, empty staging folder inside ``out_dir``; write the whole output set
    there.  On success it replaces the set in ``out_dir`` (:func:`swap_in`); on any exception
    (or interrupt) the staging folder is removed and ``out_dir`` is left as it was."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    staging = out_dir / f"{STAGING_PREFIX}{os.getpid()}-{secrets.token_hex(4)}"
    staging.mkdir()
    try:
        yield staging
        swap_in(staging, out_dir)
    finally:
        shutil.rmtree(staging, ignore_errors=True)


def swap_in(staging: Path, out_dir: Path) -> None:
    """Move the set written in ``staging`` into ``out_dir``, ``results.json`` removed first and
    put back last (see the module docstring); refused (:func:`refuse_foreign`) if a member in
    ``out_dir`` is not one the tool wrote.  The record of the members holds the old and the
    new ones while they are swapped, the new ones only once done."""
    refuse_foreign(out_dir)
    known = known_members(out_dir) or {}
    written = {rel: [d] for rel, d in member_digests(staging).items()}
    both = {rel: sorted({*known.get(rel, []), *written.get(rel, [])}) for rel in {*known, *written}}
    write_record(out_dir, both, {})
    (out_dir / "results.json").unlink(missing_ok=True)
    for name in SET_NAMES:
        new = staging / name
        target = out_dir / name
        if not os.path.lexists(new):
            if os.path.lexists(target):
                _remove(target)
            continue
        if new.is_dir():
            if os.path.lexists(target):
                old = staging / f".old-{name}"
                os.replace(target, old) if not target.is_dir() else target.rename(old)
            new.rename(target)
        else:
            if target.is_dir() and not target.is_symlink():
                shutil.rmtree(target)
            os.replace(new, target)
    _fsync_dir(out_dir)
    results = written.get("results.json", [""])[0]
    write_record(out_dir, written, {n: results for n in REPORT_NAMES if n in written})


def _fsync_dir(directory: Path) -> None:
    try:
        fd = os.open(directory, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def refuse_inputs_inside(out_dir: Path, inputs: Sequence[Path], key: str = "--out") -> None:
    """One :class:`InputError` line if one of the project's ``inputs`` (its file, its record
    files) is, or lies in, a member of the output set in ``out_dir``, which a run replaces
    (a project's ``records/`` when ``--out`` is the project's own folder)."""
    for path in inputs:
        real = os.path.realpath(path)
        for name in SET_NAMES:
            member = os.path.realpath(Path(out_dir) / name)
            if real == member or real.startswith(member + os.sep):
                raise InputError(
                    f"{path}, an input of the project, lies in {Path(out_dir) / name}, which "
                    "a run replaces; choose another folder for the results",
                    key=key,
                )


def check_out_file(path: Path, key: str = "--out") -> Path:
    """``path`` if a file can be written there (replacing a regular file is fine), else one
    :class:`InputError` line: a folder, a device, a parent that is missing or a file, or not
    writable."""
    path = Path(path)
    if path.is_dir():
        raise InputError(f"{path} is a folder; give a file name", key=key)
    if os.path.lexists(path) and not path.is_file():
        raise InputError(f"{path} is not a regular file", key=key)
    parent = path.parent
    existing = _nearest_existing(parent)
    if not existing.is_dir():
        raise InputError(f"{path} lies under {existing}, which is a file, not a folder", key=key)
    check_parent(path, key)
    if not _writable(existing):
        raise InputError(f"{path}: {existing} is not writable", key=key)
    return path
