/**
 * The argument slots of solveColored2D and its block loops (solver/coloring-kernel.ts), filled by
 * solveArguments and solveColoredSubsteps (solver/coloring.ts): where each array sits in the
 * kernel's `A` and each number in its `P`, imported as `SOLVE` (`A[SOLVE.NAME]`) by the kernel and
 * by its caller. A module of numeric constants only, which every build folds into the code
 * (threads/worker-source.ts).
 */

// A: the arrays.
/** The packed contact rows (solver/contact-pack-2d.ts), colour by colour. */
export const PACK = 0;
/** The solver body state (rows of BS2_STRIDE, solver/body-state-layout.ts). */
export const BODY_STATE = 1;
/** The solver body extra rows (rows of BX_STRIDE). */
export const BODY_EXTRA = 2;
/** 1 where the solver body takes gravity (Uint8, by solver index). */
export const DYN = 3;
/** The plan (Int32, the PLAN slots of solver/slots/colored-plan.ts). */
export const PLAN = 4;
/** Counters (Int32, 0 on entry: 0 unused, 1 blocks done, 2 abort). */
export const COUNTERS = 5;
/** Each row's packing group (Uint8: 0 .. P[SOLVE.GROUP_SLOTS] - 2, then the overflow group; 255 not packed). */
export const GROUP = 6;
/**
 * Each packing range's next pack slot of each group (Int32, P[SOLVE.GROUP_SLOTS] a range), advanced as
 * it packs.
 */
export const OFFSETS = 7;
/** Solver index of body A of each contact row (Int32). */
export const IA = 8;
/** Solver index of body B (Int32). */
export const IB = 9;
/** Contact normal x. */
export const NX = 10;
/** Contact normal y. */
export const NY = 11;
/** A's radius along the normal, m. */
export const RA = 12;
/** B's radius along the normal, m. */
export const RB = 13;
/** Separation at the start of the step, m. */
export const SEPARATION = 14;
/** Normal effective mass, kg. */
export const NORMAL_MASS = 15;
/** Tangent effective mass, kg. */
export const TANGENT_MASS = 16;
/** The friction coefficient in use. */
export const FRICTION_BOUND = 17;
/** Accumulated normal impulse, N s. */
export const NORMAL_IMPULSE = 18;
/** Accumulated tangent impulse, N s. */
export const TANGENT_IMPULSE = 19;
/** 1 if either body has infinite mass (Uint8; solver/rigid-partner.ts). */
export const RIGID_PARTNER = 20;
/** Largest normal impulse of a pass, N s. */
export const MAX_NORMAL_IMPULSE = 21;
/** Normal impulse delivered over the step, N s. */
export const TOTAL_NORMAL_IMPULSE = 22;
/** Block j is pack rows bounds[j] .. bounds[j + 1] - 1 (Int32). */
export const BOUNDS = 23;
/** The movable solver bodies by strip pair (Int32 solver indices). */
export const BODY_ORDER = 24;
/** Each even block's range of BODY_ORDER (Int32). */
export const BODY_BOUNDS = 25;
/**
 * Two a pack row: its bodies' solver state offsets (Int32: an integer index is faster a pass than a
 * double).
 */
export const PAIR = 26;
/** A pack row's normal impulse delivered over the substeps, N s (written on each substep's last pass). */
export const TOT = 27;
/** A pack row's row in the contact buffer (Int32, read by the unpacking only). */
export const ROW = 28;
/** A flag a block of every unit, numbered across the units (Int32, 0 on entry). */
export const CLAIM = 29;
/** A buffer row's pack row (Int32, written by the packing). */
export const SLOT = 30;
/** Where approachSpeeds's arrays (the APPROACH slots of solver/slots/approach.ts) start. */
export const APPROACH = 31;
// P: the numbers.
/** 1 / h_s, the substep rate, 1/s. */
export const INV_HS = 0;
/** Soft contact (dynamic pair): bias rate. */
export const SOFT_BIAS = 1;
/** Soft contact (dynamic pair): mass scale. */
export const SOFT_MASS = 2;
/** Soft contact (dynamic pair): impulse scale. */
export const SOFT_IMPULSE = 3;
/** Soft contact (against a body of infinite mass): bias rate. */
export const RIGID_BIAS = 4;
/** Soft contact (against a body of infinite mass): mass scale. */
export const RIGID_MASS = 5;
/** Soft contact (against a body of infinite mass): impulse scale. */
export const RIGID_IMPULSE = 6;
/** The largest push-out speed, m/s. */
export const PUSH_SPEED = 7;
/** The substep h_s, s. */
export const HS = 8;
/** g_x h_s, m/s. */
export const GX_HS = 9;
/** g_y h_s, m/s. */
export const GY_HS = 10;
/** The contact buffer's rows. */
export const ROWS = 11;
/** Group slots a packing range in OFFSETS. */
export const GROUP_SLOTS = 12;
/** How long a thread spins for the next unit before it blocks, microseconds. */
export const SPIN_US = 13;
/** The unit vector along gravity, x (0 without gravity). */
export const DOWN_X = 14;
/** The unit vector along gravity, y. */
export const DOWN_Y = 15;
/** solver/support.ts SUPPORT_COS. */
export const SUPPORT_COS = 16;
/** Gravity x, m/s^2. */
export const GX = 17;
/** Gravity y, m/s^2. */
export const GY = 18;
/** Gravity z, m/s^2. */
export const GZ = 19;
/** BodyType.Dynamic. */
export const DYNAMIC = 20;
/** 1 to measure the approach speeds (in blocks of 2,048 rows), else 0. */
export const MEASURE_APPROACH = 21;
