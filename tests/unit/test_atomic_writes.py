"""Results are never lost (issue 17): whole-file writes, and interrupts that keep what was computed.

Every writer (NetCDF results, PNG figures, animations, sweep records and summaries) goes through
:func:`seacable._atomic.atomic_path`. A write made to fail midway (monkeypatched to write part of
the file and then raise) must leave the previous good file byte for byte, and no temporary file.
Ctrl-C (SIGINT) or SIGTERM during the write of a computed result must not lose it; SIGTERM during
the time loop keeps what was computed, as Ctrl-C does (subprocess test).
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import yaml

import seacable as sc
from seacable._atomic import atomic_path, atomic_write, deferred_interrupts, interrupt_requested
from seacable.cli import main
from seacable.errors import InputError, SeacableWarning
from seacable.results import make_dataset, read_netcdf, var, write_netcdf

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
STATIC = EXAMPLES / "oc3_hywind_static.yaml"


def seacable_env() -> dict:
    """The environment of a subprocess that imports this seacable (the tests may run from a source tree)."""
    src = str(Path(sc.__file__).resolve().parents[1])
    return {**os.environ, "PYTHONPATH": os.pathsep.join([src, os.environ.get("PYTHONPATH", "")])}


def _result(value: float):
    return make_dataset({"tension": var("node", np.full(4, value), "N", "effective tension")},
                        {"s": var("node", np.arange(4.0), "m", "arc length")}, analysis="static")


def _leftovers(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if ".partial" in p.name or "seacable-tmp" in p.name or p.name.startswith(".seacable"))


class Boom(Exception):
    pass


def _half_then(exc):
    """A to_netcdf that writes half a file at the path it is given, then raises ``exc``."""
    def to_netcdf(self, path, *args, **kwargs):
        Path(path).write_bytes(b"CDF\x01" + b"\0" * 100)
        raise exc
    return to_netcdf


@pytest.mark.parametrize("exc, raised", [(Boom("disk gone"), Boom), (OSError(28, "No space left on device"),
                                                                      InputError),
                                         (KeyboardInterrupt(), KeyboardInterrupt)])
def test_failed_netcdf_write_keeps_the_previous_file(tmp_path, monkeypatch, exc, raised):
    path = tmp_path / "r.nc"
    write_netcdf(_result(1.0), path)
    good = path.read_bytes()
    monkeypatch.setattr(xr.Dataset, "to_netcdf", _half_then(exc))
    with pytest.raises(raised):
        write_netcdf(_result(2.0), path)
    assert path.read_bytes() == good
    assert _leftovers(tmp_path) == []
    monkeypatch.undo()
    assert float(read_netcdf(path).tension[0]) == 1.0


def test_failed_first_write_leaves_nothing(tmp_path, monkeypatch):
    monkeypatch.setattr(xr.Dataset, "to_netcdf", _half_then(Boom()))
    with pytest.raises(Boom):
        write_netcdf(_result(2.0), tmp_path / "r.nc")
    assert list(tmp_path.iterdir()) == []


def test_failed_png_write_keeps_the_previous_figure(tmp_path, monkeypatch):
    from matplotlib.figure import Figure

    from seacable.plot import plot_result

    ds = sc.run(sc.load_case(STATIC))
    (png,) = plot_result(ds, tmp_path, prefix="r")
    good = png.read_bytes()
    assert good.startswith(b"\x89PNG")

    def savefig(self, fname, *args, **kwargs):
        Path(fname).write_bytes(b"\x89PNG half")
        raise KeyboardInterrupt

    monkeypatch.setattr(Figure, "savefig", savefig)
    with pytest.raises(KeyboardInterrupt):
        plot_result(ds, tmp_path, prefix="r")
    assert png.read_bytes() == good
    assert _leftovers(tmp_path) == []


def test_failed_animation_keeps_the_previous_file(tmp_path):
    import matplotlib.pyplot as plt

    from seacable.plot import animation_writer

    def animate(path, frames_before_failure=None):
        path, writer, frames, plt_ = animation_writer(path, fps=5, max_frames=4, dpi=40, n_times=4)
        fig, ax = plt_.subplots(figsize=(2, 2))
        line, = ax.plot([], [])
        try:
            with writer.saving(fig, str(path), 40):
                for k, i in enumerate(frames):
                    if k == frames_before_failure:
                        raise Boom
                    line.set_data([0, 1], [0, i])
                    writer.grab_frame()
        finally:
            plt_.close(fig)

    gif = tmp_path / "a.gif"
    animate(gif)
    good = gif.read_bytes()
    assert good.startswith(b"GIF8")
    with pytest.raises(Boom):
        animate(gif, frames_before_failure=2)
    assert gif.read_bytes() == good
    assert _leftovers(tmp_path) == []
    plt.close("all")


def test_atomic_write_replaces_whole(tmp_path):
    path = tmp_path / "a.txt"
    atomic_write(path, lambda tmp: tmp.write_text("one"))
    assert path.read_text() == "one"
    with pytest.raises(Boom), atomic_path(path) as tmp:
        tmp.write_text("tw")
        raise Boom
    assert path.read_text() == "one" and _leftovers(tmp_path) == []
    with atomic_path(path) as tmp:
        assert tmp.parent == path.parent and tmp.suffix == ".txt" and tmp.name.startswith(".")
        tmp.write_text("two")
    assert path.read_text() == "two" and _leftovers(tmp_path) == []


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_deferred_interrupts_finish_the_block_then_interrupt(sig):
    # The signals are raised in this (the main) thread: os.kill(os.getpid(), sig) lets the kernel hand a
    # process-wide signal to any thread, and on a loaded machine (a fresh-home run of the suite, compiling)
    # that thread may not run its C handler before the block ends; the Python handler then ran after the
    # handlers were restored (the test failed twice so, passing alone). raise_signal delivers before returning.
    # From Python's own handlers, whatever an earlier test of this worker left; the handlers found in the message.
    found = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    interrupt_requested.clear()
    try:
        done = []
        with pytest.raises(KeyboardInterrupt), deferred_interrupts():
            signal.raise_signal(sig)
            time.sleep(0.05)
            done.append(1)
        assert done == [1] and interrupt_requested.is_set(), found
        interrupt_requested.clear()
        # handlers restored: SIGINT raises KeyboardInterrupt again at once
        with pytest.raises(KeyboardInterrupt):
            signal.raise_signal(signal.SIGINT)
            time.sleep(0.5)
    finally:
        for s, handler in found.items():
            signal.signal(s, signal.SIG_DFL if handler is None else handler)


def test_ctrl_c_while_the_result_is_written_still_writes_it(tmp_path, monkeypatch, capsys):
    """A Ctrl-C that arrives while the computed result is written: the file is whole, exit 130."""
    original = xr.Dataset.to_netcdf

    def slow_to_netcdf(self, path, *args, **kwargs):
        signal.raise_signal(signal.SIGINT)   # the user presses Ctrl-C during the write
        time.sleep(0.05)
        return original(self, path, *args, **kwargs)

    monkeypatch.setattr(xr.Dataset, "to_netcdf", slow_to_netcdf)
    out = tmp_path / "r.nc"
    assert main(["run", str(STATIC), "-o", str(out)]) == 130
    err = capsys.readouterr().err
    assert "interrupted" in err and str(out) in err
    monkeypatch.undo()
    ds = read_netcdf(out)
    assert ds.attrs["analysis"] == "static" and float(ds.fairlead_tension) > 0
    assert not list(tmp_path.glob("*.png"))   # stopped before the plots
    assert _leftovers(tmp_path) == []


def test_ctrl_c_while_plotting_keeps_the_result(tmp_path, monkeypatch, capsys):
    from matplotlib.figure import Figure

    def savefig(self, *args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(Figure, "savefig", savefig)
    out = tmp_path / "r.nc"
    assert main(["run", str(STATIC), "-o", str(out)]) == 130
    assert "seacable plot" in capsys.readouterr().err
    assert read_netcdf(out).attrs["analysis"] == "static"
    assert _leftovers(tmp_path) == []


# --- sweeps use the same writer ------------------------------------------------------------------

def _sweep(tmp_path: Path) -> Path:
    path = tmp_path / "sweep.yaml"
    path.write_text(yaml.safe_dump({"name": "s", "base": str(STATIC), "grid": {"environment.depth": [320.0, 330.0]}}))
    return path


def test_sweep_summary_and_records_written_whole(tmp_path, monkeypatch):
    from seacable.sweeps import sweep

    out = tmp_path / "out"
    sweep(_sweep(tmp_path), out, scheduler="synchronous")
    summary, record = out / "summary.nc", out / "cases" / "0000.json"
    good_summary, good_record = summary.read_bytes(), record.read_bytes()
    assert json.loads(good_record)["status"] == "done"
    # a failed summary write keeps the previous summary
    monkeypatch.setattr(xr.Dataset, "to_netcdf", _half_then(Boom()))
    with pytest.raises(Boom):
        sweep(_sweep(tmp_path), out, scheduler="synchronous", retry_failed=True)
    assert summary.read_bytes() == good_summary
    monkeypatch.undo()
    # a failed record write (the text written, then the process dies) keeps the previous record
    (out / "cases" / "0000.nc").unlink()   # case 0 runs again

    write_text_ = Path.write_text

    def write_text(self, *args, **kwargs):
        if self.suffix != ".json":
            return write_text_(self, *args, **kwargs)
        Path.write_bytes(self, b'{"index": 0, "stat')
        raise Boom

    monkeypatch.setattr(Path, "write_text", write_text)
    with pytest.raises(Boom), pytest.warns(SeacableWarning, match="recorded as done .* are run again: case 0"):
        sweep(_sweep(tmp_path), out, scheduler="synchronous")
    monkeypatch.undo()
    assert record.read_bytes() == good_record
    assert _leftovers(out) == [] and _leftovers(out / "cases") == []


# --- SIGTERM in a real run (subprocess) ----------------------------------------------------------

def _sigterm_run(tmp_path, case, when: bytes, options=()):
    """``seacable run`` of ``case`` (a dict, written as YAML, or a file) with ``options``, sent SIGTERM once
    ``when`` appears on its stderr: the result."""
    if isinstance(case, dict):
        path = tmp_path / "lay.yaml"
        path.write_text(yaml.safe_dump(case))
    else:
        path = case
    out = tmp_path / "lay.nc"
    proc = subprocess.Popen([sys.executable, "-m", "seacable", "run", str(path), "-o", str(out), "--no-plots",
                             *options],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=tmp_path, env=seacable_env())
    os.set_blocking(proc.stderr.fileno(), False)
    seen, t0 = b"", time.monotonic()
    while when not in seen:
        assert proc.poll() is None, seen
        assert time.monotonic() - t0 < 300, "no progress line"
        seen += proc.stderr.read() or b""
        time.sleep(0.01)
    proc.send_signal(signal.SIGTERM)
    _, stderr = proc.communicate(timeout=120)
    stderr = seen + (stderr or b"")
    assert proc.returncode == 130, stderr
    assert b"Traceback" not in stderr and b"interrupted" in stderr
    assert _leftovers(tmp_path) == []
    return read_netcdf(out)


def test_sigterm_keeps_what_was_computed(tmp_path):
    """A long lay gets SIGTERM at its first progress line: exit 130, the result file holds the run up to
    then, flagged interrupted."""
    case = yaml.safe_load((EXAMPLES / "paper001_lay_2ms_50m.yaml").read_text())
    case["analysis"]["duration"] = 30000.0   # about a minute of computing: the signal comes mid-run
    case["line"]["length"] = 70000.0
    ds = _sigterm_run(tmp_path, case, b"seacable: t = ")
    assert int(ds.attrs["interrupted"]) == 1
    assert 0.0 < float(ds.time[-1]) < case["analysis"]["duration"]


def test_sigterm_keeps_what_a_run_written_as_it_goes_computed(tmp_path):
    """Three chains run for an hour, written into the result file as they go (a MoorDyn deck with a duration
    streams, :mod:`seacable.sink`), get SIGTERM at the first progress line: exit 130, the file is in place,
    no temporary file beside it, and it holds the outputs up to then, every 0.1 s from 0, flagged
    interrupted, with the snap loads (none) of those outputs."""
    deck = tmp_path / "three.txt"
    deck.write_text((Path(__file__).parents[1] / "validation" / "data" / "three_chains_deck.txt").read_text())
    ds = _sigterm_run(tmp_path, deck, b"seacable: t = ", ("--duration", "3600", "--output-interval", "0.1"))
    assert int(ds.attrs["interrupted"]) == 1
    n = ds.sizes["time"]
    assert 1 < n < 36001
    assert np.allclose(ds.time, 0.1 * np.arange(n), rtol=0, atol=1e-9)
    assert np.all(np.isfinite(ds.fairlead_tension)) and ds.sizes["snap"] == 0


def test_sigterm_after_the_last_step_still_writes_the_whole_result(tmp_path):
    """The signal comes once the time loop has ended (its 100 % line), while the result is assembled and
    written: the whole result is written, not interrupted, and the exit status still says 130."""
    case = yaml.safe_load((EXAMPLES / "paper001_lay_2ms_50m.yaml").read_text())
    # 100 s of the example's 300 (a third of its time loop): what is tested comes after the loop's last step; the
    # result is assembled and written (about a second) whatever the duration, and the signal comes in that time
    case["analysis"]["duration"] = 100.0
    ds = _sigterm_run(tmp_path, case, b"(100 %)")
    assert int(ds.attrs["interrupted"]) == 0
    assert float(ds.time[-1]) == case["analysis"]["duration"]


def test_nested_deferrals_raise_once_after_the_outermost():
    steps = []
    with pytest.raises(KeyboardInterrupt), deferred_interrupts():
        with deferred_interrupts():
            signal.raise_signal(signal.SIGTERM)
            time.sleep(0.05)
            steps.append("inner done")
        steps.append("outer done")   # the inner block does not interrupt the outer one
    assert steps == ["inner done", "outer done"]
