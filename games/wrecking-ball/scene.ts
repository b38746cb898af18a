/**
 * The wrecking-ball scene: a tower crane whose hook (a kinematic trolley) the player steers, a chain of
 * capsule links on ball-and-socket joints with a heavy steel ball at its end, and seeded levels of
 * towers, walls and plank stacks of boxes standing around the crane. A pure builder (no DOM, no
 * three.js), shared by the page and its tests.
 *
 * The crane: the jib turns about the vertical axis at the origin (slew angle, rad), the trolley runs
 * along it (radius, m) and the hoist sets its height (m). The controls set targets; `craneSystem`
 * moves the trolley toward them at limited speeds by setting its velocity each substep, so the ball
 * swings behind it like a real pendulum (period 2 pi sqrt(L / g) for a chain of length L).
 *
 * Scoring (`scorePieces`): a piece has fallen once its centre is FALL_DROP below where it stood, its
 * up axis has tipped past TIP_ANGLE or it has been knocked KNOCK_DISTANCE along the ground; each fallen piece scores 10 points plus 10 per metre it
 * stood above the ground. A level is cleared when as many pieces have fallen as CLEAR_FRACTION of
 * those that stood above the ground (`clearTarget`).
 */
import {
  addBallJoint3D,
  addBody,
  addDistanceJoint3D,
  addPlane,
  addShape3D,
  addSystem,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  setDrag,
} from '@bitphysics/physics';

/** Height of the jib, m. */
export const JIB_HEIGHT = 11.5;
/** Smallest and largest trolley radius on the jib, m. */
export const RADIUS_RANGE: readonly [number, number] = [3, 11];
/** Lowest and highest hook height, m. */
export const HOOK_RANGE: readonly [number, number] = [5.7, 10.5];
/** Largest slew rate, rad/s; trolley speed along the jib and hoist speed, m/s. */
export const SLEW_RATE = 0.7;
export const TROLLEY_SPEED = 3.5;
export const HOIST_SPEED = 2;
/** Chain: links, each a capsule of this radius and straight half length, m. */
export const CHAIN_LINKS = 8;
export const LINK_RADIUS = 0.07;
export const LINK_HALF = 0.22;
/** Time constant, s, with which the ball's swing decays (see buildWreckingBall). */
export const SWAY_DAMPING_TIME = 4;
/** The ball: radius, m, and density, kg/m^3 (steel). */
export const BALL_RADIUS = 0.55;
export const BALL_DENSITY = 7800;
/** Density of the pieces, kg/m^3 (light wood). */
export const PIECE_DENSITY = 450;
/** A piece has fallen when its centre is this far below its start, m, or it has tipped past TIP_ANGLE (rad). */
export const FALL_DROP = 0.4;
/**
 * A piece has also fallen when its centre has moved this far across the ground from where it stood,
 * m: a bottom brick or plank swept away cannot drop, and counted as standing it made a level's
 * clearing share unreachable.
 */
export const KNOCK_DISTANCE = 1;
export const TIP_ANGLE = Math.PI / 3;
/**
 * Fraction of a level's raised pieces (those not standing on the ground) whose count must fall to
 * clear it. The bottom row (a wall's lowest bricks, a crib's lowest logs, a tower's base) rarely falls,
 * tips or slides a metre however it is hit, so counted against all pieces a flattened level could
 * still fall short of the share needed.
 */
export const CLEAR_FRACTION = 0.7;

/** How many pieces must fall to clear a level: CLEAR_FRACTION of those that stood above the ground, rounded up. */
export function clearTarget(pieces: readonly Piece[]): number {
  let raised = 0;
  for (const p of pieces) if (p.y0 - p.half[p.upAxis]! > 0.01) raised++;
  return Math.ceil(CLEAR_FRACTION * raised);
}
/** Number of distinct seeded level layouts before they repeat with more pieces. */
export const LEVELS = 5;

/** What the crane's controls ask for (the page writes these; `craneSystem` reads them each substep). */
export interface CraneControls {
  /** Slew: -1, 0 or 1 (turn clockwise seen from above, hold, counter-clockwise), or null to chase `slewTarget`. */
  slew: number;
  /** Trolley: -1 in, 0, 1 out. */
  trolley: number;
  /** Hoist: -1 down, 0, 1 up. */
  hoist: number;
  /**
   * Whether the anti-sway control is on (the player holds it): while on, and no `goal` or `moves`
   * drive the crane, the crane adds to the slew and trolley rates asked for the rates that carry the
   * hook toward the point over the ball (STEADY_GAIN times the ball's offset from under the hook), so
   * the swing dies out in a couple of seconds: the hook catches the ball as a crane operator does.
   */
  steady: boolean;
  /**
   * A point to drive the hook to (m, x and z), or null: set by a click on the ground. The crane runs
   * there at full speed and stops at once, so the lagging ball swings on through the point.
   */
  goal: [number, number] | null;
  /**
   * Timed moves (a swing at a target, see `aimAt`), done in order before `goal`: each takes the crane
   * from where it is to (angle rad, radius m, height m) at a constant rate over `duration` s.
   */
  moves: CraneMove[];
  /**
   * Swings taken on this level: counted by `craneSystem` when it begins a move marked `release` (the
   * ball let go into its run at a target), and by the page for each drag of the ball let go. A swing
   * re-aimed during its wind-up (`aimAt` again) has not been taken and is not counted.
   */
  released: number;
}

/** One timed move of the crane (see `CraneControls.moves`). */
export interface CraneMove {
  angle: number;
  radius: number;
  height: number;
  /** Seconds the move takes, > 0. */
  duration: number;
  /** Seconds of it done (the system counts it). */
  elapsed: number;
  /** Whether it is part of a swing's run at its target (after the wind-up; see `aimAt`). */
  run?: boolean;
  /** Whether beginning it releases the ball into its run: the first move of a run (counted in `released`). */
  release?: boolean;
}

/** The crane's state: where the jib points and where the trolley is on it. */
export interface CraneState {
  /** Slew angle, rad (0 along +x, counter-clockwise seen from above, i.e. about +y). */
  angle: number;
  /** Trolley radius, m. */
  radius: number;
  /** Hook height, m. */
  height: number;
}

/** One piece of a level: its body and where it started. */
export interface Piece {
  body: number;
  /** Start height of its centre, m. */
  y0: number;
  /** Start place of its centre across the ground, m. */
  x0: number;
  z0: number;
  /** Half extents, m, along the box's own axes: its x and z turned by `yaw` about the vertical, its y up. */
  half: [number, number, number];
  /** How the box was turned about the vertical when built, rad. */
  yaw: number;
  /** What it belongs to. */
  kind: 'tower' | 'wall' | 'planks';
  /** Score it gives when it falls. */
  points: number;
  /** Whether it has fallen (set by `scorePieces`). */
  fallen: boolean;
  /** The body axis (0 x, 1 y, 2 z of its principal frame) that pointed up at the start. */
  upAxis: number;
}

/** What `buildWreckingBall` returns. */
export interface WreckingBallHandles {
  /** The kinematic trolley (hook) the chain hangs from. */
  trolley: number;
  /** Chain links, top first. */
  links: number[];
  /** The ball. */
  ball: number;
  /** The pieces of the level. */
  pieces: Piece[];
  /** The crane's state (mutated by `craneSystem`). */
  crane: CraneState;
  /** The controls (mutated by the page). */
  controls: CraneControls;
  /** The level built (1-based) and its seed. */
  level: number;
  seed: number;
  /** The static crane mast's body. */
  mast: number;
}

/** Options of `buildWreckingBall`. */
export interface WreckingBallOptions {
  /** Level, integer >= 1. Default 1. */
  level?: number;
  /** Seed of the layouts, integer. Default 1. */
  seed?: number;
  /** Ball mass scale: the ball's density is BALL_DENSITY times this, > 0. Default 1. */
  ballWeight?: number;
  /** Where the crane starts (slew angle, trolley radius, hook height; clamped to their ranges). Default angle 0, radius 4 m, height 7.5 m. */
  crane?: Partial<CraneState>;
}

/** World options: 3D, Earth gravity, room for the chain and up to a few hundred pieces; 4 substeps for the chain. */
export function wreckingBallWorldOptions(substeps = 4): PhysicsWorldOptions {
  return { dimensions: 3, capacity: 1200, gravity: [0, -9.81, 0], substeps };
}

/** A small seeded generator (mulberry32): numbers in [0, 1). */
export function seededRandom(seed: number): () => number {
  let a = seed >>> 0 || 0x9e3779b9;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** The hook's position for a crane state, m. */
export function hookPosition(c: CraneState): [number, number, number] {
  return [c.radius * Math.cos(c.angle), c.height, -c.radius * Math.sin(c.angle)];
}

function addPiece(
  world: PhysicsWorld,
  pieces: Piece[],
  kind: Piece['kind'],
  x: number,
  y: number,
  z: number,
  half: [number, number, number],
  yaw: number,
): void {
  const body = addBody(world, { position: [x, y, z], orientation: [0, Math.sin(yaw / 2), 0, Math.cos(yaw / 2)] });
  addShape3D(world, body, { type: 'box', halfExtents: half, density: PIECE_DENSITY, friction: 0.6, restitution: 0.05 });
  let upAxis = 0;
  for (let i = 1; i < 3; i++) if (Math.abs(upComponent(world, body, i)) > Math.abs(upComponent(world, body, upAxis))) upAxis = i;
  pieces.push({ body, kind, y0: y, x0: x, z0: z, half, yaw, points: 10 + Math.round(10 * y), fallen: false, upAxis });
}

/** A tower of `n` cubes of edge `edge` (m) at (x, z), turned by yaw. */
function tower(world: PhysicsWorld, pieces: Piece[], x: number, z: number, n: number, edge: number, yaw: number): void {
  const h = edge / 2;
  for (let i = 0; i < n; i++) addPiece(world, pieces, 'tower', x, h + i * edge, z, [h, h, h], yaw);
}

/** A wall of bricks (1.2 x 0.6 x 0.5 m), `rows` high and `cols` long, running along the direction yaw, in stretcher bond (odd rows shifted half a brick, with half bricks at their ends). */
function wall(world: PhysicsWorld, pieces: Piece[], x: number, z: number, rows: number, cols: number, yaw: number): void {
  const ux = Math.cos(yaw),
    uz = -Math.sin(yaw);
  const L = 1.2,
    H = 0.6,
    T = 0.25; // brick length, height, half thickness
  const put = (s: number, y: number, half: number): void =>
    addPiece(world, pieces, 'wall', x + ux * s * L, y, z + uz * s * L, [half, H / 2, T], yaw);
  for (let r = 0; r < rows; r++) {
    const y = H / 2 + r * H;
    if (r % 2 === 0) {
      for (let c = 0; c < cols; c++) put(c - (cols - 1) / 2, y, 0.49 * L);
    } else {
      for (let c = 0; c < cols - 1; c++) put(c + 0.5 - (cols - 1) / 2, y, 0.49 * L);
      put(-(cols / 2 - 0.25), y, 0.24 * L);
      put(cols / 2 - 0.25, y, 0.24 * L);
    }
  }
}

/** A log-cabin stack of planks (2.4 x 0.24 x 0.36 m), `layers` high, crossing at right angles. */
function planks(world: PhysicsWorld, pieces: Piece[], x: number, z: number, layers: number, yaw: number): void {
  for (let l = 0; l < layers; l++) {
    const a = yaw + (l % 2 === 0 ? 0 : Math.PI / 2);
    const ux = -Math.sin(a),
      uz = -Math.cos(a); // across the planks
    for (const s of [-0.9, 0.9]) addPiece(world, pieces, 'planks', x + ux * s, 0.12 + l * 0.24, z + uz * s, [1.2, 0.12, 0.18], a);
  }
}

/**
 * Builds the ground, the crane (mast, trolley, chain, ball) and level `level`'s targets, seeded by
 * (seed, level); hooks `craneSystem` into the forces stage. Levels grow: more structures and taller
 * ones, up to about 110 pieces at level 5 and after.
 * @throws RangeError on a level that is not an integer >= 1, a non-integer seed or a ballWeight <= 0.
 */
export function buildWreckingBall(world: PhysicsWorld, options: WreckingBallOptions = {}): WreckingBallHandles {
  const level = options.level ?? 1,
    seed = options.seed ?? 1,
    weight = options.ballWeight ?? 1;
  if (!Number.isInteger(level) || level < 1) throw new RangeError(`buildWreckingBall: level must be an integer >= 1, got ${level}`);
  if (!Number.isInteger(seed)) throw new RangeError(`buildWreckingBall: seed must be an integer, got ${seed}`);
  if (!(weight > 0 && Number.isFinite(weight))) throw new RangeError(`buildWreckingBall: ballWeight must be > 0, got ${weight}`);
  addPlane(world, { normal: [0, 1, 0], point: [0, 0, 0], friction: 0.7 });
  // The mast: a static column the ball can hit.
  const mast = addBody(world, { position: [0, JIB_HEIGHT / 2, 0], static: true });
  addShape3D(world, mast, { type: 'box', halfExtents: [0.4, JIB_HEIGHT / 2, 0.4] });

  const at = options.crane ?? {};
  const crane: CraneState = {
    angle: wrap(at.angle ?? 0),
    radius: Math.min(RADIUS_RANGE[1], Math.max(RADIUS_RANGE[0], at.radius ?? 4)),
    height: Math.min(HOOK_RANGE[1], Math.max(HOOK_RANGE[0], at.height ?? 7.5)),
  };
  for (const v of [crane.angle, crane.radius, crane.height])
    if (!Number.isFinite(v)) throw new RangeError(`buildWreckingBall: crane must hold finite numbers, got ${JSON.stringify(at)}`);
  const controls: CraneControls = { slew: 0, trolley: 0, hoist: 0, steady: false, goal: null, moves: [], released: 0 };
  const [hx, hy, hz] = hookPosition(crane);
  const trolley = addBody(world, { position: [hx, hy, hz], kinematic: true, orientation: [0, 0, 0, 1] });
  // The chain hangs straight down from the hook; links are joined end to end.
  const links: number[] = [];
  const pitch = 2 * (LINK_HALF + LINK_RADIUS);
  let prev = trolley,
    top = hy;
  for (let i = 0; i < CHAIN_LINKS; i++) {
    const cy = top - pitch / 2;
    const link = addBody(world, { position: [hx, cy, hz] });
    addShape3D(world, link, { type: 'capsule', radius: LINK_RADIUS, halfHeight: LINK_HALF, density: 7800 });
    addBallJoint3D(world, { a: prev, b: link, anchor: [hx, top, hz] });
    links.push(link);
    prev = link;
    top -= pitch;
  }
  const ball = addBody(world, { position: [hx, top - BALL_RADIUS, hz] });
  addShape3D(world, ball, { type: 'sphere', radius: BALL_RADIUS, density: BALL_DENSITY * weight, friction: 0.4, restitution: 0.1 });
  // Sway damping, as a crane's anti-sway control gives: a swing left behind by a hit or a stop
  // decays with time constant m / k, about 4 s for the 5.4 t ball (a hanging ball under a hook
  // moving at 1.3 m/s lags about 2 degrees more for it).
  setDrag(world, ball, { linear: (BALL_DENSITY * weight * (4 / 3) * Math.PI * BALL_RADIUS ** 3) / SWAY_DAMPING_TIME });
  addBallJoint3D(world, { a: prev, b: ball, anchor: [hx, top, hz] });
  // The chain's links are light next to the ball: a rope from the hook to the ball (its length the
  // chain's) carries the load, so the chain cannot stretch (Box2D's advice for heavy ends on chains).
  addDistanceJoint3D(world, { a: trolley, b: ball, anchorA: [hx, hy, hz], anchorB: [hx, top - BALL_RADIUS, hz], minLength: 0 });

  const pieces: Piece[] = [];
  const rng = seededRandom(seed * 7919 + level * 104729);
  const layout = ((level - 1) % LEVELS) + 1;
  const extra = Math.floor((level - 1) / LEVELS);
  const kinds: Array<'tower' | 'wall' | 'planks'> = (
    [
      ['tower', 'wall', 'planks'],
      ['tower', 'planks', 'wall', 'tower'],
      ['wall', 'tower', 'tower', 'planks'],
      ['tower', 'wall', 'planks', 'wall', 'tower'],
      ['tower', 'tower', 'wall', 'planks', 'wall'],
    ] as const
  )[layout - 1]!.slice();
  for (let i = 0; i < extra && kinds.length < 7; i++) kinds.push(i % 2 === 0 ? 'tower' : 'wall');
  const spread = (2 * Math.PI) / Math.max(3, kinds.length);
  const start = rng() * 2 * Math.PI;
  kinds.forEach((kind, i) => {
    const a = start + i * spread + (rng() - 0.5) * 0.3 * spread;
    const r = 5.5 + rng() * 3.5;
    const x = r * Math.cos(a),
      z = -r * Math.sin(a);
    const facing = a + Math.PI / 2; // walls across the ball's swing about the mast
    if (kind === 'tower') tower(world, pieces, x, z, 4 + Math.floor(rng() * (2 + layout)), 0.7, rng() * Math.PI);
    else if (kind === 'wall') wall(world, pieces, x, z, 3 + Math.floor(rng() * 2), 3 + Math.floor(rng() * 2), facing);
    else planks(world, pieces, x, z, 4 + Math.floor(rng() * 3), rng() * Math.PI);
  });
  const handles: WreckingBallHandles = { trolley, links, ball, pieces, crane, controls, level, seed, mast };
  addSystem(world, 'forces', craneSystem(handles));
  return handles;
}

/** Length from the hook to the ball's centre with the chain straight, m. */
export const HANG = CHAIN_LINKS * 2 * (LINK_HALF + LINK_RADIUS) + BALL_RADIUS;

/** Period of the ball's swing on its chain, s: a pendulum of length HANG, T = 2 pi sqrt(L / g). */
export const SWING_PERIOD = 2 * Math.PI * Math.sqrt(HANG / 9.81);

/**
 * Damping ratio of the swing under the anti-sway control (`CraneControls.steady`): critical, the
 * quickest this control can stop it (both roots of s^2 + K s + w^2 at -w; more gain splits them and
 * one grows slower).
 */
export const STEADY_DAMPING = 1;
/**
 * Gain of the anti-sway control, 1/s: the hook's horizontal velocity is this times the ball's
 * horizontal offset from under the hook (within the crane's rates). For a pendulum of angular
 * frequency w = sqrt(g / L) whose pivot moves at velocity K e (e the ball's offset from under it),
 * the pivot's acceleration K de/dt enters the offset's equation as e'' = -w^2 e - K e': a damped
 * oscillator with damping ratio K / (2 w); K = 2 STEADY_DAMPING w, L = HANG (about 2.7 1/s).
 */
export const STEADY_GAIN = 2 * STEADY_DAMPING * Math.sqrt(9.81 / HANG);

/** Length, m, of the straight run the hook makes up to a target in half a swing period (see `aimAt`). */
export const RUN_UP = 6;
/** Straight pieces the run is made of (each a timed move of the crane; see `aimAt`). */
export const RUN_STEPS = 8;
/** Swing amplitude, m, a wind-up waits for the ball's swing to decay under (see `aimAt`). */
export const SWING_LEFT = 0.3;
/** How far off the run's line, m, the hook may be for a wind-up of odd half periods (see `aimAt`). */
export const SIDE_LEFT = 1;
/** Directions `aimAt` tries for the run, evenly spaced around the target. */
const RUN_DIRECTIONS = 24;

/**
 * Swings the ball at piece `piece` with timed moves (`CraneControls.moves`), from what a pendulum
 * does when its pivot moves at a constant velocity: starting at rest under the pivot, the ball lags,
 * then passes under it again half a period (T / 2) later moving at 2 w, and at rest a whole period
 * later; a pivot that moves at w1 for an odd number of half periods and then at w2 for one more
 * leaves the ball under it moving at 2 (w2 - w1) (small swings; T = SWING_PERIOD).
 * - The run: a straight line of RUN_UP m (shorter where the jib's reach asks) that ends over the
 *   piece, at constant speed over half a period (RUN_STEPS moves); the ball meets the piece at
 *   2 x 6 / 2.3 = 5 m/s and more as the hook stops over it. Of RUN_DIRECTIONS directions around the
 *   piece, the run takes the one with the fewest other pieces (standing or fallen) in the ball's
 *   way (a run along the jib's arc hit a wall's end brick and stopped short of the brick tapped),
 *   then the one whose start is nearest the hook.
 * - The wind-up before it: a straight move to the run's start, hoisted so the ball's centre passes
 *   at the piece's height, over the fewest odd half periods the crane's rates allow (one, 2.3 s,
 *   when the start is within reach of them) if the hook is within SIDE_LEFT of the run's line (as
 *   a hook near the piece is): the ball comes to the run's start swinging along the line, which the
 *   run turns into speed toward the piece (a hook backing away from the piece before the run adds
 *   to the hit). Skipped when the hook is already there. A ball still swinging from the last swing
 *   would meet the run off its line: then the wind-up takes whole periods, as many as the sway
 *   damping needs to bring the swing under SWING_LEFT, and the ball starts the run at rest.
 */
export function aimAt(world: PhysicsWorld, h: WreckingBallHandles, piece: number): void {
  const P = world.components.Position;
  const tx = P.x[piece]!,
    tz = P.z[piece]!;
  // The ball's centre at the piece's, but never lower than skimming the ground.
  const ballY = Math.max(P.y[piece]!, BALL_RADIUS + 0.05);
  const height = Math.min(HOOK_RANGE[1], Math.max(HOOK_RANGE[0], ballY + HANG));
  // The end of the run: over the piece, pulled into the jib's reach.
  const r0 = Math.min(RADIUS_RANGE[1], Math.max(RADIUS_RANGE[0], Math.hypot(tx, tz)));
  const a0 = Math.atan2(-tz, tx);
  const ex = r0 * Math.cos(a0),
    ez = -r0 * Math.sin(a0);
  const c = h.crane;
  const [hx, , hz] = hookPosition(c);
  const reachable = (x: number, z: number): boolean => {
    const r = Math.hypot(x, z);
    return r >= RADIUS_RANGE[0] - 1e-9 && r <= RADIUS_RANGE[1] + 1e-9;
  };
  /** Pieces, standing or fallen, the ball (at the piece's height) would meet from (sx, sz) along (dx, dz) for `length` m. */
  const blockedOn = (sx: number, sz: number, dx: number, dz: number, length: number): number => {
    let blocked = 0;
    for (const q of h.pieces) {
      if (q.body === piece) continue;
      const qx = P.x[q.body]! - sx,
        qy = P.y[q.body]! - ballY,
        qz = P.z[q.body]! - sz;
      const along = Math.min(length - 0.3, Math.max(0, qx * dx + qz * dz));
      const d = Math.hypot(qx - along * dx, qy, qz - along * dz);
      if (d < BALL_RADIUS + Math.max(...q.half) + 0.05) blocked++;
    }
    return blocked;
  };
  let best: { sx: number; sz: number; blocked: number; away: number; side: number } | null = null;
  for (const length of [RUN_UP, 0.75 * RUN_UP, 0.5 * RUN_UP]) {
    for (let i = 0; i < RUN_DIRECTIONS; i++) {
      const t = (2 * Math.PI * i) / RUN_DIRECTIONS;
      const dx = Math.cos(t),
        dz = Math.sin(t);
      const sx = ex - length * dx,
        sz = ez - length * dz;
      let ok = true;
      for (let k = 0; k <= RUN_STEPS && ok; k++) ok = reachable(sx + ((ex - sx) * k) / RUN_STEPS, sz + ((ez - sz) * k) / RUN_STEPS);
      if (!ok) continue;
      const blocked = blockedOn(sx, sz, dx, dz, length);
      const away = Math.hypot(sx - hx, sz - hz);
      // How far the hook is off the run's line (a wind-up across it would send the ball in sideways).
      const side = Math.abs((sx - hx) * dz - (sz - hz) * dx);
      if (best === null || blocked < best.blocked || (blocked === best.blocked && away < best.away - 1e-9))
        best = { sx, sz, blocked, away, side };
    }
    if (best !== null) break;
  }
  const moves: CraneMove[] = [];
  const at = (x: number, z: number): { angle: number; radius: number } => ({ angle: Math.atan2(-z, x), radius: Math.hypot(x, z) });
  /** RUN_STEPS straight moves from (x0, z0) to (x1, z1) over `duration` s in all, the hook's height going from y0 to `height`. */
  const straight = (x0: number, z0: number, x1: number, z1: number, y0: number, duration: number, run: boolean): void => {
    for (let k = 1; k <= RUN_STEPS; k++) {
      const f = k / RUN_STEPS;
      const y = y0 + (height - y0) * f;
      moves.push({ ...at(x0 + (x1 - x0) * f, z0 + (z1 - z0) * f), height: y, duration: duration / RUN_STEPS, elapsed: 0, run });
    }
  };
  const amp = swayAmplitude(world, h);
  const half = SWING_PERIOD / 2;
  if (best === null) {
    // Nowhere to run from (cannot happen inside the jib's reach): straight to the piece.
    moves.push({ ...at(ex, ez), height, duration: half, elapsed: 0, run: true });
  } else {
    const start = at(best.sx, best.sz);
    // A ball still swinging from the last swing would meet the run off its line: the wind-up lasts
    // the whole periods the sway damping needs to bring the swing's amplitude under SWING_LEFT.
    const settle = amp > SWING_LEFT ? Math.ceil((SWAY_DAMPING_TIME * Math.log(amp / SWING_LEFT)) / SWING_PERIOD) : 0;
    // The time the crane's rates need to reach the run's start.
    const need = Math.max(
      Math.abs(wrap(start.angle - c.angle)) / SLEW_RATE,
      Math.abs(start.radius - c.radius) / TROLLEY_SPEED,
      Math.abs(height - c.height) / HOIST_SPEED,
    );
    // Half periods the wind-up takes: the fewest odd ones the rates allow (the ball starts the run
    // swinging along its line), unless as many whole periods are as quick or the hook is off the
    // run's line by more than SIDE_LEFT (a swing across the line would carry the ball off it).
    const odd = 2 * Math.max(0, Math.ceil((need / half - 1) / 2)) + 1,
      whole = 2 * Math.max(1, Math.ceil(need / SWING_PERIOD), settle);
    if (settle > 0 || whole < odd || best.side > SIDE_LEFT) moves.push({ ...start, height, duration: whole * half, elapsed: 0 });
    else if (best.away > 0.5 || Math.abs(height - c.height) > 0.3) straight(hx, hz, best.sx, best.sz, c.height, odd * half, false);
    straight(best.sx, best.sz, ex, ez, height, half, true);
  }
  const first = moves.find((m) => m.run);
  if (first) first.release = true;
  h.controls.goal = null;
  h.controls.moves = moves;
}

/**
 * How far the ball swings from under the hook, m: the horizontal amplitude of a linear pendulum
 * with its offset (ball minus hook) and relative velocity, sqrt(e^2 + (v / w)^2), w = 2 pi / SWING_PERIOD.
 */
export function swayAmplitude(world: PhysicsWorld, h: WreckingBallHandles): number {
  const P = world.components.Position,
    V = world.components.Velocity,
    b = h.ball,
    t = h.trolley,
    w = (2 * Math.PI) / SWING_PERIOD;
  return Math.hypot(P.x[b]! - P.x[t]!, P.z[b]! - P.z[t]!, (V.x[b]! - V.x[t]!) / w, (V.z[b]! - V.z[t]!) / w);
}

/** Wraps an angle into (-pi, pi]. */
function wrap(a: number): number {
  return a - 2 * Math.PI * Math.floor((a + Math.PI) / (2 * Math.PI));
}

/**
 * A forces-stage system that drives the trolley: slews, runs and hoists at the rates the controls ask
 * for (or toward `goal`), clamped to the jib's ranges, by setting the kinematic trolley's velocity so
 * it reaches the new state over the substep (h = dt / substeps).
 */
export function craneSystem(h: WreckingBallHandles): (world: PhysicsWorld) => void {
  return (world) => {
    const c = h.crane,
      k = h.controls,
      dt = world.dt / world.substeps;
    let slew = k.slew,
      run = k.trolley;
    if (k.goal !== null) {
      // Full speed until the last substep's worth, then exactly there: no easing in, so the ball,
      // lagging behind the hook, swings on through the goal with the crane's speed.
      const [gx, gz] = k.goal;
      const want = Math.atan2(-gz, gx),
        d = wrap(want - c.angle);
      const wantR = Math.min(RADIUS_RANGE[1], Math.max(RADIUS_RANGE[0], Math.hypot(gx, gz)));
      slew = Math.max(-1, Math.min(1, d / (SLEW_RATE * dt)));
      run = Math.max(-1, Math.min(1, (wantR - c.radius) / (TROLLEY_SPEED * dt)));
      if (Math.abs(d) < 1e-9 && Math.abs(wantR - c.radius) < 1e-9) k.goal = null;
    }
    const before = hookPosition(c);
    const move = k.moves[0];
    if (move !== undefined) {
      // A timed move: the rest of the way at a constant rate over the time left.
      const left = move.duration - move.elapsed,
        f = Math.min(1, dt / Math.max(left, 1e-9));
      if (move.release === true && move.elapsed === 0) k.released++;
      c.angle = wrap(c.angle + f * wrap(move.angle - c.angle));
      c.radius += f * (move.radius - c.radius);
      c.height += f * (move.height - c.height);
      move.elapsed += dt;
      if (f === 1) k.moves.shift();
    } else {
      if (k.steady && k.goal === null) {
        // Anti-sway: the hook's velocity STEADY_GAIN times the ball's offset from under it, as
        // slew and trolley rates (radial along the jib, tangential over the radius), added to
        // those asked for and held to the crane's.
        const P = world.components.Position,
          b = h.ball;
        const ex = P.x[b]! - before[0],
          ez = P.z[b]! - before[2];
        const ca = Math.cos(c.angle),
          sa = Math.sin(c.angle);
        // Radial unit (ca, -sa); the direction of growing slew angle (-sa, -ca).
        const radial = STEADY_GAIN * (ex * ca - ez * sa),
          tangential = STEADY_GAIN * (-ex * sa - ez * ca);
        run = Math.max(-1, Math.min(1, run + radial / TROLLEY_SPEED));
        slew = Math.max(-1, Math.min(1, slew + tangential / c.radius / SLEW_RATE));
      }
      c.angle = wrap(c.angle + slew * SLEW_RATE * dt);
      c.radius = Math.min(RADIUS_RANGE[1], Math.max(RADIUS_RANGE[0], c.radius + run * TROLLEY_SPEED * dt));
      c.height = Math.min(HOOK_RANGE[1], Math.max(HOOK_RANGE[0], c.height + k.hoist * HOIST_SPEED * dt));
    }
    const after = hookPosition(c);
    const V = world.components.Velocity,
      P = world.components.Position,
      e = h.trolley;
    // Put the trolley exactly where the crane was, and give it the velocity that takes it to the new state.
    P.x[e] = before[0];
    P.y[e] = before[1];
    P.z[e] = before[2];
    V.x[e] = (after[0] - before[0]) / dt;
    V.y[e] = (after[1] - before[1]) / dt;
    V.z[e] = (after[2] - before[2]) / dt;
  };
}

/**
 * Marks pieces that have fallen (see the module comment) and returns the points they score now.
 * Pieces whose bodies were removed count as fallen.
 */
export function scorePieces(world: PhysicsWorld, pieces: Piece[]): number {
  const P = world.components.Position;
  const cosTip = Math.cos(TIP_ANGLE);
  let points = 0;
  for (const p of pieces) {
    if (p.fallen) continue;
    const e = p.body;
    if (
      P.y[e]! < p.y0 - FALL_DROP ||
      Math.abs(upComponent(world, e, p.upAxis)) < cosTip ||
      Math.hypot(P.x[e]! - p.x0, P.z[e]! - p.z0) > KNOCK_DISTANCE
    ) {
      p.fallen = true;
      points += p.points;
    }
  }
  return points;
}

/** The y component of body axis `axis` (0 x, 1 y, 2 z) in the world: row y of the rotation matrix of its orientation. */
export function upComponent(world: PhysicsWorld, e: number, axis: number): number {
  const O = world.components.Orientation;
  const x = O.x[e]!,
    y = O.y[e]!,
    z = O.z[e]!,
    w = O.w[e]!;
  return axis === 0 ? 2 * (x * y + w * z) : axis === 1 ? 1 - 2 * (x * x + z * z) : 2 * (y * z - w * x);
}

/** How many pieces have fallen. */
export function fallenCount(pieces: readonly Piece[]): number {
  let n = 0;
  for (const p of pieces) if (p.fallen) n++;
  return n;
}

/**
 * Swings a level allows: taps (or site-plan clicks) on a target and drags of the ball each use one.
 * Without a limit a level fell to any two taps; with it, where the ball is sent is the skill.
 */
export const SWING_BUDGET = 4;

/**
 * Stars for a level cleared in `swings` swings: 3 for 2 or fewer, 2 for 3, 1 for 4 (SWING_BUDGET);
 * 0 when it is not cleared.
 */
export function swingStars(swings: number, cleared: boolean): number {
  if (!cleared) return 0;
  return swings <= 2 ? 3 : swings === 3 ? 2 : 1;
}
