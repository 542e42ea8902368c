"""The layouts of the mooring kernel's flat arrays, in one place: the environment vector ``env`` (``E_*``), the
attachments' hydrodynamics ``pcda`` (``P_*``), the viscoelastic element table ``visco`` (``V_*``) and the bending
hinges' table ``hinge_ei`` (``H_*``).

Read by the parts of :mod:`seacable.mooring.kernel` and filled by :mod:`seacable.mooring.solver` and the coupled
system kernel; :mod:`seacable.mooring.kernel` re-exports every name.
"""

from __future__ import annotations

# Environment vector layout.
E_RHO, E_G, E_DEPTH, E_SLOPE, E_KBOT, E_CBOT, E_MU, E_VFRIC = 0, 1, 2, 3, 4, 5, 6, 7
E_WH, E_WT, E_WK, E_WHEAD, E_WPHASE, E_CHEAD, E_ALPHA, E_WDEPTH = 8, 9, 10, 11, 12, 13, 14, 15
E_BEDRAMP = 16
E_VDT = 17  # the time step over which the viscoelastic elements' slow stretch advances (inf: statics) [s]
E_SLACKDAMP = 18  # 1: the axial damper acts in slack elements too (MoorDyn's rule), 0: only in taut ones
E_BEDFULL = 19  # 1: the seabed damper acts in full wherever the spring is linear (MoorDyn's rule), 0: ramped
# velocity of the frame the nodes are seen in [m/s]: the water moves past them at (its velocity) - (this), the seabed
# at -(this); 0 but in the statics of a towed system, whose steady state is a static equilibrium in the frame moving
# with the vessel
E_FRAMEX, E_FRAMEY, E_FRAMEZ = 20, 21, 22
# 1: the Newton matrix holds the drag's change with the elements' direction (:func:`_drag_turn`; a towed line, whose
# shape the drag sets), 0: not (a mooring line, whose shape its weight and tension set: the terms cost time)
E_DRAGTURN = 23
# a seabed profile: its number of points m (0: the plane of E_DEPTH and E_SLOPE); the points follow the vector's
# ENV_SIZE slots, m distances along X [m] then m seabed elevations there [m] (linear between, level beyond); or a
# seabed grid (issue 41): -nx, its number of lines along X, with E_BEDNY its number along Y, ny; then follow nx x
# [m], ny y [m] and the ny nx elevations [m], row by row along y (bilinear in each cell, level beyond)
E_BEDTAB = 24
# 1: the elements of linear EA carry compression too, EA eps below eps = 0 (a cable with bending stiffness, a beam), 0:
# tension only (MoorDyn's rule: no compression)
E_COMPRESS = 25
# a towed body at node 0 (the towed line's lower end, node 1 its neighbour) with drag or added mass per axis of the
# body (:mod:`seacable.mooring._body`): 1 (0: none, its isotropic parts are the node's point arrays), its C_D A along,
# across and vertical (E_BDRAG + k) [m^2] and its added mass along, across and vertical (E_BMASS + k) [kg]
E_BODY, E_BDRAG, E_BMASS = 26, 27, 30
E_BEDNY = 33
ENV_SIZE = 34

# Columns of the attachments' hydrodynamics ``pcda`` (n, 3): drag area C_D A across the line (of all directions at
# a point whose axial one is the same) and along it [m^2], and lift area C_L A [m^2], the lift
# 1/2 rho C_L A (|u|^2 e_z - (u . e_z) u) at the water's velocity u relative to the point (:func:`point_lift`)
P_CDA, P_CDA_AXIAL, P_CLA = 0, 1, 2
# and, when a node of the network is tied to the seabed (:mod:`seacable.ties`; else the table has the three columns
# above), the node's tether: its anchor (P_TX, P_TX + 1, P_TX + 2) [m], axial stiffness EA (P_TEA) [N], unstretched
# length (P_TL, 0: no tether) [m] and the strain band its slack switch is rounded over (P_TB, 0: a sharp switch)
# [-]; and its spring clamp: the point it holds the node to (P_CX, P_CX + 1, P_CX + 2) [m] and its stiffness
# (P_CK, 0: none) [N/m] (:func:`seacable.mooring._ties.tie_loads`)
P_TX, P_TEA, P_TL, P_TB, P_CX, P_CK = 3, 6, 7, 8, 9, 12
P_SIZE = 13

# Columns of the viscoelastic element table (one row per element, or none when no element is viscoelastic):
# dynamic stiffness EA_Dc [N] (0: an elastic element) and its slope on the mean tension EA_D_Lm [-], the
# fast damper BA_D [N s], and the slow stretch and its input at the start of the step (Y0, U0) and at the
# state last evaluated (Y, U) [m]
V_EAD, V_LM, V_BAD, V_Y0, V_U0, V_Y, V_U = 0, 1, 2, 3, 4, 5, 6
# and, for an element of a Syrope rope (whose strain-tension table is its original working curve), the working
# curve's form (0: none, 1: linear, 2: quadratic, 3: exponential) and its parameters k1, k2 [-] (k1 [N] for a
# linear curve with k1 >= 1), and the largest mean tension so far, Tmax, committed (TM0) and at the state last
# evaluated (TM) [N] (:func:`syrope_tension`)
V_WC, V_K1, V_K2, V_TM0, V_TM = 7, 8, 9, 10, 11
V_SIZE = 12

# Columns of the bending hinges' table ``hinge_ei`` (one row per row of ``hinges``, :func:`bending_loads`): the
# bending stiffness EI [N m^2] of an inner hinge (the mean of its two elements') or of a held end's end element
# (H_EI); the hinge's kind (H_KIND: H_INNER, H_CLAMP or H_SPRING); for a held end its given direction, a unit vector
# from the end node into the line (H_D, H_D + 1, H_D + 2) [-], and a spring's rotational stiffness (H_K) [N m/rad];
# for a held end that turns with a moving platform, the motion channels of its direction's point (the end plus its
# direction, moved by the same rigid motion: H_DCH) and of the end itself (H_ECH), -1 for a fixed direction; for a
# hinge with a nonlinear moment-curvature law (:mod:`seacable.moment_curvature`) its number of knots n (H_NLAW; 0:
# linear, M = EI kappa), its unstretched length L0 (H_L0: the mean of its two elements', half a held end's element)
# [m] and, from column H_SIZE on, the knots in pairs (kappa_j [1/m], M_j [N m]), j = 0 .. n - 1, from (0, 0): the
# table is then H_SIZE + 2 n_max wide
H_EI, H_KIND, H_D, H_K, H_DCH, H_ECH, H_NLAW, H_L0 = 0, 1, 2, 5, 6, 7, 8, 9
H_SIZE = 10
H_INNER, H_CLAMP, H_SPRING = 0.0, 1.0, 2.0
