"""Small synthetic results of time-domain mooring runs, for the design tables and the report; the report pages'
browser checks (headless Chromium)."""

from __future__ import annotations

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
        bp = np.zeros((nt, 1, 6))
        bp[:, 0, :2] = body_xy
        coords["body"] = var("body", ["hull"], "1", "body")
        coords["dof"] = var("dof", ["x", "y", "z", "roll", "pitch", "yaw"], "1", "degree of freedom")
        data["body_position"] = var(("time", "body", "dof"), bp, "m or rad", "body position")
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


def _start_chromium(page: Path, png: Path, profile: Path, size=(1280, 5000)) -> subprocess.Popen:
    """Start headless Chromium on ``page``, to write its screenshot (:func:`_console` waits for it)."""
    cmd = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
           "--disable-background-networking", "--disable-component-update", "--disable-sync",
           f"--user-data-dir={profile}", "--enable-logging=stderr", "--v=0", f"--screenshot={png}",
           f"--window-size={size[0]},{size[1]}", page.resolve().as_uri()]
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
