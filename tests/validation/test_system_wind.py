"""Wind on a body in ``system_dynamic`` (issue 39): ``environment.wind`` on the bodies that give their wind areas
(``bodies.NAME.wind``), with DNV-RP-C205's profile and gusts (:mod:`seacable.wind`).

The spread mooring of ``examples/spread_mooring.yaml`` (a buoy on three chains) with a surge area C A = 2000 m^2 at
10 m: a 20 m/s steady wind (at 10 m the NPD profile is U0 itself) pushes it by 1/2 rho_air U^2 C A = 490 kN.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml
from scipy import integrate

import seacable as sc
from seacable.errors import InputError
from seacable.results import body_pose
from seacable.system.dynamics import body as DB
from seacable.system.dynamics import build_system_fe
from seacable.wind import AIR_DENSITY, npd_spectrum

EXAMPLE = Path(__file__).parents[2] / "examples" / "spread_mooring.yaml"
AREA, U0 = 2000.0, 20.0
FORCE = 0.5 * AIR_DENSITY * U0 ** 2 * AREA


def _case(tmp_path, wind, *, external=(0.0,) * 6, duration=1.0, areas=True, analysis=None) -> Path:
    data = yaml.safe_load(EXAMPLE.read_text())
    body = data["bodies"]["buoy"]
    body["external_force"] = list(external)
    if areas:
        body["wind"] = {"height": 10.0, "surge": [AREA], "sway": [0.0], "yaw": [0.0]}
    data["environment"]["wind"] = wind
    data["analysis"] = analysis or {"type": "system_dynamic", "duration": duration, "time_step": 0.1,
                                    "output_interval": 0.5, "n_elements": 10}
    path = tmp_path / "windy.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    return path


def test_a_steady_wind_pushes_the_body_as_its_force_by_hand(tmp_path):
    """The static start of the run under the wind is the one under the same force given as external_force (the
    same FE statics: to its tolerance), and the wind is the kernel's (its velocity at the centre of pressure,
    its table in the body's row), not a linearised damping."""
    windy = sc.run(sc.load_case(_case(tmp_path, {"speed": U0, "spectrum": "none"})))
    pushed = sc.run(sc.load_case(_case(tmp_path, None, external=(FORCE, 0, 0, 0, 0, 0), areas=False)))
    x_wind, x_force = (float(body_pose(ds)[0, 0, 0]) for ds in (windy, pushed))
    assert x_force > 1.0  # 490 kN moves the buoy by metres
    assert x_wind == pytest.approx(x_force, rel=1e-6)
    case = sc.load_case(_case(tmp_path, {"speed": U0, "spectrum": "none"}))
    fe = build_system_fe(case.system(), case.environment, case.analysis)
    still = build_system_fe(case.system(), case.environment.model_copy(update={"wind": None}), case.analysis)
    np.testing.assert_array_equal(fe.blin, still.blin)  # the relative wind is in the force law, not in blin
    np.testing.assert_allclose(fe.ext_f[0, :fe.ext_n[0], 6:], [[U0, 0.0]] * int(fe.ext_n[0]))
    assert fe.bpar[0, DB.B_NWIND] == 1 and still.bpar[0, DB.B_NWIND] == 0  # no wind: the table idle


def test_the_static_analysis_takes_the_mean_wind(tmp_path):
    """system_static with the wind (the finite-element statics, the force at the body's heading) is the
    equilibrium under the same force given by hand (the same FE statics: to its tolerance)."""
    static = {"type": "system_static"}
    windy = sc.run(sc.load_case(_case(tmp_path, {"speed": U0, "spectrum": "npd"}, analysis=static)))
    pushed = sc.run(sc.load_case(_case(tmp_path, None, external=(FORCE, 0, 0, 0, 0, 0), areas=False,
                                       analysis={**static, "statics": "finite_element"})))
    x_wind, x_force = (float(ds["body_x"].values[0, 0]) for ds in (windy, pushed))
    assert x_force > 1.0
    assert x_wind == pytest.approx(x_force, rel=1e-6)
    with pytest.raises(InputError, match=r"a wind of 20 m/s is not supported by the catenary system statics"):
        sc.run(sc.load_case(_case(tmp_path, {"speed": U0}, analysis={**static, "statics": "catenary"})))


def test_gusts_are_the_spectrums(tmp_path):
    """An hour of NPD gusts at 10 m, as the body's wind velocity series: its variance is the spectrum's within 8 %
    (an hour's record: about 5 % on its variance, measured for 3 h in tests/unit/test_wind.py), its mean U0 (the
    gusts' sum of cosines has no mean: within 1 %), along the wind's heading."""
    case = sc.load_case(_case(tmp_path, {"speed": U0, "spectrum": "npd", "seed": 3}, duration=3600.0))
    fe = build_system_fe(case.system(), case.environment, case.analysis)
    u = fe.ext_f[0, :fe.ext_n[0], 6]
    variance = integrate.quad(lambda x: npd_spectrum(x, U0, 10.0), 1e-3, 0.5, limit=200)[0]
    assert u.var() == pytest.approx(variance, rel=0.08)
    assert u.mean() == pytest.approx(U0, rel=0.01)
    assert np.all(fe.ext_f[0, :fe.ext_n[0], :6] == 0.0) and np.all(fe.ext_f[0, :fe.ext_n[0], 7] == 0.0)


@pytest.mark.parametrize("kwargs, message", [
    ({"areas": False}, r"environment.wind is given, but no free body gives its wind areas"),
])
def test_a_wind_nothing_takes_is_refused(tmp_path, kwargs, message):
    with pytest.raises(InputError, match=message):
        sc.check(sc.load_case(_case(tmp_path, {"speed": U0}, **kwargs)))
