/**
 * Replays of black hole runs (DOM-free): every input the player gives (thrust direction, next level,
 * the panel's sliders) goes through a recorder as a named call at its step; pressing the replay key
 * rewinds to where the recording began and plays the same inputs back at the same steps, which ends
 * in the same state to the last bit (the physics is deterministic: see `snapshot` and `stateHash`).
 */
import {
  createInputRecorder,
  createReplayPlayer,
  type InputRecorder,
  type Replay,
  type ReplayOptions,
  type ReplayPlayer,
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

/** A game's recorder and player: `input` records (ignored while a replay plays), `step` steps live or plays back. */
export interface BlackHoleReplay {
  /** The recording since the game began. */
  readonly recorder: InputRecorder;
  /** The replay being played, or null. */
  readonly player: ReplayPlayer | null;
  /** Gives an input (see replayOptions' handlers); ignored while a replay plays. */
  input(name: string, ...args: unknown[]): void;
  /** One step: the replay's next one while it plays, else the live game's. */
  step(): void;
  /**
   * Rewinds to the start of the recording and plays it back (from the next `step` on); or plays
   * `recording` (another game's, made with the same options) instead of this game's.
   */
  play(recording?: Replay): void;
}

/** Starts recording `game` (and its level run) now. */
export function createBlackHoleReplay(game: BlackHoleGame, run: LevelRun | null, onStep?: (event: GameStepEvent) => void): BlackHoleReplay {
  const options = replayOptions(game, run, onStep);
  const recorder = createInputRecorder(game.world, options);
  let player: ReplayPlayer | null = null;
  return {
    recorder,
    get player() {
      return player;
    },
    input(name, ...args) {
      if (!player) recorder.input(name, ...args);
    },
    step() {
      if (player) {
        player.step();
        if (player.done) player = null;
      } else {
        options.step!();
      }
    },
    play(recording?: Replay) {
      const replay = recording ?? recorder.replay;
      player = createReplayPlayer(game.world, { ...replay, events: replay.events.slice() }, options);
      if (player.done) player = null;
    },
  };
}
