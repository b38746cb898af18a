import { hasComponent } from 'bitecs';
import { evaluateForces } from '../forces/evaluate.js';
import { rotateVector, rotateVectorInverse } from '../math/quaternion.js';
import { reportNonFinite } from '../world/errors.js';
import type { PhysicsWorld } from '../world/options.js';
import { eulerAcceleration, eulerBodyAcceleration, storeUnitQuaternion } from './euler-equations.js';
import { forcedBodies, freeBodies, spinningBodies } from './queries.js';

/**
 * Shared machinery of the multi-stage integrators: the list of moving bodies, a copy of the state at
 * the start of the step, accelerations at the current (trial) state, and helpers that write trial
 * states into the component arrays so that the force laws, which read those arrays, see them.
 *
 * The state of a body is (x, v) and, for bodies that turn, (angle or orientation, w). Accelerations:
 * a = F / m + g for bodies with a force accumulator, a = g for bare particles; angular
 * alpha = I^-1 (tau - w x I w) (see `angularAcceleration`).
 *
 * Bodies with a principal inertia tensor are staged in the body frame by the explicit schemes
 * (`bodyFrameSpin`): their stages carry the body-frame angular velocity w_b and its slope from
 * Euler's equations, and a trial state's world w is R(q) w_b with the trial orientation q. Staged in
 * the world frame instead, the stages' w and q drift apart: a torque-free body (moments 1, 2, 3)
 * spun at 2 rad/s about its intermediate axis flipped with a period 10.9 % short under RK2 and 5.9 %
 * long under velocity Verlet at dt 1/60; in the body frame both are within 0.1 %.
 * @category Integrators
 */
export interface IntegratorScratch {
  /** Entities the scratch is sized for (capacity + 1 slots). */
  readonly size: number;
  /** Moving bodies this step: forced bodies first (indices < nForced), then free particles. */
  movers: Int32Array;
  nMovers: number;
  nForced: number;
  /** Turning bodies this step, and 1 in `torqued` for those with a torque accumulator and inertia. */
  spinners: Int32Array;
  nSpinners: number;
  readonly torqued: Uint8Array;
  /** State at the start of the step, per entity: x, y, z, vx, vy, vz. */
  readonly x0: Float64Array[];
  /** Angular state at the start of the step: angle (2D) or quaternion x, y, z, w (3D); w x, y, z. */
  readonly q0: Float64Array[];
  readonly w0: Float64Array[];
  /** Body-frame angular velocity at the start of the step, x, y, z, rad/s (bodies with a principal inertia tensor). */
  readonly wb0: Float64Array[];
  /**
   * True while an explicit scheme runs: bodies with a principal inertia tensor (torqued kind 2) get a
   * body-frame angular acceleration in `alpha`, and trial states rotate w_b0 + c alpha into the world
   * frame with the trial orientation (see the interface's note). False (implicit Euler): world frame.
   */
  bodyFrameSpin: boolean;
  /** Accelerations at the current state: linear a x, y, z; angular alpha x, y, z. */
  readonly acc: Float64Array[];
  readonly alpha: Float64Array[];
  /** The current stage's position slope (the velocity) x, y, z and orientation slope (see `orientationSlope`). */
  readonly kv: Float64Array[];
  readonly kq: Float64Array[];
  /** Weighted sums of stage slopes (RK schemes): x-slope x, y, z; v-slope x, y, z; q-slope x, y, z, w; w-slope x, y, z. */
  readonly sum: Float64Array[];
}

const f = (n: number): Float64Array => new Float64Array(n);

/**
 * The world's integrator scratch, made on first use (only multi-stage schemes need it).
 * @category Integrators
 */
export function getScratch(world: PhysicsWorld): IntegratorScratch {
  const existing = (world as { integratorScratch?: IntegratorScratch }).integratorScratch;
  if (existing) return existing;
  const n = world.capacity + 1;
  const s: IntegratorScratch = {
    size: n,
    movers: new Int32Array(64),
    nMovers: 0,
    nForced: 0,
    spinners: new Int32Array(64),
    nSpinners: 0,
    torqued: new Uint8Array(n),
    x0: [f(n), f(n), f(n), f(n), f(n), f(n)],
    q0: [f(n), f(n), f(n), f(n)],
    w0: [f(n), f(n), f(n)],
    wb0: [f(n), f(n), f(n)],
    bodyFrameSpin: false,
    acc: [f(n), f(n), f(n)],
    alpha: [f(n), f(n), f(n)],
    kv: [f(n), f(n), f(n)],
    kq: [f(n), f(n), f(n), f(n)],
    sum: [f(n), f(n), f(n), f(n), f(n), f(n), f(n), f(n), f(n), f(n), f(n), f(n), f(n)],
  };
  (world as { integratorScratch?: IntegratorScratch }).integratorScratch = s;
  return s;
}

/**
 * Fills the movers and spinners lists for this step.
 * @category Integrators
 */
export function gather(world: PhysicsWorld, s: IntegratorScratch): void {
  const forced = forcedBodies(world);
  const free = freeBodies(world);
  const n = forced.length + free.length;
  if (s.movers.length < n) s.movers = new Int32Array(Math.max(n, s.movers.length * 2));
  const m = s.movers;
  for (let i = 0; i < forced.length; i++) m[i] = forced[i]!;
  for (let i = 0; i < free.length; i++) m[forced.length + i] = free[i]!;
  s.nMovers = n;
  s.nForced = forced.length;

  const c = world.components;
  const spin = spinningBodies(world);
  if (s.spinners.length < spin.length) s.spinners = new Int32Array(Math.max(spin.length, s.spinners.length * 2));
  let k = 0;
  for (let i = 0; i < spin.length; i++) {
    const e = spin[i]!;
    if (hasComponent(world, e, c.Kinematic)) continue;
    s.spinners[k++] = e;
    // 2: Euler's equations with a principal inertia tensor (gyroscopic term even without torque);
    // 1: scalar inertia under torque; 0: spins freely at constant w.
    s.torqued[e] =
      world.dimensions === 3 && hasComponent(world, e, c.InertiaTensor)
        ? 2
        : hasComponent(world, e, c.Torque) && hasComponent(world, e, c.Inertia) && c.Inertia.inv[e]! > 0
          ? 1
          : 0;
  }
  s.nSpinners = k;
}

/**
 * Copies the current state of every mover and spinner into x0 / q0 / w0, and (unless `setPrevious` is
 * false, for sub-steps within a step) records it as PreviousPosition.
 * @category Integrators
 */
export function saveState(world: PhysicsWorld, s: IntegratorScratch, setPrevious = true): void {
  const c = world.components;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const { x: ox, y: oy, z: oz } = c.PreviousPosition;
  const [x0, y0, z0, u0, v0, w0] = s.x0 as [Float64Array, Float64Array, Float64Array, Float64Array, Float64Array, Float64Array];
  const m = s.movers;
  for (let i = 0; i < s.nMovers; i++) {
    const e = m[i]!;
    x0[e] = px[e]!;
    y0[e] = py[e]!;
    z0[e] = pz[e]!;
    if (setPrevious) {
      ox[e] = px[e]!;
      oy[e] = py[e]!;
      oz[e] = pz[e]!;
    }
    u0[e] = vx[e]!;
    v0[e] = vy[e]!;
    w0[e] = vz[e]!;
  }
  const { x: wx, y: wy, z: wz } = c.AngularVelocity;
  const [qa, qb, qc, qd] = s.q0 as [Float64Array, Float64Array, Float64Array, Float64Array];
  const [wa, wb, wc] = s.w0 as [Float64Array, Float64Array, Float64Array];
  const [ba, bb, bc] = s.wb0 as [Float64Array, Float64Array, Float64Array];
  const sp = s.spinners,
    torqued = s.torqued;
  const is2D = world.dimensions === 2;
  const ang = c.Angle.value,
    q = c.Orientation;
  for (let i = 0; i < s.nSpinners; i++) {
    const e = sp[i]!;
    if (is2D) qa[e] = ang[e]!;
    else {
      qa[e] = q.x[e]!;
      qb[e] = q.y[e]!;
      qc[e] = q.z[e]!;
      qd[e] = q.w[e]!;
    }
    wa[e] = wx[e]!;
    wb[e] = wy[e]!;
    wc[e] = wz[e]!;
    if (torqued[e] === 2) {
      rotateVectorInverse(qa[e]!, qb[e]!, qc[e]!, qd[e]!, wa[e]!, wb[e]!, wc[e]!, vec);
      ba[e] = vec[0]!;
      bb[e] = vec[1]!;
      bc[e] = vec[2]!;
    }
  }
}

const vec = new Float64Array(3);

/**
 * Evaluates the force laws at the state now in the component arrays (at simulated time `time`) and
 * writes linear and angular accelerations into `acc` and `alpha`. The world's time is restored.
 * @category Integrators
 */
export function accelerationsAt(world: PhysicsWorld, s: IntegratorScratch, time: number): void {
  const saved = world.time;
  world.time = time;
  evaluateForces(world);
  world.time = saved;
  accelerations(world, s);
}

/**
 * Accelerations from the force and torque accumulators as they are (no force evaluation).
 * @category Integrators
 */
export function accelerations(world: PhysicsWorld, s: IntegratorScratch): void {
  const c = world.components;
  const { x: fx, y: fy, z: fz } = c.Force;
  const im = c.Mass.inv;
  const g = world.gravity;
  const gx = g[0]!,
    gy = g[1]!,
    gz = g[2]!;
  const [ax, ay, az] = s.acc as [Float64Array, Float64Array, Float64Array];
  const m = s.movers;
  for (let i = 0; i < s.nForced; i++) {
    const e = m[i]!;
    const k = im[e]!;
    ax[e] = fx[e]! * k + gx;
    ay[e] = fy[e]! * k + gy;
    az[e] = fz[e]! * k + gz;
  }
  for (let i = s.nForced; i < s.nMovers; i++) {
    const e = m[i]!;
    ax[e] = gx;
    ay[e] = gy;
    az[e] = gz;
  }
  angularAcceleration(world, s);
}

const euler = new Float64Array(3);

/**
 * Angular acceleration of every spinner: alpha = tau / I about z in 2D; in 3D with a scalar moment of
 * inertia (balls) alpha = tau I^-1 (the gyroscopic term w x I w vanishes for isotropic inertia); with
 * a principal inertia tensor, Euler's equations (see `eulerAcceleration`), in the body frame while
 * `s.bodyFrameSpin` (see `eulerBodyAcceleration`).
 * @category Integrators
 */
function angularAcceleration(world: PhysicsWorld, s: IntegratorScratch): void {
  const c = world.components;
  const { x: tx, y: ty, z: tz } = c.Torque;
  const ii = c.Inertia.inv;
  const [bx, by, bz] = s.alpha as [Float64Array, Float64Array, Float64Array];
  const sp = s.spinners;
  const torqued = s.torqued;
  for (let i = 0; i < s.nSpinners; i++) {
    const e = sp[i]!;
    const kind = torqued[e]!;
    if (kind === 0) {
      bx[e] = 0;
      by[e] = 0;
      bz[e] = 0;
      continue;
    }
    if (kind === 2) {
      const has = hasComponent(world, e, c.Torque);
      (s.bodyFrameSpin ? eulerBodyAcceleration : eulerAcceleration)(world, e, has ? tx[e]! : 0, has ? ty[e]! : 0, has ? tz[e]! : 0, euler);
      bx[e] = euler[0]!;
      by[e] = euler[1]!;
      bz[e] = euler[2]!;
      continue;
    }
    const k = ii[e]!;
    bx[e] = tx[e]! * k;
    by[e] = ty[e]! * k;
    bz[e] = tz[e]! * k;
  }
}

/**
 * Writes the trial state x = x0 + cx dx, v = v0 + cv dv for every mover, where (dx, dv) are the
 * given per-entity slope arrays (velocity and acceleration of an earlier stage), and likewise for
 * spinners (angle/orientation from w, w from alpha). Used by the Runge-Kutta schemes.
 * @category Integrators
 */
export function writeTrial(
  world: PhysicsWorld,
  s: IntegratorScratch,
  cx: number,
  dx: Float64Array[],
  cv: number,
  dv: Float64Array[],
  cq: number,
  dq: Float64Array[],
  cw: number,
  dw: Float64Array[],
): void {
  const c = world.components;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const [x0, y0, z0, u0, v0, w0] = s.x0 as [Float64Array, Float64Array, Float64Array, Float64Array, Float64Array, Float64Array];
  const [dxx, dxy, dxz] = dx as [Float64Array, Float64Array, Float64Array];
  const [dvx, dvy, dvz] = dv as [Float64Array, Float64Array, Float64Array];
  const m = s.movers;
  const is2D = world.dimensions === 2;
  for (let i = 0; i < s.nMovers; i++) {
    const e = m[i]!;
    px[e] = x0[e]! + cx * dxx[e]!;
    py[e] = y0[e]! + cx * dxy[e]!;
    vx[e] = u0[e]! + cv * dvx[e]!;
    vy[e] = v0[e]! + cv * dvy[e]!;
    if (!is2D) {
      pz[e] = z0[e]! + cx * dxz[e]!;
      vz[e] = w0[e]! + cv * dvz[e]!;
    }
  }
  writeAngularTrial(world, s, cq, dq, cw, dw);
}

/**
 * Angular part of `writeTrial`. 2D: angle = angle0 + cq dq, w = w0 + cw dw (dq, dw: angular
 * velocity and acceleration slopes). 3D: q = q0 + cq dq with dq a quaternion slope (q' = w q / 2),
 * normalised; w = w0 + cw dw, or for a body with a principal inertia tensor while `s.bodyFrameSpin`,
 * w = R(q) (w_b0 + cw dw) with dw a body-frame slope.
 * @category Integrators
 */
function writeAngularTrial(
  world: PhysicsWorld,
  s: IntegratorScratch,
  cq: number,
  dq: Float64Array[],
  cw: number,
  dw: Float64Array[],
): void {
  if (s.nSpinners === 0) return;
  const c = world.components;
  const { x: wx, y: wy, z: wz } = c.AngularVelocity;
  const [qa, qb, qc, qd] = s.q0 as [Float64Array, Float64Array, Float64Array, Float64Array];
  const [wa, wb, wc] = s.w0 as [Float64Array, Float64Array, Float64Array];
  const sp = s.spinners;
  if (world.dimensions === 2) {
    const ang = c.Angle.value;
    const d = dq[0]!,
      dwz = dw[2]!;
    for (let i = 0; i < s.nSpinners; i++) {
      const e = sp[i]!;
      ang[e] = qa[e]! + cq * d[e]!;
      wz[e] = wc[e]! + cw * dwz[e]!;
    }
    return;
  }
  const q = c.Orientation;
  const [d0, d1, d2, d3] = dq as [Float64Array, Float64Array, Float64Array, Float64Array];
  const [e0, e1, e2] = dw as [Float64Array, Float64Array, Float64Array];
  const [ba, bb, bc] = s.wb0 as [Float64Array, Float64Array, Float64Array];
  const body = s.bodyFrameSpin,
    torqued = s.torqued;
  for (let i = 0; i < s.nSpinners; i++) {
    const e = sp[i]!;
    storeUnitQuaternion(q, e, qa[e]! + cq * d0[e]!, qb[e]! + cq * d1[e]!, qc[e]! + cq * d2[e]!, qd[e]! + cq * d3[e]!);
    if (body && torqued[e] === 2) {
      rotateVector(q.x[e]!, q.y[e]!, q.z[e]!, q.w[e]!, ba[e]! + cw * e0[e]!, bb[e]! + cw * e1[e]!, bc[e]! + cw * e2[e]!, vec);
      wx[e] = vec[0]!;
      wy[e] = vec[1]!;
      wz[e] = vec[2]!;
      continue;
    }
    wx[e] = wa[e]! + cw * e0[e]!;
    wy[e] = wb[e]! + cw * e1[e]!;
    wz[e] = wc[e]! + cw * e2[e]!;
  }
}

/**
 * Orientation slope of every spinner at the current state, written into `out`: in 2D the angular
 * velocity w_z (into out[0]); in 3D the quaternion derivative q' = (w, 0) q / 2 (world-frame w)
 * into out[0..3].
 * @category Integrators
 */
function orientationSlope(world: PhysicsWorld, s: IntegratorScratch, out: Float64Array[]): void {
  const c = world.components;
  const { x: wx, y: wy, z: wz } = c.AngularVelocity;
  const sp = s.spinners;
  if (world.dimensions === 2) {
    const o = out[0]!;
    for (let i = 0; i < s.nSpinners; i++) {
      const e = sp[i]!;
      o[e] = wz[e]!;
    }
    return;
  }
  const q = c.Orientation;
  const [o0, o1, o2, o3] = out as [Float64Array, Float64Array, Float64Array, Float64Array];
  for (let i = 0; i < s.nSpinners; i++) {
    const e = sp[i]!;
    const ax = wx[e]!,
      ay = wy[e]!,
      az = wz[e]!;
    const x = q.x[e]!,
      y = q.y[e]!,
      z = q.z[e]!,
      w = q.w[e]!;
    o0[e] = 0.5 * (ax * w + ay * z - az * y);
    o1[e] = 0.5 * (-ax * z + ay * w + az * x);
    o2[e] = 0.5 * (ax * y - ay * x + az * w);
    o3[e] = 0.5 * (-ax * x - ay * y - az * z);
  }
}

/**
 * Evaluates the slopes of the current state in the component arrays at `time`: position slope kv
 * (a copy of the velocity), acceleration acc, orientation slope kq, angular acceleration alpha.
 * `evaluate` false reuses the force accumulators as they are (the pipeline evaluated them at the
 * start of the step).
 * @category Integrators
 */
export function stageSlopes(world: PhysicsWorld, s: IntegratorScratch, time: number, evaluate: boolean): void {
  if (evaluate) accelerationsAt(world, s, time);
  else accelerations(world, s);
  const c = world.components;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const [kx, ky, kz] = s.kv as [Float64Array, Float64Array, Float64Array];
  const m = s.movers;
  for (let i = 0; i < s.nMovers; i++) {
    const e = m[i]!;
    kx[e] = vx[e]!;
    ky[e] = vy[e]!;
    kz[e] = vz[e]!;
  }
  orientationSlope(world, s, s.kq);
}

/**
 * sum = (reset ? 0 : sum) + weight * (current stage slopes), for every mover and spinner.
 * @category Integrators
 */
export function accumulate(world: PhysicsWorld, s: IntegratorScratch, weight: number, reset: boolean): void {
  const S = s.sum;
  const lin = [s.kv[0]!, s.kv[1]!, s.kv[2]!, s.acc[0]!, s.acc[1]!, s.acc[2]!];
  for (let k = 0; k < 6; k++) addScaled(S[k]!, lin[k]!, weight, reset, s.movers, s.nMovers);
  const nq = world.dimensions === 2 ? 1 : 4;
  const ang = [s.kq[0]!, s.kq[1]!, s.kq[2]!, s.kq[3]!, s.alpha[0]!, s.alpha[1]!, s.alpha[2]!];
  for (let k = 0; k < 7; k++) {
    if (k >= nq && k < 4) continue;
    addScaled(S[6 + k]!, ang[k]!, weight, reset, s.spinners, s.nSpinners);
  }
}

/**
 * out[e] = (reset ? 0 : out[e]) + weight * src[e] for the first n entities e of `ids` (the reset form
 * writes weight * src[e] itself, not 0 + weight * src[e], which would turn a -0 into +0).
 */
function addScaled(out: Float64Array, src: Float64Array, weight: number, reset: boolean, ids: Int32Array, n: number): void {
  if (reset)
    for (let i = 0; i < n; i++) {
      const e = ids[i]!;
      out[e] = weight * src[e]!;
    }
  else
    for (let i = 0; i < n; i++) {
      const e = ids[i]!;
      out[e] = out[e]! + weight * src[e]!;
    }
}

/**
 * The sum arrays grouped as writeTrial expects: [x-slope], [v-slope], [q-slope], [w-slope].
 * @category Integrators
 */
export function sumGroups(s: IntegratorScratch): [Float64Array[], Float64Array[], Float64Array[], Float64Array[]] {
  const S = s.sum;
  return [
    [S[0]!, S[1]!, S[2]!],
    [S[3]!, S[4]!, S[5]!],
    [S[6]!, S[7]!, S[8]!, S[9]!],
    [S[10]!, S[11]!, S[12]!],
  ];
}

/**
 * Adds k g to the position of every mover (k in s^2): the first-order schemes pass k = +h^2 / 2
 * (explicit Euler, which drifts with the start velocity) or -h^2 / 2 (implicit Euler, which drifts
 * with the end velocity), so the world's constant gravity moves every body along the exact parabola
 * x += v h + g h^2 / 2. Only bodies no force acted on this step are shifted: a body under another
 * force keeps the scheme's plain drift, so a force-balanced body stays at rest (the trade-off is
 * documented on semiImplicitEuler).
 * @category Integrators
 */
export function shiftByGravity(world: PhysicsWorld, s: IntegratorScratch, k: number): void {
  const g = world.gravity;
  const dx = k * g[0]!,
    dy = k * g[1]!,
    dz = k * g[2]!;
  if (dx === 0 && dy === 0 && dz === 0) return;
  const c = world.components;
  const { x: px, y: py, z: pz } = c.Position;
  const m = s.movers;
  const { x: fx, y: fy, z: fz } = c.Force;
  for (let i = 0; i < s.nMovers; i++) {
    const e = m[i]!;
    // A forced body (index < nForced) under any force keeps the scheme's own drift, so a body in
    // force balance (buoyancy = weight, a spring at equilibrium) stays exactly at rest.
    if (i < s.nForced && (fx[e] !== 0 || fy[e] !== 0 || fz[e] !== 0)) continue;
    px[e] = px[e]! + dx;
    py[e] = py[e]! + dy;
    pz[e] = pz[e]! + dz;
  }
}

/**
 * Checks the movers and spinners for non-finite state after a scheme; throws NonFiniteStateError naming the first.
 * @category Integrators
 */
export function checkFinite(world: PhysicsWorld, s: IntegratorScratch): void {
  const c = world.components;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  let sum = 0;
  const m = s.movers;
  for (let i = 0; i < s.nMovers; i++) {
    const e = m[i]!;
    sum += px[e]! + py[e]! + pz[e]! + vx[e]! + vy[e]! + vz[e]!;
  }
  const { x: wx, y: wy, z: wz } = c.AngularVelocity;
  const sp = s.spinners;
  for (let i = 0; i < s.nSpinners; i++) {
    const e = sp[i]!;
    sum += wx[e]! + wy[e]! + wz[e]!;
  }
  if (sum - sum !== 0) {
    reportNonFinite(world, m.subarray(0, s.nMovers), 'integrate');
    reportNonFinite(world, sp.subarray(0, s.nSpinners), 'integrate');
  }
}
