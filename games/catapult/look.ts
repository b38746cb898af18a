/**
 * Catapult, how things look (drawing only, no physics): castle pieces as wood with grain and nails,
 * glass with a shine, dressed stone blocks, round stones with a lit side; hills and pits; the catapult itself, a wooden throwing arm on a
 * frame whose arm swings back as the player pulls; the earth mound under it. Everything is drawn in
 * the scene's metres through the camera, into a pixi Graphics the caller clears each frame.
 */
import type { Camera } from '@bitphysics/render-pixi';
import type { Graphics } from 'pixi.js';

/** The colour a fraction t of the way from a to b (0xRRGGBB). */
export function mixColor(a: number, b: number, t: number): number {
  const c = (s: number) => Math.round(((a >> s) & 255) * (1 - t) + ((b >> s) & 255) * t) << s;
  return c(16) | c(8) | c(0);
}

/** A body's frame on the screen: centre (m), angle (rad), and the camera that maps it. */
interface Frame {
  cam: Camera;
  x: number;
  y: number;
  c: number;
  s: number;
}
/** Screen point of local point (u, v), m, in frame f: pushed onto `out` as x, y. */
function put(f: Frame, u: number, v: number, out: number[]): number[] {
  out.push(f.cam.toScreenX(f.x + f.c * u - f.s * v), f.cam.toScreenY(f.y + f.s * u + f.c * v));
  return out;
}
/** Screen polygon of the local box [u0, u1] x [v0, v1] in frame f. */
function box(f: Frame, u0: number, v0: number, u1: number, v1: number): number[] {
  const out: number[] = [];
  put(f, u0, v0, out);
  put(f, u1, v0, out);
  put(f, u1, v1, out);
  return put(f, u0, v1, out);
}
/** Screen polyline of the local segment (u0, v0) to (u1, v1) in frame f. */
function segment(g: Graphics, f: Frame, u0: number, v0: number, u1: number, v1: number): Graphics {
  const p: number[] = [];
  put(f, u0, v0, p);
  put(f, u1, v1, p);
  return g.moveTo(p[0]!, p[1]!).lineTo(p[2]!, p[3]!);
}

/**
 * A plank or post of wood centred at (x, y), m, turned by `angle` (rad), half extents (hx, hy), m:
 * `color` filled, a dark rim, grain along its length, darker end grain and a nail near each end.
 * A fallen piece is drawn darker.
 */
export function drawWood(
  g: Graphics,
  cam: Camera,
  x: number,
  y: number,
  angle: number,
  hx: number,
  hy: number,
  color: number,
  fallen: boolean,
): void {
  const f: Frame = { cam, x, y, c: Math.cos(angle), s: Math.sin(angle) };
  const base = fallen ? mixColor(color, 0x2a1d12, 0.5) : color;
  const rim = mixColor(base, 0x000000, 0.55);
  g.poly(box(f, -hx, -hy, hx, hy))
    .fill(base)
    .stroke({ width: 1.2, color: rim });
  // Along the long side: grain lines; across the short one: end grain at both ends.
  const long = hx >= hy;
  const L = long ? hx : hy,
    W = long ? hy : hx;
  const grain = { width: 1, color: mixColor(base, 0x3b2412, 0.45), alpha: 0.6 };
  const along = (w: number, a: number, b: number) =>
    long ? segment(g, f, a * L, w * W, b * L, w * W) : segment(g, f, w * W, a * L, w * W, b * L);
  along(-0.45, -0.9, 0.55).stroke(grain);
  along(0.3, -0.6, 0.92).stroke(grain);
  if (W * cam.toScreenLength(1) > 6) along(-0.05, -0.3, 0.3).stroke(grain);
  const end = Math.min(0.07, 0.3 * L);
  const endColor = { color: mixColor(base, 0x3b2412, 0.35), alpha: 0.8 };
  g.poly(long ? box(f, -hx, -hy, -hx + end, hy) : box(f, -hx, -hy, hx, -hy + end)).fill(endColor);
  g.poly(long ? box(f, hx - end, -hy, hx, hy) : box(f, -hx, hy - end, hx, hy)).fill(endColor);
  // A nail head near each end.
  const r = Math.max(1, cam.toScreenLength(0.035));
  for (const side of [-1, 1]) {
    const p = long ? put(f, side * (L - 0.16), 0, []) : put(f, 0, side * (L - 0.16), []);
    g.circle(p[0]!, p[1]!, r).fill(0x3a3a3a);
  }
}

/**
 * A glass block centred at (x, y), m, turned by `angle`, half extents (hx, hy): pale and half see-
 * through, a bright rim and a diagonal shine; a fallen one dimmer, with a crack.
 */
export function drawGlass(
  g: Graphics,
  cam: Camera,
  x: number,
  y: number,
  angle: number,
  hx: number,
  hy: number,
  color: number,
  fallen: boolean,
): void {
  const f: Frame = { cam, x, y, c: Math.cos(angle), s: Math.sin(angle) };
  g.poly(box(f, -hx, -hy, hx, hy))
    .fill({ color, alpha: fallen ? 0.45 : 0.7 })
    .stroke({ width: 1.5, color: 0xf4fcff, alpha: 0.95 });
  const shine: number[] = [];
  put(f, -0.75 * hx, 0.2 * hy, shine);
  put(f, -0.2 * hx, 0.8 * hy, shine);
  put(f, 0.1 * hx, 0.8 * hy, shine);
  put(f, -0.75 * hx, -0.1 * hy, shine);
  g.poly(shine).fill({ color: 0xffffff, alpha: 0.6 });
  if (fallen)
    segment(g, f, -0.7 * hx, -0.6 * hy, 0.1 * hx, 0.1 * hy)
      .lineTo(...(put(f, 0.6 * hx, -0.3 * hy, []) as [number, number]))
      .stroke({ width: 1, color: 0xffffff, alpha: 0.8 });
}

/**
 * A block of dressed stone centred at (x, y), m, turned by `angle`, half extents (hx, hy): `color`
 * with a dark rim, a lit top edge, a shaded bottom one and a few chisel marks; a fallen one darker.
 */
export function drawBrick(
  g: Graphics,
  cam: Camera,
  x: number,
  y: number,
  angle: number,
  hx: number,
  hy: number,
  color: number,
  fallen: boolean,
): void {
  const f: Frame = { cam, x, y, c: Math.cos(angle), s: Math.sin(angle) };
  const base = fallen ? mixColor(color, 0x000000, 0.45) : color;
  g.poly(box(f, -hx, -hy, hx, hy))
    .fill(base)
    .stroke({ width: 1.5, color: mixColor(base, 0x000000, 0.6) });
  const edge = Math.min(0.06, 0.3 * hy);
  g.poly(box(f, -hx, hy - edge, hx, hy)).fill({ color: 0xffffff, alpha: 0.25 });
  g.poly(box(f, -hx, -hy, hx, -hy + edge)).fill({ color: 0x000000, alpha: 0.2 });
  const mark = { width: 1, color: mixColor(base, 0x000000, 0.45), alpha: 0.7 };
  segment(g, f, -0.6 * hx, 0.2 * hy, -0.3 * hx, -0.1 * hy).stroke(mark);
  segment(g, f, 0.25 * hx, 0.35 * hy, 0.55 * hx, 0.05 * hy).stroke(mark);
  segment(g, f, -0.05 * hx, -0.35 * hy, 0.3 * hx, -0.5 * hy).stroke(mark);
}

/**
 * A hill (a box of earth over [minX, maxX] x [minY, maxY], m): earth, darker lower down, with
 * stones set in it, a rocky rim down its sides and grass on its top.
 */
export function drawHill(
  g: Graphics,
  cam: Camera,
  minX: number,
  maxX: number,
  minY: number,
  maxY: number,
  earth: number,
  grass: number,
): void {
  const X = (v: number) => cam.toScreenX(v),
    Y = (v: number) => cam.toScreenY(v);
  g.rect(X(minX), Y(maxY), X(maxX) - X(minX), Y(minY) - Y(maxY)).fill(earth);
  // Darker earth lower down, and stones set in it (fixed places from the hill's size).
  g.rect(X(minX), Y(minY + 0.45 * (maxY - minY)), X(maxX) - X(minX), Y(minY) - Y(minY + 0.45 * (maxY - minY))).fill({
    color: 0x2a1a0c,
    alpha: 0.18,
  });
  const w = maxX - minX,
    h = maxY - minY;
  for (let k = 0; k < Math.round(2.2 * w); k++) {
    const u = (k * 0.618034) % 1,
      v = (k * 0.754878) % 1;
    const r = 0.07 + 0.06 * ((k * 0.41) % 1);
    g.ellipse(X(minX + 0.15 + u * (w - 0.3)), Y(minY + 0.15 + v * (h - 0.45)), cam.toScreenLength(r), cam.toScreenLength(0.65 * r)).fill({
      color: 0xb3a58c,
      alpha: 0.55,
    });
  }
  const rim = mixColor(earth, 0x000000, 0.35);
  const side = Math.max(2, cam.toScreenLength(0.12));
  g.rect(X(minX), Y(maxY), side, Y(minY) - Y(maxY)).fill(rim);
  g.rect(X(maxX) - side, Y(maxY), side, Y(minY) - Y(maxY)).fill(rim);
  g.rect(X(minX) - 1, Y(maxY) - 1, X(maxX) - X(minX) + 2, Math.max(3, cam.toScreenLength(0.16))).fill(grass);
}

/**
 * A pit over [minX, maxX] from its floor at `floor` (m, < 0) up to the ground (y = 0): its far wall
 * in shadow, its side walls darker still, and its floor of earth, over the ground drawn before it.
 */
export function drawPit(g: Graphics, cam: Camera, minX: number, maxX: number, floor: number, earth: number): void {
  const X = (v: number) => cam.toScreenX(v),
    Y = (v: number) => cam.toScreenY(v);
  g.rect(X(minX), Y(0) - 1, X(maxX) - X(minX), Y(floor) - Y(0) + 1).fill(mixColor(earth, 0x000000, 0.45));
  // Light falling in from the left: the right wall lit, the left in shadow.
  const wall = Math.max(3, cam.toScreenLength(0.25));
  g.rect(X(minX), Y(0) - 1, wall, Y(floor) - Y(0) + 1).fill(mixColor(earth, 0x000000, 0.6));
  g.rect(X(maxX) - wall, Y(0) - 1, wall, Y(floor) - Y(0) + 1).fill(mixColor(earth, 0xffffff, 0.08));
  g.rect(X(minX), Y(floor), X(maxX) - X(minX), Math.max(3, cam.toScreenLength(0.14))).fill(mixColor(earth, 0xffffff, 0.12));
}

/**
 * A round stone of radius r (m) centred at (x, y), turned by `angle`: `color` with a dark rim, a lit
 * upper left and a few specks that turn with it (so a rolling stone is seen to roll).
 */
export function drawStone(g: Graphics, cam: Camera, x: number, y: number, angle: number, r: number, color: number): void {
  const sx = cam.toScreenX(x),
    sy = cam.toScreenY(y),
    R = Math.max(2, cam.toScreenLength(r));
  g.circle(sx, sy, R)
    .fill(color)
    .stroke({ width: 1.5, color: mixColor(color, 0x000000, 0.55) });
  g.circle(sx - 0.3 * R, sy - 0.3 * R, 0.45 * R).fill({ color: 0xffffff, alpha: 0.22 });
  for (let k = 0; k < 3; k++) {
    const a = angle + (k * 2 * Math.PI) / 3 + 0.4;
    const d = (0.35 + 0.15 * k) * R;
    g.circle(sx + d * Math.cos(a), sy - d * Math.sin(a), Math.max(1, 0.12 * R)).fill({ color: 0x000000, alpha: 0.3 });
  }
}

/**
 * The player's shot (a thrown or loaded stone) of radius r (m) centred at (x, y), turned by `angle`:
 * a round shot of dark iron, unlike the castle's grey stones, with a pale rim that keeps its edge
 * on dark earth and wood, a bright highlight at its upper left, and an iron band across it with a
 * rivet at each end that turns with it (so a rolling shot is seen to roll).
 */
export function drawShot(g: Graphics, cam: Camera, x: number, y: number, angle: number, r: number): void {
  const sx = cam.toScreenX(x),
    sy = cam.toScreenY(y),
    R = Math.max(3, cam.toScreenLength(r));
  g.circle(sx, sy, R + 1)
    .fill(SHOT_COLOR)
    .stroke({ width: Math.max(1.5, 0.12 * R), color: 0xf1e6c8, alpha: 0.95 });
  // The band: a chord through the middle at `angle`, darker, with a rivet at each end.
  const c = Math.cos(angle),
    s = Math.sin(angle);
  g.moveTo(sx - 0.92 * R * c, sy + 0.92 * R * s)
    .lineTo(sx + 0.92 * R * c, sy - 0.92 * R * s)
    .stroke({ width: Math.max(1.5, 0.22 * R), color: 0x14161a });
  for (const k of [-0.62, 0.62]) g.circle(sx + k * R * c, sy - k * R * s, Math.max(1, 0.1 * R)).fill(0x8d96a3);
  // Lit from the upper left: a soft sheen and a sharp highlight.
  g.circle(sx - 0.28 * R, sy - 0.3 * R, 0.5 * R).fill({ color: 0xb8c7dd, alpha: 0.22 });
  g.circle(sx - 0.38 * R, sy - 0.4 * R, Math.max(1.2, 0.2 * R)).fill({ color: 0xffffff, alpha: 0.9 });
}

/** The player's shot's iron colour (`drawShot`). */
export const SHOT_COLOR = 0x262a31;

/**
 * The catapult's parts, m and rad (angles from +x, counter-clockwise): where the arm turns (its axle
 * on the base), its length, and its angles. Cocked, the arm lies back over the base with its cup up;
 * a pull swings it further back; a throw swings it up through the launch point (upright, its cup at
 * (0, 1.5)) to the crossbar (`stop`).
 */
export const CATAPULT = {
  pivotX: 0,
  pivotY: 0.55,
  arm: 0.95,
  launch: Math.PI / 2,
  stop: (80 * Math.PI) / 180,
  cocked: Math.PI,
  /** How much further back a full pull swings the arm. */
  fullPull: (15 * Math.PI) / 180,
} as const;

/** The base's height, m (the wheels' axles). */
const BASE_Y = 0.52;

/**
 * The earth mound the catapult stands on (over the static box under it: x -1.2 to 0.6 m, 0.3 m
 * high), with grass on its top.
 */
export function drawMound(g: Graphics, cam: Camera, earth: number, grass: number): void {
  const pts = [-1.7, 0, -1.3, 0.27, -1.15, 0.31, 0.55, 0.31, 0.7, 0.27, 1.1, 0];
  const screen = pts.map((v, i) => (i % 2 === 0 ? cam.toScreenX(v) : cam.toScreenY(v)));
  g.poly(screen)
    .fill(earth)
    .stroke({ width: 1.5, color: mixColor(earth, 0x000000, 0.4) });
  g.moveTo(cam.toScreenX(-1.3), cam.toScreenY(0.27))
    .lineTo(cam.toScreenX(-1.15), cam.toScreenY(0.31))
    .lineTo(cam.toScreenX(0.55), cam.toScreenY(0.31))
    .lineTo(cam.toScreenX(0.7), cam.toScreenY(0.27))
    .stroke({ width: Math.max(2, cam.toScreenLength(0.07)), color: grass });
}

/** Where the cup is with the arm at `angle` (rad), and where a stone of radius r sits in it, m: [cupX, cupY, stoneX, stoneY]. */
export function cupAt(angle: number, r: number): [number, number, number, number] {
  const cx = CATAPULT.pivotX + CATAPULT.arm * Math.cos(angle),
    cy = CATAPULT.pivotY + CATAPULT.arm * Math.sin(angle);
  // The cup's open side faces the way the arm swings in a throw (clockwise): (sin a, -cos a).
  const d = r - 0.04;
  return [cx, cy, cx + d * Math.sin(angle), cy - d * Math.cos(angle)];
}

/**
 * The catapult: a base beam on two wheels, the arm's axle on it, an A-frame whose crossbar stops the
 * arm, and the arm from the axle to its cup at `angle` (rad; see CATAPULT).
 */
export function drawCatapult(g: Graphics, cam: Camera, angle: number): void {
  const X = (v: number) => cam.toScreenX(v),
    Y = (v: number) => cam.toScreenY(v);
  const beam = { width: Math.max(4, cam.toScreenLength(0.14)), color: 0x7a4a22 };
  const post = { width: Math.max(3, cam.toScreenLength(0.1)), color: 0x6a3f1c };
  const { pivotX: px, pivotY: py } = CATAPULT;
  // The A-frame, its apex the crossbar in front of the upright arm.
  const sa = Math.sin(CATAPULT.stop),
    ca = Math.cos(CATAPULT.stop);
  const barX = px + 0.72 * ca + 0.09 * sa,
    barY = py + 0.72 * sa - 0.09 * ca;
  g.moveTo(X(-0.3), Y(BASE_Y)).lineTo(X(barX), Y(barY)).lineTo(X(0.6), Y(BASE_Y)).stroke(post);
  // Base beam and wheels.
  g.moveTo(X(-1.1), Y(BASE_Y)).lineTo(X(0.68), Y(BASE_Y)).stroke(beam);
  for (const wx of [-0.82, 0.38]) {
    const r = cam.toScreenLength(0.21);
    g.circle(X(wx), Y(BASE_Y), r).fill(0x6b4a2e).stroke({ width: 2, color: 0x3b2412 });
    for (let k = 0; k < 3; k++) {
      const a = (k * Math.PI) / 3;
      g.moveTo(X(wx) - r * Math.cos(a), Y(BASE_Y) - r * Math.sin(a))
        .lineTo(X(wx) + r * Math.cos(a), Y(BASE_Y) + r * Math.sin(a))
        .stroke({ width: 1.2, color: 0x3b2412 });
    }
    g.circle(X(wx), Y(BASE_Y), Math.max(1.5, cam.toScreenLength(0.05))).fill(0x2b2b2b);
  }
  // The arm and its cup.
  const [cx, cy] = cupAt(angle, 0);
  g.moveTo(X(px - 0.15 * Math.cos(angle)), Y(py - 0.15 * Math.sin(angle)))
    .lineTo(X(cx), Y(cy))
    .stroke({ width: Math.max(4, cam.toScreenLength(0.13)), color: 0x9a6232 });
  // The cup: a bowl across the arm's end, open on the side the arm swings toward (screen y points down).
  const open = Math.atan2(Math.cos(angle), Math.sin(angle));
  g.arc(X(cx), Y(cy), Math.max(4, cam.toScreenLength(0.22)), open + Math.PI / 2 + 0.25, open + 1.5 * Math.PI - 0.25).stroke({
    width: Math.max(3, cam.toScreenLength(0.09)),
    color: 0x5a3517,
  });
  // The crossbar's pad, and the axle: a twisted rope bundle.
  g.circle(X(barX), Y(barY), Math.max(3, cam.toScreenLength(0.09)))
    .fill(0x8a6a4a)
    .stroke({ width: 1.5, color: 0x3b2412 });
  g.circle(X(px), Y(py), Math.max(4, cam.toScreenLength(0.13)))
    .fill(0xc9a66b)
    .stroke({ width: 1.5, color: 0x5a3517 });
}
