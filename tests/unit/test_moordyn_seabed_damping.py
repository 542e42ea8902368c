"""MoorDyn's seabed law on a MoorDyn deck: ``(kBot pen - cBot v_z) d l`` on a penetrating node.

MoorDyn v2 (``source/Line.cpp``, ``Line::getStateDeriv``) gives a line node below the seabed the vertical
force ``B_z = ((depth - z) kBot - v_z cBot) d l`` with ``l`` half the unstretched lengths of the node's two
segments: the damper acts with the whole ``cBot`` as soon as the node penetrates. seacable's own contact
(YAML cases) lets the damper engage gradually, as ``q / (q + b)`` of the rounded penetration ``q`` (``b``
the spring's rounding band, half a resting node's static penetration), i.e. two thirds of ``cBot`` at rest;
a MoorDyn deck sets ``Water.full_seabed_damping`` and follows MoorDyn's law wherever the spring is linear
(``pen >= b``). The force is isolated as the difference between the deck's model and the same model
without a seabed spring (``kBot = 0``: no contact), at the same positions and velocities (drag, weight
and tensions cancel exactly).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from seacable.mooring import kernel as K
from seacable.mooring.moordyn import moordyn_model
from seacable.mooring.solver import MooringModel

KBOT, CBOT, DIAM, SEG = 1.0e5, 1.0e4, 0.252, 10.0  # [Pa/m], [Pa s/m], [m], [m]: the WD0050 chain deck's

DECK = f"""--------------------- MoorDyn Input File ------------------------------------
a chain lying on the seabed
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      {DIAM}   390        1.674e9    -1.0        0          1.37   1.0    0.64    0.0
---------------------- POINT PROPERTIES --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     0.0     0.0     -50.0   0      0       0      0
2     Vessel    {2 * SEG}    0.0     -50.0   0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        2         {2 * SEG}      2       -
---------------------- OPTIONS -----------------------------------------
{KBOT}                kBot                 bottom stiffness (Pa/m)
{CBOT}                cBot                 bottom damping (Pa-s/m)
1025.0               WtrDnsty             water density (kg/m^3)
50                   WtrDpth              water depth (m)
0.5                  FrictionCoefficient  bottom friction coefficient (-)
------------------------- need this line --------------------------------------
"""


@pytest.fixture(scope="module")
def models(tmp_path_factory):
    path = tmp_path_factory.mktemp("bed") / "bed.txt"
    path.write_text(DECK)
    model = moordyn_model(path)
    bare = MooringModel(model.network, replace(model.water, seabed_stiffness=0.0))
    return model, bare


def _bed_force(models, pen, vz):
    """Force of the seabed on the middle node [N], pressed ``pen`` [m] into it, moving at ``vz`` [m/s]."""
    model, bare = models
    mid = model.network.line_nodes[0][1]
    X = model.network.position.copy()
    X[mid] = (SEG, 0.0, -50.0 - pen)
    V = np.zeros_like(X)
    V[mid, 2] = vz
    A = np.zeros_like(X)
    return model.evaluate(X, V, A)[0][mid] - bare.evaluate(X, V, A)[0][mid]


def test_the_deck_sets_moordyns_rule(models):
    assert models[0].water.full_seabed_damping
    assert models[0].env[K.E_BEDFULL] == 1.0


@pytest.mark.parametrize("times_band", [2.0, 5.0])  # a resting node's static penetration (2 b), and deeper
@pytest.mark.parametrize("vz", [-0.4, 0.3])  # landing, lifting off [m/s]
def test_a_penetrating_node_gets_moordyns_seabed_force(models, times_band, vz):
    """``F_z = (kBot pen - cBot v_z) d l``, l = 10 m (two half segments), exactly: the same sums of the
    same terms, so 1e-9 relative is rounding only. No horizontal velocity: no friction, F_x = F_y = 0.
    The old (YAML) ramp gives ``cBot q / (q + b)`` instead: 2/3 of the damper at 2 b, 5/6 at 5 b, which
    this bound sees (the damper term is 3-30 % of the force here)."""
    band = models[0].env[K.E_BEDRAMP]
    pen = times_band * band
    f = _bed_force(models, pen, vz)
    expected = (KBOT * pen - CBOT * vz) * DIAM * SEG
    assert f[2] == pytest.approx(expected, rel=1e-9)
    assert f[0] == f[1] == 0.0
