import { hasComponent } from 'bitecs';
import { contact3DStateOf } from '../collision/manifolds-3d.js';
import { BodyType } from '../collision/state.js';
import { shapes3DOf } from '../shapes/store-3d.js';
import type { PhysicsWorld } from '../world/options.js';
import { Not, query } from '../world/query.js';
import { addIslandEdge, EdgeFlag, type IslandEdges } from './edges.js';
import { wakeIslandForStep } from './step-wake.js';

/**
 * Sleeping for 3D shape bodies (used by islands/sleep.ts and collision/shapes-3d.ts), after Box2D
 * v3's island sleep:
 *
 * - the 3D manifolds add their edges to the step's island graph (islands/edges.ts), as the 3D joints
 *   do theirs (joints/store-3d.ts), which the sleep system reads as it does the 2D stores';
 * - a sleeping body met in the 3D broadphase by a moving body (rest time 0) or a kinematic one that
 *   can reach it within the step (`wakesSleeper3D`) wakes with its whole island, and joins the step as a dynamic body with the velocity and
 *   position the integration it skipped would have given it (v = g h, x += g h^2 / 2); met by a resting body it
 *   stays asleep and holds it up as immovable geometry, so a box settling onto a sleeping pile can
 *   fall asleep too;
 * - removing a body wakes the sleeping islands its manifolds touched.
 */

const sleepList = { list: new Uint32Array(0) };

/**
 * The bodies that may fall asleep this step: `others` (islands/sleep.ts's candidates) plus the awake dynamic
 * bodies that carry a 3D shape and are not balls (balls are among `others` already). Returns `others`
 * itself in a world without 3D shapes; otherwise a view of a reused array (valid until the next call).
 * @category Collision
 */
export function withShape3DBodies(world: PhysicsWorld, others: ArrayLike<number>): ArrayLike<number> {
  if (world.dimensions !== 3) return others;
  const s = shapes3DOf(world);
  if (s === undefined || !s.active) return others;
  const c = world.components;
  const shaped = query(world, [c.Position, c.Velocity, c.Force, Not(c.Ball), Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)]);
  const n = others.length + shaped.length;
  if (sleepList.list.length < n) sleepList.list = new Uint32Array(Math.max(n, 2 * sleepList.list.length));
  const out = sleepList.list;
  for (let i = 0; i < others.length; i++) out[i] = others[i]!;
  let k = others.length;
  for (let i = 0; i < shaped.length; i++) if (s.first[shaped[i]!] !== 0) out[k++] = shaped[i]!;
  return out.subarray(0, k);
}

/**
 * Adds the 3D manifolds' edges to `e` (islands/edges.ts): manifolds any of whose points carried a
 * normal impulse this step support and join their bodies. (The 3D joints add theirs in
 * joints/store-3d.ts `addJointEdges3D`.)
 * @category Collision
 */
export function addContactEdges3D(world: PhysicsWorld, e: IslandEdges): void {
  if (world.dimensions !== 3) return;
  const st = contact3DStateOf(world);
  if (st !== undefined) {
    const b = st.current,
      carried = b.carried,
      points = b.points;
    for (let i = 0, n = b.count; i < n; i++) {
      let pushed = false;
      for (let k = 0, m = points[i]!; k < m; k++) if (carried[4 * i + k] === 1) pushed = true;
      if (pushed) addIslandEdge(e, b.bodyA[i]!, b.bodyB[i]!, EdgeFlag.SUPPORTS | EdgeFlag.JOINS);
    }
  }
}

/**
 * Whether body `other` (of type `t`) wakes a sleeping body whose manifold with it has least separation
 * `gap` (m, < 0: overlap): it is kinematic, or dynamic and not resting (its rest time is 0), and it can
 * close the gap this step (`gap <= closing`, `closing` m: what its speed and gravity cover in the
 * step). A mover that is only within the speculative distance leaves the sleeper asleep: it meets it
 * as static geometry (a speculative row that cannot close), and the next step looks again. Waking on
 * mere proximity had a settling pile's sleeping islands woken by a rocking neighbour 0.1 m away about
 * every other step (each wake also re-runs the step's broadphase), and restarted their rest time.
 * @category Collision
 */
export function wakesSleeper3D(world: PhysicsWorld, other: number, t: number, gap = -Infinity, closing = 0): boolean {
  if (!(gap <= closing)) return false;
  return t === BodyType.Kinematic || (t === BodyType.Dynamic && world.collision.sleep.restTime[other] === 0);
}

/**
 * Wakes the island of sleeping body `e` for this step (see the module's note): every body asleep in
 * it loses the Sleeping tag and gets the skipped integration's v = g h, x += g h^2 / 2. Returns how
 * many bodies woke.
 * @category Collision
 */
export function wakeIsland3D(world: PhysicsWorld, e: number): number {
  return wakeIslandForStep(world, e);
}

/**
 * Removal hook: wakes the sleeping islands that body `eid`'s 3D manifolds of the last step touched.
 * @category Collision
 */
export function wakeTouching3D(world: PhysicsWorld, eid: number): void {
  if (world.dimensions !== 3) return;
  const st = contact3DStateOf(world);
  if (st === undefined) return;
  const b = st.current,
    c = world.components;
  for (let i = 0; i < b.count; i++) {
    const a = b.bodyA[i]!,
      d = b.bodyB[i]!;
    if (a !== eid && d !== eid) continue;
    const other = a === eid ? d : a;
    if (other !== 0 && hasComponent(world, other, c.Sleeping)) wakeIsland3D(world, other);
  }
}
