import type { PhysicsWorld } from '@bitphysics/physics';
import type { BodySnapshot, SceneRunOptions } from '../engines/types.js';
import type { TimeSummary } from '../stats.js';

/** A value a scene adds to an engine's result line (a JSON field and, optionally, a column). */
export type ExtraValue = number | string | boolean | null;

/** How the human-readable table shows one scene-specific field. */
export interface ExtraColumn {
  /** Field name in the extras record (and in the JSON line). */
  readonly key: string;
  /** Column heading. */
  readonly label: string;
  /** Formats the value for the table; the JSON line always carries the raw value. */
  format(value: ExtraValue): string;
}

/**
 * Measurements our engine takes of its own world while a scene runs (see `BenchScene.probe`): hooks
 * the runner calls around and between timed steps, outside the timed intervals, and the fields they
 * add to our result line.
 */
export interface SceneProbe {
  /** Before the first timed step (after warm-up and a forced garbage collection); `steps` timed steps follow. */
  beginTiming?(steps: number): void;
  /** After every timed step, outside its timed interval. Must not allocate per body. */
  afterStep?(): void;
  /** After the last timed step. */
  endTiming?(): void;
  /** The fields to add to our result line; called once, after `endTiming`. */
  extras(): Record<string, ExtraValue>;
  /**
   * Optional, for scenes whose body count changes as they run (churn): the bodies a timed step
   * moved (e.g. the median live particle count), used for body-steps per second instead of the
   * count at build time. Called after `endTiming`.
   */
  bodies?(): number;
}

/** A numeric scene parameter set from the command line (`--<name> <value>`). */
export interface SceneParam {
  /** Value when the flag is not given. */
  readonly default: number;
  /** One line for `--help` and `--list`. */
  readonly description: string;
  /** Whether the value must be an integer. */
  readonly integer?: boolean;
  /** Smallest accepted value (inclusive unless `exclusiveMin`). */
  readonly min: number;
  /** Whether `min` itself is rejected (e.g. an opening angle > 0). */
  readonly exclusiveMin?: boolean;
  /** Largest accepted value (inclusive); absent: no upper bound. */
  readonly max?: number;
}

/**
 * What the bench knows about a scene beyond the physics package's `SceneDefinition` (which gives
 * name, description and default count): its body-count limit, how to find our bodies among the
 * scene's handles, and the scene-specific fields it adds to every engine's result.
 */
export interface BenchScene {
  /** Scene name, the key in `SCENES`. */
  readonly name: string;
  /** Largest `--count` accepted (the scene's own validation limit). */
  readonly maxCount: number;
  /**
   * Our engine's entity ids of the scene's bodies in layout order, from the handles the scene's
   * `build` returned. Used for snapshots. Absent: every entity with a Position, in id order.
   */
  bodyIds?(handles: unknown): ArrayLike<number>;
  /**
   * Scene-specific result fields computed from an engine's final snapshot (after the timed steps),
   * the same way for every engine. They become extra JSON fields and, via `columns`, table columns.
   */
  extras?(snapshot: BodySnapshot, options: SceneRunOptions): Record<string, ExtraValue>;
  /** Table columns for the fields `extras` returns (fields without a column appear in JSON only). */
  readonly columns?: readonly ExtraColumn[];
  /** Lines printed under the table whenever this scene runs (notes, never on stdout in --json mode). */
  readonly notes?: readonly string[];
  /** Default timed and warm-up steps when `--steps` / `--warmup` are not given (else the CLI's 300 / 30). */
  readonly defaults?: { readonly steps?: number; readonly warmup?: number };
  /** Scene parameters by flag name (e.g. `theta` for `--theta`); other scenes reject those flags. */
  readonly params?: Readonly<Record<string, SceneParam>>;
  /**
   * Options for the scene's `worldOptions` and `build` beyond count and seed, from the run's params
   * (e.g. galaxy: `{ openingAngle: params.theta }`). Absent: `{ count, seed }` only.
   */
  sceneOptions?(options: SceneRunOptions): Record<string, unknown>;
  /**
   * Our engine only: measurements of its own world (heap, per-step particle counts, force error),
   * taken through the hooks of the returned probe. Called once, right after the scene is built.
   */
  probe?(world: PhysicsWorld, handles: unknown, options: SceneRunOptions): SceneProbe;
  /**
   * Fields derived from an engine's timing and extras after the run (e.g. galaxy's `directSpeedup`:
   * the estimated direct-sum time over the median Barnes-Hut step). Added to that engine's line.
   */
  derive?(engine: string, msPerStep: TimeSummary, extra: Readonly<Record<string, ExtraValue>>): Record<string, ExtraValue>;
}
