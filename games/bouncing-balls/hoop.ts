/**
 * The hoop game on top of the bouncing-balls sandbox: throw balls through a basketball hoop (a
 * backboard and a front rim, both static segments the balls bounce off with the scene's restitution)
 * as many times as you can in `ROUND_SECONDS`, each basket after the first adding `TIME_PER_BASKET`
 * to the clock; the hoop stays where it is for `BASKETS_PER_HOOP` baskets, so a throw that scored
 * scores again when repeated, then moves to another spot (`nextSpot`: the page deals them in a
 * seeded random order, different every round, after the warm-up's hoop at the layout's first spot).
 * Pure rules and the hoop's bodies: no DOM, no pixi (it runs in Node for the tests).
 *
 * A basket: the centre of one of the player's balls crosses the rim's line downwards between the
 * front rim's inner end and the backboard (`throughHoop`). Only balls released below the rim count
 * (`SHOT_LINE_GAP`), so a ball dropped straight in from above is no basket. The round's clock starts
 * with the player's first basket: until then the player warms up, learning the aim with no time
 * running, so the minute is spent scoring rather than finding out how a throw works.
 *
 * The net (`NET`, `netContact`) hangs under the rim and lets a ball in only from above: one thrown up
 * from under the hoop is stopped by the net's bottom and drops back, and one coming from the side
 * below the rim bounces off the net's side, as a real net does, so no ball passes through the drawn
 * net or up through the rim's opening.
 *
 * A throw is a slingshot (`slingVelocity`): press where the ball should start, pull back and let go;
 * the ball leaves opposite to the pull, faster the longer the pull, and `throwPath` is the dotted
 * arc the page draws while pulling, bounces off the walls, the hoop and the net included.
 */
import { addSegment, type PhysicsWorld, removeBody } from '@bitphysics/physics';
import type { DragMode } from './scene';

/** Length of a round, s, counted from the first basket (each basket after it adds TIME_PER_BASKET). */
export const ROUND_SECONDS = 60;

/**
 * Seconds each basket after the round's first adds to the clock: a player who has learned a hoop's
 * throw plays on for as long as the baskets keep coming faster than this.
 */
export const TIME_PER_BASKET = 3;

/**
 * Baskets the hoop stays for before it moves to its next spot (a round's default, createRound): the
 * throw that scored once scores again when repeated, so a hoop is learned and then cashed in, and
 * the round still goes round the court.
 */
export const BASKETS_PER_HOOP = 3;

/** Radius of the player's balls, m (fixed, so every shot is the same ball whatever the sandbox's ball count). */
export const PLAYER_RADIUS = 0.4;

/** Half the hoop's opening, m: rim centre to the front rim's inner end, and to the backboard's face. */
export const HOOP_HALF_WIDTH = 1;

/** Height of the backboard above the rim, m, and how far it reaches below it. */
export const BACKBOARD = Object.freeze({ above: 1.6, below: 0.3 });

/** Length of the front rim, m (a short horizontal bar outside the opening). */
export const FRONT_RIM_LENGTH = 0.25;

/** Thickness radius of the backboard and the rim, m. */
export const HOOP_RADIUS = 0.08;

/** A ball counts only if released with its centre at least this far below the rim, m. */
export const SHOT_LINE_GAP = 0.3;

/** A hoop position: rim centre (x, y), m, and the side of its backboard (+1 right, -1 left). */
export interface HoopSpot {
  readonly x: number;
  readonly y: number;
  readonly side: 1 | -1;
}

/**
 * Hoop spots of the wide 16 x 10 m box (scene.ts BOX), the first the warm-up's (the page deals the
 * rest in a random order, nextSpot): clear of its inclined
 * walls, rims 3 m or more under the top (room for an arc over the rim), and each reachable by a clean
 * throw with room for error from a fifth or more of the lower box (reach.ts; measured by
 * scripts/bouncing-balls-reach.mjs).
 */
export const HOOP_SPOTS: readonly HoopSpot[] = Object.freeze([
  { x: 13, y: 6, side: 1 },
  { x: 2.4, y: 6, side: -1 },
  { x: 10.5, y: 5, side: 1 },
  { x: 6.5, y: 4.5, side: -1 },
  { x: 12.6, y: 6.6, side: 1 },
]);

/** Hoop spots of the tall 10 x 16 m box (scene.ts BOX_TALL), chosen as HOOP_SPOTS are: low enough to reach from the lower box. */
export const HOOP_SPOTS_TALL: readonly HoopSpot[] = Object.freeze([
  { x: 7.8, y: 9, side: 1 },
  { x: 2, y: 6, side: -1 },
  { x: 8.2, y: 4, side: 1 },
  { x: 2, y: 7, side: -1 },
  { x: 4.6, y: 7, side: 1 },
]);

/** The spots of a layout (`tall` for the upright box). */
export function hoopSpots(tall: boolean): readonly HoopSpot[] {
  return tall ? HOOP_SPOTS_TALL : HOOP_SPOTS;
}

/** The hoop's opening: the rim's height, m, and the x range, m, a ball's centre must cross it in. */
export interface HoopOpening {
  readonly y: number;
  readonly minX: number;
  readonly maxX: number;
}

/** The opening of a hoop at `spot`: between the front rim's inner end and the backboard's face. */
export function hoopOpening(spot: HoopSpot): HoopOpening {
  const a = spot.x - HOOP_HALF_WIDTH,
    b = spot.x + HOOP_HALF_WIDTH;
  return { y: spot.y, minX: a, maxX: b };
}

/** The segments of a hoop at `spot`, m, [ax, ay, bx, by]: the backboard, then the front rim. */
export function hoopSegments(spot: HoopSpot): [number, number, number, number][] {
  const s = spot.side;
  const board = spot.x + s * (HOOP_HALF_WIDTH + HOOP_RADIUS);
  const front = spot.x - s * (HOOP_HALF_WIDTH + HOOP_RADIUS);
  return [
    [board, spot.y - BACKBOARD.below, board, spot.y + BACKBOARD.above],
    [front, spot.y, front - s * FRONT_RIM_LENGTH, spot.y],
  ];
}

/**
 * The net under the rim: it hangs `depth` m below the rim, and its bottom opening is `narrow` m
 * narrower than the rim's on each side (1.4 m: a ball of the game, 0.8 m across, falls through).
 */
export const NET = Object.freeze({ depth: 1.1, narrow: 0.3 });

/** Fraction of its speed into the net that a ball the net stops keeps, bouncing back (the net is soft). */
export const NET_BOUNCE = 0.25;

/**
 * What the net at `spot` does to a ball of radius `r` m that moved over a step from (x0, y0) to
 * (x, y), m, with velocity (vx, vy) m/s at the end: null if the net leaves it alone, else the ball's
 * corrected [x, y, vx, vy]. The net is the trapezoid under the rim's opening (NET) and is open at
 * the rim (the way in) and at its bottom opening (the way out):
 * - a ball rising from under the net whose top crosses its bottom while its centre is within the
 *   bottom opening is stopped there (its top on the net's bottom) and falls back, keeping NET_BOUNCE
 *   of its upward speed;
 * - a ball whose centre crosses a side of the net (in from outside below the rim, or out from
 *   inside) is put back where it was and bounces off that side, keeping NET_BOUNCE of the speed
 *   across it.
 * @throws RangeError on non-finite input or r <= 0.
 */
export function netContact(
  spot: HoopSpot,
  r: number,
  x0: number,
  y0: number,
  x: number,
  y: number,
  vx: number,
  vy: number,
): [number, number, number, number] | null {
  if (![x0, y0, x, y, vx, vy].every(Number.isFinite) || !(r > 0 && Number.isFinite(r)))
    throw new RangeError(
      `netContact: positions, velocity and r > 0 must be finite, got (${x0}, ${y0}) -> (${x}, ${y}), (${vx}, ${vy}), r ${r}`,
    );
  const top = spot.y,
    bottom = spot.y - NET.depth;
  const L = spot.x - HOOP_HALF_WIDTH,
    R = spot.x + HOOP_HALF_WIDTH,
    n = NET.narrow;
  // From below: the ball's top crosses the net's bottom under its opening.
  if (vy > 0 && y0 + r <= bottom && y + r > bottom && x > L + n && x < R - n) return [x, bottom - r, vx, -NET_BOUNCE * vy];
  const sideX = (h: number, left: boolean): number => (left ? L + (n * (top - h)) / NET.depth : R - (n * (top - h)) / NET.depth);
  const inside = (px: number, py: number): boolean => py > bottom && py < top && px > sideX(py, true) && px < sideX(py, false);
  const was = inside(x0, y0),
    is = inside(x, y);
  if (was === is) return null;
  // In through the rim, or out through the bottom opening: the ways the net lets a ball pass. A
  // centre that came up from below the bottom is stopped there as above.
  if (!was && y0 >= top) return null;
  if (was && y <= bottom) return null;
  if (!was && y0 <= bottom) return [x, bottom - r, vx, -NET_BOUNCE * Math.abs(vy)];
  if (was && y >= top) return null;
  // Across a side: back where it was, bouncing off the side (its normal pointing out of the net).
  const left = (x0 + x) / 2 < spot.x;
  const len = Math.hypot(NET.depth, n);
  let nx = (left ? -NET.depth : NET.depth) / len,
    ny = -n / len;
  // Seen from inside, the side's normal points in.
  if (was) {
    nx = -nx;
    ny = -ny;
  }
  const into = vx * nx + vy * ny;
  if (into >= 0) return [x0, y0, vx, vy];
  return [x0, y0, vx - (1 + NET_BOUNCE) * into * nx, vy - (1 + NET_BOUNCE) * into * ny];
}

/** Adds the hoop's backboard and front rim to `world` with the given material. @returns their entity ids. */
export function addHoop(world: PhysicsWorld, spot: HoopSpot, restitution: number, friction: number): number[] {
  return hoopSegments(spot).map(([ax, ay, bx, by]) =>
    addSegment(world, { a: [ax, ay], b: [bx, by], radius: HOOP_RADIUS, restitution, friction }),
  );
}

/** Removes the hoop's bodies (`addHoop`'s ids) from `world`. */
export function removeHoop(world: PhysicsWorld, ids: readonly number[]): void {
  for (const e of ids) removeBody(world, e);
}

/**
 * How a ball's centre moving from (x0, y0) to (x1, y1), m, in one step crossed the hoop's opening:
 * -1 down through it (a basket, if the ball may score), +1 up through it from below (the page then
 * takes the ball's chance to score away: a basket is made from above), 0 not through it (no
 * crossing of the rim's line, or a crossing outside [minX, maxX]).
 * @throws RangeError on non-finite coordinates.
 */
export function hoopCrossing(opening: HoopOpening, x0: number, y0: number, x1: number, y1: number): -1 | 0 | 1 {
  if (![x0, y0, x1, y1].every(Number.isFinite))
    throw new RangeError(`hoopCrossing: coordinates must be finite, got (${x0}, ${y0}) -> (${x1}, ${y1})`);
  const down = y0 >= opening.y && y1 < opening.y;
  const up = y0 < opening.y && y1 >= opening.y;
  if (!down && !up) return 0;
  const t = (y0 - opening.y) / (y0 - y1);
  const x = x0 + t * (x1 - x0);
  if (x < opening.minX || x > opening.maxX) return 0;
  return down ? -1 : 1;
}

/** Whether a ball released with its centre at height `y`, m, may score in the hoop at `spot` (released below the rim). */
export function mayScore(spot: HoopSpot, y: number): boolean {
  return y <= spot.y - SHOT_LINE_GAP;
}

/**
 * Whether a ball centred at (x, y), m, lies under the hoop at `spot`: below its rim and past the front
 * rim's outer end towards the backboard, out to the wall behind the board. No throw from there scores
 * cleanly (reach.ts findBasket finds none): the way in is down through the opening, and to come down
 * through it a ball must first fly out past the front rim, which an arc from under the hoop does not
 * bend back from.
 */
export function underHoop(spot: HoopSpot, x: number, y: number): boolean {
  return y < spot.y && spot.side * (x - spot.x) > -(HOOP_HALF_WIDTH + HOOP_RADIUS + FRONT_RIM_LENGTH);
}

/**
 * The balls that may be made the gold one, of `balls` ([x, y, radius] each, m): those out from under
 * the hoop at `spot` (underHoop, where it could not score) with no ball right above them (one the
 * player can reach and throw); if none is free, any out from under the hoop; if none is, all of them.
 * @returns their indices in `balls`, in order.
 */
export function goldChoices(spot: HoopSpot, balls: readonly (readonly [number, number, number])[]): number[] {
  const all = balls.map((_, i) => i);
  const open = all.filter((i) => !underHoop(spot, balls[i]![0], balls[i]![1]));
  const free = open.filter((i) => {
    const [x, y, r] = balls[i]!;
    return !balls.some(([ox, oy, or], j) => j !== i && oy > y && Math.abs(ox - x) < r + or);
  });
  return free.length > 0 ? free : open.length > 0 ? open : all;
}

/** The phase of a round: warming up until the first basket, the clock running, or time up. */
export type RoundPhase = 'ready' | 'playing' | 'over';

/**
 * Points a basket is worth before the streak multiplier, by the ball that went in: one of the
 * player's basketballs (thrown from anywhere below the rim), a ball of the heap on the floor (it has
 * to be thrown from where it lies) and the heap's one gold ball.
 */
export const BALL_POINTS = Object.freeze({ basketball: 1, heap: 2, gold: 5 });

/** The kinds of ball a basket can be made with (keys of BALL_POINTS). */
export type BallKind = keyof typeof BALL_POINTS;

/**
 * How a basket went in: a `swish` touched nothing between its throw and the basket (not the rim, the
 * backboard, a wall of the box, a ramp or another ball once it had left the heap; the net does not
 * count), a `trick` shot bounced off a wall of the box (the floor included, not its top) or a ramp
 * on its way, and a `plain` one did neither (off the rim, the backboard or the box's top, say).
 */
export type ShotStyle = 'plain' | 'swish' | 'trick';

/** Points a basket's style adds to its ball's, before the streak multiplier: a swish +1, a trick shot +3. */
export const SHOT_BONUS = Object.freeze({ plain: 0, swish: 1, trick: 3 });

/** The largest streak multiplier (reached with the fourth basket in a row). */
export const MAX_MULTIPLIER = 4;

/**
 * A thrown ball that has not gone through the hoop this long after its throw, s (world time), is a
 * miss: the streak ends (the page calls a throw a miss sooner, as soon as it falls below the rim's
 * line beside the hoop).
 */
export const MISS_SECONDS = 3;

/**
 * The multiplier of the next basket after `streak` baskets in a row (no miss between them): 1 + streak,
 * at most MAX_MULTIPLIER. @throws RangeError unless streak is an integer >= 0.
 */
export function streakMultiplier(streak: number): number {
  if (!(Number.isInteger(streak) && streak >= 0)) throw new RangeError(`streakMultiplier: streak must be an integer >= 0, got ${streak}`);
  return Math.min(MAX_MULTIPLIER, 1 + streak);
}

/** A round of the hoop game. */
export interface HoopRound {
  phase: RoundPhase;
  /** Baskets scored this round. */
  score: number;
  /** Points this round: each basket's BALL_POINTS times its streak multiplier. */
  points: number;
  /** Baskets in a row since the last miss. */
  streak: number;
  /** The longest streak of the round. */
  bestStreak: number;
  /** Points the last basket made (0 before the first). */
  lastPoints: number;
  /** How the last basket went in ('plain' before the first). */
  lastStyle: ShotStyle;
  /** Swishes and trick shots this round. */
  swishes: number;
  tricks: number;
  /** Length of the round, s. */
  readonly seconds: number;
  /** Seconds left on the clock, >= 0: `seconds` when the clock starts, less as it runs, TIME_PER_BASKET more a basket after the first. */
  timeLeft: number;
  /** Index of the hoop's spot in the layout's spots (moves after every `perHoop` baskets: `nextSpot`). */
  spot: number;
  /** Baskets the hoop stays for before it moves, integer >= 1. */
  readonly perHoop: number;
  /** Baskets scored at the hoop's current spot, in [0, perHoop). */
  atHoop: number;
  /** Whether the last basket moved the hoop (false before the first). */
  lastMoved: boolean;
  /** The spots still to come in this pass through the layout's spots, in order (`nextSpot` deals them; empty before the first basket). */
  upcoming: number[];
  /** Balls the player threw this round: in the warm-up all of them; from the first basket on, that basket's throw and those after it. */
  shots: number;
  /** Every ball the player threw this round, the warm-up's too (the end card's "from N throws"). */
  allShots: number;
}

/**
 * A new round of `seconds` s (default ROUND_SECONDS), warming up until the first basket, its hoop at
 * spot index `spot` (default 0), moving after every `perHoop` baskets (default BASKETS_PER_HOOP).
 * @throws RangeError unless seconds is finite and > 0, or if spot is not an integer >= 0 or perHoop
 * not an integer >= 1.
 */
export function createRound(seconds = ROUND_SECONDS, spot = 0, perHoop = BASKETS_PER_HOOP): HoopRound {
  if (!(seconds > 0 && Number.isFinite(seconds))) throw new RangeError(`createRound: seconds must be finite and > 0, got ${seconds}`);
  if (!(Number.isInteger(spot) && spot >= 0)) throw new RangeError(`createRound: spot must be an integer >= 0, got ${spot}`);
  if (!(Number.isInteger(perHoop) && perHoop >= 1)) throw new RangeError(`createRound: perHoop must be an integer >= 1, got ${perHoop}`);
  return {
    phase: 'ready',
    score: 0,
    points: 0,
    streak: 0,
    bestStreak: 0,
    lastPoints: 0,
    lastStyle: 'plain',
    swishes: 0,
    tricks: 0,
    seconds,
    timeLeft: seconds,
    spot,
    perHoop,
    atHoop: 0,
    lastMoved: false,
    upcoming: [],
    shots: 0,
    allShots: 0,
  };
}

/**
 * Where the hoop of `round` goes after a basket, an index of the layout's `spotCount` spots. Without
 * `random`, the next spot in turn (cycling). With `random` (a generator of numbers in [0, 1), e.g. a
 * seeded Rng's next), the spots are dealt in passes: each pass is every spot but the current one in
 * an order shuffled by `random` (Fisher-Yates), so the order differs from round to round and from
 * pass to pass, every spot comes up within spotCount baskets and none twice in a row. Keeps the pass's
 * rest in `round.upcoming`.
 * @throws RangeError if spotCount is not a positive integer, or random returns a number outside [0, 1).
 */
export function nextSpot(round: HoopRound, spotCount: number, random?: () => number): number {
  if (!(Number.isInteger(spotCount) && spotCount > 0))
    throw new RangeError(`nextSpot: spotCount must be a positive integer, got ${spotCount}`);
  if (!random || spotCount === 1) return (round.spot + 1) % spotCount;
  // A pass dealt for another layout (more spots) is dropped.
  if (round.upcoming.some((s) => s >= spotCount)) round.upcoming = [];
  if (round.upcoming.length === 0) {
    const pass: number[] = [];
    for (let s = 0; s < spotCount; s++) if (s !== round.spot) pass.push(s);
    for (let i = pass.length - 1; i > 0; i--) {
      const u = random();
      if (!(u >= 0 && u < 1)) throw new RangeError(`nextSpot: random must return numbers in [0, 1), got ${u}`);
      const j = Math.floor(u * (i + 1));
      [pass[i], pass[j]] = [pass[j]!, pass[i]!];
    }
    round.upcoming = pass;
  }
  return round.upcoming.shift()!;
}

/** The player threw a ball: counts the shot (the clock waits for the first basket). Nothing changes once time is up. */
export function roundShot(round: HoopRound): void {
  if (round.phase === 'over') return;
  round.shots++;
  round.allShots++;
}

/**
 * Runs the clock `dt` s (only while playing). @returns true when this call ended the round.
 * @throws RangeError if dt is negative or not finite.
 */
export function roundTick(round: HoopRound, dt: number): boolean {
  if (!(dt >= 0 && Number.isFinite(dt))) throw new RangeError(`roundTick: dt must be finite and >= 0 s, got ${dt}`);
  if (round.phase !== 'playing') return false;
  round.timeLeft = Math.max(0, round.timeLeft - dt);
  if (round.timeLeft > 0) return false;
  round.phase = 'over';
  return true;
}

/**
 * A basket with a ball of `kind` that went in `style`: BALL_POINTS[kind] plus SHOT_BONUS[style], times
 * the streak's multiplier (streakMultiplier of the baskets in a row before it), the streak grows, and
 * on the round's `perHoop`-th basket at this hoop the hoop moves to its next spot of `spotCount`
 * (`nextSpot`: in turn, or dealt at random by `random`, numbers in [0, 1); `lastMoved` says whether it
 * did). The first basket starts the clock and restarts the shot count at its own throw; each one after
 * it adds TIME_PER_BASKET s to the clock. Ignored once time is up. @returns whether it counted (the points it made are in `lastPoints`).
 * @throws RangeError if spotCount is not a positive integer, kind is not a key of BALL_POINTS or style
 * not one of SHOT_BONUS.
 */
export function roundBasket(
  round: HoopRound,
  spotCount: number,
  kind: BallKind = 'basketball',
  random?: () => number,
  style: ShotStyle = 'plain',
): boolean {
  if (!(Number.isInteger(spotCount) && spotCount > 0))
    throw new RangeError(`roundBasket: spotCount must be a positive integer, got ${spotCount}`);
  if (!Object.hasOwn(BALL_POINTS, kind)) throw new RangeError(`roundBasket: kind must be basketball, heap or gold, got ${kind}`);
  if (!Object.hasOwn(SHOT_BONUS, style)) throw new RangeError(`roundBasket: style must be plain, swish or trick, got ${style}`);
  if (round.phase === 'over') return false;
  // The clock starts now: of the warm-up's throws only this one counts. Later baskets buy time.
  if (round.phase === 'ready') round.shots = 1;
  else round.timeLeft += TIME_PER_BASKET;
  round.phase = 'playing';
  round.score++;
  round.lastPoints = (BALL_POINTS[kind] + SHOT_BONUS[style]) * streakMultiplier(round.streak);
  round.lastStyle = style;
  if (style === 'swish') round.swishes++;
  if (style === 'trick') round.tricks++;
  round.points += round.lastPoints;
  round.streak++;
  round.bestStreak = Math.max(round.bestStreak, round.streak);
  round.atHoop++;
  round.lastMoved = round.atHoop >= round.perHoop;
  if (round.lastMoved) {
    round.atHoop = 0;
    round.spot = nextSpot(round, spotCount, random);
  }
  return true;
}

/** A miss (a thrown ball that did not go in within MISS_SECONDS): the streak ends. Ignored once time is up. @returns whether a streak was broken. */
export function roundMiss(round: HoopRound): boolean {
  if (round.phase === 'over' || round.streak === 0) return false;
  round.streak = 0;
  return true;
}

/** How near the ceiling a flight's highest point counts as off it, m (missWords): a game step's travel up at 18 m/s (60 Hz), as the last step before the touch may stop that short of it. */
const CEILING_NEAR = 0.3;

/**
 * What the page says of a miss (a thrown ball that could score and did not): "Missed", with why when
 * its flight shows it (its centre's highest point `top`, m, against `ceiling`, the highest a ball's
 * centre goes under the box's top, m, and the rim's height `spot.y`): off the ceiling, or short of the
 * rim; and that the streak is over when the miss broke one (`broke`, roundMiss). Said for every miss:
 * one with no streak to break said nothing, and a full-power throw off the ceiling that fell back onto
 * the heap read as a throw that never happened.
 */
export function missWords(broke: boolean, top: number, ceiling: number, spot: HoopSpot): string {
  const why = top >= ceiling - CEILING_NEAR ? ': off the ceiling' : top < spot.y ? ': short of the rim' : '';
  return `Missed${why}${broke ? ' · streak over' : ''}`;
}

/** Below this speed into a surface a bounce has no restitution, m/s (the engine's default `restitutionThreshold`). */
const RESTITUTION_THRESHOLD = 0.5;

/** Fastest throw, m/s: a full pull of the slingshot (enough to reach the top of either box from its floor). */
export const MAX_THROW_SPEED = 20;

/**
 * The share of the full pull, (0, 1), up to which a throw's speed grows in step with the pull
 * (slingSpeed); past it the square of the speed does.
 */
export const SLING_KNEE = 0.5;
/** The speed at SLING_KNEE of the full pull, m/s: MAX_THROW_SPEED sqrt(knee / (2 - knee)), so the curve reaches MAX_THROW_SPEED at the full pull. */
const KNEE_SPEED = MAX_THROW_SPEED * Math.sqrt(SLING_KNEE / (2 - SLING_KNEE));
/** Speed per share of the full pull below the knee, m/s. */
const KNEE_SLOPE = KNEE_SPEED / SLING_KNEE;

/**
 * The slingshot's speeds in the tall box (a phone held upright), m/s: `low` just past no pull, `top`
 * at the full pull (slingRoom).
 */
export interface SlingRoom {
  readonly low: number;
  readonly top: number;
}

/**
 * How high over the rim a full pull straight up takes the ball in the tall box, m (slingRoom): room
 * for a lob to come down into the hoop, under the ramps over it. The box's 20 m/s top speed took
 * every full pull there to the ceiling or flat into the wall: none of them scored. At 3.5 m a full
 * pull scores from 51 of the 54 of 80 random starts under the rim that can score at all
 * (test/games/bouncing-balls-room.test.ts); of another 150, 83 of 85 (3 m: 81, 4 m: 77).
 */
export const ROOM_OVER_RIM = 3.5;

/**
 * How far under the rim a pull just past nothing takes the ball straight up in the tall box, m
 * (slingRoom): the pull's length is spent on throws that rise to the hoop, the apex of a throw
 * straight up rising from 1 m under the rim to ROOM_OVER_RIM over it (more per px over the short
 * pulls, less towards the full pull: ROOM_PULL_CURVE). With the apex gaining the same per px, a low
 * start's least power for a clean basket (the share of the full pull) was a median 50 % (with the
 * floor at half the top speed, 71 %; the old 20 m/s curve, 60 % of its speed).
 */
export const ROOM_UNDER_RIM = 1;

/**
 * How the height a tall box's throw reaches (the square of its speed, between room.low and room.top)
 * grows with the pull's share of the full pull (slingSpeed): as the share to this power. Under 1, the
 * short pulls (throws that fall short of the rim) take fewer px and the strong ones, where a low
 * start scores (from some half the height up), more: a phone's 138 px full pull spent 69 px on the
 * upper half of the height, now 95 px (a stranger found 80 px at 68 % and 140 px at 100 % too
 * sensitive for a thumb). The full pull still throws at room.top.
 */
export const ROOM_PULL_CURVE = 0.6;

/**
 * The slingshot's speeds for a throw from height `y`, m, at a hoop whose rim is at `rimY`, m, under
 * gravity `g`, m/s^2, in the tall box: the full pull throws straight up to ROOM_OVER_RIM over the rim
 * (within [6, MAX_THROW_SPEED] m/s), a pull just past nothing to ROOM_UNDER_RIM under it (0 from
 * higher up; at most 0.9 of the top). So a full pull lobs over the hoop, not into the ceiling, from
 * wherever it starts, and a short one still rises most of the way to the rim.
 * @throws RangeError unless y, rimY and g are finite.
 */
export function slingRoom(y: number, rimY: number, g: number): SlingRoom {
  if (![y, rimY, g].every(Number.isFinite)) throw new RangeError(`slingRoom: y, rimY and g must be finite, got ${y}, ${rimY}, ${g}`);
  const rise = rimY + ROOM_OVER_RIM - y,
    under = rimY - ROOM_UNDER_RIM - y;
  const top = g > 0 && rise > 0 ? Math.min(MAX_THROW_SPEED, Math.max(6, Math.sqrt(2 * g * rise))) : g > 0 ? 6 : MAX_THROW_SPEED;
  return { low: g > 0 && under > 0 ? Math.min(0.9 * top, Math.sqrt(2 * g * under)) : 0, top };
}

/**
 * The speed of a slingshot throw, m/s, for a pull of `length` px when `fullPull` px throws at
 * MAX_THROW_SPEED: in step with the pull up to SLING_KNEE of fullPull (where the baskets are, a px
 * worth the same speed throughout), then with its square growing evenly (the height a ball reaches,
 * v^2 / 2g, gains the same per px up to the full pull, and as much as at the knee), capped at
 * MAX_THROW_SPEED. A speed linear to the full pull made the height grow with the pull's square: its
 * last px swung a throw from mid-box to the ceiling (twice the height per px of the average).
 * With a `room` (the tall box's, slingRoom): from room.low just past no pull to room.top at the full
 * pull, the square of the speed (the height) growing as the pull's share to the power
 * ROOM_PULL_CURVE (fast over the short pulls, slower towards the full pull, where the baskets are);
 * 0 for no pull.
 * @throws RangeError unless length is finite and >= 0 and fullPull is finite and > 0.
 */
export function slingSpeed(length: number, fullPull: number, room?: SlingRoom): number {
  if (!(length >= 0 && Number.isFinite(length))) throw new RangeError(`slingSpeed: length must be finite and >= 0 px, got ${length}`);
  if (!(fullPull > 0 && Number.isFinite(fullPull))) throw new RangeError(`slingSpeed: fullPull must be finite and > 0 px, got ${fullPull}`);
  const p = Math.min(1, length / fullPull);
  if (room) return length === 0 ? 0 : Math.sqrt(room.low * room.low + (room.top * room.top - room.low * room.low) * p ** ROOM_PULL_CURVE);
  if (p <= SLING_KNEE) return KNEE_SLOPE * p;
  return Math.min(MAX_THROW_SPEED, Math.sqrt(KNEE_SPEED * KNEE_SPEED + 2 * KNEE_SPEED * KNEE_SLOPE * (p - SLING_KNEE)));
}

/**
 * The pull, px, that throws at `speed` m/s when `fullPull` px throws at MAX_THROW_SPEED (at
 * room.top with a `room`): the inverse of slingSpeed (with a room, 0 for speeds up to room.low).
 * @throws RangeError unless speed is in [0, MAX_THROW_SPEED] (room.top) and fullPull is finite and > 0.
 */
export function slingPull(speed: number, fullPull: number, room?: SlingRoom): number {
  const top = room ? room.top : MAX_THROW_SPEED;
  if (!(speed >= 0 && speed <= top)) throw new RangeError(`slingPull: speed must be in [0, ${top}] m/s, got ${speed}`);
  if (!(fullPull > 0 && Number.isFinite(fullPull))) throw new RangeError(`slingPull: fullPull must be finite and > 0 px, got ${fullPull}`);
  if (room)
    return (
      fullPull * (Math.max(0, speed * speed - room.low * room.low) / (room.top * room.top - room.low * room.low)) ** (1 / ROOM_PULL_CURVE)
    );
  if (speed <= KNEE_SPEED) return (fullPull * speed) / KNEE_SLOPE;
  return fullPull * (SLING_KNEE + (speed * speed - KNEE_SPEED * KNEE_SPEED) / (2 * KNEE_SPEED * KNEE_SLOPE));
}

/**
 * The velocity of a slingshot throw, m/s (y up): the ball leaves opposite to the pull (pullX,
 * pullY), px on screen (the pointer minus where the ball starts; y down), at slingSpeed of the pull's
 * length (MAX_THROW_SPEED at `fullPull` and beyond; room.top with a `room`).
 * @throws RangeError unless the pull is finite and fullPull > 0.
 */
export function slingVelocity(pullX: number, pullY: number, fullPull: number, room?: SlingRoom): [number, number] {
  if (!(Number.isFinite(pullX) && Number.isFinite(pullY)))
    throw new RangeError(`slingVelocity: pull must be finite, got (${pullX}, ${pullY})`);
  if (!(fullPull > 0 && Number.isFinite(fullPull)))
    throw new RangeError(`slingVelocity: fullPull must be finite and > 0 px, got ${fullPull}`);
  const length = Math.hypot(pullX, pullY);
  if (length === 0) return [0, 0];
  const speed = slingSpeed(length, fullPull, room);
  return [(-pullX / length) * speed, (pullY / length) * speed];
}

/**
 * How far a finger's pull is drawn to a throw that scores, px of pull (assistPull): on a phone the
 * pull lengths that score span 27 px at the tightest starts (a 138 px full pull on the phone's curve,
 * slingRoom, ROOM_PULL_CURVE; scripts/bouncing-balls-reach.mjs --pull), not much more than a thumb
 * moves as it lets go.
 */
export const PULL_ASSIST_PX = 14;

/**
 * The pull length a finger's pull of `length` px throws with, px: when a length within `reach` px
 * of it scores (`scores`, a prediction of the throw at a pull length in the pull's direction), the
 * middle of the run of scoring lengths through the nearest such one (followed at most 2 `reach` px
 * either way), else `length` itself. So a pull that is close throws the surest basket of its run,
 * and the lengths that score widen by about 2 `reach` px (a snap to the target, as the arc shows).
 * Lengths are tried every `step` px (default 1) and never below 0.
 * @throws RangeError unless length is finite and >= 0, reach is finite and >= 0 and step is finite and > 0.
 */
export function assistPull(length: number, scores: (length: number) => boolean, reach = PULL_ASSIST_PX, step = 1): number {
  if (!(length >= 0 && Number.isFinite(length))) throw new RangeError(`assistPull: length must be finite and >= 0 px, got ${length}`);
  if (!(reach >= 0 && Number.isFinite(reach))) throw new RangeError(`assistPull: reach must be finite and >= 0 px, got ${reach}`);
  if (!(step > 0 && Number.isFinite(step))) throw new RangeError(`assistPull: step must be finite and > 0 px, got ${step}`);
  let hit = Number.NaN;
  // Outward from the pull: the nearest scoring length, the shorter first at a tie.
  for (let d = 0; d <= reach + 1e-9; d += step) {
    if (length - d >= 0 && scores(length - d)) {
      hit = length - d;
      break;
    }
    if (d > 0 && scores(length + d)) {
      hit = length + d;
      break;
    }
  }
  if (Number.isNaN(hit)) return length;
  let lo = hit,
    hi = hit;
  while (hi + step - hit <= 2 * reach + 1e-9 && scores(hi + step)) hi += step;
  while (hit - (lo - step) <= 2 * reach + 1e-9 && lo - step >= 0 && scores(lo - step)) lo -= step;
  return 0.5 * (lo + hi);
}

/** Options of `throwPath`: the scene's gravity and drag, the ball's mass, and the box it flies in. */
export interface ThrowPathOptions {
  /** Gravity, m/s^2 down, >= 0. */
  gravity: number;
  /** The scene's drag law (scene.ts DragMode) and its k (kg/s linear, kg/m quadratic). */
  drag: DragMode;
  k: number;
  /** The ball's mass, kg (> 0) and radius, m (> 0). */
  mass: number;
  radius: number;
  /** The box, m: the path ends where the ball would touch a wall, the floor or the ceiling. */
  box: { readonly min: readonly [number, number]; readonly max: readonly [number, number] };
  /** Time between the points, s (> 0). Default 0.06. */
  every?: number;
  /** Longest path, s (> 0). Default 2. */
  seconds?: number;
  /** The integration step, s (> 0): the world's step. Default 1/60 (the scene's). */
  step?: number;
  /**
   * Bounces to follow, integer >= 0: at a wall of the box, a capsule of `walls` or the net of `hoop`,
   * the path bounces (restitution `restitution`) and goes on, until this many bounces have been made;
   * the next touch ends it. Default 0: the path ends at the first touch of the box, as without walls.
   */
  bounces?: number;
  /**
   * Bounces off the box's top (the ceiling) to follow besides `bounces`, integer >= 0: a touch of the
   * ceiling alone (no wall, floor or net in the same step) is followed without counting towards
   * `bounces` while any are left. Default 0. An aiming arc that would end where a high throw meets
   * the ceiling shows where the ball goes from there.
   */
  ceilingBounces?: number;
  /** Restitution of the bounces, [0, 1]. Default 0.8 (the scene's). */
  restitution?: number;
  /**
   * Friction coefficient of the bounces, >= 0. Default 0: the speed along a surface is kept. With
   * friction the bounce's sideways impulse spins the ball (a disc, I = m r^2 / 2) as the engine's
   * contacts do, which changes where it goes after the bounce.
   */
  friction?: number;
  /** The static capsules the ball bounces off, m: [ax, ay, bx, by, radius] (the scene's walls, the hoop's backboard and rim). */
  walls?: readonly (readonly [number, number, number, number, number])[];
  /** The hoop whose net (`netContact`) stops the ball as it would the real one. */
  hoop?: HoopSpot;
  /**
   * Balls the path ends at, m: [x, y, radius] each (the other balls near the throw, which move when
   * hit, so no bounce off them is predicted): the path's last point is where the ball first touches one.
   * An optional fourth number, an integer step count >= 0 (default 0), is the step from which that
   * ball stops the path: a ball the throw passes as it leaves the heap (main.ts leaveOf) stops it
   * only if the path still touches it once the leave is over.
   */
  stops?: readonly (readonly [number, number, number, number?])[];
}

/**
 * Where a ball thrown from (x, y), m, with velocity (vx, vy), m/s, flies, ignoring the other balls:
 * its centre every `every` s, flat [x0, y0, x1, y1, ...] starting at the throw, and at each bounce,
 * until `seconds` pass or it touches the box, a wall or the net once more than `bounces` allows (that
 * point is the last). Integrated in the scene's steps of `step` s with the acceleration held over
 * each step (x += v h + a h^2 / 2, v += a h): exact for the drag-free parabola, as the engine's
 * integrator is. A bounce reverses the speed into the surface times `restitution` (none below the
 * engine's 0.5 m/s restitution threshold) and, with `friction`, takes the impulse along the surface
 * that stops the contact point's slip (m / 3 of it for a disc), at most friction times the normal
 * impulse, which also spins the ball (tracked from 0 at the throw). The path ends where the ball
 * first touches one of `stops` (the other balls) moving into it, from that stop's step on.
 * @throws RangeError on a non-finite start or velocity, or a bad option.
 */
export function throwPath(x: number, y: number, vx: number, vy: number, o: ThrowPathOptions): number[] {
  if (![x, y, vx, vy].every(Number.isFinite))
    throw new RangeError(`throwPath: start and velocity must be finite, got (${x}, ${y}), (${vx}, ${vy})`);
  const every = o.every ?? 0.06,
    seconds = o.seconds ?? 2,
    h = o.step ?? 1 / 60;
  for (const [name, v] of [
    ['every', every],
    ['seconds', seconds],
    ['step', h],
    ['mass', o.mass],
    ['radius', o.radius],
  ] as const)
    if (!(v > 0 && Number.isFinite(v))) throw new RangeError(`throwPath: ${name} must be finite and > 0, got ${v}`);
  if (!(o.gravity >= 0 && o.k >= 0)) throw new RangeError(`throwPath: gravity and k must be >= 0, got ${o.gravity}, ${o.k}`);
  const most = o.bounces ?? 0,
    e = o.restitution ?? 0.8,
    mu = o.friction ?? 0;
  if (!(mu >= 0 && Number.isFinite(mu))) throw new RangeError(`throwPath: friction must be finite and >= 0, got ${mu}`);
  if (!(Number.isInteger(most) && most >= 0)) throw new RangeError(`throwPath: bounces must be an integer >= 0, got ${most}`);
  let ceilingLeft = o.ceilingBounces ?? 0;
  if (!(Number.isInteger(ceilingLeft) && ceilingLeft >= 0))
    throw new RangeError(`throwPath: ceilingBounces must be an integer >= 0, got ${ceilingLeft}`);
  if (!(e >= 0 && e <= 1)) throw new RangeError(`throwPath: restitution must be in [0, 1], got ${e}`);
  const perPoint = Math.max(1, Math.round(every / h));
  const r = o.radius,
    { min, max } = o.box;
  const walls = o.walls ?? [];
  const out = [x, y];
  const steps = Math.round(seconds / h);
  let bounced = 0,
    spin = 0;
  for (let n = 1; n <= steps; n++) {
    const px = x,
      py = y;
    let ax = 0,
      ay = -o.gravity;
    if (o.drag === 'linear') {
      ax -= (o.k / o.mass) * vx;
      ay -= (o.k / o.mass) * vy;
    } else if (o.drag === 'quadratic') {
      const v = Math.hypot(vx, vy);
      ax -= (o.k / o.mass) * v * vx;
      ay -= (o.k / o.mass) * v * vy;
    }
    x += (vx + 0.5 * ax * h) * h;
    y += (vy + 0.5 * ay * h) * h;
    vx += ax * h;
    vy += ay * h;
    // Touches: the box's sides (normal into the box), each wall (normal from the wall to the ball), the net.
    let touches = false,
      other = false;
    const bounce = (nx: number, ny: number, ceiling = false): void => {
      touches = true;
      if (!ceiling) other = true;
      const into = vx * nx + vy * ny;
      if (into >= 0) return;
      const jn = (1 + (-into > RESTITUTION_THRESHOLD ? e : 0)) * -into;
      vx += jn * nx;
      vy += jn * ny;
      // Along the surface (t = n turned +90 degrees): the contact point's slip v.t - spin r, stopped
      // by an impulse of m / 3 of it (a disc), at most mu times the normal one (both per unit mass).
      const tx = -ny,
        ty = nx;
      const slip = vx * tx + vy * ty - spin * r;
      const jt = Math.max(-mu * jn, Math.min(mu * jn, -slip / 3));
      vx += jt * tx;
      vy += jt * ty;
      spin -= (2 * jt) / r;
    };
    if (x - r <= min[0]) {
      x = min[0] + r;
      bounce(1, 0);
    } else if (x + r >= max[0]) {
      x = max[0] - r;
      bounce(-1, 0);
    }
    if (y - r <= min[1]) {
      y = min[1] + r;
      bounce(0, 1);
    } else if (y + r >= max[1]) {
      y = max[1] - r;
      bounce(0, -1, true);
    }
    for (const [wax, way, wbx, wby, wr] of walls) {
      const ex = wbx - wax,
        ey = wby - way;
      const t = Math.max(0, Math.min(1, ((x - wax) * ex + (y - way) * ey) / (ex * ex + ey * ey || 1)));
      const dx = x - wax - t * ex,
        dy = y - way - t * ey,
        d = Math.hypot(dx, dy);
      if (d >= r + wr || d === 0) continue;
      x = wax + t * ex + (dx / d) * (r + wr);
      y = way + t * ey + (dy / d) * (r + wr);
      bounce(dx / d, dy / d);
    }
    if (o.hoop) {
      const net = netContact(o.hoop, r, px, py, x, y, vx, vy);
      if (net) {
        touches = true;
        other = true;
        [x, y, vx, vy] = net;
      }
    }
    // Touching a stop while moving into it (a ball resting against the thrown one and left behind does not stop it).
    const stopped = (o.stops ?? []).some(
      ([sx, sy, sr, from = 0]) => n >= from && (x - sx) ** 2 + (y - sy) ** 2 < (r + sr) ** 2 && (x - sx) * vx + (y - sy) * vy < 0,
    );
    if (touches || stopped || n % perPoint === 0) out.push(x, y);
    if (stopped) break;
    if (touches && !other && ceilingLeft > 0) ceilingLeft--;
    else if (touches && ++bounced > most) break;
  }
  return out;
}
