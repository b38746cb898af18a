/**
 * Quaternion helpers over component arrays (x, y, z, w), unit quaternions rotating the body frame
 * into the world frame. Hamilton convention (Shoemake, SIGGRAPH 1985; Kuipers, Quaternions and
 * Rotation Sequences, 1999). Rotation of v by q: v' = v + w t + q_v x t with t = 2 q_v x v.
 */

/**
 * Rotates (vx, vy, vz) by the quaternion (qx, qy, qz, qw); writes into out[0..2].
 * @category Utilities
 */
export function rotateVector(qx: number, qy: number, qz: number, qw: number, vx: number, vy: number, vz: number, out: Float64Array): void {
  const tx = 2 * (qy * vz - qz * vy),
    ty = 2 * (qz * vx - qx * vz),
    tz = 2 * (qx * vy - qy * vx);
  out[0] = vx + qw * tx + (qy * tz - qz * ty);
  out[1] = vy + qw * ty + (qz * tx - qx * tz);
  out[2] = vz + qw * tz + (qx * ty - qy * tx);
}

/**
 * The Hamilton product a b of quaternions a = (ax, ay, az, aw) and b (rotate by b, then by a); writes
 * (x, y, z, w) into out[0..3].
 * @category Utilities
 */
export function multiplyQuaternions(
  ax: number,
  ay: number,
  az: number,
  aw: number,
  bx: number,
  by: number,
  bz: number,
  bw: number,
  out: Float64Array,
): void {
  out[0] = aw * bx + ax * bw + ay * bz - az * by;
  out[1] = aw * by - ax * bz + ay * bw + az * bx;
  out[2] = aw * bz + ax * by - ay * bx + az * bw;
  out[3] = aw * bw - ax * bx - ay * by - az * bz;
}

/**
 * The rotation matrix of the unit quaternion (x, y, z, w), row-major (math/mat3-layout.ts M00..M22),
 * into R[o..o + 8].
 * @category Utilities
 */
export function rotationMatrix(x: number, y: number, z: number, w: number, R: Float64Array, o: number): void {
  R[o] = 1 - 2 * (y * y + z * z);
  R[o + 1] = 2 * (x * y - z * w);
  R[o + 2] = 2 * (x * z + y * w);
  R[o + 3] = 2 * (x * y + z * w);
  R[o + 4] = 1 - 2 * (x * x + z * z);
  R[o + 5] = 2 * (y * z - x * w);
  R[o + 6] = 2 * (x * z - y * w);
  R[o + 7] = 2 * (y * z + x * w);
  R[o + 8] = 1 - 2 * (x * x + y * y);
}

/**
 * Rotates (vx, vy, vz) by the inverse (conjugate) of the unit quaternion: world to body frame.
 * @category Utilities
 */
export function rotateVectorInverse(
  qx: number,
  qy: number,
  qz: number,
  qw: number,
  vx: number,
  vy: number,
  vz: number,
  out: Float64Array,
): void {
  rotateVector(-qx, -qy, -qz, qw, vx, vy, vz, out);
}

/** rotateFrom's orientation, turned in place before it is renormalised. */
const turned = new Float64Array(4);

/**
 * exp(r / 2) q into out[0..3], not renormalised: the quaternion q = (q[0], q[1], q[2], q[3]) (x, y, z, w)
 * turned by the rotation vector r (angle |r| about r, world frame), given `angle` = |r| (rad; however
 * the caller computes it). An angle that is not > 0 turns by the identity: out = 1 q, term by term as
 * for any angle. `out` may be `q`.
 * @category Utilities
 */
export function turnQuaternion(q: Float64Array, rx: number, ry: number, rz: number, angle: number, out: Float64Array): void {
  const x = q[0]!,
    y = q[1]!,
    z = q[2]!,
    w = q[3]!;
  let dx = 0,
    dy = 0,
    dz = 0,
    dw = 1;
  if (angle > 0) {
    const k = Math.sin(0.5 * angle) / angle;
    dx = rx * k;
    dy = ry * k;
    dz = rz * k;
    dw = Math.cos(0.5 * angle);
  }
  out[0] = dw * x + dx * w + dy * z - dz * y;
  out[1] = dw * y - dx * z + dy * w + dz * x;
  out[2] = dw * z + dx * y - dy * x + dz * w;
  out[3] = dw * w - dx * x - dy * y - dz * z;
}

/**
 * q[e] = exp(r / 2) (x, y, z, w): the orientation (x, y, z, w) turned by the rotation vector r (angle
 * |r| about r, world frame), renormalised so it stays unit length to rounding.
 * @category Utilities
 */
export function rotateFrom(
  qx: Float64Array,
  qy: Float64Array,
  qz: Float64Array,
  qw: Float64Array,
  e: number,
  x: number,
  y: number,
  z: number,
  w: number,
  rx: number,
  ry: number,
  rz: number,
): void {
  turned[0] = x;
  turned[1] = y;
  turned[2] = z;
  turned[3] = w;
  turnQuaternion(turned, rx, ry, rz, Math.sqrt(rx * rx + ry * ry + rz * rz), turned);
  let nx = turned[0]!;
  let ny = turned[1]!;
  let nz = turned[2]!;
  let nw = turned[3]!;
  const inv = 1 / Math.sqrt(nx * nx + ny * ny + nz * nz + nw * nw);
  nx *= inv;
  ny *= inv;
  nz *= inv;
  nw *= inv;
  qx[e] = nx;
  qy[e] = ny;
  qz[e] = nz;
  qw[e] = nw;
}

/**
 * q[e] = exp(r / 2) q[e]: turns the stored orientation of entity e by the rotation vector r.
 * @category Utilities
 */
export function rotateInPlace(
  qx: Float64Array,
  qy: Float64Array,
  qz: Float64Array,
  qw: Float64Array,
  e: number,
  rx: number,
  ry: number,
  rz: number,
): void {
  rotateFrom(qx, qy, qz, qw, e, qx[e]!, qy[e]!, qz[e]!, qw[e]!, rx, ry, rz);
}
