import { hasComponent } from 'bitecs';
import { type ConvexGeometry, createGeometry } from '../shapes/geometry-2d.js';
import { assertVector, describe } from '../validation/validate.js';
import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { SHAPE_STRIDE } from '../world/shape-store-2d.js';

/**
 * Queries games need (2D): ray casts (closest hit, all hits), the shapes covering a point, and the
 * shapes whose bounding boxes meet an axis-aligned box; for picking, line of sight and spawning. They
 * read the bodies where they are now (`Position`, `Angle`), every shape (`Components.Shape`) and
 * every ball (a circle), and run in time linear in the number of shapes (no acceleration structure;
 * call them a few times a frame, not per body).
 *
 * Every shape is a convex core inflated by its radius (shapes/geometry-2d.ts), so a ray's first hit is
 * the nearest of its hits on the core's edges moved out by the radius along their normals and on the
 * circles of that radius at the core's vertices (Ericson, Real-Time Collision Detection, 5.3.2 ray
 * against a circle, 5.3.8 against a convex polygon by clipping to its edge half-planes).
 */

/**
 * One ray hit. Entities are handles (as the API hands out).
 * @category Queries
 */
export interface RayHit {
  /** The shape hit (a ball body for a ball). */
  shape: number;
  /** Its body. */
  body: number;
  /** Where along the ray, in [0, 1] of the translation. */
  fraction: number;
  /** The point hit, x, m. */
  x: number;
  /** The point hit, y, m. */
  y: number;
  /** The surface's outward unit normal there, x. */
  nx: number;
  /** The surface's outward unit normal there, y. */
  ny: number;
}

const g = createGeometry();

/** Fills `g` with collider `e`'s geometry in world frame (where its body is now); false if `e` is neither a shape nor a ball. */
function worldGeometry(world: PhysicsWorld, e: number, out: ConvexGeometry): number {
  const c = world.components,
    S = c.Shape;
  if (S.body.length > e && hasComponent(world, e, c.Shape)) {
    const b = S.body[e]!;
    const a = hasComponent(world, b, c.Angle) ? c.Angle.value[b]! : 0;
    const ca = Math.cos(a),
      sa = Math.sin(a),
      x = c.Position.x[b]!,
      y = c.Position.y[b]!;
    const n = S.count[e]!,
      o = SHAPE_STRIDE * e;
    out.count = n;
    out.radius = S.radius[e]!;
    out.kind = S.kind[e]!;
    for (let i = 0; i < n; i++) {
      const lx = S.vx[o + i]!,
        ly = S.vy[o + i]!;
      out.vx[i] = x + ca * lx - sa * ly;
      out.vy[i] = y + sa * lx + ca * ly;
      const nx = S.nx[o + i]!,
        ny = S.ny[o + i]!;
      out.nx[i] = ca * nx - sa * ny;
      out.ny[i] = sa * nx + ca * ny;
    }
    return b;
  }
  out.count = 1;
  out.radius = c.Ball.radius[e]!;
  out.kind = 0;
  out.vx[0] = c.Position.x[e]!;
  out.vy[0] = c.Position.y[e]!;
  return e;
}

/** Every collider: shape entities, then balls that carry no shape of their own. */
function colliders(world: PhysicsWorld): number[] {
  const c = world.components;
  const out: number[] = [];
  if (world.dimensions !== 2) return out;
  const shapes = query(world, [c.Shape]);
  for (let i = 0; i < shapes.length; i++) out.push(shapes[i]!);
  const balls = query(world, [c.Position, c.Ball]);
  for (let i = 0; i < balls.length; i++) if (!hasComponent(world, balls[i]!, c.Shape)) out.push(balls[i]!);
  return out;
}

const hit = { t: 0, nx: 0, ny: 0 };

/** First hit in [0, 1] of the ray p + t d on `g` (world frame), into `hit`; false if none (or the ray starts inside). */
function rayShape(px: number, py: number, dx: number, dy: number, s: ConvexGeometry): boolean {
  let best = Infinity,
    bnx = 0,
    bny = 0;
  const r = s.radius,
    n = s.count;
  if (n >= 2) {
    // Edges moved out by r; only from their outer side.
    for (let i = 0; i < n; i++) {
      const j = i + 1 < n ? i + 1 : 0;
      const nx = s.nx[i]!,
        ny = s.ny[i]!;
      const denom = nx * dx + ny * dy;
      if (denom >= 0) continue;
      const ax = s.vx[i]! + r * nx,
        ay = s.vy[i]! + r * ny;
      const t = (nx * (ax - px) + ny * (ay - py)) / denom;
      if (t < 0 || t > 1 || t >= best) continue;
      const qx = px + t * dx - ax,
        qy = py + t * dy - ay;
      const ex = s.vx[j]! - s.vx[i]!,
        ey = s.vy[j]! - s.vy[i]!;
      const u = qx * ex + qy * ey;
      if (u < 0 || u > ex * ex + ey * ey) continue;
      best = t;
      bnx = nx;
      bny = ny;
    }
  }
  if (r > 0) {
    for (let i = 0; i < n; i++) {
      const cx = s.vx[i]!,
        cy = s.vy[i]!;
      const mx = px - cx,
        my = py - cy;
      const a = dx * dx + dy * dy,
        b = mx * dx + my * dy,
        c = mx * mx + my * my - r * r;
      if (c < 0 || b > 0) continue; // starts inside this circle, or heads away
      const disc = b * b - a * c;
      if (disc < 0) continue;
      const t = (-b - Math.sqrt(disc)) / a;
      if (t < 0 || t > 1 || t >= best) continue;
      best = t;
      bnx = (mx + t * dx) / r;
      bny = (my + t * dy) / r;
    }
  }
  if (best === Infinity) return false;
  // A ray starting inside the shape reports nothing (Box2D's convention).
  if (pointDistance(px, py, s) <= r) return false;
  hit.t = best;
  hit.nx = bnx;
  hit.ny = bny;
  return true;
}

/** Distance from (x, y) to the core of `s` (0 inside a polygon core), m. */
function pointDistance(x: number, y: number, s: ConvexGeometry): number {
  const n = s.count;
  if (n === 1) return Math.hypot(x - s.vx[0]!, y - s.vy[0]!);
  let inside = n >= 3;
  let best = Infinity;
  for (let i = 0; i < n; i++) {
    const j = i + 1 < n ? i + 1 : 0;
    if (n >= 3 && s.nx[i]! * (x - s.vx[i]!) + s.ny[i]! * (y - s.vy[i]!) > 0) inside = false;
    const ax = s.vx[i]!,
      ay = s.vy[i]!,
      ex = s.vx[j]! - ax,
      ey = s.vy[j]! - ay;
    const len2 = ex * ex + ey * ey;
    let u = len2 > 0 ? ((x - ax) * ex + (y - ay) * ey) / len2 : 0;
    u = u < 0 ? 0 : u > 1 ? 1 : u;
    const d = Math.hypot(x - ax - u * ex, y - ay - u * ey);
    if (d < best) best = d;
  }
  return inside ? 0 : best;
}

function checkRay(where: string, world: PhysicsWorld, origin: unknown, translation: unknown): void {
  if (world.dimensions !== 2) throw new TypeError(`${where}: ray casts here are 2D; this world has 3 dimensions (use ${where}3D)`);
  assertVector(where, 'origin', origin, 2);
  assertVector(where, 'translation', translation, 2);
  if (translation[0] === 0 && translation[1] === 0)
    throw new RangeError(`${where}: translation must not be zero, got ${describe(translation)}`);
}

/**
 * Every shape the segment from `origin` to `origin + translation` (m) crosses, nearest first, with the
 * point, normal and fraction where it enters each. A ray that starts inside a shape does not hit it.
 * @throws TypeError on a 3D world or vectors that are not 2 finite numbers; RangeError on a zero translation.
 * @category Queries
 */
export function rayCastAll(world: PhysicsWorld, origin: ArrayLike<number>, translation: ArrayLike<number>): RayHit[] {
  checkRay('rayCastAll', world, origin, translation);
  const px = origin[0]!,
    py = origin[1]!,
    dx = translation[0]!,
    dy = translation[1]!;
  const hits: RayHit[] = [];
  for (const e of colliders(world)) {
    const b = worldGeometry(world, e, g);
    if (!rayShape(px, py, dx, dy, g)) continue;
    hits.push({
      shape: currentHandle(world, e),
      body: currentHandle(world, b),
      fraction: hit.t,
      x: px + hit.t * dx,
      y: py + hit.t * dy,
      nx: hit.nx,
      ny: hit.ny,
    });
  }
  hits.sort((a, b) => a.fraction - b.fraction);
  return hits;
}

/**
 * The nearest shape hit by the segment from `origin` to `origin + translation` (m), or null. @throws as `rayCastAll`.
 * @category Queries
 */
export function rayCast(world: PhysicsWorld, origin: ArrayLike<number>, translation: ArrayLike<number>): RayHit | null {
  checkRay('rayCast', world, origin, translation);
  return rayCastAll(world, origin, translation)[0] ?? null;
}

/**
 * The shapes (handles) that contain `point` (m): within their radius of their core.
 * @throws TypeError on a 3D world or a point that is not 2 finite numbers.
 * @category Queries
 */
export function overlapPoint(world: PhysicsWorld, point: ArrayLike<number>): number[] {
  if (world.dimensions !== 2)
    throw new TypeError('overlapPoint: shape queries here are 2D; this world has 3 dimensions (use overlapPoint3D)');
  assertVector('overlapPoint', 'point', point, 2);
  const out: number[] = [];
  for (const e of colliders(world)) {
    worldGeometry(world, e, g);
    if (pointDistance(point[0]!, point[1]!, g) <= g.radius) out.push(currentHandle(world, e));
  }
  return out;
}

/**
 * The shapes (handles) whose bounding boxes (where their bodies are now) meet the box [min, max] (m).
 * @throws TypeError on a 3D world or corners that are not 2 finite numbers; RangeError if min > max.
 * @category Queries
 */
export function overlapAABB(world: PhysicsWorld, min: ArrayLike<number>, max: ArrayLike<number>): number[] {
  const where = 'overlapAABB';
  if (world.dimensions !== 2) throw new TypeError(`${where}: shape queries here are 2D; this world has 3 dimensions (use overlapAABB3D)`);
  assertVector(where, 'min', min, 2);
  assertVector(where, 'max', max, 2);
  if (!(min[0]! <= max[0]! && min[1]! <= max[1]!))
    throw new RangeError(`${where}: min must not exceed max, got ${describe(min)} and ${describe(max)}`);
  const out: number[] = [];
  for (const e of colliders(world)) {
    worldGeometry(world, e, g);
    let x0 = Infinity,
      y0 = Infinity,
      x1 = -Infinity,
      y1 = -Infinity;
    for (let i = 0; i < g.count; i++) {
      const x = g.vx[i]!,
        y = g.vy[i]!;
      if (x < x0) x0 = x;
      if (x > x1) x1 = x;
      if (y < y0) y0 = y;
      if (y > y1) y1 = y;
    }
    const r = g.radius;
    if (x0 - r <= max[0]! && x1 + r >= min[0]! && y0 - r <= max[1]! && y1 + r >= min[1]!) out.push(currentHandle(world, e));
  }
  return out;
}
