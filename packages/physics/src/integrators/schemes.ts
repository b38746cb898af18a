import { rotateFrom, rotateVector } from '../math/quaternion.js';
import type { PhysicsWorld, System } from '../world/options.js';
import { advanceKinematic } from './semi-implicit-euler.js';
import * as IS from './state.js';

/**
 * The explicit and multi-stage integration schemes. Each advances every moving body by h from the
 * state in the component arrays, whose forces the pipeline has just evaluated (stages 2 and 3);
 * schemes that need forces at other states write those trial states into the arrays and call
 * `evaluateForces` again (Ramtal and Dobre ch. 14; Hairer, Norsett and Wanner, Solving Ordinary
 * Differential Equations I, ch. II). Every scheme also turns bodies with angular velocity the same
 * way, and moves kinematic bodies with their own velocity once per step (force laws see kinematic
 * bodies where they were at the start of the step during trial stages).
 */

function begin(world: PhysicsWorld): IS.IntegratorScratch {
  const s = IS.getScratch(world);
  s.bodyFrameSpin = true;
  IS.gather(world, s);
  IS.saveState(world, s);
  return s;
}

function end(world: PhysicsWorld, s: IS.IntegratorScratch, h: number): void {
  IS.checkFinite(world, s);
  advanceKinematic(world, h);
}

/**
 * Explicit (forward) Euler: x(t+h) = x + v h, v(t+h) = v + a(x, v, t) h. First order; not
 * symplectic: orbits spiral outward and undamped oscillators gain energy every step. The world's
 * constant gravity is integrated exactly (x gains g h^2 / 2 more, see `shiftByGravity`), so free
 * flight follows the exact parabola. Source: Ramtal and Dobre ch. 14.
 * @category Integrators
 */
export function explicitEuler(world: PhysicsWorld, h: number): void {
  const s = begin(world);
  IS.stageSlopes(world, s, world.time, false);
  IS.writeTrial(world, s, h, s.kv, h, s.acc, h, s.kq, h, s.alpha);
  IS.shiftByGravity(world, s, 0.5 * h * h);
  end(world, s, h);
}

/**
 * Heun's method (explicit trapezoidal rule, the RK2 of Ramtal and Dobre ch. 14): an Euler predictor,
 * then the average of the slopes at the start and at the predicted end. Second order.
 * @category Integrators
 */
export function rk2(world: PhysicsWorld, h: number): void {
  const s = begin(world);
  const t = world.time;
  IS.stageSlopes(world, s, t, false);
  IS.accumulate(world, s, 0.5, true);
  IS.writeTrial(world, s, h, s.kv, h, s.acc, h, s.kq, h, s.alpha);
  IS.stageSlopes(world, s, t + h, true);
  IS.accumulate(world, s, 0.5, false);
  const [sx, sv, sq, sw] = IS.sumGroups(s);
  IS.writeTrial(world, s, h, sx, h, sv, h, sq, h, sw);
  end(world, s, h);
}

/**
 * The classical fourth-order Runge-Kutta method: slopes at the start, twice at the midpoint and at
 * the end, weighted 1/6, 2/6, 2/6, 1/6. Fourth order; four force evaluations a step.
 * Source: Ramtal and Dobre ch. 14; Hairer, Norsett and Wanner, table II.1.1.
 * @category Integrators
 */
export function rk4(world: PhysicsWorld, h: number): void {
  const s = begin(world);
  const t = world.time;
  IS.stageSlopes(world, s, t, false);
  IS.accumulate(world, s, 1 / 6, true);
  IS.writeTrial(world, s, h / 2, s.kv, h / 2, s.acc, h / 2, s.kq, h / 2, s.alpha);
  IS.stageSlopes(world, s, t + h / 2, true);
  IS.accumulate(world, s, 2 / 6, false);
  IS.writeTrial(world, s, h / 2, s.kv, h / 2, s.acc, h / 2, s.kq, h / 2, s.alpha);
  IS.stageSlopes(world, s, t + h / 2, true);
  IS.accumulate(world, s, 2 / 6, false);
  IS.writeTrial(world, s, h, s.kv, h, s.acc, h, s.kq, h, s.alpha);
  IS.stageSlopes(world, s, t + h, true);
  IS.accumulate(world, s, 1 / 6, false);
  const [sx, sv, sq, sw] = IS.sumGroups(s);
  IS.writeTrial(world, s, h, sx, h, sv, h, sq, h, sw);
  end(world, s, h);
}

/**
 * Whether any force law of the world may depend on velocity. A system declares itself
 * position-only with `system.velocityDependent = false`; anything undeclared is assumed to depend
 * on velocity.
 * @category Integrators
 */
function hasVelocityDependentForces(world: PhysicsWorld): boolean {
  const list = world.stages.forces;
  for (let i = 0; i < list.length; i++) {
    if ((list[i] as System & { velocityDependent?: boolean }).velocityDependent !== false) return true;
  }
  return false;
}

/**
 * Position Verlet in its drift-kick-drift form (Stormer-Verlet with positions at the half step;
 * Hairer, Lubich and Wanner, Geometric Numerical Integration, ch. I.3): x_{1/2} = x + v h/2,
 * v(t+h) = v + a(x_{1/2}) h, x(t+h) = x_{1/2} + v(t+h) h/2. Second order, symplectic, one force
 * evaluation a step for position-only forces; equivalent to x_{n+1} = 2 x_n - x_{n-1} + a h^2 of
 * Ramtal and Dobre ch. 14 but carrying v, so collisions can change it.
 *
 * Velocity-dependent forces (drag, Lorentz, damping): the force at the half step needs v(t+h/2),
 * which is not known yet. The scheme evaluates a(x_{1/2}, v), predicts v(t+h/2) = v + a h/2 and
 * evaluates again there, which keeps second order (the error of the prediction enters a at O(h^2)).
 * @category Integrators
 */
export function positionVerlet(world: PhysicsWorld, h: number): void {
  const s = begin(world);
  const t = world.time;
  const c = world.components;
  IS.stageSlopes(world, s, t, false);
  // Drift half a step with the start velocity.
  IS.writeTrial(world, s, h / 2, s.kv, 0, s.acc, h / 2, s.kq, 0, s.alpha);
  IS.accelerationsAt(world, s, t + h / 2);
  if (hasVelocityDependentForces(world)) {
    IS.writeTrial(world, s, h / 2, s.kv, h / 2, s.acc, h / 2, s.kq, h / 2, s.alpha);
    IS.accelerationsAt(world, s, t + h / 2);
  }
  // Kick, then drift the second half with the new velocity: x = x0 + h/2 (v0 + v1).
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const [x0, y0, z0, u0, v0, w0] = s.x0 as [Float64Array, Float64Array, Float64Array, Float64Array, Float64Array, Float64Array];
  const [ax, ay, az] = s.acc as [Float64Array, Float64Array, Float64Array];
  const m = s.movers;
  for (let i = 0; i < s.nMovers; i++) {
    const e = m[i]!;
    const nx = u0[e]! + h * ax[e]!,
      ny = v0[e]! + h * ay[e]!,
      nz = w0[e]! + h * az[e]!;
    vx[e] = nx;
    vy[e] = ny;
    vz[e] = nz;
    px[e] = x0[e]! + 0.5 * h * (u0[e]! + nx);
    py[e] = y0[e]! + 0.5 * h * (v0[e]! + ny);
    pz[e] = z0[e]! + 0.5 * h * (w0[e]! + nz);
  }
  spinHalfKickHalf(world, s, h, 'dkd');
  end(world, s, h);
}

/**
 * Velocity Verlet (kick-drift-kick; Swope, Andersen, Berens and Wilson, J. Chem. Phys. 76, 1982):
 * v_{1/2} = v + a h/2, x(t+h) = x + v_{1/2} h, v(t+h) = v_{1/2} + a(x(t+h)) h/2. Second order,
 * symplectic, one new force evaluation a step.
 *
 * Velocity-dependent forces: a(t+h) is evaluated with the predicted velocity v + a h (written into
 * the velocity array while the force laws run), the usual treatment for drag in molecular dynamics
 * (Allen and Tildesley, Computer Simulation of Liquids, 2nd ed., sec. 3.2); second order is kept.
 * @category Integrators
 */
export function velocityVerlet(world: PhysicsWorld, h: number): void {
  const s = begin(world);
  const t = world.time;
  const c = world.components;
  IS.stageSlopes(world, s, t, false);
  // Keep a(t) in the sum arrays: acc is overwritten by the next evaluation.
  IS.accumulate(world, s, 1, true);
  // Drift with the half-kicked velocity; predicted end velocity for velocity-dependent laws.
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const [x0, y0, z0, u0, v0, w0] = s.x0 as [Float64Array, Float64Array, Float64Array, Float64Array, Float64Array, Float64Array];
  const S = s.sum;
  const a0x = S[3]!,
    a0y = S[4]!,
    a0z = S[5]!;
  const m = s.movers;
  for (let i = 0; i < s.nMovers; i++) {
    const e = m[i]!;
    px[e] = x0[e]! + h * (u0[e]! + 0.5 * h * a0x[e]!);
    py[e] = y0[e]! + h * (v0[e]! + 0.5 * h * a0y[e]!);
    pz[e] = z0[e]! + h * (w0[e]! + 0.5 * h * a0z[e]!);
    vx[e] = u0[e]! + h * a0x[e]!;
    vy[e] = v0[e]! + h * a0y[e]!;
    vz[e] = w0[e]! + h * a0z[e]!;
  }
  spinHalfKickHalf(world, s, h, 'kdk-drift');
  IS.accelerationsAt(world, s, t + h);
  const [ax, ay, az] = s.acc as [Float64Array, Float64Array, Float64Array];
  for (let i = 0; i < s.nMovers; i++) {
    const e = m[i]!;
    vx[e] = u0[e]! + 0.5 * h * (a0x[e]! + ax[e]!);
    vy[e] = v0[e]! + 0.5 * h * (a0y[e]! + ay[e]!);
    vz[e] = w0[e]! + 0.5 * h * (a0z[e]! + az[e]!);
  }
  spinHalfKickHalf(world, s, h, 'kdk-kick');
  end(world, s, h);
}

/**
 * The angular half of the Verlet schemes.
 * - 'dkd': after the kick alpha (in s.alpha, at the half step): w1 = w0 + h alpha, orientation
 *   advanced by h (w0 + w1) / 2 from the start.
 * - 'kdk-drift': w_{1/2} = w0 + alpha0 h/2 (alpha0 in the sums), orientation advanced by h w_{1/2};
 *   w set to the predicted w0 + alpha0 h for the force evaluation.
 * - 'kdk-kick': w1 = w_{1/2} + alpha1 h/2.
 * The orientation update rotates by the given rotation vector exactly (unit quaternions stay unit).
 */
function spinHalfKickHalf(world: PhysicsWorld, s: IS.IntegratorScratch, h: number, phase: 'dkd' | 'kdk-drift' | 'kdk-kick'): void {
  if (s.nSpinners === 0) return;
  const c = world.components;
  const { x: wx, y: wy, z: wz } = c.AngularVelocity;
  const [qa, qb, qc, qd] = s.q0 as [Float64Array, Float64Array, Float64Array, Float64Array];
  const [wa, wb, wc] = s.w0 as [Float64Array, Float64Array, Float64Array];
  const [bx, by, bz] = s.alpha as [Float64Array, Float64Array, Float64Array];
  const S = s.sum;
  const s0x = S[10]!,
    s0y = S[11]!,
    s0z = S[12]!;
  const is2D = world.dimensions === 2;
  const ang = c.Angle.value,
    q = c.Orientation;
  const [ba, bb, bc] = s.wb0 as [Float64Array, Float64Array, Float64Array];
  const sp = s.spinners,
    torqued = s.torqued;
  for (let i = 0; i < s.nSpinners; i++) {
    const e = sp[i]!;
    if (!is2D && torqued[e] === 2) {
      spinBodyFrame(q, wx, wy, wz, s, e, h, phase, ba[e]!, bb[e]!, bc[e]!);
      continue;
    }
    let rx: number, ry: number, rz: number;
    if (phase === 'dkd') {
      const nx = wa[e]! + h * bx[e]!,
        ny = wb[e]! + h * by[e]!,
        nz = wc[e]! + h * bz[e]!;
      rx = 0.5 * h * (wa[e]! + nx);
      ry = 0.5 * h * (wb[e]! + ny);
      rz = 0.5 * h * (wc[e]! + nz);
      wx[e] = nx;
      wy[e] = ny;
      wz[e] = nz;
    } else if (phase === 'kdk-drift') {
      rx = h * (wa[e]! + 0.5 * h * s0x[e]!);
      ry = h * (wb[e]! + 0.5 * h * s0y[e]!);
      rz = h * (wc[e]! + 0.5 * h * s0z[e]!);
      wx[e] = wa[e]! + h * s0x[e]!;
      wy[e] = wb[e]! + h * s0y[e]!;
      wz[e] = wc[e]! + h * s0z[e]!;
    } else {
      wx[e] = wa[e]! + 0.5 * h * (s0x[e]! + bx[e]!);
      wy[e] = wb[e]! + 0.5 * h * (s0y[e]! + by[e]!);
      wz[e] = wc[e]! + 0.5 * h * (s0z[e]! + bz[e]!);
      continue;
    }
    if (is2D) {
      ang[e] = qa[e]! + rz;
      continue;
    }
    rotateFrom(q.x, q.y, q.z, q.w, e, qa[e]!, qb[e]!, qc[e]!, qd[e]!, rx, ry, rz);
  }
}

const rb = new Float64Array(3),
  wOut = new Float64Array(3);

/**
 * `spinHalfKickHalf` for a body with a principal inertia tensor, staged in the body frame (see
 * integrators/state.ts): w_b0 = (b0x, b0y, b0z), alpha_b in s.alpha and alpha_b0 in the sums are
 * body-frame; a body-frame rotation vector r_b turns q0 into q0 exp(r_b) = exp(R(q0) r_b) q0, and the
 * world w written back is R(q) w_b with the new orientation q.
 */
function spinBodyFrame(
  q: { x: Float64Array; y: Float64Array; z: Float64Array; w: Float64Array },
  wx: Float64Array,
  wy: Float64Array,
  wz: Float64Array,
  s: IS.IntegratorScratch,
  e: number,
  h: number,
  phase: 'dkd' | 'kdk-drift' | 'kdk-kick',
  b0x: number,
  b0y: number,
  b0z: number,
): void {
  const [qa, qb, qc, qd] = s.q0 as [Float64Array, Float64Array, Float64Array, Float64Array];
  const [bx, by, bz] = s.alpha as [Float64Array, Float64Array, Float64Array];
  const S = s.sum;
  const a0x = S[10]![e]!,
    a0y = S[11]![e]!,
    a0z = S[12]![e]!;
  let nx: number, ny: number, nz: number;
  if (phase === 'kdk-kick') {
    nx = b0x + 0.5 * h * (a0x + bx[e]!);
    ny = b0y + 0.5 * h * (a0y + by[e]!);
    nz = b0z + 0.5 * h * (a0z + bz[e]!);
  } else {
    let rx: number, ry: number, rz: number;
    if (phase === 'dkd') {
      nx = b0x + h * bx[e]!;
      ny = b0y + h * by[e]!;
      nz = b0z + h * bz[e]!;
      rx = 0.5 * h * (b0x + nx);
      ry = 0.5 * h * (b0y + ny);
      rz = 0.5 * h * (b0z + nz);
    } else {
      rx = h * (b0x + 0.5 * h * a0x);
      ry = h * (b0y + 0.5 * h * a0y);
      rz = h * (b0z + 0.5 * h * a0z);
      nx = b0x + h * a0x;
      ny = b0y + h * a0y;
      nz = b0z + h * a0z;
    }
    const x0 = qa[e]!,
      y0 = qb[e]!,
      z0 = qc[e]!,
      w0 = qd[e]!;
    rotateVector(x0, y0, z0, w0, rx, ry, rz, rb);
    rotateFrom(q.x, q.y, q.z, q.w, e, x0, y0, z0, w0, rb[0]!, rb[1]!, rb[2]!);
  }
  rotateVector(q.x[e]!, q.y[e]!, q.z[e]!, q.w[e]!, nx, ny, nz, wOut);
  wx[e] = wOut[0]!;
  wy[e] = wOut[1]!;
  wz[e] = wOut[2]!;
}
