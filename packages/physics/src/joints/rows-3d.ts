import { BS3_INV_MASS, BS3_STRIDE, BS3_WX, BS3_WY, BS3_WZ } from '../solver/body-state-layout.js';
import type { PhysicsWorld } from '../world/options.js';
import {
  anchorSpeed,
  anchorVelocity,
  applyAngular,
  applyLinear,
  ax,
  bx,
  invI,
  K,
  pa,
  pb,
  pose,
  qa,
  qb,
  ra,
  rb,
  relativeRotation,
  relativeSpin,
  restrictToPlane,
  rot,
  row3D,
  solve3,
  tmp,
  v3,
  x3,
} from './rows-3d-math.js';
import type { Joint3DStore } from './store-3d.js';

/**
 * The row code the 3D joint types share: the pass every row solve reads (JointPass3D), what a type's
 * file hands the solver (JointRows3D), a joint's pose, and the pieces several types solve with: the
 * error rotation, the angular lock (fixed, hinge, slider), the point block (ball, hinge, fixed; the
 * slider's restricted to a plane), one-sided limit rows (cone, hinge, slider, distance) and the limit
 * and motor along or about an axis (hinge, slider). Each type's own rows are in its file (ball-, hinge-,
 * fixed-, slider- and distance-joint-3d.ts), run by joints/solver-3d.ts on the poses poseJoint3D leaves
 * in the scratch of rows-3d-math.ts (qa, pa, ra for body A, qb, pb, rb for B); the rows are those its
 * header describes.
 */

/**
 * What every row solve of a pass reads (joints/solver-3d.ts fills it once a pass): the joint store,
 * the packed body state and world inverse inertias, the substep (s), whether the rigid rows push out
 * their error (`useBias`) and their softness (bias rate 1/s, mass and impulse scale).
 */
export interface JointPass3D {
  s: Joint3DStore;
  sb: Float64Array;
  T: Float64Array;
  hs: number;
  useBias: boolean;
  bRate: number;
  ms: number;
  is: number;
}

/**
 * A 3D joint type's rows, which the type's file hands the solver (useJointType3D of joints/solver-3d.ts)
 * when it makes a joint, and restore for every type. Each runs on the pass `p` for joint slot `j` whose
 * bodies have solver indices `a`, `b` (0: fixed), posed in the scratch of rows-3d-math.ts.
 */
export interface JointRows3D {
  /** Its impulses of the last substep applied again (warm start; `p` holds s, sb and T). */
  warmStart(p: JointPass3D, j: number, a: number, b: number): void;
  /** One pass of its rows, soft with `p.useBias`, else relaxing; `flags` its Joint3DFlag bits. */
  solve(p: JointPass3D, j: number, a: number, b: number, flags: number): void;
  /** Its force (N) into out[0] and torque (N m) into out[1] after the substeps of `hs` s: the impulses of the last one / hs. */
  reading(s: Joint3DStore, j: number, hs: number, out: Float64Array): void;
}

/** The error rotation of the joint being solved (x, y, z, w with w >= 0; errorRotation). */
export const E = new Float64Array(4);
/** The point block's position error C = p_B + r_B - p_A - r_A, m (preparePointBlock). */
export const C3 = new Float64Array(3);

/** The error rotation E = conj(q_A) q_B conj(q_rest) (A's frame) into E, w >= 0. */
export function errorRotation(p: JointPass3D, j: number): void {
  const { s } = p;
  relativeRotation(qa, qb, E);
  const rx = E[0]!,
    ry = E[1]!,
    rz = E[2]!,
    rw = E[3]!;
  const cx = -s.rx[j]!,
    cy = -s.ry[j]!,
    cz = -s.rz[j]!,
    cw = s.rw[j]!;
  let ex = rw * cx + rx * cw + ry * cz - rz * cy,
    ey = rw * cy - rx * cz + ry * cw + rz * cx,
    ez = rw * cz + rx * cy - ry * cx + rz * cw;
  let ew = rw * cw - rx * cx - ry * cy - rz * cz;
  if (ew < 0) {
    ex = -ex;
    ey = -ey;
    ez = -ez;
    ew = -ew;
  }
  E[0] = ex;
  E[1] = ey;
  E[2] = ez;
  E[3] = ew;
}

/**
 * The angular lock (fixed and slider: 3 rows; `hinge`: the 2 perpendicular to the axis), K = I_A^-1 +
 * I_B^-1, on the error rotation in E. Leaves the hinge axis (world) in bx.
 */
export function solveAngularLock(p: JointPass3D, j: number, a: number, b: number, hinge: boolean): void {
  const { s, sb, T, bRate, ms, is } = p;
  const oa = BS3_STRIDE * a,
    ob = BS3_STRIDE * b;
  const wx = sb[ob + BS3_WX]! - sb[oa + BS3_WX]!,
    wy = sb[ob + BS3_WY]! - sb[oa + BS3_WY]!,
    wz = sb[ob + BS3_WZ]! - sb[oa + BS3_WZ]!;
  const ex = E[0]!,
    ey = E[1]!,
    ez = E[2]!;
  rot(qa, 2 * ex, 2 * ey, 2 * ez, ax); // the error as a world rotation vector
  rot(qa, s.uax[j]!, s.uay[j]!, s.uaz[j]!, bx); // hinge axis, world
  // Angular lock (fixed: 3 rows; hinge: the 2 perpendicular to the axis), K = I_A^-1 + I_B^-1.
  for (let c = 0; c < 3; c++) {
    const ux = c === 0 ? 1 : 0,
      uy = c === 1 ? 1 : 0,
      uz = c === 2 ? 1 : 0;
    invI(T, a, ux, uy, uz, tmp, 0);
    invI(T, b, ux, uy, uz, tmp, 3);
    K[c] = tmp[0]! + tmp[3]!;
    K[3 + c] = tmp[1]! + tmp[4]!;
    K[6 + c] = tmp[2]! + tmp[5]!;
  }
  let r0 = wx + bRate * ax[0]!,
    r1 = wy + bRate * ax[1]!,
    r2 = wz + bRate * ax[2]!;
  if (hinge) {
    // Remove the axial part: project the residual and the system onto the plane perpendicular to the axis.
    const hx = bx[0]!,
      hy = bx[1]!,
      hz = bx[2]!;
    const d = r0 * hx + r1 * hy + r2 * hz;
    r0 -= d * hx;
    r1 -= d * hy;
    r2 -= d * hz;
    restrictToPlane(hx, hy, hz);
  }
  solve3(K, r0, r1, r2, x3);
  let lx = -ms * x3[0]! - is * s.wx[j]!,
    ly = -ms * x3[1]! - is * s.wy[j]!,
    lz = -ms * x3[2]! - is * s.wz[j]!;
  if (hinge) {
    const d = lx * bx[0]! + ly * bx[1]! + lz * bx[2]!;
    lx -= d * bx[0]!;
    ly -= d * bx[1]!;
    lz -= d * bx[2]!;
  }
  s.wx[j] = s.wx[j]! + lx;
  s.wy[j] = s.wy[j]! + ly;
  s.wz[j] = s.wz[j]! + lz;
  applyAngular(sb, T, a, b, lx, ly, lz);
}

/** The point block: its error in C3, the anchors' relative velocity in v3 and K (3 x 3). */
export function preparePointBlock(p: JointPass3D, a: number, b: number): void {
  const { sb, T } = p;
  const oa = BS3_STRIDE * a,
    ob = BS3_STRIDE * b;
  C3[0] = pb[0]! + rb[0]! - pa[0]! - ra[0]!;
  C3[1] = pb[1]! + rb[1]! - pa[1]! - ra[1]!;
  C3[2] = pb[2]! + rb[2]! - pa[2]! - ra[2]!;
  anchorVelocity(sb, a, b, v3);
  const ma = sb[oa + BS3_INV_MASS]!,
    mb = sb[ob + BS3_INV_MASS]!;
  for (let c = 0; c < 3; c++) {
    const px = c === 0 ? 1 : 0,
      py = c === 1 ? 1 : 0,
      pz = c === 2 ? 1 : 0;
    let kx = (ma + mb) * px,
      ky = (ma + mb) * py,
      kz = (ma + mb) * pz;
    invI(T, a, ra[1]! * pz - ra[2]! * py, ra[2]! * px - ra[0]! * pz, ra[0]! * py - ra[1]! * px, tmp, 0);
    kx += tmp[1]! * ra[2]! - tmp[2]! * ra[1]!;
    ky += tmp[2]! * ra[0]! - tmp[0]! * ra[2]!;
    kz += tmp[0]! * ra[1]! - tmp[1]! * ra[0]!;
    invI(T, b, rb[1]! * pz - rb[2]! * py, rb[2]! * px - rb[0]! * pz, rb[0]! * py - rb[1]! * px, tmp, 0);
    kx += tmp[1]! * rb[2]! - tmp[2]! * rb[1]!;
    ky += tmp[2]! * rb[0]! - tmp[0]! * rb[2]!;
    kz += tmp[0]! * rb[1]! - tmp[1]! * rb[0]!;
    K[c] = kx;
    K[3 + c] = ky;
    K[6 + c] = kz;
  }
}

/** The point rows as one 3 x 3 block (ball, hinge, fixed), on preparePointBlock's C3, v3 and K. */
export function solvePointRows(p: JointPass3D, j: number, a: number, b: number): void {
  const { s, sb, T, bRate, ms, is } = p;
  solve3(K, v3[0]! + bRate * C3[0]!, v3[1]! + bRate * C3[1]!, v3[2]! + bRate * C3[2]!, x3);
  const px = -ms * x3[0]! - is * s.lx[j]!,
    py = -ms * x3[1]! - is * s.ly[j]!,
    pz = -ms * x3[2]! - is * s.lz[j]!;
  s.lx[j] = s.lx[j]! + px;
  s.ly[j] = s.ly[j]! + py;
  s.lz[j] = s.lz[j]! + pz;
  applyLinear(sb, T, a, b, px, py, pz);
}

/**
 * The warm start of the point block and the angular lock (every 3D type but the distance joint): the
 * point impulse (lx, ly, lz) at the anchors and the angular one (wx, wy, wz), world vectors, N s and N m s.
 */
export function warmStartPointAndLock(p: JointPass3D, j: number, a: number, b: number): void {
  const { s, sb, T } = p;
  applyLinear(sb, T, a, b, s.lx[j]!, s.ly[j]!, s.lz[j]!);
  applyAngular(sb, T, a, b, s.wx[j]!, s.wy[j]!, s.wz[j]!);
}

/**
 * The reading of a joint whose limit and motor act about an axis (ball, hinge, fixed): the force of its
 * point impulse and the torque of its angular lock plus its limit's and motor's, after the substeps of
 * `hs` s, into out[0] (N) and out[1] (N m).
 */
export function pointJointReading(s: Joint3DStore, j: number, hs: number, out: Float64Array): void {
  out[0] = Math.hypot(s.lx[j]!, s.ly[j]!, s.lz[j]!) / hs;
  out[1] = (Math.hypot(s.wx[j]!, s.wy[j]!, s.wz[j]!) + (Math.abs(s.limit[j]!) + Math.abs(s.motor[j]!))) / hs;
}

/** Poses joint slot j's bodies (solver indices a, b; 0: fixed) into qa, pa and qb, pb, and its anchors (world frame, from the centres) into ra, rb. */
export function poseJoint3D(world: PhysicsWorld, s: Joint3DStore, j: number, a: number, b: number): void {
  pose(world, s.a[j]!, a, qa, pa);
  pose(world, s.b[j]!, b, qb, pb);
  rot(qa, s.ax[j]!, s.ay[j]!, s.az[j]!, ra);
  rot(qb, s.bx[j]!, s.by[j]!, s.bz[j]!, rb);
}

/** A one-sided limit row's softness (limitSoftness): bias (m/s or rad/s), mass scale, impulse scale. */
export const limitSoft = new Float64Array(3);

/**
 * The softness of a one-sided limit row (cone, hinge, slider, distance) with position error C (>= 0
 * inside the limit) into limitSoft: speculative while C > 0 (bias C / h_s, rigid), soft with the pass's
 * softness while it uses bias, else rigid without bias (Box2D v3's joint limits). The row then runs with
 * its accumulated impulse kept >= 0 (row3D with lo 0, hi Infinity).
 */
export function limitSoftness(p: JointPass3D, C: number): void {
  let bias = 0,
    m = 1,
    im = 0;
  if (C > 0) bias = C / p.hs;
  else if (p.useBias) {
    bias = p.bRate * C;
    m = p.ms;
    im = p.is;
  }
  limitSoft[0] = bias;
  limitSoft[1] = m;
  limitSoft[2] = im;
}

/**
 * The motor along (`linear`: a slider's, at the anchors, effective mass 1 / k) or about (a hinge's) the
 * unit axis in bx: drives B's speed relative to A toward the motor speed with at most the largest
 * force or torque times h_s.
 */
export function axisMotor3D(p: JointPass3D, j: number, a: number, b: number, linear: boolean, k: number): void {
  const { s, sb, T } = p;
  const hx = bx[0]!,
    hy = bx[1]!,
    hz = bx[2]!;
  const max = s.maxMotorTorque[j]! * p.hs;
  const speed = linear ? anchorSpeed(sb, a, b, hx, hy, hz) : relativeSpin(sb, a, b, hx, hy, hz);
  s.motor[j] = row3D(sb, T, a, b, linear, hx, hy, hz, k, speed, -s.motorSpeed[j]!, 1, 0, s.motor[j]!, -max, max);
}

/**
 * The limits of `value` (a slider's translation along the unit axis in bx, `linear`, at the anchors
 * with effective mass 1 / k; a hinge's angle about it) within [lower, upper]: one one-sided row, on the
 * side nearer; an impulse warm-started from the other side is taken back first. s.limit holds the
 * signed impulse along the axis.
 */
export function axisLimit3D(p: JointPass3D, j: number, a: number, b: number, linear: boolean, k: number, value: number): void {
  const { s, sb, T } = p;
  const hx = bx[0]!,
    hy = bx[1]!,
    hz = bx[2]!;
  const lo = s.lower[j]!,
    hi = s.upper[j]!;
  const nearLower = value - lo < hi - value;
  const C = nearLower ? value - lo : hi - value,
    sg = nearLower ? 1 : -1;
  if (sg * s.limit[j]! < 0) {
    const l = -s.limit[j]!;
    if (linear) applyLinear(sb, T, a, b, l * hx, l * hy, l * hz);
    else applyAngular(sb, T, a, b, l * hx, l * hy, l * hz);
    s.limit[j] = 0;
  }
  const speed = linear ? anchorSpeed(sb, a, b, hx, hy, hz) : relativeSpin(sb, a, b, hx, hy, hz);
  limitSoftness(p, C);
  const lam = row3D(
    sb,
    T,
    a,
    b,
    linear,
    sg * hx,
    sg * hy,
    sg * hz,
    k,
    sg * speed,
    limitSoft[0]!,
    limitSoft[1]!,
    limitSoft[2]!,
    sg * s.limit[j]!,
    0,
    Infinity,
  );
  s.limit[j] = sg * lam;
}

/**
 * The warm start of a joint with a limit and motor along (`linear`: a slider's, at the point of A under
 * B's anchor) or about (a hinge's) A's axis: its point and angular-lock impulses, then its limit's and
 * motor's along the axis turned with A.
 */
export function warmStartAxis3D(p: JointPass3D, j: number, a: number, b: number, linear: boolean): void {
  warmStartPointAndLock(p, j, a, b);
  const { s, sb, T } = p;
  const axial = s.limit[j]! + s.motor[j]!;
  if (axial === 0) return;
  rot(qa, s.uax[j]!, s.uay[j]!, s.uaz[j]!, ax);
  if (linear) {
    sliderAnchor();
    applyLinear(sb, T, a, b, axial * ax[0]!, axial * ax[1]!, axial * ax[2]!);
  } else applyAngular(sb, T, a, b, axial * ax[0]!, axial * ax[1]!, axial * ax[2]!);
}

/** Slider: moves A's anchor (ra) to the point of A under B's anchor (ra + C), where the axial rows act. */
export function sliderAnchor(): void {
  ra[0] = pb[0]! + rb[0]! - pa[0]!;
  ra[1] = pb[1]! + rb[1]! - pa[1]!;
  ra[2] = pb[2]! + rb[2]! - pa[2]!;
}
