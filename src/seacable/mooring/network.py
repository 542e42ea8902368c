"""The discrete mooring system: nodes and two-node truss elements, as flat arrays.

A :class:`Network` is what the compiled kernel works on. It is built from a case's line
(:func:`network_from_line`, one line from the anchor, node 0, to the fairlead) or from a MoorDyn
input file (``seacable.mooring.moordyn``, several lines meeting at points). Nodes are free, fixed
(anchors) or prescribed (fairleads, moved by a motion channel). Element properties are per element,
so a distributed clump weight is simply a run of heavy elements; a lumped clump, a buoy or a point
mass is a node load.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from dataclasses import dataclass, field, fields

import numpy as np

from ..errors import InputError
from ..line import Line, resolve_sections
from ..moment_curvature import law_sum, linear_law
from ..sections import element_bending_stiffness, element_moment_curvature, element_section_properties
from ..ties import Clamp
from ._indices import (
    H_CLAMP,
    H_D,
    H_DCH,
    H_ECH,
    H_EI,
    H_K,
    H_KIND,
    H_L0,
    H_NLAW,
    H_SIZE,
    H_SPRING,
    P_CK,
    P_CX,
    P_SIZE,
    P_TB,
    P_TEA,
    P_TL,
    P_TX,
)

__all__ = [
    "FIXED",
    "FREE",
    "PRESCRIBED",
    "Network",
    "element_damping",
    "line_bending",
    "line_viscoelastic",
    "network_from_line",
    "node_arc_lengths",
    "slack_positions",
    "table_secant",
]

FREE, FIXED, PRESCRIBED = 0, 1, 2


@dataclass(frozen=True)
class Network:
    """Nodes and truss elements of a mooring system (all SI, Z up, z = 0 at the still water level).

    Attributes
    ----------
    position : (n, 3) initial node positions. [m]
    kind : (n,) FREE, FIXED or PRESCRIBED.
    channel : (n,) motion channel of a prescribed node (-1 otherwise).
    point_mass, point_added_mass : (n,) mass and isotropic added mass of attachments. [kg]
    point_weight : (n,) net weight in water of attachments, negative when buoyant. [N]
    point_volume : (n,) displaced volume of attachments (Froude-Krylov force). [m^3]
    point_drag_area : (n,) C_D A of attachments (across the line when ``point_axial_drag_area`` differs). [m^2]
    point_axial_drag_area : (n,) C_D A of attachments along the line; None: the same as across (an isotropic
        drag ``1/2 rho C_D A |u| u``). [m^2]
    point_lift_area : (n,) C_L A of attachments, lift positive up (:func:`seacable.mooring.kernel.point_lift`);
        None: no lift. [m^2]
    elements : (e, 2) node indices of each element, end A first.
    length : (e,) unstretched length. [m]
    axial_stiffness : (e,) EA; for an element with a strain-tension table (``element_tension_strain``)
        a constant stand-in (the line type's EA, else the table's secant at its end) that sets only the
        slack rounding band, the damping and the solver's tolerances: its tension is the table's. [N]
    axial_damping : (e,) internal damping coefficient c, force c (dl/dt) / L. [N s]
    mass_per_length, weight_per_length : (e,) mass in air [kg/m], weight in water [N/m].
    diameter : (e,) hydrodynamic (volume-equivalent) diameter. [m]
    cdn, cdt, can, cat : (e,) drag and added-mass coefficients normal and tangential. [-]
    element_line : (e,) the line each element belongs to.
    line_nodes : node indices of each line, end A to end B.
    line_names : a name per line.
    arc_length : (n,) unstretched arc length from end A of the node's line (NaN for a point node
        shared by several lines). [m]
    breaking_load : (e,) minimum breaking load of each element's line type, NaN if unknown; None when
        none is known. [N]
    element_tension_strain : per element, the line type's strain-tension table (``LineType.tension_strain``,
        ``(strain, tension)`` pairs) or None for a linear EA; None when no element has one. [-, N]
    bending_stiffness : (e,) EI of each element's line type; None (or all 0) for a truss. The bending
        moment acts at the inner nodes of each line (:func:`seacable.mooring.kernel.bending_loads`),
        with the mean EI of the node's two elements; line ends are pinned unless ``end_hinges`` holds them. [N m^2]
    element_viscoelastic : (e, 3) per element ``(EA_Dc, EA_D_Lm, BA_D)`` of a viscoelastic line type
        (``LineType.dynamic_axial_stiffness`` and the fast damper), zeros for an elastic element; None
        when no element is viscoelastic. ``axial_stiffness`` is then the static EA_s and
        ``axial_damping`` the slow damper BA (:func:`seacable.mooring.kernel.viscoelastic_tension`).
        [N, -, N s]
    element_moment_curvature : per element its nonlinear moment-curvature law, knots ``(kappa, M)`` from
        ``(0, 0)`` (:mod:`seacable.moment_curvature`), or None for the linear ``bending_stiffness``; None when no
        element has one. ``bending_stiffness`` is then each law's initial slope. [1/m, N m]
    point_tether : (n, 6) per node its tether to the seabed (:class:`seacable.ties.Tether`): the anchor (x, y, z),
        the axial stiffness EA, the unstretched length (0: no tether) and the strain band of its slack switch's
        rounding (:func:`seacable.mooring._ties.tie_loads`); None when no node has one. [m, m, m, N, m, -]
    point_clamp : (n, 4) per node its spring clamp (:class:`seacable.ties.Clamp` with a stiffness): the point it
        holds the node to (x, y, z) and its stiffness (0: none); None when no node has one. A rigid clamp is a
        FIXED node. [m, m, m, N/m]
    end_hinges : the line ends held at a direction, each ``(line, end, kind, stiffness, direction)``: the line's
        index, its end (0: end A, 1: end B), ``"clamp"`` or ``"spring"``, a spring's rotational stiffness
        (None for a clamp, whose stiffness is its end element's EI) and the direction the line leaves or
        reaches the end in, a unit vector along the line from end A towards end B (:class:`seacable.mooring.ends.
        EndCondition`); the other ends are pinned (:func:`seacable.mooring.kernel.end_bending_loads`). [-, -, -,
        N m/rad, -]
    element_syrope : (e, 4) per element ``(form, k1, k2, Tmax0)`` of a Syrope rope (its working curve's form,
        1 linear, 2 quadratic, 3 exponential, and parameters, and the largest mean tension before the run),
        whose ``element_tension_strain`` is its original working curve; zeros for other elements; None when
        there is none (:func:`seacable.mooring.kernel.syrope_tension`). [-, -, -, N]
    """

    position: np.ndarray
    kind: np.ndarray
    channel: np.ndarray
    point_mass: np.ndarray
    point_added_mass: np.ndarray
    point_weight: np.ndarray
    point_volume: np.ndarray
    point_drag_area: np.ndarray
    elements: np.ndarray
    length: np.ndarray
    axial_stiffness: np.ndarray
    axial_damping: np.ndarray
    mass_per_length: np.ndarray
    weight_per_length: np.ndarray
    diameter: np.ndarray
    cdn: np.ndarray
    cdt: np.ndarray
    can: np.ndarray
    cat: np.ndarray
    element_line: np.ndarray
    line_nodes: tuple[np.ndarray, ...]
    line_names: tuple[str, ...]
    arc_length: np.ndarray
    n_channels: int = 1
    channel_names: tuple[str, ...] = field(default=("fairlead",))
    breaking_load: np.ndarray | None = None
    element_tension_strain: tuple | None = None
    bending_stiffness: np.ndarray | None = None
    element_viscoelastic: np.ndarray | None = None
    element_syrope: np.ndarray | None = None
    point_axial_drag_area: np.ndarray | None = None
    point_lift_area: np.ndarray | None = None
    end_hinges: tuple = ()
    element_moment_curvature: tuple | None = None
    point_tether: np.ndarray | None = None
    point_clamp: np.ndarray | None = None

    def __post_init__(self):
        # the kernels are compiled for C-contiguous arrays: a column of a table (``P[:, 1]``) would make numba
        # compile every kernel again for a strided layout, at seconds a copy of the loads pass
        for f in fields(self):
            value = getattr(self, f.name)
            if isinstance(value, np.ndarray) and not value.flags.c_contiguous:
                object.__setattr__(self, f.name, np.ascontiguousarray(value))

    def hinge_arrays(self):
        """The bending hinges as the kernel takes them (:func:`seacable.mooring.kernel.bending_loads`).

        Returns ``(hinges, hinge_ei)``: ``hinges`` (h, 3) the inner nodes of the lines with bending stiffness, each
        with its two neighbours along its line (end A side first), then the held ends (``end_hinges``), each
        ``(end node, end node, neighbour)`` at end A and ``(neighbour, end node, end node)`` at end B;
        ``hinge_ei`` (h, H_SIZE) their table (:mod:`seacable.mooring._indices`): at an inner node the mean EI
        of its two elements [N m^2]; at a held end the end element's EI, the kind, the direction from the end into
        the line and a spring's stiffness [N m/rad]. No rows for a truss with pinned ends. A hinge next to an element
        with a nonlinear law (``element_moment_curvature``) takes the mean of its two elements' laws (a held end its
        element's), its knots in the columns from ``H_SIZE`` on.
        """
        rows, vals, laws = [], [], []
        ei = self.bending_stiffness
        of = {(int(a), int(b)): e for e, (a, b) in enumerate(self.elements)}
        nl = self.element_moment_curvature
        if nl is not None and ei is None:
            ei = np.zeros(self.n_elements)

        def law_of(*elements):
            if nl is None or all(nl[e] is None for e in elements):
                return None
            return law_sum([linear_law(ei[e]) if nl[e] is None else nl[e] for e in elements],
                           np.full(len(elements), 1.0 / len(elements)))

        if ei is not None and np.any(np.asarray(ei) > 0):
            ei = np.asarray(ei, float)
            for nodes in self.line_nodes:
                for k in range(1, len(nodes) - 1):
                    i0, i1, i2 = int(nodes[k - 1]), int(nodes[k]), int(nodes[k + 1])
                    e1 = of.get((i0, i1), of.get((i1, i0)))
                    e2 = of.get((i1, i2), of.get((i2, i1)))
                    if e1 is None or e2 is None:
                        continue
                    value = 0.5 * (ei[e1] + ei[e2])
                    law = law_of(e1, e2)
                    if value > 0 or law is not None:
                        rows.append((i0, i1, i2))
                        vals.append(np.zeros(H_SIZE))
                        vals[-1][H_EI] = value
                        vals[-1][H_L0] = 0.5 * (self.length[e1] + self.length[e2])
                        laws.append(law)
        for line, end, kind, stiffness, direction in self.end_hinges:
            nodes = self.line_nodes[line]
            ie, iw = (int(nodes[0]), int(nodes[1])) if end == 0 else (int(nodes[-1]), int(nodes[-2]))
            e = of.get((ie, iw), of.get((iw, ie)))
            row = np.zeros(H_SIZE)
            row[H_DCH] = row[H_ECH] = -1.0  # a direction fixed in space (a moving platform's: the run sets them)
            row[H_EI] = 0.0 if ei is None else float(np.asarray(ei, float)[e])
            row[H_KIND] = H_CLAMP if kind == "clamp" else H_SPRING
            row[H_L0] = 0.5 * self.length[e]
            if kind != "clamp":
                row[H_K] = float(stiffness)
            d = np.asarray(direction, float)
            row[H_D:H_D + 3] = (d if end == 0 else -d) / np.linalg.norm(d)
            rows.append((ie, ie, iw) if end == 0 else (iw, ie, ie))
            vals.append(row)
            laws.append(law_of(e))
        if not rows:
            return np.zeros((0, 3), np.int64), np.zeros((0, H_SIZE))
        table = np.array(vals, float)
        if any(law is not None for law in laws):
            width = max(len(law) for law in laws if law is not None)
            table = np.column_stack([table, np.zeros((len(rows), 2 * width))])
            for h, law in enumerate(laws):
                if law is not None:
                    table[h, H_NLAW] = len(law)
                    table[h, H_SIZE:H_SIZE + 2 * len(law)] = np.asarray(law, float).ravel()
        return np.array(rows, np.int64), table

    def tension_strain_arrays(self):
        """The strain-tension tables as the kernel takes them: ``(lo, hi, strain, tension)``.

        Element ``e`` has the table ``strain[lo[e]:hi[e]]``, ``tension[lo[e]:hi[e]]`` when
        ``hi[e] > lo[e]``, and a constant EA otherwise; elements of one table share its points. [-], [N]
        """
        n = self.n_elements
        lo, hi = np.zeros(n, np.int64), np.zeros(n, np.int64)
        xs, ys, where = [], [], {}
        for e, table in enumerate(self.element_tension_strain or ()):
            if table is None:
                continue
            key = tuple(map(tuple, table))
            if key not in where:
                start = sum(len(x) for x in xs)
                where[key] = (start, start + len(key))
                xs.append([p[0] for p in key])
                ys.append([p[1] for p in key])
            lo[e], hi[e] = where[key]
        if not xs:
            return lo, hi, np.zeros(1), np.zeros(1)
        return lo, hi, np.concatenate(xs).astype(float), np.concatenate(ys).astype(float)

    @property
    def n_nodes(self) -> int:
        return len(self.kind)

    @property
    def n_elements(self) -> int:
        return len(self.length)

    def node_weight(self) -> np.ndarray:
        """Net downward load on each node: half of each adjacent element plus attachments. [N]"""
        w = self.point_weight.copy()
        half = 0.5 * self.weight_per_length * self.length
        np.add.at(w, self.elements[:, 0], half)
        np.add.at(w, self.elements[:, 1], half)
        return w

    def replace(self, **changes) -> Network:
        return dataclasses.replace(self, **changes)

    def point_hydrodynamics(self) -> np.ndarray:
        """The attachments' drag and lift areas (n, 3) as the kernel takes them (``kernel.P_CDA``,
        ``P_CDA_AXIAL``, ``P_CLA``): C_D A across the line, along it (that across when not given) and C_L A. [m^2]"""
        out = np.zeros((self.n_nodes, 3))
        out[:, 0] = self.point_drag_area
        out[:, 1] = self.point_drag_area if self.point_axial_drag_area is None else self.point_axial_drag_area
        if self.point_lift_area is not None:
            out[:, 2] = self.point_lift_area
        if self.point_tether is None and self.point_clamp is None:
            return out
        # a node tied to the seabed: the ties' columns too (kernel.P_TX on)
        wide = np.zeros((self.n_nodes, P_SIZE))
        wide[:, :3] = out
        if self.point_tether is not None:
            wide[:, P_TX:P_TX + 3] = self.point_tether[:, :3]
            wide[:, [P_TEA, P_TL, P_TB]] = self.point_tether[:, 3:6]
        if self.point_clamp is not None:
            wide[:, P_CX:P_CX + 3] = self.point_clamp[:, :3]
            wide[:, P_CK] = self.point_clamp[:, 3]
        return wide

    def channel_positions(self, X=None) -> np.ndarray:
        """Positions (n_channels, 3) of the prescribed nodes in channel order, from ``X`` or at rest. [m]"""
        X = self.position if X is None else X
        out = np.zeros((max(self.n_channels, 1), 3))
        moved = np.flatnonzero(self.channel >= 0)
        out[self.channel[moved]] = X[moved]
        return out


def table_secant(table) -> float:
    """EA of a strain-tension table where one is needed as a constant: its secant to the last point. [N]"""
    strain, tension = table[-1]
    return tension / strain


def element_damping(axial_stiffness, mass_per_length, length, ratio=0.0, stiffness_proportional=0.0):
    """Internal axial damping coefficient of truss elements. [N s]

    ``c = zeta L sqrt(EA m) + beta EA``: the first term is MoorDyn's rule for a damping ratio
    ``zeta`` of the element's axial mode (its ``BA = -zeta``), the second the stiffness-proportional
    part ``beta K`` of Rayleigh damping written as an element damper (force ``c (dl/dt) / L``).
    """
    ea, m, L = (np.asarray(a, float) for a in (axial_stiffness, mass_per_length, length))
    return ratio * L * np.sqrt(ea * m) + stiffness_proportional * ea


def catenary_positions(a, b, s, lengths, weights, axial_stiffness, *, point_loads=(), depth=None, slope=0.0,
                       buoyant=False):
    """A start shape for the line from ``a`` to ``b``: positions at unstretched arc lengths ``s`` (from ``a``).

    When ``b`` is beside and above ``a``, the multi-segment catenary of
    :func:`seacable.statics.multisegment.line_equilibrium` in the vertical plane through both points,
    on the seabed when ``a`` lies on it (``z = -depth``). A slack line whose grounded part is longer
    than the distance to the touchdown (the catenary bunches it at the touchdown, ``H = 0``) lies
    instead on the seabed along two straight legs beside the vertical plane, so that no two nodes
    coincide. Otherwise (ends one above the other, the catenary has no solution) the start is
    :func:`slack_positions`: straight when the line is shorter than the chord, else a V hanging
    below the chord. Returns (len(s), 3) positions. [m]

    ``buoyant``: try the catenary also when some segments are buoyant (a lazy wave: the multi-segment catenary
    takes buoyant segments), falling back on the slack start when it has no solution; without it (the
    default, as before sections existed) a line with a buoyant segment starts slack.
    """
    from ..errors import SeacableError
    from ..statics.multisegment import line_equilibrium

    a, b = np.asarray(a, float), np.asarray(b, float)
    s = np.asarray(s, float)
    total = float(np.sum(lengths))
    d = b - a
    h = math.hypot(d[0], d[1])
    if h <= 1e-6 * total or d[2] <= 0 or (min(weights) <= 0 and not buoyant):
        return slack_positions(a, b, s, total, depth=depth, slope=slope)
    on_seabed = depth is not None and abs(a[2] + depth) < 1e-6 * depth
    try:
        eq = line_equilibrium(lengths, weights, axial_stiffness, h, d[2], point_loads=point_loads,
                              seabed=on_seabed, seabed_slope=slope if on_seabed else 0.0)
    except SeacableError:
        return slack_positions(a, b, s, total, depth=depth, slope=slope)
    x, z = eq.profile_at(s, points_per_segment=400)
    along, side = np.array([d[0] / h, d[1] / h, 0.0]), np.array([-d[1] / h, d[0] / h, 0.0])
    y = np.zeros_like(s)
    grounded, reach = eq.grounded_length, eq.touchdown_x
    if on_seabed and grounded > reach * (1.0 + 1e-6) + 1e-9 * total:
        # slack (H = 0): the grounded length exceeds the distance to the touchdown; lay it on two legs
        # beside the plane, apex at half the grounded length, instead of bunching it at the touchdown
        on = s <= grounded
        f = np.minimum(s[on], grounded - s[on]) / (0.5 * grounded)
        x[on] = reach * s[on] / grounded
        y[on] = f * math.sqrt(max((0.5 * grounded) ** 2 - (0.5 * reach) ** 2, 0.0))
        z[on] = 0.0
    return a + np.outer(x, along) + np.outer(y, side) + np.outer(z, [0.0, 0.0, 1.0])


def slack_positions(a, b, s, length, *, depth=None, slope=0.0):
    """A start shape that needs no equilibrium: positions at arc lengths ``s`` of a line of ``length``.

    Straight from ``a`` to ``b`` when the line is no longer than the chord; otherwise two straight
    legs of the full length meeting below the middle of the chord (away from it along the part of
    gravity normal to the chord, or sideways when the chord is vertical), with nodes that would lie
    under the seabed moved up onto it. No two nodes coincide, so every element has a direction. [m]
    """
    a, b = np.asarray(a, float), np.asarray(b, float)
    s = np.asarray(s, float)
    d = b - a
    chord = float(np.linalg.norm(d))
    if chord >= length:
        return a + np.outer(s / length, d)
    t = d / chord if chord > 0 else np.array([0.0, 0.0, 1.0])
    n = np.array([0.0, 0.0, -1.0]) - t * (-t[2])       # gravity normal to the chord
    if np.linalg.norm(n) < 1e-3:
        n = np.cross(t, [0.0, 1.0, 0.0]) if abs(t[1]) < 0.9 else np.cross(t, [1.0, 0.0, 0.0])
    n /= np.linalg.norm(n)
    mid = a + 0.5 * d
    # apex p = mid + c n with |a - p| + |p - b| = length
    c = math.sqrt(max((0.5 * length) ** 2 - (0.5 * chord) ** 2, 0.0))
    apex = mid + c * n
    half = 0.5 * length
    first = s <= half
    X = np.where(first[:, None], a + np.outer(s / half, apex - a), apex + np.outer((s - half) / half, b - apex))
    if depth is not None:
        bed = -depth + math.tan(slope) * X[1:-1, 0]
        X[1:-1, 2] = np.maximum(X[1:-1, 2], bed)  # the ends stay where they are given
    return X


def node_arc_lengths(line: Line, n_elements: int | None = None, element_length: float | None = None,
                     breaks=()):
    """Unstretched arc lengths of the nodes of ``line``, with a node at every segment end and attachment, and at
    the arc lengths ``breaks`` (a tie's node). [m]

    Each segment uses its own ``n_elements`` when given; otherwise pieces between break points get
    elements of about ``element_length``, or of ``L / n_elements`` for the whole line.
    """
    L = line.length
    target = element_length if element_length is not None else L / (n_elements or 50)
    ends = line.segment_ends
    cuts = []
    for k, seg in enumerate(line.segments):
        s0, s1 = ends[k], ends[k + 1]
        inner = sorted({a.s for a in line.attachments if s0 + 1e-9 < a.s < s1 - 1e-9}
                       | {float(b) for b in breaks if s0 + 1e-9 < b < s1 - 1e-9})
        if seg.n_elements is not None and not inner:
            cuts.append(np.linspace(s0, s1, seg.n_elements + 1)[:-1])
            continue
        breaks = [s0, *inner, s1]
        for p, q in itertools.pairwise(breaks):
            n = seg.n_elements or max(1, math.ceil((q - p) / target - 1e-9))
            cuts.append(np.linspace(p, q, n + 1)[:-1])
    return np.concatenate(cuts + [np.array([L])])


def network_from_line(line: Line, anchor, fairlead, *, water_density: float, gravity: float,
                      n_elements: int | None = None, element_length: float | None = None,
                      damping_ratio: float = 0.0, stiffness_proportional: float = 0.0,
                      end_b: str = "prescribed", initial=None, ties=()) -> Network:
    """One line from ``anchor`` (node 0, fixed) to ``fairlead`` (last node), as a network.

    Parameters
    ----------
    line
        The line, end A at the anchor.
    anchor, fairlead
        End positions (x, y, z). [m]
    water_density, gravity
        For the weights and the Froude-Krylov forces. [kg/m^3], [m/s^2]
    n_elements, element_length
        Discretisation (see :func:`node_arc_lengths`).
    damping_ratio, stiffness_proportional
        Element axial damping (see :func:`element_damping`). [-], [s]
    end_b
        ``"prescribed"`` (a fairlead moved by channel 0) or ``"free"`` (a buoy or a free end).
    initial
        (n, 3) initial node positions; default a straight line from anchor to fairlead.
    ties
        The line's clamps and tethers to the seabed (:mod:`seacable.ties`), each ``(tie, point)`` with the point
        it holds to (x, y, z) [m] (:func:`seacable.ties.tie_points`): a node at each one's arc length; a rigid
        clamp's node FIXED there (the initial positions put it there), a spring clamp's and a tether's in
        ``point_clamp`` and ``point_tether``, half a tether's mass and weight on its node.

    A line with sections (``line.sections``) is first replaced by its equivalent line
    (:func:`seacable.line.resolve_sections`: smeared buoyancy as segments of their own, discrete modules as
    attachments) and its bend stiffeners' EI added per element at the elements' mid arc lengths
    (:func:`seacable.sections.element_bending_stiffness`), so that the kernel takes them unchanged. Elements with a
    nonlinear moment-curvature law (a line type's, a stiffener's, a bend restrictor's) carry it in
    ``element_moment_curvature`` (:func:`seacable.sections.element_moment_curvature`), and stiffeners with a density
    and restrictors their own mass, weight, drag and added mass (:func:`seacable.sections.element_section_properties`).
    """
    sectioned, line = line, resolve_sections(line, water_density, gravity)
    s = node_arc_lengths(line, n_elements, element_length, breaks=[tie.s for tie, _ in ties])
    n = len(s)
    ends = np.asarray(line.segment_ends)
    mid = 0.5 * (s[:-1] + s[1:])
    seg_of = np.clip(np.searchsorted(ends, mid, side="right") - 1, 0, len(line.segments) - 1)
    types = [line.segments[k].line_type for k in seg_of]
    for k, seg in enumerate(line.segments):
        if seg.line_type.axial_stiffness is None and seg.line_type.tension_strain is None:
            raise InputError(f"line.segments[{k}] has no axial_stiffness: the mooring finite-element model needs "
                             "EA for every line type. Suggested fix: add 'axial_stiffness' in N, e.g. 3.8e8.")
    length = np.diff(s)
    ea = np.array([t.axial_stiffness if t.axial_stiffness is not None else table_secant(t.tension_strain)
                   for t in types], float)
    tables = tuple(t.tension_strain for t in types) if any(t.tension_strain for t in types) else None
    m = np.array([t.mass_per_length for t in types], float)
    a = np.asarray(anchor, float)
    b = np.asarray(fairlead, float)
    position = a + np.outer(s / s[-1], b - a) if initial is None else np.array(initial, float)
    kind = np.zeros(n, np.int64)
    kind[0] = FIXED
    channel = np.full(n, -1, np.int64)
    if end_b == "prescribed":
        kind[-1] = PRESCRIBED
        channel[-1] = 0
    zeros = np.zeros(n)
    pm, pa, pw, pv, pd, pda, pla = (zeros.copy() for _ in range(7))
    for att in line.attachments:
        i = int(np.argmin(np.abs(s - att.s)))
        pm[i] += att.mass
        pa[i] += att.added_mass
        pw[i] += att.net_weight(water_density, gravity)
        pv[i] += att.volume
        pd[i] += att.drag_area
        pda[i] += att.drag_area if att.axial_drag_area is None else att.axial_drag_area
        pla[i] += att.lift_area()
    ei = element_bending_stiffness(sectioned, s, line_bending(types))
    laws = element_moment_curvature(sectioned, s, types, ei)
    if laws is not None:  # EI: each law's initial slope
        ei = np.array([law[1, 1] / law[1, 0] if law is not None else (0.0 if ei is None else ei[e])
                       for e, law in enumerate(laws)])
    hydro = {"mass_per_length": m,
             "weight_per_length": np.array([t.submerged_weight(water_density, gravity) for t in types], float),
             "diameter": np.array([t.diameter for t in types], float),
             "cdn": np.array([t.effective_drag()[0] for t in types], float),
             "cdt": np.array([t.effective_drag()[1] for t in types], float),
             "can": np.array([t.added_mass_normal for t in types], float),
             "cat": np.array([t.added_mass_tangential for t in types], float)}
    hydro.update(element_section_properties(sectioned, s, types, water_density, gravity) or {})
    m = hydro["mass_per_length"]
    tether = clamp = None
    for tie, point in ties:
        i = int(np.argmin(np.abs(s - tie.s)))
        if isinstance(tie, Clamp) and tie.stiffness is None:
            kind[i] = FIXED
            position[i] = point
        elif isinstance(tie, Clamp):
            clamp = np.zeros((n, 4)) if clamp is None else clamp
            clamp[i] = (*point, tie.stiffness)
        else:
            tether = np.zeros((n, 6)) if tether is None else tether
            # the slack switch rounded as an element's: over the strain at which EA eps is a quarter of its weight
            tether[i] = (*point, tie.axial_stiffness, tie.length, 0.25 * tie.mass * gravity / tie.axial_stiffness)
            pm[i] += 0.5 * tie.mass
            pw[i] += 0.5 * tie.weight_in_water
    return Network(
        position=position, kind=kind, channel=channel, point_mass=pm, point_added_mass=pa, point_weight=pw,
        point_volume=pv, point_drag_area=pd,
        elements=np.column_stack([np.arange(n - 1), np.arange(1, n)]).astype(np.int64),
        length=length, axial_stiffness=ea,
        axial_damping=element_damping(ea, m, length, damping_ratio, stiffness_proportional), **hydro,
        element_line=np.zeros(n - 1, np.int64), line_nodes=(np.arange(n),), line_names=("line",),
        arc_length=s, n_channels=1 if end_b == "prescribed" else 0,
        breaking_load=np.array([np.nan if t.breaking_load is None else t.breaking_load for t in types], float),
        channel_names=("fairlead",) if end_b == "prescribed" else (), element_tension_strain=tables,
        bending_stiffness=ei, element_moment_curvature=laws,
        element_viscoelastic=line_viscoelastic(types),
        point_axial_drag_area=None if np.array_equal(pda, pd) else pda, point_lift_area=pla if np.any(pla) else None,
        point_tether=tether, point_clamp=clamp)


def line_bending(types) -> np.ndarray | None:
    """EI per element from the elements' line types; None when none bends (a truss). [N m^2]"""
    ei = np.array([t.bending_stiffness for t in types], float)
    return ei if np.any(ei > 0) else None


def line_viscoelastic(types) -> np.ndarray | None:
    """``(EA_Dc, EA_D_Lm, BA_D)`` per element of viscoelastic line types (zeros for the others; a line type
    with a strain-tension table keeps its table); None when no element is viscoelastic. [N, -, N s]"""
    rows = np.zeros((len(types), 3))
    for e, t in enumerate(types):
        if t.dynamic_axial_stiffness is not None and t.tension_strain is None and t.axial_stiffness is not None:
            rows[e] = (*t.dynamic_axial_stiffness, t.dynamic_axial_damping or 0.0)
    return rows if np.any(rows[:, 0] > 0) else None
