import type { PhysicsWorld } from '@bitphysics/physics';

/**
 * The contract every game page meets, so one browser test can open any of them:
 * 1. after its first rendered frame it sets `document.body.dataset.ready = 'true'`;
 * 2. it exposes `window.game` with at least `world`, `paused` (settable) and `stats()`.
 * Games may add more fields to `window.game` (their renderer, spawn functions, ...).
 */

/** What `window.game.stats()` returns. */
export interface GameStats {
  /** Entities alive in the world (bodies, walls, every entity counts), integer >= 0. */
  entities: number;
  /** Physics steps taken by the current world since it was created (0 after a reset), integer >= 0. */
  steps: number;
  /** Frames drawn per second, measured over the last half second or so; 0 before the first measurement. */
  fps: number;
}

/** The minimum `window.game` of every page. */
export interface GameHandle {
  /** The physics world shown now (a reset replaces it). */
  readonly world: PhysicsWorld;
  /** Whether the simulation is paused; set it to pause or resume. */
  paused: boolean;
  /** Current statistics, a fresh object each call. */
  stats(): GameStats;
}

declare global {
  interface Window {
    /** The running game, see `GameHandle` (contract.ts). */
    game?: GameHandle;
  }
}

/**
 * Publishes `game` as `window.game` and returns it.
 * @throws TypeError if `game` lacks `world`, `paused` or `stats()`.
 */
export function exposeGame<T extends GameHandle>(game: T): T {
  if (
    game === null ||
    typeof game !== 'object' ||
    !('world' in game) ||
    typeof game.stats !== 'function' ||
    typeof game.paused !== 'boolean'
  ) {
    throw new TypeError('exposeGame: game must have world, a boolean paused and stats()');
  }
  window.game = game;
  return game;
}

/** Marks the page ready for tests and screenshots: `document.body.dataset.ready = 'true'`. */
export function markReady(): void {
  document.body.dataset.ready = 'true';
}
