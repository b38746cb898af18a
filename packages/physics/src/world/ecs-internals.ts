import { $internal } from 'bitecs';
import type { PhysicsWorld } from './options.js';

/**
 * The parts of bitecs 0.4's world internals that the engine reads (entity masks, component bits,
 * queries): their shapes, and `ecsOf` to reach them. The particle archetypes and the sleep system
 * read component membership from the masks without bitecs' per-entity lookups.
 */

/** bitecs 0.4 sparse set (queries and their pending removals). */
export interface SparseSet {
  dense: number[];
  sparse: number[];
  has(v: number): boolean;
  add(v: number): void;
  remove(v: number): void;
}
/** bitecs 0.4 query data. */
export interface QueryData extends SparseSet {
  masks: Record<number, number>;
  notMasks: Record<number, number>;
  orMasks: Record<number, number>;
  generations: number[];
  toRemove: SparseSet;
}
export interface ComponentData {
  generationId: number;
  bitflag: number;
  ref: object;
}
/** bitecs 0.4 world internals used here. */
export interface EcsInternals {
  entityIndex: { aliveCount: number; dense: number[]; sparse: number[]; maxId: number; versioning: boolean };
  entityMasks: number[][];
  /** A Map of Sets in bitecs; a view answered from the masks where the world made its storage lean. */
  entityComponents: Map<number, Set<object>> | object;
  componentMap: Map<object, ComponentData>;
  queries: Set<QueryData>;
  dirtyQueries: Set<QueryData>;
  entitiesWithRelations: Set<unknown>;
}

/**
 * bitecs' data of `world`.
 * @category Utilities
 */
export function ecsOf(world: PhysicsWorld): EcsInternals {
  return (world as unknown as Record<symbol, EcsInternals>)[$internal]!;
}
