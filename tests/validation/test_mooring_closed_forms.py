"""The mooring model's damping, seabed friction, sloped seabed and platform motion against closed forms.

Each case isolates one term of the truss model (paper 004 with MoorDyn's damping and seabed) where the
answer is known without the model: a damped one-degree-of-freedom oscillator, Coulomb's law for a line
dragged along the seabed, the multi-segment catenary on a slope, and quasi-static fairlead tensions
under a slow rigid-body platform motion.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.signal import find_peaks

import seacable as sc
from seacable.mooring.motion import PlatformMotion
from seacable.mooring.network import network_from_line
from seacable.mooring.solver import MooringModel, Water, simulate, static_equilibrium

RHO, G = 1025.0, 9.81
CHAIN = sc.LineType(diameter=0.09, mass_per_length=77.7066, weight_in_water=698.094, axial_stiffness=384.243e6,
                    drag_tangential=0.0)


@pytest.mark.parametrize("damping", [{"damping_ratio": 0.5}, {"stiffness_proportional": 0.01}, {"rayleigh": 0.1}])
def test_axial_damping_decays_a_hanging_mass_at_the_closed_form_rate(damping):
    """A 10 t mass on a 100 m wire (EA 1e7 N, one element) bouncing axially: a damped oscillator.

    Stiffness k = EA / L, mass M = 10 t plus half the wire; the element damper c (dl/dt) / L
    (MoorDyn's zeta L sqrt(EA m), or Rayleigh's beta EA) and the mass-proportional alpha M give
    zeta = (c / L) / (2 sqrt(k M)) and zeta = alpha / (2 omega) respectively.
    """
    wire = sc.LineType(diameter=0.01, mass_per_length=1.0, axial_stiffness=1e7, drag_normal=0.0,
                       added_mass_normal=0.0)
    mass, length = 1e4, 100.0
    line = sc.Line(segments=(sc.Segment(line_type=wire, length=length),),
                   attachments=(sc.PointMass(s=length, mass=mass),))
    alpha = damping.pop("rayleigh", 0.0)
    net = network_from_line(line, (0, 0, -10), (0, 0, -10 - length), water_density=RHO, gravity=G, n_elements=1,
                            end_b="free", **damping)
    model = MooringModel(net, Water(depth=1000.0, density=RHO, gravity=G, rayleigh_mass=alpha))
    eq = static_equilibrium(model).position
    k, m = 1e7 / length, mass + 0.5 * length * 1.0
    omega = math.sqrt(k / m)
    zeta = net.axial_damping[0] / length / (2 * math.sqrt(k * m)) + alpha / (2 * omega)
    x0 = eq.copy()
    x0[-1, 2] -= 0.3  # 0.3 m below equilibrium: the wire stays taut (static stretch 0.98 m)
    period = 2 * math.pi / omega
    run = simulate(model, None, 10 * period, period / 200, period / 200, initial=x0)
    z = run.position[:, -1, 2] - eq[-1, 2]
    peaks, _ = find_peaks(-z)
    amplitude = -z[peaks]
    delta = np.mean(np.log(amplitude[:-1] / amplitude[1:]))
    observed = delta / math.sqrt(4 * math.pi**2 + delta**2)
    assert 0.01 < zeta < 0.05
    # sampling the peaks at T/200 misses each by at most 1 - cos(pi/200) = 1.2e-4 of the amplitude and
    # Newmark's period error is (omega dt)^2 / 12 = 8e-5: on a log decrement of 0.1-0.3 that is < 3e-3
    assert observed == pytest.approx(zeta, rel=5e-3)


def test_a_line_dragged_along_the_seabed_pulls_with_coulomb_friction():
    """200 m of chain lying on a flat seabed, its end B pulled along the line at 0.5 m/s.

    Once sliding at constant speed, the pull is mu times the weight of the free part of the line
    (all nodes but the pulled one): mu w (L - h / 2), h the element length.
    """
    mu, length, n = 0.6, 200.0, 20
    line = sc.Line.single(CHAIN, length)
    depth = 100.0
    # MoorDyn's usual axial damping (zeta 0.8 of each element's axial mode) settles the axial waves that
    # the start of sliding sends along the chain
    net = network_from_line(line, (0, 0, -depth), (length, 0, -depth), water_density=RHO, gravity=G,
                            n_elements=n, damping_ratio=0.8)
    kind = net.kind.copy()
    kind[0] = 0  # end A free too: the whole line slides
    net = net.replace(kind=kind)
    water = Water(depth=depth, density=RHO, gravity=G, friction=mu, friction_velocity=1e-3)
    model = MooringModel(net, water)
    speed, ramp = 0.5, 2.0

    def motion(times):
        t = np.asarray(times, float)
        # constant acceleration over the ramp, then constant speed
        x = np.where(t < ramp, 0.5 * speed / ramp * t**2, speed * (t - 0.5 * ramp))
        v = np.minimum(t, ramp) * speed / ramp
        a = np.where(t < ramp, speed / ramp, 0.0)
        pos = np.zeros((t.size, 1, 3))
        pos[:, 0, 0], pos[:, 0, 2] = length + x, -depth
        vel, acc = np.zeros_like(pos), np.zeros_like(pos)
        vel[:, 0, 0], acc[:, 0, 0] = v, a
        return pos, vel, acc

    run = simulate(model, motion, 20.0, 0.05, 0.5)
    pull = run.tension[run.time > 10.0, -1]
    expected = mu * 698.094 * (length - 0.5 * length / n)
    # the regularisation v / sqrt(v^2 + vf^2) costs 2e-6 at 0.5 m/s; the chain's axial waves
    # (a few hundredths of a second to cross 200 m) and the seabed spring settle well before t = 10 s
    # (at a speed 1/10 of the chain's axial wave speed the stretch is steady): 0.5 %
    assert pull == pytest.approx(np.full(pull.shape, expected), rel=5e-3)
    # and without friction nothing holds the line back but its tiny tangential added mass: no pull
    frictionless = MooringModel(net, Water(depth=depth, density=RHO, gravity=G))
    free_run = simulate(frictionless, motion, 20.0, 0.05, 0.5)
    assert np.max(free_run.tension[free_run.time > 10.0, -1]) < 1e-3 * expected


def _catenary_on_slope(length, w, ea, span, rise, slope):
    """Elastic catenary from an anchor on a frictionless seabed rising at ``slope``: (H, grounded length).

    The grounded part lies along the slope, its tension falling by w sin(slope) per metre towards the
    anchor; the suspended part leaves the seabed tangentially (V = H tan(slope) there) and is Irvine's
    elastic catenary up to the fairlead (``span``, ``rise`` from the anchor).
    """
    from scipy.optimize import fsolve

    c, s_ = math.cos(slope), math.sin(slope)

    def gaps(u):
        h, lg = math.exp(u[0]), u[1]
        ls = length - lg
        v0, v1 = h * math.tan(slope), h * math.tan(slope) + w * ls
        xs = h / w * (math.asinh(v1 / h) - math.asinh(v0 / h)) + h * ls / ea
        zs = h / w * (math.hypot(1, v1 / h) - math.hypot(1, v0 / h)) + (v1**2 - v0**2) / (2 * w * ea)
        stretched = lg + (h / c * lg - 0.5 * w * s_ * lg**2) / ea
        return [(xs + stretched * c - span) / span, (zs + stretched * s_ - rise) / span]

    u = fsolve(gaps, [math.log(w * 100.0), 0.3 * length], xtol=1e-13)
    assert max(abs(g) for g in gaps(u)) < 1e-10
    return math.exp(u[0]), u[1]


def test_static_line_on_a_sloped_seabed_is_the_catenary_on_the_slope():
    """A chain from an anchor on a 5 degree up-slope, frictionless seabed: FE statics against the closed form."""
    slope = math.radians(5.0)
    depth, length, n = 200.0, 600.0, 120
    anchor, fairlead = (0.0, 0.0, -depth), (560.0, 0.0, -20.0)
    w, ea = 698.094, 384.243e6
    net = network_from_line(sc.Line.single(CHAIN, length), anchor, fairlead, water_density=RHO, gravity=G,
                            n_elements=n)
    water = Water(depth=depth, density=RHO, gravity=G, slope=slope, seabed_stiffness=3e9)
    st = static_equilibrium(MooringModel(net, water))
    h, grounded = _catenary_on_slope(length, w, ea, fairlead[0] - anchor[0], fairlead[2] - anchor[2], slope)
    assert 0.1 * length < grounded < 0.9 * length  # a real touchdown on the slope
    ls, half = length - grounded, 0.5 * length / n
    # the end elements carry the tension at their middles: half an element's weight below the fairlead,
    # and half an element's weight along the slope above the anchor
    top = math.hypot(h, h * math.tan(slope) + w * (ls - half))
    bottom = h / math.cos(slope) - w * math.sin(slope) * (grounded - half)
    # what is left is the lumping of the weight at nodes (O(h^2)) and the seabed spring of 3e9 Pa/m
    # sinking the chain by w / (k d) = 2.6e-6 m: 0.05 %
    assert st.tension[-1] == pytest.approx(top, rel=5e-4)
    assert st.tension[0] == pytest.approx(bottom, rel=5e-4)
    # the touchdown point: the last node on the slope (within 1 mm), to one element
    bed = -depth + math.tan(slope) * st.position[:, 0]
    on_bed = net.arc_length[np.abs(st.position[:, 2] - bed) < 1e-3].max()
    assert on_bed == pytest.approx(grounded, abs=length / n)


SPREAD = """--------------------- MoorDyn Input File ------------------------------------
three chains from a platform, 120 degrees apart
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.09    77.7066    384.243e6  -0.8        0          1.6    1.0    0.1     0.0
---------------------- POINTS ----------------------------------------
ID    Attachment  X        Y         Z       Mass   Volume  CdA    Ca
(#)   (-)         (m)      (m)       (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed       853.87   0         -320    0      0       0      0
2     Fixed       -426.935 739.474   -320    0      0       0      0
3     Fixed       -426.935 -739.474  -320    0      0       0      0
4     Vessel      5.2      0         -70     0      0       0      0
5     Vessel      -2.6     4.5033    -70     0      0       0      0
6     Vessel      -2.6     -4.5033   -70     0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        4         902.2     30      -
2     chain      2        5         902.2     30      -
3     chain      3        6         902.2     30      -
---------------------- OPTIONS -----------------------------------------
320           WtrDpth       water depth (m)
------------------------- need this line --------------------------------------
"""


def test_slow_platform_motion_gives_the_quasi_static_tensions_of_each_fairlead(tmp_path):
    """The OC3-Hywind spread (three lines, one vessel) surged 10 m, swayed 5 m and yawed 0.1 rad
    over 800 s.

    At the motion's extreme (t = 200 s, velocities zero) the lines feel only the tiny inertia of an
    acceleration 10 (2 pi / 800)^2 = 6e-4 m/s^2: each fairlead's tension is the static one with the
    three fairleads moved rigidly with the platform. The surge towards anchor 1 unloads line 1 and loads
    lines 2 and 3; the sway towards anchor 2 makes lines 2 and 3 differ.
    """
    from seacable.mooring.moordyn import moordyn_model, run_moordyn_file

    f = tmp_path / "spread.txt"
    f.write_text(SPREAD)
    motion = PlatformMotion(amplitude=(10.0, 5.0, 0.0, 0.0, 0.0, 0.1), period=800.0, ramp=100.0)
    ds = run_moordyn_file(f, duration=200.0, motion=motion, time_step=1.0, output_interval=10.0)
    model = moordyn_model(f)
    net = model.network
    start = static_equilibrium(model)
    fairleads = net.channel_positions(start.position)
    moved = motion.channels(np.array([200.0]), fairleads)[0][0]
    position = start.position.copy()
    position[net.channel >= 0] = moved[net.channel[net.channel >= 0]]
    static = static_equilibrium(MooringModel(net.replace(position=position), model.water), position)
    # the fairlead tension is the force the fairlead holds (the support reaction at the line's end B)
    expected = np.linalg.norm(static.support[[nodes[-1] for nodes in net.line_nodes]], axis=-1)
    dynamic = ds.fairlead_tension.sel(time=200.0).values
    assert min(expected[1:]) > 1.2 * expected[0] and expected[2] > 1.1 * expected[1]
    # quasi-static: the inertia left, a line's mass times 6e-4 m/s^2 = 42 N, is 6e-5 of the tension, and the
    # drag of a line lagging its fairlead by a fraction of a second less still; 0.1 % leaves room for them
    assert dynamic == pytest.approx(expected, rel=1e-3)
