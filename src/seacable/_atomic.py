"""Writing files whole: a temporary file in the same folder, renamed into place.

Every writer of seacable (results, figures, animations, sweep records and summaries) goes through
:func:`atomic_path`, so that a write that fails or is interrupted midway leaves the previous file
as it was, never a 0-byte or half-written file, and no temporary file behind. The rename
(:func:`os.replace`) is atomic on POSIX and Windows when both names are in the same folder.

A write that fails (a full disk, no permission, a read-only file system, the NetCDF library's
``NetCDF: HDF error`` when the disk fills up under it) raises :class:`~seacable.errors.InputError`
naming the file and the cause (:func:`write_failure`), never the library's bare exception.

A process killed outright (SIGKILL, the out-of-memory killer, a power cut) cannot remove its
temporary file. Temporaries are named ``.NAME.seacable-tmp-HOST-PID-RANDOM.SUFFIX``
(:func:`temporary_path`), so that the first write of a later process into the same folder finds
those of processes of this host that are no longer alive and removes them
(:func:`remove_stale_temporaries`).

:func:`deferred_interrupts` holds back Ctrl-C and SIGTERM while a result that took long to compute
is written, and raises :class:`KeyboardInterrupt` once it is written.
"""

from __future__ import annotations

import contextlib
import errno
import os
import re
import signal
import socket
import threading
import uuid
from collections.abc import Callable, Iterator
from pathlib import Path

from .errors import InputError

__all__ = ["TEMPORARY", "atomic_path", "atomic_write", "clean_folder_once", "deferred_interrupts",
           "interrupt_requested", "is_write_failure", "keep_whole_outputs", "remove_stale_temporaries",
           "temporary_path", "write_failure"]

interrupt_requested = threading.Event()
"""Set by the command line's SIGINT and SIGTERM handler: the user asked to stop. A case that fails
after it was set failed because of the interrupt (a library may turn the KeyboardInterrupt raised
inside its callback into another error), so a sweep stops instead of recording it as failed."""

TEMPORARY = ".seacable-tmp-"
"""Infix of the temporary names: ``.NAME.seacable-tmp-HOST-PID-RANDOM.SUFFIX`` (hidden, same suffix as NAME)."""

_TEMPORARY_NAME = re.compile(r"^\.(?P<name>.+)\.seacable-tmp-(?P<host>[A-Za-z0-9_]*)-(?P<pid>\d+)-[0-9a-f]+")


def _host() -> str:
    return re.sub(r"[^A-Za-z0-9]", "_", socket.gethostname())[:40]


def temporary_path(path: str | Path) -> Path:
    """The temporary name under which ``path`` is written: hidden, beside it, with this host and process.

    The suffix is the target's, so that writers that choose the format by it (matplotlib, Pillow)
    write the right one.
    """
    path = Path(path)
    return path.with_name(f".{path.name}{TEMPORARY}{_host()}-{os.getpid()}-{uuid.uuid4().hex[:8]}{path.suffix}")


def _alive(pid: int) -> bool:
    """Whether process ``pid`` of this host runs (a zombie, killed but not yet reaped, does not)."""
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:    # another user's process
        return True
    except OSError:
        return True
    with contextlib.suppress(OSError, IndexError):
        stat = Path(f"/proc/{pid}/stat").read_text()
        return stat.rpartition(")")[2].split()[0] != "Z"
    return True


def remove_stale_temporaries(folder: str | Path, name: str | None = None) -> list[Path]:
    """Remove the temporary files in ``folder`` left by processes of this host that are gone.

    Parameters
    ----------
    folder
        The folder to look in.
    name
        Only the temporaries of the file of this name; default all.

    Returns
    -------
    list of Path
        The files removed. Temporaries of live processes, of other hosts (a shared file system) and
        files that are not seacable's are left alone.
    """
    folder, host = Path(folder), _host()
    removed = []
    try:
        entries = list(os.scandir(folder))
    except OSError:
        return removed
    for entry in entries:
        m = _TEMPORARY_NAME.match(entry.name)
        if m is None or m["host"] != host or (name is not None and m["name"] != name) or _alive(int(m["pid"])):
            continue
        with contextlib.suppress(OSError):
            os.unlink(entry.path)
            removed.append(Path(entry.path))
    return removed


_SWEPT: set[str] = set()
"""Folders already cleared of stale temporaries by this process (once each: a sweep writes thousands of files)."""


def clean_folder_once(folder: str | Path) -> None:
    """:func:`remove_stale_temporaries` of ``folder``, the first time this process writes there."""
    key = os.path.abspath(folder)
    if key not in _SWEPT:
        _SWEPT.add(key)
        remove_stale_temporaries(folder)


def is_write_failure(err: BaseException) -> bool:
    """Whether ``err``, raised while a file was written, says the file could not be written.

    Any :class:`OSError` (a full disk, no permission, a read-only file system, a folder removed), and
    the errors of the NetCDF library (``RuntimeError: NetCDF: HDF error`` when the disk fills up under
    HDF5).
    """
    if isinstance(err, OSError):
        return True
    return isinstance(err, RuntimeError) and str(err).lstrip().startswith(("NetCDF:", "HDF"))


_FULL = 16 * 2**20
"""Free space under which a NetCDF library error is put down to a full disk. [byte]"""


def _free_space(folder: Path) -> float | None:
    try:
        st = os.statvfs(folder)
    except (OSError, AttributeError):
        return None
    return float(st.f_bavail * st.f_frsize)


def _size(n: float) -> str:
    return f"{n / 1e6:.3g} MB" if n >= 1e6 else f"{n / 1e3:.3g} kB"


def write_failure(path: str | Path, err: BaseException, what: str = "the file") -> InputError:
    """The error to raise when ``path`` could not be written because of ``err``: the file, the cause, a fix.

    Parameters
    ----------
    path
        The file that was being written.
    err
        The exception of the failed write (see :func:`is_write_failure`).
    what
        What the file is, for the message (``"the result"``).
    """
    path = Path(path)
    folder = path.parent
    code = getattr(err, "errno", None)
    detail = getattr(err, "strerror", None) or str(err) or type(err).__name__
    if code in (errno.ENOSPC, getattr(errno, "EDQUOT", -1)):
        cause = f"the disk is full ({detail})"
        fix = f"free disk space in '{folder}', or write to another disk"
    elif code in (errno.EACCES, errno.EPERM):
        cause = f"no permission to write there ({detail})"
        fix = "give a folder you can write to, or change its permissions"
    elif code == errno.EROFS:
        cause = f"the file system is read-only ({detail})"
        fix = "give a folder on a writable file system"
    elif isinstance(err, OSError):
        cause = detail
        fix = "give a folder you can write to, on a disk with free space"
    else:
        free = _free_space(folder)
        if free is not None and free < _FULL:
            cause = f"the disk is full ({_size(free)} free in '{folder}'; the NetCDF library said '{err}')"
            fix = f"free disk space in '{folder}', or write to another disk"
        else:
            cause = f"the NetCDF library could not write it ('{err}')"
            fix = "check the disk (free space, quota, a network file system that went away) and write again"
    return InputError(f"cannot write {what} '{path}': {cause}. Nothing was written there (the previous file, "
                      f"if any, is unchanged). Suggested fix: {fix}.")


@contextlib.contextmanager
def atomic_path(path: str | Path, what: str = "the file") -> Iterator[Path]:
    """A temporary path beside ``path``; renamed to ``path`` when the block ends without error.

    Parameters
    ----------
    path
        The file to write. Its folder must exist.
    what
        What the file is, for the message of a failed write (``"the result"``).

    Yields
    ------
    Path
        Where to write: a hidden file in the same folder, with the same suffix.

    Raises
    ------
    InputError
        If the write fails (see :func:`is_write_failure`): naming the file and the cause.

    Notes
    -----
    If the block raises (any exception, :class:`KeyboardInterrupt` included), the temporary file is
    removed and ``path`` is left as it was. The first write of a process into a folder removes the
    temporaries that dead processes left there (:func:`remove_stale_temporaries`).
    """
    path = Path(path)
    clean_folder_once(path.parent)
    tmp = temporary_path(path)
    try:
        yield tmp
        os.replace(tmp, path)
    except BaseException as err:
        # the cause first: a full disk is seen before the temporary's space is given back
        failure = write_failure(path, err, what) if is_write_failure(err) else None
        with contextlib.suppress(OSError):
            tmp.unlink()
        if failure is None:
            raise
        raise failure from None


def atomic_write(path: str | Path, write: Callable[[Path], object], what: str = "the file") -> Path:
    """Call ``write(tmp)`` on a temporary path beside ``path``, then rename it to ``path``. Returns ``path``.

    Raises
    ------
    InputError
        If the write fails (:func:`write_failure`).
    """
    path = Path(path)
    with atomic_path(path, what) as tmp:
        write(tmp)
    return path


@contextlib.contextmanager
def deferred_interrupts() -> Iterator[None]:
    """Hold back SIGINT (Ctrl-C) and SIGTERM during the block; raise KeyboardInterrupt after it if one came.

    Used around the writing of a result, so that an interrupt that arrives while a long computation's
    result is being written does not lose it, and never stops the NetCDF library midway (which can
    leave its lock held and hang the next write). Nested blocks pass a held signal to the outermost,
    which raises once its block is done. Outside the main thread (where signal handlers cannot be
    set) the block runs unprotected.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    caught: list[int] = []

    def hold(signum, frame):
        caught.append(signum)

    hold.seacable_hold = True
    previous = {}
    for sig in (signal.SIGINT, signal.SIGTERM):
        previous[sig] = signal.signal(sig, hold)
    try:
        yield
    finally:
        for sig, handler in previous.items():  # None: a handler not set from Python
            signal.signal(sig, signal.SIG_DFL if handler is None else handler)
    if caught:
        interrupt_requested.set()
        outer = previous[caught[0]]
        if getattr(outer, "seacable_hold", False):
            outer(caught[0], None)   # an enclosing block raises when it is done
        else:
            raise KeyboardInterrupt


def keep_whole_outputs(*records: list) -> int:
    """Cut the lists a time loop appends to, output by output, to the shortest one's length, in place; return it.

    An interrupt (Ctrl-C or SIGTERM) between an output's appends leaves some lists one item longer than the
    others: the outputs that every list holds are kept, so that an interrupted run still returns its result.
    """
    n = min(len(rows) for rows in records)
    for rows in records:
        del rows[n:]
    return n
