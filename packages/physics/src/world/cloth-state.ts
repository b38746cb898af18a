/**
 * The cloth solver's packed arrays, rebuilt from the `ClothLink` entities whenever links are added or
 * removed (`version` changes), not every step.
 * @category Cloth
 */
export interface ClothState {
  /** Small steps a (world sub)step, each one predict / project / update pass, integer >= 1. Default 11 (the bench's 64 x 64 cloth in 4 m/s wind with 1 m/s turbulence then stretches about 5.5% at most). */
  substeps: number;
  /** Bumped by every change to the set of links; the packed arrays are rebuilt when it differs from `built`. */
  version: number;
  built: number;
  /** Links in the packed arrays; the first `rigidCount` have zero compliance. */
  count: number;
  rigidCount: number;
  /** Per link: its entity; and (2 per link) the position offsets (3 x compact index) of its points a and b in `buffer`. */
  link: Int32Array;
  pair: Int32Array;
  /** Per link: rest length (m), compliance (m/N), tear strain. */
  rest: Float64Array;
  compliance: Float64Array;
  tear: Float64Array;
  /**
   * Distinct points of the links, then the points that lost every link since they were packed (entity
   * slots; the moving ones get their velocities from their moves).
   */
  pointCount: number;
  points: Int32Array;
  /** Generational handles of `points` (see world/handles.ts), so a point that lost every link stays a cloth point while it lives. */
  pointHandles: Float64Array;
  /** Per point, in sections of the point count n: x, y (m) and inverse mass (1/kg), 3 a point, at [0, 3n); x, y before the substep (m) at [3n, 5n); vx, vy at the start of the step (m/s) at [5n, 7n) (named in cloth/layout.ts, as `pair`, `solve` and `scalars`). */
  buffer: Float64Array;
  /** Per link (2 each): r^2 / 3 (m^2) and (2/3) / D (kg), with D = w_a + w_b + alpha~ (alpha~ = compliance / h_s^2). */
  solve: Float64Array;
  /** The packing (`built`) and the substep h_s (s) `solve` was computed for; it is recomputed when either, or a point's inverse mass, changes. */
  preparedVersion: number;
  preparedStep: number;
  /** Per entity scratch: compact index of a point while packing. */
  compact: Int32Array;
  /** Per link: XPBD multiplier of the last substep (N s^2). */
  lambda: Float64Array;
  /** Per entity scratch for packing (capacity + 1) and its stamp. */
  seen: Uint32Array;
  seenStamp: number;
  /** Largest strain (length - rest) / rest of any link after the last solve. */
  maxStretch: number;
  /** Smallest (1 + tearStretch)^2 of the packed links (Infinity when none tears): no link tears while every (L / r)^2 is at most this. */
  tearQ: number;
  /** This step's scalars for the solver's passes: h_s (s), 1 / h_s (1/s), g_x h_s, g_y h_s (m/s), g_x h, g_y h (m/s), 1 / h_s^2 (1/s^2). */
  scalars: Float64Array;
  /** Soft pins (pinClothPoint with options) in the `softPin*` arrays, rows [0, softPinCount), in the order they were made; the arrays grow by doubling. */
  softPinCount: number;
  /** Per soft pin: the handle of its point. */
  softPinHandle: Float64Array;
  /** Per soft pin (2 each): the position it pulls its point toward, x and y, m. */
  softPinTarget: Float64Array;
  /** Per soft pin: its compliance, m/N, >= 0 (1 / stiffness). */
  softPinCompliance: Float64Array;
  /** Per soft pin: the largest force it pulls with, N, > 0 (Infinity: no bound). */
  softPinMaxForce: Float64Array;
  /** Per soft pin: the force it pulled with in the last substep, N (0 when its point was not moved). */
  softPinForce: Float64Array;
}

/**
 * An empty cloth state.
 * @category Cloth
 */
export function createClothState(): ClothState {
  const state: ClothState = {
    substeps: 11,
    version: 0,
    built: 0,
    count: 0,
    rigidCount: 0,
    link: new Int32Array(0),
    pair: new Int32Array(0),
    buffer: new Float64Array(0),
    solve: new Float64Array(0),
    compact: new Int32Array(0),
    rest: new Float64Array(0),
    compliance: new Float64Array(0),
    tear: new Float64Array(0),
    pointCount: 0,
    points: new Int32Array(0),
    pointHandles: new Float64Array(0),
    lambda: new Float64Array(0),
    seen: new Uint32Array(0),
    seenStamp: 0,
    maxStretch: 0,
    tearQ: Infinity,
    scalars: new Float64Array(7),
    preparedVersion: -1,
    preparedStep: 0,
    softPinCount: 0,
    softPinHandle: new Float64Array(0),
    softPinTarget: new Float64Array(0),
    softPinCompliance: new Float64Array(0),
    softPinMaxForce: new Float64Array(0),
    softPinForce: new Float64Array(0),
  };
  // maxStretch and preparedStep hold fractions: V8 gives a field first written with 0 small-integer storage
  // and changes the object's hidden class when the first fraction arrives, which threw the solver's
  // optimised code away after its first step ("wrong map"). Writing a fraction first makes them double
  // fields from birth.
  state.maxStretch = 0.5;
  state.maxStretch = 0;
  state.preparedStep = 0.5;
  state.preparedStep = 0;
  return state;
}
