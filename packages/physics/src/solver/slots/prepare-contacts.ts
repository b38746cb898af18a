/**
 * The argument slots of prepareContactRows (solver/prepare-contacts-kernel.ts), filled by
 * prepareStage (solver/ball-prepare.ts): where each array sits in the kernel's `A` and each
 * number in its `P`, imported as `PREPARE` (`A[PREPARE.NAME]`) by the kernel and by its caller. A
 * module of numeric constants only, which every build folds into the code (threads/worker-
 * source.ts).
 */

// A: the arrays.
/** Entity of body A of each contact row, 0 for the static world (Int32). */
export const A = 0;
/** Entity of body B (Int32). */
export const B = 1;
/** Solver index of body A (Int32). */
export const IA = 2;
/** Solver index of body B (Int32). */
export const IB = 3;
/** ContactKind of each row (Uint8). */
export const KIND = 4;
/** Feature id of each row, for the warm start (Int32). */
export const FEATURE = 5;
/** Contact normal x, from A to B. */
export const NX = 6;
/** Contact normal y. */
export const NY = 7;
/** A's radius along the normal to the contact point, m. */
export const RA = 8;
/** B's radius along the normal to the contact point, m. */
export const RB = 9;
/** The solver body state (rows of BS2_STRIDE, solver/body-state-layout.ts). */
export const BODY_STATE = 10;
/** Material restitution, by entity. */
export const RESTITUTION_OF = 11;
/** Material friction, by entity. */
export const FRICTION_OF = 12;
/** Material static friction, by entity. */
export const STATIC_FRICTION_OF = 13;
/** Each entity's spawn stamp (Uint32, a copy), so a recycled id matches no old row. */
export const SPAWN_STAMP = 14;
/** Normal effective mass, kg (written). */
export const NORMAL_MASS = 15;
/** Tangent effective mass, kg (written). */
export const TANGENT_MASS = 16;
/** 1 if either body has infinite mass (Uint8, written; solver/rigid-partner.ts). */
export const RIGID_PARTNER = 17;
/** Tangent x (written). */
export const T1X = 18;
/** Tangent y (written). */
export const T1Y = 19;
/** Tangent z (written). */
export const T1Z = 20;
/** Combined restitution (written). */
export const RESTITUTION = 21;
/** Combined kinetic friction (written). */
export const FRICTION = 22;
/** The friction coefficient in use, static while the row sticks (written). */
export const FRICTION_BOUND = 23;
/** Normal relative velocity of the bodies' solver velocities, m/s (written). */
export const RELATIVE_VELOCITY = 24;
/** Normal impulse delivered over the step, N s (written, 0). */
export const TOTAL_NORMAL_IMPULSE = 25;
/** The impact stage's impulse, N s (written, 0). */
export const IMPULSE = 26;
/** Warm-start normal impulse, N s (written). */
export const NORMAL_IMPULSE = 27;
/** Warm-start tangent impulse, N s (written). */
export const TANGENT_IMPULSE_1 = 28;
/** Warm-start second tangent impulse (3D), N s (written). */
export const TANGENT_IMPULSE_2 = 29;
/** Largest normal impulse of a pass, N s (written, 0). */
export const MAX_NORMAL_IMPULSE = 30;
/** Spawn stamp of body A (Uint32, written). */
export const STAMP_A = 31;
/** Spawn stamp of body B (Uint32, written). */
export const STAMP_B = 32;
/** Last step's rows: ContactKind (Uint8). */
export const PREV_KIND = 33;
/** Last step's rows: entity of body A (Int32). */
export const PREV_A = 34;
/** Last step's rows: entity of body B (Int32). */
export const PREV_B = 35;
/** Last step's rows: feature id (Int32). */
export const PREV_FEATURE = 36;
/** Last step's rows: spawn stamp of A (Uint32). */
export const PREV_STAMP_A = 37;
/** Last step's rows: spawn stamp of B (Uint32). */
export const PREV_STAMP_B = 38;
/** Last step's rows: normal impulse, N s. */
export const PREV_NORMAL_IMPULSE = 39;
/** Last step's rows: tangent impulse, N s. */
export const PREV_TANGENT_IMPULSE_1 = 40;
/** Last step's rows: second tangent impulse, N s. */
export const PREV_TANGENT_IMPULSE_2 = 41;
/** The warm-start hash slots (Int32, row + 1; collision/contacts.ts). */
export const SLOTS = 42;
/** Each row's row among last step's rows, -1 for a new contact (Int32, written). */
export const PREVIOUS = 43;
/** Contact normal z (read in 3D). */
export const NZ = 44;
// P: the numbers.
/** Below this tangential speed a row sticks (static friction), m/s. */
export const STICK_SPEED = 0;
/** The boundary box's restitution. */
export const BOX_RESTITUTION = 1;
/** The boundary box's friction. */
export const BOX_FRICTION = 2;
/** The boundary box's static friction. */
export const BOX_STATIC_FRICTION = 3;
/** Last step's rows (0: no cache). */
export const PREV_ROWS = 4;
/** Hash slots (a power of two). */
export const SLOT_COUNT = 5;
/** ContactKind.Ball. */
export const BALL = 6;
/** ContactKind.Boundary. */
export const BOUNDARY = 7;
/** 1 for a 3D world's rows (BS3_STRIDE, the normal's z read), 0 for 2D. */
export const THREE_D = 8;
