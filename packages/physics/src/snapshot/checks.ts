import { MAX_AUTO_SUBSTEPS } from '../solver/contact-scale.js';
import { describe } from '../validation/validate.js';
import { MAX_WIND_MODES } from '../world/force-settings.js';
import { INTEGRATOR_NAMES } from '../world/integrator-names.js';
import { MAX_TIME_STEP } from '../world/options.js';

/**
 * The checks `restore` makes on the values a snapshot holds in its header (scalars: settings, clocks,
 * counts), before it writes anything. A snapshot whose checksum is right holds what `snapshot` wrote,
 * so these checks matter for snapshots edited on purpose (and sealed again): a value the API would
 * refuse is refused here too, with the rule it breaks, so no restored world can hang or fill with
 * NaN from a setting (dt <= 0 made `step` loop forever). Typed arrays are checked by the reader
 * (offsets, lengths, encodings) and bitecs' id lists by the ECS part of restore (ids within the
 * capacity, no id twice).
 */

/** A rule a value breaks: its text (`an integer in [1, 64]`), or null when the value keeps it. */
type Rule = (v: unknown) => string | null;

const isNumber = (v: unknown): v is number => typeof v === 'number';
const nonNegative: Rule = (v) => (isNumber(v) && Number.isFinite(v) && v >= 0 ? null : 'a finite number >= 0');
const positive: Rule = (v) => (isNumber(v) && Number.isFinite(v) && v > 0 ? null : 'a finite number > 0');
const integer =
  (min: number, max: number): Rule =>
  (v) =>
    Number.isInteger(v) && (v as number) >= min && (v as number) <= max ? null : `an integer in [${min}, ${max}]`;
const int32: Rule = integer(-(2 ** 31), 2 ** 31 - 1);
const count: Rule = integer(0, Number.MAX_SAFE_INTEGER);

/** Rules by path in the world's state tree (external state by its registered name). */
const RULES: ReadonlyMap<string, Rule> = new Map<string, Rule>([
  ['world.dt', (v) => (isNumber(v) && v > 0 && v <= MAX_TIME_STEP ? null : `a number in (0, ${MAX_TIME_STEP}] s (MAX_TIME_STEP)`)],
  ['world.substeps', integer(1, 64)],
  ['world.h', positive],
  ['world.integrator', (v) => ((INTEGRATOR_NAMES as readonly unknown[]).includes(v) ? null : 'an integrator name')],
  ['world.steps', count],
  // The clock runs from 0 up: a negative time is no state a world reaches (and drives time-dependent forces).
  ['world.time', nonNegative],
  ['world.rng.a', int32],
  ['world.rng.b', int32],
  ['world.rng.c', int32],
  ['world.rng.d', int32],
  ['world.laws.openingAngle', nonNegative],
  ['world.laws.gravitySoftening', nonNegative],
  ['world.laws.electricSoftening', nonNegative],
  ['world.laws.wind.modes', integer(0, MAX_WIND_MODES)],
  ['world.laws.wind.gustOmega', nonNegative],
  ['world.collision.settings.solverSubsteps', integer(1, Math.max(16, MAX_AUTO_SUBSTEPS))],
  ['world.collision.settings.solverIterations', integer(1, 50)],
  ['world.collision.settings.relaxIterations', integer(0, 50)],
  ['world.collision.settings.impactIterations', integer(0, 64)],
  ['world.collision.settings.restitutionIterations', integer(0, 64)],
  ['world.collision.settings.coloredSolveMinRows', count],
  [
    'world.collision.grid.tableSize',
    (v) => (Number.isInteger(v) && (v as number) >= 0 && (v as number) <= 2 ** 28 ? null : 'an integer in [0, 2^28]'),
  ],
  // The boundary's material, as setBoundary takes it.
  ['world.collision.boundary.restitution', (v) => (isNumber(v) && v >= 0 && v <= 1 ? null : 'a number in [0, 1]')],
  ['world.collision.boundary.friction', nonNegative],
  ['world.collision.boundary.staticFriction', nonNegative],
  ['world.collision.grid.cellSize', positive],
  ['world.joints.settings.iterations', integer(0, 100)],
  ['world.cloth.substeps', integer(0, 1000)],
  // The links' version the cloth solver last prepared for; -1 before its first preparation.
  ['world.cloth.preparedVersion', integer(-1, Number.MAX_SAFE_INTEGER)],
  ['world.cloth.tearQ', (v) => (isNumber(v) && v >= 0 ? null : 'a number >= 0 (Infinity: no tearing)')],
]);

/**
 * The world's fields fixed when it is made (its options): a snapshot restores only into a world with
 * the same, which the header's copy checks; the state's copy must agree, or restore would write
 * another value (a NaN dimension) over the world's own.
 */
const FIXED: ReadonlySet<string> = new Set(['world.dimensions', 'world.capacity']);

/** Keys whose number is a count, a size, an index or a stamp: an integer >= 0 wherever it is. */
const COUNT_KEY = /^(count|size|capacity|head|budget|stamp|epoch|version|built)$|Count$|Stamp$/;

/**
 * Checks every scalar of a snapshot's state tree (`state`, and each registered external state under
 * its name): the rules above by path, counts (COUNT_KEY) as integers >= 0 and at most their object's
 * `capacity`, every other number finite (no state the engine reaches holds NaN or an infinity outside
 * the rules, such as the cloth's tearQ; external states' numbers are the user's), and each scalar of the type the target
 * world holds at the same path (`world`: a number stays a number, a boolean a boolean, a string a
 * string; null only where the world holds null), so an edited snapshot cannot put null or a string
 * where the engine reads a number.
 * @throws RangeError `restore: snapshot's <path> must be <rule>, got <value>`.
 * @category Snapshots
 */
export function checkSnapshotValues(state: unknown, external: Record<string, unknown>, world?: object): void {
  walk(state, 'world', world);
  for (const [name, enc] of Object.entries(external)) walk(enc, name, undefined);
}

/** The type a live value's encoding must have, or undefined where any is allowed (no live value, objects). */
function liveType(live: unknown): string | undefined {
  if (live === null) return 'null';
  const t = typeof live;
  return t === 'number' || t === 'boolean' || t === 'string' ? t : undefined;
}

/** The number an encoded scalar stands for (see Writer.value: non-finite numbers and -0 are tagged). */
function scalar(e: unknown): unknown {
  if (typeof e === 'object' && e !== null && !Array.isArray(e) && (e as { $t?: unknown }).$t === 'n') {
    const v = (e as { v?: unknown }).v;
    return v === '-0' ? -0 : typeof v === 'string' ? Number(v) : undefined;
  }
  return e;
}

function fail(path: string, rule: string, v: unknown): never {
  throw new RangeError(`restore: snapshot's ${path} must be ${rule}, got ${describe(v)}`);
}

function walk(e: unknown, path: string, live: unknown): void {
  if (typeof e !== 'object' || e === null || Array.isArray(e) || (e as { $t?: unknown }).$t === 'n') {
    const v = scalar(e);
    const want = liveType(live);
    // null stands for a value the world keeps empty (a lazily made store): allowed where an object lives.
    if (want !== undefined && want !== (v === null ? 'null' : typeof v)) fail(path, `a ${want} (as the world holds)`, v);
    if (FIXED.has(path) && live !== undefined && v !== live)
      fail(path, `${describe(live)}, as in the world it restores into (fixed when a world is made)`, v);
    check(v, path, path.slice(path.lastIndexOf('.') + 1));
    return;
  }
  const t = (e as { $t?: unknown }).$t;
  const v = (e as { v?: unknown }).v;
  if (t === 'o') {
    if (typeof v !== 'object' || v === null || Array.isArray(v)) fail(path, 'an encoded object', v);
    const o = v as Record<string, unknown>;
    const inner = typeof live === 'object' && live !== null && !ArrayBuffer.isView(live) ? (live as Record<string, unknown>) : undefined;
    for (const [key, x] of Object.entries(o)) walk(x, `${path}.${key}`, inner === undefined ? undefined : inner[key]);
    // A count of rows is at most the rows there is room for.
    const cap = scalar(o.capacity);
    if (typeof cap === 'number') {
      for (const key of Object.keys(o)) {
        const n = scalar(o[key]);
        if (key !== 'capacity' && /^count$|Count$/.test(key) && typeof n === 'number' && n > cap)
          fail(`${path}.${key}`, `at most ${path}.capacity (${cap})`, n);
      }
    }
    return;
  }
  if (t === 'a' || t === 's' || t === 'm') {
    if (!Array.isArray(v)) fail(path, 'an encoded list', v);
    for (const x of v as unknown[]) {
      if (t === 'm') {
        if (!Array.isArray(x) || x.length !== 2) fail(path, 'a list of [key, value] pairs', x);
        walk(x[0], `${path} (map key)`, undefined);
        walk(x[1], `${path} (map value)`, undefined);
      } else walk(x, `${path}[]`, undefined);
    }
  }
  // Typed arrays and other tags: checked by the reader.
}

function check(v: unknown, path: string, key: string): void {
  const rule = RULES.get(path);
  if (rule !== undefined) {
    const broken = rule(v);
    if (broken !== null) fail(path, broken, v);
    return;
  }
  if (typeof v !== 'number') return;
  if (COUNT_KEY.test(key)) {
    const broken = count(v);
    if (broken !== null) fail(path, broken, v);
    return;
  }
  // External states are the user's: a best time of Infinity is theirs to keep.
  if (path.startsWith('world.') && !Number.isFinite(v)) fail(path, 'a finite number', v);
}
