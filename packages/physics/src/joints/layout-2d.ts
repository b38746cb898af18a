/**
 * The layouts of the 2D joint solver's packed data (world.joints, joints/solver-2d.ts): a row's floats
 * (ROW_FLOATS a row: anchors, axes, centre and angle offsets, effective masses, softness, limits,
 * motor, impulses) and integers (ROW_INTS: entity, solver indices, type and flags), a point link's and a
 * pin's (their lean loops' own copies), and the frame a row is solved on.
 */

// Row floats. Anchors A and B from the bodies' centres, world frame, m; centre and angle of B from A
// at the start of the step (m, rad); the joint's axis (prismatic, wheel); the axial (or angular)
// effective mass (kg or kg m^2).
export const RAX = 0;
export const RAY = 1;
export const RBX = 2;
export const RBY = 3;
export const DCX = 4;
export const DCY = 5;
export const DANG = 6;
export const AXX = 7;
export const AXY = 8;
export const KAX = 9;
// Softness (bias rate 1/s, mass scale, impulse scale) of the spring (SB..SI), of the rigid rows while
// biased (JB..JI) and of a weld's angular part or a mouse joint's spin (AB..AI): Catto, "Soft
// Constraints", GDC 2011.
export const SB = 10;
export const SM = 11;
export const SI = 12;
export const JB = 13;
export const JM = 14;
export const JI = 15;
export const AB = 16;
export const AM = 17;
export const AI = 18;
// Rest length (m), length or translation limits (m, or rad for revolute), motor speed (m/s or rad/s),
// motor's largest impulse a substep, a mouse joint's largest impulse a substep.
export const LEN = 19;
export const MINL = 20;
export const MAXL = 21;
export const LOW = 22;
export const UP = 23;
export const MSPD = 24;
export const MMAX = 25;
export const FMAX = 26;
// Accumulated impulses (N s, N m s), in the order of world.joints.impulses (IMPULSES a joint): linear
// x, y, angular, spring, motor, lower and upper limit. KMOT: a wheel's motor's effective mass (kg m^2).
export const ILX = 27;
export const ILY = 28;
export const IANG = 29;
export const ISPR = 30;
export const IMOT = 31;
export const ILOW = 32;
export const IUP = 33;
export const KMOT = 34;

// Row integers: the joint's entity, its bodies' solver indices (0: the static world), and its
// type | flags << 8.
export const EID = 0;
export const IA = 1;
export const IB = 2;
export const TF = 3;
/** Extra flag (above JointFlag) in a row: the weld's angular part is soft. */
export const WELD_ANGULAR_SOFT = 8;
/** Row type of a distance joint moved to the point links (the general loops skip it). */
export const POINT_LINK = 255;
/** Row type of a revolute joint moved to the pins (no spring, motor or limit; the general loops skip it). */
export const PIN = 254;

// Point link floats (LINK_FLOATS a link): offset of B's anchor from A's at the start of the step (m),
// effective mass (kg), rest or longest length (m), accumulated impulse (N s; a rope's negated), mode
// (0 rod, 1 rope). Integers (LINK_INTS): body-state offsets of A and B, the link's row.
export const LK_DX = 0;
export const LK_DY = 1;
export const LK_MASS = 2;
export const LK_LEN = 3;
export const LK_ACC = 4;
export const LK_ROPE = 5;
export const LK_OA = 0;
export const LK_OB = 1;
export const LK_ROW = 2;

// Pin floats (PIN_FLOATS a pin): anchors A and B at the start of the step (world frame, from the
// centres, m), centre of B from A then (m), accumulated impulse x, y (N s). Integers (PIN_INTS): the
// bodies' solver indices, the pin's row.
export const PN_RAX = 0;
export const PN_RAY = 1;
export const PN_RBX = 2;
export const PN_RBY = 3;
export const PN_DCX = 4;
export const PN_DCY = 5;
export const PN_ILX = 6;
export const PN_ILY = 7;
export const PN_IA = 0;
export const PN_IB = 1;
export const PN_ROW = 2;

// The frame of the row being worked on (FRAME_SIZE numbers, filled by joints/solver-2d.ts): the
// anchors from the centres in the world frame (m), their separation B - A (m), the substep (s), the
// relative angle since the joint was made minus its reference (rad), the inverse substep (1/s); in the
// preparation the bodies' inverse masses (1/kg) and inertias (1/(kg m^2)) too.
export const F_RAX = 0;
export const F_RAY = 1;
export const F_RBX = 2;
export const F_RBY = 3;
export const F_DX = 4;
export const F_DY = 5;
export const F_HS = 6;
export const F_REL = 7;
export const F_INVH = 8;
export const F_MA = 9;
export const F_IA = 10;
export const F_MB = 11;
export const F_IB = 12;
// A joint along an axis (rows-2d.ts axisFrame, solveAlongAxis): the axis turned with A (world), B's
// translation along it (m), the angular Jacobians along it (m), and those of the row across it, that
// row's velocity error (m/s) and bias (m/s).
export const F_AXX = 13;
export const F_AXY = 14;
export const F_TRANS = 15;
export const F_A1 = 16;
export const F_A2 = 17;
export const F_S1 = 18;
export const F_S2 = 19;
export const F_CD = 20;
export const F_BIAS = 21;
export const FRAME_SIZE = 22;

/** What a type's row solve did: nothing (a distance joint of zero length). */
export const ROW_SKIPPED = 0;
/** What a type's row solve did: new velocities; the bodies stay in free flight (a slack rope). */
export const ROW_MOVED = 1;
/** What a type's row solve did: new velocities, and the joint pushes its bodies (the contact solver's `pushed` slot). */
export const ROW_PUSHED = 2;
