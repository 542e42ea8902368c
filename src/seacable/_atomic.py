"""Writing files whole: a temporary file in the same folder, renamed into place.

Every writer of seacable (results, figures, animations, sweep records and summaries) goes through
:func:`atomic_path`, so that a write that fails or is interrupted midway leaves the previous file
as it was, never a 0-byte or half-written file, and no temporary file behind. The rename
(:func:`os.replace`) is atomic on POSIX and Windows when both names are in the same folder.

:func:`deferred_interrupts` holds back Ctrl-C and SIGTERM while a result that took long to compute
is written, and raises :class:`KeyboardInterrupt` once it is written.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
import uuid
from collections.abc import Callable, Iterator
from pathlib import Path

__all__ = ["PARTIAL", "atomic_path", "atomic_write", "deferred_interrupts", "interrupt_requested"]

interrupt_requested = threading.Event()
"""Set by the command line's SIGINT and SIGTERM handler: the user asked to stop. A case that fails
after it was set failed because of the interrupt (a library may turn the KeyboardInterrupt raised
inside its callback into another error), so a sweep stops instead of recording it as failed."""

PARTIAL = ".partial"
"""Infix of the temporary names: ``.NAME.<random>.partial.SUFFIX`` (hidden, same suffix as NAME)."""


def _temporary(path: Path) -> Path:
    # the same suffix as the target, so that writers that choose the format by it (matplotlib,
    # Pillow) write the right one
    return path.with_name(f".{path.stem}.{uuid.uuid4().hex[:12]}{PARTIAL}{path.suffix}")


@contextlib.contextmanager
def atomic_path(path: str | Path) -> Iterator[Path]:
    """A temporary path beside ``path``; renamed to ``path`` when the block ends without error.

    Parameters
    ----------
    path
        The file to write. Its folder must exist.

    Yields
    ------
    Path
        Where to write: a hidden file in the same folder, with the same suffix.

    Notes
    -----
    If the block raises (any exception, :class:`KeyboardInterrupt` included), the temporary file is
    removed and ``path`` is left as it was.
    """
    path = Path(path)
    tmp = _temporary(path)
    try:
        yield tmp
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            tmp.unlink()
        raise


def atomic_write(path: str | Path, write: Callable[[Path], object]) -> Path:
    """Call ``write(tmp)`` on a temporary path beside ``path``, then rename it to ``path``. Returns ``path``."""
    path = Path(path)
    with atomic_path(path) as tmp:
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
