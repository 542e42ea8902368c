"""Every bad input gets one clear message and a non-zero exit (issue 17).

A corpus of bad inputs, generated here from the examples and from small files written by the
tests, is given to the command line in this process (``seacable.cli.main(argv)``). For each the
test asserts:

* the exit status is not 0 (2 for a user error, never 3: an internal error is a bug),
* stderr holds one ``seacable: error:`` message that names the key, the option, the variable or
  the file that is wrong,
* nothing prints a traceback.

Classes: case files (wrong types, missing keys, unknown keys, NaN / inf / negative / zero values
of every numeric field of several case types, absurd sizes), command-line options (numbers out of
range, not numbers, scheduler addresses), paths (output inside a file, a folder, a read-only
place; missing, binary or empty inputs), motion CSVs, result files (NetCDF) and sweep files.
A few subprocess tests check the exit status through the console script.
"""

from __future__ import annotations

import copy
import math
import tempfile
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import yaml

from seacable.cli import main
from seacable.results import ANALYSIS_VARIABLES

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

#: a MoorDyn input file: the OC3-Hywind line (see examples/oc3_hywind_static.yaml) from anchor to vessel
MOORDYN = """--------------------- MoorDyn Input File ------------------------------------
Test: one chain line from an anchor to a vessel point
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA     BA/-zeta    EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)    (N-s/-)   (N-m^2) (-)    (-)   (-)     (-)
chain      0.09    77.7066   384.243E6  -0.8     0     1.6    1.0   0.4     0.5
---------------------- POINTS --------------------------------
ID  Attachment  X       Y     Z      M     V      CdA   CA
(-)   (-)      (m)     (m)   (m)    (kg)  (m^3)  (m^2) (-)
1     Fixed   853.87   0   -320.0    0     0      0     0
2     Vessel    5.2    0    -70.0    0     0      0     0
---------------------- LINES --------------------------------------
ID   LineType  AttachA  AttachB  UnstrLen  NumSegs  Outputs
(-)   (-)       (-)      (-)       (m)       (-)      (-)
1     chain      1        2       902.2      20        -
---------------------- OPTIONS -----------------------------------------
320      WtrDpth
---------------------- OUTPUTS -----------------------------------------
END
------------------------- need this line -------------------------------------
"""


class Bad:
    """One bad input: the command line, the words its message must hold, and how to build its files."""

    def __init__(self, id_, argv, names, files=None, mark=None):
        self.id, self.argv, self.names, self.files, self.mark = id_, argv, names, files or {}, mark

    def param(self):
        marks = [self.mark] if self.mark is not None else []
        return pytest.param(self, id=self.id, marks=marks)


def _example(name: str) -> dict:
    return yaml.safe_load((EXAMPLES / name).read_text(encoding="utf-8"))


# --- case files --------------------------------------------------------------------------------

#: case files whose numbers are mutated: analyses of every model (statics, modal, towed, laying,
#: towline, mooring) -- file name -> the command that checks it
CASE_BASES = {
    "oc3_hywind_static.yaml": "validate",         # static
    "oc3_hywind_pushover.yaml": "run",            # pushover
    "oc3_hywind_modes.yaml": "validate",          # modal
    "paper000_steady_statics.yaml": "run",        # towed_steady
    "paper002_vertical_cable.yaml": "validate",   # vertical_modes
    "paper000_turn.yaml": "run",                  # towed_dynamic
    "paper001_lay_2ms_50m.yaml": "validate",      # laying_dynamic
    "paper003_zigzag.yaml": "run",                # towline_dynamic
    "spread_mooring.yaml": "validate",            # system_static (a mooring system: lines, points, bodies)
    "spread_mooring_watch_circle.yaml": "run",    # system_offsets
    "spread_mooring_line_break.yaml": "validate",  # system_dynamic (coupled bodies and FE lines, a failure)
}

#: numeric keys that must be > 0 wherever they appear (a zero or negative value is meaningless)
POSITIVE = {"diameter", "mass_per_length", "axial_stiffness", "length", "water_density", "gravity", "depth",
            "duration", "time_step", "output_interval", "n_nodes", "n_elements", "segment_length", "period",
            "n_modes", "n_offsets"}


def _leaves(data, path=()):
    """(path, value) of every number in nested mappings and lists."""
    items = data.items() if isinstance(data, dict) else enumerate(data) if isinstance(data, list) else ()
    for k, v in items:
        if isinstance(v, (dict, list)):
            yield from _leaves(v, path + (k,))
        elif isinstance(v, (int, float)) and not isinstance(v, bool):
            yield path + (k,), v


def _mappings(data, path=()):
    """Paths of every mapping (the case itself first)."""
    if isinstance(data, dict):
        yield path
        for k, v in data.items():
            yield from _mappings(v, path + (k,))
    elif isinstance(data, list):
        for i, v in enumerate(data):
            yield from _mappings(v, path + (i,))


def _set(data, path, value):
    data = copy.deepcopy(data)
    node = data
    for p in path[:-1]:
        node = node[p]
    node[path[-1]] = value
    return data


def _delete(data, path):
    data = copy.deepcopy(data)
    node = data
    for p in path[:-1]:
        node = node[p]
    del node[path[-1]]
    return data


def _key(path) -> str:
    """The word a message must name: the last key of the path (a list item names its list)."""
    keys = [p for p in path if isinstance(p, str)]
    return keys[-1]


def _tag(path) -> str:
    return ".".join(str(p) for p in path)


def _case_corpus() -> list[Bad]:
    out = []
    for name, command in CASE_BASES.items():
        base = _example(name)
        stem = name.removesuffix(".yaml")
        for path, value in _leaves(base):
            key = _key(path)
            bad_values = {"nan": math.nan, "inf": math.inf, "text": "abc"}
            if key in POSITIVE and not isinstance(path[-1], int):
                bad_values.update(zero=0, negative=-abs(value) if value else -1.0)
                if "lines" in base and key in ("water_density", "gravity"):
                    del bad_values["zero"]  # a system environment takes 0: gravity or buoyancy off (SystemEnvironment)
            for label, bad in bad_values.items():
                out.append(Bad(f"case-{stem}-{_tag(path)}-{label}", [command, "{case}"], [key],
                               {"case": _set(base, path, bad)}))
        # wrong types of whole blocks, unknown keys, missing keys
        for path in _mappings(base):
            if not path:
                continue
            out.append(Bad(f"case-{stem}-{_tag(path)}-list", [command, "{case}"], [_key(path)],
                           {"case": _set(base, path, [1, 2])}))
            out.append(Bad(f"case-{stem}-{_tag(path)}-unknown", [command, "{case}"], ["colour"],
                           {"case": _set(base, path + ("colour",), "red")}))
        for required in ("lines", "analysis") if "lines" in base else ("line", "analysis"):
            out.append(Bad(f"case-{stem}-missing-{required}", [command, "{case}"], [required],
                           {"case": _delete(base, (required,))}))
        out.append(Bad(f"case-{stem}-missing-analysis-type", [command, "{case}"], ["type"],
                       {"case": _delete(base, ("analysis", "type"))}))
        out.append(Bad(f"case-{stem}-unknown-top", [command, "{case}"], ["colour"],
                       {"case": {**base, "colour": "red"}}))
        out.append(Bad(f"case-{stem}-analysis-type", [command, "{case}"], ["type"],
                       {"case": _set(base, ("analysis", "type"), "no_such_analysis")}))
    return out


# --- command-line options ----------------------------------------------------------------------

STATIC = str(EXAMPLES / "oc3_hywind_static.yaml")


def _option_corpus() -> list[Bad]:
    out = []
    floats = ("0", "-0.1", "nan", "inf", "-inf", "abc", "1e400x")
    for option in ("--time-step", "--duration", "--output-interval"):
        for value in floats:
            out.append(Bad(f"run{option}={value}", ["run", "{moordyn}", option, value, "--no-plots"], [option]))
    for option in ("--max-steps", "--max-memory", "--max-cases"):
        for command, target in (("run", STATIC), ("validate", STATIC), ("sweep", "{sweep}")):
            for value in ("0", "-5", "nan", "inf", "abc"):
                out.append(Bad(f"{command}{option}={value}", [command, target, option, value], [option]))
    for option in ("--fps", "--max-frames"):
        for value in ("0", "-3", "nan", "abc", "1.5", "inf"):
            out.append(Bad(f"animate{option}={value}", ["animate", "{nc_lay}", option, value], [option]))
    for value in ("0", "-3", "nan", "abc", "1.5", "inf"):
        out.append(Bad(f"view--max-frames={value}", ["view", "{nc_lay}", "--max-frames", value], ["--max-frames"]))
    for value in ("0", "-1", "nan", "1.5", "abc"):
        out.append(Bad(f"sweep--workers={value}", ["sweep", "{sweep}", "--workers", value], ["--workers"]))
    for value in ("not a scheduler", "http://host:8786", "tcp://host", "host:99999", "tcp://:8786", "", "tcp://a b:1"):
        out.append(Bad(f"sweep--scheduler={value!r}", ["sweep", "{sweep}", "--scheduler", value], ["--scheduler"]))
    out.append(Bad("sweep-scheduler-unreachable", ["sweep", "{sweep}", "--scheduler", "tcp://127.0.0.1:9"],
                   ["scheduler", "127.0.0.1:9"]))
    # a local cluster of 100 000 processes never starts: refused with the bound (4 per core)
    for value in ("100000", "1e9"):
        out.append(Bad(f"sweep--workers={value}-too-many", ["sweep", "{sweep}", "--workers", value],
                       ["--workers", "at most", "per core"]))
    out.append(Bad("sweep-workers-and-scheduler", ["sweep", "{sweep}", "--workers", "2", "--scheduler",
                                                  "synchronous"], ["workers"]))
    for command, target in (("run", STATIC), ("validate", STATIC), ("plot", "{nc_static}"), ("animate", "{nc_lay}"),
                            ("sweep", "{sweep}"), ("view", "{nc_lay}")):
        out.append(Bad(f"{command}-unknown-option", [command, target, "--frobnicate"], ["--frobnicate"]))
    out.append(Bad("schema-unknown-option", ["schema", "--frobnicate"], ["--frobnicate"]))
    out.append(Bad("unknown-command", ["frobnicate"], ["frobnicate"]))
    out.append(Bad("run-no-case", ["run"], ["case"]))
    out.append(Bad("run-a-sweep-file", ["run", "{sweep}"], ["seacable sweep"]))
    out.append(Bad("sweep-a-case-file", ["sweep", STATIC], ["sweep file"]))
    for option, value in (("--duration", "10"), ("--time-step", "0.1"), ("--output-interval", "1"),
                          ("--motion", "m.csv")):
        out.append(Bad(f"run-yaml{option}", ["run", STATIC, option, value, "--no-plots"], [option]))
    out.append(Bad("run-moordyn-motion-without-duration", ["run", "{moordyn}", "--motion", "{motion_ok}"],
                   ["--duration"]))
    return out


# --- paths ---------------------------------------------------------------------------------------

def _path_corpus() -> list[Bad]:
    out = [
        Bad("run-o-inside-a-file", ["run", STATIC, "-o", "{file}/b.nc"], ["-o", "is a file"]),
        Bad("run-o-deep-inside-a-file", ["run", STATIC, "-o", "{file}/x/y/b.nc"], ["-o", "is a file"]),
        Bad("run-o-a-folder", ["run", STATIC, "-o", "{dir}"], ["-o", "folder"]),
        Bad("run-o-a-folder-nc", ["run", STATIC, "-o", "{dir_nc}"], ["-o", "folder"]),
        Bad("run-o-suffix-txt", ["run", STATIC, "-o", "{tmp}/r.txt"], ["-o", ".nc"]),
        Bad("run-o-no-suffix", ["run", STATIC, "-o", "{tmp}/r"], ["-o", ".nc"]),
        Bad("run-plot-dir-a-file", ["run", STATIC, "-o", "{tmp}/r.nc", "--plot-dir", "{file}"], ["--plot-dir"]),
        Bad("run-plot-dir-inside-a-file", ["run", STATIC, "-o", "{tmp}/r.nc", "--plot-dir", "{file}/p"],
            ["--plot-dir"]),
        Bad("plot-o-a-file", ["plot", "{nc_static}", "-o", "{file}"], ["-o"]),
        Bad("plot-o-inside-a-file", ["plot", "{nc_static}", "-o", "{file}/figs"], ["-o"]),
        Bad("animate-o-a-folder", ["animate", "{nc_lay}", "-o", "{dir}"], ["-o", "folder"]),
        Bad("animate-o-png", ["animate", "{nc_lay}", "-o", "{tmp}/a.png"], ["-o", ".gif"]),
        Bad("animate-o-inside-a-file", ["animate", "{nc_lay}", "-o", "{file}/a.gif"], ["-o", "is a file"]),
        Bad("view-o-a-folder", ["view", "{nc_lay}", "-o", "{dir}"], ["-o", "folder"]),
        Bad("view-o-png", ["view", "{nc_lay}", "-o", "{tmp}/a.png"], ["-o", ".html"]),
        Bad("view-o-inside-a-file", ["view", "{nc_lay}", "-o", "{file}/a.html"], ["-o", "is a file"]),
        Bad("sweep-o-a-file", ["sweep", "{sweep}", "-o", "{file}"], ["-o"]),
        Bad("sweep-o-inside-a-file", ["sweep", "{sweep}", "-o", "{file}/out"], ["-o"]),
    ]
    if Path("/proc").is_dir():   # a read-only place even for root (the tests may run as root)
        out += [Bad("run-o-read-only", ["run", STATIC, "-o", "/proc/seacable-test/r.nc"], ["-o", "cannot write"]),
                Bad("run-plot-dir-read-only", ["run", STATIC, "-o", "{tmp}/r.nc", "--plot-dir", "/proc/seacable-p"],
                    ["--plot-dir", "cannot write"]),
                Bad("sweep-o-read-only", ["sweep", "{sweep}", "-o", "/proc/seacable-sweep"], ["-o", "cannot write"]),
                Bad("plot-o-read-only", ["plot", "{nc_static}", "-o", "/proc/seacable-figs"], ["-o", "cannot write"])]
    for command in ("run", "validate", "sweep"):
        for kind in ("missing", "dir", "binary", "empty", "text"):
            out.append(Bad(f"{command}-input-{kind}", [command, "{" + kind + "_yaml}"], ["{" + kind + "_yaml}"]))
    return out


# --- motion CSVs ---------------------------------------------------------------------------------

MOTIONS = {
    "missing": None,
    "dir": "<dir>",
    "binary": b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\x00\x00",
    "latin1": "time,x\n0,1\n1,2\n# caf\xe9\n".encode("latin-1"),
    "empty": "",
    "blank": "\n\n   \n",
    "comments-only": "# nothing\n# here\n",
    "header-only": "time,x,y,z\n",
    "one-row": "time,x,y,z\n0,0,0,0\n",
    "text-values": "time,x\n0,a\n1,b\n",
    "nan-values": "time,x\n0,nan\n1,0\n",
    "inf-time": "time,x\n0,0\ninf,1\n",
    "time-decreasing": "time,x\n0,0\n2,1\n1,2\n",
    "time-repeated": "time,x\n0,0\n0,1\n",
    "no-time": "t,x\n0,0\n1,1\n",
    "no-motion-column": "time,q\n0,0\n1,1\n",
    "ragged": "time,x,y\n0,0\n1,1,1,1\n",
    "platform-no-time": "surge,heave\n0,0\n1,1\n",
    "platform-text": "time,surge\n0,x\n1,y\n",
}


def _motion_corpus() -> list[Bad]:
    return [Bad(f"motion-{name}", ["run", "{moordyn}", "--duration", "10", "--no-plots", "--motion",
                                   "{motion_" + name + "}"], ["motion file"]) for name in MOTIONS]


# --- result files (NetCDF) -----------------------------------------------------------------------

def _netcdf_corpus() -> list[Bad]:
    out = []
    for command in ("plot", "animate", "view"):
        for kind in ("missing", "dir", "text", "empty", "no_analysis", "unknown_analysis", "truncated"):
            out.append(Bad(f"{command}-nc-{kind}", [command, "{nc_" + kind + "}"], ["{nc_" + kind + "}"]))
    for analysis, names in ANALYSIS_VARIABLES.items():
        for name in names:
            out.append(Bad(f"plot-{analysis}-without-{name}", ["plot", "{nc_" + analysis + "_no_" + name + "}"],
                           [name, analysis]))
            if analysis in ("laying_dynamic", "towline_dynamic"):
                out.append(Bad(f"animate-{analysis}-without-{name}",
                               ["animate", "{nc_" + analysis + "_no_" + name + "}"], [name, analysis]))
    out.append(Bad("animate-static-result", ["animate", "{nc_static}", "-o", "{tmp}/a.gif"], ["laying_dynamic"]))
    # a result without a line shape: nothing to view
    out.append(Bad("view-static-without-x", ["view", "{nc_static_no_x}", "-o", "{tmp}/v.html"], ["x", "static"]))
    out.append(Bad("view-pushover-result", ["view", "{nc_pushover}", "-o", "{tmp}/v.html"],
                   ["pushover", "no line shape"]))
    return out


# --- sweep files ---------------------------------------------------------------------------------

def _sweep_corpus() -> list[Bad]:
    big = [float(v) for v in range(5000)]
    return [
        Bad("sweep-5000x5000-grid", ["sweep", "{sweep_big}"], ["cases", "--max-cases"]),
        Bad("validate-5000x5000-grid", ["validate", "{sweep_big}"], ["cases", "--max-cases"]),
        Bad("sweep-5000x5000-ranges", ["sweep", "{sweep_big_ranges}"], ["cases", "--max-cases"]),
        Bad("sweep-max-cases-1", ["sweep", "{sweep}", "--max-cases", "1"], ["cases", "--max-cases"]),
        Bad("validate-sweep-one-case-invalid", ["validate", "{sweep_one_bad}"], ["depth", "invalid"]),
        Bad("validate-sweep-case-cannot-reach", ["validate", "{sweep_short}"], ["case 1", "invalid"]),
        Bad("validate-sweep-all-invalid", ["validate", "{sweep_all_bad}"], ["depth", "invalid"]),
        Bad("sweep-unknown-path", ["sweep", "{sweep_unknown_path}"], ["environment.dept"]),
        Bad("sweep-bad-path", ["sweep", "{sweep_bad_path}"], ["a..b"]),
        Bad("sweep-empty-grid", ["sweep", "{sweep_empty_grid}"], ["grid"]),
        Bad("sweep-empty-list", ["sweep", "{sweep_empty_list}"], ["environment.depth"]),
        Bad("sweep-grid-and-table", ["sweep", "{sweep_grid_and_table}"], ["grid", "table"]),
        Bad("sweep-missing-table", ["sweep", "{sweep_missing_table}"], ["nope.csv"]),
        Bad("sweep-ragged-table", ["sweep", "{sweep_ragged_table}"], ["line 3"]),
        Bad("sweep-no-base", ["sweep", "{sweep_no_base}"], ["base"]),
        Bad("sweep-range-zero-step", ["sweep", "{sweep_zero_step}"], ["step"]),
        Bad("sweep-scalar-values", ["sweep", "{sweep_scalar}"], ["environment.depth"]),
    ] + [Bad(f"sweep-{len(big)}-{k}", ["validate", "{sweep_big}", "--max-cases", v], ["--max-cases"])
         for k, v in (("zero", "0"), ("nan", "nan"))]


# --- sizes ---------------------------------------------------------------------------------------

def _size_corpus() -> list[Bad]:
    out = []
    for name, key in (("paper000_turn.yaml", "duration"), ("paper001_lay_2ms_50m.yaml", "duration"),
                      ("paper003_zigzag.yaml", "duration")):
        base = _example(name)
        for value in (1e300, 1e12):
            out.append(Bad(f"size-{name.removesuffix('.yaml')}-{key}={value:g}", ["validate", "{case}"],
                           ["time steps"], {"case": _set(base, ("analysis", key), value)}))
    return out


# --- items of issue 17 fixed in the models and readers -----------------------------------------

def _other_corpus() -> list[Bad]:
    static = (EXAMPLES / "oc3_hywind_static.yaml").read_text(encoding="utf-8")
    turn = _example("paper000_turn.yaml")
    lay = _example("paper001_lay_2ms_50m.yaml")
    return [
        Bad("yaml-duplicate-analysis", ["validate", "{dup}"], ["analysis"],
            {"dup": static + "analysis:\n  type: static\n  fairlead: [800.0, -70.0]\n"}),
        # a negative UnstrLen is MoorDyn's factor on the end points' distance: -0.5 cannot reach
        Bad("moordyn-negative-length", ["run", "{md}", "--no-plots"], ["line 1", "cannot span"],
            {"md": MOORDYN.replace("902.2      20", "-0.5       20")}),
        Bad("moordyn-huge-numsegs", ["run", "{md}", "--no-plots"], ["NumSegs"],
            {"md": MOORDYN.replace("902.2      20", "902.2      100000000")}),
        Bad("moordyn-huge-duration", ["run", "{md}", "--no-plots", "--duration", "1e12"], ["time steps"],
            {"md": MOORDYN}),
        Bad("towed-zero-bending-stiffness", ["validate", "{case}"], ["bending_stiffness"],
            {"case": _set(turn, ("line_types", "paper000_cable", "bending_stiffness"), 0.0)}),
        Bad("laying-ship-speed-0", ["validate", "{case}"], ["speed"],
            {"case": _set(lay, ("analysis", "ship", "speed"), 0.0)}),
    ]


# --- mooring systems (issue 18) ------------------------------------------------------------------

def _system_corpus() -> list[Bad]:
    spread = _example("spread_mooring.yaml")
    watch = _example("spread_mooring_watch_circle.yaml")
    brk = _example("spread_mooring_line_break.yaml")
    buoy = ("bodies", "buoy")
    out = [
        Bad("system-unknown-point", ["validate", "{case}"], ["lines.line1.end_b", "fairled1", "Did you mean"],
            {"case": _set(spread, ("lines", "line1", "end_b"), "fairled1")}),
        Bad("system-unknown-body", ["validate", "{case}"], ["points.fairlead2.body", "boy"],
            {"case": _set(spread, ("points", "fairlead2", "body"), "boy")}),
        Bad("system-body-with-no-lines", ["validate", "{case}"], ["bodies.spare", "no line"],
            {"case": _set(spread, ("bodies", "spare"), {"mass": 1.0e3, "volume": 1.0})}),
        Bad("system-negative-mass", ["validate", "{case}"], ["bodies.buoy.mass", "-1"],
            {"case": _set(spread, buoy + ("mass",), -1.0)}),
        Bad("system-negative-inertia", ["validate", "{case}"], ["bodies.buoy", "inertia"],
            {"case": _set(spread, buoy + ("inertia",), [5.9e7, -5.9e7, 3.0e7])}),
        Bad("system-unknown-line-type", ["validate", "{case}"], ["lines.line3.line_type", "chian"],
            {"case": _set(spread, ("lines", "line3", "line_type"), "chian")}),
        Bad("system-anchor-below-seabed", ["validate", "{case}"], ["points.anchor2.position", "below the seabed"],
            {"case": _set(spread, ("points", "anchor2", "position"), [303.0, 524.811, -200.0])}),
        Bad("system-unknown-damaged-line", ["validate", "{case}"], ["damaged_lines", "line9"],
            {"case": _set(spread, ("analysis", "damaged_lines"), ["line9"])}),
        Bad("system-every-line-damaged", ["validate", "{case}"], ["damaged_lines", "every line"],
            {"case": _set(spread, ("analysis", "damaged_lines"), ["line1", "line2", "line3"])}),
        Bad("system-unstable-hydrostatics", ["validate", "{case}"], ["bodies.buoy", "roll", "capsizes"],
            {"case": _set(spread, buoy + ("center_of_gravity",), [0.0, 0.0, 5.0])}),
        Bad("system-no-equilibrium", ["run", "{case}", "--no-plots"], ["no equilibrium", "residual", "load_steps"],
            {"case": _set(_set(_set(spread, buoy + ("waterplane_area",), 0.0), buoy + ("waterplane_moments",),
                                    [0.0, 0.0]), buoy + ("external_force",), [5.0e5, 0.0, 0.0, 0.0, 0.0, 1.0e9])}),
        Bad("system-offsets-unknown-body", ["validate", "{case}"], ["analysis.body", "bouy"],
            {"case": _set(watch, ("analysis", "body"), "bouy")}),
        Bad("system-offsets-loads-decrease", ["validate", "{case}"], ["loads", "increase"],
            {"case": _set(watch, ("analysis", "loads"), [0.0, 5.0e5, 2.5e5])}),
        Bad("system-offsets-fixed-body", ["validate", "{case}"], ["analysis.body", "fixed"],
            {"case": _set(watch, buoy + ("kind",), "fixed")}),
        # 2 conditions x (1 + 12 headings x 5 loads) = 122 equilibria, each counted as a step of the run
        Bad("system-offsets-sweep-too-long", ["validate", "{case}", "--max-steps", "100"],
            ["system_offsets", "--max-steps"], {"case": watch}),
        # system_dynamic (examples/spread_mooring_line_break.yaml)
        Bad("system-dynamic-unknown-motion-body", ["validate", "{case}"], ["body_motions", "bouy", "Did you mean"],
            {"case": _set(brk, ("analysis", "body_motions"), {"bouy": {"amplitude": [1.0, 0.0, 0.0, 0.0, 0.0, 0.0], "period": 10.0}})}),
        Bad("system-dynamic-unknown-force-body", ["validate", "{case}"], ["external_forces", "bouy", "Did you mean"],
            {"case": _set(brk, ("analysis", "external_forces"),
                          {"bouy": {"times": [0.0, 200.0], "values": [[0.0] * 6, [0.0] * 6]}})}),
        Bad("system-dynamic-unknown-failed-line", ["validate", "{case}"], ["failures[0].line", "line7"],
            {"case": _set(brk, ("analysis", "failures"), [{"line": "line7", "end": "b", "time": 20.0}])}),
        Bad("system-dynamic-output-interval", ["validate", "{case}"], ["output_interval", "duration"],
            {"case": _set(brk, ("analysis", "output_interval"), 200.0)}),
        Bad("system-dynamic-short-force-series", ["validate", "{case}"], ["external_forces.buoy", "extend"],
            {"case": _set(brk, ("analysis", "external_forces"),
                          {"buoy": {"times": [0.0, 60.0], "values": [[0.0] * 6, [0.0] * 6]}})}),
        Bad("system-dynamic-missing-force-file", ["validate", "{case}"], ["nope.csv"],
            {"case": _set(brk, ("analysis", "external_forces"), {"buoy": {"file": "nope.csv"}})}),
        Bad("system-dynamic-failure-no-trigger", ["validate", "{case}"], ["failures", "line1", "time"],
            {"case": _set(brk, ("analysis", "failures"), [{"line": "line1", "end": "b"}])}),
    ]
    return out


# --- the corpus of bad input files (tests/unit/bad_inputs/) -------------------------------------

BAD_INPUTS = Path(__file__).resolve().parent / "bad_inputs"
"""One bad input a file (its data files, if any, in ``data/`` and ``data_sea/``). Its first line is a comment
``# expect: PHRASE``: what the message must hold (the key, the option or the file at fault). A sweep file
is given to ``seacable validate`` and ``seacable sweep``; a scatter diagram (``scatter_*.csv``) to
``seacable report RESULT --scatter FILE``; any other file (a case, a MoorDyn deck) to ``seacable validate`` and
``seacable run``. A new bad input is a new file there, nothing else."""


def _expected(path: Path) -> str:
    first = path.read_bytes().split(b"\n", 1)[0].decode("ascii").strip()
    assert first.startswith("# expect:"), f"{path.name}: its first line must be '# expect: PHRASE', got {first!r}"
    return first.removeprefix("# expect:").strip()


def _file_corpus() -> list[Bad]:
    from seacable.sweeps import is_sweep_file

    out = []
    for path in sorted(p for p in BAD_INPUTS.iterdir() if p.is_file()):
        phrase = _expected(path)
        if path.name.startswith("scatter_"):
            # read before the results (a mooring_dynamic result of the shared fixture) whether or not a life is
            # computed
            commands = [["report", "{nc_mooring_dynamic}", "--scatter", str(path), "-o", "{tmp_out}/report.html"]]
        elif is_sweep_file(path):
            commands = [["validate", str(path)], ["sweep", str(path), "-o", "{tmp_out}", "--no-plots"]]
        else:
            commands = [["validate", str(path)], ["run", str(path), "--no-plots"]]
        for argv in commands:
            out.append(Bad(f"file-{path.name}-{argv[0]}", argv, [phrase]))
    return out


CORPUS = (_file_corpus() + _case_corpus() + _other_corpus() + _system_corpus() + _option_corpus() + _path_corpus() + _motion_corpus() + _netcdf_corpus()
          + _sweep_corpus() + _size_corpus())


def test_the_corpus_is_large_and_each_id_unique():
    assert len(CORPUS) >= 200
    assert len({b.id for b in CORPUS}) == len(CORPUS)


def test_each_file_of_the_corpus_is_a_distinct_bad_input():
    # one file per bad input (issue 37's second corpus: tests/unit/bad_inputs/), none a copy of another
    files = [p for p in BAD_INPUTS.iterdir() if p.is_file()]
    assert len(files) >= 300
    assert len({p.read_bytes() for p in files}) == len(files)


# --- the files the corpus refers to --------------------------------------------------------------



#: libyaml's emitter when PyYAML has it (the corpus writes a thousand files: Python's emitter took 15 s of the run)
_DUMPER = getattr(yaml, "CSafeDumper", yaml.SafeDumper)


def _write(path: Path, content) -> str:
    if content is None:
        return str(path)  # missing
    if content == "<dir>":
        path.mkdir()
    elif isinstance(content, bytes):
        path.write_bytes(content)
    elif isinstance(content, (dict, list)):
        path.write_text(yaml.dump(content, Dumper=_DUMPER, sort_keys=False), encoding="utf-8")
    else:
        path.write_text(content, encoding="utf-8")
    return str(path)


def _result(analysis: str, drop: str | None = None) -> xr.Dataset:
    """A labelled result of ``analysis`` holding every variable of its schema but ``drop``."""
    data = {}
    for name in ANALYSIS_VARIABLES[analysis]:
        if name != drop:
            data[name] = xr.Variable(("k",), np.arange(3.0), attrs={"units": "1", "long_name": name})
    return xr.Dataset(data, attrs={"analysis": analysis, "title": analysis})


def _sweep_file(tmp: Path, name: str, **spec) -> str:
    return _write(tmp / f"{name}.yaml", {"name": name, "base": STATIC, **spec})


@pytest.fixture(scope="module")
def shared(tmp_path_factory):
    """Files shared by many corpus items (results, sweeps, inputs of each kind)."""
    tmp = tmp_path_factory.mktemp("bad")
    files = {"tmp": str(tmp), "moordyn": _write(tmp / "lines.txt", MOORDYN)}
    files["file"] = _write(tmp / "a_file", "not a folder")
    (tmp / "a_dir").mkdir()
    files["dir"] = str(tmp / "a_dir")
    (tmp / "dir.nc").mkdir()
    files["dir_nc"] = str(tmp / "dir.nc")
    files["motion_ok"] = _write(tmp / "ok.csv", "time,x\n0,0\n100,1\n")
    for name, content in MOTIONS.items():
        files[f"motion_{name}"] = _write(tmp / f"motion_{name}.csv", content)
    for kind, content in (("missing", None), ("dir", "<dir>"), ("binary", b"\x00\x01\x02\xff" * 64),
                          ("empty", ""), ("text", "just some text, not a mapping\n")):
        files[f"{kind}_yaml"] = _write(tmp / f"{kind}.yaml", content)
    # result files
    for kind, content in (("missing", None), ("dir", "<dir>"), ("text", "not a netcdf\n"), ("empty", b"")):
        files[f"nc_{kind}"] = _write(tmp / f"nc_{kind}.nc", content)
    for analysis in ANALYSIS_VARIABLES:
        path = tmp / f"{analysis}.nc"
        _result(analysis).to_netcdf(path)
        files[f"nc_{analysis}"] = str(path)
        for name in ANALYSIS_VARIABLES[analysis]:
            path = tmp / f"{analysis}_no_{name}.nc"
            _result(analysis, name).to_netcdf(path)
            files[f"nc_{analysis}_no_{name}"] = str(path)
    files["nc_lay"] = files["nc_laying_dynamic"]
    files["nc_static"] = files["nc_static"]
    no_attr = _result("static")
    no_attr.attrs = {}
    no_attr.to_netcdf(tmp / "nc_no_analysis.nc")
    files["nc_no_analysis"] = str(tmp / "nc_no_analysis.nc")
    unknown = _result("static")
    unknown.attrs["analysis"] = "flying"
    unknown.to_netcdf(tmp / "nc_unknown_analysis.nc")
    files["nc_unknown_analysis"] = str(tmp / "nc_unknown_analysis.nc")
    whole = (tmp / "static.nc").read_bytes()
    files["nc_truncated"] = _write(tmp / "nc_truncated.nc", whole[: len(whole) // 3])
    # sweep files
    files["sweep"] = _sweep_file(tmp, "sweep", grid={"environment.depth": [320.0, 330.0]})
    big = [float(300 + v) for v in range(5000)]
    files["sweep_big"] = _sweep_file(tmp, "sweep_big", grid={"environment.depth": big,
                                                             "environment.water_density": big})
    files["sweep_big_ranges"] = _sweep_file(tmp, "sweep_big_ranges", grid={
        "environment.depth": {"start": 300.0, "stop": 400.0, "num": 5000},
        "environment.water_density": {"start": 1000.0, "stop": 1030.0, "num": 5000}})
    files["sweep_one_bad"] = _sweep_file(tmp, "sweep_one_bad", grid={"environment.depth": [320.0, -5.0]})
    files["sweep_all_bad"] = _sweep_file(tmp, "sweep_all_bad", grid={"environment.depth": [-1.0, -5.0]})
    files["sweep_short"] = _sweep_file(tmp, "sweep_short", grid={"line.length": [902.2, 400.0]})
    files["sweep_unknown_path"] = _sweep_file(tmp, "sweep_unknown_path", grid={"environment.dept": [1.0]})
    files["sweep_bad_path"] = _sweep_file(tmp, "sweep_bad_path", grid={"a..b": [1.0]})
    files["sweep_empty_grid"] = _sweep_file(tmp, "sweep_empty_grid", grid={})
    files["sweep_empty_list"] = _sweep_file(tmp, "sweep_empty_list", grid={"environment.depth": []})
    files["sweep_grid_and_table"] = _sweep_file(tmp, "sweep_grid_and_table", grid={"environment.depth": [1.0]},
                                                table="t.csv")
    files["sweep_missing_table"] = _sweep_file(tmp, "sweep_missing_table", table="nope.csv")
    _write(tmp / "ragged.csv", "environment.depth,environment.water_density\n320,1025\n330\n")
    files["sweep_ragged_table"] = _sweep_file(tmp, "sweep_ragged_table", table="ragged.csv")
    files["sweep_no_base"] = _write(tmp / "sweep_no_base.yaml", {"name": "x", "grid": {"environment.depth": [1.0]},
                                                                "table": "t.csv"})
    files["sweep_zero_step"] = _sweep_file(tmp, "sweep_zero_step", grid={
        "environment.depth": {"start": 300.0, "stop": 400.0, "step": 0.0}})
    files["sweep_scalar"] = _sweep_file(tmp, "sweep_scalar", grid={"environment.depth": 320.0})
    return files


def _fill(text: str, files: dict) -> str:
    for key, value in files.items():
        text = text.replace("{" + key + "}", value)
    return text


@pytest.fixture
def workdir(tmp_path_factory) -> Path:
    """An empty folder of the test's own. Not ``tmp_path``: it numbers a test's folder by scanning the folders of
    the same name before it (quadratic in the corpus's 2469 items, a tenth of the file's time) and re-links a
    'current' symlink each time."""
    return Path(tempfile.mkdtemp(prefix="bad-", dir=tmp_path_factory.getbasetemp()))


@pytest.mark.parametrize("bad", [b.param() for b in CORPUS])
def test_bad_input_gets_one_clear_message(bad, shared, workdir, capsys, monkeypatch):
    tmp_path = workdir
    monkeypatch.chdir(tmp_path)   # default outputs (CASE.nc, sweep folders) land here
    files = dict(shared)
    for key, content in bad.files.items():
        suffix = ".txt" if key == "md" else ".yaml"   # a MoorDyn file is found by its text, not its suffix
        files[key] = _write(tmp_path / f"{key}{suffix}", content)
    files["tmp_out"] = str(tmp_path / "out")
    argv = [_fill(a, files) for a in bad.argv]
    t0 = time.monotonic()
    status = main(argv)
    elapsed = time.monotonic() - t0
    out, err = capsys.readouterr()
    if bad.id.startswith("file-"):
        # refused as it is read, before a kernel is compiled or a step computed: a second or two, even on a
        # loaded machine; a bad size that is not refused (a billion elements) runs for hours
        assert elapsed < 60, (elapsed, err)
    # nothing written where the command was run: no result (and so no NaN or inf in one)
    assert not [p for p in tmp_path.rglob("*") if p.suffix in (".nc", ".png", ".csv", ".html", ".gif", ".mp4")], list(tmp_path.rglob("*"))
    assert status not in (0, 3), (status, err)
    assert status == 2, (status, err)
    assert "Traceback" not in out + err
    assert "seacable: error:" in err, err
    for name in bad.names:
        assert _fill(name, files) in err, (name, err)
