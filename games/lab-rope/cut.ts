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

/**
 * Distance between the segments (a0, a1) and (b0, b1), m, given that they do not cross: the least of
 * each one's ends' distances to the other.
 */
function apartDistance(ax0: number, ay0: number, ax1: number, ay1: number, bx0: number, by0: number, bx1: number, by1: number): number {
  return Math.min(
    segmentDistance(ax0, ay0, bx0, by0, bx1, by1),
    segmentDistance(ax1, ay1, bx0, by0, bx1, by1),
    segmentDistance(bx0, by0, ax0, ay0, ax1, ay1),
    segmentDistance(bx1, by1, ax0, ay0, ax1, ay1),
  );
}

/** A link a swipe would cut: its rope (index), the link, and where (m). */
export interface RopeCut {
  x: number;
  y: number;
  rope: number;
  /** The link's handle. */
  link: number;
}

/**
 * The links a swipe from (x0, y0) to (x1, y1), m, would cut, without cutting them: on each rope, the
 * first live link (from the anchor) that the swipe crosses, however long the segment, or failing a
 * crossing on every rope and with `reach` > 0, the one live link nearest to the swipe's segment
 * within `reach` m (a swipe that passes a finger's width beside a rope's end, or starts on the rope
 * and moves off it, cuts it; measured only from (x1, y1), 13 of 336 fast finger swipes passing within
 * 14 px of level 1's rope cut nothing). One link a rope, so a swipe that runs along a rope cuts it
 * once, not into bits.
 */
export function findCuts(
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
  let near: RopeCut | null = null,
    nearD = reach;
  ropes.forEach((rope, r) => {
    for (let k = 0; k < rope.links.length; k++) {
      const link = rope.links[k]!;
      if (!isAlive(world, link)) continue;
      const [ax, ay, bx, by] = ends(world, rope, k, ball, p);
      if (segmentsCross(x0, y0, x1, y1, ax!, ay!, bx!, by!)) {
        out.push({ x: (ax! + bx!) / 2, y: (ay! + by!) / 2, rope: r, link });
        return;
      }
      if (reach > 0) {
        const d = apartDistance(x0, y0, x1, y1, ax!, ay!, bx!, by!);
        if (d < nearD) {
          nearD = d;
          near = { x: (ax! + bx!) / 2, y: (ay! + by!) / 2, rope: r, link };
        }
      }
    }
  });
  if (out.length === 0 && near) out.push(near);
  return out;
}

/**
 * Cuts what `findCuts` finds for the swipe from (x0, y0) to (x1, y1), m, with `reach` m (scene.ts
 * `cutRope`: the ball goes free of the piece below). @returns the cuts made.
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
  const made = findCuts(world, ropes, ball, x0, y0, x1, y1, reach);
  for (const c of made) cutRope(world, ropes[c.rope]!, c.link);
  return made;
}

/**
 * How far each cut end of a drawn rope piece is drawn short of the rope body it ends at, in cord
 * widths: a cut leaves a gap of one link (0.125 m, about 12 px on a desktop) between the two pieces,
 * which the cord's round caps (half a width and its outline each) and the frayed fibres (1.1 widths)
 * filled, so the rope looked whole after a cut until its pieces swung apart. Drawn 2 widths short at
 * each cut end, the gap shows at once, some 2 widths wider than the link.
 */
export const CUT_END_TRIM = 2;

/**
 * The polyline `pts` (x, y interleaved, at least two points) shortened by `start` along its length from
 * its first point and by `end` from its last (each >= 0, px or m alike); a polyline shorter than
 * start + end keeps a point where the two trims meet, in proportion. @returns a new array.
 */
export function trimPolyline(pts: readonly number[], start: number, end: number): number[] {
  const n = pts.length / 2;
  let total = 0;
  for (let i = 1; i < n; i++) total += Math.hypot(pts[2 * i]! - pts[2 * i - 2]!, pts[2 * i + 1]! - pts[2 * i - 1]!);
  if (start + end >= total) {
    const s = start + end > 0 ? (total * start) / (start + end) : 0;
    const p = pointAlong(pts, s);
    return [p[0], p[1], p[0], p[1]];
  }
  const out: number[] = [];
  const a = pointAlong(pts, start),
    b = pointAlong(pts, total - end);
  out.push(a[0], a[1]);
  let d = 0;
  for (let i = 1; i < n - 1; i++) {
    d += Math.hypot(pts[2 * i]! - pts[2 * i - 2]!, pts[2 * i + 1]! - pts[2 * i - 1]!);
    if (d > start && d < total - end) out.push(pts[2 * i]!, pts[2 * i + 1]!);
  }
  out.push(b[0], b[1]);
  return out;
}

/** The point `s` along the polyline `pts` from its first point (clamped to its ends). */
function pointAlong(pts: readonly number[], s: number): [number, number] {
  const n = pts.length / 2;
  for (let i = 1; i < n; i++) {
    const x0 = pts[2 * i - 2]!,
      y0 = pts[2 * i - 1]!,
      len = Math.hypot(pts[2 * i]! - x0, pts[2 * i + 1]! - y0);
    if (s <= len || i === n - 1) {
      const f = len > 0 ? Math.min(1, Math.max(0, s / len)) : 0;
      return [x0 + (pts[2 * i]! - x0) * f, y0 + (pts[2 * i + 1]! - y0) * f];
    }
    s -= len;
  }
  return [pts[0]!, pts[1]!];
}
