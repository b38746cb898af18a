import { step } from '../step/step.js';
import { assertOptions, describe } from '../validation/validate.js';
import type { PhysicsWorld } from '../world/options.js';
import type { WorldSnapshot } from './format.js';
import { restore, snapshot } from './snapshot.js';

/**
 * The host's structured clone (Node >= 17, every browser and worker). Typed here because the physics
 * package compiles without the DOM and Node type libraries.
 */
const cloneData = <T>(value: T): T => (globalThis as unknown as { structuredClone<V>(v: V): V }).structuredClone(value);

/**
 * Input replay: a run is its starting state plus the inputs given to it (physics calls made between
 * steps, by name, with their arguments, at step numbers). Played back from the same start, the inputs
 * reproduce the run to the last bit, because stepping is deterministic (see stateHash and snapshot).
 * Games record the clicks and keys they turn into physics calls; tests replay a failure; networked
 * games resimulate from a rollback point.
 */

/**
 * One input: handler `name` called with `args` before step `step` (0 = before the first recorded step).
 * @category Snapshots
 */
export interface InputEvent {
  /** Steps taken since the recording started when the input came. Integer >= 0. */
  readonly step: number;
  /** The handler's name (a key of the handlers given to the recorder and the player). */
  readonly name: string;
  /** Its arguments: structured-clonable data (numbers, strings, arrays, plain objects), never entities' live objects. */
  readonly args: readonly unknown[];
}

/**
 * A recorded run: everything `playReplay` needs to reproduce it.
 * @category Snapshots
 */
export interface Replay {
  /** The world's state when recording started. */
  readonly start: WorldSnapshot;
  /** State kept outside the world (a game's score, lives, level), as `save` returned it; undefined without `save`. */
  readonly outside: unknown;
  /** The inputs, in the order they were given. */
  readonly events: InputEvent[];
  /** Steps recorded so far. */
  steps: number;
}

/**
 * Handlers: the physics calls a recording may hold, by name.
 * @category Snapshots
 */
export type InputHandlers = Readonly<Record<string, (...args: never[]) => void>>;

/**
 * Options of `createInputRecorder` and `playReplay`.
 * @category Snapshots
 */
export interface ReplayOptions {
  /** The inputs by name; each is called with the recorded arguments. */
  handlers: InputHandlers;
  /** Saves state kept outside the world when recording starts (returns a structured-clonable value). Optional. */
  save?: () => unknown;
  /** Puts back what `save` returned, before a replay starts. Required with `save`. */
  load?: (saved: unknown) => void;
  /** Advances the run by one step (a game's own step, which calls `step(world)` once). Default `step(world)`. */
  step?: () => void;
}

const KNOWN = ['handlers', 'save', 'load', 'step'] as const;

function checkOptions(where: string, options: ReplayOptions): void {
  assertOptions(where, options, KNOWN);
  if (options.handlers === null || typeof options.handlers !== 'object') {
    throw new TypeError(`${where}: handlers must be an object of functions, got ${describe(options.handlers)}`);
  }
  for (const [name, fn] of Object.entries(options.handlers)) {
    if (typeof fn !== 'function') throw new TypeError(`${where}: handlers.${name} must be a function, got ${describe(fn)}`);
  }
  if ((options.save === undefined) !== (options.load === undefined)) throw new TypeError(`${where}: save and load must be given together`);
}

/**
 * Records the inputs of a run (see `createInputRecorder`).
 * @category Snapshots
 */
export interface InputRecorder {
  /** The recording so far (its `steps` follows the world). */
  readonly replay: Replay;
  /**
   * Calls handler `name` with `args` now and records it at the current step.
   * @throws RangeError for an unknown name; whatever the handler throws (then nothing is recorded).
   */
  input(name: string, ...args: unknown[]): void;
}

/**
 * Starts recording `world`: takes its snapshot (and `save()`), then logs every `input(name, ...args)`
 * at the step it came (the world's step count since now). Give every input that changes the run through
 * `input`; a change made around it is not in the recording and the replay will differ.
 * @throws TypeError on bad options.
 * @example
 * const rec = createInputRecorder(world, { handlers: { kick: (v: number) => setVelocity(world, ball, [v, 0]) } });
 * stepMany(world, 10); rec.input('kick', 3); stepMany(world, 50);
 * playReplay(world, rec.replay, { handlers }); // the same 60 steps again, bit for bit
 * @category Snapshots
 */
export function createInputRecorder(world: PhysicsWorld, options: ReplayOptions): InputRecorder {
  const where = 'createInputRecorder';
  checkOptions(where, options);
  const startSteps = world.steps;
  const replay: Replay = { start: snapshot(world), outside: options.save ? cloneData(options.save()) : undefined, events: [], steps: 0 };
  return {
    get replay() {
      replay.steps = world.steps - startSteps;
      return replay;
    },
    input(name: string, ...args: unknown[]): void {
      const fn = options.handlers[name];
      if (typeof fn !== 'function')
        throw new RangeError(
          `InputRecorder.input: name must be one of the handlers (${Object.keys(options.handlers).join(', ')}), got ${describe(name)}`,
        );
      const copy = cloneData(args);
      (fn as (...a: unknown[]) => void)(...args);
      replay.events.push({ step: world.steps - startSteps, name, args: copy });
    },
  };
}

/**
 * Plays a replay one step at a time (see `createReplayPlayer`).
 * @category Snapshots
 */
export interface ReplayPlayer {
  /** Steps played so far. */
  readonly played: number;
  /** Whether every recorded step has been played. */
  readonly done: boolean;
  /** Gives the inputs recorded before the next step, then takes it; nothing once done. */
  step(): void;
}

/**
 * Restores the start of `replay` into `world` (and `load`s the outside state), and returns a player
 * that steps through it: for frame-by-frame playback in a game. `world` must be the one recorded or one
 * made with the same options and systems.
 * @throws TypeError on bad options; RangeError as `restore`.
 * @category Snapshots
 */
export function createReplayPlayer(world: PhysicsWorld, replay: Replay, options: ReplayOptions): ReplayPlayer {
  const where = 'createReplayPlayer';
  checkOptions(where, options);
  if (replay === null || typeof replay !== 'object' || !Array.isArray(replay.events)) {
    throw new TypeError(`${where}: replay must be a recording from createInputRecorder, got ${describe(replay)}`);
  }
  const total = replay.steps;
  const events = replay.events.slice();
  for (const e of events) {
    if (typeof options.handlers[e.name] !== 'function')
      throw new RangeError(`${where}: the replay calls '${e.name}', which is not among the handlers`);
  }
  restore(world, replay.start);
  if (options.load) options.load(cloneData(replay.outside));
  const advance = options.step ?? (() => step(world));
  let played = 0,
    next = 0;
  const give = () => {
    while (next < events.length && events[next]!.step <= played) {
      const e = events[next++]!;
      (options.handlers[e.name] as (...a: unknown[]) => void)(...(cloneData(e.args) as unknown[]));
    }
  };
  return {
    get played() {
      return played;
    },
    get done() {
      return played >= total;
    },
    step(): void {
      if (played >= total) return;
      give();
      advance();
      played++;
      if (played >= total) give(); // inputs given after the last step belong to the end state
    },
  };
}

/**
 * Plays `replay` to its end in one call: restores its start into `world`, then gives each input before
 * the step it was recorded at and steps `replay.steps` times. Afterwards `world` is in the state the
 * recorded run ended in, to the last bit.
 * @throws as createReplayPlayer, and whatever a handler or step throws.
 * @category Snapshots
 */
export function playReplay(world: PhysicsWorld, replay: Replay, options: ReplayOptions): void {
  const player = createReplayPlayer(world, replay, options);
  while (!player.done) player.step();
}
