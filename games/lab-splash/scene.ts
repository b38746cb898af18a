/**
 * The splash scene, DOM-free (Ramtal and Dobre ch. 12, "splash"). SI units, y up, g = 9.81 m/s^2.
 *
 * Raindrops (particles of a line emitter high up, and of a point emitter for drops dropped by hand;
 * 30 mg, quadratic drag for a terminal speed of 8 m/s) fall onto a pool (x < 0) and onto the ground (x > 0), both with their surface at y = 0.
 * - On the ground: a drop has a collider (radius 4 cm) and the ground is a static segment, so the
 *   contact solver stops it there; the impact is read from the last step's contacts (a contact of
 *   the drop with the ground segment, its normal impact speed). The drop bursts: it is removed and the
 *   ground-splash emitter spawns droplets at the impact point (emitNow), as many as the impact is
 *   hard (2 per m/s), launched upwards in a fan of +-69 degrees at 1.2 to 2.8 m/s plus 10% of the drop's
 *   velocity with its vertical part reflected. Droplets have colliders (8 mm) too, so they bounce
 *   on the ground with its restitution 0.35 (the larger of the pair's; contacts slower than the
 *   world's 0.5 m/s threshold do not bounce), feel gravity and quadratic air drag, and fade out
 *   over 0.8 to 1.6 s.
 * - In the pool: water is not a collider; a drop whose centre crosses y = 0 above the pool is
 *   removed and the water-splash emitter throws up a crown of droplets (fan of +-35 degrees, 1 to
 *   2.5 m/s plus 15% of the reflected velocity, 1.4 times as many); droplets falling back through the surface rejoin the
 *   pool (removed) and leave a ripple.
 * Counting: `splashCount` is the number of splash droplets alive (both emitters), `dropCount` the
 * number of raindrops in the air.
 */

import {
  addEmitter,
  addSegment,
  ContactKind,
  createPhysicsWorld,
  emitNow,
  handleOf,
  type PhysicsWorld,
  removeBody,
  setEmitterRate,
  setMaterial,
  slotOf,
  step,
} from '@bitphysics/physics';
import { query } from 'bitecs';

/** Where the pool ends and the ground begins, m; the pool's left edge and bottom; the ground's right end. */
export const POOL = Object.freeze({ minX: -5, maxX: 0, bottom: -1.6 });
export const GROUND_END = 6;
/** Height the rain falls from, m. */
export const CLOUD_HEIGHT = 6;
/** Radius of a raindrop and of a splash droplet, m. */
export const DROP_RADIUS = 0.04,
  DROPLET_RADIUS = 0.008;
/**
 * Ground droplets start spread over a disc of this radius (m) above the impact point, not all at one
 * point: droplets have colliders, and a heap of overlapping balls would be pushed apart by the solver
 * and, colliding inelastically, share one velocity (a column instead of a fan).
 */
export const SPLASH_DISC = 0.08;
/** Most raindrops per second. */
export const MAX_RAIN = 40;
/** Ripples remembered (oldest overwritten). */
export const MAX_RIPPLES = 32;

/** Settings of the splash. */
export interface SplashSettings {
  /** Raindrops per second from the cloud, [0, MAX_RAIN]. Default 6. */
  rain: number;
  /** Droplets per m/s of impact speed, [0, 20]. Default 2 (a 7 m/s drop makes 14). */
  dropletsPerSpeed: number;
  /** Restitution of the ground, [0, 1]. Default 0.35. */
  restitution: number;
  /** Seed. Default 1. */
  seed: number;
}

/** The running splash. */
export interface Splash {
  readonly world: PhysicsWorld;
  /** Emitters: rain (line, from the cloud), hand (point, click drops), ground and water splashes. */
  readonly rain: number;
  readonly hand: number;
  readonly groundSplash: number;
  readonly waterSplash: number;
  /** The ground segment. */
  readonly ground: number;
  readonly settings: SplashSettings;
  /** Impacts so far on the ground and in the water, and droplets that fell back into the pool. */
  groundImpacts: number;
  waterImpacts: number;
  absorbed: number;
  /** Ripples: x (m) and start time (s) of the last MAX_RIPPLES water entries (ring buffer). */
  readonly rippleX: Float64Array;
  readonly rippleT: Float64Array;
  rippleHead: number;
  /** The last impact: where (m), how fast (normal speed, m/s), how many droplets, what it hit. */
  readonly last: { x: number; speed: number; droplets: number; surface: 'ground' | 'water' | ''; time: number };
}

function check(where: string, name: string, v: number, min: number, max: number): void {
  if (typeof v !== 'number' || !(v >= min && v <= max))
    throw new RangeError(`${where}: ${name} must be in [${min}, ${max}], got ${String(v)}`);
}

/** Builds the ground, the four emitters and the pool rules. @throws RangeError on a setting out of range. */
export function createSplash(options: Partial<SplashSettings> = {}): Splash {
  const settings: SplashSettings = { rain: 6, dropletsPerSpeed: 2, restitution: 0.35, seed: 1, ...options };
  check('createSplash', 'rain', settings.rain, 0, MAX_RAIN);
  check('createSplash', 'dropletsPerSpeed', settings.dropletsPerSpeed, 0, 20);
  check('createSplash', 'restitution', settings.restitution, 0, 1);
  const world = createPhysicsWorld({ dimensions: 2, capacity: 6000, gravity: [0, -9.81], seed: settings.seed });
  const ground = addSegment(world, { a: [POOL.maxX, 0], b: [GROUND_END, 0], restitution: settings.restitution, friction: 0.4 });
  // The pool's rim on the ground side, so droplets do not roll off the ground's end into the water.
  addSegment(world, { a: [POOL.maxX, 0], b: [POOL.maxX, POOL.bottom] });
  // A 30 mg drop with drag k = 4.6e-6 kg/m: terminal speed sqrt(m g / k) = 8 m/s, as for a 4 mm raindrop.
  const drop = {
    mass: 3e-5,
    quadraticDrag: 4.6e-6,
    radius: DROP_RADIUS,
    colorStart: 0xbfe0ff,
    colorEnd: 0xbfe0ff,
    sizeStart: 0.1,
    sizeEnd: 0.1,
    alphaStart: 0.95,
    alphaEnd: 0.95,
  };
  const rain = addEmitter(world, {
    position: [(POOL.minX + GROUND_END) / 2, CLOUD_HEIGHT],
    rate: settings.rain,
    shape: 'line',
    size: (GROUND_END - POOL.minX) / 2 - 0.3,
    direction: [0, -1],
    spread: 0.03,
    speed: [3, 5],
    lifetime: 10,
    policy: 'recycle-oldest',
    particle: drop,
  });
  const hand = addEmitter(world, {
    position: [0, CLOUD_HEIGHT],
    direction: [0, -1],
    spread: 0,
    speed: 1,
    lifetime: 10,
    policy: 'recycle-oldest',
    particle: drop,
  });
  const groundSplash = addEmitter(world, {
    position: [0, 0],
    shape: 'disc',
    size: SPLASH_DISC,
    direction: [0, 1],
    spread: 1.2,
    speed: [1.2, 2.8],
    lifetime: [0.8, 1.6],
    inheritVelocity: 0.1,
    policy: 'recycle-oldest',
    particle: {
      mass: 2e-6,
      quadraticDrag: 5e-8,
      radius: DROPLET_RADIUS,
      colorStart: 0xe6f3ff,
      colorEnd: 0x7fb4e6,
      sizeStart: 0.09,
      sizeEnd: 0.06,
      alphaStart: 1,
      alphaEnd: 0,
    },
  });
  const waterSplash = addEmitter(world, {
    position: [0, 0],
    direction: [0, 1],
    spread: 0.6,
    speed: [1, 2.5],
    lifetime: [1, 2],
    inheritVelocity: 0.15,
    policy: 'recycle-oldest',
    particle: {
      mass: 2e-6,
      quadraticDrag: 5e-8,
      colorStart: 0xffffff,
      colorEnd: 0x9cc8f0,
      sizeStart: 0.09,
      sizeEnd: 0.06,
      alphaStart: 1,
      alphaEnd: 0.2,
    },
  });
  return {
    world,
    rain,
    hand,
    groundSplash,
    waterSplash,
    ground,
    settings,
    groundImpacts: 0,
    waterImpacts: 0,
    absorbed: 0,
    rippleX: new Float64Array(MAX_RIPPLES),
    rippleT: new Float64Array(MAX_RIPPLES).fill(-Infinity),
    rippleHead: 0,
    last: { x: Number.NaN, speed: Number.NaN, droplets: 0, surface: '', time: Number.NaN },
  };
}

/** Sets the rain, drops per second from the cloud, [0, MAX_RAIN]. @throws RangeError otherwise. */
export function setRain(s: Splash, rate: number): void {
  check('setRain', 'rate', rate, 0, MAX_RAIN);
  s.settings.rain = rate;
  setEmitterRate(s.world, s.rain, rate);
}

/** Sets the ground's restitution, [0, 1]. @throws RangeError otherwise. */
export function setGroundRestitution(s: Splash, e: number): void {
  check('setGroundRestitution', 'e', e, 0, 1);
  s.settings.restitution = e;
  setMaterial(s.world, s.ground, { restitution: e });
}

/** Sets how many droplets an impact makes per m/s of impact speed, [0, 20]. @throws RangeError otherwise. */
export function setDropletsPerSpeed(s: Splash, n: number): void {
  check('setDropletsPerSpeed', 'n', n, 0, 20);
  s.settings.dropletsPerSpeed = n;
}

const at = new Float64Array(2),
  vel = new Float64Array(2);

/** Drops a raindrop at (x, y), m, falling at 2 m/s. @returns 1 if it was made, 0 if the world had no room. */
export function dropAt(s: Splash, x: number, y: number): number {
  at[0] = x;
  at[1] = y;
  return emitNow(s.world, s.hand, 1, at);
}

/** Live particles of emitters a or b. */
function countOf(world: PhysicsWorld, a: number, b: number): number {
  const ents = query(world, [world.components.Particle]);
  const em = world.components.Particle.emitter;
  let n = 0;
  const sa = slotOf(a),
    sb = slotOf(b); // Particle.emitter holds slots
  for (let i = 0; i < ents.length; i++) {
    const e = em[ents[i]!];
    if (e === sa || e === sb) n++;
  }
  return n;
}

/** Splash droplets alive (ground and water). */
export function splashCount(s: Splash): number {
  return countOf(s.world, s.groundSplash, s.waterSplash);
}

/** Raindrops in the air (cloud and hand). */
export function dropCount(s: Splash): number {
  return countOf(s.world, s.rain, s.hand);
}

/** Scratch: drops to burst this step (entity, 1 ground / 2 water, impact speed m/s), droplets to absorb. */
let burstE = new Int32Array(64),
  burstKind = new Uint8Array(64),
  burstSpeed = new Float64Array(64);
let absorbE = new Int32Array(256);

function grow(): void {
  const n = burstE.length * 2;
  const e = new Int32Array(n),
    k = new Uint8Array(n),
    v = new Float64Array(n);
  e.set(burstE);
  k.set(burstKind);
  v.set(burstSpeed);
  burstE = e;
  burstKind = k;
  burstSpeed = v;
}

/**
 * One step: physics, then the impacts. Drops that touched the ground (last step's contacts) or
 * crossed the water's surface burst into droplets and are removed; droplets falling into the pool
 * are removed. Removals happen after the passes over the live lists. Allocates only when a scratch
 * list has to grow.
 */
export function stepSplash(s: Splash): void {
  const world = s.world;
  step(world);
  const c = world.components;
  const em = c.Particle.emitter;
  const P = c.Position,
    V = c.Velocity;
  // Particle.emitter and contact rows hold slots; the scene keeps handles.
  const rain = slotOf(s.rain),
    hand = slotOf(s.hand),
    ground = slotOf(s.ground);
  const groundSplash = slotOf(s.groundSplash),
    waterSplash = slotOf(s.waterSplash);
  let n = 0;
  // Ground: contacts of a drop with the ground segment.
  const rows = world.collision.cache.rows;
  for (let i = 0; i < rows.count; i++) {
    if (rows.kind[i] !== ContactKind.Segment || rows.feature[i] !== ground || rows.impulse[i]! <= 0) continue;
    const b = rows.b[i]!;
    if (em[b] !== rain && em[b] !== hand) continue;
    let seen = false;
    for (let k = 0; k < n; k++)
      if (burstE[k] === b) {
        seen = true;
        break;
      }
    if (seen) continue;
    if (n === burstE.length) grow();
    burstE[n] = b;
    burstKind[n] = 1;
    burstSpeed[n] = Math.max(0, -rows.impactVelocity[i]!);
    n++;
  }
  // Water: drops whose centre went under the surface above the pool; droplets falling back in.
  const ents = query(world, [c.Particle]);
  let m = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const x = P.x[e]!,
      y = P.y[e]!;
    const source = em[e];
    if (source === rain || source === hand) {
      if (y < 0 && x < POOL.maxX) {
        if (n === burstE.length) grow();
        burstE[n] = e;
        burstKind[n] = 2;
        burstSpeed[n] = Math.max(0, -V.y[e]!);
        n++;
      } else if (y < POOL.bottom) {
        if (m === absorbE.length) {
          const a = new Int32Array(m * 2);
          a.set(absorbE);
          absorbE = a;
        }
        absorbE[m++] = e;
      }
    } else if ((source === groundSplash || source === waterSplash) && y < 0 && x < POOL.maxX && V.y[e]! < 0) {
      if (m === absorbE.length) {
        const a = new Int32Array(m * 2);
        a.set(absorbE);
        absorbE = a;
      }
      absorbE[m++] = e;
    }
  }
  for (let k = 0; k < n; k++) {
    const e = burstE[k]!,
      speed = burstSpeed[k]!;
    const water = burstKind[k] === 2;
    const x = P.x[e]!;
    // Splash velocity handed to the droplets (scaled by each emitter's inherit fraction): the drop's, bounced up.
    vel[0] = V.x[e]!;
    vel[1] = speed;
    at[0] = x;
    at[1] = water ? 0 : SPLASH_DISC + 0.02;
    removeBody(world, handleOf(world, e));
    const count = Math.round(s.settings.dropletsPerSpeed * speed * (water ? 1.4 : 1));
    const made = count > 0 ? emitNow(world, water ? s.waterSplash : s.groundSplash, count, at, vel) : 0;
    const last = s.last;
    last.x = x;
    last.speed = speed;
    last.droplets = made;
    last.surface = water ? 'water' : 'ground';
    last.time = world.time;
    if (water) {
      s.waterImpacts++;
      s.rippleX[s.rippleHead] = x;
      s.rippleT[s.rippleHead] = world.time;
      s.rippleHead = (s.rippleHead + 1) % MAX_RIPPLES;
    } else {
      s.groundImpacts++;
    }
  }
  for (let k = 0; k < m; k++) {
    const e = absorbE[k]!;
    if (em[e] === groundSplash || em[e] === waterSplash) s.absorbed++;
    removeBody(world, handleOf(world, e));
  }
}
