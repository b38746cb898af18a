/**
 * Quaternion helpers over component arrays (x, y, z, w), unit quaternions rotating the body frame
 * into the world frame. Hamilton convention (Shoemake, SIGGRAPH 1985; Kuipers, Quaternions and
 * Rotation Sequences, 1999). Rotation of v by q: v' = v + w t + q_v x t with t = 2 q_v x v.
 */

/** rotateVector's quaternion and vector, copied into arrays for quaternionRotate (scratch, not state). */
const rotateQ = new Float64Array(4),
  rotateV = new Float64Array(3);

/**
 * Rotates (vx, vy, vz) by the quaternion (qx, qy, qz, qw); writes into out[0..2]. For code run once per
 * body per step, see quaternionRotate.
 * @category Utilities
 */
export function rotateVector(qx: number, qy: number, qz: number, qw: number, vx: number, vy: number, vz: number, out: Float64Array): void {
  rotateQ[0] = qx;
  rotateQ[1] = qy;
  rotateQ[2] = qz;
  rotateQ[3] = qw;
  rotateV[0] = vx;
  rotateV[1] = vy;
  rotateV[2] = vz;
  quaternionRotate(rotateQ, rotateV, out);
}

/**
 * Rotates the vector v[0..2] by the quaternion q[0..3] (x, y, z, w): v' = v + w t + q_v x t with
 * t = 2 q_v x v; writes into out[0..2], which may be v. Arrays, not numbers, for the reason
 * quaternionProduct gives.
 * @category Utilities
 */
export function quaternionRotate(q: ArrayLike<number>, v: ArrayLike<number>, out: Float64Array): void {
  const qx = q[0]!,
    qy = q[1]!,
    qz = q[2]!,
    qw = q[3]!,
    vx = v[0]!,
    vy = v[1]!,
    vz = v[2]!;
  const tx = 2 * (qy * vz - qz * vy),
    ty = 2 * (qz * vx - qx * vz),
    tz = 2 * (qx * vy - qy * vx);
  out[0] = vx + qw * tx + (qy * tz - qz * ty);
  out[1] = vy + qw * ty + (qz * tx - qx * tz);
  out[2] = vz + qw * tz + (qx * ty - qy * tx);
}

/** multiplyQuaternions' operands, copied into arrays for quaternionProduct (scratch, not state). */
const productA = new Float64Array(4),
  productB = new Float64Array(4);

/**
 * The Hamilton product a b of quaternions a = (ax, ay, az, aw) and b (rotate by b, then by a); writes
 * (x, y, z, w) into out[0..3]. For code run once per body per step, see quaternionProduct.
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
  productA[0] = ax;
  productA[1] = ay;
  productA[2] = az;
  productA[3] = aw;
  productB[0] = bx;
  productB[1] = by;
  productB[2] = bz;
  productB[3] = bw;
  quaternionProduct(productA, productB, out);
}

/**
 * The Hamilton product a b of the quaternions in a[0..3] and b[0..3] (x, y, z, w; rotate by b, then
 * by a); writes (x, y, z, w) into out[0..3], which may be a or b. The operands are arrays, not numbers:
 * where V8 does not inline a call, it passes each number argument as a heap number (16 bytes), so a
 * call made for every body in every step with eight numbers allocates about 128 bytes a body a step,
 * and the garbage collector runs for it.
 * @category Utilities
 */
export function quaternionProduct(a: ArrayLike<number>, b: ArrayLike<number>, out: Float64Array): void {
  const ax = a[0]!,
    ay = a[1]!,
    az = a[2]!,
    aw = a[3]!,
    bx = b[0]!,
    by = b[1]!,
    bz = b[2]!,
    bw = b[3]!;
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

/** rotateFrom's and rotateInPlaceBy's orientation, turned in place before it is renormalised, and the rotation vector and angle. */
const turned = new Float64Array(4),
  turnBy = new Float64Array(4);

/**
 * exp(r / 2) q into out[0..3], not renormalised: the quaternion q = (q[0], q[1], q[2], q[3]) (x, y, z, w)
 * turned by the rotation vector r = (r[0], r[1], r[2]) (angle |r| about r, world frame), given r[3] =
 * |r| (rad; however the caller computes it). An angle that is not > 0 turns by the identity: out = 1 q,
 * term by term as for any angle. `out` may be `q`. The rotation comes in an array, not as numbers: a
 * call V8 does not inline passes each number as a heap number, garbage at every body of every step
 * (see quaternionProduct).
 * @category Utilities
 */
export function turnQuaternion(q: Float64Array, r: Float64Array, out: Float64Array): void {
  const x = q[0]!,
    y = q[1]!,
    z = q[2]!,
    w = q[3]!;
  const angle = r[3]!;
  let dx = 0,
    dy = 0,
    dz = 0,
    dw = 1;
  if (angle > 0) {
    const k = Math.sin(0.5 * angle) / angle;
    dx = r[0]! * k;
    dy = r[1]! * k;
    dz = r[2]! * k;
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
  turnBy[0] = rx;
  turnBy[1] = ry;
  turnBy[2] = rz;
  turnStored(qx, qy, qz, qw, e);
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

/**
 * q[e] = exp(r / 2) q[e] with the rotation vector in r[0..2] (rad): rotateInPlace for loops over the
 * bodies, its operands in an array for the reason quaternionProduct gives.
 * @category Utilities
 */
export function rotateInPlaceBy(
  qx: Float64Array,
  qy: Float64Array,
  qz: Float64Array,
  qw: Float64Array,
  e: number,
  r: ArrayLike<number>,
): void {
  turned[0] = qx[e]!;
  turned[1] = qy[e]!;
  turned[2] = qz[e]!;
  turned[3] = qw[e]!;
  turnBy[0] = r[0]!;
  turnBy[1] = r[1]!;
  turnBy[2] = r[2]!;
  turnStored(qx, qy, qz, qw, e);
}

/** q[e] = the orientation in `turned` turned by the rotation vector in turnBy[0..2], renormalised. */
function turnStored(qx: Float64Array, qy: Float64Array, qz: Float64Array, qw: Float64Array, e: number): void {
  const rx = turnBy[0]!,
    ry = turnBy[1]!,
    rz = turnBy[2]!;
  turnBy[3] = Math.sqrt(rx * rx + ry * ry + rz * rz);
  turnQuaternion(turned, turnBy, turned);
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
