"""The OC3-Hywind RAOs of the storm demo (examples/oc3_hywind_raos.py): the slender-body model's limits and the
shipped table being the script's output."""

from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest

from seacable.raos import read_rao_csv

EXAMPLES = Path(__file__).parents[2] / "examples"


def _model():
    spec = importlib.util.spec_from_file_location("oc3_hywind_raos", EXAMPLES / "oc3_hywind_raos.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_spar_follows_long_waves_in_heave_and_resonates_at_its_heave_period():
    """Waves much longer than the draft: the Froude-Krylov heave force tends to rho g A_wp a, the restoring to
    rho g A_wp: the heave RAO tends to 1 (to (w/w3)^2 = 1e-3 at 0.005 rad/s). At the undamped heave frequency
    w3 = sqrt(rho g A_wp / m33) inertia and restoring cancel: the response is the keel and shoulder pressure
    force rho g (A_keel e^(-120 k) - (A_keel - A_wp) e^(-8 k)) over the damping 2 zeta sqrt(c33 m33) w3, a quarter
    period behind the wave (+i in the e^(-i w t) convention)."""
    m = _model()
    heave = m.raos(np.array([0.005]))[1]
    assert abs(heave[0]) == pytest.approx(1.0, abs=2e-3)
    a_wp, a_keel = math.pi * 6.5**2 / 4, math.pi * 9.4**2 / 4
    m33 = m.MASS + m.RHO * (2 / 3) * math.pi * 4.7**3
    c33 = m.RHO * m.G * a_wp
    w3 = math.sqrt(c33 / m33)
    k = w3 * w3 / m.G
    force = m.RHO * m.G * (a_keel * math.exp(-120 * k) - (a_keel - a_wp) * math.exp(-8 * k))
    expected = 1j * force / (w3 * 2 * m.ZETA * math.sqrt(c33 * m33))
    assert m.raos(np.array([w3]))[1][0] == pytest.approx(expected, rel=1e-9)  # round-off of the 1x1 solve


def test_the_shipped_table_is_the_scripts_output(tmp_path):
    """examples/oc3_hywind_raos.csv is what the script writes (so the demo's RAOs are reproducible)."""
    m = _model()
    m.write(tmp_path / "raos.csv")
    assert (tmp_path / "raos.csv").read_text() == (EXAMPLES / "oc3_hywind_raos.csv").read_text()
    table = read_rao_csv(EXAMPLES / "oc3_hywind_raos.csv")
    assert table.values.shape == (6, 12, 60)
    # axisymmetric: waves towards 90 deg sway the spar as waves towards 0 surge it
    np.testing.assert_allclose(table.values[1, 3], table.values[0, 0], rtol=1e-5, atol=1e-9)
