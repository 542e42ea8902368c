"""Read MoorDyn input files (v2, v1 and MoorDyn-F layouts) into plain records, and turn them into a system.

seacable reads every section of a MoorDyn deck: line types (constant, viscoelastic ``EA_s|EA_d``,
nonlinear strain-tension tables, Syrope ropes; bending stiffness EI kept), rod types, bodies, rods,
points (fixed, free, coupled, on a body, on a FAST.Farm turbine), lines (ends at points or rod ends),
failures, MoorDyn-F external loads, options and outputs. :func:`moordyn_system` turns the deck into a
:class:`~seacable.system.model.MooringSystem` and its environment for the system analyses; decks with
lines and points only also run as a line network (:mod:`seacable.mooring.moordyn`). What cannot be
read (MoorDyn-F's CONTROL section, a malformed row) is refused with an :class:`~seacable.errors.InputError`
naming the file and line, so that a file is never half read in silence.

File format (as MoorDyn-C reads it: ``MoorDyn::ReadInFile``, ``findStartOfSection``,
``readLineProps`` and ``readOptionsLine`` in ``source/MoorDyn2.cpp`` of FloatingArrayDesign/MoorDyn,
v2.0.0; v1 layout from ``docs/inputs.rst`` of the same repository):

- A section header is any line containing ``---``; its kind is found from a keyword in the
  upper-cased line: ``LINE DICTIONARY``/``LINE TYPES``; ``ROD DICTIONARY``/``ROD TYPES``;
  ``BODIES``/``BODY LIST``/``BODY PROPERTIES``; ``POINTS``/``POINT LIST``/``POINT PROPERTIES``/
  ``CONNECTION PROPERTIES``/``NODE PROPERTIES``; ``RODS``/``ROD LIST``/``ROD PROPERTIES``;
  ``LINES``/``LINE LIST``/``LINE PROPERTIES``; ``FAILURE``; ``OPTIONS``; ``OUTPUT``.
  Lines before the first section are free text (the title).
- A table section has two lines after its header, column names and units, which MoorDyn
  skips unread; the rows follow until the next header. ``OPTIONS`` and ``OUTPUTS`` have none.
- ``!``, ``#`` and ``%`` start a comment that runs to the end of the line, in every line after the
  title (``docs/inputs.rst`` of MoorDyn v2; MoorDyn-C 2.7.2 reads a commented row as the row before
  the comment, which matters for the 9- or 12-column POINTS layout).
- Options are ``value name [comment]``; the name is matched in any case (MoorDyn-F upper-cases it,
  MoorDyn-C's own examples write ``kbot``). Outputs are channel names, several per line allowed.
- The file ends at a header containing ``need this line`` or ``END``, or a line ``END``.
- LINE TYPES, v2 (10 columns): ``name d m EA BA/-zeta EI Cd Ca CdAx CaAx``; v1 (9 columns):
  ``name d m EA BA/-zeta Can Cat Cdn Cdt`` (no EI; coefficients in another order). The layout
  is taken from the column-names line (``EI`` present -> v2). EA may be ``EA_s|EA_d`` or
  ``EA_s|EA_Dc|EA_D_Lm`` (viscoelastic, with BA ``BA_s|BA_d``), a file of ``strain tension`` rows
  (read; lines that do not start with two numbers are skipped), or ``SYROPE:file|EA_Dc|EA_D_Lm``
  (a Syrope settings file naming its original working curve). A BA or EI table is refused.
- v1 count lines (``3 NLines - number of line objects``) opening a section are read and checked
  against the rows.
- ROD TYPES: ``name d m/l Cd Ca CdEnd CaEnd``. RODS: ``ID type attachment Xa Ya Za Xb Yb Zb NumSegs
  outputs``, attachment Fixed, Pinned, Free, Coupled/Vessel, CoupledPinned, BodyN, BodyNPinned,
  TurbineN. BODIES: ``ID attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca`` (CG, I, CdA, Ca one
  value or several separated by '|'), or the early MoorDyn-F layout ``1coupled X0 .. y0 Xcg Ycg Zcg
  M V IX IY IZ CdA Ca``. FAILURE: ``[ID] point-or-rod-end lines time tension``. EXTERNAL LOADS:
  ``ID object Fext Blin Bquad [CSys]``. SYROPE IC: ``lines Tmax0 Tmean0``.
- POINTS: ``ID type X Y Z mass volume CdA Ca``, or 12 columns with ``FX FY FZ`` before ``CdA``.
  Types: ``Fixed``/``Fix``/``Anchor`` -> ``'fixed'``; ``Vessel``/``Ves``/``Coupled``/``Cpld``/
  ``Fairlead`` -> ``'vessel'``; ``Free``/``Point``/``Connect``/``Con`` -> ``'free'``; ``BodyN`` ->
  ``'body'``; ``TurbineN`` -> ``'turbine'``.
- LINES, v2: ``ID type AttachA AttachB UnstrLen NumSegs outputs``; v1 (``LINE PROPERTIES``
  with ``UnstrLen`` in the 3rd column): ``ID type UnstrLen NumSegs NodeAnch NodeFair flags``.
  An attachment is a point number, optionally prefixed ``C``, ``Con``, ``P`` or ``Point``, or a
  rod end ``R1A``/``R1B``. MoorDyn looks the number up by *position* in the point list (it never
  reads the ID column), and so does seacable, with a warning when the IDs are not 1..N in order. A negative ``UnstrLen`` is, as in
  MoorDyn's ``Line::initialize``, a factor on the distance between the two end points.

Physics MoorDyn attaches to these inputs (``source/Line.cpp``, ``Line::initialize`` and
``Line::getStateDeriv``, FloatingArrayDesign/MoorDyn; defaults from the ``MoorDyn`` constructor
in ``source/MoorDyn2.cpp``), for models that convert a MoorDyn file:

- Internal damping: a segment of unstretched length ``l`` carries the axial damping force
  ``BA * (dl_str/dt) / l`` along the segment, whatever its strain (a slack segment, which carries
  no elastic tension, is still damped; MoorDyn's ``Line.cpp``). ``BA >= 0`` is used as written [N s]; ``BA < 0``
  means ``zeta = -BA`` and MoorDyn sets ``BA = zeta * l * sqrt(EA * m)`` with ``l = L / N``
  (``c = -BAin * UnstrLen / N * sqrt(E * rho)`` per unit area). ``zeta`` is the damping ratio of
  the highest axial mode of the lumped-mass line (adjacent nodes out of phase):
  ``k = 4 EA / l``, ``M = m l``, ``c = 4 BA / l`` give ``c / (2 sqrt(k M)) = BA / (l sqrt(EA m))``.
  See :func:`moordyn_axial_damping`.
- Seabed, per node ``i`` below the seabed ``z_b`` (vertical only):
  ``B_z = ((z_b - z_i) * kBot - dz_i/dt * cBot) * d * l_i`` with ``l_i`` half the sum of the
  adjacent unstretched segment lengths (half one segment at an end node).
  Defaults ``kBot = 3.0e6 Pa/m``, ``cBot = 3.0e5 Pa s/m``.
- Seabed friction (same nodes): ``F_max = mu * |B_z|``; ``F = mu * FricDamp * |v_h|`` with
  ``v_h`` the node's horizontal velocity; if ``F > StatDynFricScale * F_max`` then ``F = F_max``;
  applied opposite to ``v_h`` (zero when ``v_h = 0``). Defaults ``FrictionCoefficient mu = 0``,
  ``FricDamp = 200``, ``StatDynFricScale = 1.0``.
- Other defaults: ``g = 9.80665 m/s^2`` (MoorDyn v2.0.0; the 2021-22 alphas used 9.8),
  ``rho_w = 1025 kg/m^3``, ``dtM = 0.001 s``. Water depth: MoorDyn-C deepens ``WtrDpth`` (default
  0) to the deepest point as it reads the POINTS, so a deck without ``WtrDpth`` has its seabed at
  its deepest anchor (:attr:`MoorDynInput.water_depth`). A point below a *given* ``WtrDpth`` is
  refused here (MoorDyn moves the seabed down to it with a warning): a contradiction in the file.

Options, and what seacable does with each (``MoorDynInput.notes`` carries a message for every
option it cannot honour; :func:`seacable.mooring.moordyn.prepare_moordyn` warns with them):

- honoured: ``WtrDpth``/``depth``/``WaterDepth``, ``WtrDnsty``/``rho``/``rhoW``, ``g``/``gravity``,
  ``kBot``/``kb``, ``cBot``/``cb``, ``FrictionCoefficient``, MoorDyn-F's ``mu_kT``/``mu_kA`` when
  equal, ``StatDynFricScale``/``MC`` equal to 1, and ``WaveKin``/``Currents`` equal to 0;
- no counterpart needed, no warning: MoorDyn's own numerics and output (``dtM``, ``DT``, ``cfl``,
  ``tScheme``, ``dtIC``, ``TmaxIC``, ``CdScaleIC``, ``threshIC``, ``ICgenDynamic``, ``fileIC``,
  ``inertialF``, ``inertialF_rampT``, ``writeLog``, ``WriteUnits``, ``dtOut``, ``disableOutput``,
  ``disableOutTime``, ``OutSwitch``, ``Echo``; ``dtWave``, ``waveKin_rampT``, ``UnifyCurrentGrid``
  without waves): seacable solves the static equilibrium by Newton's method and integrates with an
  implicit Newmark scheme at the step the user gives;
- warned: ``WaveKin``/``Currents`` other than 0 and ``WaterKin`` (still water instead),
  ``SeafloorFile`` (flat seabed instead), ``mu_kT`` and ``mu_kA`` that differ (their mean),
  ``FricDamp``/``CV`` and ``StatDynFricScale``/``MC`` other than 1 with friction (Coulomb friction
  regularised over 0.01 m/s instead), a line type's VIV lift ``Cl`` other than 0, and any option
  name seacable does not know (ignored, with a did-you-mean).

References
----------
.. [1] M. Hall and A. Goupee, "Validation of a lumped-mass mooring line model with DeepCwind
   semisubmersible model test data", Ocean Engineering 104, 590-603, 2015.
.. [2] MoorDyn-C source, https://github.com/FloatingArrayDesign/MoorDyn (BSD-3), files
   ``source/MoorDyn2.cpp`` and ``source/Line.cpp``; documentation ``docs/inputs.rst``.
"""

# The package, by responsibility (each layer imports only those before it; the reader imports nothing above
# seacable's errors and argument checks):
#   _records   the records the reader returns (MoorDynInput and its parts) and MoorDyn's axial damping rule
#   _sections  the text in sections and tables, with the column-order check
#   _tables    the table rows as records;  _options  OPTIONS and OUTPUTS, and the notes on options
#   _read      read_moordyn, is_moordyn_file, check_water_kinematics
#   _convert   the records as a MooringSystem and its environment (imports line, environment, system.model)
#   _case      MoorDynCase and load_moordyn_case: how a deck runs (imports system.case, .dynamics, .run)
from ._case import _DECK_MAX_STRAIN, MoorDynCase, load_moordyn_case  # noqa: F401  (mooring.moordyn: the max strain)
from ._convert import moordyn_system
from ._read import check_water_kinematics, is_moordyn_file, read_moordyn
from ._records import (
    MoorDynBody,
    MoorDynExternalLoad,
    MoorDynFailure,
    MoorDynInput,
    MoorDynLine,
    MoorDynLineType,
    MoorDynPoint,
    MoorDynRod,
    MoorDynRodType,
    moordyn_axial_damping,
)

__all__ = [
    "MoorDynBody",
    "MoorDynCase",
    "MoorDynExternalLoad",
    "MoorDynFailure",
    "MoorDynInput",
    "MoorDynLine",
    "MoorDynLineType",
    "MoorDynPoint",
    "MoorDynRod",
    "MoorDynRodType",
    "check_water_kinematics",
    "is_moordyn_file",
    "load_moordyn_case",
    "moordyn_axial_damping",
    "moordyn_system",
    "read_moordyn",
]
