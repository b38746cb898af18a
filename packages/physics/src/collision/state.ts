import { BS3_STRIDE, BX_STRIDE, IMPACT_STRIDE } from '../solver/body-state-layout.js';
import { widenToDoubles } from '../world/double-fields.js';
import { markWritable } from '../world/writable-fields.js';
import { type ContactBuffer, createContactBuffer, createWarmStartCache, type WarmStartCache } from './contacts.js';
import { type ContactEventLists, createContactEventStore, createSleepingContacts, type SleepingContacts } from './event-lists.js';
import { createShapeCollisionState, type ManifoldBuffer, type ShapeCollisionState } from './manifolds-2d.js';

/**
 * Body type codes kept in `CollisionState.bodyType` for the bodies of the current step. A sleeping
 * body takes no part in contacts except to be woken by an awake or kinematic body that comes near.
 * @category Collision
 */
export const BodyType = Object.freeze({ Dynamic: 0, Kinematic: 1, Static: 2, Sleeping: 3 } as const);

/**
 * Pair kinds written by the broadphase into `CollisionState.pairKind`.
 * @category Collision
 */
export const PairKind = Object.freeze({ BallBall: 0, SegmentBall: 2 } as const);

/**
 * Contact solver tuning (Box2D v3's soft step). Set at world creation from the world options; the
 * fields may be changed between steps. Defaults as in Box2D v3: 4 substeps, one biased and one relax
 * pass a substep, contact damping ratio 10, push-out speed 3 m/s (here for a 1 m ball), 0.1 m
 * speculative margin. Defaults that differ, and why (see each field): `contactHertz` 60 Hz for a 1 m
 * ball, scaled by sqrt(1 m / r) so small balls squash no more than big ones (Box2D v3: 30 Hz for
 * every size); `restitutionThreshold` 0.5 m/s, half Box2D v3's 1 m/s, so slower bounces survive while
 * piles still come to rest, and 0 for e = 1 contacts (`elasticRestitutionThreshold`) so a perfectly
 * elastic contact bounces at any speed; `autoSubsteps`, `impactIterations`, `restitutionIterations`,
 * `stickSpeed` and `coloredSolveMinRows` have no Box2D counterpart.
 * @category Collision
 */
export interface CollisionSettings {
  /** Solver substeps a (world) step, integer >= 1; the least a step takes when `autoSubsteps`. Default 4. */
  solverSubsteps: number;
  /**
   * Whether a step whose ball contacts are small takes more solver substeps than `solverSubsteps`, so
   * their stiffness f = contactHertz sqrt(1 m / r) fits the substep rate: ceil(dt f / 0.6) substeps
   * (2 cm balls at dt 1/60: f = 424 Hz, 11.8 -> 12; 10 cm: 6; 17.4 cm and up: the 4 set; see
   * solver/contact-scale.ts `solverSubstepsFor`, at most 16). false: exactly `solverSubsteps`. Default true.
   */
  autoSubsteps: boolean;
  /** Sequential-impulse passes with soft bias per solver substep, integer >= 1. Default 1. */
  solverIterations: number;
  /** Passes without bias per solver substep (remove the push-out velocity), integer >= 0. Default 1. */
  relaxIterations: number;
  /**
   * Approach speed below which contacts with restitution e < 1 do not bounce (e is treated as 0), m/s,
   * >= 0. World option `restitutionThreshold`, default 0.5 m/s (Box2D uses the same idea with 1 m/s).
   * The trade-off: a threshold lets a pile or a ball on the floor come to rest instead of bouncing
   * ever smaller (each slow bounce would last less than a step); below it a bouncy contact is dead.
   */
  restitutionThreshold: number;
  /**
   * The same threshold for perfectly elastic contacts (e >= 1), m/s, >= 0. Default 0: an e = 1 contact
   * bounces at any speed, as whoever sets e = 1 expects (a gas, a Newton's cradle, a ball hitting a
   * wall at 0.3 m/s). Set to `restitutionThreshold` when the world option is given.
   */
  elasticRestitutionThreshold: number;
  /**
   * Passes of the impact stage over the bouncing contacts (see solver/impacts.ts), integer >= 1. Default 8.
   * A chain of impacts in the order of their times needs one pass; more resolve impacts that come
   * back around within one step (balls packed close together).
   */
  impactIterations: number;
  /** Sequential-impulse passes of the restitution solve at the end of a step, integer >= 1. Default 4. */
  restitutionIterations: number;
  /**
   * Stiffness of contact softness, Hz, > 0, for balls of radius 1 m (`CONTACT_LENGTH_UNIT`); a step's
   * ball contacts use contactHertz sqrt(1 m / r) for the smallest radius r among them, capped at the
   * substep rate (which `autoSubsteps` raises to fit it), so small balls squash no more than big ones
   * (see solver/contact-scale.ts). Default 60 Hz (Box2D v3 uses 30 Hz for every size).
   */
  contactHertz: number;
  /** Damping ratio of contact softness, dimensionless. Default 10 (heavily overdamped: no bounce from push-out). */
  contactDampingRatio: number;
  /**
   * Fastest speed at which overlapping bodies are pushed apart, m/s, for balls of radius 1 m; ball
   * contacts scale it by sqrt(r / 1 m) (see solver/contact-scale.ts). Default 3 m/s.
   */
  contactPushSpeed: number;
  /**
   * Fewest ball contact rows for a 2D world's step (no joints or shapes in it) to solve its contacts
   * by graph colouring (solver/coloring.ts), on the world's threads or inline on one thread, integer
   * >= 0. Default 16384. The coloured solve applies impulses colour by colour instead of in buffer
   * order, and takes the same colours on every thread count, so the trajectory is the same for
   * `threads: 1` and `threads: n`. Infinity keeps buffer order at any size.
   */
  coloredSolveMinRows: number;
  /**
   * Gap within which contacts are kept even without approach speed, m. Default 0.1 m (Box2D v3 pads its
   * bounding boxes by the same margin), so a body knocked sideways during a step still meets the contacts
   * it runs into. Balls use it as it is; shapes take at most this: 2D shapes 4 % of half their smallest
   * extent (0.02 m for a 1 m box, collision/shapes-2d.ts), 3D shapes 0.02 m (collision/shapes-3d.ts), so
   * neighbours standing a few centimetres apart are no contacts.
   */
  speculativeDistance: number;
  /**
   * Tangential speed below which a contact sticks and static friction applies, m/s, for balls of
   * radius 1 m; ball contacts scale it by sqrt(r / 1 m) (see solver/contact-scale.ts). Default 0.01 m/s.
   */
  stickSpeed: number;
}

/**
 * The axis-aligned box that keeps bodies in (walls on all sides, floor and ceiling included).
 * `min` and `max` are its inner corners, m. Its surface has its own restitution and friction.
 * @category Collision
 */
export interface Boundary {
  /** Whether the box is active. */
  enabled: boolean;
  /** Inner corner with the smallest coordinates, m (x, y, z). */
  readonly min: Float64Array;
  /** Inner corner with the largest coordinates, m (x, y, z). */
  readonly max: Float64Array;
  /** Restitution of the walls, [0, 1]. */
  restitution: number;
  /** Kinetic friction coefficient of the walls, >= 0. */
  friction: number;
  /** Static friction coefficient of the walls, >= 0. */
  staticFriction: number;
}

/**
 * Sleeping (Box2D v3's idea: resting islands stop costing anything): a dynamic collider whose speed
 * stays below `linearSpeed` (m/s) and whose spin stays below `angularSpeed` (rad/s) accumulates rest
 * time; when every body of a contact island has rested `timeToSleep` (s), the island sleeps.
 * @category Collision
 */
export interface SleepState {
  /** Whether islands may sleep. World option `sleep`, default true. */
  enabled: boolean;
  /**
   * Speed below which a body rests, m/s, >= 0. Default 0.05 m/s in 2D (Box2D v3's sleep threshold)
   * and 0.1 m/s in 3D (rapier3d 0.21's, measured: a box at 0.099 m/s sleeps, at 0.101 m/s it does not);
   * in 3D the tall columns of a box pile rock at 0.05 to 0.09 m/s for seconds and kept whole piles awake.
   */
  linearSpeed: number;
  /** Spin below which a body rests, rad/s, >= 0. Default 0.05 rad/s in 2D, 0.1 rad/s in 3D (as `linearSpeed`). */
  angularSpeed: number;
  /** How long every body of an island must rest before the island sleeps, s, > 0. Default 0.5 s (Box2D's and rapier's). */
  timeToSleep: number;
  /** Per entity: rest time, s; union-find parent; the island's least rest time; the island it sleeps in. */
  restTime: Float64Array;
  island: Int32Array;
  parent: Int32Array;
  islandRest: Float64Array;
  /** Per entity: the sleep stamp of the last step in which a contact pushed it (support). */
  supported: Uint32Array;
  /** Counts sleep-system runs; compared with `supported`. */
  stamp: number;
  /** Gravity seen at the last step (a change wakes everything). */
  readonly lastGravity: Float64Array;
  /** Whether any body may be asleep (skips the wake checks when false). */
  anyAsleep: boolean;
  /** Counts the bodies woken (their Sleeping tag removed) since the world was made: the contact events of sleeping pairs check it. */
  wakes: number;
}

/**
 * Everything the collide stage keeps between and within steps.
 * @category Collision
 */
export interface CollisionState {
  /** Tuning, see CollisionSettings. */
  readonly settings: CollisionSettings;
  /** The boundary box (disabled until `setBoundary`). */
  readonly boundary: Boundary;
  /** Candidate pairs from the broadphase (rows 0..pairCount-1), see `PairKind`. */
  pairCount: number;
  /** First entity of each pair: the lower ball id, or the segment. */
  pairA: Int32Array;
  /** Second entity of each pair: a ball. */
  pairB: Int32Array;
  /** PairKind of each pair. */
  pairKind: Uint8Array;
  /**
   * The contact buffer the collide stage fills during a step; empty between steps (its rows move to
   * `cache.rows` at the end of the solve). Read a finished step's contacts with `forEachContact`.
   */
  contacts: ContactBuffer;
  /** Impulses of the previous step's contacts, for warm starting. */
  readonly cache: WarmStartCache;
  /**
   * Per-entity scratch (capacity + 1): effective inverse mass this step (0 for static and kinematic).
   * This and the other per-entity arrays here and in `sleep` are empty until the world's first body
   * component (`allocateCollisionScratch`): a world of bare particles never collides.
   */
  invMass: Float64Array;
  /** Per-entity scratch: effective inverse moment of inertia this step. */
  invInertia: Float64Array;
  /** Per-entity scratch: speculative margin |v| h + speculativeDistance / 2, m. */
  margin: Float64Array;
  /** Per-entity scratch: BodyType (0 dynamic, 1 kinematic, 2 static) of this step's colliders. */
  bodyType: Uint8Array;
  /**
   * Solver bodies of this step: the moving bodies that have at least one contact, as entity ids;
   * index 0 is the static world. Their working state lives in `bodyState`, packed.
   */
  solverBodies: Int32Array;
  /** Solver bodies in use, the static world included. */
  solverBodyCount: number;
  /** Per-entity scratch: the value of `solverStamp` when the body was given a solver index. */
  solverMark: Float64Array;
  /** Per-entity scratch: the body's index in `solverBodies` this step. */
  solverIndex: Int32Array;
  /** Counter that makes `solverMark` entries of earlier steps stale. */
  solverStamp: number;
  /**
   * Packed solver state, one row per solver body (Box2D v3's b2BodyState, kept apart from the
   * components users touch): 2D rows of 8 (vx, vy, w, dx, dy, 1/m, 1/I, pushed), 3D rows of 12 (vx, vy,
   * vz, wx, wy, wz, dx, dy, dz, 1/m, 1/I, pushed); d is the displacement within the step, m; pushed is
   * 1 once a solver row has applied an impulse to the body this step (0: free flight, see solver/contact-solver.ts).
   * Offsets and strides: BS2_* and BS3_* in solver/body-state-layout.ts.
   */
  bodyState: Float64Array;
  /**
   * Per solver body, rows of 6: the base the displacement is added to (x, y, z), m, and the rotation still to apply
   * (x, y, z), rad. Offsets: BX_* in solver/body-state-layout.ts.
   */
  bodyExtra: Float64Array;
  /**
   * Per solver body, rows of 5 (impact stage, solver/impacts.ts; offsets in solver/body-state-layout.ts): the end-position
   * correction of this step's impacts (x, y, z), m (-dv t* summed over impacts), the time of its
   * latest impact in the step, s, and whether the soft substeps leave the body alone (1) or not (0).
   */
  bodyImpact: Float64Array;
  /**
   * An entity given the `Ball` component while the world's ball collisions were not installed
   * (collision/install-balls.ts: the package's ball makers install them; `addComponent` alone does
   * not), else 0. `step` refuses to run while it is set; `installBalls` clears it.
   */
  looseBall: number;
  /** Impact stage scratch: the bouncing contacts in order of impact, and their sort keys (s). */
  impactOrder: Int32Array;
  impactKey: Float64Array;
  /** Broadphase grid scratch, see collision/broadphase/grid.ts. */
  readonly grid: GridScratch;
  /** Bodies woken during this step's broadphase (their Sleeping tags are removed after the pass). */
  wakeList: Int32Array;
  wakeCount: number;
  /** Sleep: whether resting islands go to sleep, and the per-entity scratch it keeps; see islands/sleep.ts. */
  readonly sleep: SleepState;
  /** Contacts of 2D shapes (boxes, polygons, capsules, circles): manifolds and their warm start; see collision/manifolds-2d.ts. */
  readonly shapes: ShapeCollisionState;
  /**
   * The contact and sensor events of the step being run or last run, of every contact in 2D and 3D
   * (balls, shapes, segments, planes, the boundary box): see collision/events.ts; read with `contactEvents`.
   */
  readonly events: ContactEventLists;
  /** Touching contacts of sleeping bodies, kept across their sleep so it gives no end and begin events (collision/event-lists.ts). */
  readonly sleepingContacts: SleepingContacts;
  /** Statistics of the last step: candidate pairs, contacts, the deepest overlap left at its end (m), bodies asleep. */
  readonly stats: { pairs: number; contacts: number; maxOverlap: number; sleeping: number };
}

/**
 * Spatial-hash grid scratch, sized by the body count and grown by doubling.
 * @category Collision
 */
export interface GridScratch {
  /** Cell edge, m, chosen each step from the body sizes and speeds. */
  cellSize: number;
  /**
   * Table size and its bucket start offsets (size + 1): a power of two for the spatial hash, or the
   * number of cells of the dense grid (see `spanX`).
   */
  tableSize: number;
  /**
   * Dense grid, used when the cells around the bodies number at most DENSE_CELLS_PER_BODY per body (see
   * collision/broadphase/grid.ts): cell (cx, cy, cz) is bucket (cx - originX) + (cz - originZ) spanX + (originY - cy)
   * spanXZ, so the buckets, and the pairs, contacts and solver bodies that follow them, run through
   * space row by row from the top (y descending; in 3D each row of cells along x, the z rows, then y).
   * The range covers the bodies' cells and one more on every side, so every neighbour the pass looks at
   * is inside it; originY is its top row. spanX = 0: the spatial hash (hashCell & (tableSize - 1))
   * instead. Cell coordinates and counts, integers.
   */
  originX: number;
  originY: number;
  originZ: number;
  spanX: number;
  spanXZ: number;
  bucketStart: Int32Array;
  /** Bodies sorted by bucket: entity ids, and their cell coordinates. */
  sorted: Int32Array;
  cellX: Int32Array;
  cellY: Int32Array;
  cellZ: Int32Array;
  /** Per sorted body: its bucket. */
  bucketOf: Int32Array;
  /** Bodies too large or fast for the cell size, checked by range queries. */
  oversized: Int32Array;
  oversizedCount: number;
  /** Output of range queries. */
  candidates: Int32Array;
}

/**
 * Creates the collision state of a world with room for `capacity` entities; its per-entity arrays stay
 * empty until `allocateCollisionScratch`.
 * @category Collision
 */
export function createCollisionState(
  _capacity: number,
  options: { solverSubsteps: number; solverIterations: number; restitutionThreshold?: number; sleep: boolean; dimensions?: 2 | 3 },
): CollisionState {
  const n = 0;
  const cs: CollisionState = {
    settings: {
      solverSubsteps: options.solverSubsteps,
      autoSubsteps: true,
      solverIterations: options.solverIterations,
      relaxIterations: 1,
      restitutionThreshold: options.restitutionThreshold ?? 0.5,
      elasticRestitutionThreshold: options.restitutionThreshold ?? 0,
      impactIterations: 8,
      restitutionIterations: 4,
      contactHertz: 60,
      contactDampingRatio: 10,
      contactPushSpeed: 3,
      speculativeDistance: 0.1,
      coloredSolveMinRows: 16384,
      stickSpeed: 0.01,
    },
    boundary: {
      enabled: false,
      min: new Float64Array(3),
      max: new Float64Array(3),
      restitution: 0,
      friction: 0.6,
      staticFriction: 0.6,
    },
    pairCount: 0,
    pairA: new Int32Array(1024),
    pairB: new Int32Array(1024),
    pairKind: new Uint8Array(1024),
    contacts: createContactBuffer(1024),
    cache: createWarmStartCache(),
    invMass: new Float64Array(n),
    invInertia: new Float64Array(n),
    margin: new Float64Array(n),
    bodyType: new Uint8Array(n),
    solverBodies: new Int32Array(256),
    solverBodyCount: 0,
    solverMark: new Float64Array(n),
    solverIndex: new Int32Array(n),
    solverStamp: 0,
    bodyState: new Float64Array(BS3_STRIDE * 256),
    bodyExtra: new Float64Array(BX_STRIDE * 256),
    bodyImpact: new Float64Array(IMPACT_STRIDE * 256),
    looseBall: 0,
    impactOrder: new Int32Array(256),
    impactKey: new Float64Array(256),
    grid: {
      cellSize: 1,
      tableSize: 0,
      originX: 0,
      originY: 0,
      originZ: 0,
      spanX: 0,
      spanXZ: 0,
      bucketStart: new Int32Array(1),
      sorted: new Int32Array(0),
      cellX: new Int32Array(0),
      cellY: new Int32Array(0),
      cellZ: new Int32Array(0),
      bucketOf: new Int32Array(0),
      oversized: new Int32Array(0),
      oversizedCount: 0,
      candidates: new Int32Array(0),
    },
    wakeList: new Int32Array(64),
    wakeCount: 0,
    sleep: {
      enabled: options.sleep,
      linearSpeed: options.dimensions === 3 ? 0.1 : 0.05,
      angularSpeed: options.dimensions === 3 ? 0.1 : 0.05,
      timeToSleep: 0.5,
      restTime: new Float64Array(n),
      island: new Int32Array(n),
      parent: new Int32Array(n),
      islandRest: new Float64Array(n),
      supported: new Uint32Array(n),
      stamp: 0,
      lastGravity: new Float64Array(3),
      anyAsleep: false,
      wakes: 0,
    },
    shapes: createShapeCollisionState(),
    events: createContactEventStore(),
    sleepingContacts: createSleepingContacts(),
    stats: new CollisionStats(),
  };
  // The ball contacts' buffer and the warm-start cache's rows trade places every step
  // (collision/contacts.ts swapWarmStartRows): traded twice here so V8 does not treat the fields as
  // constant and drop the optimised code at the first trade (see createShapeCollisionState).
  for (let k = 0; k < 2; k++) [cs.contacts, cs.cache.rows] = [cs.cache.rows, cs.contacts];
  // The solver's packed arrays are replaced by larger ones in the first step of a big scene: each is
  // written once more here, with a fresh array of its type and length, for the same reason.
  cs.solverBodies = new Int32Array(cs.solverBodies.length);
  cs.bodyState = new Float64Array(cs.bodyState.length);
  cs.bodyExtra = new Float64Array(cs.bodyExtra.length);
  cs.bodyImpact = new Float64Array(cs.bodyImpact.length);
  cs.impactOrder = new Int32Array(cs.impactOrder.length);
  cs.impactKey = new Float64Array(cs.impactKey.length);
  markStepWritten(cs);
  return cs;
}

/**
 * Marks writable (world/writable-fields.ts) the fields of `cs` that a world's first steps write: its
 * counters and stamps, the shape state's grown or swapped arrays, broadphase scratch, manifold
 * buffers and event lists, the sleep state's counters. Written only from the first step on, each
 * first write threw away the code compiled earlier in that step (in a pyramid of 820 boxes, the
 * manifolds' preparation at the first `lastCount`).
 */
function markStepWritten(cs: CollisionState): void {
  markWritable(cs, ['pairCount', 'solverBodyCount', 'solverStamp', 'wakeCount', 'looseBall']);
  const st = cs.shapes;
  markWritable(st, [
    'active',
    'slots',
    'dormantSlots',
    'dormantWakes',
    'sensorPairs',
    'sensorNow',
    'angleBase',
    'solverRows',
    'lastCount',
    'bodyMark',
    'anyMoving',
  ]);
  const scratch = st.scratch;
  markWritable(scratch, Object.keys(scratch) as (keyof typeof scratch & string)[]);
  for (const buf of [st.manifolds, st.previous, st.dormant]) markWritable(buf, Object.keys(buf) as (keyof ManifoldBuffer & string)[]);
  const ev = cs.events;
  for (const list of [ev.begin, ev.end, ev.hit, ev.sensorBegin, ev.sensorEnd])
    markWritable(list, Object.keys(list) as (keyof typeof list & string)[]);
  markWritable(cs.sleep, ['stamp', 'anyAsleep', 'wakes']);
  markWritable(cs.stats, ['pairs', 'contacts', 'sleeping']);
}

/**
 * Gives the per-entity arrays of `cs` (inverse masses, margins, body types, solver marks, sleep state)
 * room for `capacity` entities if they are still empty, zero-filled. createPhysicsWorld calls it on the
 * first use of a body component (see world/components.ts).
 * @category Collision
 */
export function allocateCollisionScratch(cs: CollisionState, capacity: number): void {
  const n = capacity + 1;
  if (cs.invMass.length >= n) return;
  const make = <T extends Float64Array | Int32Array | Uint32Array | Uint8Array>(like: T): T =>
    new (like.constructor as new (x: number) => T)(n);
  cs.invMass = make(cs.invMass);
  cs.invInertia = make(cs.invInertia);
  cs.margin = make(cs.margin);
  cs.bodyType = make(cs.bodyType);
  cs.solverMark = make(cs.solverMark);
  cs.solverIndex = make(cs.solverIndex);
  const sl = cs.sleep;
  sl.restTime = make(sl.restTime);
  sl.island = make(sl.island);
  sl.parent = make(sl.parent);
  sl.islandRest = make(sl.islandRest);
  sl.supported = make(sl.supported);
}

/**
 * The collide stage's statistics (CollisionState.stats), a class so that every world's object has one
 * map: a literal made again in a later world can get another, which makes V8 drop the optimised code
 * compiled against the field.
 */
class CollisionStats {
  pairs = 0;
  contacts = 0;
  maxOverlap = 0;
  sleeping = 0;
  constructor() {
    // A fraction from the first step on (world/double-fields.ts).
    widenToDoubles(this, ['maxOverlap']);
  }
}
