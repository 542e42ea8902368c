"""A MoorDyn input file as a seacable mooring network, and its static or dynamic run.

Each MoorDyn point is a node (Fixed: an anchor; Vessel/Coupled: a fairlead moved by the vessel
motion, one channel each; Free: a connection point with its mass, volume, C_D A and C_a). Each line
gets ``NumSegs`` truss elements between its two points, with MoorDyn's line-type data: weight in
water ``(m - rho pi d^2 / 4) g``, axial damping ``BA`` (a negative BA is a damping ratio, MoorDyn's
rule, see :func:`seacable.io.moordyn.moordyn_axial_damping`; as in MoorDyn it acts in slack segments
too, ``Water.slack_damping``), normal and axial drag and added mass.
The seabed is MoorDyn's: flat at ``WtrDpth`` (without it, at the deepest point, as MoorDyn-C sets it),
``kBot`` and ``cBot`` per projected area (``cBot`` in full on a node pressed in, MoorDyn's rule,
``Water.full_seabed_damping``), friction coefficient ``FrictionCoefficient`` (regularised;
MoorDyn's own friction law differs in detail). Options seacable cannot honour (waves, currents,
bathymetry files, ...) are warned by :func:`prepare_moordyn`, each with what seacable does instead.
A line type's bending stiffness ``EI`` acts at the inner nodes of its lines (MoorDyn v2's nodal
bending, ends at points pinned; :func:`seacable.mooring.kernel.bending_loads`), a viscoelastic
``EA_s|EA_d`` (or ``EA_s|EA_Dc|EA_D_Lm``) with ``BA_s|BA_d`` runs MoorDyn v2's viscoelastic model
(:func:`seacable.mooring.kernel.viscoelastic_tension`; statics at EA_s), a nonlinear (table) EA with
its table; a Syrope rope with its working curves (:func:`seacable.mooring.kernel.syrope_tension`: quasi-static,
from SYROPE IC's Tmax, without MoorDyn's dynamic stiffness and slow damper), with a warning. Decks with bodies, rods
or points on a body or turbine are refused here: they run as a mooring system
(:meth:`seacable.io.moordyn.MoorDynCase.system`).
"""

from __future__ import annotations

import itertools
import math
import warnings

import numpy as np

from .._limits import check_run_size
from ..errors import ConvergenceError, InputError, NoSolutionError, SeacableWarning
from ..io.moordyn import (
    _DECK_MAX_STRAIN,
    MoorDynCase,
    MoorDynInput,
    check_water_kinematics,
    load_moordyn_case,
    moordyn_axial_damping,
    moordyn_system,
    read_moordyn,
)
from ..results import make_dataset, var, write_netcdf
from ..sink import open_sink
from ..system.statics import solve_equilibrium
from .motion import bind, forcing_period
from .network import FIXED, FREE, PRESCRIBED, Network, catenary_positions
from .run import (
    REFERENCES,
    line_end_forces,
    network_variables,
    output_count,
    point_variables,
    run_attributes,
    slack_variables,
    snap_variables,
    stored_per_output,
)
from .solver import MooringModel, MooringRun, Water, line_end_nodes, simulate, static_equilibrium

__all__ = ["CATENARY_TOLERANCE", "catenary_check", "moordyn_model", "prepare_moordyn", "run_moordyn_case",
           "run_moordyn_file"]

#: the relative difference [-] between a line end's tension in the lumped-mass network (the deck's NumSegs) and in
#: the exact elastic catenary above which a deck's run warns (the level of the deck comparisons with MoorPy)
CATENARY_TOLERANCE = 0.01

_KIND = {"fixed": FIXED, "vessel": PRESCRIBED, "free": FREE}


_WC_FORM = {"LINEAR": 1.0, "QUADRATIC": 2.0, "EXP": 3.0}  # kernel.V_WC codes of the Syrope working curves


def _line_length(md: MoorDynInput, line, pa, pb) -> float:
    if line.length > 0:
        return line.length
    # MoorDyn: a negative length is a factor on the distance between the two end points
    return -line.length * float(np.linalg.norm(np.subtract(pb.position, pa.position)))


def moordyn_model(md: MoorDynInput | str) -> MooringModel:
    """The :class:`~seacable.mooring.solver.MooringModel` of a MoorDyn input (a path or a parsed file)."""
    if not isinstance(md, MoorDynInput):
        md = read_moordyn(md)
    _check_network_only(md)
    rho, g = md.water_density, md.gravity
    depth = md.water_depth
    points = {p.id: p for p in md.points}
    node_of = {pid: k for k, pid in enumerate(points)}
    n_pts = len(points)
    pos = [np.asarray(p.position, float) for p in points.values()]
    kind = [_KIND[p.attachment] for p in points.values()]
    channel = np.full(n_pts, -1, np.int64)
    vessels = [k for k, p in enumerate(points.values()) if p.attachment == "vessel"]
    channel[vessels] = np.arange(len(vessels))
    pm = np.array([p.mass for p in points.values()], float)
    pv = np.array([p.volume for p in points.values()], float)
    pd = np.array([p.drag_area for p in points.values()], float)
    pa = np.array([p.added_mass_coefficient * rho * p.volume for p in points.values()], float)
    pw = (pm - rho * pv) * g
    arc = [np.nan] * n_pts
    elements, props, element_line, line_nodes = [], [], [], []
    tables = []  # per element: its line type's strain-tension table (MoorDyn's nonlinear EA) or None
    bending, visco = [], []  # per element: EI; (EA_Dc, EA_D_Lm, BA_D) of a viscoelastic line type
    syrope = []  # per element: (form, k1, k2, Tmax0) of a Syrope rope's working curves, zeros otherwise
    for li, line in enumerate(md.lines):
        A, B = points[line.point_a], points[line.point_b]
        L = _line_length(md, line, A, B)
        # the line's pieces: (line type, length, elements); several for a CableDyn line of SECTIONS
        pieces = [(md.line_types[t], length, k) for t, length, k in line.sections] or \
            [(md.line_types[line.line_type], L, line.n_segments)]
        tmax0 = getattr(md, "syrope_ic", {}).get(line.id, (0.0, 0.0))[0]
        n = line.n_segments
        ws = [(lt.mass_per_length - rho * (math.pi * lt.diameter**2 / 4)) * g for lt, _, _ in pieces]
        if len(pieces) == 1:
            s = np.linspace(0.0, L, n + 1)
        else:
            ends = np.cumsum([0.0] + [length for _, length, _ in pieces])
            s = np.concatenate([np.linspace(ends[k], ends[k + 1], p[2] + 1)[:-1] for k, p in enumerate(pieces)]
                               + [[L]])
        lengths, eas = [length for _, length, _ in pieces], [lt.axial_stiffness for lt, _, _ in pieces]
        # the catenary is solved from the lower end up (a sectioned line's buoyant sections in it: a lazy wave)
        up = A.position[2] <= B.position[2]
        cable = len(pieces) > 1
        guess = (catenary_positions(A.position, B.position, s, lengths, ws, eas, depth=depth, buoyant=cable)
                 if up else catenary_positions(B.position, A.position, L - s, lengths[::-1], ws[::-1], eas[::-1],
                                               depth=depth, buoyant=cable))
        first = len(pos)
        pos.extend(guess[1:-1])
        kind.extend([FREE] * (n - 1))
        arc.extend(s[1:-1])
        ids = [node_of[A.id], *range(first, first + n - 1), node_of[B.id]]
        line_nodes.append(np.array(ids, np.int64))
        elements.extend(itertools.pairwise(ids))
        element_line.extend([li] * n)
        for (lt, length, k), w in zip(pieces, ws):
            wc = getattr(lt, "syrope", None) if lt.tension_strain is not None else None
            seg = length / k
            c = moordyn_axial_damping(lt.axial_damping, lt.axial_stiffness, lt.mass_per_length, seg)
            # the piece's k elements share their line type's values: each list extended by k copies at once
            dyn = lt.dynamic_stiffness
            props.extend([(seg, lt.axial_stiffness, c, lt.mass_per_length, w, lt.diameter, lt.drag_normal,
                           lt.drag_tangential, lt.added_mass_normal, lt.added_mass_tangential)] * k)
            tables.extend([lt.tension_strain] * k)
            bending.extend([lt.bending_stiffness] * k)
            visco.extend([(dyn[0], dyn[1] if len(dyn) > 1 else 0.0, lt.dynamic_damping or 0.0)
                          if dyn is not None and lt.tension_strain is None else (0.0, 0.0, 0.0)] * k)
            syrope.extend([(_WC_FORM[wc[0]], wc[1], wc[2], tmax0) if wc is not None else (0.0, 0.0, 0.0, 0.0)] * k)
    special = [lt.name for lt in md.line_types.values() if getattr(lt, "syrope", None) is not None]
    for name in special:
        warnings.warn(f"line type {name} is a Syrope rope: its tension follows its working curves quasi-statically "
                      "(the curve of the largest mean tension so far, from SYROPE IC's Tmax), without the dynamic "
                      "stiffness EA_Dc|EA_D_Lm and the slow damper of MoorDyn's Syrope model.", SeacableWarning,
                      stacklevel=2)
    visco = np.array(visco, float)
    syrope = np.array(syrope, float)
    n_nodes = len(pos)
    extra = n_nodes - n_pts
    P = np.array(props, float)

    def pad(a):
        return np.concatenate((a, np.zeros(extra)))

    pm, pa, pw, pv, pd = (pad(a) for a in (pm, pa, pw, pv, pd))
    pda = pd.copy()
    for li, line in enumerate(md.lines):  # CableDyn's ATTACHMENTS: at the node nearest each one's arc length
        nodes = line_nodes[li]
        s_nodes = np.array([0.0, *np.asarray(arc)[nodes[1:-1]], line.length]) if len(nodes) > 2 else None
        for s, mass, volume, cda, ca, cdax in line.attachments:
            i = nodes[int(np.argmin(np.abs(s_nodes - s)))] if s_nodes is not None else nodes[0]
            pm[i] += mass
            pv[i] += volume
            pw[i] += (mass - rho * volume) * g
            pa[i] += ca * rho * volume
            pd[i] += cda
            pda[i] += cdax

    net = Network(position=np.array(pos), kind=np.array(kind, np.int64),
                  channel=np.concatenate((channel, -np.ones(extra, int))),
                  point_mass=pm, point_added_mass=pa, point_weight=pw, point_volume=pv,
                  point_drag_area=pd, point_axial_drag_area=None if np.array_equal(pda, pd) else pda,
                  elements=np.array(elements, np.int64), length=P[:, 0],
                  axial_stiffness=P[:, 1], axial_damping=P[:, 2], mass_per_length=P[:, 3],
                  weight_per_length=P[:, 4], diameter=P[:, 5], cdn=P[:, 6], cdt=P[:, 7], can=P[:, 8], cat=P[:, 9],
                  element_line=np.array(element_line, np.int64), line_nodes=tuple(line_nodes),
                  line_names=tuple(f"line {ln.id}" for ln in md.lines), arc_length=np.array(arc, float),
                  element_tension_strain=tuple(tables) if any(t is not None for t in tables) else None,
                  bending_stiffness=np.array(bending, float) if any(bending) else None,
                  element_viscoelastic=visco if np.any(visco[:, 0] > 0) else None,
                  element_syrope=syrope if np.any(syrope[:, 0] > 0) else None,
                  n_channels=len(vessels), channel_names=tuple(f"point {p.id}" for p in points.values()
                                                               if p.attachment == "vessel"),
                  end_hinges=_end_hinges(md, bending))
    water = Water(density=rho, gravity=g, depth=depth, seabed_stiffness=md.kbot, seabed_damping=md.cbot,
                  friction=md.friction, slack_damping=True,  # MoorDyn's damper acts in slack segments too
                  full_seabed_damping=True)  # and cBot in full on a penetrating node
    return MooringModel(net, water)


def _end_hinges(md: MoorDynInput, bending) -> tuple:
    """The network's ``end_hinges`` of CableDyn's END CONNECTIONS held in bending (clamped, or a rotational spring),
    their directions global; refuses one at an end whose element has no bending stiffness."""
    ends = getattr(md, "end_connections", {})
    index = {ln.id: li for li, ln in enumerate(md.lines)}
    first = np.cumsum([0] + [ln.n_segments for ln in md.lines])
    out = []
    for (lid, end), (kind, stiffness, direction) in sorted(ends.items()):
        li = index[lid]
        e = first[li] if end == 0 else first[li + 1] - 1
        if not bending[e] > 0:
            raise InputError(f"END CONNECTIONS line {lid} End {'AB'[end]} is {'rigid' if kind == 'clamp' else 'a spring'}"
                             f", but the line's end element there has no bending stiffness (EI = {bending[e]:g} N m^2): "
                             "a moment at the end needs a line that bends. Suggested fix: give the line type its EI, "
                             "or write Pinned.")
        out.append((li, end, kind, stiffness, direction))
    return tuple(out)


def _line_view(model: MooringModel, li: int) -> MooringModel:
    """A single line of a network as its own network (node 0 at end A), for the line's variables."""
    net = model.network
    nodes = net.line_nodes[li]
    els = np.flatnonzero(net.element_line == li)
    remap = np.full(net.n_nodes, -1)
    remap[nodes] = np.arange(len(nodes))
    sub = {f: getattr(net, f)[nodes] for f in ("position", "kind", "channel", "point_mass", "point_added_mass",
                                               "point_weight", "point_volume", "point_drag_area", "arc_length")}
    sub.update({f: getattr(net, f)[els] for f in ("length", "axial_stiffness", "axial_damping", "mass_per_length",
                                                  "weight_per_length", "diameter", "cdn", "cdt", "can", "cat")})
    view = Network(**sub, elements=remap[net.elements[els]], element_line=np.zeros(len(els), np.int64),
                   line_nodes=(np.arange(len(nodes)),), line_names=(net.line_names[li],),
                   n_channels=net.n_channels, channel_names=net.channel_names,
                   element_tension_strain=None if net.element_tension_strain is None
                   else tuple(net.element_tension_strain[e] for e in els),
                   bending_stiffness=None if net.bending_stiffness is None else net.bending_stiffness[els],
                   element_viscoelastic=None if net.element_viscoelastic is None else net.element_viscoelastic[els],
                   element_syrope=None if net.element_syrope is None else net.element_syrope[els],
                   end_hinges=tuple((0, *h[1:]) for h in net.end_hinges if h[0] == li))
    # a network of one line: the view is that line renumbered, which the model's own check covered (the same
    # nodes, positions and elements)
    line = MooringModel(view, model.water, checked=len(net.line_nodes) == 1)
    line.sea, line._sea_spec = model.sea, model._sea_spec  # an irregular sea's grid, when the run has one
    return line


def _line_views(model: MooringModel) -> list[MooringModel]:
    """Every line of the network as its own network (:func:`_line_view`), built once for a run's checks and
    outputs (each output block refreshes their sea: :func:`_variables`)."""
    return [_line_view(model, li) for li in range(len(model.network.line_nodes))]


def _reads_network(model: MooringModel, view: MooringModel) -> bool:
    """Whether a line's view (:func:`_line_view`) evaluates its nodes as ``model`` does, so that the network's
    support forces and tensions hold the line's own end loads where :func:`seacable.mooring.run.line_end_forces`
    can read them: the network is that one line, in the same environment."""
    return len(model.network.line_nodes) == 1 and np.array_equal(view.env, model.env)


def catenary_check(md: MoorDynInput, model: MooringModel, position, views=None, *, support=None,
                   tension=None) -> float | str:
    """Compare the network's static end tensions with the exact elastic catenaries of the same deck; warn if they differ.

    The lumped-mass network has the deck's ``NumSegs`` per line. Where a line bends more sharply than its segments
    can follow (at a touchdown point the radius of curvature of a catenary is ``H / w``, horizontal tension over
    wet weight per length, 2.3 m for the r-test MHK_RM1 chains on 5 m segments), the network's horizontal
    tension, and with it the anchor and fairlead tensions, is off by up to tens of percent (13 % there), shrinking
    as the segments are refined. The deck is solved again as a mooring system of exact elastic catenaries on a flat
    frictionless seabed (:func:`seacable.io.moordyn.moordyn_system`, :func:`seacable.system.statics.solve_equilibrium`:
    the model MoorPy solves, agreeing with it to 1e-4 on the vendored decks) and each line end's tension compared.
    Lines the catenary does not model as the network does are left out: a Syrope rope (the network follows its
    working curve from SYROPE IC's Tmax), and a line whose bending stiffness matters (bending length
    ``sqrt(EI / T)`` over 5 % of the line: MoorDyn's BeamSimplySupported, 74 %; its VIV decks, 1.7 %, and the
    Lowe and Langley jumper, 0.9 %, agree with the catenary to 0.4 %).

    Parameters
    ----------
    md : MoorDynInput
        The deck.
    model : MooringModel
        Its network (:func:`moordyn_model`).
    position : ndarray
        The network's static node positions (``static_equilibrium(model).position``). [m]
    views : list of MooringModel, optional
        Each line of the network as its own network (:func:`_line_views`), when the caller has them.
    support, tension : ndarray, optional
        The network's support forces and element tensions at ``position`` (``static_equilibrium(model)``'s):
        a line's end tensions are read from them where they are its own (:func:`_reads_network`), the same
        floats as evaluating the line's ends. [N]

    Returns
    -------
    float or str
        The largest relative difference of a compared line end's tension [-] (its denominator the catenary's
        tension, at least 1e-3 of the line's larger end tension; an end the catenary leaves slack, under 1e-3 of the
        line's wet weight, is not compared), or why nothing was compared.

    Warns
    -----
    SeacableWarning
        When an end differs by more than :data:`CATENARY_TOLERANCE`, naming each such end with the two tensions,
        the line's segment length and its catenary's ``H / w``, and the fix (more segments).
    """
    label = md.path or "MoorDyn file"
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the deck's own notes are warned by prepare_moordyn
            system, env = moordyn_system(md)
            env = env.model_copy(update={"seabed": env.seabed.model_copy(update={"friction": 0.0})})
            eq = solve_equilibrium(system, env, max_strain=_DECK_MAX_STRAIN)
    except (InputError, NoSolutionError, ConvergenceError) as exc:
        return f"not checked: the exact catenaries of the deck were not solved ({str(exc).splitlines()[0][:200]})"
    X = np.asarray(position, float)
    net = model.network
    rho, g = md.water_density, md.gravity
    worst, flagged, skipped = 0.0, [], []
    for k, line in enumerate(md.lines):
        lt = md.line_types[line.line_type]
        cat = (float(eq.end_a_tension[k]), float(eq.end_b_tension[k]))
        seg = float(np.sum(net.length[net.element_line == k])) / line.n_segments
        bending = math.sqrt(lt.bending_stiffness / max(max(cat), 1e-300))
        # a bending stiffness the catenary leaves out: its boundary layer where the line bends most (a touchdown,
        # curvature w / H) changes the end tension by about EI (w / H)^2 / 2 (Irvine's boundary-layer correction); a
        # line where that is over a tenth of the tolerance is not compared (a lazy-wave cable: 5 %)
        boundary_layer = 0.0
        if lt.bending_stiffness > 0:
            wet = max(abs((md.line_types[name].mass_per_length - md.water_density * math.pi
                           * md.line_types[name].diameter**2 / 4) * md.gravity)
                      for name in {line.line_type, *(sec[0] for sec in (getattr(line, "sections", None) or ()))})
            horizontal = math.hypot(*np.asarray(eq.end_a_force[k], float)[:2])
            boundary_layer = (0.5 * lt.bending_stiffness * wet**2 / horizontal**3 if horizontal > 0.0
                              else math.inf)
        if (getattr(lt, "syrope", None) is not None or bending > 0.05 * line.n_segments * seg
                or boundary_layer > 0.1 * CATENARY_TOLERANCE):
            skipped.append(line.id)
            continue
        view = _line_view(model, k) if views is None else views[k]
        mine = {}
        if support is not None and tension is not None and _reads_network(model, view):
            mine = {"support": np.asarray(support)[net.line_nodes[k]],
                    "tension": np.asarray(tension)[np.flatnonzero(net.element_line == k)]}
        ends = line_end_forces(view, X[net.line_nodes[k]], **mine)
        w = (lt.mass_per_length - rho * math.pi * lt.diameter**2 / 4) * g
        floor = max(1e-3 * max(cat), 1e-9)
        # an end the catenary leaves slack (under 1e-3 of the line's wet weight) is not compared: the network's
        # compliant seabed (kBot) stretches it (a chain lying straight between two anchors on the seabed, sunk 5 mm
        # into it, carries 0.3 % of its weight; the rigid seabed of the catenary, nothing)
        slack = 1e-3 * abs(w) * float(np.sum(net.length[net.element_line == k]))
        for j, end in enumerate("AB"):
            ours = float(np.linalg.norm(ends[j]))
            if cat[j] < slack:
                continue
            diff = abs(ours - cat[j]) / max(cat[j], floor)
            worst = max(worst, diff)
            if diff > CATENARY_TOLERANCE:
                force = eq.end_a_force[k] if j == 0 else eq.end_b_force[k]
                bend = (f", its catenary's H / w {math.hypot(force[0], force[1]) / w:.3g} m" if w > 0 else "")
                flagged.append((diff, f"line {line.id} end {end}: {ours:.6g} N in the network, {cat[j]:.6g} N in the "
                                      f"exact catenary ({100 * (ours / cat[j] - 1) if cat[j] > 0 else 100:+.3g} %; "
                                      f"{line.n_segments} segments of {seg:.3g} m{bend})"))
    if flagged:
        flagged.sort(key=lambda item: -item[0])
        shown = "; ".join(text for _, text in flagged[:6]) + (f"; and {len(flagged) - 6} more" if len(flagged) > 6
                                                              else "")
        warnings.warn(f"{label}: the static end tensions of the lumped-mass network (the deck's NumSegs) differ from "
                      f"the exact elastic catenaries of the same lines by up to {100 * flagged[0][0]:.3g} % (more than "
                      f"{100 * CATENARY_TOLERANCE:g} %): {shown}. The segments are too long for where the line bends "
                      "most (at a touchdown point the catenary's radius of curvature is H / w); the difference shrinks "
                      "as the segments are refined (MoorDyn's lumped-mass line is discretised the same way). Suggested "
                      "fix: raise NumSegs of those lines (until the segments are well under H / w), or take the "
                      "statics from the exact catenaries (MoorDynCase.system() and system_static).",
                      SeacableWarning, stacklevel=3)
    if skipped and worst == 0.0 and not flagged and len(skipped) == len(md.lines):
        return "not checked: every line is a Syrope rope or has a bending stiffness the catenary does not model"
    return worst


def _dataset(model: MooringModel, X, T, S, *, title, settings, views=None):
    """The static result of a deck (:func:`_variables`)."""
    data, coords = _variables(model, X, T, S, views=views)
    ds = make_dataset(data, coords, **_provenance(model, title, settings, static=True))
    ds.attrs.update(_depth(model))
    return ds


def _depth(model: MooringModel) -> dict:
    return {} if model.water.depth is None else {"depth": float(model.water.depth)}


def _provenance(model: MooringModel, title, settings, static=False) -> dict:
    """The keywords of :func:`seacable.results.make_dataset` for a deck's result."""
    return {"analysis": "mooring_static" if static else "mooring_dynamic", "references": REFERENCES, "title": title,
            "settings": settings}


def _variables(model: MooringModel, X, T, S, time=None, *, velocity=None, acceleration=None, kinematic_nodes=None,
               extra=None, views=None):
    """Variables per line, a ``line`` dimension (NaN padded) when there are several lines; the points' forces.
    Returns the variables and the coordinates.

    ``velocity`` and ``acceleration`` (time-domain runs) let each line's end tensions include its half end
    element's water loads and inertia (:func:`seacable.mooring.run.network_variables`); ``kinematic_nodes``
    the nodes they hold (None: all); ``extra`` more variables; ``views`` the lines as networks (:func:`_line_views`;
    None: built here)."""
    net = model.network
    n_lines = len(net.line_nodes)
    # several lines: each variable in one (line, ...) array, NaN-padded to the longest line, filled line by line
    # (a line's own variables dropped once copied: the peak memory of a long run is the run plus one line)
    width = {"node": max(len(nodes) for nodes in net.line_nodes),
             "element": int(np.max(np.bincount(net.element_line, minlength=n_lines)))}
    filled = {}
    for li in range(n_lines):
        if views is None:
            view = _line_view(model, li)
        else:  # built before the run: the run's sea, as _line_view gives it
            view = views[li]
            view.sea, view._sea_spec = model.sea, model._sea_spec
        nodes = net.line_nodes[li]
        els = np.flatnonzero(net.element_line == li)
        dims = ("node",) if time is None else ("time", "node")
        if time is None:
            moving = {}
        elif kinematic_nodes is None:
            moving = {"velocity": velocity[..., nodes, :], "acceleration": acceleration[..., nodes, :], "time": time}
        else:  # the kinematics of some nodes only (simulate's ``kinematics``): those of this line, renumbered
            local = np.full(net.n_nodes, -1)
            local[nodes] = np.arange(len(nodes))
            mine = np.flatnonzero(local[kinematic_nodes] >= 0)
            moving = {"velocity": velocity[..., mine, :], "acceleration": acceleration[..., mine, :], "time": time,
                      "kinematic_nodes": local[kinematic_nodes[mine]]}
        # the line's support forces are read at its two end nodes only, where they are its own end loads (the
        # element tensions stay a fancy-indexed copy: its memory order, which later sums follow)
        own = _reads_network(model, view)
        line = network_variables(view, X[..., nodes, :], T[..., els], None, dims=dims, own_support=own,
                                 end_support=S[..., nodes[[0, -1]], :] if own else None, **moving)
        if n_lines == 1:
            data = line
            coords = {"node": var("node", np.arange(view.network.n_nodes), "1", "node index, 0 at end A"),
                      "s": var("node", _arc(view.network), "m", "unstretched arc length from end A")}
            break
        for name, v in line.items():
            a = np.asarray(v.values, float)
            if name not in filled:
                filled[name] = (np.full((n_lines,) + tuple(width.get(d, k) for d, k in zip(v.dims, a.shape)), np.nan),
                                ("line",) + v.dims, v.attrs["units"], v.attrs["long_name"])
            filled[name][0][(li,) + tuple(slice(0, k) for k in a.shape)] = a
        del line
    if n_lines > 1:
        data = {name: var(dims, values, units, long_name) for name, (values, dims, units, long_name) in filled.items()}
        coords = {"line": var("line", list(net.line_names), "1", "line"),
                  "node": var("node", np.arange(width["node"]), "1", "node index, 0 at end A")}
    data.update(point_variables(model, S, dims=("node",) if time is None else ("time", "node")))
    data.update(extra or {})
    if time is not None:
        coords["time"] = var("time", time, "s", "time")
    return data, coords


def _written(ds, out):
    """``ds``, written to the NetCDF file ``out`` first when one is given."""
    if out is not None:
        write_netcdf(ds, out)
    return ds


def _arc(net: Network):
    return np.concatenate(([0.0], np.cumsum(net.length)))


def _check_network_only(md: MoorDynInput) -> None:
    """Refuse a deck the line network cannot carry: bodies, rods, points on a body or turbine, a line
    without any line (these run as a mooring system: :meth:`seacable.io.moordyn.MoorDynCase.system`)."""
    parts = []
    if md.bodies:
        parts.append(f"{len(md.bodies)} body(ies)")
    if md.rods:
        parts.append(f"{len(md.rods)} rod(s)")
    on = [p.id for p in md.points if p.attachment in ("body", "turbine")]
    if on:
        parts.append(f"points {', '.join(map(str, on))} on a body or turbine")
    if parts or not md.lines:
        what = ", ".join(parts) if parts else "no lines"
        raise InputError(f"{md.path or 'MoorDyn file'}: this deck has {what}; the MoorDyn line network "
                         "(mooring_static/mooring_dynamic) holds lines and points only. Suggested fix: run it as a "
                         "mooring system (MoorDynCase.system() gives its MooringSystem and Environment for the "
                         "system analyses).")


def _check_geometry(md: MoorDynInput) -> None:
    """Refuse a Free point without a line (the geometry of the lines is checked with every mooring model:
    :func:`seacable.mooring.checks.check_network`)."""
    _check_network_only(md)
    attached = {ln.point_a for ln in md.lines} | {ln.point_b for ln in md.lines}
    for p in md.points:
        if p.attachment == "free" and p.id not in attached:
            raise InputError(f"{md.path or 'MoorDyn file'}: point {p.id} is Free but no line is attached to it: "
                             "it has no equilibrium (it sinks or floats away). Suggested fix: attach a line to it "
                             "in the LINES section, or remove the point.")


def prepare_moordyn(case) -> MooringModel:
    """Every check of a MoorDyn case that can be made before its run; the model the run needs.

    Warns (:class:`~seacable.errors.SeacableWarning`) with each of the file's ``notes``: an option
    seacable cannot honour (named with its value and what seacable does instead), an unknown
    option. Refuses (:class:`~seacable.errors.InputError`) a dynamic run of a deck with non-zero WaveKin or
    Currents (:func:`seacable.io.moordyn.check_water_kinematics`), a free point without a line, the
    geometry :func:`seacable.mooring.checks.check_network` refuses for every mooring model, and a dynamic run whose steps or stored results exceed the limits of
    :mod:`seacable._limits`.

    Parameters
    ----------
    case : MoorDynCase, str or pathlib.Path
        The case (:func:`seacable.io.moordyn.load_moordyn_case`), or the file.

    Returns
    -------
    MooringModel
        The network of the file in its water.
    """
    if not isinstance(case, MoorDynCase):
        case = load_moordyn_case(case)
    md = case.data
    for note in md.notes:
        warnings.warn(note, SeacableWarning, stacklevel=2)
    _check_geometry(md)
    try:
        model = moordyn_model(md)
    except InputError as err:  # the network's own checks: say which file
        raise InputError(f"{md.path or 'MoorDyn file'}: {err}") from None
    if case.duration is not None:
        check_water_kinematics(md, "a mooring_dynamic run")
        net = model.network
        stored = (math.floor(case.duration / case.output_interval) + 1) * stored_per_output(
            net, model.water.depth is not None)
        check_run_size(f"the mooring_dynamic run of {case.name}", steps=case.duration / case.time_step,
                       stored_values=stored, fix="shorten the duration, or lengthen the time step or the output "
                                                 "interval")
    return model


def run_moordyn_case(case, *, tolerance: float = 1e-8, progress=None, out=None):
    """Run a :class:`~seacable.io.moordyn.MoorDynCase`: the static equilibrium and, with a duration, the response.

    ``case.motion`` (:mod:`seacable.mooring.motion`) moves every vessel point; None holds them still. Returns a
    Dataset with the names of the ``mooring_static`` / ``mooring_dynamic`` analyses (a ``line`` dimension with
    several lines). ``progress(t, duration)`` is called as a dynamic run advances. ``out``: a NetCDF file the
    result is written to; a dynamic run writes its outputs into it as they are computed
    (:class:`seacable.sink.NetcdfSink`: its memory is that of a block of outputs, whatever its length), and the
    Dataset returned reads from the file.
    """
    if not isinstance(case, MoorDynCase):
        raise InputError(f"run_moordyn_case takes a MoorDynCase, got {type(case).__name__}. Suggested fix: "
                         "seacable.load_case('lines.txt').")
    model = prepare_moordyn(case)
    md = case.data
    st = static_equilibrium(model, tol=tolerance)
    title = md.title or str(md.path)
    settings = {"source": str(md.path), "elements": int(model.network.n_elements), "format": "MoorDyn"}
    views = _line_views(model)
    checked = catenary_check(md, model, st.position, views, support=st.support, tension=st.tension)
    if case.duration is None:
        ds = _dataset(model, st.position, st.tension, st.support, title=title, settings=settings,
                      views=views)
        ds.attrs["catenary_difference"] = checked
        return _written(ds, out)
    fn = bind(case.motion, model.network.channel_positions(st.position), case.duration)
    with open_sink(output_count(case.duration, case.output_interval), out) as sink:

        def outputs(block: MooringRun):
            sink.append(*_variables(model, block.position, block.tension, block.support, block.time,
                                    velocity=block.velocity, acceleration=block.acceleration,
                                    kinematic_nodes=block.kinematic_nodes, extra=slack_variables(block),
                                    views=views))

        run: MooringRun = simulate(model, fn, case.duration, case.time_step, case.output_interval,
                                   initial=st.position, tol=tolerance * 10, progress=progress,
                                   spectral_radius=case.spectral_radius, forcing_period=forcing_period(case.motion),
                                   kinematics=line_end_nodes(model.network), on_outputs=outputs)
        events = snap_variables(sink, model.network)
    settings = {**settings, "time_step": run.time_step, "steps": run.steps, "spectral_radius": run.spectral_radius}
    return sink.finish(events, attrs={**_depth(model), **run_attributes(run), "catenary_difference": checked},
                       **_provenance(model, title, settings))


def run_moordyn_file(path, *, duration: float | None = None, motion=None, time_step: float = 0.1,
                     output_interval: float = 0.5, tolerance: float = 1e-8, progress=None,
                     spectral_radius: float = 1.0):
    """Run a MoorDyn input file: the static equilibrium, and with ``duration`` the response to ``motion``.

    ``motion`` is a fairlead motion of :mod:`seacable.mooring.motion` applied to every vessel point;
    ``None`` holds them still; ``spectral_radius`` that of the generalised-alpha scheme (1: average
    acceleration). Returns a Dataset with the names of the
    ``mooring_static`` / ``mooring_dynamic`` analyses (a ``line`` dimension with several lines).
    The same as ``run_moordyn_case(load_moordyn_case(path).with_run(...))``.
    """
    case = load_moordyn_case(path).with_run(duration=duration, motion=motion, time_step=time_step,
                                            output_interval=output_interval, spectral_radius=spectral_radius)
    return run_moordyn_case(case, tolerance=tolerance, progress=progress)
