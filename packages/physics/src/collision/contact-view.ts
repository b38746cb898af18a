/**
 * `forEachContact(world, fn)`: one read path for every contact point of the last step, in 2D and 3D:
 * the ball rows (collision/contacts.ts), the 2D shape manifolds (collision/manifolds-2d.ts) and the 3D
 * shape manifolds (collision/manifolds-3d.ts), handed out as one kind of view.
 */

import { ANCHOR_BX, ANCHOR_BY, ANCHOR_BZ, ANCHOR_STRIDE } from '../solver/manifold-layout-3d.js';
import type { PhysicsWorld } from '../world/options.js';
import { ContactKind } from './contacts.js';
import { contact3DStateOf } from './manifolds-3d.js';

/**
 * One contact point of the last step, as `forEachContact` hands it out (the same object each call:
 * copy what you keep). Entities are slots (index stores with them; `handleOf` gives a handle).
 * @category Collision
 */
export interface ContactView {
  /**
   * ContactKind of the contact: `Ball`, `Boundary`, `Segment`, `StaticBall` or `Plane` for a ball
   * body's contact with another ball or with static geometry, `Shape` for a contact of shapes (2D or
   * 3D manifolds, a ball body against a shape included).
   */
  kind: number;
  /** Body A's slot; 0 for the static world (the body of a segment, a plane or a boundary face). */
  bodyA: number;
  /** Body B's slot (always a body that moves or can). */
  bodyB: number;
  /** Shape A's slot: a shape entity, a ball body (its own shape), a segment, plane or static ball; -1 - face for a boundary face. */
  shapeA: number;
  /** Shape B's slot (a shape entity, or a ball body). */
  shapeB: number;
  /**
   * For ball contacts: body A's slot, or the static feature's (static
   * ball, segment or plane); 0 for the boundary box. For shape contacts, `bodyA`.
   */
  a: number;
  /** `bodyB`. */
  b: number;
  /** Unit normal from A to B, x (z is 0 in 2D). */
  nx: number;
  /** Normal y (`nx` its x). */
  ny: number;
  /** Normal z (`nx` its x). */
  nz: number;
  /**
   * Contact point, world frame, m: on B's surface at the end of the step (B's centre of mass at the end
   * of the step plus the point's anchor from it; for a ball, its centre minus its radius along n).
   */
  x: number;
  /** Contact point y, m (`x` its x). */
  y: number;
  /** Contact point z, m (`x` its x). */
  z: number;
  /**
   * Normal impulse the point carried, N s (>= 0; 0 for a speculative point that never touched; B got
   * +impulse n, A -impulse n): a ball contact's over the whole step (impact, substeps, restitution),
   * a 2D shape point's summed over the step's substeps, a 3D shape point's in the last substep.
   */
  impulse: number;
  /**
   * Separation along the normal at the start of the step, m (negative: overlap; positive: a speculative
   * contact); for a ball the impact stage moved, from where its end-position correction puts its start
   * (see solver/impacts.ts).
   */
  separation: number;
}

const view: ContactView = {
  kind: 0,
  bodyA: 0,
  bodyB: 0,
  shapeA: 0,
  shapeB: 0,
  a: 0,
  b: 0,
  nx: 0,
  ny: 0,
  nz: 0,
  x: 0,
  y: 0,
  z: 0,
  impulse: 0,
  separation: 0,
};

/**
 * Calls `fn` once for every contact point of the last step, 2D or 3D: ball contacts (ball-ball,
 * ball-boundary, ball-segment, ball-static-ball, ball-plane), then the points of the shape manifolds
 * (up to two a 2D manifold, four a 3D one), with a reused view (see ContactView). The lists are the
 * narrowphase's: they include speculative contacts that did not touch (impulse 0).
 * `fn` must not step or change the world.
 * @returns the number of points visited.
 * @throws whatever `fn` throws (the world is not changed by reading).
 * @category Collision
 */
export function forEachContact(world: PhysicsWorld, fn: (contact: Readonly<ContactView>) => void): number {
  return ballContacts(world, fn) + (world.dimensions === 2 ? shapeContacts2D(world, fn) : shapeContacts3D(world, fn));
}

/**
 * `forEachContact`, kept for programs written when 3D shape contacts had their own call (it now visits
 * ball contacts too; `kind` tells them apart).
 * @deprecated use `forEachContact`, which serves 2D and 3D.
 * @category Collision
 */
export function forEachContact3D(world: PhysicsWorld, fn: (contact: Readonly<ContactView>) => void): number {
  return forEachContact(world, fn);
}

/** The ball rows of the last step (the warm-start cache's rows). */
function ballContacts(world: PhysicsWorld, fn: (contact: Readonly<ContactView>) => void): number {
  const rows = world.collision.cache.rows;
  const P = world.components.Position;
  const n = rows.count;
  for (let i = 0; i < n; i++) {
    const kind = rows.kind[i]!,
      b = rows.b[i]!,
      f = rows.feature[i]!;
    view.kind = kind;
    view.a = kind === ContactKind.Ball ? rows.a[i]! : kind === ContactKind.Boundary ? 0 : f;
    view.b = b;
    view.bodyA = kind === ContactKind.Ball ? rows.a[i]! : kind === ContactKind.StaticBall ? f : 0;
    view.bodyB = b;
    view.shapeA = kind === ContactKind.Ball ? rows.a[i]! : kind === ContactKind.Boundary ? -1 - f : f;
    view.shapeB = b;
    const nx = rows.nx[i]!,
      ny = rows.ny[i]!,
      nz = rows.nz[i]!,
      rb = rows.rb[i]!;
    view.nx = nx;
    view.ny = ny;
    view.nz = nz;
    view.x = P.x[b]! - rb * nx;
    view.y = P.y[b]! - rb * ny;
    view.z = P.z[b]! - rb * nz;
    view.impulse = rows.impulse[i]!;
    view.separation = rows.separation[i]!;
    fn(view);
  }
  return n;
}

/** The columns of a buffer of shape manifolds that `shapeContacts` reads (2D or 3D). */
interface ManifoldColumns {
  /** Manifolds in the buffer. */
  count: number;
  /** Body and shape slots of manifold i (ContactView's fields of the same names). */
  bodyA: ArrayLike<number>;
  bodyB: ArrayLike<number>;
  shapeA: ArrayLike<number>;
  shapeB: ArrayLike<number>;
  /** Unit normal of manifold i, from A to B. */
  nx: ArrayLike<number>;
  ny: ArrayLike<number>;
  /** Normal z of manifold i; null in 2D (where it is 0). */
  nz: ArrayLike<number> | null;
  /** Points of manifold i. */
  points: ArrayLike<number>;
  /** Point slots a manifold (point p of manifold i is at stride i + p). */
  stride: number;
  /**
   * Point anchors from body B's centre of mass, m; rz null in 2D. Point slot q's x is at rx[rStride q + rx0]
   * (y, z likewise: columns have rStride 1 and offsets 0; an interleaved array is passed as all three).
   */
  rx: ArrayLike<number>;
  ry: ArrayLike<number>;
  rz: ArrayLike<number> | null;
  rStride: number;
  rx0: number;
  ry0: number;
  rz0: number;
  /** Normal impulse of each point, N s. */
  impulse: ArrayLike<number>;
  /** Separation of each point, m. */
  separation: ArrayLike<number>;
}

/** The points of a buffer of shape manifolds, handed to `fn` in the reused view. */
function shapeContacts(world: PhysicsWorld, buf: ManifoldColumns, fn: (contact: Readonly<ContactView>) => void): number {
  const P = world.components.Position,
    nz = buf.nz,
    rz = buf.rz;
  let visited = 0;
  view.nz = 0;
  view.z = 0;
  for (let i = 0; i < buf.count; i++) {
    const b = buf.bodyB[i]!;
    view.bodyA = view.a = buf.bodyA[i]!;
    view.bodyB = view.b = b;
    view.shapeA = buf.shapeA[i]!;
    view.shapeB = buf.shapeB[i]!;
    view.nx = buf.nx[i]!;
    view.ny = buf.ny[i]!;
    if (nz !== null) view.nz = nz[i]!;
    for (let p = 0, m = buf.points[i]!; p < m; p++) {
      const q = buf.stride * i + p,
        r = buf.rStride * q;
      view.x = P.x[b]! + buf.rx[r + buf.rx0]!;
      view.y = P.y[b]! + buf.ry[r + buf.ry0]!;
      if (rz !== null) view.z = P.z[b]! + rz[r + buf.rz0]!;
      view.impulse = buf.impulse[q]!;
      view.separation = buf.separation[q]!;
      view.kind = ContactKind.Shape;
      fn(view);
      visited++;
    }
  }
  return visited;
}

/** The 2D shape manifolds of the last step (`previous` once the step rotated its buffers). */
function shapeContacts2D(world: PhysicsWorld, fn: (contact: Readonly<ContactView>) => void): number {
  const st = world.collision.shapes;
  if (!st.active) return 0;
  const b = st.previous;
  return shapeContacts(
    world,
    {
      ...b,
      nz: null,
      points: b.pointCount,
      stride: 2,
      rx: b.rBx,
      ry: b.rBy,
      rz: null,
      rStride: 1,
      rx0: 0,
      ry0: 0,
      rz0: 0,
      impulse: b.totalNormalImpulse,
    },
    fn,
  );
}

/** The 3D shape manifolds of the last step. */
function shapeContacts3D(world: PhysicsWorld, fn: (contact: Readonly<ContactView>) => void): number {
  const st = contact3DStateOf(world);
  if (st === undefined) return 0;
  const b = st.current;
  const R = b.anchors;
  return shapeContacts(
    world,
    {
      ...b,
      stride: 4,
      rx: R,
      ry: R,
      rz: R,
      rStride: ANCHOR_STRIDE,
      rx0: ANCHOR_BX,
      ry0: ANCHOR_BY,
      rz0: ANCHOR_BZ,
      impulse: b.ln,
      separation: b.sep,
    },
    fn,
  );
}
