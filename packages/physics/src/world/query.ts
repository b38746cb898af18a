import { Not as bitecsNot, commitRemovals, type QueryResult } from 'bitecs';
import { leanQuery } from './lean-ecs.js';

/**
 * Cached queries. bitecs 0.4's `query(world, terms)` hashes its terms on every call (map, sort and
 * join of strings, ~2 us here), which dominated the step of small worlds (about 35 queries a step).
 * This `query` looks the terms up by the identity of their objects instead (~0.1 us), asks bitecs
 * once per new combination, and thereafter returns the same live array after committing pending
 * removals, exactly as bitecs' own `query` does (so the bitecs trap applies: never query inside a
 * loop that removes). A new query of a world with lean storage is filled by world/lean-ecs.ts
 * `leanQuery` (one loop over the typed masks rather than bitecs' scan). Use `Not` from here (it memoises bitecs' Not(...) objects so they have a
 * stable identity).
 */

type Term = object;

// A WeakMap: keyed by a component (any object a caller passes, usable in several worlds) and `Not` takes no world; an entry goes with its component.
const nots = new WeakMap<object, object>();

/**
 * bitecs' Not(component), memoised per component so it can be a cache key.
 * @category Queries
 */
export function Not(component: object): Term {
  let term = nots.get(component);
  if (term === undefined) {
    term = bitecsNot(component) as object;
    nots.set(component, term);
  }
  return term;
}

interface Entry {
  terms: Term[];
  dense: QueryResult;
}

/**
 * A world's query cache, a property of the world itself (not enumerable, so nothing that walks a
 * world's fields sees it): the entries of its queries by the identity of their first term (undefined
 * for no terms). A step asks about 40 queries; two look-ups a query (the world's property, one Map)
 * cost about a third of hashing every term through a WeakMap of ids.
 */
const CACHE = Symbol('bitphysics query cache');
type Cached = { [CACHE]?: Map<Term | undefined, Entry[]> };

/**
 * Gives `world` its (empty) query cache if it has none, and returns the cache. createPhysicsWorld
 * calls it as it makes a world: the property added by the first query, in a world's first step, gave
 * the world another hidden class then, and V8 threw away the code compiled against the first one (the
 * code of everything that had read the world while the program built its scene).
 * @param world - A bitecs world (a PhysicsWorld, or a bare bitecs world queried through `query`).
 * @returns the world's cache of queries.
 */
export function addQueryCache(world: object): Map<Term | undefined, Entry[]> {
  const cache = (world as Cached)[CACHE];
  if (cache !== undefined) return cache;
  const made = new Map<Term | undefined, Entry[]>();
  Object.defineProperty(world, CACHE, { value: made, enumerable: false, writable: false, configurable: true });
  return made;
}

/**
 * The live array of entities having every component of `terms` (and none of the `Not` ones).
 * Same result and semantics as bitecs' query; cached per world by term identity.
 * @category Queries
 */
export function query(world: object, terms: Term[]): QueryResult {
  const cache = (world as Cached)[CACHE];
  if (cache !== undefined) {
    const bucket = cache.get(terms[0]);
    if (bucket !== undefined) {
      for (let b = 0; b < bucket.length; b++) {
        const entry = bucket[b]!;
        const t = entry.terms;
        if (t.length !== terms.length) continue;
        let same = true;
        for (let i = 1; i < t.length; i++)
          if (t[i] !== terms[i]) {
            same = false;
            break;
          }
        if (same) {
          commitRemovals(world as never);
          return entry.dense;
        }
      }
    }
  }
  return addQuery(world, terms);
}

/**
 * A query `query` has not cached for this world yet: asked once, filled, and cached. A function of
 * its own, called only on a miss, so that the compiled code of every system that calls `query` (which
 * V8 inlines) holds no allocation: the allocation sites here would tie that code to V8's decision
 * whether to allocate their objects straight into the old generation, and a change of that decision
 * (made by the garbage collector while a large world starts) threw it all away.
 */
function addQuery(world: object, terms: Term[]): QueryResult {
  const cache = (world as Cached)[CACHE] ?? addQueryCache(world);
  const key = terms[0];
  let bucket = cache.get(key);
  if (bucket === undefined) {
    bucket = [];
    cache.set(key, bucket);
  }
  const dense = leanQuery(world, terms);
  bucket.push({ terms: terms.slice(), dense });
  return dense;
}
