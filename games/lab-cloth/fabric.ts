/**
 * The sheet's print, drawn once on a 2D canvas: cream cotton with a fine weave and pale stripes, a
 * stitched hem along the top, and the level's targets (pattern.ts, levels.ts): shapes printed in
 * colour inside dashed cutting lines, each with a pair of scissors at the line; a peg bag on its
 * ribbon, a dashed line and scissors across the ribbon; the perforation as a dotted line with a row of
 * ticks. The texture spans the whole sheet (u across, v down).
 */
import { Texture } from 'pixi.js';
import { WINDOW_FRAME } from './levels';
import { SHAPES, type Shape } from './pattern';

/** Texture width, px (its height follows the sheet's shape). */
const WIDTH = 1024;

/** Draws a small pair of open scissors at (x, y), px, pointing along angle `a` (rad), `s` px long. */
function scissors(g: CanvasRenderingContext2D, x: number, y: number, a: number, s: number, color: string): void {
  g.save();
  g.translate(x, y);
  g.rotate(a);
  g.strokeStyle = color;
  g.fillStyle = color;
  g.lineWidth = s * 0.09;
  // Two blades from the pivot forward, two finger rings behind it.
  g.beginPath();
  g.moveTo(0, 0);
  g.lineTo(s * 0.55, -s * 0.14);
  g.moveTo(0, 0);
  g.lineTo(s * 0.55, s * 0.14);
  g.stroke();
  g.beginPath();
  g.arc(-s * 0.28, -s * 0.16, s * 0.13, 0, 2 * Math.PI);
  g.moveTo(-s * 0.28 + s * 0.13, s * 0.16);
  g.arc(-s * 0.28, s * 0.16, s * 0.13, 0, 2 * Math.PI);
  g.stroke();
  g.beginPath();
  g.arc(0, 0, s * 0.05, 0, 2 * Math.PI);
  g.fill();
  g.restore();
}

/**
 * Prints the peg bag: `outline` is the ribbon (its first three corners: top left, top right, bottom
 * right) and the bag below it (sheet m; `px` pixels a metre). The ribbon red with a dashed cutting
 * line and scissors across its middle, the bag in canvas with a drawstring, pegs and its name.
 */
function bag(g: CanvasRenderingContext2D, outline: readonly number[], px: number, color: number): void {
  const rx0 = outline[0]! * px,
    rx1 = outline[2]! * px,
    ry0 = outline[1]! * px,
    ry1 = outline[5]! * px;
  const bx0 = outline[12]! * px,
    bx1 = outline[6]! * px,
    by1 = outline[9]! * px;
  g.setLineDash([]);
  g.fillStyle = 'rgba(200, 50, 60, 0.8)';
  g.fillRect(rx0, ry0, rx1 - rx0, ry1 - ry0);
  g.fillStyle = rgba(color, 0.85);
  g.fillRect(bx0, ry1, bx1 - bx0, by1 - ry1);
  g.strokeStyle = 'rgba(90, 60, 30, 0.9)';
  g.lineWidth = 3;
  g.strokeRect(bx0 + 2, ry1 + 2, bx1 - bx0 - 4, by1 - ry1 - 4);
  // Pegs peeking out of the top, and the bag's name.
  g.fillStyle = 'rgba(230, 190, 130, 1)';
  for (let k = 0; k < 5; k++) g.fillRect(bx0 + (bx1 - bx0) * (0.15 + 0.16 * k), ry1 + 6, 8, 26);
  g.font = `bold ${Math.round((by1 - ry1) * 0.28)}px sans-serif`;
  g.fillStyle = 'rgba(255, 240, 215, 0.95)';
  g.textAlign = 'center';
  g.fillText('PEGS', (bx0 + bx1) / 2, ry1 + (by1 - ry1) * 0.78);
  g.textAlign = 'left';
  // Cut here: across the ribbon's middle, scissors pointing at it.
  const my = (ry0 + ry1) / 2;
  g.setLineDash([10, 7]);
  g.strokeStyle = 'rgba(255, 255, 255, 0.95)';
  g.lineWidth = 4;
  g.beginPath();
  g.moveTo(rx0 - 30, my);
  g.lineTo(rx1 + 30, my);
  g.stroke();
  g.setLineDash([]);
  scissors(g, rx0 - 52, my, 0, 38, 'rgba(255, 255, 255, 0.95)');
}

/** How strongly a window's pane is tinted with its colour over the cloth, 0 to 1. */
const PANE_TINT = 0.12;

/** Paints the sheet's cloth over `g`'s W x H px (within its clip): the cream ground, pale blue stripes, then the weave, fine threads both ways. */
function cloth(g: CanvasRenderingContext2D, W: number, H: number): void {
  g.fillStyle = '#f3ecdc';
  g.fillRect(0, 0, W, H);
  for (let x = 0; x < W; x += 64) {
    g.fillStyle = 'rgba(96, 140, 190, 0.16)';
    g.fillRect(x + 6, 0, 20, H);
    g.fillStyle = 'rgba(96, 140, 190, 0.1)';
    g.fillRect(x + 30, 0, 4, H);
  }
  for (let y = 0; y < H; y += 3) {
    g.fillStyle = `rgba(90, 70, 50, ${0.035 + 0.03 * ((y * 7) % 5 === 0 ? 1 : 0)})`;
    g.fillRect(0, y, W, 1);
  }
  for (let x = 0; x < W; x += 3) {
    g.fillStyle = 'rgba(90, 70, 50, 0.03)';
    g.fillRect(x, 0, 1, H);
  }
}

/** Hex colour 0xRRGGBB as CSS rgba with alpha `a`. */
function rgba(c: number, a: number): string {
  return `rgba(${(c >> 16) & 255}, ${(c >> 8) & 255}, ${c & 255}, ${a})`;
}

/**
 * Draws the print for a sheet `sheetWidth` x `sheetHeight` m whose hem (the rows that never tear) is
 * `hemHeight` m deep, with `shapes` printed on it (sheet coordinates, m) and the `perforation` line
 * (sheet coordinates, x and y interleaved) if given. @returns the texture.
 */
export function fabricTexture(
  sheetWidth: number,
  sheetHeight: number,
  hemHeight: number,
  shapes: readonly Shape[] = SHAPES,
  perforation?: readonly number[],
): Texture {
  const W = WIDTH,
    H = Math.round((WIDTH * sheetHeight) / sheetWidth);
  const px = W / sheetWidth;
  const canvas = document.createElement('canvas');
  canvas.width = W;
  canvas.height = H;
  const g = canvas.getContext('2d')!;
  cloth(g, W, H);
  // The hem: a folded band with a row of stitches under it.
  const hem = hemHeight * px;
  g.fillStyle = 'rgba(120, 96, 70, 0.16)';
  g.fillRect(0, 0, W, hem);
  g.strokeStyle = 'rgba(100, 80, 60, 0.55)';
  g.lineWidth = 2;
  g.setLineDash([8, 6]);
  g.beginPath();
  g.moveTo(0, hem - 4);
  g.lineTo(W, hem - 4);
  g.stroke();
  // The perforation: a dotted line with a tick across it at every other dot, and words at its left end.
  if (perforation) {
    g.setLineDash([]);
    g.fillStyle = 'rgba(60, 70, 84, 0.85)';
    for (let k = 2; k < perforation.length; k += 2) {
      const ax = perforation[k - 2]! * px,
        ay = perforation[k - 1]! * px,
        bx = perforation[k]! * px,
        by = perforation[k + 1]! * px;
      const len = Math.hypot(bx - ax, by - ay),
        n = Math.max(1, Math.round(len / 14));
      for (let j = 0; j < n; j++) {
        const u = j / n,
          x = ax + (bx - ax) * u,
          y = ay + (by - ay) * u;
        g.beginPath();
        g.arc(x, y, 3.2, 0, 2 * Math.PI);
        g.fill();
        if ((k / 2 + j) % 2 === 0) g.fillRect(x - 1, y - 11, 2, 7);
      }
    }
    g.font = `bold ${Math.round(0.09 * px)}px sans-serif`;
    g.fillStyle = 'rgba(60, 70, 84, 0.8)';
    g.fillText('tear along the dots', 0.25 * px, (perforation[1]! + 0.32) * px);
  }
  // A window's frame: a wooden band round each pane (under the panes' own print).
  g.setLineDash([]);
  for (const s of shapes) {
    if (s.style !== 'pane') continue;
    const o = s.outline;
    const f = WINDOW_FRAME * px;
    g.fillStyle = 'rgba(150, 108, 66, 0.9)';
    g.fillRect(o[0]! * px - f, o[1]! * px - f, (o[4]! - o[0]!) * px + 2 * f, (o[5]! - o[1]!) * px + 2 * f);
    g.strokeStyle = 'rgba(96, 66, 38, 0.9)';
    g.lineWidth = 3;
    g.strokeRect(o[0]! * px - f, o[1]! * px - f, (o[4]! - o[0]!) * px + 2 * f, (o[5]! - o[1]!) * px + 2 * f);
  }
  // The shapes: a tinted print and a dashed cutting line, scissors at the top of the line.
  for (const s of shapes) {
    const o = s.outline;
    if (s.style === 'tear') {
      // The strip: a faint tint below the perforation (the dotted line is its cutting line).
      g.beginPath();
      g.moveTo(o[0]! * px, o[1]! * px);
      for (let i = 2; i < o.length; i += 2) g.lineTo(o[i]! * px, o[i + 1]! * px);
      g.closePath();
      g.fillStyle = rgba(s.color, 0.14);
      g.fill();
      continue;
    }
    if (s.style === 'bag') {
      bag(g, o, px, s.color);
      continue;
    }
    g.beginPath();
    g.moveTo(o[0]! * px, o[1]! * px);
    for (let i = 2; i < o.length; i += 2) g.lineTo(o[i]! * px, o[i + 1]! * px);
    g.closePath();
    g.setLineDash([]);
    // A pane: the sheet's own cloth again over the frame's wood, lightly tinted: cut out, it falls
    // and lies as a piece of the same cloth (pale glass read as a ghost of a quad on the lawn).
    if (s.style === 'pane') {
      g.save();
      g.clip();
      cloth(g, W, H);
      g.restore();
    }
    g.fillStyle = rgba(s.color, s.style === 'pane' ? PANE_TINT : 0.3);
    g.fill();
    g.setLineDash([14, 9]);
    g.lineWidth = 4;
    g.strokeStyle = rgba(s.color, 0.95);
    g.stroke();
    g.setLineDash([]);
    // Scissors just outside the top of the line, pointing along it (to the right).
    let top = 0;
    for (let i = 1; i < o.length; i += 2) if (o[i]! < o[top + 1]!) top = i - 1;
    scissors(g, o[top]! * px - 34, o[top + 1]! * px - 2, 0, 38, rgba(s.color, 0.95));
  }
  return Texture.from(canvas);
}
