/**
 * Replays of black hole runs (DOM-free): every input the player gives (thrust direction, next level,
 * the panel's sliders) goes through a recorder as a named call at its step; pressing the replay key
 * rewinds to where the recording began and plays the same inputs back at the same steps, which ends
 * in the same state to the last bit (the physics is deterministic: see `snapshot` and `stateHash`).
 * Stretches where nothing happens (the ship parked at the start before the player thrusts, a cleared
 * level waiting for the next, a game over) are played through at once, up to REPLAY_LEAD_STEPS
 * before the input that ends them; `stop` leaves a replay for the moment it was started from.
 */
import {
  createInputRecorder,
  createReplayPlayer,
  type InputRecorder,
  type Replay,
  type ReplayOptions,
  type ReplayPlayer,
  restore,
  snapshot,
  type WorldSnapshot,
} from '@bitphysics/physics';
import { beginLevel, type LevelRun, stepLevel } from './levels';
import {
  type BlackHoleEvent,
  type BlackHoleGame,
  layoutHoles,
  setGScale,
  setLightSpeed,
  setThrust,
  setThrustAcceleration,
  stepBlackHole,
  type Thrust,
} from './rules';

/** What a step of the game reports (the classic game's events, or a level's). */
export type GameStepEvent = BlackHoleEvent | 'cleared' | 'waiting';

/** The game's state outside its world (lives, score, holes, the layout generator, the level run). */
interface Outside {
  game: Record<string, unknown>;
  run: Record<string, unknown> | null;
}

function save(game: BlackHoleGame, run: LevelRun | null): Outside {
  const g: Record<string, unknown> = {};
  for (const [k, v] of Object.entries(game)) if (k !== 'world') g[k] = v;
  return structuredClone({ game: g, run: run ? { ...run } : null });
}

/** Copies `from` into `into` keeping the identity of nested arrays and objects (the page holds them). */
function assignDeep(into: Record<string, unknown>, from: Record<string, unknown>): void {
  for (const [k, v] of Object.entries(from)) {
    const cur = into[k];
    if (Array.isArray(cur) && Array.isArray(v)) {
      cur.length = 0;
      cur.push(...(v as unknown[]));
    } else if (cur !== null && typeof cur === 'object' && v !== null && typeof v === 'object')
      assignDeep(cur as Record<string, unknown>, v as Record<string, unknown>);
    else into[k] = v;
  }
}

function load(game: BlackHoleGame, run: LevelRun | null, saved: Outside): void {
  assignDeep(game as unknown as Record<string, unknown>, saved.game);
  if (run && saved.run) {
    // The level spec may be a shared table entry: replaced, not written into.
    const into = run as unknown as Record<string, unknown>;
    for (const [k, v] of Object.entries(saved.run)) {
      const cur = into[k];
      if (Array.isArray(cur) && Array.isArray(v)) {
        cur.length = 0;
        cur.push(...(v as unknown[]));
      } else into[k] = v;
    }
  }
}

/**
 * The replay options of a game: its inputs by name, how to save and load its state outside the world,
 * and its step (`onStep` sees each step's event, e.g. to keep the best score).
 */
export function replayOptions(game: BlackHoleGame, run: LevelRun | null, onStep?: (event: GameStepEvent) => void): ReplayOptions {
  return {
    handlers: {
      thrust: (dir: Thrust) => setThrust(game, dir),
      beginLevel: () => {
        if (run) beginLevel(game, run);
      },
      holes: (n: number) => layoutHoles(game, n),
      gScale: (s: number) => setGScale(game, s),
      lightSpeed: (c: number) => setLightSpeed(game, c),
      thrustAcceleration: (a: number) => setThrustAcceleration(game, a),
    },
    save: () => save(game, run),
    load: (saved) => load(game, run, saved as Outside),
    step: () => {
      const event = run ? stepLevel(game, run) : stepBlackHole(game);
      onStep?.(event);
    },
  };
}

/**
 * Steps of an idle stretch a replay still shows before the input that ends it (0.5 s at 60 Hz): the
 * ship is seen on the pad before it lifts off, or the cleared field before the next level.
 */
export const REPLAY_LEAD_STEPS = 30;

/**
 * Most steps a replay plays through in one `step` call while skipping an idle stretch (a longer one
 * takes several calls), so a frame does not stall on a stretch of minutes.
 */
export const REPLAY_SKIP_MAX = 600;

/**
 * Whether the game is idle: nothing it does depends on the time that passes until the next input
 * (levels: the ship parked at the start with no thrust, or a cleared level waiting; any game: over).
 * The classic game's ship is never held, so it is idle only once over.
 */
export function isIdle(game: BlackHoleGame, run: LevelRun | null): boolean {
  if (game.over) return true;
  return run !== null && (run.waiting || (run.parked && game.thrust === 'none'));
}

/** A game's recorder and player: `input` records (ignored while a replay plays), `step` steps live or plays back. */
export interface BlackHoleReplay {
  /** The recording since the game began or the last `restart` (a level's start). */
  readonly recorder: InputRecorder;
  /**
   * Starts a new recording from the state now (the one before is dropped), so V replays from here:
   * called when a level begins, V replays the level being played (or just cleared), not the run from
   * its first level. Ignored while a replay plays.
   */
  restart(): void;
  /** The replay being played, or null. */
  readonly player: ReplayPlayer | null;
  /** Gives an input (see replayOptions' handlers); ignored while a replay plays. */
  input(name: string, ...args: unknown[]): void;
  /** One step: the replay's next one while it plays, else the live game's. */
  step(): void;
  /**
   * Rewinds to the start of the recording and plays it back (from the next `step` on); or plays
   * `recording` (another game's, made with the same options) instead of this game's. The state at the
   * call is kept for `stop`.
   */
  play(recording?: Replay): void;
  /**
   * Leaves the replay being played: the game is put back, to the last bit, in the state it had when
   * `play` was called (the live run goes on from there). No effect when none plays.
   */
  stop(): void;
}

/** Starts recording `game` (and its level run) now. */
export function createBlackHoleReplay(game: BlackHoleGame, run: LevelRun | null, onStep?: (event: GameStepEvent) => void): BlackHoleReplay {
  const options = replayOptions(game, run, onStep);
  let recorder = createInputRecorder(game.world, options);
  let player: ReplayPlayer | null = null;
  /** The played recording's input steps, in order, and the index of the next not yet given. */
  let inputSteps: number[] = [],
    nextInput = 0,
    total = 0;
  /** The state when `play` was called (`stop` returns to it). */
  let present: { world: WorldSnapshot; outside: Outside } | null = null;
  /** Steps from the player's position to the next input (to the recording's end when none is left). */
  const idleAhead = (p: ReplayPlayer): number => {
    while (nextInput < inputSteps.length && inputSteps[nextInput]! < p.played) nextInput++;
    return (nextInput < inputSteps.length ? inputSteps[nextInput]! : total) - p.played;
  };
  const finish = (): void => {
    player = null;
    present = null;
  };
  return {
    get recorder() {
      return recorder;
    },
    restart() {
      if (!player) recorder = createInputRecorder(game.world, options);
    },
    get player() {
      return player;
    },
    input(name, ...args) {
      if (!player) recorder.input(name, ...args);
    },
    step() {
      if (player) {
        // An idle stretch is played through at once, up to REPLAY_LEAD_STEPS before the input ending
        // it (at the recording's end, all of it): the same steps, so the replay still ends bit-equal.
        for (let k = 0; k < REPLAY_SKIP_MAX && isIdle(game, run) && !player.done; k++) {
          const ahead = idleAhead(player);
          if (ahead <= REPLAY_LEAD_STEPS && nextInput < inputSteps.length) break;
          player.step();
        }
        if (!player.done) player.step();
        if (player.done) finish();
      } else {
        options.step!();
      }
    },
    play(recording?: Replay) {
      const replay = recording ?? recorder.replay;
      present = { world: snapshot(game.world), outside: save(game, run) };
      player = createReplayPlayer(game.world, { ...replay, events: replay.events.slice() }, options);
      inputSteps = replay.events.map((e) => e.step);
      nextInput = 0;
      total = replay.steps;
      if (player.done) finish();
    },
    stop() {
      if (!player || !present) return;
      restore(game.world, present.world);
      load(game, run, present.outside);
      finish();
    },
  };
}
