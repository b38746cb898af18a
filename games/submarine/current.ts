/**
 * The submarine game's water currents: on levels 2 and 3 the sea flows horizontally, in bands that
 * change with depth, so a boat let go drifts with the water and must be held against it with the
 * screw (Ahead or Astern) to stay on a beacon. The scene's drag is the hull's drag in still water,
 * -k |v| v; `driftInCurrent` adds k (|v| v - |v - w| (v - w)), so the hull feels -k |v_r| v_r with
 * v_r = v - w its velocity through the water w. The helm (./helm.ts steer) takes the same current,
 * so its screw and coasting brake act through the water too. Headless, tested in node
 * (test/games/submarine-current.test.ts).
 */

import { applyImpulse, type PhysicsWorld } from '@bitphysics/physics';
import { SUBMARINE, type SubmarineHandles } from '@bitphysics/projects';
import type { Graphics } from 'pixi.js';

/** The current's settings on each level (index: level number - 1). */
export const CURRENTS: readonly Readonly<{ speed: number; band: number; phase: number }>[] = Object.freeze([
  /** Level 1: still water (the tutorial). */
  Object.freeze({ speed: 0, band: 40, phase: 0 }),
  /**
   * Level 2: up to 1.5 m/s (a fifth of the top speed, 8 m/s), in bands of 35 m that flow ahead and
   * back by turns.
   */
  Object.freeze({ speed: 1.5, band: 35, phase: 0.6 }),
  /** Level 3: up to 2.4 m/s, in bands of 28 m. */
  Object.freeze({ speed: 2.4, band: 28, phase: 1.9 }),
]);

/**
 * The water's horizontal velocity on level `level` at height `y` (m, negative under water), m/s
 * (positive: the way the course runs): `speed` sin(pi d / band + phase) with d = -y the depth, so
 * neighbouring bands `band` m thick flow opposite ways; 0 above the surface and on level 1. It
 * eases in over the top 6 m so the boat on the surface floats in still water.
 * @throws RangeError when `level` is not an integer from 1 to CURRENTS.length or `y` is not finite.
 */
export function currentAt(level: number, y: number): number {
  if (!(Number.isInteger(level) && level >= 1 && level <= CURRENTS.length))
    throw new RangeError(`currentAt: level must be an integer from 1 to ${CURRENTS.length}, got ${level}`);
  if (!Number.isFinite(y)) throw new RangeError(`currentAt: y must be finite m, got ${y}`);
  const c = CURRENTS[level - 1]!;
  const d = -y;
  if (c.speed === 0 || d <= 0) return 0;
  return c.speed * Math.min(1, d / 6) * Math.sin((Math.PI * d) / c.band + c.phase);
}

/**
 * Makes the hull's drag act on its velocity through the water: an impulse over the coming step
 * (`world.dt`) of k (|v| v - |v - w| (v - w)) times the submerged share of the hull, k the scene's
 * `SUBMARINE.dragCoefficient`, v the hull's velocity and w = (`current`, 0) m/s. Call it after the
 * helm, before `step(world)`. Nothing for still water.
 * @throws RangeError when `current` is not finite.
 */
export function driftInCurrent(world: PhysicsWorld, handles: SubmarineHandles, current: number): void {
  if (!Number.isFinite(current)) throw new RangeError(`driftInCurrent: current must be finite m/s, got ${current}`);
  if (current === 0) return;
  const c = world.components,
    e = handles.hull;
  const surface = c.FluidRegion.surface[handles.sea]!;
  const submerged = Math.min(1, Math.max(0, (surface - (c.Position.y[e]! - SUBMARINE.height / 2)) / SUBMARINE.height));
  const vx = c.Velocity.x[e]!,
    vy = c.Velocity.y[e]!,
    rx = vx - current;
  const v = Math.hypot(vx, vy),
    r = Math.hypot(rx, vy);
  const k = SUBMARINE.dragCoefficient * submerged * world.dt;
  applyImpulse(world, e, [k * (v * vx - r * rx), k * (v * vy - r * vy)]);
}

/** Spacing of the current's drifting specks, m: along x and between rows. */
const SPECK_DX = 13,
  SPECK_DY = 7;

/** A well-mixed 32-bit hash of two integers. */
function hash2(i: number, j: number): number {
  let h = Math.imul(i, 0x27d4eb2d) ^ Math.imul(j, 0x165667b1);
  h = Math.imul(h ^ (h >>> 15), 0x85ebca6b);
  h = Math.imul(h ^ (h >>> 13), 0xc2b2ae35);
  return (h ^ (h >>> 16)) >>> 0;
}

/**
 * Draws level `level`'s current (drawing only) between `left` and `right` and from `bottom` up to
 * `top` (world m): rows of specks SPECK_DY m apart, each carried along x at the water's speed at
 * its depth (wrapping within its SPECK_DX m cell) with a streak behind it 0.9 s of that speed long,
 * fainter where the flow is slower; nothing in still water, and none under the seabed (`bed`: its
 * height, m, at x). `scale` px a metre, through `sx` and `sy` (world m to screen px), at time `t` s.
 */
export function drawCurrent(
  g: Graphics,
  level: number,
  left: number,
  right: number,
  bottom: number,
  top: number,
  t: number,
  scale: number,
  sx: (x: number) => number,
  sy: (y: number) => number,
  bed: (x: number) => number,
): void {
  const most = CURRENTS[level - 1]?.speed ?? 0;
  if (most === 0) return;
  for (let j = Math.floor(bottom / SPECK_DY); j <= Math.ceil(Math.min(0, top) / SPECK_DY); j++) {
    for (let i = Math.floor(left / SPECK_DX) - 1; i <= Math.ceil(right / SPECK_DX) + 1; i++) {
      const h = hash2(i, j);
      const y = (j + ((h & 255) / 256) * 0.8) * SPECK_DY;
      const u = currentAt(level, y);
      if (Math.abs(u) < 0.15) continue;
      const along = ((((h >>> 8) & 255) / 256) * SPECK_DX + u * t) % SPECK_DX;
      const x = (i + (along < 0 ? along + SPECK_DX : along) / SPECK_DX) * SPECK_DX;
      if (y < bed(x)) continue;
      const px = sx(x),
        py = sy(y),
        tail = Math.max(3, Math.abs(u) * 0.9 * scale) * Math.sign(u);
      const alpha = 0.08 + 0.27 * (Math.abs(u) / most);
      g.moveTo(px - tail, py)
        .lineTo(px, py)
        .stroke({ color: 0xcfeeff, width: 1, alpha });
      g.circle(px, py, 1.3).fill({ color: 0xe6f7ff, alpha: Math.min(1, alpha * 1.6) });
    }
  }
}

/** The water's speed (m/s) from which the status line names the current and its first push is told. */
export const CURRENT_SHOWN = 0.3;
/** The water's speed (m/s) that counts as the current's first push: the note (`currentNote`) comes up then. */
export const CURRENT_NOTE_SPEED = 0.8;
/** How long the note of the current's first push stays up, s of game time. */
export const CURRENT_NOTE_LIFE = 6;

/**
 * The current for the status line: "current ◀2.4 m/s" (a tenth; the arrow the way the water flows,
 * ▶ the way the course runs), '' under `CURRENT_SHOWN`: the same figure and unit as `currentNote`
 * gives for the same water. `u`: the water's speed at the boat, m/s.
 * @throws RangeError when `u` is not finite.
 */
export function currentMark(u: number): string {
  if (!Number.isFinite(u)) throw new RangeError(`currentMark: u must be finite m/s, got ${u}`);
  if (Math.abs(u) < CURRENT_SHOWN) return '';
  return `current ${u > 0 ? '▶' : '◀'}${Math.abs(u).toFixed(1)} m/s`;
}

/**
 * The note told the first time the current pushes the boat (the water at `u` m/s, |u| at least
 * `CURRENT_NOTE_SPEED`; the page keeps it up a while, told afresh as the water at the boat changes):
 * which way it carries the boat, how fast (the same figure and unit as `currentMark`), and that the
 * speed shown is over the ground. `u`: the water's speed at the boat, m/s (positive: the way the course runs).
 * @throws RangeError when `u` is not finite.
 */
export function currentNote(u: number): string {
  if (!Number.isFinite(u)) throw new RangeError(`currentNote: u must be finite m/s, got ${u}`);
  const way = u < 0 ? '◀ against you' : '▶ with you';
  return `Current ${way}, ${Math.abs(u).toFixed(1)} m/s: it carries the boat (speed shown over the ground)`;
}
