"""A full disk never loses a result, nor crashes (issue 37): faults of the file system, provoked.

- A full disk while the result is written (a real 64 kB tmpfs where it can be mounted, else a write
  monkeypatched to fail with ENOSPC; and the NetCDF library's own ``RuntimeError: NetCDF: HDF error``):
  exit 2, one message naming the file and the cause, no traceback, no temporary file left.
- A sweep resumed after one of its case results was damaged (truncated, or its header overwritten):
  the damaged case is run again, and said so; its result is the one an undamaged run gives.
- A run killed outright (SIGKILL) while it writes its result leaves its temporary file; the next write
  into that folder removes it, and leaves alone the temporaries of live processes.
"""

from __future__ import annotations

import contextlib
import errno
import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
import xarray as xr
import yaml

import seacable as sc
from seacable._atomic import TEMPORARY, remove_stale_temporaries, temporary_path
from seacable.cli import main
from seacable.results import read_netcdf

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
STATIC = EXAMPLES / "oc3_hywind_static.yaml"
DECK = Path(__file__).resolve().parents[1] / "validation" / "data" / "three_chains_deck.txt"


def _temporaries(folder: Path) -> list[str]:
    return sorted(p.name for p in Path(folder).rglob("*") if TEMPORARY in p.name or ".partial" in p.name)


def _env() -> dict:
    src = str(Path(sc.__file__).resolve().parents[1])
    return {**os.environ, "PYTHONPATH": os.pathsep.join([src, os.environ.get("PYTHONPATH", "")])}


@contextlib.contextmanager
def _small_disk(folder: Path, size: str = "64k"):
    """A tmpfs of ``size`` mounted on ``folder`` (root only); the test is skipped if mounting is refused."""
    folder.mkdir()
    if shutil.which("mount") is None:
        pytest.skip("no 'mount' command: the monkeypatched ENOSPC tests cover the full disk")
    done = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(folder)],
                          capture_output=True, text=True, check=False)
    if done.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here ({done.stderr.strip() or done.returncode}): the monkeypatched "
                    "ENOSPC tests cover the full disk")
    try:
        yield folder
    finally:
        subprocess.run(["umount", "-l", str(folder)], capture_output=True, check=False)


def _fill(folder: Path, leave: int) -> None:
    """Fill ``folder``'s file system until about ``leave`` bytes are free."""
    st = os.statvfs(folder)
    free = st.f_bavail * st.f_frsize
    (folder / "filler").write_bytes(b"\0" * max(0, free - leave))


def _one_error(err: str, *words: str) -> None:
    assert "Traceback" not in err and err.count("seacable: error:") == 1, err
    for w in words:
        assert w in err, (w, err)


def test_full_tmpfs_while_the_result_is_written(tmp_path, capsys):
    """The static OC3 result is 34 kB; 8 kB are free: the NetCDF library fails ('NetCDF: HDF error')."""
    with _small_disk(tmp_path / "disk") as disk:
        _fill(disk, 8192)
        out = disk / "r.nc"
        assert main(["run", str(STATIC), "-o", str(out), "--no-plots"]) == 2
        _one_error(capsys.readouterr().err, str(out), "the disk is full")
        assert not out.exists() and _temporaries(disk) == []


def test_full_tmpfs_while_a_run_streams_its_result(tmp_path, capsys):
    """Three chains for 2 s, written into the file as the run goes (seacable.sink), on a disk of 8 kB free."""
    with _small_disk(tmp_path / "disk") as disk:
        _fill(disk, 8192)
        out = disk / "three.nc"
        status = main(["run", str(DECK), "--duration", "2", "--output-interval", "0.1", "--no-plots", "-o", str(out)])
        err = capsys.readouterr().err
        assert status == 2, err
        _one_error(err, str(out), "the disk is full")
        assert not out.exists() and _temporaries(disk) == []


@pytest.mark.parametrize("exc, cause", [
    (OSError(errno.ENOSPC, "No space left on device"), "the disk is full"),
    (OSError(errno.EROFS, "Read-only file system"), "read-only"),
    (OSError(errno.EACCES, "Permission denied"), "no permission"),
    (RuntimeError("NetCDF: HDF error"), "NetCDF"),
])
def test_a_failed_write_is_one_message(tmp_path, monkeypatch, capsys, exc, cause):
    """Whatever the write fails with: exit 2, the file and the cause named, the temporary removed."""
    def to_netcdf(self, path, *args, **kwargs):
        Path(path).write_bytes(b"CDF\x01" + b"\0" * 1000)   # a part written, then the failure
        raise exc

    monkeypatch.setattr(xr.Dataset, "to_netcdf", to_netcdf)
    out = tmp_path / "r.nc"
    assert main(["run", str(STATIC), "-o", str(out), "--no-plots"]) == 2
    _one_error(capsys.readouterr().err, str(out), cause)
    assert list(tmp_path.iterdir()) == []


def test_a_failed_figure_write_is_one_message(tmp_path, monkeypatch, capsys):
    from matplotlib.figure import Figure

    def savefig(self, fname, *args, **kwargs):
        Path(fname).write_bytes(b"\x89PNG half")
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(Figure, "savefig", savefig)
    out = tmp_path / "r.nc"
    assert main(["run", str(STATIC), "-o", str(out)]) == 2
    _one_error(capsys.readouterr().err, ".png", "the disk is full")
    assert read_netcdf(out).attrs["analysis"] == "static"   # the result, written before the figures, is kept
    assert _temporaries(tmp_path) == []


# --- a sweep resumed over a damaged case result ---------------------------------------------------

def _sweep(tmp_path: Path) -> Path:
    path = tmp_path / "sweep.yaml"
    path.write_text(yaml.safe_dump({"name": "s", "base": str(STATIC), "grid": {"environment.depth": [320.0, 330.0]}}))
    return path


@pytest.mark.parametrize("damage", ["truncated", "header"])
def test_a_resumed_sweep_runs_a_damaged_case_again(tmp_path, capsys, damage):
    """Case 1's result is cut in half (a disk that filled up, a copy stopped midway) or its first 512 bytes
    overwritten (same size): the next run of the sweep says so and runs it again, and its fairlead tension is
    the first run's to the last bit (the same deterministic statics)."""
    spec, out = _sweep(tmp_path), tmp_path / "out"
    argv = ["sweep", str(spec), "-o", str(out), "--scheduler", "synchronous", "--no-plots"]
    assert main(argv) == 0
    nc = out / "cases" / "0001.nc"
    first = float(read_netcdf(nc).fairlead_tension)
    assert 9e5 < first < 1.1e6   # the OC3 line at 330 m depth: about 1.0 MN (the sweep's summary, above)
    data = nc.read_bytes()
    nc.write_bytes(data[: len(data) // 2] if damage == "truncated" else b"\0" * 512 + data[512:])
    capsys.readouterr()
    assert main(argv) == 0
    err = capsys.readouterr().err
    assert "Traceback" not in err
    assert "seacable: warning: 1 case result(s)" in err and "case 1" in err and str(nc) in err, err
    assert "run again" in err
    assert float(read_netcdf(nc).fairlead_tension) == first
    record = json.loads((out / "cases" / "0001.json").read_text())
    assert record["status"] == "done" and record["result_bytes"] == nc.stat().st_size
    summary = xr.load_dataset(out / "summary.nc")
    assert list(summary.reused.values) == [1, 0]   # case 0 kept, case 1 run again
    assert _temporaries(out) == []


def test_a_resumed_sweep_keeps_whole_results(tmp_path, capsys):
    spec, out = _sweep(tmp_path), tmp_path / "out"
    argv = ["sweep", str(spec), "-o", str(out), "--scheduler", "synchronous", "--no-plots"]
    assert main(argv) == 0
    capsys.readouterr()
    assert main(argv) == 0
    assert "warning" not in capsys.readouterr().err
    assert list(xr.load_dataset(out / "summary.nc").reused.values) == [1, 1]


# --- SIGKILL: temporaries of dead processes ---------------------------------------------------------

def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def test_stale_temporaries_of_dead_processes_are_removed(tmp_path):
    target = tmp_path / "r.nc"
    mine = temporary_path(target)
    assert mine.name.startswith(".r.nc.seacable-tmp-") and mine.suffix == ".nc" and str(os.getpid()) in mine.name
    dead = mine.with_name(mine.name.replace(f"-{os.getpid()}-", f"-{_dead_pid()}-"))
    other_host = dead.with_name(dead.name.replace(".seacable-tmp-", ".seacable-tmp-elsewhere"))
    live = mine.with_name(mine.name.replace(f"-{os.getpid()}-", "-1-"))     # init: alive
    plain = tmp_path / ".r.nc.backup"
    for p in (mine, dead, other_host, live, plain):
        p.write_bytes(b"x")
    assert remove_stale_temporaries(tmp_path) == [dead]
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(p.name for p in (mine, other_host, live, plain))


def test_sigkill_mid_write_then_the_next_run_cleans_up(tmp_path, capsys):
    """A run of the three chains writing its result as it goes is killed (SIGKILL) once its temporary file is
    there (its first block of outputs being written, before its first progress line): the file is left (nothing
    can remove it). The next run into that folder removes it."""
    deck = tmp_path / "three.txt"
    deck.write_text(DECK.read_text())
    out = tmp_path / "three.nc"
    proc = subprocess.Popen([sys.executable, "-m", "seacable", "run", str(deck), "-o", str(out), "--no-plots",
                             "--duration", "3600", "--output-interval", "0.1"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, cwd=tmp_path, env=_env())
    os.set_blocking(proc.stderr.fileno(), False)
    seen, t0 = b"", time.monotonic()
    while not _temporaries(tmp_path):
        assert proc.poll() is None, seen
        assert time.monotonic() - t0 < 600, "no result file begun"
        seen += proc.stderr.read() or b""
        time.sleep(0.02)
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=60)
    proc.stderr.close()
    left = _temporaries(tmp_path)
    assert len(left) == 1 and left[0].startswith(f".three.nc{TEMPORARY}") and f"-{proc.pid}-" in left[0], left
    assert not out.exists()
    # the next run into the folder (another result) removes it
    assert main(["run", str(STATIC), "-o", str(tmp_path / "static.nc"), "--no-plots"]) == 0
    capsys.readouterr()
    assert _temporaries(tmp_path) == []
