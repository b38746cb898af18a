import { type ContactBuffer, ContactKind } from '../collision/contacts.js';
import type { PhysicsWorld } from '../world/options.js';
import * as BS from './body-state-layout.js';
import { ballMotion, faceMotion, motionIO } from './impact-motion.js';
import { impactScalars, markChanged, sweepIO } from './impact-state.js';

/** One impact of the impact stage (solver/impacts.ts): a contact's state at its time of impact (swept), and the impulse that stops or bounces it. */

/**
 * Cheap test before the sweep: whether the bodies of contact i move apart fast enough, relative to
 * each other, that they could hit at more than the resting speed floor (`impactScalars[0]`, m/s)
 * within the step (|w| + g h > floor, g h = `impactScalars[1]`).
 */
export function fastEnough(sb: Float64Array, buf: ContactBuffer, i: number, S: number): boolean {
  const floor = impactScalars[0]!,
    gh = impactScalars[1]!;
  if (floor === 0) return true;
  const oa = buf.ia[i]! * S,
    ob = buf.ib[i]! * S;
  const wx = sb[ob + BS.BS2_VX]! - sb[oa + BS.BS2_VX]!,
    wy = sb[ob + BS.BS2_VY]! - sb[oa + BS.BS2_VY]!,
    wz = S === BS.BS2_STRIDE ? 0 : sb[ob + BS.BS3_VZ]! - sb[oa + BS.BS3_VZ]!;
  const lim = floor - gh;
  return lim <= 0 || wx * wx + wy * wy + wz * wz > lim * lim;
}

/** Scratch of `contactState`: time of impact, normal, relative normal velocity at t*. */
const hit = new Float64Array(5);

/**
 * Time of impact of contact i at the bodies' current solver state: writes [t*, nx, ny, nz, v_n(t*)]
 * into `hit` and returns true if the bodies touch within the step while approaching.
 */
export function contactState(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number): boolean {
  const imp = world.collision.bodyImpact;
  const qa = buf.ia[i]! * BS.IMPACT_STRIDE,
    qb = buf.ib[i]! * BS.IMPACT_STRIDE;
  const t0 = Math.max(imp[qa + BS.BI_TIME]!, imp[qb + BS.BI_TIME]!);
  if (t0 > world.h) return false;
  const kind = buf.kind[i]!;
  return kind === ContactKind.Ball || kind === ContactKind.StaticBall ? ballsHit(world, buf, i, S, t0) : faceHit(world, buf, i, S, t0);
}

/** contactState of ball contact i from t0 (s): the sweep of the balls' relative path from there, refined once for gravity. */
function ballsHit(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number, t0: number): boolean {
  const h = world.h;
  // Relative position and velocity at t0: r = r0 + d_offsets + w t0 + a t0^2 / 2, u = w + a t0.
  ballMotion(world, buf, i, S, t0);
  const io = sweepIO;
  let rx = io[0]!,
    ry = io[1]!,
    rz = io[2]!,
    ux = io[3]!,
    uy = io[4]!,
    uz = io[5]!;
  const R = io[6]!;
  const ax = motionIO[0]!,
    ay = motionIO[1]!,
    az = motionIO[2]!;
  const c0 = rx * rx + ry * ry + rz * rz - R * R;
  let t = 0;
  if (c0 > 0) {
    const span = h - t0;
    io[7] = span;
    sweep();
    t = io[8]!;
    if (t < 0 && (ax !== 0 || ay !== 0 || az !== 0)) {
      // Gravity bends the relative path: sweep again with the velocity at the middle of the span.
      io[3] = ux + 0.5 * ax * span;
      io[4] = uy + 0.5 * ay * span;
      io[5] = uz + 0.5 * az * span;
      sweep();
      t = io[8]!;
    } else if (t >= 0 && (ax !== 0 || ay !== 0 || az !== 0)) {
      // Refine with the mean velocity over [0, t].
      io[3] = ux + 0.5 * ax * t;
      io[4] = uy + 0.5 * ay * t;
      io[5] = uz + 0.5 * az * t;
      sweep();
      const t2 = io[8]!;
      if (t2 >= 0) t = t2;
    }
    if (t < 0) return false;
    rx += ux * t + 0.5 * ax * t * t;
    ry += uy * t + 0.5 * ay * t * t;
    rz += uz * t + 0.5 * az * t * t;
    ux += ax * t;
    uy += ay * t;
    uz += az * t;
  }
  const d = Math.sqrt(rx * rx + ry * ry + rz * rz);
  if (!(d > 1e-12 * R)) return false;
  const nx = rx / d,
    ny = ry / d,
    nz = rz / d;
  const vn = ux * nx + uy * ny + uz * nz;
  if (!(vn < 0)) return false;
  return hitAt(t0 + t, nx, ny, nz, vn);
}

/** contactState of fixed-normal contact i (boundary face, plane, segment) from t0 (s): the gap's quadratic along the normal. */
function faceHit(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number, t0: number): boolean {
  faceMotion(world, buf, i, S, t0);
  const s = motionIO[0]!,
    v = motionIO[1]!,
    an = motionIO[2]!;
  let t = 0;
  if (s > 0) {
    const disc = v * v - 2 * an * s;
    if (disc < 0) return false;
    const den = -v + Math.sqrt(disc);
    if (!(den > 0)) return false;
    t = (2 * s) / den;
    if (t0 + t > world.h) return false;
  }
  const vn = v + an * t;
  if (!(vn < 0)) return false;
  return hitAt(t0 + t, buf.nx[i]!, buf.ny[i]!, buf.nz[i]!, vn);
}

/** Writes a contact's time of impact t (s), normal n and relative normal velocity vn (m/s) into `hit`; returns true. */
function hitAt(t: number, nx: number, ny: number, nz: number, vn: number): boolean {
  hit[0] = t;
  hit[1] = nx;
  hit[2] = ny;
  hit[3] = nz;
  hit[4] = vn;
  return true;
}

/**
 * Smallest t in [0, span] with |r + u t| = R for r outside the sphere, or -1: r, u, R and span read
 * from `sweepIO` (slots 0-7), t written to its slot 8; returns whether t >= 0.
 */
export function sweep(): boolean {
  const io = sweepIO;
  const rx = io[0]!,
    ry = io[1]!,
    rz = io[2]!,
    ux = io[3]!,
    uy = io[4]!,
    uz = io[5]!,
    R = io[6]!,
    span = io[7]!;
  io[8] = -1;
  const cc = rx * rx + ry * ry + rz * rz - R * R;
  const bb = rx * ux + ry * uy + rz * uz;
  if (bb >= 0) return false;
  const aa = ux * ux + uy * uy + uz * uz;
  const disc = bb * bb - aa * cc;
  if (disc < 0) return false;
  // Stable root: t = c / (-b + sqrt(disc)).
  const t = cc / (-bb + Math.sqrt(disc));
  if (!(t <= span)) return false;
  io[8] = t;
  return t >= 0;
}

/**
 * Applies contact i's impact if it happens this step above its threshold (at least the resting speed,
 * `impactScalars[0]`); returns whether it did.
 */
export function impact(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number): boolean {
  if (!contactState(world, buf, i, S)) return false;
  const resting = impactScalars[0]!;
  const cs = world.collision;
  const st = cs.settings;
  const e = buf.restitution[i]!;
  const vn = hit[4]!;
  const threshold = Math.max(e >= 1 ? st.elasticRestitutionThreshold : st.restitutionThreshold, resting);
  if (!(vn < -threshold)) return false;
  const nm = buf.normalMass[i]!;
  if (!(nm > 0)) return false;
  const t = hit[0]!,
    nx = hit[1]!,
    ny = hit[2]!,
    nz = hit[3]!;
  const sb = cs.bodyState,
    imp = cs.bodyImpact,
    ex = cs.bodyExtra;
  const ia = buf.ia[i]!,
    ib = buf.ib[i]!;
  const oa = ia * S,
    ob = ib * S;
  const is2D = S === BS.BS2_STRIDE;
  const im = is2D ? BS.BS2_INV_MASS : BS.BS3_INV_MASS,
    iI = is2D ? BS.BS2_INV_INERTIA : BS.BS3_INV_INERTIA;
  const imA = sb[oa + im]!,
    imB = sb[ob + im]!,
    iiA = sb[oa + iI]!,
    iiB = sb[ob + iI]!;
  const ra = buf.ra[i]!,
    rb = buf.rb[i]!;
  const J = -(1 + e) * vn * nm;
  // The row's first impact this step records its approach speed (measureApproach keeps it for a row
  // that separates afterwards, so `impactVelocity` reports the hit, not the rebound).
  if (buf.impulse[i] === 0) buf.impactVelocity[i] = vn;
  let Px = J * nx,
    Py = J * ny,
    Pz = J * nz;
  // Coulomb friction at the contact point, bounded by mu J (contact-point velocity v + w x r, r_A = ra n, r_B = -rb n).
  const mu = buf.frictionBound[i]!;
  let dwa0 = 0,
    dwa1 = 0,
    dwa2 = 0,
    dwb0 = 0,
    dwb1 = 0,
    dwb2 = 0;
  if (mu > 0 && buf.tangentMass[i]! > 0) {
    const tm = buf.tangentMass[i]!;
    const maxF = mu * J;
    if (is2D) {
      const vt =
        (sb[ob + BS.BS2_VX]! - sb[oa + BS.BS2_VX]!) * -ny +
        (sb[ob + BS.BS2_VY]! - sb[oa + BS.BS2_VY]!) * nx -
        sb[ob + BS.BS2_W]! * rb -
        sb[oa + BS.BS2_W]! * ra;
      let lt = -tm * vt;
      lt = lt < -maxF ? -maxF : lt > maxF ? maxF : lt;
      Px += -lt * ny;
      Py += lt * nx;
      dwa2 = -iiA * ra * lt;
      dwb2 = -iiB * rb * lt;
    } else {
      let t1x: number, t1y: number, t1z: number;
      if (Math.abs(nx) < 0.57735) {
        const inv = 1 / Math.sqrt(ny * ny + nz * nz);
        t1x = 0;
        t1y = nz * inv;
        t1z = -ny * inv;
      } else {
        const inv = 1 / Math.sqrt(nx * nx + ny * ny);
        t1x = ny * inv;
        t1y = -nx * inv;
        t1z = 0;
      }
      const t2x = ny * t1z - nz * t1y,
        t2y = nz * t1x - nx * t1z,
        t2z = nx * t1y - ny * t1x;
      const sx = -rb * sb[ob + BS.BS3_WX]! - ra * sb[oa + BS.BS3_WX]!,
        sy = -rb * sb[ob + BS.BS3_WY]! - ra * sb[oa + BS.BS3_WY]!,
        sz = -rb * sb[ob + BS.BS3_WZ]! - ra * sb[oa + BS.BS3_WZ]!;
      const ux = sb[ob + BS.BS3_VX]! - sb[oa + BS.BS3_VX]! + sy * nz - sz * ny,
        uy = sb[ob + BS.BS3_VY]! - sb[oa + BS.BS3_VY]! + sz * nx - sx * nz,
        uz = sb[ob + BS.BS3_VZ]! - sb[oa + BS.BS3_VZ]! + sx * ny - sy * nx;
      let l1 = -tm * (ux * t1x + uy * t1y + uz * t1z),
        l2 = -tm * (ux * t2x + uy * t2y + uz * t2z);
      const mag2 = l1 * l1 + l2 * l2;
      if (mag2 > maxF * maxF) {
        const q = maxF / Math.sqrt(mag2);
        l1 *= q;
        l2 *= q;
      }
      const Tx = l1 * t1x + l2 * t2x,
        Ty = l1 * t1y + l2 * t2y,
        Tz = l1 * t1z + l2 * t2z;
      Px += Tx;
      Py += Ty;
      Pz += Tz;
      const cx = ny * Tz - nz * Ty,
        cy = nz * Tx - nx * Tz,
        cz = nx * Ty - ny * Tx;
      dwa0 = -iiA * ra * cx;
      dwa1 = -iiA * ra * cy;
      dwa2 = -iiA * ra * cz;
      dwb0 = -iiB * rb * cx;
      dwb1 = -iiB * rb * cy;
      dwb2 = -iiB * rb * cz;
    }
  }
  const qa = ia * BS.IMPACT_STRIDE,
    qb = ib * BS.IMPACT_STRIDE;
  const xa = ia * BS.BX_STRIDE,
    xb = ib * BS.BX_STRIDE;
  // Velocity changes; positions corrected by -dv t (the bodies kept the old velocity until t).
  sb[oa + BS.BS2_VX] = sb[oa + BS.BS2_VX]! - imA * Px;
  sb[oa + BS.BS2_VY] = sb[oa + BS.BS2_VY]! - imA * Py;
  sb[ob + BS.BS2_VX] = sb[ob + BS.BS2_VX]! + imB * Px;
  sb[ob + BS.BS2_VY] = sb[ob + BS.BS2_VY]! + imB * Py;
  imp[qa + BS.BI_CORR_X] = imp[qa + BS.BI_CORR_X]! + imA * Px * t;
  imp[qa + BS.BI_CORR_Y] = imp[qa + BS.BI_CORR_Y]! + imA * Py * t;
  imp[qb + BS.BI_CORR_X] = imp[qb + BS.BI_CORR_X]! - imB * Px * t;
  imp[qb + BS.BI_CORR_Y] = imp[qb + BS.BI_CORR_Y]! - imB * Py * t;
  if (is2D) {
    if (iiA > 0) {
      sb[oa + BS.BS2_W] = sb[oa + BS.BS2_W]! + dwa2;
      ex[xa + BS.BX_ROT_Z] = ex[xa + BS.BX_ROT_Z]! - dwa2 * t;
    }
    if (iiB > 0) {
      sb[ob + BS.BS2_W] = sb[ob + BS.BS2_W]! + dwb2;
      ex[xb + BS.BX_ROT_Z] = ex[xb + BS.BX_ROT_Z]! - dwb2 * t;
    }
  } else {
    sb[oa + BS.BS3_VZ] = sb[oa + BS.BS3_VZ]! - imA * Pz;
    sb[ob + BS.BS3_VZ] = sb[ob + BS.BS3_VZ]! + imB * Pz;
    imp[qa + BS.BI_CORR_Z] = imp[qa + BS.BI_CORR_Z]! + imA * Pz * t;
    imp[qb + BS.BI_CORR_Z] = imp[qb + BS.BI_CORR_Z]! - imB * Pz * t;
    if (iiA > 0) spinChange3D(sb, ex, oa, xa, dwa0, dwa1, dwa2, t);
    if (iiB > 0) spinChange3D(sb, ex, ob, xb, dwb0, dwb1, dwb2, t);
  }
  if (ia !== 0 && imA > 0) imp[qa + BS.BI_TIME] = t;
  if (imB > 0) imp[qb + BS.BI_TIME] = t;
  buf.nx[i] = nx;
  buf.ny[i] = ny;
  buf.nz[i] = nz;
  markChanged(i);
  buf.impulse[i] = buf.impulse[i]! + J;
  return true;
}

/**
 * Adds an impact's spin change (d0, d1, d2), rad/s, to the 3D solver body whose packed state starts at
 * `o` and extra row at `x`, and takes d t off the rotation it still owes (rad): it kept its old spin
 * until the time of impact t (s).
 */
function spinChange3D(sb: Float64Array, ex: Float64Array, o: number, x: number, d0: number, d1: number, d2: number, t: number): void {
  sb[o + BS.BS3_WX] = sb[o + BS.BS3_WX]! + d0;
  sb[o + BS.BS3_WY] = sb[o + BS.BS3_WY]! + d1;
  sb[o + BS.BS3_WZ] = sb[o + BS.BS3_WZ]! + d2;
  ex[x + BS.BX_ROT_X] = ex[x + BS.BX_ROT_X]! - d0 * t;
  ex[x + BS.BX_ROT_Y] = ex[x + BS.BX_ROT_Y]! - d1 * t;
  ex[x + BS.BX_ROT_Z] = ex[x + BS.BX_ROT_Z]! - d2 * t;
}
