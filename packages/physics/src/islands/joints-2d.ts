import { JointType } from '../world/joint-store-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';

/**
 * Joints in the sleeping islands (islands/sleep.ts): bodies joined by a joint sleep and wake
 * together, as Box2D v3's islands join bodies through contacts and joints alike.
 */

/**
 * A joint that carried force in the last step supports its bodies (a pendulum at rest hangs on its pin).
 * @category Joints and ropes
 */
export function markJointSupport(world: PhysicsWorld, supported: Uint32Array, stamp: number): void {
  if (world.joints.attached.length === 0) return;
  const J = world.components.Joint;
  const joints = query(world, [J]);
  for (let i = 0; i < joints.length; i++) {
    const j = joints[i]!;
    if (!(J.force[j]! > 0)) continue;
    supported[J.a[j]!] = stamp;
    supported[J.b[j]!] = stamp;
  }
}

/**
 * Joins the islands of the sleep candidates `bodies` (whose union-find `parent` is initialised) that
 * a joint holds together. A body dragged by a mouse joint, or jointed to a moving body that cannot
 * sleep (one without a collider), keeps its island awake (its rest time is reset).
 * @category Joints and ropes
 */
export function joinJointIslands(world: PhysicsWorld, bodies: ArrayLike<number>, rest: Float64Array, parent: Int32Array): void {
  const js = world.joints;
  if (js.attached.length === 0) return;
  const J = world.components.Joint;
  const joints = query(world, [J]);
  if (joints.length === 0) return;
  const mark = js.bodyStamp,
    cls = js.bodyClass;
  const stamp = ++js.stamp;
  for (let i = 0; i < bodies.length; i++) mark[bodies[i]!] = stamp;
  const find = (x: number): number => {
    while (parent[x] !== x) {
      parent[x] = parent[parent[x]!]!;
      x = parent[x]!;
    }
    return x;
  };
  for (let i = 0; i < joints.length; i++) {
    const j = joints[i]!;
    const a = J.a[j]!,
      b = J.b[j]!;
    const inA = a !== 0 && mark[a] === stamp,
      inB = mark[b] === stamp;
    if (J.type[j] === JointType.Mouse) {
      rest[b] = 0;
      continue;
    }
    if (inA && inB) {
      const ra = find(a),
        rb = find(b);
      if (ra !== rb) parent[ra] = rb;
    } else if (inA !== inB) {
      // The other end is the world, a fixed body, or a moving body that never sleeps (class from the
      // last solver gather: 0 dynamic, 1 kinematic).
      const other = inA ? b : a;
      if (other !== 0 && (cls[other]! & 3) <= 1) rest[inA ? a : b] = 0;
    }
  }
}
