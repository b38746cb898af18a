import type { BodySnapshot, SceneRunOptions } from '../engines/types';

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
}
