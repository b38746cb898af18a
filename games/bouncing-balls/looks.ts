/**
 * The bouncing-balls court's looks, drawn in code: the gym wall (painted blocks lit by a lamp above,
 * darker towards the sides), the hardwood floor (boards of slightly varied tone with a sheen and the
 * lamp's reflection), the balls' sphere shading (the renderer's shared disc texture redrawn once as a
 * lit sphere, so every ball, sprite or particle, is shaded at no cost per frame), and the soft shadows
 * the balls cast on the floor (one Graphics a frame).
 */

import type { Container, Graphics, Texture } from 'pixi.js';

/** Screen rectangle of the court's wall, CSS px: x0 left, x1 right, y0 top, y1 floor line. */
export interface CourtRect {
  x0: number;
  x1: number;
  y0: number;
  y1: number;
}

/** Mixes two 0xRRGGBB colours: `t` 0 gives `a`, 1 gives `b` (t in [0, 1]). */
export function mix(a: number, b: number, t: number): number {
  const ch = (s: number): number => Math.round(((a >> s) & 255) + (((b >> s) & 255) - ((a >> s) & 255)) * t);
  return (ch(16) << 16) | (ch(8) << 8) | ch(0);
}

/**
 * Draws the gym wall into `g` over `r`: a vertical gradient (lighter near the lamp at the top), painted
 * block courses `block` px high with staggered joints (faint lines), a lamp's glow spreading from the
 * top middle (stacked ellipses of low alpha) and a shade darkening the two sides. Drawn once per camera.
 */
export function drawWall(g: Graphics, r: CourtRect, block: number): void {
  const { x0, x1, y0, y1 } = r;
  const w = x1 - x0,
    h = y1 - y0;
  const bands = 16;
  for (let i = 0; i < bands; i++) {
    const f = i / (bands - 1);
    g.rect(x0, y0 + (h * i) / bands, w, h / bands + 1).fill(mix(0x2a3858, 0x1b2540, f));
  }
  // The lamp's glow: wide soft ellipses from the top middle.
  const cx = (x0 + x1) / 2;
  for (let k = 10; k >= 1; k--) {
    const f = k / 10;
    // The lower half of an ellipse centred on the wall's top, kept inside the wall.
    const rx = Math.min(0.62 * w * f, w / 2),
      ry = 0.95 * h * f;
    const pts: number[] = [];
    for (let j = 0; j <= 24; j++) {
      const a = (Math.PI * j) / 24;
      pts.push(cx + rx * Math.cos(a), y0 + ry * Math.sin(a));
    }
    g.poly(pts).fill({ color: 0x9fb4e0, alpha: 0.028 });
  }
  // The painted blocks: mortar lines, a lighter line under each (the course's lit top edge).
  const bw = 2 * block;
  let row = 0;
  for (let y = y1 - block; y > y0; y -= block, row++) {
    g.rect(x0, y, w, 1).fill({ color: 0x0d1322, alpha: 0.35 });
    g.rect(x0, y + 1, w, 1).fill({ color: 0xc8d4f0, alpha: 0.05 });
    const off = row % 2 ? bw / 2 : 0;
    for (let x = x0 + off; x < x1; x += bw) if (x > x0 + 2) g.rect(x, y + 1, 1, block - 1).fill({ color: 0x0d1322, alpha: 0.28 });
  }
  // The sides in shade, and a dark band along the floor (ambient occlusion where wall meets floor).
  const side = 0.16 * w;
  for (let k = 0; k < 6; k++) {
    const s = side * (1 - k / 6);
    g.rect(x0, y0, s, h).fill({ color: 0x05080f, alpha: 0.06 });
    g.rect(x1 - s, y0, s, h).fill({ color: 0x05080f, alpha: 0.06 });
  }
  for (let k = 1; k <= 5; k++) g.rect(x0, y1 - (k * block) / 5, w, (k * block) / 5).fill({ color: 0x05080f, alpha: 0.05 });
}

/**
 * Draws the hardwood floor into `g`: `depth` px of boards under the floor line `r.y1`, each `board` px
 * long in a slightly different tone (a fixed pattern, no randomness), their seams, a lit top edge, a
 * sheen band along the upper half and the lamp's reflection in the middle.
 */
export function drawFloor(g: Graphics, r: CourtRect, depth: number, board: number): void {
  const { x0, x1, y1 } = r;
  const w = x1 - x0;
  const tones = [0xc8904f, 0xbf8646, 0xd09a58, 0xc48b4b, 0xcc9453];
  let i = 0;
  for (let x = x0; x < x1; x += board, i++) {
    g.rect(x, y1, Math.min(board, x1 - x), depth).fill(tones[(i * 3) % tones.length]!);
    if (x > x0) g.rect(x, y1 + 2, 1, depth - 2).fill({ color: 0x7a4f24, alpha: 0.8 });
  }
  // A second course of boards, offset by half a board, when the floor is deep enough to show it.
  if (depth >= 16) {
    const mid = y1 + Math.round(depth / 2);
    g.rect(x0, mid, w, 1).fill({ color: 0x7a4f24, alpha: 0.6 });
  }
  // The sheen: a lighter band along the top, and the lamp's reflection (a soft bright ellipse).
  for (let k = 1; k <= 4; k++) g.rect(x0, y1, w, (depth * k) / 8).fill({ color: 0xfff1d6, alpha: 0.05 });
  for (let k = 6; k >= 1; k--)
    g.ellipse((x0 + x1) / 2, y1 + depth * 0.35, 0.3 * w * (k / 6), depth * 0.3 * (k / 6)).fill({ color: 0xfff6e4, alpha: 0.05 });
  g.rect(x0, y1, w, 2).fill(0xe9bd84);
  g.rect(x0, y1 + depth - 2, w, 2).fill({ color: 0x4a2e12, alpha: 0.6 });
}

/**
 * Redraws the renderer's shared ball texture (found on the first sprite or particle of its `balls`
 * container under `root`) as a lit sphere in greys: light from above and to the left, white at the
 * highlight, darker to a shaded rim. Tinting multiplies it, so each ball keeps its colour, shaded.
 * @returns whether the texture was found and redrawn (false leaves the balls as they were).
 */
export function shadeBallTexture(root: Container): boolean {
  const layer = root.children.find((c) => c.label === 'balls');
  let texture: Texture | undefined;
  const visit = (c: Container): void => {
    if (texture) return;
    const t = (c as unknown as { texture?: Texture }).texture;
    if (t?.source) texture = t;
    const particles = (c as unknown as { particleChildren?: { texture: Texture }[] }).particleChildren;
    if (!texture && particles?.length) texture = particles[0]!.texture;
    for (const k of c.children) visit(k as Container);
  };
  if (layer) visit(layer as Container);
  const canvas = texture?.source.resource as HTMLCanvasElement | undefined;
  const ctx = canvas?.getContext?.('2d');
  if (!texture || !canvas || !ctx) return false;
  const size = canvas.width,
    c = size / 2,
    r = c - 1;
  ctx.clearRect(0, 0, size, size);
  const grad = ctx.createRadialGradient(c - 0.38 * r, c - 0.42 * r, 0.04 * r, c, c, r);
  grad.addColorStop(0, '#ffffff');
  grad.addColorStop(0.45, '#ececec');
  grad.addColorStop(0.8, '#b8b8b8');
  grad.addColorStop(1, '#7a7a7a');
  ctx.beginPath();
  ctx.arc(c, c, r, 0, Math.PI * 2);
  ctx.fillStyle = grad;
  ctx.fill();
  ctx.lineWidth = Math.max(1, size * 0.025);
  ctx.strokeStyle = '#6a6a6a';
  ctx.beginPath();
  ctx.arc(c, c, r - ctx.lineWidth / 2, 0, Math.PI * 2);
  ctx.stroke();
  texture.source.update();
  return true;
}

/**
 * Draws a ball's soft shadow on the floor into `g`: a flat ellipse under (`x`, the floor line `floorY`),
 * px, for a ball of radius `r` px whose bottom is `height` px above the floor; wider, fainter and gone
 * 6 radii up (the lamp is high above).
 */
export function drawShadow(g: Graphics, x: number, floorY: number, r: number, height: number): void {
  const f = Math.max(0, 1 - height / (6 * r));
  if (f <= 0) return;
  const w = r * (1.05 + 0.5 * (1 - f));
  g.ellipse(x, floorY, w * 1.25, 0.3 * r + 1).fill({ color: 0x000000, alpha: 0.12 * f });
  g.ellipse(x, floorY, w * 0.9, 0.2 * r + 1).fill({ color: 0x000000, alpha: 0.22 * f });
}

/**
 * Draws a white glint on a ball of radius `r` px at (`x`, `y`) into `g`: the lamp's reflection, up and
 * to the left (tinting cannot make the sphere texture whiter than the ball's colour); `alpha` in [0, 1].
 */
export function drawGlint(g: Graphics, x: number, y: number, r: number, alpha: number): void {
  if (r < 3 || alpha <= 0) return;
  g.ellipse(x - 0.36 * r, y - 0.42 * r, 0.3 * r, 0.22 * r).fill({ color: 0xffffff, alpha: 0.1 * alpha });
  g.ellipse(x - 0.36 * r, y - 0.44 * r, 0.14 * r, 0.1 * r).fill({ color: 0xffffff, alpha: 0.55 * alpha });
}
