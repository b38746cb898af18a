/**
 * Molecules scene (Ramtal and Dobre ch. 11, "molecules"): `count` equal discs in a closed box, no
 * gravity, perfectly elastic (e = 1) and frictionless, all starting at the same speed in random
 * directions on a jittered grid. Collisions share the energy out until the speeds follow the 2D
 * Maxwell-Boltzmann distribution f(v) = (m v / kT) exp(-m v^2 / (2 kT)), with kT the mean kinetic
 * energy per disc (equipartition over two degrees of freedom). A pure, deterministic builder; no DOM.
 */
import { addBody, type PhysicsWorld, type PhysicsWorldOptions, Rng, setBoundary, slotOf } from '@bitphysics/physics';

/** Options of the scene; every field optional. */
export interface GasOptions {
  /** Molecules, integer in [10, 2000]. Default 400. */
  count?: number;
  /** Starting speed of every molecule, m/s, in [0.1, 10]. Default 1. */
  speed?: number;
  /** Disc radius, m, in [0.02, 0.3]. Default 0.1. */
  radius?: number;
  /** Seed of the layout. Default 1. */
  seed?: number;
}

/** Resolved options. */
export type GasParams = Required<GasOptions>;

/** Defaults. */
export const GAS_DEFAULTS: Readonly<GasParams> = Object.freeze({ count: 400, speed: 1, radius: 0.1, seed: 1 });

/** Mass of a molecule, kg. */
export const MOLECULE_MASS = 1;

/** What the builder returns. */
export interface GasHandles {
  /** The molecules. */
  molecules: number[];
  /** The box: width and height, m (corner at the origin). */
  width: number;
  height: number;
  /** The options used. */
  params: GasParams;
}

/** World options: 2D, no gravity, no sleeping. */
export function gasWorldOptions(options: GasOptions = {}): PhysicsWorldOptions {
  const p = { ...GAS_DEFAULTS, ...options };
  return { dimensions: 2, capacity: p.count + 8, gravity: [0, 0], sleep: false, seed: p.seed };
}

/** Builds the gas: a 3:2 box holding the discs at about 12 % area fraction. */
export function buildGas(world: PhysicsWorld, options: GasOptions = {}): GasHandles {
  const params: GasParams = { ...GAS_DEFAULTS, ...options };
  const { count, speed, radius } = params;
  const area = (count * Math.PI * radius * radius) / 0.12;
  const height = Math.sqrt(area / 1.5),
    width = 1.5 * height;
  setBoundary(world, { min: [0, 0], max: [width, height], restitution: 1, friction: 0 });
  const cols = Math.ceil(Math.sqrt(count * 1.5)),
    rows = Math.ceil(count / cols);
  const dx = width / cols,
    dy = height / rows;
  const rng = new Rng(params.seed);
  const molecules: number[] = [];
  for (let i = 0; i < count; i++) {
    const x = ((i % cols) + 0.5) * dx + rng.range(-0.2, 0.2) * (dx - 2 * radius);
    const y = (Math.floor(i / cols) + 0.5) * dy + rng.range(-0.2, 0.2) * (dy - 2 * radius);
    const a = rng.range(0, 2 * Math.PI);
    molecules.push(
      addBody(world, {
        position: [x, y],
        velocity: [speed * Math.cos(a), speed * Math.sin(a)],
        radius,
        mass: MOLECULE_MASS,
        restitution: 1,
        friction: 0,
      }),
    );
  }
  return { molecules, width, height, params };
}

/**
 * The 2D Maxwell-Boltzmann speed density at v (m/s, >= 0) for kT (J, > 0) and mass m (kg, > 0), in
 * 1/(m/s): f(v) = (m v / kT) exp(-m v^2 / (2 kT)) (a Rayleigh density of scale sqrt(kT / m)). It
 * integrates to 1 over v >= 0, peaks at the most probable speed sqrt(kT / m), and has mean speed
 * sqrt(pi kT / (2 m)).
 * @throws RangeError if v is not a finite number >= 0, or kT or m not finite and > 0.
 */
export function maxwellBoltzmann2D(v: number, kT: number, m = MOLECULE_MASS): number {
  if (!(v >= 0 && v < Infinity)) throw new RangeError(`maxwellBoltzmann2D: v must be a finite speed >= 0 m/s, got ${v}`);
  if (!(kT > 0 && kT < Infinity)) throw new RangeError(`maxwellBoltzmann2D: kT must be finite and > 0 J, got ${kT}`);
  if (!(m > 0 && m < Infinity)) throw new RangeError(`maxwellBoltzmann2D: m must be finite and > 0 kg, got ${m}`);
  return ((m * v) / kT) * Math.exp((-m * v * v) / (2 * kT));
}

/** What {@link measureSpeeds} returns besides the counts. */
export interface SpeedMeasure {
  /** Temperature as energy, J: mean translational kinetic energy per molecule, m <v^2> / 2 (equipartition over two degrees of freedom). */
  kT: number;
  /** Width of one histogram bin, m/s: 4 sqrt(kT / m) / counts.length (the bins reach four times the most probable speed). */
  binWidth: number;
}

/**
 * The lab's temperature and speed histogram now: kT from the molecules' velocities and, in `counts`
 * (overwritten), how many molecules have a speed in each bin [k w, (k + 1) w), w = `binWidth`;
 * speeds of 4 sqrt(kT / m) and above (a fraction exp(-8) = 3.4e-4 of a Maxwell-Boltzmann gas) are
 * not counted. The page draws these counts against N w f(v), f = {@link maxwellBoltzmann2D}.
 * @throws RangeError if `molecules` is empty or `counts` has no bins.
 */
export function measureSpeeds(world: PhysicsWorld, molecules: readonly number[], counts: Float64Array, m = MOLECULE_MASS): SpeedMeasure {
  if (molecules.length === 0) throw new RangeError('measureSpeeds: molecules must not be empty');
  if (counts.length === 0) throw new RangeError('measureSpeeds: counts must have at least one bin, got length 0');
  const V = world.components.Velocity;
  let v2 = 0;
  for (const e of molecules) {
    const s = slotOf(e);
    v2 += V.x[s]! * V.x[s]! + V.y[s]! * V.y[s]!;
  }
  const kT = (0.5 * m * v2) / molecules.length;
  const binWidth = (4 * Math.sqrt(kT / m)) / counts.length;
  counts.fill(0);
  for (const e of molecules) {
    const s = slotOf(e);
    const k = Math.floor(Math.hypot(V.x[s]!, V.y[s]!) / binWidth);
    if (k < counts.length) counts[k]!++;
  }
  return { kT, binWidth };
}
