/**
 * Pendulum lab scene: a bob on a stiff damped spring to a fixed anchor at the origin.
 *
 * Why a spring: the physics package has no rigid rod or distance constraint (its constraints stage
 * is empty so far), and a spring much stiffer than gravity's pull is a rod for every purpose the
 * lab has: with k = m (2 pi 15 Hz)^2 the rod's own vibration is about 50 times faster than the
 * swing, it stretches by m g / k = 1.1 mm, and its rest length is shortened by that static stretch so
 * that the hanging length is exactly L. The spring's damping acts only along the rod, so it quiets
 * the rod's vibration without slowing the swing; the swing's damping is the bob's linear drag
 * (setDrag), F = -b v. Velocity Verlet with 8 substeps (h = 1/480 s) resolves the rod's vibration
 * (omega h = 0.2). A pure, deterministic builder; no DOM.
 */
import { addBody, addSpring, type PhysicsWorld, type PhysicsWorldOptions, setDrag } from '@bitphysics/physics';

/** Mass of the bob, kg. */
export const BOB_MASS = 1;
/** Frequency of the rod's stretching vibration, Hz (sets the spring's stiffness). */
export const ROD_FREQUENCY = 15;
/** Rod stiffness, N/m: m (2 pi f)^2. */
export const ROD_STIFFNESS = BOB_MASS * (2 * Math.PI * ROD_FREQUENCY) ** 2;
/** Rod damping along its length, N s/m: 0.3 of critical for the bob on the rod. */
export const ROD_DAMPING = 0.3 * 2 * Math.sqrt(ROD_STIFFNESS * BOB_MASS);
/** Substeps of each 1/60 s step. */
export const SUBSTEPS = 8;

/** Options of the scene; every field optional. */
export interface PendulumOptions {
  /** Length L from the anchor to the bob's centre when hanging, m, in [0.2, 20]. Default 2. */
  length?: number;
  /** Starting angle from the downward vertical, degrees, in [-179, 179] (counter-clockwise positive). Default 20. */
  amplitude?: number;
  /** Gravity g, m/s^2 (downwards), in [0.5, 30]. Default 9.81. */
  gravity?: number;
  /** Linear drag on the bob b, N s/m, in [0, 5]. Default 0. */
  damping?: number;
}

/** Resolved options. */
export type PendulumParams = Required<PendulumOptions>;

/** Defaults. */
export const PENDULUM_DEFAULTS: Readonly<PendulumParams> = Object.freeze({ length: 2, amplitude: 20, gravity: 9.81, damping: 0 });

/** Ranges of the options: [min, max]. */
export const PENDULUM_RANGES = Object.freeze({ length: [0.2, 20], amplitude: [-179, 179], gravity: [0.5, 30], damping: [0, 5] } as const);

/** What the builder returns. */
export interface PendulumHandles {
  /** The bob. */
  bob: number;
  /** The rod (a Spring entity anchored at `anchor`). */
  rod: number;
  /** The anchor, m. */
  anchor: readonly [number, number];
  /** Radius the bob is drawn (and collides) with, m. */
  bobRadius: number;
  /** The options used. */
  params: PendulumParams;
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolvePendulumOptions(options: PendulumOptions = {}): PendulumParams {
  for (const k of Object.keys(options)) {
    if (!(k in PENDULUM_DEFAULTS))
      throw new TypeError(`lab-pendulum: unknown option ${JSON.stringify(k)}; known: ${Object.keys(PENDULUM_DEFAULTS).join(', ')}`);
  }
  const p = { ...PENDULUM_DEFAULTS, ...options } as PendulumParams;
  for (const [key, [min, max]] of Object.entries(PENDULUM_RANGES)) {
    const v = p[key as keyof PendulumParams];
    if (!(typeof v === 'number' && v >= min && v <= max))
      throw new RangeError(`lab-pendulum: ${key} must be a number in [${min}, ${max}], got ${String(v)}`);
  }
  return p;
}

/** World options: 2D, gravity (0, -g), velocity Verlet, `SUBSTEPS` substeps of 1/60 s steps. */
export function pendulumWorldOptions(options: PendulumOptions = {}): PhysicsWorldOptions {
  const p = resolvePendulumOptions(options);
  return { dimensions: 2, capacity: 4, gravity: [0, -p.gravity], dt: 1 / 60, substeps: SUBSTEPS, integrator: 'velocity-verlet' };
}

/**
 * Builds the pendulum into a fresh 2D world (ideally from `pendulumWorldOptions`): the bob at rest
 * at distance L from the anchor, `amplitude` degrees from the downward vertical.
 * @throws TypeError | RangeError on bad options or a 3D world.
 */
export function buildPendulum(world: PhysicsWorld, options: PendulumOptions = {}): PendulumHandles {
  const p = resolvePendulumOptions(options);
  if (world.dimensions !== 2) throw new RangeError(`lab-pendulum: needs a 2D world, got dimensions ${world.dimensions}`);
  const anchor = [0, 0] as const;
  const a = (p.amplitude * Math.PI) / 180;
  const bobRadius = Math.max(0.04, 0.06 * p.length);
  const bob = addBody(world, {
    position: [anchor[0] + p.length * Math.sin(a), anchor[1] - p.length * Math.cos(a)],
    radius: bobRadius,
    mass: BOB_MASS,
    rotates: false,
  });
  setDrag(world, bob, { linear: p.damping });
  // Rest length shortened by the static stretch m g / k, so that the hanging length is L.
  const restLength = p.length - (BOB_MASS * p.gravity) / ROD_STIFFNESS;
  const rod = addSpring(world, { anchor, b: bob, stiffness: ROD_STIFFNESS, restLength, damping: ROD_DAMPING });
  return { bob, rod, anchor, bobRadius, params: p };
}
