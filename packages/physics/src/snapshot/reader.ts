import { describe } from '../validation/validate.js';
import type { Encoded } from './format.js';
import { TANGENT_2D } from './state-scope.js';
import { countingTo, iotaFrom1, sameFrom1Native, TYPED, type TypedArray, zeroFill } from './typed-arrays.js';

export function isTagged(e: Encoded): e is { [key: string]: Encoded } {
  return typeof e === 'object' && e !== null && !Array.isArray(e);
}

/**
 * Whether the world's value `x` is an object whose keys a snapshot's 'o' encoding restores one by one:
 * not null, an array, a Set, a Map or a typed array (those are replaced or refilled whole).
 */
function isPlainObject(x: unknown): x is Record<string, unknown> {
  return x !== null && typeof x === 'object' && !Array.isArray(x) && !(x instanceof Set) && !(x instanceof Map) && !ArrayBuffer.isView(x);
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

/**
 * Whether a TANGENT_2D note's numbers are sound, for both the dry run and the restore: `len` and
 * `upto` integers with 0 <= upto <= len, and `axis` 'x' or 'y'.
 */
function tangentNoteSound(e: { [key: string]: Encoded }): boolean {
  const len = e.len as number,
    upto = e.upto as number;
  return Number.isInteger(len) && Number.isInteger(upto) && upto >= 0 && upto <= len && (e.axis === 'x' || e.axis === 'y');
}

/**
 * Whether a TANGENT_2D note's rows written apart (`pairs`: row, value, row, value, ...) come in
 * pairs, each row an integer in [0, upto).
 */
function tangentRowsSound(pairs: ArrayLike<number>, upto: number): boolean {
  if (pairs.length % 2 !== 0) return false;
  for (let k = 0; k < pairs.length; k += 2) {
    const row = pairs[k]!;
    if (!(Number.isInteger(row) && row >= 0 && row < upto)) return false;
  }
  return true;
}

export class Reader {
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
      if (t === 'o' && isPlainObject(cur)) {
        this.objectInto(cur, e.v as Record<string, Encoded>, path, keep);
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
    if (t === 'o' && isPlainObject(cur)) {
      if (typeof e.v !== 'object' || e.v === null || Array.isArray(e.v)) throw damaged();
      this.objectInto(cur, e.v as Record<string, Encoded>, path, keep);
      return;
    }
    // Anything else replaces the world's value: decoding it checks it.
    this.fresh(e, path);
  }
  /** The dry run of `tangent`: the note and its rows must be sound, and the normals it reads stored as Float64Arrays long enough. */
  private checkTangent(enc: Record<string, Encoded>, key: string, e: { [key: string]: Encoded }, path: string): void {
    const src = enc[e.axis === 'x' ? 'ny' : 'nx'];
    const upto = e.upto as number;
    if (
      !(
        tangentNoteSound(e) &&
        (e.len as number) <= MAX_ELEMENTS &&
        isTagged(src) &&
        src.$t === 'Float64Array' &&
        (src.len as number) >= upto
      )
    )
      throw new RangeError(`restore: snapshot's ${path}.${key} is damaged`);
    if (e.rows !== undefined) {
      if (!isTagged(e.rows) || e.rows.$t !== 'Float64Array') throw new RangeError(`restore: snapshot's ${path}.${key} is damaged`);
      if (!tangentRowsSound(this.full(e.rows, `${path}.${key}.rows`), upto))
        throw new RangeError(`restore: snapshot's ${path}.${key} is damaged`);
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
    if (!(tangentNoteSound(e) && src instanceof Float64Array && src.length >= upto))
      throw new RangeError(`restore: snapshot's ${path} is damaged`);
    const pairs = e.rows === undefined ? null : isTagged(e.rows) ? this.full(e.rows, `${path}.rows`) : undefined;
    if (pairs === undefined || (pairs !== null && !(pairs instanceof Float64Array && tangentRowsSound(pairs, upto))))
      throw new RangeError(`restore: snapshot's ${path} is damaged`);
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
