/**
 * The contact solver's entry points into the 2D joint rows (joints/solver-2d.ts), through a table
 * that the world's assembly (create-world.ts) fills once for the program. The solver runs the joints' stages beside the
 * contacts' without importing the joints, which sit above it (a joint type's file holds both its
 * add call and its row solve). Until the table is filled no world exists, and each entry does what
 * the real function does in a world without 2D joints: nothing.
 */
import type { PhysicsWorld } from '../world/options.js';

/**
 * The 2D joint rows' functions the contact solver calls (see this module's header).
 * @category Joints and ropes
 */
export interface JointRows2D {
  jointsToSolve(world: PhysicsWorld): boolean;
  gatherJointBodies(world: PhysicsWorld, count: number): number;
  prepareJoints(world: PhysicsWorld, hs: number): void;
  warmStartJoints(world: PhysicsWorld): void;
  integrateJointRotations(world: PhysicsWorld, hs: number): void;
  solveJoints(world: PhysicsWorld, hs: number, useBias: boolean): void;
  finishJoints(world: PhysicsWorld, hs: number): void;
}

let rows: JointRows2D | null = null;

/**
 * Hands the contact solver the 2D joint rows (called once by create-world.ts; the table serves every world).
 * @category Joints and ropes
 */
export function setJointRows2D(table: JointRows2D): void {
  rows = table;
}

/** joints/solver-2d.ts jointsToSolve; false before the table is set. */
export function jointsToSolve(world: PhysicsWorld): boolean {
  return rows?.jointsToSolve(world) === true;
}

/** joints/solver-2d.ts gatherJointBodies; `count` unchanged before the table is set. */
export function gatherJointBodies(world: PhysicsWorld, count: number): number {
  return rows === null ? count : rows.gatherJointBodies(world, count);
}

/** joints/solver-2d.ts prepareJoints; nothing before the table is set. */
export function prepareJoints(world: PhysicsWorld, hs: number): void {
  if (rows !== null) rows.prepareJoints(world, hs);
}

/** joints/solver-2d.ts warmStartJoints; nothing before the table is set. */
export function warmStartJoints(world: PhysicsWorld): void {
  if (rows !== null) rows.warmStartJoints(world);
}

/** joints/solver-2d.ts integrateJointRotations; nothing before the table is set. */
export function integrateJointRotations(world: PhysicsWorld, hs: number): void {
  if (rows !== null) rows.integrateJointRotations(world, hs);
}

/** joints/solver-2d.ts solveJoints; nothing before the table is set. */
export function solveJoints(world: PhysicsWorld, hs: number, useBias: boolean): void {
  if (rows !== null) rows.solveJoints(world, hs, useBias);
}

/** joints/solver-2d.ts finishJoints; nothing before the table is set. */
export function finishJoints(world: PhysicsWorld, hs: number): void {
  if (rows !== null) rows.finishJoints(world, hs);
}
