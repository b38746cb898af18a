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
 * stood above the ground. A level is cleared when as many pieces have fallen as its clearing share
 * (`clearShare`) of those that stood above the ground (`clearTarget`), in at most its swings
 * (`swingBudget`).
 */
import { seededRandom } from '@bitphysics/game-kit';
import {
  addBallJoint3D,
  addBody,
  addDistanceJoint3D,
  addPlane,
  addShape3D,
  addSystem,
  isAlive,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  setDrag,
} from '@bitphysics/physics';

/** Height of the jib, m. */
export const JIB_HEIGHT = 11.5;
/** Smallest and largest trolley radius on the jib, m. */
export const RADIUS_RANGE: readonly [number, number] = [3, 11];
/**
 * Lowest and highest hook height, m. At the lowest the hanging ball's bottom is 6 cm off the ground
 * (the hook to the ball's centre is HANG, 5.19 m, and its radius 0.55 m): at 5.7 m it sat on the
 * ground with its chain slack, and a swing let go from there dragged along the ground.
 */
export const HOOK_RANGE: readonly [number, number] = [5.8, 10.5];
/** Largest slew rate, rad/s; trolley speed along the jib and hoist speed, m/s. */
export const SLEW_RATE = 0.7;
export const TROLLEY_SPEED = 3.5;
export const HOIST_SPEED = 2;
/**
 * The slew and the trolley driven by the player (`CraneControls.slew`, `.trolley`) have mass: they
 * speed up at SLEW_ACCEL (rad/s^2) and TROLLEY_ACCEL (m/s^2) to the rate asked, full speed in
 * 0.5 s; let go, they coast to a stop at SLEW_COAST and TROLLEY_COAST (0.7 s, the jib turning 14
 * degrees on); driven the other way, they brake at SLEW_REVERSE and TROLLEY_REVERSE (0.25 s to a
 * stop), so the crane does not move like a cursor, starting and stopping dead; the ball still
 * swings out behind a start and on past a stop (both take well under a quarter of its 4.6 s swing),
 * so a player pumps it by reversing the jib in time with the swing.
 */
export const SLEW_ACCEL = SLEW_RATE / 0.5;
export const SLEW_COAST = SLEW_RATE / 0.7;
export const SLEW_REVERSE = SLEW_RATE / 0.25;
export const TROLLEY_ACCEL = TROLLEY_SPEED / 0.5;
export const TROLLEY_COAST = TROLLEY_SPEED / 0.7;
export const TROLLEY_REVERSE = TROLLEY_SPEED / 0.25;
/** Chain: links, each a capsule of this radius and straight half length, m. */
export const CHAIN_LINKS = 8;
export const LINK_RADIUS = 0.07;
export const LINK_HALF = 0.22;
/**
 * Density of the chain's links, kg/m^3: each link about 8 kg, the chain 66 kg against the ball's
 * 5.4 t. The rope from the hook to the ball carries the load (see buildWreckingBall); the links show
 * the chain. When the hook turned with the ball swinging, the links' joints stretched and folded
 * (they still do, and the page draws the chain through the links' centres); as steel (7800, the
 * chain 510 kg) the tangle held the ball up to 2 m above where its rope let it hang, for a second
 * or more, and a swing planned for a ball on its rope flew over the piece aimed at. At this density
 * the rope stays taut and the ball arrives within a few centimetres of the planned height.
 */
export const LINK_DENSITY = 1000;
/** Time constant, s, with which the ball's swing decays (see buildWreckingBall). */
export const SWAY_DAMPING_TIME = 4;
/** The ball: radius, m, and density, kg/m^3 (steel). */
export const BALL_RADIUS = 0.55;
export const BALL_DENSITY = 7800;
/**
 * The ball's mass at BALL_DENSITY, t, to 0.1 t (4/3 pi BALL_RADIUS^3 BALL_DENSITY = 5.44 t shows as
 * 5.4): the settings panel's ball mass slider reads in t and scales the density by its value over this.
 */
export const BALL_TONNES = Math.round(((4 / 3) * Math.PI * BALL_RADIUS ** 3 * BALL_DENSITY) / 100) / 10;
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
 * clear it: 0.75 on levels 1 to 3 and 0.76 after (the levels grow, so the count grows too).
 * The bottom row (a wall's lowest bricks, a crib's lowest logs, a tower's base) rarely falls, tips or
 * slides a metre however it is hit, so the share counts raised pieces only. With the pars of
 * `swingPar`, no one swing clears level 1 or 2 (a swing of scripts/wrecking-ball-par.mjs brings
 * down at most 10 on level 1, 9 on level 2, well short of the 16 and 18 needed), so three stars ask
 * for two swings at the right structures, while its careless games (the top of each structure in
 * turn, the biggest structure, the piece nearest the ball) still clear both within 4 swings. A lower
 * share lets one swing clear level 1: at 0.5 a swing aimed hard at the plank stack, at 0.65 (14 of
 * its 21 raised pieces) a player's first drag.
 * @throws RangeError on a level that is not an integer >= 1.
 */
export function clearShare(level: number): number {
  if (!Number.isInteger(level) || level < 1) throw new RangeError(`clearShare: level must be an integer >= 1, got ${level}`);
  return level <= 3 ? 0.75 : 0.76;
}

/**
 * How many pieces must fall to clear level `level`: its `clearShare` of the pieces that stood above
 * the ground, rounded up.
 * @throws RangeError on a level that is not an integer >= 1.
 */
export function clearTarget(pieces: readonly Piece[], level: number): number {
  const share = clearShare(level);
  let raised = 0;
  for (const p of pieces) if (p.y0 - p.half[p.upAxis]! > 0.01) raised++;
  return Math.ceil(share * raised);
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
   * The swing the moves are planned for (see `aimAt`), made again from where the ball is as it
   * runs; null when the moves are not a planned swing (and once they are done).
   */
  swing: SwingAim | null;
  /**
   * Swings taken on this level: counted by `craneSystem` when it begins a move marked `release` (the
   * ball let go into its run at a target), and by the page for each drag of the ball let go. A swing
   * re-aimed during its wind-up (`aimAt` again) has not been taken and is not counted.
   */
  released: number;
  /**
   * The tagline holding the ball back for the player's swing (see `pullBack`), or null: while set,
   * the crane runs the hook over the piece and the line draws the ball back along its chain's arc;
   * once let go, and ready, the line slips and the ball swings down from there on to the piece.
   */
  pull: PullBack | null;
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
  /** Whether it is the run's follow-through, after the ball's arrival at its target (see FOLLOW_SPEED). */
  follow?: boolean;
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
  /** The level's static concrete shields (`SHIELD_HALF`), bodies: they stop the ball and never fall. */
  shields: number[];
  /**
   * The crane's drive now: slew rate, rad/s (positive counter-clockwise seen from above), and
   * trolley speed along the jib, m/s (positive outward); mutated by `craneSystem`, which ramps them
   * toward what the controls ask (see SLEW_ACCEL); 0 while a timed move or a run to a goal drives
   * the crane (those stop it dead at their end).
   */
  drive: { slew: number; trolley: number };
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
  /**
   * Whether the jib starts pointing into the widest gap between the level's structures (`openingAngle`)
   * rather than at `crane.angle`: the ball then hangs clear of every target, not in front of one.
   * Default false (angle 0, as the tests and scripts were measured from).
   */
  openStart?: boolean;
}

/**
 * The slew angle, rad, half way across the widest gap between the directions (about the mast) of
 * structures at angles `angles` (rad, any range; at least one): where a ball hangs clear of them all.
 * @throws RangeError on an empty list or an angle that is not finite.
 */
export function openingAngle(angles: readonly number[]): number {
  if (angles.length === 0 || !angles.every(Number.isFinite))
    throw new RangeError(`openingAngle: angles must be a non-empty list of finite numbers, got ${JSON.stringify(angles)}`);
  const a = angles.map((x) => ((x % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI)).sort((x, y) => x - y);
  let best = 0,
    at = a[0]! + Math.PI;
  for (let i = 0; i < a.length; i++) {
    const next = i + 1 < a.length ? a[i + 1]! : a[0]! + 2 * Math.PI;
    if (next - a[i]! > best) {
      best = next - a[i]!;
      at = (a[i]! + next) / 2;
    }
  }
  return wrap(at);
}

/** World options: 3D, Earth gravity, room for the chain and up to a few hundred pieces; 4 substeps for the chain. */
export function wreckingBallWorldOptions(substeps = 4): PhysicsWorldOptions {
  return { dimensions: 3, capacity: 1200, gravity: [0, -9.81, 0], substeps };
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
 * A structure of a level: what it is, its direction about the mast (rad) and distance from it (m),
 * and its sizes (drawn from the level's seed). 'tower', 'wall' and 'planks' are the first levels'
 * kinds; the later levels' are made of the same pieces: 'tall' a tower of 8 or 9 cubes, 'row' three
 * towers in a line across the ball's swing about the mast (one swing along the line can topple them
 * in turn), 'shielded' a tower behind a concrete shield on the mast's side (`SHIELD_HALF`: a swing
 * straight out from the mast meets the shield, so the tower wants a swing from the side), 'heavy' a tower of four big 1.1 m cubes (600 kg each,
 * four times a small cube) and 'long' a wall 5 bricks long and 4 or 5 high. Sizes: a tower's cubes and
 * turn (rad), a wall's rows and bricks, a stack's layers and turn.
 */
interface Structure {
  kind: 'tower' | 'wall' | 'planks' | 'tall' | 'row' | 'shielded' | 'heavy' | 'long';
  a: number;
  r: number;
  sizes: number[];
}

/**
 * The structures of each of the LEVELS layouts, a progression: level 1 a tower, a wall and a plank
 * stack; 2 four of those; 3 tall towers, one row of three; 4 towers behind shield walls; 5 a heavy
 * tower, a long wall, a row, a shielded tower and a tall one.
 */
const LAYOUTS: ReadonlyArray<ReadonlyArray<Structure['kind']>> = [
  ['tower', 'wall', 'planks'],
  ['tower', 'planks', 'wall', 'tower'],
  ['row', 'tall', 'planks', 'tall'],
  ['shielded', 'wall', 'shielded', 'planks'],
  ['heavy', 'long', 'row', 'shielded', 'tall'],
];

/** Level `level`'s structures for seed `seed`: LAYOUTS, cycled with one more tower or wall each LEVELS levels (at most 7 structures). */
function levelLayout(seed: number, level: number): Structure[] {
  const rng = seededRandom(seed * 7919 + level * 104729);
  const layout = ((level - 1) % LEVELS) + 1;
  const extra = Math.floor((level - 1) / LEVELS);
  const kinds = LAYOUTS[layout - 1]!.slice();
  for (let i = 0; i < extra && kinds.length < 7; i++) kinds.push(i % 2 === 0 ? 'tower' : 'wall');
  const spread = (2 * Math.PI) / Math.max(3, kinds.length);
  const start = rng() * 2 * Math.PI;
  return kinds.map((kind, i) => {
    const a = start + i * spread + (rng() - 0.5) * 0.3 * spread;
    const r = 5.5 + rng() * 3.5;
    let sizes: number[];
    if (kind === 'tower') sizes = [4 + Math.floor(rng() * (2 + layout)), rng() * Math.PI];
    else if (kind === 'wall') sizes = [3 + Math.floor(rng() * 2), 3 + Math.floor(rng() * 2)];
    else if (kind === 'planks') sizes = [4 + Math.floor(rng() * 3), rng() * Math.PI];
    else if (kind === 'tall') sizes = [8 + Math.floor(rng() * 2), rng() * Math.PI];
    else if (kind === 'row' || kind === 'shielded') sizes = [5 + Math.floor(rng() * 2), rng() * Math.PI];
    else if (kind === 'heavy') sizes = [4, rng() * Math.PI];
    else sizes = [4 + Math.floor(rng() * 2), 5];
    return { kind, a, r, sizes };
  });
}

/**
 * Half extents of a concrete shield, m (3.2 m long, 1.6 m tall, 0.5 m thick): static, it stops a
 * ball swung at a tower behind it low and straight from the mast; over it or round it, the ball
 * reaches the tower.
 */
export const SHIELD_HALF: readonly [number, number, number] = [1.6, 0.8, 0.25];
/** How far in front of its tower (toward the mast) a shield stands, m. */
export const SHIELD_GAP = 1.3;

/** Builds structure `s` of a level (see Structure), its pieces added to `pieces` and its shields' bodies to `shields`. */
function buildStructure(world: PhysicsWorld, pieces: Piece[], shields: number[], s: Structure): void {
  const { kind, a, r, sizes } = s;
  const x = r * Math.cos(a),
    z = -r * Math.sin(a);
  const facing = a + Math.PI / 2; // walls across the ball's swing about the mast
  const n = sizes[0]!,
    second = sizes[1]!; // a tower's or stack's turn, a wall's bricks
  const yaw = second;
  if (kind === 'tower' || kind === 'tall') tower(world, pieces, x, z, n, 0.7, yaw);
  else if (kind === 'wall' || kind === 'long') wall(world, pieces, x, z, n, second, facing);
  else if (kind === 'planks') planks(world, pieces, x, z, n, yaw);
  else if (kind === 'heavy') tower(world, pieces, x, z, n, 1.1, yaw);
  else if (kind === 'row') {
    // Across the swing about the mast: along (sin a, cos a), 1.5 m apart.
    for (const k of [-1, 0, 1]) tower(world, pieces, x + k * 1.5 * Math.sin(a), z + k * 1.5 * Math.cos(a), n, 0.7, yaw);
  } else {
    tower(world, pieces, x, z, n, 0.7, yaw);
    // The shield: SHIELD_GAP nearer the mast, square to the line to it.
    const d = r - SHIELD_GAP;
    const shield = addBody(world, {
      position: [d * Math.cos(a), SHIELD_HALF[1], -d * Math.sin(a)],
      orientation: [0, Math.sin(facing / 2), 0, Math.cos(facing / 2)],
      static: true,
    });
    addShape3D(world, shield, { type: 'box', halfExtents: [...SHIELD_HALF], friction: 0.6, restitution: 0.1 });
    shields.push(shield);
  }
}

/**
 * Builds the ground, the crane (mast, trolley, chain, ball) and level `level`'s targets, seeded by
 * (seed, level); hooks `craneSystem` into the forces stage. The levels follow LAYOUTS (`levelLayout`):
 * each brings structures of its own, and every LEVELS levels they begin again with one more.
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

  // The layout first (its random draws in the order the pieces are built in below), so the crane
  // may start pointing between the structures (openStart).
  const placed = levelLayout(seed, level);

  const at = options.crane ?? {};
  const crane: CraneState = {
    angle: wrap(options.openStart ? openingAngle(placed.map((p) => p.a)) : (at.angle ?? 0)),
    radius: Math.min(RADIUS_RANGE[1], Math.max(RADIUS_RANGE[0], at.radius ?? 4)),
    height: Math.min(HOOK_RANGE[1], Math.max(HOOK_RANGE[0], at.height ?? 7.5)),
  };
  for (const v of [crane.angle, crane.radius, crane.height])
    if (!Number.isFinite(v)) throw new RangeError(`buildWreckingBall: crane must hold finite numbers, got ${JSON.stringify(at)}`);
  const controls: CraneControls = {
    slew: 0,
    trolley: 0,
    hoist: 0,
    steady: false,
    goal: null,
    moves: [],
    swing: null,
    released: 0,
    pull: null,
  };
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
    addShape3D(world, link, { type: 'capsule', radius: LINK_RADIUS, halfHeight: LINK_HALF, density: LINK_DENSITY });
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

  const pieces: Piece[] = [],
    shields: number[] = [];
  for (const p of placed) buildStructure(world, pieces, shields, p);
  const handles: WreckingBallHandles = {
    trolley,
    links,
    ball,
    pieces,
    crane,
    controls,
    level,
    seed,
    mast,
    shields,
    drive: { slew: 0, trolley: 0 },
  };
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

/** Horizontal speed, m/s, the ball has as it reaches the tapped piece (see `aimAt`). */
export const HIT_SPEED = 6;
/**
 * The ball's speed at the piece, m/s, for a full pull of the player's swing (see `swingSpeed`): the
 * tap's speed the level pars were measured with (0.8 HIT_SPEED). Above it the plans slow down
 * sharply: the ball must be pumped for a whole swing of its chain to arrive faster (median over
 * levels 1 to 5, from rest, aimed straight and 30 degrees off: 2.9 s at 4.8 m/s, 3.7 s at 5.4, 4.5 s
 * at 6, 5.0 s at 6.9, the old full pull), while the wood pieces fall alike (16 targets on levels 1
 * and 2, struck at 3.5, 4.5 and 5.5 m/s: the same count within 1 on 13 of them).
 */
export const FULL_SWING_SPEED = 4.8;
/**
 * The ball's speed at the piece, m/s, for a pull of power `power` (share of a full pull, [0, 1]):
 * 60 % of FULL_SWING_SPEED with no pull, rising evenly to all of it at a full pull.
 * @throws RangeError on a power outside [0, 1].
 */
export function swingSpeed(power: number): number {
  if (!(power >= 0 && power <= 1)) throw new RangeError(`swingSpeed: power must be in [0, 1], got ${power}`);
  return FULL_SWING_SPEED * (0.6 + 0.4 * power);
}
/** Shortest and longest time, s, from a tap to the ball's arrival that `aimAt` plans for. */
export const PLAN_TIME_RANGE: readonly [number, number] = [1.2, 10];
/** Step of the plan times `aimAt` tries, s. */
const PLAN_TIME_STEP = 0.1;
/**
 * How much faster than the player's keys (SLEW_RATE, TROLLEY_SPEED) the crane may slew and run its
 * trolley in a planned swing: an operator's practised full-speed move, so the ball is on its way
 * at once and strikes soon after the player lets go (at the keys' rates a target across the site
 * would take 7 to 8 s to reach, at 1.5 times them a drag's hit would still come 3 to 5 s after it).
 */
export const PLAN_RATE = 2.5;
/** How a plan's time is shared among its three straight legs (`aimAt` tries each). */
const LEG_SPLITS: ReadonlyArray<readonly [number, number, number]> = [
  [1 / 3, 1 / 3, 1 / 3],
  [0.5, 0.25, 0.25],
  [0.25, 0.25, 0.5],
  [0.25, 0.5, 0.25],
  [0.4, 0.4, 0.2],
];
/** Integration step of the plan's pendulum model, s: the physics' substep (60 Hz, 4 substeps). */
const PLAN_H = 1 / 240;
/** Longest timed move of a plan, in PLAN_H steps (0.1 s): the hook's height follows its own profile. */
const MOVE_STEPS = 24;
/** Directions `aimAt` tries for the ball's approach, evenly spaced around the piece. */
const APPROACH_DIRECTIONS = 24;
/**
 * Farthest, m, a plan lets the ball swing from under the hook (about 35 degrees on the chain): the
 * plan's pendulum is linear; a plan that swung the ball 4 m out would send it 2.7 m up at a crib 0.6 m
 * up, and at 1.8 m almost no plan is quick enough. At 3 m the ball reaches the piece within 0.2 s
 * of the plan's time (measured over levels 1 to 5, see test/games/wrecking-ball-windup.test.ts).
 */
export const MAX_OFFSET = 3;
/**
 * A swing the player aimed (see `aimAt`): the direction the ball travels across the ground as it
 * reaches the piece, rad (atan2 of its z and x velocity: 0 along +x, pi/2 along +z), and its
 * horizontal speed there, m/s, in (0, 2 HIT_SPEED].
 */
export interface SwingRequest {
  direction: number;
  speed: number;
}
/**
 * The least pull power, as a share of a full pull in [0, 1], that the aiming hint calls full: any
 * power that shows as 99 % or more, so the hint never asks for a longer pull it can barely give.
 */
export const FULL_POWER_SHOWN = 0.985;
/**
 * The aiming hint's words for a pull of power `power` (share of a full pull, [0, 1]): 'full power'
 * from FULL_POWER_SHOWN up, else 'power N %' with N the rounded percentage.
 */
export function powerWords(power: number): string {
  if (!Number.isFinite(power) || power < 0 || power > 1) throw new Error(`powerWords: power must be in [0, 1], got ${power}`);
  return power >= FULL_POWER_SHOWN ? 'full power' : `power ${Math.round(100 * power)} %`;
}
/**
 * Seconds of plan cost per radian an approach strays from the player's direction (`aimAt` with a
 * SwingRequest) by more than AIM_FREE: larger than any other cost, so beyond AIM_FREE the nearest
 * direction the crane can swing wins.
 */
const AIM_COST = 200;
/**
 * How far, rad, an approach may stray from the player's direction at no cost: one of the
 * APPROACH_DIRECTIONS steps (15 degrees), so of the directions either side of the player's the
 * quicker plan wins. Held to the nearest direction, a light drag at a tower could wait 6.3 s for a
 * hit that the direction beside it brings in 2.5 s.
 */
const AIM_FREE = (2 * Math.PI) / APPROACH_DIRECTIONS;
/** Seconds of plan time a ball along a long piece's length costs (see `aimAt`). */
const GLANCE_COST = 2;
/** Seconds before the arrival in which pieces near the ball's path count as in the way of the hit. */
const APPROACH_TIME = 0.8;
/**
 * Pieces whose start centres lie within this distance (m, across the ground) of the tapped piece's
 * are its structure: a tower, a wall or a plank stack (the layouts keep structures 3 m apart or more).
 */
export const STRUCTURE_RADIUS = 2.5;
/**
 * Share of its structure's height (from the ground) a swing strikes at, at most (never above the
 * tapped piece, never below skimming the ground): a ball at the top of a plank stack knocked off its
 * top two layers and came to rest on the rest; one low in the stack sweeps most of it out.
 */
export const STRIKE_SHARE = 0.35;
/**
 * After its hit the hook runs on along the ball's approach at FOLLOW_SPEED m/s to FOLLOW_CLEAR m past
 * the structure's far side (with the ball's radius): the ball swings through and comes to rest
 * beyond the structure, not on it (a hook stopped over the piece would hang the ball in what is left).
 */
export const FOLLOW_SPEED = 3;
export const FOLLOW_CLEAR = 0.4;
/** Seconds of plan cost per metre a follow-through would take the hook past the jib's reach. */
const REACH_COST = 2;
/**
 * A swing's plan is made again from where the ball is every REPLAN_EVERY s (the chain is not quite
 * the model's pendulum), until REPLAN_UNTIL s before the hit (closer in, the legs' speeds it asks
 * for grow past the crane's rates).
 */
export const REPLAN_EVERY = 0.25;
export const REPLAN_UNTIL = 0.8;

/**
 * One axis of the plan's pendulum model: the ball at `b` (m) moving at `v` (m/s) on a chain from a
 * hook at `p` (m) that moves at `u[i]` m/s for `n[i]` steps of PLAN_H s in turn; the ball obeys
 * b'' = w^2 (p - b) - b' / SWAY_DAMPING_TIME (a linear pendulum with the ball's drag), w = 2 pi /
 * SWING_PERIOD. @returns the final [p, b, v]; `path`, when given, gets b after every step.
 */
function pendulumAxis(
  b: number,
  v: number,
  p: number,
  u: ArrayLike<number>,
  n: ArrayLike<number>,
  path?: number[],
): [number, number, number] {
  const w2 = (2 * Math.PI) ** 2 / SWING_PERIOD ** 2,
    c = 1 / SWAY_DAMPING_TIME,
    h = PLAN_H;
  for (let i = 0; i < n.length; i++) {
    const ui = u[i]!;
    for (let k = 0; k < n[i]!; k++) {
      p += ui * h;
      v += (w2 * (p - b) - c * v) * h;
      b += v * h;
      path?.push(b);
    }
  }
  return [p, b, v];
}

/** The determinant of the 3 x 3 matrix with rows (a, b, c). */
function det3(a0: number, a1: number, a2: number, b0: number, b1: number, b2: number, c0: number, c1: number, c2: number): number {
  return a0 * (b1 * c2 - b2 * c1) - a1 * (b0 * c2 - b2 * c0) + a2 * (b0 * c1 - b1 * c0);
}

/** Solves the 3 x 3 system m x = r (m by rows) by Cramer's rule, or null when it is singular. */
function solve3(m: number[][], r: number[]): number[] | null {
  const [a0, a1, a2] = m[0]!,
    [b0, b1, b2] = m[1]!,
    [c0, c1, c2] = m[2]!;
  const [r0, r1, r2] = r;
  const d = det3(a0!, a1!, a2!, b0!, b1!, b2!, c0!, c1!, c2!);
  if (Math.abs(d) < 1e-12) return null;
  return [
    det3(r0!, a1!, a2!, r1!, b1!, b2!, r2!, c1!, c2!) / d,
    det3(a0!, r0!, a2!, b0!, r1!, b2!, c0!, r2!, c2!) / d,
    det3(a0!, a1!, r0!, b0!, b1!, r1!, c0!, c1!, r2!) / d,
  ];
}

/**
 * Hook height, m, a planned swing lifts the ball to on its way (its centre 2.5 m up, over the
 * rubble and the low stacks) when the plan's time allows (see `hoistProfile`): a ball left low in
 * the rubble of the last hit dragged through it and missed.
 */
/** Seconds before the hit the hook is down at the piece's height by, when the plan's time allows. */
const LEVEL_OFF = 0.3;
export const CRUISE_HEIGHT = Math.min(HOOK_RANGE[1], 2.5 + HANG);

/**
 * The hook's height, m, at time t (s) of a plan of `total` s from `from` to `to` (m) at HOIST_SPEED:
 * up at once toward CRUISE_HEIGHT (or as far toward it as there is time to come down again), held,
 * and down as late as it can to `to` (and level for the last LEVEL_OFF s): a ball lowered late swings
 * over the pieces on its way.
 */
function hoistProfile(from: number, to: number, total: number, t: number): number {
  // Level for the last LEVEL_OFF s when there is time (the ball meets the piece moving across, not down).
  const need = Math.abs(to - from) / HOIST_SPEED;
  total = Math.max(need, total - LEVEL_OFF);
  if (t >= total) return to;
  const top = Math.max(from, to, Math.min(CRUISE_HEIGHT, (HOIST_SPEED * total + from + to) / 2));
  const up = (top - from) / HOIST_SPEED,
    down = total - (top - to) / HOIST_SPEED;
  if (t <= up) return from + HOIST_SPEED * t;
  if (t <= down) return top;
  return Math.max(to, top - HOIST_SPEED * (t - down));
}

/** A swing being planned (`CraneControls.swing`): what it aims at and how far it has gone. */
export interface SwingAim {
  /** The piece tapped. */
  piece: number;
  /** Where the hook ends, over the piece (m, x and z), and its height there, m. */
  x: number;
  z: number;
  height: number;
  /** The ball's horizontal velocity at the piece, m/s. */
  vx: number;
  vz: number;
  /** Steps of PLAN_H s the plan takes in all, has done, and after which its run begins. */
  steps: number;
  done: number;
  runAt: number;
  /** The step at which the plan is made again next (see REPLAN_EVERY). */
  replanAt: number;
  /** Where the hook's follow-through after the hit ends (m, x and z; see FOLLOW_SPEED). */
  followX: number;
  followZ: number;
}

/** Where the plan starts: the ball's horizontal position and velocity and the hook's position (m, m/s). */
interface PlanStart {
  bx: number;
  bz: number;
  vx: number;
  vz: number;
  hx: number;
  hz: number;
}

/** Legs of a plan: the hook's velocity (m/s, x and z) on each and their lengths in PLAN_H steps. */
interface Legs {
  ux: number[];
  uz: number[];
  steps: number[];
}

/**
 * What the legs of a plan from `s` over `steps` solve against, whatever the arrival asked: the
 * 3 x 3 matrix (by rows) of the final hook position, ball position and ball velocity per unit leg
 * velocity (`pendulumAxis` from rest, one leg at 1 m/s), and the final [p, b, v] of each axis with
 * the hook held still. The model is linear, so the legs for any arrival follow from these.
 */
interface LegBasis {
  steps: number[];
  m: number[][];
  fx: [number, number, number];
  fz: [number, number, number];
}

/** The LegBasis of a plan from `s` over `steps` (see LegBasis). */
function legBasis(s: PlanStart, steps: number[]): LegBasis {
  const unit = [0, 1, 2].map((i) =>
    pendulumAxis(
      0,
      0,
      0,
      [0, 1, 2].map((j) => (i === j ? 1 : 0)),
      steps,
    ),
  );
  return {
    steps,
    m: [unit.map((r) => r[0]), unit.map((r) => r[1]), unit.map((r) => r[2])],
    fx: pendulumAxis(s.bx, s.vx, s.hx, [0, 0, 0], steps),
    fz: pendulumAxis(s.bz, s.vz, s.hz, [0, 0, 0], steps),
  };
}

/**
 * The legs that take the hook to (ex, ez) over the basis' steps while the ball comes there too,
 * moving at (wx, wz) m/s: a 3 x 3 linear system per axis on the basis (`legBasis`). Null when singular.
 */
function solveLegs(basis: LegBasis, ex: number, ez: number, wx: number, wz: number): Legs | null {
  const { m, fx, fz, steps } = basis;
  const ux = solve3(m, [ex - fx[0], ex - fx[1], wx - fx[2]]),
    uz = solve3(m, [ez - fz[0], ez - fz[1], wz - fz[2]]);
  return ux === null || uz === null ? null : { ux, uz, steps };
}

/** Whether legs from (hx, hz) keep the hook within the jib's reach and `rate` times the crane's slew and trolley rates. */
function legsFeasible(hx: number, hz: number, legs: Legs, rate: number): boolean {
  let x = hx,
    z = hz;
  for (let i = 0; i < legs.steps.length; i++) {
    const len = legs.steps[i]! * PLAN_H,
      ux = legs.ux[i]!,
      uz = legs.uz[i]!;
    for (let s = 0; s <= 4; s++) {
      const px = x + (ux * len * s) / 4,
        pz = z + (uz * len * s) / 4;
      const r = Math.hypot(px, pz);
      if (r < RADIUS_RANGE[0] - 0.05 || r > RADIUS_RANGE[1] + 0.05) return false;
      const radial = (ux * px + uz * pz) / r,
        across = Math.abs(ux * pz - uz * px) / r;
      if (Math.abs(radial) > rate * TROLLEY_SPEED || across > rate * SLEW_RATE * r) return false;
    }
    x += ux * len;
    z += uz * len;
  }
  return true;
}

/**
 * Whether the ball, on legs `legs` from `s`, stays within `limit` (m) of under the hook (the model's
 * pendulum is linear: past MAX_OFFSET the chain's ball rises and lags and the plan misses).
 */
function offsetWithin(s: PlanStart, legs: Legs, limit: number): boolean {
  // pendulumAxis on both axes in step, the ball checked against the hook every fourth step.
  const w2 = (2 * Math.PI) ** 2 / SWING_PERIOD ** 2,
    c = 1 / SWAY_DAMPING_TIME,
    h = PLAN_H;
  let bx = s.bx,
    vx = s.vx,
    px = s.hx,
    bz = s.bz,
    vz = s.vz,
    pz = s.hz,
    k = 0;
  for (let i = 0; i < legs.steps.length; i++) {
    const ux = legs.ux[i]!,
      uz = legs.uz[i]!;
    for (let j = 0; j < legs.steps[i]!; j++, k++) {
      px += ux * h;
      vx += (w2 * (px - bx) - c * vx) * h;
      bx += vx * h;
      pz += uz * h;
      vz += (w2 * (pz - bz) - c * vz) * h;
      bz += vz * h;
      if (k % 4 === 0 && Math.hypot(bx - px, bz - pz) > limit) return false;
    }
  }
  return true;
}

/** The ball's and hook's state now, for a plan. */
function planStart(world: PhysicsWorld, h: WreckingBallHandles): PlanStart {
  const P = world.components.Position,
    V = world.components.Velocity,
    b = h.ball;
  const [hx, , hz] = hookPosition(h.crane);
  return { bx: P.x[b]!, bz: P.z[b]!, vx: V.x[b]!, vz: V.z[b]!, hx, hz };
}

/**
 * The timed moves of legs `legs` from (hx, hz), the rest of swing `aim` (from its step `aim.done`),
 * the hook's height from `hy` on `hoistProfile`: moves of MOVE_STEPS steps at most, cut where a leg
 * ends and where the run begins; the moves from `aim.runAt` on are the run, the first of them
 * releases it (when it is still to come).
 */
function legMoves(hx: number, hy: number, hz: number, legs: Legs, aim: SwingAim): CraneMove[] {
  const moves: CraneMove[] = [];
  const left = aim.steps - aim.done;
  let x = hx,
    z = hz,
    k = 0;
  for (let i = 0; i < legs.steps.length; i++) {
    const end = k + legs.steps[i]!;
    while (k < end) {
      const step = aim.done + k;
      let next = Math.min(end, k + MOVE_STEPS);
      if (step < aim.runAt && aim.done + next > aim.runAt) next = aim.runAt - aim.done;
      const dt = (next - k) * PLAN_H;
      x += legs.ux[i]! * dt;
      z += legs.uz[i]! * dt;
      k = next;
      const run = step >= aim.runAt;
      moves.push({
        angle: Math.atan2(-z, x),
        radius: Math.hypot(x, z),
        height: hoistProfile(hy, aim.height, left * PLAN_H, k * PLAN_H),
        duration: dt,
        elapsed: 0,
        run,
        release: step === aim.runAt,
      });
    }
  }
  // The follow-through: on past the structure at FOLLOW_SPEED, at the hit's height.
  const d = Math.hypot(aim.followX - aim.x, aim.followZ - aim.z);
  if (d > 1e-6)
    moves.push({
      angle: Math.atan2(-aim.followZ, aim.followX),
      radius: Math.hypot(aim.followX, aim.followZ),
      height: aim.height,
      duration: d / FOLLOW_SPEED,
      elapsed: 0,
      run: true,
      follow: true,
    });
  return moves;
}

/**
 * The standing pieces of piece `piece`'s structure: those whose start centres lie within
 * STRUCTURE_RADIUS of its start centre, across the ground (itself among them).
 */
export function structureOf(pieces: readonly Piece[], piece: Piece): Piece[] {
  return pieces.filter((q) => !q.fallen && Math.hypot(q.x0 - piece.x0, q.z0 - piece.z0) < STRUCTURE_RADIUS);
}

/** How far box piece `p` reaches from its centre along the horizontal unit direction (ux, uz), m. */
function reachAlong(p: Piece, ux: number, uz: number): number {
  const c = Math.cos(p.yaw),
    s = Math.sin(p.yaw);
  // The box's own x axis is (cos yaw, -sin yaw) across the ground, its z axis (sin yaw, cos yaw).
  return p.half[0] * Math.abs(ux * c - uz * s) + p.half[2] * Math.abs(ux * s + uz * c);
}

/**
 * Swings the ball at piece `piece` with timed moves (`CraneControls.moves`) planned on a pendulum
 * model of the ball and its chain (`pendulumAxis`, linear, with the ball's drag): the hook runs
 * three straight legs at constant velocities, chosen (a 3 x 3 linear system per horizontal axis) so
 * that at the plan's end the hook is over the piece and the ball is there too, at the piece's
 * height, moving at HIT_SPEED toward it from one of APPROACH_DIRECTIONS directions. Whatever the
 * ball was doing at the tap (hanging still, or swinging from the last hit) is the model's start, so
 * no time goes on waiting for a swing to die down. For each direction the plan is the quickest (of
 * PLAN_TIME_RANGE in steps of PLAN_TIME_STEP, each shared among the legs as LEG_SPLITS) whose legs
 * keep within the jib's reach, PLAN_RATE times the crane's slew and trolley rates and its hoist
 * rate; of those, the one of the lowest cost: its time, up to GLANCE_COST s for meeting a long piece
 * along its length rather than square to it, 3 s for each piece the ball would
 * meet in the last APPROACH_TIME before it reaches the piece tapped, 1 s for each one earlier and
 * 20 s for passing the mast, and REACH_COST s a metre for a follow-through past the jib's reach.
 * The ball strikes at the piece's height, but no higher than STRIKE_SHARE of its structure's
 * (`structureOf`), across the ground at the piece in a wall and at the middle of a stack or a tower. The last leg is the swing's run (`CraneMove.run`; its first move releases it);
 * after the hit the hook follows through (FOLLOW_SPEED), so the ball swings on through the structure
 * and comes to rest past it. `craneSystem` makes the plan again from where the ball is every
 * REPLAN_EVERY s. With `request` (the player's swing) the swing is as aimed: the ball arrives at
 * request.speed instead of HIT_SPEED, from the quickest direction within AIM_FREE of
 * request.direction, else the nearest the crane can swing it (AIM_COST), at the piece's own height
 * (no STRIKE_SHARE), with no cost for a glancing blow or for pieces in its way (it strikes them); without it, from the
 * direction of the lowest cost (the level scripts' and ?demo's swings). Throws a RangeError for a request
 * whose direction is not finite or whose speed is outside (0, 2 HIT_SPEED].
 */
export function aimAt(world: PhysicsWorld, h: WreckingBallHandles, piece: number, request?: SwingRequest): void {
  if (
    request !== undefined &&
    !(Number.isFinite(request.direction) && Number.isFinite(request.speed) && request.speed > 0 && request.speed <= 2 * HIT_SPEED)
  )
    throw new RangeError(
      `aimAt: request needs a finite direction and a speed in (0, ${2 * HIT_SPEED}] m/s, got ${JSON.stringify(request)}`,
    );
  const speed = request?.speed ?? HIT_SPEED;
  const P = world.components.Position;
  const { tapped, structure, tx, tz } = strikeSpot(world, h, piece);
  // The ball's centre at the piece's height, never lower than skimming the ground. The player's
  // swing (a request) strikes the piece chosen where it is: at a tower's top it knocks off the top,
  // at its foot it brings down what stands on it, so where the player aims is the skill. A swing
  // planned for them (no request) strikes no higher than STRIKE_SHARE of the structure's height.
  let top = 0;
  for (const q of structure) top = Math.max(top, P.y[q.body]! + q.half[1]);
  const pieceY = P.y[piece]!;
  const ballY = Math.max(BALL_RADIUS + 0.05, request ? pieceY : Math.min(pieceY, STRIKE_SHARE * top || pieceY));
  const height = Math.min(HOOK_RANGE[1], Math.max(HOOK_RANGE[0], ballY + HANG));
  // The hook ends over the piece, pulled into the jib's reach.
  const r0 = Math.min(RADIUS_RANGE[1], Math.max(RADIUS_RANGE[0], Math.hypot(tx, tz)));
  const a0 = Math.atan2(-tz, tx);
  const ex = r0 * Math.cos(a0),
    ez = -r0 * Math.sin(a0);
  const hy = h.crane.height;
  const start = planStart(world, h);
  // A ball already swinging wider than MAX_OFFSET (a drag let go) may swing as wide as it does.
  const limit = Math.max(MAX_OFFSET, 1.05 * swayAmplitude(world, h));
  const hoistTime = Math.abs(height - hy) / HOIST_SPEED;
  // For each direction, the quickest plan.
  const best: Array<Legs | null> = new Array(APPROACH_DIRECTIONS).fill(null);
  let left = APPROACH_DIRECTIONS;
  for (let time = PLAN_TIME_RANGE[0]; time <= PLAN_TIME_RANGE[1] + 1e-9 && left > 0; time += PLAN_TIME_STEP) {
    if (time < hoistTime) continue;
    for (const split of LEG_SPLITS) {
      const basis = legBasis(
        start,
        split.map((f) => Math.round((f * time) / PLAN_H)),
      );
      for (let d = 0; d < APPROACH_DIRECTIONS; d++) {
        if (best[d] !== null) continue;
        const t = (2 * Math.PI * d) / APPROACH_DIRECTIONS;
        const legs = solveLegs(basis, ex, ez, speed * Math.cos(t), speed * Math.sin(t));
        if (legs === null || !legsFeasible(start.hx, start.hz, legs, PLAN_RATE) || !offsetWithin(start, legs, limit)) continue;
        best[d] = legs;
        left--;
      }
    }
  }
  // The cost of each direction's plan: its time, how square it meets the piece, what the ball
  // would meet on its way there and whether its follow-through stays in the jib's reach.
  const reach = BALL_RADIUS + Math.max(...(tapped?.half ?? [0.3])) + 0.05;
  // (A stack is struck at its middle, where its layers cross: square to one or the other.)
  const long: [number, number] | null =
    tapped && tapped.kind === 'wall' && Math.max(tapped.half[0], tapped.half[2]) > 1.5 * Math.min(tapped.half[0], tapped.half[2])
      ? tapped.half[0] > tapped.half[2]
        ? [Math.cos(tapped.yaw), -Math.sin(tapped.yaw)]
        : [Math.sin(tapped.yaw), Math.cos(tapped.yaw)]
      : null;
  let chosen = -1,
    chosenCost = Number.POSITIVE_INFINITY;
  const follow: Array<[number, number]> = best.map((_, d) => followEnd(world, structure, ex, ez, tx, tz, d));
  best.forEach((legs, d) => {
    if (legs === null) return;
    const pathX: number[] = [],
      pathZ: number[] = [];
    pendulumAxis(start.bx, start.vx, start.hx, legs.ux, legs.steps, pathX);
    pendulumAxis(start.bz, start.vz, start.hz, legs.uz, legs.steps, pathZ);
    const time = pathX.length * PLAN_H;
    // A long piece (a brick, a plank) is knocked from its place by a ball square to its length; one
    // along it only glances off its end: up to GLANCE_COST s more for a ball along it.
    const t = (2 * Math.PI * d) / APPROACH_DIRECTIONS;
    // (Not for the player's swing: a ball sent along a wall glances off it, as aimed.)
    let cost = time + (long && !request ? GLANCE_COST * Math.abs(Math.cos(t) * long[0] + Math.sin(t) * long[1]) : 0);
    // The player's direction: the feasible one nearest it, whatever the others would cost.
    if (request)
      cost += AIM_COST * Math.max(0, Math.abs(Math.atan2(Math.sin(t - request.direction), Math.cos(t - request.direction))) - AIM_FREE);
    const [fx, fz] = follow[d]!,
      fr = Math.hypot(fx, fz);
    cost += REACH_COST * (Math.max(0, fr - RADIUS_RANGE[1]) + Math.max(0, RADIUS_RANGE[0] - fr));
    const approach = pathX.length - Math.round(APPROACH_TIME / PLAN_H);
    const met = new Set<number>();
    for (let k = 0; k < pathX.length; k += 6) {
      const x = pathX[k]!,
        z = pathZ[k]!;
      const y = hoistProfile(hy, height, time, k * PLAN_H) - HANG;
      if (Math.hypot(x - tx, y - ballY, z - tz) < reach) break;
      if (Math.hypot(x, z) < 0.4 + BALL_RADIUS + 0.1) cost += 20;
      for (const q of h.pieces) {
        if (q.body === piece || met.has(q.body)) continue;
        // (Not for the player's swing: a structure left in the arrow's way is struck first, as aimed.)
        if (!request && Math.hypot(P.x[q.body]! - x, P.y[q.body]! - y, P.z[q.body]! - z) < BALL_RADIUS + Math.max(...q.half) + 0.05) {
          met.add(q.body);
          cost += k >= approach ? 3 : 1;
        }
      }
    }
    if (cost < chosenCost) {
      chosenCost = cost;
      chosen = d;
    }
  });
  h.controls.goal = null;
  h.controls.pull = null;
  const legs = best[chosen];
  if (legs === undefined || legs === null) {
    // No plan within the crane's rates (not met inside the jib's reach): straight to the piece.
    h.controls.swing = null;
    h.controls.moves = [
      { angle: Math.atan2(-ez, ex), radius: r0, height, duration: SWING_PERIOD / 2, elapsed: 0, run: true, release: true },
    ];
    return;
  }
  const dir = (2 * Math.PI * chosen) / APPROACH_DIRECTIONS;
  const steps = legs.steps[0]! + legs.steps[1]! + legs.steps[2]!;
  const aim: SwingAim = {
    piece,
    x: ex,
    z: ez,
    height,
    vx: speed * Math.cos(dir),
    vz: speed * Math.sin(dir),
    steps,
    done: 0,
    runAt: steps - legs.steps[2]!,
    replanAt: Math.round(REPLAN_EVERY / PLAN_H),
    followX: follow[chosen]![0],
    followZ: follow[chosen]![1],
  };
  h.controls.swing = aim;
  h.controls.moves = legMoves(start.hx, hy, start.hz, legs, aim);
}

/**
 * Where the follow-through of a swing from direction `d` (of APPROACH_DIRECTIONS) ends: from the
 * hook's end (ex, ez) on along the approach, as far past the piece at (tx, tz) as `structure`
 * reaches beyond it along the approach plus the ball's radius and FOLLOW_CLEAR, m.
 */
function followEnd(
  world: PhysicsWorld,
  structure: readonly Piece[],
  ex: number,
  ez: number,
  tx: number,
  tz: number,
  d: number,
): [number, number] {
  const P = world.components.Position;
  const t = (2 * Math.PI * d) / APPROACH_DIRECTIONS,
    ux = Math.cos(t),
    uz = Math.sin(t);
  let far = 0;
  for (const q of structure) far = Math.max(far, (P.x[q.body]! - tx) * ux + (P.z[q.body]! - tz) * uz + reachAlong(q, ux, uz));
  const past = far + BALL_RADIUS + FOLLOW_CLEAR;
  return [ex + past * ux, ez + past * uz];
}

/**
 * Makes the running swing's plan again from where the ball and hook are now, for the same arrival
 * (step, place and velocity): of LEG_SPLITS over the time left, the legs with the lowest top speed
 * within PLAN_RATE times the crane's rates (and a tenth more: the model's error is what is being
 * made up). Keeps the moves as they are when none is.
 */
function replan(world: PhysicsWorld, h: WreckingBallHandles, aim: SwingAim): void {
  const left = aim.steps - aim.done;
  const start = planStart(world, h);
  const limit = Math.max(MAX_OFFSET, 1.05 * swayAmplitude(world, h));
  let chosen: Legs | null = null,
    top = Number.POSITIVE_INFINITY;
  for (const split of LEG_SPLITS) {
    const steps = split.map((f) => Math.round(f * left));
    steps[2] = left - steps[0]! - steps[1]!;
    const legs = solveLegs(legBasis(start, steps), aim.x, aim.z, aim.vx, aim.vz);
    if (legs === null || !legsFeasible(start.hx, start.hz, legs, 1.1 * PLAN_RATE) || !offsetWithin(start, legs, limit)) continue;
    const fastest = Math.max(...legs.ux.map((u, i) => Math.hypot(u, legs.uz[i]!)));
    if (fastest < top) {
      top = fastest;
      chosen = legs;
    }
  }
  if (chosen !== null) h.controls.moves = legMoves(start.hx, h.crane.height, start.hz, chosen, aim);
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

/**
 * The tagline of the player's swing (`CraneControls.pull`, see `pullBack`): the hook's goal over
 * the piece, how far back along the ball's travel the line draws the ball from under the hook,
 * and whether the player has let go.
 */
export interface PullBack {
  /** The piece aimed at. */
  piece: number;
  /** Where the hook goes (m, x and z): over the strike point; its height there, m. */
  x: number;
  z: number;
  height: number;
  /** The ball's travel across the ground as it meets the piece, unit vector (x, z). */
  ux: number;
  uz: number;
  /** How far across the ground, m, the line draws the ball back from under the hook (0: paying out, no swing). */
  offset: number;
  /**
   * The way the line draws the ball now, unit vector (x, z): the ball is held `offset` back from
   * under the hook against it. It turns toward (ux, uz) at DRAW_TURN rad/s at most, so a drag swept
   * round carries the ball round the hook at the line's length, not straight across through the
   * structure beneath; the line slips only once it is (ux, uz).
   */
  dx: number;
  dz: number;
  /** Whether the player let go: the line slips as soon as the hook and the ball are in place (`pullReady`). */
  letGo: boolean;
  /** Seconds the ball has been held up (nearly still) since the player let go with the hook in place (see PULL_WAIT). */
  waited: number;
  /** Whether it re-aims a swing already let go whose run has not begun (the same swing, aimed anew). */
  again: boolean;
  /** Where the follow-through after the hit takes the hook (m, x and z; see FOLLOW_SPEED). */
  followX: number;
  followZ: number;
}
/**
 * Stiffness of the tagline's pull, as the frequency (Hz) of the ball's critically damped approach
 * to where it is drawn: it settles in about half a second, and a ball still moving when let go would
 * swing off its arc.
 */
const PULL_HERTZ = 2;
/**
 * Largest acceleration, m/s^2, the tagline gives the ball across the ground (a winch's pull on 5 t):
 * enough to draw the ball the 3 m back from under the hook in about half a second.
 */
const PULL_ACCEL = 20;
/**
 * Top speed, m/s, and acceleration, m/s^2, of the hook across the ground while the line holds the
 * ball: what the line can carry the 5 t ball along at without it flying out on its chain (at the
 * planned swings' 2.5 times the crane's rates the ball swung out level with the hook) or touching
 * a piece on its way (wrecking-ball-pull.test.ts counts none).
 */
const PULL_HOOK_SPEED = 6;
const PULL_HOOK_ACCEL = 8;
/**
 * Seconds after the player let go, with the hook in place and the ball held up (nearly still short
 * of where it is drawn: against a piece), that the line slips: the swing goes from where the ball is.
 */
const PULL_WAIT = 0.3;
/** Seconds after the player let go, with the hook in place but held up over a piece beside the drawn-back ball, that the line slips from there. */
const PULL_STUCK = 2;
/**
 * Distance across the ground, m, from the hook's goal within which it lets the ball down from
 * CRUISE_HEIGHT and the line starts drawing it back: both then overlap the rest of the hook's run.
 */
const PULL_LOWER = 3.5;
/**
 * Nearest, m, a held ball's centre or its chain comes to the mast's axis: the mast's corner (0.57 m)
 * and the ball's radius with room, so the ball is never drawn into the mast nor the chain across it.
 */
const MAST_CLEAR = 1.4;
/** How near, m and m/s, the ball must be to where it is drawn, and how still, for the line to slip. */
const READY_NEAR = 0.4;
const READY_STILL = 1;

/**
 * Draws the ball back for the player's swing at piece `piece`: the hook runs over the strike point
 * (the piece in a wall, the middle of a stack or a tower, at the piece's height; within the jib's
 * reach) and a tagline draws the ball back along its chain's arc, opposite `request.direction`, as
 * far as a pendulum let go from rest needs to pass under the hook at `request.speed` (`offset`: L
 * sin theta with v^2 = 2 g L (1 - cos theta)), or less so that neither the ball nor its chain comes
 * within MAST_CLEAR of the mast. Once let go (`letGoPull`) the line slips when all is in place, and
 * the ball swings down from there under gravity alone, meeting the piece about a quarter of its
 * swing later (SWING_PERIOD / 4, 1.1 s); the hook then follows through as a planned swing's does.
 * Called again as the player drags, it sets the new goal and draw (not yet let go). Drops any planned
 * moves or goal.
 */
export function pullBack(world: PhysicsWorld, h: WreckingBallHandles, piece: number, request: SwingRequest): void {
  const {
    goal: { x, z, height, ux, uz, offset },
    structure,
    tx,
    tz,
  } = swingSetup(world, h, piece, request);
  const d = Math.round(((request.direction / (2 * Math.PI)) * APPROACH_DIRECTIONS + APPROACH_DIRECTIONS) % APPROACH_DIRECTIONS);
  const [followX, followZ] = followEnd(world, structure, x, z, tx, tz, d);
  const old = h.controls.pull;
  const again = old !== null && old.offset > 0 && (old.letGo || old.again);
  const dx = old === null ? ux : old.dx,
    dz = old === null ? uz : old.dz;
  h.controls.pull = { piece, x, z, height, ux, uz, offset, dx, dz, letGo: false, waited: 0, again, followX, followZ };
  h.controls.moves = [];
  h.controls.swing = null;
  h.controls.goal = null;
}

/** Lets the tagline go (the swing goes as soon as the ball is in place); nothing without one. */
export function letGoPull(h: WreckingBallHandles): void {
  if (h.controls.pull !== null) h.controls.pull.letGo = true;
}

/** Pays the tagline out with no swing: the hook stays, the ball is let down under it, then the line is gone. */
export function dropPull(h: WreckingBallHandles): void {
  const pull = h.controls.pull;
  if (pull === null) return;
  [pull.x, pull.height, pull.z] = hookPosition(h.crane);
  pull.offset = 0;
  pull.letGo = true;
}

/**
 * Where a swing at `piece` strikes across the ground (tx, tz, m): the piece itself in a wall (a brick
 * along it), else the middle of its plank stack or tower, so a plank tapped at the stack's edge is not
 * only glanced off. Also the piece's record (undefined if `piece` is no piece) and its structure.
 */
function strikeSpot(
  world: PhysicsWorld,
  h: WreckingBallHandles,
  piece: number,
): { tapped: Piece | undefined; structure: Piece[]; tx: number; tz: number } {
  const P = world.components.Position;
  const tapped = h.pieces.find((q) => q.body === piece);
  const structure = tapped ? structureOf(h.pieces, tapped) : [];
  let tx = P.x[piece]!,
    tz = P.z[piece]!;
  if (tapped && tapped.kind !== 'wall' && structure.length > 0) {
    tx = structure.reduce((a, q) => a + P.x[q.body]!, 0) / structure.length;
    tz = structure.reduce((a, q) => a + P.z[q.body]!, 0) / structure.length;
  }
  return { tapped, structure, tx, tz };
}

/** Nearest distance, m, across the ground from the mast's axis to the segment from (ax, az) to (bx, bz). */
export function segmentToAxis(ax: number, az: number, bx: number, bz: number): number {
  const dx = bx - ax,
    dz = bz - az,
    l2 = dx * dx + dz * dz;
  const t = l2 < 1e-12 ? 0 : Math.min(1, Math.max(0, -(ax * dx + az * dz) / l2));
  return Math.hypot(ax + t * dx, az + t * dz);
}

/**
 * One substep of the tagline (`CraneControls.pull`): the hook closes on its goal (at PULL_GAIN,
 * within PLAN_RATE times the crane's slew and trolley rates and its hoist rate), the line pulls the
 * ball across the ground toward `offset` back from under the hook (a critically damped spring of
 * PULL_HERTZ, with the chain's pull at that angle made up, at most PULL_ACCEL); once let go and
 * in place (`pullReady`), the line slips: the swing's run begins (a hold while the ball swings down
 * through the piece, then the follow-through), or with no offset, the line is simply gone.
 */
function pullStep(world: PhysicsWorld, h: WreckingBallHandles, pull: PullBack, dt: number): void {
  const c = h.crane;
  const [hx, , hz] = hookPosition(c);
  const [gx, , gz] = hookPosition({ angle: Math.atan2(-pull.z, pull.x), radius: Math.hypot(pull.x, pull.z), height: pull.height });
  const P = world.components.Position,
    b = h.ball;
  // Far from its goal the hook carries the ball high (CRUISE_HEIGHT), and lets it down to the
  // strike's height over the last PULL_LOWER m; never lower than keeps the ball over every piece
  // between where it is and where it goes (its next stop: under the goal, or drawn back from it).
  const far = Math.hypot(hx - gx, hz - gz) > PULL_LOWER;
  const to = far ? [gx, gz] : [gx - pull.offset * pull.dx, gz - pull.offset * pull.dz];
  const over = carryHeight(world, h.pieces, P.x[b]!, P.z[b]!, to[0]!, to[1]!, far ? CARRY_SIDE : CARRY_NEAR_SIDE);
  const want = Math.max(far ? Math.max(pull.height, CRUISE_HEIGHT) : pull.height, over);
  // In place at the height that keeps the ball clear (the strike's, or over a piece beside the
  // drawn-back ball: the swing then goes from there).
  const inPlace = Math.hypot(hx - gx, hz - gz) < 0.05 && Math.abs(c.height - want) < 0.1;
  const atStrike = Math.abs(c.height - pull.height) < 0.1;
  // The wait counts once the line draws the ball the way the swing goes (see turnDraw), and only
  // while the ball is held up (nearly still past the hook): one still on its way to where it is
  // drawn would swing from short of there, not along the swing drawn for the player.
  const V = world.components.Velocity;
  const held = Math.hypot(V.x[b]! - V.x[h.trolley]!, V.z[b]! - V.z[h.trolley]!) < READY_STILL;
  if (pull.letGo && inPlace && held && pull.dx * pull.ux + pull.dz * pull.uz > DRAWN_COS) pull.waited += dt;
  if (pull.letGo && inPlace && ((atStrike && (pullReady(world, h, pull, want) || pull.waited > PULL_WAIT)) || pull.waited > PULL_STUCK)) {
    h.controls.pull = null;
    if (pull.offset === 0) return;
    const hold = SWING_PERIOD / 4 + 0.4;
    h.controls.moves = [
      { angle: c.angle, radius: c.radius, height: c.height, duration: hold, elapsed: 0, run: true, release: true },
      {
        angle: Math.atan2(-pull.followZ, pull.followX),
        radius: Math.min(RADIUS_RANGE[1], Math.max(RADIUS_RANGE[0], Math.hypot(pull.followX, pull.followZ))),
        height: c.height,
        duration: Math.max(0.1, Math.hypot(pull.followX - hx, pull.followZ - hz) / FOLLOW_SPEED),
        elapsed: 0,
        run: true,
        follow: true,
      },
    ];
    return;
  }
  // Slew and trolley each on a braking profile (speeding up at PULL_HOOK_ACCEL, slowing to stop at
  // the goal), the slew's rates those of the hook across the ground at its radius; braking to a
  // stop while the hook is too low to carry the ball over what lies ahead.
  // A way across that passes over a structure too tall to carry the ball over (a tall tower's top
  // above the ball at the hook's highest) goes round it: the trolley runs in toward the mast, the jib
  // slews only once its arc at that radius is clear, and the trolley runs out under the goal.
  const r = Math.max(RADIUS_RANGE[0], c.radius);
  const low = c.height < over - CARRY_SLACK;
  const goalAngle = Math.atan2(-pull.z, pull.x),
    goalRadius = Math.hypot(pull.x, pull.z);
  const turn = wrap(goalAngle - c.angle);
  let slewTo = turn,
    runTo = goalRadius - c.radius;
  if (far && Math.abs(turn) > TUCK_TURN && sweepBlocked(world, h.pieces, c.angle, c.radius, goalAngle, goalRadius)) {
    runTo = RADIUS_RANGE[0] - c.radius;
    if (sweepBlocked(world, h.pieces, c.angle, c.radius, goalAngle, c.radius)) slewTo = 0;
  }
  h.drive.slew = closeOn(h.drive.slew, low ? 0 : slewTo, PULL_HOOK_SPEED / r, PULL_HOOK_ACCEL / r, dt);
  h.drive.trolley = closeOn(h.drive.trolley, low ? 0 : runTo, PULL_HOOK_SPEED, PULL_HOOK_ACCEL, dt);
  const lift = Math.max(-PULL_HOIST_SPEED * dt, Math.min(PULL_HOIST_SPEED * dt, want - c.height));
  c.angle = wrap(c.angle + h.drive.slew * dt);
  c.radius = Math.min(RADIUS_RANGE[1], Math.max(RADIUS_RANGE[0], c.radius + h.drive.trolley * dt));
  c.height = Math.min(HOOK_RANGE[1], Math.max(HOOK_RANGE[0], c.height + lift));
  const F = world.components.Force,
    M = world.components.Mass;
  const [nx, , nz] = hookPosition(c);
  // On its way the line holds the ball under the hook (drawn back, it swung wide and through what it
  // passed); over the last PULL_LOWER m it draws it back.
  const drawn = far ? 0 : pull.offset;
  // With the hook too low to carry the ball over what lies on its way to where it is drawn, the line
  // holds the ball where it is (it is drawn on as the hook rises).
  if (!low) turnDraw(pull, far, gx - hx, gz - hz, dt);
  const ex = low && !far ? 0 : P.x[b]! - (nx - drawn * pull.dx),
    ez = low && !far ? 0 : P.z[b]! - (nz - drawn * pull.dz);
  const w = 2 * Math.PI * PULL_HERTZ;
  // The chain's pull toward under the hook at the drawn angle, g d / sqrt(L^2 - d^2), made up.
  const hold = (9.81 * drawn) / Math.sqrt(HANG * HANG - drawn * drawn);
  let ax = -w * w * ex - 2 * w * (V.x[b]! - (nx - hx) / dt) - hold * pull.dx,
    az = -w * w * ez - 2 * w * (V.z[b]! - (nz - hz) / dt) - hold * pull.dz;
  const a = Math.hypot(ax, az);
  if (a > PULL_ACCEL) {
    ax *= PULL_ACCEL / a;
    az *= PULL_ACCEL / a;
  }
  // The line's brake: the ball never runs faster than HELD_SPEED across the ground past the hook,
  // so one still swinging from the hook's run is caught before it reaches a piece.
  const rx = V.x[b]! - (nx - hx) / dt,
    rz = V.z[b]! - (nz - hz) / dt,
    rv = Math.hypot(rx, rz);
  if (rv > HELD_SPEED) {
    const brake = Math.min(HELD_BRAKE, (rv - HELD_SPEED) / dt) / rv;
    ax -= brake * rx;
    az -= brake * rz;
  }
  const m = 1 / M.inv[b]!;
  F.x[b] = F.x[b]! + m * ax;
  F.z[b] = F.z[b]! + m * az;
}

/** Fastest, m/s, the tagline lets the ball run across the ground past the hook (see pullStep). */
const HELD_SPEED = 5;
/** Largest deceleration, m/s^2, with which the tagline brakes a ball running faster than HELD_SPEED. */
const HELD_BRAKE = 30;

/**
 * Fastest the way the line draws the ball turns about the hook, rad/s (see PullBack.dx): the drawn
 * ball then runs round at most 5 m/s at the line's full length (HELD_SPEED), within what the line's pull
 * (PULL_ACCEL) holds on that circle.
 */
const DRAW_TURN = 1.5;
/** The same once the player has let go (the swing is on its way; nothing is being aimed past the structure). */
const DRAW_TURN_LET_GO = 2.4;
/** Cosine of the angle within which the line draws the ball the swing's way (about 8 degrees): the line may slip. */
const DRAWN_COS = 0.99;

/**
 * Turns the way the line draws the ball (`pull.dx`, `dz`) over `dt` s: while the hook carries the
 * ball under it (`far`), along the hook's way to its goal (gx, gz from the hook, m), so the ball is
 * drawn back from where it trails the hook when the hook comes near; else toward (ux, uz) by
 * DRAW_TURN dt at most (DRAW_TURN_LET_GO once let go).
 */
function turnDraw(pull: PullBack, far: boolean, gx: number, gz: number, dt: number): void {
  const g = Math.hypot(gx, gz);
  if (far && g > 1e-6) {
    pull.dx = gx / g;
    pull.dz = gz / g;
    return;
  }
  const now = Math.atan2(pull.dz, pull.dx),
    turn = wrap(Math.atan2(pull.uz, pull.ux) - now);
  const most = (pull.letGo ? DRAW_TURN_LET_GO : DRAW_TURN) * dt;
  const a = now + Math.max(-most, Math.min(most, turn));
  pull.dx = Math.cos(a);
  pull.dz = Math.sin(a);
}

/** Rate, m/s, the hook is raised and lowered while the tagline holds the ball (three times HOIST_SPEED: it lifts the ball over the pieces on its way without holding the run up long). */
const PULL_HOIST_SPEED = 3 * HOIST_SPEED;
/** Room, m, the carried ball's underside keeps over the top of a piece it passes over. */
const CARRY_CLEAR = 0.3;
/** Room, m, across the ground either side of the carried ball's way (it lags and sways on its chain while the hook runs). */
const CARRY_SIDE = 1;
/** Room, m, across the ground either side of the ball's way as it is drawn back (it lags the line's pull). */
const CARRY_NEAR_SIDE = 0.2;
/** How far, m, the hook may be below the height that carries the ball over what lies ahead and still run on (it rises as it goes). */
const CARRY_SLACK = 0.5;

/** Slew left, rad, under which the hook runs straight to its goal without going round (the way is then mostly in and out along the jib). */
const TUCK_TURN = 0.15;
/** Points along the hook's way at which `sweepBlocked` looks for a structure too tall to carry the ball over. */
const SWEEP_SAMPLES = 16;

/**
 * Whether the hook's way from slew angle a0 at radius r0 to a1 at r1 (both rates at once, as the
 * crane drives: a spiral about the mast) passes within the ball's radius and CARRY_SIDE of a standing
 * piece whose top the ball cannot clear by CARRY_CLEAR even with the hook at its highest (HOOK_RANGE[1]).
 */
function sweepBlocked(world: PhysicsWorld, pieces: Piece[], a0: number, r0: number, a1: number, r1: number): boolean {
  const P = world.components.Position;
  const reachTop = HOOK_RANGE[1] - HANG - BALL_RADIUS - CARRY_CLEAR;
  const turn = wrap(a1 - a0);
  for (const q of pieces) {
    if (q.fallen || P.y[q.body]! + q.half[1] <= reachTop) continue;
    const near = Math.hypot(q.half[0], q.half[2]) + BALL_RADIUS + CARRY_SIDE;
    for (let i = 0; i <= SWEEP_SAMPLES; i++) {
      const f = i / SWEEP_SAMPLES,
        a = a0 + f * turn,
        r = r0 + f * (r1 - r0);
      if (Math.hypot(r * Math.cos(a) - P.x[q.body]!, -r * Math.sin(a) - P.z[q.body]!) < near) return true;
    }
  }
  return false;
}

/**
 * Lowest hook height, m (within HOOK_RANGE; HOOK_RANGE[0] when nothing is in the way), that keeps
 * the ball hanging on its chain CARRY_CLEAR over every standing piece whose top lies within the
 * ball's radius and `side` m of its way across the ground from (ax, az) to (bx, bz) (a piece
 * reaching its half diagonal across the ground and its half height up: it still stands).
 */
function carryHeight(world: PhysicsWorld, pieces: Piece[], ax: number, az: number, bx: number, bz: number, side: number): number {
  const P = world.components.Position;
  let top = Number.NEGATIVE_INFINITY;
  for (const q of pieces) {
    if (q.fallen) continue;
    const reach = Math.hypot(q.half[0], q.half[2]);
    const px = P.x[q.body]!,
      pz = P.z[q.body]!;
    const dx = bx - ax,
      dz = bz - az,
      l2 = dx * dx + dz * dz;
    const t = l2 < 1e-12 ? 0 : Math.min(1, Math.max(0, ((px - ax) * dx + (pz - az) * dz) / l2));
    if (Math.hypot(ax + t * dx - px, az + t * dz - pz) < reach + BALL_RADIUS + side) top = Math.max(top, P.y[q.body]! + q.half[1]);
  }
  return Math.min(HOOK_RANGE[1], Math.max(HOOK_RANGE[0], top + CARRY_CLEAR + BALL_RADIUS + HANG));
}

/**
 * Rate `v` (per s) of a drive `e` short of its goal after the next `dt` s: toward the rate that stops
 * it at the goal at `accel` (sqrt(2 accel e), at most `top`), changing by `accel` dt at most; exactly
 * onto the goal when that is within the step.
 */
function closeOn(v: number, e: number, top: number, accel: number, dt: number): number {
  if (Math.abs(e) <= Math.abs(v) * dt + accel * dt * dt && Math.abs(v) <= 2 * accel * dt + Math.sqrt(2 * accel * Math.abs(e)))
    return e / dt;
  const want = Math.sign(e) * Math.min(top, Math.sqrt(2 * accel * Math.abs(e)));
  return v + Math.max(-accel * dt, Math.min(accel * dt, want - v));
}

/** Whether the hook is at its goal (at crane height `height`) and the ball where the tagline draws it and nearly still: the line may slip. */
function pullReady(world: PhysicsWorld, h: WreckingBallHandles, pull: PullBack, height: number): boolean {
  const [hx, , hz] = hookPosition(h.crane);
  if (Math.hypot(hx - pull.x, hz - pull.z) > 0.08 || Math.abs(h.crane.height - height) > 0.1) return false;
  const P = world.components.Position,
    V = world.components.Velocity,
    b = h.ball;
  const near = Math.hypot(P.x[b]! - (hx - pull.offset * pull.ux), P.z[b]! - (hz - pull.offset * pull.uz));
  return near < READY_NEAR && Math.hypot(V.x[b]! - V.x[h.trolley]!, V.z[b]! - V.z[h.trolley]!) < READY_STILL;
}

/**
 * Rate `v` moved toward `want` over `dt` s: at `accel` while speeding up (from rest or the same
 * way), at `coast` while slowing to a lesser rate the same way or to rest, at `reverse` while `want`
 * is the other way; never past `want`.
 */
function ramp(v: number, want: number, dt: number, accel: number, coast: number, reverse: number): number {
  const rate = v === 0 || (Math.sign(want) === Math.sign(v) && Math.abs(want) > Math.abs(v)) ? accel : want * v < 0 ? reverse : coast;
  const step = rate * dt;
  return Math.abs(want - v) <= step ? want : v + Math.sign(want - v) * step;
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
    const radius0 = c.radius;
    let slew = k.slew,
      run = k.trolley;
    // Whether a run to a goal drives the crane this substep (including the one it arrives in).
    const toGoal = k.goal !== null;
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
    const aim = k.swing;
    if (aim !== null && k.moves.length === 0) k.swing = null;
    else if (aim !== null) {
      if (aim.done >= aim.replanAt && aim.steps - aim.done > REPLAN_UNTIL / PLAN_H) {
        aim.replanAt += Math.round(REPLAN_EVERY / PLAN_H);
        replan(world, h, aim);
      }
      aim.done++;
    }
    const move = k.moves[0];
    const pulling = k.pull !== null && move === undefined && !toGoal;
    if (pulling) {
      pullStep(world, h, k.pull!, dt);
    } else if (move !== undefined) {
      // A timed move: the rest of the way along a straight line at a constant velocity over the
      // time left (`aimAt` plans the hook's velocities), held to the jib's reach.
      // A move ends on the substep that has a substep's time left or less (within a part in a
      // million): summed substeps fall short of the move's duration by rounding, and waiting one
      // more substep for that sliver halted the hook for a substep at the end of every move.
      const left = move.duration - move.elapsed,
        f = left <= dt * (1 + 1e-6) ? 1 : dt / left;
      if (move.release === true && move.elapsed === 0) k.released++;
      const [gx, , gz] = hookPosition(move);
      const x = before[0] + f * (gx - before[0]),
        z = before[2] + f * (gz - before[2]);
      c.angle = Math.atan2(-z, x);
      c.radius = Math.min(RADIUS_RANGE[1], Math.max(RADIUS_RANGE[0], Math.hypot(x, z)));
      c.height += f * (move.height - c.height);
      move.elapsed += dt;
      if (f === 1) k.moves.shift();
    } else {
      let slewRate = slew * SLEW_RATE,
        runRate = run * TROLLEY_SPEED;
      if (!toGoal) {
        // The player's drive: ramped toward the rate asked (see SLEW_ACCEL).
        h.drive.slew = ramp(h.drive.slew, slewRate, dt, SLEW_ACCEL, SLEW_COAST, SLEW_REVERSE);
        h.drive.trolley = ramp(h.drive.trolley, runRate, dt, TROLLEY_ACCEL, TROLLEY_COAST, TROLLEY_REVERSE);
        slewRate = h.drive.slew;
        runRate = h.drive.trolley;
      }
      if (k.steady && !toGoal) {
        // Anti-sway: the hook's velocity STEADY_GAIN times the ball's offset from under it, as
        // slew and trolley rates (radial along the jib, tangential over the radius), added to
        // the drive's and held to the crane's; not ramped (the crane's own control, not the player's).
        const P = world.components.Position,
          b = h.ball;
        const ex = P.x[b]! - before[0],
          ez = P.z[b]! - before[2];
        const ca = Math.cos(c.angle),
          sa = Math.sin(c.angle);
        // Radial unit (ca, -sa); the direction of growing slew angle (-sa, -ca).
        const radial = STEADY_GAIN * (ex * ca - ez * sa),
          tangential = STEADY_GAIN * (-ex * sa - ez * ca);
        runRate = Math.max(-TROLLEY_SPEED, Math.min(TROLLEY_SPEED, runRate + radial));
        slewRate = Math.max(-SLEW_RATE, Math.min(SLEW_RATE, slewRate + tangential / c.radius));
      }
      c.angle = wrap(c.angle + slewRate * dt);
      c.radius = Math.min(RADIUS_RANGE[1], Math.max(RADIUS_RANGE[0], c.radius + runRate * dt));
      c.height = Math.min(HOOK_RANGE[1], Math.max(HOOK_RANGE[0], c.height + k.hoist * HOIST_SPEED * dt));
      // A trolley held at the jib's end stops there.
      if (c.radius === RADIUS_RANGE[0] || c.radius === RADIUS_RANGE[1]) h.drive.trolley = (c.radius - radius0) / dt;
    }
    // A timed move or a run to a goal drives the crane and stops it dead at its end (the ball swings
    // on through; see `goal`): the player's drive starts from rest after it.
    if (move !== undefined || toGoal) h.drive.slew = h.drive.trolley = 0;
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

/** Samples along a swing that `pieceOnSwing` looks for pieces at. */
const SWING_SAMPLES = 40;
/**
 * How far past the hook, as a share of how far the ball was pulled from under it, `pieceOnSwing`
 * follows the swing: beyond it the ball is slowing to its turn (at 0.75 of the way it still has
 * sqrt(1 - 0.75^2), two thirds, of its top speed) and a piece it reaches is only nudged.
 */
export const SWING_REACH = 0.75;

/**
 * The first standing piece the ball at `ball` (m) meets when let go from rest under a hook held
 * still at `hook` (m): as a pendulum of length HANG it swings along the line from where it is
 * through the point under the hook, SWING_REACH as far past it, its centre sqrt(HANG^2 - d^2) under
 * the hook at d across the ground from it; a piece is met where its box (as built, turned about the
 * vertical by its yaw, where its centre is now) comes within the ball's radius of the ball's centre.
 * @returns its body, or 0 when the swing meets none.
 */
export function pieceOnSwing(world: PhysicsWorld, pieces: readonly Piece[], ball: ArrayLike<number>, hook: ArrayLike<number>): number {
  return swingPath(world, pieces, ball, hook);
}

/**
 * The swing of `pieceOnSwing` traced: fills `path` (when given) with the ball centre's places along
 * it, x, y, z in turn (m; SWING_SAMPLES + 1 at most), from where it is let go to where it first
 * meets a standing piece (that place the last), or to SWING_REACH past the hook when it meets none.
 * @returns the piece met first, or 0.
 */
export function swingPath(
  world: PhysicsWorld,
  pieces: readonly Piece[],
  ball: ArrayLike<number>,
  hook: ArrayLike<number>,
  path?: number[],
): number {
  const P = world.components.Position;
  const hx = hook[0]!,
    hy = hook[1]!,
    hz = hook[2]!;
  const ex = ball[0]! - hx,
    ez = ball[2]! - hz;
  if (path) path.length = 0;
  for (let k = 0; k <= SWING_SAMPLES; k++) {
    const f = 1 - ((1 + SWING_REACH) * k) / SWING_SAMPLES;
    const x = hx + f * ex,
      z = hz + f * ez;
    const y = hy - Math.sqrt(Math.max(0, HANG * HANG - f * f * (ex * ex + ez * ez)));
    path?.push(x, y, z);
    for (const p of pieces) {
      if (p.fallen || !isAlive(world, p.body)) continue;
      // The ball's centre in the box's frame (its x axis (cos yaw, -sin yaw) across the ground, z (sin yaw, cos yaw)).
      const dx = x - P.x[p.body]!,
        dy = y - P.y[p.body]!,
        dz = z - P.z[p.body]!;
      const c = Math.cos(p.yaw),
        sn = Math.sin(p.yaw);
      const lx = dx * c - dz * sn,
        lz = dx * sn + dz * c;
      const gap = Math.hypot(
        Math.max(0, Math.abs(lx) - p.half[0]),
        Math.max(0, Math.abs(dy) - p.half[1]),
        Math.max(0, Math.abs(lz) - p.half[2]),
      );
      if (gap < BALL_RADIUS) return p.body;
    }
  }
  return 0;
}

/**
 * The swing a drag at `piece` asks for, as `pullBack` sets it up: the hook's place over the strike
 * point (x, height, z, m), the ball's travel (ux, uz) and how far back from under the hook the line
 * draws it (offset, m). With `swingPath` from the drawn-back ball, the page draws where the ball
 * will go before the crane has carried it there.
 */
export function swingGoal(
  world: PhysicsWorld,
  h: WreckingBallHandles,
  piece: number,
  request: SwingRequest,
): { x: number; z: number; height: number; ux: number; uz: number; offset: number } {
  return swingSetup(world, h, piece, request).goal;
}

/** `swingGoal`, with the strike spot's structure and place (tx, tz, m) for the follow-through. */
function swingSetup(world: PhysicsWorld, h: WreckingBallHandles, piece: number, request: SwingRequest) {
  const P = world.components.Position;
  const { structure, tx, tz } = strikeSpot(world, h, piece);
  const ballY = Math.max(BALL_RADIUS + 0.05, P.y[piece]!);
  const height = Math.min(HOOK_RANGE[1], Math.max(HOOK_RANGE[0], ballY + HANG));
  const r0 = Math.min(RADIUS_RANGE[1], Math.max(RADIUS_RANGE[0], Math.hypot(tx, tz)));
  const a0 = Math.atan2(-tz, tx);
  const x = r0 * Math.cos(a0),
    z = -r0 * Math.sin(a0);
  const ux = Math.cos(request.direction),
    uz = Math.sin(request.direction);
  const cos = Math.max(0.2, 1 - (request.speed * request.speed) / (2 * 9.81 * HANG));
  let offset = HANG * Math.sqrt(1 - cos * cos);
  // Shortened till the segment from the hook to the ball keeps MAST_CLEAR from the mast's axis.
  while (offset > 0.3 && segmentToAxis(x, z, x - offset * ux, z - offset * uz) < MAST_CLEAR) offset -= 0.1;
  // Drawn back beside or over a piece, the ball hangs clear of it (see pullStep): the hook stays as
  // high as that takes, and the swing goes from there (it may pass over what it was aimed at).
  const sx = x - offset * ux,
    sz = z - offset * uz;
  const clear = Math.max(height, carryHeight(world, h.pieces, sx, sz, sx, sz, CARRY_NEAR_SIDE));
  return { goal: { x, z, height: clear, ux, uz, offset }, structure, tx, tz };
}

/** How many pieces have fallen. */
export function fallenCount(pieces: readonly Piece[]): number {
  let n = 0;
  for (const p of pieces) if (p.fallen) n++;
  return n;
}

/** Swings each of the LEVELS layouts allows (see swingBudget). */
const BUDGETS = [5, 6, 6, 6, 8];
/** Swings that clear each of the LEVELS layouts for three stars (see swingPar). */
const PARS = [2, 2, 3, 3, 3];

/**
 * Swings level `level` allows: taps (or site-plan clicks) on a target and drags of the ball each use
 * one. Without a limit a level falls to any two taps; with it, where the ball is sent is the skill.
 * By layout 5, 6, 6, 6 and 8 (one more each LEVELS levels, as they gain a structure): the careless
 * games of scripts/wrecking-ball-par.mjs (three ways, three starts each, tapping as the page's tap
 * swings) take at most 5, 6, 5, 5 and 8 swings on levels 1 to 5, so every one of them earns a star.
 * @throws RangeError on a level that is not an integer >= 1.
 */
export function swingBudget(level: number): number {
  if (!Number.isInteger(level) || level < 1) throw new RangeError(`swingBudget: level must be an integer >= 1, got ${level}`);
  return BUDGETS[(level - 1) % LEVELS]! + Math.floor((level - 1) / LEVELS);
}

/**
 * Swings that clear level `level` for three stars: by layout 2, 2, 3, 3 and 3 (one more each LEVELS
 * levels). With the shares of `clearShare` they ask for a plan: no single swing clears any of levels
 * 1 to 5, the careless games of scripts/wrecking-ball-par.mjs earn three stars in 1 of their 45
 * (level 2), while its careful player (each swing the one that brings down the most) clears levels
 * 3, 4 and 5 in 3 swings each: par there is that plan.
 * @throws RangeError on a level that is not an integer >= 1.
 */
export function swingPar(level: number): number {
  if (!Number.isInteger(level) || level < 1) throw new RangeError(`swingPar: level must be an integer >= 1, got ${level}`);
  return PARS[(level - 1) % LEVELS]! + Math.floor((level - 1) / LEVELS);
}

/**
 * The plan level `level`'s structures ask for, as the hint before its first swing says it after the
 * three stars' target: each layout's own (its row of towers, its shield walls, its heavy tower).
 * @throws RangeError on a level that is not an integer >= 1.
 */
export function levelTip(level: number): string {
  if (!Number.isInteger(level) || level < 1) throw new RangeError(`levelTip: level must be an integer >= 1, got ${level}`);
  return [
    'strike the biggest structures low',
    'strike the biggest structures low',
    'swing along the row of towers: each topples the next',
    'swing round the grey shields, in from the side',
    'big blocks need a full pull; swing along the row',
  ][(level - 1) % LEVELS]!;
}

/**
 * Whether a level's clear target is reached now, to be credited to the swings used so far: as many
 * pieces `fallen` as its `target` and no tagline holding the ball
 * (`pulling`: a drag held, or let go and not yet slipped). Pieces that fall while the ball is drawn
 * back are credited to that swing once it is let go and counted, so the swings a result names are
 * the swings the player used.
 */
export function clearReached(fallen: number, target: number, pulling: boolean): boolean {
  return fallen >= target && !pulling;
}

/** Speed, m/s, over which a piece counts as still falling (see `stillFalling`). */
export const SETTLE_SPEED = 0.3;
/** Seconds the wreckage must lie still (no piece still falling) before the level's result is given. */
export const SETTLE_QUIET = 0.6;
/** Seconds after the clear target is reached (or a piece last fell after it) before the result is given, at least. */
export const SETTLE_LEAST = 1;
/** Seconds after the clear target is reached that the result is given even if something still moves (a piece rocking). */
export const SETTLE_MOST = 8;

/**
 * How many pieces are still falling: moving faster than SETTLE_SPEED (standing or already counted
 * fallen; the score keeps counting those that go down while the wreckage settles).
 */
export function stillFalling(world: PhysicsWorld, pieces: readonly Piece[]): number {
  const V = world.components.Velocity;
  let n = 0;
  for (const p of pieces) if (Math.hypot(V.x[p.body]!, V.y[p.body]!, V.z[p.body]!) > SETTLE_SPEED) n++;
  return n;
}

/**
 * Whether a level's settling is over and its result is given: the clear target reached (or a piece
 * last fell) `since` s ago, at least SETTLE_LEAST, with nothing still falling for `quiet` s, at least
 * SETTLE_QUIET; or SETTLE_MOST s after it was reached (`reached` s ago) whatever still moves. The
 * player sees the collapse finish before the end card.
 */
export function settleOver(since: number, quiet: number, reached: number): boolean {
  return (since >= SETTLE_LEAST && quiet >= SETTLE_QUIET) || reached >= SETTLE_MOST;
}

/**
 * Stars for level `level` cleared in `swings` swings: 3 up to its par (`swingPar`), 2 for one swing
 * more, 1 for more up to the budget; 0 when it is not cleared.
 * @throws RangeError on a level that is not an integer >= 1.
 */
export function swingStars(swings: number, cleared: boolean, level: number): number {
  const par = swingPar(level);
  if (!cleared) return 0;
  return swings <= par ? 3 : swings === par + 1 ? 2 : 1;
}

/** Points for clearing a level, whatever the stars. */
export const CLEAR_BONUS = 500;
/** Points for each star a cleared level earns (`swingStars`). */
export const STAR_BONUS = 250;

/** A cleared level's score, part by part: the blocks' points, the clear bonus, the stars' bonus and their sum. */
export interface ClearScore {
  blocks: number;
  clear: number;
  stars: number;
  total: number;
}

/**
 * A cleared level's score: the points of the blocks brought down before it cleared, CLEAR_BONUS,
 * and STAR_BONUS for each of its `stars` (0 to 3).
 * @throws RangeError on negative or non-integer `blocks`, or `stars` not an integer in [0, 3].
 */
export function clearScore(blocks: number, stars: number): ClearScore {
  if (!Number.isInteger(blocks) || blocks < 0) throw new RangeError(`clearScore: blocks must be an integer >= 0, got ${blocks}`);
  if (!Number.isInteger(stars) || stars < 0 || stars > 3)
    throw new RangeError(`clearScore: stars must be an integer in [0, 3], got ${stars}`);
  const starPoints = STAR_BONUS * stars;
  return { blocks, clear: CLEAR_BONUS, stars: starPoints, total: blocks + CLEAR_BONUS + starPoints };
}

/** The score's breakdown as the level-clear banner says it: "blocks 396 + clear 500 + ★★ 500 = 1396". */
export function clearScoreLine(score: ClearScore, stars: number): string {
  return `blocks ${score.blocks} + clear ${score.clear} + ${stars > 0 ? '★'.repeat(stars) : 'no stars'} ${score.stars} = ${score.total}`;
}

/**
 * The stars' rule for level `level` (`swingStars`): "★★★ in ≤2 swings · ★★ in 3 · ★ in 4–5".
 * @throws RangeError on a level that is not an integer >= 1.
 */
export function starsRule(level: number): string {
  const par = swingPar(level),
    budget = swingBudget(level);
  const one = par + 2 === budget ? `${budget}` : `${par + 2}–${budget}`;
  return `★★★ in ≤${par} swings · ★★ in ${par + 1} · ★ in ${one}`;
}
