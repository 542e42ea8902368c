"""RAOs of the OC3-Hywind spar from a slender-body model, written as an SI CSV table (``oc3_hywind_raos.csv``).

No BEM output of OC3-Hywind is public in a form we can ship, so the demo's RAOs come from the long-wave
(slender-body) theory of a deep-draft spar, with the platform of Jonkman (2010), "Definition of the floating
system for phase IV of OC3", NREL/TP-500-47535, Tables 2-1 and 3-1 (turbine included as a point mass):

- geometry: 6.5 m diameter from the waterline to 4 m down, a taper to 9.4 m at 12 m down, 9.4 m to the
  keel at 120 m; deep water (320 m: e^{kz} profiles, kd > 2 above 0.26 rad/s, where the spectrum has its energy);
- excitation: Morison inertia (C_m = 2) on each strip for surge and its moment about the waterline for pitch;
  Froude-Krylov pressure on the keel and on the taper's shoulder for heave; the elevation at the spar's axis
  is ``a cos(w t)``;
- mass: 8,066,048 kg with its centre of gravity 77.94 m down (platform 7,466,330 kg at -89.92 m, rotor-nacelle
  and tower 599,718 kg at +64.0 m, OC3 Tables 2-1 and 3-1); pitch inertia about the centre of gravity
  4.229e9 kg m^2 (the platform's) plus the turbine's point mass; added mass C_a = 1 on each strip, a hemisphere's
  at the keel for heave;
- stiffness: heave rho g A_wp; pitch rho g (V z_B + I_wp) - m g z_G; surge the mooring's 41,180 N/m (OC3 Table 5-1);
- damping: 5 % of critical in each mode (viscous and radiation together: a spar's linear radiation damping
  is small in waves this long).

Accurate to the slender-body limit (D/L << 1): an illustration of the design workflow, not a replacement
for a BEM analysis. Run: ``python examples/oc3_hywind_raos.py`` (writes the CSV beside this file).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

RHO, G = 1025.0, 9.80665
MASS, ZG = 8_066_048.0, -77.94            # [kg], [m]
I_CG = 4.229e9 + 599_718.0 * (64.0 + 77.94) ** 2 + 7_466_330.0 * (89.92 - 77.94) ** 2  # about the CG [kg m^2]
K_SURGE = 41_180.0                        # mooring [N/m]
ZETA = 0.05                               # damping ratio of each mode


def diameter(z):
    """Spar diameter at depth z (<= 0). [m]"""
    return np.interp(-z, [0.0, 4.0, 12.0, 120.0], [6.5, 6.5, 9.4, 9.4])


def raos(omega):
    """Complex RAOs (surge [m/m], heave [m/m], pitch [rad/m]) for waves travelling towards +x, H = |H| e^(-i
    phase) for the motion |H| cos(w t + phase) under the elevation cos(w t) at the axis."""
    z = np.linspace(-120.0, 0.0, 2401)
    area = math.pi * diameter(z) ** 2 / 4
    dz = z[1] - z[0]
    volume = float(np.sum((area[1:] + area[:-1]) / 2) * dz)
    zb = float(np.sum(((area * z)[1:] + (area * z)[:-1]) / 2) * dz) / volume
    a_wp, a_keel = area[-1], area[0]
    # rigid-body mass (about the waterline) and strip added mass (C_a = 1)
    m11 = MASS + RHO * volume
    m15 = MASS * ZG + RHO * float(np.sum(((area * z)[1:] + (area * z)[:-1]) / 2) * dz)
    m55 = I_CG + MASS * ZG**2 + RHO * float(np.sum(((area * z * z)[1:] + (area * z * z)[:-1]) / 2) * dz)
    m33 = MASS + RHO * (2 / 3) * math.pi * (9.4 / 2) ** 3
    c33 = RHO * G * a_wp
    c55 = RHO * G * (volume * zb + math.pi * 6.5**4 / 64) - MASS * G * ZG
    out = np.zeros((3, omega.size), complex)
    for i, w in enumerate(omega):
        k = w * w / G
        decay = np.exp(k * z)
        strip = RHO * 2.0 * area * (-1j * w * w) * decay  # Morison inertia on each strip [N/m per m of wave]
        f1 = np.sum((strip[1:] + strip[:-1]) / 2) * dz
        f5 = np.sum(((strip * z)[1:] + (strip * z)[:-1]) / 2) * dz
        f3 = RHO * G * (a_keel * math.exp(-120.0 * k) - (a_keel - a_wp) * math.exp(-8.0 * k))
        M = np.array([[m11, m15], [m15, m55]])
        C = np.diag([K_SURGE, c55])
        # damping: 5 % of critical of each uncoupled mode
        B = np.diag([2 * ZETA * math.sqrt(K_SURGE * m11), 2 * ZETA * math.sqrt(c55 * m55)])
        x15 = np.linalg.solve(-w * w * M - 1j * w * B + C, [f1, f5])
        b33 = 2 * ZETA * math.sqrt(c33 * m33)
        out[:, i] = [x15[0], f3 / (-w * w * m33 - 1j * w * b33 + c33), x15[1]]
    return out


def write(path: Path) -> None:
    omega = np.round(np.arange(0.05, 3.001, 0.05), 4)
    headings = np.radians(np.arange(0.0, 360.0, 30.0))
    surge, heave, pitch = raos(omega)
    rows = ["frequency,heading,dof,amplitude,phase"]
    for b in headings:
        # an axisymmetric spar: waves towards b move it along b and pitch it about the axis normal to b
        per_dof = (surge * math.cos(b), surge * math.sin(b), heave, -pitch * math.sin(b), pitch * math.cos(b),
                   np.zeros_like(surge))
        for j, h in enumerate(per_dof):
            for w, v in zip(omega, h):
                rows.append(f"{w:.4f},{b:.6f},{j + 1},{abs(v):.6e},{-np.angle(v) if abs(v) > 0 else 0.0:.6f}")
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")


if __name__ == "__main__":
    write(Path(__file__).with_name("oc3_hywind_raos.csv"))
