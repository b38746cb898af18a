/**
 * The sleep system's entry points into the 3D shapes' and joints' islands (islands/shapes-3d.ts,
 * islands/joints-3d.ts), through a table that `install3D` (collision/install-3d.ts) fills when a
 * program first makes a 3D shape or joint. Until then each entry does what the real function does in a
 * world without 3D shapes, shape contacts or joints (nothing), so the sleep system does not bring them
 * into a program that never makes them.
 */
import type { PhysicsWorld } from '../world/options.js';

/**
 * The 3D islands' functions the sleep system calls (see this module's header).
 * @category Sleep
 */
export interface Islands3D {
  withShape3DBodies(world: PhysicsWorld, others: ArrayLike<number>): ArrayLike<number>;
  markShape3DSupport(world: PhysicsWorld, supported: Uint32Array, stamp: number): void;
  joinShape3DIslands(world: PhysicsWorld, parent: Int32Array, find: (x: number) => number): void;
  wakeTouching3D(world: PhysicsWorld, eid: number): void;
  markJoint3DSupport(world: PhysicsWorld, supported: Uint32Array, stamp: number): void;
  joinJoint3DIslands(
    world: PhysicsWorld,
    bodies: ArrayLike<number>,
    rest: Float64Array,
    parent: Int32Array,
    member: Uint32Array,
    stamp: number,
  ): number[] | null;
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

/** islands/shapes-3d.ts markShape3DSupport; nothing before install3D. */
export function markShape3DSupport(world: PhysicsWorld, supported: Uint32Array, stamp: number): void {
  if (islands !== null) islands.markShape3DSupport(world, supported, stamp);
}

/** islands/shapes-3d.ts joinShape3DIslands; nothing before install3D. */
export function joinShape3DIslands(world: PhysicsWorld, parent: Int32Array, find: (x: number) => number): void {
  if (islands !== null) islands.joinShape3DIslands(world, parent, find);
}

/** islands/shapes-3d.ts wakeTouching3D; nothing before install3D. */
export function wakeTouching3D(world: PhysicsWorld, eid: number): void {
  if (islands !== null) islands.wakeTouching3D(world, eid);
}

/** islands/joints-3d.ts markJoint3DSupport; nothing before install3D. */
export function markJoint3DSupport(world: PhysicsWorld, supported: Uint32Array, stamp: number): void {
  if (islands !== null) islands.markJoint3DSupport(world, supported, stamp);
}

/** islands/joints-3d.ts joinJoint3DIslands; null (no joint island) before install3D. */
export function joinJoint3DIslands(
  world: PhysicsWorld,
  bodies: ArrayLike<number>,
  rest: Float64Array,
  parent: Int32Array,
  member: Uint32Array,
  stamp: number,
): number[] | null {
  return islands === null ? null : islands.joinJoint3DIslands(world, bodies, rest, parent, member, stamp);
}
