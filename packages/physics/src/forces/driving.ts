import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
import type { ForceLaw } from './law.js';

/**
 * Periodic driving force F = F0 cos(omega t + phase). Position-only (a function of time). Ramtal and Dobre ch. 8.
 * @category Forces
 */
export const drivingForceSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const ents = query(world, [c.DrivingForce, c.Force]);
  if (ents.length === 0) return;
  const D = c.DrivingForce,
    t = world.time;
  const { x: fx, y: fy, z: fz } = c.Force;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const k = Math.cos(D.omega[e]! * t + D.phase[e]!);
    fx[e] = fx[e]! + D.x[e]! * k;
    fy[e] = fy[e]! + D.y[e]! * k;
    fz[e] = fz[e]! + D.z[e]! * k;
  }
};
drivingForceSystem.velocityDependent = false;

/** 32-bit integer hash (Wellons' "lowbias32"), mapped to [-1, 1). */
function noiseValue(seed: number, knot: number, axis: number): number {
  let x = (Math.imul(seed | 0, 0x9e3779b9) ^ Math.imul(knot | 0, 0x85ebca6b) ^ Math.imul(axis + 1, 0xc2b2ae35)) >>> 0;
  x ^= x >>> 16;
  x = Math.imul(x, 0x7feb352d);
  x ^= x >>> 15;
  x = Math.imul(x, 0x846ca68b);
  x ^= x >>> 16;
  return (x >>> 0) / 2147483648 - 1;
}

/**
 * Smooth seeded value noise in [-1, 1): random values at knots t = k tau, joined by the smoothstep
 * 3 s^2 - 2 s^3 (continuous with a continuous derivative). A pure function of (seed, t, axis).
 * @category Forces
 */
export function valueNoise(seed: number, t: number, tau: number, axis: number): number {
  const x = t / tau;
  const k = Math.floor(x);
  const s = x - k;
  const w = s * s * (3 - 2 * s);
  const a = noiseValue(seed, k, axis),
    b = noiseValue(seed, k + 1, axis);
  return a + (b - a) * w;
}

/**
 * Seeded random driving force: each component magnitude x valueNoise(seed, t, correlationTime), so
 * it is in [-magnitude, magnitude] N and changes smoothly over about `correlationTime` s.
 * Position-only (a function of time).
 * @category Forces
 */
export const randomForceSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const ents = query(world, [c.RandomForce, c.Force]);
  if (ents.length === 0) return;
  const R = c.RandomForce,
    t = world.time;
  const { x: fx, y: fy, z: fz } = c.Force;
  const is3D = world.dimensions === 3;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const m = R.magnitude[e]!,
      tau = R.correlationTime[e]!,
      seed = R.seed[e]!;
    fx[e] = fx[e]! + m * valueNoise(seed, t, tau, 0);
    fy[e] = fy[e]! + m * valueNoise(seed, t, tau, 1);
    if (is3D) fz[e] = fz[e]! + m * valueNoise(seed, t, tau, 2);
  }
};
randomForceSystem.velocityDependent = false;

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(drivingForceSystem, (w) => [[w.components.DrivingForce, w.components.Force]]);
idleWithout(randomForceSystem, (w) => [[w.components.RandomForce, w.components.Force]]);
