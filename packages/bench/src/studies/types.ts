import type { SceneParam } from '../scenes/types.js';

/**
 * What a study is given: the command line's count, timing, seed and scene parameters, already
 * checked (count within the study's limit, params within their ranges with defaults filled in).
 */
export interface StudyRunOptions {
  /** Bodies of the timed worlds (`--count`), integer in [1, the study's `maxCount`]. */
  readonly count: number;
  /** Timed steps per timed world (`--steps`), integer >= 1. */
  readonly steps: number;
  /** Untimed warm-up steps per timed world before timing (`--warmup`), integer >= 0. */
  readonly warmup: number;
  /** Seed of the bodies' layout and of every world's random number generator; any finite number. */
  readonly seed: number;
  /** The study's parameters by name (`--<name> <value>`), every declared one present. */
  readonly params: Readonly<Record<string, number>>;
  /** Called with a short description of what runs next (progress on stderr; never on stdout). */
  readonly onProgress?: (what: string) => void;
}

/** A study's results: one JSON record and one table row per measured item (an integrator, a force law). */
export interface StudyResult {
  /** One object per item, printed as one JSON line each with `--json` (the study adds `scene` first). */
  readonly records: ReadonlyArray<Record<string, unknown>>;
  /** Column headings of the human table. */
  readonly header: readonly string[];
  /** Table cells, one row per item, in the order of `records`. */
  readonly rows: ReadonlyArray<readonly string[]>;
  /** Lines printed under the table (how it was measured). Never printed with `--json`. */
  readonly notes: readonly string[];
}

/**
 * A bench-only scene that is not a world to step side by side with peers but a set of measurements
 * over many small worlds (convergence orders, energy errors, per-law costs): `--scene <name>` runs
 * it, `--json` prints its records. It has no peer engines, and `--block` / `--times` do not apply.
 */
export interface BenchStudy {
  /** Name given to `--scene`. Must not clash with a scene of the physics package's `SCENES`. */
  readonly name: string;
  /** One line for `--list`. */
  readonly description: string;
  /** `--count` when none is given, integer >= 1. */
  readonly defaultCount: number;
  /** Largest `--count` accepted, integer >= `defaultCount`. */
  readonly maxCount: number;
  /** Timed and warm-up steps when `--steps` / `--warmup` are not given. */
  readonly defaults: { readonly steps: number; readonly warmup: number };
  /** Parameters by flag name (`--<name> <value>`); other scenes reject those flags. */
  readonly params?: Readonly<Record<string, SceneParam>>;
  /**
   * Runs every measurement (synchronously; may take seconds to minutes) and returns the results.
   * @throws RangeError if the options are out of the study's range (the CLI has already checked them).
   */
  run(options: StudyRunOptions): StudyResult;
}
