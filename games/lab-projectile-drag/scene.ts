/**
 * Projectile lab scene: a ball launched from the edge of a cliff over flat ground, with no drag,
 * linear drag (LinearDrag component, F = -k v) or quadratic drag (QuadraticDrag, F = -k |v| v).
 * A pure, deterministic builder (world options + build); no DOM, runs in Node.
 *
 * Geometry, m: the ball's centre starts at (0, height); the cliff top is a static segment ending
 * just left of it, the cliff face drops to the ground, the ground is a long static segment at y = 0.
 */
import {
  addBody,
  addSegment,
  INTEGRATOR_NAMES,
  type IntegratorName,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  setDrag,
} from '@bitphysics/physics';

/** Drag law of the projectile. */
export type DragLaw = 'none' | 'linear' | 'quadratic';

/** The drag laws, for menus and URL parameters. */
export const DRAG_LAWS: readonly DragLaw[] = ['none', 'linear', 'quadratic'];

/** Radius of the ball, m (a beach ball). */
export const BALL_RADIUS = 0.4;

/** Options of the scene; every field optional. */
export interface ProjectileOptions {
  /** Drag law. Default 'linear'. */
  law?: DragLaw;
  /** Linear drag coefficient k, N s/m (= kg/s), in [0, 50]. Default 0.2. */
  linearK?: number;
  /** Quadratic drag coefficient k, kg/m, in [0, 5]. Default 0.02. */
  quadraticK?: number;
  /** Launch speed, m/s, in [0, 100]. Default 20. */
  speed?: number;
  /** Launch angle above the +x axis, degrees, in [-90, 180]. Default 50. */
  angle?: number;
  /** Mass, kg, in [0.01, 100]. Default 1. */
  mass?: number;
  /** Height of the ball's centre at launch above the ground, m, in [1, 100]. Default 10. */
  height?: number;
  /** Gravity, m/s^2 (downwards), in [0.1, 50]. Default 9.81. */
  gravity?: number;
  /** Integration scheme. Default 'rk4'. */
  integrator?: IntegratorName;
}

/** Resolved options. */
export type ProjectileParams = Required<ProjectileOptions>;

/** Defaults of every option. */
export const PROJECTILE_DEFAULTS: Readonly<ProjectileParams> = Object.freeze({
  law: 'linear',
  linearK: 0.2,
  quadraticK: 0.02,
  speed: 20,
  angle: 50,
  mass: 1,
  height: 10,
  gravity: 9.81,
  integrator: 'rk4',
});

/** Ranges of the numeric options: [min, max]. */
export const PROJECTILE_RANGES = Object.freeze({
  linearK: [0, 50],
  quadraticK: [0, 5],
  speed: [0, 100],
  angle: [-90, 180],
  mass: [0.01, 100],
  height: [1, 100],
  gravity: [0.1, 50],
} as const);

/** What the builder returns. */
export interface ProjectileHandles {
  /** The ball. */
  ball: number;
  /** Launch state: position (m) and velocity (m/s). */
  x0: number;
  y0: number;
  vx0: number;
  vy0: number;
  /** The static segments: ground, cliff top, cliff face. */
  segments: number[];
  /** The options used. */
  params: ProjectileParams;
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolveProjectileOptions(options: ProjectileOptions = {}): ProjectileParams {
  for (const k of Object.keys(options)) {
    if (!(k in PROJECTILE_DEFAULTS))
      throw new TypeError(
        `lab-projectile-drag: unknown option ${JSON.stringify(k)}; known: ${Object.keys(PROJECTILE_DEFAULTS).join(', ')}`,
      );
  }
  const p = { ...PROJECTILE_DEFAULTS, ...options } as ProjectileParams;
  if (!DRAG_LAWS.includes(p.law))
    throw new RangeError(`lab-projectile-drag: law must be one of ${DRAG_LAWS.join(', ')}, got ${JSON.stringify(p.law)}`);
  if (!(INTEGRATOR_NAMES as readonly string[]).includes(p.integrator)) {
    throw new RangeError(
      `lab-projectile-drag: integrator must be one of ${INTEGRATOR_NAMES.join(', ')}, got ${JSON.stringify(p.integrator)}`,
    );
  }
  for (const [key, [min, max]] of Object.entries(PROJECTILE_RANGES)) {
    const v = p[key as keyof typeof PROJECTILE_RANGES];
    if (!(typeof v === 'number' && v >= min && v <= max))
      throw new RangeError(`lab-projectile-drag: ${key} must be a number in [${min}, ${max}], got ${String(v)}`);
  }
  return p;
}

/** World options: 2D, gravity (0, -g), the chosen integrator, 1/60 s steps. */
export function projectileWorldOptions(options: ProjectileOptions = {}): PhysicsWorldOptions {
  const p = resolveProjectileOptions(options);
  return { dimensions: 2, capacity: 8, gravity: [0, -p.gravity], integrator: p.integrator, dt: 1 / 60 };
}

/**
 * Builds the scene into a fresh 2D world (ideally from `projectileWorldOptions`): ground, cliff and
 * the ball already moving with the launch velocity, its drag law set through setDrag.
 * @throws TypeError | RangeError on bad options or a 3D world.
 */
export function buildProjectile(world: PhysicsWorld, options: ProjectileOptions = {}): ProjectileHandles {
  const p = resolveProjectileOptions(options);
  if (world.dimensions !== 2) throw new RangeError(`lab-projectile-drag: needs a 2D world, got dimensions ${world.dimensions}`);
  const r = BALL_RADIUS;
  const edge = -(r + 0.1);
  const top = p.height - r - 0.05;
  const segments = [addSegment(world, { a: [-2000, 0], b: [4000, 0], friction: 0.5, restitution: 0.2 })];
  if (top > 0.05) {
    segments.push(addSegment(world, { a: [-2000, top], b: [edge, top], friction: 0.5, restitution: 0.2 }));
    segments.push(addSegment(world, { a: [edge, top], b: [edge, 0], friction: 0.5, restitution: 0.2 }));
  }
  const a = (p.angle * Math.PI) / 180;
  const vx0 = p.speed * Math.cos(a),
    vy0 = p.speed * Math.sin(a);
  const ball = addBody(world, { position: [0, p.height], velocity: [vx0, vy0], radius: r, mass: p.mass, restitution: 0.2, friction: 0.5 });
  applyDragLaw(world, ball, p.law, p.linearK, p.quadraticK);
  return { ball, x0: 0, y0: p.height, vx0, vy0, segments, params: p };
}

/**
 * Gives the ball drag law `law` with coefficients `linearK` (N s/m) and `quadraticK` (kg/m); the
 * law not in use gets coefficient 0. @throws RangeError on an unknown law or a negative coefficient.
 */
export function applyDragLaw(world: PhysicsWorld, ball: number, law: DragLaw, linearK: number, quadraticK: number): void {
  if (!DRAG_LAWS.includes(law))
    throw new RangeError(`lab-projectile-drag: law must be one of ${DRAG_LAWS.join(', ')}, got ${JSON.stringify(law)}`);
  setDrag(world, ball, { linear: law === 'linear' ? linearK : 0, quadratic: law === 'quadratic' ? quadraticK : 0 });
}
