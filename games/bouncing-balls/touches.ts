/**
 * What a thrown ball touched, for its basket's style (hoop.ts ShotStyle). The contact events name
 * every static thing by body 0 (the box's faces, the ramps and the hoop's backboard and rim alike),
 * so a touch is told by the other side's shape: a negative one is a face of the box, a segment's is
 * its own id. Telling them by body made a bank shot off the backboard a trick shot. No DOM: the
 * tests run it in Node.
 */
import { contactEvents, type PhysicsWorld } from '@bitphysics/physics';

/**
 * What a ball met: the box's top (`ceiling`), another face of the box (`wall`: a side or the floor),
 * a ramp, the hoop (its backboard or front rim), or a body (another ball, a crate).
 */
export type TouchKind = 'ceiling' | 'wall' | 'ramp' | 'hoop' | 'body';

/** How far down a face's normal must push a ball for the face to be the box's top (the normal's y is -1 there, 0 on a side). */
const CEILING_NORMAL = -0.5;

/**
 * Calls `fn(e, other, kind)` for each side `e` of a contact that began in `world`'s last step that is
 * a body (a ball or a crate), with what it met: `other` the other side's body if it is one, else its
 * shape (a segment's id, or a negative face of the box), and its kind. The box's top is the face whose
 * contact normal pushes `e` down (the event's normal points from its A side to its B side); a shape
 * in `ramps` is a ramp and one in `hoop` is the hoop.
 */
export function forEachTouch(
  world: PhysicsWorld,
  ramps: readonly number[],
  hoop: readonly number[],
  fn: (e: number, other: number, kind: TouchKind) => void,
): void {
  const list = contactEvents(world).begin;
  for (let i = 0; i < list.count; i++) {
    const bodyA = list.bodyA[i]!,
      bodyB = list.bodyB[i]!;
    for (const [e, otherBody, otherShape, pushY] of [
      [bodyA, bodyB, list.shapeB[i]!, -list.ny[i]!],
      [bodyB, bodyA, list.shapeA[i]!, list.ny[i]!],
    ] as const) {
      if (e <= 0) continue;
      if (otherBody > 0) fn(e, otherBody, 'body');
      else if (otherShape < 0) fn(e, otherShape, pushY < CEILING_NORMAL ? 'ceiling' : 'wall');
      else fn(e, otherShape, ramps.includes(otherShape) ? 'ramp' : hoop.includes(otherShape) ? 'hoop' : 'wall');
    }
  }
}
