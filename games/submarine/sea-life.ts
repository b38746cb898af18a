/**
 * Fish for the submarine's sea (drawing only, no physics): small schools fixed in the water, one
 * to some of each 40 m cell, each swimming to and fro around its home and scattering from the boat
 * when it comes within a few metres, so the sea is alive and the boat is seen to move through it.
 */

import type { Graphics } from 'pixi.js';

/** Side of a school's cell, m. */
const CELL = 40;
/** Distance from the boat inside which fish dart away, m. */
const SCARE = 9;

/** A well-mixed 32-bit hash of a cell index and a salt. */
function hash(i: number, salt: number): number {
  let h = Math.imul(i, 0x27d4eb2d) ^ Math.imul(salt, 0x165667b1);
  h = Math.imul(h ^ (h >>> 15), 0x85ebca6b);
  h = Math.imul(h ^ (h >>> 13), 0xc2b2ae35);
  return (h ^ (h >>> 16)) >>> 0;
}

/** Colours of the schools: silver, orange, teal. */
const COLOURS = [0xc8d8e6, 0xff9f43, 0x5fd3c4];

/**
 * Draws the schools whose homes lie between `left` and `right` (m, world x) at time `t` (s): each
 * fish a body and a tail, `scale` px a metre, through `sx` and `sy` (world m to screen px). Homes
 * keep at least 4 m under the surface and `bedAt(x) + 3` over the seabed. The boat is at (bx, by).
 */
export function drawFish(
  g: Graphics,
  left: number,
  right: number,
  t: number,
  scale: number,
  sx: (x: number) => number,
  sy: (y: number) => number,
  bedAt: (x: number) => number,
  bx: number,
  by: number,
): void {
  for (let i = Math.floor(left / CELL) - 1; i <= Math.ceil(right / CELL) + 1; i++) {
    const h = hash(i, 31337);
    if ((h & 3) === 0) continue;
    const homeX = (i + ((h >>> 2) & 255) / 256) * CELL;
    const bed = bedAt(homeX);
    const homeY = -4 + (bed + 3 + 4) * (((h >>> 10) & 255) / 256);
    const count = 4 + ((h >>> 18) & 7);
    const colour = COLOURS[(h >>> 21) % COLOURS.length]!;
    const size = 0.45 + ((h >>> 23) & 3) * 0.15;
    // The school swims to and fro along x (period 20 to 35 s) and bobs a little.
    const period = 20 + ((h >>> 25) & 15);
    const phase = (2 * Math.PI * t) / period + (h & 255);
    const swimX = 7 * Math.sin(phase),
      heading = Math.cos(phase) >= 0 ? 1 : -1;
    for (let k = 0; k < count; k++) {
      const f = hash(i * 16 + k, 4242);
      let x = homeX + swimX + ((f & 255) / 255 - 0.5) * 8,
        y = homeY + (((f >>> 8) & 255) / 255 - 0.5) * 4 + 0.4 * Math.sin(2 * t + k);
      // Scattered by the boat: pushed out to SCARE m from it.
      const dx = x - bx,
        dy = y - by,
        d = Math.hypot(dx, dy);
      if (d < SCARE && d > 1e-6) {
        x = bx + (dx / d) * SCARE;
        y = by + (dy / d) * SCARE;
      }
      const px = sx(x),
        py = sy(y),
        len = size * scale * 1.6,
        tall = size * scale * 0.6,
        wag = 0.35 * Math.sin(9 * t + k);
      g.ellipse(px, py, Math.max(2, len / 2), Math.max(1, tall / 2)).fill({ color: colour, alpha: 0.85 });
      const tx = px - heading * Math.max(2, len / 2);
      g.poly([
        tx,
        py,
        tx - heading * Math.max(2, len * 0.35),
        py - Math.max(1.5, tall * 0.6) * (1 + wag),
        tx - heading * Math.max(2, len * 0.35),
        py + Math.max(1.5, tall * 0.6) * (1 - wag),
      ]).fill({
        color: colour,
        alpha: 0.85,
      });
    }
  }
}
