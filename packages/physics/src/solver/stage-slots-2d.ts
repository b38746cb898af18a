/**
 * The argument slots of the 2D solver's stage kernels (solver/stages-kernel.ts: gatherFill2D GF_,
 * approach2D AP_, finishBodies2D FB_, restitutionColored2D RC_): where each array sits
 * in a kernel's `A` and each number in its `P`. A caller fills the slots by these names and the kernel
 * reads them by the same names. A module of numeric constants only, which every build folds into the
 * code, so the kernels' source text that the workers get stays self-contained (threads/worker-source.ts).
 */

// gatherFill2D: A.
/** Position x, m (Float64, by entity). */
export const GF_PX = 0;
/** Position y, m. */
export const GF_PY = 1;
/** Velocity x, m/s (Float64, by entity). */
export const GF_VX = 2;
/** Velocity y, m/s. */
export const GF_VY = 3;
/** AngularVelocity z, rad/s (Float64, by entity). */
export const GF_WZ = 4;
/** Force x, N (Float64, by entity). */
export const GF_FX = 5;
/** Force y, N. */
export const GF_FY = 6;
/** Force z, N (a body with any force is not in free flight). */
export const GF_FZ = 7;
/** The collision state's body type (Uint8, by entity: BodyType). */
export const GF_BODY_TYPE = 8;
/** The collision state's inverse mass, 1/kg (Float64, by entity). */
export const GF_INV_MASS = 9;
/** The collision state's inverse moment of inertia, 1/(kg m^2) (Float64, by entity). */
export const GF_INV_INERTIA = 10;
/** The solver body state (rows of BS2_STRIDE, solver/body-state-layout.ts), written. */
export const GF_BODY_STATE = 11;
/** The solver body extra rows (rows of BX_STRIDE), written. */
export const GF_BODY_EXTRA = 12;
// gatherFill2D: P.
/** The step h, s. */
export const GF_H = 0;
/** g_x h, m/s. */
export const GF_GX_H = 1;
/** g_y h, m/s. */
export const GF_GY_H = 2;
/** 1: joints are in the step, so every body counts as pushed; 0: not. */
export const GF_PUSHED = 3;
/** BodyType.Dynamic. */
export const GF_DYNAMIC = 4;
/** BodyType.Kinematic. */
export const GF_KINEMATIC = 5;

// approach2D: A, each at A[P[AP_BASE] + slot] (the coloured solve passes them after its own arrays).
/** Solver index of body A of each contact row (Int32). */
export const AP_IA = 0;
/** Solver index of body B (Int32). */
export const AP_IB = 1;
/** Entity of body A, 0 for the static world (Int32). */
export const AP_A = 2;
/** Entity of body B (Int32). */
export const AP_B = 3;
/** Contact normal x, from A to B. */
export const AP_NX = 4;
/** Contact normal y. */
export const AP_NY = 5;
/** Contact normal z. */
export const AP_NZ = 6;
/** Normal relative velocity after the impact stage, m/s (written). */
export const AP_RELATIVE_VELOCITY = 7;
/** Normal speed at impact, m/s (written). */
export const AP_IMPACT_VELOCITY = 8;
/** Separation at the start of the step, m. */
export const AP_SEPARATION = 9;
/** The impact stage's impulse on the row, N s. */
export const AP_IMPULSE = 10;
/** The collision state's body type (Uint8, by entity). */
export const AP_BODY_TYPE = 11;
/** The solver body state (rows of BS2_STRIDE). */
export const AP_BODY_STATE = 12;
/** Arrays approach2D takes. */
export const AP_ARRAYS = 13;
// approach2D: P.
/** Gravity x, m/s^2. */
export const AP_GX = 0;
/** Gravity y, m/s^2. */
export const AP_GY = 1;
/** Gravity z, m/s^2. */
export const AP_GZ = 2;
/** BodyType.Dynamic. */
export const AP_DYNAMIC = 3;
/** Where approach2D's arrays start in A. */
export const AP_BASE = 4;

// finishBodies2D and its loops (finishBodyRows2D, containBodies2D, deepestRow2D): A.
/** Position x, m (Float64, by entity), written. */
export const FB_PX = 0;
/** Position y, m, written. */
export const FB_PY = 1;
/** Velocity x, m/s, written. */
export const FB_VX = 2;
/** Velocity y, m/s, written. */
export const FB_VY = 3;
/** AngularVelocity z, rad/s, written. */
export const FB_WZ = 4;
/** Angle, rad, written. */
export const FB_ANGLE = 5;
/** The collision state's body type (Uint8, by entity). */
export const FB_BODY_TYPE = 6;
/** The solver body state (rows of BS2_STRIDE). */
export const FB_BODY_STATE = 7;
/** The solver body extra rows (rows of BX_STRIDE). */
export const FB_BODY_EXTRA = 8;
/** The solver bodies' impact rows (rows of P[FB_IMPACT_STRIDE]). */
export const FB_BODY_IMPACT = 9;
/** Ball radius, m (by entity). */
export const FB_RADIUS = 10;
/** Material restitution (by entity). */
export const FB_RESTITUTION = 11;
/** The deepest overlap each thread found, m (one slot a thread), written. */
export const FB_DEEPEST = 12;
/** Solver index of body A of each contact row (Int32). */
export const FB_IA = 13;
/** Solver index of body B (Int32). */
export const FB_IB = 14;
/** Separation at the start of the step, m. */
export const FB_SEPARATION = 15;
/** Contact normal x. */
export const FB_NX = 16;
/** Contact normal y. */
export const FB_NY = 17;
// finishBodies2D: P.
/** Free flight's correction -g_x h h_s / 2, m. */
export const FB_FREE_X = 0;
/** Free flight's correction -g_y h h_s / 2, m. */
export const FB_FREE_Y = 1;
/** BodyType.Dynamic. */
export const FB_DYNAMIC = 2;
/** Numbers an impact row (IMPACT_STRIDE). */
export const FB_IMPACT_STRIDE = 3;
/** 1: the boundary box is on (contain the bodies), 0: off. */
export const FB_CONTAIN = 4;
/** The box's min x, m (min y follows at FB_MIN_X + 1). */
export const FB_MIN_X = 5;
/** The box's min y, m. */
export const FB_MIN_Y = 6;
/** The box's max x, m (max y follows at FB_MAX_X + 1). */
export const FB_MAX_X = 7;
/** The box's max y, m. */
export const FB_MAX_Y = 8;
/** The box's restitution. */
export const FB_BOX_RESTITUTION = 9;
/** Gravity x, m/s^2. */
export const FB_GX = 10;
/** Gravity y, m/s^2. */
export const FB_GY = 11;
/** Contact rows. */
export const FB_ROWS = 12;
/** Solver bodies - 1 (the loop's length). */
export const FB_BODIES = 13;
// restitutionColored2D: A.
/** The packed contact rows (solver/contact-pack-2d.ts), colour by colour. */
export const RC_PACK = 0;
/** The coloured solve's plan (Int32, the PL_ slots of solver/colored-slots-2d.ts). */
export const RC_PLAN = 1;
/** Counters (Int32, 0 on entry: 0 unused, 1 blocks done, 2 abort, 3 bouncing rows). */
export const RC_COUNTERS = 2;
/** The solver body state (rows of BS2_STRIDE). */
export const RC_BODY_STATE = 3;
/** Solver index of body A of each contact row (Int32). */
export const RC_IA = 4;
/** Solver index of body B (Int32). */
export const RC_IB = 5;
/** Contact normal x. */
export const RC_NX = 6;
/** Contact normal y. */
export const RC_NY = 7;
/** Normal effective mass, kg. */
export const RC_NORMAL_MASS = 8;
/** Combined restitution. */
export const RC_RESTITUTION = 9;
/** Normal relative velocity, m/s. */
export const RC_RELATIVE_VELOCITY = 10;
/** Normal speed at impact, m/s. */
export const RC_IMPACT_VELOCITY = 11;
/** Largest normal impulse of a pass, N s. */
export const RC_MAX_NORMAL_IMPULSE = 12;
/** Normal impulse delivered over the step, N s. */
export const RC_TOTAL_NORMAL_IMPULSE = 13;
/** The impact stage's impulse, N s. */
export const RC_IMPULSE = 14;
/** Block j is pack rows bounds[j] .. bounds[j + 1] - 1 (Int32). */
export const RC_BOUNDS = 15;
/** Two a pack row: its bodies' solver state offsets (Int32). */
export const RC_PAIR = 16;
/** A pack row's row in the contact buffer (Int32). */
export const RC_ROW = 17;
/** A flag a block, numbered across the units (Int32, 0 on entry; restitutionBlocks2D of them). */
export const RC_CLAIM = 18;
// restitutionColored2D: P.
/** Contact rows. */
export const RC_ROWS = 0;
/** restitutionThreshold, m/s. */
export const RC_THRESHOLD = 1;
/** elasticRestitutionThreshold, m/s. */
export const RC_ELASTIC_THRESHOLD = 2;
/** restitutionIterations. */
export const RC_ITERATIONS = 3;
/** 1: the calling thread may block in Atomics.wait. */
export const RC_MAY_WAIT = 4;
/** How long a thread spins before it blocks, microseconds. */
export const RC_SPIN_US = 5;
