"""Where numba keeps seacable's compiled kernels: a folder keyed by seacable's source.

The kernels are ``@numba.njit(cache=True)`` functions. numba checks a cached kernel only
against the file that defines it, so a kernel that calls a function of another module keeps
running the old machine code after that other module changed. This module gives numba a
cache folder per *version of the whole package*: its name is a hash of every ``*.py`` file
under ``seacable/`` and of the Python, numba, llvmlite and NumPy versions, so any change of
source or of compiler starts from an empty folder. The folder is

* ``$NUMBA_CACHE_DIR/seacable/<key>`` when the user set numba's cache folder, else
* ``$XDG_CACHE_HOME/seacable/numba/<key>`` (``~/.cache/...``; ``%LOCALAPPDATA%`` on Windows).

Each import marks its folder as used; folders of other keys are removed when they are not
among the :data:`KEEP` most recently used and have not been used for :data:`MIN_AGE` seconds
(another process may still be running that source).

When no candidate folder can be written (read-only install, no home folder), seacable's
kernels are compiled in memory for the process only, with a one-line note on stderr, instead
of numba's ``RuntimeError: cannot cache function``.

Only functions defined in seacable's own files are affected: numba's other functions keep
numba's usual cache locations. The hook is a cache locator placed first in numba's list
(``numba.core.caching.CacheImpl._locator_classes``, the same in numba 0.59 and 0.68). numba
picks a function's locator when the function is decorated, so this must run before any kernel
module is imported, which is why every kernel module takes its ``njit`` from :mod:`seacable._jit`,
which imports this module first (``import seacable`` alone imports neither, nor numba). An
explicit ``NUMBA_CACHE_LOCATOR_CLASSES`` (recent numba) replaces that list and wins.

Why not set ``numba.config.CACHE_DIR`` instead: it is read at decoration too, but numba's
``reload_config()``, run at every compilation, re-reads it from the environment whenever a
``NUMBA_*`` variable changed, silently undoing the setting for kernel modules imported later;
it would move every numba function of the process, not only seacable's; and it cannot stop
numba from falling back to ``__pycache__`` beside the source, which is not keyed.
"""

from __future__ import annotations

import hashlib
import inspect
import os
import re
import shutil
import sys
import tempfile
import time
from pathlib import Path

__all__ = [
    "KEEP",
    "MIN_AGE",
    "PACKAGE_DIR",
    "cache_folder",
    "candidate_roots",
    "install",
    "prune",
    "source_key",
]

PACKAGE_DIR = Path(__file__).resolve().parent
"""The installed ``seacable`` package whose source keys the cache."""
KEEP = 8
"""Key folders kept: the current one and the most recently used others. [1]"""
MIN_AGE = 3600.0
"""A key folder used less than this long ago is never removed. [s]"""
NOTE_PREFIX = "seacable: note:"

_KEY_LENGTH = 16
_KEY_RE = re.compile(rf"[0-9a-f]{{{_KEY_LENGTH}}}")
_folder: Path | None = None
_reason: str | None = None


def _versions() -> bytes:
    import llvmlite
    import numba
    import numpy

    return (f"{sys.implementation.name} {sys.version_info[:3]} numba {numba.__version__} "
            f"llvmlite {llvmlite.__version__} numpy {numpy.__version__}").encode()


def source_key(package_dir: str | os.PathLike = PACKAGE_DIR, versions: bytes | None = None) -> str:
    """Hash of a package's source files and of the compiler versions.

    Parameters
    ----------
    package_dir : path
        Folder whose ``*.py`` files (recursively, ``__pycache__`` excluded) are hashed with
        their paths relative to it. [-]
    versions : bytes, optional
        Versions to mix in; default: Python, numba, llvmlite and NumPy of this process. [-]

    Returns
    -------
    str
        16 hexadecimal digits (64 bits of SHA-256): the same for the same files and
        versions wherever the package lies, different when any byte changes. [-]
    """
    root = os.fspath(package_dir)
    digest = hashlib.sha256(_versions() if versions is None else versions)
    files = []
    for folder, subfolders, names in os.walk(root):
        subfolders[:] = [d for d in subfolders if d != "__pycache__"]
        files += [os.path.join(folder, n) for n in names if n.endswith(".py")]
    for path in sorted(files):
        with open(path, "rb") as f:
            data = f.read()
        rel = os.path.relpath(path, root).replace(os.sep, "/").encode()
        digest.update(b"%d:%s%d:" % (len(rel), rel, len(data)))
        digest.update(data)
    return digest.hexdigest()[:_KEY_LENGTH]


def candidate_roots(numba_cache_dir: str = "", environ=os.environ) -> list[Path]:
    """Folders that may hold the key folders, in order of preference.

    Parameters
    ----------
    numba_cache_dir : str
        numba's configured cache folder (``numba.core.config.CACHE_DIR``: ``NUMBA_CACHE_DIR``
        or ``.numba_config.yaml``), empty when unset. [-]
    environ : mapping
        Environment to read ``XDG_CACHE_HOME``, ``LOCALAPPDATA`` and the home folder from. [-]

    Returns
    -------
    list of Path
        ``<numba_cache_dir>/seacable`` if set, then ``<user cache>/seacable/numba``. [-]
    """
    roots = []
    if numba_cache_dir:
        roots.append(Path(os.path.abspath(numba_cache_dir)) / "seacable")
    base = environ.get("XDG_CACHE_HOME", "")
    if not os.path.isabs(base):  # the XDG spec: a relative value is ignored
        base = environ.get("LOCALAPPDATA", "") if os.name == "nt" else ""
    if not os.path.isabs(base):
        home = environ.get("HOME") or (os.path.expanduser("~") if os.name == "nt" else _passwd_home())
        base = os.path.join(home, ".cache") if home and os.path.isabs(home) else ""
    if base:
        roots.append(Path(base) / "seacable" / "numba")
    return roots


def _passwd_home() -> str:
    try:
        import pwd

        return pwd.getpwuid(os.getuid()).pw_dir
    except (ImportError, KeyError, OSError):
        return ""


def prune(root: str | os.PathLike, current: str, keep: int = KEEP, min_age: float = MIN_AGE,
          now: float | None = None) -> list[str]:
    """Remove old key folders under ``root``.

    Only folders named like a key (16 hexadecimal digits) are considered; ``current`` and the
    ``keep - 1`` most recently used others stay, and so does any folder used less than
    ``min_age`` seconds ago.

    Parameters
    ----------
    root : path
        Folder holding the key folders. [-]
    current : str
        The key of this process. [-]
    keep : int
        Key folders kept, the current one included. [1]
    min_age : float
        Age of last use below which a folder is kept. [s]
    now : float, optional
        Present time (``time.time()``). [s]

    Returns
    -------
    list of str
        Names of the folders removed. [-]
    """
    now = time.time() if now is None else now
    others = []
    with os.scandir(root) as entries:
        for entry in entries:
            if entry.name != current and _KEY_RE.fullmatch(entry.name) and entry.is_dir(follow_symlinks=False):
                others.append((entry.stat(follow_symlinks=False).st_mtime, entry.name))
    others.sort(reverse=True)
    removed = []
    for mtime, name in others[max(keep - 1, 0):]:
        if now - mtime >= min_age:
            shutil.rmtree(os.path.join(root, name), ignore_errors=True)
            removed.append(name)
    return removed


def _is_ours(py_file: str) -> bool:
    try:
        path = os.path.realpath(py_file)
    except (OSError, ValueError):
        return False
    return path.startswith(str(PACKAGE_DIR) + os.sep)


def _writable_folder(folder: Path) -> None:
    """Create ``folder`` and write a file in it (what numba needs), or raise OSError."""
    folder.mkdir(parents=True, exist_ok=True)
    tempfile.TemporaryFile(dir=folder).close()


def _locator_class(folder: Path):
    from numba.core import caching

    class SeacableCacheLocator(caching._CacheLocator):
        """numba cache locator for seacable's own files: ``<folder>/<subpackage path>``."""

        def __init__(self, py_func, py_file):
            self._py_file = py_file
            self._lineno = py_func.__code__.co_firstlineno
            rel = os.path.relpath(os.path.dirname(os.path.realpath(py_file)), PACKAGE_DIR)
            self._cache_path = os.path.join(folder, "seacable" if rel == os.curdir else rel)

        def get_cache_path(self):
            return self._cache_path

        def get_source_stamp(self):
            # the folder is keyed by the whole package as it was at import; this stamp
            # also catches a file that changed after that (a module imported later)
            with open(self._py_file, "rb") as f:
                return hashlib.sha256(f.read()).hexdigest()

        def get_disambiguator(self):
            return str(self._lineno)

        @classmethod
        def from_function(cls, py_func, py_file):
            if not _is_ours(py_file):
                return None
            self = cls(py_func, py_file)
            try:
                self.ensure_cache_path()
            except OSError:
                return None
            return self

    return SeacableCacheLocator


def _disable_seacable_caching() -> None:
    """Compile seacable's ``cache=True`` functions in memory only (numba's NullCache)."""
    from numba.core.dispatcher import Dispatcher

    original = Dispatcher.enable_caching
    if getattr(original, "_seacable_wrapped", False):
        return

    def enable_caching(self):
        try:
            ours = _is_ours(inspect.getfile(self.py_func))
        except TypeError:
            ours = False
        if not ours:
            original(self)

    enable_caching._seacable_wrapped = True
    Dispatcher.enable_caching = enable_caching


def install() -> Path | None:
    """Key numba's cache of seacable's kernels to the source (called once, at import).

    Returns
    -------
    Path or None
        The cache folder in use, or None when kernels are compiled in memory only. [-]
    """
    global _folder, _reason
    from numba.core import caching, config

    try:
        existing = caching.CacheImpl._locator_classes
        caching._CacheLocator  # noqa: B018  (the base class the locator needs)
    except AttributeError:  # a numba whose cache internals moved: keep numba's default
        _reason = "numba has no cache locator list; numba's default cache is used"
        return None
    key = source_key()
    tried = []
    for root in candidate_roots(config.CACHE_DIR or ""):
        folder = root / key
        try:
            _writable_folder(folder)
        except OSError as exc:
            tried.append(f"{folder}: {exc.strerror or exc}")
            continue
        try:
            os.utime(folder)  # marks the last use, for prune()
            prune(root, key)
        except OSError:
            pass  # a shared folder we do not own, or another process pruning at the same time
        existing[:] = [c for c in existing if getattr(c, "__name__", "") != "SeacableCacheLocator"]
        existing.insert(0, _locator_class(folder))
        _folder = folder
        return folder
    _disable_seacable_caching()
    _reason = "; ".join(tried) or "no home folder, XDG_CACHE_HOME or NUMBA_CACHE_DIR"
    print(f"{NOTE_PREFIX} no writable folder for numba's compiled-kernel cache ({_reason}); kernels are "
          "compiled in memory for this process only. Suggested fix: set NUMBA_CACHE_DIR or "
          "XDG_CACHE_HOME to a writable folder.", file=sys.stderr)
    return None


def cache_folder() -> Path | None:
    """The folder holding seacable's compiled kernels, or None if they are not cached. [-]"""
    return _folder


install()
