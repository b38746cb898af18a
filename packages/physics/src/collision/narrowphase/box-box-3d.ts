import { M00, M01, M02, M10, M11, M12, M20, M21, M22 } from '../../math/mat3-layout.js';
import {
  BOX_A,
  BOX_ARGS,
  BOX_B,
  BOX_CX,
  BOX_CY,
  BOX_CZ,
  BOX_HX,
  BOX_HY,
  BOX_HZ,
  BOX_MARGIN,
  PLANE_ARGS,
  PLANE_BOX_CX,
  PLANE_BOX_CY,
  PLANE_BOX_CZ,
  PLANE_BOX_HX,
  PLANE_BOX_HY,
  PLANE_BOX_HZ,
  PLANE_D,
  PLANE_MARGIN,
  PLANE_NX,
  PLANE_NY,
  PLANE_NZ,
} from './box-args-3d.js';
import type { Manifold3D } from './manifold-3d.js';

/**
 * Box against box and box against plane, the common case of a pile, without posing either box's
 * hull: the manifold of two oriented boxes from their centres, rotations and half extents.
 *
 * - Separating axes (Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996; Ericson, Real-Time
 *   Collision Detection, 4.4.1): the three face normals of each box and the nine cross products of
 *   their edge directions, all measured in A's frame through C = R_A^T R_B, so a pair costs about a
 *   hundred multiplications. An edge axis is divided by its length |a_i x b_j| = sqrt(1 - C_ij^2) and
 *   skipped when the edges are parallel (a face axis covers them).
 * - Faces are preferred over edges unless an edge axis separates more by `EDGE_BIAS` of the smaller
 *   box's smallest half extent, and A's face over B's unless B's separates more by `FACE_BIAS` of it
 *   (the biases of Box2D and Bullet), so a resting box keeps its four corners and the reference face
 *   does not flicker between steps.
 * - Face contact: the incident face (B's face most opposed to the reference normal) clipped against
 *   the reference face's four side planes in the reference face's own 2D coordinates (Sutherland and
 *   Hodgman, 1974); up to eight points, reduced to four (collision/narrowphase/candidates-3d.ts's rule: the deepest, the
 *   farthest from it, the largest areas on either side). Edge contact: one point midway between the
 *   closest points of the two edges (Ericson 5.1.9).
 * - Feature ids: the reference face (box, axis, side), the incident face (axis, side), and the incident
 *   corner or the (incident edge, side plane) that cut a clipped point, so the solver's warm start finds
 *   the same point again while the same features touch.
 *
 * The normal points from A to B; each point lies midway between the surfaces; separation < 0 is overlap;
 * points farther apart than `margin` are dropped. Scratch is module-level and reused: no allocation.
 */

/** An edge axis must separate by this fraction of the smallest half extent more than the best face to be used. */
const EDGE_BIAS = 0.02;
/** B's face must separate by this fraction of the smallest half extent more than A's to be the reference. */
const FACE_BIAS = 0.005;

/**
 * The reference face is widened by this fraction of its half extents before clipping, so the corners of
 * an incident face of the same size (a box on an equal box) stay corners with their own ids instead of
 * flickering between corners and cut points at rounding level.
 */
const CLIP_SLACK = 0.01;

const C = new Float64Array(9),
  AC = new Float64Array(9);
// Incident polygon and clipping scratch: up to 8 points in reference-face coordinates (u, v, w) and ids.
const pu = new Float64Array(16),
  pv = new Float64Array(16),
  pw = new Float64Array(16),
  pid = new Float64Array(16);
const qu = new Float64Array(16),
  qv = new Float64Array(16),
  qw = new Float64Array(16),
  qid = new Float64Array(16);
// Candidate points (world) before the reduction to four.
const kx = new Float64Array(16),
  ky = new Float64Array(16),
  kz = new Float64Array(16),
  ks = new Float64Array(16),
  kid = new Float64Array(16);

/**
 * The manifold of box A (centre a, rotation at RA[oa] shape-to-world in the layout of math/mat3-layout.ts, half extents ea*)
 * against box B, or count 0 when farther apart than `margin` (m).
 * @category Collision
 */
export function boxBox3D(
  ax: number,
  ay: number,
  az: number,
  RA: Float64Array,
  oa: number,
  ea0: number,
  ea1: number,
  ea2: number,
  bx: number,
  by: number,
  bz: number,
  RB: Float64Array,
  ob: number,
  eb0: number,
  eb1: number,
  eb2: number,
  margin: number,
  out: Manifold3D,
): void {
  const g = boxArgs;
  g[BOX_A + BOX_CX] = ax;
  g[BOX_A + BOX_CY] = ay;
  g[BOX_A + BOX_CZ] = az;
  g[BOX_A + BOX_HX] = ea0;
  g[BOX_A + BOX_HY] = ea1;
  g[BOX_A + BOX_HZ] = ea2;
  g[BOX_B + BOX_CX] = bx;
  g[BOX_B + BOX_CY] = by;
  g[BOX_B + BOX_CZ] = bz;
  g[BOX_B + BOX_HX] = eb0;
  g[BOX_B + BOX_HY] = eb1;
  g[BOX_B + BOX_HZ] = eb2;
  g[BOX_MARGIN] = margin;
  boxBox3DAt(RA, oa, RB, ob, out);
}

/**
 * `boxBox3D`'s numbers, for `boxBox3DAt`: A's centre (m) and half extents (m), B's centre and half
 * extents, then the margin (m), in the layout of collision/narrowphase/box-args-3d.ts. A hot caller
 * writes them here instead of passing them: V8 boxes every double passed to a call it does not inline
 * (a heap number each, garbage every step).
 * @category Collision
 */
export const boxArgs = new Float64Array(BOX_ARGS);

/**
 * `boxBox3D` with its numbers read from `boxArgs` (A's centre, half extents, B's centre, half extents, margin).
 * @category Collision
 */
export function boxBox3DAt(RA: Float64Array, oa: number, RB: Float64Array, ob: number, out: Manifold3D): void {
  const g = boxArgs;
  const ax = g[BOX_A + BOX_CX]!,
    ay = g[BOX_A + BOX_CY]!,
    az = g[BOX_A + BOX_CZ]!,
    ea0 = g[BOX_A + BOX_HX]!,
    ea1 = g[BOX_A + BOX_HY]!,
    ea2 = g[BOX_A + BOX_HZ]!;
  const bx = g[BOX_B + BOX_CX]!,
    by = g[BOX_B + BOX_CY]!,
    bz = g[BOX_B + BOX_CZ]!,
    eb0 = g[BOX_B + BOX_HX]!,
    eb1 = g[BOX_B + BOX_HY]!,
    eb2 = g[BOX_B + BOX_HZ]!,
    margin = g[BOX_MARGIN]!;
  out.count = 0;
  const tx = bx - ax,
    ty = by - ay,
    tz = bz - az;
  // C_ij = a_i . b_j (columns of R are the box axes in the world).
  for (let i = 0; i < 3; i++) {
    const a0 = RA[oa + M00 + i]!,
      a1 = RA[oa + M10 + i]!,
      a2 = RA[oa + M20 + i]!;
    for (let j = 0; j < 3; j++) {
      const c = a0 * RB[ob + M00 + j]! + a1 * RB[ob + M10 + j]! + a2 * RB[ob + M20 + j]!;
      C[3 * i + j] = c;
      AC[3 * i + j] = Math.abs(c) + 1e-9;
    }
  }
  // t in A's frame and in B's frame.
  const ta0 = tx * RA[oa + M00]! + ty * RA[oa + M10]! + tz * RA[oa + M20]!;
  const ta1 = tx * RA[oa + M01]! + ty * RA[oa + M11]! + tz * RA[oa + M21]!;
  const ta2 = tx * RA[oa + M02]! + ty * RA[oa + M12]! + tz * RA[oa + M22]!;
  const tb0 = tx * RB[ob + M00]! + ty * RB[ob + M10]! + tz * RB[ob + M20]!;
  const tb1 = tx * RB[ob + M01]! + ty * RB[ob + M11]! + tz * RB[ob + M21]!;
  const tb2 = tx * RB[ob + M02]! + ty * RB[ob + M12]! + tz * RB[ob + M22]!;
  // A's faces.
  const sa0 = Math.abs(ta0) - ea0 - (eb0 * AC[0]! + eb1 * AC[1]! + eb2 * AC[2]!),
    sa1 = Math.abs(ta1) - ea1 - (eb0 * AC[3]! + eb1 * AC[4]! + eb2 * AC[5]!),
    sa2 = Math.abs(ta2) - ea2 - (eb0 * AC[6]! + eb1 * AC[7]! + eb2 * AC[8]!);
  const fA = largestOf3(sa0, sa1, sa2),
    sA = fA === 0 ? sa0 : fA === 1 ? sa1 : sa2;
  if (sA > margin) return;
  // B's faces.
  const sb0 = Math.abs(tb0) - eb0 - (ea0 * AC[0]! + ea1 * AC[3]! + ea2 * AC[6]!),
    sb1 = Math.abs(tb1) - eb1 - (ea0 * AC[1]! + ea1 * AC[4]! + ea2 * AC[7]!),
    sb2 = Math.abs(tb2) - eb2 - (ea0 * AC[2]! + ea1 * AC[5]! + ea2 * AC[8]!);
  const fB = largestOf3(sb0, sb1, sb2),
    sB = fB === 0 ? sb0 : fB === 1 ? sb1 : sb2;
  if (sB > margin) return;
  // Edge axes a_i x b_j.
  let sE = -Infinity,
    eI = -1,
    eJ = -1;
  for (let i = 0; i < 3; i++) {
    const i1 = i === 2 ? 0 : i + 1,
      i2 = i === 0 ? 2 : i - 1;
    const eai1 = i1 === 0 ? ea0 : i1 === 1 ? ea1 : ea2,
      eai2 = i2 === 0 ? ea0 : i2 === 1 ? ea1 : ea2;
    const tai1 = i1 === 0 ? ta0 : i1 === 1 ? ta1 : ta2,
      tai2 = i2 === 0 ? ta0 : i2 === 1 ? ta1 : ta2;
    for (let j = 0; j < 3; j++) {
      const cij = C[3 * i + j]!;
      const len2 = 1 - cij * cij;
      if (len2 < 1e-6) continue;
      const j1 = j === 2 ? 0 : j + 1,
        j2 = j === 0 ? 2 : j - 1;
      const ebj1 = j1 === 0 ? eb0 : j1 === 1 ? eb1 : eb2,
        ebj2 = j2 === 0 ? eb0 : j2 === 1 ? eb1 : eb2;
      const rA = eai1 * AC[3 * i2 + j]! + eai2 * AC[3 * i1 + j]!;
      const rB = ebj1 * AC[3 * i + j2]! + ebj2 * AC[3 * i + j1]!;
      const d = Math.abs(tai2 * C[3 * i1 + j]! - tai1 * C[3 * i2 + j]!);
      const s = (d - rA - rB) / Math.sqrt(len2);
      if (s > margin) return;
      if (s > sE) {
        sE = s;
        eI = i;
        eJ = j;
      }
    }
  }
  const size = Math.min(ea0, ea1, ea2, eb0, eb1, eb2);
  const faceBest = sA > sB ? sA : sB;
  if (eI >= 0 && sE > faceBest + EDGE_BIAS * size) {
    edgeContact(RA, oa, RB, ob, eI, eJ, out);
    return;
  }
  // faceContact reads the boxes' numbers from boxArgs: reference first when flipped is 0, else incident first.
  if (sB > sA + FACE_BIAS * size) {
    // B's face is the reference: A is the incident box; the normal comes out of B, flipped to A -> B.
    const tb = fB === 0 ? tb0 : fB === 1 ? tb1 : tb2;
    faceContact(RB, ob, fB, tb > 0 ? -1 : 1, RA, oa, out, 1);
    out.nx = -out.nx;
    out.ny = -out.ny;
    out.nz = -out.nz;
  } else {
    const tf = fA === 0 ? ta0 : fA === 1 ? ta1 : ta2;
    faceContact(RA, oa, fA, tf >= 0 ? 1 : -1, RB, ob, out, 0);
  }
}

/** Which of s0, s1, s2 is the largest: 0, 1 or 2, the first of equal ones (a NaN never wins over an earlier one). */
function largestOf3(s0: number, s1: number, s2: number): number {
  let s = s0,
    f = 0;
  if (s1 > s) {
    s = s1;
    f = 1;
  }
  return s2 > s ? 2 : f;
}

/**
 * Reference box R's face (axis k, side sg: normal sg r_k, pointing at the incident box I) against I's
 * most opposed face, clipped; writes the points and the normal (out of R) into `out`.
 */
function faceContact(
  RR: Float64Array,
  or: number,
  k: number,
  sg: number,
  RI: Float64Array,
  oi: number,
  out: Manifold3D,
  flipped: number,
): void {
  // Centre and half extents of the reference box R and the incident box I (boxArgs: A then B; R is B when flipped).
  const g = boxArgs,
    r = flipped === 0 ? BOX_A : BOX_B,
    io = flipped === 0 ? BOX_B : BOX_A,
    margin = g[BOX_MARGIN]!;
  const rx = g[r + BOX_CX]!,
    ry = g[r + BOX_CY]!,
    rz = g[r + BOX_CZ]!,
    er0 = g[r + BOX_HX]!,
    er1 = g[r + BOX_HY]!,
    er2 = g[r + BOX_HZ]!;
  const ix = g[io + BOX_CX]!,
    iy = g[io + BOX_CY]!,
    iz = g[io + BOX_CZ]!,
    ei0 = g[io + BOX_HX]!,
    ei1 = g[io + BOX_HY]!,
    ei2 = g[io + BOX_HZ]!;
  const k1 = k === 2 ? 0 : k + 1,
    k2 = k === 0 ? 2 : k - 1;
  const nx = sg * RR[or + M00 + k]!,
    ny = sg * RR[or + M10 + k]!,
    nz = sg * RR[or + M20 + k]!;
  const ux = RR[or + M00 + k1]!,
    uy = RR[or + M10 + k1]!,
    uz = RR[or + M20 + k1]!;
  const vx = RR[or + M00 + k2]!,
    vy = RR[or + M10 + k2]!,
    vz = RR[or + M20 + k2]!;
  const ek = k === 0 ? er0 : k === 1 ? er1 : er2,
    eu = k1 === 0 ? er0 : k1 === 1 ? er1 : er2,
    ev = k2 === 0 ? er0 : k2 === 1 ? er1 : er2;
  // Incident face: I's axis most (anti)parallel to n, on the side facing R.
  let m = 0,
    best = -1,
    dsg = 0;
  for (let j = 0; j < 3; j++) {
    const d = nx * RI[oi + M00 + j]! + ny * RI[oi + M10 + j]! + nz * RI[oi + M20 + j]!;
    if (Math.abs(d) > best) {
      best = Math.abs(d);
      m = j;
      dsg = d > 0 ? -1 : 1;
    }
  }
  const m1 = m === 2 ? 0 : m + 1,
    m2 = m === 0 ? 2 : m - 1;
  const em = m === 0 ? ei0 : m === 1 ? ei1 : ei2,
    e1 = m1 === 0 ? ei0 : m1 === 1 ? ei1 : ei2,
    e2 = m2 === 0 ? ei0 : m2 === 1 ? ei1 : ei2;
  // Face centre and its two half-edge vectors, in R's face coordinates (u, v, w) about R's centre.
  const fcx = ix + dsg * em * RI[oi + M00 + m]! - rx,
    fcy = iy + dsg * em * RI[oi + M10 + m]! - ry,
    fcz = iz + dsg * em * RI[oi + M20 + m]! - rz;
  const ax_ = e1 * RI[oi + M00 + m1]!,
    ay_ = e1 * RI[oi + M10 + m1]!,
    az_ = e1 * RI[oi + M20 + m1]!;
  const bx_ = e2 * RI[oi + M00 + m2]!,
    by_ = e2 * RI[oi + M10 + m2]!,
    bz_ = e2 * RI[oi + M20 + m2]!;
  const cu = fcx * ux + fcy * uy + fcz * uz,
    cv = fcx * vx + fcy * vy + fcz * vz,
    cw = fcx * nx + fcy * ny + fcz * nz;
  const au = ax_ * ux + ay_ * uy + az_ * uz,
    av = ax_ * vx + ay_ * vy + az_ * vz,
    aw = ax_ * nx + ay_ * ny + az_ * nz;
  const bu = bx_ * ux + by_ * uy + bz_ * uz,
    bv = bx_ * vx + by_ * vy + bz_ * vz,
    bw = bx_ * nx + by_ * ny + bz_ * nz;
  // The four corners in order (+a+b, -a+b, -a-b, +a-b); ids 0..3.
  pu[0] = cu + au + bu;
  pv[0] = cv + av + bv;
  pw[0] = cw + aw + bw;
  pid[0] = 0;
  pu[1] = cu - au + bu;
  pv[1] = cv - av + bv;
  pw[1] = cw - aw + bw;
  pid[1] = 1;
  pu[2] = cu - au - bu;
  pv[2] = cv - av - bv;
  pw[2] = cw - aw - bw;
  pid[2] = 2;
  pu[3] = cu + au - bu;
  pv[3] = cv + av - bv;
  pw[3] = cw + aw - bw;
  pid[3] = 3;
  faceHalf[0] = eu;
  faceHalf[1] = ev;
  const n = clipIncident();
  // After four passes the points are back in p*.
  out.nx = nx;
  out.ny = ny;
  out.nz = nz;
  const base = (((flipped * 3 + k) * 2 + (sg > 0 ? 1 : 0)) * 6 + 2 * m + (dsg > 0 ? 1 : 0)) * 256;
  let c = 0;
  for (let i = 0; i < n; i++) {
    const s = pw[i]! - ek;
    if (s > margin) continue;
    const w = pw[i]! - s / 2;
    kx[c] = rx + pu[i]! * ux + pv[i]! * vx + w * nx;
    ky[c] = ry + pu[i]! * uy + pv[i]! * vy + w * ny;
    kz[c] = rz + pu[i]! * uz + pv[i]! * vz + w * nz;
    ks[c] = s;
    kid[c] = base + pid[i]!;
    c++;
  }
  reduceToFour(c, out);
}

/** The reference face's half widths along u and v (m), for clipIncident: a typed array, so no double is passed to a call. */
const faceHalf = new Float64Array(2);

/**
 * Clips the incident face's four corners (p*, in the reference face's coordinates) against the reference
 * face's sides u <= eu, u >= -eu, v <= ev, v >= -ev (sides 0..3; eu, ev from faceHalf), each widened by
 * CLIP_SLACK (Sutherland and Hodgman); returns how many points are left, back in p* after the four passes.
 */
function clipIncident(): number {
  const eu = faceHalf[0]!,
    ev = faceHalf[1]!;
  let n = 4;
  for (let side = 0; side < 4 && n > 0; side++) {
    const useV = side >= 2,
      sgn = (side & 1) === 0 ? 1 : -1,
      lim = (useV ? ev : eu) * (1 + CLIP_SLACK);
    const src_u = (side & 1) === 0 ? pu : qu,
      src_v = (side & 1) === 0 ? pv : qv,
      src_w = (side & 1) === 0 ? pw : qw,
      src_id = (side & 1) === 0 ? pid : qid;
    const dst_u = (side & 1) === 0 ? qu : pu,
      dst_v = (side & 1) === 0 ? qv : pv,
      dst_w = (side & 1) === 0 ? qw : pw,
      dst_id = (side & 1) === 0 ? qid : pid;
    let m2c = 0;
    for (let i = 0; i < n; i++) {
      const j = i + 1 < n ? i + 1 : 0;
      const di = sgn * (useV ? src_v[i]! : src_u[i]!) - lim,
        dj = sgn * (useV ? src_v[j]! : src_u[j]!) - lim;
      if (di <= 0) {
        dst_u[m2c] = src_u[i]!;
        dst_v[m2c] = src_v[i]!;
        dst_w[m2c] = src_w[i]!;
        dst_id[m2c] = src_id[i]!;
        m2c++;
      }
      if (di <= 0 !== dj <= 0) {
        const t = di / (di - dj);
        dst_u[m2c] = src_u[i]! + (src_u[j]! - src_u[i]!) * t;
        dst_v[m2c] = src_v[i]! + (src_v[j]! - src_v[i]!) * t;
        dst_w[m2c] = src_w[i]! + (src_w[j]! - src_w[i]!) * t;
        // A cut point: the incident edge (its first corner's id, low 4 bits) cut by this side, entering or leaving.
        dst_id[m2c] = 16 + (src_id[i]! % 16) + 16 * (side + 4 * (di <= 0 ? 0 : 1));
        m2c++;
      }
    }
    n = m2c;
  }
  return n;
}

/** Edge a_i of A against edge b_j of B (the boxes' numbers in boxArgs, as boxBox3DAt reads them): one point between their closest points. */
function edgeContact(RA: Float64Array, oa: number, RB: Float64Array, ob: number, i: number, j: number, out: Manifold3D): void {
  // Half extent k of A at g[BOX_A + BOX_HX + k], of B at g[BOX_B + BOX_HX + k] (box-args-3d.ts).
  const g = boxArgs,
    ha = BOX_A + BOX_HX,
    hb = BOX_B + BOX_HX;
  const ax = g[BOX_A + BOX_CX]!,
    ay = g[BOX_A + BOX_CY]!,
    az = g[BOX_A + BOX_CZ]!;
  const bx = g[BOX_B + BOX_CX]!,
    by = g[BOX_B + BOX_CY]!,
    bz = g[BOX_B + BOX_CZ]!;
  const tx = bx - ax,
    ty = by - ay,
    tz = bz - az;
  const dax = RA[oa + M00 + i]!,
    day = RA[oa + M10 + i]!,
    daz = RA[oa + M20 + i]!;
  const dbx = RB[ob + M00 + j]!,
    dby = RB[ob + M10 + j]!,
    dbz = RB[ob + M20 + j]!;
  let nx = day * dbz - daz * dby,
    ny = daz * dbx - dax * dbz,
    nz = dax * dby - day * dbx;
  const l = Math.sqrt(nx * nx + ny * ny + nz * nz);
  nx /= l;
  ny /= l;
  nz /= l;
  if (nx * tx + ny * ty + nz * tz < 0) {
    nx = -nx;
    ny = -ny;
    nz = -nz;
  }
  // A's edge: the support of A along n among the edges parallel to a_i; B's along -n.
  let pax = ax,
    pay = ay,
    paz = az,
    pbx = bx,
    pby = by,
    pbz = bz,
    bitsA = 0,
    bitsB = 0;
  for (let k = 0; k < 3; k++) {
    if (k !== i) {
      const e = g[ha + k]!;
      const cx = RA[oa + M00 + k]!,
        cy = RA[oa + M10 + k]!,
        cz = RA[oa + M20 + k]!;
      const s = nx * cx + ny * cy + nz * cz > 0 ? 1 : -1;
      pax += s * e * cx;
      pay += s * e * cy;
      paz += s * e * cz;
      if (s > 0) bitsA |= 1 << k;
    }
    if (k !== j) {
      const e = g[hb + k]!;
      const cx = RB[ob + M00 + k]!,
        cy = RB[ob + M10 + k]!,
        cz = RB[ob + M20 + k]!;
      const s = nx * cx + ny * cy + nz * cz > 0 ? -1 : 1;
      pbx += s * e * cx;
      pby += s * e * cy;
      pbz += s * e * cz;
      if (s > 0) bitsB |= 1 << k;
    }
  }
  // Closest points of the two lines p_a + s d_a and p_b + t d_b (unit directions), clamped to the half lengths.
  const hA = g[ha + i]!,
    hB = g[hb + j]!;
  const rx = pax - pbx,
    ry = pay - pby,
    rz = paz - pbz;
  const b = dax * dbx + day * dby + daz * dbz,
    c = dax * rx + day * ry + daz * rz,
    f = dbx * rx + dby * ry + dbz * rz;
  const den = 1 - b * b;
  let s = den > 1e-12 ? (b * f - c) / den : 0;
  s = s < -hA ? -hA : s > hA ? hA : s;
  let t = b * s + f;
  if (t < -hB) {
    t = -hB;
    s = -c - b * hB;
    s = s < -hA ? -hA : s > hA ? hA : s;
  } else if (t > hB) {
    t = hB;
    s = -c + b * hB;
    s = s < -hA ? -hA : s > hA ? hA : s;
  }
  const qax = pax + dax * s,
    qay = pay + day * s,
    qaz = paz + daz * s;
  const qbx = pbx + dbx * t,
    qby = pby + dby * t,
    qbz = pbz + dbz * t;
  const sep = (qbx - qax) * nx + (qby - qay) * ny + (qbz - qaz) * nz;
  if (sep > g[BOX_MARGIN]!) return;
  out.nx = nx;
  out.ny = ny;
  out.nz = nz;
  out.x[0] = (qax + qbx) / 2;
  out.y[0] = (qay + qby) / 2;
  out.z[0] = (qaz + qbz) / 2;
  out.sep[0] = sep;
  out.id[0] = 2 ** 32 + ((i * 3 + j) * 8 + bitsA) * 8 + bitsB;
  out.count = 1;
}

/**
 * A plane n . x = d (solid below, A) against box B (centre c, rotation at R[o] (math/mat3-layout.ts), half extents e*):
 * the corners below the margin, reduced to four; normal the plane's; ids the corner numbers.
 * @category Collision
 */
export function planeBox3D(
  nx: number,
  ny: number,
  nz: number,
  d: number,
  cx: number,
  cy: number,
  cz: number,
  R: Float64Array,
  o: number,
  e0: number,
  e1: number,
  e2: number,
  margin: number,
  out: Manifold3D,
): void {
  const g = planeArgs;
  g[PLANE_NX] = nx;
  g[PLANE_NY] = ny;
  g[PLANE_NZ] = nz;
  g[PLANE_D] = d;
  g[PLANE_BOX_CX] = cx;
  g[PLANE_BOX_CY] = cy;
  g[PLANE_BOX_CZ] = cz;
  g[PLANE_BOX_HX] = e0;
  g[PLANE_BOX_HY] = e1;
  g[PLANE_BOX_HZ] = e2;
  g[PLANE_MARGIN] = margin;
  planeBox3DAt(R, o, out);
}

/**
 * `planeBox3D`'s numbers for `planeBox3DAt` (see `boxArgs`): the plane's n and d, the box's centre and half extents, the margin (collision/narrowphase/box-args-3d.ts).
 * @category Collision
 */
export const planeArgs = new Float64Array(PLANE_ARGS);

/**
 * `planeBox3D` with its numbers read from `planeArgs`.
 * @category Collision
 */
export function planeBox3DAt(R: Float64Array, o: number, out: Manifold3D): void {
  const g = planeArgs;
  const nx = g[PLANE_NX]!,
    ny = g[PLANE_NY]!,
    nz = g[PLANE_NZ]!,
    d = g[PLANE_D]!,
    cx = g[PLANE_BOX_CX]!,
    cy = g[PLANE_BOX_CY]!,
    cz = g[PLANE_BOX_CZ]!,
    e0 = g[PLANE_BOX_HX]!,
    e1 = g[PLANE_BOX_HY]!,
    e2 = g[PLANE_BOX_HZ]!,
    margin = g[PLANE_MARGIN]!;
  out.count = 0;
  out.nx = nx;
  out.ny = ny;
  out.nz = nz;
  const c0 = cx * nx + cy * ny + cz * nz - d;
  // Corner heights above the plane: c0 +- e_k (n . r_k).
  const h0 = e0 * (nx * R[o + M00]! + ny * R[o + M10]! + nz * R[o + M20]!),
    h1 = e1 * (nx * R[o + M01]! + ny * R[o + M11]! + nz * R[o + M21]!),
    h2 = e2 * (nx * R[o + M02]! + ny * R[o + M12]! + nz * R[o + M22]!);
  if (c0 - Math.abs(h0) - Math.abs(h1) - Math.abs(h2) > margin) return;
  let c = 0;
  for (let v = 0; v < 8; v++) {
    const s0 = v & 1 ? 1 : -1,
      s1 = v & 2 ? 1 : -1,
      s2 = v & 4 ? 1 : -1;
    const s = c0 + s0 * h0 + s1 * h1 + s2 * h2;
    if (s > margin) continue;
    const x = cx + s0 * e0 * R[o + M00]! + s1 * e1 * R[o + M01]! + s2 * e2 * R[o + M02]!;
    const y = cy + s0 * e0 * R[o + M10]! + s1 * e1 * R[o + M11]! + s2 * e2 * R[o + M12]!;
    const z = cz + s0 * e0 * R[o + M20]! + s1 * e1 * R[o + M21]! + s2 * e2 * R[o + M22]!;
    kx[c] = x - (nx * s) / 2;
    ky[c] = y - (ny * s) / 2;
    kz[c] = z - (nz * s) / 2;
    ks[c] = s;
    kid[c] = v;
    c++;
  }
  reduceToFour(c, out);
}

/** Copies the c candidates into `out` (its normal already set), reduced to four when more (the deepest, the farthest from it, the largest areas either side). */
function reduceToFour(c: number, out: Manifold3D): void {
  const nx = out.nx,
    ny = out.ny,
    nz = out.nz;
  if (c <= 4) {
    for (let i = 0; i < c; i++) {
      out.x[i] = kx[i]!;
      out.y[i] = ky[i]!;
      out.z[i] = kz[i]!;
      out.sep[i] = ks[i]!;
      out.id[i] = kid[i]!;
    }
    out.count = c;
    return;
  }
  let a = 0;
  for (let i = 1; i < c; i++) if (ks[i]! < ks[a]!) a = i;
  let b = -1,
    far = -1;
  for (let i = 0; i < c; i++) {
    const d = (kx[i]! - kx[a]!) ** 2 + (ky[i]! - ky[a]!) ** 2 + (kz[i]! - kz[a]!) ** 2;
    if (d > far) {
      far = d;
      b = i;
    }
  }
  const ux = kx[b]! - kx[a]!,
    uy = ky[b]! - ky[a]!,
    uz = kz[b]! - kz[a]!;
  let p = -1,
    q = -1,
    maxA = 0,
    minA = 0;
  for (let i = 0; i < c; i++) {
    const vx = kx[i]! - kx[a]!,
      vy = ky[i]! - ky[a]!,
      vz = kz[i]! - kz[a]!;
    const s = nx * (uy * vz - uz * vy) + ny * (uz * vx - ux * vz) + nz * (ux * vy - uy * vx);
    if (s > maxA) {
      maxA = s;
      p = i;
    }
    if (s < minA) {
      minA = s;
      q = i;
    }
  }
  let n = 0;
  for (let r = 0; r < 4; r++) {
    const i = r === 0 ? a : r === 1 ? b : r === 2 ? p : q;
    if (i < 0) continue;
    out.x[n] = kx[i]!;
    out.y[n] = ky[i]!;
    out.z[n] = kz[i]!;
    out.sep[n] = ks[i]!;
    out.id[n] = kid[i]!;
    n++;
  }
  out.count = n;
}
