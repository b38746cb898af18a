/**
 * The cyclotron lab's scene (Ramtal and Dobre ch. 10: the Lorentz force): one charged ball in a
 * uniform magnetic field B (out of the screen) and an optional uniform electric field E along y. A
 * pure builder (no DOM, no pixi) with the trajectory measurements, shared by the page and the tests.
 *
 * Physics, composed from the physics package: the ball has `Charge`; the fields are a MagneticField
 * and an ElectricField entity; the physics' Lorentz law F = q (E + v x B) moves it with the world's
 * integrator. Without E the ball circles with radius r = m v / (|q| B) and period T = 2 pi m / (|q| B);
 * with E it drifts with v_d = E x B / B^2 while circling with radius m |v - v_d| / (|q| B) in the
 * drifting frame, period unchanged (Griffiths, Introduction to Electrodynamics, 4th ed., ex. 5.2).
 *
 * The radius and period are measured from the trajectory alone (`OrbitMeter`): v_y changes sign from
 * - to + once a revolution (E is along y, so the drift is along x and never adds to v_y); the time
 * between two such crossings (interpolated linearly within the step) is the period, and half the span
 * of y between them is the radius.
 */
import {
  addBody,
  addElectricField,
  addMagneticField,
  type IntegratorName,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  setCharge,
} from '@bitphysics/physics';

/** Options of the scene; every field optional. Units chosen so the orbit is metres across and seconds long. */
export interface CyclotronOptions {
  /** Charge, mC, in [-5, 5], non-zero. Default 1. */
  charge?: number;
  /** Mass, g, in [0.5, 20]. Default 1. */
  mass?: number;
  /** Magnetic field B_z, T, in [0.1, 4] (its sign is the direction; `flipped` reverses it). Default 1. */
  field?: number;
  /** Launch speed, m/s, in [0.1, 20]. Default 3. */
  speed?: number;
  /** Electric field along y, V/m, in [-5, 5]. Default 0. */
  electric?: number;
  /** Integration scheme. Default 'rk4'. */
  integrator?: IntegratorName;
  /** Substeps a step, integer in [1, 64]. Default 1. */
  substeps?: number;
}

/** Resolved options. */
export type CyclotronParams = Required<CyclotronOptions>;

const KNOWN = ['charge', 'mass', 'field', 'speed', 'electric', 'integrator', 'substeps'];

function fail(message: string): never {
  throw new RangeError(`lab-cyclotron: ${message}`);
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolveCyclotronOptions(options: CyclotronOptions = {}): CyclotronParams {
  for (const k of Object.keys(options)) {
    if (!KNOWN.includes(k)) throw new TypeError(`lab-cyclotron: unknown option ${JSON.stringify(k)}; known: ${KNOWN.join(', ')}`);
  }
  const p: CyclotronParams = {
    charge: options.charge ?? 1,
    mass: options.mass ?? 1,
    field: options.field ?? 1,
    speed: options.speed ?? 3,
    electric: options.electric ?? 0,
    integrator: options.integrator ?? 'rk4',
    substeps: options.substeps ?? 1,
  };
  if (!(p.charge >= -5 && p.charge <= 5 && p.charge !== 0)) fail(`charge must be non-zero in [-5, 5] mC, got ${p.charge}`);
  if (!(p.mass >= 0.5 && p.mass <= 20)) fail(`mass must be in [0.5, 20] g, got ${p.mass}`);
  if (!(p.field >= 0.1 && p.field <= 4)) fail(`field must be in [0.1, 4] T, got ${p.field}`);
  if (!(p.speed >= 0.1 && p.speed <= 20)) fail(`speed must be in [0.1, 20] m/s, got ${p.speed}`);
  if (!(p.electric >= -5 && p.electric <= 5)) fail(`electric must be in [-5, 5] V/m, got ${p.electric}`);
  if (!(Number.isInteger(p.substeps) && p.substeps >= 1 && p.substeps <= 64))
    fail(`substeps must be an integer in [1, 64], got ${p.substeps}`);
  return p;
}

/** World options: 2D, no gravity, the chosen scheme and substeps. */
export function cyclotronWorldOptions(options: CyclotronOptions = {}): PhysicsWorldOptions {
  const p = resolveCyclotronOptions(options);
  return { dimensions: 2, capacity: 8, gravity: [0, 0], integrator: p.integrator, substeps: p.substeps };
}

/** Measures radius and period of a circling body from its trajectory (see the file comment). */
export interface OrbitMeter {
  /** Last measured period, s (NaN until two crossings). */
  period: number;
  /** Last measured radius, m (NaN until two crossings). */
  radius: number;
  /** Revolutions measured since the last restart. */
  revolutions: number;
  /** Time of the last upward crossing of v_y, s (NaN before the first). */
  lastCrossing: number;
  /** Extremes of y since the last crossing, m. */
  minY: number;
  maxY: number;
  /** v_y and time of the previous sample. */
  prevVy: number;
  prevT: number;
}

/** A meter that has measured nothing yet. */
export function createOrbitMeter(): OrbitMeter {
  const m = {} as OrbitMeter;
  restartMeter(m);
  return m;
}

/** Forgets every measurement (after a reset, a flip or a change of parameters). */
export function restartMeter(m: OrbitMeter): void {
  m.period = Number.NaN;
  m.radius = Number.NaN;
  m.revolutions = 0;
  m.lastCrossing = Number.NaN;
  m.minY = Infinity;
  m.maxY = -Infinity;
  m.prevVy = Number.NaN;
  m.prevT = Number.NaN;
}

/** Feeds the meter the body's state after a step: time t (s), y (m), v_y (m/s). */
export function meterSample(m: OrbitMeter, t: number, y: number, vy: number): void {
  if (y < m.minY) m.minY = y;
  if (y > m.maxY) m.maxY = y;
  if (m.prevVy < 0 && vy >= 0) {
    const tc = m.prevT + ((t - m.prevT) * -m.prevVy) / (vy - m.prevVy);
    if (!Number.isNaN(m.lastCrossing)) {
      m.period = tc - m.lastCrossing;
      m.radius = 0.5 * (m.maxY - m.minY);
      m.revolutions++;
    }
    m.lastCrossing = tc;
    m.minY = y;
    m.maxY = y;
  }
  m.prevVy = vy;
  m.prevT = t;
}

/** What `buildCyclotron` returns. */
export interface CyclotronHandles {
  /** The charged ball. */
  particle: number;
  /** The magnetic and electric field entities. */
  magnetic: number;
  electric: number;
  /** The exact orbit of the current run: guiding centre at `baseTime`, m, radius, m, and period, s. */
  centreX: number;
  centreY: number;
  baseTime: number;
  exactRadius: number;
  exactPeriod: number;
  /** Drift velocity E x B / B^2 along x, m/s. */
  drift: number;
  params: CyclotronParams;
  meter: OrbitMeter;
}

/** Charge in C, mass in kg, B_z in T of the current run (B_z carries the flip). */
function sim(world: PhysicsWorld, h: CyclotronHandles): { q: number; m: number; b: number } {
  return {
    q: world.components.Charge.value[h.particle]!,
    m: world.components.Mass.value[h.particle]!,
    b: world.components.MagneticField.z[h.magnetic]!,
  };
}

/**
 * Builds the scene: the field entities and the ball launched along +x with `speed` from where its
 * exact orbit is centred on the origin. @throws TypeError | RangeError on bad options.
 */
export function buildCyclotron(world: PhysicsWorld, options: CyclotronOptions = {}): CyclotronHandles {
  const p = resolveCyclotronOptions(options);
  const q = p.charge * 1e-3,
    m = p.mass * 1e-3;
  const omega = (q * p.field) / m; // signed: > 0 turns clockwise
  const drift = p.electric / p.field;
  // Centre = x + (v_y, -v_x)_rel / omega with v_rel = v - v_d = (speed - drift, 0): start at (0, (speed - drift) / omega).
  const y0 = (p.speed - drift) / omega;
  const r = Math.abs(y0);
  const particle = addBody(world, { position: [0, y0], velocity: [p.speed, 0], mass: m, radius: Math.max(0.02, 0.05 * r), rotates: false });
  const magnetic = addMagneticField(world, { field: p.field });
  const electric = addElectricField(world, { field: [0, p.electric] });
  const h: CyclotronHandles = {
    particle,
    magnetic,
    electric,
    centreX: 0,
    centreY: 0,
    baseTime: 0,
    exactRadius: 0,
    exactPeriod: 0,
    drift,
    params: p,
    meter: createOrbitMeter(),
  };
  setCharge(world, particle, q);
  rebaseline(world, h);
  return h;
}

/**
 * Takes the current state as the start of a new run: the exact orbit (guiding centre, radius
 * m |v - v_d| / (|q| B), period 2 pi m / (|q| B)) from the present velocity, and a fresh meter.
 * Source: Ramtal and Dobre ch. 10; Griffiths ex. 5.2.
 */
export function rebaseline(world: PhysicsWorld, h: CyclotronHandles): void {
  const { q, m, b } = sim(world, h);
  const P = world.components.Position,
    V = world.components.Velocity;
  const e = h.particle;
  const ey = world.components.ElectricField.y[h.electric]!;
  h.drift = ey / b;
  const omega = (q * b) / m;
  const ux = V.x[e]! - h.drift,
    uy = V.y[e]!;
  h.centreX = P.x[e]! + uy / omega;
  h.centreY = P.y[e]! - ux / omega;
  h.baseTime = world.time;
  h.exactRadius = Math.hypot(ux, uy) / Math.abs(omega);
  h.exactPeriod = (2 * Math.PI) / Math.abs(omega);
  restartMeter(h.meter);
}

/** Reverses the magnetic field (B -> -B) and starts a new run from the current state. */
export function flipField(world: PhysicsWorld, h: CyclotronHandles): void {
  const B = world.components.MagneticField;
  B.z[h.magnetic] = -B.z[h.magnetic]!;
  rebaseline(world, h);
}

/** Feeds the meter after a step. */
export function measure(world: PhysicsWorld, h: CyclotronHandles): void {
  const e = h.particle;
  meterSample(h.meter, world.time, world.components.Position.y[e]!, world.components.Velocity.y[e]!);
}

/** Where the exact orbit's guiding centre is now, m (it drifts with v_d), into out[0], out[1]. */
export function exactCentre(world: PhysicsWorld, h: CyclotronHandles, out: Float64Array): Float64Array {
  out[0] = h.centreX + h.drift * (world.time - h.baseTime);
  out[1] = h.centreY;
  return out;
}
