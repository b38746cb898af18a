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
 *   momentum stays fixed (the Dzhanibekov or tennis-racket effect; Ashbaugh, Chicone and Cushman,
 *   "The twisting tennis racket", J. Dyn. Diff. Eq. 3, 1991).
 */
import {
  addBody,
  addPlane,
  addShape3D,
  addSystem,
  applyForceAtPoint,
  inertiaOfSolidBox,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  type System,
  setAngularVelocity,
} from '@bitphysics/physics';

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

/** Options of `buildRotatingCube`. */
export interface RotatingCubeOptions {
  /** The mode. Default 'room'. */
  mode?: Mode;
  /** Flip mode: spin about the intermediate (y) axis, rad/s, finite. Default 6. */
  spin?: number;
  /** Flip mode: the perturbation about x and z, rad/s, finite. Default 0.01. */
  perturbation?: number;
  /** Cube mode: the starting angular velocity, rad/s, world frame. Default (0.35, 0.8, 0.2). */
  tumble?: ArrayLike<number>;
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
 * @throws RangeError on an unknown mode, a non-finite spin, perturbation or tumble, or a 2D world.
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
  const mass = MASS[mode];
  const inertia = inertiaOfSolidBox(mass, EDGES[mode]);
  if (mode === 'room') return buildRoom(world, tumble);
  const body = addBody(world, {
    position: [0, 0, 0],
    mass,
    inertia,
    angularVelocity: mode === 'flip' ? [perturbation, spin, perturbation] : tumble,
  });
  const pivot: [number, number, number] = [0, 0, 0];
  addSystem(world, 'constraints', holdAtPivot(body, pivot));
  return { body, mode, inertia, pivot, walls: [] };
}

/**
 * Room mode: a floor (plane y = 0, friction 0.5) and four static box walls around a 2 ROOM_HALF square,
 * and the cube (1 kg, a 1 m box collider of density 1 kg/m^3, restitution 0.3) dropped tumbling from 1.5 m.
 */
function buildRoom(world: PhysicsWorld, tumble: ArrayLike<number>): RotatingCubeHandles {
  addPlane(world, { normal: [0, 1, 0], point: [0, 0, 0], friction: 0.5, restitution: 0.3 });
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
    addShape3D(world, wall, { type: 'box', halfExtents: [hx, h, hz], friction: 0.5, restitution: 0.3 });
    walls.push(wall);
  }
  const body = addBody(world, { position: [0, 1.5, 0], orientation: [0.2, 0.1, 0.15, 0.96] });
  addShape3D(world, body, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: MASS.room, friction: 0.5, restitution: 0.3 });
  setAngularVelocity(world, body, tumble);
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
