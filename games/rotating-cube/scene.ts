/**
 * The rotating-cube scene: one rigid box turning by Euler's equations I dw/dt = tau - w x I w (the
 * physics package's 3D rigid rotation). A pure builder (no DOM, no three.js), shared by the game and
 * its tests.
 *
 * Three modes:
 * - `'room'` (the default): a 1 m cube of 1 kg free under gravity in a room (a floor and four walls
 *   of static boxes): a box collider (`addShape3D`), so it lands, tumbles, slides and bounces off the
 *   floor and the walls; keys and clicks push it harder (ROOM_PUSH times), and it can jump.
 * - `'cube'`: the same cube without gravity, held at its centre of mass by a frictionless pivot (all
 *   three principal moments equal, m s^2 / 6, so L stays parallel to w), tumbling slowly; torques
 *   from the keys and impulses from clicks change its turning.
 * - `'flip'`: a 0.3 x 0.8 x 1.4 m box of 2 kg (three distinct moments, the 0.8 m edge's axis y the
 *   intermediate one) on the pivot, spun about y with a tiny perturbation: rotation about the
 *   intermediate axis is unstable, so the box flips over and back again and again while its angular
 *   momentum keeps its direction (the Dzhanibekov or tennis-racket effect; Ashbaugh, Chicone and Cushman,
 *   "The twisting tennis racket", J. Dyn. Diff. Eq. 3, 1991).
 */
import { seededRandom } from '@bitphysics/game-kit';
import {
  addBody,
  addPlane,
  addShape3D,
  addSystem,
  applyForceAtPoint,
  inertiaOfSolidBox,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  rotateVectorInverse,
  type System,
  setAngularVelocity,
  spinAngularMomentum,
} from '@bitphysics/physics';
import {
  GRID_IDENTITY,
  type GridOrientation,
  gridOrientationOf,
  moveRoute,
  type RollMove,
  type RollPuzzle,
  rollOrientation,
  turnOrientation,
} from './roll-puzzle';

/** The modes, the default first (the M key cycles through them in this order). */
export const MODES = ['room', 'cube', 'flip'] as const;
/** One of `MODES`. */
export type Mode = (typeof MODES)[number];

/** Edges (x, y, z) of the body in each mode, m. */
export const EDGES: Readonly<Record<Mode, readonly [number, number, number]>> = Object.freeze({
  cube: [1, 1, 1] as const,
  flip: [0.3, 0.8, 1.4] as const,
  room: [1, 1, 1] as const,
});

/** Mass of the body in each mode, kg. */
export const MASS: Readonly<Record<Mode, number>> = Object.freeze({ cube: 1, flip: 2, room: 1 });

/** Room mode: the room's inside half width (x and z), m, its walls' height and half thickness, m. */
export const ROOM_HALF = 3;
export const WALL_HEIGHT = 1.5;
export const WALL_HALF_THICKNESS = 0.2;
/** Room mode: key torques and click impulses are this many times the panel's values (the cube must beat friction on the floor). */
export const ROOM_PUSH = 10;
/** Room mode: the jump's impulse, N s (a 1 kg cube leaves the floor at 4 m/s, rising 0.8 m). */
export const JUMP_IMPULSE = 4;
/** Room mode: the friction coefficient of the floor, the walls and the cube (a cube sliding on a face slows at ROOM_FRICTION g). */
export const ROOM_FRICTION = 0.5;
/** Room mode: the fastest push, m/s (a push towards a point farther away than this reaches stops short of it). */
export const PUSH_SPEED_MAX = 7;
/**
 * Room mode: the roll keys' torque, N m (twice what tips a 1 kg, 1 m cube over an edge, m g / 2), and
 * the spin about the key's axis, rad/s, above which the keys stop pushing: a held key rolls the cube
 * along at a steady pace (a face in about 0.6 s), and let go it stops after the face it is rolling
 * over (at 2.6 rad/s a cube turning about its edge has 2.3 J, short of the 2.0 J plus the landing's
 * loss that would lift it over the next edge).
 */
export const ROLL_TORQUE = 10;
export const ROLL_SPIN_MAX = 2.6;
/**
 * Room mode: the spin a roll key's press gives a cube resting flat at once, rad/s, about the bottom
 * edge it rolls over (`rollStart`): it tips from the press's first step (about a degree a step at 60
 * steps a second), where ROLL_TORQUE alone moved it 0.1 degrees in its first step and 3 degrees only
 * after 7 (a torque large enough to start it faster slips that edge on the floor and lands the cube
 * off its cell). Short of ROLL_SPIN_MAX, so the torque still brings the roll to its usual pace.
 */
export const ROLL_START_SPIN = 1.1;

/**
 * Room mode: starts a roll of the cube `body` (a cube of edge 2 `half` m) when it rests flat and still
 * (its centre under 0.53 m high, `cubeStill`): sets its spin to `spin` rad/s about the level unit axis
 * (ax, 0, az), the roll's (y x d, the top going along the travel d), and its centre's velocity to the
 * one that turning about its bottom edge on the side of d gives it (spin x (centre - edge)): that edge
 * stays put on the floor, and no friction is needed to hold it. A cube not resting flat is left alone.
 * @returns whether it started the roll.
 */
export function rollStart(world: PhysicsWorld, body: number, ax: number, az: number, spin = ROLL_START_SPIN, half = 0.5): boolean {
  const P = world.components.Position,
    V = world.components.Velocity,
    W = world.components.AngularVelocity;
  if (P.y[body]! > half + 0.03 || !cubeStill(world, body)) return false;
  // The travel d = axis x y = (-az, 0, ax); centre - edge r = (-half d.x, half, -half d.z).
  const rx = half * az,
    ry = half,
    rz = -half * ax;
  const wx = spin * ax,
    wz = spin * az;
  W.x[body] = wx;
  W.y[body] = 0;
  W.z[body] = wz;
  // v = w x r with w.y = 0.
  V.x[body] = -wz * ry;
  V.y[body] = wz * rx - wx * rz;
  V.z[body] = wx * ry;
  return true;
}

/**
 * Room mode: the spin, rad/s, a roll key's press gives a resting cube whose roll a wall blocks
 * (`rollBlocked`): it tips about 6.5 degrees towards the wall and falls back onto the same face (a
 * bump the player sees), short of the 30 degrees at which its top edge would reach the wall. The
 * roll's torque, held on against a wall, turned the cube over in place onto another face instead.
 */
export const BUMP_SPIN = 1.3;

/**
 * Room mode: whether a roll of the cube resting with its centre at (`x`, `z`) m, over its bottom edge
 * towards the level travel (`dx`, `dz`) (a unit vector), is blocked by a wall: the cell it would land
 * on (its centre 1 m along) lies past the room's inside half width less the cube's half edge, with
 * 0.1 m of slack (a cube that would graze the wall by less is nudged back by it and rolls fine).
 */
export function rollBlocked(x: number, z: number, dx: number, dz: number): boolean {
  const most = ROOM_HALF - 0.5 + 0.1;
  return Math.abs(x + dx) > most || Math.abs(z + dz) > most;
}

/**
 * Room mode: the speed, m/s, that a cube sliding on a face across the room's floor needs to stop after
 * `distance` m: sqrt(2 ROOM_FRICTION g d) (uniform deceleration by kinetic friction), at most PUSH_SPEED_MAX.
 * @param distance the slide, m, >= 0.
 * @param gravity the magnitude of gravity, m/s^2, > 0 (default 9.81).
 * @throws RangeError if `distance` is negative or not finite, or `gravity` is not positive and finite.
 */
export function slideSpeed(distance: number, gravity = 9.81): number {
  if (!(distance >= 0) || !Number.isFinite(distance))
    throw new RangeError(`slideSpeed: distance must be a finite number >= 0, got ${distance}`);
  if (!(gravity > 0) || !Number.isFinite(gravity)) throw new RangeError(`slideSpeed: gravity must be a finite number > 0, got ${gravity}`);
  return Math.min(PUSH_SPEED_MAX, Math.sqrt(2 * ROOM_FRICTION * gravity * distance));
}

/** Options of `buildRotatingCube`. */
export interface RotatingCubeOptions {
  /** The mode. Default 'room'. */
  mode?: Mode;
  /** Flip mode: spin about the intermediate (y) axis, rad/s, finite. Default 6. */
  spin?: number;
  /** Flip mode: the perturbation about x and z, rad/s, finite. Default 0.01. */
  perturbation?: number;
  /** Flip mode: the pivot's drag, 1/s, finite and >= 0 (see FLIP_DRAG). Default FLIP_DRAG. */
  drag?: number;
  /**
   * Flip mode: the drag acts only in steps where this returns true (default: always). The game drags
   * only while its round runs, so the box keeps its starting spin while the player reads the goal.
   */
  dragWhile?: () => boolean;
  /** Cube mode: the starting angular velocity, rad/s, world frame. Default (0.35, 0.8, 0.2). */
  tumble?: ArrayLike<number>;
  /**
   * Room mode: the heading of the dropped cube about the vertical, rad, finite (default 0: its faces
   * square to the walls). The cube is dropped tipped and turning about one of its level edges only,
   * so it lands still at this heading: a game passes the camera's heading, so the roll keys' screen
   * directions run straight along the cube's edges.
   */
  heading?: number;
}

/** What `buildRotatingCube` returns. */
export interface RotatingCubeHandles {
  /** The body. */
  body: number;
  /** The mode built. */
  mode: Mode;
  /** Principal moments (x, y, z), kg m^2. */
  inertia: [number, number, number];
  /** The pivot: the body's centre of mass is held here (m); in room mode where it started (it is free). */
  pivot: [number, number, number];
  /** Room mode: the static wall bodies (empty in the other modes). */
  walls: number[];
}

/** World options of `mode` (default 'room'): 3D; in room mode Earth gravity and 2 substeps, on the pivot no gravity. */
export function rotatingCubeWorldOptions(mode: Mode = 'room'): PhysicsWorldOptions {
  return mode === 'room'
    ? { dimensions: 3, capacity: 16, gravity: [0, -9.81, 0], substeps: 2 }
    : { dimensions: 3, capacity: 8, gravity: [0, 0, 0] };
}

/**
 * Builds the scene of `mode` (default 'room': see `buildRoom`). On the pivot ('cube', 'flip'): the
 * body at the origin (inertia from `inertiaOfSolidBox`) and a constraints-stage system that holds its
 * centre of mass at the pivot: a frictionless ball joint at the centre of mass takes the linear part
 * of every force and impulse and leaves the turning (torque about the centre of mass) untouched.
 * @throws RangeError on an unknown mode, a non-finite spin, perturbation, tumble or heading, or a 2D world.
 */
export function buildRotatingCube(world: PhysicsWorld, options: RotatingCubeOptions = {}): RotatingCubeHandles {
  const mode = options.mode ?? 'room';
  if (!MODES.includes(mode)) throw new RangeError(`rotating-cube: mode must be one of ${MODES.join(', ')}, got ${String(mode)}`);
  if (world.dimensions !== 3) throw new RangeError(`rotating-cube: needs a 3D world, got dimensions ${world.dimensions}`);
  const spin = options.spin ?? 6,
    perturbation = options.perturbation ?? 0.01;
  const tumble = options.tumble ?? [0.35, 0.8, 0.2];
  if (tumble.length !== 3 || !Array.from(tumble).every(Number.isFinite))
    throw new RangeError(`rotating-cube: tumble must be 3 finite numbers, got ${JSON.stringify(Array.from(tumble))}`);
  if (!Number.isFinite(spin)) throw new RangeError(`rotating-cube: spin must be finite, got ${spin}`);
  if (!Number.isFinite(perturbation)) throw new RangeError(`rotating-cube: perturbation must be finite, got ${perturbation}`);
  const drag = options.drag ?? FLIP_DRAG;
  if (!(drag >= 0) || !Number.isFinite(drag)) throw new RangeError(`rotating-cube: drag must be a finite number >= 0, got ${drag}`);
  const heading = options.heading ?? 0;
  if (!Number.isFinite(heading)) throw new RangeError(`rotating-cube: heading must be finite, got ${heading}`);
  const mass = MASS[mode];
  const inertia = inertiaOfSolidBox(mass, EDGES[mode]);
  if (mode === 'room') return buildRoom(world, heading);
  const body = addBody(world, {
    position: [0, 0, 0],
    mass,
    inertia,
    angularVelocity: mode === 'flip' ? [perturbation, spin, perturbation] : tumble,
  });
  const pivot: [number, number, number] = [0, 0, 0];
  addSystem(world, 'constraints', holdAtPivot(body, pivot));
  if (mode === 'flip' && drag > 0) addSystem(world, 'forces', flipDrag(world, body, drag, options.dragWhile ?? (() => true)));
  return { body, mode, inertia, pivot, walls: [] };
}

/** Room mode: the dropped cube's tip about its level x edge, rad, and its turning about that edge, rad/s (it lands on the edge and falls back flat). */
const DROP_TIP = 0.3,
  DROP_SPIN = 0.8;

/**
 * Room mode: a floor (plane y = 0) and four static box walls around a 2 ROOM_HALF square, and the cube
 * (1 kg, a 1 m box collider of density 1 kg/m^3) dropped from 1.5 m at `heading` (rad about the
 * vertical), tipped DROP_TIP about its level x axis and turning about it at DROP_SPIN: it lands on an
 * edge and falls back flat with +y up, still at `heading` (a turn about one level axis has no part
 * about the vertical); friction ROOM_FRICTION and restitution 0.3 everywhere.
 */
function buildRoom(world: PhysicsWorld, heading: number): RotatingCubeHandles {
  addPlane(world, { normal: [0, 1, 0], point: [0, 0, 0], friction: ROOM_FRICTION, restitution: 0.3 });
  const walls: number[] = [];
  const h = WALL_HEIGHT / 2,
    t = WALL_HALF_THICKNESS,
    a = ROOM_HALF + t,
    l = ROOM_HALF + 2 * t;
  for (const [x, z, hx, hz] of [
    [a, 0, t, l],
    [-a, 0, t, l],
    [0, a, l, t],
    [0, -a, l, t],
  ] as const) {
    const wall = addBody(world, { position: [x, h, z], static: true });
    addShape3D(world, wall, { type: 'box', halfExtents: [hx, h, hz], friction: ROOM_FRICTION, restitution: 0.3 });
    walls.push(wall);
  }
  // q = (heading about y) (tip about x): the body's x axis, level, along (cos h, 0, -sin h).
  const ch = Math.cos(heading / 2),
    sh = Math.sin(heading / 2),
    ct = Math.cos(DROP_TIP / 2),
    st = Math.sin(DROP_TIP / 2);
  const body = addBody(world, { position: [0, 1.5, 0], orientation: [ch * st, sh * ct, -sh * st, ch * ct] });
  addShape3D(world, body, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: MASS.room, friction: ROOM_FRICTION, restitution: 0.3 });
  setAngularVelocity(world, body, [DROP_SPIN * Math.cos(heading), 0, -DROP_SPIN * Math.sin(heading)]);
  return { body, mode: 'room', inertia: inertiaOfSolidBox(MASS.room, EDGES.room), pivot: [0, 1.5, 0], walls };
}

/** A constraints-stage system that puts `body` back on `pivot` with zero linear velocity. */
function holdAtPivot(body: number, pivot: readonly [number, number, number]): System {
  return (world: PhysicsWorld): void => {
    const c = world.components;
    c.Position.x[body] = pivot[0];
    c.Position.y[body] = pivot[1];
    c.Position.z[body] = pivot[2];
    c.PreviousPosition.x[body] = pivot[0];
    c.PreviousPosition.y[body] = pivot[1];
    c.PreviousPosition.z[body] = pivot[2];
    c.Velocity.x[body] = 0;
    c.Velocity.y[body] = 0;
    c.Velocity.z[body] = 0;
  };
}

/**
 * Flip mode: the pivot's drag on the box, 1/s: a torque of -FLIP_DRAG L (L its angular momentum), so
 * left alone its spin decays by this share a second (10 %: from 12 rad/s, the top of FLIP_BAND, to 8,
 * its bottom, in 4 s). A spin put in the band and left there slips out of it before FLIP_GOAL flips:
 * the player keeps it up with the yaw key (a tap or a short hold every second or few) while it flips.
 * Scaling L scales the rotational energy alike (dE/dt = w . tau = -2 FLIP_DRAG E, d|L|^2/dt =
 * -2 FLIP_DRAG |L|^2), so the box flips the same way as before, only slower as it slows.
 */
export const FLIP_DRAG = 0.1;
/**
 * Flip mode: the keys' torque is this many times the panel's (0.5 N m): 1 N m about the box's
 * intermediate axis (0.34 kg m^2) adds 2.9 rad/s a second, against the drag's 1 rad/s at 10 rad/s.
 */
export const FLIP_PUSH = 2;

/**
 * Room mode: how fast a rolled cube's leftover motion dies once it lies flat on its new face, 1/s:
 * at 12/s a landing's 0.3 m/s of slide and its rock back and forth fade within about 0.2 s, so a
 * roll ends square on its cell instead of skidding and rocking on for another half second.
 */
export const ROLL_SETTLE_RATE = 12;

/**
 * A forces-stage system for the room: while `on()` (the game: a roll key's roll has ended and the
 * cube has not been pushed since) and the cube lies flat on a face (its centre under 0.53 m, a body
 * axis within 8 degrees of vertical), its level velocity and its spin about level axes decay at
 * ROLL_SETTLE_RATE (scaled by exp(-rate dt) each step); its spin about the vertical (the yaw
 * keeper's) and its fall are left alone. Off the floor, on an edge or mid-roll it does nothing.
 */
export function rollSettle(body: number, on: () => boolean): System {
  const flat = Math.cos((8 * Math.PI) / 180);
  return (world) => {
    if (!on()) return;
    const P = world.components.Position,
      V = world.components.Velocity,
      W = world.components.AngularVelocity,
      q = world.components.Orientation;
    if (P.y[body]! > 0.53) return;
    const x = q.x[body]!,
      y = q.y[body]!,
      z = q.z[body]!,
      w = q.w[body]!;
    // The world y components of the body's axes: row y of its rotation matrix.
    const up = Math.max(Math.abs(2 * (x * y + w * z)), Math.abs(1 - 2 * (x * x + z * z)), Math.abs(2 * (y * z - w * x)));
    if (up < flat) return;
    const k = Math.exp(-ROLL_SETTLE_RATE * world.dt);
    V.x[body] = V.x[body]! * k;
    V.z[body] = V.z[body]! * k;
    W.x[body] = W.x[body]! * k;
    W.z[body] = W.z[body]! * k;
  };
}

/** A forces-stage system: the torque -drag L on `body` (flip mode's pivot drag, `FLIP_DRAG`) in the steps where `on` returns true. */
function flipDrag(world: PhysicsWorld, body: number, drag: number, on: () => boolean): System {
  const L = new Float64Array(3);
  return torqueCouple(body, () => {
    if (!on()) return L.fill(0);
    spinAngularMomentum(world, body, L);
    for (let i = 0; i < 3; i++) L[i] = -drag * L[i]!;
    return L;
  });
}

/**
 * A forces-stage system that applies the torque `torque` (N m, world frame, read each call) to
 * `body` as a couple of two equal and opposite forces (`applyForceAtPoint`) half a metre either side
 * of its centre: no net force, torque r x F + (-r) x (-F) = 2 r x F. The vector is read through the
 * callback so a game can change it from its keys. Allocation-free per call (applyForceAtPoint
 * validates its vectors, which is cheap for one body).
 */
export function torqueCouple(body: number, torque: () => ArrayLike<number>): System {
  const force = new Float64Array(3),
    point = new Float64Array(3);
  const d = 0.5;
  return (world: PhysicsWorld): void => {
    const t = torque();
    const tx = t[0]!,
      ty = t[1]!,
      tz = t[2]!;
    const T = Math.sqrt(tx * tx + ty * ty + tz * tz);
    if (!(T > 0)) return;
    const nx = tx / T,
      ny = ty / T,
      nz = tz / T;
    // u: a unit vector perpendicular to the torque axis n; F = f (n x u) at +d u, -F at -d u.
    let ux: number, uy: number, uz: number;
    if (Math.abs(nx) < 0.9) {
      ux = 0;
      uy = nz;
      uz = -ny;
    } else {
      ux = -nz;
      uy = 0;
      uz = nx;
    }
    const ul = 1 / Math.sqrt(ux * ux + uy * uy + uz * uz);
    ux *= ul;
    uy *= ul;
    uz *= ul;
    const f = T / (2 * d);
    const fx = f * (ny * uz - nz * uy),
      fy = f * (nz * ux - nx * uz),
      fz = f * (nx * uy - ny * ux);
    const P = world.components.Position;
    const cx = P.x[body]!,
      cy = P.y[body]!,
      cz = P.z[body]!;
    force[0] = fx;
    force[1] = fy;
    force[2] = fz;
    point[0] = cx + d * ux;
    point[1] = cy + d * uy;
    point[2] = cz + d * uz;
    applyForceAtPoint(world, body, force, point);
    force[0] = -fx;
    force[1] = -fy;
    force[2] = -fz;
    point[0] = cx - d * ux;
    point[1] = cy - d * uy;
    point[2] = cz - d * uz;
    applyForceAtPoint(world, body, force, point);
  };
}

/** Room mode, the yaw keeper's gains: stiffness, N m/rad, and damping, N m s/rad (near critical for the cube's 1/6 kg m^2 about the vertical). */
export const YAW_STIFFNESS = 120;
export const YAW_DAMPING = 9;
/** A quarter turn, rad. */
const QUARTER = Math.PI / 2;
/** `a` wrapped into [-QUARTER / 2, QUARTER / 2): the cube looks the same after every quarter turn about the vertical. */
function wrapQuarter(a: number): number {
  return a - QUARTER * Math.round(a / QUARTER);
}

/**
 * Room mode: keeps the cube square to a grid of headings (a heading about the vertical and every
 * quarter turn from it) while it lies flat on a face, and turns it by quarter turns on command. Its
 * faces then stay square to the walls, the pads and the roll keys' screen directions whatever knocked
 * it (a corner striking a wall, a spin): each step it gives the torque about the vertical, N m, of a
 * spring and damper (YAW_STIFFNESS, YAW_DAMPING) towards its target heading, at most `maxTorque`; the
 * target is the grid heading nearest the cube's, or after `turn` the one a quarter turn on. The
 * cube's heading is read from its most nearly level body axis and followed through whole turns; the
 * keeper only acts while the axis most nearly vertical is within 20 degrees of it (not while it rolls
 * over an edge, which keeps it square: a roll turns it about a level axis of the grid). Rest on the
 * floor holds it within about 2 degrees (where the spring's torque falls below the floor's friction).
 */
export class YawKeeper {
  /** The grid's heading, rad: the angle from +z of a level face normal (atan2(x, z)). */
  private grid = 0;
  /** The cube's heading from the grid, rad, followed through whole turns; NaN before the first reading. */
  yaw = Number.NaN;
  /** The heading it is turned to, rad from the grid, a multiple of a quarter turn. */
  target = 0;
  /** Whether a commanded turn (`turn`) is under way: until the cube is within 5 degrees of its target. */
  turning = false;
  /** The last reading of the heading wrapped to a quarter turn, rad. */
  private last = Number.NaN;
  /**
   * @param heading the grid's heading about the vertical, rad, finite (as `buildRotatingCube`'s `heading`: 0 is square to the room).
   * @throws RangeError if `heading` is not finite.
   */
  constructor(heading = 0) {
    this.reset(heading);
  }
  /** Starts over with the grid at `heading`, rad. @throws RangeError if `heading` is not finite. */
  reset(heading = 0): void {
    if (!Number.isFinite(heading)) throw new RangeError(`YawKeeper: heading must be finite, got ${heading}`);
    this.grid = heading;
    this.yaw = Number.NaN;
    this.last = Number.NaN;
    this.target = 0;
    this.turning = false;
  }
  /**
   * Turns the cube a quarter turn about the vertical: `direction` +1 anticlockwise seen from above
   * (the torque along +y), -1 clockwise; from the grid heading nearest it (or the target of a turn
   * under way). @throws RangeError if `direction` is not 1 or -1.
   */
  turn(direction: number): void {
    if (direction !== 1 && direction !== -1) throw new RangeError(`YawKeeper.turn: direction must be 1 or -1, got ${direction}`);
    const from = this.turning || !Number.isFinite(this.yaw) ? this.target : QUARTER * Math.round(this.yaw / QUARTER);
    this.target = from + direction * QUARTER;
    this.turning = true;
  }
  /**
   * Reads the heading of `body` in `world` and returns the torque about the vertical, N m, to apply
   * this step (0 while it is not flat on a face), at most `maxTorque` (N m, >= 0) either way.
   */
  torque(world: PhysicsWorld, body: number, maxTorque: number): number {
    const q = world.components.Orientation;
    const x = q.x[body]!,
      y = q.y[body]!,
      z = q.z[body]!,
      w = q.w[body]!;
    // The body's axes in the world: the columns of its rotation matrix; their y parts are row y.
    const cols = [
      [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)],
      [2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)],
      [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)],
    ];
    let level = 0,
      upright = 0;
    for (let i = 1; i < 3; i++) {
      if (Math.abs(cols[i]![1]!) < Math.abs(cols[level]![1]!)) level = i;
      if (Math.abs(cols[i]![1]!) > Math.abs(cols[upright]![1]!)) upright = i;
    }
    const c = cols[level]!;
    const reading = wrapQuarter(Math.atan2(c[0]!, c[2]!) - this.grid);
    if (Number.isNaN(this.yaw)) {
      this.yaw = reading;
      this.target = QUARTER * Math.round(reading / QUARTER);
    } else this.yaw += wrapQuarter(reading - this.last);
    this.last = reading;
    if (Math.abs(cols[upright]![1]!) < Math.cos((20 * Math.PI) / 180)) return 0;
    if (this.turning && Math.abs(this.target - this.yaw) < (5 * Math.PI) / 180) this.turning = false;
    if (!this.turning) this.target = QUARTER * Math.round(this.yaw / QUARTER);
    const wy = world.components.AngularVelocity.y[body]!;
    const t = YAW_STIFFNESS * (this.target - this.yaw) - YAW_DAMPING * wy;
    return Math.max(-maxTorque, Math.min(maxTorque, t));
  }
}

// ---- Challenges -------------------------------------------------------------------------------

/**
 * Room mode's challenge: the classic pads' centres (x, z), m, in the order they light up (the
 * layout of seed -1, CLASSIC_LAYOUT; the game lays out a fresh round per run with `padLayout`). Each is a
 * square of half edge PAD_HALF on the floor, clear of the walls by more than the cube's half diagonal.
 */
export const PADS: readonly (readonly [number, number])[] = Object.freeze([
  [1.6, -1.5],
  [-1.7, 1.4],
  [1.5, 1.7],
  [-1.6, -1.6],
  [0, 0.9],
]);
/** Largest half edge of a pad, m (the first pad's): the cube scores when its centre rests within a pad's half edge plus PAD_GRACE of its centre on x and z. */
export const PAD_HALF = 0.6;
/**
 * How far past a pad's drawn edge the cube's centre may rest and still count, m: a quarter of the
 * cube's 1 m edge, so a cube with at least a quarter of its width over the pad counts (a cube half on a
 * pad looks landed to a player). The game lights the pad's rim while the centre is that near.
 */
export const PAD_GRACE = 0.25;
/**
 * The faces of the cube, in the order of its body axes and of three.js's BoxGeometry groups: +x, -x,
 * +y, -y, +z, -z (the game paints them red, yellow, green, purple, blue, white).
 */
export const FACES = Object.freeze(['+x', '-x', '+y', '-y', '+z', '-z'] as const);
/** The classic layout's wanted faces (an index into FACES, -1 for any), kept beside PADS. */
export const PAD_FACES: readonly number[] = Object.freeze([-1, -1, 0, 4, 2]);

/** A round of pads: centres (x, z), m; the face each wants on top (index into FACES, -1: any); half edges, m. */
export interface PadLayout {
  /** The seed it was laid out from (an integer). */
  readonly seed: number;
  /** Pad centres (x, z), m, in the order they light up; PAD_COUNT of them. */
  readonly pads: readonly (readonly [number, number])[];
  /** The face each pad wants on top: an index into FACES, or -1 for any face. */
  readonly faces: readonly number[];
  /** Each pad's half edge, m, in (0, PAD_HALF]: the pads shrink as the round goes on. */
  readonly halves: readonly number[];
  /** Each pad's bed of tiles, cells (roll-puzzle.ts `RollPuzzle.bed`): -1 none, 0 the pad's cell, 1 the cells around it too, ROLL_ONLY_BED the whole floor. */
  readonly beds: readonly number[];
}
/** Pads in a round. */
export const PAD_COUNT = 5;
/** Half edges of the pads in a round, m: the later pads are smaller targets. */
export const PAD_HALVES: readonly number[] = Object.freeze([0.6, 0.55, 0.5, 0.45, 0.42]);
/**
 * A bed this wide covers every cell of the room (ROOM_HALF 3 m: no cell lies ROLL_ONLY_BED m from a
 * pad inside it): no slide stops anywhere, so the cube rolls all the way from where it rests, and the
 * route across the floor decides the face on top (roll-puzzle.ts `edgeCells` is empty).
 */
export const ROLL_ONLY_BED = 9;
/**
 * The pads' beds of tiles, cells (roll-puzzle.ts): the first pad none (slide onto it), the second its
 * own cell (roll on from beside it), the next two the cells around them too (roll across the bed, so
 * the route decides the face on top), the last the whole floor (ROLL_ONLY_BED: rolls only, planned).
 */
export const PAD_BEDS: readonly number[] = Object.freeze([-1, 0, 1, 1, ROLL_ONLY_BED]);
/** The largest |x| and |z| of a resting cube's centre the roll puzzle uses, m: the room's inside half width less the cube's half edge and 5 cm. */
export const CELL_REACH = ROOM_HALF - 0.55;
/** A pad centre lies within this of the room's centre on x and z, m (clear of the walls by more than a pad and the cube's half diagonal). */
export const PAD_REACH = 2.1;
/** The face the room's cube lands with on top when dropped at the start (+y: it is dropped nearly level). */
export const LANDING_FACE = 2;
/** The classic layout (PADS, PAD_FACES, every pad PAD_HALF), seed -1. */
export const CLASSIC_LAYOUT: PadLayout = Object.freeze({
  seed: -1,
  pads: PADS,
  faces: PAD_FACES,
  halves: Object.freeze(PADS.map(() => PAD_HALF)),
  beds: PAD_BEDS,
});

/**
 * A round's layout from `seed` (the same seed, the same round): PAD_COUNT pads within PAD_REACH of
 * the centre, the first at least 1.5 m from where the cube lands (the centre), each at least 2 m from
 * the one before and 1.4 m from every other (none overlap); the first takes any face, the others each
 * want one, in a sequence that grows harder: the second a face beside LANDING_FACE (one roll), then the
 * face opposite the previous pad's (two rolls straight across its bed), then one beside it, and last
 * a pad rolled to across the whole floor with the face and spot that take the most moves
 * (`rollOnlyPad`); the pads shrink (PAD_HALVES) and lie in beds (PAD_BEDS).
 * The pads with a bed of 1 or less are always solvable by rolling on (`PadChallenge`): a pad lies
 * within PAD_REACH of the centre, so along each axis the spot 1 m to one side of it (a roll's length)
 * lies within ROOM_HALF - 0.9 m of the centre, where the cube fits; set the wanted face up as a side
 * facing away from the pad (rolls elsewhere, Q/E spins), slide to that spot (a slide keeps the faces)
 * and roll on. The last is solvable by rolls from the pad before (on its grid, `rollOnlyPad`).
 * @param seed any finite number (floored to an integer).
 * @throws RangeError if `seed` is not finite.
 */
export function padLayout(seed: number): PadLayout {
  if (!Number.isFinite(seed)) throw new RangeError(`padLayout: seed must be a finite number, got ${seed}`);
  const s = Math.floor(seed);
  const random = seededRandom(s);
  const pads: [number, number][] = [];
  /** Lays pad k (pads.length) at random until it is clear of the ones before. */
  const place = (): void => {
    const k = pads.length;
    for (let tries = 0; ; tries++) {
      const x = Math.round((2 * random() - 1) * PAD_REACH * 10) / 10,
        z = Math.round((2 * random() - 1) * PAD_REACH * 10) / 10;
      const prev = k > 0 ? pads[k - 1]! : null;
      // Apart from every pad before it by 1.4 m (no two overlap), from the one before by 2 m.
      const ok =
        (prev ? Math.hypot(x - prev[0], z - prev[1]) >= 2 : Math.hypot(x, z) >= 1.5) &&
        pads.every(([px, pz]) => Math.hypot(x - px, z - pz) >= 1.4);
      if (ok || tries > 200) {
        pads.push([x, z]);
        break;
      }
    }
  };
  for (let k = 0; k < PAD_COUNT; k++) place();
  const faces = [-1];
  // Beside a face: the four faces on the other two axes.
  const beside = (f: number): number => {
    const axes = [0, 1, 2].filter((i) => i !== f >> 1);
    return 2 * axes[Math.floor(random() * 2)]! + (random() < 0.5 ? 1 : 0);
  };
  faces.push(beside(LANDING_FACE));
  faces.push(faces[1]! ^ 1);
  faces.push(beside(faces[2]!));
  // The last pad laid at random goes (it is drawn so that a seed's other pads and faces stay as they were);
  // the roll-only one takes its place.
  pads.pop();
  // The pad before the last one moves until the last has a spot (rare: it sat where no spot 3 to 5 cells off is clear).
  let lastPad = rollOnlyPad(pads, faces, random);
  for (let tries = 0; !lastPad && tries < 100; tries++) {
    pads.pop();
    place();
    lastPad = rollOnlyPad(pads, faces, random);
  }
  const [last, want] = lastPad ?? [[pads[PAD_COUNT - 2]![0] > 0 ? -2 : 2, 0] as [number, number], LANDING_FACE ^ 1];
  pads.push(last);
  faces.push(want);
  return Object.freeze({ seed: s, pads: Object.freeze(pads), faces: Object.freeze(faces), halves: PAD_HALVES, beds: PAD_BEDS });
}

/**
 * The round's last pad, rolled to across the whole floor (ROLL_ONLY_BED), and the face it wants: a
 * whole number of cells from the pad before (so the grid the cube rolls on from there lines up with
 * it), 3 to 5 cells along the floor's rows away, within PAD_REACH and 1.4 m from every pad before
 * (1.1 m if no spot is); of those, and of the faces, the one (taken by `random` among equals) with the most moves
 * (`moveRoute`) from where a shortest play of the pads before leaves the cube (dropped at the centre
 * with LANDING_FACE up), so the last pad asks for a route that is planned.
 * @returns [[x, z], face], or null if no spot fits (`padLayout` then lays the pad before again).
 */
function rollOnlyPad(
  pads: readonly (readonly [number, number])[],
  faces: readonly number[],
  random: () => number,
): [[number, number], number] | null {
  let at: readonly [number, number] = [0, 0],
    o: GridOrientation = GRID_IDENTITY;
  for (let k = 0; k < pads.length; k++) {
    const p: RollPuzzle = { pad: pads[k]!, want: faces[k]!, bed: PAD_BEDS[k]!, reach: CELL_REACH };
    const route = moveRoute(p, [Math.round(at[0] - p.pad[0]), Math.round(at[1] - p.pad[1])], o) ?? [];
    for (const m of route)
      if (m.kind === 'roll') o = rollOrientation(o, m.direction);
      else if (m.kind === 'turn') o = turnOrientation(o, m.direction);
    at = p.pad;
  }
  const prev = pads[pads.length - 1]!;
  let best: [[number, number], number][] = [],
    most = -1;
  // Spaced 1.4 m from every pad before if any spot allows, else 1.1 m (clear of the others: half edges up to 0.6 m and 0.42 m).
  for (const gap of [1.4, 1.1]) {
    if (best.length > 0) break;
    for (let i = -4; i <= 4; i++)
      for (let j = -4; j <= 4; j++) {
        const x = Math.round((prev[0] + i) * 10) / 10,
          z = Math.round((prev[1] + j) * 10) / 10;
        const cells = Math.abs(i) + Math.abs(j);
        if (cells < 3 || cells > 5 || Math.max(Math.abs(x), Math.abs(z)) > PAD_REACH) continue;
        if (!pads.every(([px, pz]) => Math.hypot(x - px, z - pz) >= gap)) continue;
        for (let want = 0; want < 6; want++) {
          const n = moveRoute({ pad: [x, z], want, bed: ROLL_ONLY_BED, reach: CELL_REACH }, [-i, -j], o)?.length ?? -1;
          if (n > most) [best, most] = [[], n];
          if (n === most) best.push([[x, z], want]);
        }
      }
  }
  return best.length > 0 ? best[Math.floor(random() * best.length)]! : null;
}

/**
 * The face of `body` on top: the index into FACES of its body axis (either way) pointing most nearly
 * up in the world, from its orientation.
 */
export function topFace(world: PhysicsWorld, body: number): number {
  const q = world.components.Orientation;
  const x = q.x[body]!,
    y = q.y[body]!,
    z = q.z[body]!,
    w = q.w[body]!;
  // The world y components of the body's x, y and z axes: row y of its rotation matrix.
  const up = [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)];
  let best = 0;
  for (let i = 1; i < 3; i++) if (Math.abs(up[i]!) > Math.abs(up[best]!)) best = i;
  return 2 * best + (up[best]! < 0 ? 1 : 0);
}
/** Pad `k` of `layout` as a roll puzzle (roll-puzzle.ts): its centre, wanted face and bed, in the room's cells. */
export function padPuzzle(layout: PadLayout, k: number): RollPuzzle {
  const pad = layout.pads[k];
  if (!pad) throw new RangeError(`padPuzzle: k must index one of the layout's ${layout.pads.length} pads, got ${k}`);
  return { pad: [pad[0], pad[1]], want: layout.faces[k]!, bed: layout.beds[k]!, reach: CELL_REACH };
}
/**
 * A shortest route (roll-puzzle.ts `moveRoute`) for `body` where it is now in `world` onto pad `k` of
 * `layout` with the face it wants on top, from its orientation (square to the world's axes) and its
 * cell (the 1 m square, offset from the pad, that its centre lies over: a roll lands the cube up to
 * about 0.3 m past the next cell's centre, so after a few rolls it may stand well off centre, and it
 * is still on the square the player sees it on; main.ts draws that square as the cube's footprint).
 * @returns the moves, or null if none reaches it.
 */
export function padMoveRoute(world: PhysicsWorld, body: number, layout: PadLayout, k: number): RollMove[] | null {
  const p = padPuzzle(layout, k);
  const P = world.components.Position,
    q = world.components.Orientation;
  const u = P.x[body]! - p.pad[0],
    v = P.z[body]! - p.pad[1];
  const i = Math.round(u),
    j = Math.round(v);
  const o = gridOrientationOf(q.x[body]!, q.y[body]!, q.z[body]!, q.w[body]!);
  // The page asks every frame the cube rests (about 0.2 ms a search): the last answer is kept for its question.
  const key = `${k} ${i} ${j} ${o.join()}`;
  if (lastRoute.layout !== layout || lastRoute.key !== key) {
    lastRoute.layout = layout;
    lastRoute.key = key;
    lastRoute.route = moveRoute(p, [i, j], o);
  }
  return lastRoute.route ? [...lastRoute.route] : null;
}
/** padMoveRoute's last question (the layout, then pad, cell and orientation) and its answer. */
const lastRoute: { layout: PadLayout | null; key: string; route: RollMove[] | null } = { layout: null, key: '', route: null };
/** The par of pad `k` of `layout` for `body` where it is now in `world`: the length of `padMoveRoute`, or -1 if none reaches it. */
export function padMovePar(world: PhysicsWorld, body: number, layout: PadLayout, k: number): number {
  return padMoveRoute(world, body, layout, k)?.length ?? -1;
}
/** Room challenge: three stars for a round within par + PAR_SLACK[0] moves, two within par + PAR_SLACK[1], else one. */
export const PAR_SLACK: readonly [number, number] = Object.freeze([2, 8]) as readonly [number, number];

/**
 * Whether `body` rests on the pad centred at (px, pz) (m): its centre within `half` (m, default
 * PAD_HALF) of the pad on x and z, at most 0.6 m up (a 1 m cube lying on a face sits at 0.5 m),
 * moving slower than 0.2 m/s and turning slower than 0.5 rad/s.
 */
export function restsOnPad(world: PhysicsWorld, body: number, px: number, pz: number, half = PAD_HALF): boolean {
  const P = world.components.Position;
  if (Math.abs(P.x[body]! - px) > half || Math.abs(P.z[body]! - pz) > half || P.y[body]! > 0.6) return false;
  return cubeStill(world, body);
}

/**
 * Whether `body` is still enough for the player to plan the next move: moving slower than 0.2 m/s
 * and turning slower than 0.5 rad/s (a slide or a roll has settled). The pad round's clock runs only then.
 */
export function cubeStill(world: PhysicsWorld, body: number): boolean {
  const V = world.components.Velocity,
    W = world.components.AngularVelocity;
  return Math.hypot(V.x[body]!, V.y[body]!, V.z[body]!) < 0.2 && Math.hypot(W.x[body]!, W.y[body]!, W.z[body]!) < 0.5;
}

/**
 * Stars for a pad round finished in `moves` moves against `par` (PadChallenge `par`): 3 within par +
 * PAR_SLACK[0], 2 within par + PAR_SLACK[1], else 1.
 * @throws RangeError if `moves` or `par` is not a finite number >= 0.
 */
export function padStars(moves: number, par: number): number {
  if (!(moves >= 0) || !Number.isFinite(moves)) throw new RangeError(`padStars: moves must be a finite number >= 0, got ${moves}`);
  if (!(par >= 0) || !Number.isFinite(par)) throw new RangeError(`padStars: par must be a finite number >= 0, got ${par}`);
  return moves <= par + PAR_SLACK[0] ? 3 : moves <= par + PAR_SLACK[1] ? 2 : 1;
}

/** Flip mode's challenge: flips to make, and the time allowed, s. */
export const FLIP_GOAL = 10;
export const FLIP_TIME = 20;
/**
 * Flip mode: a flip counts only while the box's spin (`flipSpin`: |L| over its intermediate moment)
 * is within this band, rad/s. The box starts below it (6 rad/s), a held yaw key spins it up through
 * the band and out of it, and the pivot's drag (FLIP_DRAG) slows it out of the band from below; so
 * the player spins it up, lets go, and gives it more yaw each time it sags (several holds or taps a
 * round), and kicks it with a pitch or roll key, which tips w off the intermediate axis so it flips sooner.
 */
export const FLIP_BAND: readonly [number, number] = Object.freeze([8, 12]) as readonly [number, number];

/**
 * Flip mode: the box's spin, rad/s, from the magnitude of its angular momentum `l` (kg m^2/s, >= 0):
 * l over its intermediate moment (about y), the rate it turns spinning about that axis alone. Unlike
 * |w|, which swings up and down as the box flips (its w moves between the axes of unequal moments
 * while L stays fixed), it stays steady between the keys' torques, so the band's check does not flicker.
 */
export function flipSpin(l: number): number {
  return l / FLIP_I_MID;
}
/** The flip box's intermediate principal moment (about its y axis), kg m^2. */
const FLIP_I_MID = inertiaOfSolidBox(MASS.flip, EDGES.flip)[1];

/**
 * Counts flips of a spinning box: the cosine between its intermediate (y) axis and its angular
 * momentum L swings between about +1 and -1 as it turns over; a flip is counted each time the cosine
 * crosses from beyond +0.5 to beyond -0.5 or back (the gap keeps a wobble near zero from counting).
 */
export class FlipCounter {
  /** Flips counted since construction or `reset`, >= 0. */
  count = 0;
  /** Sign of the last cosine beyond 0.5 in magnitude: +1, -1, or 0 before the first. */
  private side = 0;
  /** Forgets the flips and the side. */
  reset(): void {
    this.count = 0;
    this.missed = 0;
    this.side = 0;
  }
  /** Flips made while `counts` was false (out of the band): seen, not counted. */
  missed = 0;
  /**
   * Feeds the cosine between the box's y axis and L (in [-1, 1]; a non-finite value is ignored); a
   * flip completed while `counts` is false (default true) goes to `missed` instead of `count`.
   * @returns the flips counted so far.
   */
  update(cosine: number, counts = true): number {
    if (cosine > 0.5) {
      if (this.side < 0) counts ? this.count++ : this.missed++;
      this.side = 1;
    } else if (cosine < -0.5) {
      if (this.side > 0) counts ? this.count++ : this.missed++;
      this.side = -1;
    }
    return this.count;
  }
}

/**
 * Room mode's challenge, a round of pads laid out by a `PadLayout` (default CLASSIC_LAYOUT): the pad
 * `pad` is lit; when the cube rests on it (`restsOnPad`, within its half edge) with the face the pad
 * wants on top (`topFace`) the next one lights. A pad that wants a face counts only when the cube
 * ROLLED onto it: its top face changed after the last slide (`slid`), so the route to it matters (a
 * slide keeps the top face, and rolling on changes it: the player picks the side to roll on from).
 * Every move that can change the puzzle counts for the stars: a roll (a change of the top face,
 * counted here), a slide (`slid`), a quarter turn (`turned`: it keeps the top face but changes which
 * face each roll brings up, so the par's search counts it too); a hop on the spot (`jumped`) is free,
 * as it lands on the same cell with the same face up (a jump that tumbles it counts as the roll it
 * makes); against the round's par, the sum of each pad's
 * `padMovePar` worked out from where the cube is when the pad lights. After the last pad the round is
 * over at `doneAt` (world time, s). The round's clock (`time`) starts at `startedAt`, the world time of the player's
 * first input (`start`), not at the world's start, so reading the help costs nothing; and it runs only while the
 * player can act (`cubeStill`): the seconds a slide or a roll takes to settle are not the player's.
 */
export class PadChallenge {
  /** The round's pads. */
  layout: PadLayout;
  /** Index of the lit pad, in [0, layout.pads.length] (the length: the round is over). */
  pad = 0;
  /** World time the last pad was reached, s, or -1 while the round runs. */
  doneAt = -1;
  /** World time the round's clock started (the first input), s, or -1 before it. */
  startedAt = -1;
  /** Rolls made in the round so far (changes of the face on top), >= 0. */
  rolls = 0;
  /** Moves made in the round so far (rolls, slides, quarter turns; not jumps), >= 0. */
  moves = 0;
  /** Jumps made in the round so far, >= 0 (free: not moves). */
  jumps = 0;
  /** Each lit pad's par (`padMovePar` when it lit), in order: one entry per pad lit so far. */
  pars: number[] = [];
  /** `moves` when the lit pad lit. */
  movesAtLight = 0;
  /** Whether the top face changed since the last slide (`slid`): a pad that wants a face counts only then. */
  rolled = false;
  /** Whether, at the last `update`, the cube's centre was within the lit pad's half edge plus PAD_GRACE of its centre on x and z (resting or not). */
  over = false;
  /**
   * Why the cube resting on the lit pad at the last `update` did not count: 'face' (another face on
   * top than the pad wants), 'slide' (the wanted face on top, but slid on, not rolled), or '' (it
   * counted, or it does not rest on the pad).
   */
  blocked: '' | 'face' | 'slide' = '';
  /** World time `blocked` last took a reason after none or another, s, or -1 while it is ''. */
  private blockedSince = -1;
  /** The face on top at the last `update` (index into FACES), or -1 before the first. */
  private lastTop = -1;
  /** The round's clock, s: world time since the start spent with the cube still, up to the round's end. */
  private clock = 0;
  /** World time of the last `update`, s, or -1 before the first (the clock grows by the step between two). */
  private lastTime = -1;
  /** @param layout the round's pads (default CLASSIC_LAYOUT). */
  constructor(layout: PadLayout = CLASSIC_LAYOUT) {
    this.layout = layout;
  }
  /** Starts the round again (pad 0, clock stopped), with `layout` when given. */
  reset(layout?: PadLayout): void {
    if (layout) this.layout = layout;
    this.pad = 0;
    this.doneAt = -1;
    this.startedAt = -1;
    this.rolls = 0;
    this.moves = 0;
    this.jumps = 0;
    this.pars = [];
    this.movesAtLight = 0;
    this.rolled = false;
    this.over = false;
    this.blocked = '';
    this.blockedSince = -1;
    this.lastTop = -1;
    this.clock = 0;
    this.lastTime = -1;
  }
  /** Counts a slide (a push of the cube), a move: the next pad that wants a face needs a roll onto it first. */
  slid(): void {
    this.rolled = false;
    if (!this.done) this.moves++;
  }
  /** Counts a quarter turn about the vertical, a move. */
  turned(): void {
    if (!this.done) this.moves++;
  }
  /** Counts a jump in `jumps`, not in `moves`: a hop lands on the same cell with the same face up. */
  jumped(): void {
    if (!this.done) this.jumps++;
  }
  /** The round's par so far: the sum of the lit pads' pars (each worked out when it lit), >= 0. */
  get par(): number {
    return this.pars.reduce((a, b) => a + Math.max(0, b), 0);
  }
  /** The lit pad's par, or 0 once the round is over or before the first `update`. */
  get padPar(): number {
    return this.done ? 0 : Math.max(0, this.pars[this.pad] ?? 0);
  }
  /** Moves made on the lit pad since it lit, >= 0. */
  get padMoves(): number {
    return this.moves - this.movesAtLight;
  }
  /** Starts the round's clock at world time `time`, s (only the first call counts). */
  start(time: number): void {
    if (this.startedAt < 0) this.startedAt = time;
  }
  /** Whether the round is over. */
  get done(): boolean {
    return this.doneAt >= 0;
  }
  /**
   * The round's clock, s, >= 0: the world time between the start and the round's end (or the last
   * `update`) during which the cube was still (`cubeStill`) at the end of a step; 0 before the start.
   */
  time(): number {
    return this.clock;
  }
  /**
   * `blocked` once it has held, the same reason at every `update`, for BLOCKED_SETTLE_TIME s of world
   * time: the cube has come to rest on the lit pad and stays there (else ''). A cube only passing
   * through rest there, as it does for a step between two rolls or in a landing's bounce, gives ''.
   */
  get settledBlocked(): '' | 'face' | 'slide' {
    return this.blockedSince >= 0 && this.lastTime - this.blockedSince >= BLOCKED_SETTLE_TIME - 1e-9 ? this.blocked : '';
  }
  /**
   * Checks `body` against the lit pad after a step of `world` and lights the next one when it rests
   * there, its centre within the pad's half edge plus PAD_GRACE (a pad reached before `start` starts
   * the clock then); sets `over` and `blocked`. @returns whether a pad was reached by this call.
   */
  update(world: PhysicsWorld, body: number): boolean {
    const was = this.blocked;
    const reached = this.check(world, body);
    if (this.blocked !== was) this.blockedSince = this.blocked ? world.time : -1;
    return reached;
  }
  /** The work of `update`, which also keeps `blockedSince` (when `blocked` last changed). */
  private check(world: PhysicsWorld, body: number): boolean {
    const { pads, faces, halves } = this.layout;
    this.blocked = '';
    const dt = this.lastTime >= 0 ? Math.max(0, world.time - this.lastTime) : 0;
    this.lastTime = world.time;
    if (this.startedAt >= 0 && !this.done && cubeStill(world, body)) this.clock += Math.min(dt, world.time - this.startedAt);
    if (this.done) {
      this.over = false;
      return false;
    }
    const top = topFace(world, body);
    if (this.lastTop >= 0 && top !== this.lastTop) {
      this.rolls++;
      this.moves++;
      this.rolled = true;
    }
    if (this.pars.length === this.pad) this.pars.push(padMovePar(world, body, this.layout, this.pad));
    this.lastTop = top;
    const spot = pads[this.pad]!,
      face = faces[this.pad]!,
      reach = halves[this.pad]! + PAD_GRACE;
    const P = world.components.Position;
    this.over = Math.abs(P.x[body]! - spot[0]) <= reach && Math.abs(P.z[body]! - spot[1]) <= reach;
    if (!restsOnPad(world, body, spot[0], spot[1], reach)) {
      this.lowerPar(world, body);
      return false;
    }
    if (face >= 0 && top !== face) {
      this.blocked = 'face';
      this.lowerPar(world, body);
      return false;
    }
    if (face >= 0 && !this.rolled) {
      this.blocked = 'slide';
      this.lowerPar(world, body, SLID_ON_MOVES);
      return false;
    }
    this.over = false;
    this.start(world.time);
    this.pad++;
    this.movesAtLight = this.moves;
    if (this.pad === pads.length) this.doneAt = world.time;
    else this.pars.push(padMovePar(world, body, this.layout, this.pad));
    return true;
  }
  /**
   * Keeps the lit pad's par the fewest moves the player was shown (the page's "best: N more"): while
   * the cube rests flat, the moves made on the pad plus the fewest left from there (`left`, default
   * `padMovePar`; SLID_ON_MOVES when slid onto a face pad) is a way onto the pad. Before the pad's
   * first move that sets the par (one worked out as the pad lit, the cube still settling, may be off
   * by a cell); after it, it only lowers the par.
   */
  private lowerPar(world: PhysicsWorld, body: number, left = -2): void {
    if (!cubeStill(world, body) || world.components.Position.y[body]! > 0.55) return;
    const rest = left === -2 ? padMovePar(world, body, this.layout, this.pad) : left;
    const par = this.pars[this.pad] ?? -1;
    if (rest >= 0 && (par < 0 || this.padMoves === 0 || this.padMoves + rest < par)) this.pars[this.pad] = this.padMoves + rest;
  }
}

/**
 * How long, s, a cube resting on the lit pad must stay there, not counted for the same reason, before
 * the page says why (PadChallenge `settledBlocked`). The pad counts a landing the moment the cube is
 * still (`cubeStill`), but a roll's landing is still for a step or two in its bounce, and a queued
 * roll starts from there: with the wrong face on top that step is no reason to cry wrong face. At 60
 * steps a second a landing's bounce breaks its rest for 4 steps, 0.07 s; 0.25 s is well past that
 * and short enough to read as at once.
 */
export const BLOCKED_SETTLE_TIME = 0.25;

/** The fewest moves left with the cube slid onto the lit pad, the wanted face on top: a roll off and the roll back on. */
export const SLID_ON_MOVES = 2;

/**
 * Flip mode: the round's time to FLIP_GOAL flips, s, for three stars and for two (a win slower than
 * the second earns one). Spun up into FLIP_BAND with the yaw key and kept there by more yaw each time
 * it sags (held under 9 rad/s, let go over 11), the box flips FLIP_GOAL times in about 10 to 11 s:
 * two stars at most. Three take a pitch kick (W or S) that tips it off its intermediate axis: one
 * 0.35 s tap on reaching the band wins in about 6.5 s (test/games/rotating-cube-flip.test.ts).
 */
export const FLIP_STAR_TIMES: readonly [number, number] = Object.freeze([9, 12]) as readonly [number, number];

/**
 * Flip mode's challenge: count the box's flips (`FlipCounter`) made with its spin (`flipSpin`) inside FLIP_BAND
 * over FLIP_TIME seconds from `startedAt`, the world time of the player's first input (`start`: like
 * the pads' clock, reading the goal costs nothing; nothing counts before it); won when FLIP_GOAL
 * flips come within the time (`wonAt`), lost when the time runs out first. Stars (`stars`) only for
 * a round won after the player's inputs (`input`), by its time against FLIP_STAR_TIMES.
 */
export class FlipChallenge {
  /** The flips counted. */
  readonly counter = new FlipCounter();
  /** World time the goal was reached, s, or -1. */
  wonAt = -1;
  /** World time the round's clock started (the first input), s, or -1 before it. */
  startedAt = -1;
  /** The player's inputs (key presses, clicks on the box) counted by `input` since the reset, >= 0. */
  inputs = 0;
  private readonly L = new Float64Array(3);
  private readonly axis = new Float64Array(3);
  /** Starts again. */
  reset(): void {
    this.counter.reset();
    this.wonAt = -1;
    this.startedAt = -1;
    this.inputs = 0;
  }
  /** Starts the round's clock at world time `time`, s (only the first call counts). */
  start(time: number): void {
    if (this.startedAt < 0) this.startedAt = time;
  }
  /** Counts an input of the player at world time `time`, s, and starts the round's clock with the first (`start`). */
  input(time: number): void {
    this.start(time);
    this.inputs++;
  }
  /** The round's clock at world time `now`, s: 0 before the start, at most FLIP_TIME, the time taken once won. */
  time(now: number): number {
    if (this.startedAt < 0) return 0;
    return Math.min(FLIP_TIME, Math.max(0, (this.wonAt >= 0 ? this.wonAt : now) - this.startedAt));
  }
  /** Whether the round is over (won, or FLIP_TIME passed since the start). */
  over(world: PhysicsWorld): boolean {
    return this.wonAt >= 0 || (this.startedAt >= 0 && world.time - this.startedAt >= FLIP_TIME);
  }
  /**
   * Stars of the round: 0 unless it was won after at least one input of the player (`inputs`); then 3
   * for FLIP_GOAL flips within FLIP_STAR_TIMES[0] s of the start, 2 within FLIP_STAR_TIMES[1] s, else 1.
   */
  stars(): number {
    if (this.wonAt < 0 || this.inputs === 0) return 0;
    const t = this.wonAt - this.startedAt;
    return t <= FLIP_STAR_TIMES[0] ? 3 : t <= FLIP_STAR_TIMES[1] ? 2 : 1;
  }
  /** Feeds the body's state after a step of `world` (nothing before the start or once the round is over). */
  update(world: PhysicsWorld, body: number): void {
    if (this.startedAt < 0 || this.over(world)) return;
    const L = this.L,
      a = this.axis,
      q = world.components.Orientation;
    spinAngularMomentum(world, body, L);
    const l = Math.hypot(L[0]!, L[1]!, L[2]!);
    if (!(l > 0)) return;
    // The body's y axis in the world frame: (0, 1, 0) rotated by q, the inverse rotation by its conjugate.
    rotateVectorInverse(-q.x[body]!, -q.y[body]!, -q.z[body]!, q.w[body]!, 0, 1, 0, a);
    const w = flipSpin(l);
    const inBand = w >= FLIP_BAND[0] && w <= FLIP_BAND[1];
    if (this.counter.update((a[0]! * L[0]! + a[1]! * L[1]! + a[2]! * L[2]!) / l, inBand) >= FLIP_GOAL) this.wonAt = world.time;
  }
}
