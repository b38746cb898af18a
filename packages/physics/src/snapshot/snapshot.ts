import { $internal, query as bitecsQuery, Not, Or, registerComponent } from 'bitecs';
import { installCloth } from '../cloth/create.js';
import { install3D } from '../collision/install-3d.js';
import { installBalls } from '../collision/install-balls.js';
import { barnesHutGravity } from '../forces/barnes-hut/tree.js';
import { setBarnesHutGravity } from '../forces/gravity.js';
import { installEmitters } from '../particles/emitter-systems.js';
import { shareStores } from '../threads/shared-stores.js';
import { externalWorldStates } from '../world/external-state.js';
import { assignSparseSet, hasMaskComponentSets } from '../world/lean-ecs.js';
import type { PhysicsWorld } from '../world/options.js';
import { describe } from '../world/validate.js';
import { checkSnapshotValues } from './checks.js';
import { snapshotChecksum } from './checksum.js';

/**
 * Snapshots: the complete state of a world as transferable data, and `restore`, which puts it back.
 *
 * Layout (format version 3): a JSON-able header (the encoded state tree, and a checksum of the header and
 * the buffer's data: snapshot/checksum.ts) and ONE ArrayBuffer holding the
 * contents of every typed array of the state, each at an 8-byte aligned offset. An array is stored up
 * to its last non-zero element only (for a per-entity store that is at most the highest live id; the
 * tail is all zeros and restore writes zeros there), a component store no live entity has is stored as
 * its type and length only, and bitecs' query lists that equal an earlier list (most queries hold the
 * same entities in the same order) as a reference to it, a list of consecutive ids (1 .. N) as its first
 * id and length (a query list neither of whose sets changed
 * since the world's last snapshot found them equal is not compared again: world/lean-ecs.ts counts each
 * set's changes). Component stores are scanned for their last non-zero element from the highest entity
 * id down (their entries above it are zero). Scratch arrays (the broadphase grid and the collision
 * stage's per-step arrays, see SCRATCH; the solver's marks, see STAMPED) are stored as their type and
 * length only, and the 2D contact buffers' columns up to their row count (CONTACT_BUFFERS), their 2D tangents
 * as a note plus the rows that differ from (-ny, nx) (TANGENT_2D); an Int32Array whose element i is i
 * (union-find parents) as its element 0 and count (`iota`, see Writer.arrayTo). Restoring a snapshot object into the world it was taken from (or into
 * one it was restored into before) leaves alone the query lists that have not changed since (their
 * versions say so), and the entity index when it is equal. `restore` writes into the world's own arrays
 * where their type and length match (systems and renderers keep them), so it allocates no big array
 * in a world that already has them.
 *
 * What is captured, generically (so state added later is captured without listing it here):
 * - every field of the world object (stage settings, time, steps, the random generator, every component
 *   store allocated, the collision, joint and cloth state with their warm-start caches and sleeping
 *   islands, spawn stamps), walked recursively: typed arrays are copied into ArrayBuffers, numbers,
 *   booleans and strings go into the JSON header, Sets and Maps as lists;
 * - per-world state that modules keep outside the world (the emitters' particle books, the dissipation
 *   stamps), registered in world-state.ts;
 * - bitecs' entity index (the order in which removed ids are reused), each entity's component set, and
 *   the order of every query's entities and pending removals (iteration order decides the order of
 *   floating-point sums, so restoring it is what makes stepping after `restore` bit-identical).
 *
 * Not captured: the systems of each stage, removal hooks and particle death hooks (code, not data: the
 * world restored into must have the same ones), and stage timings.
 */

/**
 * Fields of the world object that are code, measurements or the machine it runs on, not state;
 * everything else is captured. `threads` and `threadPool` are the world's own: a snapshot of a world
 * with any number of threads restores into a world with any number, which keeps its pool.
 */
const NOT_STATE = new Set(['stages', 'builtins', 'removeHooks', 'timings', 'entityIndex', 'threads', 'threadPool']);

/**
 * Typed arrays of the world that are scratch: written in full before they are read, within the step
 * that reads them, so they carry nothing from one step to the next (the broadphase's spatial-hash
 * grid, rebuilt by every broadphaseSystem before its pair search: collision/broadphase/grid.ts). A snapshot
 * keeps their type only and restore leaves the target world's own arrays as they are (the
 * broadphase grows them when too small). About 4 MB of a 100,000-ball world's 10.4 MB.
 */
const SCRATCH = new Set([
  ...['bucketStart', 'sorted', 'cellX', 'cellY', 'cellZ', 'bucketOf', 'oversized', 'candidates'].map((k) => `world.collision.grid.${k}`),
  ...PER_STEP_SCRATCH(),
]);

/**
 * Collision scratch that every step writes before it reads it (checked against the step order), kept
 * as type and length only: the restored world keeps its own array when it has one of that type and
 * at least that length, and gets a zeroed one otherwise.
 * - `margin`: every ball's speculative margin, written for all balls (static ones after) at the top of
 *   broadphaseSystem, read only by the broadphase (collision/broadphase/grid.ts, broadphase-pairs*.ts).
 * - `pairA`, `pairB`, `pairKind`: the broadphase's pair list; broadphaseSystem sets `pairCount` to 0
 *   first, the narrowphase reads the first `pairCount` pairs of this step.
 * - `solverIndex`: read only for bodies whose `solverMark` equals this step's `solverStamp`, which
 *   gatherBodies (solver/contact-solver.ts) raises by one before giving indices (see STAMPED for `solverMark`).
 * - `bodyState`, `bodyExtra`: packed rows of this step's solver bodies, filled by gatherBodies for rows
 *   1 .. solverBodyCount - 1 (row 0, the static world, is zeroed there or never written) before any
 *   solver stage reads them; `bodyImpact`: zeroed up to solverBodyCount by applyImpacts (solver/impacts.ts),
 *   which runs before anything reads it.
 * About 3 MB of a settled 100,000-ball world's 9 to 13 MB.
 */
function PER_STEP_SCRATCH(): string[] {
  return ['margin', 'pairA', 'pairB', 'pairKind', 'solverIndex', 'bodyState', 'bodyExtra', 'bodyImpact', 'impactOrder', 'impactKey'].map(
    (k) => `world.collision.${k}`,
  );
}

/**
 * The 2D ball contact buffers (collision/contacts.ts, ContactBuffer): a column's rows from `count` on
 * are not state (contacts.ts: rows 0..count-1 are the contacts; `storeWarmStart` swaps the two
 * buffers and leaves the new `contacts` with count 0 and stale rows, which the next step refills from
 * row 0; `growContactBuffer` keeps rows below count only). A snapshot stores each column up to its
 * count (up to its last non-zero row below it), and restore writes those rows and zeroes the rest
 * below count, leaving the world's rows from count on as they are. `contacts` holds no rows between
 * steps: about 40 % of a settled 100,000-ball snapshot before this.
 */
const CONTACT_BUFFERS = new Set(['world.collision.contacts', 'world.collision.cache.rows']);

/**
 * Stamp-marked scratch: an array of marks and the counter they are compared with. A mark counts only
 * while it equals the counter, which its user raises by one before it marks (gatherBodies,
 * solver/contact-solver.ts: `solverMark[e] === ++solverStamp`), so every mark is at most the counter and
 * the marks' values carry nothing else. A snapshot keeps the mark array's type and length only;
 * restore keeps the world's own marks (or gives it zeroed ones) and sets the counter to the larger
 * of the snapshot's and the world's own, so no kept mark can equal a future counter value. Only the
 * counter's value differs from the original world's; no stage reads it except to compare marks.
 */
const STAMPED: ReadonlyMap<string, { parent: (world: PhysicsWorld) => Record<string, unknown>; counter: string }> = new Map([
  [
    'world.collision.solverMark',
    { parent: (world: PhysicsWorld) => world.collision as unknown as Record<string, unknown>, counter: 'solverStamp' },
  ],
]);

/**
 * A snapshot: a small JSON-able header and the ArrayBuffers it points into (transferable to a Worker, or writable to disk).
 * @category Snapshots
 */
export interface WorldSnapshot {
  /** Format, world shape and the encoded state tree (see `snapshot`); JSON-able. */
  readonly header: SnapshotHeader;
  /** The data of every typed array of the state: one ArrayBuffer, the header's `o` fields are byte offsets into it. */
  readonly buffers: ArrayBuffer[];
}

/**
 * An encoded value: a JSON primitive, an array, an object of encoded values, or a tagged special value.
 * @category Snapshots
 */
export type Encoded = number | boolean | string | null | Encoded[] | { [key: string]: Encoded };

/**
 * Header of a WorldSnapshot.
 * @category Snapshots
 */
export interface SnapshotHeader {
  /** 'bitphysics-snapshot'. */
  format: string;
  /** Format version, 3. */
  version: number;
  /** The world's dimensions and capacity (a snapshot restores only into a world with the same). */
  dimensions: number;
  capacity: number;
  /** The world object's state tree. */
  state: Encoded;
  /** Registered external state by name (null: the world had none). */
  external: Record<string, Encoded>;
  /** bitecs: entity index (aliveCount, maxId, buffer of the dense id list), component bit layout, masks, queries. */
  ecs: Encoded;
  /** Bytes of the buffer that hold data (the buffer may be longer: see `snapshot`'s `reuse`). */
  bytes: number;
  /** 16 hex digits: the hash of every other field (as JSON) and of the buffer's first `bytes` bytes (snapshot/checksum.ts). */
  checksum: string;
}

type TypedArray =
  | Float64Array
  | Float32Array
  | Int32Array
  | Uint32Array
  | Int16Array
  | Uint16Array
  | Int8Array
  | Uint8Array
  | Uint8ClampedArray;
const TYPED: Record<string, new (b: ArrayBuffer | number | ArrayLike<number>) => TypedArray> = {
  Float64Array,
  Float32Array,
  Int32Array,
  Uint32Array,
  Int16Array,
  Uint16Array,
  Int8Array,
  Uint8Array,
  Uint8ClampedArray,
};

/**
 * Length of `a`'s first `end` elements up to the last one whose bits are not all zero (so -0 and NaN
 * count as values). The trailing zeros are found by `zeroTail64` (64-bit words; BigInt64Array
 * compares compile without allocating, about twice as fast as OR-ing 32-bit words here) or
 * `zeroTail32` as the array's alignment allows; the bytes past the last whole word and within the last
 * non-zero word are judged by their bits. Each scan loop is a small function of its own that every call
 * runs, so it never lacks type feedback when optimised (one scan with all the branches inline fell into
 * a deoptimisation loop in a 100,000-ball world, and unoptimised BigInt reads allocate).
 */
function usedLength(a: TypedArray, end: number): number {
  // Where the host has a native byte comparison (Node's Buffer.compare, a memcmp: ~5x the speed of the
  // word loops below, ~0.02 against ~0.13 ms for 800 kB of zeros), whole blocks of trailing zeros are
  // dropped with it first; the loops then scan at most one block.
  const bytesPer = a.BYTES_PER_ELEMENT;
  if (nativeCompare !== undefined && end * bytesPer > ZERO_BLOCK.length) {
    const u8 = new Uint8Array(a.buffer, a.byteOffset, end * bytesPer);
    let hi = u8.length;
    while (hi > 0) {
      const lo = Math.max(0, hi - ZERO_BLOCK.length);
      if (nativeCompare(u8.subarray(lo, hi), hi - lo === ZERO_BLOCK.length ? ZERO_BLOCK : ZERO_BLOCK.subarray(0, hi - lo)) !== 0) break;
      hi = lo;
    }
    end = hi / bytesPer; // blocks are whole elements (the block length is a multiple of 8)
  }
  return usedLengthScan(a, end);
}

/**
 * A native comparison of two byte arrays (memcmp: negative, 0 or positive) where the host has one
 * (Node's `Buffer.compare`, which takes Uint8Arrays); undefined elsewhere (a page), where the
 * snapshot's scans use the JS loops alone. Only equality is used, so the result is the same either way.
 */
const nativeCompare: ((a: Uint8Array, b: Uint8Array) => number) | undefined = (() => {
  const B = (globalThis as { Buffer?: { compare?: unknown } }).Buffer;
  return typeof B?.compare === 'function' ? (B.compare as (a: Uint8Array, b: Uint8Array) => number) : undefined;
})();
/** Zeros compared against by `usedLength` (64 kB: a multiple of every element size). */
const ZERO_BLOCK = new Uint8Array(nativeCompare !== undefined ? 65536 : 0);

/**
 * Makes elements `from` .. `to`-1 of `a` zero (all bits: +0). Where the host compares natively (see
 * nativeCompare), only the 64 kB blocks that are not all zero already are written: restore zeroes
 * ~14 MB of per-entity stores past their stored part in a 100,000-ball world, most of it zero already
 * (forces, torques, z components), and reading it is cheaper than writing it.
 */
function zeroFill(a: TypedArray, from: number, to: number): void {
  const bytes = a.BYTES_PER_ELEMENT;
  if (nativeCompare === undefined || (to - from) * bytes <= ZERO_BLOCK.length) {
    a.fill(0, from, to);
    return;
  }
  const u8 = new Uint8Array(a.buffer, a.byteOffset + from * bytes, (to - from) * bytes);
  const B = ZERO_BLOCK.length;
  for (let lo = 0; lo < u8.length; lo += B) {
    const hi = Math.min(u8.length, lo + B);
    if (nativeCompare(u8.subarray(lo, hi), hi - lo === B ? ZERO_BLOCK : ZERO_BLOCK.subarray(0, hi - lo)) !== 0) u8.fill(0, lo, hi);
  }
}

/** Whether elements 1 .. n-1 of `a` have the same bits, by the native comparison (false without one, or for n < 3: then the caller writes). */
function sameFrom1Native(a: TypedArray, n: number): boolean {
  if (nativeCompare === undefined || n < 3) return false;
  const bytes = a.BYTES_PER_ELEMENT;
  const u8 = new Uint8Array(a.buffer, a.byteOffset, n * bytes);
  return nativeCompare(u8.subarray(bytes, (n - 1) * bytes), u8.subarray(2 * bytes, n * bytes)) === 0;
}

/** `usedLength` by JS loops alone (see there). */
function usedLengthScan(a: TypedArray, end: number): number {
  const bytes = a.BYTES_PER_ELEMENT;
  const total = end * bytes;
  if ((a.byteOffset & 3) !== 0) {
    let n = end;
    while (n > 0 && a[n - 1] === 0 && !Object.is(a[n - 1], -0)) n--;
    return n;
  }
  const whole = total & ~3;
  // The bytes past the last whole 4-byte word (1- and 2-byte elements), by their bits.
  if (whole !== total) {
    const tail = new Uint8Array(a.buffer, a.byteOffset + whole, total - whole);
    for (let k = tail.length - 1; k >= 0; k--) if (tail[k] !== 0) return Math.ceil((whole + k + 1) / bytes);
  }
  let used: number; // bytes
  if ((a.byteOffset & 7) === 0) {
    const w8 = whole & ~7;
    used =
      w8 !== whole && new Int32Array(a.buffer, a.byteOffset + w8, 1)[0] !== 0
        ? whole
        : 8 * zeroTail64(new BigInt64Array(a.buffer, a.byteOffset, w8 >> 3), w8 >> 3);
  } else {
    used = 4 * zeroTail32(new Int32Array(a.buffer, a.byteOffset, whole >> 2), whole >> 2);
  }
  if (bytes < 8 && used > 0) {
    // Smaller elements: up to the last non-zero byte of the last non-zero word (else a store of one
    // repeated value would gain a 0 and lose its repeat encoding).
    const k0 = Math.min(8, used);
    const last = new Uint8Array(a.buffer, a.byteOffset + used - k0, k0);
    let k = k0;
    while (k > 1 && last[k - 1] === 0) k--;
    used -= k0 - k;
  }
  return Math.ceil(used / bytes);
}

/** How many of the first `n` 64-bit words of `w` remain when its trailing zero words are dropped. */
function zeroTail64(w: BigInt64Array, n: number): number {
  while (n > 0 && w[n - 1] === 0n) n--;
  return n;
}

/** How many of the first `n` 32-bit words of `w` remain when its trailing zero words are dropped (eight OR-ed a step, then one). */
function zeroTail32(w: Int32Array, n: number): number {
  while (n >= 8 && (w[n - 1]! | w[n - 2]! | w[n - 3]! | w[n - 4]! | w[n - 5]! | w[n - 6]! | w[n - 7]! | w[n - 8]!) === 0) n -= 8;
  while (n > 0 && w[n - 1] === 0) n--;
  return n;
}

/**
 * Whether elements 1 .. n-1 of `a` have the same bits (and are not NaN, whose payload a fill could
 * change). Compares 32-bit words XOR-ed against the pattern and OR-ed four at a time, or 64-bit words
 * (see usedLength). Arrays of 1- and 2-byte elements are not checked (false).
 */
function uniformFrom1(a: TypedArray, n: number): boolean {
  const bytes = a.BYTES_PER_ELEMENT;
  if (bytes < 4 || (a.byteOffset & 3) !== 0) return false;
  const v = a[1]!;
  if (v !== v) return false;
  // Natively (see nativeCompare): elements 1 .. n-2 equal elements 2 .. n-1 exactly when 1 .. n-1 are all the same.
  if (nativeCompare !== undefined && n >= 3) {
    const u8 = new Uint8Array(a.buffer, a.byteOffset, n * bytes);
    return nativeCompare(u8.subarray(bytes, (n - 1) * bytes), u8.subarray(2 * bytes, n * bytes)) === 0;
  }
  const words = new Int32Array(a.buffer, a.byteOffset, (n * bytes) >> 2);
  if (bytes === 4) {
    const w = words[1]!;
    let i = 2;
    for (; i + 4 <= n; i += 4) if (((words[i]! ^ w) | (words[i + 1]! ^ w) | (words[i + 2]! ^ w) | (words[i + 3]! ^ w)) !== 0) return false;
    for (; i < n; i++) if (words[i] !== w) return false;
    return true;
  }
  // 8-byte elements: as 64-bit words where aligned (see usedLength), else element k is words 2k and 2k + 1.
  if ((a.byteOffset & 7) === 0) return sameFrom64(new BigInt64Array(a.buffer, a.byteOffset, n), n);
  const lo = words[2]!,
    hi = words[3]!;
  const m = 2 * n;
  let i = 4;
  for (; i + 4 <= m; i += 4)
    if (((words[i]! ^ lo) | (words[i + 1]! ^ hi) | (words[i + 2]! ^ lo) | (words[i + 3]! ^ hi)) !== 0) return false;
  for (; i < m; i += 2) if (words[i] !== lo || words[i + 1] !== hi) return false;
  return true;
}

/** Whether 64-bit words 2 .. n-1 of `w` equal word 1. */
function sameFrom64(w: BigInt64Array, n: number): boolean {
  const first = w[1]!;
  for (let i = 2; i < n; i++) if (w[i] !== first) return false;
  return true;
}

interface PendingCopy {
  readonly src: TypedArray | readonly number[];
  readonly n: number;
  readonly offset: number;
  readonly type: string;
}

class Writer {
  private readonly pending: PendingCopy[] = [];
  private bytes = 0;
  private readonly seen = new Set<object>();
  /** Stores no entity has: their arrays' contents are never read, so only their type and length are kept. */
  unused: ReadonlySet<object> = new Set();
  /**
   * @param storeLength capacity + 1: a component store's arrays are k times as long (k entries an entity).
   * @param maxId the highest entity id the world has made: a component's entries above it are zero (no
   *   entity ever had them; restore zeroes what it lowers), so the scan for trailing zeros starts there.
   * @param components names of the stores of world.components that are registered bitecs components
   *   (a store that is not may hold values anywhere, and is scanned in full).
   */
  constructor(
    private readonly storeLength: number,
    private readonly maxId: number,
    private readonly components: ReadonlySet<string>,
  ) {}
  /**
   * Encodes a typed array: its type, full length `len`, and its first `n` elements (up to the last
   * non-zero one), copied into the snapshot's buffer at byte offset `o` by `finish`.
   * @param path where the array is: arrays of registered component stores (`world.components.*`) are scanned from the highest id down.
   */
  array(a: TypedArray, path: string): Encoded {
    const k = a.length / this.storeLength;
    const end =
      Number.isInteger(k) && k >= 1 && path.startsWith('world.components.') && this.components.has(path.split('.')[2]!)
        ? Math.min(a.length, (this.maxId + 1) * k)
        : a.length;
    return this.arrayTo(a, end);
  }
  /**
   * `array` for an array whose entries from `end` on are known to be zero, or with `rowsOnly` are not
   * state (a contact buffer's rows from its count on): then the encoding says so (`upto`: restore
   * zeroes the stored part's tail up to `end` and leaves the entries from `end` on as they are).
   */
  arrayTo(a: TypedArray, end: number, rowsOnly = false): Encoded {
    const used = usedLength(a, end);
    // A store whose entities all hold one value (materials, masses of equal bodies) keeps two elements:
    // index 0 (no entity) and the value, repeated up to `rep` by restore.
    const rep = used > 3 && uniformFrom1(a, used) ? used : 0;
    // An Int32Array whose element i is i for 1 .. used-1 (the sleep stage's union-find parents between
    // island searches: 0.4 MB of a 100,000-ball world) keeps element 0 only; restore writes the rest.
    const iota = rep === 0 && used >= 64 && a instanceof Int32Array && iotaFrom1(a, used) ? used : 0;
    const n = rep > 0 ? 2 : iota > 0 ? 1 : used;
    const type = a.constructor.name;
    const offset = this.place(n * a.BYTES_PER_ELEMENT);
    this.pending.push({ src: a, n, offset, type });
    const e: Record<string, Encoded> = rep > 0 ? { $t: type, o: offset, n, len: a.length, rep } : { $t: type, o: offset, n, len: a.length };
    if (iota > 0) e.iota = iota;
    if (rowsOnly) e.upto = end;
    return e;
  }
  /** Encodes a JS list of entity ids (no zeros: ids start at 1) as an Int32Array of its length, copied by `finish`. */
  ids(list: readonly number[]): Encoded {
    const n = list.length;
    const offset = this.place(4 * n);
    this.pending.push({ src: list, n, offset, type: 'Int32Array' });
    return { $t: 'Int32Array', o: offset, n, len: n };
  }
  /** Bytes placed so far: the length of the data in the buffer `finish` returns. */
  get length(): number {
    return this.bytes;
  }
  private place(byteLength: number): number {
    const offset = (this.bytes + 7) & ~7;
    this.bytes = offset + byteLength;
    return offset;
  }
  /**
   * The snapshot's one buffer with every encoded array copied in (call once, right after encoding):
   * `reuse` if it is large enough (its old contents are overwritten where the arrays go), else a new one:
   * of the exact size without `reuse`; with it (a rollback ring), a quarter larger, so that the ring's
   * later snapshots, which grow as contacts and caches fill (about 1 % a step in a settling 100,000-ball
   * box), still fit in it when it comes round again (before, every reuse missed by a few kB and paid
   * for a new buffer, whose page faults cost more than the copy into it).
   */
  finish(reuse?: ArrayBuffer): ArrayBuffer {
    const buf =
      reuse === undefined
        ? new ArrayBuffer(this.bytes)
        : reuse.byteLength >= this.bytes
          ? reuse
          : new ArrayBuffer((this.bytes + (this.bytes >> 2) + 7) & ~7);
    for (const { src, n, offset, type } of this.pending) {
      if (n === 0) continue;
      const Ctor = TYPED[type] as unknown as new (b: ArrayBuffer, o: number, n: number) => TypedArray;
      const out = new Ctor(buf, offset, n);
      if (Array.isArray(src)) out.set(src);
      else {
        const t = src as TypedArray;
        out.set((n === t.length ? t : t.subarray(0, n)) as never);
      }
    }
    return buf;
  }
  value(v: unknown, path: string): Encoded {
    if (typeof v === 'number') {
      if (Number.isFinite(v) && !Object.is(v, -0)) return v;
      return { $t: 'n', v: Object.is(v, -0) ? '-0' : String(v) };
    }
    if (typeof v === 'boolean' || typeof v === 'string' || v === null) return v;
    if (v === undefined) return { $t: 'u' };
    if (typeof v !== 'object') throw new TypeError(`snapshot: cannot capture ${path} (a ${typeof v}); state must be data`);
    if (ArrayBuffer.isView(v)) {
      if (!(v.constructor.name in TYPED)) throw new TypeError(`snapshot: cannot capture ${path} (a ${v.constructor.name})`);
      if (SCRATCH.has(path) || STAMPED.has(path)) return { $t: 'scratch', type: v.constructor.name, len: (v as TypedArray).length };
      return this.array(v as TypedArray, path);
    }
    if (this.unused.has(v)) {
      const out: Record<string, Encoded> = {};
      for (const [key, x] of Object.entries(v)) {
        out[key] = ArrayBuffer.isView(x)
          ? { $t: 'unused', type: x.constructor.name, n: (x as TypedArray).length }
          : this.value(x, `${path}.${key}`);
      }
      return { $t: 'o', v: out };
    }
    if (this.seen.has(v)) throw new TypeError(`snapshot: ${path} is reached twice (shared or cyclic state cannot be captured)`);
    this.seen.add(v);
    if (Array.isArray(v)) return { $t: 'a', v: v.map((x, i) => this.value(x, `${path}[${i}]`)) };
    if (v instanceof Set) return { $t: 's', v: [...v].map((x, i) => this.value(x, `${path} (set item ${i})`)) };
    if (v instanceof Map) {
      return {
        $t: 'm',
        v: [...v].map(([k, x], i) => [this.value(k, `${path} (map key ${i})`), this.value(x, `${path}.get(${String(k)})`)]),
      };
    }
    return this.object(v as Record<string, unknown>, path, undefined);
  }
  /**
   * The TANGENT_2D note of contact buffer `o`'s column `key` (t1x or t1y) for rows 0 .. n-1, with the
   * rows that differ from -ny (t1x) or nx (t1y) as (row, value) pairs; null (store the column) when the
   * columns are not all Float64Array of the buffer's capacity or more than an eighth of the rows differ.
   */
  tangent(o: Record<string, unknown>, key: string, n: number): Encoded | null {
    const t = o[key],
      src = key === 't1x' ? o.ny : o.nx;
    if (!(t instanceof Float64Array && src instanceof Float64Array && t.length === o.capacity && src.length === t.length)) return null;
    const pairs = tangentExceptions(t, src, key === 't1x', n, n >> 3);
    if (pairs === null) return null;
    const e: Record<string, Encoded> = { $t: TANGENT_2D, axis: key === 't1x' ? 'x' : 'y', len: t.length, upto: n };
    if (pairs.length > 0) e.rows = this.arrayTo(Float64Array.from(pairs), pairs.length);
    return e;
  }
  object(o: Record<string, unknown>, path: string, skip: ReadonlySet<string> | undefined): Encoded {
    const out: Record<string, Encoded> = {};
    // A contact buffer (see CONTACT_BUFFERS): its columns (capacity rows) up to its count only.
    const rows = CONTACT_BUFFERS.has(path) && typeof o.count === 'number' && typeof o.capacity === 'number' ? o.count : -1;
    for (const key of Object.keys(o)) {
      if (skip?.has(key)) continue;
      const v = o[key];
      // Its 2D tangents, where most rows' are (-ny, nx) to the bit, as a note and the other rows (see TANGENT_2D).
      if (rows > 0 && (key === 't1x' || key === 't1y')) {
        const note = this.tangent(o, key, Math.min(rows, o.capacity as number));
        if (note !== null) {
          out[key] = note;
          continue;
        }
      }
      if (rows >= 0 && ArrayBuffer.isView(v) && (v as TypedArray).length === o.capacity && v.constructor.name in TYPED) {
        out[key] = this.arrayTo(v as TypedArray, Math.min(rows, (v as TypedArray).length), true);
        continue;
      }
      out[key] = this.value(v, `${path}.${key}`);
    }
    return { $t: 'o', v: out };
  }
}

/**
 * Tag of a 2D contact tangent column stored as a note: tangent 1 of a 2D contact is (-ny, nx) as
 * prepareContacts (solver/contact-solver.ts, and its kernel) computes it, so `t1x` and `t1y` are stored as
 * a note, `{ $t: 'tangent2d', axis, len, upto, rows? }`, plus the rows that differ (a normal the
 * impact stage or the relax pass turned after the tangent was set: ~2 % of a 100,000-ball box's rows)
 * as (row, value) pairs in `rows`, a Float64Array. Restore writes -ny (axis x) or nx (axis y) into rows
 * 0 .. upto-1, then the pairs (rows from the count on are left as they are, as for every contact
 * column). Compared bit for bit (-0 included, NaN never equal) when the snapshot is taken; a 3D
 * buffer's basis differs in most rows and is stored as it is. ~0.9 MB of a settled 100,000-ball pile.
 */
const TANGENT_2D = 'tangent2d';

/**
 * The rows i < n where `t[i]` differs in its bits from -src[i] (`negate`) or src[i], as a flat list
 * (row, t[i], row, t[i], ...), or null when more than `most` rows differ.
 */
function tangentExceptions(t: Float64Array, src: Float64Array, negate: boolean, n: number, most: number): number[] | null {
  const pairs: number[] = [];
  const sign = negate ? -1 : 1;
  for (let i = 0; i < n; i++) {
    const a = t[i]!,
      b = sign * src[i]!;
    // === is bitwise for every value but zeros (+0 === -0, told apart by 1 / x) and NaN (never equal: a pair).
    if (a === b && (a !== 0 || 1 / a === 1 / b)) continue;
    // A NaN tangent keeps its column (a NaN's payload may not survive a trip through a JS number).
    if (pairs.length >= 2 * most || a !== a) return null;
    pairs.push(i, a);
  }
  return pairs;
}

function isTagged(e: Encoded): e is { [key: string]: Encoded } {
  return typeof e === 'object' && e !== null && !Array.isArray(e);
}

/**
 * The typed array constructor named by `type`, once `n` is checked as a length (an integer in
 * [0, MAX_ELEMENTS]). @throws RangeError `restore: snapshot's <path> is damaged` otherwise.
 */
function allocatable(type: Encoded | undefined, n: Encoded | undefined, path: string): new (n: number) => TypedArray {
  const Ctor = typeof type === 'string' && Object.hasOwn(TYPED, type) ? TYPED[type] : undefined;
  if (Ctor === undefined || !(Number.isInteger(n) && (n as number) >= 0 && (n as number) <= MAX_ELEMENTS))
    throw new RangeError(`restore: snapshot's ${path} is damaged`);
  return Ctor as unknown as new (
    n: number,
  ) => TypedArray;
}

/** The most elements a snapshot's typed array may declare (2^28: 2 GB of Float64Array); more is damage. */
const MAX_ELEMENTS = 2 ** 28;

class Reader {
  /**
   * With `dry` set, `objectInto` writes nothing: it walks the encoding against the target as a restore
   * would and throws where the restore would, or where a value is damaged (restore runs it first, so a
   * refused snapshot leaves the world as it was).
   */
  dry = false;
  /**
   * @param buffer the snapshot's buffer.
   * @param capacity the world's capacity: arrays of k (capacity + 1) elements are per-entity stores.
   * @param oldMaxId the world's highest entity id before the restore: per-entity arrays hold zeros above
   *   it, so only their entries up to it need zeroing past the snapshot's data.
   */
  constructor(
    private readonly buffer: ArrayBuffer,
    private readonly capacity: number,
    private readonly oldMaxId: number,
  ) {}
  /** A view of an encoded array's stored elements (its first `n`; the rest, up to `len`, are zeros). */
  array(e: { [key: string]: Encoded }, path: string): TypedArray {
    const Ctor = (Object.hasOwn(TYPED, e.$t as string) ? TYPED[e.$t as string] : undefined) as unknown as
      | (new (
          b: ArrayBuffer,
          o: number,
          n: number,
        ) => TypedArray)
      | undefined;
    const o = e.o as number,
      n = e.n as number,
      len = e.len as number;
    const rep = e.rep as number | undefined;
    const iota = e.iota as number | undefined;
    const upto = e.upto as number | undefined;
    if (
      Ctor === undefined ||
      !(
        Number.isInteger(n) &&
        Number.isInteger(len) &&
        Number.isInteger(o) &&
        n >= 0 &&
        n <= len &&
        len <= MAX_ELEMENTS &&
        o >= 0 &&
        o % Ctor.prototype.BYTES_PER_ELEMENT === 0 &&
        o + n * Ctor.prototype.BYTES_PER_ELEMENT <= this.buffer.byteLength
      ) ||
      (rep !== undefined && !(n === 2 && rep >= 2 && rep <= len)) ||
      (iota !== undefined &&
        !(Ctor === Int32Array && rep === undefined && n === 1 && Number.isInteger(iota) && iota >= 2 && iota <= len)) ||
      (upto !== undefined && !(upto >= (rep ?? iota ?? n) && upto <= len))
    ) {
      throw new RangeError(`restore: snapshot's ${path} is damaged`);
    }
    return new Ctor(this.buffer, o, n);
  }
  /** Writes the encoded elements into the start of `out` (stored ones, then a repeated value); @returns how many. */
  write(out: TypedArray, src: TypedArray, e: { [key: string]: Encoded }): number {
    out.set(src as never);
    const iota = e.iota as number | undefined;
    if (iota !== undefined) {
      // Elements 1 .. iota-1 are 1 .. iota-1 (see Writer.arrayTo): left as they are where they already are.
      if (!iotaFrom1(out as Int32Array, iota)) out.set(countingTo(iota - 1).subarray(0, iota - 1), 1);
      return iota;
    }
    const rep = e.rep as number | undefined;
    if (rep === undefined) return src.length;
    // Elements 1 .. rep-1 of `out` already the same (element 1 was just set): left as they are.
    if (!sameFrom1Native(out, rep)) out.fill(src[1]! as never, 2, rep);
    return rep;
  }
  /** The encoded elements up to the last non-zero one: a view into the snapshot, or a copy if a value repeats (or elements are their index). */
  used(e: { [key: string]: Encoded }, path: string): TypedArray {
    const src = this.array(e, path);
    const rep = (e.rep ?? e.iota) as number | undefined;
    if (rep === undefined) return src;
    const out = new TYPED[e.$t as string]!(rep);
    this.write(out, src, e);
    return out;
  }
  /** A new array of the encoded type and full length with the stored elements in it. */
  full(e: { [key: string]: Encoded }, path: string): TypedArray {
    const src = this.array(e, path);
    const out = new TYPED[e.$t as string]!(e.len as number);
    this.write(out, src, e);
    return out;
  }
  /**
   * End of the part of `a`, an array of the world being restored at `path`, that may hold non-zero
   * values: a component store's array (k (capacity + 1) long, k entries an entity) holds zeros above
   * the highest id the world has had; any other array may hold values anywhere (lists, rings, scratch).
   */
  private extent(a: TypedArray, path: string): number {
    const k = a.length / (this.capacity + 1);
    return path.startsWith('world.components.') && Number.isInteger(k) && k >= 1 ? Math.min(a.length, (this.oldMaxId + 1) * k) : a.length;
  }
  /** A fresh value from the encoding (typed arrays copied out of the snapshot). */
  fresh(e: Encoded, path: string): unknown {
    if (!isTagged(e)) return e;
    const t = e.$t as string;
    if (t === 'n') {
      if (typeof e.v !== 'string') throw new RangeError(`restore: snapshot's ${path} is damaged`);
      return e.v === '-0' ? -0 : Number(e.v);
    }
    if (t === 'u') return undefined;
    if (Object.hasOwn(TYPED, t)) return this.full(e, path);
    if (t === 'unused') return new (allocatable(e.type, e.n, path))(e.n as number);
    if (t === 'scratch') return new (allocatable(e.type, e.len ?? 0, path))(typeof e.len === 'number' ? e.len : 0);
    const v = e.v as Encoded;
    if ((t === 'a' || t === 's' || t === 'm') && !Array.isArray(v)) throw new RangeError(`restore: snapshot's ${path} is damaged`);
    if (t === 'm' && !(v as Encoded[]).every((p) => Array.isArray(p) && p.length === 2))
      throw new RangeError(`restore: snapshot's ${path} is damaged`);
    if (t === 'o' && (typeof v !== 'object' || v === null || Array.isArray(v)))
      throw new RangeError(`restore: snapshot's ${path} is damaged`);
    if (t === 'a') return (v as Encoded[]).map((x, i) => this.fresh(x, `${path}[${i}]`));
    if (t === 's') return new Set((v as Encoded[]).map((x) => this.fresh(x, path)));
    if (t === 'm') return new Map((v as Encoded[][]).map(([k, x]) => [this.fresh(k!, path), this.fresh(x!, path)]));
    if (t === 'o') {
      const o: Record<string, unknown> = {};
      const derived: string[] = [];
      for (const [k, x] of Object.entries(v as Record<string, Encoded>)) {
        if (isTagged(x) && x.$t === TANGENT_2D) {
          derived.push(k);
          o[k] = null;
          continue;
        } // keeps the key order
        o[k] = this.fresh(x, `${path}.${k}`);
      }
      for (const k of derived) this.tangent(o, k, (v as Record<string, Record<string, Encoded>>)[k]!, `${path}.${k}`);
      return o;
    }
    throw new RangeError(`restore: snapshot's ${path} is damaged (unknown tag ${describe(t)})`);
  }
  /**
   * Writes the encoding into `target[key]`, keeping the identity of the objects and arrays already there
   * (systems and renderers hold them): typed arrays of the same type and length are overwritten, others replaced.
   */
  into(target: Record<string, unknown>, key: string, e: Encoded, path: string, keep?: ReadonlySet<string>): void {
    const cur = target[key];
    if (this.dry) {
      this.check(cur, e, path, keep);
      return;
    }
    if (isTagged(e)) {
      const t = e.$t as string;
      // Scratch (see SCRATCH, STAMPED): the target's own array stays if it is long enough (snapshots
      // that recorded no length: any array of the target stays, as the broadphase grows the grid's).
      if (
        t === 'scratch' &&
        cur !== null &&
        typeof cur === 'object' &&
        ArrayBuffer.isView(cur) &&
        (typeof e.len !== 'number' || (cur.constructor.name === e.type && (cur as TypedArray).length >= e.len))
      )
        return;
      if (t === 'unused') {
        // No entity has the store's component: its contents are never read. A store the world has
        // allocated stays allocated (zeroed, as if new); one it lacks gets the snapshot's allocation.
        const Ctor = TYPED[e.type as string]!;
        const n = e.n as number;
        if (
          cur !== null &&
          typeof cur === 'object' &&
          ArrayBuffer.isView(cur) &&
          cur.constructor === Ctor &&
          (cur as TypedArray).length >= n
        ) {
          zeroFill(cur as TypedArray, 0, this.extent(cur as TypedArray, path));
        } else {
          target[key] = new Ctor(n);
        }
        return;
      }
      if (Object.hasOwn(TYPED, t)) {
        const src = this.array(e, path);
        if (
          cur !== null &&
          typeof cur === 'object' &&
          ArrayBuffer.isView(cur) &&
          cur.constructor === src.constructor &&
          (cur as TypedArray).length === e.len
        ) {
          const a = cur as TypedArray;
          const written = this.write(a, src, e);
          // A contact buffer's column (CONTACT_BUFFERS): zeros up to the count, rows past it left as they are.
          const end = typeof e.upto === 'number' ? e.upto : this.extent(a, path);
          if (end > written) zeroFill(a, written, end);
        } else {
          target[key] = this.full(e, path);
        }
        return;
      }
      if (
        t === 'o' &&
        cur !== null &&
        typeof cur === 'object' &&
        !Array.isArray(cur) &&
        !(cur instanceof Set) &&
        !(cur instanceof Map) &&
        !ArrayBuffer.isView(cur)
      ) {
        this.objectInto(cur as Record<string, unknown>, e.v as Record<string, Encoded>, path, keep);
        return;
      }
      if (t === 'a' && Array.isArray(cur)) {
        const items = (e.v as Encoded[]).map((x, i) => this.fresh(x, `${path}[${i}]`));
        cur.length = 0;
        for (const x of items) cur.push(x);
        return;
      }
      if (t === 's' && cur instanceof Set) {
        cur.clear();
        for (const x of this.fresh(e, path) as Set<unknown>) cur.add(x);
        return;
      }
      if (t === 'm' && cur instanceof Map) {
        cur.clear();
        for (const [k, x] of this.fresh(e, path) as Map<unknown, unknown>) cur.set(k, x);
        return;
      }
    }
    target[key] = this.fresh(e, path);
  }
  /**
   * The dry run of `into` (see `dry`): throws where `into` would, or where the encoding is damaged;
   * writes nothing. A scalar where the world holds a scalar of another type (a string where a number
   * belongs) is damage.
   */
  private check(cur: unknown, e: Encoded, path: string, keep?: ReadonlySet<string>): void {
    const damaged = () => new RangeError(`restore: snapshot's ${path} is damaged`);
    if (!isTagged(e) || e.$t === 'n' || e.$t === 'u') {
      if (Array.isArray(e)) throw damaged();
      const v = this.fresh(e, path);
      const kind = (x: unknown) => (x === null || x === undefined ? 'none' : typeof x);
      if (['number', 'boolean', 'string'].includes(kind(cur)) && kind(v) !== 'none' && kind(v) !== kind(cur)) throw damaged();
      return;
    }
    const t = e.$t as string;
    if (t === 'scratch') {
      allocatable(e.type, e.len ?? 0, path);
      return;
    }
    if (t === 'unused') {
      allocatable(e.type, e.n, path);
      return;
    }
    if (Object.hasOwn(TYPED, t)) {
      this.array(e, path);
      return;
    }
    if (
      t === 'o' &&
      cur !== null &&
      typeof cur === 'object' &&
      !Array.isArray(cur) &&
      !(cur instanceof Set) &&
      !(cur instanceof Map) &&
      !ArrayBuffer.isView(cur)
    ) {
      if (typeof e.v !== 'object' || e.v === null || Array.isArray(e.v)) throw damaged();
      this.objectInto(cur as Record<string, unknown>, e.v as Record<string, Encoded>, path, keep);
      return;
    }
    // Anything else replaces the world's value: decoding it checks it.
    this.fresh(e, path);
  }
  /** The dry run of `tangent`: the note and its rows must be sound, and the normals it reads stored as Float64Arrays long enough. */
  private checkTangent(enc: Record<string, Encoded>, key: string, e: { [key: string]: Encoded }, path: string): void {
    const src = enc[e.axis === 'x' ? 'ny' : 'nx'];
    const len = e.len as number,
      upto = e.upto as number;
    if (
      !(
        Number.isInteger(len) &&
        Number.isInteger(upto) &&
        upto >= 0 &&
        upto <= len &&
        len <= MAX_ELEMENTS &&
        (e.axis === 'x' || e.axis === 'y') &&
        isTagged(src) &&
        src.$t === 'Float64Array' &&
        (src.len as number) >= upto
      )
    )
      throw new RangeError(`restore: snapshot's ${path}.${key} is damaged`);
    if (e.rows !== undefined) {
      if (!isTagged(e.rows) || e.rows.$t !== 'Float64Array') throw new RangeError(`restore: snapshot's ${path}.${key} is damaged`);
      const pairs = this.full(e.rows, `${path}.${key}.rows`);
      if (pairs.length % 2 !== 0) throw new RangeError(`restore: snapshot's ${path}.${key} is damaged`);
      for (let k = 0; k < pairs.length; k += 2) {
        const row = pairs[k]!;
        if (!(Number.isInteger(row) && row >= 0 && row < upto)) throw new RangeError(`restore: snapshot's ${path}.${key} is damaged`);
      }
    }
  }
  objectInto(target: Record<string, unknown>, enc: Record<string, Encoded>, path: string, keep?: ReadonlySet<string>): void {
    for (const key of Object.keys(target)) {
      if (keep?.has(key)) continue;
      if (!(key in enc) && typeof target[key] !== 'function') {
        throw new RangeError(`restore: snapshot has no ${path}.${key} (it was made by another version of bitphysics)`);
      }
    }
    let derived = false;
    for (const [key, x] of Object.entries(enc)) {
      if (keep?.has(key)) continue;
      if (isTagged(x) && x.$t === TANGENT_2D) {
        derived = true;
        if (this.dry) this.checkTangent(enc, key, x, path);
        continue;
      }
      this.into(target, key, x, `${path}.${key}`);
    }
    // Derived columns after the rest: they are computed from the normals just restored.
    if (derived && !this.dry) {
      for (const [key, x] of Object.entries(enc)) {
        if (!keep?.has(key) && isTagged(x) && x.$t === TANGENT_2D) this.tangent(target, key, x, `${path}.${key}`);
      }
    }
  }
  /**
   * Writes a 2D tangent column noted by TANGENT_2D into `target[key]` from `target.nx` / `target.ny`
   * (restored before it): rows below `upto` get -ny (axis x) or nx (axis y), the world's rows from
   * `upto` on stay; an array of another type or length is replaced by a zeroed one of `len` first.
   * @throws RangeError if the note is damaged or the normals are missing or too short.
   */
  tangent(target: Record<string, unknown>, key: string, e: { [key: string]: Encoded }, path: string): void {
    const len = e.len as number,
      upto = e.upto as number,
      axis = e.axis;
    const src = axis === 'x' ? target.ny : target.nx;
    if (
      !(
        Number.isInteger(len) &&
        Number.isInteger(upto) &&
        upto >= 0 &&
        upto <= len &&
        (axis === 'x' || axis === 'y') &&
        src instanceof Float64Array &&
        src.length >= upto
      )
    ) {
      throw new RangeError(`restore: snapshot's ${path} is damaged`);
    }
    const pairs = e.rows === undefined ? null : isTagged(e.rows) ? this.full(e.rows, `${path}.rows`) : undefined;
    if (pairs === undefined || (pairs !== null && !(pairs instanceof Float64Array && pairs.length % 2 === 0)))
      throw new RangeError(`restore: snapshot's ${path} is damaged`);
    if (pairs !== null) {
      for (let k = 0; k < pairs.length; k += 2) {
        const row = pairs[k]!;
        if (!(Number.isInteger(row) && row >= 0 && row < upto)) throw new RangeError(`restore: snapshot's ${path} is damaged`);
      }
    }
    let out = target[key];
    if (!(out instanceof Float64Array && out.length === len)) {
      out = new Float64Array(len);
      target[key] = out;
    }
    const t = out as Float64Array;
    // -x is exactly x with its sign bit flipped, as prepareContacts' -ny.
    if (axis === 'x') for (let i = 0; i < upto; i++) t[i] = -src[i]!;
    else t.set(src.subarray(0, upto));
    if (pairs !== null) for (let k = 0; k < pairs.length; k += 2) t[pairs[k]!] = pairs[k + 1]!;
  }
}

// --- bitecs internals (0.4): the entity index, component masks, entity component sets, queries. ---

interface SparseSetLike {
  dense: ArrayLike<number>;
  add(v: number): void;
  reset(): void;
  has(v: number): boolean;
}
interface QueryData extends SparseSetLike {
  allComponents: object[];
  notComponents: object[];
  orComponents: object[];
  toRemove: SparseSetLike;
}
interface ComponentData {
  generationId: number;
  bitflag: number;
  ref: object;
}
interface EcsInternals {
  entityIndex: { aliveCount: number; dense: number[]; sparse: number[] | Int32Array; maxId: number; versioning: boolean };
  entityMasks: (number[] | Int32Array)[];
  entityComponents: Map<number, Set<object>>;
  componentMap: Map<object, ComponentData>;
  queries: Set<QueryData>;
  dirtyQueries: Set<QueryData>;
}
function internals(world: PhysicsWorld): EcsInternals {
  return (world as unknown as Record<symbol, EcsInternals>)[$internal]!;
}

function namesOf(world: PhysicsWorld): Map<object, string> {
  // The map is kept per world while world.components holds the same stores under the same names, so
  // query descriptors computed from it stay valid (see describeKeyed).
  const entries = Object.entries(world.components);
  const last = nameMaps.get(world);
  if (last !== undefined && last.size === entries.length && entries.every(([name, store]) => last.get(store as object) === name))
    return last;
  const names = new Map<object, string>();
  for (const [name, store] of entries) names.set(store as object, name);
  nameMaps.set(world, names);
  return names;
}
/** The last name map of each world (see namesOf). */
const nameMaps = new WeakMap<PhysicsWorld, Map<object, string>>();

/**
 * Each query's descriptor and key as last computed, with the name map they were computed from (a
 * query's components never change; the names of world.components could, so a new map recomputes).
 */
const described = new WeakMap<
  object,
  { names: Map<object, string>; d: { and: string[]; not: string[]; or: string[] } | null; key: string }
>();

/** `describeQuery` and its `keyOf` (key '' when null), computed once per query and name map (see `namesOf`). */
function describeKeyed(
  q: QueryData,
  names: Map<object, string>,
): { d: { and: string[]; not: string[]; or: string[] } | null; key: string } {
  let c = described.get(q);
  if (c === undefined || c.names !== names) {
    const d = describeQuery(q, names);
    c = { names, d, key: d === null ? '' : keyOf(d) };
    described.set(q, c);
  }
  return c;
}

/** Query descriptor: its component names (and, not, or), or null if it involves a component outside world.components. */
function describeQuery(q: QueryData, names: Map<object, string>): { and: string[]; not: string[]; or: string[] } | null {
  const name = (c: object) => names.get(c);
  const not = q.notComponents.map(name),
    or = q.orComponents.map(name);
  const and = q.allComponents.filter((c) => !q.notComponents.includes(c) && !q.orComponents.includes(c)).map(name);
  if ([...and, ...not, ...or].some((n) => n === undefined)) return null;
  return { and: (and as string[]).sort(), not: (not as string[]).sort(), or: (or as string[]).sort() };
}
const keyOf = (d: { and: string[]; not: string[]; or: string[] }) => `${d.and.join(',')}|${d.not.join(',')}|${d.or.join(',')}`;

function toInt32(a: ArrayLike<number>): Int32Array {
  if (a instanceof Int32Array) return a;
  const out = new Int32Array(a.length);
  for (let i = 0; i < a.length; i++) out[i] = a[i]!;
  return out;
}

function bitIndex(bitflag: number): number {
  return 31 - Math.clz32(bitflag);
}

/**
 * Whether two id lists hold the same ids in the same order. Two copies, each with one pair of array
 * kinds, so the element reads stay monomorphic (a shared one mixing JS and typed arrays ran several
 * times slower on the 100,000-entity lists); four ids a step, XOR-ed and OR-ed (ids are small integers).
 */
function sameLists(a: readonly number[], b: readonly number[]): boolean {
  const n = a.length;
  if (n !== b.length) return false;
  let i = 0;
  for (; i + 4 <= n; i += 4)
    if (((a[i]! ^ b[i]!) | (a[i + 1]! ^ b[i + 1]!) | (a[i + 2]! ^ b[i + 2]!) | (a[i + 3]! ^ b[i + 3]!)) !== 0) return false;
  for (; i < n; i++) if (a[i] !== b[i]) return false;
  return true;
}
function sameAsStored(a: readonly number[], b: Int32Array): boolean {
  const n = a.length;
  if (n !== b.length) return false;
  let i = 0;
  for (; i + 4 <= n; i += 4)
    if (((a[i]! ^ b[i]!) | (a[i + 1]! ^ b[i + 1]!) | (a[i + 2]! ^ b[i + 2]!) | (a[i + 3]! ^ b[i + 3]!)) !== 0) return false;
  for (; i < n; i++) if (a[i] !== b[i]) return false;
  return true;
}

/**
 * What the last snapshot of a world found about one of its query sets (lean storage: sets with a
 * `version`, see world/lean-ecs.ts): its version and length then, and the earlier set of that snapshot it
 * was equal to (null: none) with that set's version and length then.
 */
interface ListMemo {
  version: number;
  length: number;
  same: object | null;
  sameVersion: number;
  sameLength: number;
}
const listMemos = new WeakMap<PhysicsWorld, Map<object, ListMemo>>();

/**
 * Encodes bitecs id lists, each once: a list equal to one encoded before (most queries hold the same
 * entities in the same order) becomes a reference `{ $t: 'same', i }` to that one's position in `lists`.
 * Finding that costs a comparison of the two lists, except where neither set has changed (same
 * version and length, world/lean-ecs.ts) since the world's last snapshot found them equal.
 */
class IdLists {
  private readonly done: Array<{ ids: readonly number[]; index: number; set: object | null }> = [];
  /** Index in `lists` of each set encoded by this snapshot. */
  private readonly indexOf = new Map<object, number>();
  private readonly memos: Map<object, ListMemo>;
  readonly lists: Encoded[] = [];
  constructor(
    private readonly w: Writer,
    world: PhysicsWorld,
  ) {
    let m = listMemos.get(world);
    if (m === undefined) {
      m = new Map();
      listMemos.set(world, m);
    }
    this.memos = m;
  }
  /** Encodes the members of `set` (a query's sparse set, or null for a list of no set). */
  encode(ids: ArrayLike<number>, set: object | null): Encoded {
    if (ids.length === 0) return { $t: 'ids', v: [] };
    const js = Array.isArray(ids) ? (ids as readonly number[]) : null; // bitecs' buffered queries hold typed lists
    const version = (set as { version?: number } | null)?.version;
    if (js !== null && set !== null && version !== undefined) {
      const m = this.memos.get(set);
      if (m !== undefined && m.same !== null && m.version === version && m.length === js.length) {
        const same = m.same as { version?: number; dense: ArrayLike<number> };
        const i = this.indexOf.get(same);
        if (i !== undefined && same.version === m.sameVersion && same.dense.length === m.sameLength) {
          this.indexOf.set(set, i);
          return { $t: 'same', i };
        }
      }
    }
    if (js !== null) {
      for (const d of this.done) {
        if (!sameLists(d.ids, js)) continue;
        if (set !== null && version !== undefined) {
          const other = d.set as { version?: number } | null;
          this.memos.set(
            set,
            other !== null && other.version !== undefined
              ? { version, length: js.length, same: other, sameVersion: other.version, sameLength: d.ids.length }
              : { version, length: js.length, same: null, sameVersion: 0, sameLength: 0 },
          );
          this.indexOf.set(set, d.index);
        }
        return { $t: 'same', i: d.index };
      }
    }
    const index = this.lists.length;
    // A list of consecutive ids (the entity list of a world without removals: 1 .. N) as its first id
    // and length, `{ $t: 'range', first, n }`: 0.4 MB less to copy for 100,000 bodies.
    this.lists.push(
      js !== null && isRange(js)
        ? { $t: 'range', first: js[0]!, n: js.length }
        : js !== null
          ? this.w.ids(js)
          : this.w.arrayTo(toInt32(ids), ids.length),
    );
    if (js !== null) this.done.push({ ids: js, index, set });
    if (set !== null && version !== undefined) {
      this.indexOf.set(set, index);
      this.memos.set(set, { version, length: ids.length, same: null, sameVersion: 0, sameLength: 0 });
    }
    return { $t: 'same', i: index };
  }
}

/** Whether `list` (at least 64 ids) holds consecutive ids: list[i] = list[0] + i. */
function isRange(list: readonly number[]): boolean {
  const n = list.length;
  if (n < 64) return false;
  const first = list[0]!;
  if (list[n - 1] !== first + n - 1) return false;
  for (let i = 1; i < n; i++) if (list[i] !== first + i) return false;
  return true;
}

/**
 * The id lists of a snapshot's ECS part, each an Int32Array: stored ones are views into the snapshot,
 * ranges (see IdLists) are views of one shared list of the ids 1, 2, ... (made once: no allocation a restore).
 * @throws RangeError if a range is damaged (ids must be integers from 1, within the capacity).
 */
function readIdLists(encoded: readonly Encoded[], r: Reader, capacity: number): Int32Array[] {
  return encoded.map((l, i) => {
    const e = l as Record<string, Encoded>;
    if (e.$t !== 'range') return r.used(e, `ecs.lists[${i}]`) as Int32Array;
    checkRange(e, i, capacity);
    const first = e.first as number,
      n = e.n as number;
    // The list 1 .. capacity, made once and shared; a range is a view of it (its ids are never written).
    return countingTo(capacity).subarray(first - 1, first - 1 + n);
  });
}
/** @throws RangeError `restore: snapshot's ecs.lists[i] is damaged` unless the range `e` holds integer ids from 1 up to `capacity`. */
function checkRange(e: Record<string, Encoded>, i: number, capacity: number): void {
  const first = e.first as number,
    n = e.n as number;
  if (!(Number.isInteger(first) && Number.isInteger(n) && first >= 1 && n >= 1 && first + n - 1 <= capacity)) {
    throw new RangeError(`restore: snapshot's ecs.lists[${i}] is damaged`);
  }
}

/** 1, 2, ..., at least the largest capacity restored into so far (see readIdLists, countingTo). */
let counting = new Int32Array(0);

/** The shared list 1, 2, ..., at least `n` long (grown by doubling; its elements are never written elsewhere). */
function countingTo(n: number): Int32Array {
  if (counting.length < n) {
    const next = new Int32Array(Math.max(n, 2 * counting.length));
    for (let k = 0; k < next.length; k++) next[k] = k + 1;
    counting = next;
  }
  return counting;
}

/**
 * Whether element i of `a` is i for i = 1 .. n-1 (n <= a.length): natively, elements 1 .. n-1
 * against the shared list 1, 2, ... (see countingTo), where the host compares natively; else a loop.
 */
function iotaFrom1(a: Int32Array, n: number): boolean {
  if (n < 2 || a[1] !== 1 || a[n - 1] !== n - 1) return n < 2;
  if (nativeCompare !== undefined) {
    const ones = countingTo(n - 1);
    const x = new Uint8Array(a.buffer, a.byteOffset + 4, 4 * (n - 1));
    const y = new Uint8Array(ones.buffer, ones.byteOffset, 4 * (n - 1));
    return nativeCompare(x, y) === 0;
  }
  for (let i = 2; i < n - 1; i++) if (a[i] !== i) return false;
  return true;
}

function captureEcs(world: PhysicsWorld, w: Writer): Encoded {
  const ctx = internals(world);
  const ix = ctx.entityIndex;
  if (ix.versioning) throw new Error('snapshot: worlds with a versioned entity index are not supported');
  const names = namesOf(world);
  const maxId = ix.maxId;
  // Component bit layout; a component outside world.components may not be on any live entity.
  const layout: Encoded[] = [];
  const known = new Int32Array(ctx.entityMasks.length);
  let foreign = false;
  for (const data of ctx.componentMap.values()) {
    const name = names.get(data.ref);
    if (name !== undefined) {
      layout.push([name, data.generationId, bitIndex(data.bitflag)]);
      known[data.generationId]! |= data.bitflag;
    } else {
      foreign = true;
    }
  }
  const masks: Encoded[] = [];
  for (let g = 0; g < ctx.entityMasks.length; g++) {
    const src = ctx.entityMasks[g]!;
    const unknown = ~known[g]!;
    const n = Math.min(src.length, maxId + 1);
    let bad = 0;
    // Only a world with a registered component outside world.components can have a foreign bit set.
    if (foreign) for (let e = 0; e < n; e++) bad |= (src[e] ?? 0) & unknown;
    if (bad !== 0) {
      let e = 0;
      while (((src[e] ?? 0) & unknown) === 0) e++;
      throw new Error(`snapshot: entity ${e} has a component that is not one of world.components; only those can be captured`);
    }
    // Typed masks (world/lean-ecs.ts) are stored as they are, up to their last set entry (ids above maxId
    // have none); JS ones as Int32Array.
    if (src instanceof Int32Array) {
      masks.push(w.arrayTo(src, n));
      continue;
    }
    const m = new Int32Array(n);
    for (let e = 0; e < n; e++) m[e] = src[e] ?? 0;
    masks.push(w.arrayTo(m, n));
  }
  const lists = new IdLists(w, world);
  const queries: Encoded[] = [];
  for (const q of ctx.queries) {
    const d = describeKeyed(q, names).d;
    if (d === null) continue;
    queries.push({
      $t: 'o',
      v: {
        and: d.and.slice(),
        not: d.not.slice(),
        or: d.or.slice(),
        dense: lists.encode(q.dense, q),
        toRemove: lists.encode(q.toRemove.dense, q.toRemove),
      },
    });
  }
  // The entity index has no version: compared with the query lists (it usually equals a query's).
  const dense = lists.encode(ix.dense, null);
  const ecs = { aliveCount: ix.aliveCount, maxId, dense, layout, masks, queries, lists: lists.lists };
  const versions = new WeakMap<object, number>();
  for (const q of ctx.queries) {
    for (const set of [q, q.toRemove]) {
      const v = versionOf(set);
      if (v !== undefined) versions.set(set, v);
    }
  }
  matching.set(ecs, versions);
  return ecs;
}

/**
 * For the ECS part of a snapshot (by object identity, so a cloned or parsed snapshot has none): the
 * version (world/lean-ecs.ts) each query set of a world had when its members were known to equal the
 * snapshot's list for it, recorded when the snapshot was taken and when a restore wrote the list.
 * A set whose version is still that one has not changed since: restoring the snapshot again (a
 * rewind, a rollback) need not compare or write it.
 */
const matching = new WeakMap<object, WeakMap<object, number>>();
function newMatching(ecs: object): WeakMap<object, number> {
  const m = new WeakMap<object, number>();
  matching.set(ecs, m);
  return m;
}
function versionOf(set: object): number | undefined {
  return (set as { version?: number }).version;
}

/** Reads an id list encoded by IdLists. */
function idList(e: Encoded, lists: readonly Int32Array[], path: string): Int32Array {
  const t = isTagged(e) ? e.$t : undefined;
  if (t === 'ids') return new Int32Array(0);
  const list = t === 'same' ? lists[(e as Record<string, Encoded>).i as number] : undefined;
  if (list === undefined) throw new RangeError(`restore: snapshot's ${path} is damaged`);
  return list;
}

function restoreEcs(world: PhysicsWorld, ecs: Record<string, Encoded>, r: Reader, oldMaxId: number): void {
  const ctx = internals(world);
  const ix = ctx.entityIndex;
  const C = world.components as unknown as Record<string, object>;
  const lists = readIdLists(ecs.lists as Encoded[], r, world.capacity);
  // Layout: the target's bit of each snapshot component (registering components the target has not seen).
  const layout = ecs.layout as [string, number, number][];
  // The stored masks: views into the snapshot, checked here (before anything is written); a repeated
  // value is expanded only where the layouts differ (else written straight into the world's masks).
  const maskEnc = (ecs.masks as Encoded[]).map((m) => m as Record<string, Encoded>);
  const maskViews = maskEnc.map((m, g) => r.array(m, `masks[${g}]`) as Int32Array);
  let same = true;
  const map: Array<{ sg: number; sbit: number; tg: number; tflag: number }> = [];
  for (const [name, sg, sbit] of layout) {
    const comp = C[name];
    if (comp === undefined) throw new RangeError(`restore: snapshot has component '${name}', which this world does not`);
    const data = ctx.componentMap.get(comp) ?? (registerComponent(world as never, comp) as unknown as ComponentData);
    if (data.generationId !== sg || bitIndex(data.bitflag) !== sbit) same = false;
    map.push({ sg, sbit, tg: data.generationId, tflag: data.bitflag });
  }
  // Queries of the snapshot this world lacks are made now, before its masks and entity index change:
  // bitecs fills a new query by testing every live entity (about 0.5 s for 100,000 entities and the
  // 40-odd queries of a world that has not stepped yet), and these lists are overwritten below anyway.
  const names = namesOf(world);
  const byKey = new Map<string, QueryData>();
  for (const q of ctx.queries) {
    const { d, key } = describeKeyed(q, names);
    if (d !== null) byKey.set(key, q);
  }
  for (const enc of ecs.queries as Encoded[]) {
    const qd = (enc as Record<string, Encoded>).v as Record<string, Encoded>;
    const d = { and: qd.and as string[], not: qd.not as string[], or: qd.or as string[] };
    const key = keyOf(d);
    if (byKey.has(key)) continue;
    const terms: object[] = d.and.map((n) => C[n]!);
    for (const n of d.not) terms.push(Not(C[n]! as never) as object);
    if (d.or.length > 0) terms.push(Or(...d.or.map((n) => C[n]! as never)) as object);
    bitecsQuery(world as never, terms as never);
    const q = [...ctx.queries].find((x) => {
      const dx = describeKeyed(x, names);
      return dx.d !== null && dx.key === key;
    });
    if (q === undefined) throw new Error(`restore: could not make the query ${key}`);
    byKey.set(key, q);
  }
  const maxId = ecs.maxId as number;
  const gens = ctx.entityMasks.length;
  // Masks, written in place: entries up to the larger of the two highest ids (ids above both are 0).
  const top = Math.max(maxId, oldMaxId) + 1;
  if (same) {
    for (let g = 0; g < gens; g++) {
      const arr = ctx.entityMasks[g]!,
        e = maskEnc[g];
      if (e !== undefined && e.rep !== undefined && arr instanceof Int32Array && arr.length >= (e.rep as number)) {
        // A repeated mask (every entity up to the highest id with the same components) written in
        // place, its repeat left as it is where the world already holds it (Reader.write); zeros up to `top`.
        const written = r.write(arr, maskViews[g]!, e);
        if (top > written) zeroFill(arr, written, Math.min(top, arr.length));
      } else {
        writeMask(arr, e === undefined ? undefined : (r.used(e, `masks[${g}]`) as Int32Array), top);
      }
    }
  } else {
    const srcMasks = maskEnc.map((m, g) => r.used(m, `masks[${g}]`) as Int32Array);
    const newMasks: Int32Array[] = [];
    for (let g = 0; g < gens; g++) newMasks.push(new Int32Array(top));
    for (const { sg, sbit, tg, tflag } of map) {
      const s = srcMasks[sg]!,
        t = newMasks[tg]!;
      const f = 1 << sbit;
      for (let e = 0; e < s.length; e++) if ((s[e]! & f) !== 0) t[e]! |= tflag;
    }
    for (let g = 0; g < gens; g++) writeMask(ctx.entityMasks[g]!, newMasks[g], top);
  }
  // Entity index (written in place: its arrays stay packed).
  const dense = idList(ecs.dense!, lists, 'ecs.dense');
  const aliveCount = ecs.aliveCount as number;
  // Unchanged (a rewind without births or deaths): its sparse array, kept in step with it, is too.
  if (!sameAsStored(ix.dense, dense)) {
    writeInPlace(ix.dense, dense, dense.length);
    const sparse = ix.sparse;
    for (let i = 0; i < dense.length; i++) sparse[dense[i]!] = i;
  }
  ix.aliveCount = aliveCount;
  ix.maxId = maxId;
  // Component sets: derived from the masks in a world made by createPhysicsWorld; rebuilt otherwise.
  if (!hasMaskComponentSets(world)) {
    const bits: object[][] = [];
    for (const data of ctx.componentMap.values()) (bits[data.generationId] ??= [])[bitIndex(data.bitflag)] = data.ref;
    ctx.entityComponents.clear();
    for (let i = 0; i < aliveCount; i++) {
      const e = dense[i]!;
      const set = new Set<object>();
      for (let g = 0; g < gens; g++) {
        let m = ctx.entityMasks[g]![e] ?? 0;
        while (m !== 0) {
          const b = 31 - Math.clz32(m);
          set.add(bits[g]![b]!);
          m &= ~(1 << b);
        }
      }
      ctx.entityComponents.set(e, set);
    }
  }
  // Queries: the snapshot's in their order; any other query of this world is rebuilt in entity order.
  const done = new Set<QueryData>();
  let known = matching.get(ecs);
  // The first set this restore gave each stored list, its version before, and whether it was written.
  const holders = new Map<Int32Array, { set: object; before: number; changed: boolean }>();
  ctx.dirtyQueries.clear();
  for (const enc of ecs.queries as Encoded[]) {
    const qd = (enc as Record<string, Encoded>).v as Record<string, Encoded>;
    const d = { and: qd.and as string[], not: qd.not as string[], or: qd.or as string[] };
    const q = byKey.get(keyOf(d))!; // made above
    done.add(q);
    const rem = idList(qd.toRemove!, lists, 'query');
    for (const [set, ids] of [
      [q, idList(qd.dense!, lists, 'query')],
      [q.toRemove, rem],
    ] as const) {
      // A set that has not changed since it last held this snapshot's list (taken from this world, or
      // written by an earlier restore of it) is left as it is; any other is compared and written.
      const v = versionOf(set);
      const holder = v !== undefined && ids.length > 0 ? holders.get(ids) : undefined;
      if (v !== undefined && known?.get(set) === v) {
        if (ids.length > 0 && holder === undefined) holders.set(ids, { set, before: v, changed: false });
        continue;
      }
      // A set that held what the list's first set (its twin) held, as of both sets' versions then
      // (recorded by an earlier restore into this world), equals the list exactly when its twin did:
      // left as it is, or written without comparing.
      const twin = holder !== undefined ? twins.get(set) : undefined;
      let changed: boolean;
      if (
        holder !== undefined &&
        twin !== undefined &&
        twin.peer === holder.set &&
        twin.version === v &&
        twin.peerVersion === holder.before
      ) {
        changed = holder.changed;
        if (changed) setContent(set, ids, false);
      } else {
        changed = setContent(set, ids, true);
      }
      const after = versionOf(set);
      if (after !== undefined) (known ??= newMatching(ecs)).set(set, after);
      if (after !== undefined && ids.length > 0) {
        if (holder === undefined) holders.set(ids, { set, before: v!, changed });
        else twins.set(set, { peer: holder.set, version: after, peerVersion: versionOf(holder.set)! });
      }
    }
    if (rem.length > 0) ctx.dirtyQueries.add(q);
  }
  for (const q of ctx.queries) {
    if (done.has(q)) continue;
    q.reset();
    q.toRemove.reset();
    for (let i = 0; i < aliveCount; i++) {
      const e = ix.dense[i]!;
      if (matches(ctx, q, e)) q.add(e);
    }
  }
}

/** Makes mask array `arr` hold `src` (missing entries 0) for ids below `top`; typed masks are written with set and fill. */
function writeMask(arr: number[] | Int32Array, src: ArrayLike<number> | undefined, top: number): void {
  const n = Math.min(src?.length ?? 0, top);
  if (arr instanceof Int32Array) {
    if (n > 0) arr.set(n === src!.length ? src! : (src as Int32Array).subarray(0, n));
    if (top > n) arr.fill(0, n, Math.min(top, arr.length));
    return;
  }
  for (let i = 0; i < n; i++) arr[i] = src![i]!;
  for (let i = n; i < Math.min(top, arr.length); i++) arr[i] = 0;
}

/** Makes `arr` hold `src[0..n)` (JS array written in place, so it stays packed). */
function writeInPlace(arr: number[], src: ArrayLike<number>, n: number): void {
  const m = Math.min(arr.length, n);
  for (let i = 0; i < m; i++) arr[i] = src[i]!;
  if (arr.length > n) arr.length = n;
  for (let i = m; i < n; i++) arr.push(src[i]!);
}

/**
 * Makes a bitecs sparse set hold exactly `ids`, in that order: untouched if it already does (with
 * `compare`), else written. @returns whether it was written.
 */
function setContent(set: SparseSetLike, ids: Int32Array, compare: boolean): boolean {
  const dense = set.dense;
  if (compare && Array.isArray(dense) && sameAsStored(dense as number[], ids)) return false;
  // Lean storage (world/lean-ecs.ts): written in bulk, its typed sparse array allocated if it was not yet.
  if (assignSparseSet(set, ids)) return true;
  const sparse = (set as unknown as { sparse: ArrayLike<number> & { [i: number]: number } }).sparse;
  if (Array.isArray(dense)) {
    writeInPlace(dense, ids, ids.length);
    for (let i = 0; i < ids.length; i++) sparse[ids[i]!] = i;
    return true;
  }
  set.reset();
  for (let i = 0; i < ids.length; i++) set.add(ids[i]!);
  return true;
}

/**
 * Query sets of a world (lean storage, with versions) known to hold the same ids in the same order as
 * another set of it, `peer`, while their versions are still `version` and `peerVersion`: written by
 * restore when both were given one stored list. A world restored again and again from snapshots of
 * another (a replica) then compares each list with one set only, not with every query holding it.
 */
const twins = new WeakMap<object, { peer: object; version: number; peerVersion: number }>();

function matches(ctx: EcsInternals, q: QueryData, e: number): boolean {
  const has = (c: object) => {
    const d = ctx.componentMap.get(c);
    return d !== undefined && ((ctx.entityMasks[d.generationId]![e] ?? 0) & d.bitflag) !== 0;
  };
  const and = q.allComponents.filter((c) => !q.notComponents.includes(c) && !q.orComponents.includes(c));
  if (!and.every(has)) return false;
  if (q.notComponents.some(has)) return false;
  return q.orComponents.length === 0 || q.orComponents.some(has);
}

/**
 * The component stores no live entity has (one pass OR-ing the entities' component masks). A typed
 * mask generation is OR-ed in id order up to the highest id, four entries a step: removal clears a
 * slot's masks, so a free slot adds nothing (and a stale bit could only keep a store, never drop one).
 */
function unusedStores(world: PhysicsWorld): Set<object> {
  const ctx = internals(world);
  const ix = ctx.entityIndex;
  const union = new Int32Array(ctx.entityMasks.length);
  for (let g = 0; g < union.length; g++) {
    const m = ctx.entityMasks[g]!;
    let u = 0;
    if (m instanceof Int32Array) {
      const n = Math.min(m.length, ix.maxId + 1);
      // Every entity with the same components (a world of one kind of body): one native comparison.
      if (sameFrom1Native(m, n)) u = m[0]! | m[1]!;
      else {
        let e = 0;
        for (; e + 4 <= n; e += 4) u |= m[e]! | m[e + 1]! | m[e + 2]! | m[e + 3]!;
        for (; e < n; e++) u |= m[e]!;
      }
    } else {
      for (let i = 0; i < ix.aliveCount; i++) u |= m[ix.dense[i]!] ?? 0;
    }
    union[g] = u;
  }
  const unused = new Set<object>();
  for (const store of Object.values(world.components)) {
    const data = ctx.componentMap.get(store as object);
    if (data !== undefined && (union[data.generationId]! & data.bitflag) === 0) unused.add(store as object);
  }
  return unused;
}

/**
 * The complete state of `world` as transferable data: a JSON-able header and one ArrayBuffer (post it to
 * a Worker in the transfer list, or write it to disk; layout in the module docstring). The world is not changed.
 * Restore it with `restore` into this world or another made with the same options and systems.
 *
 * @param reuse optional: an earlier snapshot that is no longer needed (a rollback ring's oldest entry).
 *   Its buffer is written over and shared by the new snapshot when it is large enough, which saves
 *   allocating (and the system zeroing) a new one; `reuse` itself must not be restored afterwards. When
 *   it is too small, the new buffer is allocated a quarter larger than the data (room for the snapshot
 *   to grow before the ring reuses it again), so the new snapshot's buffer may be longer than its data.
 * @throws TypeError if the world holds state that cannot be copied (a function or a shared object where
 *   data belongs), if `reuse` is not a snapshot, or Error if an entity carries a component outside
 *   `world.components`.
 * @example
 * const saved = snapshot(world); stepMany(world, 100); restore(world, saved); // back 100 steps
 * @category Snapshots
 */
export function snapshot(world: PhysicsWorld, reuse?: WorldSnapshot): WorldSnapshot {
  const old = reuse?.buffers?.[0];
  if (reuse !== undefined && !(old instanceof ArrayBuffer && reuse.buffers.length === 1)) {
    throw new TypeError(`snapshot: reuse must be a snapshot returned by snapshot(world), got ${describe(reuse)}`);
  }
  const ctx = internals(world);
  const registered = new Set<string>();
  for (const [name, store] of Object.entries(world.components)) if (ctx.componentMap.has(store as object)) registered.add(name);
  const w = new Writer(world.capacity + 1, ctx.entityIndex.maxId, registered);
  w.unused = unusedStores(world);
  const state = w.object(world as unknown as Record<string, unknown>, 'world', NOT_STATE);
  const external: Record<string, Encoded> = {};
  for (const ext of externalWorldStates()) {
    const s = ext.get(world, false);
    external[ext.name] = s === undefined ? null : w.object(s as Record<string, unknown>, ext.name, new Set(ext.keep ?? []));
  }
  const ecs = captureEcs(world, w);
  const buffer = w.finish(old);
  const fields = {
    format: FORMAT,
    version: VERSION,
    dimensions: world.dimensions,
    capacity: world.capacity,
    bytes: w.length,
    state,
    external,
    ecs,
  };
  return { header: { ...fields, checksum: snapshotChecksum(fields, buffer, w.length) }, buffers: [buffer] };
}

/** The header's format name. */
const FORMAT = 'bitphysics-snapshot';
/** The format version `snapshot` writes and `restore` reads: 3 (version 2 had no checksum). */
const VERSION = 3;

/** A snapshot's header without its checksum, in the order `snapshot` wrote it (see snapshotChecksum). */
function checksumFields(h: SnapshotHeader): object {
  const { format, version, dimensions, capacity, bytes, state, external, ecs } = h;
  return { format, version, dimensions, capacity, bytes, state, external, ecs };
}

/**
 * Writes `snap`'s checksum again, for its header and buffer as they are now: for tools that edit a
 * snapshot on purpose (and tests that check what restore makes of edited values). A snapshot taken
 * by `snapshot` needs none of this. Not exported by the package.
 * @category Snapshots
 */
export function sealSnapshot(snap: WorldSnapshot): void {
  const h = snap.header as { -readonly [K in keyof SnapshotHeader]: SnapshotHeader[K] };
  h.checksum = snapshotChecksum(checksumFields(h), snap.buffers[0]!, h.bytes);
}

/**
 * Puts the state of `snap` into `world`: afterwards stepping `world` gives bit-identical results to
 * stepping the world the snapshot was taken from. The world must have been made with the same
 * dimensions and capacity and have the same systems (custom systems, force laws and death hooks are
 * code and are not in a snapshot); stage settings (gravity, dt, integrator, solver settings) come from
 * the snapshot. The snapshot is not changed and can be restored again.
 *
 * Restore is all or nothing: it checks the snapshot first (format and version, the world's
 * dimensions and capacity, the checksum of the header and buffer, every encoded array's type, offset
 * and length, every scalar against the rules of snapshot/checks.ts, the entity ids against the
 * capacity) by a dry run of the whole restore, and writes only when all of it passed. A refused
 * snapshot leaves the world exactly as it was.
 *
 * Threads: the world keeps its own thread count and worker pool (they are not state: see NOT_STATE),
 * so a snapshot of a world with any number of threads restores into a world with any number. Stepping
 * on is bit-identical for every pair of thread counts (each body's arithmetic and every stage's order
 * do not depend on them; steps solved by colours take the same colours on one thread).
 *
 * @throws RangeError `restore: snapshot ...` if `snap` is not a snapshot, was taken from a world of
 *   other dimensions or capacity or by another version, is damaged (checksum), or holds a value out
 *   of range; the world is then left as it was.
 * @category Snapshots
 */
export function restore(world: PhysicsWorld, snap: WorldSnapshot): void {
  const where = 'restore';
  if (
    snap === null ||
    typeof snap !== 'object' ||
    snap.header === null ||
    typeof snap.header !== 'object' ||
    !Array.isArray(snap.buffers)
  ) {
    throw new RangeError(`${where}: snapshot must be a value returned by snapshot(world), got ${describe(snap)}`);
  }
  const h = snap.header;
  if (h.format !== FORMAT || h.version !== VERSION) {
    throw new RangeError(
      `${where}: snapshot must be a bitphysics snapshot of version ${VERSION}, got format ${describe(h.format)} version ${describe(h.version)}`,
    );
  }
  if (h.dimensions !== world.dimensions || h.capacity !== world.capacity) {
    throw new RangeError(
      `${where}: snapshot must come from a world with the same options: it has dimensions ${describe(h.dimensions)} and capacity ${describe(h.capacity)}, this world ${world.dimensions} and ${world.capacity}`,
    );
  }
  const buffer = snap.buffers[0];
  if (snap.buffers.length !== 1 || !(buffer instanceof ArrayBuffer)) {
    throw new RangeError(`${where}: snapshot must hold one ArrayBuffer, got ${snap.buffers.length} buffers`);
  }
  if (!(Number.isInteger(h.bytes) && h.bytes >= 0 && h.bytes <= buffer.byteLength)) {
    throw new RangeError(
      `${where}: snapshot is damaged: its header says ${describe(h.bytes)} bytes of data, its buffer holds ${buffer.byteLength}`,
    );
  }
  const sum = snapshotChecksum(checksumFields(h), buffer, h.bytes);
  if (sum !== h.checksum) {
    throw new RangeError(`${where}: snapshot is damaged: its checksum is ${describe(h.checksum)}, its contents hash to '${sum}'`);
  }
  if (!isTagged(h.state) || h.state.$t !== 'o' || !isTagged(h.state.v) || !isTagged(h.external as Encoded) || !isTagged(h.ecs)) {
    throw new RangeError(`${where}: snapshot is damaged: its header lacks the world's state`);
  }
  const state = h.state.v as Record<string, Encoded>;
  checkSnapshotValues(h.state, h.external, world);
  for (const key of Object.keys(world)) {
    if (!NOT_STATE.has(key) && !(key in state))
      throw new RangeError(`${where}: snapshot has no world.${key} (it was made by another version of bitphysics)`);
  }
  for (const ext of externalWorldStates()) {
    if (!(ext.name in h.external))
      throw new RangeError(`${where}: snapshot has no '${ext.name}' state (it was made by another version of bitphysics)`);
  }
  const oldMaxId = internals(world).entityIndex.maxId;
  const r = new Reader(buffer, world.capacity, oldMaxId);
  // The dry run: everything the restore below reads is checked, nothing is written.
  r.dry = true;
  r.objectInto(world as unknown as Record<string, unknown>, state, 'world', NOT_STATE);
  for (const ext of externalWorldStates()) {
    const enc = h.external[ext.name]!;
    if (enc === null) continue;
    if (!isTagged(enc) || enc.$t !== 'o') throw new RangeError(`${where}: snapshot's ${ext.name} is damaged`);
    const target = ext.get(world, false);
    if (target === undefined) r.fresh(enc, ext.name);
    else r.objectInto(target as Record<string, unknown>, enc.v as Record<string, Encoded>, ext.name, new Set(ext.keep ?? []));
  }
  checkEcs(world, h.ecs, r);
  r.dry = false;
  // Stamp counters (see STAMPED): the world's own, before the snapshot's are written.
  const counters = [...STAMPED.values()].map(({ parent, counter }) => parent(world)[counter]);
  r.objectInto(world as unknown as Record<string, unknown>, state, 'world', NOT_STATE);
  let s = 0;
  for (const { parent, counter } of STAMPED.values()) {
    const own = counters[s++],
      target = parent(world);
    if (typeof own === 'number' && typeof target[counter] === 'number' && own > (target[counter] as number)) target[counter] = own;
  }
  for (const ext of externalWorldStates()) {
    const enc = h.external[ext.name]!;
    if (enc === null) {
      ext.clear(world);
      continue;
    }
    const target = ext.get(world, true)!;
    r.objectInto(
      target as Record<string, unknown>,
      (enc as Record<string, Encoded>).v as Record<string, Encoded>,
      ext.name,
      new Set(ext.keep ?? []),
    );
  }
  restoreEcs(world, h.ecs as Record<string, Encoded>, r, oldMaxId);
  installEveryFeature(world);
  // A store the restore gave a new array (one this world had not allocated) goes on shared memory,
  // where the pool's workers can see it.
  if (world.threadPool !== null) shareStores(world.components, world.capacity);
}

/**
 * Installs every feature's systems into a restored world (world/install.ts): the emitters', the balls', the 3D
 * shapes' and joints', the cloth's and the Barnes-Hut sum, so the world runs whatever the snapshot's
 * world ran. A feature the snapshot's world never used has nothing to act on and writes nothing.
 */
function installEveryFeature(world: PhysicsWorld): void {
  installEmitters(world);
  installBalls(world);
  install3D(world);
  installCloth(world);
  setBarnesHutGravity(barnesHutGravity);
}

/**
 * Checks the ECS part of a snapshot before restoreEcs writes it: every id list sound and within the
 * capacity, the entity index (alive count, highest id, its id list: each id from 1 to the highest
 * once), the component layout (names of this world's components, generations and bits in range),
 * the masks, and the queries (names of this world's components, id lists that exist).
 * @throws RangeError `restore: snapshot's ecs... is damaged` (or names the component this world lacks).
 */
function checkEcs(world: PhysicsWorld, ecs: Record<string, Encoded>, r: Reader): void {
  const capacity = world.capacity;
  const damaged = (path: string, why: string) => new RangeError(`restore: snapshot's ecs.${path} is damaged: ${why}`);
  const C = world.components as unknown as Record<string, object>;
  const has = (n: unknown) => typeof n === 'string' && Object.hasOwn(C, n);
  if (!Array.isArray(ecs.lists) || !Array.isArray(ecs.layout) || !Array.isArray(ecs.masks) || !Array.isArray(ecs.queries))
    throw damaged('', 'lists, layout, masks or queries missing');
  ecs.lists.forEach((l, i) => {
    if (!isTagged(l)) throw damaged(`lists[${i}]`, 'not a list');
    if (l.$t === 'range') {
      checkRange(l, i, capacity);
      return;
    }
    if (l.$t !== 'Int32Array') throw damaged(`lists[${i}]`, 'not a list of ids');
    const ids = r.used(l, `ecs.lists[${i}]`);
    for (let k = 0; k < ids.length; k++) {
      const id = ids[k]!;
      if (!(id >= 1 && id <= capacity)) throw damaged(`lists[${i}]`, `id ${id} is outside 1 .. ${capacity}`);
    }
  });
  const lists = readIdLists(ecs.lists as Encoded[], r, capacity);
  const aliveCount = ecs.aliveCount,
    maxId = ecs.maxId;
  if (!(Number.isInteger(maxId) && (maxId as number) >= 0 && (maxId as number) <= capacity))
    throw damaged('maxId', `must be an integer in [0, ${capacity}], got ${describe(maxId)}`);
  const dense = idList(ecs.dense!, lists, 'ecs.dense');
  if (!(Number.isInteger(aliveCount) && (aliveCount as number) >= 0 && (aliveCount as number) <= dense.length))
    throw damaged('aliveCount', `must be an integer in [0, ${dense.length}], got ${describe(aliveCount)}`);
  const seen = new Uint8Array((maxId as number) + 1);
  for (let i = 0; i < dense.length; i++) {
    const id = dense[i]!;
    if (!(id >= 1 && id <= (maxId as number)) || seen[id] !== 0) throw damaged('dense', `id ${id} is out of range or listed twice`);
    seen[id] = 1;
  }
  const gens = (ecs.masks as Encoded[]).length;
  (ecs.masks as Encoded[]).forEach((m, g) => {
    if (!isTagged(m) || m.$t !== 'Int32Array') throw damaged(`masks[${g}]`, 'not a mask list');
    r.array(m, `masks[${g}]`);
  });
  for (const entry of ecs.layout as Encoded[]) {
    if (!Array.isArray(entry) || entry.length !== 3) throw damaged('layout', 'an entry is not [name, generation, bit]');
    const [name, g, bit] = entry;
    if (typeof name === 'string' && !has(name))
      throw new RangeError(`restore: snapshot has component '${name}', which this world does not`);
    if (
      !(
        has(name) &&
        Number.isInteger(g) &&
        (g as number) >= 0 &&
        (g as number) < gens &&
        Number.isInteger(bit) &&
        (bit as number) >= 0 &&
        (bit as number) <= 31
      )
    )
      throw damaged('layout', `entry ${describe(entry)}`);
  }
  (ecs.queries as Encoded[]).forEach((enc, i) => {
    const qd = isTagged(enc) && isTagged(enc.v) ? enc.v : undefined;
    if (qd === undefined) throw damaged(`queries[${i}]`, 'not a query');
    for (const part of ['and', 'not', 'or'] as const) {
      const names = qd[part];
      if (!Array.isArray(names) || !names.every(has)) throw damaged(`queries[${i}].${part}`, "not a list of this world's components");
    }
    idList(qd.dense!, lists, `ecs.queries[${i}].dense`);
    idList(qd.toRemove!, lists, `ecs.queries[${i}].toRemove`);
  });
}
