/**
 * Cutting the ropes, headless: a swipe cuts every rope link it crosses, and a tap cuts the link nearest
 * to it within reach. A link is drawn (and tested) as the straight segment between the points it joins:
 * the anchor or a rope body, and the next rope body or the ball.
 */

import { segmentsCross } from '@bitphysics/game-kit';
import { isAlive, type PhysicsWorld, slotOf } from '@bitphysics/physics';
import { cutRope, type RopePiece } from './scene';

/** A link's ends now, m: [ax, ay, bx, by]. */
function ends(world: PhysicsWorld, rope: RopePiece, k: number, ball: number, out: number[]): number[] {
  const P = world.components.Position;
  const n = rope.bodies.length;
  // Link k joins point k and point k + 1 of the sequence anchor, bodies..., ball.
  const at = (i: number, o: number): void => {
    if (i === 0) {
      out[o] = rope.anchor[0];
      out[o + 1] = rope.anchor[1];
      return;
    }
    const h = i <= n ? rope.bodies[i - 1]! : ball;
    const e = slotOf(h);
    out[o] = P.x[e]!;
    out[o + 1] = P.y[e]!;
  };
  at(k, 0);
  at(k + 1, 2);
  return out;
}

/** Distance from point (px, py) to segment (a, b), m. */
export function segmentDistance(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const dx = bx - ax,
    dy = by - ay,
    l2 = dx * dx + dy * dy;
  const t = l2 > 0 ? Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / l2)) : 0;
  return Math.hypot(px - ax - t * dx, py - ay - t * dy);
}

/** A cut: where (m) and which rope (its index). */
export interface RopeCut {
  x: number;
  y: number;
  rope: number;
}

/**
 * Cuts (scene.ts `cutRope`: the ball goes free of the piece below), on each rope, the first live
 * link (from the anchor) that the swipe from (x0, y0) to (x1, y1), m, crosses, however long the
 * segment, or failing a crossing and with `reach` > 0, the live link nearest to (x1, y1) within
 * `reach` m. One cut a rope a call, so a swipe that runs along a rope cuts it once, not into bits.
 * @returns the cuts made.
 */
export function cutRopes(
  world: PhysicsWorld,
  ropes: readonly RopePiece[],
  ball: number,
  x0: number,
  y0: number,
  x1: number,
  y1: number,
  reach = 0,
): RopeCut[] {
  const out: RopeCut[] = [];
  const p = [0, 0, 0, 0];
  let near = 0,
    nearD = reach,
    nearRope = -1,
    nearX = 0,
    nearY = 0;
  ropes.forEach((rope, r) => {
    for (let k = 0; k < rope.links.length; k++) {
      const link = rope.links[k]!;
      if (!isAlive(world, link)) continue;
      const [ax, ay, bx, by] = ends(world, rope, k, ball, p);
      if (segmentsCross(x0, y0, x1, y1, ax!, ay!, bx!, by!)) {
        cutRope(world, rope, link);
        out.push({ x: (ax! + bx!) / 2, y: (ay! + by!) / 2, rope: r });
        return;
      }
      if (reach > 0) {
        const d = segmentDistance(x1, y1, ax!, ay!, bx!, by!);
        if (d < nearD) {
          nearD = d;
          near = link;
          nearRope = r;
          nearX = (ax! + bx!) / 2;
          nearY = (ay! + by!) / 2;
        }
      }
    }
  });
  if (out.length === 0 && near !== 0) {
    cutRope(world, ropes[nearRope]!, near);
    out.push({ x: nearX, y: nearY, rope: nearRope });
  }
  return out;
}
