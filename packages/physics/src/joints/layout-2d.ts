/**
 * The layout of a 2D joint row (world.joints.rows and rowInts, joints/solver-2d.ts): the offsets of its
 * floats (anchors, axes, centre and angle offsets, effective masses, softness, limits, motor, impulses)
 * and of its integers (entity, solver indices, type and flags), and the row types moved to the pins and
 * point links.
 */

// Row float offsets (ROW_FLOATS a row).
// Anchors A and B from the bodies' centres, world frame, m; centre and angle of B from A at the start
// of the step (m, rad); the joint's axis (prismatic, wheel, distance); the axial (or angular) effective
// mass (KAX, kg or kg m^2).
export const RAX = 0,
  RAY = 1,
  RBX = 2,
  RBY = 3,
  DCX = 4,
  DCY = 5,
  DANG = 6,
  AXX = 7,
  AXY = 8,
  KAX = 9;
// Softness (bias rate 1/s, mass scale, impulse scale) of the spring (SB..SI), of the rigid rows while
// biased (JB..JI) and of a soft weld's angular part (AB..AI): Catto, "Soft Constraints", GDC 2011.
export const SB = 10,
  SM = 11,
  SI = 12,
  JB = 13,
  JM = 14,
  JI = 15,
  AB = 16,
  AM = 17,
  AI = 18;
// Rest length (m), length or translation limits (m, or rad for revolute), motor speed (m/s or rad/s),
// motor's largest impulse a substep, a mouse joint's largest impulse a substep.
export const LEN = 19,
  MINL = 20,
  MAXL = 21,
  LOW = 22,
  UP = 23,
  MSPD = 24,
  MMAX = 25,
  FMAX = 26;
// Accumulated impulses (N s, N m s): linear x, y, angular, spring, motor, lower and upper limit;
// KMOT the motor's effective mass (kg m^2).
export const ILX = 27,
  ILY = 28,
  IANG = 29,
  ISPR = 30,
  IMOT = 31,
  ILOW = 32,
  IUP = 33,
  KMOT = 34;
// Row integer offsets (ROW_INTS a row): the joint's entity, its bodies' solver indices (0: the
// static world), and its type | flags << 8.
export const EID = 0,
  IA = 1,
  IB = 2,
  TF = 3;
/** Extra flag (above JointFlag) in a row: the weld's angular part is soft. */
export const WELD_ANGULAR_SOFT = 8;
/** Row type of a distance joint moved to the point links (the general loops skip it). */
export const POINT_LINK = 255;
/** Row type of a revolute joint moved to the pins (no spring, motor or limit; the general loops skip it). */
export const PIN = 254;

// The frame of the row being solved (FRAME_SIZE numbers; joints/solve-2d.ts fills it, each type's row
// solve reads it and writes its bodies' new velocities back): the velocities of A and B (m/s, rad/s),
// their inverse masses (1/kg) and inverse inertias (1/(kg m^2)), the anchors from the centres in the
// world frame (m), the anchors' separation B - A (m), body A's rotation (cos, sin), the relative angle
// since the joint was made minus its reference (rad) and the inverse substep (1/s).
export const F_VAX = 0,
  F_VAY = 1,
  F_WA = 2,
  F_VBX = 3,
  F_VBY = 4,
  F_WB = 5,
  F_MA = 6,
  F_IA = 7,
  F_MB = 8,
  F_IB = 9,
  F_RAX = 10,
  F_RAY = 11,
  F_RBX = 12,
  F_RBY = 13,
  F_DX = 14,
  F_DY = 15,
  F_CA = 16,
  F_SA = 17,
  F_REL = 18,
  F_INVH = 19,
  FRAME_SIZE = 20;
/** What a type's row solve did: nothing to write back (a distance joint of zero length). */
export const ROW_SKIPPED = 0;
/** What a type's row solve did: new velocities in the frame; the bodies stay in free flight (a slack rope). */
export const ROW_MOVED = 1;
/** What a type's row solve did: new velocities in the frame, and the joint pushes its bodies (the contact solver's `pushed` slot). */
export const ROW_PUSHED = 2;
