import type { Encoded } from './format.js';
import { CONTACT_BUFFERS, SCRATCH, STAMPED, TANGENT_2D, tangentExceptions } from './state-scope.js';
import { iotaFrom1, TYPED, type TypedArray, uniformFrom1, usedLength } from './typed-arrays.js';

/** Encoding a world's state tree into a snapshot: the JSON-able header and one buffer of typed-array contents. */

interface PendingCopy {
  readonly src: TypedArray | readonly number[];
  readonly n: number;
  readonly offset: number;
  readonly type: string;
}

export class Writer {
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
