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
