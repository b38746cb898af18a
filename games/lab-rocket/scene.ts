/**
 * The rocket lab's scene (Ramtal and Dobre ch. 6: rockets, Newtonian gravity; ch. 7: drag): a rocket
 * with burning fuel leaves a planet. A pure builder (no DOM, no pixi) plus the exact comparison
 * curves, shared by the page and the tests.
 *
 * Physics, composed from the physics package: the planet is a static ball (the launch pad and the
 * ground) that is also a Newtonian `Attractor`; the rocket is a dynamic ball with `Thrust` (variable
 * mass: the mass drops as the fuel burns) and `QuadraticDrag`. Two game rules run before each step:
 * the pilot's throttle and heading are written into the Thrust component (mass flow rate and
 * direction), and the drag coefficient follows the air density at the rocket's altitude,
 * k = k0 exp(-h / H) (the physics package's drag coefficient is a per-body constant; it has no
 * atmosphere with a density profile).
 *
 * Planets: 'toy' (R = 1 km, surface gravity 9.81 m/s^2, G scaled to 1 m^3 kg^-1 s^-2 so M = g R^2),
 * 'earth' (SI: G = 6.6743e-11, M = 5.972e24 kg, R = 6.371e6 m) and 'none' (free space: no gravity,
 * no air).
 */
import { addBody, G_SI, type PhysicsWorld, type PhysicsWorldOptions, setAttractor, setGravitation, setThrust } from '@bitphysics/physics';

/** The planets. */
export type PlanetName = 'toy' | 'earth' | 'none';
/** Planet names, in menu order. */
export const PLANETS: readonly PlanetName[] = ['toy', 'earth', 'none'];

/** A planet and the rocket designed for it. */
export interface PlanetSpec {
  /** Radius, m (0 in free space). */
  radius: number;
  /** Mass, kg. */
  mass: number;
  /** Gravitational constant used, m^3 kg^-1 s^-2. */
  G: number;
  /** Atmosphere: sea-level drag coefficient of the rocket k0, kg/m, and scale height H, m. */
  drag: number;
  scaleHeight: number;
  /** Rocket defaults: dry mass and fuel (kg), exhaust velocity (m/s), full-throttle mass flow (kg/s). */
  dryMass: number;
  fuel: number;
  exhaustVelocity: number;
  massFlowRate: number;
  /** Rocket collider radius and drawn length, m. */
  rocketRadius: number;
  rocketLength: number;
  /** Steering rate, rad/s. */
  turnRate: number;
}

/**
 * The planets' data. Toy: a 1 km planet with Earth's surface gravity and a 300 m scale height
 * (circular orbit at the surface 99 m/s, escape 140 m/s; the rocket's ideal delta-v is 202 m/s).
 * Earth: IAU/WGS84 values; the rocket is a single stage in the class of a Falcon 9 first stage
 * (ve 3 km/s, 2.5 t/s, 420 t at lift-off), drag area of a 3.7 m cylinder with C_d 0.3.
 */
export const PLANET_SPECS: Readonly<Record<PlanetName, Readonly<PlanetSpec>>> = Object.freeze({
  toy: {
    radius: 1000,
    mass: 9.81 * 1000 * 1000,
    G: 1,
    drag: 0.25,
    scaleHeight: 300,
    dryMass: 300,
    fuel: 450,
    exhaustVelocity: 220,
    massFlowRate: 45,
    rocketRadius: 1.5,
    rocketLength: 12,
    turnRate: 0.8,
  },
  earth: {
    radius: 6.371e6,
    mass: 5.972e24,
    G: G_SI,
    drag: 1.98,
    scaleHeight: 8500,
    dryMass: 25_000,
    fuel: 395_000,
    exhaustVelocity: 3000,
    massFlowRate: 2500,
    rocketRadius: 5,
    rocketLength: 45,
    turnRate: 0.1,
  },
  none: {
    radius: 0,
    mass: 0,
    G: 0,
    drag: 0,
    scaleHeight: 1,
    dryMass: 300,
    fuel: 450,
    exhaustVelocity: 220,
    massFlowRate: 45,
    rocketRadius: 1.5,
    rocketLength: 12,
    turnRate: 0.8,
  },
});

/** Options of the scene; every field optional (defaults from the planet's spec). */
export interface RocketOptions {
  /** Planet. Default 'toy'. */
  planet?: PlanetName;
  /** Dry mass, kg, > 0. */
  dryMass?: number;
  /** Fuel, kg, >= 0. */
  fuel?: number;
  /** Exhaust velocity, m/s, > 0. */
  exhaustVelocity?: number;
  /** Full-throttle mass flow rate, kg/s, > 0. */
  massFlowRate?: number;
  /** Air drag on (only where there is a planet). Default true. */
  drag?: boolean;
  /** Time warp: the world's step is warp / 60 s in `warp` substeps (accuracy unchanged), integer in [1, 50]. Default 1. */
  warp?: number;
}

/** Resolved options. */
export type RocketParams = Required<RocketOptions>;

const KNOWN = ['planet', 'dryMass', 'fuel', 'exhaustVelocity', 'massFlowRate', 'drag', 'warp'];

function fail(message: string): never {
  throw new RangeError(`lab-rocket: ${message}`);
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolveRocketOptions(options: RocketOptions = {}): RocketParams {
  for (const k of Object.keys(options)) {
    if (!KNOWN.includes(k)) throw new TypeError(`lab-rocket: unknown option ${JSON.stringify(k)}; known: ${KNOWN.join(', ')}`);
  }
  const planet = options.planet ?? 'toy';
  if (!PLANETS.includes(planet)) fail(`planet must be one of ${PLANETS.join(', ')}, got ${JSON.stringify(planet)}`);
  const s = PLANET_SPECS[planet];
  const p: RocketParams = {
    planet,
    dryMass: options.dryMass ?? s.dryMass,
    fuel: options.fuel ?? s.fuel,
    exhaustVelocity: options.exhaustVelocity ?? s.exhaustVelocity,
    massFlowRate: options.massFlowRate ?? s.massFlowRate,
    drag: options.drag ?? true,
    warp: options.warp ?? 1,
  };
  if (!(p.dryMass > 0 && Number.isFinite(p.dryMass))) fail(`dryMass must be > 0 kg, got ${p.dryMass}`);
  if (!(p.fuel >= 0 && Number.isFinite(p.fuel))) fail(`fuel must be >= 0 kg, got ${p.fuel}`);
  if (!(p.exhaustVelocity > 0 && Number.isFinite(p.exhaustVelocity))) fail(`exhaustVelocity must be > 0 m/s, got ${p.exhaustVelocity}`);
  if (!(p.massFlowRate > 0 && Number.isFinite(p.massFlowRate))) fail(`massFlowRate must be > 0 kg/s, got ${p.massFlowRate}`);
  if (typeof p.drag !== 'boolean') throw new TypeError(`lab-rocket: drag must be a boolean, got ${String(p.drag)}`);
  if (!(Number.isInteger(p.warp) && p.warp >= 1 && p.warp <= 50)) fail(`warp must be an integer in [1, 50], got ${p.warp}`);
  return p;
}

/** World options: 2D, no uniform gravity (the planet attracts), RK4, dt = warp / 60 s in warp substeps. */
export function rocketWorldOptions(options: RocketOptions = {}): PhysicsWorldOptions {
  const p = resolveRocketOptions(options);
  return { dimensions: 2, capacity: 8, gravity: [0, 0], integrator: 'rk4', dt: p.warp / 60, substeps: p.warp };
}

/** The pilot's controls and the state of the flight, read and written by the page and the rules. */
export interface RocketHandles {
  /** The rocket and the planet (0 in free space). */
  rocket: number;
  planet: number;
  spec: Readonly<PlanetSpec>;
  params: RocketParams;
  /** Throttle in [0, 1]. */
  throttle: number;
  /** Heading: direction of the thrust, rad from +x (pi/2 = up at launch). */
  heading: number;
  /** Mass at the start, kg. */
  initialMass: number;
  /** Time, s, mass, kg, throttle, and gravity at the rocket's centre (m/s^2) when it left the pad (NaN before). */
  liftoffTime: number;
  liftoffMass: number;
  liftoffThrottle: number;
  liftoffGravity: number;
  /** Whether the flight has stayed vertical at constant throttle since lift-off (the uniform-g model applies). */
  vertical: boolean;
}

/**
 * Builds the scene: the planet (static ball and attractor, G set for the planet) and the rocket on its
 * pad at the north pole (or at the origin in free space) at full throttle, pointing up.
 * @throws TypeError | RangeError on bad options.
 */
export function buildRocket(world: PhysicsWorld, options: RocketOptions = {}): RocketHandles {
  const p = resolveRocketOptions(options);
  const s = PLANET_SPECS[p.planet];
  let planet = 0;
  if (p.planet !== 'none') {
    setGravitation(world, { constant: s.G });
    planet = addBody(world, { position: [0, 0], radius: s.radius, static: true, friction: 0.9, restitution: 0 });
    setAttractor(world, planet, { mass: s.mass });
  }
  const m0 = p.dryMass + p.fuel;
  const rocket = addBody(world, {
    position: p.planet === 'none' ? [0, 0] : [0, s.radius + s.rocketRadius],
    mass: m0,
    radius: s.rocketRadius,
    rotates: false,
    friction: 0.9,
    restitution: 0,
    // Drag law on every planet (its coefficient is set each step by applyControls; 0 with drag off).
    ...(p.planet !== 'none' ? { quadraticDrag: p.drag ? s.drag : 0 } : {}),
  });
  setThrust(world, rocket, { exhaustVelocity: p.exhaustVelocity, massFlowRate: p.massFlowRate, fuel: p.fuel, direction: [0, 1] });
  return {
    rocket,
    planet,
    spec: s,
    params: p,
    throttle: 1,
    heading: Math.PI / 2,
    initialMass: m0,
    liftoffTime: Number.NaN,
    liftoffMass: Number.NaN,
    liftoffThrottle: Number.NaN,
    liftoffGravity: Number.NaN,
    vertical: true,
  };
}

/** Altitude of the rocket's bottom above the ground, m (distance from the start point, the origin, in free space). */
export function altitude(world: PhysicsWorld, h: RocketHandles): number {
  const P = world.components.Position;
  const r = Math.hypot(P.x[h.rocket]!, P.y[h.rocket]!);
  return h.planet === 0 ? r : r - h.spec.radius - h.spec.rocketRadius;
}

/** The rocket's speed, m/s. */
export function speed(world: PhysicsWorld, h: RocketHandles): number {
  const V = world.components.Velocity;
  return Math.hypot(V.x[h.rocket]!, V.y[h.rocket]!);
}

/**
 * The game rules, run before each step: writes throttle and heading into the Thrust component, sets
 * the drag coefficient for the altitude (k0 exp(-h / H)), and notes lift-off and whether the flight is
 * still vertical at constant throttle.
 */
export function applyControls(world: PhysicsWorld, h: RocketHandles): void {
  const T = world.components.Thrust,
    e = h.rocket;
  T.massFlowRate[e] = h.throttle * h.params.massFlowRate;
  T.dirX[e] = Math.cos(h.heading);
  T.dirY[e] = Math.sin(h.heading);
  const alt = altitude(world, h);
  if (h.planet !== 0)
    world.components.QuadraticDrag.k[e] = h.params.drag ? h.spec.drag * Math.exp(-Math.max(0, alt) / h.spec.scaleHeight) : 0;
  // Lift-off: the moment the thrust exceeds the weight on the pad (in free space: the first thrust).
  const thrust = h.params.exhaustVelocity * T.massFlowRate[e]! * (T.fuel[e]! > 0 ? 1 : 0);
  if (Number.isNaN(h.liftoffTime) && thrust > world.components.Mass.value[e]! * surfaceGravity(h)) {
    h.liftoffTime = world.time;
    h.liftoffMass = world.components.Mass.value[e]!;
    h.liftoffThrottle = h.throttle;
    const P = world.components.Position;
    const r2 = P.x[e]! ** 2 + P.y[e]! ** 2;
    h.liftoffGravity = h.planet === 0 ? 0 : (h.spec.G * h.spec.mass) / r2;
  }
  if (!Number.isNaN(h.liftoffTime) && (h.throttle !== h.liftoffThrottle || Math.abs(h.heading - Math.PI / 2) > 1e-9)) h.vertical = false;
}

/** Surface gravity g0 = G M / R^2 of the planet, m/s^2 (0 in free space). */
export function surfaceGravity(h: RocketHandles): number {
  return h.planet === 0 ? 0 : (h.spec.G * h.spec.mass) / (h.spec.radius * h.spec.radius);
}

/**
 * Tsiolkovsky's ideal speed gain, m/s: ve ln(m0 / m), m0 the starting mass and m the mass now. It is
 * the speed in free space for a burn in a fixed direction from rest, whatever the throttle profile.
 * Source: Ramtal and Dobre ch. 6; Tsiolkovsky (1903).
 */
export function tsiolkovsky(ve: number, m0: number, m: number): number {
  return ve * Math.log(m0 / m);
}

/**
 * The uniform-gravity model of a vertical ascent from lift-off, no drag (exact for that model):
 * speed v = ve ln(m_l / m) - g0 t, and, while the mass flow mu has been constant since lift-off,
 * height z = ve (t - (m / mu) ln(m_l / m)) - g0 t^2 / 2 during the burn and ballistic after it;
 * t the time since lift-off, m_l the mass at lift-off, g0 the gravity at the rocket's centre then. The gap between it and the flight is the
 * weakening of gravity with height (inverse square) and the drag. NaN before lift-off, when the
 * flight is no longer vertical at constant throttle, or in free space.
 * Source: Thomson, Introduction to Space Dynamics (1961), sec. 7.2; Ramtal and Dobre ch. 6.
 * Writes [speed m/s, height m] into `out`.
 */
export function uniformGravityModel(world: PhysicsWorld, h: RocketHandles, out: Float64Array): Float64Array {
  out[0] = Number.NaN;
  out[1] = Number.NaN;
  if (h.planet === 0 || Number.isNaN(h.liftoffTime) || !h.vertical) return out;
  const g = h.liftoffGravity,
    ve = h.params.exhaustVelocity;
  const t = world.time - h.liftoffTime;
  const m = world.components.Mass.value[h.rocket]!;
  const ml = h.liftoffMass;
  const mu = h.liftoffThrottle * h.params.massFlowRate;
  out[0] = Math.abs(ve * Math.log(ml / m) - g * t);
  if (mu > 0) {
    const tb = Math.min(t, (ml - h.params.dryMass) / mu); // burn time so far (the fuel runs out at (ml - dry) / mu)
    const mb = ml - mu * tb;
    const zb = ve * (tb - (mb / mu) * Math.log(ml / mb)) - 0.5 * g * tb * tb;
    const vb = ve * Math.log(ml / mb) - g * tb;
    const c = t - tb;
    out[1] = zb + vb * c - 0.5 * g * c * c;
  }
  return out;
}

/**
 * Periapsis and apoapsis altitudes of the Kepler orbit through the rocket's present state (vis-viva:
 * a = -mu / (2 eps), e = sqrt(1 + 2 eps L^2 / mu^2), r = a (1 -+ e)), m above the ground, into `out`
 * [periapsis, apoapsis]; apoapsis Infinity on an escape orbit. NaN in free space.
 * Source: Ramtal and Dobre ch. 6; any orbital mechanics text (Curtis, Orbital Mechanics for Engineering Students, ch. 2).
 */
export function orbitAltitudes(world: PhysicsWorld, h: RocketHandles, out: Float64Array): Float64Array {
  out[0] = Number.NaN;
  out[1] = Number.NaN;
  if (h.planet === 0) return out;
  const P = world.components.Position,
    V = world.components.Velocity,
    e = h.rocket;
  const x = P.x[e]!,
    y = P.y[e]!,
    vx = V.x[e]!,
    vy = V.y[e]!;
  const mu = h.spec.G * h.spec.mass;
  const r = Math.hypot(x, y),
    v2 = vx * vx + vy * vy;
  const eps = v2 / 2 - mu / r;
  const L = x * vy - y * vx;
  const ecc = Math.sqrt(Math.max(0, 1 + (2 * eps * L * L) / (mu * mu)));
  const R = h.spec.radius;
  if (eps >= 0) {
    out[0] = (L * L) / (mu * (1 + ecc)) - R;
    out[1] = Infinity;
    return out;
  }
  const a = -mu / (2 * eps);
  out[0] = a * (1 - ecc) - R;
  out[1] = a * (1 + ecc) - R;
  return out;
}
