import { commitRemovals } from 'bitecs';
import { type EcsInternals, ecsOf, type QueryData } from '../world/ecs-internals.js';
import { registerExternalWorldState } from '../world/external-state.js';
import { touchSparseSet } from '../world/lean-ecs.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * Particle archetypes: creating and removing many entities of one fixed component set without
 * bitecs' per-call work, leaving bitecs' data exactly as `addEntity` + `addComponent` and
 * `removeEntity` would (entity index, component masks, each entity's component set, and the
 * membership of every query), so every system, renderer, `query()` and snapshot sees the particles as
 * ordinary entities.
 *
 * Why: bitecs 0.4 checks every `addComponent` against every query of the component, runs the onAdd
 * observers (each call allocates), and `removeEntity` visits every query of the world and allocates
 * its work lists; a particle's birth and death cost about 20 us in a world of ~60 queries. Here an
 * archetype (the component masks of the set, and the list of queries an entity with exactly those
 * masks belongs to) is worked out once, and a birth writes the entity index, the masks and those
 * queries directly: about 0.1 us.
 *
 * A death follows bitecs' deferred removal: the slot is freed at once (the entity no longer exists for
 * `entityExists`, handles and the API) and stays *pending* in its queries' arrays until the next
 * `query()` call commits bitecs' pending removals (the table joins bitecs' dirty queries with a
 * sentinel whose commit takes the pending deaths out), so no system ever iterates a dead particle.
 * The pending deaths are kept here, one mark a slot, rather than in bitecs' per-query removal lists:
 * bitecs empties those with `length = 0`, which frees their storage, so every step would allocate
 * them again. A birth that takes a pending slot of the same archetype keeps its place in every query
 * (bitecs' queryAddEntity rule); bitecs hands out the slot freed last first, so a step whose births
 * follow its deaths before any query (the spawn stage: expiries, their bursts, then the emitters'
 * births) moves nothing in the query arrays. They stay in slot order and the systems' loops walk
 * memory in order (a query in random slot order makes every loop over the particles jump around
 * memory, several times slower); `defragment` restores the order when births and deaths that could not be matched
 * have stirred it.
 *
 * What a fast birth does not do: run bitecs onAdd observers. The component defaults the world's
 * observers write (create-world.ts) are written by the caller instead, and the first entity of every
 * archetype is made through bitecs' ordinary path (observers, lazily allocated stores, dependent
 * components), from which the archetype is read; so is any later one while a store of the archetype
 * has no arrays (a restore can put back a store's unallocated state). Code that needs to act on
 * every particle's birth uses `onParticleBirth` (emitter.ts) rather than a bitecs observer.
 *
 * Component sets: where bitecs keeps a Set of components an entity (`entityComponents` a Map), a
 * particle's set is kept when it dies and given back to the next particle of the same archetype in
 * that slot, so steady churn allocates nothing (a dead slot's stale set is never read: bitecs reads
 * the sets of live entities only). Where the world answers component sets from the masks (no Map),
 * there is nothing to keep.
 */

/**
 * A fixed component set and the queries an entity with exactly that set belongs to.
 * @category Particles
 */
export interface Archetype {
  /** Index in the table's list, 0-based. */
  readonly id: number;
  /** The component stores (bitecs components) of the set. */
  readonly components: readonly object[];
  /** bitecs component mask of the set, one 32-bit word a mask generation. */
  readonly masks: Int32Array;
  /** One typed-array field of each store of the set that has any: the store is allocated when its length exceeds the capacity. */
  readonly probes: ReadonlyArray<readonly [Record<string, ArrayLike<number>>, string]>;
  /** Queries the set matches; recomputed when the world's query count changes. */
  queries: QueryData[];
  /** The world's query count when `queries` was computed. */
  queryCount: number;
  /** The table the archetype belongs to. */
  readonly table: ArchetypeTable;
}

/**
 * Per-world archetype bookkeeping: a cache of bitecs' structure, and how stirred the query lists are.
 * @category Particles
 */
export interface ArchetypeTable {
  /** Every archetype met, by id. */
  readonly list: Archetype[];
  /** Archetype by a caller's key (an emitter's particle kind, bulk particles). */
  readonly byKey: Map<number, Archetype>;
  /**
   * `disorder`: query entries added at a list's end or moved by a removal since the lists were last put
   * in slot order (births that found no pending death of their archetype in their slot, and deaths no
   * birth reused); see `defragment`. It decides when the lists are reordered, so it is world state,
   * kept in snapshots (the only part of the table that is).
   */
  readonly order: { disorder: number };
  /** The world's capacity: the per-slot arrays below get capacity + 1 entries at the first churn (empty until then). */
  readonly capacity: number;
  /** Per slot: id + 1 of the archetype the slot's entity was born with (0: unknown). */
  slotArchetype: Int32Array;
  /** Per slot: the component set left behind by the slot's last fast death, and id + 1 of its archetype. */
  staleSet: Array<Set<object> | undefined>;
  staleArchetype: Int32Array;
  /** Scratch of `defragment`: a mark a slot. */
  marks: Uint8Array;
  /** Per slot: id + 1 of the archetype of a pending death (0: none). */
  pendingMark: Int32Array;
  /** Slots of pending deaths, in death order (entries whose mark a birth cleared are skipped). */
  pending: Int32Array;
  pendingCount: number;
  /** Scratch of `applyQueuedBirths`: the queries done, a flag an archetype, the births with query work. */
  readonly seenQueries: Set<QueryData>;
  archFlags: Uint8Array;
  work: Int32Array;
  /** What bitecs' commitRemovals sees in its dirty queries while deaths pend: its commit calls `settle`. */
  readonly sentinel: { toRemove: { dense: number[]; reset(): void }; remove(e: number): void };
}

// Only `order` is state; the rest is a cache of bitecs' structure that a restored world rebuilds.
registerExternalWorldState({
  name: 'particle-archetypes',
  // A snapshot or restore first commits the pending deaths, as the next query() would.
  get: (world, create) => {
    const t = create ? archetypes(world) : (world.features['particle-archetypes'] as ArchetypeTable | undefined);
    if (t !== undefined) settle(world, t);
    return t;
  },
  clear: (world) => {
    world.features['particle-archetypes'] = undefined;
  },
  keep: [
    'list',
    'byKey',
    'capacity',
    'slotArchetype',
    'staleSet',
    'staleArchetype',
    'marks',
    'pendingMark',
    'pending',
    'pendingCount',
    'sentinel',
    'seenQueries',
    'archFlags',
    'work',
  ],
});

/**
 * The archetype table of `world`, made on first use (small until the first churn: see `capacity`).
 * @category Particles
 */
export function archetypes(world: PhysicsWorld): ArchetypeTable {
  let t = world.features['particle-archetypes'] as ArchetypeTable | undefined;
  if (t === undefined) {
    typedMasks(world);
    const none = new Int32Array(0);
    const table: ArchetypeTable = {
      list: [],
      byKey: new Map(),
      order: { disorder: 0 },
      capacity: world.capacity,
      slotArchetype: none,
      staleSet: [],
      staleArchetype: none,
      marks: new Uint8Array(0),
      pendingMark: none,
      pending: none,
      pendingCount: 0,
      seenQueries: new Set(),
      archFlags: new Uint8Array(0),
      work: new Int32Array(0),
      sentinel: { toRemove: { dense: [], reset: () => settle(world, table) }, remove: () => {} },
    };
    t = table;
    world.features['particle-archetypes'] = t;
  }
  return t;
}

/**
 * Where the world keeps its first generation of component masks in an Int32Array (lean storage,
 * world/lean-ecs.ts), the other generations get one too: bitecs grows them as JS arrays written at scattered
 * slots, which V8 may keep as a dictionary, and a particle's own components can sit in any
 * generation (bits follow registration order). Same values; every reader (bitecs, snapshots) indexes them.
 */
function typedMasks(world: PhysicsWorld): void {
  const ecs = ecsOf(world);
  const em = ecs.entityMasks as Array<number[] | Int32Array>;
  if (!(em[0] instanceof Int32Array)) return;
  const n = world.capacity + 1;
  for (let g = 1; g < em.length; g++) {
    const m = em[g]!;
    if (m instanceof Int32Array || m.length > n) continue;
    const t = new Int32Array(n);
    for (let e = 0; e < m.length; e++) t[e] = m[e] ?? 0;
    em[g] = t;
  }
}

/** Allocates the per-slot arrays of `table` (once). */
function slotArrays(table: ArchetypeTable): void {
  if (table.slotArchetype.length !== 0) return;
  const n = table.capacity + 1;
  table.slotArchetype = new Int32Array(n);
  table.staleArchetype = new Int32Array(n);
  table.marks = new Uint8Array(n);
  table.pendingMark = new Int32Array(n);
  table.pending = new Int32Array(n);
}

function matchesMasks(q: QueryData, masks: Int32Array): boolean {
  let orMatch = true;
  for (const _ in q.orMasks) {
    orMatch = false;
    break;
  }
  const gens = q.generations;
  for (let i = 0; i < gens.length; i++) {
    const g = gens[i]!;
    const m = g < masks.length ? masks[g]! : 0;
    const qm = q.masks[g],
      qn = q.notMasks[g],
      qo = q.orMasks[g];
    if (qn && (m & qn) !== 0) return false;
    if (qm && (m & qm) !== qm) return false;
    if (qo && (m & qo) !== 0) orMatch = true;
  }
  return orMatch;
}

function refreshQueries(ecs: EcsInternals, a: Archetype): void {
  const list: QueryData[] = [];
  for (const q of ecs.queries) if (matchesMasks(q, a.masks)) list.push(q);
  a.queries = list;
  a.queryCount = ecs.queries.size;
}

/** The archetype of component masks `masks` (one word a generation), registered on first use. */
function archetypeOfMasks(ecs: EcsInternals, table: ArchetypeTable, masks: Int32Array): Archetype {
  for (let i = 0; i < table.list.length; i++) if (sameMasks(table.list[i]!.masks, masks)) return table.list[i]!;
  const components: object[] = [];
  for (const d of ecs.componentMap.values()) {
    if (d.generationId < masks.length && (masks[d.generationId]! & d.bitflag) === d.bitflag) components.push(d.ref);
  }
  const probes: Array<readonly [Record<string, ArrayLike<number>>, string]> = [];
  for (const store of components as Array<Record<string, ArrayLike<number>>>) {
    const key = Object.keys(store).find((k) => ArrayBuffer.isView(store[k]));
    if (key !== undefined) probes.push([store, key]);
  }
  const a: Archetype = { id: table.list.length, components, masks: masks.slice(), probes, queries: [], queryCount: -1, table };
  refreshQueries(ecs, a);
  table.list.push(a);
  return a;
}

function masksOf(ecs: EcsInternals, slot: number): Int32Array {
  const gens = ecs.entityMasks.length;
  const masks = new Int32Array(gens);
  for (let g = 0; g < gens; g++) masks[g] = ecs.entityMasks[g]![slot] ?? 0;
  return masks;
}

/**
 * id + 1 of the archetype of a death pending in `slot` (0: none): pass to `archetypeFromEntity` before bitecs creates an entity there.
 * @category Particles
 */
export function pendingArchetype(table: ArchetypeTable, slot: number): number {
  return slot < table.pendingMark.length ? table.pendingMark[slot]! : 0;
}

/**
 * Registers the component set of the live entity in `slot`, just made through bitecs' ordinary path,
 * as the archetype under `key`. bitecs may have handed out a slot whose death is pending (`pending`:
 * from `pendingArchetype` before the entity was made): bitecs keeps the slot's place in the queries
 * its new components match; here it leaves the others, and the birth's disorder is counted, exactly
 * as `bornSlot` would, so the state does not depend on which path made the entity.
 * @category Particles
 */
export function archetypeFromEntity(world: PhysicsWorld, table: ArchetypeTable, key: number, slot: number, pending: number): Archetype {
  const ecs = ecsOf(world);
  const a = archetypeOfMasks(ecs, table, masksOf(ecs, slot));
  if (a.queryCount !== ecs.queries.size) refreshQueries(ecs, a);
  table.byKey.set(key, a);
  const mark = a.id + 1;
  // The per-slot arrays exist once anything churned (bulk creation alone never needs them).
  if (table.slotArchetype.length !== 0) {
    table.slotArchetype[slot] = mark;
    if (pending !== 0 && pending !== mark) leaveOthers(table.list[pending - 1]!, a, slot);
    table.pendingMark[slot] = 0;
  }
  countBirth(table, pending === mark);
  if (ecs.entityComponents instanceof Map) {
    table.staleSet[slot] = ecs.entityComponents.get(slot);
    table.staleArchetype[slot] = mark;
  }
  return a;
}

/** A slot pending as `old` reborn as `a`: out of the queries of `old` that `a` does not match. */
function leaveOthers(old: Archetype, a: Archetype, e: number): void {
  const qs = old.queries;
  for (let i = 0; i < qs.length; i++) if (!matchesMasks(qs[i]!, a.masks)) qs[i]!.remove(e);
}

/**
 * The query work of `n` births made with `bornSlotQueued`, in birth order for each query: slot
 * `slots[k]` of archetype id + 1 `marks[k]`, whose slot was pending as `pends[k]` (0: not pending).
 * For each query, the births' operations on it come in the order `bornSlot` would have made them (a
 * birth in a pending slot of another archetype leaves that archetype's queries it does not match;
 * one not in place joins its own archetype's queries, or leaves bitecs' pending removals of one
 * that still lists the slot), and queries are independent of each other, so the lists end as
 * `bornSlot` one birth at a time leaves them. Done one query at a time: the births of a step land in
 * slots scattered over the capacity, and taking each query's arrays in turn keeps the memory pages in
 * use few (see emitter.ts `flushBirths`).
 * @category Particles
 */
export function applyQueuedBirths(table: ArchetypeTable, slots: Int32Array, marks: Int32Array, pends: Int32Array, n: number): void {
  const list = table.list;
  // Births not in place, and rebirths over another archetype's pending death: the only ones with query work.
  if (table.work.length < n) table.work = new Int32Array(Math.max(n, 2 * table.work.length));
  const list2 = table.work;
  let work = 0,
    leaving = 0;
  for (let k = 0; k < n; k++) {
    const p = pends[k]!,
      m = marks[k]!;
    if (p !== m) {
      list2[work++] = k;
      if (p !== 0) leaving++;
    }
  }
  if (work === 0) return;
  // The archetypes involved (1: born not in place, 2: a pending death of it reborn as another).
  if (table.archFlags.length < 2 * list.length) table.archFlags = new Uint8Array(4 * list.length);
  const flags = table.archFlags;
  flags.fill(0, 0, list.length);
  for (let w = 0; w < work; w++) {
    const k = list2[w]!,
      p = pends[k]!,
      m = marks[k]!;
    flags[m - 1]! |= 1;
    if (p !== 0) flags[p - 1]! |= 2;
  }
  const seen = table.seenQueries;
  seen.clear();
  for (let i = 0; i < list.length; i++) {
    if (flags[i] === 0) continue;
    const qs = list[i]!.queries;
    for (let j = 0; j < qs.length; j++) {
      const q = qs[j]!;
      if (seen.has(q)) continue;
      seen.add(q);
      // Per archetype: 1 if it belongs to q, 2 if its masks match q (what leaveOthers asks).
      for (let b = 0; b < list.length; b++)
        flags[list.length + b] = (list[b]!.queries.includes(q) ? 1 : 0) | (leaving > 0 && matchesMasks(q, list[b]!.masks) ? 2 : 0);
      applyToQuery(flags, list.length, q, slots, marks, pends, list2, work, leaving > 0);
    }
  }
  seen.clear();
}

/**
 * `applyQueuedBirths` for one query `q`, over the births `work[0..n-1]` (indices of those with query
 * work, in birth order). `flags[o + i]` says of archetype id i: 1 it belongs to q, 2 its masks match q
 * (computed only when `leaving`: some birth took another archetype's pending slot).
 */
function applyToQuery(
  flags: Uint8Array,
  o: number,
  q: QueryData,
  slots: Int32Array,
  marks: Int32Array,
  pends: Int32Array,
  work: Int32Array,
  n: number,
  leaving: boolean,
): void {
  const r = q.toRemove;
  for (let w = 0; w < n; w++) {
    const k = work[w]!,
      p = pends[k]!,
      m = marks[k]!;
    const e = slots[k]!;
    const f = flags[o + m - 1]!;
    if (leaving && p !== 0 && (f & 2) === 0) {
      // leaveOthers: out of the old archetype's queries that the new one does not match.
      if ((flags[o + p - 1]! & 1) !== 0) q.remove(e);
      continue;
    }
    if ((f & 1) === 0) continue;
    if (r.dense.length !== 0 && r.has(e)) r.remove(e);
    else q.add(e);
  }
}

function countBirth(table: ArchetypeTable, inPlace: boolean): void {
  const o = table.order;
  if (!inPlace) o.disorder++;
  else if (o.disorder > 0) o.disorder--;
}

function sameMasks(a: Int32Array, b: Int32Array): boolean {
  const n = Math.max(a.length, b.length);
  for (let g = 0; g < n; g++) if ((a[g] ?? 0) !== (b[g] ?? 0)) return false;
  return true;
}

/**
 * Before a batch of births into archetype `a`: its query list follows new queries.
 * @returns false if a store of the archetype has no arrays (never allocated, or put back so by a
 *   restore): the next particle must then be made through bitecs, whose observers allocate it.
 * @category Particles
 */
export function prepareArchetype(world: PhysicsWorld, a: Archetype): boolean {
  const ecs = ecsOf(world);
  for (let i = 0; i < a.probes.length; i++) {
    const probe = a.probes[i]!;
    if (probe[0][probe[1]]!.length <= world.capacity) return false;
  }
  if (a.queryCount !== ecs.queries.size) refreshQueries(ecs, a);
  return true;
}

/**
 * Creates an entity of archetype `a` (call `prepareArchetype` first in the batch; the world must have
 * room) and counts its life in `world.spawnStamp`. Writes no component data: the caller writes every
 * field of every component of the set. @returns its slot.
 * @category Particles
 */
export function bornSlot(world: PhysicsWorld, a: Archetype): number {
  return born(world, a, false);
}

/**
 * `bornSlot` whose query work is left to `applyQueuedBirths`: the entity exists (entity index, masks,
 * component set, spawn stamp) and `queuedPending` holds the slot's pending mark (`pendingArchetype`)
 * from before the birth, which the caller keeps with the slot and passes to `applyQueuedBirths`
 * before anything reads the queries. @returns its slot.
 * @category Particles
 */
export function bornSlotQueued(world: PhysicsWorld, a: Archetype): number {
  return born(world, a, true);
}

/** The pending mark of the slot `bornSlotQueued` returned last (0: none). */
export let queuedPending = 0;

/**
 * Takes the slot bitecs hands out next (the slot freed last, else a new one) into the entity index as
 * alive, and raises its spawn stamp (world.spawnStamp) by one. @returns the slot.
 */
function takeSlot(ix: EcsInternals['entityIndex'], spawn: Uint32Array): number {
  const alive = ix.aliveCount;
  let e: number;
  if (alive < ix.dense.length) e = ix.dense[alive]!;
  else {
    e = ++ix.maxId;
    ix.dense.push(e);
  }
  ix.sparse[e] = alive;
  ix.aliveCount = alive + 1;
  spawn[e] = spawn[e]! + 1;
  return e;
}

function born(world: PhysicsWorld, a: Archetype, queued: boolean): number {
  const table = a.table,
    ecs = ecsOf(world);
  if (table.slotArchetype.length === 0) slotArrays(table);
  // A hook between births may have made a query.
  if (a.queryCount !== ecs.queries.size) refreshQueries(ecs, a);
  const e = takeSlot(ecs.entityIndex, world.spawnStamp);
  const masks = a.masks,
    em = ecs.entityMasks;
  for (let g = 0; g < masks.length; g++) em[g]![e] = masks[g]!;
  const mark = a.id + 1;
  // Component set (where bitecs keeps Sets): the one this slot's last particle of the same archetype left, if untouched since.
  const sets = ecs.entityComponents;
  if (sets instanceof Map) {
    const set = sets.get(e);
    if (set === undefined || set !== table.staleSet[e] || table.staleArchetype[e] !== mark) {
      const s = set ?? new Set<object>();
      s.clear();
      const cs = a.components;
      for (let i = 0; i < cs.length; i++) s.add(cs[i]!);
      if (s !== set) sets.set(e, s);
      table.staleSet[e] = s;
      table.staleArchetype[e] = mark;
    }
  }
  table.slotArchetype[e] = mark;
  // Queries: where the slot is still pending removal it keeps its place (bitecs' queryAddEntity).
  // A pending death of the same archetype in this slot keeps its place in every query; another
  // archetype's keeps it in the queries both match.
  const pend = table.pendingMark[e]!;
  const inPlace = pend === mark;
  if (queued) {
    queuedPending = pend;
    if (pend !== 0) table.pendingMark[e] = 0;
    countBirth(table, inPlace);
    return e;
  }
  if (pend !== 0) {
    table.pendingMark[e] = 0;
    if (!inPlace) leaveOthers(table.list[pend - 1]!, a, e);
  }
  if (!inPlace) {
    const qs = a.queries;
    for (let i = 0; i < qs.length; i++) {
      const q = qs[i]!,
        r = q.toRemove;
      // A slot bitecs itself freed and still lists as pending keeps its place too (queryAddEntity).
      if (r.dense.length !== 0 && r.has(e)) r.remove(e);
      else q.add(e);
    }
  }
  countBirth(table, inPlace);
  return e;
}

/**
 * Removes the live entity in `slot` (any component set; its archetype is registered on first use)
 * as bitecs' removeEntity would, without its per-call work: frees the slot, clears its masks, and
 * leaves it pending in its queries until the next `query()` (see `settle`). The caller has run the
 * removal hooks. @returns false (nothing done) for an entity with bitecs relations: remove
 * it with bitecs' removeEntity.
 * @category Particles
 */
export function killSlot(world: PhysicsWorld, ecs: EcsInternals, table: ArchetypeTable, e: number): boolean {
  if (ecs.entitiesWithRelations.size !== 0 && ecs.entitiesWithRelations.has(e)) return false;
  if (table.slotArchetype.length === 0) slotArrays(table);
  const em = ecs.entityMasks;
  let mark = table.slotArchetype[e]!;
  let a = mark > 0 ? table.list[mark - 1] : undefined;
  if (a === undefined || !hasMasks(em, e, a.masks)) {
    // Any component set works (a user may have changed the particle's): its archetype is made once.
    a = archetypeOfMasks(ecs, table, masksOf(ecs, e));
    mark = a.id + 1;
  }
  if (a.queryCount !== ecs.queries.size) refreshQueries(ecs, a);
  if (ecs.entityComponents instanceof Map) {
    table.staleSet[e] = ecs.entityComponents.get(e);
    table.staleArchetype[e] = mark;
  }
  if (table.pendingCount === table.pending.length) settle(world, table);
  if (table.pendingCount === 0) ecs.dirtyQueries.add(table.sentinel as never);
  table.pendingMark[e] = mark;
  table.pending[table.pendingCount++] = e;
  const ix = ecs.entityIndex;
  const at = ix.sparse[e]!,
    last = ix.aliveCount - 1,
    lastId = ix.dense[last]!;
  ix.sparse[lastId] = at;
  ix.dense[at] = lastId;
  ix.sparse[e] = last;
  ix.dense[last] = e;
  ix.aliveCount = last;
  for (let g = 0; g < em.length; g++) em[g]![e] = 0;
  table.order.disorder++;
  return true;
}

function hasMasks(em: number[][], e: number, masks: Int32Array): boolean {
  for (let g = 0; g < em.length; g++) if ((em[g]![e] ?? 0) !== (g < masks.length ? masks[g]! : 0)) return false;
  return true;
}

/**
 * Commits the pending deaths: each slot no birth reused leaves the queries of its archetype (bitecs'
 * commitRemovals calls this through the sentinel, at the next `query()`; a snapshot or restore calls
 * it first).
 * @category Particles
 */
export function settle(world: PhysicsWorld, table: ArchetypeTable): void {
  if (table.pendingCount === 0) return;
  const list = table.list,
    mark = table.pendingMark,
    pending = table.pending;
  for (let k = 0; k < table.pendingCount; k++) {
    const e = pending[k]!;
    const m = mark[e]!;
    if (m === 0) continue;
    mark[e] = 0;
    const qs = list[m - 1]!.queries;
    for (let i = 0; i < qs.length; i++) qs[i]!.remove(e);
  }
  table.pendingCount = 0;
  ecsOf(world).dirtyQueries.delete(table.sentinel as never);
}

/**
 * Puts the query lists of every archetype back in slot order once births and deaths that could not be
 * matched in place (see `disorder`) reach 1/32 of the live entities (at least 256): systems then walk
 * the component arrays in memory order, which in a world of 50,000 particles is about five times
 * faster than in the random order churn leaves. A list is rewritten in place in O(capacity) (a mark
 * a member, then one pass over the slots), or by sorting a copy when it is small. The order of a
 * query is part of the world's state (snapshots keep it), and this runs at a fixed point of the step,
 * so it is as deterministic as the rest.
 * @category Particles
 */
export function defragment(world: PhysicsWorld, table: ArchetypeTable): void {
  const alive = world.entityIndex.aliveCount;
  const order = table.order;
  if (order.disorder < 1024 || order.disorder * 8 < alive) return;
  order.disorder = 0;
  slotArrays(table);
  // Pending removals first (what the next query() would do), so the lists sorted are the final ones.
  commitRemovals(world as never);
  const ecs = ecsOf(world);
  const maxId = ecs.entityIndex.maxId;
  const seen = new Set<QueryData>();
  for (const a of table.list) {
    for (const q of a.queries) {
      if (seen.has(q)) continue;
      seen.add(q);
      sortQuery(q, table.marks, maxId);
    }
  }
}

function sortQuery(q: QueryData, marks: Uint8Array, maxId: number): void {
  const dense = q.dense,
    sparse = q.sparse,
    n = dense.length;
  let sorted = true;
  for (let i = 1; i < n; i++)
    if (dense[i]! < dense[i - 1]!) {
      sorted = false;
      break;
    }
  if (sorted) return;
  touchSparseSet(q); // written directly below: snapshots must not take it for unchanged
  if (n * 8 < maxId) {
    const copy = Int32Array.from(dense).sort();
    for (let i = 0; i < n; i++) {
      const e = copy[i]!;
      dense[i] = e;
      sparse[e] = i;
    }
    return;
  }
  for (let i = 0; i < n; i++) marks[dense[i]!] = 1;
  let j = 0;
  for (let e = 1; e <= maxId; e++) {
    if (marks[e] === 1) {
      marks[e] = 0;
      dense[j] = e;
      sparse[e] = j;
      j++;
    }
  }
}

/**
 * Creates `count` entities of archetype `a` (call `prepareArchetype` first; the world must have room),
 * writing their slots into `out` in the
 * order bitecs would hand them out. `bornSlot` without the churn bookkeeping, for bulk creation, one
 * array at a time (entity index, each mask generation, each query). Writes no component data.
 * @category Particles
 */
export function bornSlots(world: PhysicsWorld, a: Archetype, count: number, out: Int32Array): void {
  const ecs = ecsOf(world);
  const ix = ecs.entityIndex,
    spawn = world.spawnStamp;
  for (let k = 0; k < count; k++) out[k] = takeSlot(ix, spawn);
  // A free slot's masks are 0 (removal clears them), so generations the archetype has no bit in need no writes.
  const masks = a.masks;
  for (let g = 0; g < masks.length; g++) {
    const em = ecs.entityMasks[g]!,
      m = masks[g]!;
    if (m !== 0) for (let k = 0; k < count; k++) em[out[k]!] = m;
  }
  const qs = a.queries;
  for (let i = 0; i < qs.length; i++) {
    const q = qs[i]!;
    // A slot still pending removal keeps its place (bitecs' queryAddEntity); the set's own add for the
    // first new member (it may allocate its sparse array), then its arrays directly.
    const r = q.toRemove;
    let k = 0;
    for (; k < count; k++) {
      const e = out[k]!;
      if (r.has(e)) {
        r.remove(e);
        continue;
      }
      q.add(e);
      break;
    }
    const dense = q.dense,
      sparse = q.sparse;
    const pending = r.dense.length > 0;
    for (k++; k < count; k++) {
      const e = out[k]!;
      if (pending && r.has(e)) {
        r.remove(e);
        continue;
      }
      if (dense[sparse[e]!] !== e) sparse[e] = dense.push(e) - 1;
    }
    touchSparseSet(q); // written directly above: snapshots must not take it for unchanged
  }
  if (ecs.entityComponents instanceof Map) {
    const sets = ecs.entityComponents;
    for (let k = 0; k < count; k++) sets.set(out[k]!, new Set(a.components));
  }
}
