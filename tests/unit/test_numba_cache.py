"""numba's cache of seacable's kernels: keyed to the source, and never a crash at import.

``seacable._numba_cache`` puts the compiled kernels in a folder named by a hash of the
package source, so that a kernel calling a function of another module is recompiled when
that module changes (numba itself checks only the kernel's own file), and compiles in memory
with a one-line note when no folder can be written (issue 17).

The end-to-end tests run Python in a subprocess on a copy of the package, so that they can
change its source and its environment (home folder, cache variables) without touching the
installed one.
"""

import os
import shutil
import subprocess
import sys
import textwrap

import pytest

from seacable import _numba_cache as nc

IGNORE = shutil.ignore_patterns("__pycache__", "*.pyc")


def _copy_package(dest, *, pycache_files=False):
    """Copy seacable to ``dest/seacable``; optionally make every ``__pycache__`` a plain file,
    so that nothing can be written beside the source (a read-only site-packages, as root too)."""
    pkg = dest / "seacable"
    shutil.copytree(nc.PACKAGE_DIR, pkg, ignore=IGNORE)
    if pycache_files:
        for folder, _, _ in os.walk(pkg):
            with open(os.path.join(folder, "__pycache__"), "w"):
                pass
    return pkg


def _env(path_dir, **extra):
    env = {k: v for k, v in os.environ.items()
           if k not in ("NUMBA_CACHE_DIR", "XDG_CACHE_HOME", "HOME", "PYTHONPATH")}
    env["PYTHONPATH"] = str(path_dir)
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    env.update({k: str(v) for k, v in extra.items() if v is not None})
    return env


def _python(code, env, cwd):
    return subprocess.run([sys.executable, "-c", textwrap.dedent(code)], check=False, env=env, cwd=cwd,
                          capture_output=True, text=True, timeout=600)


# ---------------------------------------------------------------------------------------------
# the key


def test_key_changes_with_one_byte_of_any_source_file(tmp_path):
    a = _copy_package(tmp_path / "a")
    b = _copy_package(tmp_path / "b")
    # the same source elsewhere gives the same key: two checkouts of one commit share a cache
    assert nc.source_key(a) == nc.source_key(b) == nc.source_key()
    before = nc.source_key(b)
    helper = b / "statics" / "catenary.py"  # a file without kernels, called by others
    data = bytearray(helper.read_bytes())
    data[-2:-1] = b" " if data[-2:-1] != b" " else b"\t"
    helper.write_bytes(bytes(data))
    changed = nc.source_key(b)
    assert changed != before
    # a new module counts, a file that is not Python does not
    (b / "new_module.py").write_text("x = 1\n")
    assert nc.source_key(b) != changed
    newer = nc.source_key(b)
    (b / "notes.txt").write_text("not source\n")
    assert nc.source_key(b) == newer


def test_key_changes_with_the_compiler_versions():
    assert nc.source_key(versions=b"numba 0.60.0") != nc.source_key(versions=b"numba 0.61.0")


def test_candidate_roots(tmp_path):
    home = str(tmp_path / "home")
    assert nc.candidate_roots("", {"HOME": home}) == [tmp_path / "home" / ".cache" / "seacable" / "numba"]
    xdg = str(tmp_path / "xdg")
    assert nc.candidate_roots("", {"HOME": home, "XDG_CACHE_HOME": xdg}) == [tmp_path / "xdg" / "seacable" / "numba"]
    # a relative XDG_CACHE_HOME is invalid by the XDG spec and ignored
    assert nc.candidate_roots("", {"HOME": home, "XDG_CACHE_HOME": "rel"})[0].parent.parent.name == ".cache"
    # NUMBA_CACHE_DIR set by the user: seacable keys a subfolder of it, tried first
    user = str(tmp_path / "numba")
    assert nc.candidate_roots(user, {"XDG_CACHE_HOME": xdg}) == [tmp_path / "numba" / "seacable",
                                                                  tmp_path / "xdg" / "seacable" / "numba"]


def _key_folders(root, ages, now):
    for key, age in ages.items():
        (root / key / "sub").mkdir(parents=True)
        os.utime(root / key, (now - age, now - age))


def test_prune_keeps_the_current_and_the_most_recently_used_folders(tmp_path):
    now, hour = 1.0e9, 3600.0
    ages = {"0" * 16: 50 * hour,  # the current key: kept whatever its age
            "1" * 16: 2 * hour, "2" * 16: 3 * hour, "3" * 16: 4 * hour,  # 3 most recent others
            "4" * 16: 5 * hour, "5" * 16: 30 * hour}  # older: removed
    _key_folders(tmp_path, ages, now)
    # not ours: a folder with another name, a file named like a key
    (tmp_path / "my-notes").mkdir()
    os.utime(tmp_path / "my-notes", (now - 99 * hour,) * 2)
    (tmp_path / ("f" * 16)).write_text("a file")
    removed = nc.prune(tmp_path, "0" * 16, keep=4, min_age=hour, now=now)
    assert sorted(removed) == ["4" * 16, "5" * 16]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["0" * 16, "1" * 16, "2" * 16, "3" * 16,
                                                          "f" * 16, "my-notes"]


def test_prune_keeps_a_folder_used_recently_by_another_process(tmp_path):
    now, hour = 1.0e9, 3600.0
    ages = {"0" * 16: 0.0, "1" * 16: 0.2 * hour,  # current and the most recent other: by rank
            "2" * 16: 0.4 * hour, "3" * 16: 0.9 * hour,  # used in the last hour: kept by age
            "4" * 16: 1.5 * hour}  # removed
    _key_folders(tmp_path, ages, now)
    assert nc.prune(tmp_path, "0" * 16, keep=2, min_age=hour, now=now) == ["4" * 16]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["0" * 16, "1" * 16, "2" * 16, "3" * 16]


def test_this_process_caches_in_the_keyed_folder():
    folder = nc.cache_folder()
    if folder is None:  # the machine running the tests has no writable cache folder
        pytest.skip("no writable cache folder here; covered by the subprocess tests")
    assert folder.name == nc.source_key()
    from seacable.waves import airy_kinematics

    assert airy_kinematics._cache.cache_path.startswith(str(folder) + os.sep)


# ---------------------------------------------------------------------------------------------
# end to end, in subprocesses

# two kernel modules as seacable's are written: their njit from seacable._jit, which keys the cache first
PROBE_A = """
from seacable import _probe_b
from seacable._jit import njit

@njit(cache=True)
def f():
    return _probe_b.g()
"""
PROBE_B = """
from seacable._jit import njit

@njit(cache=True)
def g():
    return {value}
"""
RUN_PROBE = "import seacable._probe_a as a; print(a.f())"


def test_a_change_in_another_module_recompiles_the_kernel(tmp_path):
    # Regression (issue 17): kernel f (module _probe_a) calls g (module _probe_b); numba keys
    # f's cache entry to _probe_a.py only, so after g changed it ran the old g. Keyed by the
    # whole package, the second run must see the new g.
    pkg = _copy_package(tmp_path / "src")
    (pkg / "_probe_a.py").write_text(PROBE_A)
    (pkg / "_probe_b.py").write_text(PROBE_B.format(value="1.0"))
    env = _env(tmp_path / "src", HOME=tmp_path / "home", XDG_CACHE_HOME=tmp_path / "cache")
    first = _python(RUN_PROBE, env, tmp_path)
    assert first.returncode == 0, first.stderr
    assert first.stdout.split() == ["1.0"]
    first_key = nc.source_key(pkg)

    (pkg / "_probe_b.py").write_text(PROBE_B.format(value="2.0"))
    second = _python(RUN_PROBE, env, tmp_path)
    assert second.returncode == 0, second.stderr
    assert second.stdout.split() == ["2.0"]
    # f was cached where the keys say, once per source, not beside the source
    for key in (first_key, nc.source_key(pkg)):
        assert list((tmp_path / "cache" / "seacable" / "numba" / key / "seacable").glob("_probe_a.f-*.nbi"))
    assert not (pkg / "__pycache__").exists()

    # a user-set NUMBA_CACHE_DIR is respected: seacable keys a subfolder of it
    env = _env(tmp_path / "src", HOME=tmp_path / "home", NUMBA_CACHE_DIR=tmp_path / "numba")
    third = _python(RUN_PROBE, env, tmp_path)
    assert third.returncode == 0, third.stderr
    assert third.stdout.split() == ["2.0"]
    assert list((tmp_path / "numba" / "seacable" / nc.source_key(pkg) / "seacable").glob("_probe_a.f-*.nbi"))


def test_import_and_a_kernel_run_without_a_writable_cache_folder(tmp_path):
    # Regression (issue 17): with a read-only install and no usable home, numba raised
    # "RuntimeError: cannot cache function" while importing seacable. Nothing can be written:
    # every __pycache__ of the copy is a plain file (stops writes even as root), and the cache
    # variables point below a plain file; there is no HOME.
    _copy_package(tmp_path / "src", pycache_files=True)
    blocker = tmp_path / "a_file"
    blocker.write_text("")
    env = _env(tmp_path / "src", XDG_CACHE_HOME=blocker / "xdg", NUMBA_CACHE_DIR=blocker / "numba")
    code = """
        import seacable
        from seacable._numba_cache import cache_folder
        from seacable.waves import airy_kinematics
        print(cache_folder(), *airy_kinematics(3.0, 0.0, -10.0, 1.0, 2.0, 8.0, 0.08, 50.0, 0.0, 0.0, 9.81))
    """
    result = _python(code, env, tmp_path)
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("seacable: note: no writable folder")
    assert "NUMBA_CACHE_DIR" in lines[0] and str(blocker) in lines[0]
    out = result.stdout.split()
    assert out[0] == "None"
    # the kernel compiled in memory gives the same numbers as this process's (cached) one
    from seacable.waves import airy_kinematics

    expected = airy_kinematics(3.0, 0.0, -10.0, 1.0, 2.0, 8.0, 0.08, 50.0, 0.0, 0.0, 9.81)
    # same code from the same compiler: equal to the last bit (repr round-trips a float)
    assert [float(v) for v in out[1:]] == [float(v) for v in expected]
    assert not list(tmp_path.rglob("*.nbi"))  # nothing cached anywhere under the copy

