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
