import { BS3_INV_MASS, BS3_STRIDE, BS3_WX, BS3_WY, BS3_WZ } from '../solver/body-state-layout.js';
import {
  anchorSpeed,
  anchorVelocity,
  angularRow,
  applyAngular,
  applyLinear,
  ax,
  bx,
  invI,
  K,
  linearK,
  linearRow,
  pa,
  pb,
  qa,
  qb,
  ra,
  rb,
  referenceK,
  restrictToPlane,
  rot,
  sliderAnchor,
  solve3,
  tmp,
  v3,
  x3,
} from './rows-3d-math.js';
import { fixedSpring } from './spring.js';
import { Joint3DFlag, type Joint3DStore } from './store-3d.js';

/**
 * Each 3D joint type's row solve (one pass, soft with `useBias`, else relaxing), run by
 * joints/solver-3d.ts on the poses it leaves in the scratch of rows-3d-math.ts (qa, pa, ra for body A,
 * qb, pb, rb for B), and the pieces they share: the error rotation, the angular lock (fixed, hinge,
 * slider) and the point block (ball, hinge, fixed; the slider's restricted to a plane). The rows are
 * those joints/solver-3d.ts's header describes. Each takes the pass (JointPass3D), the joint's slot,
 * its bodies' solver indices and its flags.
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

/** The error rotation of the joint being solved (x, y, z, w with w >= 0; errorRotation). */
const E = new Float64Array(4);
/** The point block's position error C = p_B + r_B - p_A - r_A, m (preparePointBlock). */
const C3 = new Float64Array(3);
/** Scratch of a spring's soft coefficients. */
const spring = new Float64Array(3);

/**
 * A distance joint's rows along the anchors' line: the spring (soft, fixed stiffness), the rod, and the
 * one-sided length limits (speculative when apart). Anchors that meet reset its impulses.
 */
export function solveDistanceRow3D(p: JointPass3D, j: number, a: number, b: number, flags: number): void {
  const { s, sb, T, hs, useBias, bRate, ms, is } = p;
  let dx = pb[0]! + rb[0]! - pa[0]! - ra[0]!,
    dy = pb[1]! + rb[1]! - pa[1]! - ra[1]!,
    dz = pb[2]! + rb[2]! - pa[2]! - ra[2]!;
  const len = Math.hypot(dx, dy, dz);
  // No direction: nothing was warm-started; the rows start again from zero.
  if (!(len > 1e-12)) {
    s.lx[j] = 0;
    s.limit[j] = 0;
    s.ly[j] = 0;
    return;
  }
  dx /= len;
  dy /= len;
  dz /= len;
  const k = linearK(sb, T, a, b, dx, dy, dz);
  if (!(k > 0)) return;
  const L = s.length[j]!;
  if (flags & Joint3DFlag.Spring) {
    if (useBias) {
      // A spring of fixed stiffness (see fixedSpring): its softness gamma from the reference mass,
      // the row's mass from the effective mass k of the moment.
      fixedSpring(spring, 0, s.hertz[j]!, s.dampingRatio[j]!, hs, referenceK(sb, T, a, b));
      const gamma = spring[1]!,
        soft = gamma < Infinity;
      spring[1] = soft ? k / (k + gamma) : 0;
      spring[2] = soft ? gamma / (k + gamma) : 1;
      s.lx[j] = linearRow(
        sb,
        T,
        a,
        b,
        dx,
        dy,
        dz,
        k,
        anchorSpeed(sb, a, b, dx, dy, dz),
        spring[0]! * (len - L),
        spring[1]!,
        spring[2]!,
        s.lx[j]!,
        -Infinity,
        Infinity,
      );
    }
  } else if (!(flags & Joint3DFlag.Limit)) {
    s.lx[j] = linearRow(
      sb,
      T,
      a,
      b,
      dx,
      dy,
      dz,
      k,
      anchorSpeed(sb, a, b, dx, dy, dz),
      bRate * (len - L),
      ms,
      is,
      s.lx[j]!,
      -Infinity,
      Infinity,
    );
  }
  if (flags & Joint3DFlag.Limit) {
    // One-sided rows: len >= lower (impulse along +u) and len <= upper (along -u); speculative when apart.
    if (s.lower[j]! > 0 || !(flags & Joint3DFlag.Spring)) {
      const C = len - s.lower[j]!;
      const bias = C > 0 ? C / hs : useBias ? bRate * C : 0,
        m = C > 0 || !useBias ? 1 : ms,
        im = C > 0 || !useBias ? 0 : is;
      s.limit[j] = linearRow(sb, T, a, b, dx, dy, dz, k, anchorSpeed(sb, a, b, dx, dy, dz), bias, m, im, s.limit[j]!, 0, Infinity);
    }
    if (Number.isFinite(s.upper[j]!)) {
      const C = s.upper[j]! - len;
      const bias = C > 0 ? C / hs : useBias ? bRate * C : 0,
        m = C > 0 || !useBias ? 1 : ms,
        im = C > 0 || !useBias ? 0 : is;
      s.ly[j] = linearRow(sb, T, a, b, -dx, -dy, -dz, k, -anchorSpeed(sb, a, b, dx, dy, dz), bias, m, im, s.ly[j]!, 0, Infinity);
    }
  }
}

/** The error rotation E = conj(q_A) q_B conj(q_rest) (A's frame) into E, w >= 0. */
function errorRotation(p: JointPass3D, j: number): void {
  const { s } = p;
  const x1 = -qa[0]!,
    y1 = -qa[1]!,
    z1 = -qa[2]!,
    w1 = qa[3]!,
    x2 = qb[0]!,
    y2 = qb[1]!,
    z2 = qb[2]!,
    w2 = qb[3]!;
  const rx = w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
    ry = w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
    rz = w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
    rw = w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2;
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
function solveAngularLock(p: JointPass3D, j: number, a: number, b: number, hinge: boolean): void {
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

/** A hinge's motor and angle limit about its axis (bx, from solveAngularLock), on the angle of E. */
function solveHingeAxial(p: JointPass3D, j: number, a: number, b: number, flags: number): void {
  const { s, sb, T, hs, useBias, bRate, ms, is } = p;
  const oa = BS3_STRIDE * a,
    ob = BS3_STRIDE * b;
  const ex = E[0]!,
    ey = E[1]!,
    ez = E[2]!,
    ew = E[3]!;
  const hx = bx[0]!,
    hy = bx[1]!,
    hz = bx[2]!;
  const angle = 2 * Math.atan2(ex * s.uax[j]! + ey * s.uay[j]! + ez * s.uaz[j]!, ew);
  if (flags & Joint3DFlag.Motor) {
    const maxL = s.maxMotorTorque[j]! * hs;
    const rel =
      (sb[ob + BS3_WX]! - sb[oa + BS3_WX]!) * hx + (sb[ob + BS3_WY]! - sb[oa + BS3_WY]!) * hy + (sb[ob + BS3_WZ]! - sb[oa + BS3_WZ]!) * hz;
    s.motor[j] = angularRow(sb, T, a, b, hx, hy, hz, rel, -s.motorSpeed[j]!, 1, 0, s.motor[j]!, -maxL, maxL);
  }
  if (flags & Joint3DFlag.Limit) {
    const lo = s.lower[j]!,
      hi = s.upper[j]!;
    const nearLower = angle - lo < hi - angle;
    const C = nearLower ? angle - lo : hi - angle,
      sg = nearLower ? 1 : -1;
    let bias = 0,
      m = 1,
      im = 0;
    if (C > 0) bias = C / hs;
    else if (useBias) {
      bias = bRate * C;
      m = ms;
      im = is;
    }
    // A warm-started impulse from the other limit is taken back first.
    if (sg * s.limit[j]! < 0) {
      const l = -s.limit[j]!;
      applyAngular(sb, T, a, b, l * hx, l * hy, l * hz);
      s.limit[j] = 0;
    }
    const rel =
      (sb[ob + BS3_WX]! - sb[oa + BS3_WX]!) * hx + (sb[ob + BS3_WY]! - sb[oa + BS3_WY]!) * hy + (sb[ob + BS3_WZ]! - sb[oa + BS3_WZ]!) * hz;
    const lam = angularRow(sb, T, a, b, sg * hx, sg * hy, sg * hz, sg * rel, bias, m, im, sg * s.limit[j]!, 0, Infinity);
    s.limit[j] = sg * lam;
  }
}

/** The point block: its error in C3, the anchors' relative velocity in v3 and K (3 x 3). */
function preparePointBlock(p: JointPass3D, a: number, b: number): void {
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
function solvePointRows(p: JointPass3D, j: number, a: number, b: number): void {
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
 * A slider's point block restricted to the plane across A's axis, then along the axis (at the point
 * of A under B's anchor) its motor and translation limit.
 */
function solveSliderAxis(p: JointPass3D, j: number, a: number, b: number, flags: number): void {
  const { s, sb, T, hs, useBias, bRate, ms, is } = p;
  // Only the part perpendicular to the axis (A's, in the world) is held.
  rot(qa, s.uax[j]!, s.uay[j]!, s.uaz[j]!, bx);
  const hx = bx[0]!,
    hy = bx[1]!,
    hz = bx[2]!;
  const Cx = C3[0]!,
    Cy = C3[1]!,
    Cz = C3[2]!;
  const t = Cx * hx + Cy * hy + Cz * hz,
    dv = v3[0]! * hx + v3[1]! * hy + v3[2]! * hz;
  restrictToPlane(hx, hy, hz);
  solve3(
    K,
    v3[0]! - dv * hx + bRate * (Cx - t * hx),
    v3[1]! - dv * hy + bRate * (Cy - t * hy),
    v3[2]! - dv * hz + bRate * (Cz - t * hz),
    x3,
  );
  let px = -ms * x3[0]! - is * s.lx[j]!,
    py = -ms * x3[1]! - is * s.ly[j]!,
    pz = -ms * x3[2]! - is * s.lz[j]!;
  const d = px * hx + py * hy + pz * hz;
  px -= d * hx;
  py -= d * hy;
  pz -= d * hz;
  s.lx[j] = s.lx[j]! + px;
  s.ly[j] = s.ly[j]! + py;
  s.lz[j] = s.lz[j]! + pz;
  applyLinear(sb, T, a, b, px, py, pz);
  if (flags & (Joint3DFlag.Limit | Joint3DFlag.Motor)) {
    // Axial rows act at the point of A under B's anchor.
    sliderAnchor();
    const k = linearK(sb, T, a, b, hx, hy, hz);
    if (k > 0 && flags & Joint3DFlag.Motor) {
      const maxP = s.maxMotorTorque[j]! * hs;
      s.motor[j] = linearRow(
        sb,
        T,
        a,
        b,
        hx,
        hy,
        hz,
        k,
        anchorSpeed(sb, a, b, hx, hy, hz),
        -s.motorSpeed[j]!,
        1,
        0,
        s.motor[j]!,
        -maxP,
        maxP,
      );
    }
    if (k > 0 && flags & Joint3DFlag.Limit) {
      const lo = s.lower[j]!,
        hi = s.upper[j]!;
      const nearLower = t - lo < hi - t;
      const C = nearLower ? t - lo : hi - t,
        sg = nearLower ? 1 : -1;
      let bias = 0,
        m = 1,
        im = 0;
      if (C > 0) bias = C / hs;
      else if (useBias) {
        bias = bRate * C;
        m = ms;
        im = is;
      }
      if (sg * s.limit[j]! < 0) {
        const l = -s.limit[j]!;
        applyLinear(sb, T, a, b, l * hx, l * hy, l * hz);
        s.limit[j] = 0;
      }
      const lam = linearRow(
        sb,
        T,
        a,
        b,
        sg * hx,
        sg * hy,
        sg * hz,
        k,
        sg * anchorSpeed(sb, a, b, hx, hy, hz),
        bias,
        m,
        im,
        sg * s.limit[j]!,
        0,
        Infinity,
      );
      s.limit[j] = sg * lam;
    }
  }
}

/** A ball joint's cone: the angle between A's axis and B's stays within the half angle (s.upper). */
function solveCone(p: JointPass3D, j: number, a: number, b: number): void {
  const { s, sb, T, hs, useBias, bRate, ms, is } = p;
  const oa = BS3_STRIDE * a,
    ob = BS3_STRIDE * b;
  rot(qa, s.uax[j]!, s.uay[j]!, s.uaz[j]!, ax);
  rot(qb, s.ubx[j]!, s.uby[j]!, s.ubz[j]!, bx);
  let nx = ax[1]! * bx[2]! - ax[2]! * bx[1]!,
    ny = ax[2]! * bx[0]! - ax[0]! * bx[2]!,
    nz = ax[0]! * bx[1]! - ax[1]! * bx[0]!;
  const sn = Math.hypot(nx, ny, nz);
  if (sn > 1e-9) {
    nx /= sn;
    ny /= sn;
    nz /= sn;
    const phi = Math.atan2(sn, ax[0]! * bx[0]! + ax[1]! * bx[1]! + ax[2]! * bx[2]!);
    const C = s.upper[j]! - phi;
    let bias = 0,
      m = 1,
      im = 0;
    if (C > 0) bias = C / hs;
    else if (useBias) {
      bias = bRate * C;
      m = ms;
      im = is;
    }
    const cdot = -(
      (sb[ob + BS3_WX]! - sb[oa + BS3_WX]!) * nx +
      (sb[ob + BS3_WY]! - sb[oa + BS3_WY]!) * ny +
      (sb[ob + BS3_WZ]! - sb[oa + BS3_WZ]!) * nz
    );
    s.limit[j] = angularRow(sb, T, a, b, -nx, -ny, -nz, cdot, bias, m, im, s.limit[j]!, 0, Infinity);
  } else s.limit[j] = 0; // axes parallel: n undefined, far inside the cone; the row starts again from zero
}

/** A ball-and-socket joint: the point block, then its cone limit if it has one. */
export function solveBallRow3D(p: JointPass3D, j: number, a: number, b: number, flags: number): void {
  preparePointBlock(p, a, b);
  solvePointRows(p, j, a, b);
  if (flags & Joint3DFlag.Cone) solveCone(p, j, a, b);
}

/** A hinge: the two angular rows across its axis, its motor and limit, then the point block. */
export function solveHingeRow3D(p: JointPass3D, j: number, a: number, b: number, flags: number): void {
  errorRotation(p, j);
  solveAngularLock(p, j, a, b, true);
  if (flags & (Joint3DFlag.Limit | Joint3DFlag.Motor)) solveHingeAxial(p, j, a, b, flags);
  preparePointBlock(p, a, b);
  solvePointRows(p, j, a, b);
}

/** A fixed joint: the three angular rows, then the point block. */
export function solveFixedRow3D(p: JointPass3D, j: number, a: number, b: number, _flags: number): void {
  errorRotation(p, j);
  solveAngularLock(p, j, a, b, false);
  preparePointBlock(p, a, b);
  solvePointRows(p, j, a, b);
}

/** A slider: the three angular rows, the point block across its axis, then its motor and limit along it. */
export function solveSliderRow3D(p: JointPass3D, j: number, a: number, b: number, flags: number): void {
  errorRotation(p, j);
  solveAngularLock(p, j, a, b, false);
  preparePointBlock(p, a, b);
  solveSliderAxis(p, j, a, b, flags);
}
