/**
 * The contact solver's row families (solver/contact-solver.ts): the 2D and 3D joints' rows, the ball
 * contacts' rows (2D discs and 3D spheres) and the 2D and 3D shape contacts' rows, each one object with
 * the same named stages, which the solver runs over the families in FAMILY_ORDER. A family whose code a
 * program may leave out is handed over when the program first needs it: the 2D joints by the world's
 * assembly (create-world.ts), the ball rows by `installBalls` (collision/install-balls.ts), the 3D joints
 * and shape contacts by `install3D` (collision/install-3d.ts); the 2D shape contacts by the contact
 * solver itself. Until then no world has that family's rows, and the solver skips it. So the solver does
 * not import the families, which sit above it (a joint type's file holds both its add call and its row
 * solve), nor bring a family (the ball rows' impact stage and coloured solve, the 3D rows) into a
 * program that never makes it.
 */
import type { ContactBuffer } from '../collision/contacts.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * One family of solver rows: its stages, each run once a step (or a substep, or a pass) over all its
 * rows on the packed solver body state (CollisionState.bodyState). `hs` is the substep (s).
 * @category Collision
 */
export interface RowFamily {
  /** The world dimension the family's rows live in: 2 or 3, or 0 for both; the solver skips it in another. */
  readonly dimensions: 0 | 2 | 3;
  /** True if the family's rows push their bodies without marking them pushed: then no body of the step counts as free flying. */
  readonly pushesUnmarked: boolean;
  /** Whether the world has rows of this family to solve this step (called every step the solver runs). */
  toSolve(world: PhysicsWorld): boolean;
  /** Gives the family's moving bodies solver indices from `count` on; returns the new body count. */
  gather(world: PhysicsWorld, count: number): number;
  /** Effective masses, anchors, softness and last step's impulses of this step's rows. */
  prepare(world: PhysicsWorld, hs: number): void;
  /** Applies every row's accumulated impulse (once a substep). */
  warmStart(world: PhysicsWorld): void;
  /** One pass over the rows: with soft bias if `useBias`, else relaxed; `last` on the substep's last relax pass. */
  solve(world: PhysicsWorld, hs: number, useBias: boolean, last: boolean): void;
  /** After the substep's positions are advanced, before its relax passes. */
  integrate(world: PhysicsWorld, hs: number): void;
  /** At the end of a substep, after its relax passes. */
  endSubstep(world: PhysicsWorld): void;
  /** The bounce of the rows that approached faster than the restitution threshold (after the substeps). */
  restitution(world: PhysicsWorld): void;
  /** After the bodies are written back: impulses kept for the next step's warm start, events, readings. */
  finish(world: PhysicsWorld, hs: number): void;
}

/**
 * The ball contacts' rows (solver/ball-rows.ts): a row family on the step's contact buffer
 * (CollisionState.contacts), with the stages only they have. Their `finish` does nothing: the solver
 * calls `events` and `store` after every family's finish.
 * @category Collision
 */
export interface BallRows extends RowFamily {
  /** After every family is prepared: the impact stage and the approach speeds; true when the coloured solve takes the step (`others`: other families have rows). */
  approach(world: PhysicsWorld, buf: ContactBuffer, others: boolean, hs: number): boolean;
  /** Before the substeps: the relax sweep's first rows, and the coloured substeps when `colored`. */
  plan(world: PhysicsWorld, buf: ContactBuffer, colored: boolean, hs: number): void;
  /** The begin and end touch events of the step's rows (`prepared`: the solver ran this step). */
  events(world: PhysicsWorld, buf: ContactBuffer, prepared: boolean): void;
  /** Keeps the rows for the next step's warm start; returns the contact buffer the next step fills. */
  store(world: PhysicsWorld, buf: ContactBuffer, onThreads: boolean): ContactBuffer;
}

/** The families, by name, in the order the solver runs every stage over them. */
export const FAMILY_ORDER = ['joints2D', 'joints3D', 'balls', 'manifolds2D', 'manifolds3D'] as const;

/** A family's name (FAMILY_ORDER). */
export type RowFamilyName = (typeof FAMILY_ORDER)[number];

/**
 * The families of one world dimension, in FAMILY_ORDER (`list`), and the ball rows among them (null before installBalls).
 * @category Collision
 */
export interface RowFamilies {
  readonly list: readonly RowFamily[];
  readonly balls: BallRows | null;
}

const byName: Partial<Record<RowFamilyName, RowFamily>> = {};
const empty: RowFamilies = { list: [], balls: null };
let ordered: { 2: RowFamilies; 3: RowFamilies } = { 2: empty, 3: empty };

/** The families of `dimensions` handed over so far, in FAMILY_ORDER. */
function order(dimensions: 2 | 3): RowFamilies {
  const list: RowFamily[] = [];
  for (const n of FAMILY_ORDER) {
    const f = byName[n];
    if (f !== undefined && (f.dimensions === 0 || f.dimensions === dimensions)) list.push(f);
  }
  return { list, balls: (byName.balls as BallRows | undefined) ?? null };
}

/**
 * Hands the contact solver the family `name` (once for the program; the family serves every world).
 * @category Collision
 */
export function setRowFamily(name: 'balls', family: BallRows): void;
export function setRowFamily(name: Exclude<RowFamilyName, 'balls'>, family: RowFamily): void;
export function setRowFamily(name: RowFamilyName, family: RowFamily): void {
  byName[name] = family;
  ordered = { 2: order(2), 3: order(3) };
}

/** The families handed over so far whose rows live in a world of `dimensions` (2 or 3), in FAMILY_ORDER. */
export function rowFamilies(dimensions: number): RowFamilies {
  return dimensions === 2 ? ordered[2] : ordered[3];
}

/** Whether `world` has joint rows to solve this step (false before the joint families are handed over). */
export function jointsToSolve(world: PhysicsWorld): boolean {
  return byName[world.dimensions === 2 ? 'joints2D' : 'joints3D']?.toSolve(world) === true;
}
