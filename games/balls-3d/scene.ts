/**
 * The balls-3d scene: the book's chapter 15 demo (bouncing balls in a 3D box) grown up. A pure,
 * seeded builder in the shape of the physics package's scenes (world options + build), kept next to
 * the game; no DOM, no three.js, so it runs in Node too.
 *
 * A glass box 4 m wide, 3 m tall and 4 m deep (`setBoundary`); `count` balls of three sizes (0.6, 1
 * and 1.5 times a mean radius that makes the balls fill about 8% of the box) and one density (so mass
 * goes with r^3) on a jittered grid in the upper part of the box, with random horizontal velocities.
 */
import {
  addBody,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  Rng,
  removeBody,
  setBoundary,
  setGravity,
  setMaterial,
} from '@bitphysics/physics';

/** Options of the scene. Every field optional. */
export interface Balls3DOptions {
  /** Number of balls, integer in [1, 10_000]. Default 300. */
  count?: number;
  /** Seed of the layout, sizes and starting velocities. Default 1. */
  seed?: number;
  /** Magnitude of gravity, m/s^2, in [0, 100] (pointing down, -y). Default 9.81. */
  gravity?: number;
  /** Restitution of balls and walls, [0, 1]. Default 0.6. */
  restitution?: number;
  /** Friction coefficient of balls and walls, >= 0. Default 0.3. */
  friction?: number;
  /** Extra room for balls thrown later, integer in [0, 100_000]. Default 500. */
  spawnBudget?: number;
}

/** Resolved options. */
export type Balls3DParams = Required<Balls3DOptions>;

/** Inner corners of the glass box, m. */
export const BOX = Object.freeze({ min: [-2, 0, -2] as const, max: [2, 3, 2] as const });

/** Ball sizes as factors of the mean radius, and how often each is picked (cumulative). */
export const SIZES = Object.freeze([
  { factor: 0.6, upTo: 0.4 },
  { factor: 1, upTo: 0.85 },
  { factor: 1.5, upTo: 1 },
]);

/** Density of every ball, kg/m^3 (water: a 10 cm ball weighs about 4 kg). */
export const DENSITY = 1000;

/** What `buildBalls3D` returns; the game keeps it to change materials and to throw balls. */
export interface Balls3DHandles {
  /** Entity ids of the balls, oldest first (thrown balls are appended; the oldest goes when the world is full). */
  balls: number[];
  /** Mean ball radius, m. */
  meanRadius: number;
  /** The options used (kept up to date by `applyMaterial` and `applyGravity`). */
  params: Balls3DParams;
  /** Generator of thrown balls' sizes (seeded from the scene seed). */
  rng: Rng;
}

function check(cond: boolean, message: string): void {
  if (!cond) throw new RangeError(`balls-3d: ${message}`);
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolveOptions(options: Balls3DOptions = {}): Balls3DParams {
  const known = ['count', 'seed', 'gravity', 'restitution', 'friction', 'spawnBudget'];
  for (const k of Object.keys(options)) {
    if (!known.includes(k)) throw new TypeError(`balls-3d: unknown option ${JSON.stringify(k)}; known options are ${known.join(', ')}`);
  }
  const p: Balls3DParams = {
    count: options.count ?? 300,
    seed: options.seed ?? 1,
    gravity: options.gravity ?? 9.81,
    restitution: options.restitution ?? 0.6,
    friction: options.friction ?? 0.3,
    spawnBudget: options.spawnBudget ?? 500,
  };
  check(Number.isInteger(p.count) && p.count >= 1 && p.count <= 10_000, `count must be an integer in [1, 10000], got ${p.count}`);
  check(Number.isFinite(p.seed), `seed must be finite, got ${p.seed}`);
  check(p.gravity >= 0 && p.gravity <= 100, `gravity must be in [0, 100] m/s^2, got ${p.gravity}`);
  check(p.restitution >= 0 && p.restitution <= 1, `restitution must be in [0, 1], got ${p.restitution}`);
  check(p.friction >= 0 && Number.isFinite(p.friction), `friction must be >= 0, got ${p.friction}`);
  check(
    Number.isInteger(p.spawnBudget) && p.spawnBudget >= 0 && p.spawnBudget <= 100_000,
    `spawnBudget must be an integer in [0, 100000], got ${p.spawnBudget}`,
  );
  return p;
}

/** World options for the scene: 3D, room for the balls and the spawn budget, gravity, seed. */
export function balls3DWorldOptions(options: Balls3DOptions = {}): PhysicsWorldOptions {
  const p = resolveOptions(options);
  return { dimensions: 3, capacity: p.count + p.spawnBudget + 8, gravity: [0, -p.gravity, 0], seed: p.seed };
}

/** Volume of the box, m^3. */
const BOX_VOLUME = (BOX.max[0] - BOX.min[0]) * (BOX.max[1] - BOX.min[1]) * (BOX.max[2] - BOX.min[2]);

/**
 * Mean radius, m, for `count` balls: their mean volume (4/3 pi r^3, r the mean radius) times count
 * is 8% of the box; clamped to [0.03, 0.3] m.
 */
export function meanRadiusFor(count: number): number {
  return Math.min(0.3, Math.max(0.03, Math.cbrt((0.08 * BOX_VOLUME) / (count * (4 / 3) * Math.PI))));
}

/** A size factor drawn from `SIZES`. */
function sizeFactor(rng: Rng): number {
  const u = rng.next();
  for (const s of SIZES) if (u < s.upTo) return s.factor;
  return SIZES[SIZES.length - 1]!.factor;
}

/**
 * Builds the scene into `world` (a fresh 3D world, ideally from `balls3DWorldOptions`).
 * @throws TypeError | RangeError on bad options, a 2D world, or a count that does not fit the box.
 */
export function buildBalls3D(world: PhysicsWorld, options: Balls3DOptions = {}): Balls3DHandles {
  const p = resolveOptions(options);
  check(world.dimensions === 3, `needs a 3D world, got dimensions ${world.dimensions}`);
  const rng = new Rng(p.seed);
  setBoundary(world, { min: BOX.min, max: BOX.max, restitution: p.restitution, friction: p.friction });
  const rMean = meanRadiusFor(p.count);
  const rMax = 1.5 * rMean;
  const pitch = 2 * rMax * 1.12;
  const x0 = BOX.min[0] + rMax + 0.02,
    x1 = BOX.max[0] - rMax - 0.02;
  const z0 = BOX.min[2] + rMax + 0.02,
    z1 = BOX.max[2] - rMax - 0.02;
  const cols = Math.max(1, Math.floor((x1 - x0) / pitch) + 1);
  const rows = Math.max(1, Math.floor((z1 - z0) / pitch) + 1);
  const jitter = 0.45 * (pitch - 2 * rMax);
  const handles: Balls3DHandles = { balls: [], meanRadius: rMean, params: p, rng };
  const pos = [0, 0, 0],
    vel = [0, 0, 0];
  let y = BOX.max[1] - rMax - 0.02;
  while (handles.balls.length < p.count) {
    check(y >= BOX.min[1] + rMax, `${p.count} balls do not fit the box`);
    for (let j = 0; j < rows && handles.balls.length < p.count; j++) {
      for (let i = 0; i < cols && handles.balls.length < p.count; i++) {
        pos[0] = x0 + i * pitch + rng.range(-jitter, jitter);
        pos[1] = y + rng.range(-jitter, jitter);
        pos[2] = z0 + j * pitch + rng.range(-jitter, jitter);
        vel[0] = rng.range(-1.5, 1.5);
        vel[1] = rng.range(-0.5, 0.5);
        vel[2] = rng.range(-1.5, 1.5);
        handles.balls.push(addBall(world, p, pos, vel, rMean * sizeFactor(rng)));
      }
    }
    y -= pitch;
  }
  return handles;
}

function addBall(world: PhysicsWorld, p: Balls3DParams, position: ArrayLike<number>, velocity: ArrayLike<number>, radius: number): number {
  return addBody(world, { position, velocity, radius, density: DENSITY, restitution: p.restitution, friction: p.friction });
}

/**
 * Adds a ball at `position` (m, clamped inside the box) with `velocity` (m/s) and radius `radius` m
 * (default: one of the scene's sizes, seeded). If the world is full the oldest ball goes first.
 * @returns the new entity id. @throws RangeError on non-finite input or radius <= 0.
 */
export function spawnBall(
  world: PhysicsWorld,
  h: Balls3DHandles,
  position: ArrayLike<number>,
  velocity: ArrayLike<number> = [0, 0, 0],
  radius?: number,
): number {
  for (let i = 0; i < 3; i++) {
    check(Number.isFinite(position[i]), `spawnBall: position[${i}] must be finite, got ${position[i]}`);
    check(Number.isFinite(velocity[i]), `spawnBall: velocity[${i}] must be finite, got ${velocity[i]}`);
  }
  const r = radius ?? h.meanRadius * sizeFactor(h.rng);
  check(r > 0 && Number.isFinite(r), `spawnBall: radius must be > 0, got ${r}`);
  const p = [0, 0, 0];
  for (let i = 0; i < 3; i++) p[i] = Math.min(BOX.max[i]! - r, Math.max(BOX.min[i]! + r, position[i]!));
  if (world.entityIndex.aliveCount >= world.capacity && h.balls.length > 0) removeBody(world, h.balls.shift()!);
  const eid = addBall(world, h.params, p, velocity, r);
  h.balls.push(eid);
  return eid;
}

/** Sets restitution and friction of every ball and the box. @throws RangeError on values out of range. */
export function applyMaterial(world: PhysicsWorld, h: Balls3DHandles, restitution: number, friction: number): void {
  check(restitution >= 0 && restitution <= 1, `restitution must be in [0, 1], got ${restitution}`);
  check(friction >= 0 && Number.isFinite(friction), `friction must be >= 0, got ${friction}`);
  h.params.restitution = restitution;
  h.params.friction = friction;
  const m = { restitution, friction };
  for (const e of h.balls) setMaterial(world, e, m);
  setBoundary(world, { min: BOX.min, max: BOX.max, restitution, friction });
}

/** Sets gravity to g m/s^2 pointing down (-y). @throws RangeError unless g is in [0, 100]. */
export function applyGravity(world: PhysicsWorld, h: Balls3DHandles, g: number): void {
  check(g >= 0 && g <= 100, `gravity must be in [0, 100] m/s^2, got ${g}`);
  h.params.gravity = g;
  setGravity(world, [0, -g, 0]);
}

/**
 * Where a ray (origin o, unit direction d; m) enters the box shrunk by `margin` m on every side:
 * the slab method (Kay and Kajiya, SIGGRAPH 1986). Returns the entry distance t >= 0 (0 when o is
 * inside), or -1 if the ray misses.
 */
export function rayEntersBox(o: ArrayLike<number>, d: ArrayLike<number>, margin = 0): number {
  let t0 = 0,
    t1 = Infinity;
  for (let i = 0; i < 3; i++) {
    const lo = BOX.min[i]! + margin,
      hi = BOX.max[i]! - margin;
    const di = d[i]!,
      oi = o[i]!;
    if (Math.abs(di) < 1e-12) {
      if (oi < lo || oi > hi) return -1;
      continue;
    }
    let a = (lo - oi) / di,
      b = (hi - oi) / di;
    if (a > b) {
      const t = a;
      a = b;
      b = t;
    }
    if (a > t0) t0 = a;
    if (b < t1) t1 = b;
    if (t0 > t1) return -1;
  }
  return t0;
}

/** Removes ball `eid` from the world and from `h.balls`. @throws RangeError if it is not one of the scene's balls. */
export function removeBall(world: PhysicsWorld, h: Balls3DHandles, eid: number): void {
  const i = h.balls.indexOf(eid);
  check(i >= 0, `removeBall: ${eid} is not a ball of this scene`);
  h.balls.splice(i, 1);
  removeBody(world, eid);
}
