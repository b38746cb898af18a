import { $internal, query as bitecsQuery, Prefab, type QueryResult } from 'bitecs';

/**
 * bitecs' bookkeeping per entity made lean, for worlds of a million particles.
 *
 * 1. Component sets derived from the component masks instead of stored.
 * bitecs 0.4 keeps, beside each entity's component bit mask, a `Set` of its components in a `Map`
 * keyed by entity id (`entityComponents`): about 180 bytes an entity, more than the Position and
 * Velocity of a bare particle together. The masks already say which components an entity has, so
 * `useMaskComponentSets` replaces that map with a view that answers from the masks: bitecs' own
 * writes to it (`set` on addEntity, `add` / `delete` on addComponent / removeComponent, `delete` on
 * removeEntity) come after its mask updates and are no-ops here, and its reads (`getEntityComponents`,
 * relation cleanup on removeEntity, `getAllEntities`) list the components whose bit is set, in the
 * order the components were registered with the world, and the live ids of the entity index.
 * Nothing is allocated per entity or per call except by iteration (`getEntityComponents` returns a
 * new array, as bitecs' does).
 *
 * 2. Fixed typed arrays where bitecs grows JS arrays indexed by entity id: the entity index's `sparse`
 * (id -> position in `dense`), every generation of component masks (31 components each; the core
 * stores fill the first two, later ones are typed as bitecs adds them), and each query's `sparse` (and
 * its pending removals'), all Int32Array of capacity + 1. A JS
 * array of a million small integers costs about 10.5 bytes an element once grown by pushes; the typed
 * one 4; bitecs' removeEntity writes every generation's entry of a removed id, so a JS generation
 * grows to the highest id anyway, and one written at scattered ids may be kept as a dictionary (and
 * snapshots had to convert it each time). The dense lists stay JS arrays (queries hand them to
 * systems; bitecs pushes onto them).
 *
 * 3. Each query's add and remove observables notify without allocating while nothing listens
 * (`leanObservable`).
 *
 * 4. A query made while entities exist is filled by one loop over the typed masks (`leanQuery`)
 * instead of bitecs' scan, which calls a generic component check per entity (a Map look-up and an
 * `Object.keys` array each): a world's first step makes its systems' queries (about 45), and in a
 * world of tens of thousands of entities bitecs' scans would be most of that step.
 * Ids above the capacity are never made (createSlot refuses them).
 */

interface ComponentData {
  generationId: number;
  bitflag: number;
  ref: object;
}
interface EcsContext {
  entityIndex: { aliveCount: number; dense: number[]; sparse: ArrayLike<number | undefined> & { [i: number]: number | undefined } };
  entityMasks: (ArrayLike<number> & { [i: number]: number })[];
  componentMap: Map<object, ComponentData>;
  entityComponents: unknown;
  queries: Set<SparseSetLike & { toRemove: SparseSetLike }>;
}

/** bitecs' sparse set (createSparseSet): the members are read through these properties. */
interface SparseSetLike {
  dense: number[];
  sparse: ArrayLike<number | undefined>;
  add(v: number): void;
  remove(v: number): void;
  has(v: number): boolean;
  reset(): void;
  sort(compare?: (a: number, b: number) => number): void;
  /** Lean sets only: counts the changes of membership or order (see `typedSparseSet`). */
  version?: number;
  /** Lean sets only: makes the set hold exactly the given ids in that order (see `assignSparseSet`). */
  assign?: (ids: ArrayLike<number>) => void;
}

/**
 * Gives bitecs sparse set `set` an Int32Array `sparse` (same members, same order), allocated with
 * `capacity + 1` entries on the set's first member (most queries of a world never hold an entity).
 * `has(v)` reads `dense[sparse[v]] === v`, so stale entries of removed ids need no clearing.
 * `version` goes up with every change of the members or their order (add, remove, reset, sort, and
 * `assignSparseSet`; code that writes `dense` directly calls `touchSparseSet`), so a snapshot can tell
 * a list unchanged since the last one without comparing it.
 */
function typedSparseSet(set: SparseSetLike, capacity: number): void {
  const dense = set.dense;
  let sparse = new Int32Array(dense.length === 0 ? 0 : capacity + 1);
  for (let i = 0; i < dense.length; i++) sparse[dense[i]!] = i;
  const has = (v: number): boolean => dense[sparse[v]!] === v;
  set.sparse = sparse;
  set.has = has;
  set.version = 0;
  set.add = (v: number): void => {
    if (has(v)) return;
    if (sparse.length === 0) {
      sparse = new Int32Array(capacity + 1);
      set.sparse = sparse;
    }
    sparse[v] = dense.push(v) - 1;
    set.version!++;
  };
  set.remove = (v: number): void => {
    if (!has(v)) return;
    set.version!++;
    const index = sparse[v]!;
    const swapped = dense.pop()!;
    if (swapped !== v) {
      dense[index] = swapped;
      sparse[swapped] = index;
    }
  };
  set.reset = (): void => {
    dense.length = 0;
    set.version!++;
  };
  set.assign = (ids: ArrayLike<number>): void => {
    const n = ids.length;
    if (n > 0 && sparse.length === 0) {
      sparse = new Int32Array(capacity + 1);
      set.sparse = sparse;
    }
    const m = Math.min(dense.length, n);
    for (let i = 0; i < m; i++) dense[i] = ids[i]!;
    if (dense.length > n) dense.length = n;
    for (let i = m; i < n; i++) dense.push(ids[i]!);
    for (let i = 0; i < n; i++) sparse[ids[i]!] = i;
    set.version!++;
  };
  set.sort = (compare?: (a: number, b: number) => number): void => {
    dense.sort(compare);
    set.version!++;
    if (dense.length > 0 && sparse.length === 0) {
      sparse = new Int32Array(capacity + 1);
      set.sparse = sparse;
    }
    for (let i = 0; i < dense.length; i++) sparse[dense[i]!] = i;
  };
}

/**
 * Makes `set`, a query's sparse set (or its pending removals') in a world with lean storage, hold
 * exactly `ids` in that order: its dense list written in place (it stays a packed JS array, the same
 * object) and its typed sparse array allocated if it was not yet. For restoring a snapshot.
 * @returns false (nothing done) for a set lean storage did not make.
 * @category Bodies
 */
export function assignSparseSet(set: object, ids: ArrayLike<number>): boolean {
  const assign = (set as { assign?: (ids: ArrayLike<number>) => void }).assign;
  if (assign === undefined) return false;
  assign(ids);
  return true;
}

/**
 * Records a change to `set`'s members or order made by writing its `dense` array directly (bulk
 * births, defragmentation: particles/archetype.ts), so snapshots do not take it for unchanged. No-op
 * for a set lean storage did not make.
 * @category Bodies
 */
export function touchSparseSet(set: object): void {
  const s = set as { version?: number };
  if (s.version !== undefined) s.version++;
}

/** bitecs' observable (createObservable): listeners subscribe; notify calls each with the entity and merges their object results. */
interface Observable {
  subscribe(listener: (entity: number, ...args: unknown[]) => unknown): () => void;
  notify(entity: number, ...args: unknown[]): object;
}

const NO_RESULT: object = Object.freeze({});

/**
 * bitecs' observable without its garbage: bitecs' notify copies the listener set to an array, reduces
 * it into a fresh object and gathers rest arguments on every call, which a query's add and remove
 * observables get for every entity entering or leaving the query (bodies falling asleep and waking:
 * about 100 kB a step in box-pile-3d of 5,000). With no listener (the usual case) this notify returns
 * a shared frozen empty object (bitecs discards a query observable's result); with listeners it calls
 * each in subscription order with the same arguments and merges their object results as bitecs does.
 */
function leanObservable(): Observable {
  const listeners = new Set<(entity: number, ...args: unknown[]) => unknown>();
  return {
    subscribe(listener) {
      listeners.add(listener);
      return () => {
        listeners.delete(listener);
      };
    },
    // No rest parameter: it would gather an array on every call; `arguments` is read only with listeners.
    notify(entity: number): object {
      if (listeners.size === 0) return NO_RESULT;
      // biome-ignore lint/complexity/noArguments: a rest parameter would allocate on every call
      const args = Array.prototype.slice.call(arguments, 1) as unknown[];
      let acc: object = {};
      for (const listener of Array.from(listeners)) {
        const result = listener(entity, ...args);
        if (result && typeof result === 'object') acc = { ...acc, ...result };
      }
      return acc;
    },
  };
}

/** The world's query set: each query registered gets typed sparse arrays before bitecs fills it. */
class LeanQuerySet<Q extends SparseSetLike & { toRemove: SparseSetLike }> extends Set<Q> {
  /** The query registered last (bitecs' registerQuery adds it here before it fills it), or null. */
  latest: Q | null = null;
  constructor(
    private readonly capacity: number,
    queries: Iterable<Q>,
  ) {
    super();
    // Queries made before (the component defaults' observers) keep bitecs' observables: they may have listeners.
    for (const q of queries) this.register(q, false);
  }
  override add(q: Q): this {
    this.latest = q;
    return this.register(q, true);
  }
  /** Typed sparse sets for `q` (once), and lean observables if `lean` and `q` is new (no listener can hold bitecs' yet). */
  private register(q: Q, lean: boolean): this {
    if (!(q.sparse instanceof Int32Array)) {
      typedSparseSet(q, this.capacity);
      typedSparseSet(q.toRemove, this.capacity);
      const o = q as unknown as { addObservable?: Observable; removeObservable?: Observable };
      if (lean && o.addObservable !== undefined) o.addObservable = leanObservable();
      if (lean && o.removeObservable !== undefined) o.removeObservable = leanObservable();
    }
    return super.add(q);
  }
}

/** What bitecs' registerQuery keeps of a query besides its sparse set: its masks per component generation. */
interface QueryMasks extends SparseSetLike {
  masks: Record<number, number>;
  notMasks: Record<number, number>;
  orMasks: Record<number, number>;
  generations: number[];
}

/**
 * bitecs' `query(world, terms)` (same live array, same members in the same order), with a query that
 * is new to a world with lean storage filled by `fillQuery` rather than by bitecs' scan (see the
 * module docstring). A world without lean storage, or with no entity, gets bitecs' own call.
 * @category Bodies
 */
export function leanQuery(world: object, terms: object[]): QueryResult {
  const ctx = (world as Record<symbol, EcsContext>)[$internal]!;
  const queries = ctx.queries;
  const index = ctx.entityIndex;
  const alive = index.aliveCount;
  if (!(queries instanceof LeanQuerySet) || alive === 0) return bitecsQuery(world as never, terms as never);
  queries.latest = null;
  // bitecs registers a new query, then scans the first `aliveCount` ids of the entity index: with
  // none alive for the call, it only registers it, and the loop below fills it.
  index.aliveCount = 0;
  let dense: QueryResult;
  try {
    dense = bitecsQuery(world as never, terms as never);
  } finally {
    index.aliveCount = alive;
  }
  const made = queries.latest as QueryMasks | null;
  if (made !== null) fillQuery(ctx, made);
  return dense;
}

/**
 * Fills the new query `q` with every live entity that matches it, in the entity index's order, as
 * bitecs' registerQuery does: prefabs skipped; an entity matches if, in every generation of the
 * query's components, it has all of `masks` and none of `notMasks`, and, if the query has
 * `orMasks`, at least one of them in some generation. The members are written at once (the query is
 * new: nothing listens to its add observable yet, so there is nothing to notify).
 */
function fillQuery(ctx: EcsContext, q: QueryMasks): void {
  const gens = q.generations.slice();
  const all = gens.map((g) => q.masks[g] ?? 0),
    none = gens.map((g) => q.notMasks[g] ?? 0),
    any = gens.map((g) => q.orMasks[g] ?? 0);
  // bitecs' scan skips prefabs: the same as a Not of the Prefab component.
  const prefab = ctx.componentMap.get(Prefab);
  if (prefab !== undefined) {
    let k = gens.indexOf(prefab.generationId);
    if (k < 0) {
      k = gens.push(prefab.generationId) - 1;
      all.push(0);
      none.push(0);
      any.push(0);
    }
    none[k] = none[k]! | prefab.bitflag;
  }
  const needAny = Object.keys(q.orMasks).length > 0;
  const index = ctx.entityIndex,
    masks = ctx.entityMasks;
  const n = index.aliveCount;
  const ids = new Int32Array(n);
  let count: number;
  if (gens.length <= 2) {
    // One or two mask words an entity (every world of up to 62 components): one loop, no arrays of masks.
    const two = gens.length === 2;
    count = matchTwoWords(
      index.dense,
      n,
      masks[gens[0]!]!,
      all[0]!,
      none[0]!,
      any[0]!,
      two ? masks[gens[1]!]! : masks[gens[0]!]!,
      two ? all[1]! : 0,
      two ? none[1]! : 0,
      two ? any[1]! : 0,
      needAny,
      ids,
    );
  } else {
    count = 0;
    for (let i = 0; i < n; i++) {
      const e = index.dense[i]!;
      let match = true,
        anyMatch = !needAny;
      for (let k = 0; k < gens.length && match; k++) {
        const bits = masks[gens[k]!]![e] ?? 0;
        if ((bits & none[k]!) !== 0 || (bits & all[k]!) !== all[k]) match = false;
        else if ((bits & any[k]!) !== 0) anyMatch = true;
      }
      if (match && anyMatch) ids[count++] = e;
    }
  }
  const members = ids.subarray(0, count);
  if (!assignSparseSet(q, members)) for (let i = 0; i < count; i++) q.add(members[i]!);
}

/**
 * The entities of `dense[0..n)` whose mask words `m0[e]`, `m1[e]` hold all bits of `a0`, `a1`, none of
 * `z0`, `z1` and, if `needAny`, some bit of `o0` or `o1`, written to `out` in order. @returns their count.
 */
function matchTwoWords(
  dense: ArrayLike<number>,
  n: number,
  m0: ArrayLike<number>,
  a0: number,
  z0: number,
  o0: number,
  m1: ArrayLike<number>,
  a1: number,
  z1: number,
  o1: number,
  needAny: boolean,
  out: Int32Array,
): number {
  let count = 0;
  for (let i = 0; i < n; i++) {
    const e = dense[i]!;
    const b0 = m0[e]! | 0,
      b1 = m1[e]! | 0;
    if ((b0 & a0) !== a0 || (b0 & z0) !== 0 || (b1 & a1) !== a1 || (b1 & z1) !== 0) continue;
    if (needAny && ((b0 & o0) | (b1 & o1)) === 0) continue;
    out[count++] = e;
  }
  return count;
}

/** The component set of one entity: read-only view over its mask (bitecs' writes are ignored). */
class MaskComponentSet {
  /** The entity the view answers for: set by `MaskComponentSets.get` just before bitecs reads it. */
  eid = 0;
  constructor(private readonly ctx: EcsContext) {}
  /** No-op: bitecs has already set the component's bit in the entity's mask. */
  add(): this {
    return this;
  }
  /** No-op: bitecs has already cleared the component's bit. */
  delete(): boolean {
    return true;
  }
  has(component: object): boolean {
    const d = this.ctx.componentMap.get(component);
    return d !== undefined && ((this.ctx.entityMasks[d.generationId]![this.eid] ?? 0) & d.bitflag) === d.bitflag;
  }
  get size(): number {
    let n = 0;
    for (const _ of this) n++;
    return n;
  }
  *[Symbol.iterator](): IterableIterator<object> {
    const eid = this.eid,
      ctx = this.ctx;
    for (const d of ctx.componentMap.values()) {
      if (((ctx.entityMasks[d.generationId]![eid] ?? 0) & d.bitflag) === d.bitflag) yield d.ref;
    }
  }
  values(): IterableIterator<object> {
    return this[Symbol.iterator]();
  }
  keys(): IterableIterator<object> {
    return this[Symbol.iterator]();
  }
  forEach(fn: (c: object, c2: object, set: this) => void): void {
    for (const c of this) fn(c, c, this);
  }
}

/** The map bitecs reads as `entityComponents`: live entity id -> its component set (a mask view). */
class MaskComponentSets {
  private readonly view: MaskComponentSet;
  constructor(private readonly ctx: EcsContext) {
    this.view = new MaskComponentSet(ctx);
  }
  private alive(eid: number): boolean {
    const ix = this.ctx.entityIndex;
    const i = ix.sparse[eid];
    return i !== undefined && i < ix.aliveCount && ix.dense[i] === eid;
  }
  /** No-op (bitecs' addEntity hands a fresh empty Set; the mask is the record). */
  set(): this {
    return this;
  }
  /** The entity's components as a view, or undefined for an id that is not alive. The view is shared: read it before the next `get`. */
  get(eid: number): MaskComponentSet | undefined {
    if (!this.alive(eid)) return undefined;
    this.view.eid = eid;
    return this.view;
  }
  has(eid: number): boolean {
    return this.alive(eid);
  }
  /** No-op (bitecs clears the removed entity's masks itself). */
  delete(): boolean {
    return true;
  }
  /** No-op: the entity index is the record of live ids. */
  clear(): void {}
  get size(): number {
    return this.ctx.entityIndex.aliveCount;
  }
  *keys(): IterableIterator<number> {
    const ix = this.ctx.entityIndex;
    for (let i = 0; i < ix.aliveCount; i++) yield ix.dense[i]!;
  }
}

/**
 * Makes bitecs' per-entity bookkeeping lean (see the module docstring): component sets from the masks,
 * and Int32Array sparse arrays of `capacity + 1` for the entity index, the first component mask
 * generation and every query. Call on a new world, before any entity exists, after its
 * components are registered (createPhysicsWorld does, after installing the component defaults).
 * @param capacity the world's capacity: the highest entity id.
 * @throws Error if the world already has entities.
 * @category Bodies
 */
export function useLeanEcsStorage(world: object, capacity: number): void {
  const ctx = (world as Record<symbol, EcsContext>)[$internal]!;
  if (ctx.entityIndex.aliveCount !== 0 || ctx.entityIndex.dense.length !== 0)
    throw new Error('useLeanEcsStorage: the world must have no entities yet');
  ctx.entityComponents = new MaskComponentSets(ctx);
  ctx.entityIndex.sparse = new Int32Array(capacity + 1) as never;
  // Every generation typed, those bitecs adds later too (it pushes an empty JS array when a
  // registration fills a generation's 31 bits).
  const masks = ctx.entityMasks;
  for (let g = 0; g < masks.length; g++) masks[g] = new Int32Array(capacity + 1);
  Object.defineProperty(masks, 'push', {
    value: (...items: unknown[]): number =>
      Array.prototype.push.apply(
        masks,
        items.map(() => new Int32Array(capacity + 1)),
      ),
    enumerable: false,
  });
  ctx.queries = new LeanQuerySet(capacity, ctx.queries);
}

/**
 * Whether `world`'s component sets are derived from its masks (`useLeanEcsStorage`): nothing to rebuild after its masks change.
 * @category Bodies
 */
export function hasMaskComponentSets(world: object): boolean {
  return (world as Record<symbol, EcsContext>)[$internal]!.entityComponents instanceof MaskComponentSets;
}
