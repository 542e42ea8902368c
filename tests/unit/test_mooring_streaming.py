"""A long mooring run's outputs go out in blocks as they are computed, into memory or into a NetCDF file
(issue 19: a 3-hour run of three 40-element lines with an output every 0.1 s fits in 1 GB).

The blocks must be the run cut in pieces (every output once, in order, the same floats), a block must lie in
the irregular sea's grid window it was computed in, an interrupt must lose no output, and the result written
as it goes must be the result built in memory. The process's memory is measured on the issue's own case in
``bench/bench_memory.py``; here, with tracemalloc, that a run written as it goes holds a block, not the run.
"""

from __future__ import annotations

import tracemalloc
import warnings
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import seacable as sc
from seacable.extremes import snap_loads
from seacable.io.moordyn import load_moordyn_case
from seacable.mooring import solver as S
from seacable.mooring.moordyn import moordyn_model, run_moordyn_case
from seacable.mooring.motion import HarmonicMotion, bind
from seacable.mooring.run import prepare_mooring_dynamic, stored_per_output
from seacable.mooring.solver import line_end_nodes, simulate, static_equilibrium
from seacable.results import open_netcdf

DATA = Path(__file__).parents[1] / "validation" / "data"
THREE = DATA / "three_chains_deck.txt"  # three 40-segment WD0200 chains (bench/bench_memory.py's case)
FIELDS = ("time", "position", "velocity", "acceleration", "tension", "support")

# two copies of the tank chain of snap_deck.txt, 30 segments each, 2 m apart: both go slack and snap
TWO_SNAPPING = """two tank chains whose fairleads heave 0.15 m every 1.25 s (snap loads on both lines)
---------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.0054  0.0948     3.0e5      -0.8        0          1.2    1.0    0.2     0.0
---------------------- POINT PROPERTIES --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     0.0     0.0     -2.5    0      0       0      0
2     Vessel    32.0    0.0     -0.3    0      0       0      0
3     Fixed     0.0     2.0     -2.5    0      0       0      0
4     Vessel    32.0    2.0     -0.3    0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        2         33.0      30      -
2     chain      3        4         33.0      30      -
---------------------- OPTIONS -----------------------------------------
3.0e6                kBot                 bottom stiffness (Pa/m)
1.0e4                cBot                 bottom damping (Pa-s/m)
1000.0               WtrDnsty             water density (kg/m^3)
2.5                  WtrDpth              water depth (m)
------------------------- need this line --------------------------------------
"""


def _three_case(duration, output_interval=0.1):
    return load_moordyn_case(THREE).with_run(duration=duration, time_step=0.1, output_interval=output_interval,
                                             motion=HarmonicMotion(amplitude=(0.0, 0.0, 2.0), period=10.0))


def _run(case, out=None):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the decks' MoorDyn-only options
        return run_moordyn_case(case, out=out)


def _same(a: xr.Dataset, b: xr.Dataset) -> None:
    """Identical variables, coordinates and attributes, but for the wall time."""
    a, b = a.copy(), b.copy()
    for ds in (a, b):
        ds.attrs.pop("wall_time")
    xr.testing.assert_identical(a, b)


@pytest.fixture(scope="module")
def three():
    model = moordyn_model(THREE)
    st = static_equilibrium(model)
    motion = bind(HarmonicMotion(amplitude=(0.0, 0.0, 2.0), period=10.0), model.network.channel_positions(st.position),
                  20.0)
    return model, st.position, motion


def test_blocks_are_the_run_cut_in_pieces(three):
    """Blocks of 7 outputs: 101 outputs in 15 blocks, each output once and in order, the same floats as the
    run that keeps them all; the run returned holds no outputs but the same counts."""
    model, start, motion = three
    ends = line_end_nodes(model.network)
    whole = simulate(model, motion, 20.0, 0.1, 0.2, initial=start, kinematics=ends)
    blocks = []
    run = simulate(model, motion, 20.0, 0.1, 0.2, initial=start, kinematics=ends, on_outputs=blocks.append,
                   block_outputs=7)
    assert [b.time.size for b in blocks] == [7] * 14 + [3]
    for name in FIELDS:
        assert np.array_equal(np.concatenate([getattr(b, name) for b in blocks]), getattr(whole, name)), name
    assert run.time.size == 0 and run.position.shape == (0, model.network.n_nodes, 3)
    assert (run.steps, run.iterations, run.interrupted) == (whole.steps, whole.iterations, False)


def test_an_interrupt_loses_no_output_and_sends_none_twice(three):
    """Ctrl-C at the 7th output (in the progress callback, inside a compiled chunk), blocks of 3: outputs 0 to
    7 (t = 0 to 1.4 s) go out once each, as a run that keeps them all keeps them."""
    model, start, motion = three

    def stop_at_seventh():
        seen = []

        def progress(t, duration):
            seen.append(t)
            if len(seen) == 7:
                raise KeyboardInterrupt
        return progress

    whole = simulate(model, motion, 20.0, 0.1, 0.2, initial=start, progress=stop_at_seventh())
    blocks = []
    run = simulate(model, motion, 20.0, 0.1, 0.2, initial=start, progress=stop_at_seventh(),
                   on_outputs=blocks.append, block_outputs=3)
    assert run.interrupted and whole.interrupted
    times = np.concatenate([b.time for b in blocks])
    assert times == pytest.approx(np.arange(8) * 0.2, abs=1e-12)
    assert np.array_equal(np.concatenate([b.position for b in blocks]), whole.position)
    assert all(b.interrupted for b in blocks[-1:])


def test_a_block_lies_in_the_sea_window_it_was_computed_in(monkeypatch):
    """An irregular sea in grid windows of 2.5 s (a smaller window limit), blocks of 50 outputs (25 s): each block goes out before the
    window moves on, so that its states lie in the window of ``model.sea`` when it goes out (the end forces
    of its outputs are evaluated in it), and the blocks are still the whole run."""
    from seacable.seastate import S_DT, S_NT, S_T0

    monkeypatch.setattr(S, "SEA_WINDOW_VALUES", 2e4)
    case = sc.load_case(DATA / "seastate" / "oc3_jonswap.yaml")
    setup = prepare_mooring_dynamic(case)
    model = setup.model
    start = static_equilibrium(setup.start_model).position
    a = case.analysis
    whole = simulate(model, setup.motion, a.duration, a.time_step, a.output_interval, initial=start)
    windows = set()
    blocks = []

    def take(block):
        s = model.sea
        t0, t1 = s[S_T0], s[S_T0] + s[S_DT] * (s[S_NT] - 1)
        windows.add(t0)
        assert t0 <= block.time[0] and block.time[-1] <= t1
        blocks.append(block)

    simulate(model, setup.motion, a.duration, a.time_step, a.output_interval, initial=start, on_outputs=take,
             block_outputs=50)
    assert len(windows) >= 3  # the run crossed windows
    assert len(blocks) == len(windows)  # windows of 2.5 s, shorter than a block: a block ends with its window
    for name in FIELDS:
        assert np.array_equal(np.concatenate([getattr(b, name) for b in blocks]), getattr(whole, name)), name


def test_a_result_written_as_it_goes_is_the_result_in_memory(tmp_path, monkeypatch):
    """Three chains, 20 s, an output every 0.1 s: the result built in one block, in blocks of 16 outputs,
    and written into a NetCDF file in blocks of 16 (13 writes) are identical; the file
    is in place under its name, no temporary file beside it."""
    one = _run(_three_case(20.0))
    monkeypatch.setattr(S, "BLOCK_VALUES", 2**14)  # 931 values an output: blocks of 16
    many = _run(_three_case(20.0))
    out = tmp_path / "three.nc"
    written = _run(_three_case(20.0), out)
    _same(one, many)
    _same(one, written.load())
    assert sorted(p.name for p in tmp_path.iterdir()) == ["three.nc"]
    with open_netcdf(out) as ds:
        # chunks of about 2**17 values: 1065 outputs of 3 x 41, down to a power of two (whole chunks a block)
        assert ds["x"].encoding["chunksizes"] == (3, 1024, 41)


def test_snap_loads_of_a_result_in_blocks_are_those_of_the_whole_run(tmp_path, monkeypatch):
    """Two snapping lines: the snap events found line by line in the stored tensions (blocks of 8 outputs,
    written to a file) are those :func:`seacable.extremes.snap_loads` finds in the whole run's element
    tensions: same times, elements (network indices) and peaks, in the same order."""
    deck = tmp_path / "two.txt"
    deck.write_text("-" * 20 + " MoorDyn Input File " + "-" * 20 + "\n" + TWO_SNAPPING)
    motion = HarmonicMotion(amplitude=(0.0, 0.0, 0.15), period=1.25)
    # 2.5 s, two periods of the heave (was 5 s, four): both lines still snap, 358 events in 156 blocks (610 in 312
    # over 5 s); the time went into the blocks' writes, one per 16 ms of simulated time
    duration = 2.5
    case = load_moordyn_case(deck).with_run(duration=duration, time_step=2e-3, output_interval=2e-3, motion=motion)
    model = moordyn_model(deck)
    st = static_equilibrium(model, tol=1e-8)
    whole = simulate(model, bind(motion, model.network.channel_positions(st.position), duration), duration, 2e-3,
                     2e-3, initial=st.position, tol=1e-7)
    t, e, peak = snap_loads(whole.time, whole.tension)
    assert set(model.network.element_line[e]) == {0, 1}  # both lines snap
    monkeypatch.setattr(S, "BLOCK_VALUES", 8 * (1 + 6 * model.network.n_nodes + 60 + 6 * 8))
    ds = _run(case, tmp_path / "two.nc")
    assert ds.sizes["snap"] == t.size > 20
    assert np.array_equal(ds["snap_time"], t) and np.array_equal(ds["snap_element"], e)
    assert np.array_equal(ds["snap_tension"], peak)


def test_the_size_of_a_result_is_what_the_run_size_check_counts(monkeypatch):
    """``stored_per_output`` counts the values of the result an output: for three 40-element lines
    (x, y, z and node tension of 3 x 41 nodes, 3 x 40 element tensions, 7 per line and the touchdown's s, x and
    y, 4 per point for 6 points, time, slack count and wave elevation): 669, 0.578 GB for the issue's 3 hours at
    0.1 s, which a 1 GB limit lets through. A 20 s result holds that but the wave elevation (calm water)."""
    from seacable.mooring.moordyn import prepare_moordyn

    model = moordyn_model(THREE)
    assert stored_per_output(model.network, model.water.depth is not None) == 4 * 123 + 120 + 21 + 9 + 24 + 3
    assert 108_001 * 669 * 8 == pytest.approx(0.578e9, rel=1e-3)
    monkeypatch.setenv("SEACABLE_MAX_MEMORY", "1e9")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        prepare_moordyn(_three_case(3 * 3600.0))  # refused above the limit
        monkeypatch.setenv("SEACABLE_MAX_MEMORY", "0.5e9")
        with pytest.raises(sc.InputError, match="would store about 578 MB of results"):
            prepare_moordyn(_three_case(3 * 3600.0))
    ds = _run(_three_case(20.0))
    timed = sum(v.nbytes for v in ds.variables.values() if "time" in v.dims)
    assert timed == 201 * (669 - 1) * 8


def test_a_run_written_as_it_goes_holds_a_block_not_the_run(tmp_path, monkeypatch):
    """Python's allocations (tracemalloc) of the three chains over 15 s and 60 s (an output every 0.1 s,
    blocks of 64): kept in memory, the peak grows by the result (450 outputs of 665 values, 2.39 MB; measured
    2.47 MB); written as it goes, by at most about 7 % of that: what is left in proportion to the outputs is the
    fairlead motion at the output times (for the checks, 3 channels x 9 values), and one line's element
    tensions read back for the snap loads (40 values). Bound 15 %: twice that. (Measured 4 % over 15 s and
    60 s, 3 % over 30 s and 120 s, 5 % over 60 s and 240 s; a run written as it goes that kept the run would
    grow by 100 %.)"""
    monkeypatch.setattr(S, "BLOCK_VALUES", 2**16)
    _run(_three_case(1.0))  # the kernels loaded, and the NetCDF library's first use, outside the measure
    _run(_three_case(1.0), tmp_path / "first.nc").close()

    def peak(duration, out):
        tracemalloc.start()
        ds = _run(_three_case(duration), out)
        size = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        ds.close()
        return size

    # 15 s / 60 s rather than 60 s / 240 s (a sixth of the time; 30 s / 120 s took 4.7 CPU-s, these 2.9): the
    # tracemalloc counts are deterministic, the growth in memory is still the whole result (measured 5 % above it)
    # and the file's under the same bound
    grown_memory = peak(60.0, None) - peak(15.0, None)
    grown_file = peak(60.0, tmp_path / "b.nc") - peak(15.0, tmp_path / "a.nc")
    assert grown_memory >= 450 * 665 * 8  # the result, at least
    assert grown_file <= 0.15 * grown_memory


def test_a_write_that_fails_midway_says_why_and_leaves_no_file(tmp_path, monkeypatch):
    """The disk fills while a run is written (the library raises OSError at the third block): an InputError
    naming the file, the reason and a fix; neither the file nor its temporary is left."""
    from seacable.sink import NetcdfSink

    append, calls = NetcdfSink.append, []

    def full_at_third(self, data, coords):
        calls.append(1)
        if len(calls) == 3:
            class Full:
                def __getitem__(self, name):
                    return self

                def __setitem__(self, index, value):
                    raise OSError(28, "No space left on device")

                def close(self):
                    pass
            self._nc.close()
            self._nc = Full()
        return append(self, data, coords)

    monkeypatch.setattr(NetcdfSink, "append", full_at_third)
    monkeypatch.setattr(S, "BLOCK_VALUES", 2**14)
    out = tmp_path / "three.nc"
    with pytest.raises(sc.InputError, match=r"cannot write the result .*three\.nc': the disk is full \(No space left "
                                            r"on device\)\..*Suggested fix: free disk space"):
        _run(_three_case(5.0), out)
    assert list(tmp_path.iterdir()) == []
