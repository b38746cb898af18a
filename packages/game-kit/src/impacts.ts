/**
 * Impacts of the last step for the games' sounds: the contact `begin` events of 2D shapes
 * (`world.collision.shapes.events`) or 3D shapes (`contactEvents3D`), each with an estimate of the
 * impulse it carried. No DOM.
 */
import { contactEvents3D, type PhysicsWorld, slotOf } from '@bitphysics/physics';

/** Called once per impact: the two bodies (handles; 0 the static world, negative a boundary face) and the impulse estimate, N s (>= 0). */
export type ImpactListener = (bodyA: number, bodyB: number, impulse: number) => void;

/** The rows of an event list both dimensions share. */
interface BeginList {
  count: number;
  bodyA: Float64Array;
  bodyB: Float64Array;
  approachSpeed: Float64Array;
}

/**
 * Calls `fn` for every pair of shapes that started touching in the last step, with the impulse of a
 * perfectly inelastic collision along the normal, J = m_red v_n (m_red = 1 / (1/m_a + 1/m_b), static
 * and boundary bodies of infinite mass; v_n the approach speed at the start of the step): the impulse
 * that stops the approach, the scale a loudness should follow. 2D or 3D by `dimension`.
 * @returns the number of impacts reported.
 */
export function forEachImpact(world: PhysicsWorld, fn: ImpactListener, dimension: 2 | 3 = 2): number {
  const list: BeginList = dimension === 3 ? contactEvents3D(world).begin : world.collision.shapes.events.begin;
  const inv = world.components.Mass.inv;
  const invOf = (h: number): number => (h > 0 ? inv[slotOf(h)]! : 0);
  for (let i = 0; i < list.count; i++) {
    const a = list.bodyA[i]!,
      b = list.bodyB[i]!;
    const sum = invOf(a) + invOf(b);
    const impulse = sum > 0 ? list.approachSpeed[i]! / sum : 0;
    fn(a, b, impulse);
  }
  return list.count;
}
