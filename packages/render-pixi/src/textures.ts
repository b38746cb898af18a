import { assertBoolean, assertInteger, assertKnownKeys } from '@bitphysics/physics/validate';
import { CanvasSource, DOMAdapter, type ICanvas, Texture } from 'pixi.js';

/**
 * A canvas of `width` x `height` px from pixi's DOM adapter (a page's canvas, or an OffscreenCanvas
 * in a worker) and its 2D context, for drawing a texture once.
 * @throws Error naming `where` if this environment has no 2D canvas context.
 */
export function canvas2d(where: string, width: number, height: number): { canvas: ICanvas; ctx: CanvasRenderingContext2D } {
  const canvas = DOMAdapter.get().createCanvas(width, height);
  const ctx = canvas.getContext('2d') as CanvasRenderingContext2D | null;
  if (!ctx) throw new Error(`${where}: this environment has no 2D canvas context`);
  return { canvas, ctx };
}

/**
 * A mipmapped `size` x `size` px texture of a white disc whose opacity follows `stops` from the centre
 * (offset 0) to the edge (offset 1): each stop is [offset in [0, 1], opacity in [0, 1]]. Tint multiplies
 * it. The soft particle texture and the point texture are two such radial profiles.
 * @throws Error naming `where` if there is no 2D canvas.
 */
export function radialAlphaTexture(where: string, size: number, stops: readonly (readonly [number, number])[]): Texture {
  const { canvas, ctx } = canvas2d(where, size, size);
  const c = size / 2;
  const g = ctx.createRadialGradient(c, c, 0, c, c, c);
  for (const [offset, opacity] of stops) g.addColorStop(offset, `rgba(255,255,255,${opacity})`);
  ctx.clearRect(0, 0, size, size);
  ctx.fillStyle = g;
  ctx.fillRect(0, 0, size, size);
  return new Texture({ source: new CanvasSource({ resource: canvas, autoGenerateMipmaps: true, scaleMode: 'linear' }) });
}

/** Edge lengths of the streak texture, px. */
export const STREAK_W = 64,
  STREAK_H = 16;

/**
 * Creates the streak texture of particle and point trails: opacity rising from 0 at the left (tail) to
 * 1 at the right (head), with a soft profile across. 64 x 16 px.
 * @throws Error if there is no 2D canvas.
 */
export function createStreakTexture(): Texture {
  const { canvas, ctx } = canvas2d('createStreakTexture', STREAK_W, STREAK_H);
  const image = ctx.createImageData(STREAK_W, STREAK_H);
  const d = image.data;
  for (let y = 0; y < STREAK_H; y++) {
    const v = ((y + 0.5) / STREAK_H) * 2 - 1; // -1..1 across
    const across = Math.max(0, 1 - v * v);
    for (let x = 0; x < STREAK_W; x++) {
      const u = (x + 0.5) / STREAK_W; // 0 tail .. 1 head
      const a = u * u * across;
      const o = (y * STREAK_W + x) * 4;
      d[o] = 255;
      d[o + 1] = 255;
      d[o + 2] = 255;
      d[o + 3] = Math.round(a * 255);
    }
  }
  ctx.putImageData(image, 0, 0);
  return new Texture({ source: new CanvasSource({ resource: canvas, scaleMode: 'linear' }) });
}

let sharedStreak: Texture | null = null;

/**
 * The one streak texture every particle and point layer shares, made on first use and never destroyed
 * (a few kilobytes, and a texture destroyed while pixi's particle shader still has it bound makes pixi warn).
 * @throws Error if there is no 2D canvas.
 */
export function sharedStreakTexture(): Texture {
  if (!sharedStreak) sharedStreak = createStreakTexture();
  return sharedStreak;
}

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
  const { canvas, ctx } = canvas2d(where, size, size);
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
