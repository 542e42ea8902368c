"""Small synthetic results of time-domain mooring runs, for the design tables and the report; the report pages'
browser checks (headless Chromium)."""

from __future__ import annotations

import functools
import subprocess
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
import yaml

from seacable.results import make_dataset, var

#: Nodes of every synthetic line (constant in time): the anchor (node 0) on the seabed, the first element
#: rising 3 m over its 5 m (4 m horizontally), the fairlead (node 2) near the surface. [m]
NODES = np.array([[0.0, 0.0, -100.0], [4.0, 0.0, -97.0], [50.0, 0.0, -10.0]])


def synthetic_result(fairlead: dict, *, dt: float = 0.5, anchor: dict | None = None, case: dict | None = None,
                     breaking_load: dict | None = None, failure_time: dict | None = None, body_xy=None,
                     analysis: str = "mooring_dynamic", nodes=NODES):
    """A result Dataset of a time-domain mooring run: per line its fairlead tension (and anchor tension,
    default 0.8 of it) [N] at steps of ``dt`` [s]; nodes ``nodes`` [m] (line, time, node); optionally the
    case (a mapping, stored as YAML), ``breaking_load`` [N] and ``failure_time`` [s] per line, and one body's
    horizontal track ``body_xy`` (time, 2) [m]."""
    lines = list(fairlead)
    ft = np.array([np.asarray(fairlead[k], float) for k in lines])
    at = np.array([np.asarray((anchor or {}).get(k, 0.8 * ft[i]), float) for i, k in enumerate(lines)])
    nt = ft.shape[1]
    nodes = np.asarray(nodes, float)
    pos = np.broadcast_to(nodes, (len(lines), nt) + nodes.shape)
    data = {"fairlead_tension": var(("line", "time"), ft, "N", "fairlead tension"),
            "anchor_tension": var(("line", "time"), at, "N", "anchor tension")}
    for k, name in enumerate("xyz"):
        data[name] = var(("line", "time", "node"), pos[..., k].copy(), "m", f"{name} position")
    coords = {"line": var("line", lines, "1", "line"), "time": var("time", np.arange(nt) * dt, "s", "time"),
              "node": var("node", np.arange(nodes.shape[0]), "1", "node")}
    if breaking_load is not None:
        data["breaking_load"] = var("line", [breaking_load.get(k, np.nan) for k in lines], "N",
                                    "minimum breaking load")
    if failure_time is not None:
        data["failure_time"] = var("line", [failure_time.get(k, np.nan) for k in lines], "s", "failure time")
    if body_xy is not None:
        bp = np.zeros((nt, 1, 3))
        bp[:, 0, :2] = body_xy
        coords["body"] = var("body", ["hull"], "1", "body")
        coords["axis"] = var("axis", ["x", "y", "z"], "1", "global axis")
        coords["angle"] = var("angle", ["roll", "pitch", "yaw"], "1", "rotation")
        data["body_position"] = var(("time", "body", "axis"), bp, "m", "body position")
        data["body_rotation"] = var(("time", "body", "angle"), np.zeros((nt, 1, 3)), "rad", "body rotation")
    ds = make_dataset(data, coords, analysis=analysis, settings={"time_step": dt},
                      references=["A reference of the model."], title=(case or {}).get("name", "synthetic"))
    if case is not None:
        ds.attrs["case"] = yaml.safe_dump(case, sort_keys=False)
        ds.attrs["case_name"] = case.get("name", "synthetic")
    return ds


def chain_case(name="storm", *, hs=None, tp=None, seed=None, breaking_load=7.3e6, diameter=0.171,
               type_name="studless_chain", lines=("L1", "L2")):
    """A system case (as stored with a result) of lines of one chain type from fixed anchors (end A) to a
    body's fairleads (end B), with an irregular sea when ``hs`` is given."""
    lt = {"diameter": diameter, "mass_per_length": 180.0, "breaking_load": breaking_load, "name": None}
    waves = None if hs is None else {"spectrum": "jonswap", "hs": hs, "tp": tp, "seed": seed}
    points = {}
    system_lines = {}
    for k, line in enumerate(lines):
        points[f"a{k}"] = {"kind": "fixed", "position": [0.0, 0.0, -100.0]}
        points[f"f{k}"] = {"kind": "body", "body": "hull", "position": [50.0, 0.0, -10.0]}
        system_lines[line] = {"line": {"segments": [{"line_type": dict(lt), "length": 120.0}]},
                              "end_a": f"a{k}", "end_b": f"f{k}"}
    return {"name": name, "line_types": {type_name: dict(lt)}, "environment": {"depth": 100.0, "waves": waves},
            "bodies": {"hull": {"position": [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]}}, "points": points,
            "lines": system_lines, "analysis": {"type": "system_dynamic"}}


def write_sweep(folder, runs: list[tuple[dict, object]], name="storm", failed: dict | None = None):
    """A folder as 'seacable sweep' writes it: ``summary.nc`` (one row per case, the swept parameters as
    coordinates named by their key path) and ``cases/NNNN.nc``. ``runs``: (parameters, result Dataset);
    ``failed``: case index -> error message of the cases that failed (no result file)."""
    failed = failed or {}
    import json

    from seacable.results import write_netcdf

    params = list(runs[0][0])
    coords = {"case": var("case", np.arange(len(runs)), "1", "case index"),
              "name": var("case", np.array([f"{name}_{k:04d}" for k in range(len(runs))], dtype=object), "1",
                          "case name")}
    units = {"environment.waves.hs": "m", "environment.waves.tp": "s", "environment.waves.seed": ""}
    for p in params:
        coords[p] = var("case", np.array([r[0][p] for r in runs], float), units.get(p, ""), p)
    data = {"status": var("case", np.array(["failed" if k in failed else "done" for k in range(len(runs))],
                                           dtype=object), "1", "status"),
            "error": var("case", np.array([failed.get(k, "") for k in range(len(runs))], dtype=object), "1",
                         "error")}
    summary = make_dataset(data, coords, analysis="sweep", title=name, references=())
    summary.attrs.update(parameters=json.dumps(params), case_analysis=runs[0][1].attrs["analysis"], cases=len(runs),
                         done=len(runs) - len(failed), failed=len(failed), not_run=0, sweep=f"name: {name}\n")
    write_netcdf(summary, folder / "summary.nc")
    for k, (_, ds) in enumerate(runs):
        if k not in failed:
            write_netcdf(ds, folder / "cases" / f"{k:04d}.nc")
    return folder


@pytest.fixture(scope="session")
def synth():
    """The builders of this module: ``result``, ``case``, ``sweep`` and the ``nodes`` of every line (pure
    functions: one namespace serves the session, and module-scoped fixtures)."""
    return SimpleNamespace(result=synthetic_result, case=chain_case, sweep=write_sweep, nodes=NODES)


def count_colours(pixels) -> int:
    """The number of distinct RGB colours of an image read by ``plt.imread`` (values k / 255 from the 8-bit PNGs
    matplotlib writes): ``np.unique(pixels.reshape(-1, 3), axis=0)``'s count, from one integer per pixel
    (np.unique along an axis took seconds an image). A deeper PNG's near colours would merge: fewer, never
    more."""
    q = np.round(np.asarray(pixels)[..., :3] * 255).astype(np.uint32)
    return int(np.unique((q[..., 0] << 16) | (q[..., 1] << 8) | q[..., 2]).size)


@pytest.fixture(scope="session")
def n_colours():
    """:func:`count_colours`: the plot tests' check that something was drawn."""
    return count_colours


# ------------------------------------------------------------------------------- a page in a real browser

#: Debian's headless Chromium (the 'chromium' package: .ci/run installs it); the browser tests skip without it
CHROMIUM = "/usr/bin/chromium"


def _start_chromium(page: Path, png: Path, profile: Path, size=(1280, 5000), extra=()) -> subprocess.Popen:
    """Start headless Chromium on ``page``, to write its screenshot (:func:`_console` waits for it); ``extra``:
    more command-line switches (a proxy that records the page's requests, a time budget for its scripts)."""
    cmd = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
           "--disable-background-networking", "--disable-component-update", "--disable-sync",
           f"--user-data-dir={profile}", "--enable-logging=stderr", "--v=0", f"--screenshot={png}",
           f"--window-size={size[0]},{size[1]}", *extra, page.resolve().as_uri()]
    return subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


def _console(browser: subprocess.Popen) -> list[str]:
    """Wait for a Chromium of :func:`_start_chromium`, its screenshot written; the console lines it logged."""
    try:
        _, stderr = browser.communicate(timeout=180)
    finally:
        browser.kill()
    assert browser.returncode == 0, stderr[-2000:]
    return [line for line in stderr.splitlines() if "CONSOLE" in line or "Uncaught" in line]


def _near(rgb: np.ndarray, colour: tuple[int, int, int], tol: int = 12) -> int:
    """Pixels of ``rgb`` (h, w, 3) within ``tol`` of ``colour`` in every channel."""
    return int(np.sum(np.all(np.abs(rgb - np.array(colour)) <= tol, axis=-1)))


@pytest.fixture(scope="session")
def browser():
    """The report pages' browser checks: ``start(page, png, profile, size)`` (headless Chromium writing ``png``),
    ``console(process)`` (waits; the console lines it logged) and ``near(rgb, colour, tol)`` (pixels of a colour)."""
    return SimpleNamespace(start=_start_chromium, console=_console, near=_near)


# --------------------------------------------------------------------------- two cables in a mooring system (issue 40)

#: The 80 m lazy wave's cable (examples/lazy_wave_80m.yaml: Lozon et al. 2025) and its smeared buoyancy, twice on a
#: fixed hull with a chain: two line types of the same cable with different limits, so a check that takes the other
#: line's limits (or shape) is seen.
_CABLE = {"diameter": 0.16, "mass_per_length": 36.70, "axial_stiffness": 4.69e8, "bending_stiffness": 1.99e4,
          "drag_normal": 1.2, "drag_tangential": 0.1, "added_mass_normal": 1.0}
_SECTIONS = [{"type": "buoyancy", "start": 52.101, "length": 50.0, "pitch": 5.0, "representation": "smeared",
              "module": {"length": 5.0, "diameter": 0.29, "mass": 114.15, "volume": 0.2297289628,
                         "drag_normal": 1.2}}]
_TWO = SimpleNamespace(
    limits={"cable_a": {"minimum_bend_radius": 2.0, "minimum_bend_radius_dynamic": 3.0, "allowable_tension": 2.0e4},
            "cable_b": {"minimum_bend_radius": 4.0, "minimum_bend_radius_dynamic": 6.0, "allowable_tension": 1.5e4,
                        "allowable_compression": 500.0}},
    length={"cable_a": 170.215, "cable_b": 175.0},
    # the hang-offs' horizontal distance from each cable's anchor (0 and 240 m, the hull at x = 120 m) [m]
    span={"cable_a": 120.0, "cable_b": 115.0},
    design={"sag_bend_clearance": 12.0, "hog_bend_clearance": 25.0, "hang_off_declination": [0.1, 0.3],
            "line_clearance": 4.0},
    n_elements=60)


def _two_cables_case(analysis: dict):
    """:func:`_two_cables_data` as a case."""
    from seacable.system.case import SystemCase

    return SystemCase.parse(_two_cables_data(analysis))


def _two_cables_data(analysis: dict) -> dict:
    """A fixed hull at (120, 0, -4) m in 80 m of water: cable_a from an anchor at x = 0 to a hang-off 10 m below the
    hull, cable_b (4.785 m longer) from x = 240 m to a hang-off 5 m aft of it, both clamped 10 deg off vertical, and a
    chain from the seabed to a fairlead 20 m to the side; the case's data, as a file holds it."""
    types = {"ca": {**_CABLE, **_TWO.limits["cable_a"]}, "cb": {**_CABLE, **_TWO.limits["cable_b"]},
             "chain": {"diameter": 0.1, "mass_per_length": 60.0, "axial_stiffness": 5e8}}
    lines = {name: {"segments": [{"line_type": t, "length": _TWO.length[name]}], "sections": _SECTIONS,
                    "end_a": f"anchor_{name[-1]}", "end_b": f"hang_{name[-1]}", "n_elements": _TWO.n_elements,
                    "end_b_condition": {"type": "clamped", "declination": 0.1745, "azimuth": az}}
             for name, t, az in (("cable_a", "ca", 0.0), ("cable_b", "cb", np.pi))}
    lines["chain"] = {"line_type": "chain", "length": 160.0, "end_a": "anchor_c", "end_b": "fair_c", "n_elements": 10}
    return {
        "name": "two_cables", "line_types": types, "environment": {"water_density": 1025.0, "gravity": 9.80665,
                                                                   "depth": 80.0},
        "bodies": {"hull": {"kind": "fixed", "position": [120.0, 0.0, -4.0, 0.0, 0.0, 0.0]}},
        "points": {"anchor_a": {"kind": "fixed", "position": [0.0, 0.0, -80.0]},
                   "anchor_b": {"kind": "fixed", "position": [240.0, 0.0, -80.0]},
                   "anchor_c": {"kind": "fixed", "position": [120.0, -150.0, -80.0]},
                   "hang_a": {"kind": "body", "body": "hull", "position": [0.0, 0.0, -10.0]},
                   "hang_b": {"kind": "body", "body": "hull", "position": [5.0, 0.0, -10.0]},
                   "fair_c": {"kind": "body", "body": "hull", "position": [0.0, -20.0, -10.0]}},
        "lines": lines, "analysis": analysis}


def _two_cables_single(name: str, analysis: str = "mooring_static"):
    """One of the two cables alone, in its own vertical plane: the same line, mesh, limits and hang-off."""
    from seacable.io import parse_case

    design = {k: v for k, v in _TWO.design.items() if k != "line_clearance"}
    return parse_case({"name": name, "line_types": {"cable": {**_CABLE, **_TWO.limits[name]}},
                       "line": {"segments": [{"line_type": "cable", "length": _TWO.length[name]}],
                                "sections": _SECTIONS},
                       "environment": {"water_density": 1025.0, "gravity": 9.80665, "depth": 80.0},
                       "analysis": {"type": analysis, "anchor": [0.0, -80.0], "fairlead": [_TWO.span[name], -14.0],
                                    "n_elements": _TWO.n_elements, "design": design,
                                    "fairlead_end_condition": {"type": "clamped", "declination": 0.1745}}})


class _TwoCables(SimpleNamespace):
    """Two lazy-wave cables and a chain on a fixed hull (:func:`_two_cables_case`): ``case(analysis)``,
    ``single(name)`` (a cable alone), the constants, and the results, each run once when first asked for: ``static``
    (system_static, damaged without cable_b) and ``dynamic`` (system_dynamic, 1 s of still water from the
    equilibrium)."""

    @functools.cached_property
    def static(self):
        import seacable as sc

        return sc.run(self.case({"type": "system_static", "design": self.design, "damaged_lines": ["cable_b"]}))

    @functools.cached_property
    def dynamic(self):
        import seacable as sc

        return sc.run(self.case({"type": "system_dynamic", "duration": 1.0, "time_step": 0.1, "output_interval": 0.5,
                                 "design": self.design}))


@pytest.fixture(scope="session")
def two_cables():
    """:class:`_TwoCables`, one for the session."""
    return _TwoCables(case=_two_cables_case, data=_two_cables_data, single=_two_cables_single, **vars(_TWO))
