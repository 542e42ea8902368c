"""A lazy-wave cable in a current that reaches the seabed (issue 40): the statics' friction holds its grounded part.

``examples/lazy_wave_80m.yaml`` (Lozon et al. 2025's 80 m lazy wave) in a uniform 1 m/s current from its hang-off
towards its seabed end: the current pushes the lazy wave towards the anchor and its grounded part along itself.
Frictionless, nothing holds the grounded part: no static equilibrium, and the message says why and what to give. With
the seabed's friction (0.5) the statics converge from the as-laid state, the grounded cable carrying the push in
compression (``compression: true``, as a cable with bending stiffness does; tension-only elements pass no push on,
and the message says so), held by its friction.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.errors import ConvergenceError

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "lazy_wave_80m.yaml"


def _case(friction, compression=True, speed=1.0):
    data = yaml.safe_load(EXAMPLE.read_text())
    data["environment"]["current"] = {"speed": speed, "heading": math.pi}
    data["environment"]["seabed"] = {"friction": friction}
    data["analysis"]["compression"] = compression
    return sc.Case.parse(data)


def test_frictionless_the_lazy_wave_in_a_current_to_its_anchor_has_no_equilibrium_and_says_so():
    with pytest.raises(ConvergenceError, match=r"the current's drag, 25.76 N/m \(1 m/s at the seabed\), and the statics "
                                               r"have no friction to hold it.*Suggested fix: give the seabed its "
                                               r"friction coefficient"):
        sc.run(_case(0.0))


def test_tension_only_elements_cannot_pass_the_push_on_and_the_message_says_so():
    with pytest.raises(ConvergenceError, match=r"pushed along itself towards its anchor.*carry no compression"
                                               r".*'compression: true'"):
        sc.run(_case(0.5, compression=False))


def test_with_friction_the_lazy_wave_converges_its_grounded_part_held_by_coulomb_friction():
    """Friction 0.5 (``mu w`` 79 N/m for the cable's 158 N/m in water): the statics converge; the cable still lies on
    the seabed from its anchor (the current moves the lazy wave 25-30 m towards it, and the touchdown with it); the
    grounded part is in compression (the push), which its friction takes out along it at no more than ``mu w`` per
    metre (Coulomb's bound, with the current's axial drag, 1 N/m here: between any two grounded nodes the
    compression changes from the grounded run's end to the anchor by at most ``(mu w + q_t)`` times its length: locally
    the buckled cable's bending shear moves axial force about, not in the whole); the anchor takes less than the
    largest push; and near the anchor the cable has hardly moved (under 0.1 m within 5 m of it, against the lazy
    wave's 25 m)."""
    still = sc.run(_case(0.5, speed=0.0))  # no current: the as-laid state
    ds = sc.run(_case(0.5))
    s, z, T = ds.s.values, ds.z.values, ds.tension.values
    grounded = np.flatnonzero(z < -79.99)
    assert grounded[0] == 0 and grounded.size > 20
    run = grounded[: np.argmax(np.diff(grounded) > 1)] if np.any(np.diff(grounded) > 1) else grounded
    moved = np.hypot(ds.x.values - still.x.values, ds.y.values - still.y.values)
    assert moved[s < 5.0].max() < 0.1 and moved.max() > 20.0
    w = 36.70 * 9.81 - 1025.0 * 9.81 * math.pi / 4 * 0.16**2
    assert float(np.min(T[run])) < -0.1 * 0.5 * w * s[run[-1]]  # a push the friction holds
    # the anchor takes the push less what the grounded cable's friction holds, at most mu w + q_t per metre
    assert abs(T[run[-1]] - T[0]) <= (0.5 * w + 1.0) * s[run[-1]]
    assert 0.0 < -T[0] < -float(np.min(T[run]))  # the anchor pushed, by less than the largest push
