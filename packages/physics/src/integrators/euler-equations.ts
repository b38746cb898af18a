import { hasComponent } from 'bitecs';
import { rotateVector, rotateVectorInverse } from '../math/quaternion.js';
import type { PhysicsWorld } from '../world/options.js';

const b = new Float64Array(3),
  t = new Float64Array(3),
  ab = new Float64Array(3);

/**
 * Angular acceleration of a 3D body with principal moments (Ix, Iy, Iz) from Euler's equations,
 * I dw/dt = tau - w x (I w), evaluated in the body frame (where I is diagonal) and rotated back:
 * alpha = R I^-1 (R^T tau - w_b x I w_b), w_b = R^T w. Writes into res[0..2] (rad/s^2).
 * Source: Goldstein, Classical Mechanics (3rd ed.), sec. 5.5; Ramtal and Dobre ch. 15.
 * @category Integrators
 */
export function eulerAcceleration(
  world: PhysicsWorld,
  e: number,
  torqueX: number,
  torqueY: number,
  torqueZ: number,
  res: Float64Array,
): void {
  eulerBodyAcceleration(world, e, torqueX, torqueY, torqueZ, ab);
  const q = world.components.Orientation;
  rotateVector(q.x[e]!, q.y[e]!, q.z[e]!, q.w[e]!, ab[0]!, ab[1]!, ab[2]!, res);
}

/**
 * Euler's equations in the body frame: alpha_b = I^-1 (R^T tau - w_b x I w_b), w_b = R^T w, for a 3D
 * body with principal moments (Ix, Iy, Iz) (rad/s^2, body axes; an axis with a zero moment gets 0).
 * The explicit schemes stage these bodies' angular velocity in the body frame (see
 * integrators/state.ts). Writes into res[0..2]. Source: Goldstein, Classical Mechanics (3rd ed.), sec. 5.5.
 * @category Integrators
 */
export function eulerBodyAcceleration(
  world: PhysicsWorld,
  e: number,
  torqueX: number,
  torqueY: number,
  torqueZ: number,
  res: Float64Array,
): void {
  const c = world.components;
  const q = c.Orientation,
    T = c.InertiaTensor;
  const qx = q.x[e]!,
    qy = q.y[e]!,
    qz = q.z[e]!,
    qw = q.w[e]!;
  rotateVectorInverse(qx, qy, qz, qw, c.AngularVelocity.x[e]!, c.AngularVelocity.y[e]!, c.AngularVelocity.z[e]!, b);
  rotateVectorInverse(qx, qy, qz, qw, torqueX, torqueY, torqueZ, t);
  const wx = b[0]!,
    wy = b[1]!,
    wz = b[2]!;
  const Lx = T.x[e]! * wx,
    Ly = T.y[e]! * wy,
    Lz = T.z[e]! * wz;
  res[0] = (t[0]! - (wy * Lz - wz * Ly)) * T.invX[e]!;
  res[1] = (t[1]! - (wz * Lx - wx * Lz)) * T.invY[e]!;
  res[2] = (t[2]! - (wx * Ly - wy * Lx)) * T.invZ[e]!;
}

/**
 * Semi-implicit Euler's rotation step for a body with a principal inertia tensor: a torque kick
 * L += h tau, then the free rigid-body flow split into exact rotations about the principal axes in
 * the symmetric sequence x(h/2) y(h/2) z(h) y(h/2) x(h/2), each turning the body by h L_k / I_k about
 * its axis k (Dullweber, Leimkuhler and McLachlan, J. Chem. Phys. 107, 1997; Hairer, Lubich and
 * Wanner, Geometric Numerical Integration, VII.5). Symplectic and second order for the free flow:
 * |L| is conserved exactly, the energy error stays bounded (no drift), orientation and angular
 * velocity stay consistent. Updates both the angular velocity and the orientation. Axes with a zero
 * moment stay locked. An isotropic body (equal principal moments, none zero) takes the exact flow
 * instead, which the splitting only approximates: w fixed in the world, one turn by |w| h about it. The orientation is renormalised at the end (divided by its length, the square
 * root of its components' squares). Runs over the bodies `ents` (entity ids, each with a principal
 * inertia tensor), the torque read from each body's `Torque` (zero for a body without one), rad/s and
 * unit quaternions written in place. The loop is here, not in the caller, and no double crosses a
 * call: everything is in locals, the five turns included (one loop over the axes): no allocation
 * per body (heap use over repeated calls, node 20).
 * @category Integrators
 */
export function splitRigidRotations(world: PhysicsWorld, ents: ArrayLike<number>, h: number): void {
  const c = world.components;
  const q = c.Orientation,
    T = c.InertiaTensor,
    W = c.AngularVelocity,
    Tq = c.Torque;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const has = hasComponent(world, e, Tq);
    const torqueX = has ? Tq.x[e]! : 0,
      torqueY = has ? Tq.y[e]! : 0,
      torqueZ = has ? Tq.z[e]! : 0;
    const Ix = T.x[e]!,
      Iy = T.y[e]!,
      Iz = T.z[e]!,
      ix = T.invX[e]!,
      iy = T.invY[e]!,
      iz = T.invZ[e]!;
    let x = q.x[e]!,
      y = q.y[e]!,
      z = q.z[e]!,
      w = q.w[e]!;
    if (ix === iy && iy === iz && ix > 0) {
      // Isotropic (a cube, a sphere): I^-1 L is parallel to L, so the free flow keeps w fixed in the world
      // and turns the body by |w| h about it; the five turns below would approximate that to O(h^3).
      // The kick (w += h I^-1 tau), then that one exact turn: q <- (sin(|w| h / 2) w / |w|, cos(|w| h / 2)) q.
      const ox = W.x[e]! + h * torqueX * ix,
        oy = W.y[e]! + h * torqueY * ix,
        oz = W.z[e]! + h * torqueZ * ix;
      const angle = Math.sqrt(ox * ox + oy * oy + oz * oz) * h;
      if (angle > 0) {
        const k = (Math.sin(0.5 * angle) / angle) * h,
          dx = ox * k,
          dy = oy * k,
          dz = oz * k,
          dw = Math.cos(0.5 * angle);
        // Renormalised here, not by storeUnitQuaternion: V8 does not always inline a call, and one that is
        // not boxes each double argument (16 bytes a number, a body, a step).
        const nx = dw * x + dx * w + dy * z - dz * y,
          ny = dw * y - dx * z + dy * w + dz * x,
          nz = dw * z + dx * y - dy * x + dz * w,
          nw = dw * w - dx * x - dy * y - dz * z;
        const n = 1 / Math.sqrt(nx * nx + ny * ny + nz * nz + nw * nw);
        q.x[e] = nx * n;
        q.y[e] = ny * n;
        q.z[e] = nz * n;
        q.w[e] = nw * n;
      }
      W.x[e] = ox;
      W.y[e] = oy;
      W.z[e] = oz;
      continue;
    }
    // World momentum plus the torque kick, then into the body frame (v' = v + w t + u x t, t = 2 u x v,
    // u the quaternion's vector part; its conjugate for world to body).
    const wx = W.x[e]!,
      wy = W.y[e]!,
      wz = W.z[e]!;
    let tx = 2 * (-y * wz + z * wy),
      ty = 2 * (-z * wx + x * wz),
      tz = 2 * (-x * wy + y * wx);
    const bx = (wx + w * tx + (-y * tz + z * ty)) * Ix,
      by = (wy + w * ty + (-z * tx + x * tz)) * Iy,
      bz = (wz + w * tz + (-x * ty + y * tx)) * Iz;
    tx = 2 * (y * bz - z * by);
    ty = 2 * (z * bx - x * bz);
    tz = 2 * (x * by - y * bx);
    const lx = bx + w * tx + (y * tz - z * ty) + h * torqueX,
      ly = by + w * ty + (z * tx - x * tz) + h * torqueY,
      lz = bz + w * tz + (x * ty - y * tx) + h * torqueZ;
    tx = 2 * (-y * lz + z * ly);
    ty = 2 * (-z * lx + x * lz);
    tz = 2 * (-x * ly + y * lx);
    let L0 = lx + w * tx + (-y * tz + z * ty),
      L1 = ly + w * ty + (-z * tx + x * tz),
      L2 = lz + w * tz + (-x * ty + y * tx);
    if (ix === 0) L0 = 0;
    if (iy === 0) L1 = 0;
    if (iz === 0) L2 = 0;
    // The five turns about body axes k = 0, 1, 2, 1, 0 by a = (h/2, h/2, h, h/2, h/2) L_k / I_k: the body
    // turns by +a about its axis k, so in the body frame the (fixed) world momentum turns by -a, and
    // q <- q (cos a/2, sin a/2 e_k) (a rotation about a body axis multiplies on the right).
    const hh = 0.5 * h;
    for (let step = 0; step < 5; step++) {
      const k = step < 3 ? step : 4 - step;
      const a = k === 0 ? hh * (L0 * ix) : k === 1 ? hh * (L1 * iy) : h * (L2 * iz);
      if (a === 0) continue;
      const cs = Math.cos(a),
        sn = Math.sin(a);
      if (k === 0) {
        const li = L1;
        L1 = cs * li + sn * L2;
        L2 = -sn * li + cs * L2;
      } else if (k === 1) {
        const li = L2;
        L2 = cs * li + sn * L0;
        L0 = -sn * li + cs * L0;
      } else {
        const li = L0;
        L0 = cs * li + sn * L1;
        L1 = -sn * li + cs * L1;
      }
      const hs = Math.sin(0.5 * a),
        dw = Math.cos(0.5 * a),
        dx = k === 0 ? hs : 0,
        dy = k === 1 ? hs : 0,
        dz = k === 2 ? hs : 0;
      const nx = w * dx + x * dw + y * dz - z * dy,
        ny = w * dy - x * dz + y * dw + z * dx;
      const nz = w * dz + x * dy - y * dx + z * dw,
        nw = w * dw - x * dx - y * dy - z * dz;
      x = nx;
      y = ny;
      z = nz;
      w = nw;
    }
    // Renormalised in place (as above, no call with doubles), then read back as stored.
    const n = 1 / Math.sqrt(x * x + y * y + z * z + w * w);
    q.x[e] = x * n;
    q.y[e] = y * n;
    q.z[e] = z * n;
    q.w[e] = w * n;
    x = q.x[e]!;
    y = q.y[e]!;
    z = q.z[e]!;
    w = q.w[e]!;
    // omega = R (I^-1 L_body).
    const ox = L0 * ix,
      oy = L1 * iy,
      oz = L2 * iz;
    tx = 2 * (y * oz - z * oy);
    ty = 2 * (z * ox - x * oz);
    tz = 2 * (x * oy - y * ox);
    W.x[e] = ox + w * tx + (y * tz - z * ty);
    W.y[e] = oy + w * ty + (z * tx - x * tz);
    W.z[e] = oz + w * tz + (x * ty - y * tx);
  }
}

/**
 * Writes the quaternion (x, y, z, w) scaled to unit length into entity `e`'s slots of `q` (an
 * Orientation store): each component times 1 / |q|. The caller passes a finite, non-zero quaternion
 * (a zero one writes NaN, which the integrators' finiteness checks then report).
 * @category Integrators
 */
export function storeUnitQuaternion(
  q: { x: Float64Array; y: Float64Array; z: Float64Array; w: Float64Array },
  e: number,
  x: number,
  y: number,
  z: number,
  w: number,
): void {
  const n = 1 / Math.sqrt(x * x + y * y + z * z + w * w);
  q.x[e] = x * n;
  q.y[e] = y * n;
  q.z[e] = z * n;
  q.w[e] = w * n;
}
