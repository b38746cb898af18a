/**
 * The layout of a 2D joint row (world.joints.rows and rowInts, joints/solver-2d.ts): the offsets of its
 * floats (anchors, axes, centre and angle offsets, effective masses, softness, limits, motor, impulses)
 * and of its integers (entity, solver indices, type and flags), and the row types moved to the pins and
 * point links.
 */

// Row float offsets.
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
export const SB = 10,
  SM = 11,
  SI = 12,
  JB = 13,
  JM = 14,
  JI = 15,
  AB = 16,
  AM = 17,
  AI = 18;
export const LEN = 19,
  MINL = 20,
  MAXL = 21,
  LOW = 22,
  UP = 23,
  MSPD = 24,
  MMAX = 25,
  FMAX = 26;
export const ILX = 27,
  ILY = 28,
  IANG = 29,
  ISPR = 30,
  IMOT = 31,
  ILOW = 32,
  IUP = 33,
  KMOT = 34;
// Row integer offsets.
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
