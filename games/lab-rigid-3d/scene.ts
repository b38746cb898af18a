/**
 * Lab: 3D rigid bodies. Five seeded scenes on the physics' 3D shapes and joints, pure builders (no DOM,
 * no three.js) shared by the page and its tests:
 * - `tumble`: a box thrown spinning onto a table (a static compound of a top and four legs);
 * - `stack`: a tower of ten 0.5 m boxes;
 * - `dominoes`: a ring of dominoes (100 by default), the first one pushed;
 * - `top`: a symmetric top (a disc on a capsule stem) spinning fast, standing free on the floor on its
 *   tip (the stem's rounded lower end, a 1.5 cm ball; no joint): it precesses at about
 *   Omega = m g r / (I3 omega3) (the gyroscope limit of Euler's equations for a fast top; e.g.
 *   Goldstein, Classical Mechanics, 3rd ed., sec. 5.7; Kleppner and Kolenkow, An Introduction to
 *   Mechanics, ch. 7), r the distance from the tip ball's centre to the centre of mass (on a smooth
 *   floor the normal force passes through that centre), I3 the moment about the symmetry axis,
 *   omega3 the spin. The tip's friction (`tipFriction`, default 0: a polished tip on a smooth table)
 *   decides how it moves: without friction the centre of mass stays on its vertical line and the tip
 *   circles; with friction the rounded tip rolls, the top wanders and precesses a little slower
 *   (measured: 5 to 7 % below the formula at tipFriction 0.6);
 * - `ragdoll`: a ragdoll of eleven capsules on ball-and-socket joints with swing cones (shoulders, hips,
 *   neck) and hinges with limits (elbows, knees), dropped onto a flight of steps.
 */
import {
  addBallJoint3D,
  addBody,
  addHingeJoint3D,
  addPlane,
  addShape3D,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  setAngularVelocity,
  setVelocity,
} from '@bitphysics/physics';

/** The scenes. */
export const SCENES = ['tumble', 'stack', 'dominoes', 'top', 'ragdoll'] as const;
/** One of `SCENES`. */
export type SceneName = (typeof SCENES)[number];

/** Options of `buildLab`. */
export interface LabOptions {
  /** Dominoes in the ring, integer in [2, 400]. Default 100. */
  dominoes?: number;
  /** The top's spin about its axis, rad/s, > 0. Default 60. */
  spin?: number;
  /** The top's tilt from the vertical, rad, in (0, 1.4]. Default 0.35. */
  tilt?: number;
  /**
   * Friction of the top's stem and tip, >= 0 (combined with the floor's by the geometric mean, so 0
   * makes the tip's contact smooth). Default 0.
   */
  tipFriction?: number;
  /** Friction of every shape, >= 0. Default 0.6. */
  friction?: number;
}

/** What `buildLab` returns. */
export interface LabHandles {
  scene: SceneName;
  /** Every dynamic body of the scene. */
  bodies: number[];
  /** The static bodies (the table, the steps). */
  statics: number[];
  /** tumble: the thrown box; stack: the top box; dominoes: the first; top: the top; ragdoll: the pelvis. */
  main: number;
  /** stack: the boxes bottom up; dominoes: the dominoes in order; ragdoll: its parts. */
  parts: number[];
  /** dominoes: each domino's start heading (rad, about y). */
  headings: number[];
  /** dominoes: the body axis (0 x, 1 y, 2 z of its principal frame) that stood up at the start. */
  upAxes: number[];
  /**
   * top: the tip ball's centre at the start (m), mass (kg), r (tip ball's centre to centre of mass, m),
   * rho (the tip ball's radius, m), I3 and I1 (about the symmetry axis, and across it about the centre
   * of mass, kg m^2), spin omega3 (the angular velocity's component along the axis, rad/s), tilt (rad),
   * tipFriction, `precession` = m g r / (I3 omega3) (the gyroscope formula, rad/s) and
   * `steadyPrecession`, the slow root of m g r = Omega (I3 omega3 - I1 Omega cos tilt) (steady
   * precession of a heavy symmetric top, Goldstein sec. 5.7; for a top free on a smooth floor I1 is
   * the moment about the centre of mass, which stays on its vertical line), which the gyroscope
   * formula approximates to first order in I1 cos(tilt) m g r / (I3 omega3)^2.
   */
  top: {
    tip: [number, number, number];
    mass: number;
    r: number;
    rho: number;
    I3: number;
    I1: number;
    spin: number;
    tilt: number;
    tipFriction: number;
    precession: number;
    steadyPrecession: number;
  } | null;
}

/**
 * World options: 3D, Earth gravity, room for the scenes; 4 substeps, 16 for the top (its single body
 * is cheap, and the top gains tilt at a rate first order in the substep: at 16 about 1.3 degrees a
 * second).
 */
export function labWorldOptions(scene: SceneName = 'stack'): PhysicsWorldOptions {
  return { dimensions: 3, capacity: 1024, gravity: [0, -9.81, 0], substeps: scene === 'top' ? 16 : 4 };
}

/** Builds `scene` into `world` (with a floor at y = 0). @throws RangeError on an unknown scene or an option out of range. */
export function buildLab(world: PhysicsWorld, scene: SceneName, options: LabOptions = {}): LabHandles {
  if (!SCENES.includes(scene)) throw new RangeError(`buildLab: scene must be one of ${SCENES.join(', ')}, got ${String(scene)}`);
  const n = options.dominoes ?? 100,
    spin = options.spin ?? 60,
    tilt = options.tilt ?? 0.35,
    mu = options.friction ?? 0.6;
  const tipMu = options.tipFriction ?? 0;
  if (!Number.isInteger(n) || n < 2 || n > 400) throw new RangeError(`buildLab: dominoes must be an integer in [2, 400], got ${n}`);
  if (!(spin > 0 && Number.isFinite(spin))) throw new RangeError(`buildLab: spin must be > 0, got ${spin}`);
  if (!(tilt > 0 && tilt <= 1.4)) throw new RangeError(`buildLab: tilt must be in (0, 1.4], got ${tilt}`);
  if (!(mu >= 0 && Number.isFinite(mu))) throw new RangeError(`buildLab: friction must be >= 0, got ${mu}`);
  if (!(tipMu >= 0 && Number.isFinite(tipMu))) throw new RangeError(`buildLab: tipFriction must be >= 0, got ${tipMu}`);
  addPlane(world, { normal: [0, 1, 0], point: [0, 0, 0], friction: mu });
  const h: LabHandles = { scene, bodies: [], statics: [], main: 0, parts: [], headings: [], upAxes: [], top: null };
  switch (scene) {
    case 'tumble':
      tumble(world, h, mu);
      break;
    case 'stack':
      stack(world, h, mu);
      break;
    case 'dominoes':
      dominoes(world, h, n, mu);
      break;
    case 'top':
      top(world, h, spin, tilt, tipMu, mu);
      break;
    case 'ragdoll':
      ragdoll(world, h, mu);
      break;
  }
  return h;
}

function box(
  world: PhysicsWorld,
  p: [number, number, number],
  half: [number, number, number],
  mu: number,
  q: [number, number, number, number] = [0, 0, 0, 1],
  density = 600,
): number {
  const e = addBody(world, { position: p, orientation: q });
  addShape3D(world, e, { type: 'box', halfExtents: half, density, friction: mu, restitution: 0.1 });
  return e;
}

function yaw(a: number): [number, number, number, number] {
  return [0, Math.sin(a / 2), 0, Math.cos(a / 2)];
}

/** A static table (1.6 x 1 m top at 0.8 m, four legs) and a 0.3 m box thrown onto it spinning. */
function tumble(world: PhysicsWorld, h: LabHandles, mu: number): void {
  const table = addBody(world, { position: [0, 0.8, 0], static: true });
  h.statics.push(table);
  addShape3D(world, table, { type: 'box', halfExtents: [0.8, 0.04, 0.5], friction: mu });
  for (const [x, z] of [
    [-0.7, -0.4],
    [0.7, -0.4],
    [-0.7, 0.4],
    [0.7, 0.4],
  ] as const) {
    addShape3D(world, table, { type: 'box', halfExtents: [0.04, 0.38, 0.04], offset: [x, -0.42, z], friction: mu });
  }
  const b = box(world, [-1.2, 1.6, 0], [0.15, 0.15, 0.15], mu, [0.2, 0.3, 0.1, 0.93]);
  setVelocity(world, b, [2.2, 0.5, 0.1]);
  setAngularVelocity(world, b, [3, -6, 8]);
  h.main = b;
  h.bodies.push(b);
  h.parts.push(b);
}

/** Ten 0.5 m boxes stacked, each turned a little. */
function stack(world: PhysicsWorld, h: LabHandles, mu: number): void {
  for (let i = 0; i < 10; i++) {
    const b = box(world, [0, 0.25 + 0.5 * i, 0], [0.25, 0.25, 0.25], mu, yaw(0.1 * ((i * 7) % 5)));
    h.bodies.push(b);
    h.parts.push(b);
  }
  h.main = h.parts[h.parts.length - 1]!;
}

/** Domino size (half extents: thickness, height, width), m, and spacing along the ring, m. */
export const DOMINO_HALF: readonly [number, number, number] = [0.04, 0.25, 0.12];
export const DOMINO_SPACING = 0.22;

/** A ring of n dominoes (0.08 x 0.5 x 0.24 m, 0.22 m apart) standing on the floor, the first one pushed. */
function dominoes(world: PhysicsWorld, h: LabHandles, n: number, mu: number): void {
  // Around 0.92 of a circle, so the last does not fall onto the first.
  const R = (n * DOMINO_SPACING) / (2 * Math.PI * 0.92);
  for (let i = 0; i < n; i++) {
    const a = (i * DOMINO_SPACING) / R;
    // Tangent direction (the way the wave runs): d/da of (R cos a, -R sin a) is (-sin a, -cos a); the domino's thin x axis along it.
    const heading = Math.atan2(Math.cos(a), -Math.sin(a)); // rotation about y taking +x to the tangent
    const d = box(world, [R * Math.cos(a), DOMINO_HALF[1], -R * Math.sin(a)], [...DOMINO_HALF], mu, yaw(heading), 700);
    let up = 0;
    for (let k = 1; k < 3; k++) if (Math.abs(upComponent(world, d, k)) > Math.abs(upComponent(world, d, up))) up = k;
    h.bodies.push(d);
    h.parts.push(d);
    h.headings.push(heading);
    h.upAxes.push(up);
  }
  h.main = h.parts[0]!;
  // The push: the first domino's top moves along the ring at 0.8 m/s (an angular velocity about its base edge's axis).
  const first = h.parts[0]!,
    a = h.headings[0]!;
  const tx = Math.cos(a),
    tz = -Math.sin(a);
  // Pivoting about its base edge, omega = k (y x t) moves the top along t at k h (Euler: v = omega x r).
  setAngularVelocity(world, first, [1.6 * tz, 0, -1.6 * tx]);
  setVelocity(world, first, [tx * 0.4, 0, tz * 0.4]);
}

/** Radius of the top's stem and of the ball that ends it, its tip, m. */
export const TOP_TIP_RADIUS = 0.015;

/**
 * A top: a disc (r 0.25 m, 4 cm thick, 0.25 m up the axis) on a capsule stem (r 1.5 cm, 0.4 m between
 * its end centres), of aluminium (2,700 kg/m^3), standing on its tip (the stem's lower end) on the floor.
 * Tip radius: the rate does not depend on it. On a smooth floor over the first second the top
 * precesses within 0.1 % of the steady root on a 5 mm, 1 cm or 1.5 cm tip at these 16 substeps
 * (test/physics/top-small-tip.test.ts; at one substep a step this top tilts over within a second
 * whatever its tip).
 * 1.5 cm is kept for what the tip's friction shows: a rolling
 * tip moves at about its radius times the spin, so at tipFriction 0.6 a 1.5 cm tip wanders 17 cm in
 * the first second and precesses 5 % below m g r / (I3 omega3), while a 5 mm one wanders 1.4 cm and
 * precesses 1.1 % above it, as on a smooth floor (nearly a fixed pivot); and a 3 cm stem is visible
 * at the lab's zoom.
 */
function top(world: PhysicsWorld, h: LabHandles, spin: number, tilt: number, tipMu: number, mu: number): void {
  const rho = TOP_TIP_RADIUS;
  // The tip ball's centre, the body's frame origin: the ball touches the floor.
  const tip: [number, number, number] = [0, rho, 0];
  // The symmetry axis tilted by `tilt` toward +x: q about z by -tilt.
  const q: [number, number, number, number] = [0, 0, Math.sin(-tilt / 2), Math.cos(-tilt / 2)];
  const b = addBody(world, { position: tip, orientation: q });
  addShape3D(world, b, { type: 'capsule', radius: rho, halfHeight: 0.2, offset: [0, 0.2, 0], density: 2700, friction: tipMu });
  addShape3D(world, b, { type: 'cylinder', radius: 0.25, halfHeight: 0.02, offset: [0, 0.25, 0], density: 2700, friction: mu });
  const c = world.components;
  const mass = c.Mass.value[b]!;
  const dx = c.Position.x[b]! - tip[0],
    dy = c.Position.y[b]! - tip[1],
    dz = c.Position.z[b]! - tip[2];
  const r = Math.hypot(dx, dy, dz);
  // The symmetric top's principal moments about its centre of mass: two equal (across) and I3 (about the symmetry axis), the one that differs.
  const T = c.InertiaTensor;
  const I = [T.x[b]!, T.y[b]!, T.z[b]!].sort((u, v) => u - v);
  const firstOdd = Math.abs(I[0]! - I[1]!) > Math.abs(I[1]! - I[2]!);
  const I3 = firstOdd ? I[0]! : I[2]!,
    I1 = firstOdd ? I[2]! : I[0]!; // across, about the centre of mass (it stays put on a smooth floor)
  const g = Math.abs(world.gravity[1]!),
    L = I3 * spin,
    cos = Math.cos(tilt),
    torque = mass * g * r;
  const precession = torque / L;
  const steadyPrecession = (L - Math.sqrt(L * L - 4 * I1 * cos * torque)) / (2 * I1 * cos);
  // Spin omega3 along the symmetry axis (world: y tilted toward +x) and the steady precession about +y,
  // so it starts without nutation: omega = (omega3 - Omega cos tilt) axis + Omega y.
  const ax = Math.sin(tilt),
    ay = cos,
    s = spin - steadyPrecession * cos;
  setAngularVelocity(world, b, [s * ax, s * ay + steadyPrecession, 0]);
  h.main = b;
  h.bodies.push(b);
  h.parts.push(b);
  h.top = { tip, mass, r, rho, I3, I1, spin, tilt, tipFriction: tipMu, precession, steadyPrecession };
}

/** A flight of five static steps and a ragdoll of eleven capsules above the top one. */
function ragdoll(world: PhysicsWorld, h: LabHandles, mu: number): void {
  // Step i runs from x = 0.5 i - 0.25 back to x = 3 and is 0.3 (i + 1) m high.
  for (let i = 0; i < 5; i++) {
    const x1 = 0.5 * i - 0.25,
      x2 = 3,
      top = 0.3 * (i + 1);
    const s = addBody(world, { position: [(x1 + x2) / 2, top / 2, 0], static: true });
    h.statics.push(s);
    addShape3D(world, s, { type: 'box', halfExtents: [(x2 - x1) / 2, top / 2, 1], friction: mu });
  }
  const x0 = 2.5,
    y0 = 2.6;
  const part = (p: [number, number, number], r: number, hh: number, horizontal = false): number => {
    const e = addBody(world, { position: p, orientation: horizontal ? [Math.SQRT1_2, 0, 0, Math.SQRT1_2] : [0, 0, 0, 1] });
    addShape3D(world, e, { type: 'capsule', radius: r, halfHeight: hh, density: 1000, friction: mu });
    h.bodies.push(e);
    h.parts.push(e);
    return e;
  };
  const pelvis = part([x0, y0, 0], 0.12, 0.1, true);
  const chest = part([x0, y0 + 0.4, 0], 0.14, 0.12, true);
  const head = part([x0, y0 + 0.78, 0], 0.11, 0.02);
  const upperArmL = part([x0, y0 + 0.4, -0.42], 0.05, 0.12, false);
  const upperArmR = part([x0, y0 + 0.4, 0.42], 0.05, 0.12, false);
  const foreArmL = part([x0, y0 + 0.06, -0.42], 0.045, 0.11);
  const foreArmR = part([x0, y0 + 0.06, 0.42], 0.045, 0.11);
  const thighL = part([x0, y0 - 0.4, -0.12], 0.07, 0.15);
  const thighR = part([x0, y0 - 0.4, 0.12], 0.07, 0.15);
  const shinL = part([x0, y0 - 0.86, -0.12], 0.06, 0.15);
  const shinR = part([x0, y0 - 0.86, 0.12], 0.06, 0.15);
  const cone = (a: number, b: number, at: [number, number, number], angle: number): number =>
    addBallJoint3D(world, { a, b, anchor: at, axis: [0, -1, 0], coneAngle: angle });
  cone(pelvis, chest, [x0, y0 + 0.2, 0], 0.5);
  cone(chest, head, [x0, y0 + 0.62, 0], 0.6);
  cone(chest, upperArmL, [x0, y0 + 0.56, -0.42], 1.8);
  cone(chest, upperArmR, [x0, y0 + 0.56, 0.42], 1.8);
  addHingeJoint3D(world, { a: upperArmL, b: foreArmL, anchor: [x0, y0 + 0.23, -0.42], axis: [0, 0, 1], lower: -2.4, upper: 0 });
  addHingeJoint3D(world, { a: upperArmR, b: foreArmR, anchor: [x0, y0 + 0.23, 0.42], axis: [0, 0, 1], lower: -2.4, upper: 0 });
  cone(pelvis, thighL, [x0, y0 - 0.2, -0.12], 1.2);
  cone(pelvis, thighR, [x0, y0 - 0.2, 0.12], 1.2);
  addHingeJoint3D(world, { a: thighL, b: shinL, anchor: [x0, y0 - 0.63, -0.12], axis: [0, 0, 1], lower: 0, upper: 2.4 });
  addHingeJoint3D(world, { a: thighR, b: shinR, anchor: [x0, y0 - 0.63, 0.12], axis: [0, 0, 1], lower: 0, upper: 2.4 });
  // A shove toward the edge of the landing: it tumbles down the steps.
  setVelocity(world, pelvis, [-3, 1, 0.3]);
  setVelocity(world, chest, [-3.5, 1, 0.3]);
  h.main = pelvis;
}

/** Tilt from the vertical past which a domino counts as toppled, rad (a domino leaning on the next, 0.22 m on at 0.5 m high, leans 26 degrees). */
export const TOPPLED_TILT = (20 * Math.PI) / 180;

/** The y component of body axis `axis` (0 x, 1 y, 2 z) in the world: row y of its rotation matrix. */
export function upComponent(world: PhysicsWorld, e: number, axis: number): number {
  const O = world.components.Orientation;
  const x = O.x[e]!,
    y = O.y[e]!,
    z = O.z[e]!,
    w = O.w[e]!;
  return axis === 0 ? 2 * (x * y + w * z) : axis === 1 ? 1 - 2 * (x * x + z * z) : 2 * (y * z - w * x);
}

/** Whether domino i has toppled: the axis that stood up has tipped past TOPPLED_TILT. */
export function hasToppled(world: PhysicsWorld, h: LabHandles, i: number): boolean {
  return Math.abs(upComponent(world, h.parts[i]!, h.upAxes[i]!)) < Math.cos(TOPPLED_TILT);
}

/** How many dominoes have toppled. */
export function toppledCount(world: PhysicsWorld, h: LabHandles): number {
  let n = 0;
  for (let i = 0; i < h.parts.length; i++) if (hasToppled(world, h, i)) n++;
  return n;
}

/**
 * The top's symmetry axis (its body y axis) in the world frame, a unit vector, into `out` (length >= 3).
 * @returns out.
 */
export function topAxis(world: PhysicsWorld, h: LabHandles, out: number[] | Float64Array = [0, 0, 0]): number[] | Float64Array {
  const O = world.components.Orientation,
    b = h.main;
  const x = O.x[b]!,
    y = O.y[b]!,
    z = O.z[b]!,
    w = O.w[b]!;
  out[0] = 2 * (x * y - w * z);
  out[1] = 1 - 2 * (x * x + z * z);
  out[2] = 2 * (y * z + w * x);
  return out;
}

const axisScratch = [0, 0, 0];
/**
 * The top's precession angle: the heading (rad, about +y, unwrapped by the caller) of its symmetry
 * axis's horizontal projection (from the tip toward the disc). The tip of a free top moves, so the
 * heading is read from the body's orientation, not from a fixed point.
 */
export function topHeading(world: PhysicsWorld, h: LabHandles): number {
  const a = topAxis(world, h, axisScratch);
  return Math.atan2(-a[2]!, a[0]!);
}
