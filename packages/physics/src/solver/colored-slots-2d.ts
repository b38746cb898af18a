/**
 * The argument slots of the coloured 2D contact solve's kernels: solveColored2D and its block loops
 * (solver/coloring-kernel.ts: CS_), the plan they share (PL_, the Int32 array at A[CS_PLAN]), the
 * strip cut (solver/strips-kernel.ts: SC_) and the strip plan (solver/strip-plan-kernel.ts: SP_, whose
 * A starts with solveColored2D's arrays). Their callers (solver/coloring.ts) fill the slots by these
 * names and the kernels read them by the same names. A module of numeric constants only, which every
 * build folds into the code (threads/worker-source.ts).
 */

// solveColored2D: A.
/** The packed contact rows (solver/contact-pack-2d.ts), colour by colour. */
export const CS_PACK = 0;
/** The solver body state (rows of BS2_STRIDE, solver/body-state-layout.ts). */
export const CS_BODY_STATE = 1;
/** The solver body extra rows (rows of BX_STRIDE). */
export const CS_BODY_EXTRA = 2;
/** 1 where the solver body takes gravity (Uint8, by solver index). */
export const CS_DYN = 3;
/** The plan (Int32, the PL_ slots). */
export const CS_PLAN = 4;
/** Counters (Int32, 0 on entry: 0 unused, 1 blocks done, 2 abort). */
export const CS_COUNTERS = 5;
/** Each row's packing group (Uint8: 0 .. P[CS_GROUP_SLOTS] - 2, then the overflow group; 255 not packed). */
export const CS_GROUP = 6;
/** Each packing range's next pack slot of each group (Int32, P[CS_GROUP_SLOTS] a range), advanced as it packs. */
export const CS_OFFSETS = 7;
/** Solver index of body A of each contact row (Int32). */
export const CS_IA = 8;
/** Solver index of body B (Int32). */
export const CS_IB = 9;
/** Contact normal x. */
export const CS_NX = 10;
/** Contact normal y. */
export const CS_NY = 11;
/** A's radius along the normal, m. */
export const CS_RA = 12;
/** B's radius along the normal, m. */
export const CS_RB = 13;
/** Separation at the start of the step, m. */
export const CS_SEPARATION = 14;
/** Normal effective mass, kg. */
export const CS_NORMAL_MASS = 15;
/** Tangent effective mass, kg. */
export const CS_TANGENT_MASS = 16;
/** The friction coefficient in use. */
export const CS_FRICTION_BOUND = 17;
/** Accumulated normal impulse, N s. */
export const CS_NORMAL_IMPULSE = 18;
/** Accumulated tangent impulse, N s. */
export const CS_TANGENT_IMPULSE = 19;
/** 1 if body A has infinite mass (Uint8). */
export const CS_RIGID_PARTNER = 20;
/** Largest normal impulse of a pass, N s. */
export const CS_MAX_NORMAL_IMPULSE = 21;
/** Normal impulse delivered over the step, N s. */
export const CS_TOTAL_NORMAL_IMPULSE = 22;
/** Block j is pack rows bounds[j] .. bounds[j + 1] - 1 (Int32). */
export const CS_BOUNDS = 23;
/** The movable solver bodies by strip pair (Int32 solver indices). */
export const CS_BODY_ORDER = 24;
/** Each even block's range of BODY_ORDER (Int32). */
export const CS_BODY_BOUNDS = 25;
/** Two a pack row: its bodies' solver state offsets (Int32: an integer index is faster a pass than a double). */
export const CS_PAIR = 26;
/** A pack row's normal impulse delivered over the substeps, N s (written on each substep's last pass). */
export const CS_TOT = 27;
/** A pack row's row in the contact buffer (Int32, read by the unpacking only). */
export const CS_ROW = 28;
/** A flag a block of every unit, numbered across the units (Int32, 0 on entry). */
export const CS_CLAIM = 29;
/** A buffer row's pack row (Int32, written by the packing). */
export const CS_SLOT = 30;
/** Where approach2D's arrays (the AP_ slots of solver/stage-slots-2d.ts) start. */
export const CS_APPROACH = 31;
// solveColored2D: P.
/** 1 / h_s, the substep rate, 1/s. */
export const CS_INV_HS = 0;
/** Soft contact (dynamic pair): bias rate. */
export const CS_SOFT_BIAS = 1;
/** Soft contact (dynamic pair): mass scale. */
export const CS_SOFT_MASS = 2;
/** Soft contact (dynamic pair): impulse scale. */
export const CS_SOFT_IMPULSE = 3;
/** Soft contact (against a body of infinite mass): bias rate. */
export const CS_RIGID_BIAS = 4;
/** Soft contact (against a body of infinite mass): mass scale. */
export const CS_RIGID_MASS = 5;
/** Soft contact (against a body of infinite mass): impulse scale. */
export const CS_RIGID_IMPULSE = 6;
/** The largest push-out speed, m/s. */
export const CS_PUSH_SPEED = 7;
/** The substep h_s, s. */
export const CS_HS = 8;
/** g_x h_s, m/s. */
export const CS_GX_HS = 9;
/** g_y h_s, m/s. */
export const CS_GY_HS = 10;
/** The contact buffer's rows. */
export const CS_ROWS = 11;
/** Group slots a packing range in OFFSETS. */
export const CS_GROUP_SLOTS = 12;
/** How long a thread spins for the next unit before it blocks, microseconds. */
export const CS_SPIN_US = 13;
/** The unit vector along gravity, x (0 without gravity). */
export const CS_DOWN_X = 14;
/** The unit vector along gravity, y. */
export const CS_DOWN_Y = 15;
/** solver/support.ts SUPPORT_COS. */
export const CS_SUPPORT_COS = 16;
/** Gravity x, m/s^2. */
export const CS_GX = 17;
/** Gravity y, m/s^2. */
export const CS_GY = 18;
/** Gravity z, m/s^2. */
export const CS_GZ = 19;
/** BodyType.Dynamic. */
export const CS_DYNAMIC = 20;
/** 1 to measure the approach speeds (in blocks of 2,048 rows), else 0. */
export const CS_MEASURE_APPROACH = 21;
// The plan (Int32, A[CS_PLAN]).
/** Substeps. */
export const PL_SUBSTEPS = 0;
/** Biased passes a substep. */
export const PL_ITERATIONS = 1;
/** Relax passes a substep. */
export const PL_RELAX = 2;
/** Threads running the kernel. */
export const PL_THREADS = 3;
/** Colours C. */
export const PL_COLORS = 4;
/** Solver bodies. */
export const PL_BODIES = 5;
/** 1: the calling thread may block in Atomics.wait. */
export const PL_MAY_WAIT = 6;
/** Packing ranges (0: the rows are packed already). */
export const PL_PARTS = 7;
/** Rows packed. */
export const PL_PACKED_ROWS = 8;
/** 1: strips (the body stages fused into colour 0's blocks). */
export const PL_STRIPS = 9;
/** Even blocks. */
export const PL_EVEN_BLOCKS = 10;
/** 1 when the strip plan packed the rows. */
export const PL_PACKED = 11;
/** Colour c's first block is plan[PL_COLOR_BLOCKS + c], c = 0 .. C (C the overflow colour); plan[PL_COLOR_BLOCKS + C + 1] the end. */
export const PL_COLOR_BLOCKS = 12;
// stripCut2D: A, each at A[P[SC_BASE] + slot].
/** The solver body state (rows of BS2_STRIDE). */
export const SC_BODY_STATE = 0;
/** The solver body extra rows (rows of BX_STRIDE). */
export const SC_BODY_EXTRA = 1;
/** The collision state's body type (Uint8, by entity). */
export const SC_BODY_TYPE = 2;
/** The solver bodies' entity ids (Int32, by solver index). */
export const SC_BODIES = 3;
/** 1 where the solver body takes gravity (Uint8, written). */
export const SC_DYN = 4;
/** Each solver body's strip (Uint8, written; 255: not movable). */
export const SC_STRIP = 5;
/** Each solver body's bin (Uint16, written; P[SC_NO_BIN]: not movable). */
export const SC_BIN = 6;
/** Rows a bin (Int32, written). */
export const SC_BIN_ROWS = 7;
/** Each bin's strip (Uint8, written). */
export const SC_BIN_STRIP = 8;
/** Solver index of body A of each row (Int32). */
export const SC_IA = 9;
/** Solver index of body B (Int32). */
export const SC_IB = 10;
/** Arrays stripCut2D takes. */
export const SC_ARRAYS = 11;
// stripCut2D: P (the strip plan passes its own, whose first slots are these).
/** Solver bodies. */
export const SC_P_BODIES = 0;
/** Contact rows. */
export const SC_P_ROWS = 1;
/** Strips (2 .. 255). */
export const SC_P_STRIPS = 2;
/** Bins (<= P[SC_NO_BIN]). */
export const SC_BINS = 3;
/** BodyType.Dynamic. */
export const SC_P_DYNAMIC = 4;
/** The "no bin" mark. */
export const SC_NO_BIN = 5;
/** Where stripCut2D's arrays start in A. */
export const SC_BASE = 6;
// stripPlan2D: A is solveColored2D's (CS_ slots), then stripCut2D's from SP_CUT, then its own.
/** Where stripCut2D's arrays start in the strip plan's A. */
export const SP_CUT = 31;
/** Rows a group (Int32, MAX_COLORS + 2 slots), scratch. */
export const SP_COUNTS = 42;
/** Each group's first row (Int32), scratch. */
export const SP_START = 43;
/** Each row's next row in its group (Int32), scratch. */
export const SP_NEXT = 44;
// stripPlan2D: P. Slots 0 to 6 are stripCut2D's (SC_), 11 and 12 coloredPack2D's (CS_ROWS, CS_GROUP_SLOTS).
/** Packing ranges. */
export const SP_PARTS = 7;
/** 1: pack the rows here, 0: not. */
export const SP_PACK = 8;
/** 1: cut the strips here, 0: the cut is made. */
export const SP_CUT_HERE = 9;
/** The most rows the overflow group may take. */
export const SP_MAX_OVERFLOW = 10;
/** PLAN_HEAD (solver/coloring.ts): where the colours' blocks start in the plan. */
export const SP_PLAN_HEAD = 13;
/** MAX_COLORS (solver/coloring.ts). */
export const SP_MAX_COLORS = 14;
/** Rows a block. */
export const SP_BLOCK_ROWS = 15;
