import { hasComponent } from 'bitecs';
import { query } from '../query.js';
import type { PhysicsWorld } from '../world.js';
import { currentHandle } from '../handles.js';
import { assertVector, describe } from '../validate.js';
import { Shape3DKind, shapes3DOf } from '../shapes3d/store.js';
import { meshesOf } from './mesh3d.js';

/**
 * Ray casts in 3D, for picking, line of sight and aiming: every 3D shape (shapes3d/), ball body
 * (a sphere), plane and static triangle mesh, where the bodies are now (`Position`, `Orientation`). Time
 * linear in the number of shapes (no acceleration structure: a few casts a frame, not one per body).
 *
 * Formulas (Ericson, Real-Time Collision Detection, 2005): ray against a sphere (5.3.2), against a
 * convex polyhedron by clipping to its face half-spaces (5.3.8; Haines, "Fast Ray-Convex Polyhedron
 * Intersection", Graphics Gems II), against a capsule as its two end spheres and the cylinder between
 * them (5.3.7), against a triangle (Moller and Trumbore, J. Graphics Tools 2(1), 1997).
 */

/** One 3D ray hit. Entities are handles. */
export interface RayHit3D {
  /** The shape hit (a ball body for a ball, the plane or mesh entity for those). */
  shape: number;
  /** Its body (0 for a plane or mesh: the static world). */
  body: number;
  /** Where along the ray, in [0, 1] of the translation. */
  fraction: number;
  /** The point hit, m. */
  x: number; y: number; z: number;
  /** The surface's outward unit normal there. */
  nx: number; ny: number; nz: number;
}

const hit = { t: 0, nx: 0, ny: 0, nz: 0 };

function checkRay(where: string, world: PhysicsWorld, origin: ArrayLike<number>, translation: ArrayLike<number>): void {
  if (world.dimensions !== 3) throw new TypeError(`${where}: needs a 3D world (use rayCast in 2D), got dimensions ${world.dimensions}`);
  assertVector(where, 'origin', origin, 3);
  assertVector(where, 'translation', translation, 3);
  if (translation[0] === 0 && translation[1] === 0 && translation[2] === 0) throw new RangeError(`${where}: translation must not be zero, got ${describe(translation)}`);
}

/** Ray (o + t d, t in [0, 1]) against a sphere of centre c and radius r; fills `hit`. */
function raySphere(ox: number, oy: number, oz: number, dx: number, dy: number, dz: number, cx: number, cy: number, cz: number, r: number): boolean {
  const mx = ox - cx, my = oy - cy, mz = oz - cz;
  const c = mx * mx + my * my + mz * mz - r * r;
  if (c <= 0) return false; // starts inside
  const a = dx * dx + dy * dy + dz * dz, b = mx * dx + my * dy + mz * dz;
  const disc = b * b - a * c;
  if (b > 0 || disc < 0) return false;
  const t = (-b - Math.sqrt(disc)) / a;
  if (t < 0 || t > 1) return false;
  const x = mx + t * dx, y = my + t * dy, z = mz + t * dz, l = Math.hypot(x, y, z);
  hit.t = t; hit.nx = x / l; hit.ny = y / l; hit.nz = z / l;
  return true;
}

/** Ray against a capsule of segment p q and radius r: nearest of the end spheres and the side. */
function rayCapsule(ox: number, oy: number, oz: number, dx: number, dy: number, dz: number, px: number, py: number, pz: number, qx: number, qy: number, qz: number, r: number): boolean {
  let best = Infinity, bx = 0, by = 0, bz = 0;
  for (const [cx, cy, cz] of [[px, py, pz], [qx, qy, qz]] as const) {
    if (raySphere(ox, oy, oz, dx, dy, dz, cx, cy, cz, r) && hit.t < best) { best = hit.t; bx = hit.nx; by = hit.ny; bz = hit.nz; }
  }
  // Side: |(o + t d - p) x u|^2 = r^2 with u the unit axis, hit within the segment.
  const ax = qx - px, ay = qy - py, az = qz - pz, L = Math.hypot(ax, ay, az);
  const ux = ax / L, uy = ay / L, uz = az / L;
  const mx = ox - px, my = oy - py, mz = oz - pz;
  const md = mx * ux + my * uy + mz * uz, dd = dx * ux + dy * uy + dz * uz;
  const pmx = mx - md * ux, pmy = my - md * uy, pmz = mz - md * uz, pdx = dx - dd * ux, pdy = dy - dd * uy, pdz = dz - dd * uz;
  const a = pdx * pdx + pdy * pdy + pdz * pdz, b = pmx * pdx + pmy * pdy + pmz * pdz, c = pmx * pmx + pmy * pmy + pmz * pmz - r * r;
  if (c <= 0 && md >= 0 && md <= L) return false; // starts inside
  const disc = b * b - a * c;
  if (a > 0 && disc >= 0 && b < 0) {
    const t = (-b - Math.sqrt(disc)) / a;
    const s = md + t * dd;
    if (t >= 0 && t <= 1 && s >= 0 && s <= L && t < best) {
      best = t;
      const nx = pmx + t * pdx, ny = pmy + t * pdy, nz = pmz + t * pdz, l = Math.hypot(nx, ny, nz);
      bx = nx / l; by = ny / l; bz = nz / l;
    }
  }
  if (best === Infinity) return false;
  hit.t = best; hit.nx = bx; hit.ny = by; hit.nz = bz;
  return true;
}

/** Ray against a convex polyhedron given by world face normals and offsets (n . x <= d inside). */
function rayPolyhedron(ox: number, oy: number, oz: number, dx: number, dy: number, dz: number, fn: Float64Array, fd: Float64Array, nf: number): boolean {
  let tin = 0, tout = 1, face = -1, inside = true;
  for (let f = 0; f < nf; f++) {
    const nx = fn[3 * f]!, ny = fn[3 * f + 1]!, nz = fn[3 * f + 2]!;
    const dist = nx * ox + ny * oy + nz * oz - fd[f]!, den = nx * dx + ny * dy + nz * dz;
    if (dist > 0) inside = false;
    if (den === 0) { if (dist > 0) return false; continue; }
    const t = -dist / den;
    if (den < 0) { if (t > tin) { tin = t; face = f; } } else if (t < tout) tout = t;
    if (tin > tout) return false;
  }
  if (inside || face < 0) return false;
  hit.t = tin; hit.nx = fn[3 * face]!; hit.ny = fn[3 * face + 1]!; hit.nz = fn[3 * face + 2]!;
  return true;
}

const fn = new Float64Array(3 * 256), fd = new Float64Array(256);

/** Every hit of the segment from `origin` to `origin + translation` (m), nearest first. A ray that starts inside a shape does not hit it. @throws TypeError on a 2D world or vectors that are not 3 finite numbers; RangeError on a zero translation. */
export function rayCastAll3D(world: PhysicsWorld, origin: ArrayLike<number>, translation: ArrayLike<number>): RayHit3D[] {
  checkRay('rayCastAll3D', world, origin, translation);
  const out: RayHit3D[] = [];
  const ox = origin[0]!, oy = origin[1]!, oz = origin[2]!, dx = translation[0]!, dy = translation[1]!, dz = translation[2]!;
  const push = (shape: number, body: number): void => {
    out.push({ shape: currentHandle(world, shape), body: body === 0 ? 0 : currentHandle(world, body), fraction: hit.t, x: ox + hit.t * dx, y: oy + hit.t * dy, z: oz + hit.t * dz, nx: hit.nx, ny: hit.ny, nz: hit.nz });
  };
  const c = world.components, P = c.Position, Q = c.Orientation;
  const s = shapes3DOf(world);
  if (s !== undefined) {
    for (let e = 1; e <= world.capacity; e++) {
      const b = s.body[e]!;
      if (b === 0) continue;
      const has = hasComponent(world, b, c.Orientation);
      const qx = has ? Q.x[b]! : 0, qy = has ? Q.y[b]! : 0, qz = has ? Q.z[b]! : 0, qw = has ? Q.w[b]! : 1;
      // Shape pose: the body's composed with the placement.
      const rot = (vx: number, vy: number, vz: number, x: number, y: number, z: number, w: number): [number, number, number] => {
        const tx = 2 * (y * vz - z * vy), ty = 2 * (z * vx - x * vz), tz = 2 * (x * vy - y * vx);
        return [vx + w * tx + (y * tz - z * ty), vy + w * ty + (z * tx - x * tz), vz + w * tz + (x * ty - y * tx)];
      };
      const p = rot(s.px[e]!, s.py[e]!, s.pz[e]!, qx, qy, qz, qw);
      const cx = P.x[b]! + p[0], cy = P.y[b]! + p[1], cz = P.z[b]! + p[2];
      const ax = s.qx[e]!, ay = s.qy[e]!, az = s.qz[e]!, aw = s.qw[e]!;
      const x = qw * ax + qx * aw + qy * az - qz * ay, y = qw * ay - qx * az + qy * aw + qz * ax, z = qw * az + qx * ay - qy * ax + qz * aw, w = qw * aw - qx * ax - qy * ay - qz * az;
      const kind = s.kind[e]!;
      let ok = false;
      if (kind === Shape3DKind.Sphere) ok = raySphere(ox, oy, oz, dx, dy, dz, cx, cy, cz, s.radius[e]!);
      else if (kind === Shape3DKind.Capsule) {
        const u = rot(0, s.hy[e]!, 0, x, y, z, w);
        ok = rayCapsule(ox, oy, oz, dx, dy, dz, cx - u[0], cy - u[1], cz - u[2], cx + u[0], cy + u[1], cz + u[2], s.radius[e]!);
      } else {
        const h = s.hulls[s.hull[e]!]!, nf = h.faceOffsets.length;
        for (let f = 0; f < nf; f++) {
          const n = rot(h.faceNormals[3 * f]!, h.faceNormals[3 * f + 1]!, h.faceNormals[3 * f + 2]!, x, y, z, w);
          fn[3 * f] = n[0]; fn[3 * f + 1] = n[1]; fn[3 * f + 2] = n[2];
          fd[f] = h.faceOffsets[f]! + n[0] * cx + n[1] * cy + n[2] * cz;
        }
        ok = rayPolyhedron(ox, oy, oz, dx, dy, dz, fn, fd, nf);
      }
      if (ok) push(e, b);
    }
  }
  const balls = query(world, [c.Position, c.Ball]);
  for (let i = 0; i < balls.length; i++) {
    const b = balls[i]!;
    if (s !== undefined && s.first[b] !== 0) continue;
    if (raySphere(ox, oy, oz, dx, dy, dz, P.x[b]!, P.y[b]!, P.z[b]!, c.Ball.radius[b]!)) push(b, b);
  }
  const planes = query(world, [c.Plane]);
  for (let i = 0; i < planes.length; i++) {
    const p = planes[i]!, nx = c.Plane.nx[p]!, ny = c.Plane.ny[p]!, nz = c.Plane.nz[p]!;
    const dist = nx * ox + ny * oy + nz * oz - c.Plane.d[p]!, den = nx * dx + ny * dy + nz * dz;
    if (dist <= 0 || den >= 0) continue;
    const t = -dist / den;
    if (t > 1) continue;
    hit.t = t; hit.nx = nx; hit.ny = ny; hit.nz = nz;
    push(p, 0);
  }
  for (const m of meshesOf(world)) {
    const V = m.vertices, T = m.triangles;
    let best = Infinity, bn = [0, 0, 0];
    for (let k = 0; k < T.length; k += 3) {
      const a = 3 * T[k]!, b = 3 * T[k + 1]!, cc = 3 * T[k + 2]!;
      const e1x = V[b]! - V[a]!, e1y = V[b + 1]! - V[a + 1]!, e1z = V[b + 2]! - V[a + 2]!;
      const e2x = V[cc]! - V[a]!, e2y = V[cc + 1]! - V[a + 1]!, e2z = V[cc + 2]! - V[a + 2]!;
      const px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
      const det = e1x * px + e1y * py + e1z * pz;
      if (det <= 1e-300) continue; // one-sided: only the front (counter-clockwise) face, hit from outside
      const inv = 1 / det;
      const tx = ox - V[a]!, ty = oy - V[a + 1]!, tz = oz - V[a + 2]!;
      const u = (tx * px + ty * py + tz * pz) * inv;
      if (u < 0 || u > 1) continue;
      const qx = ty * e1z - tz * e1y, qy = tz * e1x - tx * e1z, qz = tx * e1y - ty * e1x;
      const v = (dx * qx + dy * qy + dz * qz) * inv;
      if (v < 0 || u + v > 1) continue;
      const t = (e2x * qx + e2y * qy + e2z * qz) * inv;
      if (t < 0 || t > 1 || t >= best) continue;
      best = t;
      const nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x, l = Math.hypot(nx, ny, nz);
      bn = [nx / l, ny / l, nz / l];
    }
    if (best <= 1) { hit.t = best; hit.nx = bn[0]!; hit.ny = bn[1]!; hit.nz = bn[2]!; push(m.entity, 0); }
  }
  out.sort((a, b) => a.fraction - b.fraction);
  return out;
}

/** The nearest hit of the segment from `origin` to `origin + translation` (m), or null. @throws as `rayCastAll3D`. */
export function rayCast3D(world: PhysicsWorld, origin: ArrayLike<number>, translation: ArrayLike<number>): RayHit3D | null {
  checkRay('rayCast3D', world, origin, translation);
  return rayCastAll3D(world, origin, translation)[0] ?? null;
}
