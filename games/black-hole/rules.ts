/**
 * Black hole: the game of Ramtal and Dobre (ch. 6, Newtonian gravity), DOM-free so its rules run in
 * Node tests. The page (main.ts) adds keys, touch buttons, drawing and the panel.
 *
 * The rules:
 * - The player's ship starts near the bottom of a `FIELD` (32 m x 24 m) and thrusts with the arrow
 *   keys (two at right angles held together aim it between them: `heldThrust`) with acceleration
 *   `thrust` (m/s^2), whatever the direction. The engine starts gently and then builds up to full
 *   thrust over `THRUST_RAMP.up`, and dies over `THRUST_RAMP.down` (`rampThrust`), so a tap is a
 *   small nudge and a held arrow full thrust.
 * - Black holes of random size pull it with Newtonian gravity F = G M m / d^2 (the physics package's
 *   attractors). Each hole's mass is set so that its drawn radius r is its Schwarzschild radius,
 *   r = 2 G M / c^2, that is M = c^2 r / (2 G) (Schwarzschild 1916; any general relativity text,
 *   e.g. Schutz, A First Course in General Relativity, ch. 11).
 * - Crossing the line near the top scores the number of holes on screen, adds a hole and lays them
 *   all out again; the ship goes back to the start.
 * - Falling into a hole (the ship, SHIP_RADIUS m round its centre, touching its horizon during a
 *   step) costs one of three lives; the ship goes back to the start.
 * - Leaving the field puts the ship back at the start without penalty. On a field narrower than
 *   `FIELD` (a phone's) soft side walls turn a coasting ship back (`SOFT_WALL`), the sideways
 *   thrust is weaker (`BlackHoleOptions.sideScale`) and a side arrow alone builds at most
 *   `NARROW_SIDE_SPEED` sideways.
 * - At zero lives the game is over (the page restarts it with a key).
 *
 * Game-scale constants (SI would make a 1 m hole weigh 6.7e26 kg): G = `G_GAME` = 1 m^3 kg^-1 s^-2
 * and c = `C_GAME` = 10 m/s, so a hole of radius r has mass M = c^2 r / 2G = 50 r kg and pulls with
 * g(d) = G M / d^2 = c^2 r / (2 d^2): 12.5 m/s^2 at two radii. At the horizon the escape speed
 * sqrt(2 G M / r) equals c. The panel scales G and changes c; each hole keeps its mass and its
 * horizon follows r = 2 G M / c^2, so the relation always holds. Note that with r fixed the pull
 * c^2 r / (2 d^2) does not depend on G at all; a larger G grows the horizons instead.
 *
 * Beyond the book: exhaust particles from an emitter attached to the ship (enabled while thrusting,
 * pointing against the thrust; they feel the holes too and vanish into horizons), and the ship's
 * predicted path for the next seconds (the page draws 3 s of it; `pathEnd` says whether it falls in, is
 * lost off the field or stays clear), integrated in a small second world that holds copies of the
 * holes and of the ship (`createPredictor`), with the same force laws, step and integrator, so with
 * the input held it is exactly the path the ship will take.
 */

import {
  addBody,
  addEmitter,
  addSystem,
  createPhysicsWorld,
  handleOf,
  type PhysicsWorld,
  Rng,
  removeBody,
  setAttractor,
  setEmitterEnabled,
  setGravitation,
  setPosition,
  setVelocity,
  slotOf,
  step,
} from '@bitphysics/physics';
import { query } from 'bitecs';

/** The playing field, m: x in [0, width], y in [0, height]. Leaving it sends the ship back to the start. */
export const FIELD = Object.freeze({ width: 32, height: 24 });

/** The finish line: crossing y = LINE_Y (m) scores. */
export const LINE_Y = FIELD.height - 2;

/** Where the ship starts, m. */
export const START: readonly [number, number] = Object.freeze([FIELD.width / 2, 1.5]);

/** Game-scale gravitational constant, m^3 kg^-1 s^-2 (the panel scales it). */
export const G_GAME = 1;

/** Game-scale speed of light, m/s. */
export const C_GAME = 10;

/** Radius range of a new hole, m. */
export const HOLE_RADIUS: readonly [number, number] = Object.freeze([0.5, 1.4]);

/** Most holes on the field in the classic game and in a level's scattered holes; scoring beyond it keeps the count. */
export const MAX_HOLES = 16;

/**
 * Most holes any layout puts on the field, a level's wall of small holes included (./levels.ts): the
 * predictor's world holds this many.
 */
export const MAX_FIELD_HOLES = 40;

/** The ship's mass, kg. */
export const SHIP_MASS = 1;

/**
 * The ship's size for the horizons, m: it falls in when its centre comes within a horizon's radius
 * plus this (the drawn ship is about 0.8 m wide, so it goes when it is seen to touch the black
 * disc). Its motion is a point's.
 */
export const SHIP_RADIUS = 0.3;

/**
 * How the engine answers an arrow, from rest: it first builds gently, at `trim` x thrust / `gentle`
 * m/s^3, up to `trim` of the thrust in `gentle` s, then quickly up to full thrust by `up` s; let go,
 * it dies from full to nothing in `down` s. With the default 6 m/s^2 a 0.15 s tap changes the speed
 * by 0.16 m/s (a small nudge a player can repeat to trim the course), a 0.3 s press by 0.7 m/s,
 * and an arrow held for 1 s by 5 m/s (counting the die-away). The thrust vector moves towards
 * the arrow's (a change of direction swings it over at the quick rate, unless it passes near
 * nothing, as reversing does: then the new direction starts gently, as a fresh press would). See
 * `rampThrust`.
 */
export const THRUST_RAMP = Object.freeze({ trim: 0.4, gentle: 0.2, up: 0.4, down: 0.1 });

/**
 * The default `sideRamp` of a field narrower than `FIELD` (a phone held upright plays one 20 m wide),
 * s: the sideways thrust grows at most at thrust / 0.9 = 6.7 m/s^3 there, so from rest a 0.5 s hold of
 * → gains about 1 m/s (2 m/s at THRUST_RAMP.up: 10 m to the edge in some 5 s, or under 2 s where a
 * loaded phone's hold ran long), a tap about 0.25 m/s, and an arrow held 1 s about 3.6 m/s: for the
 * field's width, a little more than the 5 m/s the 32 m wide field's engine gives.
 */
export const NARROW_SIDE_RAMP = 0.9;

/**
 * The soft side walls of a field narrower than `FIELD` (a phone's): within `width` m of a side edge
 * the ship is pushed back towards the middle at up to `push` m/s^2 (at the edge, falling off linearly
 * to 0 at `width` m in), plus `damp` s^-1 times its speed towards the edge, unless the engine thrusts
 * towards that edge (a held arrow still flies out, so a held diagonal leaves the field as before). A
 * ship drifting out after a tap turns back: coasting, it is stopped within `width` m from up to
 * sqrt(push x width) = 6.5 m/s, and from the top sideways speed a side arrow builds there
 * (`NARROW_SIDE_SPEED`, 3 m/s) within 3 sqrt(width / push) = 1.4 m, 1.6 m inside the field. See
 * `softWallPush`.
 */
export const SOFT_WALL = Object.freeze({ width: 3, push: 14, damp: 3 });

/**
 * The top sideways speed the engine builds on a field narrower than `FIELD` (a phone's), m/s: its
 * sideways push fades out over the last `SIDE_SPEED_FADE` m/s below it (`sideThrustShare`), so an arrow
 * held for a second or more flies the ship sideways at this speed, not faster; the soft side walls
 * (`SOFT_WALL`) stop a ship coasting at it well inside the field. Only while a side arrow is held
 * alone (a dodge): a diagonal (a climb that steers) keeps the engine's whole sideways push, so a held
 * diagonal still leaves the field, as the levels' layout check (./levels.ts `heldThrustClears`)
 * expects. Coasting, falling and the holes' pull are not limited.
 */
export const NARROW_SIDE_SPEED = 3;

/**
 * The sideways kick a side arrow gives the ship the moment it is pressed on a field narrower than
 * `FIELD` (a phone's), m/s: a tap there is a short press, whose thrust alone (built up at the narrow
 * field's gentle `NARROW_SIDE_RAMP`) barely changed the course; with the kick a tap is a visible
 * nudge of about 1 m/s, and a hold builds on from it to `NARROW_SIDE_SPEED`. The kick never takes the
 * sideways speed along the arrow past the top speed (`BlackHoleOptions.sideSpeed`).
 */
export const SIDE_TAP_KICK = 0.7;

/** The band of sideways speed, m/s, below the top one (`BlackHoleOptions.sideSpeed`) over which the engine's sideways push fades to 0. */
export const SIDE_SPEED_FADE = 0.75;

/**
 * The share, in [0, 1], of the engine's sideways acceleration `engineX` (m/s^2) that acts on a ship
 * moving sideways at vx (m/s) with top sideways speed `top` (m/s; Infinity: no limit): 1 while the
 * engine pushes against the motion or the speed along the push is at most top - SIDE_SPEED_FADE,
 * falling linearly to 0 at `top` and beyond.
 */
export function sideThrustShare(engineX: number, vx: number, top: number): number {
  if (engineX === 0 || !(top < Infinity)) return 1;
  const along = engineX > 0 ? vx : -vx;
  return Math.max(0, Math.min(1, (top - along) / SIDE_SPEED_FADE));
}

/**
 * The acceleration, m/s^2 (+x towards the middle from the left edge), of the soft side walls on a
 * ship at x (m) moving at vx (m/s) in a field `fieldWidth` m wide whose engine thrusts at `engineX`
 * m/s^2 sideways, walls `wall` m wide (0: none): within `wall` m of the left edge,
 * SOFT_WALL.push x (1 - x / wall) + SOFT_WALL.damp x max(0, -vx), unless engineX < 0 (thrusting
 * towards that edge); the mirror of it at the right edge; 0 elsewhere, outside the field included
 * (the ship is lost there).
 */
export function softWallPush(x: number, vx: number, engineX: number, fieldWidth: number, wall: number): number {
  if (!(wall > 0)) return 0;
  if (x >= 0 && x < wall && !(engineX < 0)) return SOFT_WALL.push * (1 - x / wall) + SOFT_WALL.damp * Math.max(0, -vx);
  const d = fieldWidth - x;
  if (d >= 0 && d < wall && !(engineX > 0)) return -(SOFT_WALL.push * (1 - d / wall) + SOFT_WALL.damp * Math.max(0, vx));
  return 0;
}

/**
 * Thrust directions: none, one of the four arrows, or two arrows at right angles held together
 * (a diagonal, e.g. 'up-right').
 */
export type Thrust = 'none' | 'up' | 'down' | 'left' | 'right' | 'up-left' | 'up-right' | 'down-left' | 'down-right';

/** One arrow: the four thrust directions a key or a pad button gives. */
export type Arrow = 'up' | 'down' | 'left' | 'right';

/**
 * The unit vector of each thrust direction. A diagonal is the sum of its two arrows normalised to
 * length 1: the ship has one engine (one flame, drawn opposite the thrust; one fuel tank burning a
 * second a second) that points where the arrows say, so two arrows held aim it between them
 * rather than add a second engine. That keeps the acceleration `thrust` m/s^2 whatever is held, and
 * with it the levels' tuning, which measures the holes' pull against the thrust (./levels.ts).
 */
export const THRUST_DIRECTION: Readonly<Record<Thrust, readonly [number, number]>> = Object.freeze({
  none: [0, 0],
  up: [0, 1],
  down: [0, -1],
  left: [-1, 0],
  right: [1, 0],
  'up-left': [-Math.SQRT1_2, Math.SQRT1_2],
  'up-right': [Math.SQRT1_2, Math.SQRT1_2],
  'down-left': [-Math.SQRT1_2, -Math.SQRT1_2],
  'down-right': [Math.SQRT1_2, -Math.SQRT1_2],
});

/**
 * The thrust of the arrows held, `held` in the order they were pressed (oldest first): the latest of
 * up / down held and the latest of left / right held, combined into a diagonal when there is one of
 * each ('up' and 'right' give 'up-right'); of two opposite arrows the later wins, as with one key
 * over another. No arrows give 'none'.
 * @throws RangeError on an entry that is not an arrow.
 */
export function heldThrust(held: readonly Arrow[]): Thrust {
  let vertical: 'up' | 'down' | '' = '',
    horizontal: 'left' | 'right' | '' = '';
  for (const a of held) {
    if (a === 'up' || a === 'down') vertical = a;
    else if (a === 'left' || a === 'right') horizontal = a;
    else throw new RangeError(`black-hole: heldThrust: held must hold only up, down, left, right, got ${JSON.stringify(a)}`);
  }
  if (vertical && horizontal) return `${vertical}-${horizontal}`;
  return vertical || horizontal || 'none';
}

/**
 * The thrust a ship parked on the start pad takes when `thrust` is asked: its downward part dropped
 * ('down' gives 'none', 'down-left' and 'down-right' give 'left' and 'right'); any other unchanged.
 * @throws RangeError if `thrust` is not a `Thrust`.
 */
export function padThrust(thrust: Thrust): Thrust {
  if (!(thrust in THRUST_DIRECTION)) throw new RangeError(`black-hole: padThrust: thrust must be a Thrust, got ${JSON.stringify(thrust)}`);
  if (thrust === 'down') return 'none';
  if (thrust === 'down-left') return 'left';
  if (thrust === 'down-right') return 'right';
  return thrust;
}

/** What happened in a step. */
export type BlackHoleEvent = 'none' | 'fell' | 'scored' | 'lost' | 'over';

/** Options of the game. Every field optional. */
export interface BlackHoleOptions {
  /** Seed of the hole layouts. Any finite number. Default 1. */
  seed?: number;
  /** Holes at the start, integer in [1, MAX_HOLES]. Default 3. */
  holes?: number;
  /** G as a multiple of G_GAME, in [0.1, 10]. Default 1. */
  gScale?: number;
  /** Speed of light, m/s, in [2, 50]. Default C_GAME (10). */
  c?: number;
  /** Thrust acceleration, m/s^2, in [0, 40]. Default 6. */
  thrust?: number;
  /** Lives at the start, integer in [1, 9]. Default 3. */
  lives?: number;
  /**
   * How long the sideways part of the thrust takes to build up, s, in [THRUST_RAMP.up, 2]: a gentler
   * sideways engine for a narrow field (a phone's, where a short hold of → drifted off the edge).
   * Default NARROW_SIDE_RAMP on a field narrower than `FIELD`, else THRUST_RAMP.up (the sideways part
   * builds as fast as the rest). See `rampThrust`.
   */
  sideRamp?: number;
  /**
   * The share of the thrust an arrow gives sideways, in [0.3, 1]: a narrow field needs less sideways
   * speed for its width. Default (1 + width / FIELD.width) / 2 on a field narrower than `FIELD`
   * (0.8125 on a phone's 20 m: the full share, width / FIELD.width, made the crossing to level 2's
   * gap too slow for a slow player), else 1. Up and down keep the full thrust; a diagonal aims steeper.
   */
  sideScale?: number;
  /**
   * Width of the soft side walls, m, in [0, 5] (0: none; see SOFT_WALL and `softWallPush`). Default
   * SOFT_WALL.width on a field narrower than `FIELD`, else 0.
   */
  softWall?: number;
  /**
   * The top sideways speed the engine builds, m/s, in [1, Infinity] (Infinity: no limit; see
   * `sideThrustShare`). Default NARROW_SIDE_SPEED on a field narrower than `FIELD`, else Infinity.
   */
  sideSpeed?: number;
  /**
   * The sideways speed, m/s, in [0, 3], a side arrow adds at once when its press begins (see
   * SIDE_TAP_KICK and `stepBlackHole`). Default SIDE_TAP_KICK on a field narrower than `FIELD`, else 0.
   */
  sideKick?: number;
  /**
   * Whether the ship waits parked on the start pad after each reset (the start of the game, a fall,
   * an exit, a crossing): held at rest there, the holes' pull ignored, until an arrow with a part
   * other than ↓ thrusts; the downward part of an arrow held meanwhile is dropped (`padThrust`), so ↓
   * cannot fly it off the bottom of the field. Default false (./levels.ts parks its ship itself).
   */
  park?: boolean;
  /**
   * Size of the playing field, m: width in [12, 64], height in [16, 64]. Default `FIELD` (32 x 24);
   * a phone held upright plays a tall one. The start is at the middle of the bottom, 1.5 m up, and
   * the finish line 2 m below the top.
   */
  field?: FieldSize;
}

/** A playing field's size, m: x in [0, width], y in [0, height]. */
export interface FieldSize {
  readonly width: number;
  readonly height: number;
}

/** Resolved options. */
export type BlackHoleParams = Required<Omit<BlackHoleOptions, 'field'>> & {
  readonly field: FieldSize;
};

/** The state of a game: world, ship, holes, lives, score, last message. */
export interface BlackHoleGame {
  readonly world: PhysicsWorld;
  readonly params: BlackHoleParams;
  /** The ship's entity id. */
  readonly ship: number;
  /** Hole entity ids, their horizon radii (m) and masses (kg), same order. */
  readonly holes: number[];
  readonly holeRadius: number[];
  readonly holeMass: number[];
  /** Lives left, score, and whether the game is over (lives 0). */
  lives: number;
  score: number;
  over: boolean;
  /** The last message for the player. */
  message: string;
  /** The current thrust direction (set with `setThrust`). */
  thrust: Thrust;
  /** The engine's acceleration now, m/s^2 (x, y): it follows `thrust` at the rates of `THRUST_RAMP`. */
  readonly thrustVec: [number, number];
  /** Counts of events since the start. */
  falls: number;
  crossings: number;
  resets: number;
  /**
   * Whether the ship waits parked at the start (`params.park`: from each reset until an arrow other
   * than ↓ thrusts); always false without `params.park`.
   */
  parked: boolean;
  /**
   * The sign of the sideways part of the thrust at the last step (-1 left, 0 none, 1 right): a step
   * whose side differs from it, not 0, is a new side press, which kicks (`params.sideKick`).
   */
  side: number;
  /** Bumped whenever the holes change (layout, G, c), so copies (the predictor) know to resync. */
  version: number;
  /** Generator of the layouts. */
  readonly rng: Rng;
  /** The playing field (`params.field`), m: x in [0, width], y in [0, height]. */
  readonly field: FieldSize;
  /** Where the ship starts, m: the middle of the field's bottom, 1.5 m up. */
  readonly start: readonly [number, number];
  /** The finish line: crossing y = lineY (m, 2 m below the top) scores. */
  readonly lineY: number;
  /**
   * Whether crossing the line scores now (default true). A level closes it while rings are left to fly
   * through (./levels.ts `LevelSpec.rings`): the ship then flies on past the line and leaves the field.
   */
  lineOpen: boolean;
}

function check(cond: boolean, message: string): void {
  if (!cond) throw new RangeError(`black-hole: ${message}`);
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolveBlackHoleOptions(options: BlackHoleOptions = {}): BlackHoleParams {
  const known = [
    'seed',
    'holes',
    'gScale',
    'c',
    'thrust',
    'lives',
    'sideRamp',
    'sideScale',
    'softWall',
    'sideSpeed',
    'sideKick',
    'park',
    'field',
  ];
  for (const k of Object.keys(options)) {
    if (!known.includes(k)) throw new TypeError(`black-hole: unknown option ${JSON.stringify(k)}; known options are ${known.join(', ')}`);
  }
  const fieldWidth = options.field?.width ?? FIELD.width,
    narrow = fieldWidth < FIELD.width;
  const p: BlackHoleParams = {
    seed: options.seed ?? 1,
    holes: options.holes ?? 3,
    gScale: options.gScale ?? 1,
    c: options.c ?? C_GAME,
    thrust: options.thrust ?? 6,
    lives: options.lives ?? 3,
    sideRamp: options.sideRamp ?? (narrow ? NARROW_SIDE_RAMP : THRUST_RAMP.up),
    sideScale: options.sideScale ?? (narrow ? (1 + fieldWidth / FIELD.width) / 2 : 1),
    softWall: options.softWall ?? (narrow ? SOFT_WALL.width : 0),
    sideSpeed: options.sideSpeed ?? (narrow ? NARROW_SIDE_SPEED : Infinity),
    sideKick: options.sideKick ?? (narrow ? SIDE_TAP_KICK : 0),
    park: options.park ?? false,
    field: { width: options.field?.width ?? FIELD.width, height: options.field?.height ?? FIELD.height },
  };
  check(Number.isFinite(p.seed), `seed must be finite, got ${p.seed}`);
  check(Number.isInteger(p.holes) && p.holes >= 1 && p.holes <= MAX_HOLES, `holes must be an integer in [1, ${MAX_HOLES}], got ${p.holes}`);
  checkGScale(p.gScale);
  checkC(p.c);
  checkThrust(p.thrust);
  check(Number.isInteger(p.lives) && p.lives >= 1 && p.lives <= 9, `lives must be an integer in [1, 9], got ${p.lives}`);
  check(
    typeof p.sideRamp === 'number' && p.sideRamp >= THRUST_RAMP.up && p.sideRamp <= 2,
    `sideRamp must be in [${THRUST_RAMP.up}, 2] s, got ${String(p.sideRamp)}`,
  );
  check(
    typeof p.field.width === 'number' && p.field.width >= 12 && p.field.width <= 64,
    `field.width must be in [12, 64] m, got ${String(p.field.width)}`,
  );
  check(
    typeof p.field.height === 'number' && p.field.height >= 16 && p.field.height <= 64,
    `field.height must be in [16, 64] m, got ${String(p.field.height)}`,
  );
  check(
    typeof p.sideScale === 'number' && p.sideScale >= 0.3 && p.sideScale <= 1,
    `sideScale must be in [0.3, 1], got ${String(p.sideScale)}`,
  );
  check(typeof p.softWall === 'number' && p.softWall >= 0 && p.softWall <= 5, `softWall must be in [0, 5] m, got ${String(p.softWall)}`);
  check(typeof p.sideKick === 'number' && p.sideKick >= 0 && p.sideKick <= 3, `sideKick must be in [0, 3] m/s, got ${String(p.sideKick)}`);
  check(typeof p.park === 'boolean', `park must be a boolean, got ${String(p.park)}`);
  check(typeof p.sideSpeed === 'number' && p.sideSpeed >= 1, `sideSpeed must be in [1, Infinity] m/s, got ${String(p.sideSpeed)}`);
  return p;
}

function checkGScale(s: number): void {
  check(s >= 0.1 && s <= 10, `gScale must be in [0.1, 10], got ${s}`);
}
function checkC(c: number): void {
  check(c >= 2 && c <= 50, `c must be in [2, 50] m/s, got ${c}`);
}
function checkThrust(a: number): void {
  check(a >= 0 && a <= 40, `thrust must be in [0, 40] m/s^2, got ${a}`);
}

/**
 * Mass, kg, of a black hole whose Schwarzschild radius is `radius` m: M = c^2 r / (2 G).
 * @param c speed of light, m/s (> 0). @param G gravitational constant, m^3 kg^-1 s^-2 (> 0).
 * @throws RangeError unless radius, c and G are finite and > 0.
 */
export function schwarzschildMass(radius: number, c: number, G: number): number {
  check(
    radius > 0 && c > 0 && G > 0 && Number.isFinite(radius * c * G),
    `schwarzschildMass: radius, c and G must be finite and > 0, got ${radius}, ${c}, ${G}`,
  );
  return (c * c * radius) / (2 * G);
}

/**
 * Schwarzschild radius, m, of mass `mass` kg: r = 2 G M / c^2.
 * @throws RangeError unless mass, c and G are finite and > 0.
 */
export function schwarzschildRadius(mass: number, c: number, G: number): number {
  check(
    mass > 0 && c > 0 && G > 0 && Number.isFinite(mass * c * G),
    `schwarzschildRadius: mass, c and G must be finite and > 0, got ${mass}, ${c}, ${G}`,
  );
  return (2 * G * mass) / (c * c);
}

/** The gravitational constant in use, m^3 kg^-1 s^-2. */
export function gravitationalConstant(game: BlackHoleGame): number {
  return G_GAME * game.params.gScale;
}

/**
 * One step of the engine: moves `vec` (the thrust now, m/s^2) towards the target (tx, ty) m/s^2 by
 * at most `rate` x dt. While an arrow is held (the target is not zero) the rate is
 * trim x full / gentle while |vec| is under trim x full and growing (the gentle start; growing: vec
 * does not point away from the target, so a reversal first dies down at the quick rate), else
 * (1 - trim) x full / (up - gentle), the constants those of `THRUST_RAMP`; when it is let go the
 * rate is full / THRUST_RAMP.down. `full` is the thrust acceleration (m/s^2, the larger of it and
 * |vec|, so a thrust slider set to 0 still lets the engine die away).
 * While an arrow is held the sideways part (x) grows in size by at most full / `sideUp` x dt a step
 * (`sideUp` s >= THRUST_RAMP.up, default THRUST_RAMP.up, where the cap is not applied): a slower
 * sideways build-up for a narrow field; letting go is as quick as ever.
 * @throws RangeError unless dt > 0, full >= 0 and sideUp >= THRUST_RAMP.up are finite.
 */
export function rampThrust(vec: [number, number], tx: number, ty: number, full: number, dt: number, sideUp: number = THRUST_RAMP.up): void {
  // Checked without building the message first: this runs every step of the game and the predictor.
  if (!(dt > 0 && full >= 0 && sideUp >= THRUST_RAMP.up && Number.isFinite(dt * full * sideUp)))
    throw new RangeError(
      `black-hole: rampThrust: dt must be > 0, full >= 0 and sideUp >= ${THRUST_RAMP.up}, got ${dt}, ${full}, ${sideUp}`,
    );
  const x0 = vec[0],
    y0 = vec[1];
  const dx = tx - x0,
    dy = ty - y0,
    gap = Math.hypot(dx, dy);
  const held = tx !== 0 || ty !== 0;
  const size = Math.hypot(x0, y0),
    big = Math.max(full, size);
  let rate: number;
  if (!held) rate = big / THRUST_RAMP.down;
  // (Below trim by more than rounding: a sum of equal steps can fall an ulp short of it.)
  else if (size < THRUST_RAMP.trim * big * (1 - 1e-9) && x0 * dx + y0 * dy >= 0) rate = (THRUST_RAMP.trim * big) / THRUST_RAMP.gentle;
  else rate = ((1 - THRUST_RAMP.trim) * big) / (THRUST_RAMP.up - THRUST_RAMP.gentle);
  // Reached within rounding too (a rate such as (1 - trim) x 6 / (up - gentle) can come out an ulp short).
  const most = rate * dt;
  if (gap <= most * (1 + 1e-9)) {
    vec[0] = tx;
    vec[1] = ty;
  } else {
    vec[0] += (dx * most) / gap;
    vec[1] += (dy * most) / gap;
  }
  if (held && sideUp > THRUST_RAMP.up) {
    const side = Math.abs(x0) + (full / sideUp) * dt;
    if (Math.abs(vec[0]) > side) vec[0] = Math.sign(vec[0]) * side;
  }
}

/**
 * The thrust force law: F = m a on the ship, a the engine's acceleration `engine.thrustVec`, which
 * each step moves towards a_T (s d_x, d_y) (d the unit vector of `game.thrust`, s `params.sideScale`;
 * 0 when none or when the game is over) as `rampThrust` says, its x part cut near the top sideways
 * speed (`sideThrustShare`, `params.sideSpeed`) while a side arrow alone is held; then the soft side walls' push
 * (`softWallPush`, `params.softWall` m wide). Runs in the forces stage. `engine` is the game (or the
 * predictor, which keeps its own copy of the engine).
 */
function thrustLaw(
  game: BlackHoleGame,
  ship: number,
  engine: { readonly thrustVec: [number, number]; readonly letGo?: boolean },
): (world: PhysicsWorld) => void {
  return (world) => {
    const d = THRUST_DIRECTION[game.over || engine.letGo === true ? 'none' : game.thrust];
    const a = game.params.thrust;
    const v = engine.thrustVec;
    rampThrust(v, a * game.params.sideScale * d[0], a * d[1], a, world.dt, game.params.sideRamp);
    const F = world.components.Force;
    const s = slotOf(ship);
    if (v[0] !== 0 || v[1] !== 0) {
      F.x[s] =
        F.x[s]! + SHIP_MASS * v[0] * sideThrustShare(v[0], world.components.Velocity.x[s]!, d[1] === 0 ? game.params.sideSpeed : Infinity);
      F.y[s] = F.y[s]! + SHIP_MASS * v[1];
    }
    const wall = softWallPush(
      world.components.Position.x[s]!,
      world.components.Velocity.x[s]!,
      v[0],
      game.field.width,
      game.params.softWall,
    );
    if (wall !== 0) F.x[s] = F.x[s]! + SHIP_MASS * wall;
  };
}

/**
 * Creates a game: a 2D world without uniform gravity, G = gScale x G_GAME, the ship at `START`,
 * its exhaust emitter (off), and `holes` holes laid out at random.
 * @throws TypeError | RangeError on bad options.
 */
export function createBlackHoleGame(options: BlackHoleOptions = {}): BlackHoleGame {
  const p = resolveBlackHoleOptions(options);
  const world = createPhysicsWorld({ dimensions: 2, gravity: [0, 0], capacity: 1500, seed: p.seed });
  setGravitation(world, { constant: G_GAME * p.gScale });
  const start: [number, number] = [p.field.width / 2, 1.5];
  const ship = addBody(world, { position: start, mass: SHIP_MASS });
  addEmitter(world, {
    attachTo: ship,
    rate: 160,
    enabled: false,
    direction: [0, -1],
    spread: 0.28,
    speed: [4, 7],
    lifetime: [0.35, 0.8],
    inheritVelocity: 1,
    policy: 'recycle-oldest',
    particle: { mass: 0.01, colorStart: 0xfff0a0, colorEnd: 0xff3a10, sizeStart: 0.45, sizeEnd: 0.12, alphaStart: 1, alphaEnd: 0 },
  });
  const game: BlackHoleGame = {
    world,
    params: p,
    ship,
    holes: [],
    holeRadius: [],
    holeMass: [],
    lives: p.lives,
    score: 0,
    over: false,
    message: 'Reach the green line at the top. The arrow keys or buttons thrust.',
    thrust: 'none',
    thrustVec: [0, 0],
    falls: 0,
    crossings: 0,
    resets: 0,
    parked: p.park,
    side: 0,
    version: 0,
    rng: new Rng(p.seed),
    field: p.field,
    start,
    lineY: p.field.height - 2,
    lineOpen: true,
  };
  addSystem(world, 'forces', thrustLaw(game, ship, game));
  layoutHoles(game, p.holes);
  return game;
}

/**
 * Lays out `count` holes (default: as many as now) at random: radii in HOLE_RADIUS, centres in the
 * band between y = 5 m and 3 m below the line, at least 3 m of clear space between horizons and 4 m
 * from the start (relaxed after many failed tries, so a layout always completes). Each hole is a
 * static body with an attractor of mass c^2 r / 2G.
 * @throws RangeError unless count is an integer in [1, MAX_HOLES].
 */
export function layoutHoles(game: BlackHoleGame, count = game.holes.length): void {
  check(
    Number.isInteger(count) && count >= 1 && count <= MAX_HOLES,
    `layoutHoles: count must be an integer in [1, ${MAX_HOLES}], got ${count}`,
  );
  const world = game.world;
  for (const h of game.holes) removeBody(world, h);
  game.holes.length = 0;
  game.holeRadius.length = 0;
  game.holeMass.length = 0;
  const G = gravitationalConstant(game),
    c = game.params.c;
  const { xs, ys, rs } = drawLayout(game, count);
  for (let k = 0; k < count; k++) {
    const mass = schwarzschildMass(rs[k]!, c, G);
    const e = addBody(world, { position: [xs[k]!, ys[k]!], static: true });
    setAttractor(world, e, { mass });
    game.holes.push(e);
    game.holeRadius.push(rs[k]!);
    game.holeMass.push(mass);
  }
  game.version++;
}

/**
 * The draws of `layoutHoles` from `game.rng` for `count` holes: centres xs, ys (m) and horizon radii
 * rs (m), the field left as it is.
 */
function drawLayout(game: BlackHoleGame, count: number): { xs: number[]; ys: number[]; rs: number[] } {
  const rng = game.rng;
  const xs: number[] = [],
    ys: number[] = [],
    rs: number[] = [];
  for (let k = 0; k < count; k++) {
    let bestX = 0,
      bestY = 0,
      bestR = HOLE_RADIUS[0],
      bestGap = -Infinity;
    for (let attempt = 0; attempt < 300; attempt++) {
      const r = rng.range(HOLE_RADIUS[0], HOLE_RADIUS[1]);
      const x = rng.range(1.5 + r, game.field.width - 1.5 - r);
      const y = rng.range(5 + r, game.lineY - 3 - r);
      // Smallest clearance to the other horizons (minus 3 m) and to the start (minus 4 m).
      let gap = Math.hypot(x - game.start[0], y - game.start[1]) - r - 4;
      for (let j = 0; j < xs.length; j++) gap = Math.min(gap, Math.hypot(x - xs[j]!, y - ys[j]!) - r - rs[j]! - 3);
      if (gap > bestGap) {
        bestGap = gap;
        bestX = x;
        bestY = y;
        bestR = r;
      }
      if (gap >= 0) break;
    }
    xs.push(bestX);
    ys.push(bestY);
    rs.push(bestR);
  }
  return { xs, ys, rs };
}

/**
 * Puts the game's layout generator (`game.rng`) back where a new game's stands once its first
 * `params.holes` holes are laid out (`createBlackHoleGame`), the field left as it is: the layouts
 * drawn next are those a new game of the same options draws first. The levels (./levels.ts) lay out
 * each level from here, so a level has one layout per seed however it is reached.
 */
export function rewindLayouts(game: BlackHoleGame): void {
  game.rng.reset(game.params.seed);
  drawLayout(game, game.params.holes);
}

/**
 * Sets G to gScale x G_GAME (gScale in [0.1, 10]): the holes keep their masses and their horizons
 * become r = 2 G M / c^2. @throws RangeError out of range.
 */
export function setGScale(game: BlackHoleGame, gScale: number): void {
  checkGScale(gScale);
  game.params.gScale = gScale;
  setGravitation(game.world, { constant: G_GAME * gScale });
  updateHorizons(game);
}

/** Sets the speed of light, m/s in [2, 50]: the holes keep their masses, their horizons follow. @throws RangeError out of range. */
export function setLightSpeed(game: BlackHoleGame, c: number): void {
  checkC(c);
  game.params.c = c;
  updateHorizons(game);
}

/** Sets the thrust acceleration, m/s^2 in [0, 40]. @throws RangeError out of range. */
export function setThrustAcceleration(game: BlackHoleGame, a: number): void {
  checkThrust(a);
  game.params.thrust = a;
}

function updateHorizons(game: BlackHoleGame): void {
  const G = gravitationalConstant(game),
    c = game.params.c;
  for (let i = 0; i < game.holes.length; i++) game.holeRadius[i] = schwarzschildRadius(game.holeMass[i]!, c, G);
  game.version++;
}

/**
 * Points the ship's thrust (an arrow's direction or a diagonal, always of acceleration
 * `params.thrust`; 'none' stops it) and turns the exhaust on
 * while thrusting, pointing against the thrust. Ignored once the game is over.
 * @throws RangeError on an unknown direction.
 */
export function setThrust(game: BlackHoleGame, thrust: Thrust): void {
  check(thrust in THRUST_DIRECTION, `setThrust: thrust must be one of ${Object.keys(THRUST_DIRECTION).join(', ')}, got ${String(thrust)}`);
  const t = game.over ? 'none' : thrust;
  game.thrust = t;
  const world = game.world;
  const on = t !== 'none';
  setEmitterEnabled(world, game.ship, on);
  if (on) {
    // The physics API has no setter for an emitter's direction; its unit vector is component data.
    const E = world.components.Emitter,
      d = THRUST_DIRECTION[t];
    E.dirX[slotOf(game.ship)] = -d[0];
    E.dirY[slotOf(game.ship)] = -d[1];
  }
}

/** Puts the ship back at the start, at rest, its engine idle (a teleport: no interpolation across it). */
export function resetShip(game: BlackHoleGame): void {
  setPosition(game.world, game.ship, game.start);
  setVelocity(game.world, game.ship, [0, 0]);
  game.thrustVec[0] = game.thrustVec[1] = 0;
  game.resets++;
  game.parked = game.params.park;
  game.side = 0;
}

/**
 * Index of the hole whose horizon the ship touches on its way from (ax, ay) to (bx, by) (m), or -1:
 * the closest point of the segment to each centre is compared with the radius plus SHIP_RADIUS, so a
 * fast ship cannot jump over a horizon within one step.
 */
export function holeHit(game: BlackHoleGame, ax: number, ay: number, bx: number, by: number): number {
  const P = game.world.components.Position;
  const ex = bx - ax,
    ey = by - ay,
    len2 = ex * ex + ey * ey;
  for (let i = 0; i < game.holes.length; i++) {
    const h = game.holes[i]!;
    const cx = P.x[slotOf(h)]!,
      cy = P.y[slotOf(h)]!;
    const t = len2 > 0 ? Math.max(0, Math.min(1, ((cx - ax) * ex + (cy - ay) * ey) / len2)) : 0;
    const dx = ax + t * ex - cx,
      dy = ay + t * ey - cy;
    const r = game.holeRadius[i]! + SHIP_RADIUS;
    if (dx * dx + dy * dy < r * r) return i;
  }
  return -1;
}

/**
 * One step of the game: the physics step (thrust, the holes' pull, exhaust), then the rules in this
 * order: fell into a hole (a life lost; at zero the game is over), crossed the line while it is open
 * (`BlackHoleGame.lineOpen`; score += holes,
 * one more hole, new layout), left the field (back to the start, no penalty). Exhaust particles that
 * cross a horizon are removed. Once the game is over the ship waits at the start; so does a parked one
 * (`params.park`, `BlackHoleGame.parked`), which drops the thrust's downward part.
 * @returns what happened. @throws what `step` throws.
 */
export function stepBlackHole(game: BlackHoleGame): BlackHoleEvent {
  const world = game.world;
  // A parked ship (params.park) drops the downward part of the thrust (the pad is under it) and
  // leaves the pad at the first thrust left.
  if (game.parked) {
    const t = padThrust(game.thrust);
    if (t !== game.thrust) setThrust(game, t);
    if (t !== 'none') game.parked = false;
  }
  // A new side press (the thrust's side changed to left or right) kicks the ship that way at once,
  // up to the top sideways speed.
  const side = Math.sign(THRUST_DIRECTION[game.thrust][0]);
  if (side !== 0 && side !== game.side && !game.parked && !game.over && game.params.sideKick > 0) {
    const V = world.components.Velocity,
      s = slotOf(game.ship);
    const along = side * V.x[s]!;
    const kicked = Math.min(along + game.params.sideKick, game.params.sideSpeed);
    if (kicked > along) V.x[s] = side * kicked;
  }
  game.side = side;
  step(world);
  swallowParticles(game);
  const ship = game.ship;
  if (game.parked) {
    setPosition(world, ship, game.start);
    setVelocity(world, ship, [0, 0]);
  }
  const P = world.components.Position,
    O = world.components.PreviousPosition;
  if (game.over) {
    setPosition(world, ship, game.start);
    setVelocity(world, ship, [0, 0]);
    return 'none';
  }
  const x = P.x[slotOf(ship)]!,
    y = P.y[slotOf(ship)]!;
  const hit = holeHit(game, O.x[slotOf(ship)]!, O.y[slotOf(ship)]!, x, y);
  if (hit >= 0) {
    game.lives--;
    game.falls++;
    resetShip(game);
    if (game.lives <= 0) {
      game.lives = 0;
      game.over = true;
      setThrust(game, 'none');
      game.message = `Swallowed! Game over with ${game.score} ${game.score === 1 ? 'point' : 'points'}. Press Enter or R to play again.`;
      return 'over';
    }
    game.message = `Swallowed by a black hole! ${game.lives} ${game.lives === 1 ? 'life' : 'lives'} left.`;
    return 'fell';
  }
  if (game.lineOpen && y >= game.lineY) {
    const n = game.holes.length;
    game.score += n;
    game.crossings++;
    layoutHoles(game, Math.min(MAX_HOLES, n + 1));
    resetShip(game);
    game.message = `Made it! +${n} (one hole per hole on screen). Now ${game.holes.length} ${game.holes.length === 1 ? 'hole' : 'holes'}.`;
    return 'scored';
  }
  if (x < 0 || x > game.field.width || y < 0 || y > game.field.height) {
    resetShip(game);
    game.message = 'Off the field: back to the start (no penalty).';
    return 'lost';
  }
  return 'none';
}

/**
 * Removes every exhaust particle from the game's world (a cleared level's exhaust would otherwise
 * hang over the next level's start while the run waits without stepping).
 */
export function clearParticles(game: BlackHoleGame): void {
  const world = game.world;
  const c = world.components;
  // Copied first: removing while iterating a bitecs query skips entities.
  const ents = Array.from(query(world, [c.Particle, c.Position]));
  for (const e of ents) removeBody(world, handleOf(world, e)); // query() gives slots; the API takes handles
}

/** Removes every particle inside a horizon (matter falling in). */
function swallowParticles(game: BlackHoleGame): void {
  const world = game.world;
  const c = world.components;
  const ents = query(world, [c.Particle, c.Position]);
  const px = c.Position.x,
    py = c.Position.y;
  const holes = game.holes,
    radius = game.holeRadius;
  let n = 0;
  const doomed = swallowScratch;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    for (let k = 0; k < holes.length; k++) {
      const h = holes[k]!;
      const dx = px[e]! - px[slotOf(h)]!,
        dy = py[e]! - py[slotOf(h)]!,
        r = radius[k]!;
      if (dx * dx + dy * dy < r * r) {
        if (n < doomed.length) doomed[n++] = e;
        break;
      }
    }
  }
  // Removed after the pass (removing while iterating a bitecs query skips entities).
  for (let i = 0; i < n; i++) removeBody(world, handleOf(world, doomed[i]!)); // query() gives slots; the API takes handles
}

const swallowScratch = new Int32Array(1024);

/** Restarts a finished (or running) game in place: lives, score, message, holes at the starting count, the ship at the start. */
export function restart(game: BlackHoleGame): void {
  game.lives = game.params.lives;
  game.score = 0;
  game.over = false;
  game.message = 'Reach the green line at the top. The arrow keys or buttons thrust.';
  setThrust(game, 'none');
  layoutHoles(game, game.params.holes);
  resetShip(game);
}

// ---- The predicted path -------------------------------------------------------------------------

/**
 * Where hole `i` (centre at x, m; horizon radius r, m) is dt s later, moving sideways at vx[i] m/s
 * (missing or 0: it stays put): it turns back (the sign of vx[i] flipped) where its centre would come
 * within 1.5 m plus r of the side of a field `width` m wide.
 */
export function driftedX(x: number, i: number, r: number, vx: number[], width: number, dt: number): number {
  const v = vx[i] ?? 0;
  if (v === 0) return x;
  let at = x + v * dt;
  const lo = 1.5 + r,
    hi = width - 1.5 - r;
  if (at < lo) {
    at = 2 * lo - at;
    vx[i] = Math.abs(v);
  }
  if (at > hi) {
    at = 2 * hi - at;
    vx[i] = -Math.abs(v);
  }
  return at;
}

/** A small second world that integrates a copy of the ship ahead in the same force field. */
export interface Predictor {
  /** The copy's world: the holes (static attractors), the ship, the thrust law; no particles. */
  readonly world: PhysicsWorld;
  /** The copy of the ship. */
  readonly ship: number;
  /** The game version the copy's holes match. */
  version: number;
  /** The holes in the copy. */
  readonly holes: number[];
  /** The copy's engine (set from the game's at the start of each `predictPath`), m/s^2. */
  readonly thrustVec: [number, number];
  /** Whether the copy's arrows are let go (past `predictPath`'s `thrustSteps`): its engine dies away. */
  letGo: boolean;
}

/** Creates the predictor of `game` (its holes are copied on the first `predictPath`). */
export function createPredictor(game: BlackHoleGame): Predictor {
  const world = createPhysicsWorld({
    dimensions: 2,
    gravity: [0, 0],
    capacity: MAX_FIELD_HOLES + 4,
    dt: game.world.dt,
    integrator: game.world.integrator,
  });
  const ship = addBody(world, { position: game.start, mass: SHIP_MASS });
  const pred: Predictor = { world, ship, version: -1, holes: [], thrustVec: [0, 0], letGo: false };
  addSystem(world, 'forces', thrustLaw(game, ship, pred));
  return pred;
}

function syncPredictor(game: BlackHoleGame, pred: Predictor): void {
  const w = pred.world;
  setGravitation(w, { constant: gravitationalConstant(game) });
  for (const h of pred.holes) removeBody(w, h);
  pred.holes.length = 0;
  const P = game.world.components.Position;
  for (let i = 0; i < game.holes.length; i++) {
    const h = game.holes[i]!;
    const e = addBody(w, { position: [P.x[slotOf(h)]!, P.y[slotOf(h)]!], static: true });
    setAttractor(w, e, { mass: game.holeMass[i]! });
    pred.holes.push(e);
  }
  pred.version = game.version;
}

/**
 * The ship's path for the next `steps` steps (default 60: one second at 60 Hz) with the current
 * thrust held: the ship's position and velocity and the engine's thrust now are copied into the predictor's world, which then
 * steps with the same dt, integrator, G, holes and thrust law as the game. `holeVx`, when given, is
 * each hole's sideways speed, m/s (./levels.ts `LevelRun.holeVx`, same order as game.holes; missing or
 * 0: it stays put): the copy's holes drift as the game's do (`driftedX`, before each step). Positions
 * (m) go into `out` as x0, y0, x1, y1, ... starting with the ship's current position; the path stops
 * early where the ship touches a horizon on its way through a step (the game's test, `holeHit`; see
 * SHIP_RADIUS) or leaves the field. `thrustSteps` (default Infinity: held throughout) is how many of
 * the steps the thrust is held: after them it is let go and the engine dies away as the game's does
 * (a tap's thrust, which ends at a known step: ./press-timing.ts `releaseStep`).
 * @returns the number of points written (1 + steps taken), at most out.length / 2.
 * @throws RangeError unless steps is an integer in [1, 10_000] and thrustSteps >= 0 (an integer or Infinity).
 */
export function predictPath(
  game: BlackHoleGame,
  pred: Predictor,
  out: Float64Array,
  steps = 60,
  holeVx?: readonly number[],
  thrustSteps = Infinity,
): number {
  check(Number.isInteger(steps) && steps >= 1 && steps <= 10_000, `predictPath: steps must be an integer in [1, 10000], got ${steps}`);
  check(
    thrustSteps === Infinity || (Number.isInteger(thrustSteps) && thrustSteps >= 0),
    `predictPath: thrustSteps must be an integer >= 0 or Infinity, got ${thrustSteps}`,
  );
  if (pred.version !== game.version) syncPredictor(game, pred);
  const w = pred.world,
    s = pred.ship;
  const src = game.world.components,
    dst = w.components;
  const P = dst.Position,
    O = dst.PreviousPosition,
    V = dst.Velocity;
  P.x[s] = src.Position.x[slotOf(game.ship)]!;
  P.y[s] = src.Position.y[slotOf(game.ship)]!;
  O.x[s] = P.x[s]!;
  O.y[s] = P.y[s]!;
  V.x[s] = src.Velocity.x[slotOf(game.ship)]!;
  V.y[s] = src.Velocity.y[slotOf(game.ship)]!;
  pred.thrustVec[0] = game.thrustVec[0];
  pred.thrustVec[1] = game.thrustVec[1];
  const max = Math.min(steps + 1, out.length >> 1);
  if (max < 1) return 0;
  out[0] = P.x[s]!;
  out[1] = P.y[s]!;
  let n = 1;
  const radius = game.holeRadius;
  const HP = P;
  // Drifting holes move in the copy as `stepLevel` moves them in the game: from where they are now,
  // before each step, turning back at the field's edges (a copy of their speeds: turning flips them).
  let drift: number[] | null = null;
  if (holeVx?.some((v) => v !== 0)) {
    drift = predictDrift;
    drift.length = 0;
    for (let i = 0; i < pred.holes.length; i++) drift.push(holeVx[i] ?? 0);
    const GP = src.Position;
    for (let i = 0; i < pred.holes.length; i++) {
      holeAt[0] = GP.x[slotOf(game.holes[i]!)]!;
      holeAt[1] = GP.y[slotOf(game.holes[i]!)]!;
      setPosition(w, pred.holes[i]!, holeAt);
    }
  }
  while (n < max) {
    pred.letGo = n > thrustSteps;
    if (drift) {
      for (let i = 0; i < pred.holes.length; i++) {
        if (drift[i] === 0) continue;
        const h = pred.holes[i]!;
        holeAt[0] = driftedX(HP.x[slotOf(h)]!, i, radius[i]!, drift, game.field.width, w.dt);
        holeAt[1] = HP.y[slotOf(h)]!;
        setPosition(w, h, holeAt);
      }
    }
    const ax = P.x[s]!,
      ay = P.y[s]!;
    step(w);
    const x = P.x[s]!,
      y = P.y[s]!;
    out[2 * n] = x;
    out[2 * n + 1] = y;
    n++;
    // The game's own test (`holeHit`): the closest point of the step's segment to each centre, so a
    // path that grazes a horizon between two steps ends there as the ship would.
    const ex = x - ax,
      ey = y - ay,
      len2 = ex * ex + ey * ey;
    let inside = false;
    for (let i = 0; i < pred.holes.length; i++) {
      const h = pred.holes[i]!;
      const cx = HP.x[slotOf(h)]!,
        cy = HP.y[slotOf(h)]!;
      const t = len2 > 0 ? Math.max(0, Math.min(1, ((cx - ax) * ex + (cy - ay) * ey) / len2)) : 0;
      const dx = ax + t * ex - cx,
        dy = ay + t * ey - cy,
        r = radius[i]! + SHIP_RADIUS;
      if (dx * dx + dy * dy < r * r) {
        inside = true;
        break;
      }
    }
    if (inside || x < 0 || x > game.field.width || y < 0 || y > game.field.height) break;
  }
  pred.letGo = false;
  return n;
}

/** Scratch of `predictPath`: the drifting holes' speeds, m/s, and a hole's position, m. */
const predictDrift: number[] = [];
const holeAt: [number, number] = [0, 0];

/** How a predicted path ends (`pathEnd`). */
export type PathEnd = 'clear' | 'falls' | 'lost';

/**
 * How the predicted path of `n` points in `out` (x0, y0, x1, y1, ... m, as `predictPath` writes them,
 * asked for `steps` steps) ends: 'falls' when it stops short inside the field (on a horizon);
 * 'lost' when it leaves the field (x < 0, x > width or y < 0, or above the field) before reaching
 * the finish line (or at all while the line is closed: `BlackHoleGame.lineOpen`), where the game would put the ship back at the start ("Off the field");
 * 'clear' otherwise (it runs its full length, or reaches the line first).
 * @throws RangeError unless n is an integer in [1, out.length / 2] and steps an integer >= 1.
 */
export function pathEnd(game: BlackHoleGame, out: Float64Array, n: number, steps: number): PathEnd {
  check(Number.isInteger(n) && n >= 1 && 2 * n <= out.length, `pathEnd: n must be an integer in [1, ${out.length >> 1}], got ${n}`);
  check(Number.isInteger(steps) && steps >= 1, `pathEnd: steps must be an integer >= 1, got ${steps}`);
  if (game.lineOpen) for (let i = 0; i < n; i++) if (out[2 * i + 1]! >= game.lineY) return 'clear';
  const x = out[2 * n - 2]!,
    y = out[2 * n - 1]!;
  const outside = x < 0 || x > game.field.width || y < 0 || y > game.field.height;
  if (outside) return 'lost';
  return n < steps + 1 ? 'falls' : 'clear';
}
