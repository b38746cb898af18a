/**
 * The electric field lab's scene (Ramtal and Dobre ch. 10: Coulomb's law, electric fields): fixed
 * point charges and one free test charge that moves under their Coulomb force, in an elastic box.
 * A pure builder (no DOM, no pixi), shared by the page and the tests.
 *
 * Physics, composed from the physics package: the fixed charges are static bodies with `Charge`, the
 * test charge a dynamic ball with `Charge`; the physics' Coulomb law (softened, constant and softening
 * from `setElectrostatics`) moves it. Walls have restitution 1 and no friction (and the world's
 * restitution threshold is 0), so the test charge's energy is conserved through bounces too.
 *
 * Energy of the test charge: kinetic energy plus its electric potential energy in the field of the
 * fixed charges, both from the physics package's diagnostics (`kineticEnergy`,
 * `electricPotentialEnergy`); the constant energy of the fixed charges among themselves is measured
 * with the same diagnostic (test charge momentarily neutral) and subtracted.
 *
 * The field lines are drawn by integrating the direction of the field E(x) = sum_i k q_i (x - x_i) /
 * (|x - x_i|^2 + eps^2)^(3/2), the same softened Coulomb field the physics applies (same constant k
 * and softening eps, read from the world), with classical RK4 steps of fixed arc length.
 */
import {
  addBody,
  electricPotentialEnergy,
  type IntegratorName,
  kineticEnergy,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  removeBody,
  setBoundary,
  setCharge,
  setElectrostatics,
  setPosition,
  setVelocity,
  slotOf,
} from '@bitphysics/physics';

/** Inner corners of the box, m. */
export const BOX = Object.freeze({ minX: -8, minY: -5, maxX: 8, maxY: 5 });
/** Most fixed charges at once. */
export const MAX_CHARGES = 16;
/** One microcoulomb, C. */
export const MICRO = 1e-6;
/** Radius of the test charge's ball, m. */
export const TEST_RADIUS = 0.12;

/** Named layouts of fixed charges. */
export type Preset = 'dipole' | 'like pair' | 'quadrupole' | 'single' | 'none';
/** The presets, in menu order. */
export const PRESETS: readonly Preset[] = ['dipole', 'like pair', 'quadrupole', 'single', 'none'];

/** Options of the scene; every field optional. */
export interface ElectricOptions {
  /** Layout of fixed charges. Default 'dipole'. */
  preset?: Preset;
  /** Magnitude of the preset charges, uC, in (0, 20]. Default 2. */
  sourceCharge?: number;
  /** Test charge, uC, in [-10, 10]. Default 0.5. */
  testCharge?: number;
  /** Test charge mass, g, in [0.01, 1000]. Default 1. */
  testMass?: number;
  /** Coulomb softening length, m, in [0, 2]. Default 0.2. */
  softening?: number;
  /** Integration scheme. Default 'velocity-verlet'. */
  integrator?: IntegratorName;
  /** Substeps a step, integer in [1, 64]. Default 8. */
  substeps?: number;
  /** Launch position of the test charge, m. Default (0, 2.5). */
  launchPosition?: [number, number];
  /** Launch velocity of the test charge, m/s. Default (1.2, 0). */
  launchVelocity?: [number, number];
}

/** Resolved options. */
export type ElectricParams = Required<ElectricOptions>;

const KNOWN = [
  'preset',
  'sourceCharge',
  'testCharge',
  'testMass',
  'softening',
  'integrator',
  'substeps',
  'launchPosition',
  'launchVelocity',
];

function fail(message: string): never {
  throw new RangeError(`lab-electric-field: ${message}`);
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolveElectricOptions(options: ElectricOptions = {}): ElectricParams {
  for (const k of Object.keys(options)) {
    if (!KNOWN.includes(k)) throw new TypeError(`lab-electric-field: unknown option ${JSON.stringify(k)}; known: ${KNOWN.join(', ')}`);
  }
  const p: ElectricParams = {
    preset: options.preset ?? 'dipole',
    sourceCharge: options.sourceCharge ?? 2,
    testCharge: options.testCharge ?? 0.5,
    testMass: options.testMass ?? 1,
    softening: options.softening ?? 0.2,
    integrator: options.integrator ?? 'velocity-verlet',
    substeps: options.substeps ?? 8,
    launchPosition: options.launchPosition ?? [0, 2.5],
    launchVelocity: options.launchVelocity ?? [1.2, 0],
  };
  if (!PRESETS.includes(p.preset)) fail(`preset must be one of ${PRESETS.join(', ')}, got ${JSON.stringify(p.preset)}`);
  if (!(p.sourceCharge > 0 && p.sourceCharge <= 20)) fail(`sourceCharge must be in (0, 20] uC, got ${p.sourceCharge}`);
  if (!(p.testCharge >= -10 && p.testCharge <= 10)) fail(`testCharge must be in [-10, 10] uC, got ${p.testCharge}`);
  if (!(p.testMass >= 0.01 && p.testMass <= 1000)) fail(`testMass must be in [0.01, 1000] g, got ${p.testMass}`);
  if (!(p.softening >= 0 && p.softening <= 2)) fail(`softening must be in [0, 2] m, got ${p.softening}`);
  if (!(Number.isInteger(p.substeps) && p.substeps >= 1 && p.substeps <= 64))
    fail(`substeps must be an integer in [1, 64], got ${p.substeps}`);
  for (const [name, v] of [
    ['launchPosition', p.launchPosition],
    ['launchVelocity', p.launchVelocity],
  ] as const) {
    if (!(Array.isArray(v) && v.length === 2 && v.every(Number.isFinite)))
      fail(`${name} must be two finite numbers, got ${JSON.stringify(v)}`);
  }
  return p;
}

/** World options: 2D, no gravity, restitution threshold 0 (elastic walls at every speed), the scheme and substeps. */
export function electricWorldOptions(options: ElectricOptions = {}): PhysicsWorldOptions {
  const p = resolveElectricOptions(options);
  return {
    dimensions: 2,
    capacity: MAX_CHARGES + 8,
    gravity: [0, 0],
    integrator: p.integrator,
    substeps: p.substeps,
    restitutionThreshold: 0,
  };
}

/** What `buildElectric` returns. */
export interface ElectricHandles {
  /** The fixed charges (static bodies), in the order placed. */
  charges: number[];
  /** The test charge. */
  test: number;
  /** Energy of the fixed charges among themselves, J (see `rebaseline`). */
  sourceEnergy: number;
  /** The test charge's energy when last (re)baselined, J: the exact, constant value. */
  initialEnergy: number;
  params: ElectricParams;
}

/** Preset charge layouts: [x m, y m, sign]. */
function presetLayout(preset: Preset): [number, number, number][] {
  switch (preset) {
    case 'dipole':
      return [
        [-3, 0, 1],
        [3, 0, -1],
      ];
    case 'like pair':
      return [
        [-3, 0, 1],
        [3, 0, 1],
      ];
    case 'quadrupole':
      return [
        [-2.5, -2, 1],
        [2.5, -2, -1],
        [2.5, 2, 1],
        [-2.5, 2, -1],
      ];
    case 'single':
      return [[0, 0, -1]];
    case 'none':
      return [];
  }
}

/**
 * Builds the scene into `world` (a fresh world from `electricWorldOptions`): elastic walls, the preset's
 * fixed charges, and the test charge at its launch point and velocity; sets the Coulomb softening.
 * @throws TypeError | RangeError on bad options or a 3D world.
 */
export function buildElectric(world: PhysicsWorld, options: ElectricOptions = {}): ElectricHandles {
  const p = resolveElectricOptions(options);
  if (world.dimensions !== 2) fail(`needs a 2D world, got dimensions ${world.dimensions}`);
  setBoundary(world, { min: [BOX.minX, BOX.minY], max: [BOX.maxX, BOX.maxY], restitution: 1, friction: 0 });
  setElectrostatics(world, { softening: p.softening });
  const test = addBody(world, {
    position: p.launchPosition,
    velocity: p.launchVelocity,
    radius: TEST_RADIUS,
    mass: p.testMass * 1e-3,
    restitution: 1,
    friction: 0,
    rotates: false,
  });
  setCharge(world, test, p.testCharge * MICRO);
  const h: ElectricHandles = { charges: [], test, sourceEnergy: 0, initialEnergy: 0, params: p };
  for (const [x, y, s] of presetLayout(p.preset)) addCharge(world, h, x, y, s * p.sourceCharge);
  rebaseline(world, h);
  return h;
}

/**
 * Adds a fixed charge of `microcoulombs` uC (non-zero, |q| <= 20) at (x, y) m (clamped into the box).
 * Call `rebaseline` afterwards (the field changed). @returns its entity.
 * @throws RangeError on a bad charge or position, or when MAX_CHARGES are placed.
 */
export function addCharge(world: PhysicsWorld, h: ElectricHandles, x: number, y: number, microcoulombs: number): number {
  if (!Number.isFinite(x) || !Number.isFinite(y)) fail(`addCharge: x and y must be finite, got ${x}, ${y}`);
  if (!(microcoulombs !== 0 && Math.abs(microcoulombs) <= 20))
    fail(`addCharge: charge must be non-zero with |q| <= 20 uC, got ${microcoulombs}`);
  if (h.charges.length >= MAX_CHARGES) fail(`addCharge: at most ${MAX_CHARGES} charges`);
  const e = addBody(world, { position: [clampX(x), clampY(y)], static: true });
  setCharge(world, e, microcoulombs * MICRO);
  h.charges.push(e);
  return e;
}

function clampX(x: number): number {
  return Math.min(BOX.maxX, Math.max(BOX.minX, x));
}
function clampY(y: number): number {
  return Math.min(BOX.maxY, Math.max(BOX.minY, y));
}

/** Moves fixed charge `eid` to (x, y) m (clamped into the box). Call `rebaseline` afterwards. @throws RangeError if it is not a fixed charge. */
export function moveCharge(world: PhysicsWorld, h: ElectricHandles, eid: number, x: number, y: number): void {
  if (!h.charges.includes(eid)) fail(`moveCharge: ${eid} is not a fixed charge`);
  setPosition(world, eid, [clampX(x), clampY(y)]);
}

/** Removes fixed charge `eid`. Call `rebaseline` afterwards. @throws RangeError if it is not a fixed charge. */
export function removeCharge(world: PhysicsWorld, h: ElectricHandles, eid: number): void {
  const i = h.charges.indexOf(eid);
  if (i < 0) fail(`removeCharge: ${eid} is not a fixed charge`);
  h.charges.splice(i, 1);
  removeBody(world, eid);
}

/** Sets fixed charge `eid` to `microcoulombs` uC (non-zero, |q| <= 20). Call `rebaseline` afterwards. @throws RangeError. */
export function setChargeValue(world: PhysicsWorld, h: ElectricHandles, eid: number, microcoulombs: number): void {
  if (!h.charges.includes(eid)) fail(`setChargeValue: ${eid} is not a fixed charge`);
  if (!(microcoulombs !== 0 && Math.abs(microcoulombs) <= 20))
    fail(`setChargeValue: charge must be non-zero with |q| <= 20 uC, got ${microcoulombs}`);
  setCharge(world, eid, microcoulombs * MICRO);
}

/** Puts the test charge back at its launch point with its launch velocity. Call `rebaseline` afterwards. */
export function relaunch(world: PhysicsWorld, h: ElectricHandles): void {
  setPosition(world, h.test, h.params.launchPosition);
  setVelocity(world, h.test, h.params.launchVelocity);
}

/**
 * The test charge's energy now, J: kinetic plus electric potential in the field of the fixed charges
 * (the physics' diagnostics, minus the fixed charges' own pair energy `h.sourceEnergy`).
 */
export function testEnergy(world: PhysicsWorld, h: ElectricHandles): number {
  return kineticEnergy(world) + electricPotentialEnergy(world) - h.sourceEnergy;
}

/**
 * Re-measures the fixed charges' own energy and takes the test charge's energy now as the new exact
 * (constant) value. Call after anything that changes the field or the test charge (placing, moving,
 * removing or changing charges, softening, relaunching).
 */
export function rebaseline(world: PhysicsWorld, h: ElectricHandles): void {
  const q = world.components.Charge.value;
  const saved = q[slotOf(h.test)]!;
  q[slotOf(h.test)] = 0;
  h.sourceEnergy = electricPotentialEnergy(world);
  q[slotOf(h.test)] = saved;
  h.initialEnergy = testEnergy(world, h);
}

/** Sets the test charge, uC in [-10, 10]. Call `rebaseline` afterwards. @throws RangeError out of range. */
export function setTestCharge(world: PhysicsWorld, h: ElectricHandles, microcoulombs: number): void {
  if (!(microcoulombs >= -10 && microcoulombs <= 10)) fail(`testCharge must be in [-10, 10] uC, got ${microcoulombs}`);
  h.params.testCharge = microcoulombs;
  setCharge(world, h.test, microcoulombs * MICRO);
}

/** Sets the softening length, m in [0, 2]. Call `rebaseline` afterwards. @throws RangeError out of range. */
export function setSoftening(world: PhysicsWorld, h: ElectricHandles, eps: number): void {
  if (!(eps >= 0 && eps <= 2)) fail(`softening must be in [0, 2] m, got ${eps}`);
  h.params.softening = eps;
  setElectrostatics(world, { softening: eps });
}

// ---- Field lines ---------------------------------------------------------------------------------

/** Buffers of traced field lines: points of every line packed in `xy`, line k spanning [start[k], start[k+1]). */
export interface FieldLines {
  /** Line points, m: x0, y0, x1, y1, ... */
  xy: Float64Array;
  /** Index of each line's first point (in points, not numbers), and one past the last line's end. */
  start: Int32Array;
  /** Lines traced. */
  count: number;
}

/** Field-line tracing settings. */
export interface TraceOptions {
  /** Lines per uC of charge (at least 4, at most 32 per charge). Default 8. */
  linesPerMicrocoulomb?: number;
  /** Arc length of one RK4 step, m. Default 0.05. */
  stepLength?: number;
  /** Most steps a line. Default 700. */
  maxSteps?: number;
  /** Distance from a charge at which lines start and end, m. Default 0.18. */
  radius?: number;
}

/** Allocates field-line buffers for up to `MAX_CHARGES` x 32 lines of `maxSteps` + 1 points. */
export function createFieldLines(maxSteps = 700): FieldLines {
  const lines = MAX_CHARGES * 32;
  return { xy: new Float64Array(lines * (maxSteps + 1) * 2), start: new Int32Array(lines + 1), count: 0 };
}

const ex = new Float64Array(1),
  ey = new Float64Array(1);

/** The softened Coulomb field of the fixed charges at (x, y), V/m, into ex[0], ey[0] (same law and constants as the physics). */
function fieldAt(world: PhysicsWorld, charges: readonly number[], x: number, y: number): void {
  const P = world.components.Position,
    q = world.components.Charge.value;
  const K = world.laws.coulombConstant,
    eps2 = world.laws.electricSoftening ** 2;
  let sx = 0,
    sy = 0;
  for (let i = 0; i < charges.length; i++) {
    const c = charges[i]!;
    const dx = x - P.x[slotOf(c)]!,
      dy = y - P.y[slotOf(c)]!;
    const r2 = dx * dx + dy * dy + eps2;
    if (r2 === 0) continue;
    const k = (K * q[slotOf(c)]!) / (r2 * Math.sqrt(r2));
    sx += k * dx;
    sy += k * dy;
  }
  ex[0] = sx;
  ey[0] = sy;
}

/**
 * Traces field lines of the fixed charges into `out` (reusing its buffers): from every positive
 * charge, `linesPerMicrocoulomb` x q lines leave evenly spaced around it and follow E; from every
 * negative charge, lines are traced against E and kept only if they do not end on a positive charge
 * (those were drawn already). A line stops on reaching another charge, leaving the box or after `maxSteps` steps. Each step is classical RK4 on dx/ds = E / |E| with ds =
 * `stepLength`. @returns `out`.
 */
export function traceFieldLines(world: PhysicsWorld, h: ElectricHandles, out: FieldLines, options: TraceOptions = {}): FieldLines {
  const perUC = options.linesPerMicrocoulomb ?? 8,
    ds = options.stepLength ?? 0.05,
    radius = options.radius ?? 0.18;
  const maxSteps = Math.min(options.maxSteps ?? 700, out.xy.length / 2 / (MAX_CHARGES * 32) - 1);
  const P = world.components.Position,
    Q = world.components.Charge.value;
  const charges = h.charges;
  const xy = out.xy,
    start = out.start;
  let line = 0,
    point = 0;
  const margin = 0.05;
  // Direction of the (normalised) field at (x, y) times sign, into dir[0], dir[1]; false where E = 0.
  const dir = [0, 0];
  const direction = (x: number, y: number, sign: number): boolean => {
    fieldAt(world, charges, x, y);
    const n = Math.hypot(ex[0]!, ey[0]!);
    if (!(n > 0)) return false;
    dir[0] = (sign * ex[0]!) / n;
    dir[1] = (sign * ey[0]!) / n;
    return true;
  };
  for (const pass of [1, -1]) {
    for (const c of charges) {
      const q = Q[slotOf(c)]! / MICRO;
      if (Math.sign(q) !== pass) continue;
      const n = Math.max(4, Math.min(32, Math.round(perUC * Math.abs(q))));
      for (let k = 0; k < n; k++) {
        if (line >= start.length - 1) break;
        const a = (2 * Math.PI * (k + 0.5)) / n;
        let x = P.x[slotOf(c)]! + radius * Math.cos(a),
          y = P.y[slotOf(c)]! + radius * Math.sin(a);
        const first = point;
        start[line] = first;
        xy[2 * point] = x;
        xy[2 * point + 1] = y;
        point++;
        let endedOnPositive = false;
        for (let s = 0; s < maxSteps; s++) {
          if (!direction(x, y, pass)) break;
          const k1x = dir[0]!,
            k1y = dir[1]!;
          if (!direction(x + 0.5 * ds * k1x, y + 0.5 * ds * k1y, pass)) break;
          const k2x = dir[0]!,
            k2y = dir[1]!;
          if (!direction(x + 0.5 * ds * k2x, y + 0.5 * ds * k2y, pass)) break;
          const k3x = dir[0]!,
            k3y = dir[1]!;
          if (!direction(x + ds * k3x, y + ds * k3y, pass)) break;
          x += (ds / 6) * (k1x + 2 * k2x + 2 * k3x + dir[0]!);
          y += (ds / 6) * (k1y + 2 * k2y + 2 * k3y + dir[1]!);
          xy[2 * point] = x;
          xy[2 * point + 1] = y;
          point++;
          if (x < BOX.minX - margin || x > BOX.maxX + margin || y < BOX.minY - margin || y > BOX.maxY + margin) break;
          let hit = 0;
          for (const o of charges) {
            if (o === c) continue;
            const dx = x - P.x[slotOf(o)]!,
              dy = y - P.y[slotOf(o)]!;
            if (dx * dx + dy * dy < radius * radius) {
              hit = o;
              break;
            }
          }
          if (hit !== 0) {
            endedOnPositive = Q[hit]! > 0;
            break;
          }
        }
        if (pass === -1 && endedOnPositive) {
          point = first;
          continue;
        }
        line++;
      }
    }
  }
  start[line] = point;
  out.count = line;
  return out;
}

/** Whether another fixed charge fits (MAX_CHARGES and the world's capacity). */
export function hasRoom(world: PhysicsWorld, h: ElectricHandles): boolean {
  return h.charges.length < MAX_CHARGES && world.entityIndex.aliveCount < world.capacity;
}
