"""Natural frequencies and mode shapes of a cable linearised about a static equilibrium.

The cable is a chain of elastic truss elements (element ``i`` joins node ``i`` and node
``i + 1``). Each element is linearised about its static state: its tangent stiffness is

.. math::

    k_e = \\frac{EA}{L_0}\\, t t^T + \\frac{T}{L}\\, (I - t t^T),

the material stiffness along the unit tangent :math:`t` plus the geometric (string)
stiffness across it, with :math:`L_0` the unstretched and :math:`L` the stretched length.
Its mass is :math:`m L_0 I + m_a L_0 (I - t t^T)`: the structural mass moves in every
direction, the hydrodynamic added mass only normal to the element. Gravity is a dead load
and enters through the static tension and geometry only (the restoring force of a swinging
sagged cable comes from :math:`T(s)` and the curvature of the equilibrium). The
generalised symmetric eigenproblem :math:`K \\phi = \\omega^2 M \\phi` is solved on the free
degrees of freedom, densely (:func:`scipy.linalg.eigh`) for small meshes and by
shift-invert Lanczos (:func:`scipy.sparse.linalg.eigsh`) for large ones.

When the equilibrium lies in one vertical plane the in-plane (along the plane's
horizontal direction and Z) and out-of-plane motions decouple exactly; they are solved as
two separate problems and each mode is labelled ``"in"`` or ``"out"``. A non-planar
equilibrium is solved in 3-D and its modes are labelled ``"3d"``.

With lumped mass, the frequencies converge to the continuum from below with an error
proportional to :math:`1/n^2` (n elements); with consistent mass, from above
(Rayleigh-Ritz upper bound), also as :math:`1/n^2`.

References
----------
.. [1] Irvine, H. M. and Caughey, T. K. (1974). The linear theory of free vibrations of a
   suspended cable. Proc. R. Soc. Lond. A 341, 299-315.
.. [2] Irvine, H. M. (1981). Cable Structures. MIT Press, Cambridge MA. Ch. 3 and 4.
.. [3] Cook, R. D., Malkus, D. S., Plesha, M. E. and Witt, R. J. (2002). Concepts and
   Applications of Finite Element Analysis, 4th ed., Wiley. Sec. 11.3 (mass matrices)
   and 18.3 (geometric stiffness of a bar).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

import numpy as np
import scipy.linalg
import scipy.sparse
import scipy.sparse.linalg

from .. import _validate as v
from ..errors import ConvergenceError, InputError

__all__ = ["MassMatrix", "Plane", "CableModes", "cable_modes"]

#: Largest number of degrees of freedom (per subproblem) solved with dense ``eigh``.
DENSE_LIMIT = 300


class MassMatrix(enum.StrEnum):
    """How the element mass is distributed to the nodes."""

    LUMPED = "lumped"
    """Half of each element's mass at each of its nodes (frequencies converge from below)."""
    CONSISTENT = "consistent"
    """Linear shape functions, ``m/6 [[2, 1], [1, 2]]`` (frequencies converge from above)."""


class Plane(enum.StrEnum):
    """Which motion a mode belongs to."""

    IN = "in"
    """In the vertical plane of a planar equilibrium."""
    OUT = "out"
    """Normal to the vertical plane of a planar equilibrium."""
    THREE_D = "3d"
    """Mode of a non-planar equilibrium (no separation)."""


@dataclass(frozen=True)
class CableModes:
    """Natural modes of a cable about a static equilibrium, sorted by frequency.

    Attributes
    ----------
    frequency
        Natural frequencies, shape (mode,). [Hz]
    angular_frequency
        Natural angular frequencies, shape (mode,). [rad/s]
    period
        Natural periods, shape (mode,). [s]
    plane
        Label of each mode: ``"in"``, ``"out"`` or ``"3d"`` (see :class:`Plane`), shape (mode,).
    shape
        Mode shapes as nodal displacements in global (x, y, z), shape (mode, node, 3),
        scaled so that the largest nodal displacement has unit length and the largest
        component (the first in node order if several tie within 1e-6) is positive;
        zero at fixed nodes. [-]
    """

    frequency: np.ndarray
    angular_frequency: np.ndarray
    period: np.ndarray
    plane: np.ndarray
    shape: np.ndarray

    def __len__(self) -> int:
        return int(self.frequency.size)

    def select(self, plane: str) -> "CableModes":
        """Return only the modes labelled ``plane`` (``"in"``, ``"out"`` or ``"3d"``)."""
        plane = _enum(Plane, plane, "plane")
        keep = self.plane == plane.value
        return CableModes(self.frequency[keep], self.angular_frequency[keep], self.period[keep],
                          self.plane[keep], self.shape[keep])


def _enum(kind, value, name):
    return kind(v.one_of(name, value, [k.value for k in kind]))


def _per_element(name, value, n, unit, check, fix):
    arr = check(name, value, unit, fix)
    arr = np.asarray(arr, dtype=float)
    if arr.ndim == 0:
        return np.full(n, float(arr))
    if arr.shape != (n,):
        raise InputError(f"{name} must be a scalar or have one value per element ({n},), "
                         f"got shape {arr.shape}. Suggested fix: give one value per element "
                         f"(len(nodes) - 1 = {n}).")
    return arr


def _plane_basis(nodes3, tol):
    """Rotation R (rows e_h, e_n, e_z) and whether the nodes lie in one vertical plane."""
    xy = nodes3[:, :2] - nodes3[:, :2].mean(axis=0)
    _, s, vt = np.linalg.svd(xy, full_matrices=False)
    if s[0] <= tol:  # vertical line: any vertical plane contains it; take x-z
        e_h = np.array([1.0, 0.0])
        planar = True
    else:
        e_h = vt[0]
        chord = nodes3[-1, :2] - nodes3[0, :2]
        if chord @ e_h < 0 or (abs(chord @ e_h) <= tol and e_h[np.argmax(np.abs(e_h))] < 0):
            e_h = -e_h
        planar = s.size < 2 or s[1] <= tol
    rot = np.array([[e_h[0], e_h[1], 0.0],
                    [-e_h[1], e_h[0], 0.0],   # e_n = e_z x e_h
                    [0.0, 0.0, 1.0]])
    return rot, planar


def _assemble(pos, l0, tension, mass, added, ea, point_masses, consistent):
    """Global 3-D stiffness and mass matrices (sparse CSR) in the coordinates of ``pos``."""
    n_el = l0.size
    d = pos[1:] - pos[:-1]
    length = np.linalg.norm(d, axis=1)
    t = d / length[:, None]
    tt = t[:, :, None] * t[:, None, :]
    eye = np.eye(3)
    k = (ea / l0)[:, None, None] * tt + (tension / length)[:, None, None] * (eye - tt)
    m_dir = (mass * l0)[:, None, None] * eye + (added * l0)[:, None, None] * (eye - tt)

    a = np.arange(n_el)
    blocks_k = {(0, 0): k, (1, 1): k, (0, 1): -k, (1, 0): -k}
    if consistent:
        blocks_m = {(0, 0): m_dir / 3, (1, 1): m_dir / 3, (0, 1): m_dir / 6, (1, 0): m_dir / 6}
    else:
        blocks_m = {(0, 0): m_dir / 2, (1, 1): m_dir / 2}
    n_dof = 3 * (n_el + 1)
    comp_r, comp_c = np.meshgrid(np.arange(3), np.arange(3), indexing="ij")

    def build(blocks, extra=None):
        rows, cols, vals = [], [], []
        for (p, q), blk in blocks.items():
            rows.append((3 * (a + p))[:, None, None] + comp_r)
            cols.append((3 * (a + q))[:, None, None] + comp_c)
            vals.append(blk)
        if extra is not None:
            nodes = np.arange(n_el + 1)
            rows.append((3 * nodes)[:, None, None] + comp_r)
            cols.append((3 * nodes)[:, None, None] + comp_c)
            vals.append(extra[:, None, None] * eye)
        r = np.concatenate([x.ravel() for x in rows])
        c = np.concatenate([x.ravel() for x in cols])
        val = np.concatenate([x.ravel() for x in vals])
        return scipy.sparse.coo_matrix((val, (r, c)), shape=(n_dof, n_dof)).tocsr()

    return build(blocks_k), build(blocks_m, point_masses)


_NOT_PD = ("the linearised stiffness matrix must be positive definite, but {detail}. "
           "Suggested fix: check that every tension is > 0 and finite, that at least one node "
           "is fixed, and that the equilibrium has no coincident nodes.")


def _solve(kk, mm, n_modes):
    """Lowest ``n_modes`` eigenpairs of K phi = w^2 M phi (K, M symmetric positive definite)."""
    n = kk.shape[0]
    k = min(n_modes, n)
    if n <= DENSE_LIMIT or k >= n - 1:
        # Solve M phi = mu K phi for the largest mu = 1/omega^2 (dense shift-invert about 0):
        # their error is relative to the largest mu, so the lowest frequencies keep full
        # precision even when EA/L0 dwarfs T/L (eigh(K, M) would lose digits to the axial modes).
        try:
            mu, phi = scipy.linalg.eigh(mm.toarray(), kk.toarray(),
                                        subset_by_index=[n - k, n - 1])
        except np.linalg.LinAlgError:
            raise InputError(_NOT_PD.format(detail="its Cholesky factorisation failed")) from None
        with np.errstate(divide="ignore"):
            w2, phi = 1.0 / mu[::-1], phi[:, ::-1]
    else:
        maxiter = 20 * n
        try:
            w2, phi = scipy.sparse.linalg.eigsh(kk.tocsc(), k=k, M=mm.tocsc(), sigma=0.0,
                                                which="LM", maxiter=maxiter)
        except scipy.sparse.linalg.ArpackNoConvergence as exc:
            raise ConvergenceError(
                f"the shift-invert Lanczos eigen-solver (ARPACK) did not converge for {k} modes "
                f"of a {n}-DOF problem in {maxiter} iterations ({len(exc.eigenvalues)} "
                f"converged). Suggested fix: ask for fewer modes (n_modes) or use a coarser mesh.",
                iterations=maxiter) from None
        except RuntimeError as exc:  # SuperLU: K is exactly singular
            raise InputError(_NOT_PD.format(detail=f"its factorisation failed ({exc})")) from None
        order = np.argsort(w2)
        w2, phi = w2[order], phi[:, order]
    if np.any(~np.isfinite(w2)) or np.any(w2 <= 0.0):
        bad = w2[~np.isfinite(w2) | (w2 <= 0.0)][0]
        raise InputError(_NOT_PD.format(detail=f"got an eigenvalue omega^2 = {bad:.6g} rad^2/s^2"))
    return w2, phi


def cable_modes(nodes, unstretched_lengths, tensions, mass_per_length, axial_stiffness, *,
                added_mass_per_length=0.0, point_masses=None, fixed=(0, -1), n_modes=10,
                planes=("in", "out"), mass_matrix="lumped") -> CableModes:
    """Natural frequencies and mode shapes of a cable about a static equilibrium.

    Linearised elastic-truss finite elements: material stiffness ``EA/L0 t t^T`` plus
    geometric stiffness ``T/L (I - t t^T)`` per element, lumped or consistent mass with
    the added mass acting only normal to the element, generalised symmetric eigenproblem
    on the free degrees of freedom.

    Parameters
    ----------
    nodes : array_like, shape (n+1, 2) or (n+1, 3)
        Node positions of the static equilibrium, ``[x, z]`` or ``[x, y, z]``, Z up.
        Element ``i`` joins node ``i`` and node ``i + 1``. [m]
    unstretched_lengths : array_like, shape (n,) or scalar
        Unstretched length ``L0`` of each element. [m]
    tensions : array_like, shape (n,) or scalar
        Static (effective) tension of each element, e.g. at its mid-point; must be > 0. [N]
    mass_per_length : array_like, shape (n,) or scalar
        Structural mass per unit unstretched length. [kg/m]
    axial_stiffness : array_like, shape (n,) or scalar
        Axial stiffness EA. [N]
    added_mass_per_length : array_like, shape (n,) or scalar, optional
        Hydrodynamic added mass per unit unstretched length, acting normal to the element
        only (e.g. ``C_a rho pi d^2 / 4``). [kg/m]
    point_masses : array_like, shape (n+1,), optional
        Extra mass at each node (clump weights, buoys, sensors), isotropic. [kg]
    fixed : sequence of int, optional
        Indices of fixed nodes (negative indices count from the end). Default: both ends.
        Nodes resting on the seabed may be added here. [-]
    n_modes : int, optional
        Number of modes returned (the lowest over the requested planes; fewer if the model
        has fewer degrees of freedom). [-]
    planes : sequence of {"in", "out"}, optional
        For a planar equilibrium, which motions to compute. A non-planar equilibrium is
        solved in 3-D and needs both. [-]
    mass_matrix : {"lumped", "consistent"} or MassMatrix, optional
        Mass distribution; see :class:`MassMatrix`. [-]

    Returns
    -------
    CableModes
        Frequencies [Hz], angular frequencies [rad/s], periods [s], plane labels and
        mode shapes (mode, node, 3), sorted by frequency.

    Raises
    ------
    InputError
        If an array has the wrong shape or length, a value is NaN or infinite, a tension,
        length, mass or EA is <= 0 (a slack element has no transverse stiffness, so the
        eigenproblem is singular: this is an error, not a warning), an added or point mass
        is < 0, two consecutive nodes coincide, a fixed index is out of range, no degree of
        freedom is free, ``planes``/``mass_matrix`` is unknown, ``planes`` omits one plane of
        a non-planar equilibrium, or the assembled stiffness is not positive definite.
    ConvergenceError
        If the sparse shift-invert eigen-solver (used above ``DENSE_LIMIT`` DOFs) fails.

    Notes
    -----
    For a planar equilibrium the in-plane and out-of-plane problems are solved separately
    (they are exactly uncoupled), so degenerate frequencies (e.g. a taut string) get clean,
    correctly labelled shapes. Both solvers work about omega = 0 (dense: the pencil
    ``(M, K)`` for the largest ``1/omega^2``; sparse: shift-invert), so the lowest
    frequencies keep full precision even when ``EA/L0`` exceeds ``T/L`` by 1e12.

    Lumped-mass frequencies converge as ``1/n^2`` once the mesh resolves the shortest length
    over which the tension changes by its own size (``T0/w`` at the bottom of a vertical
    cable with bottom tension ``T0``); coarser meshes are pre-asymptotic.

    Gravity is a dead load: it enters only through the static
    geometry and tensions, which must be in equilibrium for the modes to be meaningful.

    References
    ----------
    .. [1] Irvine, H. M. and Caughey, T. K. (1974). The linear theory of free vibrations of
       a suspended cable. Proc. R. Soc. Lond. A 341, 299-315.
    .. [2] Irvine, H. M. (1981). Cable Structures. MIT Press. Ch. 3-4.
    .. [3] Cook, R. D. et al. (2002). Concepts and Applications of Finite Element Analysis,
       4th ed., Wiley. Sec. 11.3 and 18.3.

    Examples
    --------
    >>> import numpy as np
    >>> x = np.linspace(0.0, 10.0, 21)
    >>> modes = cable_modes(np.c_[x, 0 * x], 0.5, 1000.0, 1.0, 1e9, planes=("out",), n_modes=1)
    >>> round(float(modes.frequency[0]), 2)  # 1/(2L) sqrt(T/m) = 1.58 Hz
    1.58
    """
    fix_nodes = "give node positions as an (n+1, 2) [x, z] or (n+1, 3) [x, y, z] array in metres"
    pos = np.asarray(v.finite("nodes", nodes, "m", fix_nodes), dtype=float)
    if pos.ndim != 2 or pos.shape[1] not in (2, 3) or pos.shape[0] < 2:
        raise InputError(f"nodes must have shape (n+1, 2) or (n+1, 3) with n >= 1, got shape "
                         f"{pos.shape}. Suggested fix: {fix_nodes}.")
    if pos.shape[1] == 2:
        pos = np.column_stack([pos[:, 0], np.zeros(len(pos)), pos[:, 1]])
    n_el = len(pos) - 1
    l0 = _per_element("unstretched_lengths", unstretched_lengths, n_el, "m", v.positive,
                      "give the unstretched length of every element in metres")
    tension = _per_element(
        "tensions", tensions, n_el, "N", v.positive,
        "a slack element (T <= 0) has no transverse stiffness; give the element mid-point "
        "tension, or fix the slack nodes (e.g. nodes resting on the seabed)")
    mass = _per_element("mass_per_length", mass_per_length, n_el, "kg/m", v.positive,
                        "give the structural mass per metre (not the weight in water)")
    ea = _per_element("axial_stiffness", axial_stiffness, n_el, "N", v.positive,
                      "give EA in newtons")
    added = _per_element("added_mass_per_length", added_mass_per_length, n_el, "kg/m",
                         v.nonnegative, "give the added mass per metre, >= 0")
    if point_masses is None:
        pm = np.zeros(n_el + 1)
    else:
        pm = np.asarray(v.nonnegative("point_masses", point_masses, "kg",
                                      "give one mass >= 0 per node"), dtype=float)
        if pm.shape != (n_el + 1,):
            raise InputError(f"point_masses must have one value per node ({n_el + 1},), got "
                             f"shape {pm.shape}. Suggested fix: use zeros for nodes without "
                             f"a point mass.")
    n_modes_arr = np.asarray(n_modes)
    if n_modes_arr.ndim != 0 or not np.issubdtype(n_modes_arr.dtype, np.integer) or n_modes < 1:
        raise InputError(f"n_modes must be an integer >= 1, got {n_modes!r}. "
                         f"Suggested fix: ask for at least one mode.")
    kind = _enum(MassMatrix, mass_matrix, "mass_matrix")
    if isinstance(planes, str):
        planes = (planes,)
    wanted = [_enum(Plane, p, "planes") for p in planes]
    if not wanted or Plane.THREE_D in wanted:
        raise InputError(f"planes must be a non-empty subset of ('in', 'out'), got {planes!r}. "
                         f"Suggested fix: use planes=('in', 'out').")

    length = np.linalg.norm(np.diff(pos, axis=0), axis=1)
    scale = max(float(np.ptp(pos, axis=0).max()), float(l0.sum()))
    if np.any(length <= 1e-12 * scale):
        i = int(np.argmax(length <= 1e-12 * scale))
        raise InputError(f"element {i} must have a stretched length > 0 m, got {length[i]:.6g} m "
                         f"(nodes {i} and {i + 1} coincide). Suggested fix: remove duplicate nodes.")

    fixed_idx = np.atleast_1d(np.asarray(fixed))
    if fixed_idx.size == 0 or not np.issubdtype(fixed_idx.dtype, np.integer) or fixed_idx.ndim != 1:
        raise InputError(f"fixed must be a non-empty sequence of node indices, got {fixed!r}. "
                         f"Suggested fix: fix at least one node, e.g. fixed=(0, -1); a cable with "
                         f"no fixed node has zero-frequency rigid-body modes.")
    is_fixed = np.zeros(n_el + 1, dtype=bool)
    for idx in fixed_idx:
        if not -(n_el + 1) <= idx <= n_el:
            raise InputError(f"fixed node index must be in [{-(n_el + 1)}, {n_el}], got {idx}. "
                             f"Suggested fix: give node indices of the {n_el + 1} nodes.")
        is_fixed[idx] = True
    if is_fixed.all():
        raise InputError(f"at least one node must be free, got all {n_el + 1} nodes fixed. "
                         f"Suggested fix: fix only the supports (e.g. fixed=(0, -1)).")

    rot, planar = _plane_basis(pos, 1e-9 * scale)
    local = pos @ rot.T
    kk, mm = _assemble(local, l0, tension, mass, added, ea, pm,
                       kind is MassMatrix.CONSISTENT)

    free_nodes = np.flatnonzero(~is_fixed)
    if planar:
        groups = {Plane.IN: (0, 2), Plane.OUT: (1,)}
        groups = {p: c for p, c in groups.items() if p in wanted}
    else:
        if set(wanted) != {Plane.IN, Plane.OUT}:
            raise InputError(f"planes must be ('in', 'out') for a non-planar equilibrium, got "
                             f"{planes!r}. Suggested fix: use planes=('in', 'out'); the modes "
                             f"are then labelled '3d'.")
        groups = {Plane.THREE_D: (0, 1, 2)}

    freqs, labels, shapes = [], [], []
    for plane, comps in groups.items():
        dofs = (3 * free_nodes[:, None] + np.asarray(comps)[None, :]).ravel()
        w2, phi = _solve(kk[dofs][:, dofs], mm[dofs][:, dofs], n_modes)
        full = np.zeros((w2.size, 3 * (n_el + 1)))
        full[:, dofs] = phi.T
        u = full.reshape(w2.size, n_el + 1, 3) @ rot  # local (h, n, z) -> global (x, y, z)
        freqs.append(np.sqrt(w2))
        labels += [plane.value] * w2.size
        shapes.append(u)

    omega = np.concatenate(freqs)
    order = np.argsort(omega, kind="stable")[:n_modes]
    omega = omega[order]
    shape = np.concatenate(shapes)[order]
    amp = np.linalg.norm(shape, axis=2)
    shape = shape / amp.max(axis=1)[:, None, None]
    # sign: the first (in node order) component within 1e-6 of the largest is positive, so
    # that antisymmetric shapes, whose two peaks tie up to round-off, get a reproducible sign
    flat = np.abs(shape.reshape(len(omega), -1))
    first = np.argmax(flat >= (1 - 1e-6) * flat.max(axis=1, keepdims=True), axis=1)
    sign = np.sign(shape.reshape(len(omega), -1)[np.arange(len(omega)), first])
    shape = shape * sign[:, None, None]
    return CableModes(frequency=omega / (2 * np.pi), angular_frequency=omega,
                      period=2 * np.pi / omega, plane=np.asarray(labels)[order], shape=shape)
