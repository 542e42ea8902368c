"""A body's RAOs from its database (issue 39): the long-wave limits a floating body must reach, and the RAO table
seacable's vessel motions read."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from seacable.errors import InputError
from seacable.hydro import frequency_response, read_wamit
from seacable.hydro.response import coefficients_at, natural_periods, raos

ROOT = Path(__file__).parents[2] / "data" / "volturnus" / "IEA-15-240-RWT-UMaineSemi"
MASS = 1025.0 * 20206.34889


@pytest.fixture(scope="module")
def db():
    return read_wamit(ROOT)


def test_in_long_waves_a_free_body_heaves_with_the_surface(db):
    """At 0.05 rad/s (a 3.9 km wave on a 100 m platform) the heave RAO of the freely floating body is 1 and in
    phase (the excitation is rho g A_wp, the hydrostatic stiffness's, and the inertia is (w / w_n)^2 = 1.3 % of
    it at w_n = 0.30 rad/s): |H33 - 1| below 2 %."""
    mass = np.diag([MASS, MASS, MASS, 1.2507e10, 1.2507e10, 2.3667e10])
    stiffness = db.hydrostatics.copy()
    stiffness[0, 0] = stiffness[1, 1] = 8e4
    stiffness[5, 5] = 2e8
    table = raos(db, mass, stiffness)
    h = table.values[2, table.heading.tolist().index(0.0), 0]
    assert abs(h - 1.0) < 0.02, h
    # the table is the frequency response at each of its frequencies and headings
    f, b = 4, 20
    a, bb = coefficients_at(db, table.omega[f])
    ref = frequency_response(mass, a[0], bb[0], stiffness, db.excitation[b, f], table.omega[f])
    np.testing.assert_allclose(table.values[:, b, f], ref, rtol=1e-12)


def test_coefficients_below_the_first_frequency_go_to_the_zero_frequency_limit(db):
    a, b = coefficients_at(db, [0.0, 0.5 * db.omega[0], db.omega[0]])
    np.testing.assert_allclose(a[0], db.added_mass_zero, rtol=1e-14)
    np.testing.assert_allclose(b[0], 0.0)
    np.testing.assert_allclose(a[1], 0.5 * (db.added_mass_zero + db.added_mass[0]), rtol=1e-12)
    np.testing.assert_allclose(b[2], db.damping[0], rtol=1e-14)
    with pytest.raises(InputError, match=r"asked for at 6 rad/s, outside 0-5 rad/s"):
        coefficients_at(db, 6.0)


def test_natural_periods_use_the_added_mass_at_their_own_frequency(db):
    """Heave: 2 pi sqrt((M + A33(w_n)) / C33) at the converged w_n; a DOF without restoring has none."""
    mass = np.diag([MASS] * 3 + [1.2507e10, 1.2507e10, 2.3667e10])
    periods = natural_periods(db, mass, db.hydrostatics)
    w = 2 * math.pi / periods[2]
    a33 = coefficients_at(db, w)[0][0, 2, 2]
    assert periods[2] == pytest.approx(2 * math.pi * math.sqrt((MASS + a33) / db.hydrostatics[2, 2]), rel=1e-9)
    assert math.isinf(periods[0]) and math.isinf(periods[5])


def test_a_body_without_restoring_or_inertia_is_refused(db):
    with pytest.raises(InputError, match=r"mass must be a finite 6x6 matrix"):
        raos(db, np.eye(2), np.eye(6))
