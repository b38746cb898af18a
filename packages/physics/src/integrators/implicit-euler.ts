import { rotateFrom } from '../math/quaternion.js';
import type { PhysicsWorld } from '../world/options.js';
import { advanceKinematic } from './semi-implicit-euler.js';
import * as IS from './state.js';

/** Newton iterations before implicit Euler gives up on a step. */
const MAX_NEWTON = 30;
/** BiCGSTAB iterations per Newton step. */
const MAX_KRYLOV = 200;
/** Converged when |R|_inf <= RESIDUAL_TOL (1 + |v|_inf + h |a|_inf): the velocity equation holds to ~1e-10 of its terms. */
const RESIDUAL_TOL = 1e-10;

interface Work {
  n: number;
  u: Float64Array;
  u0: Float64Array;
  A: Float64Array;
  R: Float64Array;
  d: Float64Array;
  r: Float64Array;
  rh: Float64Array;
  p: Float64Array;
  v: Float64Array;
  s: Float64Array;
  t: Float64Array;
  w: Float64Array;
  Ap: Float64Array;
}

function work(world: PhysicsWorld, n: number): Work {
  const holder = world as { implicitWork?: Work };
  const old = holder.implicitWork;
  if (old && old.n >= n) return old;
  const size = Math.max(n, 64);
  const f = () => new Float64Array(size);
  const w: Work = { n: size, u: f(), u0: f(), A: f(), R: f(), d: f(), r: f(), rh: f(), p: f(), v: f(), s: f(), t: f(), w: f(), Ap: f() };
  holder.implicitWork = w;
  return w;
}

/**
 * Implicit (backward) Euler: v(t+h) = v + a(x(t+h), v(t+h), t+h) h, x(t+h) = x + v(t+h) h, and the
 * same for angular velocity and orientation. First order, unconditionally stable on linear damped
 * systems: it stays bounded where explicit Euler blows up (stiff springs), at the price of
 * numerical damping. The world's constant gravity moves bodies along the exact parabola (the drift
 * is corrected by -g h^2 / 2). Source: Ramtal and Dobre ch. 14; Hairer and Wanner, Solving ODEs II, ch. IV.
 *
 * The step is solved for the end velocities u of every moving body (and angular velocities) by
 * Newton's method on R(u) = u - v - h a(x + h u, u) = 0, started from the explicit Euler guess.
 * The Jacobian is never formed: each Newton step solves J d = -R with BiCGSTAB (van der Vorst, SIAM
 * J. Sci. Stat. Comput. 13, 1992), where J p = p - h (a(u + e p) - a(u)) / e costs one force
 * evaluation (Jacobian-free Newton-Krylov; Knoll and Keyes, J. Comput. Phys. 193, 2004). Linear
 * force laws converge in one Newton step. Convergence test: |R|_inf <= 1e-10 (1 + |v|_inf + h |a|_inf).
 *
 * If Newton does not converge (a collapsing orbit, a very stiff force at this h), the step is retried
 * as two half steps, recursively down to h / 64, before giving up.
 *
 * @throws RangeError if Newton does not converge even at h / 64 (a force law that is not
 *   differentiable enough); the message gives the residual. Use a smaller dt.
 * @category Integrators
 */
export function implicitEuler(world: PhysicsWorld, h: number): void {
  const t = world.time;
  if (!implicitStep(world, h, t, false, true)) subdivide(world, h, t, 1);
  advanceKinematic(world, h);
}

/** Most halvings before implicit Euler gives up on a step (h / 2^6 = h / 64). */
const MAX_DEPTH = 6;

function subdivide(world: PhysicsWorld, h: number, t: number, depth: number): void {
  const half = h / 2;
  for (let k = 0; k < 2; k++) {
    const start = t + k * half;
    if (implicitStep(world, half, start, true, false)) continue;
    if (depth >= MAX_DEPTH) {
      throw new RangeError(
        `implicit Euler: Newton did not converge in ${MAX_NEWTON} iterations at t = ${start} s even with the step cut to ${half.toExponential(3)} s (residual ${lastResidual.toExponential(3)} m/s); use a smaller dt`,
      );
    }
    subdivide(world, half, start, depth + 1);
  }
}

let lastResidual = 0;

/**
 * One implicit Euler step of h from the state in the arrays at time t. `evaluate`: evaluate the
 * forces at the start first (the pipeline has done it for a whole step); `setPrevious`: record the
 * start as PreviousPosition (only for the whole step). Returns false, with the start state restored,
 * if Newton does not converge.
 */
function implicitStep(world: PhysicsWorld, h: number, t: number, evaluate: boolean, setPrevious: boolean): boolean {
  const s = IS.getScratch(world);
  s.bodyFrameSpin = false; // this scheme's Newton solve works on world-frame w and alpha
  IS.gather(world, s);
  IS.saveState(world, s, setPrevious);
  IS.stageSlopes(world, s, t, evaluate);
  const nm = s.nMovers,
    ns = s.nSpinners;
  const n = 3 * (nm + ns);
  if (n === 0) return true;
  const W = work(world, n);
  const { u, u0, A, R, d } = W;

  // u0: start velocities; u: explicit Euler guess u0 + h a0.
  pack(s, s.x0, 3, s.w0, u0);
  pack(s, s.acc, 0, s.alpha, A);
  let scale = 0;
  for (let i = 0; i < n; i++) {
    u[i] = u0[i]! + h * A[i]!;
    scale = Math.max(scale, Math.abs(u0[i]!), h * Math.abs(A[i]!));
  }
  const tol = RESIDUAL_TOL * (1 + scale);

  for (let it = 0; it <= MAX_NEWTON; it++) {
    writeState(world, s, h, u);
    IS.accelerationsAt(world, s, t + h);
    pack(s, s.acc, 0, s.alpha, A);
    let residual = 0;
    for (let i = 0; i < n; i++) {
      const r = u[i]! - u0[i]! - h * A[i]!;
      R[i] = -r;
      residual = Math.max(residual, Math.abs(r));
    }
    if (residual <= tol) {
      // The drift used the end velocity; gravity's share of it is made exact (see shiftByGravity).
      IS.shiftByGravity(world, s, -0.5 * h * h);
      IS.checkFinite(world, s);
      return true;
    }
    lastResidual = residual;
    // A NaN or infinite residual from a non-finite state (not a hard Newton step): name it, as every scheme does.
    if (!(residual < Infinity)) IS.checkFinite(world, s);
    if (it === MAX_NEWTON || !(residual < Infinity)) break;
    solveBiCGStab(world, s, h, t, W, n);
    for (let i = 0; i < n; i++) u[i] = u[i]! + d[i]!;
  }
  // Not converged: put the start state back (v = u0, x = x0, and the orientations) for the caller to retry.
  writeState(world, s, 0, u0);
  return false;
}

/**
 * Packs 3 numbers a body into `out`: each mover's linear[at], linear[at + 1], linear[at + 2], then each
 * spinner's angular[0], angular[1], angular[2] (the layout of u: start velocities from x0 and w0,
 * accelerations from acc and alpha).
 */
function pack(s: IS.IntegratorScratch, linear: Float64Array[], at: number, angular: Float64Array[], out: Float64Array): void {
  const ax = linear[at]!,
    ay = linear[at + 1]!,
    az = linear[at + 2]!;
  const [bx, by, bz] = angular as [Float64Array, Float64Array, Float64Array];
  const m = s.movers;
  let k = 0;
  for (let i = 0; i < s.nMovers; i++) {
    const e = m[i]!;
    out[k++] = ax[e]!;
    out[k++] = ay[e]!;
    out[k++] = az[e]!;
  }
  const sp = s.spinners;
  for (let i = 0; i < s.nSpinners; i++) {
    const e = sp[i]!;
    out[k++] = bx[e]!;
    out[k++] = by[e]!;
    out[k++] = bz[e]!;
  }
}

/** Writes the end state implied by end velocities u: v = u, x = x0 + h u; w = u, orientation turned by h w. */
function writeState(world: PhysicsWorld, s: IS.IntegratorScratch, h: number, u: Float64Array): void {
  const c = world.components;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const [x0, y0, z0] = s.x0 as [Float64Array, Float64Array, Float64Array];
  const is2D = world.dimensions === 2;
  const m = s.movers;
  let k = 0;
  for (let i = 0; i < s.nMovers; i++) {
    const e = m[i]!;
    const a = u[k++]!,
      b = u[k++]!,
      cz = u[k++]!;
    vx[e] = a;
    vy[e] = b;
    px[e] = x0[e]! + h * a;
    py[e] = y0[e]! + h * b;
    if (!is2D) {
      vz[e] = cz;
      pz[e] = z0[e]! + h * cz;
    }
  }
  if (s.nSpinners === 0) return;
  const { x: wx, y: wy, z: wz } = c.AngularVelocity;
  const [qa, qb, qc, qd] = s.q0 as [Float64Array, Float64Array, Float64Array, Float64Array];
  const ang = c.Angle.value,
    q = c.Orientation;
  const sp = s.spinners;
  for (let i = 0; i < s.nSpinners; i++) {
    const e = sp[i]!;
    const a = u[k++]!,
      b = u[k++]!,
      cz = u[k++]!;
    wz[e] = cz;
    if (is2D) {
      ang[e] = qa[e]! + h * cz;
      continue;
    }
    wx[e] = a;
    wy[e] = b;
    rotateFrom(q.x, q.y, q.z, q.w, e, qa[e]!, qb[e]!, qc[e]!, qd[e]!, h * a, h * b, h * cz);
  }
}

function dot(a: Float64Array, b: Float64Array, n: number): number {
  let sum = 0;
  for (let i = 0; i < n; i++) sum += a[i]! * b[i]!;
  return sum;
}

/** out = J p with J = I - h da/du, by a forward difference of the accelerations (one force evaluation). */
function jacobianTimes(
  world: PhysicsWorld,
  s: IS.IntegratorScratch,
  h: number,
  t: number,
  W: Work,
  n: number,
  p: Float64Array,
  out: Float64Array,
): void {
  const { u, A, w } = W;
  let pn = 0,
    un = 0;
  for (let i = 0; i < n; i++) {
    pn = Math.max(pn, Math.abs(p[i]!));
    un = Math.max(un, Math.abs(u[i]!));
  }
  if (pn === 0) {
    out.fill(0, 0, n);
    return;
  }
  const eps = (Math.sqrt(Number.EPSILON) * (1 + un)) / pn;
  for (let i = 0; i < n; i++) w[i] = u[i]! + eps * p[i]!;
  writeState(world, s, h, w);
  IS.accelerationsAt(world, s, t + h);
  pack(s, s.acc, 0, s.alpha, W.Ap);
  const Ap = W.Ap;
  for (let i = 0; i < n; i++) out[i] = p[i]! - (h * (Ap[i]! - A[i]!)) / eps;
}

/** BiCGSTAB for J d = b with b = W.R (already -R); result in W.d. A is the accelerations at u. */
function solveBiCGStab(world: PhysicsWorld, s: IS.IntegratorScratch, h: number, t: number, W: Work, n: number): void {
  const { R: b, d, r, rh, p, v, s: sv, t: tv } = W;
  d.fill(0, 0, n);
  for (let i = 0; i < n; i++) {
    r[i] = b[i]!;
    rh[i] = b[i]!;
    p[i] = 0;
    v[i] = 0;
  }
  const bnorm = Math.sqrt(dot(b, b, n));
  if (bnorm === 0) return;
  const tol = 1e-12 * bnorm;
  let rho = 1,
    alpha = 1,
    omega = 1;
  for (let it = 0; it < MAX_KRYLOV; it++) {
    const rhoNew = dot(rh, r, n);
    if (rhoNew === 0) break;
    const beta = (rhoNew / rho) * (alpha / omega);
    rho = rhoNew;
    for (let i = 0; i < n; i++) p[i] = r[i]! + beta * (p[i]! - omega * v[i]!);
    jacobianTimes(world, s, h, t, W, n, p, v);
    const rv = dot(rh, v, n);
    if (rv === 0) break;
    alpha = rho / rv;
    for (let i = 0; i < n; i++) sv[i] = r[i]! - alpha * v[i]!;
    if (Math.sqrt(dot(sv, sv, n)) <= tol) {
      for (let i = 0; i < n; i++) d[i] = d[i]! + alpha * p[i]!;
      break;
    }
    jacobianTimes(world, s, h, t, W, n, sv, tv);
    const tt = dot(tv, tv, n);
    omega = tt === 0 ? 0 : dot(tv, sv, n) / tt;
    for (let i = 0; i < n; i++) {
      d[i] = d[i]! + alpha * p[i]! + omega * sv[i]!;
      r[i] = sv[i]! - omega * tv[i]!;
    }
    if (Math.sqrt(dot(r, r, n)) <= tol || omega === 0) break;
  }
}
