import { $internal } from 'bitecs';
import type { PhysicsWorld } from '../world/options.js';
import type { ListMemo, QueryDescriptor } from '../world/scratch.js';
import type { Encoded } from './format.js';
import type { Reader } from './reader.js';
import { countingTo } from './typed-arrays.js';
import type { Writer } from './writer.js';

/** Capturing bitecs' state for a snapshot: the entity index, each entity's components, and the order of every query's entities. */

// --- bitecs internals (0.4): the entity index, component masks, entity component sets, queries. ---

export interface SparseSetLike {
  dense: ArrayLike<number>;
  add(v: number): void;
  reset(): void;
  has(v: number): boolean;
}
export interface QueryData extends SparseSetLike {
  allComponents: object[];
  notComponents: object[];
  orComponents: object[];
  toRemove: SparseSetLike;
}
export interface ComponentData {
  generationId: number;
  bitflag: number;
  ref: object;
}
export interface EcsInternals {
  entityIndex: { aliveCount: number; dense: number[]; sparse: number[] | Int32Array; maxId: number; versioning: boolean };
  entityMasks: (number[] | Int32Array)[];
  entityComponents: Map<number, Set<object>>;
  componentMap: Map<object, ComponentData>;
  queries: Set<QueryData>;
  dirtyQueries: Set<QueryData>;
}
export function internals(world: PhysicsWorld): EcsInternals {
  return (world as unknown as Record<symbol, EcsInternals>)[$internal]!;
}

/** The world's component stores by name (`world.scratch.componentNames`). */
export function namesOf(world: PhysicsWorld): Map<object, string> {
  // The map is kept while world.components holds the same stores under the same names, so query
  // descriptors computed from it stay valid (see describeKeyed).
  const entries = Object.entries(world.components);
  const last = world.scratch.componentNames;
  if (last !== undefined && last.size === entries.length && entries.every(([name, store]) => last.get(store as object) === name))
    return last;
  const names = new Map<object, string>();
  for (const [name, store] of entries) names.set(store as object, name);
  world.scratch.componentNames = names;
  return names;
}

/**
 * `describeQuery` of `q`, one of `world`'s queries, and its `keyOf` (key '' when null), computed once
 * per query and name map (see `namesOf`): kept in `world.scratch.queryKeys` with the name map they were
 * computed from (a query's components never change; the names of world.components could, so a new map
 * recomputes).
 */
export function describeKeyed(world: PhysicsWorld, q: QueryData, names: Map<object, string>): { d: QueryDescriptor; key: string } {
  const described = world.scratch.queryKeys;
  let c = described.get(q);
  if (c === undefined || c.names !== names) {
    const d = describeQuery(q, names);
    c = { names, d, key: d === null ? '' : keyOf(d) };
    described.set(q, c);
  }
  return c;
}

/** Query descriptor: its component names (and, not, or), or null if it involves a component outside world.components. */
function describeQuery(q: QueryData, names: Map<object, string>): QueryDescriptor {
  const name = (c: object) => names.get(c);
  const not = q.notComponents.map(name),
    or = q.orComponents.map(name);
  const and = q.allComponents.filter((c) => !q.notComponents.includes(c) && !q.orComponents.includes(c)).map(name);
  if ([...and, ...not, ...or].some((n) => n === undefined)) return null;
  return { and: (and as string[]).sort(), not: (not as string[]).sort(), or: (or as string[]).sort() };
}
export const keyOf = (d: { and: string[]; not: string[]; or: string[] }) => `${d.and.join(',')}|${d.not.join(',')}|${d.or.join(',')}`;

function toInt32(a: ArrayLike<number>): Int32Array {
  if (a instanceof Int32Array) return a;
  const out = new Int32Array(a.length);
  for (let i = 0; i < a.length; i++) out[i] = a[i]!;
  return out;
}

export function bitIndex(bitflag: number): number {
  return 31 - Math.clz32(bitflag);
}

/**
 * Whether two id lists hold the same ids in the same order. Two copies, each with one pair of array
 * kinds, so the element reads stay monomorphic (a shared one mixing JS and typed arrays would read
 * them through a slow generic path); four ids a step, XOR-ed and OR-ed (ids are small integers).
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
export function sameAsStored(a: readonly number[], b: Int32Array): boolean {
  const n = a.length;
  if (n !== b.length) return false;
  let i = 0;
  for (; i + 4 <= n; i += 4)
    if (((a[i]! ^ b[i]!) | (a[i + 1]! ^ b[i + 1]!) | (a[i + 2]! ^ b[i + 2]!) | (a[i + 3]! ^ b[i + 3]!)) !== 0) return false;
  for (; i < n; i++) if (a[i] !== b[i]) return false;
  return true;
}

/**
 * Encodes bitecs id lists, each once: a list equal to one encoded before (most queries hold the same
 * entities in the same order) becomes a reference `{ $t: 'same', i }` to that one's position in `lists`.
 * Finding that costs a comparison of the two lists, except where neither set has changed (same
 * version and length, world/lean-ecs.ts) since the world's last snapshot found them equal (what it
 * found: `world.scratch.listMemos`).
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
    this.memos = world.scratch.listMemos;
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
export function readIdLists(encoded: readonly Encoded[], r: Reader, capacity: number): Int32Array[] {
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
export function checkRange(e: Record<string, Encoded>, i: number, capacity: number): void {
  const first = e.first as number,
    n = e.n as number;
  if (!(Number.isInteger(first) && Number.isInteger(n) && first >= 1 && n >= 1 && first + n - 1 <= capacity)) {
    throw new RangeError(`restore: snapshot's ecs.lists[${i}] is damaged`);
  }
}

export function captureEcs(world: PhysicsWorld, w: Writer): Encoded {
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
    const d = describeKeyed(world, q, names).d;
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

/** Restoring bitecs' state from a snapshot into a world: entity index, component masks and query order, leaving unchanged lists alone. */

// `matching` is a WeakMap: keyed by a snapshot, which the caller holds (and may restore into any world); an entry goes with its snapshot.
/**
 * For the ECS part of a snapshot (by object identity, so a cloned or parsed snapshot has none): the
 * version (world/lean-ecs.ts) each query set of a world had when its members were known to equal the
 * snapshot's list for it, recorded when the snapshot was taken and when a restore wrote the list.
 * A set whose version is still that one has not changed since: restoring the snapshot again (a
 * rewind, a rollback) need not compare or write it.
 */
export const matching = new WeakMap<object, WeakMap<object, number>>();
export function newMatching(ecs: object): WeakMap<object, number> {
  const m = new WeakMap<object, number>();
  matching.set(ecs, m);
  return m;
}
export function versionOf(set: object): number | undefined {
  return (set as { version?: number }).version;
}
