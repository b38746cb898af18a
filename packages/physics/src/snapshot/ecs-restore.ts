import { query as bitecsQuery, Not, Or, registerComponent } from 'bitecs';
import { describe } from '../validation/validate.js';
import { assignSparseSet, hasMaskComponentSets } from '../world/lean-ecs.js';
import type { PhysicsWorld } from '../world/options.js';
import type { QueryTwin } from '../world/scratch.js';
import {
  bitIndex,
  type ComponentData,
  checkRange,
  describeKeyed,
  type EcsInternals,
  internals,
  keyOf,
  matching,
  namesOf,
  newMatching,
  type QueryData,
  readIdLists,
  type SparseSetLike,
  sameAsStored,
  versionOf,
} from './ecs-capture.js';
import type { Encoded } from './format.js';
import { isTagged, type Reader } from './reader.js';
import { sameFrom1Native, zeroFill } from './typed-arrays.js';

/** Reads an id list encoded by IdLists. @throws RangeError `restore: snapshot's <path> is damaged`. */
export function idList(e: Encoded, lists: readonly Int32Array[], path: string): Int32Array {
  const t = isTagged(e) ? e.$t : undefined;
  if (t === 'ids') return new Int32Array(0);
  const list = t === 'same' ? lists[(e as Record<string, Encoded>).i as number] : undefined;
  if (list === undefined) throw new RangeError(`restore: snapshot's ${path} is damaged`);
  return list;
}

/**
 * Writes the stored ECS state `ecs` (component layout, masks, entity index, queries) into `world`
 * from reader `r`; `oldMaxId` is the world's highest entity id before the restore.
 * @throws RangeError on a damaged snapshot or one with a component this world does not have.
 */
export function restoreEcs(world: PhysicsWorld, ecs: Record<string, Encoded>, r: Reader, oldMaxId: number): void {
  const ctx = internals(world);
  const lists = readIdLists(ecs.lists as Encoded[], r, world.capacity);
  const { map, same } = componentLayout(world, ctx, ecs);
  const byKey = snapshotQueries(world, ctx, ecs);
  const maxId = ecs.maxId as number;
  restoreMasks(ctx, ecs, r, map, same, Math.max(maxId, oldMaxId) + 1);
  restoreEntityIndex(world, ctx, ecs, lists);
  restoreQueries(ctx, ecs, lists, byKey, ecs.aliveCount as number, world.scratch.queryTwins);
}

/** One snapshot component's bit (generation `sg`, bit `sbit`) and the target world's (generation `tg`, flag `tflag`). */
interface BitMap {
  sg: number;
  sbit: number;
  tg: number;
  tflag: number;
}

/**
 * The target's bit of each snapshot component (registering components the target has not seen), and
 * whether every bit is the same in both.
 */
function componentLayout(world: PhysicsWorld, ctx: EcsInternals, ecs: Record<string, Encoded>): { map: BitMap[]; same: boolean } {
  const C = world.components as unknown as Record<string, object>;
  const layout = ecs.layout as [string, number, number][];
  let same = true;
  const map: BitMap[] = [];
  for (const [name, sg, sbit] of layout) {
    const comp = C[name];
    if (comp === undefined) throw new RangeError(`restore: snapshot has component '${name}', which this world does not`);
    const data = ctx.componentMap.get(comp) ?? (registerComponent(world as never, comp) as unknown as ComponentData);
    if (data.generationId !== sg || bitIndex(data.bitflag) !== sbit) same = false;
    map.push({ sg, sbit, tg: data.generationId, tflag: data.bitflag });
  }
  return { map, same };
}

/**
 * The world's queries by key, with the snapshot's queries this world lacks made now, before its masks
 * and entity index change: bitecs fills a new query by testing every live entity (about 0.5 s for
 * 100,000 entities and the 40-odd queries of a world that has not stepped yet), and these lists are
 * overwritten by restoreQueries anyway.
 */
function snapshotQueries(world: PhysicsWorld, ctx: EcsInternals, ecs: Record<string, Encoded>): Map<string, QueryData> {
  const C = world.components as unknown as Record<string, object>;
  const names = namesOf(world);
  const byKey = new Map<string, QueryData>();
  for (const q of ctx.queries) {
    const { d, key } = describeKeyed(world, q, names);
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
      const dx = describeKeyed(world, x, names);
      return dx.d !== null && dx.key === key;
    });
    if (q === undefined) throw new Error(`restore: could not make the query ${key}`);
    byKey.set(key, q);
  }
  return byKey;
}

/**
 * The component masks, written in place for ids below `top` (the larger of the two highest ids, plus
 * one; ids above both are 0). The stored masks are views into the snapshot, checked before anything is
 * written; a repeated value is expanded only where the layouts differ (else written straight into the
 * world's masks).
 */
function restoreMasks(
  ctx: EcsInternals,
  ecs: Record<string, Encoded>,
  r: Reader,
  map: readonly BitMap[],
  same: boolean,
  top: number,
): void {
  const maskEnc = (ecs.masks as Encoded[]).map((m) => m as Record<string, Encoded>);
  const maskViews = maskEnc.map((m, g) => r.array(m, `masks[${g}]`) as Int32Array);
  const gens = ctx.entityMasks.length;
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
    return;
  }
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

/**
 * The entity index (written in place: its arrays stay packed) and, in a world not made by
 * createPhysicsWorld, the entities' component sets rebuilt from the masks.
 */
function restoreEntityIndex(world: PhysicsWorld, ctx: EcsInternals, ecs: Record<string, Encoded>, lists: readonly Int32Array[]): void {
  const ix = ctx.entityIndex;
  const dense = idList(ecs.dense!, lists, 'ecs.dense');
  const aliveCount = ecs.aliveCount as number;
  // Unchanged (a rewind without births or deaths): its sparse array, kept in step with it, is too.
  if (!sameAsStored(ix.dense, dense)) {
    writeInPlace(ix.dense, dense, dense.length);
    const sparse = ix.sparse;
    for (let i = 0; i < dense.length; i++) sparse[dense[i]!] = i;
  }
  ix.aliveCount = aliveCount;
  ix.maxId = ecs.maxId as number;
  if (hasMaskComponentSets(world)) return;
  const gens = ctx.entityMasks.length;
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

/**
 * The queries: the snapshot's in their order (each made by snapshotQueries, in `byKey`); any other
 * query of this world is rebuilt in entity order over the first `aliveCount` entities. `twins`: the
 * world's query sets (lean storage, with versions) known to hold the same ids in the same order as
 * another set of it, `peer`, while their versions are still `version` and `peerVersion`
 * (`world.scratch.queryTwins`), written here when both were given one stored list: a world restored
 * again and again from snapshots of another (a replica) then compares each list with one set only,
 * not with every query holding it.
 */
function restoreQueries(
  ctx: EcsInternals,
  ecs: Record<string, Encoded>,
  lists: readonly Int32Array[],
  byKey: ReadonlyMap<string, QueryData>,
  aliveCount: number,
  twins: Map<object, QueryTwin>,
): void {
  const ix = ctx.entityIndex;
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
export function unusedStores(world: PhysicsWorld): Set<object> {
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
 * Checks the ECS part of a snapshot before restoreEcs writes it: every id list sound and within the
 * capacity, the entity index (alive count, highest id, its id list: each id from 1 to the highest
 * once), the component layout (names of this world's components, generations and bits in range),
 * the masks, and the queries (names of this world's components, id lists that exist).
 * @throws RangeError `restore: snapshot's ecs... is damaged` (or names the component this world lacks).
 */
export function checkEcs(world: PhysicsWorld, ecs: Record<string, Encoded>, r: Reader): void {
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
