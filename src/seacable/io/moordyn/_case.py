"""A MoorDyn deck as a case (:class:`MoorDynCase`, :func:`load_moordyn_case`): how it runs, and, for a deck
with bodies, rods or points on a body, the :class:`~seacable.system.case.SystemCase` it runs as."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from pathlib import Path

from ... import _validate
from ...errors import InputError
from ._convert import moordyn_system
from ._read import check_water_kinematics, read_moordyn
from ._records import MoorDynInput


@dataclass(frozen=True)
class MoorDynCase:
    """A MoorDyn input file as a case: the file's network and how to run it.

    What :func:`seacable.load_case` returns for a MoorDyn file and :func:`seacable.run` runs
    (``mooring_static`` without ``duration``, ``mooring_dynamic`` with it). Build one with
    :func:`load_moordyn_case`; :meth:`with_run` sets the run.

    Parameters
    ----------
    data
        The file, as read by :func:`read_moordyn`.
    name
        Short name, used for output files (default: the file's stem).
    duration
        Simulated time after the static equilibrium; None for statics only. [s]
    motion
        Vessel-point motion (:mod:`seacable.mooring.motion`); None holds the vessel points still.
    time_step
        Newmark time step. [s]
    output_interval
        Time between stored states. [s]
    spectral_radius
        Generalised-alpha amplification per step of the modes far above 1 / time_step (1: Newmark's
        average acceleration, no numerical damping; :func:`seacable.mooring.solver.generalized_alpha`). [-]
    """

    data: MoorDynInput
    name: str = "moordyn"
    duration: float | None = None
    motion: object = None
    time_step: float = 0.1
    output_interval: float = 0.5
    spectral_radius: float = 1.0

    @property
    def path(self) -> str | None:
        """The file's path (None for text)."""
        return self.data.path

    @property
    def analysis_type(self) -> str:
        """``'mooring_static'`` or, with a ``duration``, ``'mooring_dynamic'``; ``system_static`` and
        ``system_dynamic`` for a deck with bodies, rods or points on a body (:meth:`system_case`)."""
        kind = "system" if self.has_structures else "mooring"
        return f"{kind}_static" if self.duration is None else f"{kind}_dynamic"

    def with_run(self, *, duration=None, motion=None, time_step=None, output_interval=None,
                 spectral_radius=None) -> MoorDynCase:
        """The same file with a run set (each argument None keeps the current value).

        Raises
        ------
        InputError
            A duration, time step or output interval that is not a positive finite number of
            seconds, a motion without a duration, an output interval shorter than the step, or a
            spectral radius outside [0, 1].
        """
        rho = self.spectral_radius if spectral_radius is None else _validate.in_range(
            "spectral radius", spectral_radius, 0.0, 1.0, "", "use 1 (average acceleration, the default) or 0.8")
        duration = self.duration if duration is None else _validate.positive(
            "duration", duration, "s", "give the simulated time in seconds, e.g. 100")
        time_step = self.time_step if time_step is None else _validate.positive(
            "time step", time_step, "s", "give the Newmark time step in seconds, e.g. 0.1")
        interval = self.output_interval if output_interval is None else _validate.positive(
            "output interval", output_interval, "s", "give the time between stored states, e.g. 0.5")
        motion = self.motion if motion is None else motion
        if motion is not None and duration is None:
            raise InputError("a vessel motion needs a duration (s): the length of the run. Suggested fix: "
                             "give the duration too (--duration on the command line).")
        if interval < time_step:
            raise InputError(f"output interval must be >= the time step {time_step:g} s, got {interval:g} s. "
                             "Suggested fix: store every step at most (output interval = time step).")
        return dataclasses.replace(self, duration=duration, motion=motion, time_step=time_step,
                                   output_interval=interval, spectral_radius=rho)

    @property
    def has_structures(self) -> bool:
        """True when the deck has bodies, rods or points on a body or turbine: a system analysis runs it."""
        md = self.data
        return bool(md.bodies or md.rods or any(p.attachment in ("body", "turbine") for p in md.points))

    def system(self, *, turbine_positions: dict | None = None):
        """The deck as ``(MooringSystem, Environment)`` (:func:`moordyn_system`), for the system analyses."""
        return moordyn_system(self.data, turbine_positions=turbine_positions)

    def system_case(self):
        """The deck as a :class:`~seacable.system.case.SystemCase`: ``system_static``, or with a duration
        ``system_dynamic`` with the deck's ``FAILURE`` rows (what :func:`seacable.run` runs for a deck with
        bodies, rods or points on a body), started from the static equilibrium (``start: auto``: held where
        the deck puts the free bodies, with a warning, when that is not found), or with the free bodies
        held there when a free body has no line nor horizontal restoring (no static equilibrium; MoorDyn
        starts them so).

        Raises
        ------
        InputError
            What :func:`moordyn_system` refuses; a vessel ``motion`` of offsets x, y, z for a deck with a coupled
            body, or for a deck with nothing coupled (:func:`_deck_motions`: the coupled points follow ``motion``,
            the coupled bodies and rods its six platform motions about their reference points).
        """
        from ...system.case import SystemCase, SystemDynamicAnalysis, SystemStaticAnalysis

        label = self.data.path or "MoorDyn file"
        if self.duration is not None and self.spectral_radius != 1.0:
            raise InputError(f"{label}: spectral radius {self.spectral_radius:g}: a deck with bodies, rods or points "
                             "on a body runs as a mooring system, whose dynamics step by average acceleration only "
                             "(spectral radius 1). Suggested fix: leave out the spectral radius (--spectral-radius) "
                             "for this deck.")
        system, environment = self.system()
        if self.duration is None:
            analysis = SystemStaticAnalysis(max_strain=_DECK_MAX_STRAIN)
        else:
            from ...system.run import check_bodies_without_lines

            check_water_kinematics(self.data, "a system_dynamic run")

            try:  # a free body nothing holds has no static start: released where the deck puts it, as MoorDyn
                check_bodies_without_lines(system)
                start = "auto"  # the static start, or held where the deck puts the bodies when none is found
            except InputError:
                start = "held"
            body_motions, point_motions = _deck_motions(label, self.motion, system)
            analysis = SystemDynamicAnalysis(duration=self.duration, time_step=self.time_step,
                                             output_interval=self.output_interval,
                                             failures=_line_failures(self.data), start=start,
                                             body_motions=body_motions, point_motions=point_motions)
        return SystemCase(name=self.name, description=f"MoorDyn file {label}", environment=environment,
                          points=system.points, bodies=system.bodies, lines=system.lines, analysis=analysis)

    def describe(self) -> str:
        """One line for ``seacable validate``."""
        md = self.data
        segments = sum(ln.n_segments for ln in md.lines)
        length = sum(ln.length for ln in md.lines)
        depth = md.water_depth
        where = "no seabed" if depth is None else f"depth {depth:g} m"
        return (f"MoorDyn network, {self.analysis_type} analysis: {len(md.lines)} line(s), {len(md.points)} "
                f"point(s), {segments} segment(s), line length {length:g} m, {where}")


#: the largest line strain the statics of a MoorDyn deck accept: MoorDyn has no limit, and its test decks
#: model springs as lines stretched to 10 times their length (stability/spring.txt); above 10 % a warning says so
_DECK_MAX_STRAIN = 20.0


def _deck_motions(label: str, motion, system) -> tuple[dict, dict]:
    """The ``body_motions`` and ``point_motions`` of a deck with structures under one ``motion``, as MoorDyn's driver
    moves a deck: every coupled point (``point<ID>``, kind coupled) follows the motion as a deck without bodies does
    (offsets x, y, z; or the six platform motions about the origin), every coupled body or rod (and FAST.Farm turbine:
    the prescribed bodies) the six platform motions about its own reference point at rest.

    Raises
    ------
    InputError
        Offsets x, y, z for a deck with a coupled body (a body moves in six degrees of freedom), or a deck with
        nothing coupled to move.
    """
    if motion is None:
        return {}, {}
    points = {name: motion for name, p in system.points.items() if p.kind == "coupled"}
    prescribed = [name for name, b in system.bodies.items() if b.kind == "prescribed"]
    if prescribed and getattr(motion, "type", None) != "platform":
        raise InputError(f"{label}: the motion moves coupled bodies ({', '.join(prescribed)}), which move in six "
                         f"degrees of freedom, but it is a '{getattr(motion, 'type', motion)}' motion of offsets x, y, "
                         "z. Suggested fix: give a CSV of the platform motions with the header 'time, surge, sway, "
                         "heave, roll, pitch, yaw' [s, m, rad] (about each body's reference point at rest).")
    if not points and not prescribed:
        raise InputError(f"{label}: a vessel motion is given, but the deck has no coupled point, body or rod for it "
                         "to move. Suggested fix: leave out the motion (--motion), or make the fairleads 'Coupled'.")
    return {name: motion for name in prescribed}, points


def _line_failures(md: MoorDynInput) -> list:
    """The deck's ``FAILURE`` rows as :class:`~seacable.system.case.LineFailure` items (one per line end)."""
    from ...system.case import LineFailure

    out = []
    for f in md.failures:
        for line_id in f.lines:
            line = next((ln for ln in md.lines if ln.id == line_id), None)
            if line is None:
                raise InputError(f"{md.path or 'MoorDyn file'}: FAILURE {f.id} names line {line_id}, which the "
                                 "LINES section does not define. Suggested fix: name a line of the deck.")
            if isinstance(f.attachment, tuple):
                end = "a" if line.rod_a == f.attachment else "b" if line.rod_b == f.attachment else None
            else:
                end = "a" if line.point_a == f.attachment else "b" if line.point_b == f.attachment else None
            if end is None:
                raise InputError(f"{md.path or 'MoorDyn file'}: FAILURE {f.id}: line {line_id} does not end at "
                                 f"attachment {f.attachment}. Suggested fix: name the point (or rod end) the line "
                                 "ends at.")
            # a 0 disables that trigger; both 0 breaks the line at the start (MoorDyn-F)
            out.append(LineFailure(line=f"line{line_id}", end=end,
                                   time=f.time if f.time > 0 or not f.tension > 0 else None,
                                   tension=f.tension if f.tension > 0 else None))
    return out


def load_moordyn_case(path, *, name=None) -> MoorDynCase:
    """Read a MoorDyn input file (:func:`read_moordyn`) as a :class:`MoorDynCase` (statics).

    Parameters
    ----------
    path : str or pathlib.Path
        The MoorDyn file.
    name : str, optional
        The case name (default: the file's stem).
    """
    data = read_moordyn(path)
    return MoorDynCase(data, name=name or Path(path).stem or "moordyn")
