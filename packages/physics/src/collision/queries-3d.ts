import { hasComponent } from 'bitecs';
import { multiplyQuaternions, rotateVector } from '../math/quaternion.js';
import { meshesOf } from '../shapes/mesh-3d.js';
import { Shape3DKind, type Shape3DStore, shapes3DOf } from '../shapes/store-3d.js';
import { assertVector, describe } from '../validation/validate.js';
import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';

/**
 * Queries in 3D, for picking, line of sight, aiming and spawning: ray casts (nearest hit, all hits),
 * the shapes containing a point, and the shapes whose bounding boxes meet an axis-aligned box. They
 * read every 3D shape (shapes3d/), ball body (a sphere), plane and static triangle mesh where the
 * bodies are now (`Position`, `Orientation`), in time linear in the number of shapes (no acceleration
 * structure: a few queries a frame, not one per body).
 *
 * Every shape is taken exactly as its kind describes it: a cylinder is the round cylinder of its
 * radius and half height (the contact solver collides it as a 16-sided prism inscribed in it, at most
 * 1 - cos(pi / 16) = 1.9 % of the radius inside), a box and a hull their polyhedra, a capsule its
 * segment inflated by its radius.
 *
 * Formulas (Ericson, Real-Time Collision Detection, 2005): ray against a sphere (5.3.2), against a
 * convex polyhedron by clipping to its face half-spaces (5.3.8; Haines, "Fast Ray-Convex Polyhedron
 * Intersection", Graphics Gems II), against a capsule as its two end spheres and the cylinder between
 * them (5.3.7), against a capped cylinder as its side (the quadratic of 5.3.7 in the shape's frame)
 * and its two end discs, against a triangle (Moller and Trumbore, J. Graphics Tools 2(1), 1997); a
 * point against a capsule by its distance to the segment (5.1.2); the bounding box of a rotated box
 * and of a cylinder by their extents along each world axis (4.2.6).
 */

/**
 * One 3D ray hit. Entities are handles.
 * @category Queries
 */
export interface RayHit3D {
  /** The shape hit (a ball body for a ball, the plane or mesh entity for those). */
  shape: number;
  /** Its body (0 for a plane or mesh: the static world). */
  body: number;
  /** Where along the ray, in [0, 1] of the translation. */
  fraction: number;
  /** The point hit, m. */
  x: number;
  y: number;
  z: number;
  /** The surface's outward unit normal there. */
  nx: number;
  ny: number;
  nz: number;
}

const hit = { t: 0, nx: 0, ny: 0, nz: 0 };

/** Fills `hit` with fraction t and unit normal n; returns true (a hit). */
function setHit(t: number, nx: number, ny: number, nz: number): boolean {
  hit.t = t;
  hit.nx = nx;
  hit.ny = ny;
  hit.nz = nz;
  return true;
}

function checkRay(where: string, world: PhysicsWorld, origin: ArrayLike<number>, translation: ArrayLike<number>): void {
  if (world.dimensions !== 3) throw new TypeError(`${where}: needs a 3D world (use rayCast in 2D), got dimensions ${world.dimensions}`);
  assertVector(where, 'origin', origin, 3);
  assertVector(where, 'translation', translation, 3);
  if (translation[0] === 0 && translation[1] === 0 && translation[2] === 0)
    throw new RangeError(`${where}: translation must not be zero, got ${describe(translation)}`);
}

/** Ray (o + t d, t in [0, 1]) against a sphere of centre c and radius r; fills `hit`. */
function raySphere(
  ox: number,
  oy: number,
  oz: number,
  dx: number,
  dy: number,
  dz: number,
  cx: number,
  cy: number,
  cz: number,
  r: number,
): boolean {
  const mx = ox - cx,
    my = oy - cy,
    mz = oz - cz;
  const c = mx * mx + my * my + mz * mz - r * r;
  if (c <= 0) return false; // starts inside
  const a = dx * dx + dy * dy + dz * dz,
    b = mx * dx + my * dy + mz * dz;
  const disc = b * b - a * c;
  if (b > 0 || disc < 0) return false;
  const t = (-b - Math.sqrt(disc)) / a;
  if (t < 0 || t > 1) return false;
  const x = mx + t * dx,
    y = my + t * dy,
    z = mz + t * dz,
    l = Math.hypot(x, y, z);
  return setHit(t, x / l, y / l, z / l);
}

/** Ray against a capsule of segment p q and radius r: nearest of the end spheres and the side. */
function rayCapsule(
  ox: number,
  oy: number,
  oz: number,
  dx: number,
  dy: number,
  dz: number,
  px: number,
  py: number,
  pz: number,
  qx: number,
  qy: number,
  qz: number,
  r: number,
): boolean {
  let best = Infinity,
    bx = 0,
    by = 0,
    bz = 0;
  for (const [cx, cy, cz] of [
    [px, py, pz],
    [qx, qy, qz],
  ] as const) {
    if (raySphere(ox, oy, oz, dx, dy, dz, cx, cy, cz, r) && hit.t < best) {
      best = hit.t;
      bx = hit.nx;
      by = hit.ny;
      bz = hit.nz;
    }
  }
  // Side: |(o + t d - p) x u|^2 = r^2 with u the unit axis, hit within the segment.
  const ax = qx - px,
    ay = qy - py,
    az = qz - pz,
    L = Math.hypot(ax, ay, az);
  const ux = ax / L,
    uy = ay / L,
    uz = az / L;
  const mx = ox - px,
    my = oy - py,
    mz = oz - pz;
  const md = mx * ux + my * uy + mz * uz,
    dd = dx * ux + dy * uy + dz * uz;
  const pmx = mx - md * ux,
    pmy = my - md * uy,
    pmz = mz - md * uz,
    pdx = dx - dd * ux,
    pdy = dy - dd * uy,
    pdz = dz - dd * uz;
  const a = pdx * pdx + pdy * pdy + pdz * pdz,
    b = pmx * pdx + pmy * pdy + pmz * pdz,
    c = pmx * pmx + pmy * pmy + pmz * pmz - r * r;
  if (c <= 0 && md >= 0 && md <= L) return false; // starts inside
  const disc = b * b - a * c;
  if (a > 0 && disc >= 0 && b < 0) {
    const t = (-b - Math.sqrt(disc)) / a;
    const s = md + t * dd;
    if (t >= 0 && t <= 1 && s >= 0 && s <= L && t < best) {
      best = t;
      const nx = pmx + t * pdx,
        ny = pmy + t * pdy,
        nz = pmz + t * pdz,
        l = Math.hypot(nx, ny, nz);
      bx = nx / l;
      by = ny / l;
      bz = nz / l;
    }
  }
  return best !== Infinity && setHit(best, bx, by, bz);
}

/** Ray against a convex polyhedron given by world face normals and offsets (n . x <= d inside). */
function rayPolyhedron(
  ox: number,
  oy: number,
  oz: number,
  dx: number,
  dy: number,
  dz: number,
  fn: Float64Array,
  fd: Float64Array,
  nf: number,
): boolean {
  let tin = 0,
    tout = 1,
    face = -1,
    inside = true;
  for (let f = 0; f < nf; f++) {
    const nx = fn[3 * f]!,
      ny = fn[3 * f + 1]!,
      nz = fn[3 * f + 2]!;
    const dist = nx * ox + ny * oy + nz * oz - fd[f]!,
      den = nx * dx + ny * dy + nz * dz;
    if (dist > 0) inside = false;
    if (den === 0) {
      if (dist > 0) return false;
      continue;
    }
    const t = -dist / den;
    if (den < 0) {
      if (t > tin) {
        tin = t;
        face = f;
      }
    } else if (t < tout) tout = t;
    if (tin > tout) return false;
  }
  return !(inside || face < 0) && setHit(tin, fn[3 * face]!, fn[3 * face + 1]!, fn[3 * face + 2]!);
}

/**
 * Ray against a capped cylinder of radius r and half height hh along the y axis of its frame, centred
 * at the origin, the ray (o, d) given in that frame; fills `hit` with the normal in that frame.
 */
function rayCylinder(ox: number, oy: number, oz: number, dx: number, dy: number, dz: number, r: number, hh: number): boolean {
  const r2 = r * r,
    c = ox * ox + oz * oz - r2;
  if (c <= 0 && oy >= -hh && oy <= hh) return false; // starts inside
  let best = Infinity,
    bx = 0,
    by = 0,
    bz = 0;
  // Side: |(o + t d)_xz|^2 = r^2, entering (the smaller root), within the height.
  const a = dx * dx + dz * dz,
    b = ox * dx + oz * dz;
  if (a > 0 && c > 0 && b < 0) {
    const disc = b * b - a * c;
    if (disc >= 0) {
      const t = (-b - Math.sqrt(disc)) / a,
        y = oy + t * dy;
      if (t >= 0 && t <= 1 && y >= -hh && y <= hh) {
        best = t;
        bx = (ox + t * dx) / r;
        by = 0;
        bz = (oz + t * dz) / r;
      }
    }
  }
  // End discs: the plane y = +-hh crossed from outside, within the radius.
  for (let k = -1; k <= 1; k += 2) {
    const side = k * oy - hh; // > 0: outside the disc's plane
    const den = k * dy;
    if (side < 0 || den >= 0) continue;
    const t = -side / den;
    if (t < 0 || t > 1 || t >= best) continue;
    const x = ox + t * dx,
      z = oz + t * dz;
    if (x * x + z * z <= r2) {
      best = t;
      bx = 0;
      by = k;
      bz = 0;
    }
  }
  return best !== Infinity && setHit(best, bx, by, bz);
}

/**
 * A collider's pose (posed by `poseShape` or `poseBall`): centre, m (world), the rotation of its frame
 * into the world (unit quaternion x, y, z, w), its kind (Shape3DKind) and radius, m.
 */
const pose = { cx: 0, cy: 0, cz: 0, x: 0, y: 0, z: 0, w: 1, kind: 0, r: 0 };
/** A vector rotated by a shape's pose (math/quaternion.ts rotateVector; -x, -y, -z for the inverse). */
const v3 = new Float64Array(3);
/** A shape's orientation in the world (its body's composed with its placement). */
const q4 = new Float64Array(4);

/** Fills `pose` with shape `e`'s pose where its body `b` is now: the body's pose composed with the shape's placement. */
function poseShape(world: PhysicsWorld, s: Shape3DStore, e: number, b: number): void {
  const c = world.components,
    P = c.Position,
    Q = c.Orientation;
  const has = hasComponent(world, b, c.Orientation);
  const qx = has ? Q.x[b]! : 0,
    qy = has ? Q.y[b]! : 0,
    qz = has ? Q.z[b]! : 0,
    qw = has ? Q.w[b]! : 1;
  rotateVector(qx, qy, qz, qw, s.px[e]!, s.py[e]!, s.pz[e]!, v3);
  pose.cx = P.x[b]! + v3[0]!;
  pose.cy = P.y[b]! + v3[1]!;
  pose.cz = P.z[b]! + v3[2]!;
  multiplyQuaternions(qx, qy, qz, qw, s.qx[e]!, s.qy[e]!, s.qz[e]!, s.qw[e]!, q4);
  pose.x = q4[0]!;
  pose.y = q4[1]!;
  pose.z = q4[2]!;
  pose.w = q4[3]!;
  pose.kind = s.kind[e]!;
  pose.r = s.radius[e]!;
}

/** Fills `pose` with ball body `b` where it is now: a sphere of its `Ball` radius, unturned. */
function poseBall(world: PhysicsWorld, b: number): void {
  const P = world.components.Position;
  pose.cx = P.x[b]!;
  pose.cy = P.y[b]!;
  pose.cz = P.z[b]!;
  pose.x = pose.y = pose.z = 0;
  pose.w = 1;
  pose.kind = Shape3DKind.Sphere;
  pose.r = world.components.Ball.radius[b]!;
}

/**
 * Visits every collider where it is now, posed in `pose`: each 3D shape `e` of body `b`, then each ball
 * body without a 3D shape as a sphere (e = b). `s` is the shape store (undefined in a world without 3D
 * shapes: then only balls, whose pose is all a visit reads).
 */
function eachCollider(world: PhysicsWorld, visit: (s: Shape3DStore | undefined, e: number, b: number) => void): void {
  const s = shapes3DOf(world);
  if (s !== undefined) {
    for (let e = 1; e <= world.capacity; e++) {
      const b = s.body[e]!;
      if (b === 0) continue;
      poseShape(world, s, e, b);
      visit(s, e, b);
    }
  }
  const balls = query(world, [world.components.Position, world.components.Ball]);
  for (let i = 0; i < balls.length; i++) {
    const b = balls[i]!;
    if (s !== undefined && s.first[b] !== 0) continue;
    poseBall(world, b);
    visit(s, b, b);
  }
}

const fn = new Float64Array(3 * 256),
  fd = new Float64Array(256);

/** The ray of rayCastAll3D: origin o and translation d, m. Scratch. */
const ray = { ox: 0, oy: 0, oz: 0, dx: 0, dy: 0, dz: 0 };

/** Whether the segment `ray` hits the collider posed in `pose` (shape `e` of `s`, or a ball), filling `hit`. */
function rayCollider(s: Shape3DStore | undefined, e: number): boolean {
  const { ox, oy, oz, dx, dy, dz } = ray;
  const { cx, cy, cz, x, y, z, w, kind, r } = pose;
  if (kind === Shape3DKind.Sphere) return raySphere(ox, oy, oz, dx, dy, dz, cx, cy, cz, r);
  const st = s as Shape3DStore;
  if (kind === Shape3DKind.Capsule) {
    rotateVector(x, y, z, w, 0, st.hy[e]!, 0, v3);
    const ux = v3[0]!,
      uy = v3[1]!,
      uz = v3[2]!;
    return rayCapsule(ox, oy, oz, dx, dy, dz, cx - ux, cy - uy, cz - uz, cx + ux, cy + uy, cz + uz, r);
  }
  if (kind === Shape3DKind.Cylinder) {
    // In the cylinder's frame, then the normal back to the world.
    rotateVector(-x, -y, -z, w, ox - cx, oy - cy, oz - cz, v3);
    const lx = v3[0]!,
      ly = v3[1]!,
      lz = v3[2]!;
    rotateVector(-x, -y, -z, w, dx, dy, dz, v3);
    if (!rayCylinder(lx, ly, lz, v3[0]!, v3[1]!, v3[2]!, r, st.hy[e]!)) return false;
    rotateVector(x, y, z, w, hit.nx, hit.ny, hit.nz, v3);
    return setHit(hit.t, v3[0]!, v3[1]!, v3[2]!);
  }
  const h = st.hulls[st.hull[e]!]!,
    nf = h.faceOffsets.length;
  for (let f = 0; f < nf; f++) {
    rotateVector(x, y, z, w, h.faceNormals[3 * f]!, h.faceNormals[3 * f + 1]!, h.faceNormals[3 * f + 2]!, v3);
    fn[3 * f] = v3[0]!;
    fn[3 * f + 1] = v3[1]!;
    fn[3 * f + 2] = v3[2]!;
    fd[f] = h.faceOffsets[f]! + v3[0]! * cx + v3[1]! * cy + v3[2]! * cz;
  }
  return rayPolyhedron(ox, oy, oz, dx, dy, dz, fn, fd, nf);
}

/**
 * Every hit of the segment from `origin` to `origin + translation` (m), nearest first. A ray that starts inside a shape does not hit it. @throws TypeError on a 2D world or vectors that are not 3 finite numbers; RangeError on a zero translation.
 * @category Queries
 */
export function rayCastAll3D(world: PhysicsWorld, origin: ArrayLike<number>, translation: ArrayLike<number>): RayHit3D[] {
  checkRay('rayCastAll3D', world, origin, translation);
  const out: RayHit3D[] = [];
  const ox = origin[0]!,
    oy = origin[1]!,
    oz = origin[2]!,
    dx = translation[0]!,
    dy = translation[1]!,
    dz = translation[2]!;
  const push = (shape: number, body: number): void => {
    out.push({
      shape: currentHandle(world, shape),
      body: body === 0 ? 0 : currentHandle(world, body),
      fraction: hit.t,
      x: ox + hit.t * dx,
      y: oy + hit.t * dy,
      z: oz + hit.t * dz,
      nx: hit.nx,
      ny: hit.ny,
      nz: hit.nz,
    });
  };
  Object.assign(ray, { ox, oy, oz, dx, dy, dz });
  eachCollider(world, (s, e, b) => {
    if (rayCollider(s, e)) push(e, b);
  });
  const c = world.components;
  const planes = query(world, [c.Plane]);
  for (let i = 0; i < planes.length; i++) {
    const p = planes[i]!,
      nx = c.Plane.nx[p]!,
      ny = c.Plane.ny[p]!,
      nz = c.Plane.nz[p]!;
    const dist = nx * ox + ny * oy + nz * oz - c.Plane.d[p]!,
      den = nx * dx + ny * dy + nz * dz;
    if (dist <= 0 || den >= 0) continue;
    const t = -dist / den;
    if (t > 1) continue;
    setHit(t, nx, ny, nz);
    push(p, 0);
  }
  for (const m of meshesOf(world)) {
    const V = m.vertices,
      T = m.triangles;
    // `hit` holds the nearest triangle hit so far.
    let best = Infinity;
    for (let k = 0; k < T.length; k += 3) {
      const a = 3 * T[k]!,
        b = 3 * T[k + 1]!,
        cc = 3 * T[k + 2]!;
      const e1x = V[b]! - V[a]!,
        e1y = V[b + 1]! - V[a + 1]!,
        e1z = V[b + 2]! - V[a + 2]!;
      const e2x = V[cc]! - V[a]!,
        e2y = V[cc + 1]! - V[a + 1]!,
        e2z = V[cc + 2]! - V[a + 2]!;
      const px = dy * e2z - dz * e2y,
        py = dz * e2x - dx * e2z,
        pz = dx * e2y - dy * e2x;
      const det = e1x * px + e1y * py + e1z * pz;
      if (det <= 1e-300) continue; // one-sided: only the front (counter-clockwise) face, hit from outside
      const inv = 1 / det;
      const tx = ox - V[a]!,
        ty = oy - V[a + 1]!,
        tz = oz - V[a + 2]!;
      const u = (tx * px + ty * py + tz * pz) * inv;
      if (u < 0 || u > 1) continue;
      const qx = ty * e1z - tz * e1y,
        qy = tz * e1x - tx * e1z,
        qz = tx * e1y - ty * e1x;
      const v = (dx * qx + dy * qy + dz * qz) * inv;
      if (v < 0 || u + v > 1) continue;
      const t = (e2x * qx + e2y * qy + e2z * qz) * inv;
      if (t < 0 || t > 1 || t >= best) continue;
      best = t;
      const nx = e1y * e2z - e1z * e2y,
        ny = e1z * e2x - e1x * e2z,
        nz = e1x * e2y - e1y * e2x,
        l = Math.hypot(nx, ny, nz);
      setHit(t, nx / l, ny / l, nz / l);
    }
    if (best <= 1) push(m.entity, 0);
  }
  out.sort((a, b) => a.fraction - b.fraction);
  return out;
}

/**
 * The nearest hit of the segment from `origin` to `origin + translation` (m), or null. @throws as `rayCastAll3D`.
 * @category Queries
 */
export function rayCast3D(world: PhysicsWorld, origin: ArrayLike<number>, translation: ArrayLike<number>): RayHit3D | null {
  checkRay('rayCast3D', world, origin, translation);
  return rayCastAll3D(world, origin, translation)[0] ?? null;
}

/** Whether the point (px, py, pz), m, lies in the collider posed in `pose` (shape `e` of `s`, or a ball), boundary included. */
function shapeContains(st: Shape3DStore | undefined, e: number, px: number, py: number, pz: number): boolean {
  const { cx, cy, cz, x, y, z, w, kind, r } = pose;
  rotateVector(-x, -y, -z, w, px - cx, py - cy, pz - cz, v3);
  const lx = v3[0]!,
    ly = v3[1]!,
    lz = v3[2]!,
    s = st as Shape3DStore;
  switch (kind) {
    case Shape3DKind.Sphere:
      return lx * lx + ly * ly + lz * lz <= r * r;
    case Shape3DKind.Box:
      return Math.abs(lx) <= s.hx[e]! && Math.abs(ly) <= s.hy[e]! && Math.abs(lz) <= s.hz[e]!;
    case Shape3DKind.Capsule: {
      const hh = s.hy[e]!,
        cyc = ly > hh ? hh : ly < -hh ? -hh : ly,
        dy = ly - cyc;
      return lx * lx + dy * dy + lz * lz <= r * r;
    }
    case Shape3DKind.Cylinder:
      return lx * lx + lz * lz <= r * r && Math.abs(ly) <= s.hy[e]!;
    default: {
      const h = s.hulls[s.hull[e]!]!,
        N = h.faceNormals,
        D = h.faceOffsets;
      for (let f = 0; f < D.length; f++) if (N[3 * f]! * lx + N[3 * f + 1]! * ly + N[3 * f + 2]! * lz > D[f]!) return false;
      return true;
    }
  }
}

/** Fills `box` (min x, y, z, max x, y, z; m) with the world bounding box of the collider posed in `pose` (shape `e` of `s`, or a ball). */
function shapeBounds(st: Shape3DStore | undefined, e: number, box: Float64Array): void {
  const { cx, cy, cz, x, y, z, w, kind, r } = pose,
    s = st as Shape3DStore;
  if (kind === Shape3DKind.Sphere || kind === Shape3DKind.Capsule || kind === Shape3DKind.Cylinder) {
    // The axis u = R (0, 1, 0): the segment's ends reach |u_i| hh along world axis i (a sphere's
    // segment is a point, hh = 0); a sphere or capsule adds r, a cylinder's end disc r sqrt(1 - u_i^2).
    rotateVector(x, y, z, w, 0, 1, 0, v3);
    const hh = kind === Shape3DKind.Sphere ? 0 : s.hy[e]!,
      cap = kind !== Shape3DKind.Cylinder;
    for (let i = 0; i < 3; i++) {
      const u = v3[i]!,
        ext = Math.abs(u) * hh + (cap ? r : r * Math.sqrt(Math.max(0, 1 - u * u)));
      const c = i === 0 ? cx : i === 1 ? cy : cz;
      box[i] = c - ext;
      box[3 + i] = c + ext;
    }
    return;
  }
  // A box and a hull: their vertices, turned into the world.
  const V = s.hulls[s.hull[e]!]!.vertices;
  box[0] = box[1] = box[2] = Infinity;
  box[3] = box[4] = box[5] = -Infinity;
  for (let k = 0; k < V.length; k += 3) {
    rotateVector(x, y, z, w, V[k]!, V[k + 1]!, V[k + 2]!, v3);
    for (let i = 0; i < 3; i++) {
      const c = (i === 0 ? cx : i === 1 ? cy : cz) + v3[i]!;
      if (c < box[i]!) box[i] = c;
      if (c > box[3 + i]!) box[3 + i] = c;
    }
  }
}

/** The handles of the colliders (eachCollider: 3D shapes, then shapeless balls) for which `test` holds, posed in `pose`: a fresh array. */
function collect(world: PhysicsWorld, test: (s: Shape3DStore | undefined, e: number) => boolean): number[] {
  const out: number[] = [];
  eachCollider(world, (s, e) => {
    if (test(s, e)) out.push(currentHandle(world, e));
  });
  return out;
}

function checkWorld3D(where: string, world: PhysicsWorld): void {
  if (world.dimensions !== 3)
    throw new TypeError(`${where}: needs a 3D world (use ${where.replace('3D', '')} in 2D), got dimensions ${world.dimensions}`);
}

/**
 * The shapes (handles) that contain `point` (m, world), boundary included: every 3D shape as its
 * kind describes it (shapes3d/; a cylinder the round one), every ball body without a 3D shape (a
 * sphere of its `Ball` radius), and every plane, which is solid on the side its normal points away
 * from (a point at or below the ground is in it). Triangle meshes and height fields are surfaces
 * with no inside and are never returned; sensors are. Where the bodies are now (`Position`,
 * `Orientation`); time linear in the number of shapes. A fresh array each call, in no set order.
 * @throws TypeError on a 2D world or a point that is not 3 finite numbers.
 * @category Queries
 */
export function overlapPoint3D(world: PhysicsWorld, point: ArrayLike<number>): number[] {
  const where = 'overlapPoint3D';
  checkWorld3D(where, world);
  assertVector(where, 'point', point, 3);
  const px = point[0]!,
    py = point[1]!,
    pz = point[2]!;
  const c = world.components;
  const out = collect(world, (s, e) => shapeContains(s, e, px, py, pz));
  const planes = query(world, [c.Plane]);
  for (let i = 0; i < planes.length; i++) {
    const p = planes[i]!;
    if (c.Plane.nx[p]! * px + c.Plane.ny[p]! * py + c.Plane.nz[p]! * pz <= c.Plane.d[p]!) out.push(currentHandle(world, p));
  }
  return out;
}

const bounds = new Float64Array(6);

/**
 * The shapes (handles) whose world bounding boxes meet the box [min, max] (m, world), touching
 * included: every 3D shape (the tight box of its kind: a rotated box's corners, a cylinder's end
 * discs, a hull's vertices), every ball body without a 3D shape, every plane whose solid side (see
 * `overlapPoint3D`) reaches into the box, and every triangle mesh or height field with a triangle
 * whose bounding box meets it. Sensors are returned too. Where the bodies are now; time linear in
 * the number of shapes and triangles. A fresh array each call, in no set order.
 * @throws TypeError on a 2D world or corners that are not 3 finite numbers; RangeError if min exceeds max on an axis.
 * @category Queries
 */
export function overlapAABB3D(world: PhysicsWorld, min: ArrayLike<number>, max: ArrayLike<number>): number[] {
  const where = 'overlapAABB3D';
  checkWorld3D(where, world);
  assertVector(where, 'min', min, 3);
  assertVector(where, 'max', max, 3);
  const x0 = min[0]!,
    y0 = min[1]!,
    z0 = min[2]!,
    x1 = max[0]!,
    y1 = max[1]!,
    z1 = max[2]!;
  if (!(x0 <= x1 && y0 <= y1 && z0 <= z1))
    throw new RangeError(`${where}: min must not exceed max, got ${describe(min)} and ${describe(max)}`);
  const meets = (b: Float64Array): boolean => b[0]! <= x1 && b[3]! >= x0 && b[1]! <= y1 && b[4]! >= y0 && b[2]! <= z1 && b[5]! >= z0;
  const c = world.components;
  const out = collect(world, (s, e) => {
    shapeBounds(s, e, bounds);
    return meets(bounds);
  });
  const planes = query(world, [c.Plane]);
  for (let i = 0; i < planes.length; i++) {
    const p = planes[i]!,
      nx = c.Plane.nx[p]!,
      ny = c.Plane.ny[p]!,
      nz = c.Plane.nz[p]!;
    // The box's lowest value of n . x (the corner farthest against n) against d.
    const low = (nx > 0 ? nx * x0 : nx * x1) + (ny > 0 ? ny * y0 : ny * y1) + (nz > 0 ? nz * z0 : nz * z1);
    if (low <= c.Plane.d[p]!) out.push(currentHandle(world, p));
  }
  for (const m of meshesOf(world)) {
    const V = m.vertices,
      T = m.triangles;
    for (let k = 0; k < T.length; k += 3) {
      const a = 3 * T[k]!,
        b = 3 * T[k + 1]!,
        d = 3 * T[k + 2]!;
      for (let i = 0; i < 3; i++) {
        const va = V[a + i]!,
          vb = V[b + i]!,
          vd = V[d + i]!;
        bounds[i] = Math.min(va, vb, vd);
        bounds[3 + i] = Math.max(va, vb, vd);
      }
      if (meets(bounds)) {
        out.push(currentHandle(world, m.entity));
        break;
      }
    }
  }
  return out;
}
