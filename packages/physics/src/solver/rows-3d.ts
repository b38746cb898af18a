/**
 * The contact solver's entry points into the 3D joint and shape-contact rows (joints/solver-3d.ts,
 * solver/manifold-rows-3d.ts), through a table that `install3D` (collision/install-3d.ts) fills when a
 * program first makes a 3D shape or joint. Until then no world has a 3D joint, a 3D shape or the 3D
 * contact state (collision/manifolds-3d.ts contact3DStateOf, made only by those rows, the 3D shapes'
 * collision and restore, which installs them), and each entry does what the real function does then:
 * nothing (the 3D contact state, which prepareManifolds3D would make in a 3D world of balls, holds
 * nothing the balls' solve reads). So the contact solver does not bring the 3D rows into a program that
 * never makes them.
 */
import type { PhysicsWorld } from '../world/options.js';

/**
 * The 3D rows' functions the contact solver calls (see this module's header).
 * @category Collision
 */
export interface Rows3D {
  joints3DToSolve(world: PhysicsWorld): boolean;
  gatherJoint3DBodies(world: PhysicsWorld, count: number): number;
  prepareJoints3D(world: PhysicsWorld, hs: number): void;
  warmStartJoints3D(world: PhysicsWorld): void;
  solveJoints3D(world: PhysicsWorld, hs: number, useBias: boolean): void;
  finishJoints3D(world: PhysicsWorld, hs: number): void;
  manifolds3DToSolve(world: PhysicsWorld): boolean;
  gatherManifold3DBodies(world: PhysicsWorld, count: number): number;
  prepareManifolds3D(world: PhysicsWorld): void;
  finishManifolds3D(world: PhysicsWorld): void;
  warmStartManifolds3D(world: PhysicsWorld): void;
  solveManifolds3D(world: PhysicsWorld, hs: number, useBias: boolean): void;
  applyManifold3DRestitution(world: PhysicsWorld): void;
}

let rows: Rows3D | null = null;

/**
 * Hands the contact solver the 3D rows (called by install3D; the table serves every world, and does
 * nothing in one without 3D shapes or joints).
 * @category Collision
 */
export function setRows3D(table: Rows3D): void {
  rows = table;
}

/** joints/solver-3d.ts joints3DToSolve; false before install3D (no 3D joint exists). */
export function joints3DToSolve(world: PhysicsWorld): boolean {
  return rows?.joints3DToSolve(world) === true;
}

/** joints/solver-3d.ts gatherJoint3DBodies; `count` unchanged before install3D. */
export function gatherJoint3DBodies(world: PhysicsWorld, count: number): number {
  return rows === null ? count : rows.gatherJoint3DBodies(world, count);
}

/** joints/solver-3d.ts prepareJoints3D; nothing before install3D. */
export function prepareJoints3D(world: PhysicsWorld, hs: number): void {
  if (rows !== null) rows.prepareJoints3D(world, hs);
}

/** joints/solver-3d.ts warmStartJoints3D; nothing before install3D. */
export function warmStartJoints3D(world: PhysicsWorld): void {
  if (rows !== null) rows.warmStartJoints3D(world);
}

/** joints/solver-3d.ts solveJoints3D; nothing before install3D. */
export function solveJoints3D(world: PhysicsWorld, hs: number, useBias: boolean): void {
  if (rows !== null) rows.solveJoints3D(world, hs, useBias);
}

/** joints/solver-3d.ts finishJoints3D; nothing before install3D. */
export function finishJoints3D(world: PhysicsWorld, hs: number): void {
  if (rows !== null) rows.finishJoints3D(world, hs);
}

/** solver/manifold-rows-3d.ts warmStartManifolds3D; nothing before install3D (no manifold to start). */
export function warmStartManifolds3D(world: PhysicsWorld): void {
  if (rows !== null) rows.warmStartManifolds3D(world);
}

/** solver/manifold-rows-3d.ts solveManifolds3D; nothing before install3D. */
export function solveManifolds3D(world: PhysicsWorld, hs: number, useBias: boolean): void {
  if (rows !== null) rows.solveManifolds3D(world, hs, useBias);
}

/** solver/manifold-rows-3d.ts manifolds3DToSolve; false before install3D. */
export function manifolds3DToSolve(world: PhysicsWorld): boolean {
  return rows?.manifolds3DToSolve(world) === true;
}

/** solver/manifold-rows-3d.ts gatherManifold3DBodies; `count` unchanged before install3D. */
export function gatherManifold3DBodies(world: PhysicsWorld, count: number): number {
  return rows === null ? count : rows.gatherManifold3DBodies(world, count);
}

/** solver/manifold-rows-3d.ts prepareManifolds3D; nothing before install3D. */
export function prepareManifolds3D(world: PhysicsWorld): void {
  if (rows !== null) rows.prepareManifolds3D(world);
}

/** solver/manifold-rows-3d.ts finishManifolds3D; nothing before install3D. */
export function finishManifolds3D(world: PhysicsWorld): void {
  if (rows !== null) rows.finishManifolds3D(world);
}

/** solver/manifold-rows-3d.ts applyManifold3DRestitution; nothing before install3D. */
export function applyManifold3DRestitution(world: PhysicsWorld): void {
  if (rows !== null) rows.applyManifold3DRestitution(world);
}
