/**
 * How the submarine is drawn (drawing only, no physics): a yellow hull with a rounded bow and a
 * tapered stern, the sail with its periscope, the rudder and stern planes, a screw whose blades turn
 * with the throttle, lit portholes, windows into the two ballast tanks showing their water, and a
 * headlight that shows in the dark of the deep, and the dive planes at the bow and the stern, turned
 * as the helm turns them. The hull is given in its own coordinates (u along it
 * towards the bow, v up across it, m) through `pt`, which maps them to the screen.
 */

import type { Graphics } from 'pixi.js';

/** What `drawBoat` needs: the hull's size, the mapping to the screen and the state to show. */
/**
 * The headlight's cone in the hull's frame: from the bow it reaches `reach` m ahead (its tip 8 %
 * further) and spreads to `spread` m either side of the axis there; it shows below `fromDepth` m,
 * brighter the deeper the boat.
 */
export const HEADLIGHT = Object.freeze({ reach: 26, spread: 7, fromDepth: 8 });

/**
 * Whether the point (u, v), m in the hull's frame (u along the hull from its centre, v across it),
 * is inside the headlight's cone of a hull `length` m long (> 0).
 */
export function inHeadlight(u: number, v: number, length: number): boolean {
  const along = u - length / 2;
  if (along < 0) return false;
  if (along <= HEADLIGHT.reach) return Math.abs(v) <= 0.3 + ((HEADLIGHT.spread - 0.3) * along) / HEADLIGHT.reach;
  const tip = 0.08 * HEADLIGHT.reach;
  return along <= HEADLIGHT.reach + tip && Math.abs(v) <= (HEADLIGHT.spread * (HEADLIGHT.reach + tip - along)) / tip;
}

export interface BoatPicture {
  /** Hull length and height, m. */
  length: number;
  height: number;
  /** Maps hull coordinates (u, v), m, to screen pixels. */
  pt: (u: number, v: number) => [number, number];
  /** Screen pixels a metre. */
  scale: number;
  /** Hull angle on screen, rad (counter-clockwise, y up in the world). */
  angle: number;
  /** Fill of the fore and aft tanks, [0, 1], and where they sit (u, m). */
  tanks: readonly [number, number];
  tankArm: number;
  /** The screw's turn, rad (advances with the throttle), and the throttle in [-0.5, 1]. */
  screwPhase: number;
  throttle: number;
  /** Depth of the hull, m (the headlight and portholes glow more in the dark). */
  depth: number;
  /** Whether the hull is scraping the seabed (it flashes red). */
  touching: boolean;
  /** The dive planes' angle, rad (positive: leading edge up, lifting); drawn at the bow and the stern. Default 0. */
  planes?: number;
}

/** Colours of the boat. */
const YELLOW = 0xf5c518,
  YELLOW_DARK = 0xc9970a,
  OUTLINE = 0x3a2a05,
  STEEL = 0x39434d;

/** Draws the boat into `g` (appends to its current path list). */
export function drawBoat(g: Graphics, b: BoatPicture): void {
  const L = b.length / 2,
    H = b.height / 2,
    pt = b.pt;
  const poly = (points: number[][]): number[] => points.flatMap(([u, v]) => pt(u!, v!));
  // The headlight: a cone ahead of the bow in five nested layers (brightest along the axis), showing
  // only below the sunlit water and brighter the deeper the boat.
  const glow = Math.max(0, Math.min(0.14, (b.depth - HEADLIGHT.fromDepth) / 300));
  if (glow > 0)
    for (let i = 0; i < 5; i++) {
      const reach = HEADLIGHT.reach - 3 * i,
        spread = HEADLIGHT.spread - 1.3 * i;
      g.poly(
        poly([
          [L - 0.2, 0.3],
          [L + reach, spread],
          [L + reach * 1.08, 0],
          [L + reach, -spread],
          [L - 0.2, -0.3],
        ]),
      ).fill({ color: 0xfff3c0, alpha: glow });
    }
  // Rudder and stern planes (the fin across the stern, seen edge-on as a cross).
  g.poly(
    poly([
      [-L + 0.3, 0],
      [-L + 1.6, H * 0.3],
      [-L + 0.9, H + 0.9],
      [-L - 0.1, H + 0.9],
    ]),
  )
    .fill(YELLOW_DARK)
    .stroke({ color: OUTLINE, width: 1 });
  g.poly(
    poly([
      [-L + 0.3, 0],
      [-L + 1.6, -H * 0.3],
      [-L + 0.9, -H - 0.9],
      [-L - 0.1, -H - 0.9],
    ]),
  )
    .fill(YELLOW_DARK)
    .stroke({ color: OUTLINE, width: 1 });
  // The screw behind the stern: two blades seen side on, their length turning with the phase.
  const [hx, hy] = pt(-L - 0.35, 0);
  for (const offset of [0, Math.PI / 2]) {
    const reach = 1.15 * Math.cos(b.screwPhase + offset);
    const [ax, ay] = pt(-L - 0.35, reach),
      [bx, by] = pt(-L - 0.35, -reach);
    g.moveTo(ax, ay)
      .lineTo(bx, by)
      .stroke({ color: STEEL, width: Math.max(2, 0.45 * b.scale), cap: 'round' });
  }
  g.circle(hx, hy, Math.max(1.5, 0.3 * b.scale)).fill(STEEL);
  // The hull: a rounded bow (a half ellipse), straight sides, a stern tapering to the screw's boss.
  const outline: number[][] = [];
  const bowStart = L - H * 1.4;
  for (let i = 0; i <= 10; i++) {
    const t = -Math.PI / 2 + (Math.PI * i) / 10;
    outline.push([bowStart + H * 1.4 * Math.cos(t), H * Math.sin(t)]);
  }
  outline.push([-L * 0.55, H], [-L + 0.3, H * 0.35], [-L + 0.3, -H * 0.35], [-L * 0.55, -H]);
  g.poly(poly(outline))
    .fill(b.touching ? 0xe0503c : YELLOW)
    .stroke({ color: OUTLINE, width: Math.max(1.2, 0.12 * b.scale) });
  // A darker belly line for shape.
  g.poly(
    poly([
      [bowStart + 0.3, -H * 0.55],
      [bowStart + H * 1.2, -H * 0.45],
      [bowStart + H * 0.9, -H * 0.85],
      [-L * 0.55, -H * 0.98],
      [-L + 0.5, -H * 0.4],
    ]),
  ).fill({ color: YELLOW_DARK, alpha: b.touching ? 0 : 0.55 });
  // The sail (conning tower) with its periscope.
  g.poly(
    poly([
      [-1.4, H - 0.1],
      [-0.9, H + 1.7],
      [1.3, H + 1.7],
      [2.1, H - 0.1],
    ]),
  )
    .fill(b.touching ? 0xe0503c : YELLOW)
    .stroke({ color: OUTLINE, width: Math.max(1.2, 0.12 * b.scale) });
  const [p0x, p0y] = pt(0.5, H + 1.7),
    [p1x, p1y] = pt(0.5, H + 2.8),
    [p2x, p2y] = pt(1.2, H + 2.8);
  g.moveTo(p0x, p0y)
    .lineTo(p1x, p1y)
    .lineTo(p2x, p2y)
    .stroke({ color: STEEL, width: Math.max(1.5, 0.22 * b.scale) });
  // Windows into the ballast tanks: the water in each (blue, rising with the fill).
  for (const [u, f] of [
    [b.tankArm, b.tanks[0]],
    [-b.tankArm, b.tanks[1]],
  ] as const) {
    const lo = -H * 0.5,
      hi = H * 0.3;
    g.poly(
      poly([
        [u - 0.9, lo],
        [u + 0.9, lo],
        [u + 0.9, hi],
        [u - 0.9, hi],
      ]),
    ).fill({ color: 0x1b2a38, alpha: 0.85 });
    if (f > 0.001)
      g.poly(
        poly([
          [u - 0.9, lo],
          [u + 0.9, lo],
          [u + 0.9, lo + (hi - lo) * f],
          [u - 0.9, lo + (hi - lo) * f],
        ]),
      ).fill({ color: 0x4fb0ff, alpha: 0.9 });
  }
  // The dive planes: a foil at the bow and one at the stern (seen side on), turned about their middle.
  const delta = b.planes ?? 0,
    dc = Math.cos(delta),
    ds = Math.sin(delta);
  for (const [cu, cv, chord] of [
    [L - 2.4, H * 0.1, 1.8],
    [-L + 1.4, 0, 1.5],
  ] as const) {
    const foil: number[][] = [
      [chord / 2, 0],
      [chord / 4, 0.2],
      [-chord / 2, 0.06],
      [-chord / 2, -0.06],
      [chord / 4, -0.2],
    ].map(([fu, fv]) => [cu + fu! * dc - fv! * ds, cv + fu! * ds + fv! * dc]);
    g.poly(poly(foil)).fill(STEEL).stroke({ color: OUTLINE, width: 1 });
  }
  // Portholes between the tanks, lit from inside.
  const lit = Math.min(1, 0.55 + b.depth / 80);
  for (const u of [-1.3, 0.3, 1.9]) {
    const [x, y] = pt(u, H * 0.05);
    const r = Math.max(1.5, 0.42 * b.scale);
    g.circle(x, y, r * 1.8).fill({ color: 0xffe9a0, alpha: 0.18 * lit });
    g.circle(x, y, r).fill({ color: 0xfff2c4, alpha: lit }).stroke({ color: OUTLINE, width: 1 });
  }
}
