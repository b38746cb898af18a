import { SN_STRIDE } from '../solver/contact-point-layout.js';
import { MAX_MANIFOLDS } from './manifold-limits-2d.js';

/**
 * Storage of shape contacts (2D): one row per manifold (a touching pair of shapes, up to two points),
 * structure of arrays grown by doubling, kept in `world.collision.shapes`. Like the ball contacts of
 * contacts.ts these are solver rows, not entities.
 *
 * Sign convention: the normal (nx, ny) points from shape A to shape B; the normal relative velocity
 * at a point is vn = (v_B + w_B x r_B - v_A - w_A x r_A) . n, negative when approaching. Body A or B
 * may be static or kinematic; a contact with a plane, a segment or the boundary box has body A = 0
 * (the static world) and `shapeA` the plane or segment entity, or -1 - face for a boundary face
 * (faces 0 -x, 1 +x, 2 -y, 3 +y).
 * @category Collision
 */
export interface ManifoldBuffer {
  /** Rows in use. */
  count: number;
  /** Rows allocated. */
  capacity: number;
  /** Shape entity of A (see the module comment for its special values). */
  shapeA: Int32Array;
  /** Shape entity of B. */
  shapeB: Int32Array;
  /** Body entity of A (0: the static world). */
  bodyA: Int32Array;
  /** Body entity of B (always an entity). */
  bodyB: Int32Array;
  /** Solver-body index of A this step (0: the static world); set by the solver. */
  ia: Int32Array;
  /** Solver-body index of B this step; set by the solver. */
  ib: Int32Array;
  /** Points in use, 1 or 2. */
  pointCount: Uint8Array;
  /** Unit normal from A to B, x. */
  nx: Float64Array;
  /** Unit normal from A to B, y (`nx` its x). */
  ny: Float64Array;
  /** Accumulated angular impulse of the rolling constraint, N m s (written after the solve). */
  rollingImpulse: Float64Array;
  /** 1 if the pair touched at the end of the step (a point carried a normal impulse, or overlapped). */
  touching: Uint8Array;
  /** Spawn stamp of shape A when the row was made (0 for the static world), to validate the warm start. */
  stampA: Uint32Array;
  /** Spawn stamp of shape B when the row was made. */
  stampB: Uint32Array;
  /** Per point (row i, point k at index 2 i + k): feature id. */
  id: Int32Array;
  /** Per point: contact point at the start of the step, world frame, x, m. */
  px: Float64Array;
  /** Per point: contact point y, m (`px` its x). */
  py: Float64Array;
  /** Per point: anchor from A's centre of mass to the point at the start of the step, x, m. */
  rAx: Float64Array;
  /** Per point: anchor from A's centre of mass to the point, y, m. */
  rAy: Float64Array;
  /** Per point: anchor from B's centre of mass to the point, x, m. */
  rBx: Float64Array;
  /** Per point: anchor from B's centre of mass to the point, y, m. */
  rBy: Float64Array;
  /** Per point: separation at the start of the step (from where the solver starts the bodies once prepareManifolds ran), m (< 0: overlap). */
  separation: Float64Array;
  /** Per point: accumulated normal impulse of the step's last substep, N s (written after the solve: the next step's warm start). */
  normalImpulse: Float64Array;
  /** Per point: accumulated tangent (friction) impulse of the step's last substep, N s (written after the solve). */
  tangentImpulse: Float64Array;
  /** Per point: normal impulse summed over the step's substeps, N s. */
  totalNormalImpulse: Float64Array;
  /** Per point: normal relative velocity at the start of the step, m/s (negative: approaching). */
  relativeVelocity: Float64Array;
}

const ROW_FLOAT = ['nx', 'ny', 'rollingImpulse'] as const;
const ROW_INT = ['shapeA', 'shapeB', 'bodyA', 'bodyB', 'ia', 'ib'] as const;
const POINT_FLOAT = [
  'px',
  'py',
  'rAx',
  'rAy',
  'rBx',
  'rBy',
  'separation',
  'normalImpulse',
  'tangentImpulse',
  'totalNormalImpulse',
  'relativeVelocity',
] as const;

/**
 * A manifold buffer with room for `capacity` rows (written as one literal: see contacts.ts).
 * @category Collision
 */
export function createManifoldBuffer(capacity = 256): ManifoldBuffer {
  const f = (): Float64Array => new Float64Array(capacity);
  const p = (): Float64Array => new Float64Array(2 * capacity);
  const i = (): Int32Array => new Int32Array(capacity);
  return {
    count: 0,
    capacity,
    shapeA: i(),
    shapeB: i(),
    bodyA: i(),
    bodyB: i(),
    ia: i(),
    ib: i(),
    pointCount: new Uint8Array(capacity),
    nx: f(),
    ny: f(),
    rollingImpulse: f(),
    touching: new Uint8Array(capacity),
    stampA: new Uint32Array(capacity),
    stampB: new Uint32Array(capacity),
    id: new Int32Array(2 * capacity),
    px: p(),
    py: p(),
    rAx: p(),
    rAy: p(),
    rBx: p(),
    rBy: p(),
    separation: p(),
    normalImpulse: p(),
    tangentImpulse: p(),
    totalNormalImpulse: p(),
    relativeVelocity: p(),
  };
}

/**
 * Grows `buf` (doubling) to hold at least `needed` rows, keeping rows 0..count-1.
 * @throws RangeError if `needed` is above MAX_MANIFOLDS.
 * @category Collision
 */
export function growManifoldBuffer(buf: ManifoldBuffer, needed: number): void {
  if (needed <= buf.capacity) return;
  if (needed > MAX_MANIFOLDS) throw new RangeError(`growManifoldBuffer: needed must be at most ${MAX_MANIFOLDS} manifolds, got ${needed}`);
  let cap = buf.capacity;
  while (cap < needed) cap *= 2;
  const rec = buf as unknown as Record<string, Float64Array | Int32Array | Uint32Array | Uint8Array>;
  const n = buf.count;
  const grow = (key: string, per: number): void => {
    const old = rec[key]!;
    const next = new (old.constructor as new (k: number) => typeof old)(cap * per);
    next.set(old.subarray(0, n * per));
    rec[key] = next;
  };
  for (const k of ROW_FLOAT) grow(k, 1);
  for (const k of ROW_INT) grow(k, 1);
  for (const k of POINT_FLOAT) grow(k, 2);
  grow('pointCount', 1);
  grow('touching', 1);
  grow('stampA', 1);
  grow('stampB', 1);
  grow('id', 2);
  buf.capacity = cap;
}

/**
 * Collider flags (ShapeScratch.flags).
 * @category Collision
 */
export const MOVING = 1,
  BALL = 2;

/**
 * Per-step scratch of the shape broadphase (colliders: shape entities and ball bodies).
 * @category Collision
 */
export interface ShapeScratch {
  /** Colliders this step: shape entity (a ball body counts as its own circle shape) and its body. */
  count: number;
  shape: Int32Array;
  body: Int32Array;
  /** Start-of-step transform of the collider's body: centre of mass (m) and cos, sin of its angle. */
  x: Float64Array;
  y: Float64Array;
  c: Float64Array;
  s: Float64Array;
  /** Fattened bounding box (m) and the speculative distance of the collider (m). */
  minX: Float64Array;
  minY: Float64Array;
  maxX: Float64Array;
  maxY: Float64Array;
  spec: Float64Array;
  /** Per collider: half the smaller extent of its start-of-step box plus its radius, m (how far it may move in a step and be met by speculative contacts; beyond that collision/continuous-2d.ts sweeps it). */
  size: Float64Array;
  /** Per collider: bit 1 its body moves this step (dynamic or kinematic), bit 2 it is a ball body without a shape. */
  flags: Uint8Array;
  /** Grid: cell of each collider's box corner, bucket starts, colliders sorted by bucket. */
  cellX: Int32Array;
  cellY: Int32Array;
  bucket: Int32Array;
  sorted: Int32Array;
  bucketStart: Int32Array;
  oversized: Int32Array;
  /** Candidate pairs (collider indices). */
  pairCount: number;
  pairI: Int32Array;
  pairJ: Int32Array;
}

function createShapeScratch(): ShapeScratch {
  const z = (): Float64Array => new Float64Array(0);
  const zi = (): Int32Array => new Int32Array(0);
  return {
    count: 0,
    shape: zi(),
    body: zi(),
    x: z(),
    y: z(),
    c: z(),
    s: z(),
    minX: z(),
    minY: z(),
    maxX: z(),
    maxY: z(),
    spec: z(),
    size: z(),
    flags: new Uint8Array(0),
    cellX: zi(),
    cellY: zi(),
    bucket: zi(),
    sorted: zi(),
    bucketStart: new Int32Array(1),
    oversized: zi(),
    pairCount: 0,
    pairI: new Int32Array(256),
    pairJ: new Int32Array(256),
  };
}

/**
 * Everything the shape collision keeps between and within steps; `world.collision.shapes`.
 * @category Collision
 */
export interface ShapeCollisionState {
  /** Whether any shape was ever added (until then the shape systems return at once). */
  active: boolean;
  /** This step's manifolds (the solver's rows). */
  manifolds: ManifoldBuffer;
  /** Last step's manifolds: warm start and end events. */
  previous: ManifoldBuffer;
  /** Hash of `previous` by (shapeA, shapeB): power-of-two slots (at least 16), row + 1 (0 empty). */
  slots: Int32Array;
  /**
   * The warm start of the contacts of sleeping bodies: their touching rows of the step they fell
   * asleep in, read by the first step after their wake (collision/dormant-manifolds-2d.ts).
   */
  dormant: ManifoldBuffer;
  /** Hash of `dormant` by (shapeA, shapeB), as `slots` is of `previous`. */
  dormantSlots: Int32Array;
  /** `sleep.wakes` when `dormant` was last pruned of the rows of woken bodies. */
  dormantWakes: number;
  /** Sensor overlaps of the last step, as keys shapeA * 2^25 + shapeB. */
  sensorPairs: Set<number>;
  /** Broadphase scratch. */
  readonly scratch: ShapeScratch;
  /** This step's contact softness table of the shape contacts (solver/contact-point-layout.ts SN_*), filled by prepareManifolds. */
  readonly softness: Float64Array;
  /** Per solver body: the rotation still owed at the start of the solve (its rotation within the step is measured from it). */
  angleBase: Float64Array;
  /**
   * This step's manifolds as the solver's packed rows (solver/manifold-layout-2d.ts: MR_STRIDE numbers a
   * manifold), filled by prepareManifolds before the substeps read them.
   */
  solverRows: Float64Array;
  /** Per entity (capacity + 1), allocated with the first shape: the body's first extra shape entity (0 none). */
  firstShape: Int32Array;
  /** Per entity: where the body's reference point (its position when created) lies from its centre of mass, body frame, x, m. */
  originX: Float64Array;
  /** Per entity: the reference point's offset from the centre of mass, y, m (`originX` its x). */
  originY: Float64Array;
  /** Sleeping bodies reached by moving ones in this pass of the shape collision (woken within the step). */
  wakeNow: number[];
  /** Rows the emptied buffer held before `rotateManifolds` (the step before's, for end events). */
  lastCount: number;
  /** Sensor overlaps found this step (swapped with `sensorPairs`). */
  sensorNow: Set<number>;
  /** Per entity: stamp of the step in which the body was classified. */
  bodyMarks: Uint32Array;
  /** The step counter of `bodyMarks`. */
  bodyMark: number;
  /** Whether any collider moves this step (else the broadphase has nothing to pair). */
  anyMoving: boolean;
  /** Per entity: the body's angular velocity this step (0 if it does not turn), rad/s. */
  bodyW: Float64Array;
  /** Per entity: the body's angle at the start of the step, rad. */
  bodyAngle0: Float64Array;
}

/**
 * The state of a world without shapes (arrays are allocated with the first shape).
 * @category Collision
 */
export function createShapeCollisionState(): ShapeCollisionState {
  const st: ShapeCollisionState = {
    active: false,
    manifolds: createManifoldBuffer(),
    previous: createManifoldBuffer(),
    slots: new Int32Array(16),
    dormant: createManifoldBuffer(16),
    dormantSlots: new Int32Array(0),
    dormantWakes: 0,
    sensorPairs: new Set(),
    scratch: createShapeScratch(),
    softness: new Float64Array(SN_STRIDE),
    angleBase: new Float64Array(256),
    solverRows: new Float64Array(0),
    firstShape: new Int32Array(0),
    originX: new Float64Array(0),
    originY: new Float64Array(0),
    wakeNow: [],
    lastCount: 0,
    sensorNow: new Set(),
    bodyMarks: new Uint32Array(0),
    bodyMark: 0,
    bodyW: new Float64Array(0),
    bodyAngle0: new Float64Array(0),
    anyMoving: false,
  };
  // rotateManifolds swaps these two every step. V8 treats a field written only when its object was
  // made as constant, and at the first other write drops the optimised code that relied on that:
  // every shape stage's, after the first step. Swapped twice here (back as they were), the fields are
  // writable before any code is optimised.
  for (let k = 0; k < 2; k++) [st.manifolds, st.previous] = [st.previous, st.manifolds];
  return st;
}

/**
 * Allocates the per-entity arrays of the shape state (with the world's first shape).
 * @category Collision
 */
export function ensureShapeState(st: ShapeCollisionState, capacity: number): void {
  if (st.firstShape.length > 0) return;
  const n = capacity + 1;
  st.firstShape = new Int32Array(n);
  st.originX = new Float64Array(n);
  st.originY = new Float64Array(n);
  st.bodyMarks = new Uint32Array(n);
  st.bodyW = new Float64Array(n);
  st.bodyAngle0 = new Float64Array(n);
}

/**
 * Hash of a shape pair key (the boundary's negative shape ids included).
 * @category Collision
 */
export function pairHash(a: number, b: number): number {
  let h = Math.imul(a, 0x9e3779b1) ^ Math.imul(b, 0x85ebca77);
  h ^= h >>> 15;
  return Math.imul(h, 0x27d4eb2f) >>> 0;
}

/**
 * Finds the row of `previous` for the pair (a, b), or -1.
 * @category Collision
 */
export function findPrevious(st: ShapeCollisionState, a: number, b: number): number {
  const slots = st.slots;
  const size = slots.length;
  if (size === 0) return -1;
  const mask = size - 1;
  const prev = st.previous;
  let s = pairHash(a, b) & mask;
  for (;;) {
    const r = slots[s]!;
    // The slot's pair is read and compared before the empty-slot test, row 0's for an empty slot: a
    // world's first step finds every slot empty, and code compiled then would lack these loads and
    // comparisons (V8 records no type feedback for code that never ran) and be thrown away at the
    // first pair found in the second step.
    const i = Math.max(r - 1, 0);
    const sameA = prev.shapeA[i] === a,
      sameB = prev.shapeB[i] === b;
    const next = (s + 1) & mask;
    if (r === 0) return -1;
    if (sameA && sameB) return i;
    s = next;
  }
}

/**
 * Makes `manifolds` the previous step's (swapping buffers) and hashes it; the new current buffer is
 * empty (count 0) but keeps the rows of the step before until refilled (`lastCount` of them).
 * @category Collision
 */
/**
 * A zeroed open-addressing table of at least `n` slots (a power of two, at least 16). Its own function:
 * code that runs only in a world's first steps, before V8 records type feedback, is compiled as a
 * deoptimisation, and inside rotateManifolds it would throw the whole function back to the
 * interpreter in a later world's first step.
 */
function slotTable(n: number): Int32Array {
  let size = 16;
  while (size < n) size *= 2;
  return new Int32Array(size);
}

export function rotateManifolds(st: ShapeCollisionState): void {
  const cur = st.manifolds;
  st.manifolds = st.previous;
  st.lastCount = st.manifolds.count;
  st.manifolds.count = 0;
  st.previous = cur;
  const n = cur.count;
  // The table's growth runs only in a world's first steps: kept out of this function (see slotTable).
  const slots = st.slots.length >= 2 * n && st.slots.length > 0 ? st.slots.fill(0) : (st.slots = slotTable(2 * n));
  const mask = slots.length - 1;
  for (let i = 0; i < n; i++) {
    let s = pairHash(cur.shapeA[i]!, cur.shapeB[i]!) & mask;
    while (slots[s] !== 0) s = (s + 1) & mask;
    slots[s] = i + 1;
  }
}
