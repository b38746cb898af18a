/**
 * Bungee lab scene: a jumper (a ball) tied to the edge of a bridge by a one-sided spring, the
 * physics package's bungee (addSpring with oneSided: true: it pulls only while stretched beyond its
 * rest length, the unstretched rope length). The jumper starts at rest at the anchor, so the first
 * phase is free fall. The bridge deck and the river bank are static segments. The world uses
 * velocity Verlet (exact for the constant acceleration of free fall) with 4 substeps.
 * A pure, deterministic builder; no DOM.
 */
import { addBody, addSegment, addSpring, type PhysicsWorld, type PhysicsWorldOptions } from '@bitphysics/physics';

/** Height of the bridge deck (and of the rope's anchor) above the river, m. */
export const BRIDGE_HEIGHT = 60;
/** Radius of the jumper's ball, m. */
export const JUMPER_RADIUS = 0.5;
/** Gravity, m/s^2 (downwards). */
export const GRAVITY = 9.81;

/** Options of the scene; every field optional. */
export interface BungeeOptions {
  /** Unstretched rope length L, m, in [2, 50]. Default 15. */
  ropeLength?: number;
  /** Rope stiffness k, N/m, in [10, 5000]. Default 120. */
  stiffness?: number;
  /** Rope damping along the rope while stretched, N s/m, in [0, 1000]. Default 0. */
  damping?: number;
  /** Jumper mass m, kg, in [20, 200]. Default 70. */
  mass?: number;
}

/** Resolved options. */
export type BungeeParams = Required<BungeeOptions>;

/** Defaults. */
export const BUNGEE_DEFAULTS: Readonly<BungeeParams> = Object.freeze({ ropeLength: 15, stiffness: 120, damping: 0, mass: 70 });

/** What the builder returns. */
export interface BungeeHandles {
  /** The jumper. */
  jumper: number;
  /** The rope (a one-sided Spring entity). */
  rope: number;
  /** The rope's anchor on the bridge, m. */
  anchor: readonly [number, number];
  /** The bridge deck and river segments. */
  segments: number[];
  /** The options used. */
  params: BungeeParams;
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolveBungeeOptions(options: BungeeOptions = {}): BungeeParams {
  for (const k of Object.keys(options)) {
    if (!(k in BUNGEE_DEFAULTS))
      throw new TypeError(`lab-bungee: unknown option ${JSON.stringify(k)}; known: ${Object.keys(BUNGEE_DEFAULTS).join(', ')}`);
  }
  const p = { ...BUNGEE_DEFAULTS, ...options } as BungeeParams;
  const check = (ok: boolean, what: string, v: unknown) => {
    if (!ok) throw new RangeError(`lab-bungee: ${what}, got ${String(v)}`);
  };
  check(p.ropeLength >= 2 && p.ropeLength <= 50, 'ropeLength must be in [2, 50] m', p.ropeLength);
  check(p.stiffness >= 10 && p.stiffness <= 5000, 'stiffness must be in [10, 5000] N/m', p.stiffness);
  check(p.damping >= 0 && p.damping <= 1000, 'damping must be in [0, 1000] N s/m', p.damping);
  check(p.mass >= 20 && p.mass <= 200, 'mass must be in [20, 200] kg', p.mass);
  return p;
}

/** World options: 2D, gravity, velocity Verlet, 4 substeps of 1/60 s steps. */
export function bungeeWorldOptions(): PhysicsWorldOptions {
  return { dimensions: 2, capacity: 8, gravity: [0, -GRAVITY], dt: 1 / 60, substeps: 4, integrator: 'velocity-verlet' };
}

/**
 * Builds the scene into a fresh 2D world (ideally from `bungeeWorldOptions`): deck, river, the
 * jumper at rest at the anchor (x = 0, y = BRIDGE_HEIGHT) and the rope.
 * @throws TypeError | RangeError on bad options or a 3D world.
 */
export function buildBungee(world: PhysicsWorld, options: BungeeOptions = {}): BungeeHandles {
  const p = resolveBungeeOptions(options);
  if (world.dimensions !== 2) throw new RangeError(`lab-bungee: needs a 2D world, got dimensions ${world.dimensions}`);
  const H = BRIDGE_HEIGHT;
  const segments = [
    addSegment(world, { a: [-40, H], b: [-0.8, H], radius: 0.3, friction: 0.8 }),
    addSegment(world, { a: [-60, 0], b: [60, 0], friction: 0.8 }),
  ];
  const anchor = [0, H] as const;
  const jumper = addBody(world, {
    position: [anchor[0], anchor[1]],
    radius: JUMPER_RADIUS,
    mass: p.mass,
    rotates: false,
    restitution: 0.1,
  });
  const rope = addSpring(world, {
    anchor,
    b: jumper,
    stiffness: p.stiffness,
    restLength: p.ropeLength,
    damping: p.damping,
    oneSided: true,
  });
  return { jumper, rope, anchor, segments, params: p };
}
