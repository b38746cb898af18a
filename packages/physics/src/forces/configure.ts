/**
 * The functions that change a world's force-law settings (gravitation, electrostatics, wind) and
 * evaluate the wind; the settings themselves are data in world/force-settings.ts.
 */

import { cosine } from '../math/cosine.js';
import { Rng } from '../math/rng.js';
import * as check from '../validation/validate.js';
import { type GravityMethod, MAX_WIND_MODES } from '../world/force-settings.js';
import type { PhysicsWorld } from '../world/options.js';
import { barnesHutGravity } from './barnes-hut/tree.js';
import { setBarnesHutGravity } from './gravity.js';

/**
 * Options of `setGravitation`.
 * @category Forces
 */
export interface GravitationOptions {
  /** G, m^3 kg^-1 s^-2, finite and >= 0 (use 1 for game units). */
  constant?: number;
  /** Softening length, m, >= 0. */
  softening?: number;
  /** 'direct' or 'barnes-hut'. */
  method?: GravityMethod;
  /** Barnes-Hut opening angle, > 0: cells interact as wholes when (r_A + r_B) / R < theta (0.5: ~0.1% median force error; 0.7: faster, ~0.1-0.6%). */
  openingAngle?: number;
}

/**
 * Sets the constant, softening and summation method of Newtonian gravity (mutual and attractors).
 * Omitted options keep their value; a refused call changes nothing.
 * @throws TypeError on a missing options object, unknown or null options; RangeError on G < 0, softening < 0,
 *   theta <= 0, an unknown method.
 * @category Forces
 */
export function setGravitation(world: PhysicsWorld, options: GravitationOptions): void {
  const where = 'setGravitation';
  check.assertOptions(where, options, ['constant', 'softening', 'method', 'openingAngle']);
  if (options.constant !== undefined) check.assertNonNegative(where, 'constant', options.constant);
  if (options.softening !== undefined) check.assertNonNegative(where, 'softening', options.softening);
  if (options.method !== undefined) check.assertOneOf(where, 'method', options.method, ['direct', 'barnes-hut']);
  if (options.openingAngle !== undefined) check.assertPositive(where, 'openingAngle', options.openingAngle);
  const L = world.laws;
  if (options.constant !== undefined) L.gravitationalConstant = options.constant;
  if (options.softening !== undefined) L.gravitySoftening = options.softening;
  if (options.method === 'barnes-hut') setBarnesHutGravity(barnesHutGravity);
  if (options.method !== undefined) L.gravityMethod = options.method;
  if (options.openingAngle !== undefined) L.openingAngle = options.openingAngle;
}

/**
 * Sets the Coulomb constant (N m^2 C^-2, >= 0) and softening (m, >= 0) of the electric pair force.
 * Omitted options keep their value; a refused call changes nothing.
 * @throws TypeError on a missing options object, unknown or null options; RangeError on negative values.
 * @category Forces
 */
export function setElectrostatics(world: PhysicsWorld, options: { constant?: number; softening?: number }): void {
  const where = 'setElectrostatics';
  check.assertOptions(where, options, ['constant', 'softening']);
  if (options.constant !== undefined) check.assertNonNegative(where, 'constant', options.constant);
  if (options.softening !== undefined) check.assertNonNegative(where, 'softening', options.softening);
  if (options.constant !== undefined) world.laws.coulombConstant = options.constant;
  if (options.softening !== undefined) world.laws.electricSoftening = options.softening;
}

/**
 * Options of `setWind`. Vectors have `world.dimensions` components.
 * @category Forces
 */
export interface WindOptions {
  /** Mean wind, m/s. */
  velocity?: ArrayLike<number>;
  /** Gust amplitude, m/s. */
  gust?: ArrayLike<number>;
  /** Gust angular frequency, rad/s (>= 0). */
  gustOmega?: number;
  /** Gust phase, rad. */
  gustPhase?: number;
  /** Turbulence; omit or intensity 0 for none. */
  turbulence?: { intensity: number; lengthScale: number; timeScale: number; seed?: number; modes?: number };
}

/**
 * Sets the wind that drag and lift act against. Replaces the whole wind field; a refused call changes nothing.
 * @throws TypeError on a missing options object, unknown or null options, or bad vectors; RangeError on negative intensity, non-positive
 *   length or time scale, or a mode count outside [1, 32].
 * @category Forces
 */
export function setWind(world: PhysicsWorld, options: WindOptions): void {
  const where = 'setWind';
  check.assertOptions(where, options, ['velocity', 'gust', 'gustOmega', 'gustPhase', 'turbulence']);
  const d = world.dimensions;
  if (options.velocity !== undefined) check.assertVector(where, 'velocity', options.velocity, d);
  if (options.gust !== undefined) check.assertVector(where, 'gust', options.gust, d);
  if (options.gustOmega !== undefined) check.assertNonNegative(where, 'gustOmega', options.gustOmega);
  if (options.gustPhase !== undefined) check.assertFinite(where, 'gustPhase', options.gustPhase);
  const t = options.turbulence;
  if (t !== undefined) {
    check.assertOptions(where, t, ['intensity', 'lengthScale', 'timeScale', 'seed', 'modes'], 'turbulence');
    check.assertNonNegative(where, 'turbulence.intensity', t.intensity);
    check.assertPositive(where, 'turbulence.lengthScale', t.lengthScale);
    check.assertPositive(where, 'turbulence.timeScale', t.timeScale);
    if (t.seed !== undefined) check.assertFinite(where, 'turbulence.seed', t.seed);
    check.assertInteger(where, 'turbulence.modes', t.modes ?? 16, 1, MAX_WIND_MODES);
  }
  const w = world.laws.wind;
  w.velocity.fill(0);
  w.gust.fill(0);
  w.gustOmega = 0;
  w.gustPhase = 0;
  w.modes = 0;
  w.intensity = 0;
  if (options.velocity !== undefined) for (let i = 0; i < d; i++) w.velocity[i] = options.velocity[i]!;
  if (options.gust !== undefined) for (let i = 0; i < d; i++) w.gust[i] = options.gust[i]!;
  if (options.gustOmega !== undefined) w.gustOmega = options.gustOmega;
  if (options.gustPhase !== undefined) w.gustPhase = options.gustPhase;
  if (t !== undefined) {
    const modes = t.modes ?? 16;
    const rng = new Rng(t.seed ?? 1);
    w.intensity = t.intensity;
    w.modes = t.intensity > 0 ? modes : 0;
    const data = w.modeData;
    for (let m = 0; m < modes; m++) {
      // Random direction (in the plane for 2D), wavelength log-uniform in [L/2, 2L].
      let kx: number, ky: number, kz: number;
      if (d === 2) {
        const a = rng.range(0, 2 * Math.PI);
        kx = Math.cos(a);
        ky = Math.sin(a);
        kz = 0;
      } else {
        const zc = rng.range(-1, 1),
          a = rng.range(0, 2 * Math.PI),
          r = Math.sqrt(1 - zc * zc);
        kx = r * Math.cos(a);
        ky = r * Math.sin(a);
        kz = zc;
      }
      const wavelength = t.lengthScale * 2 ** rng.range(-1, 1);
      const kmag = (2 * Math.PI) / wavelength;
      // Amplitude direction perpendicular to k (divergence-free field).
      let ax: number, ay: number, az: number;
      if (d === 2) {
        ax = -ky;
        ay = kx;
        az = 0;
      } else {
        const px = rng.normal(),
          py = rng.normal(),
          pz = rng.normal();
        ax = py * kz - pz * ky;
        ay = pz * kx - px * kz;
        az = px * ky - py * kx;
        const n = Math.hypot(ax, ay, az) || 1;
        ax /= n;
        ay /= n;
        az /= n;
      }
      const o = m * 8;
      data[o] = kx * kmag;
      data[o + 1] = ky * kmag;
      data[o + 2] = kz * kmag;
      data[o + 3] = (1 / t.timeScale) * 2 ** rng.range(-1, 1);
      data[o + 4] = rng.range(0, 2 * Math.PI);
      data[o + 5] = ax;
      data[o + 6] = ay;
      data[o + 7] = az;
    }
  }
}

/**
 * The wind velocity at (x, y, z) and time t, m/s, written into out[0..2]. Each turbulent mode has
 * amplitude intensity sqrt(2 d / modes) in a d-dimensional world: a cosine has mean square 1/2 and a
 * random unit direction puts 1/d of its square on each axis, so each component's RMS is `intensity`.
 * The cosines are math/cosine.ts's polynomial (within 5e-14 + 2.4e-16 |argument| of Math.cos, cheaper,
 * and the same in every engine).
 * @category Forces
 */
export function windAt(world: PhysicsWorld, x: number, y: number, z: number, t: number, out: Float64Array): void {
  const w = world.laws.wind;
  const gc = w.gustOmega === 0 && w.gustPhase === 0 ? 1 : Math.cos(w.gustOmega * t + w.gustPhase);
  let u = w.velocity[0]! + w.gust[0]! * gc;
  let v = w.velocity[1]! + w.gust[1]! * gc;
  let s = w.velocity[2]! + w.gust[2]! * gc;
  const modes = w.modes;
  if (modes > 0) {
    const data = w.modeData;
    const amp = w.intensity * Math.sqrt((2 * world.dimensions) / modes);
    for (let m = 0; m < modes; m++) {
      const o = m * 8;
      const c = amp * cosine(data[o]! * x + data[o + 1]! * y + data[o + 2]! * z - data[o + 3]! * t + data[o + 4]!);
      u += c * data[o + 5]!;
      v += c * data[o + 6]!;
      s += c * data[o + 7]!;
    }
  }
  out[0] = u;
  out[1] = v;
  out[2] = s;
}
