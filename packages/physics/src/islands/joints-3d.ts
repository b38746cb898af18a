import { hasComponent } from 'bitecs';
import { joints3DOf } from '../joints/store-3d.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * A 3D joint that carried an impulse in the last step (any of its rows' accumulated impulses is not 0)
 * supports its bodies, as a 2D joint does (`markJointSupport`): a bob at rest on its string may sleep.
 * @category Joints and ropes
 */
export function markJoint3DSupport(world: PhysicsWorld, supported: Uint32Array, stamp: number): void {
  const s = joints3DOf(world);
  if (s === undefined || world.dimensions !== 3 || s.list.length === 0) return;
  const list = s.list;
  for (let i = 0; i < list.length; i++) {
    const j: number = list[i]!;
    const load =
      Math.abs(s.lx[j]!) +
      Math.abs(s.ly[j]!) +
      Math.abs(s.lz[j]!) +
      Math.abs(s.wx[j]!) +
      Math.abs(s.wy[j]!) +
      Math.abs(s.wz[j]!) +
      Math.abs(s.limit[j]!) +
      Math.abs(s.motor[j]!);
    if (!(load > 0)) continue;
    supported[s.a[j]!] = stamp;
    supported[s.b[j]!] = stamp;
  }
}

/**
 * 3D joints in the sleeping islands (islands/sleep.ts), as `joinJointIslands` does for 2D joints:
 * bodies joined by a 3D joint sleep and wake together (Box2D v3's islands join bodies through
 * contacts and joints alike). Without it each jointed body slept on its own: a ragdoll's upper arm
 * fell asleep while the forearm hinged to it kept swinging, on an elbow that no longer moved.
 *
 * `bodies` are this step's sleep candidates, whose union-find `parent` is initialised (parent[e] = e);
 * `member` is per-entity scratch (capacity + 1 slots) that this call stamps with `stamp` to mark them.
 * A joint between two candidates unites their islands. A joint from a candidate to a body that moves
 * and cannot sleep (kinematic, or dynamic but not a candidate: one without a collider) resets the
 * candidate's rest time, so it stays awake; the fixed world and static bodies hold nothing awake. A
 * sleeping body jointed to a candidate that moves (rest time 0) is returned, for the caller to wake
 * its island (it would otherwise hold the moving body like a fixed anchor); null when there is none.
 * @category Joints and ropes
 */
export function joinJoint3DIslands(
  world: PhysicsWorld,
  bodies: ArrayLike<number>,
  rest: Float64Array,
  parent: Int32Array,
  member: Uint32Array,
  stamp: number,
): number[] | null {
  const s = joints3DOf(world);
  if (s === undefined || world.dimensions !== 3 || s.list.length === 0) return null;
  for (let i = 0; i < bodies.length; i++) member[bodies[i]!] = stamp;
  const find = (x: number): number => {
    while (parent[x] !== x) {
      parent[x] = parent[parent[x]!]!;
      x = parent[x]!;
    }
    return x;
  };
  const c = world.components;
  const list = s.list;
  let wake: number[] | null = null;
  for (let i = 0; i < list.length; i++) {
    const j: number = list[i]!;
    const a: number = s.a[j]!,
      b: number = s.b[j]!;
    const inA: boolean = a !== 0 && member[a] === stamp,
      inB: boolean = b !== 0 && member[b] === stamp;
    if (inA && inB) {
      const ra = find(a),
        rb = find(b);
      if (ra !== rb) parent[ra] = rb;
    } else if (inA !== inB) {
      const other = inA ? b : a,
        own = inA ? a : b;
      if (other === 0 || hasComponent(world, other, c.Static)) continue;
      if (hasComponent(world, other, c.Sleeping)) {
        if (rest[own] === 0) (wake ??= []).push(other);
        continue;
      }
      rest[own] = 0;
    }
  }
  return wake;
}
