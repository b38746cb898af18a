/**
 * The sheet's print, drawn once on a 2D canvas: cream cotton with a fine weave and pale stripes, a
 * stitched hem along the top, and the challenge's shapes (pattern.ts) printed in colour inside dashed
 * cutting lines, each with a pair of scissors at the line. The texture spans the whole sheet (u across,
 * v down).
 */
import { Texture } from 'pixi.js';
import { SHAPES } from './pattern';

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

/** Hex colour 0xRRGGBB as CSS rgba with alpha `a`. */
function rgba(c: number, a: number): string {
  return `rgba(${(c >> 16) & 255}, ${(c >> 8) & 255}, ${c & 255}, ${a})`;
}

/**
 * Draws the print for a sheet `sheetWidth` x `sheetHeight` m whose hem (the rows that never tear) is
 * `hemHeight` m deep. @returns the texture.
 */
export function fabricTexture(sheetWidth: number, sheetHeight: number, hemHeight: number): Texture {
  const W = WIDTH,
    H = Math.round((WIDTH * sheetHeight) / sheetWidth);
  const px = W / sheetWidth;
  const canvas = document.createElement('canvas');
  canvas.width = W;
  canvas.height = H;
  const g = canvas.getContext('2d')!;
  g.fillStyle = '#f3ecdc';
  g.fillRect(0, 0, W, H);
  // Pale blue stripes, then the weave: fine threads both ways.
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
  // The shapes: a tinted print and a dashed cutting line, scissors at the top of the line.
  for (const s of SHAPES) {
    const o = s.outline;
    g.beginPath();
    g.moveTo(o[0]! * px, o[1]! * px);
    for (let i = 2; i < o.length; i += 2) g.lineTo(o[i]! * px, o[i + 1]! * px);
    g.closePath();
    g.setLineDash([]);
    g.fillStyle = rgba(s.color, 0.3);
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
