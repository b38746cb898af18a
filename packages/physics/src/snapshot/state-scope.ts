import type { PhysicsWorld } from '../world/options.js';

/** Which parts of a world a snapshot stores as state, and which only by type and length (scratch, per-step buffers, stamps). */

/**
 * Fields of the world object that are code, measurements or the machine it runs on, not state;
 * everything else is captured. `threads` and `threadPool` are the world's own: a snapshot of a world
 * with any number of threads restores into a world with any number, which keeps its pool.
 * `features` is state, but each entry is carried by the registration of the feature that made it
 * (world/external-state.ts: its name in the header's `external`, the keys kept as code).
 * `scratch` is the world's buffers and caches (world/scratch.ts), which carry nothing between steps.
 */
export const NOT_STATE = new Set([
  'stages',
  'builtins',
  'removeHooks',
  'timings',
  'entityIndex',
  'threads',
  'threadPool',
  'features',
  'scratch',
]);

/**
 * Typed arrays of the world that are scratch: written in full before they are read, within the step
 * that reads them, so they carry nothing from one step to the next (the broadphase's spatial-hash
 * grid, rebuilt by every broadphaseSystem before its pair search: collision/broadphase/grid.ts). A snapshot
 * keeps their type only and restore leaves the target world's own arrays as they are (the
 * broadphase grows them when too small). About 4 MB of a 100,000-ball world's 10.4 MB.
 */
export const SCRATCH = new Set([
  ...['bucketStart', 'sorted', 'cellX', 'cellY', 'cellZ', 'bucketOf', 'oversized', 'candidates'].map((k) => `world.collision.grid.${k}`),
  ...PER_STEP_SCRATCH(),
]);

/**
 * Collision scratch that every step writes before it reads it (checked against the step order), kept
 * as type and length only: the restored world keeps its own array when it has one of that type and
 * at least that length, and gets a zeroed one otherwise.
 * - `margin`: every ball's speculative margin, written for all balls (static ones after) at the top of
 *   broadphaseSystem, read only by the broadphase (collision/broadphase/grid.ts, broadphase-pairs*.ts).
 * - `pairA`, `pairB`, `pairKind`: the broadphase's pair list; broadphaseSystem sets `pairCount` to 0
 *   first, the narrowphase reads the first `pairCount` pairs of this step.
 * - `solverIndex`: read only for bodies whose `solverMark` equals this step's `solverStamp`, which
 *   gatherBodies (solver/contact-solver.ts) raises by one before giving indices (see STAMPED for `solverMark`).
 * - `bodyState`, `bodyExtra`: packed rows of this step's solver bodies, filled by gatherBodies for rows
 *   1 .. solverBodyCount - 1 (row 0, the static world, is zeroed there or never written) before any
 *   solver stage reads them; `bodyImpact`: zeroed up to solverBodyCount by applyImpacts (solver/impacts.ts),
 *   which runs before anything reads it.
 * - `shapes.solverRows`: the 2D manifolds' packed solver rows, filled for every manifold of the step by
 *   prepareManifolds (solver/manifold-prepare-2d.ts) before the substeps read them.
 * About 3 MB of a settled 100,000-ball world's 9 to 13 MB.
 */
function PER_STEP_SCRATCH(): string[] {
  return [
    'margin',
    'pairA',
    'pairB',
    'pairKind',
    'solverIndex',
    'bodyState',
    'bodyExtra',
    'bodyImpact',
    'impactOrder',
    'impactKey',
    'shapes.solverRows',
  ].map((k) => `world.collision.${k}`);
}

/**
 * The 2D ball contact buffers (collision/contacts.ts, ContactBuffer): a column's rows from `count` on
 * are not state (contacts.ts: rows 0..count-1 are the contacts; `storeWarmStart` swaps the two
 * buffers and leaves the new `contacts` with count 0 and stale rows, which the next step refills from
 * row 0; `growContactBuffer` keeps rows below count only). A snapshot stores each column up to its
 * count (up to its last non-zero row below it), and restore writes those rows and zeroes the rest
 * below count, leaving the world's rows from count on as they are. `contacts` holds no rows between
 * steps, so a snapshot stores none of its capacity.
 */
export const CONTACT_BUFFERS = new Set(['world.collision.contacts', 'world.collision.cache.rows']);

/**
 * Stamp-marked scratch: an array of marks and the counter they are compared with. A mark counts only
 * while it equals the counter, which its user raises by one before it marks (gatherBodies,
 * solver/contact-solver.ts: `solverMark[e] === ++solverStamp`), so every mark is at most the counter and
 * the marks' values carry nothing else. A snapshot keeps the mark array's type and length only;
 * restore keeps the world's own marks (or gives it zeroed ones) and sets the counter to the larger
 * of the snapshot's and the world's own, so no kept mark can equal a future counter value. Only the
 * counter's value differs from the original world's; no stage reads it except to compare marks.
 */
export const STAMPED: ReadonlyMap<string, { parent: (world: PhysicsWorld) => Record<string, unknown>; counter: string }> = new Map([
  [
    'world.collision.solverMark',
    { parent: (world: PhysicsWorld) => world.collision as unknown as Record<string, unknown>, counter: 'solverStamp' },
  ],
]);

/** Decoding a snapshot's header and buffer back into the typed arrays and values of a world's state, with the checks that refuse a damaged one. */

/**
 * Tag of a 2D contact tangent column stored as a note: tangent 1 of a 2D contact is (-ny, nx) as
 * prepareContacts (solver/contact-solver.ts, and its kernel) computes it, so `t1x` and `t1y` are stored as
 * a note, `{ $t: 'tangent2d', axis, len, upto, rows? }`, plus the rows that differ (a normal the
 * impact stage or the relax pass turned after the tangent was set: ~2 % of a 100,000-ball box's rows)
 * as (row, value) pairs in `rows`, a Float64Array. Restore writes -ny (axis x) or nx (axis y) into rows
 * 0 .. upto-1, then the pairs (rows from the count on are left as they are, as for every contact
 * column). Compared bit for bit (-0 included, NaN never equal) when the snapshot is taken; a 3D
 * buffer's basis differs in most rows and is stored as it is. ~0.9 MB of a settled 100,000-ball pile.
 */
export const TANGENT_2D = 'tangent2d';

/**
 * The rows i < n where `t[i]` differs in its bits from -src[i] (`negate`) or src[i], as a flat list
 * (row, t[i], row, t[i], ...), or null when more than `most` rows differ.
 */
export function tangentExceptions(t: Float64Array, src: Float64Array, negate: boolean, n: number, most: number): number[] | null {
  const pairs: number[] = [];
  const sign = negate ? -1 : 1;
  for (let i = 0; i < n; i++) {
    const a = t[i]!,
      b = sign * src[i]!;
    // === is bitwise for every value but zeros (+0 === -0, told apart by 1 / x) and NaN (never equal: a pair).
    if (a === b && (a !== 0 || 1 / a === 1 / b)) continue;
    // A NaN tangent keeps its column (a NaN's payload may not survive a trip through a JS number).
    if (pairs.length >= 2 * most || a !== a) return null;
    pairs.push(i, a);
  }
  return pairs;
}
