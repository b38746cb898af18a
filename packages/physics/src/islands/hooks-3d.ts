/**
 * The sleep system's entry points into the 3D shapes' and joints' islands (islands/shapes-3d.ts),
 * through a table that `install3D` (collision/install-3d.ts) fills when a program first makes a 3D
 * shape or joint. Until then each entry does what the real function does in a world without 3D
 * shapes, contacts or joints (nothing), so the sleep system does not bring them into a program that
 * never makes them.
 */
import type { PhysicsWorld } from '../world/options.js';
import type { IslandEdges } from './edges.js';

/**
 * The 3D islands' functions the sleep system calls (see this module's header).
 * @category Sleep
 */
export interface Islands3D {
  withShape3DBodies(world: PhysicsWorld, others: ArrayLike<number>): ArrayLike<number>;
  addIslandEdges3D(world: PhysicsWorld, e: IslandEdges): void;
  wakeTouching3D(world: PhysicsWorld, eid: number): void;
}

let islands: Islands3D | null = null;

/**
 * Hands the sleep system the 3D islands (called by install3D; the table serves every world).
 * @category Sleep
 */
export function setIslands3D(table: Islands3D): void {
  islands = table;
}

/** islands/shapes-3d.ts withShape3DBodies; `others` before install3D. */
export function withShape3DBodies(world: PhysicsWorld, others: ArrayLike<number>): ArrayLike<number> {
  return islands === null ? others : islands.withShape3DBodies(world, others);
}

/** islands/shapes-3d.ts addIslandEdges3D; nothing before install3D. */
export function addIslandEdges3D(world: PhysicsWorld, e: IslandEdges): void {
  if (islands !== null) islands.addIslandEdges3D(world, e);
}

/** islands/shapes-3d.ts wakeTouching3D; nothing before install3D. */
export function wakeTouching3D(world: PhysicsWorld, eid: number): void {
  if (islands !== null) islands.wakeTouching3D(world, eid);
}
