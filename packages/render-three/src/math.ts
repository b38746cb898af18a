/**
 * Allocation-free maths of the renderer: quaternion interpolation, instance matrices, the box a
 * principal inertia tensor describes. No three.js, no DOM: plain numbers in and typed arrays out, so
 * the hot loop of `WorldRenderer3D.render` never makes a three.js object per entity.
 *
 * Quaternions are (x, y, z, w) with w the scalar part, as in @bitphysics/physics (`Orientation`) and
 * three.js; they rotate the body frame to the world frame.
 */

/** A writable array of numbers (Float32Array for GPU buffers, Float64Array for state). */
export type NumberArray = Float32Array | Float64Array | number[];

/**
 * Spherical linear interpolation between unit quaternions a (t = 0) and b (t = 1) along the shorter
 * arc (b is negated when a . b < 0, since q and -q are the same rotation), written to out[o..o+3] and
 * renormalised. Falls back to normalised linear interpolation when the quaternions are within about
 * 2 degrees of each other, where slerp's sin(theta) denominator loses precision.
 * Source: Shoemake, "Animating rotation with quaternion curves", SIGGRAPH 1985.
 * @param t interpolation factor, usually in [0, 1] (not checked: the hot path calls this).
 */
export function slerpInto(
  ax: number,
  ay: number,
  az: number,
  aw: number,
  bx: number,
  by: number,
  bz: number,
  bw: number,
  t: number,
  out: NumberArray,
  o: number,
): void {
  let cos = ax * bx + ay * by + az * bz + aw * bw;
  if (cos < 0) {
    cos = -cos;
    bx = -bx;
    by = -by;
    bz = -bz;
    bw = -bw;
  }
  let k0: number, k1: number;
  if (cos > 0.9995) {
    k0 = 1 - t;
    k1 = t;
  } else {
    const theta = Math.acos(cos);
    const s = 1 / Math.sin(theta);
    k0 = Math.sin((1 - t) * theta) * s;
    k1 = Math.sin(t * theta) * s;
  }
  const x = k0 * ax + k1 * bx,
    y = k0 * ay + k1 * by,
    z = k0 * az + k1 * bz,
    w = k0 * aw + k1 * bw;
  const inv = 1 / Math.sqrt(x * x + y * y + z * z + w * w);
  out[o] = x * inv;
  out[o + 1] = y * inv;
  out[o + 2] = z * inv;
  out[o + 3] = w * inv;
}

/**
 * The orientation one step of length h earlier for a body turning at the constant world-frame angular
 * velocity (wx, wy, wz) rad/s: q_prev = exp(-w h / 2) q (the inverse of the update the integrators
 * apply, `rotateFrom` in @bitphysics/physics). Written to out[o..o+3], unit length.
 * Used to interpolate orientations when more than one step ran since the last frame.
 */
export function rotateBack(
  qx: number,
  qy: number,
  qz: number,
  qw: number,
  wx: number,
  wy: number,
  wz: number,
  h: number,
  out: NumberArray,
  o: number,
): void {
  const rx = -wx * h,
    ry = -wy * h,
    rz = -wz * h;
  const angle = Math.sqrt(rx * rx + ry * ry + rz * rz);
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
  const x = dw * qx + dx * qw + dy * qz - dz * qy;
  const y = dw * qy - dx * qz + dy * qw + dz * qx;
  const z = dw * qz + dx * qy - dy * qx + dz * qw;
  const w = dw * qw - dx * qx - dy * qy - dz * qz;
  const inv = 1 / Math.sqrt(x * x + y * y + z * z + w * w);
  out[o] = x * inv;
  out[o + 1] = y * inv;
  out[o + 2] = z * inv;
  out[o + 3] = w * inv;
}

/**
 * Writes the 4x4 transform translate(p) rotate(q) scale(s) to m[o..o+15], column-major (the layout of
 * three.js `Matrix4.elements` and of `InstancedMesh.instanceMatrix`): the same result as three's
 * `Matrix4.compose`. q must be a unit quaternion.
 */
export function composeInto(
  m: NumberArray,
  o: number,
  px: number,
  py: number,
  pz: number,
  qx: number,
  qy: number,
  qz: number,
  qw: number,
  sx: number,
  sy: number,
  sz: number,
): void {
  const x2 = qx + qx,
    y2 = qy + qy,
    z2 = qz + qz;
  const xx = qx * x2,
    xy = qx * y2,
    xz = qx * z2;
  const yy = qy * y2,
    yz = qy * z2,
    zz = qz * z2;
  const wx = qw * x2,
    wy = qw * y2,
    wz = qw * z2;
  m[o] = (1 - (yy + zz)) * sx;
  m[o + 1] = (xy + wz) * sx;
  m[o + 2] = (xz - wy) * sx;
  m[o + 3] = 0;
  m[o + 4] = (xy - wz) * sy;
  m[o + 5] = (1 - (xx + zz)) * sy;
  m[o + 6] = (yz + wx) * sy;
  m[o + 7] = 0;
  m[o + 8] = (xz + wy) * sz;
  m[o + 9] = (yz - wx) * sz;
  m[o + 10] = (1 - (xx + yy)) * sz;
  m[o + 11] = 0;
  m[o + 12] = px;
  m[o + 13] = py;
  m[o + 14] = pz;
  m[o + 15] = 1;
}

/**
 * Rotates (vx, vy, vz) by the unit quaternion q (body to world), written to out[o..o+2]:
 * v' = v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z).
 */
export function rotateInto(
  qx: number,
  qy: number,
  qz: number,
  qw: number,
  vx: number,
  vy: number,
  vz: number,
  out: NumberArray,
  o: number,
): void {
  const tx = 2 * (qy * vz - qz * vy),
    ty = 2 * (qz * vx - qx * vz),
    tz = 2 * (qx * vy - qy * vx);
  out[o] = vx + qw * tx + (qy * tz - qz * ty);
  out[o + 1] = vy + qw * ty + (qz * tx - qx * tz);
  out[o + 2] = vz + qw * tz + (qx * ty - qy * tx);
}

/**
 * Edges (a, b, c), m, of the solid box of `mass` kg whose principal moments are (Ix, Iy, Iz) kg m^2:
 * inverting I_x = m (b^2 + c^2) / 12 and its cyclic versions gives a^2 = 6 (I_y + I_z - I_x) / m, and
 * so on (the "equivalent inertia box" physics engines draw for bodies without a mesh). A tensor that
 * no box has (a negative square) or a zero moment (a locked axis) clamps that edge to `minFraction`
 * of the longest edge. Written to out[0..2]; returns false (out untouched) if mass or every moment
 * is not > 0.
 * Source: moments of a solid cuboid, any mechanics text (Goldstein, Classical Mechanics, ch. 5).
 */
export function equivalentBoxEdges(mass: number, ix: number, iy: number, iz: number, out: NumberArray, minFraction = 0.02): boolean {
  if (!(mass > 0) || !(ix > 0 || iy > 0 || iz > 0)) return false;
  const k = 6 / mass;
  const a2 = k * (iy + iz - ix),
    b2 = k * (ix + iz - iy),
    c2 = k * (ix + iy - iz);
  let a = a2 > 0 ? Math.sqrt(a2) : 0,
    b = b2 > 0 ? Math.sqrt(b2) : 0,
    c = c2 > 0 ? Math.sqrt(c2) : 0;
  const longest = Math.max(a, b, c);
  if (!(longest > 0) || !Number.isFinite(longest)) return false;
  const floor = longest * minFraction;
  if (a < floor) a = floor;
  if (b < floor) b = floor;
  if (c < floor) c = floor;
  out[0] = a;
  out[1] = b;
  out[2] = c;
  return true;
}

/**
 * Converts an sRGB colour 0xRRGGBB to linear RGB in [0, 1] (the IEC 61966-2-1 transfer function,
 * what three.js' `Color.setHex` does under its default colour management), written to out[o..o+2].
 */
export function hexToLinear(hex: number, out: NumberArray, o: number): void {
  out[o] = srgbToLinear(((hex >> 16) & 255) / 255);
  out[o + 1] = srgbToLinear(((hex >> 8) & 255) / 255);
  out[o + 2] = srgbToLinear((hex & 255) / 255);
}

function srgbToLinear(c: number): number {
  return c < 0.04045 ? c * 0.0773993808 : (c * 0.9478672986 + 0.0521327014) ** 2.4;
}
