"""The generalised-alpha time integration of the mooring model against the scheme's own theory.

Sources
-------
- Chung, J. and Hulbert, G. M. (1993). A time integration algorithm for structural dynamics with
  improved numerical dissipation: the generalized-alpha method. J. Appl. Mech. 60, 371-375: the
  parameters of a spectral radius at infinity rho_inf, alpha_m = (2 rho_inf - 1) / (rho_inf + 1),
  alpha_f = rho_inf / (rho_inf + 1), gamma = 1/2 - alpha_m + alpha_f, beta = (1 - alpha_m + alpha_f)^2 / 4;
  second-order accuracy; the amplification matrix of the undamped oscillator, whose spectral radius
  tends to rho_inf as omega dt grows.
- Hughes, T. J. R. (2000). The Finite Element Method, Dover, ch. 9.1: average acceleration (rho_inf = 1)
  conserves the energy of a linear undamped system.

The single-degree-of-freedom oscillator is one truss element in vacuum (no drag, no added mass, no
seabed) hanging from a fixed node, a point mass at its free end moving along the element: while taut
its equation is exactly linear, ``m x'' + (EA / L) x = 0`` about the static stretch, so the model's
steps must be the scheme's amplification matrix applied to the start, to the Newton tolerance.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import seacable as sc
from seacable.errors import InputError
from seacable.mooring.motion import HarmonicMotion
from seacable.mooring.network import network_from_line
from seacable.mooring.solver import MooringModel, Water, generalized_alpha, simulate, static_equilibrium

G = 9.80665
EA, LENGTH, MASS, WIRE = 1e7, 100.0, 1e4, 1.0  # [N], [m], [kg], [kg/m]
K_AXIAL = EA / LENGTH
M_NODE = MASS + 0.5 * WIRE * LENGTH  # the point mass and half the wire's
OMEGA = math.sqrt(K_AXIAL / M_NODE)  # 3.154 rad/s
X0 = 0.3  # start 0.3 m below the static position (static stretch W L / EA = 0.98 m: taut throughout)


def _scheme(rho):
    """Chung and Hulbert's parameters, written out here (not the model's function)."""
    am = (2 * rho - 1) / (rho + 1)
    af = rho / (rho + 1)
    gamma = 0.5 - am + af
    beta = 0.25 * (1 - am + af) ** 2
    return am, af, beta, gamma


def _amplification(omega_dt, rho):
    """The generalised-alpha amplification matrix of ``x'' + omega^2 x = 0`` on the state
    (x, dt v, dt^2 a): Newmark's updates and the equilibrium
    ``(1 - am) a1 + am a0 + omega^2 ((1 - af) x1 + af x0) = 0`` (Chung and Hulbert eqs. 2-5)."""
    am, af, beta, gamma = _scheme(rho)
    w2 = omega_dt**2
    A = np.zeros((3, 3))
    for j, (x0, v0, a0) in enumerate(np.eye(3)):
        a1 = -(am * a0 + w2 * x0 + w2 * (1 - af) * (v0 + (0.5 - beta) * a0)) / ((1 - am) + w2 * (1 - af) * beta)
        A[:, j] = x0 + v0 + (0.5 - beta) * a0 + beta * a1, v0 + (1 - gamma) * a0 + gamma * a1, a1
    return A


@pytest.fixture(scope="module")
def oscillator():
    wire = sc.LineType(diameter=0.01, mass_per_length=WIRE, axial_stiffness=EA, drag_normal=0.0,
                       drag_tangential=0.0, added_mass_normal=0.0, added_mass_tangential=0.0)
    line = sc.Line(segments=(sc.Segment(line_type=wire, length=LENGTH),),
                   attachments=(sc.PointMass(s=LENGTH, mass=MASS),))
    net = network_from_line(line, (0, 0, 0.0), (0, 0, -LENGTH), water_density=0.0, gravity=G, n_elements=1,
                            end_b="free")
    model = MooringModel(net, Water(density=0.0, gravity=G, depth=None))
    return model, static_equilibrium(model, tol=1e-12).position


def _run(oscillator, omega_dt, n_steps, rho, x0=X0):
    model, eq = oscillator
    start = eq.copy()
    start[-1, 2] -= x0
    dt = omega_dt / OMEGA
    run = simulate(model, None, n_steps * dt, dt, dt, initial=start, tol=1e-12, spectral_radius=rho)
    # displacement, velocity and acceleration from the static position (z down is negative: flip)
    return run, -(run.position[:, -1, 2] - eq[-1, 2]), -run.velocity[:, -1, 2], -run.acceleration[:, -1, 2]


def test_the_parameters_are_chung_and_hulberts():
    for rho in (0.0, 0.5, 0.8, 0.95):
        assert generalized_alpha(rho) == pytest.approx(_scheme(rho), abs=1e-15)
    # rho_inf = 1 is average acceleration: Chung and Hulbert's alpha_m = alpha_f = 1/2 give the same beta,
    # gamma and (the equilibrium being the mean of the two ends', which holds at the start) the same steps
    assert generalized_alpha(1.0) == (0.0, 0.0, 0.25, 0.5)
    assert _scheme(1.0) == (0.5, 0.5, 0.25, 0.5)


@pytest.mark.parametrize("bad", [1.01, -0.2, math.nan, "high", True])
def test_a_spectral_radius_outside_0_1_is_refused(bad):
    with pytest.raises(InputError, match="spectral_radius"):
        generalized_alpha(bad)


def test_the_case_refuses_a_spectral_radius_above_1():
    case = sc.load_case("examples/oc3_hywind_line.yaml")
    data = case.model_dump(mode="json", exclude_none=True)
    data["analysis"]["spectral_radius"] = 1.5
    with pytest.raises(InputError, match=r"analysis\.spectral_radius must be <= 1, got 1\.5"):
        sc.Case(**data)


@pytest.mark.parametrize("rho", [0.8, 0.5, 0.0])
@pytest.mark.parametrize("omega_dt", [0.5, 10.0, 1000.0])
def test_each_step_is_the_schemes_amplification_matrix(oscillator, omega_dt, rho):
    """The run's (x, dt v, dt^2 a) after n steps equal A(omega dt)^n applied to the start, and the
    roots of the recursion the displacements follow are the eigenvalues of A: the amplification of
    the mode per step is the one the scheme predicts, ``rho(A) -> rho_inf`` as ``omega dt -> inf``."""
    n = 20
    _, x, v, a = _run(oscillator, omega_dt, n, rho)
    dt = omega_dt / OMEGA
    A = _amplification(omega_dt, rho)
    y = np.array([X0, 0.0, -OMEGA**2 * X0 * dt**2])  # the start: at rest, acceleration from equilibrium
    expected = [y]
    for _ in range(n):
        expected.append(A @ expected[-1])
    ours = np.column_stack([x, dt * v, dt**2 * a])
    # each step solves a linear equation to the Newton tolerance 1e-12 of the force scale (the weight,
    # 1e5 N): 1e-7 N, i.e. 1e-12 m at k = 1e5 N/m, plus the round-off of coordinates near 100 m
    # (2e-14 m); 1e-9 of the start's 0.3 m is far above both and far below any scheme error (a wrong
    # gamma changes the third step by 1e-2 of the start)
    assert ours == pytest.approx(np.array(expected), abs=1e-9 * X0 * max(1.0, omega_dt**2))
    # the observed amplification: x_n obeys the characteristic polynomial of A (Cayley-Hamilton);
    # fitting its three coefficients recovers the roots
    rows = np.column_stack([x[2:-1], x[1:-2], x[:-3]])
    coef = np.linalg.lstsq(rows, x[3:], rcond=None)[0]
    observed = np.sort(np.abs(np.roots([1.0, *(-coef)])))
    theory = np.sort(np.abs(np.linalg.eigvals(A)))
    # the fit is exact up to the 1e-12 relative noise of x over 20 steps that decay to rho^20 (1e-2 at
    # rho 0.8; 1e-6 of the start at rho_inf = 0.5 and omega dt = 1000): measured within 3.3e-8 of
    # theory (0.80772122 against 0.80772125 at rho_inf 0.8, omega dt 1000); 1e-6 allows for that noise
    assert observed[-1] == pytest.approx(theory[-1], rel=1e-6)
    if omega_dt >= 1000.0:
        # Chung and Hulbert: rho(A) = rho_inf + O(1 / (omega dt)) (0.8077 at 0.8, 0.508 at 0.5, 0.0101 at 0)
        assert observed[-1] == pytest.approx(rho, abs=0.011)
    if omega_dt <= 0.5:
        # a resolved mode (omega dt 0.5) is hardly damped: 1 - rho(A) < 2e-3 per step for rho_inf >= 0
        assert observed[-1] > 0.98


def test_newton_converges_in_one_iteration_on_a_linear_oscillator(oscillator):
    """The Newton matrix is the exact derivative of the generalised-alpha equilibrium,
    ((1 - alpha_m) / (beta dt^2) M + (1 - alpha_f) (gamma / (beta dt) C + K)) / (1 - alpha_f): on a linear
    system every step converges at its first correction (two residual evaluations a step). A tangent
    with the wrong alpha_f weighting converges linearly, in many more. The start is 1 cm off the static
    position so that the predictor, ``x + dt v + dt^2 a / 2``, about (omega dt)^2 / 2 = 4.5 times the
    amplitude away, keeps the wire taut (stretch 0.98 m): a slack predictor is a nonlinear start."""
    for rho in (1.0, 0.8, 0.3):
        run, *_ = _run(oscillator, 3.0, 20, rho, x0=0.01)
        assert run.steps == 20
        assert run.iterations == 2 * run.steps


def test_average_acceleration_conserves_the_energy_of_a_linear_oscillator(oscillator):
    """rho_inf = 1: 1/2 m v^2 + 1/2 k x^2 is constant at any step (here omega dt = 0.5 and 20), while
    rho_inf = 0.8 loses energy at a rate the scheme's amplification gives."""
    for omega_dt in (0.5, 20.0):
        _, x, v, _ = _run(oscillator, omega_dt, 100, 1.0)
        energy = 0.5 * M_NODE * v**2 + 0.5 * K_AXIAL * x**2
        # the Newton tolerance (1e-7 N on 1e5 N/m: 1e-12 m on 0.3 m) and round-off leave < 1e-9 of it
        assert np.ptp(energy) < 1e-9 * energy[0]
        _, x, v, _ = _run(oscillator, omega_dt, 100, 0.8)
        damped = 0.5 * M_NODE * v**2 + 0.5 * K_AXIAL * x**2
        # 100 steps at the scheme's amplification: energy ~ rho(A)^(2 n), at omega dt 0.5 a loss of
        # 1 - 0.99996^200 = 0.8 %, at 20 a factor 0.9^200; either far beyond the 1e-9 above
        assert damped[-1] < (1 - 1e-3) * damped[0]


@pytest.mark.parametrize("rho", [0.8, 0.5])
def test_generalized_alpha_is_second_order_on_the_oscillator(oscillator, rho):
    """The largest displacement error over three periods against x0 cos(omega t): it falls by 4 per
    halving of the step."""
    err = []
    for n in (40, 80, 160):
        run, x, _, _ = _run(oscillator, 2 * math.pi / n, 3 * n, rho)
        err.append(np.max(np.abs(x - X0 * np.cos(OMEGA * run.time))))
    order = np.log2(np.array(err[:-1]) / np.array(err[1:]))
    # the leading error is the period error, O((omega dt)^2) (the amplitude error is of higher order:
    # measured at the peaks alone the order is 3.9); the next term is (omega dt)^2 = 2.5e-2 to 1.5e-3
    # of it at 40-160 steps a period: orders within 2 +- 0.05
    assert order == pytest.approx([2.0, 2.0], abs=0.05)


@pytest.fixture(scope="module")
def moved_chain():
    """A 10 m chain (1 kg/m, EA 1e4 N, 10 elements) hanging in water between (0, -10) and (8, -5) m, its
    upper end moved on an ellipse (0.5 m surge, 0.3 m heave at 2 s, 1 s ramp): drag, added mass and
    geometric nonlinearity, no seabed. Its axial modes (up to about 200 rad/s) are resolved at the steps
    below (omega dt <= 0.5)."""
    line_type = sc.LineType(diameter=0.02, mass_per_length=1.0, axial_stiffness=1e4, drag_normal=1.2,
                            drag_tangential=0.2, added_mass_normal=1.0)
    net = network_from_line(sc.Line.single(line_type, 10.0), (0, 0, -10.0), (8.0, 0, -5.0), water_density=1025.0,
                            gravity=G, n_elements=10)
    model = MooringModel(net, Water(density=1025.0, gravity=G, depth=None))
    start = static_equilibrium(model).position
    motion = HarmonicMotion(amplitude=(0.5, 0.0, 0.3), period=2.0, ramp=1.0)
    base = net.channel_positions(start)
    return model, start, lambda t: motion.channels(t, base)


def test_generalized_alpha_is_second_order_on_a_moved_chain(moved_chain):
    """rho_inf = 0.8: node positions at t = 2 s against a run at dt = 1/25600 s. Measured errors
    9.4e-4, 2.3e-4, 6.0e-5 m at dt = 1/400, 1/800, 1/1600 s: orders 2.03 and 1.95 (the reference's own
    error, 1/256 of the last, shifts the last order by < 0.01). Coarser steps are pre-asymptotic (the
    axial modes at omega dt ~ 1-2: order 1.86 from 1/200 s). [1.8, 2.2] is the band for order 2."""
    model, start, motion = moved_chain

    def at_two_seconds(n):
        return simulate(model, motion, 2.0, 1.0 / n, 2.0, initial=start, tol=1e-10, spectral_radius=0.8).position[-1]

    ref = at_two_seconds(25600)
    err = np.array([np.linalg.norm(at_two_seconds(n) - ref) for n in (400, 800, 1600)])
    order = np.log2(err[:-1] / err[1:])
    assert np.all((order > 1.8) & (order < 2.2)), order


def test_chung_and_hulberts_rho_1_is_average_acceleration(moved_chain, monkeypatch):
    """Chung and Hulbert's parameters for rho_inf = 1, alpha_m = alpha_f = 1/2 (the equilibrium at mid-step,
    inertia and forces interpolated), run through the generalised-alpha path of the kernel, give the
    average-acceleration run that rho_inf = 1 selects (the equilibrium at the step's end) on this nonlinear
    chain: the mid-step equilibrium is the mean of the two ends', and the start's holds. Measured: the
    positions agree to 3.0e-9 m over 2 s (the Newton tolerance, 1e-10 of the force scale, carried by the
    scheme's spurious root -1); rho_inf = 0.8 moves them by 3.6e-5 m. 1e-7 m separates the two."""
    from seacable.mooring import solver

    model, start, motion = moved_chain
    newmark = simulate(model, motion, 2.0, 1 / 400, 0.05, initial=start, tol=1e-10)
    assert newmark.spectral_radius == 1.0
    monkeypatch.setattr(solver, "generalized_alpha", lambda rho: (0.5, 0.5, 0.25, 0.5))
    midpoint = simulate(model, motion, 2.0, 1 / 400, 0.05, initial=start, tol=1e-10)
    monkeypatch.undo()
    damped = simulate(model, motion, 2.0, 1 / 400, 0.05, initial=start, tol=1e-10, spectral_radius=0.8)
    assert np.abs(midpoint.position - newmark.position).max() < 1e-7
    assert np.abs(damped.position - newmark.position).max() > 1e-5


ONE_LINE = """--------------------- MoorDyn Input File ------------------------------------
one chain from an anchor to a vessel point
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.1     60         5e8        -0.5        0          1.2    1.0    0.2     0.0
---------------------- POINTS ----------------------------------------
ID    Attachment  X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)         (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed       -300    0       -100    0      0       0      0
2     Vessel      0       0       -20     0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        2         320       16      -
---------------------- OPTIONS -----------------------------------------
300           WtrDpth       water depth (m)
------------------------- need this line --------------------------------------
"""


def test_the_case_and_a_moordyn_deck_run_with_their_spectral_radius(tmp_path):
    """``analysis.spectral_radius`` and a deck's ``spectral_radius`` reach the time loop (the tensions
    change with it) and are recorded in the result's settings; the default stays average acceleration."""
    import json

    from seacable.io.moordyn import load_moordyn_case
    from seacable.mooring.moordyn import run_moordyn_file

    data = sc.load_case("examples/oc3_hywind_line.yaml").model_dump(mode="json", exclude_none=True)
    data["analysis"].update(duration=2.0, time_step=0.1, output_interval=0.5)
    plain = sc.run(sc.Case(**data))
    data["analysis"]["spectral_radius"] = 0.5
    damped = sc.run(sc.Case(**data))
    assert json.loads(plain.attrs["settings"])["spectral_radius"] == 1.0
    assert json.loads(damped.attrs["settings"])["spectral_radius"] == 0.5
    assert np.abs(damped.fairlead_tension.values - plain.fairlead_tension.values).max() > 1e-6

    deck = tmp_path / "one.txt"
    deck.write_text(ONE_LINE)
    motion = HarmonicMotion(amplitude=(2.0, 0.0, 1.0), period=5.0)
    runs = {rho: run_moordyn_file(deck, duration=2.0, time_step=0.05, output_interval=0.5, motion=motion,
                                  spectral_radius=rho) for rho in (1.0, 0.5)}
    assert [json.loads(ds.attrs["settings"])["spectral_radius"] for ds in runs.values()] == [1.0, 0.5]
    assert np.abs(runs[1.0].fairlead_tension.values - runs[0.5].fairlead_tension.values).max() > 1e-6
    assert load_moordyn_case(deck).spectral_radius == 1.0
    with pytest.raises(InputError, match=r"spectral radius must be in \[0, 1\], got 1\.5"):
        load_moordyn_case(deck).with_run(duration=1.0, spectral_radius=1.5)
