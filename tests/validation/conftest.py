"""Shared helpers of the validation tests (fixtures, since the tests import in importlib mode)."""

from __future__ import annotations

import pytest

import seacable as sc
from seacable.mooring.solver import MooringModel, Water, simulate, static_equilibrium


def coupled_and_mooring(line_type, *, n=20, duration=10.0, dt=0.1):
    """One 100 m line from a fixed anchor to a coupled point moved harmonically (0.5 m, 0.25 m at 10 s),
    run by the coupled body-line kernel (system_dynamic) and by the mooring kernel; element tensions
    (nt, e) of both."""
    from seacable.mooring.motion import HarmonicMotion, bind
    from seacable.mooring.network import network_from_line
    from seacable.system.dynamics import (
        SystemDynamicAnalysis,
        build_system_fe,
        simulate_system,
        static_system,
    )
    from seacable.system.model import MooringSystem, SystemLine, SystemPoint

    line = sc.Line.single(line_type, 100.0)
    a, b = (0.0, 0.0, -60.0), (80.0, 0.0, -10.0)
    motion = HarmonicMotion(amplitude=(0.5, 0.0, 0.25), period=10.0)
    system = MooringSystem(points={"anchor": SystemPoint(kind="fixed", position=a),
                                   "fair": SystemPoint(kind="coupled", position=b)}, bodies={},
                           lines={"l": SystemLine(line=line, end_a="anchor", end_b="fair", n_elements=n)})
    analysis = SystemDynamicAnalysis(duration=duration, time_step=dt, output_interval=0.5,
                                     point_motions={"fair": motion})
    fe = build_system_fe(system, sc.Environment(water_density=1025.0, gravity=9.81, depth=100.0), analysis)
    coupled = simulate_system(fe, static_system(fe), duration, dt, 0.5, analysis=analysis)
    net = network_from_line(line, a, b, water_density=1025.0, gravity=9.81, n_elements=n)
    model = MooringModel(net, Water(density=1025.0, gravity=9.81, depth=100.0))
    start = static_equilibrium(model, initial=fe.model.network.position[fe.model.network.line_nodes[0]])
    alone = simulate(model, bind(motion, net.channel_positions(start.position), duration), duration, dt, 0.5,
                     initial=start.position)
    return coupled.tension, alone.tension


@pytest.fixture
def two_kernels():
    """:func:`coupled_and_mooring`: the same line run by the coupled body-line kernel and the mooring kernel."""
    return coupled_and_mooring


def system_and_mooring_cases(duration=10.0, n=20):
    """One 600 m chain with a 5 t clump (drag, added mass) from an anchor 200 m deep to a fairlead moved
    harmonically (4 m surge, 1 m heave at 15 s, ramped over 15 s), in 4 m / 9 s waves and a 0.5 m/s current, about
    300 m of it on a seabed with friction 0.5: every load of the lines' kernel at once. Run as a ``system_dynamic``
    case (coupled body-line kernel) and as a ``mooring_dynamic`` case (mooring kernel); their Datasets."""
    lt = {"diameter": 0.09, "mass_per_length": 77.7, "axial_stiffness": 3.8e8, "drag_normal": 1.6,
          "added_mass_normal": 1.0, "drag_tangential": 0.1}
    line = {"segments": [{"line_type": "c", "length": 600.0}],
            "attachments": [{"s": 300.0, "mass": 5000.0, "volume": 0.3, "drag_area": 1.0, "added_mass": 300.0,
                             "kind": "clump"}]}
    env = {"water_density": 1025.0, "gravity": 9.81, "depth": 200.0, "waves": {"height": 4.0, "period": 9.0},
           "current": {"speed": 0.5}, "seabed": {"friction": 0.5}}
    motion = {"type": "harmonic", "amplitude": [4.0, 0.0, 1.0], "period": 15.0, "ramp": 15.0}
    run = {"duration": duration, "time_step": 0.1, "output_interval": 0.5, "n_elements": n}
    mooring = sc.parse_case({"name": "m", "line_types": {"c": lt}, "line": line, "environment": env,
                             "analysis": {"type": "mooring_dynamic", "fairlead": [520.0, -20.0], "motion": motion,
                                          **run}})
    system = sc.parse_case({"name": "s", "line_types": {"c": lt}, "environment": env,
                            "points": {"anchor": {"kind": "fixed", "position": [0.0, 0.0, -200.0]},
                                       "fair": {"kind": "coupled", "position": [520.0, 0.0, -20.0]}},
                            "lines": {"l": {**line, "end_a": "anchor", "end_b": "fair"}},
                            "analysis": {"type": "system_dynamic", "point_motions": {"fair": motion}, **run}})
    return sc.run(system), sc.run(mooring)


@pytest.fixture
def two_kernel_cases():
    """:func:`system_and_mooring_cases`: a line in waves, current and on the seabed, run by both kernels."""
    return system_and_mooring_cases


def volturnus_hull_case(folder, *, waves, rope, body=None, analysis=None):
    """A case file (its path) of the VolturnUS-S hull with its WAMIT database (tests/data/volturnus: the displaced
    volume's mass, the platform's inertias, its centre of gravity 5 m below the reference point, a linear damping
    of 5-20 % of critical) on three ropes of line type ``rope`` from anchors 300 m out in 200 m of water to
    fairleads 40 m out at 14 m draft, in ``waves``; ``body`` updates the hull, ``analysis`` the analysis (a 600 s
    ``system_dynamic`` at 0.1 s by default) or, of another type, is the analysis."""
    import math
    from pathlib import Path

    import numpy as np
    import yaml

    root = Path(__file__).parents[1] / "data" / "volturnus" / "IEA-15-240-RWT-UMaineSemi"
    rho, volume = 1025.0, 20206.34889
    points, lines = {}, {}
    for k in range(3):
        ang = 2 * math.pi * k / 3
        points[f"anchor{k}"] = {"kind": "fixed", "position": [300 * math.cos(ang), 300 * math.sin(ang), -200.0]}
        points[f"fair{k}"] = {"kind": "body", "body": "hull", "position": [40 * math.cos(ang), 40 * math.sin(ang), -14.0]}
        lines[f"rope{k}"] = {"line_type": "rope", "length": 300.0, "end_a": f"anchor{k}", "end_b": f"fair{k}"}
    hull = {"kind": "free", "mass": rho * volume, "inertia": [1.2507e10, 1.2507e10, 2.3667e10], "volume": volume,
            "center_of_gravity": [0, 0, -5.0], "linear_damping": np.diag([6e5, 6e5, 1.4e6, 1.4e9, 1.4e9, 6e8]).tolist(),
            "hydrodynamics": {"file": str(root), "kernel_length": 60.0, "ramp": 40.0}}
    hull.update(body or {})
    data = {"name": "hull", "line_types": {"rope": rope},
            "environment": {"water_density": rho, "gravity": 9.80665, "depth": 200.0, "waves": waves},
            "bodies": {"hull": hull}, "points": points, "lines": lines,
            "analysis": {"type": "system_dynamic", "duration": 600.0, "time_step": 0.1, "output_interval": 0.1,
                         "n_elements": 10, **(analysis or {})}}
    if (analysis or {}).get("type", "system_dynamic") != "system_dynamic":
        data["analysis"] = analysis  # another analysis: as given
    path = Path(folder) / "hull.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    return path


@pytest.fixture
def hull_case():
    """:func:`volturnus_hull_case`, for the tests of floating bodies with a database."""
    return volturnus_hull_case
