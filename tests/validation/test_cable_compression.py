"""Elements that carry compression (``analysis.compression``, :data:`seacable.mooring.kernel.E_COMPRESS`) against
the closed forms of a straight rod under end shortening (Timoshenko and Gere 1961, *Theory of Elastic Stability*,
sec. 2.1 and 2.7): below Euler's load the rod stays straight and carries ``EA delta / L`` in compression; beyond
it the rod buckles, its compression holds at Euler's ``P_cr = pi^2 EI / L^2`` (pinned ends) to first order in the
end shortening, and its deflection is the elastica's ``a = (2 / pi) sqrt(e L)`` for the shortening ``e`` the
bending takes. And the steep wave that has no equilibrium without compression (its base clamped straight up
while the line pulls sideways) converges with it, its base in compression."""

from __future__ import annotations

import math

import numpy as np
import pytest

import seacable as sc
from seacable.case import Case
from seacable.line import Line, LineType
from seacable.mooring.network import network_from_line
from seacable.mooring.solver import MooringModel, Water, static_equilibrium

RHO, G = 1025.0, 9.81
EI, EA, L, N = 1.0e4, 1.0e6, 20.0, 40
P_CR = math.pi**2 * EI / L**2  # 246.7 N


def _rod(shortening: float):
    """A weightless 20 m rod (EI 10 kN m^2, EA 1 MN, 40 elements) between pinned ends ``shortening`` closer than
    its length, from the solver's start (a V below the chord, which breaks the symmetry)."""
    rod = LineType(diameter=0.1, mass_per_length=RHO * math.pi / 4 * 0.01, axial_stiffness=EA,
                   bending_stiffness=EI)
    net = network_from_line(Line.single(rod, L), (0, 0, -50.0), (L - shortening, 0, -50.0), water_density=RHO,
                            gravity=G, n_elements=N)
    from seacable.mooring.network import slack_positions

    start = slack_positions((0, 0, -50.0), (L - shortening, 0, -50.0), net.arc_length, L)
    return static_equilibrium(MooringModel(net.replace(position=start), Water(density=RHO, gravity=G,
                                                                               compression=True)), tol=1e-10)


def test_straight_rod_below_eulers_load_carries_ea_strain():
    """Shortened by half Euler's strain, the rod is straight again and every element carries -EA delta / L
    (-123 N): measured 6e-11, 1e-6 asserted; the nodes on the chord to 1e-9 m. Without compression it would
    carry nothing."""
    delta = 0.5 * P_CR * L / EA
    st = _rod(delta)
    assert st.tension == pytest.approx(np.full(N, -EA * delta / L), rel=1e-6)
    assert np.max(np.abs(st.position[:, 2] + 50.0)) < 1e-6


def test_buckled_rod_holds_eulers_load_and_the_elasticas_deflection():
    """Shortened by 0.1 m (20 times Euler's strain), it buckles. Its end force (the compression along the chord) is
    Euler's load, raised by the elastica's first order ``e / 2L`` (2.4e-3, e the bending's share of the shortening:
    0.1 m less the axial P L / EA) and lowered by the discrete rod's ``pi^2 / (12 n^2)`` (5.1e-4): measured 4.9e-4
    from that, 1e-3 asserted (the next orders, (e / L)^2 and h^2 e / L); without the elastica's rise it is 2.4e-3
    off. Its mid-span deflection is the elastica's (2 / pi) sqrt(e L): measured 1.2e-3, 1 % asserted (the next
    order, e / L = 5e-3)."""
    st = _rod(0.1)
    P = abs(float(st.support[0, 0]))
    e = 0.1 - P * L / EA
    assert P / P_CR == pytest.approx(1 + e / (2 * L) - math.pi**2 / (12 * N**2), abs=1e-3)
    a = float(np.max(np.abs(st.position[:, 2] + 50.0)))
    assert a == pytest.approx(2 / math.pi * math.sqrt(e * L), rel=1e-2)


def test_steep_wave_base_in_compression_converges():
    """The steep wave clamped straight up with 30 m of bare cable below its buoyancy, hung off 100 m away: without
    compression no equilibrium at 1 m elements (tests/unit/test_cable_configurations.py); with it, it converges
    at 1 and 4 elements a metre, the base in compression (about 0.6-1.2 kN: the bare stub bending over carries its
    weight into the clamp)."""
    import yaml
    from pathlib import Path

    data = yaml.safe_load((Path(sc.__file__).resolve().parents[2] / "examples" / "steep_wave_80m.yaml").read_text())
    data["environment"].pop("current")
    data["line"]["sections"][0].update(start=30.0, length=50.0)
    for per_metre in (1.0, 4.0):
        data["analysis"].update(fairlead=[100.0, -14.0], element_length=1.0 / per_metre, compression=True)
        ds = sc.run(Case.parse(data))
        assert float(ds.segment_tension[0]) < -500.0
