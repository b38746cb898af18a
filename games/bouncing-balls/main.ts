/**
 * Bouncing balls: the book's bouncing balls grown up. Balls of different sizes and masses fall,
 * bounce off the box, the inclined walls (and their end points) and each other.
 *
 * The game on top (./hoop.ts): throw balls through the hoop for points in 60 s, each basket after the
 * first giving 3 s back (TIME_PER_BASKET); the hoop stays for 3 baskets (BASKETS_PER_HOOP, dots over
 * its board count them), so a throw that scored scores again, then moves once no thrown ball is in
 * flight (hoopAt follows round.spot then); the clock starts with the
 * first basket (a warm-up until then). The heap matters: a
 * pull that starts on one of its balls throws that ball, worth 2 (hoop.ts BALL_POINTS), and one of
 * them is gold (a halo, worth 5; a new one after it scores); a pull from empty space throws a new
 * basketball, worth 1. A swish (touching nothing on its way) adds 1, a trick shot off a side wall, the floor
 * or a ramp (not the box's top: a lob off it is no trick) adds 3 (hoop.ts SHOT_BONUS, markTouches). Baskets in a row multiply (x2, x3, x4: hoop.ts streakMultiplier); a thrown
 * ball that falls below the rim beside the hoop is a miss and ends the streak (falling notes). The
 * aiming arc ends with a red cross at a ball in its way; a heap ball buried under others is lifted to
 * the top of the heap over it first (liftSpot: its arc and its throw start there; with no room there
 * the pull is refused in red), and it leaves the balls it rests on freely (leaveOf). The best
 * round's points are kept in localStorage, one per court (best.ts); when time is up an end card over the box shows the points,
 * baskets, throws and longest streak, and R or the Play-again button starts a new round. The status
 * row above the box says the goal and shows points, the next basket's multiplier, time and best.
 *
 * Input: a finger's quick flick up throws the way it flicks, faster the quicker (flick.ts: read from
 * the pointer events' own times, so a flick throws at 10 frames a second as at 60; flickRelease), and
 * a press on the frame round the box counts as one just inside it (pressInBox). A click drops a ball at the pointer, and a pull throws one slingshot-style from where the
 * press began, on a ball or not; a pull from under the floor (the court's stand) throws the top ball
 * of the heap over it (columnTop; opposite to
 * the pull, faster the longer it is, hoop.ts slingVelocity: the height it reaches grows evenly over
 * the second half of the pull; on a phone held upright over all of it, from 1 m under the hoop's rim
 * to 3.5 m over it straight up, slingRoom, so every full pull can lob into the hoop), with a power gauge round the ball and a dotted arc of its flight
 * while pulling (hoop.ts throwPath: over its top and down to just above the rim's height, arcSeconds;
 * at least AIM_SECONDS of it, the same all round, 1.5 times as long on
 * a phone held upright (TALL_AIM_SCALE); fading out, up to its first touch of a ball, a wall, a ramp
 * or the hoop; the player judges the bounce and the last stretch). Each basketball thrown or dropped fades out once it has come to rest (MAX_LOOSE). A pull taken back
 * to within CANCEL_PULL of its press point ("release here to cancel") and let go throws nothing; the
 * same pull throws at the same speed wherever it is pressed (fullPull: no shorter full pull by the
 * window's edge, which made one pull throw at 62 % from one press and 69 % from another; a finger's,
 * fingerFullPull, fits under a ball on the floor, so a full-power pull stays on a phone's screen). A pull
 * under way as the clock runs out is the round's last throw: the round waits for it and its ball
 * (lastCall), under a big "Last throw!"; the last 10 s the clock is red, the last 5 a big countdown ticks. The net stops a
 * ball from below or the side (hoop.ts netContact). The player's balls are basketballs, all the same
 * size (hoop.ts PLAYER_RADIUS). Holding still on a ball or crate for HOLD_MS, 1 s (a ring fills from
 * HOLD_RING_MS on, labelled), picks it up with a mouse joint to carry it around; any pull before then
 * throws, so a press on the pile throws unless the pickup is meant. The band from the ball to the
 * pointer warms from white to gold to red with the pull's power; a release snaps and whooshes (louder
 * the faster) and a ring bursts from the ball. A basket is celebrated: a swish
 * and a rising chord, confetti from the rim (kept inside the court), "+1" and the hoop glowing out (the
 * new one ringed when it moved), and the status row's score bumps. Knocks: the loudest few collisions a step (knocks.ts), so
 * a pile does not roar. When time is up, the Play-again button floats over the stand under the box's
 * floor, clear of the ramps at its top. Until a press, a ring pulses round a ball to throw
 * (markThrowable; "drag me" over it until the round's first throw). A pull close to one that throws
 * through the middle of the hoop is drawn to it (currentThrow, aim-assist.ts). The aiming arc shows only
 * the first part of the flight and no verdict (preview.ts shortArc); after 3 misses in a row (aimHelp)
 * it shows the whole flight as help until the next basket: a throw that goes in then shows its arc on
 * into the net, green, the rim ringed green and "on target" by the gauge (throwScores).
 *
 * Looks: a court (a wall with panels over a wooden floor, the box framed in steel), wooden ramps,
 * plain coloured balls (no rotation marks, no trails unless asked for), a plain white backboard,
 * an orange rim and a net of diamond mesh; the player's balls are orange with black seams
 * that turn with the ball.
 * Keys: P pause (the play area dims and says so), N single step, R new round, T trails, D debug overlay.
 * URL: ?count=N (balls, 1..10000; default 40, 20 on a tall screen), ?round=S (hoop round, s, 5..600), ?seed=S, ?mode=auto|sprites|particles, ?trails=0|1, ?debug.
 * From 1000 balls on (mode auto) the renderer draws with pixi's ParticleContainer.
 */

import {
  choiceParam,
  createActionButton,
  createPanel,
  createStatusRow,
  flagParam,
  forEachImpact,
  getSound,
  numberParam,
  pageLayout,
  pauseUnderDrawers,
  plural,
  type SoundMaterial,
  seedParam,
} from '@bitphysics/game-kit';
import { enableMouseDrag } from '@bitphysics/game-kit/drag';
import { createPauseOverlay, createResultCard, startPixiGame } from '@bitphysics/game-kit/pixi';
import {
  addBox,
  addSystem,
  createPhysicsWorld,
  type PhysicsWorld,
  Rng,
  restore,
  setAngularVelocity,
  setMaterial as setBodyMaterial,
  setPosition,
  setVelocity,
  slotOf,
  snapshot,
  step,
  type WorldSnapshot,
} from '@bitphysics/physics';
import { Graphics, Text } from 'pixi.js';
import { assistAim } from './aim-assist';
import { pageStorage, readBest, writeBest } from './best';
import { FINGER_REACH_PX, fingerBall } from './finger-pick';
import { FlickTracker, flickPull } from './flick';
import {
  addHoop,
  assistPull,
  BACKBOARD,
  BALL_POINTS,
  type BallKind,
  createRound,
  FRONT_RIM_LENGTH,
  goldChoices,
  HOOP_HALF_WIDTH,
  HOOP_RADIUS,
  type HoopRound,
  type HoopSpot,
  hoopCrossing,
  hoopOpening,
  hoopSegments,
  hoopSpots,
  MAX_THROW_SPEED,
  MISS_SECONDS,
  mayScore,
  missWords,
  NET,
  netContact,
  PLAYER_RADIUS,
  ROUND_SECONDS,
  removeHoop,
  roundBasket,
  roundMiss,
  roundShot,
  roundTick,
  SHOT_BONUS,
  type ShotStyle,
  type SlingRoom,
  slingPull,
  slingRoom,
  slingVelocity,
  streakMultiplier,
  TIME_PER_BASKET,
  throwPath,
  underHoop,
} from './hoop';
import { createKnockLimiter, KNOCK_LIMITS } from './knocks';
import { drawFloor, drawGlint, drawShadow, drawWall, shadeBallTexture } from './looks';
import { aimHelp, shortArc } from './preview';
import { pressInBox, ringInside } from './pull-fit';
import { noShotWords } from './reach';
import {
  applyDrag,
  applyGravity,
  applyMaterial,
  type BouncingBallsHandles,
  bouncingBallsWorldOptions,
  buildBouncingBalls,
  DENSITIES,
  DRAG_MODES,
  type DragMode,
  isHeavy,
  layoutOf,
  meanRadiusFor,
  removeBall,
  SEGMENT_RADIUS,
  spawnBall,
} from './scene';
import { forEachTouch } from './touches';

/** Colour of the heavy balls (density 4 kg/m^2, steel); the others keep their seeded colours from BALL_PALETTE. */
const HEAVY_COLOR = 0xa9b4c6;
/** The sandbox balls' colours: bright, so they read on the court's dark wall; no yellow or orange, the gold ball's and the basketballs'. */
const BALL_PALETTE = [0x4cc9f0, 0xf15bb5, 0x9b5de5, 0x00bbf9, 0x00f5d4, 0xb8a1ff, 0xff6b6b, 0x8ac926, 0xff8fab, 0x72efdd];
/** A mouse press that moves less than this, CSS px, is a click (drop) or a hold; more is a throw. */
const CLICK_SLOP = 6;
/** The same for a finger, CSS px: a fingertip resting on glass wobbles a few pixels. */
const TOUCH_SLOP = 12;
/**
 * A pull shorter than this, CSS px (for a finger, or than the thrown ball's drawn radius, if that is
 * larger: cancelRadius), let go cancels the aim: no throw, no shot, the streak kept. Dragging back
 * onto the press point takes it back.
 */
const CANCEL_PULL = 15;
/** A screen taller than wide (a phone held upright) gets the tall box, which fills it. */
const TALL = window.innerHeight > 1.2 * window.innerWidth;
/**
 * Sandbox balls at the start: 40, or 20 in the tall box, where 40 balls of the same size crowd a
 * court 360 px wide and cross most throws (the aiming arc ignores them).
 */
const initialCount = numberParam('count', { default: TALL ? 20 : 40, min: 1, max: 10_000, integer: true });
const params = {
  count: initialCount,
  seed: seedParam(),
  gravity: 9.81,
  restitution: 0.8,
  friction: 0.2,
  drag: 'none' as DragMode,
  dragK: 0.05,
  // Off unless asked for: trails read as a physics plot, not a game.
  trails: flagParam('trails'),
  debug: flagParam('debug'),
  reset: () => game.shell.reset(),
};
/** Length of a hoop round, s (?round=S, 5..600). */
const roundSeconds = numberParam('round', { default: ROUND_SECONDS, min: 5, max: 600 });
const mode = choiceParam('mode', ['auto', 'sprites', 'particles'] as const, 'auto');

let handles: BouncingBallsHandles;
/** Crates dropped with X (boxes: shapes that tumble among the balls), oldest first. */
let crates: number[] = [];
/** The hoop game's round (a new one with each world: R restarts the round). */
let round: HoopRound = createRound(roundSeconds);
/** Entity ids of the hoop's backboard and front rim. */
let hoopIds: number[] = [];
/**
 * The spot index where the hoop stands (its bodies, its drawing, the aim): the round's spot
 * (round.spot), which it follows once no thrown ball is in flight (playHoop).
 */
let hoopAt = 0;
/** When the hoop last moved to a new spot, world s (its ring closing in on the new rim: drawCelebration). */
let hoopMovedAt = Number.NEGATIVE_INFINITY;
/**
 * The balls in flight after a throw: whether each may still score (released below the rim, not up
 * through the net), its centre after the last step, m, what it is worth (BALL_POINTS), the world
 * time it was thrown, s, and what it has touched since (markTouches): anything (`touched`: no swish)
 * and a wall of the box or a ramp (`trick`), its centre's highest point, m (`top`: missWords), and
 * whether it went up through the net (`up`). A ball that has not gone in MISS_SECONDS after its throw
 * is a miss and leaves.
 */
let flights = new Map<
  number,
  {
    scores: boolean;
    up: boolean;
    x: number;
    y: number;
    top: number;
    kind: BallKind;
    at: number;
    touched: boolean;
    trick: boolean;
    /** noShotAt of its start: '' when some pull from there scores. */
    noShot: string;
  }
>();
/** The player's basketballs (made by a throw or a click from empty space): drawn orange with seams. */
let basketballs = new Set<number>();
/** The heap's gold ball (0 when the heap is empty): worth BALL_POINTS.gold. */
let goldBall = 0;
/** Colour of the player's balls (a basketball's orange), of those released too high to score, and of the gold ball. */
const PLAYER_COLOR = 0xff8a2a;
const HIGH_COLOR = 0x9aa4b5;
/** The aiming dots of a throw from above the rim's line: lighter than HIGH_COLOR, to stand out on the wall. */
const HIGH_AIM_COLOR = 0xe6ebf3;
const GOLD_COLOR = 0xffd23f;
/** The aiming arc's dots and the rim's ring when the throw goes in (throwScores): a bright green, clear of the orange and grey dots. */
const ON_TARGET_COLOR = 0x5cf08a;
/** The best round's points (a basket's points: ball x streak) on this court, kept across reloads (best.ts). */
let best = readBest(pageStorage(), TALL);
/**
 * The best points kept when the round began (0 when none): the end card cheers a new best only when
 * the round beats a best there was; a first scoring round is a score to beat, not a record.
 */
let bestBefore = best;
/** Whether the round's points beat a best kept before it began (a real one: bestBefore > 0). */
function beatBest(): boolean {
  return bestBefore > 0 && round.points > bestBefore;
}
/**
 * The last basket, for its celebration: where it went in (the rim's centre, m), the world time it was
 * scored (s), the hoop's spot it went through (an index of hoopSpots) and the score it made.
 */
let lastBasket: {
  x: number;
  y: number;
  time: number;
  spot: number;
  moved: boolean;
  score: number;
  points: number;
  kind: BallKind;
  style: ShotStyle;
} = {
  x: 0,
  y: 0,
  time: -10,
  spot: 0,
  moved: false,
  score: 0,
  points: 0,
  kind: 'basketball',
  style: 'plain',
};
/** When a thrown ball last missed (playSeconds, s of game time), for the status row's word (missSaid, MISS_SHOWN s). */
let missAt = -1e9;
/** How long the status row says a miss, s of game time. */
const MISS_SHOWN = 2.5;
/** What the status row says of the last miss (hoop.ts missWords), or of a flick too slow to throw (release). */
let missSaid = 'Missed';
/** The player's misses in a row (across rounds; a basket ends them): from AIM_HELP_MISSES on the aiming arc shows its whole flight and verdict (preview.ts aimHelp). */
let missesInARow = 0;
/** Whether the aiming arc always shows its whole flight and verdict (the test hook aimHelp; preview.ts). */
let aimHelpAlways = false;

/** Builds a fresh world with the scene from the current params (the shell calls it at start and on R). */
function createWorld(): PhysicsWorld {
  const options = {
    count: params.count,
    seed: params.seed,
    gravity: params.gravity,
    restitution: params.restitution,
    friction: params.friction,
    drag: params.drag,
    dragK: params.dragK,
    tall: TALL,
  };
  const world = createPhysicsWorld(bouncingBallsWorldOptions(options));
  handles = buildBouncingBalls(world, options);
  settleHeap(world, handles, options);
  crates = [];
  // Each round's warm-up hoop is the layout's first spot; after it the spots come in an order of the
  // round's own (hoopOrder).
  round = createRound(roundSeconds);
  bestBefore = best;
  flights = new Map();
  basketballs = new Set();
  fading = new Map();
  goldBall = 0;
  goldRng = new Rng(params.seed + 7);
  missAt = -1e9;
  lastCall = { aiming: false, ball: 0 };
  ruleHint = '';
  lastThrown = 0;
  lastBasket = { x: 0, y: 0, time: -10, spot: 0, moved: false, score: 0, points: 0, kind: 'basketball', style: 'plain' };
  hoopAt = round.spot;
  hoopMovedAt = Number.NEGATIVE_INFINITY;
  hoopIds = addHoop(world, hoopSpots(TALL)[hoopAt]!, params.restitution, params.friction);
  leaving = new Map();
  addSystem(world, 'integrate', keepLeavingFree);
  addSystem(world, 'collide', leaveFreely);
  return world;
}

// ---- The heap starts settled ---------------------------------------------------------------------

/** Most balls whose heap is settled before the world is shown (settleHeap); more start on their grid and fall. */
const SETTLE_MAX_BALLS = 200;
/** The longest settle, s of simulated time (settleHeap stops sooner once every ball is slower than SETTLE_SPEED). */
const SETTLE_SECONDS = 10;
/** A settling ball whose bottom is this close to the floor, m, is on it (settleHeap stops it turning). */
const SETTLE_FLOOR_GAP = 0.02;
/** A settling ball slower than this, m/s, is at rest. */
const SETTLE_SPEED = 0.1;

/**
 * Starts the balls of a new `world` (built by buildBouncingBalls with `options`) where they have
 * fallen to: the scene is built again in a world of its own with no bounce (restitution 0, so the
 * balls land and stay) and no hoop (on whose rim and backboard balls came to rest), stepped until
 * every ball is slower than SETTLE_SPEED (at most SETTLE_SECONDS), and each ball of `world` takes its
 * twin's place and motion (a ball still rolling off a ramp rolls on). The twin's balls on the floor
 * do not turn (rolling, they crossed the box for seconds). `world` itself takes no step:
 * its step 0 is the fallen heap, the same for a seed every time (R). A page opened on a grid of balls
 * hanging in the air for the seconds they took to fall and stop bouncing. Nothing is done past
 * SETTLE_MAX_BALLS balls (the sandbox's thousands fall as built). Each heap is settled once a page
 * (settled).
 */
function settleHeap(world: PhysicsWorld, h: BouncingBallsHandles, options: Parameters<typeof buildBouncingBalls>[1]): void {
  if (h.balls.length > SETTLE_MAX_BALLS) return;
  const key = JSON.stringify(options);
  let fallen = settled.get(key);
  if (!fallen) {
    fallen = fallenHeap(options);
    settled.set(key, fallen);
  }
  for (let i = 0; i < h.balls.length; i++) {
    const e = h.balls[i]!;
    setPosition(world, e, [fallen[5 * i]!, fallen[5 * i + 1]!]);
    setVelocity(world, e, [fallen[5 * i + 2]!, fallen[5 * i + 3]!]);
    setAngularVelocity(world, e, fallen[5 * i + 4]!);
  }
}

/**
 * The fallen heaps made so far, by their scene's options (JSON): each ball's x, y (m), vx, vy (m/s)
 * and spin (rad/s), five numbers a ball in build order. A heap is the same every time for the same
 * options, so R and Play again reuse it instead of settling it again.
 */
const settled = new Map<string, Float64Array>();

/** The twin world of settleHeap for a scene built with `options`, stepped until its heap has fallen: fallen's five numbers a ball. */
function fallenHeap(options: Parameters<typeof buildBouncingBalls>[1]): Float64Array {
  const calm = { ...options, restitution: 0 };
  const twin = createPhysicsWorld(bouncingBallsWorldOptions(calm));
  const twins = buildBouncingBalls(twin, calm);
  const P = twin.components.Position,
    V = twin.components.Velocity,
    W = twin.components.AngularVelocity;
  const most = Math.round(SETTLE_SECONDS / twin.dt);
  const floor = layoutOf(TALL).box.min[1],
    R = twin.components.Ball.radius;
  for (let n = 1; n <= most; n++) {
    step(twin);
    // A ball on the floor stops turning, so it slides to a stop: one rolling there rolled for ever.
    for (const e of twins.balls) if (P.y[slotOf(e)]! - R[slotOf(e)]! < floor + SETTLE_FLOOR_GAP) W.z[slotOf(e)] = 0;
    if (n % 10 === 0 && twins.balls.every((e) => V.x[slotOf(e)]! ** 2 + V.y[slotOf(e)]! ** 2 < SETTLE_SPEED ** 2)) break;
  }
  const out = new Float64Array(5 * twins.balls.length);
  twins.balls.forEach((e, i) => {
    const s = slotOf(e);
    out.set([P.x[s]!, P.y[s]!, V.x[s]!, V.y[s]!, W.z[s]!], 5 * i);
  });
  return out;
}

// ---- A thrown ball leaves the balls it rests on freely ------------------------------------------

/**
 * The longest a thrown ball of the scene flies free of the balls it rested on as it leaves them, s:
 * their contacts, still in the solver for a step or two, pushed it off its aimed arc.
 */
const LEAVE_MAX_SECONDS = 0.2;

/**
 * The thrown balls leaving the heap: until (world time, s), their state after the last integrate (m,
 * m/s), and the balls it touched then with their state (id, x, y, vx, vy; m, m/s), whose push by it
 * the collide that follows is made sideways only.
 */
let leaving = new Map<number, { until: number; x: number; y: number; vx: number; vy: number; near: number[] }>();

/** After each (sub)step's integrate: each leaving ball's state as it flies free of contacts, until its leave ends. */
function keepLeavingFree(world: PhysicsWorld): void {
  if (leaving.size === 0) return;
  const P = world.components.Position,
    V = world.components.Velocity;
  for (const [e, l] of leaving) {
    if (world.time >= l.until || !handles.balls.includes(e)) {
      leaving.delete(e);
      continue;
    }
    const s = slotOf(e);
    l.x = P.x[s]!;
    l.y = P.y[s]!;
    l.vx = V.x[s]!;
    l.vy = V.y[s]!;
    // The balls it may touch in this collide (within a step's travel of touching it), as they are before it.
    const R = world.components.Ball.radius,
      reach = R[s]! + Math.hypot(l.vx, l.vy) * world.h;
    l.near.length = 0;
    for (const o of handles.balls) {
      if (o === e) continue;
      const q = slotOf(o);
      if ((P.x[q]! - l.x) ** 2 + (P.y[q]! - l.y) ** 2 < (reach + R[q]!) ** 2) l.near.push(o, P.x[q]!, P.y[q]!, V.x[q]!, V.y[q]!);
    }
  }
}

/**
 * After each (sub)step's collide: a leaving ball goes on as if the balls round it were not there,
 * unless it touches the box, a ramp or the hoop: then it stops leaving and bounces as any ball does.
 * The balls it passes are pushed aside, not ahead: of what the collide did to them, the part along the
 * thrown ball's way is taken back (a ball pushed ahead of it, up through the heap, would be in its
 * way again when the leave ended, and it would plough).
 */
function leaveFreely(world: PhysicsWorld): void {
  if (leaving.size === 0) return;
  const P = world.components.Position,
    V = world.components.Velocity;
  const { box, segments } = layoutOf(TALL);
  const walls = [
    ...segments.map(([ax, ay, bx, by]) => [ax, ay, bx, by, SEGMENT_RADIUS] as const),
    ...hoopSegments(hoopSpots(TALL)[hoopAt]!).map(([ax, ay, bx, by]) => [ax, ay, bx, by, HOOP_RADIUS] as const),
  ];
  for (const [e, l] of leaving) {
    const s = slotOf(e);
    const r = world.components.Ball.radius[s]!;
    const clear =
      l.x - r > box.min[0] &&
      l.x + r < box.max[0] &&
      l.y - r > box.min[1] &&
      l.y + r < box.max[1] &&
      walls.every(([ax, ay, bx, by, wr]) => distanceToSegment(l.x, l.y, ax, ay, bx, by) > r + wr);
    if (!clear) {
      leaving.delete(e);
      continue;
    }
    P.x[s] = l.x;
    P.y[s] = l.y;
    V.x[s] = l.vx;
    V.y[s] = l.vy;
    const speed = Math.hypot(l.vx, l.vy);
    if (speed === 0) continue;
    const ux = l.vx / speed,
      uy = l.vy / speed;
    for (let i = 0; i < l.near.length; i += 5) {
      const o = l.near[i]!;
      if (!handles.balls.includes(o)) continue;
      const q = slotOf(o);
      const dp = (P.x[q]! - l.near[i + 1]!) * ux + (P.y[q]! - l.near[i + 2]!) * uy,
        dv = (V.x[q]! - l.near[i + 3]!) * ux + (V.y[q]! - l.near[i + 4]!) * uy;
      if (dp > 0) {
        P.x[q] = P.x[q]! - dp * ux;
        P.y[q] = P.y[q]! - dp * uy;
      }
      if (dv > 0) {
        V.x[q] = V.x[q]! - dv * ux;
        V.y[q] = V.y[q]! - dv * uy;
      }
    }
  }
}

// ---- A buried ball is lifted to the top of the heap before it is thrown ------------------------------

/**
 * Whether ball `e` of the scene is buried: another ball touches it (within 0.03 m) from above, its
 * centre higher by more than 0.15 of their radii's sum (some 80 degrees or less from straight up). A
 * throw from there would drive into that ball at once: a buried ball is lifted first (liftSpot), and
 * its arc and its throw both start where it is lifted to.
 */
function buried(e: number): boolean {
  return someNeighbour(e, false, (_dx, dy, d, sum) => dy > 0.15 * sum && d < sum + 0.03);
}

/**
 * Whether another ball of the scene than `e` (not one in flight when `resting`) passes `test`, given
 * its centre's offset from e's, (dx, dy), m, their distance, m, and their radii's sum, m: the one scan
 * of e's neighbours that buried and freeUp both make.
 */
function someNeighbour(e: number, resting: boolean, test: (dx: number, dy: number, d: number, sum: number) => boolean): boolean {
  const c = shell.world.components,
    P = c.Position,
    R = c.Ball.radius,
    s = slotOf(e);
  const x = P.x[s]!,
    y = P.y[s]!;
  for (const o of handles.balls) {
    if (o === e || (resting && flights.has(o))) continue;
    const q = slotOf(o);
    const dx = P.x[q]! - x,
      dy = P.y[q]! - y;
    if (test(dx, dy, Math.hypot(dx, dy), R[s]! + R[q]!)) return true;
  }
  return false;
}

/** How far clear of every other ball a lifted ball is put, m. */
const LIFT_CLEARANCE = 0.01;

/**
 * Where ball `e` starts its throw, m: where it is unless it is buried (`buried`) or `lift` (default: it
 * is the ball a finger pressed on that has no free way up, fingerLift); then the lowest spot
 * straight above it that is clear of every other ball (by LIFT_CLEARANCE), of the ramps and the hoop,
 * and inside the box: on top of the heap over it. null when a buried ball has no such spot (the heap
 * reaches the box's top, or a ramp or the hoop lies over it): the press is refused.
 */
function liftSpot(e: number, lift = e === fingerLift): [number, number] | null {
  const c = shell.world.components,
    P = c.Position,
    R = c.Ball.radius,
    s = slotOf(e);
  const x = P.x[s]!,
    y = P.y[s]!,
    r = R[s]!;
  if (!lift && !buried(e)) return [x, y];
  const { box, segments } = layoutOf(TALL);
  const walls = [
    ...segments.map(([ax, ay, bx, by]) => [ax, ay, bx, by, SEGMENT_RADIUS] as const),
    ...hoopSegments(hoopSpots(TALL)[hoopAt]!).map(([ax, ay, bx, by]) => [ax, ay, bx, by, HOOP_RADIUS] as const),
  ];
  // The column over the ball: the balls it would meet going straight up, and the heights (centre, m)
  // at which it would rest on each of them.
  const column: number[] = [];
  const heights: number[] = [];
  for (const o of handles.balls) {
    if (o === e) continue;
    const q = slotOf(o);
    const dx = P.x[q]! - x,
      reach = r + R[q]! + LIFT_CLEARANCE;
    if (Math.abs(dx) >= reach) continue;
    column.push(q);
    const top = P.y[q]! + Math.sqrt(reach * reach - dx * dx);
    if (top > y) heights.push(top + 1e-6);
  }
  heights.sort((u, v) => u - v);
  // Not through a ramp or the hoop: the way straight up (past the first 0.05 m, where a ball resting on
  // a ramp still touches it) must stay a ball's radius clear of them.
  const through = (h: number): boolean => {
    for (let yy = y + 0.05; yy < h; yy += 0.05)
      if (walls.some(([ax, ay, bx, by, wr]) => distanceToSegment(x, yy, ax, ay, bx, by) < r + wr - 0.01)) return true;
    return false;
  };
  for (const h of heights) {
    if (h + r > box.max[1] || through(h)) return null;
    if (column.some((q) => (P.x[q]! - x) ** 2 + (P.y[q]! - h) ** 2 < (r + R[q]! + LIFT_CLEARANCE) ** 2 - 1e-9)) continue;
    if (walls.some(([ax, ay, bx, by, wr]) => distanceToSegment(x, h, ax, ay, bx, by) < r + wr)) continue;
    return [x, h];
  }
  return null;
}

/** Distance from (px, py) to the segment (ax, ay)-(bx, by), m. */
function distanceToSegment(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const ex = bx - ax,
    ey = by - ay;
  const t = Math.max(0, Math.min(1, ((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey || 1)));
  return Math.hypot(px - ax - t * ex, py - ay - t * ey);
}

/**
 * How a ball of radius `r`, m, thrown from (x, y), m, with velocity (vx, vy), m/s, leaves the balls
 * it rests on (`near`, the balls near its start, [x, y, radius] each, m): those it touches (within
 * 0.02 m and a step's travel, as the engine's contacts begin) and moves away from are `met`; the leave
 * lasts the world steps (of `h` s) its drag-free path stays within that reach of one of them, up to
 * LEAVE_MAX_SECONDS, and ends at the first step clear of them all. It passes no ball it moves into:
 * that ball ends its aiming arc at once (arcStops). The page's throw and its aiming arc both use this.
 */
function leaveOf(
  near: readonly [number, number, number][],
  x: number,
  y: number,
  vx: number,
  vy: number,
  r: number,
  h: number,
): { steps: number; met: Set<[number, number, number]> } {
  const g = handles.params.gravity;
  const reach = r + Math.hypot(vx, vy) * h + 0.02;
  const met = new Set<[number, number, number]>();
  for (const b of near) if ((x - b[0]) ** 2 + (y - b[1]) ** 2 < (reach + b[2]) ** 2 && (b[0] - x) * vx + (b[1] - y) * vy <= 0) met.add(b);
  const hard = Math.round(LEAVE_MAX_SECONDS / h);
  let steps = 0;
  for (let n = 1; n <= hard && met.size > 0; n++) {
    const t = n * h;
    const px = x + vx * t,
      py = y + vy * t - 0.5 * g * t * t;
    let inside = false;
    for (const b of met) if ((px - b[0]) ** 2 + (py - b[1]) ** 2 < (reach + b[2]) ** 2) inside = true;
    if (!inside) break;
    steps = n;
  }
  return { steps, met };
}

/** Drops a crate (a box of about two mean ball diameters, turned a little) near the top of the box. */
function dropCrate(): number {
  const r = handles.meanRadius,
    n = crates.length;
  const { box } = layoutOf(TALL);
  const span = box.max[0] - box.min[0] - 8;
  const crate = addBox(shell.world, {
    position: [box.min[0] + 4 + ((n * 2.7) % span), box.max[1] - 1],
    angle: 0.4 * ((n % 5) - 2),
    halfExtents: [2 * r, 1.4 * r],
    density: 1 / (Math.PI * r * r),
    restitution: params.restitution,
    friction: params.friction,
  });
  crates.push(crate);
  return crate;
}

/** Trail settings: one trail per ball up to 400 balls (36 frames long). */
function trailOptions(count: number) {
  return { length: 36, maxEntities: Math.min(400, Math.max(1, count + 200)) };
}

const sound = getSound();

/** What a body sounds like: a crate wood, a heavy ball metal, the others rubber; walls stone. */
function materialOf(world: PhysicsWorld, body: number): SoundMaterial {
  if (body <= 0) return 'stone';
  // The rim and the backboard clang.
  if (hoopIds.includes(body)) return 'metal';
  if (crates.includes(body)) return 'wood';
  return isHeavy(world, body) ? 'metal' : 'soft';
}

/** What a ball is worth in a basket: the gold ball, one of the player's basketballs, or a ball of the heap. */
function kindOf(e: number): BallKind {
  return e === goldBall ? 'gold' : basketballs.has(e) ? 'basketball' : 'heap';
}

/**
 * Makes a new gold ball: a heap ball (not a basketball, not in flight, not `not`) picked at random
 * among hoop.ts goldChoices (out from under the hoop, where it could not score, and with no ball
 * right above it, so the player can reach and throw it); 0 when the heap is empty.
 */
function pickGold(world: PhysicsWorld, not = 0): void {
  const c = world.components,
    P = c.Position;
  const heap = handles.balls.filter((e) => !basketballs.has(e) && !flights.has(e) && e !== not);
  const at = heap.map((e) => [P.x[slotOf(e)]!, P.y[slotOf(e)]!, c.Ball.radius[slotOf(e)]!] as const);
  const from = goldChoices(hoopSpots(TALL)[hoopAt]!, at).map((i) => heap[i]!);
  goldBall = from.length > 0 ? from[Math.floor(goldRng.next() * from.length)]! : 0;
  goldRest = 0;
  if (goldBall === 0) return;
  goldWas = renderer.colorOf(goldBall);
  renderer.setColor(goldBall, GOLD_COLOR);
}

/**
 * Keeps the gold ball one that can score: once it has lain at rest (under GOLD_REST_SPEED, not in
 * flight, held or pressed to aim) under the hoop (hoop.ts underHoop: a miss that dropped under the backboard, or a
 * hoop that moved over it) for GOLD_REST_SECONDS, it is a heap ball again and another one is gold.
 */
function keepGoldPlayable(world: PhysicsWorld): void {
  if (goldBall === 0 || !handles.balls.includes(goldBall)) return;
  const s = slotOf(goldBall),
    P = world.components.Position,
    V = world.components.Velocity;
  const resting =
    !flights.has(goldBall) && drag.body !== goldBall && pressBall !== goldBall && Math.hypot(V.x[s]!, V.y[s]!) < GOLD_REST_SPEED;
  goldRest = resting && underHoop(hoopSpots(TALL)[hoopAt]!, P.x[s]!, P.y[s]!) ? goldRest + world.dt : 0;
  if (goldRest < GOLD_REST_SECONDS) return;
  const old = goldBall;
  renderer.setColor(old, goldWas);
  pickGold(world, old);
}
/** How long the gold ball lies at rest under the hoop before another ball is gold, s. */
const GOLD_REST_SECONDS = 0.5;
/** Below this speed the gold ball is at rest, m/s. */
const GOLD_REST_SPEED = 0.3;
/** How long the gold ball has lain at rest under the hoop, s. */
let goldRest = 0;
/** The gold ball's own colour, given back when another ball becomes gold while it is in the scene. */
let goldWas = 0;
/** Picks the gold balls (seeded, so a seed's round is the same). */
let goldRng = new Rng(1);
/**
 * Deals the hoop's spots as it moves (hoop.ts nextSpot): made once per page from the seed, not
 * per world, so every new round (R, Play again) goes round the hoops in another order, and a page with
 * a given ?seed plays the same rounds in the same order.
 */
const hoopOrder = new Rng(params.seed * 31 + 17);
/** hoopOrder's next number in [0, 1), for nextSpot. */
const hoopRandom = (): number => hoopOrder.next();

/**
 * The hoop game after a step: a thrown ball whose centre went down through the hoop's opening is a
 * basket (the ball is taken out, the hoop moves on after every BASKETS_PER_HOOP of them; the gold
 * ball goes to another heap ball); a
 * thrown ball still out MISS_SECONDS after its throw is a miss, which ends the streak; then the clock
 * runs. Keeps the best score.
 */
function playHoop(world: PhysicsWorld): void {
  const P = world.components.Position;
  const spots = hoopSpots(TALL);
  const opening = hoopOpening(spots[hoopAt]!);
  for (const [e, b] of flights) {
    if (!handles.balls.includes(e)) {
      flights.delete(e);
      continue;
    }
    const x = P.x[slotOf(e)]!,
      y = P.y[slotOf(e)]!;
    const crossing = hoopCrossing(opening, b.x, b.y, x, y);
    if (crossing === 1 && b.scores) {
      // Up through the hoop from below: no basket when it comes back down.
      b.scores = false;
      b.up = true;
      if (basketballs.has(e)) renderer.setColor(e, HIGH_COLOR);
      if (e === lastThrown) ruleHint = 'below';
    }
    const wasSpot = round.spot;
    const style: ShotStyle = b.trick ? 'trick' : b.touched ? 'plain' : 'swish';
    if (b.scores && crossing === -1 && roundBasket(round, spots.length, b.kind, hoopRandom, style)) {
      // A basket in the hoop still standing where the round's last spot was (waiting for this ball):
      // it is no basket of the next hoop's, which starts its count from none.
      if (hoopAt !== wasSpot && !round.lastMoved) round.atHoop = 0;
      lastBasket = {
        x: opening.minX + 0.5 * (opening.maxX - opening.minX),
        y: opening.y,
        time: world.time,
        spot: hoopAt,
        moved: round.spot !== wasSpot,
        score: round.score,
        points: round.lastPoints,
        kind: b.kind,
        style,
      };
      flights.delete(e);
      basketballs.delete(e);
      missesInARow = 0;
      const sunk = world.components.Ball.radius[slotOf(e)]!;
      removeBall(world, handles, e);
      feedHeap(world, opening, sunk);
      if (e === goldBall) pickGold(world);
      cheer(round.score, b.kind);
      keepBest();
      continue;
    }
    b.x = x;
    b.y = y;
    b.top = Math.max(b.top, y);
    // Falling below the rim's line beside the hoop (the way in is down through it), or out too long: a
    // miss. A ball above the rim over the hoop (on the backboard's top, on the rim) may still drop in:
    // it has MISS_SECONDS more, and then the rest of MISS_SECONDS_OVER_HOOP.
    const falling = world.components.Velocity.y[slotOf(e)]! < 0 && y < opening.y;
    const overHoop = y >= opening.y && x > opening.minX - HOOP_REACH && x < opening.maxX + HOOP_REACH;
    const out = world.time - b.at;
    if (falling || out > MISS_SECONDS_OVER_HOOP || (out > MISS_SECONDS && !overHoop)) {
      flights.delete(e);
      if (round.phase === 'over') continue;
      if (b.scores) {
        const broke = roundMiss(round);
        missesInARow++;
        // Every miss is said, with why (a throw off the ceiling back onto the heap looked like none).
        missAt = playSeconds;
        missSaid = b.noShot
          ? `Missed · ${b.noShot}${broke ? ' · streak over' : ''}`
          : missWords(broke, b.top, layoutOf(TALL).box.max[1] - world.components.Ball.radius[slotOf(e)]!, spots[hoopAt]!);
        // A falling pair of low notes: the streak is gone.
        if (broke) {
          sound.chime(294, 0.2);
          setTimeout(() => sound.chime(220, 0.35), 110);
        }
      }
      // Said on the court too, where the ball is (the status row is far from a thumb's throw).
      // Short enough for a phone's court: the streak is in the status row.
      const ceiling = layoutOf(TALL).box.max[1] - world.components.Ball.radius[slotOf(e)]!;
      // A throw from where no pull scores says so (noShotAt), in short: the status row says where to go.
      const said = b.noShot
        ? `No shot ${b.noShot.slice('no shot '.length, b.noShot.indexOf(':'))}`
        : missWords(false, b.top, ceiling, spots[hoopAt]!);
      sayOnCourt(b.scores ? said : b.up ? 'Up through the net' : 'Too high to score', x, y);
    }
  }
  // The hoop stays for BASKETS_PER_HOOP baskets (hoop.ts roundBasket), then moves, once no thrown
  // ball is in flight: a ball thrown at it lands or misses where it was aimed.
  if (hoopAt !== round.spot && flights.size === 0) {
    removeHoop(world, hoopIds);
    hoopAt = round.spot;
    hoopIds = addHoop(world, spots[hoopAt]!, handles.params.restitution, handles.params.friction);
    hoopMovedAt = world.time;
  }
  if (lastThrowPending(world.dt)) round.timeLeft = Math.max(0, round.timeLeft - world.dt);
  else if (roundTick(round, world.dt)) {
    // Time is up: a press under way that was not a pull ends with nothing done.
    endAim();
    keepBest();
    sound.chime(440, 0.6);
    setTimeout(() => sound.chime(554.37, 0.5), 160);
    setTimeout(() => sound.chime(659.25, 0.9), 320);
  }
}

/**
 * The round's last throw: when the clock reaches 0 with a pull under way, the round waits for it to be
 * let go (`aiming`), then for the ball it throws (`ball`, its id) to score or miss, and only then is
 * time up, so a throw being aimed as time runs out is not lost. No new press starts meanwhile.
 */
let lastCall = { aiming: false, ball: 0 };

/**
 * Whether the round's end waits for its last throw (lastCall) after this step of `dt` s: the pull
 * under way as the clock reaches 0, then its ball while it is in flight and may still score.
 */
function lastThrowPending(dt: number): boolean {
  if (round.phase !== 'playing') return false;
  if (lastCall.aiming) return true;
  if (lastCall.ball !== 0) {
    if (flights.get(lastCall.ball)?.scores) return true;
    lastCall.ball = 0;
    return false;
  }
  if (round.timeLeft <= dt && pointerId !== -1 && dragged) {
    lastCall.aiming = true;
    return true;
  }
  return false;
}

/**
 * How far beside the hoop's opening, m, a thrown ball above the rim may still drop in (over the
 * backboard's top or the front rim: a ball of radius up to 0.6 m resting on either).
 */
const HOOP_REACH = 0.8;
/**
 * The longest a thrown ball may be out, s, if it is over the hoop (HOOP_REACH) when MISS_SECONDS have
 * passed: one that sat on the backboard's top, then rolled off into the net, went in with no basket.
 */
const MISS_SECONDS_OVER_HOOP = 3 * MISS_SECONDS;

/**
 * Basketballs left lying about that the court keeps; past this many the oldest at rest fade out: none,
 * so each throw's ball (and a click's dropped one) is taken away once it has scored or missed and come
 * to rest. Kept ones (12, then 2) grew the heap by a ball a throw, burying the heap's balls.
 */
const MAX_LOOSE = 0;
/** How long a basketball takes to fade out, s. */
const FADE_SECONDS = 1;
/** The court's wall near the floor, which a fading basketball's colour goes to. */
const FADE_TO = 0x2c3a56;
/** Basketballs fading out: the world time (s) their fade began and their colour then. */
let fading = new Map<number, { at: number; color: number }>();

/**
 * Keeps the player's loose basketballs to MAX_LOOSE: past that the oldest ones at rest (not in flight,
 * not held, under 0.5 m/s) fade to the wall's colour over FADE_SECONDS and are removed, so thrown balls
 * do not pile up in the heap. As many fade at once as there are over MAX_LOOSE.
 */
function clearLoose(world: PhysicsWorld): void {
  const V = world.components.Velocity;
  for (const [e, f] of fading) {
    if (!handles.balls.includes(e) || flights.has(e) || drag.body === e) {
      fading.delete(e);
      if (handles.balls.includes(e)) renderer.setColor(e, f.color);
      continue;
    }
    const t = (world.time - f.at) / FADE_SECONDS;
    if (t >= 1) {
      fading.delete(e);
      basketballs.delete(e);
      removeBall(world, handles, e);
      continue;
    }
    renderer.setColor(e, mixColor(f.color, FADE_TO, t));
  }
  // A basketball removed otherwise (by the page's API) is no longer the court's to fade.
  for (const e of basketballs) if (!handles.balls.includes(e)) basketballs.delete(e);
  let over = -MAX_LOOSE;
  for (const e of basketballs) if (!flights.has(e) && !fading.has(e)) over++;
  for (const e of basketballs) {
    if (over <= 0) return;
    const s = slotOf(e);
    if (flights.has(e) || fading.has(e) || drag.body === e || Math.hypot(V.x[s]!, V.y[s]!) > 0.5) continue;
    fading.set(e, { at: world.time, color: renderer.colorOf(e) });
    over--;
  }
}

/** Colour `a` blended towards `b` by `t` in [0, 1], per channel (0xRRGGBB). */
function mixColor(a: number, b: number, t: number): number {
  let out = 0;
  for (const shift of [16, 8, 0]) {
    const ca = (a >> shift) & 0xff,
      cb = (b >> shift) & 0xff;
    out |= Math.round(ca + (cb - ca) * t) << shift;
  }
  return out;
}

/**
 * Gives the heap back a ball for one that went in, so it keeps as many balls as the round began with
 * (params.count; the player's own balls not counted) and a round's last throws still have a choice:
 * a ball of the sunk one's `radius` (m) comes back in at the box's side away from the hoop whose
 * `opening` it went through (clear of the throws' way to it), just over the heap there, and rolls
 * towards the middle.
 */
function feedHeap(world: PhysicsWorld, opening: { minX: number; maxX: number; y: number }, radius: number): void {
  if (handles.balls.length - basketballs.size >= params.count) return;
  const { box } = layoutOf(TALL);
  const mid = 0.5 * (box.min[0] + box.max[0]);
  const side = 0.5 * (opening.minX + opening.maxX) > mid ? -1 : 1;
  const x = side < 0 ? box.min[0] + radius + 0.05 : box.max[0] - radius - 0.05;
  // Over every ball in its column, so it overlaps none.
  const c = world.components;
  let y = box.min[1] + radius + 0.05;
  for (const e of handles.balls) {
    const q = slotOf(e);
    if (Math.abs(c.Position.x[q]! - x) < radius + c.Ball.radius[q]!) y = Math.max(y, c.Position.y[q]! + c.Ball.radius[q]! + radius + 0.05);
  }
  if (y + radius > box.max[1]) return;
  spawnBall(world, handles, x, y, -1.5 * side, 0, radius);
}

/**
 * A basket's sound: the net's swish, then a rising major chord (three notes 90 ms apart) that starts
 * a semitone higher with each basket of the streak (up to an octave); the gold ball adds the octave
 * on top.
 */
function cheer(score: number, kind: BallKind): void {
  sound.rip(0.3);
  const base = 523.25 * 2 ** (Math.min(12, Math.max(score, round.streak) - 1) / 12);
  sound.chime(base, 0.3);
  setTimeout(() => sound.chime(base * 1.26, 0.3), 90);
  setTimeout(() => sound.chime(base * 1.5, 0.55), 180);
  if (kind === 'gold') setTimeout(() => sound.chime(base * 2, 0.8), 270);
  bumpScore();
}

/** Keeps the round's score as the best if it beats it (in localStorage when it can, per court: best.ts). */
function keepBest(): void {
  if (round.points <= best) return;
  best = round.points;
  writeBest(pageStorage(), TALL, best);
}

/** The net stops the balls it would stop (hoop.ts netContact): every ball, after each step. */
function applyNet(world: PhysicsWorld): void {
  const spot = hoopSpots(TALL)[hoopAt]!;
  const c = world.components,
    P = c.Position,
    O = c.PreviousPosition,
    V = c.Velocity,
    B = c.Ball;
  // Only balls near the hoop can touch its net (a cheap test first: the sandbox may hold thousands).
  const reach = HOOP_HALF_SPAN + 2;
  for (const e of handles.balls) {
    const s = slotOf(e);
    const x = P.x[s]!,
      y = P.y[s]!;
    if (Math.abs(x - spot.x) > reach || Math.abs(y - spot.y) > reach) continue;
    const hit = netContact(spot, B.radius[s]!, O.x[s]!, O.y[s]!, x, y, V.x[s]!, V.y[s]!);
    if (!hit) continue;
    P.x[s] = hit[0];
    P.y[s] = hit[1];
    V.x[s] = hit[2];
    V.y[s] = hit[3];
  }
}
/** Half the hoop's width with its net, m (for applyNet's quick test). */
const HOOP_HALF_SPAN = 1.5;

/**
 * Marks what each ball in flight touched in the last step (the step's contact begin events, told
 * apart by shape and normal: touches.ts), for its basket's style (hoop.ts ShotStyle): a side wall or the floor of the box (a boundary face) or a
 * ramp makes it a trick shot; the box's top (the ceiling) does not (a lob off it is the easy way
 * up, and as a trick shot it would be the best play): it only ends the swish, as anything else does but
 * the balls round it as it leaves the heap (its first LEAVE_MAX_SECONDS).
 */
function markTouches(world: PhysicsWorld): void {
  if (flights.size === 0) return;
  forEachTouch(world, handles.segments, hoopIds, (e, other, kind) => {
    const f = flights.get(e);
    if (!f) return;
    if (kind === 'wall' || kind === 'ramp') f.trick = true;
    else if (kind === 'body' && !crates.includes(other) && world.time - f.at < LEAVE_MAX_SECONDS) return;
    f.touched = true;
  });
}

/**
 * Game seconds stepped since the page opened, across rounds and resets (world.time starts again at a
 * reset): the taking-turns hints' clock (updateStatus), so they wait while the game is paused and a
 * test steps through them instead of waiting for the wall clock.
 */
let playSeconds = 0;

/** Which impacts are heard (knocks.ts): the loudest few a step, a cooldown per body, a budget a second. */
const knocks = createKnockLimiter(KNOCK_LIMITS);

/** One step, then a knock for each impact the limiter keeps: loudness from its impulse, the harder of the two materials. */
function stepWorld(world: PhysicsWorld): void {
  step(world);
  playSeconds += world.dt;
  markTouches(world);
  applyNet(world);
  playHoop(world);
  keepGoldPlayable(world);
  clearLoose(world);
  forEachImpact(world, (a, b, impulse) => knocks.offer(a, b, impulse));
  for (const { a, b, impulse } of knocks.take(world.time)) {
    const ma = materialOf(world, a),
      mb = materialOf(world, b);
    const m = ma === 'metal' || mb === 'metal' ? 'metal' : ma === 'wood' || mb === 'wood' ? 'wood' : ma === 'soft' ? mb : ma;
    sound.impact(impulse, m, { threshold: 0.5 * KNOCK_LIMITS.minImpulse, loud: 20 });
  }
}

/** Whether the page is played by touch (a phone): its help and hints are worded for a finger. */
const TOUCH_UI = pageLayout().touch();

/**
 * The pause overlay (game-kit's): paused, the play area dims and says "Paused" and how to resume, as
 * the other games do, on one line in a small banner at the box's top (placePauseWords): in the middle
 * of the view the words stood over the hoop and the aiming arc.
 */
const pause = createPauseOverlay({ fontSize: 20 });

const game = await startPixiGame({
  title: 'Bouncing balls',
  createWorld,
  step: stepWorld,
  bodies: () => handles.balls.length,
  controls: [
    ...(TOUCH_UI
      ? // The phone's card (under the floor, game-kit's touch hint) has a line for each: short ones.
        [
          { keys: 'Drag', action: 'pull back, let go: throw (from a ball: that ball)' },
          { keys: 'Flick', touch: 'Flick', action: 'up at the hoop: throw' },
          { keys: 'Click', action: 'drop a ball' },
          { keys: 'Hold', touch: 'Hold', action: 'still 1 s on a ball: carry it' },
        ]
      : [
          {
            keys: 'Drag',
            action: 'press, pull back, let go: throw. On a ball: that ball flies; under the floor: the top ball above',
          },
          { keys: 'Click', action: 'drop a ball' },
          { keys: 'Hold', action: 'still 1 s on a ball or crate: pick it up and carry it' },
        ]),
    { keys: 'R', action: 'new round' },
    { keys: 'T', action: 'trails on / off' },
    { keys: 'D', action: 'debug: velocities, contacts' },
    { keys: 'X', action: 'drop a crate' },
  ],
  keys: [
    { key: 't', label: 'trails', action: () => setTrails(!params.trails) },
    { key: 'd', label: 'debug', action: () => setDebug(!params.debug) },
    { key: 'x', label: 'crate', action: () => dropCrate() },
  ],
  renderer: {
    view: 'boundary',
    balls: mode,
    trails: params.trails ? trailOptions(params.count) : false,
    debug: params.debug,
    // Plain balls (no rotation marks: those read as a physics diagram) in bright colours.
    rotation: false,
    palette: BALL_PALETTE,
  },
  app: { background: 0x0b0f18 },
  beforeFrame: () => anchorCourt(),
  onFrame: (alpha, world) => {
    rememberSpots();
    drawCourt();
    drawBasketballs(alpha, world);
    drawPointer();
    drawHoop();
    // On top of everything drawn since (confetti, the countdown): moved last when it is not.
    if (app.stage.children.at(-1) !== pause.container) app.stage.addChild(pause.container);
    pause.draw(shell.paused, app.screen.width, app.screen.height, pageLayout().touch());
    if (pause.visible) placePauseWords();
  },
});
const { shell, renderer, app } = game;

// A drawer opened over the scene on a small screen pauses the round and its clock.
pauseUnderDrawers(shell, { compactOnly: true });

/** Gives the heavy balls of `world` their user colour (the others keep their seeded colours). */
function colorHeavy(world: PhysicsWorld): void {
  for (const e of handles.balls) if (isHeavy(world, e)) renderer.setColor(e, HEAVY_COLOR);
}
colorHeavy(shell.world);
pickGold(shell.world);
shell.onWorldChange((world) => {
  colorHeavy(world);
  pickGold(world);
});

/** Sets restitution and friction of the scene and of the hoop (the panel). */
function setMaterial(restitution: number, friction: number): void {
  applyMaterial(shell.world, handles, restitution, friction);
  for (const e of hoopIds) setBodyMaterial(shell.world, e, { restitution, friction });
}

/** Turns trails on or off (the T key and the panel). */
function setTrails(on: boolean): void {
  params.trails = on;
  renderer.setTrails(on ? trailOptions(params.count) : false);
  panel.refresh();
}

/** Turns the debug overlay on or off (the D key and the panel). */
function setDebug(on: boolean): void {
  params.debug = on;
  renderer.setDebug(on);
  panel.refresh();
}

const panel = createPanel(
  params,
  [
    {
      type: 'slider',
      key: 'gravity',
      label: 'gravity (m/s²)',
      min: 0,
      max: 30,
      step: 0.01,
      onChange: (g) => applyGravity(shell.world, handles, g),
    },
    {
      type: 'slider',
      key: 'restitution',
      min: 0,
      max: 1,
      step: 0.01,
      onChange: (e, p) => setMaterial(e, p.friction),
    },
    {
      type: 'slider',
      key: 'friction',
      min: 0,
      max: 1,
      step: 0.01,
      onChange: (mu, p) => setMaterial(p.restitution, mu),
    },
    { type: 'choice', key: 'drag', options: DRAG_MODES, onChange: (m, p) => applyDrag(shell.world, handles, m as DragMode, p.dragK) },
    {
      type: 'slider',
      key: 'dragK',
      label: 'drag k (kg/s | kg/m)',
      min: 0,
      max: 2,
      step: 0.01,
      onChange: (k, p) => applyDrag(shell.world, handles, p.drag, k),
    },
    {
      type: 'slider',
      key: 'count',
      label: 'balls (rebuilds)',
      min: 1,
      max: 6000,
      step: 1,
      onRelease: true,
      onChange: () => {
        shell.reset();
        if (params.trails) renderer.setTrails(trailOptions(params.count));
      },
    },
    { type: 'checkbox', key: 'trails', onChange: (v) => setTrails(v === true) },
    { type: 'checkbox', key: 'debug', label: 'debug overlay', onChange: (v) => setDebug(v === true) },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Bouncing balls' },
);

// ---- Pointer: a click drops, a drag throws; holding still on a body picks it up -----------------

const canvas = app.canvas;
/**
 * True only while the long press hands its pointer to the mouse-joint drag (a synthetic press): a
 * real press never grabs, so a throw started on a ball (balls still falling at a round's start, a
 * crowded phone box) throws instead of dragging that ball away.
 */
let grabbing = false;
// Reach 0.6 mean radii: a ball grabs within that of its edge, a crate (a box, no radius) within that of
// its centre.
const drag = enableMouseDrag(
  canvas,
  () => shell.world,
  () => renderer.camera,
  { reach: 0.6 * meanRadiusFor(params.count), enabled: () => grabbing },
);
/**
 * Holding still this long, ms, on a ball or crate picks it up (a long press) instead of dropping a
 * ball. Long enough that a player who presses on the pile, aims a moment and then pulls throws: the
 * pickup has to be meant (450 ms picked balls up from players who meant to throw).
 */
const HOLD_MS = 1000;
/** A still press on a ball shows its pick-up ring from this long on, ms (a press that is pulled at once shows none). */
const HOLD_RING_MS = 250;
let holdTimer = 0;
/** How far the current press may wander and still be a click or a hold, CSS px (CLICK_SLOP, or TOUCH_SLOP for a finger). */
let slop = CLICK_SLOP;

/** The ball the aiming overlay last drew lifted out of the heap (0: none): its halo is drawn there, not where it lies. */
let liftedShown = 0;
const overlay = new Graphics({ label: 'pointer' });
app.stage.addChild(overlay);
let pointerId = -1;
/** Where the press began (the ball's spot) and where the pointer is now, CSS px on the canvas. */
let startX = 0,
  startY = 0,
  lastX = 0,
  lastY = 0;
let dragged = false;

/** The pointer position in CSS px relative to the canvas' top-left corner. */
function local(event: PointerEvent): [number, number] {
  const rect = canvas.getBoundingClientRect();
  return [event.clientX - rect.left, event.clientY - rect.top];
}

/**
 * The pull, px, that throws at full speed (MAX_THROW_SPEED): 60 % of the canvas' shorter side, within
 * [230, 420] px. Long, so a few px of a shaky hand change a throw little: a basket's throws take
 * pulls of about 55 to 140 px on a phone (234 px full) and 120 to 250 px on a desktop (420 px), and
 * the window of pull lengths that still score is some 15 px wide (phone) and 24 px (desktop), of
 * sideways pull 9 and 16 px (medians of `node scripts/bouncing-balls-reach.mjs --pull 420,234`).
 * Not longer on a phone: a throw from 1.5 m over the floor of its box has some 170 px of screen
 * under it to pull into, and the steepest baskets must fit in it with room to spare (a full pull of
 * 7.5 m of the court, 268 px there, left players at the screen's bottom edge short of the hoop).
 * That is a mouse's; a finger's is fingerFullPull (longer, within the room under the heap).
 * The same for every press, wherever it begins (taken when the press begins), so a pull's power is
 * a function of its length alone. Pointer capture keeps the pull going past the canvas' and the
 * window's edge.
 */
function fullPull(): number {
  return Math.min(420, Math.max(230, 0.6 * Math.min(canvas.clientWidth || innerWidth, canvas.clientHeight || innerHeight)));
}

/**
 * How much longer a finger's full pull is than fullPull where the screen has room for it under the
 * heap (fingerFullPull): gentler, so a few px of a finger change a throw less.
 */
const FINGER_PULL_SCALE = 1.5;

/**
 * A finger's full-speed pull, CSS px: FINGER_PULL_SCALE times fullPull, but no longer than the
 * screen's room under a ball lying on the box's floor (its centre down to the screen's bottom edge,
 * less FINGER_EDGE_PX): on a phone held upright a 351 px pull ran off the screen's bottom at 55 to
 * 64 % power, short of every hoop, from the balls where they lie (some 150 to 180 px over the edge).
 * The same for every press of a page (the room under the floor, not under the press), so a pull's
 * power is still a function of its length alone. At least FINGER_MIN_PULL.
 */
function fingerFullPull(): number {
  const cam = renderer.camera,
    rect = canvas.getBoundingClientRect();
  const floorBall = rect.top + cam.toScreenY(layoutOf(TALL).box.min[1] + PLAYER_RADIUS);
  const room = (window.innerHeight || rect.bottom) - floorBall - FINGER_EDGE_PX;
  return Math.min(fullPull() * FINGER_PULL_SCALE, Math.max(FINGER_MIN_PULL, room));
}

/** Room a finger's full pull leaves at the screen's bottom edge, CSS px (a thumb does not reach the last pixels). */
const FINGER_EDGE_PX = 10;

/** The shortest full pull a finger gets, CSS px (fingerFullPull): at that, a px of pull is some 1.2 % of the top speed. */
const FINGER_MIN_PULL = 100;

/** Whether the current press is a finger's (pointer type 'touch'). */
let pressFinger = false;
/** The current press's full-speed pull, CSS px (fullPull, or fingerFullPull for a finger, when it began). */
let fullPullNow = 420;

/**
 * The cancel zone's radius round the press, CSS px: CANCEL_PULL for a mouse; for a finger, the thrown
 * ball's drawn radius if larger (the thumb covers the ball it took back). A mouse's zone as wide as
 * a big heap ball (33 px on a desktop) showed no arc for pulls of 30 px and less.
 */
function cancelRadius(): number {
  if (!pressFinger) return CANCEL_PULL;
  const c = shell.world.components;
  const r = pressBall !== 0 && handles.balls.includes(pressBall) ? c.Ball.radius[slotOf(pressBall)]! : PLAYER_RADIUS;
  return Math.max(CANCEL_PULL, renderer.camera.toScreenLength(r));
}

/** Whether the pull now is in the cancel zone: pulled (past the slop) and then back within cancelRadius of the press. */
function inCancelZone(): boolean {
  return dragged && Math.hypot(lastX - startX, lastY - startY) < cancelRadius();
}

/**
 * Ends the current press with nothing done (no throw, no drop, no shot): the aim when the round ends
 * under it. The pointer's later release is then ignored.
 */
function endAim(): void {
  if (pointerId === -1) return;
  if (canvas.hasPointerCapture(pointerId)) canvas.releasePointerCapture(pointerId);
  pointerId = -1;
  pressBall = 0;
  fingerLift = 0;
  dragged = false;
  clearTimeout(holdTimer);
}

/**
 * The throw the pointer would make now: start (m), velocity (m/s) of the slingshot, and the ball's
 * radius (m) and mass (kg): from the pressed ball's centre when the press began on a ball (that ball
 * is thrown), lifted to the top of the heap over it if it is buried (liftSpot), else from the press's start spot (pressSpot: a new basketball).
 * A pull close to one that throws through the middle of the hoop (within about 10 % of its length
 * and 5 degrees; aim-assist.ts assistAim) throws that one, a mouse's and a finger's alike; a finger's
 * that is not, within PULL_ASSIST_PX of a length that scores, throws the middle of that run of
 * lengths (hoop.ts assistPull).
 */
function currentThrow(): { x: number; y: number; vx: number; vy: number; radius: number; mass: number } {
  const t = pulledThrow();
  assisting = false;
  const pdx = lastX - startX,
    pdy = lastY - startY,
    len = Math.hypot(pdx, pdy);
  if (!dragged || len === 0 || len >= fullPullNow || inCancelZone() || refused()) return t;
  // Worked out once for each pull, as the arc and the release both ask for it.
  const key = `${startX},${startY},${lastX},${lastY},${pressBall},${hoopAt}`;
  if (assistMemo.key !== key) assistMemo = { key, ...assistedPull(t, pdx, pdy) };
  if (!assistMemo.on) return t;
  assisting = true;
  const [vx, vy] = slingVelocity(assistMemo.x, assistMemo.y, fullPullNow, roomAt(t.y));
  return { ...t, vx, vy };
}

/**
 * The pull, px, that pull (pdx, pdy) of throw `t` is drawn to (currentThrow), and whether it is drawn
 * to a basket (`on`; else the pull itself).
 */
function assistedPull(t: ReturnType<typeof pulledThrow>, pdx: number, pdy: number): { x: number; y: number; on: boolean } {
  const throwAt = (px: number, py: number): boolean => {
    if (Math.hypot(px, py) > fullPullNow) return false;
    const [vx, vy] = slingVelocity(px, py, fullPullNow, room);
    return scoresClean({ ...t, vx, vy }, pressBall);
  };
  const spot = hoopSpots(TALL)[hoopAt]!,
    room = roomAt(t.y);
  const options = { gravity: handles.params.gravity, fullPull: fullPullNow, finger: pressFinger, ...(room ? { room } : {}) };
  const aim = assistAim(pdx, pdy, t.x, t.y, spot, options, throwAt);
  if (aim) return { x: aim[0], y: aim[1], on: true };
  if (!pressFinger) return { x: pdx, y: pdy, on: false };
  const len = Math.hypot(pdx, pdy);
  const length = assistPull(len, (l) => throwAt((pdx * l) / len, (pdy * l) / len));
  return { x: (pdx * length) / len, y: (pdy * length) / len, on: length !== len || throwAt(pdx, pdy) };
}

/** Whether the last currentThrow was drawn to a basket by the aim assist (its label says so: drawPointer). */
let assisting = false;
/** The current pull's assisted pull, px (x, y), for the pull and press in `key`, and whether it is on a basket (`on`). */
let assistMemo = { key: '', x: 0, y: 0, on: false };

/**
 * Whether throw `t` of ball `thrown` (0: a new basketball) goes down through the hoop's opening
 * before it touches anything: its aiming flight (arcOf, no bounces, a point each world step) crosses
 * the rim's line downwards between the front rim and the board, from below the shot line (mayScore).
 */
function scoresClean(t: { x: number; y: number; vx: number; vy: number; radius: number; mass: number }, thrown: number): boolean {
  const spot = hoopSpots(TALL)[hoopAt]!;
  if (!mayScore(spot, t.y)) return false;
  // Followed until its drag-free flight is 1 m under the rim on the way down, and 0.3 s more (drag
  // only lowers and shortens it); one that never reaches the rim's height drag-free never scores.
  const g = handles.params.gravity,
    rise = t.vy * t.vy + 2 * g * (t.y - spot.y);
  if (g > 0 && rise < 0) return false;
  const seconds = g > 0 ? Math.min(FLIGHT_SECONDS, (t.vy + Math.sqrt(rise + 2 * g)) / g + 0.3) : FLIGHT_SECONDS;
  // A throw aimed down hard (a finger pulled up from below) is 1 m under the rim before it starts.
  if (!(seconds > 0)) return false;
  const path = arcOf(t, thrown, seconds, 0, 0, shell.world.dt);
  const o = hoopOpening(spot);
  // The last point is the first touch when the flight ended early: a crossing into it does not count.
  for (let i = 1; i < path.length / 2 - 1; i++)
    if (hoopCrossing(o, path[2 * i - 2]!, path[2 * i - 1]!, path[2 * i]!, path[2 * i + 1]!) === -1) return true;
  return false;
}

/** The throw the pointer's pull makes as it is (currentThrow before a finger's assist). */
function pulledThrow(): { x: number; y: number; vx: number; vy: number; radius: number; mass: number } {
  const pull = (y: number): [number, number] => slingVelocity(lastX - startX, lastY - startY, fullPullNow, roomAt(y));
  if (pressBall !== 0 && handles.balls.includes(pressBall)) {
    const c = shell.world.components,
      s = slotOf(pressBall);
    // A buried ball is thrown from the top of the heap over it (liftSpot); one with no room there stays.
    const [x, y] = liftSpot(pressBall) ?? [c.Position.x[s]!, c.Position.y[s]!];
    const [vx, vy] = pull(y);
    return { x, y, vx, vy, radius: c.Ball.radius[s]!, mass: c.Mass.value[s]! };
  }
  const mass = Math.PI * PLAYER_RADIUS * PLAYER_RADIUS * DENSITIES.normal;
  const [vx, vy] = pull(pressSpot[1]);
  return { x: pressSpot[0], y: pressSpot[1], vx, vy, radius: PLAYER_RADIUS, mass };
}

/**
 * The slingshot's speeds for a throw from height `y`, m, in the tall box (a phone held upright; hoop.ts
 * slingRoom: a full pull lobs to ROOM_OVER_RIM over the hoop's rim), or undefined in the wide box,
 * whose full pull throws at MAX_THROW_SPEED.
 */
function roomAt(y: number): SlingRoom | undefined {
  return TALL ? slingRoom(y, hoopSpots(TALL)[hoopAt]!.y, handles.params.gravity) : undefined;
}

/**
 * What the aiming label says for a throw from (x, y), m, when no pull from there scores in the scene's
 * default physics (reach.ts noShotWords: g 9.81 m/s^2, no drag, the slingshot's speeds roomAt), else
 * '': under the hoop, 'no shot from under the hoop: start further out'. Worked out once for each start
 * (to the cm) and hoop: up to some 3,000 short flights when none scores.
 */
function noShotAt(x: number, y: number): string {
  const p = handles.params;
  if (p.gravity !== 9.81 || p.drag !== 'none') return '';
  const key = `${x.toFixed(2)},${y.toFixed(2)},${hoopAt}`;
  if (noShotMemo.key !== key) {
    const room = roomAt(y);
    noShotMemo = { key, words: noShotWords(hoopSpots(TALL)[hoopAt]!, TALL, x, y, room ? room.low : 0, room ? room.top : MAX_THROW_SPEED) };
  }
  return noShotMemo.words;
}
/** noShotAt's last answer and the start and hoop it is for. */
let noShotMemo = { key: '', words: '' };

/**
 * The power a throw `t` shows (the gauge, the band, the label), [0, 1]: in the wide box its speed over
 * MAX_THROW_SPEED; in the tall box the share of the full pull that throws at its speed (roomAt), so
 * the full pull shows 100 % there too.
 */
function powerOf(t: { y: number; vx: number; vy: number }): number {
  const speed = Math.hypot(t.vx, t.vy),
    room = roomAt(t.y);
  if (!room) return Math.min(1, speed / MAX_THROW_SPEED);
  return speed === 0 ? 0 : slingPull(Math.min(room.top, speed), 1, room);
}

/** Where the current press's new basketball starts, m (startSpot of the press point): a pull throws it from there, a click drops it there. */
let pressSpot: [number, number] = [0, 0];
/** Where the current press began, m. */
let pressAt: [number, number] = [0, 0];
/** When a tap on the hoop was let go (performance.now() ms; its hint shows HOOP_TAP_SHOWN ms), or -Infinity. */
let hoopTapAt = Number.NEGATIVE_INFINITY;
/** How long the hint after a tap on the hoop shows, ms. */
const HOOP_TAP_SHOWN = 2500;
/** Reach, m, round the hoop's drawn parts within which a press counts as on it (a finger's width on a phone). */
const HOOP_TAP_REACH = 0.3;
/**
 * Whether (x, y), m, is on the hoop as drawn: within HOOP_TAP_REACH of the box from the front rim's
 * tip to the backboard, from the net's foot to the board's top.
 */
function onHoop(x: number, y: number): boolean {
  const spot = hoopSpots(TALL)[hoopAt]!;
  const board = spot.x + spot.side * (HOOP_HALF_WIDTH + HOOP_RADIUS),
    tip = spot.x - spot.side * (HOOP_HALF_WIDTH + HOOP_RADIUS + FRONT_RIM_LENGTH);
  return (
    x >= Math.min(board, tip) - HOOP_TAP_REACH &&
    x <= Math.max(board, tip) + HOOP_TAP_REACH &&
    y >= spot.y - NET.depth - HOOP_TAP_REACH &&
    y <= spot.y + BACKBOARD.above + HOOP_TAP_REACH
  );
}

/** How far a new basketball starts clear of a ramp or the hoop it was pressed on, m. */
const START_CLEARANCE = 0.02;

/**
 * Where a new basketball pressed at (x, y), m, starts, m: the press point, moved off a ramp, the
 * backboard or the rim it would overlap (straight out from it, on the press's side) and in from the
 * box's walls; null where no ball can start: outside the box (a press under its floor is given a
 * spot on the floor by the pointer handler) or where moving it off one wall puts it into another.
 * A press there starts nothing: a ball dropped in the box's corner or pushed off a ramp by the
 * solver, never thrown, would read as a broken throw.
 */
function startSpot(x: number, y: number): [number, number] | null {
  const { box, segments } = layoutOf(TALL);
  const r = PLAYER_RADIUS;
  if (!(x >= box.min[0] && x <= box.max[0] && y >= box.min[1] && y <= box.max[1])) return null;
  const walls = [
    ...segments.map(([ax, ay, bx, by]) => [ax, ay, bx, by, SEGMENT_RADIUS] as const),
    ...hoopSegments(hoopSpots(TALL)[hoopAt]!).map(([ax, ay, bx, by]) => [ax, ay, bx, by, HOOP_RADIUS] as const),
  ];
  const closest = (px: number, py: number, [ax, ay, bx, by]: readonly number[]): [number, number] => {
    const ex = bx! - ax!,
      ey = by! - ay!;
    const t = Math.max(0, Math.min(1, ((px - ax!) * ex + (py - ay!) * ey) / (ex * ex + ey * ey || 1)));
    return [ax! + t * ex, ay! + t * ey];
  };
  let sx = Math.min(box.max[0] - r, Math.max(box.min[0] + r, x)),
    sy = Math.min(box.max[1] - r, Math.max(box.min[1] + r, y));
  for (const w of walls) {
    const [cx, cy] = closest(sx, sy, w);
    const need = r + w[4] + START_CLEARANCE;
    let dx = sx - cx,
      dy = sy - cy;
    const d = Math.hypot(dx, dy);
    if (d >= need) continue;
    if (d < 1e-9) {
      // On the wall's line: out on its upper side (the wall's normal pointing up).
      const ex = w[2] - w[0],
        ey = w[3] - w[1];
      [dx, dy] = ex >= 0 ? [-ey, ex] : [ey, -ex];
    }
    const len = Math.hypot(dx, dy);
    sx = cx + (dx / len) * need;
    sy = cy + (dy / len) * need;
  }
  if (sx < box.min[0] + r || sx > box.max[0] - r || sy < box.min[1] + r || sy > box.max[1] - r) return null;
  for (const w of walls) {
    const [cx, cy] = closest(sx, sy, w);
    if (Math.hypot(sx - cx, sy - cy) < r + w[4]) return null;
  }
  return [sx, sy];
}

/** The ball a press began on (a pull throws it), 0 when it began on empty space (a pull throws a new basketball). */
let pressBall = 0;

/** The ball whose edge is nearest (x, y), m, within the drag's reach of it (0.6 mean radii), or 0. */
function ballUnder(x: number, y: number): number {
  const c = shell.world.components,
    reach = 0.6 * meanRadiusFor(params.count);
  let best = 0,
    bestGap = reach;
  for (const e of handles.balls) {
    const s = slotOf(e);
    const gap = Math.hypot(c.Position.x[s]! - x, c.Position.y[s]! - y) - c.Ball.radius[s]!;
    if (gap <= bestGap) {
      bestGap = gap;
      best = e;
    }
  }
  return best;
}

/** Balls faster than this, m/s, are not the top of their column for a press under the floor (columnTop): a ball falling through it is no ball of the heap. */
const COLUMN_REST_SPEED = 1.5;

/**
 * The ball a press under the box's floor at `x`, m, throws: the top one of the heap's column over it
 * (the highest ball whose width spans x), or, if none spans it, the ball nearest the new basketball's
 * spot on the floor (`floor`, [x, y], m) that it would overlap; not a ball in flight, fading out or
 * faster than COLUMN_REST_SPEED. 0 when there is none: the press throws a new basketball from `floor`.
 */
function columnTop(x: number, floor: readonly [number, number]): number {
  const c = shell.world.components,
    P = c.Position,
    V = c.Velocity,
    R = c.Ball.radius;
  let top = 0,
    topY = Number.NEGATIVE_INFINITY,
    near = 0,
    nearGap = 0;
  for (const e of handles.balls) {
    if (flights.has(e) || fading.has(e)) continue;
    const s = slotOf(e);
    if (V.x[s]! ** 2 + V.y[s]! ** 2 > COLUMN_REST_SPEED ** 2) continue;
    if (Math.abs(P.x[s]! - x) < R[s]! && P.y[s]! + R[s]! > topY) {
      top = e;
      topY = P.y[s]! + R[s]!;
    }
    const gap = Math.hypot(P.x[s]! - floor[0], P.y[s]! - floor[1]) - R[s]! - PLAYER_RADIUS;
    if (gap < nearGap) {
      near = e;
      nearGap = gap;
    }
  }
  return top || near;
}

/**
 * Whether ball `e` has a free way up: no other ball touches it on its upper half (a throw up and to
 * that side would drive into it, "blocked") and none lies in the column straight over it.
 */
function freeUp(e: number): boolean {
  return !someNeighbour(e, true, (dx, dy, d, sum) => dy > 0 && (d < sum + 0.03 || Math.abs(dx) < 0.8 * sum));
}

/** How far sideways of a press a ball with a free way up may be and still be the one it throws, m. */
const FREE_PICK_REACH = 0.9;

/**
 * The ball a press at (x, y), m, throws when the ball under it (`under`, 0 for none: a press over or
 * beside the heap) has no free way up (freeUp): the free ball nearest the press within
 * FREE_PICK_REACH of its edge (under the floor, `stand`: by sideways distance alone, the heap's free
 * top near that x); `under` itself when it is free, buried (then it is lifted, liftSpot) or no free
 * ball is near (0 then: a new basketball). Resting balls only.
 */
function pickFree(under: number, x: number, y: number, stand: boolean): number {
  if (under !== 0 && (freeUp(under) || (!stand && buried(under)))) return under;
  const c = shell.world.components,
    P = c.Position,
    V = c.Velocity,
    R = c.Ball.radius;
  let best = under,
    bestGap = FREE_PICK_REACH;
  for (const e of handles.balls) {
    if (e === under || flights.has(e) || fading.has(e)) continue;
    const s = slotOf(e);
    if (V.x[s]! ** 2 + V.y[s]! ** 2 > COLUMN_REST_SPEED ** 2) continue;
    const gap = (stand ? Math.abs(P.x[s]! - x) : Math.hypot(P.x[s]! - x, P.y[s]! - y)) - R[s]!;
    if (gap < bestGap && freeUp(e)) {
      best = e;
      bestGap = gap;
    }
  }
  return best;
}

/**
 * The ball a new basketball started at (x, y), m, would overlap (the one whose edge is nearest it), or
 * 0: a press there throws that ball (pickFree), not a new basketball pushed out of the heap at once.
 */
function overlapped(x: number, y: number): number {
  const c = shell.world.components;
  let best = 0,
    bestGap = 0;
  for (const e of handles.balls) {
    if (flights.has(e) || fading.has(e)) continue;
    const s = slotOf(e);
    const gap = Math.hypot(c.Position.x[s]! - x, c.Position.y[s]! - y) - c.Ball.radius[s]! - PLAYER_RADIUS;
    if (gap < bestGap) {
      best = e;
      bestGap = gap;
    }
  }
  return best;
}

/** Whether the current press's ball was picked for it (pickFree, repickFree: the press was not on that ball), so another may be picked as the pull goes on. */
let pressPicked = false;

/**
 * A pull of a ball picked for the press (pressPicked) that its arc shows blocked at once
 * (blockedAtOnce): the pull goes to the next resting ball within FREE_PICK_REACH of the press
 * (nearest first; not one buried with no room over it) whose throw with the same pull is not
 * blocked; it stays when there is none. The player did not choose the ball: on top of the heap two
 * balls side by side at one height block each other's throw toward the hoop, and "blocked" showed
 * there where the throw looked fine, while the neighbour flies. A ball pressed on is the player's
 * choice and stays.
 */
function repickFree(): void {
  if (pressBall === 0 || !blockedAtOnce(currentThrow(), pressBall)) return;
  const c = shell.world.components,
    P = c.Position,
    V = c.Velocity,
    R = c.Ball.radius;
  const [x, y] = pressAt;
  const near: [number, number][] = [];
  for (const e of handles.balls) {
    if (e === pressBall || flights.has(e) || fading.has(e)) continue;
    const s = slotOf(e);
    if (V.x[s]! ** 2 + V.y[s]! ** 2 > COLUMN_REST_SPEED ** 2) continue;
    const gap = (pressStand ? Math.abs(P.x[s]! - x) : Math.hypot(P.x[s]! - x, P.y[s]! - y)) - R[s]!;
    if (gap < FREE_PICK_REACH && liftSpot(e) !== null) near.push([gap, e]);
  }
  near.sort((a, b) => a[0] - b[0]);
  const was = pressBall;
  for (const [, e] of near) {
    pressBall = e;
    if (!blockedAtOnce(currentThrow(), e)) return;
  }
  pressBall = was;
}

/** Whether the current press began under the box's floor (on the court's stand): it throws the ball over it (columnTop); a tap there does nothing. */
let pressStand = false;
/** When a tap on the stand was let go (performance.now() ms; its hint shows HOOP_TAP_SHOWN ms), or -Infinity. */
let standTapAt = Number.NEGATIVE_INFINITY;

/**
 * What a press at (wx, wy), m (inside the box, pressInBox), throws: `onBall` the ball (0: a new
 * basketball), `stand` whether it is under the box's floor and `floor` the new basketball's spot on
 * the floor under it, `lift` the ball to lift over the heap for the throw (fingerLift; 0: none). A
 * `finger`'s press takes the ball it is on, or was on as drawn a moment before, within a finger's
 * reach (fingerUnder), and keeps it though it has no free way up (lifted then).
 */
function pressPick(wx: number, wy: number, finger: boolean): { stand: boolean; floor: [number, number]; onBall: number; lift: number } {
  const { box } = layoutOf(TALL);
  // Under the floor (the stand, room to pull back into): the press throws the top ball of the heap
  // over it, or a new basketball from the floor there when the heap is empty.
  const stand = wy < box.min[1];
  const floor: [number, number] = [
    Math.min(box.max[0] - PLAYER_RADIUS, Math.max(box.min[0] + PLAYER_RADIUS, wx)),
    box.min[1] + PLAYER_RADIUS + START_CLEARANCE,
  ];
  // A ball with a neighbour over it would be "blocked": the free ball nearest the press is taken instead.
  // A press just over or beside the heap (no ball under it) takes the free ball nearest it too, so a
  // new basketball starts only in open space, clear of the heap (one there read as coming from nowhere).
  const under = stand ? columnTop(wx, floor) : (finger ? fingerUnder(wx, wy) : ballUnder(wx, wy)) || overlapped(wx, wy);
  // A finger's ball is the one it pressed on (the player's choice), lifted to the top of the heap over
  // it (liftSpot) when it has no free way up, unless there is no room there.
  if (finger && !stand && under !== 0 && !freeUp(under) && liftSpot(under, true) !== null)
    return { stand, floor, onBall: under, lift: buried(under) ? 0 : under };
  const onBall = under !== 0 || !stand ? pickFree(under, wx, wy, stand) : 0;
  return { stand, floor, onBall, lift: 0 };
}

/**
 * The ball a finger's press at (x, y), m, is on (fingerBall): against where the balls are and where
 * they were drawn SEEN_FRAMES frames before, within the drag's reach of an edge or FINGER_REACH_PX of
 * a centre; 0 for none.
 */
function fingerUnder(x: number, y: number): number {
  const P = shell.world.components.Position,
    R = shell.world.components.Ball.radius;
  const now = handles.balls.map((id) => ({ id, x: P.x[slotOf(id)]!, y: P.y[slotOf(id)]!, r: R[slotOf(id)]! }));
  const fingerReach = FINGER_REACH_PX / renderer.camera.toScreenLength(1);
  return fingerBall(now, seenSpots[0] ?? new Map(), x, y, 0.6 * meanRadiusFor(params.count), fingerReach);
}

/** How many frames back fingerUnder also takes the balls where they were drawn: 6, a tenth of a second (a finger lands where the player saw the ball). */
const SEEN_FRAMES = 6;
/** The balls' centres, m, by id, as drawn in each of the last SEEN_FRAMES frames, oldest first (rememberSpots). */
const seenSpots: Map<number, readonly [number, number]>[] = [];

/** Keeps this frame's ball centres in seenSpots (dropping the oldest past SEEN_FRAMES). */
function rememberSpots(): void {
  const P = shell.world.components.Position;
  const spots = new Map<number, readonly [number, number]>();
  for (const e of handles.balls) spots.set(e, [P.x[slotOf(e)]!, P.y[slotOf(e)]!]);
  seenSpots.push(spots);
  while (seenSpots.length > SEEN_FRAMES) seenSpots.shift();
}

/** The ball a finger pressed on that has no free way up and is not buried (pressPick): its throw starts lifted over the heap (liftSpot), as a buried one's does. 0: none. */
let fingerLift = 0;

canvas.addEventListener('pointerdown', (event) => {
  // (On a small screen a press on the field also closes an open drawer: game-kit's page layout.)
  if (grabbing || event.button !== 0 || pointerId !== -1 || drag.joint !== 0) return;
  // The clock is out and the round waits for its last throw, or the round is over (the end card
  // covers the box): no new throw, no pick-up.
  if (lastCall.aiming || lastCall.ball !== 0 || round.phase === 'over') return;
  const [px, py] = local(event);
  const { box } = layoutOf(TALL);
  // A press on the frame beside or over the box is taken as one just inside it, so a press anywhere
  // on the play area starts an aim (one on the steel frame did nothing).
  const [wx, wy] = pressInBox(renderer.camera.toWorldX(px), renderer.camera.toWorldY(py), box.min, box.max);
  const { stand, floor, onBall, lift } = pressPick(wx, wy, event.pointerType === 'touch');
  const spot = onBall !== 0 ? null : startSpot(...(stand ? floor : ([wx, wy] as const)));
  // Where no ball can start (a ramp's far side) and nothing to pick up: the press does nothing, seen or heard.
  if (onBall === 0 && spot === null && !bodyUnder(wx, wy)) return;
  pressStand = stand;
  pressSpot = spot ?? [wx, wy];
  pressAt = [wx, wy];
  pointerId = event.pointerId;
  canvas.setPointerCapture(event.pointerId);
  [startX, startY] = [px, py];
  lastX = startX;
  lastY = startY;
  dragged = false;
  pressBall = onBall;
  fingerLift = lift;
  pressPicked = onBall !== 0 && onBall !== (event.pointerType === 'touch' ? fingerUnder(wx, wy) : ballUnder(wx, wy));
  boardSaid = false;
  slop = event.pointerType === 'touch' ? TOUCH_SLOP : CLICK_SLOP;
  pressFinger = event.pointerType === 'touch';
  followed = pulledMost = 0;
  fullPullNow = pressFinger ? fingerFullPull() : fullPull();
  holdStart = performance.now();
  flick.press(px, py, event.timeStamp);
  clearTimeout(holdTimer);
  const { clientX, clientY, pointerId: id, pointerType, timeStamp } = event;
  holdTimer = window.setTimeout(() => {
    if (pointerId !== id || dragged) return;
    // Still and pressed: hand the pointer to the drag. A press beside every body grabs nothing and
    // stays a click (a dropped ball on release).
    grabbing = true;
    canvas.dispatchEvent(new PointerEvent('pointerdown', { clientX, clientY, pointerId: id, pointerType, button: 0, bubbles: true }));
    grabbing = false;
    if (drag.joint !== 0) {
      pointerId = -1;
      heldFrom = { id, timeStamp };
    }
  }, HOLD_MS);
});
/**
 * The press the hold handed to the drag: its pointer and when it went down (event time, ms). A busy
 * page may run the hold's timer after moves that came sooner: a move made within HOLD_MS of the
 * press (by its event time) takes the press back from the drag, a throw after all.
 */
let heldFrom = { id: -1, timeStamp: 0 };
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== heldFrom.id || drag.joint === 0 || event.timeStamp - heldFrom.timeStamp >= HOLD_MS) return;
  const [x, y] = local(event);
  if (Math.hypot(x - startX, y - startY) <= slop) return;
  drag.release();
  heldFrom.id = -1;
  pointerId = event.pointerId;
  [lastX, lastY] = [x, y];
  dragged = true;
});
/** When the current press began, performance.now() ms (for the hold ring). */
let holdStart = 0;

/** Whether a ball or crate is within the drag's reach of (x, y), m (a long press there picks it up). */
function bodyUnder(x: number, y: number): boolean {
  const c = shell.world.components,
    reach = 0.6 * meanRadiusFor(params.count);
  for (const e of handles.balls) {
    const s = slotOf(e);
    if (Math.hypot(c.Position.x[s]! - x, c.Position.y[s]! - y) - c.Ball.radius[s]! <= reach) return true;
  }
  for (const e of crates) {
    const s = slotOf(e);
    if (Math.hypot(c.Position.x[s]! - x, c.Position.y[s]! - y) <= reach) return true;
  }
  return false;
}

canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== pointerId) return;
  // Each move a slow page handed over at once, with its own time, for the release's flick speed.
  for (const e of event.getCoalescedEvents?.() ?? [event]) flick.move(...local(e), e.timeStamp);
  [lastX, lastY] = local(event);
  if (Math.hypot(lastX - startX, lastY - startY) > slop) dragged = true;
  // A finger above the pull's anchor would throw down, never a basket: the anchor follows it there,
  // so a finger slid up from a ball into open space pulls back from where it is, with room below and
  // to the side (a ball by the screen's edge or bottom boxed the pull in; FINGER_PULL_SCALE).
  if (lastY >= startY) pulledMost = Math.max(pulledMost, Math.hypot(lastX - startX, lastY - startY));
  if (pressFinger && !pressStand && lastY < startY) {
    followed += startY - lastY;
    [startX, startY] = [lastX, lastY];
  }
});

/**
 * Pointer released: a click drops a ball where it was pressed; a pull throws one from there,
 * slingshot-style; a pull taken back into the cancel zone (inCancelZone) does nothing. Only a throw counts as a shot (and the clock waits for the first basket).
 */
function release(event: PointerEvent, cancelled: boolean): void {
  const mine = event.pointerId === pointerId;
  releasePress(event, cancelled);
  // The press is over: a finger's ball not thrown is no longer to be lifted.
  if (mine) fingerLift = 0;
}

/** The body of `release`. */
function releasePress(event: PointerEvent, cancelled: boolean): void {
  if (event.pointerId !== pointerId) return;
  pointerId = -1;
  clearTimeout(holdTimer);
  // The round's last throw (the clock ran out during its pull): the round waits for its ball, if any.
  const last = lastCall.aiming;
  lastCall.aiming = false;
  if (cancelled) return;
  [lastX, lastY] = local(event);
  if (Math.hypot(lastX - startX, lastY - startY) > slop) dragged = true;
  flickRelease(event);
  const t = currentThrow();
  const ball = pressBall;
  const cancel = inCancelZone();
  pressBall = 0;
  if (cancel) {
    // A finger slid up (the anchor following it) and let go too slowly for a flick: nothing is
    // thrown, and the court says so, where the finger pressed.
    if (
      pressFinger &&
      followed > slop &&
      pulledMost <= cancelRadius() &&
      !(ball !== 0 && handles.balls.includes(ball) && liftSpot(ball) === null)
    ) {
      missSaid = 'Too slow to throw: flick up quicker, or pull back';
      missAt = playSeconds;
      sayOnCourt('Flick quicker to throw', pressAt[0], pressAt[1]);
    }
    return;
  }
  // What the label said at this pointer's spot decides (the frame's check), so the outcome agrees with
  // it; a release away from the last drawn spot is checked afresh.
  const saidBlocked = Math.hypot(lastX - shownBlocked.x, lastY - shownBlocked.y) < 3 ? shownBlocked.blocked : blockedAtOnce(t, ball);
  shownBlocked = { blocked: false, x: Number.NaN, y: Number.NaN };
  if (dragged && saidBlocked) {
    // Its arc showed a ball in the way at once ("blocked"): letting go throws nothing (no shot, no
    // miss to end the streak) and says to pick the ball on top.
    blockedAt = performance.now();
    blockedSpot = [t.x, t.y];
    return;
  }
  if (!dragged) {
    // A tap on the hoop: the hoop is the goal, not a place to drop a ball (one dropped there fell
    // into the net, dead): nothing drops, and the hint says how to score. A tap under the floor
    // drops nothing either (no ball can be there): the hint says what a pull from there does.
    if (pressStand) standTapAt = performance.now();
    else if (ball === 0 && onHoop(pressAt[0], pressAt[1])) hoopTapAt = performance.now();
    else shoot(pressSpot[0], pressSpot[1], 0, 0, false);
  } else if (ball !== 0 && handles.balls.includes(ball)) {
    // A buried ball with no room over it is not thrown (its pull said so: drawPointer).
    if (!throwBall(ball, t.vx, t.vy)) return;
    if (boardSaid) boardTaught = true;
    released(t);
    if (last) lastCall.ball = ball;
  } else {
    if (boardSaid) boardTaught = true;
    released(t);
    const e = shoot(t.x, t.y, t.vx, t.vy);
    if (last) lastCall.ball = e;
  }
}
/** How far the current press's anchor has followed a finger up, CSS px (a finger slid up to flick: release). */
let followed = 0;
/** The current press's longest pull back (down), CSS px: a finger that slid up and never pulled back was a flick, not a cancel (release). */
let pulledMost = 0;
/** The current press's pointer samples (event times), for the speed of a finger's flick as it lets go. */
const flick = new FlickTracker();

/**
 * A finger let go in a flick up (flick.ts: its speed read from the events' own times, so a slow
 * page's flick throws as a fast one's): when the pull itself would throw nothing (not pulled, or back
 * in the cancel zone, as a finger sliding up drags the anchor along) or down (pulled up from the
 * stand), the pull is set to the flick's (flickPull): the ball goes the way the finger flicked,
 * faster the quicker the flick, and the aim assist draws it to a basket as it does a pull.
 */
function flickRelease(event: PointerEvent): void {
  if (!pressFinger) return;
  const [vx, vy] = flick.release(lastX, lastY, event.timeStamp);
  if (dragged && !inCancelZone() && lastY >= startY) return;
  const pull = flickPull(vx, vy, fullPullNow);
  if (!pull) return;
  lastX = startX + pull[0];
  lastY = startY + pull[1];
  dragged = true;
}

/** Whether the last drawn aiming label said "blocked", and the pointer's spot then (CSS px on the canvas). */
let shownBlocked = { blocked: false, x: Number.NaN, y: Number.NaN };
/** When a release was refused because a ball was in the way at once (performance.now() ms; its hint shows HOOP_TAP_SHOWN ms), or -Infinity. */
let blockedAt = Number.NEGATIVE_INFINITY;
/** Where that refused throw would have started, m. */
let blockedSpot: [number, number] = [0, 0];
/** What the page says where a throw was refused because a ball was in its way. */
const BLOCKED_WORDS = 'blocked — pick the top ball';

/**
 * Whether throw `t` of ball `thrown` (0 for a new basketball) is blocked at once: its aiming arc
 * ends on another ball within BLOCKED_SOON_M of its start (arcCut), so it would roll off its neighbour
 * rather than fly.
 */
function blockedAtOnce(t: { x: number; y: number; vx: number; vy: number; radius: number; mass: number }, thrown: number): boolean {
  if (thrown !== 0 && handles.balls.includes(thrown) && liftSpot(thrown) === null) return false;
  const cut = arcCut(t, arcOf(t, thrown, arcSeconds(t.y, t.vy), 0, 0), thrown);
  return cut !== null && cut.kind === 'ball' && cut.soon;
}

/**
 * A throw's release, heard and seen: the slingshot's snap and a whoosh, louder the faster the throw,
 * and a ring bursting from the ball's start (drawPointer, RELEASE_MS).
 */
function released(t: { x: number; y: number; vx: number; vy: number; radius: number }): void {
  const f = Math.min(1, Math.hypot(t.vx, t.vy) / MAX_THROW_SPEED);
  sound.snap(0.15 + 0.35 * f);
  sound.launch(0.3 + 0.7 * f);
  releaseFx = { x: t.x, y: t.y, r: t.radius, at: performance.now(), power: f };
}
/** How long a release's ring bursts, ms. */
const RELEASE_MS = 260;
/** The last throw's release (its start, m, the ball's radius, m, when, performance.now() ms, and its speed / MAX_THROW_SPEED). */
let releaseFx = { x: 0, y: 0, r: 0, at: -1e9, power: 0 };

// A long press on a touch screen may open the browser's menu: the hold picks a ball up instead.
canvas.addEventListener('contextmenu', (event) => event.preventDefault());

/**
 * A player's ball at (x, y), m, with velocity (vx, vy), m/s: orange if released below the rim (it may
 * score), grey if not. A `thrown` ball (a throw, not a click's drop) counts as a shot. @returns its id.
 */
function shoot(x: number, y: number, vx: number, vy: number, thrown = true): number {
  const e = spawnBall(shell.world, handles, x, y, vx, vy, PLAYER_RADIUS);
  basketballs.add(e);
  launch(e, thrown);
  return e;
}

/**
 * Ball `e` of the scene (a heap ball, the gold one or a basketball lying about) thrown with velocity
 * (vx, vy), m/s, as the slingshot throws: from where it is, or lifted first to the top of the heap over
 * it if it is buried (liftSpot, where its aiming arc starts too); its spin stopped, it counts as a shot
 * and may score its BALL_POINTS if it is below the rim. A buried ball with nowhere to go is not thrown.
 * @returns whether it was thrown. @throws RangeError if it is not a ball of the scene.
 */
function throwBall(e: number, vx: number, vy: number): boolean {
  if (!handles.balls.includes(e)) throw new RangeError(`throwBall: ${e} is not a ball of the scene`);
  const from = liftSpot(e);
  if (from === null) return false;
  if (e === fingerLift) fingerLift = 0;
  const c = shell.world.components,
    s = slotOf(e);
  if (from[0] !== c.Position.x[s] || from[1] !== c.Position.y[s]) setPosition(shell.world, e, from);
  setVelocity(shell.world, e, [vx, vy]);
  setAngularVelocity(shell.world, e, 0);
  // Free of the balls it rested on while it leaves them (leaveOf, as its aiming arc showed): their
  // contacts would push it off its arc.
  const dt = shell.world.dt;
  const { steps } = leaveOf(nearBalls(from[0], from[1], e), from[0], from[1], vx, vy, c.Ball.radius[s]!, dt);
  // Free through the integrate of the leave's last step (world time is a step behind there).
  if (steps > 0) leaving.set(e, { until: shell.world.time + (steps - 0.5) * dt, x: from[0], y: from[1], vx, vy, near: [] });
  launch(e, true);
  return true;
}

/**
 * Follows ball `e`, just released, as a throw (`thrown`) or a drop: orange (a basketball) if it may
 * score, grey if released above the rim's line; a throw counts as a shot.
 */
function launch(e: number, thrown: boolean): void {
  const P = shell.world.components.Position;
  const bx = P.x[slotOf(e)]!,
    by = P.y[slotOf(e)]!;
  const scores = mayScore(hoopSpots(TALL)[hoopAt]!, by);
  if (basketballs.has(e)) renderer.setColor(e, scores ? PLAYER_COLOR : HIGH_COLOR);
  // A drop falls: it cannot go down through the hoop from below the rim, nor be a miss.
  if (thrown)
    flights.set(e, {
      scores,
      up: false,
      x: bx,
      y: by,
      top: by,
      kind: kindOf(e),
      at: shell.world.time,
      touched: false,
      trick: false,
      noShot: noShotAt(bx, by),
    });
  else flights.delete(e);
  if (round.phase !== 'over' && thrown) {
    roundShot(round);
    // Each throw replaces the last one's reminder: a throw from below the line clears it.
    lastThrown = e;
    ruleHint = scores ? '' : 'high';
  }
}
canvas.addEventListener('pointerup', (event) => release(event, false));
canvas.addEventListener('pointercancel', (event) => release(event, true));

/**
 * The dotted arc of the throw the pointer would make now: its points, m (flat x, y pairs), or [] when
 * not pulling. Through the top of the flight and down to just above the rim's height (arcSeconds),
 * and only up to its first touch: it ends where the ball would meet a wall, a ramp, the box's top, the
 * hoop or a ball (the red cross), so where a bounce sends it is the player's to judge: an arc drawn
 * through its first bounce would let a player wiggle the pull until the dots dropped through the hoop,
 * with no aim.
 */
function aimPath(): number[] {
  if (pointerId === -1 || !dragged || inCancelZone() || refused()) return [];
  const t = currentThrow();
  return arcOf(t, pressBall, throwScores(t) ? basketSeconds(t.y, t.vy) : arcSeconds(t.y, t.vy), 0, 0);
}

/**
 * Whether the throw being pulled, `t` (currentThrow), goes in clean: drawn to a basket by the aim
 * assist (assisting) or through the opening as it is (scoresClean). Its arc then runs on into the net
 * (basketSeconds), green, the rim glows and the gauge says "on target" (drawPointer): the player sees
 * the shot that scores, and learns it. Worked out once for each throw (every frame asks).
 */
function throwScores(t: { x: number; y: number; vx: number; vy: number; radius: number; mass: number }): boolean {
  if (assisting) return true;
  const key = `${t.x},${t.y},${t.vx},${t.vy},${pressBall},${hoopAt}`;
  if (scoresMemo.key !== key) scoresMemo = { key, on: scoresClean(t, pressBall) };
  return scoresMemo.on;
}
/** The last throw throwScores judged (its start, velocity, ball and hoop) and whether it goes in. */
let scoresMemo = { key: '', on: false };

/**
 * How much of a throw that goes in (throwScores) from height `y`, m, with vertical speed `vy`, m/s,
 * its aiming arc shows, s: the drag-free time until its centre is BASKET_ARC_BELOW_RIM under the
 * rim, in the net (at most FLIGHT_SECONDS); it ends sooner at its first touch (the net).
 */
function basketSeconds(y: number, vy: number): number {
  const g = handles.params.gravity;
  if (!(g > 0)) return arcSeconds(y, vy);
  const apex = vy > 0 ? vy / g : 0;
  const drop = y + (vy > 0 ? (vy * vy) / (2 * g) : 0) - (hoopSpots(TALL)[hoopAt]!.y - BASKET_ARC_BELOW_RIM);
  return Math.min(FLIGHT_SECONDS, Math.max(arcSeconds(y, vy), apex + Math.sqrt(Math.max(0, 2 * drop) / g)));
}
/** How far under the rim the arc of a throw that goes in ends, m: inside the net, so the dots are seen to drop through the ring. */
const BASKET_ARC_BELOW_RIM = 0.6;

/**
 * How much of a throw from height `y`, m, with vertical speed `vy`, m/s (up), its aiming arc shows, s:
 * the drag-free time until it comes back down to ARC_END_ABOVE_RIM over the rim's height, so the
 * arc shows where the ball comes down as well as how it rises, and the player judges its last stretch
 * into the hoop. A throw whose top is under that height shows to APEX_MORE past its top. At least
 * aimSeconds and at most FLIGHT_SECONDS; it ends sooner at its first touch (aimPath).
 */
function arcSeconds(y: number, vy: number): number {
  const g = handles.params.gravity;
  if (!(g > 0)) return aimSeconds();
  const apex = vy > 0 ? vy / g : 0;
  const drop = y + (vy > 0 ? (vy * vy) / (2 * g) : 0) - (hoopSpots(TALL)[hoopAt]!.y + ARC_END_ABOVE_RIM);
  const down = drop > 0 ? apex + Math.sqrt((2 * drop) / g) : apex + APEX_MORE;
  return Math.min(FLIGHT_SECONDS, Math.max(aimSeconds(), down));
}
/** How far past its top the aiming arc of a throw that peaks under the rim goes on, s of flight. */
const APEX_MORE = 0.2;
/**
 * How far over the rim's height the aiming arc of a falling throw ends, m: a basketball's radius
 * short of the rim, so the dots show where the ball comes down and the player still aims its last stretch.
 */
const ARC_END_ABOVE_RIM = 0.4;

/** Whether the press is on a buried ball with no room over it (liftSpot null): its pull throws nothing. */
function refused(): boolean {
  return pressBall !== 0 && handles.balls.includes(pressBall) && liftSpot(pressBall) === null;
}

/** The whole flight of the throw the pointer would make now (FLIGHT_SECONDS, AIM_BOUNCES bounces): points, m, or [] when not pulling. */
function aimFlight(): number[] {
  if (pointerId === -1 || !dragged || inCancelZone() || refused()) return [];
  return arcOf(currentThrow(), pressBall, FLIGHT_SECONDS, AIM_BOUNCES);
}

/**
 * The least of a throw's flight its aiming arc shows, s (arcSeconds): AIM_SECONDS, the same in the
 * warm-up and once the clock runs, TALL_AIM_SCALE times longer in the tall box (a phone held upright).
 */
function aimSeconds(): number {
  return AIM_SECONDS * (TALL ? TALL_AIM_SCALE : 1);
}
/**
 * How much longer the aiming arc is in the tall box: a phone draws the court at some 36 px a metre
 * (a desktop 56), so the same 0.6 s of flight would be a third shorter on its screen, most of it under
 * the thumb's side of the ball; 1.5 times longer, it spans about as many pixels as a desktop's.
 */
const TALL_AIM_SCALE = 1.5;
/**
 * The aiming arc's least length, s of flight, in the warm-up and once the clock runs alike: most of
 * a basket's flight (a basket from the natural starts of reach.ts reaches the rim 0.8 to 2 s after its
 * throw, 1.7 s the median), for a throw that does not come down to the rim's height sooner
 * (arcSeconds). It ends sooner at its first touch: a ball, a wall, a ramp or the hoop (aimPath). Much
 * shorter, a flat throw's arc ends well short of the hoop and the player guesses the rest.
 */
const AIM_SECONDS = 1.2;
/** The longest flight `aimFlight` and the test hook `aimFrom` follow, s. */
const FLIGHT_SECONDS = 2.5;

/**
 * The aiming arc of throw `t` (start, m; velocity, m/s; the ball's radius, m, and mass, kg) for its
 * first `seconds` s of flight and `bounces` bounces, besides `ceilingBounces` off the box's top
 * (hoop.ts throwPath), ending at any ball but `thrown` in its way.
 */
function arcOf(
  t: { x: number; y: number; vx: number; vy: number; radius: number; mass: number },
  thrown: number,
  seconds = FLIGHT_SECONDS,
  bounces = AIM_BOUNCES,
  ceilingBounces = 0,
  every?: number,
): number[] {
  const p = handles.params;
  const spot = hoopSpots(TALL)[hoopAt]!;
  const walls = [
    ...layoutOf(TALL).segments.map(([ax, ay, bx, by]) => [ax, ay, bx, by, SEGMENT_RADIUS] as const),
    ...hoopSegments(spot).map(([ax, ay, bx, by]) => [ax, ay, bx, by, HOOP_RADIUS] as const),
  ];
  return throwPath(t.x, t.y, t.vx, t.vy, {
    gravity: p.gravity,
    drag: p.drag,
    k: p.dragK,
    mass: t.mass,
    radius: t.radius,
    box: layoutOf(TALL).box,
    seconds,
    ...(every === undefined ? {} : { every }),
    bounces,
    ceilingBounces,
    restitution: p.restitution,
    friction: p.friction,
    walls,
    hoop: spot,
    stops: arcStops(t, thrown),
  });
}

/** How far from a throw's start the other balls end its aiming arc, m: the heap round it (balls further off that move get out of the way before the ball gets there). */
const STOP_REACH = 3;
/**
 * How far from a throw's start the balls at rest (under REST_SPEED) end its aiming arc too, m: a
 * throw skimming the heap met a resting ball 4 m on, under the arc it showed.
 */
const REST_REACH = 8;
/** Balls slower than this, m/s, are at rest for REST_REACH. */
const REST_SPEED = 0.5;

/** The balls within STOP_REACH of (x, y), m, or at rest within REST_REACH of it, but `except`: [x, y, radius] each, for the aiming arc's stops. */
function nearBalls(x: number, y: number, except: number): [number, number, number][] {
  const c = shell.world.components,
    V = c.Velocity;
  const out: [number, number, number][] = [];
  for (const e of handles.balls) {
    if (e === except) continue;
    const s = slotOf(e);
    const bx = c.Position.x[s]!,
      by = c.Position.y[s]!;
    const d = Math.max(Math.abs(bx - x), Math.abs(by - y));
    if (d < STOP_REACH || (d < REST_REACH && V.x[s]! ** 2 + V.y[s]! ** 2 < REST_SPEED ** 2)) out.push([bx, by, c.Ball.radius[s]!]);
  }
  return out;
}
/**
 * The balls that end throw `t`'s aiming arc, [x, y, radius, from step] each: those near its start but
 * ball `thrown`; for a ball of the scene, the ones it rests on and leaves (leaveOf) only after the
 * leave, the others (a ball it is thrown into) from its first step.
 */
function arcStops(t: { x: number; y: number; vx: number; vy: number; radius: number }, thrown: number): [number, number, number, number][] {
  const near = nearBalls(t.x, t.y, thrown);
  if (thrown === 0) return near.map(([x, y, r]) => [x, y, r, 0]);
  const { steps, met } = leaveOf(near, t.x, t.y, t.vx, t.vy, t.radius, shell.world.dt);
  return near.map(([x, y, r], i) => [x, y, r, met.has(near[i]!) ? steps + 1 : 0]);
}
/** Bounces the whole predicted flight (aimFlight, aimFrom) follows (off the walls, the hoop and its net) before it ends; the shown arc follows none. */
const AIM_BOUNCES = 2;

/** An aiming arc that ends on a ball less than this far from the throw's start, m, is labelled blocked. */
const BLOCKED_SOON_M = 1.5;

/**
 * How far, degrees, the way an aiming arc meets a ball near its start may be from straight at that
 * ball's centre for the throw to be blocked (arcCut); a throw meeting it more sideways glances off.
 */
const HEAD_ON_DEG = 60;

/** How close to a thing the end of an aiming arc is for the arc to have been cut by it, m (past the ball's and the thing's radii). */
const CUT_REACH = 0.05;

/**
 * What ends aiming arc `path` (points, m, as aimPath) of throw `t` short, and where: 'ball' (another
 * ball in its way), 'ramp' (one of the layout's inclined walls), 'board' (the hoop's backboard, its
 * face or top: a shot that often banks in, so not a block), 'rim' (the hoop's front rim) or 'net'
 * (the hoop's net, from below or the side); null when it runs its length, ends
 * at the box, or goes down through the hoop's opening (from below the shot line) before it ends. `soon`: a ball in the way within BLOCKED_SOON_M of the throw's start, met nearly head-on
 * (HEAD_ON_DEG; a throw into its neighbour in the heap; releasing it throws nothing: release).
 */
function arcCut(
  t: { x: number; y: number; radius: number },
  path: readonly number[],
  thrown: number,
): { kind: CutKind; x: number; y: number; soon: boolean } | null {
  const n = path.length / 2;
  if (n < 2) return null;
  const ex = path[2 * n - 2]!,
    ey = path[2 * n - 1]!;
  const near = Math.hypot(ex - t.x, ey - t.y) < BLOCKED_SOON_M;
  // The arc's way at its end (its last stretch), for how squarely it meets the ball there.
  const wx = ex - path[2 * n - 4]!,
    wy = ey - path[2 * n - 3]!,
    wl = Math.hypot(wx, wy) || 1;
  for (const [bx, by, br] of nearBalls(t.x, t.y, thrown)) {
    const d = Math.hypot(ex - bx, ey - by);
    if (d >= t.radius + br + 0.02) continue;
    // Blocked only when it drives into that ball (within HEAD_ON_DEG of straight at its centre): a
    // throw grazing a neighbour's top on its way up glances off it and flies on ("hits a ball").
    const headOn = ((bx - ex) * wx + (by - ey) * wy) / ((d || 1) * wl) > Math.cos((HEAD_ON_DEG * Math.PI) / 180);
    return { kind: 'ball', x: ex, y: ey, soon: near && headOn };
  }
  for (const [ax, ay, bx, by] of layoutOf(TALL).segments)
    if (distanceToSegment(ex, ey, ax, ay, bx, by) < t.radius + SEGMENT_RADIUS + CUT_REACH)
      return { kind: 'ramp', x: ex, y: ey, soon: false };
  const spot = hoopSpots(TALL)[hoopAt]!;
  // An arc that went down through the opening first shows a basket: what it meets after (the net
  // catching it) is no cut ("hits the net" by a basket read as a miss).
  if (mayScore(spot, t.y)) {
    const o = hoopOpening(spot);
    for (let i = 1; i < n; i++) if (hoopCrossing(o, path[2 * i - 2]!, path[2 * i - 1]!, path[2 * i]!, path[2 * i + 1]!) === -1) return null;
  }
  // hoopSegments: the backboard first, then the front rim.
  for (const [i, [ax, ay, bx, by]] of hoopSegments(spot).entries())
    if (distanceToSegment(ex, ey, ax, ay, bx, by) < t.radius + HOOP_RADIUS + CUT_REACH)
      return { kind: i === 0 ? 'board' : 'rim', x: ex, y: ey, soon: false };
  // The net hangs NET.depth under the rim, between the rim's ends.
  if (Math.abs(ex - spot.x) < HOOP_HALF_WIDTH + t.radius + CUT_REACH && ey < spot.y && ey > spot.y - NET.depth - t.radius - CUT_REACH)
    return { kind: 'net', x: ex, y: ey, soon: false };
  return null;
}

/** What ends an aiming arc short (arcCut). */
type CutKind = 'ball' | 'ramp' | 'board' | 'rim' | 'net';

/** What the small label by an aiming arc's cut says, by what cut it (arcCut). */
const CUT_WORDS = {
  ball: 'hits a ball',
  ramp: 'hits the ramp',
  board: 'hits the board',
  rim: 'hits the hoop',
  net: 'hits the net',
} as const;

/**
 * What the cut label says for the backboard until a throw shown so is let go (boardTaught): only
 * what is known, that the ball hits the board and may go in or bounce out (the arc ends there), so
 * it reads neither as a miss nor as a basket ("a bank shot still scores" read as "this scores").
 */
const BOARD_RULE_WORDS = 'hits the board · may bounce in or out';
/** Whether a throw has been let go with its arc cut by the backboard and BOARD_RULE_WORDS beside it (then the short words do). */
let boardTaught = false;
/** Whether the current press's arc showed BOARD_RULE_WORDS. */
let boardSaid = false;

/** The words beside an arc cut by `kind` (CUT_WORDS; the backboard's rule the first time: BOARD_RULE_WORDS). */
function cutWords(kind: CutKind): string {
  return kind === 'board' && !boardTaught ? BOARD_RULE_WORDS : CUT_WORDS[kind];
}

/** The cut label's colour: red for a block, pale blue for the backboard (a bank shot, often in). */
const CUT_FILL = { block: 0xffb3b3, board: 0xbfe3ff } as const;

/** The small label by the ✕ where the aiming arc is cut (arcCut). */
const cutLabel = new Text({
  text: '',
  style: { fontFamily: 'system-ui, sans-serif', fontSize: 12, fontWeight: '600', fill: 0xffb3b3, stroke: { color: 0x0b0f16, width: 3 } },
});
cutLabel.anchor.set(0.5, 1);
cutLabel.visible = false;

/** The band's colour for a pull of `power` (powerOf, [0, 1]): white, to gold at half, to red at full. */
function powerColor(power: number): number {
  return power < 0.5 ? mixColor(0xffffff, 0xffd166, power / 0.5) : mixColor(0xffd166, 0xff4d4d, (power - 0.5) / 0.5);
}

/** The label over a press held on a ball (what the hold does) and over a ball picked up (how to let go). */
const holdLabel = new Text({
  text: '',
  style: {
    fontFamily: 'system-ui, sans-serif',
    fontSize: 14,
    fontWeight: '600',
    align: 'center',
    fill: 0xffffff,
    stroke: { color: 0x0b0f16, width: 4 },
  },
});
holdLabel.anchor.set(0.5, 1);
holdLabel.visible = false;
app.stage.addChild(holdLabel);
app.stage.addChild(cutLabel);

/** The "drag me" label over the marked ball (markThrowable) until the round's first throw. */
const markLabel = new Text({
  text: 'drag me',
  style: { fontFamily: 'system-ui, sans-serif', fontSize: 15, fontWeight: '700', fill: 0xffd166, stroke: { color: 0x0b0f16, width: 4 } },
});
markLabel.anchor.set(0.5, 1);
markLabel.visible = false;
app.stage.addChild(markLabel);
/** How often the marked ball is chosen again, ms (markThrowable): the heap settles slowly, and liftSpot is not free. */
const MARK_EVERY_MS = 400;
/** The ball marked as the one to throw (0: none) and when it was chosen, performance.now() ms. */
let marked = { ball: 0, at: Number.NEGATIVE_INFINITY };

/**
 * How near a side wall of the tall box a ball's centre may lie, m, before the ball to mark as
 * throwable (throwableBall) passes it over: on a phone one by the wall left no room on the screen to pull
 * towards that wall. Counted as this much less height in the ranking.
 */
const EDGE_ROOM = 1.5;

/**
 * The ball to mark as throwable: of the heap's balls at rest (slower than COLUMN_REST_SPEED, not in
 * flight or fading), released below the shot line and not buried (liftSpot leaves it where it lies),
 * the one whose top is highest, a metre of distance sideways from the hoop (up to 5 m) counting as
 * 0.3 m of height (a throw from under the hoop is a hard one), one within EDGE_ROOM of a side wall
 * of the tall box EDGE_ROOM less. 0 when there is none.
 */
function throwableBall(): number {
  const c = shell.world.components,
    P = c.Position,
    V = c.Velocity,
    R = c.Ball.radius;
  const spot = hoopSpots(TALL)[hoopAt]!,
    { box } = layoutOf(TALL);
  const ranked: [number, number][] = [];
  for (const e of handles.balls) {
    if (flights.has(e) || fading.has(e)) continue;
    const s = slotOf(e);
    if (V.x[s]! ** 2 + V.y[s]! ** 2 > COLUMN_REST_SPEED ** 2 || !mayScore(spot, P.y[s]!)) continue;
    // In the tall box (a phone held upright) a ball by a side wall (within EDGE_ROOM) is passed over
    // for one with room beside it to pull into; the wide box's screen has room beside its walls.
    const edge = TALL && Math.min(P.x[s]! - box.min[0], box.max[0] - P.x[s]!) < EDGE_ROOM ? EDGE_ROOM : 0;
    ranked.push([e, P.y[s]! + R[s]! + 0.3 * Math.min(5, Math.abs(P.x[s]! - spot.x)) - edge]);
  }
  ranked.sort((a, b) => b[1] - a[1]);
  // The best few only: a buried one is passed over (liftSpot is the costly part).
  for (const [e] of ranked.slice(0, 6)) if (!buried(e)) return e;
  return 0;
}

/**
 * Marks the ball to throw when no press is under way: a ring pulsing round it (once a second) and,
 * until the round's first throw, "drag me" over it, so a newcomer sees what to pull before trying.
 */
function markThrowable(): void {
  markLabel.visible = false;
  if (pointerId !== -1 || drag.joint !== 0 || round.phase === 'over' || shell.paused) return;
  const now = performance.now();
  if (now - marked.at > MARK_EVERY_MS || !handles.balls.includes(marked.ball) || flights.has(marked.ball))
    marked = { ball: throwableBall(), at: now };
  if (marked.ball === 0) return;
  const cam = renderer.camera,
    s = slotOf(marked.ball),
    P = shell.world.components.Position;
  const x = cam.toScreenX(P.x[s]!),
    y = cam.toScreenY(P.y[s]!),
    r = cam.toScreenLength(shell.world.components.Ball.radius[s]!);
  const pulse = 0.5 + 0.5 * Math.sin((2 * Math.PI * now) / 1000);
  overlay.circle(x, y, r + 5 + 4 * pulse).stroke({ width: 3, color: 0xffffff, alpha: 0.5 + 0.45 * pulse });
  if (round.shots === 0 && round.phase === 'ready') {
    placeInside(markLabel, x, y - r - 12 - 4 * pulse);
    markLabel.visible = true;
  }
}

/** Shows `text` on the hold label centred at x, its bottom at y (CSS px on the canvas), kept inside the canvas. */
function showHoldLabel(text: string, x: number, y: number): void {
  if (holdLabel.text !== text) holdLabel.text = text;
  placeInside(holdLabel, x, y);
  holdLabel.visible = true;
}

/** How far from the canvas' sides placeInside keeps a label, CSS px: clear of a phone's rounded corners and its edge swipe (4 px read as cut off). */
const LABEL_EDGE_PX = 12;
/** Puts `label` (anchored at its bottom centre) centred at x, its bottom at y (CSS px on the canvas), moved to lie LABEL_EDGE_PX inside the canvas' sides (centred when wider than that leaves). */
function placeInside(label: Text, x: number, y: number): void {
  const half = label.width / 2 + LABEL_EDGE_PX;
  const w = app.screen.width;
  label.position.set(half * 2 >= w ? w / 2 : Math.min(w - half, Math.max(half, x)), Math.max(label.height + 2, y));
}

/** Radius of the power ring drawn round a finger pulling a throw on a touch screen, CSS px: clear of a thumb's contact (about 10 mm across). */
const FINGER_RING_PX = 40;

/**
 * Draws the pointer preview: the ball to be dropped; while pulling, the ball at its spot (orange if
 * it may score, grey if above the rim's line; a buried ball lifted to the top of the heap, or refused
 * in red with no room there), the slingshot's band to the pointer, a power gauge round the ball with
 * its percentage, and a dotted arc of where the ball will fly, its dots fading along it.
 */
/** A dashed white line on the pointer overlay from `gap` px off (x0, y0) to 4 px short of (x1, y1), CSS px: a ball tied to its press under the floor. */
function dashTo(x0: number, y0: number, gap: number, x1: number, y1: number): void {
  const len = Math.hypot(x1 - x0, y1 - y0);
  for (let d = gap; d < len - 4; d += 10) {
    const f = d / len,
      g = Math.min(len - 4, d + 5) / len;
    overlay.moveTo(x0 + f * (x1 - x0), y0 + f * (y1 - y0)).lineTo(x0 + g * (x1 - x0), y0 + g * (y1 - y0));
  }
  overlay.stroke({ width: 2, color: 0xffffff, alpha: 0.6 });
}

function drawPointer(): void {
  overlay.clear();
  markLabel.visible = false;
  liftedShown = 0;
  holdLabel.visible = false;
  cutLabel.visible = false;
  const cam = renderer.camera;
  // A release's ring, bursting out from where the ball left and fading.
  const age = (performance.now() - releaseFx.at) / RELEASE_MS;
  if (age >= 0 && age < 1) {
    const rr = cam.toScreenLength(releaseFx.r) * (1 + 1.2 * age) + 4;
    overlay
      .circle(cam.toScreenX(releaseFx.x), cam.toScreenY(releaseFx.y), rr)
      .stroke({ width: 3 + 3 * releaseFx.power, color: powerColor(releaseFx.power), alpha: 0.9 * (1 - age) });
  }
  if (pointerId === -1) {
    markThrowable();
    // A throw refused as blocked: say why where it would have started, for a moment.
    if (performance.now() - blockedAt < HOOP_TAP_SHOWN)
      showHoldLabel(BLOCKED_WORDS, cam.toScreenX(blockedSpot[0]), cam.toScreenY(blockedSpot[1]) - cam.toScreenLength(PLAYER_RADIUS) - 8);
    // A ball picked up: say how to let it go, over it.
    if (drag.joint !== 0 && drag.body !== 0) {
      const s = slotOf(drag.body);
      const P = shell.world.components.Position;
      showHoldLabel('carry it · let go to drop it', cam.toScreenX(P.x[s]!), cam.toScreenY(P.y[s]!) - cam.toScreenLength(PLAYER_RADIUS) - 8);
    }
    return;
  }
  const r = cam.toScreenLength(PLAYER_RADIUS);
  if (!dragged && pressStand) {
    // Pressed under the floor: the ball it throws ringed (the top of the heap over the press, or the
    // new basketball's spot on the floor), a dashed line down to the press, and what to do.
    const t = currentThrow();
    const bx = cam.toScreenX(t.x),
      by = cam.toScreenY(t.y),
      br = cam.toScreenLength(t.radius);
    if (pressBall === 0) overlay.circle(bx, by, br).fill({ color: PLAYER_COLOR, alpha: 0.85 });
    overlay.circle(bx, by, br + 4).stroke({ width: 3, color: 0xffffff, alpha: 0.9 });
    dashTo(bx, by, br + 6, startX, startY);
    overlay.circle(startX, startY, 6).fill({ color: 0xffffff, alpha: 0.7 });
    showHoldLabel('pull back to throw this ball', bx, by - br - 10);
    return;
  }
  if (!dragged) {
    overlay.circle(startX, startY, r).stroke({ width: 2, color: 0xffffff, alpha: 0.6 });
    // The ball a pull will throw (the free one pickFree took, maybe not the one under the press):
    // ringed before the pull, tied to the press by a dashed line when it is another.
    if (pressBall !== 0 && handles.balls.includes(pressBall)) {
      const s = slotOf(pressBall),
        P = shell.world.components.Position;
      const bx = cam.toScreenX(P.x[s]!),
        by = cam.toScreenY(P.y[s]!),
        br = cam.toScreenLength(shell.world.components.Ball.radius[s]!);
      overlay.circle(bx, by, br + 4).stroke({ width: 3, color: 0xffffff, alpha: 0.9 });
      if (Math.hypot(bx - startX, by - startY) > br + 4) dashTo(bx, by, br + 6, startX, startY);
    }
    // Held still on a ball or crate: after HOLD_RING_MS a ring fills, picking it up when full (a
    // pull before then throws), and a label says so.
    const held = performance.now() - holdStart;
    if (held >= HOLD_RING_MS && bodyUnder(cam.toWorldX(startX), cam.toWorldY(startY))) {
      const f = Math.min(1, (held - HOLD_RING_MS) / (HOLD_MS - HOLD_RING_MS));
      overlay.circle(startX, startY, r + 6).stroke({ width: 4, color: 0x0b0f16, alpha: 0.5 });
      // From the top, clockwise, as a polyline (pixi's arc here joined the canvas's corner to it with a line).
      const steps = Math.max(1, Math.ceil(48 * f));
      overlay.moveTo(startX, startY - r - 6);
      for (let k = 1; k <= steps; k++) {
        const a = -Math.PI / 2 + (2 * Math.PI * f * k) / steps;
        overlay.lineTo(startX + (r + 6) * Math.cos(a), startY + (r + 6) * Math.sin(a));
      }
      overlay.stroke({ width: 4, color: 0xffd166, alpha: 0.95 });
      showHoldLabel('hold still to pick up · pull to throw', startX, startY - r - 12);
    }
    return;
  }
  // Pulled back into the cancel zone: a dashed ring round it and what letting go does, no arc.
  if (inCancelZone()) {
    const cr = cancelRadius();
    overlay.circle(startX, startY, cr).stroke({ width: 2, color: 0xffffff, alpha: 0.8 });
    overlay.circle(startX, startY, cr + 3).stroke({ width: 2, color: 0x0b0f16, alpha: 0.5 });
    showHoldLabel('release here to cancel', startX, startY - cr - 8);
    return;
  }
  if (pressPicked) repickFree();
  // A buried ball with no room over it: a red ring round it and why nothing will be thrown.
  const pressed = pressBall !== 0 && handles.balls.includes(pressBall) ? pressBall : 0;
  const lift = pressed !== 0 ? liftSpot(pressed) : null;
  const P = shell.world.components.Position;
  if (pressed !== 0 && lift === null) {
    const s = slotOf(pressed);
    const bx = cam.toScreenX(P.x[s]!),
      by = cam.toScreenY(P.y[s]!),
      br = cam.toScreenLength(shell.world.components.Ball.radius[s]!);
    overlay.circle(bx, by, br + 4).stroke({ width: 4, color: 0xff4d4d, alpha: 0.95 });
    showHoldLabel('buried · hold still 1 s to carry it', bx, by - br - 8);
    return;
  }
  // From the ball being thrown: the pressed ball's centre (lifted to the top of the heap if it is
  // buried), or the press point for a new basketball.
  const t = currentThrow();
  if (pressed !== 0 && lift !== null) {
    const s = slotOf(pressed);
    const bx = cam.toScreenX(P.x[s]!),
      by = cam.toScreenY(P.y[s]!);
    if (Math.hypot(cam.toScreenX(lift[0]) - bx, cam.toScreenY(lift[1]) - by) > 1) {
      // Lifted: the ball is drawn where it will be thrown from, in full, and where it lies is shown
      // empty (dimmed to the court's colour, its halo too, inside a dashed outline), with a dashed line
      // up between them: one ball of its colour on the screen, not two.
      const ty = cam.toScreenY(lift[1]),
        br = cam.toScreenLength(t.radius);
      overlay.circle(bx, by, br + 9).fill({ color: 0x0b0f18, alpha: 0.8 });
      // Each dash from its own start point: pixi's arc joins the path's current point (the canvas's
      // corner when there is none) to the arc's start with a line.
      for (let k = 0; k < 16; k += 2) {
        const a0 = (k * Math.PI) / 8;
        overlay.moveTo(bx + br * Math.cos(a0), by + br * Math.sin(a0)).arc(bx, by, br, a0, ((k + 1) * Math.PI) / 8);
      }
      overlay.stroke({ width: 2, color: 0xffffff, alpha: 0.6 });
      for (let yy = by - br; yy > ty + br; yy -= 10) overlay.moveTo(bx, yy).lineTo(bx, Math.max(ty + br, yy - 5));
      overlay.stroke({ width: 2, color: 0xffffff, alpha: 0.7 });
      liftedShown = pressed;
      const lx = cam.toScreenX(lift[0]);
      if (pressed === goldBall) overlay.circle(lx, ty, br + 5).stroke({ width: 3, color: GOLD_COLOR, alpha: 0.9 });
      overlay.circle(lx, ty, br).fill({ color: renderer.colorOf(pressed), alpha: 1 });
    }
  }
  const ox = cam.toScreenX(t.x),
    oy = cam.toScreenY(t.y),
    or = cam.toScreenLength(t.radius);
  // A grey (too high) throw's dots are drawn lighter than its ball: grey dots are lost on the wall.
  const thrownColor = mayScore(hoopSpots(TALL)[hoopAt]!, t.y) ? PLAYER_COLOR : HIGH_AIM_COLOR;
  // The band: thicker and warmer the harder the pull (white, gold, red at full power).
  const power = powerOf(t);
  // It is as long as the pull that counts: a pull past the full pull stops at it with a bar across
  // (the cap), and a faint line goes on from its end to the pointer (there too when a lifted ball
  // moved the band's start off the press point).
  const pdx = lastX - startX,
    pdy = lastY - startY,
    plen = Math.hypot(pdx, pdy);
  const capped = plen > fullPullNow;
  const k = capped ? fullPullNow / plen : 1;
  // A pull from under the floor: the band runs from the press to the finger, in the room under the
  // floor, and a dashed line ties it up to the ball it throws (a band from the ball ran down through
  // the heap and the floor).
  const [ax, ay] = pressStand ? [startX, startY] : [ox, oy];
  if (pressStand) dashTo(ox, oy, or + 6, startX, startY);
  const bx = ax + k * pdx,
    by = ay + k * pdy;
  if (Math.hypot(lastX - bx, lastY - by) > 4) overlay.moveTo(bx, by).lineTo(lastX, lastY).stroke({ width: 2, color: 0xffffff, alpha: 0.3 });
  overlay
    .moveTo(ax, ay)
    .lineTo(bx, by)
    .stroke({ width: 3 + 3 * power, color: powerColor(power), alpha: 0.75 });
  overlay.circle(bx, by, 5 + 2 * power).fill({ color: powerColor(power), alpha: 0.7 });
  if (capped) {
    const ux = pdx / plen,
      uy = pdy / plen,
      w = 12;
    overlay
      .moveTo(bx - w * uy, by + w * ux)
      .lineTo(bx + w * uy, by - w * ux)
      .stroke({ width: 4, color: 0x0b0f16, alpha: 0.6 })
      .moveTo(bx - w * uy, by + w * ux)
      .lineTo(bx + w * uy, by - w * ux)
      .stroke({ width: 2, color: 0xffffff, alpha: 0.95 });
  }
  // On a touch screen the thumb covers the ball and its gauge in a pull straight down: a ring round
  // the finger, wider than a thumb's contact, repeats the gauge where the eye is (dark track, the
  // power filling clockwise from the top).
  // Kept inside the canvas (ringInside): a finger by the screen's edge put half of it off screen.
  if (TOUCH_UI) {
    const fr = FINGER_RING_PX;
    const [rx, ry] = ringInside(lastX, lastY, fr + 4, app.screen.width, app.screen.height);
    overlay.circle(rx, ry, fr).stroke({ width: 7, color: 0x0b0f16, alpha: 0.5 });
    const steps = Math.max(1, Math.ceil(48 * power));
    overlay.moveTo(rx, ry - fr);
    for (let j = 1; j <= steps; j++) {
      const a = -Math.PI / 2 + (2 * Math.PI * power * j) / steps;
      overlay.lineTo(rx + fr * Math.cos(a), ry + fr * Math.sin(a));
    }
    overlay.stroke({ width: 4, color: powerColor(power), alpha: 0.95 });
  }
  // Without help (preview.ts aimHelp: after 3 misses in a row) the dots show only the first part of
  // the flight (shortArc) and no verdict: no green, no "on target", no cut past the shown part.
  const help = aimHelp(missesInARow, aimHelpAlways);
  const full = aimPath();
  const path = help ? full : shortArc(full, hoopSpots(TALL)[hoopAt]!.x);
  const n = path.length / 2;
  // The dots shrink and fade out along the arc (it ends short of the rim's height: arcSeconds); green
  // when the throw goes in (throwScores: drawn to a basket by the aim assist, or as pulled), as the
  // label's "on target", and the rim glows green under the arc's end in the net.
  const onTarget = help && throwScores(t);
  const dotColor = onTarget ? ON_TARGET_COLOR : thrownColor;
  if (onTarget) {
    const spot = hoopSpots(TALL)[hoopAt]!;
    const hx = cam.toScreenX(spot.x),
      hy = cam.toScreenY(spot.y),
      hw = cam.toScreenLength(HOOP_HALF_WIDTH);
    // Wider than the rim's ellipse, so the rim drawn over it leaves a green halo round it.
    overlay
      .ellipse(hx, hy, hw + 10, 14)
      .fill({ color: ON_TARGET_COLOR, alpha: 0.18 })
      .stroke({ width: 8, color: 0x0b0f16, alpha: 0.4 })
      .ellipse(hx, hy, hw + 10, 14)
      .stroke({ width: 4, color: ON_TARGET_COLOR, alpha: 0.95 });
  }
  for (let i = 1; i < n; i++) {
    const f = i / n;
    overlay
      .circle(cam.toScreenX(path[2 * i]!), cam.toScreenY(path[2 * i + 1]!), Math.max(3, 0.32 * r * (1 - 0.45 * f)))
      .fill({ color: dotColor, alpha: 1 - 0.75 * f })
      .stroke({ width: 1.5, color: 0x0b0f16, alpha: 0.8 - 0.6 * f });
  }
  if (pressBall !== 0 && handles.balls.includes(pressBall)) {
    // A ball of the scene is thrown: a ring round it and what it is worth.
    overlay.circle(ox, oy, or + 4).stroke({ width: 3, color: 0xffffff, alpha: 0.9 });
  } else overlay.circle(ox, oy, or).fill({ color: thrownColor, alpha: 0.85 }).stroke({ width: 2, color: 0xffffff, alpha: 0.9 });
  // The power gauge: a ring round the ball filling clockwise from the top with the throw's power
  // (powerOf) in the band's colour, on a dark track, and the percentage over it.
  const gr = or + 10;
  overlay.circle(ox, oy, gr).stroke({ width: 6, color: 0x0b0f16, alpha: 0.55 });
  const arcSteps = Math.max(1, Math.ceil(60 * power));
  overlay.moveTo(ox, oy - gr);
  for (let k = 1; k <= arcSteps; k++) {
    const a = -Math.PI / 2 + (2 * Math.PI * power * k) / arcSteps;
    overlay.lineTo(ox + gr * Math.cos(a), oy + gr * Math.sin(a));
  }
  overlay.stroke({ width: 4, color: powerColor(power), alpha: 0.95 });
  // The arc cut short by a ball, a ramp or the hoop: a red cross where it ends (over the thrown
  // ball's disc when a ball blocks it at once) and what it hits beside it.
  // Without help only a cut the short arc reaches is shown, or a ball in the way at once (blocked).
  const fullCut = arcCut(t, full, pressBall);
  const cut = fullCut !== null && (help || fullCut.soon || path.length === full.length) ? fullCut : null;
  // Blocked by a ball within the ball's first BLOCKED_SOON_M of flight: the label says so, as the
  // cross is small and under the gauge (a heap ball thrown into its neighbour rolled off along the
  // heap), and letting go throws nothing (release).
  const soon = cut?.soon === true;
  shownBlocked = { blocked: soon, x: lastX, y: lastY };
  let label = `${soon ? 'blocked · ' : ''}power ${Math.round(100 * power)}%${capped && !onTarget ? ' (max)' : ''}${onTarget ? ' · on target' : ''}`;
  if (pressed !== 0) {
    const points = BALL_POINTS[kindOf(pressed)];
    const lifted = lift !== null && (lift[0] !== P.x[slotOf(pressed)] || lift[1] !== P.y[slotOf(pressed)]);
    label = `${lifted ? 'lifted · ' : ''}${label} · ${points} ${points === 1 ? 'point' : 'points'}`;
  } else label = `new ball · ${label} · ${BALL_POINTS.basketball} point`;
  // From where no pull scores (under the hoop, say) a line over it says so: a pull there only misses.
  const noShot = noShotAt(t.x, t.y);
  if (noShot !== '') label = `${noShot}\n${label}`;
  showHoldLabel(label, ox, oy - gr - 6);
  if (cut !== null) {
    const sx = cam.toScreenX(cut.x),
      sy = cam.toScreenY(cut.y),
      k = 7;
    // Off the backboard: a pale ring, no cross (a bank shot may go in).
    if (cut.kind === 'board')
      overlay
        .circle(sx, sy, k)
        .stroke({ width: 5, color: 0x0b0f16, alpha: 0.6 })
        .circle(sx, sy, k)
        .stroke({ width: 3, color: CUT_FILL.board, alpha: 0.95 });
    else
      overlay
        .moveTo(sx - k, sy - k)
        .lineTo(sx + k, sy + k)
        .moveTo(sx + k, sy - k)
        .lineTo(sx - k, sy + k)
        .stroke({ width: 6, color: 0x0b0f16, alpha: 0.6 })
        .moveTo(sx - k, sy - k)
        .lineTo(sx + k, sy + k)
        .moveTo(sx + k, sy - k)
        .lineTo(sx - k, sy + k)
        .stroke({ width: 4, color: 0xff4d4d, alpha: 0.95 });
    // Beside the cross, unless the main label says it (a ball in the way at once).
    if (!soon) {
      const words = cutWords(cut.kind);
      if (words === BOARD_RULE_WORDS) boardSaid = true;
      if (cutLabel.text !== words) cutLabel.text = words;
      const fill = cut.kind === 'board' ? CUT_FILL.board : CUT_FILL.block;
      if (cutLabel.style.fill !== fill) cutLabel.style.fill = fill;
      // Off the board, the label sits on the court's side of the mark, clear of the board drawn over it.
      const away = cut.kind === 'board' ? -hoopSpots(TALL)[hoopAt]!.side * (cutLabel.width / 2) : 0;
      placeInside(cutLabel, sx + away, sy - k - 4);
      cutLabel.visible = true;
    }
  }
}

// ---- The hoop game: net, shot line, basket pop, status row and the play-again button -------------

const hoopLayer = new Graphics({ label: 'hoop' });
app.stage.addChild(hoopLayer);
// The aiming labels over the hoop (moved up the stage): an arc cut at the net or the board has its
// words beside the hoop, and the rim and the net drawn over them hid "hits" of "hits the net".
app.stage.addChild(holdLabel, cutLabel);
const confetti = new Graphics({ label: 'confetti' });
const popText = new Text({
  text: '+1',
  style: { fontFamily: 'system-ui, sans-serif', fontSize: 44, fontWeight: '800', fill: 0xffd166, stroke: { color: 0x3a1a02, width: 6 } },
});
popText.anchor.set(0.5, 1);
popText.visible = false;
const praiseText = new Text({
  text: 'Basket!',
  style: { fontFamily: 'system-ui, sans-serif', fontSize: 24, fontWeight: '700', fill: 0xffffff, stroke: { color: 0x0b0f16, width: 5 } },
});
praiseText.anchor.set(0.5, 1);
praiseText.visible = false;
/** The court's rectangle on screen, the mask that keeps a basket's effects (confetti, rings, the old hoop's glow) inside the box. */
const courtMask = new Graphics({ label: 'confetti-mask' });
confetti.mask = courtMask;
app.stage.addChild(courtMask, confetti, popText, praiseText);
/**
 * The words of a throw's end that was no basket, said on the court (sayOnCourt; drawOutcome): a miss
 * and why, a throw that could not score, or a flick too slow to throw. Drawn over the ball where it
 * ended for OUTCOME_SECONDS, rising and fading, inside the court.
 */
const outcomeText = new Text({
  text: 'Missed',
  style: {
    fontFamily: 'system-ui, sans-serif',
    fontSize: 20,
    fontWeight: '700',
    fill: 0xffc2b8,
    stroke: { color: 0x0b0f16, width: 5 },
    align: 'center',
    wordWrap: true,
    wordWrapWidth: 300,
  },
});
outcomeText.anchor.set(0.5, 1);
outcomeText.visible = false;
app.stage.addChild(outcomeText);
/** How long a throw's end is said on the court, s (world time). */
const OUTCOME_SECONDS = 2;
/** The last words said on the court: what, where, m, when, world s, and in which world (a new round's says nothing of the last's). */
let outcome: { words: string; x: number; y: number; time: number; world: PhysicsWorld | null } = {
  words: '',
  x: 0,
  y: 0,
  time: Number.NEGATIVE_INFINITY,
  world: null,
};

/** Says `words` on the court at (x, y), m, from now (drawOutcome). */
function sayOnCourt(words: string, x: number, y: number): void {
  outcome = { words, x, y, time: shell.world.time, world: shell.world };
}

/** The court's words (sayOnCourt), `age` s after they were said: over their spot, rising 20 px and fading over the last half, kept inside the court. */
function drawOutcome(age: number): void {
  outcomeText.visible = age >= 0 && age < OUTCOME_SECONDS && outcome.words !== '' && outcome.world === shell.world;
  if (!outcomeText.visible) return;
  const cam = renderer.camera,
    { box } = layoutOf(TALL);
  const left = cam.toScreenX(box.min[0]),
    right = cam.toScreenX(box.max[0]);
  // Wrapped to the court's width (a phone's is some 360 px).
  const wrap = Math.max(120, right - left - 16);
  if (outcomeText.style.wordWrapWidth !== wrap) outcomeText.style.wordWrapWidth = wrap;
  if (outcomeText.text !== outcome.words) outcomeText.text = outcome.words;
  const f = age / OUTCOME_SECONDS;
  const half = outcomeText.width / 2 + 4,
    top = cam.toScreenY(box.max[1]) + outcomeText.height + 4,
    bottom = cam.toScreenY(box.min[1]) - 4;
  const x = half * 2 >= right - left ? (left + right) / 2 : Math.min(right - half, Math.max(left + half, cam.toScreenX(outcome.x)));
  const y = Math.min(bottom, Math.max(top, cam.toScreenY(outcome.y) - 30 - 20 * f));
  outcomeText.position.set(x, y);
  outcomeText.alpha = f < 0.5 ? 1 : 2 * (1 - f);
}

/** How long a basket's celebration lasts, s (world time). */
const CELEBRATE_SECONDS = 1.6;
/** What the praise line says for the n-th basket of a round (1-based): the first few differ. */
const PRAISE = ['Basket!', 'Again!', 'Hat trick!', 'On fire!'];

/**
 * The words over a basket: a trick shot's or a swish's, else the gold ball's, else a streak's, else
 * PRAISE for the n-th basket; then how its points add up (pointsSum) when a bonus or the streak
 * counted, e.g. "Swish! 2 + 1" for a heap ball's swish (its "+3" shows under it).
 */
function praiseFor(b: { score: number; points: number; kind: BallKind; style: ShotStyle }): string {
  const mult = Math.round(b.points / (BALL_POINTS[b.kind] + SHOT_BONUS[b.style]));
  const sum = pointsSum(b.kind, b.style, mult);
  const word =
    b.style === 'trick'
      ? 'Trick shot!'
      : b.style === 'swish'
        ? 'Swish!'
        : b.kind === 'gold'
          ? 'Gold ball!'
          : mult > 1
            ? 'Streak!'
            : PRAISE[Math.min(PRAISE.length, b.score) - 1]!;
  return sum === '' ? word : `${word} ${sum}`;
}

/**
 * How a basket's points add up, the one way every place says it: the ball's points, then its bonus
 * as "+ 1" (a swish, SHOT_BONUS) or "+ 3" (a trick shot), in brackets times the streak's multiplier
 * when that is over 1: "2 + 1", "(1 + 3) ×2", "2 ×3"; '' for a plain basket at ×1 (its points alone).
 */
function pointsSum(kind: BallKind, style: ShotStyle, mult: number): string {
  const bonus = SHOT_BONUS[style];
  const parts = bonus > 0 ? `${BALL_POINTS[kind]} + ${bonus}` : `${BALL_POINTS[kind]}`;
  if (mult > 1) return bonus > 0 ? `(${parts}) ×${mult}` : `${parts} ×${mult}`;
  return bonus > 0 ? parts : '';
}
/**
 * The confetti of a basket: each piece's launch velocity (m/s, up from the rim, fanned 60 degrees
 * either side of vertical), spin (rad/s), size (m) and colour, drawn from a fixed generator so every
 * basket throws the same fan.
 */
const CONFETTI = (() => {
  let seed = 7;
  const next = (): number => {
    seed = (seed * 1103515245 + 12345) >>> 0;
    return seed / 2 ** 32;
  };
  const colors = [0xffd166, 0xff8a2a, 0xffffff, 0x4cc9f0, 0xf15bb5, 0x7ee787];
  return Array.from({ length: 40 }, (_, i) => {
    const a = Math.PI / 2 + (next() - 0.5) * ((2 * Math.PI) / 3),
      v = 3 + 4.5 * next();
    return {
      vx: v * Math.cos(a),
      vy: v * Math.sin(a),
      spin: (next() - 0.5) * 20,
      w: 0.12 + 0.1 * next(),
      h: 0.06 + 0.04 * next(),
      color: colors[i % colors.length]!,
    };
  });
})();
/**
 * Why the player's last throw cannot score, for the status row's reminder ('' when it may): released
 * above the line ('high'), or went up through the hoop from below ('below'). Kept until the next
 * throw, so the reminder stays on the row however long the ball flies (a rotating tip replaced it).
 */
let ruleHint: '' | 'high' | 'below' = '';
/** The ball of the player's last throw (0 before the first): only its rule breaks set ruleHint. */
let lastThrown = 0;

/**
 * Draws the hoop each frame: the backboard (a plain white board, on a bracket
 * from the box's side), the net under the rim (strings from the rim to its narrower bottom, crossed
 * into diamonds), the orange rim across the opening, the shot line at rim height (balls released
 * below it may score), the dots over the board counting the baskets before the hoop moves, and a
 * basket's pop.
 */
function drawHoop(): void {
  const cam = renderer.camera;
  const world = shell.world;
  const spot = hoopSpots(TALL)[hoopAt]!;
  const o = hoopOpening(spot);
  const { box } = layoutOf(TALL);
  hoopLayer.clear();
  // The shot line: short dashes at rim height, faint, with a label at the box's far side.
  const yLine = cam.toScreenY(o.y);
  const dash = 8;
  for (let x = cam.toScreenX(box.min[0]); x < cam.toScreenX(box.max[0]); x += 3 * dash)
    hoopLayer.moveTo(x, yLine).lineTo(Math.min(x + dash, cam.toScreenX(box.max[0])), yLine);
  hoopLayer.stroke({ width: 2, color: 0xff9f43, alpha: 0.45 });
  drawBackboard(spot);
  // The rim seen from a little above: an ellipse; its back half first, darker, behind the net.
  const rimX = cam.toScreenX((o.minX + o.maxX) / 2),
    rimRx = cam.toScreenLength((o.maxX - o.minX) / 2 + HOOP_RADIUS),
    rimRy = Math.max(3, 0.16 * rimRx);
  const rimArc = (from: number, to: number): void => {
    for (let k = 0; k <= 16; k++) {
      const a = from + ((to - from) * k) / 16;
      const px = rimX + rimRx * Math.cos(a),
        py = yLine + rimRy * Math.sin(a);
      if (k === 0) hoopLayer.moveTo(px, py);
      else hoopLayer.lineTo(px, py);
    }
  };
  const rimBack = Math.max(2, cam.toScreenLength(1.2 * HOOP_RADIUS));
  rimArc(Math.PI, 2 * Math.PI);
  hoopLayer.stroke({ width: rimBack, color: 0xa8440a, cap: 'round' });
  // The net: five strings from the rim to the narrower bottom, crossed by two rows of diagonals
  // (a diamond mesh), white, over the balls inside it.
  const L = o.minX,
    R = o.maxX,
    depth = NET.depth,
    narrow = NET.narrow;
  const at = (t: number, f: number): [number, number] => {
    // Point of the net at fraction t across (0 left, 1 right) and f down (0 rim, 1 bottom), m.
    const inset = narrow * f;
    return [L + inset + t * (R - L - 2 * inset), o.y - depth * f];
  };
  const line = (a: [number, number], b: [number, number]): void => {
    hoopLayer.moveTo(cam.toScreenX(a[0]), cam.toScreenY(a[1])).lineTo(cam.toScreenX(b[0]), cam.toScreenY(b[1]));
  };
  const cols = 6,
    rows = 3;
  for (let i = 0; i < cols; i++)
    for (let j = 0; j < rows; j++) {
      line(at(i / cols, j / rows), at((i + 1) / cols, (j + 1) / rows));
      line(at((i + 1) / cols, j / rows), at(i / cols, (j + 1) / rows));
    }
  line(at(0, 0), at(0, 1));
  line(at(1, 0), at(1, 1));
  line(at(0, 1), at(1, 1));
  hoopLayer.stroke({ width: 1.6, color: 0xf4f6fb, alpha: 0.85 });
  // The rim across the opening (drawn only: balls pass through it), thick orange with a dark edge.
  // Its front half over the net: a dark edge, the orange tube, a light line along its top (lit from above).
  const rimW = Math.max(4, cam.toScreenLength(2 * HOOP_RADIUS));
  rimArc(0, Math.PI);
  hoopLayer.stroke({ width: rimW + 2, color: 0x7a2e05, cap: 'round' });
  rimArc(0, Math.PI);
  hoopLayer.stroke({ width: rimW, color: 0xff7a1a, cap: 'round' });
  rimArc(0.15, Math.PI - 0.15);
  hoopLayer.stroke({ width: Math.max(1, rimW / 3), color: 0xffc08a, alpha: 0.8, cap: 'round' });
  // Over the backboard, a dot for each basket the hoop stays for (BASKETS_PER_HOOP): gold for those
  // scored here, hollow for those to go before it moves; none once the round is over (the end card
  // stands there).
  const pipR = Math.max(5.5, cam.toScreenLength(0.13)),
    pitch = 2.8 * pipR,
    boardX = cam.toScreenX(hoopSegments(spot)[0]![0]),
    pipY = cam.toScreenY(spot.y + BACKBOARD.above) - pipR - 6;
  for (let i = 0; i < (round.phase === 'over' ? 0 : round.perHoop); i++) {
    const px = boardX + (i - (round.perHoop - 1) / 2) * pitch;
    if (i < round.atHoop) hoopLayer.circle(px, pipY, pipR).fill({ color: GOLD_COLOR }).stroke({ width: 1.5, color: 0x3a1a02 });
    else hoopLayer.circle(px, pipY, pipR - 0.75).stroke({ width: 1.5, color: 0xf4f6fb, alpha: 0.8 });
  }
  drawCelebration(world.time - lastBasket.time);
  drawOutcome(world.time - outcome.time);
  updateStatus();
  placeTouchHint();
}

/**
 * A basket's celebration, `age` s (world time) after it (nothing outside [0, CELEBRATE_SECONDS)): the
 * hoop it went through glows gold and fades where it was, a gold ring widens from the rim, confetti
 * flies up from it and falls under gravity, a big "+1" and a word of praise rise over it, and, when
 * the hoop moved, a ring closes in on the new hoop so the eye finds it. All of it is kept inside
 * the court (courtMask; the words are moved in).
 */
function drawCelebration(age: number): void {
  confetti.clear();
  // A hoop that moved: a ring closing in on the new rim over its first second there, so the eye finds
  // it (0.3 s after the basket when it moves at once; once the last ball in flight is down otherwise).
  const moved = shell.world.time - Math.max(hoopMovedAt, lastBasket.time + 0.3);
  if (hoopMovedAt >= lastBasket.time && moved > 0 && moved < 1) {
    const cam = renderer.camera;
    const o = hoopOpening(hoopSpots(TALL)[hoopAt]!);
    confetti
      .circle(cam.toScreenX(0.5 * (o.minX + o.maxX)), cam.toScreenY(o.y), cam.toScreenLength(3.2 - 1.8 * moved))
      .stroke({ width: 3, color: 0xffffff, alpha: 0.8 * (1 - moved) });
  }
  const on = age >= 0 && age < CELEBRATE_SECONDS;
  popText.visible = praiseText.visible = on;
  if (!on) return;
  const cam = renderer.camera;
  const f = age / CELEBRATE_SECONDS;
  const { box } = layoutOf(TALL);
  const left = cam.toScreenX(box.min[0]),
    top = cam.toScreenY(box.max[1]);
  courtMask
    .clear()
    .rect(left, top, cam.toScreenX(box.max[0]) - left, cam.toScreenY(box.min[1]) - top)
    .fill({ color: 0xffffff });
  const x = cam.toScreenX(lastBasket.x),
    y = cam.toScreenY(lastBasket.y);
  // The old hoop glowing out over 0.8 s: its rim and net in gold.
  const glow = Math.max(0, 1 - age / 0.8);
  if (glow > 0) {
    const o = hoopOpening(hoopSpots(TALL)[lastBasket.spot]!);
    const rimW = Math.max(4, cam.toScreenLength(2 * HOOP_RADIUS));
    const L = o.minX,
      R = o.maxX,
      n = NET.narrow,
      b = o.y - NET.depth;
    confetti
      .moveTo(cam.toScreenX(L - HOOP_RADIUS), cam.toScreenY(o.y))
      .lineTo(cam.toScreenX(R + HOOP_RADIUS), cam.toScreenY(o.y))
      .stroke({ width: rimW + 6, color: 0xffd166, alpha: glow, cap: 'round' });
    confetti
      .moveTo(cam.toScreenX(L), cam.toScreenY(o.y))
      .lineTo(cam.toScreenX(L + n), cam.toScreenY(b))
      .lineTo(cam.toScreenX(R - n), cam.toScreenY(b))
      .lineTo(cam.toScreenX(R), cam.toScreenY(o.y))
      .stroke({ width: 3, color: 0xffd166, alpha: 0.8 * glow });
  }
  // A ring widening from the rim over the first half.
  if (f < 0.5) confetti.circle(x, y, cam.toScreenLength(0.6 + 3 * f)).stroke({ width: 4, color: 0xffd166, alpha: 1 - 2 * f });
  // The confetti: thrown up from the rim, falling under g, turning, fading over the last 40 %.
  const g = 9.81;
  const fade = Math.min(1, (1 - f) / 0.4);
  for (const c of CONFETTI) {
    const px = lastBasket.x + c.vx * age,
      py = lastBasket.y + c.vy * age - 0.5 * g * age * age;
    const a = c.spin * age,
      cos = Math.cos(a),
      sin = Math.sin(a);
    const hw = cam.toScreenLength(c.w) / 2,
      hh = cam.toScreenLength(c.h) / 2 + 0.5;
    const sx = cam.toScreenX(px),
      sy = cam.toScreenY(py);
    confetti
      .poly([
        sx - hw * cos + hh * sin,
        sy - hw * sin - hh * cos,
        sx + hw * cos + hh * sin,
        sy + hw * sin - hh * cos,
        sx + hw * cos - hh * sin,
        sy + hw * sin + hh * cos,
        sx - hw * cos - hh * sin,
        sy - hw * sin + hh * cos,
      ])
      .fill({ color: c.color, alpha: fade });
  }
  // "+1" and the praise rising over the rim, fading over the last 40 %.
  const rise = 30 + 50 * Math.min(1, 2 * f);
  const pop = age < 0.12 ? 0.6 + (0.4 * age) / 0.12 : 1;
  popText.text = `+${lastBasket.points}`;
  popText.scale.set(pop);
  praiseText.text = praiseFor(lastBasket);
  // Inside the court too: held down under its top, and in from its sides.
  const textY = Math.max(y - rise, top + 4 + praiseText.height + 2 + popText.height);
  const half = Math.max(popText.width, praiseText.width) / 2 + 4;
  const textX = Math.min(cam.toScreenX(box.max[0]) - half, Math.max(left + half, x));
  popText.position.set(textX, textY);
  popText.alpha = fade;
  praiseText.position.set(textX, textY - popText.height - 2);
  praiseText.alpha = fade;
}

/**
 * The backboard of the hoop at `spot`: a white board (its physics is the capsule of hoopSegments,
 * drawn as a board 0.16 m thick; plain: a red target square on it meant nothing in the game), and a steel bracket from
 * the board to the box's side wall behind it. The bracket has no body (balls that go over the board
 * fall behind it), so it is drawn dim on the wall under the balls (`bracketLayer`): a ball falling
 * behind the board passes in front of it, not through it.
 */
function drawBackboard(spot: HoopSpot): void {
  const cam = renderer.camera;
  const [bx, by0, , by1] = hoopSegments(spot)[0]!;
  const { box } = layoutOf(TALL);
  const wall = spot.side > 0 ? box.max[0] : box.min[0];
  // The bracket: two struts from the board's back to the side wall (if there is room between them).
  const back = bx + spot.side * HOOP_RADIUS;
  bracketLayer.clear();
  if (Math.abs(wall - back) > 0.05) {
    for (const y of [spot.y + 0.15, spot.y + 0.9]) {
      bracketLayer.moveTo(cam.toScreenX(back), cam.toScreenY(y)).lineTo(cam.toScreenX(wall), cam.toScreenY(y + 0.25));
    }
    bracketLayer.stroke({ width: Math.max(3, cam.toScreenLength(0.1)), color: 0x4a5670 });
  }
  const t = Math.max(6, cam.toScreenLength(2 * HOOP_RADIUS));
  const x = cam.toScreenX(bx),
    top = cam.toScreenY(by1),
    bottom = cam.toScreenY(by0);
  // Its soft shadow on the wall behind and below (the lamp is above), then the board: the glass's edge
  // seen side-on, a shaded face towards the wall, a lit front face, and a glint along it.
  const sh = Math.max(3, 0.6 * t);
  for (const [grow, a] of [
    [sh, 0.1],
    [sh / 2, 0.14],
  ] as const)
    bracketLayer.roundRect(x - t / 2 - grow / 2 + sh / 2, top + sh, t + grow, bottom - top + grow, t).fill({ color: 0x000000, alpha: a });
  const side = -spot.side;
  hoopLayer
    .roundRect(x - t / 2, top, t, bottom - top, t / 2)
    .fill(0xc9d0de)
    .stroke({ width: 1.5, color: 0x5e6678 });
  hoopLayer.roundRect(x + (side > 0 ? 0 : -t / 2) + 1, top + 2, t / 2 - 1, bottom - top - 4, t / 4).fill(0xf8faff);
  hoopLayer.rect(x + side * (t / 4) - 0.75, top + t / 2, 1.5, (bottom - top) * 0.45).fill({ color: 0xffffff, alpha: 0.9 });
}

// ---- The court: wall, floor, frame and ramps (redrawn when the camera changes) --------------------

/** The court under everything: drawn once per camera (the renderer's plain walls and box are hidden). */
const court = new Graphics({ label: 'court' });
app.stage.addChildAt(court, 0);
/** A label on the stand under the floor, when it is tall enough: it is room to pull a throw back into. */
const standLabel = new Text({
  text: '↓ room to pull back into ↓',
  style: { fontFamily: 'system-ui, sans-serif', fontSize: 14, fill: 0xb4bdcc },
});
standLabel.anchor.set(0.5);
standLabel.visible = false;
/** Whether the stand under the floor is tall enough for its label (drawCourt), and its top, CSS px on the canvas. */
let standRoom = false,
  standTop = 0;
app.stage.addChildAt(standLabel, 1);
/** The backboard's bracket, on the wall under the balls (drawBackboard). */
const bracketLayer = new Graphics({ label: 'hoop-bracket' });
app.stage.addChildAt(bracketLayer, 2);
/** The balls' soft shadows on the floor, under the balls (drawShadows). */
const shadowLayer = new Graphics({ label: 'ball-shadows' });
app.stage.addChildAt(shadowLayer, 3);
// Every ball (sprite or particle) shares one disc texture: redrawn once as a lit sphere.
shadeBallTexture(renderer.root);
// The renderer's walls (thin lines with end dots, the box's outline) look like a physics diagram:
// the court draws them as a frame and wooden ramps instead.
const plainWalls = renderer.root.children.find((c) => c.label === 'walls');
if (plainWalls) plainWalls.visible = false;
let courtVersion = -1;

/** Draws the court if the camera changed: the wall with panels, the wooden floor, the steel frame, the ramps. */
function drawCourt(): void {
  const cam = renderer.camera;
  if (cam.version === courtVersion) return;
  courtVersion = cam.version;
  const { box, segments } = layoutOf(TALL);
  const x0 = cam.toScreenX(box.min[0]),
    x1 = cam.toScreenX(box.max[0]),
    y0 = cam.toScreenY(box.max[1]),
    y1 = cam.toScreenY(box.min[1]);
  court.clear();
  // The wall (painted blocks lit from above) and the hardwood floor under the box, 0.35 m deep.
  const floor = Math.max(10, cam.toScreenLength(0.35));
  drawWall(court, { x0, x1, y0, y1 }, Math.max(8, cam.toScreenLength(0.5)));
  drawFloor(court, { x0, x1, y0, y1 }, floor, Math.max(20, cam.toScreenLength(1.3)));
  // The frame: dark steel round the box, a lighter inner edge.
  const w = Math.max(6, cam.toScreenLength(0.18));
  court.rect(x0 - w, y0 - w, x1 - x0 + 2 * w, w).fill(0x3a4252);
  court.rect(x0 - w, y0 - w, w, y1 - y0 + w + floor).fill(0x3a4252);
  court.rect(x1, y0 - w, w, y1 - y0 + w + floor).fill(0x3a4252);
  court.rect(x0, y0, x1 - x0, 2).fill(0x5b6577);
  // The stand under the floor, down to the canvas' bottom: on a tall page (anchorCourt) the spare height
  // under the box would read as an empty strip of page; here it is the steel base the court stands on.
  const base = y1 + floor;
  if (cam.height > base + 1) {
    court.rect(x0 - w, base, x1 - x0 + 2 * w, cam.height - base).fill(0x262c37);
    court.rect(x0 - w, base, x1 - x0 + 2 * w, 3).fill(0x5b6577);
  }
  standRoom = cam.height - base > 48;
  standTop = base;
  standLabel.visible = standRoom;
  standLabel.position.set((x0 + x1) / 2, (base + cam.height) / 2);
  // The ramps: wooden beams with a lighter top edge, round ends.
  for (const [ax, ay, bx, by] of segments) {
    const width = Math.max(6, cam.toScreenLength(2 * SEGMENT_RADIUS + 0.06));
    court
      .moveTo(cam.toScreenX(ax), cam.toScreenY(ay))
      .lineTo(cam.toScreenX(bx), cam.toScreenY(by))
      .stroke({ width, color: 0x8a5a32, cap: 'round' });
    court
      .moveTo(cam.toScreenX(ax), cam.toScreenY(ay) - width / 4)
      .lineTo(cam.toScreenX(bx), cam.toScreenY(by) - width / 4)
      .stroke({ width: width / 3, color: 0xc08a54, cap: 'round' });
  }
}

// ---- The player's balls: basketballs --------------------------------------------------------------

/** Seams over the player's balls (orange discs drawn by the renderer), above the balls. */
const seams = new Graphics({ label: 'basketball-seams' });
app.stage.addChild(seams);

/** Balls up to which each ball gets a glint and a shadow (beyond, a frame's extra shapes would cost too much). */
const SHADED_MAX = 400;

/** Draws each ball's glint (into `seams`) and its soft shadow on the floor (shadowLayer), at its drawn place. */
function drawShading(alpha: number, world: PhysicsWorld): void {
  shadowLayer.clear();
  if (handles.balls.length > SHADED_MAX) return;
  const cam = renderer.camera;
  const c = world.components,
    P = c.Position,
    O = c.PreviousPosition;
  const floorY = cam.toScreenY(layoutOf(TALL).box.min[1]);
  for (const e of handles.balls) {
    if (e === liftedShown) continue;
    const s = slotOf(e);
    const x = cam.toScreenX(O.x[s]! + (P.x[s]! - O.x[s]!) * alpha),
      y = cam.toScreenY(O.y[s]! + (P.y[s]! - O.y[s]!) * alpha);
    const r = cam.toScreenLength(c.Ball.radius[s]!);
    const fade = fading.get(e);
    const shown = fade ? Math.max(0, 1 - (world.time - fade.at) / FADE_SECONDS) : 1;
    drawShadow(shadowLayer, x, floorY, r, floorY - (y + r));
    drawGlint(seams, x, y, r, shown);
  }
}

/** Draws each player's ball's seams (a black outline, two crossing seams and two curved ones) at its drawn place, turned with it. */
function drawBasketballs(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  seams.clear();
  const c = world.components,
    P = c.Position,
    O = c.PreviousPosition;
  drawShading(alpha, world);
  const r = cam.toScreenLength(PLAYER_RADIUS);
  const w = Math.max(1, 0.09 * r);
  for (const e of basketballs) {
    const s = slotOf(e);
    const x = cam.toScreenX(O.x[s]! + (P.x[s]! - O.x[s]!) * alpha),
      y = cam.toScreenY(O.y[s]! + (P.y[s]! - O.y[s]!) * alpha);
    // Screen y is down: a turn of +a in the world is -a on screen.
    const a = -(c.Angle?.value[s] ?? 0);
    const cos = Math.cos(a),
      sin = Math.sin(a);
    const pt = (u: number, v: number): [number, number] => [x + r * (cos * u - sin * v), y + r * (sin * u + cos * v)];
    seams.moveTo(...pt(-0.97, 0)).lineTo(...pt(0.97, 0));
    seams.moveTo(...pt(0, -0.97)).lineTo(...pt(0, 0.97));
    for (const side of [-1, 1]) {
      seams.moveTo(...pt(side * 0.45, -0.88));
      for (let k = 1; k <= 8; k++) {
        const v = -0.88 + (1.76 * k) / 8;
        seams.lineTo(...pt(side * (0.45 - 0.2 * (1 - v * v)), v));
      }
    }
    // A fading ball's seams fade with it.
    const fade = fading.get(e);
    const shown = fade ? Math.max(0, 1 - (world.time - fade.at) / FADE_SECONDS) : 1;
    seams.stroke({ width: w, color: 0x1a0d05, alpha: 0.85 * shown });
    seams.circle(x, y, r - w / 2).stroke({ width: w, color: 0x5a2a08, alpha: 0.7 * shown });
  }
  // The gold ball: a pulsing halo and a glint, so the eye finds it in the heap.
  if (goldBall !== 0 && handles.balls.includes(goldBall) && liftedShown !== goldBall) {
    const s = slotOf(goldBall);
    const x = cam.toScreenX(O.x[s]! + (P.x[s]! - O.x[s]!) * alpha),
      y = cam.toScreenY(O.y[s]! + (P.y[s]! - O.y[s]!) * alpha);
    const gr = cam.toScreenLength(c.Ball.radius[s]!);
    const pulse = 0.5 + 0.5 * Math.sin(performance.now() / 180);
    seams.circle(x, y, gr + 3 + 4 * pulse).stroke({ width: 3, color: GOLD_COLOR, alpha: 0.45 + 0.45 * pulse });
    seams.circle(x - 0.35 * gr, y - 0.35 * gr, Math.max(2, 0.18 * gr)).fill({ color: 0xffffff, alpha: 0.85 });
  }
}

const status = createStatusRow({ name: 'hoop' });
const touch = TOUCH_UI;
// On a phone game-kit's touch hint card sits over the bottom of the stage: the floor, where the balls
// pile and a throw starts; under the box's top it covered the hoop and the arcs to it. Here it goes
// on the court's stand under the floor, in smaller type (one line a gesture: TOUCH_UI's controls),
// so the whole box shows while it does (it fades at the first touch anyway; the stand's own label
// waits under it). Placed each frame while it shows, as the status row above the box may still move
// the canvas.
const touchHint = document.querySelector<HTMLElement>('[data-hud="touch-hint"]');
if (touchHint) {
  touchHint.style.fontSize = '13px';
  touchHint.style.lineHeight = '1.35';
  touchHint.style.padding = '6px 10px';
}
/** Keeps the touch hint card in the middle of the stand under the floor, or its foot 4 px over the canvas's foot if the stand is lower than the card (while it is on the page). */
function placeTouchHint(): void {
  const shown = !!touchHint?.isConnected && !!touchHint.offsetParent;
  // Not under the Play-again button when the round is over (it floats over the stand then), nor
  // while a pull is under way: the pull's band and the finger's power ring are drawn there.
  standLabel.visible = standRoom && !shown && round.phase !== 'over' && !(pointerId !== -1 && dragged);
  if (!shown) return;
  const top = canvas.getBoundingClientRect().top - touchHint!.offsetParent!.getBoundingClientRect().top;
  const h = touchHint!.offsetHeight,
    foot = renderer.camera.height;
  const y = Math.min(foot - 4 - h, 0.5 * (standTop + foot) - 0.5 * h);
  touchHint!.style.bottom = 'auto';
  touchHint!.style.top = `${Math.round(top + y)}px`;
}

/**
 * Room to pull back into under the wide box's floor on a desktop, m: a pull from a heap ball lying on the
 * floor goes down, and with the floor near the window's bottom the mouse met the window's edge some 65 px
 * under the lowest ball (a maximized window's mouse stops at the screen's edge). This strip (the
 * court's stand) gives it about 160 px at 1280 x 800, for a box 16 % smaller. The phone's box is
 * narrower than its screen is tall and leaves a strip of its own.
 */
const DESK_PULL_ROOM = 2.5;

/**
 * Frames the box at the top of the canvas (the camera's padding under the status row) with spare height
 * under the floor to pull back into. On a tall page the box is narrower than the canvas is tall, so a
 * centred fit left a band above and below it, the band above between the status row and the box; on a
 * wide one the view reaches DESK_PULL_ROOM under the floor (centred across the canvas).
 * The camera's view is a rectangle as wide as the box, ending at its top and reaching down as far as
 * the canvas's aspect allows (at least DESK_PULL_ROOM under the floor on a wide page); refitted only
 * when the canvas size changes the wanted rectangle.
 */
function anchorCourt(): void {
  const cam = renderer.camera;
  const { box } = layoutOf(TALL);
  const w = box.max[0] - box.min[0],
    h = box.max[1] - box.min[1] + (TALL ? 0 : DESK_PULL_ROOM);
  const pad = cam.padding;
  if (cam.width <= 2 * pad || cam.height <= 2 * pad) return;
  // The scale a centred fit of the box (and the strip) gives, and the height in m the canvas shows at that scale.
  const ppm = Math.min((cam.width - 2 * pad) / w, (cam.height - 2 * pad) / h);
  const shown = Math.max(h, (cam.height - 2 * pad) / ppm);
  const minY = box.max[1] - shown;
  const v = cam.view;
  if (v && v.minX === box.min[0] && v.maxX === box.max[0] && v.maxY === box.max[1] && Math.abs(v.minY - minY) < 1e-9) return;
  cam.fit({ minX: box.min[0], minY, maxX: box.max[0], maxY: box.max[1] });
}

/**
 * The big Play-again button when time is up: over the bottom of the stage, on the stand under the
 * box's floor, clear of the ramps and the hoop at the top of the box and of the end card over its middle.
 */
const setAction = createActionButton('Play again ▶', () => shell.reset());

// The numbers line bumps (grows and turns gold for a moment) when a basket scores. Each line of the
// row is one line, whatever its text (a long one is cut with an ellipsis; the phone's texts are short
// enough not to be): a hint that wrapped to two lines mid-drag moved the box down under the finger.
const bumpStyle = document.createElement('style');
bumpStyle.textContent = `@keyframes bb-bump { 0% { transform: scale(1); color: inherit; } 20% { transform: scale(var(--bb-bump-scale, 1.3)); color: #ffd166; }
  70% { color: #ffd166; } 100% { transform: scale(1); color: inherit; } }
[data-hud="hoop"] [data-hud="numbers"].bb-bump { animation: bb-bump 0.9s ease-out; }
[data-hud="hoop"] > div { white-space: nowrap; overflow: hidden; text-overflow: ellipsis; }
[data-hud="hoop"] [data-hud="numbers"].bb-hurry { color: #ff6b6b; }`;
document.head.append(bumpStyle);
/** How much the numbers line grows at most when it bumps (bumpScore). */
const BUMP_SCALE = 1.3;

/**
 * Bumps the status row's numbers line (a basket scored), grown by at most BUMP_SCALE and no more
 * than keeps its text inside the line's box (on a phone the text nearly fills the width).
 */
function bumpScore(): void {
  const el = status.numbers;
  const box = el.getBoundingClientRect();
  const range = document.createRange();
  range.selectNodeContents(el);
  const text = range.getBoundingClientRect();
  // The grow is about the box's centre: each text edge moves out by the scale times its distance from it.
  const cx = box.left + box.width / 2;
  let scale = BUMP_SCALE;
  if (text.width > 0) {
    if (text.left < cx) scale = Math.min(scale, (cx - box.left - 2) / (cx - text.left));
    if (text.right > cx) scale = Math.min(scale, (box.right - 2 - cx) / (text.right - cx));
  }
  el.style.setProperty('--bb-bump-scale', Math.max(1, scale).toFixed(3));
  el.classList.remove('bb-bump');
  // Reading the layout restarts the animation when the class comes back.
  void el.offsetWidth;
  el.classList.add('bb-bump');
}

/** How long each of the taking-turns hints shows, s of game time (updateStatus, playSeconds): long enough to read. */
const TEACH_SECONDS = 6;
/** Which taking-turns hint shows (0-3) and since when (playSeconds, s). */
const teachTurn = { turn: 0, at: 0 };

/** Writes the status row (goal, baskets, time, best, a hint) when it changed, and shows Play again when time is up. */
function updateStatus(): void {
  const secs = Math.ceil(round.timeLeft);
  const over = round.phase === 'over';
  const cheering = shell.world.time - lastBasket.time < CELEBRATE_SECONDS && lastBasket.score === round.score;
  const goal = over
    ? `Time! ${plural(round.points, 'point', 'points')}${beatBest() ? ' — new best!' : ''}`
    : lastCall.aiming
      ? 'Time! Let go: this last throw still counts'
      : lastCall.ball !== 0
        ? 'Last throw…'
        : cheering
          ? `${praiseFor(lastBasket)}${/\d$/.test(praiseFor(lastBasket)) ? ' =' : ''} +${lastBasket.points} · ${lastBasket.score === 1 ? 'the clock runs' : `+${TIME_PER_BASKET} s`}${lastBasket.moved ? (TALL ? ' · new hoop' : hoopAt !== round.spot ? ' · the hoop moves next' : ' · the hoop moved') : ''}`
          : round.phase === 'ready'
            ? `Score once to start the ${round.seconds} s clock`
            : round.streak > 0
              ? `${round.streak} in a row: the next basket scores ×${streakMultiplier(round.streak)}`
              : hoopAt !== round.spot
                ? 'The hoop moves once your ball is down'
                : `${plural(round.perHoop - round.atHoop, 'basket', 'baskets')} here, then the hoop moves`;
  const numbers = `Points ${round.points} · ×${streakMultiplier(round.streak)} · Time ${secs} s · Best ${best}`;
  // The last throw's rule break (ruleHint) stays until the next throw; otherwise, while playing, the
  // hint takes turns (TEACH_SECONDS of game time each, held while a press is down so it can be read
  // while aiming) between the heap's balls, the streak and the bonus shots.
  const now = playSeconds;
  if (pointerId !== -1) teachTurn.at = Math.max(teachTurn.at, now - TEACH_SECONDS);
  else if (now - teachTurn.at >= TEACH_SECONDS) {
    teachTurn.turn = (teachTurn.turn + 1) % 4;
    teachTurn.at = now;
  }
  const turn = teachTurn.turn;
  const teach =
    turn === 3
      ? `Each basket +${TIME_PER_BASKET} s · the hoop moves every ${plural(round.perHoop, 'basket', 'baskets')}`
      : turn === 0
        ? touch
          ? `Pull a heap ball back to throw it: ${BALL_POINTS.heap} points, gold ${BALL_POINTS.gold}`
          : `Press on a heap ball and pull back to throw it: ${BALL_POINTS.heap} points, the gold one ${BALL_POINTS.gold}`
        : turn === 1
          ? 'Baskets in a row multiply, up to ×4; a miss ends it'
          : touch
            ? `Swish +${SHOT_BONUS.swish} · off a wall or ramp +${SHOT_BONUS.trick}`
            : `Bonus: a swish (touching nothing) +${SHOT_BONUS.swish}, a trick shot off a wall or ramp +${SHOT_BONUS.trick}`;
  const hint = over
    ? `${touch ? 'Tap' : 'R or'} Play again for a new round`
    : playSeconds - missAt < MISS_SHOWN
      ? missSaid
      : performance.now() - blockedAt < HOOP_TAP_SHOWN
        ? `Blocked: not thrown · pick the top ball${touch ? '' : ' or hold one still 1 s to carry it'}`
        : performance.now() - hoopTapAt < HOOP_TAP_SHOWN
          ? 'Throw into the hoop from below the orange line'
          : performance.now() - standTapAt < HOOP_TAP_SHOWN
            ? 'Press here and pull back to throw the ball above'
            : ruleHint === 'high'
              ? 'Too high: throw from below the orange line to score'
              : ruleHint === 'below'
                ? `Up through the net does not count${touch ? '' : ': drop it in from above'}`
                : round.phase === 'ready' && round.shots === 0
                  ? // One line on a phone too (a second line there moved the box down the moment it changed), so the phone's is shorter.
                    touch
                    ? 'Throw through the hoop from below the orange line'
                    : 'Press, drag back and let go to throw through the hoop from below the orange line'
                  : teach;
  if (status.set({ goal, numbers, hint }, over)) setAction(over);
  // The last HURRY_SECONDS: the numbers line turns red.
  status.numbers.classList.toggle('bb-hurry', round.phase === 'playing' && round.timeLeft <= HURRY_SECONDS);
  drawCountdown();
  drawEndCard(over);
}

// ---- The last seconds: a red clock, a big countdown and a tick -------------------------------------

/** The numbers line (points, time) turns red for the last this many seconds of the clock. */
const HURRY_SECONDS = 10;
/** A big countdown over the box, and a tick each second, for the last this many seconds. */
const COUNTDOWN_SECONDS = 5;
const countdownText = new Text({
  text: '',
  style: { fontFamily: 'system-ui, sans-serif', fontSize: 96, fontWeight: '800', fill: 0xff6b6b, stroke: { color: 0x0b0f16, width: 8 } },
});
countdownText.anchor.set(0.5);
countdownText.visible = false;
app.stage.addChild(countdownText);
/** Sets the countdown's text and font size, px, when they change (a change redraws the text). */
function setCountdown(text: string, size: number): void {
  if (countdownText.text !== text) countdownText.text = text;
  if (countdownText.style.fontSize !== size) countdownText.style.fontSize = size;
}
/** The countdown's last second shown (for the tick once a second); 0 when none. */
let countdownShown = 0;

/**
 * The last COUNTDOWN_SECONDS of a round: each second's number big in the box's upper part, on the side
 * away from the hoop (the middle on a phone),
 * shrinking and fading through its second, with a tick; at 0 with the last throw under way (lastCall),
 * "Last throw!" instead.
 */
function drawCountdown(): void {
  const playing = round.phase === 'playing';
  const secs = Math.ceil(round.timeLeft);
  const last = lastCall.aiming || lastCall.ball !== 0;
  countdownText.visible = playing && (last || (secs >= 1 && secs <= COUNTDOWN_SECONDS));
  if (!countdownText.visible) {
    countdownShown = 0;
    return;
  }
  const cam = renderer.camera;
  const { box } = layoutOf(TALL);
  // Over the half of the box away from the hoop, so it never covers the hoop being aimed at.
  const o = hoopOpening(hoopSpots(TALL)[hoopAt]!);
  const mid = 0.5 * (box.min[0] + box.max[0]),
    across = 0.5 * (o.minX + o.maxX) > mid ? 0.3 : 0.7;
  const x = box.min[0] + across * (box.max[0] - box.min[0]);
  countdownText.position.set(cam.toScreenX(TALL ? mid : x), cam.toScreenY(box.max[1] - 0.3 * (box.max[1] - box.min[1])));
  if (last) {
    setCountdown('Last throw!', TALL ? 44 : 56);
    countdownText.alpha = 0.8;
    countdownText.scale.set(1);
    return;
  }
  setCountdown(String(secs), TALL ? 72 : 96);
  const f = secs - round.timeLeft;
  countdownText.alpha = 0.75 * (1 - 0.6 * f);
  countdownText.scale.set(1.15 - 0.3 * f);
  if (secs !== countdownShown) {
    countdownShown = secs;
    sound.chime(secs === 1 ? 988 : 784, 0.08);
  }
}

// ---- The end of a round: a card with the points and what made them ------------------------------

// On a phone the box is about 340 px wide: the big line ("263 points") in 42 px type keeps a margin
// inside the card's sides (in 56 px it filled the card edge to edge).
const endCard = createResultCard(app.stage, { label: 'end-card', bigSize: TALL ? 42 : 56 });

/** Gap, CSS px, between the end card and the pause overlay's words moved off it. */
const PAUSE_WORDS_GAP = 16;
/**
 * Puts the pause overlay's words (drawn in two lines in the middle of the view) on one line in a
 * banner just inside the box's top, clear of the hoops (every rim 3 m or more under the top); with
 * the end card up (the Play-again button at the box's top), off the card: under it if they fit above
 * the view's foot, else over it, else not at all (never over the card's lines).
 */
function placePauseWords(): void {
  const card = endCard.box,
    words = pause.words;
  if (words.text.includes('\n')) words.text = words.text.replace('\n', ' · ');
  const half = words.height / 2;
  words.visible = true;
  if (!endCard.container.visible) {
    const { box } = layoutOf(TALL);
    words.position.y = Math.max(half + 4, renderer.camera.toScreenY(box.max[1]) + half + 6);
    return;
  }
  const below = card.y + card.height + PAUSE_WORDS_GAP + half;
  const above = card.y - PAUSE_WORDS_GAP - half;
  if (below + half <= app.screen.height) words.position.y = below;
  else if (above - half >= 0) words.position.y = above;
  // No room off the card (a phone's): the dimmed view says it is paused without them.
  else words.visible = false;
}

/**
 * Shows the end card when time is up (`over`), centred in the box under the Play-again button: the
 * round's points, its baskets, longest streak and throws that went in, the best, and a tip for the
 * next round.
 */
function drawEndCard(over: boolean): void {
  if (!over) {
    endCard.hide();
    return;
  }
  const cam = renderer.camera;
  const { box } = layoutOf(TALL);
  const newBest = beatBest();
  // A first scoring round has no best to beat: it is said plainly, not cheered as a record. A line
  // of its own, short enough not to wrap on a phone.
  const bestLine = newBest ? `Your old best was ${bestBefore}` : bestBefore === 0 && round.points > 0 ? 'Now beat that!' : `Best ${best}`;
  const tip =
    round.bestStreak < 3
      ? 'Tip: baskets in a row multiply points'
      : round.tricks === 0
        ? `Tip: a trick shot off a wall or a ramp adds +${SHOT_BONUS.trick}`
        : round.score < 6
          ? `Tip: the gold ball is worth ${BALL_POINTS.gold}`
          : `Tip: each basket after the first gives ${TIME_PER_BASKET} s back`;
  const bonus =
    round.swishes + round.tricks > 0
      ? [
          `${plural(round.swishes, 'swish', 'swishes')} (+${SHOT_BONUS.swish} each) · ${plural(round.tricks, 'trick shot', 'trick shots')} (+${SHOT_BONUS.trick} each)`,
        ]
      : [];
  const room = cam.toScreenX(box.max[0]) - cam.toScreenX(box.min[0]) - 24;
  // Under the Play-again button at the box's top: the middle of the box's upper half.
  endCard.show(
    {
      title: newBest ? 'Time! A new best' : 'Time!',
      big: plural(round.points, 'point', 'points'),
      // The result first (against the best), then what made it, then a tip; Play again is under the card.
      lines: [
        bestLine,
        `${plural(round.score, 'basket', 'baskets')} from ${plural(round.allShots, 'throw', 'throws')}`,
        `Longest streak ${round.bestStreak}`,
        ...bonus,
        tip,
      ],
    },
    {
      cx: cam.toScreenX(0.5 * (box.min[0] + box.max[0])),
      top: cam.toScreenY(box.max[1] - 0.28 * (box.max[1] - box.min[1])),
      maxWidth: room,
      wrapWidth: room - 32,
    },
  );
}

// ---- Test and console hooks on window.game ---------------------------------------------------

shell.expose({
  /** Whether the pause overlay (the dimmed play area with "Paused") shows, its words, and their box, CSS px [x, y, width, height] (all 0 when the words are hidden). */
  pauseOverlay: (): { visible: boolean; text: string; words: number[] } => {
    const b = pause.words.visible ? pause.words.getBounds() : { x: 0, y: 0, width: 0, height: 0 };
    return { visible: pause.visible, text: pause.text, words: [b.x, b.y, b.width, b.height] };
  },
  /** The end card's box, CSS px [x, y, width, height], and whether it shows. */
  endCard: (): { visible: boolean; box: number[] } => {
    const b = endCard.box;
    return { visible: endCard.container.visible, box: [b.x, b.y, b.width, b.height] };
  },
  params,
  panel,
  /** The pointer's mouse-joint drag: `joint` (0 when nothing is held) and `body`. */
  drag,
  /** Entity ids of the balls, oldest first (a copy). */
  ballIds: (): number[] => handles.balls.slice(),
  /** Entity ids of the crates dropped with X, oldest first (a copy). */
  crateIds: (): number[] => crates.slice(),
  /** The ball a press at (x, y), m, would throw now (0: a new basketball or nothing), a finger's when `finger`. */
  pickAt: (x: number, y: number, finger = false): number => {
    const { box } = layoutOf(TALL);
    return pressPick(...pressInBox(x, y, box.min, box.max), finger).onBall;
  },
  /** Ball positions, m, flat [x0, y0, x1, y1, ...] in `ballIds` order. */
  positions: (): number[] => {
    const P = shell.world.components.Position;
    const out: number[] = [];
    for (const e of handles.balls) out.push(P.x[slotOf(e)]!, P.y[slotOf(e)]!);
    return out;
  },
  /** Adds a ball at (x, y) m with velocity (vx, vy) m/s; returns its id. */
  spawn: (x: number, y: number, vx = 0, vy = 0): number => spawnBall(shell.world, handles, x, y, vx, vy),
  /** The hoop game's round (a copy): phase, score, timeLeft (s), spot index, shots. */
  round: (): HoopRound => ({ ...round }),
  /** The best score kept (localStorage). */
  best: (): number => best,
  /** The heap's gold ball (0 when none). */
  goldBall: (): number => goldBall,
  /**
   * Throws ball `eid` of the scene with velocity (vx, vy) m/s, as a pull that starts on it does: from
   * where it is, or from the top of the heap over it if it is buried. @returns whether it was thrown
   * (false: buried with no room above it).
   */
  throwBall: (eid: number, vx: number, vy: number): boolean => throwBall(eid, vx, vy),
  /** The ball marked as the one to throw (0: none; markThrowable) and the label over it ('' when none shows, 'drag me' before the round's first throw). */
  throwable: (): { ball: number; label: string } => ({ ball: marked.ball, label: markLabel.visible ? markLabel.text : '' }),
  /** The hoop's opening where it stands now (it follows the round's spot once no thrown ball is in flight): rim height y and the x range, m. */
  hoop: () => hoopOpening(hoopSpots(TALL)[hoopAt]!),
  /** A player's ball at (x, y) m with velocity (vx, vy) m/s, as a throw releases it (counts for the hoop). @returns its id. */
  shoot: (x: number, y: number, vx = 0, vy = 0): number => shoot(x, y, vx, vy),
  /**
   * The whole predicted flight of a throw of ball `eid` with velocity (vx, vy), m/s (2.5 s, two
   * bounces; a pull starting on it shows the start of it), from the top of the heap over it if it is
   * buried (liftSpot): its points, m (flat x, y pairs), ending at a ball in its way. @throws RangeError if `eid` is not a ball of the scene.
   */
  aimFrom: (eid: number, vx: number, vy: number): number[] => {
    if (!handles.balls.includes(eid)) throw new RangeError(`aimFrom: ${eid} is not a ball of the scene`);
    const c = shell.world.components,
      s = slotOf(eid);
    const [x, y] = liftSpot(eid) ?? [c.Position.x[s]!, c.Position.y[s]!];
    return arcOf({ x, y, vx, vy, radius: c.Ball.radius[s]!, mass: c.Mass.value[s]! }, eid);
  },
  /**
   * The dotted arc drawn while pulling a throw: its points, m (flat x, y pairs), or [] when not pulling
   * or in the cancel zone: the flight over its top and down to 0.4 m over the rim's height (at least
   * 1.2 s of it, 1.5 times that in the tall box; at most 2.5 s;
   * to 0.2 s past its top if that is under the rim), up to its first touch of a ball, a wall, a ramp,
   * the box's top or the hoop.
   */
  aimPath: (): number[] => aimPath(),
  /** The aiming arc as drawn: its first part only (preview.ts shortArc) unless help is on (aimHelp); points, m, or [] as aimPath. */
  aimShown: (): number[] => (aimHelp(missesInARow, aimHelpAlways) ? aimPath() : shortArc(aimPath(), hoopSpots(TALL)[hoopAt]!.x)),
  /** Turns the aiming arc's help on or off for good (its whole flight and verdict: preview.ts); @returns whether help shows now (also after 3 misses in a row). */
  aimHelp: (on?: boolean): boolean => {
    if (on !== undefined) aimHelpAlways = on;
    return aimHelp(missesInARow, aimHelpAlways);
  },
  /**
   * Where and why the aiming arc being pulled is cut short (a ball, a ramp, the backboard, the rim or the net; m),
   * with the words shown beside its cross ('' when the gauge's label says it): null when not pulling
   * or when the arc runs its length.
   */
  aimCut: (): { kind: string; x: number; y: number; words: string } | null => {
    const path = aimPath();
    const cut = path.length > 0 ? arcCut(currentThrow(), path, pressBall) : null;
    return cut && { kind: cut.kind, x: cut.x, y: cut.y, words: cut.soon ? '' : cutWords(cut.kind) };
  },
  /** Which of the status row's taking-turns hints shows (0-3): each TEACH_SECONDS (6 s of game time), held while a press is down. */
  hintTurn: (): number => teachTurn.turn,
  /** Bumps the status row's numbers line as a basket does (grows it, kept inside the row's width). */
  bumpScore: (): void => bumpScore(),
  /** The whole predicted flight of the throw being pulled (2.5 s, two bounces; the arc shows its start): points, m, or [] as aimPath. */
  aimFlight: (): number[] => aimFlight(),
  /** The least of a throw's flight the aiming arc shows, s (1.2, in the warm-up and after the first basket alike; 1.5 times that in the tall box). */
  aimSeconds: (): number => aimSeconds(),
  /** The round's last throw (the clock ran out during its pull): whether its pull is under way, and its ball (0 when none). */
  lastThrow: () => ({ ...lastCall }),
  /** The big countdown over the box ('' when none shows): the last seconds, or 'Last throw!'. */
  countdown: (): string => (countdownText.visible ? countdownText.text : ''),
  /** Whether a press is under way (pressed and not yet released, cancelled or ended by the round's end). */
  aiming: (): boolean => pointerId !== -1,
  /** The words said on the court of the last throw that was no basket ('' when none shows; sayOnCourt), e.g. 'Missed: short of the rim'. */
  courtWords: (): string => (outcomeText.visible ? outcomeText.text : ''),
  /** The label over the press or the carried ball ('' when none shows), e.g. 'release here to cancel'. */
  aimLabel: (): string => (holdLabel.visible ? holdLabel.text : ''),
  /** The full-speed pull of the current (or last) press, CSS px (fullPull, or fingerFullPull for a finger, when it began). */
  fullPull: (): number => fullPullNow,
  /** The status row's text (goal, numbers, hint). */
  statusText: (): string => status.element.innerText,
  /** Removes ball `eid`. @throws RangeError if it is not a ball of the scene. */
  remove: (eid: number): void => removeBall(shell.world, handles, eid),
  /**
   * Test hook: the world's whole physics state (physics `snapshot`), to put back with `restoreWorld`
   * after `reset` (a new round of the same scene), which then steps on bit for bit as the world did
   * from where it was taken. Only the world: the round and the throws in flight are the new round's.
   */
  saveWorld: (): WorldSnapshot => snapshot(shell.world),
  /**
   * Test hook: puts back a state taken by `saveWorld` into the current world (physics `restore`).
   * @throws RangeError if `snap` is not such a snapshot or comes from a world of another size.
   */
  restoreWorld: (snap: WorldSnapshot): void => restore(shell.world, snap),
});
