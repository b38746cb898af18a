/**
 * The contact solver's entry points into the ball contacts' rows (solver/ball-rows.ts), through a
 * table that `installBalls` (collision/install-balls.ts) fills when a program first makes a ball.
 * Until then no world has a ball contact (the broadphase and narrowphase that make them are installed
 * with the table), and the solver skips these stages. So the contact solver does not bring the ball
 * rows, the impact stage and the coloured solve into a program of shapes and joints only.
 */
import type { ContactBuffer } from '../collision/contacts.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * The ball rows' stages the contact solver calls (solver/ball-rows.ts says what each does).
 * @category Collision
 */
export interface BallRows {
  prepare(world: PhysicsWorld, buf: ContactBuffer): void;
  approach(world: PhysicsWorld, buf: ContactBuffer, others: boolean, hs: number): boolean;
  plan(world: PhysicsWorld, buf: ContactBuffer, colored: boolean, hs: number): void;
  warmStart(world: PhysicsWorld, buf: ContactBuffer): void;
  solve(world: PhysicsWorld, buf: ContactBuffer, useBias: boolean): void;
  endSubstep(buf: ContactBuffer): void;
  restitution(world: PhysicsWorld, buf: ContactBuffer): void;
  events(world: PhysicsWorld, buf: ContactBuffer, prepared: boolean): void;
  store(world: PhysicsWorld, buf: ContactBuffer, onThreads: boolean): ContactBuffer;
}

let rows: BallRows | null = null;

/**
 * Hands the contact solver the ball rows (called by installBalls; the table serves every world).
 * @category Collision
 */
export function setBallRows(table: BallRows): void {
  rows = table;
}

/** The ball rows, or null before the program made its first ball (then no world has a ball contact). */
export function ballRows(): BallRows | null {
  return rows;
}
