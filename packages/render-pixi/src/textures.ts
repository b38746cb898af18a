import { CanvasSource, DOMAdapter, Texture } from 'pixi.js';
import { assertBoolean, assertInteger, assertKnownKeys } from '@bitphysics/physics/validate';

/** Options of `createBallTexture`. Unknown fields are rejected. */
export interface BallTextureOptions {
  /** Edge of the square texture, px, integer in [8, 1024]. Default 128 (mipmapped, so balls of any size stay smooth). */
  size?: number;
  /** Draw the rotation mark: a dark radius from the centre towards local +x (angle 0). Default true. */
  mark?: boolean;
}

/** Where the disc sits inside a ball texture: its diameter in texture pixels (the texture keeps a 1 px margin). */
export function ballTextureDiameter(texture: Texture): number {
  return texture.width - 2;
}

/**
 * Creates the one circle texture every ball shares: a white disc with a light grey rim and, if
 * `mark`, a dark grey radius along local +x. Tinting multiplies it, so a ball of any colour keeps a
 * visibly darker rim and mark and its spin shows. Drawn once on a 2D canvas; mipmaps are generated.
 * @throws TypeError on unknown options or wrong types; RangeError on a size out of range.
 */
export function createBallTexture(options: BallTextureOptions = {}): Texture {
  const where = 'createBallTexture';
  assertKnownKeys(where, options, ['size', 'mark']);
  const size = options.size ?? 128;
  assertInteger(where, 'size', size, 8, 1024);
  const mark = options.mark ?? true;
  assertBoolean(where, 'mark', mark);
  const canvas = DOMAdapter.get().createCanvas(size, size);
  const ctx = canvas.getContext('2d') as CanvasRenderingContext2D | null;
  if (!ctx) throw new Error(`${where}: this environment has no 2D canvas context`);
  const c = size / 2;
  const r = c - 1;
  ctx.clearRect(0, 0, size, size);
  ctx.beginPath();
  ctx.arc(c, c, r, 0, Math.PI * 2);
  ctx.fillStyle = '#ffffff';
  ctx.fill();
  const rim = Math.max(1, size * 0.07);
  ctx.beginPath();
  ctx.arc(c, c, r - rim / 2, 0, Math.PI * 2);
  ctx.lineWidth = rim;
  ctx.strokeStyle = '#b4b4b4';
  ctx.stroke();
  if (mark) {
    ctx.beginPath();
    ctx.moveTo(c, c);
    ctx.lineTo(c + r - rim * 0.5, c);
    ctx.lineWidth = Math.max(1, size * 0.09);
    ctx.lineCap = 'round';
    ctx.strokeStyle = '#4a4a4a';
    ctx.stroke();
    ctx.beginPath();
    ctx.arc(c, c, Math.max(1, size * 0.07), 0, Math.PI * 2);
    ctx.fillStyle = '#4a4a4a';
    ctx.fill();
  }
  const source = new CanvasSource({ resource: canvas, autoGenerateMipmaps: true, scaleMode: 'linear' });
  return new Texture({ source });
}
