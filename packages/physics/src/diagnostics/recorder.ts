import { assertInteger, assertOptions, describe, optionOr } from '../validation/validate.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * A quantity to record: a function of the world returning a number (J, m, kg m/s, ...).
 * @category Diagnostics
 */
export type Quantity = (world: PhysicsWorld) => number;

/**
 * Options of `createRecorder`.
 * @category Diagnostics
 */
export interface RecorderOptions {
  /** Named quantities to sample, e.g. { energy: totalEnergy, height: (w) => w.components.Position.y[ball] }. */
  quantities: Record<string, Quantity>;
  /** Record every `every` steps (integer >= 1). Default 1. */
  every?: number;
  /** Samples kept (integer >= 2); the oldest are dropped beyond it (a ring buffer). Default 10_000. */
  capacity?: number;
}

/**
 * A sampler of quantities over simulated time, for plots (uPlot takes `columns()` directly) and tests.
 * @category Diagnostics
 */
export interface Recorder {
  /** Samples currently held. */
  readonly length: number;
  /** Names of the quantities, in order. */
  readonly names: readonly string[];
  /** Takes a sample now if the step count is due (call after each step), or always with force = true. */
  sample(force?: boolean): void;
  /** Oldest-first copies: [time (s), quantity 1, quantity 2, ...]. */
  columns(): Float64Array[];
  /** Oldest-first copy of one named quantity. @throws RangeError on an unknown name. */
  series(name: string): Float64Array;
  /** Oldest-first copy of the sample times, s. */
  times(): Float64Array;
  /** Forgets every sample. */
  clear(): void;
}

/**
 * Creates a recorder of `quantities` over time, with bounded memory.
 * @throws TypeError on a missing options object, unknown or null options, or a quantity that is not a function; RangeError on bad counts.
 * @category Diagnostics
 */
export function createRecorder(world: PhysicsWorld, options: RecorderOptions): Recorder {
  const where = 'createRecorder';
  assertOptions(where, options, ['quantities', 'every', 'capacity']);
  const names = Object.keys(options.quantities ?? {});
  if (names.length === 0) throw new TypeError(`${where}: quantities must name at least one function`);
  const fns = names.map((n) => {
    const f = options.quantities[n];
    if (typeof f !== 'function') throw new TypeError(`${where}: quantity ${JSON.stringify(n)} must be a function, got ${describe(f)}`);
    return f;
  });
  const every = optionOr(where, 'every', options.every, 1, assertInteger, 1, 1_000_000_000);
  const cap = optionOr(where, 'capacity', options.capacity, 10_000, assertInteger, 2, 100_000_000);
  const data = [new Float64Array(cap), ...names.map(() => new Float64Array(cap))];
  let head = 0,
    count = 0;
  const ordered = (arr: Float64Array): Float64Array => {
    const out = new Float64Array(count);
    const start = (head - count + cap) % cap;
    for (let i = 0; i < count; i++) out[i] = arr[(start + i) % cap]!;
    return out;
  };
  return {
    get length() {
      return count;
    },
    names,
    sample(force = false) {
      if (!force && world.steps % every !== 0) return;
      data[0]![head] = world.time;
      for (let i = 0; i < fns.length; i++) data[i + 1]![head] = fns[i]!(world);
      head = (head + 1) % cap;
      if (count < cap) count++;
    },
    columns() {
      return data.map(ordered);
    },
    series(name: string) {
      const i = names.indexOf(name);
      if (i < 0) throw new RangeError(`Recorder.series: unknown quantity ${JSON.stringify(name)}; recorded: ${names.join(', ')}`);
      return ordered(data[i + 1]!);
    },
    times() {
      return ordered(data[0]!);
    },
    clear() {
      head = 0;
      count = 0;
    },
  };
}
