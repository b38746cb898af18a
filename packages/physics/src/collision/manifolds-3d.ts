import { SN_STRIDE } from '../solver/contact-point-layout.js';
import { ANCHOR_STRIDE } from '../solver/manifold-layout-3d.js';
import { registerExternalWorldState } from '../world/external-state.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * The 3D shape contacts of a world: this step's manifolds as solver rows (structure of arrays, four
 * point slots a manifold), last step's rows for warm starting (looked up by shape pair, then by
 * feature id), and the per-solver-body world inverse inertia tensors. Kept outside the world object
 * (registered for snapshots).
 * @category Collision
 */
export interface Manifold3DBuffer {
  count: number;
  /** Body slots (0: the static world, e.g. a plane) and shape slots (a plane's own slot for a plane). */
  bodyA: Int32Array;
  bodyB: Int32Array;
  shapeA: Int32Array;
  shapeB: Int32Array;
  /** 0, or for a row against a triangle mesh the triangle's index + 1 (a mesh pair has a row per triangle). */
  sub: Int32Array;
  /** Solver indices of the bodies (0: static). */
  ia: Int32Array;
  ib: Int32Array;
  /** Points in use (1 to 4), unit normal A to B, tangents (t1, t2 = n x t1), friction and restitution. */
  points: Uint8Array;
  /** 1 when both bodies' world inverse inertia is isotropic (i 1) this step (solver/manifold-rows-3d.ts reads fewer numbers), else 0. */
  iso: Uint8Array;
  nx: Float64Array;
  ny: Float64Array;
  nz: Float64Array;
  t1x: Float64Array;
  t1y: Float64Array;
  t1z: Float64Array;
  friction: Float64Array;
  restitution: Float64Array;
  /**
   * Per point (4 i + k): anchors from the centres of mass (m, world), r_A then r_B side by side
   * (solver/manifold-layout-3d.ts ANCHOR_*, ANCHOR_STRIDE numbers a point); separation at the step's
   * start (m); feature id.
   */
  anchors: Float64Array;
  sep: Float64Array;
  id: Float64Array;
  /**
   * Per point: accumulated normal impulse (N s); approach speed at the start (m/s); 1 once the point has carried a normal impulse this step (> 0 after some pass),
   * else 0.
   */
  ln: Float64Array;
  vn0: Float64Array;
  carried: Uint8Array;
  /**
   * Per row, the manifold's friction (solver/manifold-rows-3d.ts: one anchor a manifold), three numbers a
   * row (one run of memory the solve reads and writes): accumulated impulses along t1 and t2 (N s) and
   * about n (twist, N m s). Their effective masses and the twist arm are rebuilt
   * every step by the prepare, straight into the solve's head (solver/manifold-layout-3d.ts HEAD_MT1 ..).
   */
  ft: Float64Array;
  /**
   * Box-box rows (collision/shapes-3d.ts reuses them while the pair's relative pose barely changes): 1 when
   * the row carries the fields below, else 0. `relPose` (12 a row): B's centre in A's frame, m, then
   * R_A^T R_B row-major, when the manifold was last computed; `localNormal` (3 a row): the normal in A's
   * frame; `localA`, `localB` (3 a point, 12 a row): each point's ends on A's and B's surfaces in their frames, m.
   */
  local: Uint8Array;
  relPose: Float64Array;
  localNormal: Float64Array;
  localA: Float64Array;
  localB: Float64Array;
  /**
   * Per row: the previous step's row of the same key (`previous`, for warm starting), or -1; written
   * when the row is made. `touch`: the pair's entry in the touch list the row's step ended with
   * (Contact3DState.touching), or -1 if the row did not touch; written by finishManifolds3D
   * (solver/manifold-rows-3d.ts), which reads the previous row's to find, without a hash look-up, a
   * pair that touched last step too.
   */
  prevRow: Int32Array;
  touch: Int32Array;
}

function createBuffer(n: number): Manifold3DBuffer {
  const i = (k: number): Int32Array => new Int32Array(k),
    f = (k: number): Float64Array => new Float64Array(k);
  const p = 4 * n;
  return {
    count: 0,
    bodyA: i(n),
    bodyB: i(n),
    shapeA: i(n),
    shapeB: i(n),
    sub: i(n),
    ia: i(n),
    ib: i(n),
    points: new Uint8Array(n),
    iso: new Uint8Array(n),
    nx: f(n),
    ny: f(n),
    nz: f(n),
    t1x: f(n),
    t1y: f(n),
    t1z: f(n),
    friction: f(n),
    restitution: f(n),
    anchors: f(ANCHOR_STRIDE * p),
    sep: f(p),
    id: f(p),
    ln: f(p),
    vn0: f(p),
    carried: new Uint8Array(p),
    ft: f(3 * n),
    local: new Uint8Array(n),
    relPose: f(12 * n),
    localNormal: f(3 * n),
    localA: f(3 * p),
    localB: f(3 * p),
    prevRow: i(n),
    touch: i(n),
  };
}

/**
 * Doubles a buffer's room (again until it holds at least `rows` rows, if given), keeping its rows.
 * @category Collision
 */
export function growManifold3DBuffer(b: Manifold3DBuffer, rows = 0): Manifold3DBuffer {
  let n = b.bodyA.length * 2;
  while (n < rows) n *= 2;
  const g = createBuffer(n) as unknown as Record<string, unknown>;
  for (const [k, v] of Object.entries(b))
    if (ArrayBuffer.isView(v)) (g[k] as { set(a: ArrayLike<number>): void }).set(v as unknown as ArrayLike<number>);
  g.count = b.count;
  return g as unknown as Manifold3DBuffer;
}

/**
 * The world's 3D contact state.
 * @category Collision
 */
export interface Contact3DState {
  current: Manifold3DBuffer;
  previous: Manifold3DBuffer;
  /** Row key (`rowKey`) -> row in `previous`. */
  previousIndex: RowIndex;
  /** World inverse inertia tensor per solver body index (6 a body: xx, yy, zz, xy, xz, yz), 1 / (kg m^2). */
  invInertia: Float64Array;
  /** Pairs touching at the end of the last step (for begin and end events). */
  touching: TouchList;
  /** The list the next step's touching pairs are written into (swapped with `touching`). */
  touchingNext: TouchList;
  /** Sensor overlaps of the last step, as `touching`. */
  sensing: Map<number, number[]>;
  /** Sensor overlaps found this step (moved into `sensing` when the step's events are made). */
  sensingNow: Map<number, number[]>;
  /**
   * Per point of `current` (6 numbers each, solver/manifold-layout-3d.ts JAC_STRIDE): I^-1 (r x n) of both
   * bodies, written only for rows whose bodies are not isotropic (a pile of cubes never reads it).
   * Rebuilt every step; single precision.
   */
  jacobiansInv: Float32Array;
  /**
   * Per row of `current` (18 numbers each, not isotropic rows only): I^-1 (r x u) of both bodies for the
   * friction anchor's u = t1, t2, then I^-1 n of both (twist). Rebuilt every step; single precision.
   */
  frictionInv: Float32Array;
  /**
   * Per row of `current` (solver/manifold-layout-3d.ts REC_STRIDE numbers each): everything the solve reads
   * of the row every pass in one block: normal, tangent, friction, effective masses, the speculative
   * skip's bounds, isotropic inverse inertias, the friction anchor's crosses, and each point's r x n of
   * both bodies, separation and effective mass along n. Written by prepareManifolds3D; rebuilt every step.
   */
  solveRecord: Float64Array;
  /** 0 or 1, flipped at every biased solve pass: the order the points of a manifold are solved in (solver/manifold-rows-3d.ts). */
  solveParity: number;
  /** Per solver body: its rotation owed at the start of the solve (the linearised rotation is measured from it). */
  rotationBase: Float64Array;
  /** This step's contact softness table (solver/contact-point-layout.ts SN_*), filled by prepareManifolds3D. */
  readonly softness: Float64Array;
}

/**
 * Key of a row for warm starting: shapeA (capacity + 1) + shapeB, or for a mesh triangle -(shapeB 2^22 + triangle + 1).
 * @category Collision
 */
export function rowKey(capacity: number, shapeA: number, shapeB: number, sub: number): number {
  return sub === 0 ? shapeA * (capacity + 1) + shapeB : -(shapeB * 4194304 + sub);
}

/**
 * A hash table from row keys to rows (open addressing with linear probing, in typed arrays, so building
 * it each step allocates nothing once it has grown to the pile's size).
 * @category Collision
 */
export interface RowIndex {
  /** Keys (row keys; unused slots hold NaN) and rows, mask + 1 slots. */
  keys: Float64Array;
  rows: Int32Array;
  mask: number;
  /** Keys inserted since the last clear (a clear of an empty index costs nothing). */
  count: number;
}

function createRowIndex(): RowIndex {
  return { keys: new Float64Array(64).fill(NaN), rows: new Int32Array(64), mask: 63, count: 0 };
}

/**
 * Empties the index and makes room for `count` keys (at most half full).
 * @category Collision
 */
export function clearRowIndex(index: RowIndex, count: number): void {
  let size = index.mask + 1;
  if (size < 2 * count) {
    while (size < 2 * count) size *= 2;
    index.keys = new Float64Array(size).fill(NaN);
    index.rows = new Int32Array(size);
    index.mask = size - 1;
  } else if (index.count > 0) index.keys.fill(NaN);
  index.count = 0;
}

function slotOfKey(key: number, mask: number): number {
  // Mix the key's low and high 32 bits (keys are non-negative integers below 2^53, or their negatives).
  const lo = (key % 4294967296) | 0,
    hi = (key / 4294967296) | 0;
  return (Math.imul(lo ^ (lo >>> 16), 0x45d9f3b) ^ Math.imul(hi, 0x27d4eb2d)) & mask;
}

/**
 * Adds key -> row (the index must have room: clearRowIndex).
 * @category Collision
 */
export function insertRow(index: RowIndex, key: number, row: number): void {
  const K = index.keys,
    mask = index.mask;
  let h = slotOfKey(key, mask);
  while (K[h] === K[h] && K[h] !== key) h = (h + 1) & mask;
  K[h] = key;
  index.rows[h] = row;
  index.count++;
}

/**
 * The slot of `key` in the index: where it is, or the empty slot an insert would put it in (the caller
 * tells them apart by index.keys[slot] === key, and fills an empty one: keys, rows and count).
 * @category Collision
 */
export function slotOfRow(index: RowIndex, key: number): number {
  const K = index.keys,
    mask = index.mask;
  let h = slotOfKey(key, mask);
  for (;;) {
    const k = K[h]!;
    if (k === key || k !== k) return h;
    h = (h + 1) & mask;
  }
}

/**
 * The row of `key`, or -1.
 * @category Collision
 */
export function lookupRow(index: RowIndex, key: number): number {
  const K = index.keys,
    mask = index.mask;
  let h = slotOfKey(key, mask);
  for (;;) {
    const k = K[h]!;
    if (k === key) return index.rows[h]!;
    if (k !== k) return -1;
    h = (h + 1) & mask;
  }
}

/**
 * Touching shape pairs: key (shapeA (capacity + 1) + shapeB), the shapes and their bodies (slots), indexed by key.
 * @category Collision
 */
export interface TouchList {
  count: number;
  keys: Float64Array;
  shapeA: Int32Array;
  shapeB: Int32Array;
  bodyA: Int32Array;
  bodyB: Int32Array;
  index: RowIndex;
}

function createTouchList(n = 64): TouchList {
  return {
    count: 0,
    keys: new Float64Array(n),
    shapeA: new Int32Array(n),
    shapeB: new Int32Array(n),
    bodyA: new Int32Array(n),
    bodyB: new Int32Array(n),
    index: createRowIndex(),
  };
}

/**
 * Appends a pair (growing the list; the caller indexes it). Returns its row.
 * @category Collision
 */
export function pushTouch(l: TouchList, key: number, shapeA: number, shapeB: number, bodyA: number, bodyB: number): number {
  if (l.count >= l.keys.length) {
    const n = 2 * l.keys.length;
    const f = new Float64Array(n);
    f.set(l.keys);
    l.keys = f;
    for (const k of ['shapeA', 'shapeB', 'bodyA', 'bodyB'] as const) {
      const a = new Int32Array(n);
      a.set(l[k]);
      l[k] = a;
    }
  }
  const i = l.count++;
  l.keys[i] = key;
  l.shapeA[i] = shapeA;
  l.shapeB[i] = shapeB;
  l.bodyA[i] = bodyA;
  l.bodyB[i] = bodyB;
  return i;
}

/**
 * The world's 3D contact state (made when `create` is true).
 * @category Collision
 */
export function contact3DStateOf(world: PhysicsWorld, create: true): Contact3DState;
export function contact3DStateOf(world: PhysicsWorld, create?: boolean): Contact3DState | undefined;
export function contact3DStateOf(world: PhysicsWorld, create = false): Contact3DState | undefined {
  let s = world.features.contacts3d as Contact3DState | undefined;
  if (s === undefined && create) {
    s = {
      current: createBuffer(64),
      previous: createBuffer(64),
      previousIndex: createRowIndex(),
      invInertia: new Float64Array(6 * 64),
      rotationBase: new Float64Array(3 * 64),
      touching: createTouchList(),
      touchingNext: createTouchList(),
      sensing: new Map(),
      sensingNow: new Map(),
      solveParity: 0,
      jacobiansInv: new Float32Array(0),
      frictionInv: new Float32Array(0),
      solveRecord: new Float64Array(0),
      softness: new Float64Array(SN_STRIDE),
    };
    // Swapped every step (collision/shapes-3d.ts): swapped twice here so V8 does not treat them as
    // constant and drop the optimised code at the first swap (see createShapeCollisionState).
    for (let k = 0; k < 2; k++) [s.current, s.previous] = [s.previous, s.current];
    world.features.contacts3d = s;
  }
  return s;
}

registerExternalWorldState({
  name: 'contacts3d',
  get: (world, create) => contact3DStateOf(world, create),
  clear: (world) => {
    world.features.contacts3d = undefined;
  },
});
