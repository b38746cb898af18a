/**
 * Impacts of the last step for the games' sounds: the contact `begin` events (`contactEvents`: balls
 * and shapes, 2D and 3D), each with an estimate of the impulse it carried. No DOM.
 */
import { contactEvents, type PhysicsWorld, slotOf } from '@bitphysics/physics';

/** Called once per impact: the two bodies (handles; 0 the static world, negative a boundary face) and the impulse estimate, N s (>= 0). */
export type ImpactListener = (bodyA: number, bodyB: number, impulse: number) => void;

/**
 * Calls `fn` for every pair of shapes that started touching in the last step, with the impulse of a
 * perfectly inelastic collision along the normal, J = m_red v_n (m_red = 1 / (1/m_a + 1/m_b), static
 * and boundary bodies of infinite mass; v_n the approach speed at the start of the step): the impulse
 * that stops the approach, the scale a loudness should follow. `_dimension` is not needed (the events
 * of both dimensions come from `contactEvents`) and kept for the callers that pass it.
 * @returns the number of impacts reported.
 */
export function forEachImpact(world: PhysicsWorld, fn: ImpactListener, _dimension: 2 | 3 = 2): number {
  const list = contactEvents(world).begin;
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
