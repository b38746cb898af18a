/**
 * Spring-chain lab scene: `links` balls of equal mass hanging from a fixed anchor at the origin,
 * each joined to the one above by a Hooke spring with damping (the physics package's Spring
 * entities, addSpring; the first spring is tied to the anchor point). The chain starts straight
 * and unstretched at `angle` from the downward vertical, so it falls and swings. A pure,
 * deterministic builder; no DOM.
 */
import {
  addBody,
  addSpring,
  INTEGRATOR_NAMES,
  type IntegratorName,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  slotOf,
} from '@bitphysics/physics';

/** Rest length of every spring, m. */
export const LINK_LENGTH = 0.5;
/** Radius of the balls, m. */
export const BALL_RADIUS = 0.09;
/** Gravity, m/s^2 (downwards). */
export const GRAVITY = 9.81;

/** Options of the scene; every field optional. */
export interface ChainOptions {
  /** Balls (and springs), integer in [1, 40]. Default 8. */
  links?: number;
  /** Spring stiffness, N/m, in [1, 5000]. Default 200. */
  stiffness?: number;
  /** Spring damping (along each spring), N s/m, in [0, 50]. Default 0. */
  damping?: number;
  /** Mass of each ball, kg, in [0.01, 10]. Default 0.2. */
  mass?: number;
  /** Starting angle of the straight chain from the downward vertical, degrees, in [-180, 180]. Default 70. */
  angle?: number;
  /** Integration scheme. Default 'velocity-verlet' (second order and symplectic: the energy stays within 0.2 % where semi-implicit Euler wanders by 3 %). */
  integrator?: IntegratorName;
}

/** Resolved options. */
export type ChainParams = Required<ChainOptions>;

/** Defaults. */
export const CHAIN_DEFAULTS: Readonly<ChainParams> = Object.freeze({
  links: 8,
  stiffness: 200,
  damping: 0,
  mass: 0.2,
  angle: 70,
  integrator: 'velocity-verlet',
});

/** What the builder returns. */
export interface ChainHandles {
  /** The balls, top to bottom. */
  balls: number[];
  /** The springs: springs[0] ties balls[0] to the anchor, springs[i] ties balls[i] to balls[i - 1]. */
  springs: number[];
  /** The anchor point, m. */
  anchor: readonly [number, number];
  /** The options used (stiffness and damping kept up to date by `setSpringConstants`). */
  params: ChainParams;
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolveChainOptions(options: ChainOptions = {}): ChainParams {
  for (const k of Object.keys(options)) {
    if (!(k in CHAIN_DEFAULTS))
      throw new TypeError(`lab-spring-chain: unknown option ${JSON.stringify(k)}; known: ${Object.keys(CHAIN_DEFAULTS).join(', ')}`);
  }
  const p = { ...CHAIN_DEFAULTS, ...options } as ChainParams;
  const check = (ok: boolean, what: string, v: unknown) => {
    if (!ok) throw new RangeError(`lab-spring-chain: ${what}, got ${String(v)}`);
  };
  check(Number.isInteger(p.links) && p.links >= 1 && p.links <= 40, 'links must be an integer in [1, 40]', p.links);
  check(p.stiffness >= 1 && p.stiffness <= 5000, 'stiffness must be in [1, 5000] N/m', p.stiffness);
  check(p.damping >= 0 && p.damping <= 50, 'damping must be in [0, 50] N s/m', p.damping);
  check(p.mass >= 0.01 && p.mass <= 10, 'mass must be in [0.01, 10] kg', p.mass);
  check(p.angle >= -180 && p.angle <= 180, 'angle must be in [-180, 180] degrees', p.angle);
  check(
    (INTEGRATOR_NAMES as readonly string[]).includes(p.integrator),
    `integrator must be one of ${INTEGRATOR_NAMES.join(', ')}`,
    p.integrator,
  );
  return p;
}

/**
 * Substeps per 1/60 s step that keep the chain's fastest mode resolved: a chain of equal masses and
 * springs has normal-mode frequencies below 2 sqrt(k / m), and explicit schemes need omega h well
 * under 2 to stay stable; this keeps omega h <= 0.5. Integer in [1, 64].
 */
export function substepsFor(stiffness: number, mass: number, dt = 1 / 60): number {
  const omega = 2 * Math.sqrt(stiffness / mass);
  return Math.min(64, Math.max(1, Math.ceil((omega * dt) / 0.5)));
}

/** World options: 2D, gravity, substeps from `substepsFor`, room for balls, springs and a mouse spring. */
export function chainWorldOptions(options: ChainOptions = {}): PhysicsWorldOptions {
  const p = resolveChainOptions(options);
  return {
    dimensions: 2,
    capacity: 2 * p.links + 8,
    gravity: [0, -GRAVITY],
    dt: 1 / 60,
    substeps: substepsFor(p.stiffness, p.mass),
    integrator: p.integrator,
  };
}

/**
 * How far below the anchor the chain reaches when it hangs at rest, m: N L0 plus the springs'
 * static stretch, the i-th spring from the bottom holding i m g: m g N (N + 1) / (2 k). For the view.
 */
export function hangingLength(p: ChainParams): number {
  return p.links * LINK_LENGTH + (p.mass * GRAVITY * p.links * (p.links + 1)) / (2 * p.stiffness);
}

/**
 * Builds the chain into a fresh 2D world (ideally from `chainWorldOptions`).
 * @throws TypeError | RangeError on bad options or a 3D world.
 */
export function buildChain(world: PhysicsWorld, options: ChainOptions = {}): ChainHandles {
  const p = resolveChainOptions(options);
  if (world.dimensions !== 2) throw new RangeError(`lab-spring-chain: needs a 2D world, got dimensions ${world.dimensions}`);
  const anchor = [0, 0] as const;
  const a = (p.angle * Math.PI) / 180;
  const ux = Math.sin(a),
    uy = -Math.cos(a);
  const h: ChainHandles = { balls: [], springs: [], anchor, params: p };
  for (let i = 0; i < p.links; i++) {
    const d = (i + 1) * LINK_LENGTH;
    const ball = addBody(world, {
      position: [anchor[0] + ux * d, anchor[1] + uy * d],
      radius: BALL_RADIUS,
      mass: p.mass,
      rotates: false,
      restitution: 0.5,
      friction: 0.1,
    });
    const spring =
      i === 0
        ? addSpring(world, { anchor, b: ball, stiffness: p.stiffness, restLength: LINK_LENGTH, damping: p.damping })
        : addSpring(world, { a: h.balls[i - 1]!, b: ball, stiffness: p.stiffness, restLength: LINK_LENGTH, damping: p.damping });
    h.balls.push(ball);
    h.springs.push(spring);
  }
  return h;
}

/**
 * Sets the stiffness (N/m, [1, 5000]) and damping (N s/m, [0, 50]) of every chain spring on the
 * running world (the Spring component's fields) and the substeps the stiffness needs.
 * @throws RangeError out of range.
 */
export function setSpringConstants(world: PhysicsWorld, h: ChainHandles, stiffness: number, damping: number): void {
  const p = resolveChainOptions({ ...h.params, stiffness, damping });
  const S = world.components.Spring;
  for (const s of h.springs) {
    S.stiffness[slotOf(s)] = p.stiffness;
    S.damping[slotOf(s)] = p.damping;
  }
  world.substeps = substepsFor(p.stiffness, p.mass, world.dt);
  h.params = p;
}
