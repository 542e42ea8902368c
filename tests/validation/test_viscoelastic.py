"""Viscoelastic axial stiffness (MoorDyn v2's ``EA_s|EA_d`` line types) in the mooring finite elements.

Issue 18: a synthetic rope's element is MoorDyn's viscoelastic model (Hall, Duong and Lozon, "A
viscoelastic model for synthetic mooring lines", IOWTC2023; MoorDyn ``Line.cpp``): a fast spring
``EA_D`` with damper ``BA_D`` in series with a slow spring ``EA_1 = EA_D EA_s / (EA_D - EA_s)`` with
damper ``BA``, so that the static stiffness is ``EA_s``; the slow stretch is an internal state of
each element, integrated over each implicit step. Closed forms of this series Kelvin-Kelvin solid:

- creep under a constant load ``P``: ``eps(t) = P / EA_D (1 - exp(-t EA_D / BA_D))
  + P / EA_1 (1 - exp(-t EA_1 / BA))``, from the dynamic strain ``P / EA_D`` to the static ``P / EA_s``;
- its complex stiffness under harmonic stretch ``dl e^{i w t}``: ``T L / dl = Z1 Z2 / (Z1 + Z2)``,
  ``Z1 = EA_1 + i w BA``, ``Z2 = EA_D + i w BA_D``, from ``EA_s`` at low to ``EA_D`` at high frequency
  (``BA_D = 0``);
- statics at ``EA_s``;

and MoorDyn 2.7.2 on the same taut line under a harmonic fairlead motion, side by side, with the
constant (``EA_s|EA_d``) and the mean-load-dependent (``EA_s|EA_Dc|EA_D_Lm``) dynamic stiffness.
"""

from __future__ import annotations

import math
import os

import numpy as np
import pytest

import seacable as sc
from seacable.mooring.moordyn import moordyn_model
from seacable.mooring.network import FIXED, FREE, PRESCRIBED, Network, network_from_line
from seacable.mooring.solver import MooringModel, Water, simulate, static_equilibrium

EA_S, EA_D, BA = 1.0e7, 2.0e7, 2.0e8  # [N], [N], [N s]
EA_1 = EA_D * EA_S / (EA_D - EA_S)  # 2e7 N
L = 10.0


def _element(*, free, ba_d, load=0.0, mass=1.0, ea_d=EA_D, mean_load_slope=0.0):
    """One vertical viscoelastic element from a fixed node at z = -10 m; its lower node free (carrying
    ``load`` [N] and ``mass`` [kg]) or prescribed (channel 0). No water, no line weight."""
    z, one = np.zeros(2), np.ones(1)
    net = Network(position=np.array([[0.0, 0.0, -10.0], [0.0, 0.0, -10.0 - L]]),
                  kind=np.array([FIXED, FREE if free else PRESCRIBED]), channel=np.array([-1, -1 if free else 0]),
                  point_mass=np.array([0.0, mass]), point_added_mass=z.copy(), point_weight=np.array([0.0, load]),
                  point_volume=z.copy(), point_drag_area=z.copy(), elements=np.array([[0, 1]]), length=L * one,
                  axial_stiffness=EA_S * one, axial_damping=BA * one, mass_per_length=1e-3 * one,
                  weight_per_length=0.0 * one, diameter=0.01 * one, cdn=0.0 * one, cdt=0.0 * one, can=0.0 * one,
                  cat=0.0 * one, element_line=np.zeros(1, np.int64), line_nodes=(np.arange(2),), line_names=("e",),
                  arc_length=np.array([0.0, L]), n_channels=0 if free else 1, channel_names=() if free else ("f",),
                  element_viscoelastic=np.array([[ea_d, mean_load_slope, ba_d]]))
    return MooringModel(net, Water(density=0.0, gravity=9.81, depth=None))


def test_creep_under_a_step_load():
    """P = 100 kN hung at t = 0 on the unstretched element (1 kg, BA_D = 1e5 N s: the fast branch settles
    in BA_D / EA_D = 5 ms, overdamped): the strain follows the closed form from P / EA_D = 0.005 to
    P / EA_s = 0.01 with the creep time BA / EA_1 = 10 s, within 5e-5 relative from 1 s on (observed
    2.6e-5 at 1 s, falling to 2e-7; the node's inertia, 1 kg against the 100 kN, stays below 1e-4)."""
    P, ba_d = 1.0e5, 1.0e5
    model = _element(free=True, ba_d=ba_d, load=P)
    x0 = model.network.position.copy()
    run = simulate(model, None, 40.0, 0.1, 1.0, initial=x0)
    t = run.time[1:]
    strain = -(run.position[1:, 1, 2] - x0[1, 2]) / L
    exact = P / EA_D * (1 - np.exp(-t * EA_D / ba_d)) + P / EA_1 * (1 - np.exp(-t * EA_1 / BA))
    assert np.max(np.abs(strain / exact - 1)) < 5e-5
    assert strain[0] == pytest.approx(P / EA_D + P / EA_1 * (1 - math.exp(-0.1)), rel=1e-4)  # dynamic first
    assert strain[-1] == pytest.approx(P / EA_S, rel=0.01)  # static after 4 creep times (exp(-4) = 1.8 %)
    assert run.tension[-1, 0] == pytest.approx(P, rel=1e-4)


def _harmonic(omega, *, per_period=100):
    """Tension amplitude and phase of the element under a stretch 1 % + 0.1 % sin(w t) (BA_D = 0),
    fitted over the last two periods after eight relaxation times; returns the measured and the exact
    complex stiffness [N]."""
    model = _element(free=False, ba_d=0.0)
    x0 = model.network.position.copy()
    x0[1, 2] -= 0.01 * L
    base, amp = x0[1].copy(), 1e-3 * L

    def motion(t):
        t = np.asarray(t, float)
        x = np.broadcast_to(base, (len(t), 1, 3)).copy()
        v, a = np.zeros_like(x), np.zeros_like(x)
        x[:, 0, 2] -= amp * np.sin(omega * t)
        v[:, 0, 2] = -amp * omega * np.cos(omega * t)
        a[:, 0, 2] = amp * omega**2 * np.sin(omega * t)
        return x, v, a

    period = 2 * math.pi / omega
    tau = BA / (EA_D + EA_1)
    n_periods = math.ceil(8 * tau / period) + 2
    dt = period / per_period
    run = simulate(model, motion, n_periods * period, dt, dt, initial=x0)
    keep = run.time >= (n_periods - 2) * period - 1e-9
    t = run.time[keep]
    G = np.column_stack([np.ones(t.size), np.sin(omega * t), np.cos(omega * t)])
    c = np.linalg.lstsq(G, run.tension[keep, 0], rcond=None)[0]
    z1 = EA_1 + 1j * omega * BA
    return (c[1] + 1j * c[2]) * L / amp, z1 * EA_D / (z1 + EA_D), c[0]


@pytest.mark.parametrize("omega", [0.02, 0.2, 2.0, 20.0])
def test_apparent_stiffness_under_harmonic_stretch(omega):
    """w tau = 0.1, 1, 10, 100 (tau = BA / (EA_D + EA_1) = 5 s): the complex stiffness Z1 Z2 / (Z1 + Z2),
    |Z| = 1.015e7, 1.581e7, 1.993e7, 2.000e7 N, within 1e-3 in modulus and 2e-3 rad in phase (100 steps
    a period: the second-order error of the integration, observed 3e-4 at the lowest frequency and
    below 1e-6 at the highest); the mean tension stays the static EA_s x 1 % = 100 kN. At w tau = 100
    the element is as stiff as EA_D to 1e-4: the fast loading sees the dynamic stiffness."""
    measured, exact, mean = _harmonic(omega)
    assert abs(measured) == pytest.approx(abs(exact), rel=1e-3)
    assert np.angle(measured) == pytest.approx(np.angle(exact), abs=2e-3)
    assert mean == pytest.approx(EA_S * 0.01, rel=1e-4)
    if omega == 20.0:
        assert abs(measured) == pytest.approx(EA_D, rel=1e-4)
    if omega == 0.02:
        assert abs(measured) == pytest.approx(EA_S, rel=0.02)


def test_statics_use_the_static_stiffness():
    """A 100 m hanging polyester line with a 50 kN weight: its static shape and tensions with EA_s|EA_d
    are the elastic line's with EA_s, bit for bit (statics take the viscoelastic element as the elastic
    one at EA_s, with its slack rounding; the static slow stretch makes the series springs EA_s)."""
    def hanging(**kw):
        lt = sc.LineType(diameter=0.1, mass_per_length=8.0, axial_stiffness=EA_S, drag_normal=0.0, **kw)
        line = sc.Line.single(lt, 100.0, attachments=(sc.PointMass(s=100.0, weight_in_water=5e4),))
        net = network_from_line(line, (0, 0, -10.0), (0, 0, -110.0), water_density=1025.0, gravity=9.81,
                                n_elements=10, end_b="free")
        return static_equilibrium(MooringModel(net, Water(depth=None)), tol=1e-12)

    visco = hanging(dynamic_axial_stiffness=(EA_D, 0.0), dynamic_axial_damping=1e5)
    elastic = hanging()
    assert np.array_equal(visco.position, elastic.position) and np.array_equal(visco.tension, elastic.tension)
    # and the stretch is EA_s's, not EA_D's: the 50 kN weight alone stretches the lowest element by 0.5 %
    assert visco.position[-2, 2] - visco.position[-1, 2] == pytest.approx(10.0 * (1 + 5e4 / EA_S), rel=1e-3)


def test_dynamic_stiffness_must_exceed_the_static():
    with pytest.raises(ValueError, match=r"EA_Dc = 1e\+07 N must exceed the static axial_stiffness EA_s"):
        sc.LineType(diameter=0.1, mass_per_length=8.0, axial_stiffness=EA_S, dynamic_axial_stiffness=(EA_S, 0.0))


DECK = """--------------------- MoorDyn Input File ------------------------------------
a taut viscoelastic line, its fairlead moved along the line
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA            BA/-zeta      EI    Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)           (N-s/-)       (N-m^2) (-)  (-)    (-)     (-)
rope       0.02    1.0        {ea}   1.0e6|1.0e3   0.0   0.0    0.0    0.0     0.0
---------------------- POINT PROPERTIES --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     0       0.0     -50.0   0      0       0      0
2     Coupled   100     0.0     -50.0   0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     rope       1        2         99.0      10       -
---------------------- OPTIONS -----------------------------------------
0             writeLog
2e-4          dtM
100           WtrDpth
0.0           kBot
0.0           cBot
1025          WtrDnsty
9.80665       g
1.0           dtIC
1e-7          threshIC
20.0          TmaxIC
------------------------- need this line --------------------------------------
"""
# MoorDyn's dtM (read by MoorDyn only; seacable steps at DT): 2e-4 s moves MoorDyn's fairlead tension by 6e-6 of
# its range from 1e-4 s (0.3 % of the side-by-side test's 2e-3; 5e-4 s: 1.3e-4), at half the cost
AMP, OMEGA, DURATION, DT = 0.2, 1.0, 30.0, 0.01


def _moordyn_fairlead_tension(moordyn, deck):
    """MoorDyn 2.7.2: the fairlead moved by AMP sin(OMEGA t) along the line, its tension every DT."""
    saved, null = os.dup(1), os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)  # MoorDyn prints every step
    try:
        system = moordyn.Create(str(deck))
        x0 = np.array([100.0, 0.0, -50.0])
        moordyn.Init(system, x0.tolist(), [0.0, 0.0, 0.0])
        out = []
        for k in range(round(DURATION / DT)):
            t = k * DT
            x, x1 = (x0 + [AMP * math.sin(OMEGA * s), 0.0, 0.0] for s in (t, t + DT))
            moordyn.Step(system, x.tolist(), ((x1 - x) / DT).tolist(), t, DT)
            fh, fv, _, _ = moordyn.GetFASTtens(system, 1)
            out.append(math.hypot(fh[0], fv[0]))
        moordyn.Close(system)
    finally:
        os.dup2(saved, 1)
        os.close(null)
    return np.array(out)


def _seacable_fairlead_tension(deck):
    model = moordyn_model(deck)
    st = static_equilibrium(model, tol=1e-10)
    base = model.network.channel_positions(st.position)

    def motion(t):
        t = np.asarray(t, float)
        x = np.broadcast_to(base, (len(t), *base.shape)).copy()
        v, a = np.zeros_like(x), np.zeros_like(x)
        x[:, 0, 0] += AMP * np.sin(OMEGA * t)
        v[:, 0, 0] = AMP * OMEGA * np.cos(OMEGA * t)
        a[:, 0, 0] = -AMP * OMEGA**2 * np.sin(OMEGA * t)
        return x, v, a

    run = simulate(model, motion, DURATION, DT, DT, initial=st.position)
    fair = int(np.flatnonzero(model.network.kind == PRESCRIBED)[0])
    return np.linalg.norm(run.support[1:, fair], axis=1)


@pytest.mark.parametrize("ea", ["1.0e6|2.0e6", "1.0e6|1.5e6|20.0"])
def test_side_by_side_with_moordyn(tmp_path, ea):
    """A 99 m rope (EA_s 1 MN, BA 1 MN s, BA_D 1 kN s, 10 segments) stretched 1 % between two points
    100 m apart, its fairlead moved 0.2 m along it at 1 rad/s for 30 s: the fairlead tension against
    MoorDyn 2.7.2's within 2e-3 of its peak-to-peak range from t = 5 s on (observed 6.8e-4 with
    EA_D = 2 MN, 9.1e-4 with the mean-load-dependent EA_D = 1.5 MN + 20 T_mean; the start differs by the
    two codes' start-up at rest, and both codes' elastic ropes differ by 0.18 % statically, MoorDyn's
    fairlead tension including its end node's weight). The same rope elastic at EA_s, in seacable, is
    off MoorDyn's viscoelastic answer by 12 % of the range: the comparison sees the model."""
    moordyn = pytest.importorskip("moordyn")
    deck = tmp_path / "rope.txt"
    deck.write_text(DECK.format(ea=ea))
    peer = _moordyn_fairlead_tension(moordyn, deck)
    ours = _seacable_fairlead_tension(deck)
    late = np.arange(1, peer.size + 1) * DT >= 5.0
    span = np.ptp(peer[late])
    assert np.max(np.abs(ours - peer)[late]) < 2e-3 * span
    elastic = tmp_path / "elastic.txt"
    elastic.write_text(DECK.format(ea="1.0e6").replace("1.0e6|1.0e3", "1.0e3      "))
    assert np.max(np.abs(_seacable_fairlead_tension(elastic) - peer)[late]) > 0.05 * span


def test_coupled_system_kernel_carries_the_viscoelasticity(two_kernels):
    """The coupled body-line kernel (system_dynamic) and the mooring kernel run the same viscoelastic
    line (EA_s 1e7 N, EA_D 2e7 N, BA_D 4e7 N s: relaxation time 1 s) under the same fairlead motion:
    the same tensions to 1e-6 of the largest (observed 1e-10), and the slow stretch's state, carried
    from step to step in both, moves the tensions from the elastic line's by more than 20 % of their
    range (observed 49 %)."""
    kw = {"diameter": 0.1, "mass_per_length": 20.0, "axial_stiffness": 1e7}
    visco = two_kernels(sc.LineType(**kw, dynamic_axial_stiffness=(2e7, 0.0), dynamic_axial_damping=4e7))
    elastic = two_kernels(sc.LineType(**kw))
    assert np.max(np.abs(visco[0] - visco[1])) < 1e-6 * np.max(visco[1])
    assert np.max(np.abs(visco[1] - elastic[1])) > 0.2 * np.ptp(elastic[1])


def test_slack_rounding_is_the_elastic_elements():
    """Going slack in the time domain: the viscoelastic element's tension-only switch is rounded over the
    elastic element's band (a quarter of the element's weight in air, Tb = EA_s sband). With a step so long
    that the slow stretch has settled (dt = 1e12 s: T = EA_s eps), its tension at eps = -sband/2, 0,
    sband/2 and 2 sband equals the elastic element's (the static path, rounded) to 1e-5 relative (the
    roundings are the same parabola, (T + Tb)^2 / (4 Tb); the band here is 2.5e-9 m of a 10 m element, whose
    stretch the two paths form differently, l - L and l / L - 1, to 1e-15 m: 1e-6 of it); before, it was
    0 at and below eps = 0."""
    from seacable.mooring import kernel as K

    model = _element(free=False, ba_d=1.0e3)
    net = model.network
    sband = 0.25 * net.mass_per_length[0] * model.water.gravity * L / EA_S

    def tension(eps, dt):
        X = net.position.copy()
        X[1, 2] = X[0, 2] - L * (1 + eps)
        env = model.env.copy()
        env[K.E_VDT] = dt
        F, M, T = np.zeros((2, 3)), np.zeros((2, 3, 3)), np.zeros(1)
        K.loads(X, np.zeros_like(X), 0.0, *model.element_args(), model.fidx, env, model.cur_depth,
                model.cur_speed, False, model.sea, F, M, T, np.zeros((0, 2 * model.bw + 1)), model.bw, 0.0, 0.0)
        return T[0]

    for f in (-0.5, 0.0, 0.5, 2.0):
        elastic = tension(f * sband, math.inf)
        assert elastic > 0.0
        assert tension(f * sband, 1e12) == pytest.approx(elastic, rel=1e-5)
    assert tension(-1.5 * sband, 1e12) == 0.0
