"""The combined low- and wave-frequency tension (issue 39): API RP 2SK's and DNV-OS-E301's combinations, the
split of a record into its parts, and which parts a run's case modelled."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.design.combination import (
    api_combined_tension,
    dnv_combined_tension,
    modelled_components,
    most_probable_maximum,
    split_tension,
)
from seacable.errors import InputError


def test_api_rp_2sk_combination_is_the_larger_of_its_two_sums():
    """T_mean 1 MN, sigma_LF 100 kN at 100 s, sigma_WF 50 kN at 10 s, 3 h: T_lf,max = 1e5 sqrt(2 ln 108) =
    306.0 kN, T_wf,max = 5e4 sqrt(2 ln 1080) = 186.9 kN; the sums 306.0 + 100 and 200 + 186.9: T_max = 1406.0 kN,
    the first. A given LF maximum replaces the Rayleigh one."""
    got = api_combined_tension(1e6, 1e5, 5e4, 100.0, 10.0, 10800.0)
    lf_max, wf_max = 1e5 * math.sqrt(2 * math.log(108)), 5e4 * math.sqrt(2 * math.log(1080))
    assert got.maximum == pytest.approx(1e6 + max(lf_max + 1e5, 2e5 + wf_max), rel=1e-14)
    assert got.terms["lf_sig"] == 2e5 and got.dynamic == pytest.approx(lf_max + 1e5, rel=1e-14)
    # a WF-dominated line takes the other sum
    wf = api_combined_tension(1e6, 1e4, 2e5, 100.0, 10.0)
    assert wf.maximum == pytest.approx(1e6 + 2e4 + 2e5 * math.sqrt(2 * math.log(1080)), rel=1e-14)
    assert api_combined_tension(1e6, 1e5, 5e4, 100.0, 10.0, lf_max=5e5).maximum == pytest.approx(1e6 + 5e5 + 1e5)


def test_dnv_combination_is_the_maximum_of_the_gaussian_sum():
    """The sum of independent Gaussian parts has sigma^2 = 1e10 + 2.5e9 and up-crossing rate
    sqrt(sigma_lf^2/100^2 + sigma_wf^2/10^2)/sigma = 0.0537 /s; T_c,dyn = sigma sqrt(2 ln(nu 10800)). One part
    alone gives its own Rayleigh maximum (most_probable_maximum)."""
    got = dnv_combined_tension(1e6, 1e5, 5e4, 100.0, 10.0, 10800.0)
    sigma = math.hypot(1e5, 5e4)
    nu = math.sqrt((1e5 / 100) ** 2 + (5e4 / 10) ** 2) / sigma
    assert got.dynamic == pytest.approx(sigma * math.sqrt(2 * math.log(nu * 10800)), rel=1e-14)
    assert got.mean == 1e6 and got.maximum == got.mean + got.dynamic
    assert dnv_combined_tension(0.0, 0.0, 5e4, 100.0, 10.0).dynamic == pytest.approx(
        most_probable_maximum(5e4, 10.0, 10800.0), rel=1e-14)
    with pytest.raises(InputError, match="too few for a most probable maximum"):
        most_probable_maximum(1.0, 100.0, 150.0)


def test_split_tension_recovers_the_parts_of_a_two_tone_record():
    """A mean of 1 MN, a 150 s sine of amplitude 141.4 kN (sigma 100 kN) and a 10 s sine of 70.7 kN (sigma 50
    kN), each a whole number of periods in the 3000 s record: the ideal filter at 30 s returns each part's sigma
    and period to round-off (1e-9), and each part's maximum its amplitude."""
    t = np.arange(0.0, 3000.0, 0.5)
    x = 1e6 + 1e5 * math.sqrt(2) * np.sin(2 * np.pi * t / 150.0) + 5e4 * math.sqrt(2) * np.sin(2 * np.pi * t / 10.0)
    c = split_tension(x, t)
    assert c.mean == pytest.approx(1e6, rel=1e-12)
    assert (c.lf_std, c.wf_std) == pytest.approx((1e5, 5e4), rel=1e-9)
    assert (c.lf_period, c.wf_period) == pytest.approx((150.0, 10.0), rel=1e-9)
    assert (c.lf_max, c.wf_max) == pytest.approx((1e5 * math.sqrt(2), 5e4 * math.sqrt(2)), rel=1e-6)
    with pytest.raises(InputError, match="under two split periods"):
        split_tension(x[:100], t[:100])
    with pytest.raises(InputError, match="equally spaced"):
        split_tension(x[:20], np.r_[t[:10], t[10:20] + 0.1])


def test_modelled_components_say_what_the_oc3_demo_leaves_out():
    """The OC3 demo's case (a prescribed RAO spar with a constant external force for wind, current and drift):
    waves modelled, slow drift NOT MODELLED, wind, current and mean drift steady only; a free body with a
    database in an irregular sea with wind and current: everything modelled."""
    oc3 = {"environment": {"waves": {"spectrum": "jonswap", "hs": 10.0, "tp": 14.0}},
           "bodies": {"spar": {"kind": "prescribed", "external_force": [6e5, 0, 0, 0, 3.6e7, 0]}},
           "analysis": {"body_motions": {"spar": {"type": "rao"}}}}
    status = {c["component"]: c["status"] for c in modelled_components(oc3)}
    assert status == {"waves (WF)": "modelled", "LF slow drift": "NOT MODELLED", "mean wave drift": "steady only",
                      "wind": "steady only", "current": "steady only"}
    full = {"environment": {"waves": {"spectrum": "jonswap", "hs": 10.0, "tp": 14.0},
                            "wind": {"speed": 30.0}, "current": {"speed": 1.0}},
            "bodies": {"hull": {"kind": "free", "hydrodynamics": {"file": "hull", "drift": "newman"},
                                "wind": {"height": 10.0}}}}
    assert {c["status"] for c in modelled_components(full)} == {"modelled"}
    full["bodies"]["hull"]["hydrodynamics"]["drift"] = "qtf"  # the full QTF's slow drift
    full["bodies"]["hull"]["current"] = {"surge": [900.0]}
    rows = {c["component"]: c for c in modelled_components(full)}
    assert {r["status"] for r in rows.values()} == {"modelled"}
    assert "full QTF" in rows["LF slow drift"]["how"] and "hull (current areas" in rows["current"]["how"]
    assert {c["status"] for c in modelled_components(None)} == {"unknown"}
