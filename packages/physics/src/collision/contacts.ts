/**
 * Contact storage: one row per contact point, structure of arrays, grown by doubling (never per step).
 *
 * Contacts are transient solver data, not entities: tens of thousands a step would be too slow as
 * bitecs entities. After a step, read the step's contacts with `forEachContact` (collision/contact-view.ts; the rows then live in
 * `world.collision.cache.rows`, rows 0..count-1; `world.collision.contacts` is the buffer the next
 * step fills and holds no rows between steps).
 *
 * Sign convention: the normal (nx, ny, nz) points from body A to body B, and the normal relative
 * velocity is vn = (v_B - v_A) . n, negative when approaching. A is 0 (the static world) for
 * contacts with the boundary box, static segments and static balls.
 */

import * as WARM from '../solver/slots/warm-start.js';
import { warmStartTable } from '../solver/warm-start-kernel.js';
import type { KernelArray } from '../threads/kernel-types.js';

/**
 * What body A of a contact is:
 * - `Ball` (0): two balls, both entities (either may be kinematic);
 * - `Boundary` (1): ball B against a face of the boundary box; `feature` is the face
 *   (0 -x, 1 +x, 2 -y, 3 +y, 4 -z, 5 +z);
 * - `Segment` (2): ball B against the static segment entity `feature`;
 * - `StaticBall` (3): ball B against the static ball entity `feature`;
 * - `Plane` (4): ball B against the static plane entity `feature`;
 * - `Shape` (5): never a row of this buffer: the kind `forEachContact` gives a contact of shapes (the 2D
 *   and 3D manifolds, collision/manifolds-2d.ts and manifolds-3d.ts).
 * @category Collision
 */
export const ContactKind = Object.freeze({ Ball: 0, Boundary: 1, Segment: 2, StaticBall: 3, Plane: 4, Shape: 5 } as const);

/**
 * The contact rows of one step.
 * @category Collision
 */
export interface ContactBuffer {
  /** Rows in use. */
  count: number;
  /** Rows allocated. */
  capacity: number;
  /** ContactKind of each row. */
  kind: Uint8Array;
  /** Body A entity id (0 = static world). */
  a: Int32Array;
  /** Body B entity id (always a moving body). */
  b: Int32Array;
  /** Solver-body indices of A and B this step (0 = static world); set by the solver. */
  ia: Int32Array;
  ib: Int32Array;
  /** Static feature: boundary face or static entity id, see ContactKind. */
  feature: Int32Array;
  /** Unit normal from A to B. */
  nx: Float64Array;
  ny: Float64Array;
  nz: Float64Array;
  /** Separation along the normal where the bodies were at the start of the step, m (< 0: overlap). */
  separation: Float64Array;
  /** Distance from A's centre to the contact point along +n, m (0 for the static world). */
  ra: Float64Array;
  /** Distance from B's centre to the contact point along -n, m. */
  rb: Float64Array;
  /** Combined restitution, [0, 1]. */
  restitution: Float64Array;
  /** Combined kinetic friction coefficient. */
  friction: Float64Array;
  /** Friction bound used this step: mu_s while sticking, mu_k while sliding. */
  frictionBound: Float64Array;
  /** Effective mass along the normal, kg. */
  normalMass: Float64Array;
  /** Effective mass along the tangents, kg. */
  tangentMass: Float64Array;
  /** 1 if either body has infinite mass (inverse mass 0 in the solver: static, sleeping or kinematic; solver/rigid-partner.ts): the contact uses the stiffer softness. */
  rigidPartner: Uint8Array;
  /** Accumulated normal impulse of a solver substep, N s (>= 0). Warm-started from the previous step. */
  normalImpulse: Float64Array;
  /** Largest normal impulse applied in any substep this step, N s (restitution applies only if > 0). */
  maxNormalImpulse: Float64Array;
  /** Normal impulse delivered over the soft substeps (sum over substeps), N s: the compression impulse. */
  totalNormalImpulse: Float64Array;
  /**
   * Normal impulse the contact delivered over the whole step, N s (>= 0): impact, soft substeps and
   * restitution together. Body B received +impulse n, body A -impulse n.
   */
  impulse: Float64Array;
  /**
   * Normal relative speed at impact, m/s (negative: approaching): the start-of-step speed plus what
   * gravity adds across the speculative gap, so a bounce neither loses nor gains that energy; for a
   * contact the impact stage bounced this step, the approach speed at its time of impact.
   */
  impactVelocity: Float64Array;
  /** Accumulated friction impulse along tangent 1, N s. */
  tangentImpulse1: Float64Array;
  /** Accumulated friction impulse along tangent 2 (3D only), N s. */
  tangentImpulse2: Float64Array;
  /** Tangent 1 (3D: first axis of the basis (n, t1, n x t1); 2D: (-ny, nx)). */
  t1x: Float64Array;
  t1y: Float64Array;
  t1z: Float64Array;
  /** Normal relative velocity at the start of the step, before this step's gravity, m/s (negative: approaching). */
  relativeVelocity: Float64Array;
  /** Spawn stamps of A (or of the static feature) and B when the contact was made, to validate the warm-start cache. */
  stampA: Uint32Array;
  stampB: Uint32Array;
  /**
   * The row of the same contact among the previous step's rows (`cache.rows`), or -1 for a new
   * contact: found with the warm start when the rows are prepared, read by the contact events.
   */
  previous: Int32Array;
  /** 1 if the contact touched in its step (it carried a normal impulse, or overlapped at the start), else 0: begin and end events. */
  touching: Uint8Array;
  /** Rows whose `touching` is 1 (set with them). */
  touchingCount: number;
}

const FLOAT_FIELDS = [
  'nx',
  'ny',
  'nz',
  'separation',
  'ra',
  'rb',
  'restitution',
  'friction',
  'frictionBound',
  'normalMass',
  'tangentMass',
  'normalImpulse',
  'maxNormalImpulse',
  'totalNormalImpulse',
  'impulse',
  'impactVelocity',
  'tangentImpulse1',
  'tangentImpulse2',
  't1x',
  't1y',
  't1z',
  'relativeVelocity',
] as const;
const INT_FIELDS = ['a', 'b', 'ia', 'ib', 'feature', 'previous'] as const;
const UINT_FIELDS = ['stampA', 'stampB'] as const;

/**
 * Allocates a contact buffer with room for `capacity` rows. Written as one object literal on purpose:
 * an object that gains many properties through computed keys drops into V8's slow dictionary mode.
 * @category Collision
 */
export function createContactBuffer(capacity = 1024): ContactBuffer {
  const f = (): Float64Array => new Float64Array(capacity);
  return {
    count: 0,
    capacity,
    kind: new Uint8Array(capacity),
    a: new Int32Array(capacity),
    b: new Int32Array(capacity),
    ia: new Int32Array(capacity),
    ib: new Int32Array(capacity),
    feature: new Int32Array(capacity),
    nx: f(),
    ny: f(),
    nz: f(),
    separation: f(),
    ra: f(),
    rb: f(),
    restitution: f(),
    friction: f(),
    frictionBound: f(),
    normalMass: f(),
    tangentMass: f(),
    rigidPartner: new Uint8Array(capacity),
    normalImpulse: f(),
    maxNormalImpulse: f(),
    totalNormalImpulse: f(),
    impulse: f(),
    impactVelocity: f(),
    tangentImpulse1: f(),
    tangentImpulse2: f(),
    t1x: f(),
    t1y: f(),
    t1z: f(),
    relativeVelocity: f(),
    stampA: new Uint32Array(capacity),
    stampB: new Uint32Array(capacity),
    previous: new Int32Array(capacity),
    touching: new Uint8Array(capacity),
    touchingCount: 0,
  };
}

/**
 * Doubles the rows of `buf` until it holds at least `needed`, keeping rows 0..count-1.
 * @category Collision
 */
export function growContactBuffer(buf: ContactBuffer, needed: number): void {
  if (needed <= buf.capacity) return;
  let cap = buf.capacity;
  while (cap < needed) cap *= 2;
  const rec = buf as unknown as Record<string, Float64Array | Int32Array | Uint32Array | Uint8Array>;
  const grow = <T extends Float64Array | Int32Array | Uint32Array | Uint8Array>(old: T, make: (n: number) => T): T => {
    const next = make(cap);
    next.set(old.subarray(0, buf.count));
    return next;
  };
  buf.kind = grow(buf.kind, (n) => new Uint8Array(n));
  buf.rigidPartner = grow(buf.rigidPartner, (n) => new Uint8Array(n));
  buf.touching = grow(buf.touching, (n) => new Uint8Array(n));
  for (const f of FLOAT_FIELDS) rec[f] = grow(rec[f] as Float64Array, (n) => new Float64Array(n));
  for (const f of INT_FIELDS) rec[f] = grow(rec[f] as Int32Array, (n) => new Int32Array(n));
  for (const f of UINT_FIELDS) rec[f] = grow(rec[f] as Uint32Array, (n) => new Uint32Array(n));
  buf.capacity = cap;
}

/**
 * Contact rows a world of `balls` balls may need at most in its usual scenes: 4 a ball in 3D, 2.5 in 2D
 * (settled piles measured about 3.8 and 2.3: spheres-in-box 5,000 and balls-in-box 20,000 after 200
 * steps; close packing with walls reaches about 7 and 3.5, one doubling further).
 * @category Collision
 */
export function contactRowsEstimate(balls: number, dimensions: number): number {
  return Math.ceil(balls * (dimensions === 3 ? 4 : 2.5));
}

/**
 * Warm-start cache: the accumulated impulses of the previous step's contacts, found by
 * (kind, a, b, feature) in an open-addressing hash table (linear probing). Starting the solver from
 * last step's impulses is what lets a few iterations hold a deep pile still (Catto, "Iterative
 * Dynamics with Temporal Coherence", GDC 2005).
 * @category Collision
 */
export interface WarmStartCache {
  /** Power-of-two slot count. */
  size: number;
  /** Slot -> row + 1 in `rows` (0 = empty). */
  slots: Int32Array;
  /** The previous step's contacts (rows 0..count-1). */
  rows: ContactBuffer;
}

/**
 * Makes an empty cache.
 * @category Collision
 */
export function createWarmStartCache(): WarmStartCache {
  return { size: 0, slots: new Int32Array(0), rows: createContactBuffer(16) };
}

function hashKey(kind: number, a: number, b: number, f: number): number {
  let h = Math.imul(a ^ (kind << 28), 0x9e3779b1);
  h ^= Math.imul(b, 0x85ebca77);
  h ^= Math.imul(f, 0xc2b2ae3d);
  h ^= h >>> 15;
  return Math.imul(h, 0x27d4eb2f) >>> 0;
}

/**
 * Makes `cache.slots` hold a warm-start table for `n` rows (>= 0): the least power of two slots, at
 * least 16, that is at least 2n, kept when the present table is large enough; on a SharedArrayBuffer
 * when `shared` (a worker builds it) or when it is already there. Its contents are left to the build
 * (solver/warm-start-kernel.ts warmStartTable zeroes them).
 * @category Collision
 */
export function reserveWarmStartTable(cache: WarmStartCache, n: number, shared: boolean): void {
  const fits = cache.size >= 2 * n && cache.size !== 0;
  if (fits && (!shared || (typeof SharedArrayBuffer === 'function' && cache.slots.buffer instanceof SharedArrayBuffer))) return;
  let size = cache.size;
  if (!fits) {
    size = 16;
    while (size < 2 * n) size *= 2;
  }
  cache.slots = shared ? new Int32Array(new SharedArrayBuffer(4 * size)) : new Int32Array(size);
  cache.size = size;
}

/**
 * Makes `current` the cache's rows (no copying) and returns the buffer the caller should fill next,
 * emptied (it holds stale rows, refilled from count 0).
 * @category Collision
 */
export function swapWarmStartRows(cache: WarmStartCache, current: ContactBuffer): ContactBuffer {
  const spare = cache.rows;
  cache.rows = current;
  spare.count = 0;
  return spare;
}

/** warmStartTable's arguments on the calling thread (storeWarmStart). Not state. */
const tableArrays: KernelArray[] = [];
const tableParams = new Float64Array(2);

/**
 * Stores this step's contacts as the cache for the next step: the rows by swapWarmStartRows, the
 * table (slot -> row + 1 by hashKey and linear probing) built here by warmStartTable.
 * Returns the buffer the caller should use as its next `current`.
 * @category Collision
 */
export function storeWarmStart(cache: WarmStartCache, current: ContactBuffer): ContactBuffer {
  reserveWarmStartTable(cache, current.count, false);
  warmStartArguments(cache, current, tableArrays, tableParams);
  warmStartTable(tableArrays, tableParams, null, 0, 1);
  return swapWarmStartRows(cache, current);
}

/**
 * Fills warmStartTable's arguments (the WARM slots of solver/slots/warm-start.ts) for the table of
 * `cache` over the rows of `rows`: `A` is emptied first, `P` needs 2 slots.
 * @category Collision
 */
export function warmStartArguments(cache: WarmStartCache, rows: ContactBuffer, A: KernelArray[], P: Float64Array): void {
  A.length = 0;
  A[WARM.SLOTS] = cache.slots;
  A[WARM.KIND] = rows.kind;
  A[WARM.A] = rows.a;
  A[WARM.B] = rows.b;
  A[WARM.FEATURE] = rows.feature;
  P[WARM.ROWS] = rows.count;
  P[WARM.SLOT_COUNT] = cache.size;
}

/**
 * Finds the previous step's row of the contact (kind, a, b, feature) with matching spawn stamps,
 * or -1 if it is new.
 * @category Collision
 */
export function findWarmStart(
  cache: WarmStartCache,
  kind: number,
  a: number,
  b: number,
  f: number,
  stampA: number,
  stampB: number,
): number {
  if (cache.size === 0) return -1;
  const mask = cache.size - 1;
  const slots = cache.slots;
  const rows = cache.rows;
  let s = hashKey(kind, a, b, f) & mask;
  for (;;) {
    const r = slots[s]!;
    if (r === 0) return -1;
    const i = r - 1;
    if (rows.kind[i] === kind && rows.a[i] === a && rows.b[i] === b && rows.feature[i] === f) {
      return rows.stampA[i] === stampA && rows.stampB[i] === stampB ? i : -1;
    }
    s = (s + 1) & mask;
  }
}
