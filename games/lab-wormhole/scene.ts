/**
 * The wormhole scene, DOM-free (Ramtal and Dobre ch. 12, "particles in force fields: a wormhole").
 * G = 1 game units: lengths m, masses kg, the holes' "masses" are G M in m^3/s^2.
 *
 * - The black hole is a static body carrying the physics package's Attractor component: every star
 *   feels F = -G M m r / (r^2 + eps^2)^(3/2), r from the hole (softened, eps = 0.3 m).
 * - The white hole pushes outward with the same inverse-square law reversed. An Attractor cannot do
 *   that (its mass must be > 0: setAttractor rejects a negative one, and it only ever pulls), so the
 *   push is composed from the general central force F = k r^(n-1) r_hat with n = -1 (inverse square)
 *   and k = +G M_w m > 0 (repulsive), given to every star with the white hole as its centre
 *   (setCentralForce). Far from both holes the two laws add up to the field of a net mass
 *   M - M_w at distance r plus a dipole: with M_w < M the stars are pulled back in from afar.
 * - The wormhole itself is a rule, not a force: after each step a star closer to the black hole than
 *   the horizon radius r_h is moved (setPosition, which also sets PreviousPosition so nothing sweeps
 *   or streaks across the jump) to the same offset from the white hole, n r_h with n the unit vector
 *   from the black hole to the star, and given its velocity reflected about n (setVelocity with
 *   v - 2 (v.n) n): same speed, the radial part now pointing out of the white hole.
 * - Stars carry linear drag F = -k v (k per kg of star, s^-1), so they lose the energy the white hole
 *   gives them and fall back; stars that wander beyond `CULL_RADIUS` from the origin re-enter the
 *   black hole's disc (between `DISC_INNER` and `DISC_OUTER` from it, on the circular orbit of its
 *   pull alone): a game rule that keeps the flow going.
 */
import {
  addBody,
  createPhysicsWorld,
  type PhysicsWorld,
  Rng,
  setAttractor,
  setCentralForce,
  setDrag,
  setGravitation,
  setPosition,
  setVelocity,
  step,
} from '@bitphysics/physics';

/** Distance from the origin beyond which a star re-enters, m. */
export const CULL_RADIUS = 19;
/** The black hole's disc, where stars start and re-enter: inner and outer radius, m. */
export const DISC_INNER = 1.5;
export const DISC_OUTER = 6;
/** Softening of the black hole's pull, m. */
export const BLACK_HOLE_SOFTENING = 0.3;
/** Most stars added by clicks on top of the initial ones. */
export const EXTRA_STARS = 1000;

/** Options of the wormhole. Every field optional. */
export interface WormholeOptions {
  /** Initial stars, integer in [1, 20_000]. Default 2000. */
  count?: number;
  /** Black hole G M, m^3/s^2, > 0. Default 60. */
  blackHole?: number;
  /** White hole G M_w (strength of the push), m^3/s^2, >= 0. Default 30. */
  whiteHole?: number;
  /** Horizon radius r_h, m, > BLACK_HOLE_SOFTENING. Default 0.8. */
  horizon?: number;
  /** Linear drag per kg of star, 1/s, >= 0. Default 0.5. */
  drag?: number;
  /** Positions of the holes, m. Defaults (-6, 0) and (6, 0). */
  blackHolePosition?: [number, number];
  whiteHolePosition?: [number, number];
  /** Seed. Default 1. */
  seed?: number;
}

/** The running wormhole: entity ids, settings and counters (mutable; the page and tests read it). */
export interface Wormhole {
  readonly world: PhysicsWorld;
  /** The black hole (static, Attractor) and white hole (static marker) bodies. */
  readonly blackHole: number;
  readonly whiteHole: number;
  /** Star ids, oldest first; `count` of `ids` in use. */
  readonly ids: Uint32Array;
  count: number;
  /** Current settings. */
  settings: Required<Omit<WormholeOptions, 'count' | 'seed' | 'blackHolePosition' | 'whiteHolePosition'>>;
  /** Stars moved through the wormhole since the start. */
  teleports: number;
  /** Stars that re-entered the black hole's disc after wandering off. */
  respawns: number;
  /** The last jump: speed before and after (m/s), and where the star came out (m). */
  readonly last: { speedIn: number; speedOut: number; x: number; y: number; step: number };
  /** Generator of re-entry points and click spawns. */
  readonly rng: Rng;
}

const scratchP = new Float64Array(2);
const scratchV = new Float64Array(2);

function check(where: string, name: string, v: number, min: number, max: number): void {
  if (typeof v !== 'number' || !(v >= min && v <= max))
    throw new RangeError(`${where}: ${name} must be in [${min}, ${max}], got ${String(v)}`);
}

/**
 * Builds a world with the two holes and `count` stars in the black hole's disc (see `placeInDisc`).
 * @throws RangeError on an option out of range.
 */
export function createWormhole(options: WormholeOptions = {}): Wormhole {
  const where = 'createWormhole';
  const count = options.count ?? 2000;
  if (!Number.isInteger(count) || count < 1 || count > 20_000)
    throw new RangeError(`${where}: count must be an integer in [1, 20000], got ${count}`);
  const settings = {
    blackHole: options.blackHole ?? 60,
    whiteHole: options.whiteHole ?? 30,
    horizon: options.horizon ?? 0.8,
    drag: options.drag ?? 0.5,
  };
  check(where, 'blackHole', settings.blackHole, 1e-6, 1e6);
  check(where, 'whiteHole', settings.whiteHole, 0, 1e6);
  check(where, 'horizon', settings.horizon, BLACK_HOLE_SOFTENING, 10);
  check(where, 'drag', settings.drag, 0, 100);
  const world = createPhysicsWorld({ dimensions: 2, capacity: count + EXTRA_STARS + 8, gravity: [0, 0], seed: options.seed ?? 1 });
  setGravitation(world, { constant: 1 });
  const bhp = options.blackHolePosition ?? [-6, 0],
    whp = options.whiteHolePosition ?? [6, 0];
  const blackHole = addBody(world, { position: bhp, static: true });
  setAttractor(world, blackHole, { mass: settings.blackHole, softening: BLACK_HOLE_SOFTENING });
  const whiteHole = addBody(world, { position: whp, static: true });
  const w: Wormhole = {
    world,
    blackHole,
    whiteHole,
    ids: new Uint32Array(count + EXTRA_STARS),
    count: 0,
    settings,
    teleports: 0,
    respawns: 0,
    last: { speedIn: Number.NaN, speedOut: Number.NaN, x: Number.NaN, y: Number.NaN, step: -1 },
    rng: new Rng(options.seed ?? 1),
  };
  for (let i = 0; i < count; i++) {
    placeInDisc(w);
    addStar(w, scratchP[0]!, scratchP[1]!, scratchV[0]!, scratchV[1]!);
  }
  return w;
}

/**
 * Draws a place in the black hole's disc into scratchP / scratchV: radius uniform in
 * [DISC_INNER, DISC_OUTER], counter-clockwise circular speed sqrt(G M / r) of the black hole's pull.
 */
function placeInDisc(w: Wormhole): void {
  const P = w.world.components.Position;
  const r = w.rng.range(DISC_INNER, DISC_OUTER),
    a = w.rng.range(0, 2 * Math.PI),
    v = Math.sqrt(w.settings.blackHole / r);
  scratchP[0] = P.x[w.blackHole]! + r * Math.cos(a);
  scratchP[1] = P.y[w.blackHole]! + r * Math.sin(a);
  scratchV[0] = -v * Math.sin(a);
  scratchV[1] = v * Math.cos(a);
}

/**
 * Adds a star (1 kg) at (x, y), m, with velocity (vx, vy), m/s, feeling the white hole's push and the
 * drag. @returns its id, or 0 when there is no room (the world is full).
 */
export function addStar(w: Wormhole, x: number, y: number, vx = 0, vy = 0): number {
  if (w.count >= w.ids.length || w.world.entityIndex.aliveCount >= w.world.capacity) return 0;
  scratchP[0] = x;
  scratchP[1] = y;
  scratchV[0] = vx;
  scratchV[1] = vy;
  const e = addBody(w.world, { position: scratchP, velocity: scratchV, mass: 1, linearDrag: w.settings.drag });
  setCentralForce(w.world, e, { centre: holeAt(w, w.whiteHole), k: w.settings.whiteHole, n: -1 });
  w.ids[w.count++] = e;
  return e;
}

const holeScratch: [number, number] = [0, 0];
function holeAt(w: Wormhole, hole: number): [number, number] {
  const P = w.world.components.Position;
  holeScratch[0] = P.x[hole]!;
  holeScratch[1] = P.y[hole]!;
  return holeScratch;
}

/** Sets the black hole's G M, m^3/s^2 (> 0). @throws RangeError otherwise. */
export function setBlackHoleMass(w: Wormhole, gm: number): void {
  check('setBlackHoleMass', 'gm', gm, 1e-6, 1e6);
  w.settings.blackHole = gm;
  setAttractor(w.world, w.blackHole, { mass: gm, softening: BLACK_HOLE_SOFTENING });
}

/** Sets the white hole's push G M_w, m^3/s^2 (>= 0), on every star. @throws RangeError otherwise. */
export function setWhiteHoleStrength(w: Wormhole, gm: number): void {
  check('setWhiteHoleStrength', 'gm', gm, 0, 1e6);
  w.settings.whiteHole = gm;
  refreshPush(w);
}

/** Sets the horizon radius, m, in [BLACK_HOLE_SOFTENING, 10]. @throws RangeError otherwise. */
export function setHorizon(w: Wormhole, r: number): void {
  check('setHorizon', 'r', r, BLACK_HOLE_SOFTENING, 10);
  w.settings.horizon = r;
}

/** Sets the stars' linear drag per kg, 1/s (>= 0). @throws RangeError otherwise. */
export function setStarDrag(w: Wormhole, k: number): void {
  check('setStarDrag', 'k', k, 0, 100);
  w.settings.drag = k;
  for (let i = 0; i < w.count; i++) setDrag(w.world, w.ids[i]!, { linear: k });
}

/** Moves hole `which` to (x, y), m; moving the white hole moves the centre of every star's push. */
export function moveHole(w: Wormhole, which: 'black' | 'white', x: number, y: number): void {
  scratchP[0] = x;
  scratchP[1] = y;
  setPosition(w.world, which === 'black' ? w.blackHole : w.whiteHole, scratchP);
  if (which === 'white') refreshPush(w);
}

function refreshPush(w: Wormhole): void {
  const centre = holeAt(w, w.whiteHole);
  for (let i = 0; i < w.count; i++) setCentralForce(w.world, w.ids[i]!, { centre, k: w.settings.whiteHole, n: -1 });
}

/**
 * One step: physics, then the wormhole rule (stars inside the horizon come out of the white hole with
 * their speed and the reflected direction) and the re-entry rule. No allocation.
 */
export function stepWormhole(w: Wormhole): void {
  const world = w.world;
  step(world);
  const P = world.components.Position,
    V = world.components.Velocity;
  const bx = P.x[w.blackHole]!,
    by = P.y[w.blackHole]!,
    wx = P.x[w.whiteHole]!,
    wy = P.y[w.whiteHole]!;
  const rh = w.settings.horizon,
    cull2 = CULL_RADIUS * CULL_RADIUS;
  const ids = w.ids;
  for (let i = 0; i < w.count; i++) {
    const e = ids[i]!;
    const x = P.x[e]!,
      y = P.y[e]!;
    const dx = x - bx,
      dy = y - by;
    const r2 = dx * dx + dy * dy;
    if (r2 < rh * rh) {
      const r = Math.sqrt(r2);
      // n: unit vector from the black hole to the star (any direction if it sits on the centre).
      const nx = r > 0 ? dx / r : 1,
        ny = r > 0 ? dy / r : 0;
      const vx = V.x[e]!,
        vy = V.y[e]!;
      const vn = vx * nx + vy * ny;
      scratchP[0] = wx + nx * rh;
      scratchP[1] = wy + ny * rh;
      scratchV[0] = vx - 2 * vn * nx;
      scratchV[1] = vy - 2 * vn * ny;
      setPosition(world, e, scratchP);
      setVelocity(world, e, scratchV);
      w.teleports++;
      const last = w.last;
      last.speedIn = Math.sqrt(vx * vx + vy * vy);
      last.speedOut = Math.hypot(scratchV[0], scratchV[1]);
      last.x = scratchP[0];
      last.y = scratchP[1];
      last.step = world.steps;
    } else if (x * x + y * y > cull2) {
      placeInDisc(w);
      setPosition(world, e, scratchP);
      setVelocity(world, e, scratchV);
      w.respawns++;
    }
  }
}
