import { BodyType } from '../collision/state.js';
import type { PhysicsWorld } from '../world/options.js';
import { Not, query } from '../world/query.js';

/**
 * Sleeping for shape bodies (used by islands/sleep.ts): shape bodies join the bodies that may sleep, a shape
 * contact that pushed this step supports both its bodies, and shape contacts between two dynamic
 * bodies that pushed tie them into one island (Box2D v3's islands over touching contacts).
 */

/**
 * The bodies that may fall asleep this step: `balls` (islands/sleep.ts's query of awake dynamic balls) plus
 * the awake dynamic bodies carrying a shape. Returns `balls` itself when the world has no shapes;
 * otherwise a view of a reused array (valid until the next call).
 * @category Collision
 */
export function withShapeBodies(world: PhysicsWorld, balls: ArrayLike<number>): ArrayLike<number> {
  const st = world.collision.shapes;
  if (!st.active) return balls;
  const c = world.components;
  const shaped = query(world, [c.Position, c.Velocity, c.Shape, c.Force, Not(c.Ball), Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)]);
  const n = balls.length + shaped.length;
  if (st.sleepList.length < n) st.sleepList = new Uint32Array(Math.max(n, 2 * st.sleepList.length));
  const out = st.sleepList;
  for (let i = 0; i < balls.length; i++) out[i] = balls[i]!;
  for (let i = 0; i < shaped.length; i++) out[balls.length + i] = shaped[i]!;
  return out.subarray(0, n);
}

/**
 * Marks `supported[e] = stamp` for both bodies of every shape contact that carried a normal impulse this step.
 * @category Collision
 */
export function markShapeSupport(world: PhysicsWorld, supported: Uint32Array, stamp: number): void {
  const st = world.collision.shapes;
  if (!st.active) return;
  const rows = st.previous; // this step's rows (finishManifolds made them the cache)
  for (let i = 0, n = rows.count; i < n; i++) {
    if (!pushed(rows, i)) continue;
    supported[rows.bodyA[i]!] = stamp;
    supported[rows.bodyB[i]!] = stamp;
  }
}

/**
 * Unites, in the union-find `parent` (with its `find`), the two bodies of every shape contact between dynamic bodies that pushed.
 * @category Collision
 */
export function joinShapeIslands(world: PhysicsWorld, parent: Int32Array, find: (x: number) => number): void {
  const st = world.collision.shapes;
  if (!st.active) return;
  const rows = st.previous,
    type = world.collision.bodyType;
  for (let i = 0, n = rows.count; i < n; i++) {
    const a = rows.bodyA[i]!,
      b = rows.bodyB[i]!;
    if (a === 0 || type[a] !== BodyType.Dynamic || type[b] !== BodyType.Dynamic || !pushed(rows, i)) continue;
    const ra = find(a),
      rb = find(b);
    if (ra !== rb) parent[ra] = rb;
  }
}

function pushed(rows: PhysicsWorld['collision']['shapes']['previous'], i: number): boolean {
  for (let p = 0, m = rows.pointCount[i]!; p < m; p++) if (rows.normalImpulse[2 * i + p]! > 0) return true;
  return false;
}
