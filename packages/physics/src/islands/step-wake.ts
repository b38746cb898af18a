import { hasComponent, removeComponent } from 'bitecs';
import { BodyType } from '../collision/state.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';

/**
 * Wakes the island of sleeping body `e` for the step under way, from the collide stage: every body
 * asleep in it loses the Sleeping tag, its rest time is reset, and it gets what the integration it
 * skipped this step would have given it (v = g h, x += g h^2 / 2, the previous position where it
 * slept), so it takes part in this step's contact solve. Returns how many bodies woke (0 if `e` is
 * awake).
 * @category Collision
 */
export function wakeIslandForStep(world: PhysicsWorld, e: number): number {
  const c = world.components;
  if (!hasComponent(world, e, c.Sleeping)) return 0;
  const island = world.collision.sleep.island,
    id = island[e]!;
  const asleep = query(world, [c.Sleeping]);
  let list: number[] | null = null;
  for (let i = 0; i < asleep.length; i++) if (island[asleep[i]!] === id) (list ??= []).push(asleep[i]!);
  if (list === null) return 0;
  const g = world.gravity,
    h = world.h,
    f = 0.5 * h * h;
  const P = c.Position,
    O = c.PreviousPosition,
    V = c.Velocity;
  for (const b of list) {
    removeComponent(world, b, c.Sleeping);
    world.collision.sleep.wakes++;
    world.collision.sleep.restTime[b] = 0;
    V.x[b] = g[0]! * h;
    V.y[b] = g[1]! * h;
    V.z[b] = g[2]! * h;
    O.x[b] = P.x[b]!;
    O.y[b] = P.y[b]!;
    O.z[b] = P.z[b]!;
    P.x[b] = P.x[b]! + g[0]! * f;
    P.y[b] = P.y[b]! + g[1]! * f;
    P.z[b] = P.z[b]! + g[2]! * f;
  }
  return list.length;
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
export function wakesSleeper(world: PhysicsWorld, other: number, t: number, gap = -Infinity, closing = 0): boolean {
  if (!(gap <= closing)) return false;
  return t === BodyType.Kinematic || (t === BodyType.Dynamic && world.collision.sleep.restTime[other] === 0);
}
