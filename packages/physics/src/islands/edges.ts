import { hasComponent } from 'bitecs';
import { contact3DStateOf } from '../collision/manifolds-3d.js';
import { BodyType } from '../collision/state.js';
import { JointType } from '../world/joint-store-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { markWritable } from '../world/writable-fields.js';

/**
 * The island graph of one step (after Box2D v3's islands, which join bodies through touching contacts
 * and joints alike): one list of edges that every contact store and joint store of the world adds to,
 * read by the sleep system (islands/sleep.ts) for support and for its union-find. An edge is a body
 * pair with flags:
 *
 * - `SUPPORTS`: a contact or joint that carried an impulse this step; it supports both bodies (only a
 *   supported body rests, so a body in free flight never sleeps).
 * - `JOINS`: a contact that pushed; when both bodies are dynamic it ties them into one island.
 * - `JOINT`: a joint (any load); its bodies sleep and wake together (see `joinJointEdges`).
 * - `MOUSE`: a mouse joint; the body it drags stays awake.
 *
 * The list is scratch, rebuilt from the stores at every sleep-system run and valid until the next
 * (it carries nothing between steps and is shared by every world in the program).
 */
export interface IslandEdges {
  /** Edges in use. */
  count: number;
  /** Per edge: first body (0: the static world). */
  a: Int32Array;
  /** Per edge: second body. */
  b: Int32Array;
  /** Per edge: `EdgeFlag` bits. */
  flags: Uint8Array;
}

/**
 * Bits of `IslandEdges.flags`.
 * @category Sleep
 */
export const EdgeFlag = Object.freeze({ SUPPORTS: 1, JOINS: 2, JOINT: 4, MOUSE: 8 } as const);

const edges: IslandEdges = { count: 0, a: new Int32Array(64), b: new Int32Array(64), flags: new Uint8Array(64) };
// Grown by a large world's first step (world/writable-fields.ts).
markWritable(edges, ['count', 'a', 'b', 'flags']);

/**
 * The island edges' scratch, emptied (see IslandEdges).
 * @category Sleep
 */
export function emptyIslandEdges(): IslandEdges {
  edges.count = 0;
  return edges;
}

/**
 * Appends the edge (a, b) with `flags` to `e`, growing its arrays as needed.
 * @category Sleep
 */
export function addIslandEdge(e: IslandEdges, a: number, b: number, flags: number): void {
  const k = e.count;
  if (k === e.a.length) {
    const n = 2 * k;
    const a2 = new Int32Array(n),
      b2 = new Int32Array(n),
      f2 = new Uint8Array(n);
    a2.set(e.a);
    b2.set(e.b);
    f2.set(e.flags);
    e.a = a2;
    e.b = b2;
    e.flags = f2;
  }
  e.a[k] = a;
  e.b[k] = b;
  e.flags[k] = flags;
  e.count = k + 1;
}

/**
 * The 3D joints' edges (joints/store-3d.ts addJointEdges3D), handed over by `install3D` when a program
 * first makes a 3D shape or joint (the joint store sits above this module); nothing until then.
 */
let jointEdges3D: ((world: PhysicsWorld, e: IslandEdges) => void) | null = null;

/**
 * Hands the island graph the 3D joints' edges (called by install3D; the function serves every world).
 * @category Sleep
 */
export function setJointEdges3D(add: (world: PhysicsWorld, e: IslandEdges) => void): void {
  jointEdges3D = add;
}

/**
 * Adds every contact's and joint's edge of this step to `e`, in 2D and 3D: each contact (ball row, 2D
 * or 3D manifold) that carried a normal impulse supports its bodies and, unless a ball meets static
 * geometry, joins them; each joint is a `JOINT` edge, supporting when it carried a load (a pendulum at
 * rest hangs on its pin), `MOUSE` for a mouse joint.
 * @category Sleep
 */
export function addIslandEdges(world: PhysicsWorld, e: IslandEdges): void {
  const F = EdgeFlag;
  // Each long loop is a function of its own that ends with it: V8 compiles such a loop on the stack
  // (OSR) and enters that code at the loop in later calls; an operation past the loop that it has no
  // type feedback for would throw it away there, call after call.
  addRowEdges(e, world.collision.cache.rows);
  if (world.dimensions === 3) {
    const m = contact3DStateOf(world)?.current;
    if (m !== undefined) addManifoldEdges(e, m.bodyA, m.bodyB, m.points, m.carried, 4, m.count);
    jointEdges3D?.(world, e);
    return;
  }
  const st = world.collision.shapes;
  // The 2D manifolds: this step's rows (finishManifolds made them the cache).
  if (st.active)
    addManifoldEdges(e, st.previous.bodyA, st.previous.bodyB, st.previous.pointCount, st.previous.normalImpulse, 2, st.previous.count);
  if (world.joints.attached.length === 0) return;
  const J = world.components.Joint;
  const joints = query(world, [J]);
  for (let i = 0; i < joints.length; i++) {
    const j = joints[i]!;
    const flags = F.JOINT | (J.force[j]! > 0 ? F.SUPPORTS : 0) | (J.type[j] === JointType.Mouse ? F.MOUSE : 0);
    addIslandEdge(e, J.a[j]!, J.b[j]!, flags);
  }
}

/** Adds the edge of each ball contact row that carried a normal impulse (joining unless a ball meets static geometry: kind 0 joins). */
function addRowEdges(e: IslandEdges, rows: PhysicsWorld['collision']['cache']['rows']): void {
  const F = EdgeFlag;
  for (let i = 0; i < rows.count; i++) {
    if (rows.normalImpulse[i]! <= 0) continue;
    addIslandEdge(e, rows.a[i]!, rows.b[i]!, rows.kind[i] === 0 ? F.SUPPORTS | F.JOINS : F.SUPPORTS);
  }
}

/**
 * Adds the supporting, joining edge of each of the first `n` manifolds (bodies A[i], B[i]) one of
 * whose `points[i]` points (`stride` a manifold in `pushed`) pushed: `pushed` > 0 there.
 */
function addManifoldEdges(
  e: IslandEdges,
  A: Int32Array,
  B: Int32Array,
  points: ArrayLike<number>,
  pushed: ArrayLike<number>,
  stride: number,
  n: number,
): void {
  for (let i = 0; i < n; i++) {
    let any = false;
    for (let p = 0, k = points[i]!; p < k; p++) if (pushed[stride * i + p]! > 0) any = true;
    if (any) addIslandEdge(e, A[i]!, B[i]!, EdgeFlag.SUPPORTS | EdgeFlag.JOINS);
  }
}

/**
 * The sleeping bodies that an awake dynamic body leaned on this step through a 2D shape contact (one
 * of its points carried a normal impulse; the sleeper held still as immovable geometry): their
 * islands are woken for the next step, so that the two rest, and sleep, as one island. A contact
 * that did not push (a neighbour within the speculative distance) wakes nothing. Returns them, or
 * null when there is none.
 * @category Sleep
 */
export function pushedSleepers2D(world: PhysicsWorld): number[] | null {
  const st = world.collision.shapes;
  if (!st.active || !world.collision.sleep.anyAsleep) return null;
  const type = world.collision.bodyType;
  const m = st.previous; // this step's rows (finishManifolds made them the cache)
  let out: number[] | null = null;
  for (let i = 0, n = m.count; i < n; i++) {
    const a = m.bodyA[i]!,
      b = m.bodyB[i]!;
    const ta = a === 0 ? BodyType.Static : type[a],
      tb = type[b];
    if (ta !== BodyType.Sleeping && tb !== BodyType.Sleeping) continue;
    let pushed = false;
    for (let p = 0, k = m.pointCount[i]!; p < k; p++) if (m.normalImpulse[2 * i + p]! > 0) pushed = true;
    if (pushed) (out ??= []).push(ta === BodyType.Sleeping ? a : b);
  }
  return out;
}

/**
 * Marks `supported[x] = stamp` for both bodies of every `SUPPORTS` edge.
 * @category Sleep
 */
export function markSupport(e: IslandEdges, supported: Uint32Array, stamp: number): void {
  const A = e.a,
    B = e.b,
    flags = e.flags;
  for (let i = 0; i < e.count; i++) {
    if ((flags[i]! & EdgeFlag.SUPPORTS) === 0) continue;
    supported[A[i]!] = stamp;
    supported[B[i]!] = stamp;
  }
}

/**
 * The union-find root of x in `parent`, halving the path on the way.
 * @category Sleep
 */
export function findRoot(parent: Int32Array, x: number): number {
  while (parent[x] !== x) {
    parent[x] = parent[parent[x]!]!;
    x = parent[x]!;
  }
  return x;
}

/**
 * Unites, in the union-find `parent`, the two bodies of every `JOINS` edge between two dynamic bodies.
 * @category Sleep
 */
export function joinContactEdges(world: PhysicsWorld, e: IslandEdges, parent: Int32Array): void {
  const type = world.collision.bodyType;
  const A = e.a,
    B = e.b,
    flags = e.flags;
  for (let i = 0; i < e.count; i++) {
    if ((flags[i]! & EdgeFlag.JOINS) === 0) continue;
    const a = A[i]!,
      b = B[i]!;
    if (a === 0 || b === 0 || type[a] !== BodyType.Dynamic || type[b] !== BodyType.Dynamic) continue;
    const ra = findRoot(parent, a),
      rb = findRoot(parent, b);
    if (ra !== rb) parent[ra] = rb;
  }
}

/**
 * Makes both bodies of every `JOINS` edge of `e` their own root in `parent` again (parent[x] = x), as
 * before joinContactEdges united them.
 * @category Sleep
 */
export function resetJoinedParents(e: IslandEdges, parent: Int32Array): void {
  const A = e.a,
    B = e.b,
    flags = e.flags;
  for (let i = 0; i < e.count; i++) {
    if ((flags[i]! & EdgeFlag.JOINS) === 0) continue;
    parent[A[i]!] = A[i]!;
    parent[B[i]!] = B[i]!;
  }
}

/**
 * Joins the islands of the sleep candidates that a joint holds together, in 2D and 3D alike:
 *
 * - a mouse joint keeps the body it drags awake (its rest time is reset);
 * - a joint between two candidates unites their islands;
 * - a joint from a candidate to a body that moves and cannot sleep (kinematic, or dynamic but not a
 *   candidate: one without a collider) resets the candidate's rest time, so it stays awake; the
 *   fixed world and static bodies hold nothing awake;
 * - a sleeping body jointed to a candidate that moves (rest time 0) is returned, for the caller to
 *   wake its island (it would otherwise hold the moving body like a fixed anchor).
 *
 * `member` is per-entity scratch (capacity + 1 slots) that this call stamps with `stamp` to mark the
 * candidates `bodies`, whose union-find `parent` is initialised (parent[x] = x). Returns the sleeping
 * bodies to wake, or null when there is none.
 * @category Sleep
 */
export function joinJointEdges(
  world: PhysicsWorld,
  e: IslandEdges,
  bodies: ArrayLike<number>,
  rest: Float64Array,
  parent: Int32Array,
  member: Uint32Array,
  stamp: number,
): number[] | null {
  if (!hasJointEdge(e)) return null;
  markMembers(member, bodies, stamp);
  const A = e.a,
    B = e.b,
    flags = e.flags;
  const c = world.components;
  let wake: number[] | null = null;
  for (let i = 0; i < e.count; i++) {
    const f = flags[i]!;
    if ((f & EdgeFlag.JOINT) === 0) continue;
    const a = A[i]!,
      b = B[i]!;
    if ((f & EdgeFlag.MOUSE) !== 0) {
      rest[b] = 0;
      continue;
    }
    const inA = a !== 0 && member[a] === stamp,
      inB = b !== 0 && member[b] === stamp;
    if (inA && inB) {
      const ra = findRoot(parent, a),
        rb = findRoot(parent, b);
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

/** Whether some edge of `e` is a joint's (`JOINT`). Its loop ends the function (see addIslandEdges). */
function hasJointEdge(e: IslandEdges): boolean {
  const flags = e.flags;
  let any = false;
  for (let i = 0; i < e.count && !any; i++) any = (flags[i]! & EdgeFlag.JOINT) !== 0;
  return any;
}

/** member[x] = stamp for each x of `bodies`. */
function markMembers(member: Uint32Array, bodies: ArrayLike<number>, stamp: number): void {
  for (let i = 0; i < bodies.length; i++) member[bodies[i]!] = stamp;
}
