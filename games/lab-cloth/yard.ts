/**
 * The yard the sheet hangs in, drawn around it: a sky, hills, the lawn (the ground), the house wall on
 * the left and a brick wall on the right (the world's boundary box), two posts and the washing line,
 * and the wind made visible: streaks of air, leaves and grass blades that move with the world's wind
 * (windAt), so a gust shows before the sheet answers it. Drawing only: the streaks and leaves are not
 * bodies of the world.
 */
import { seededRandom } from '@bitphysics/game-kit';
import { type PhysicsWorld, windAt } from '@bitphysics/physics';
import type { Camera } from '@bitphysics/render-pixi';
import { Container, Graphics, Sprite, Texture } from 'pixi.js';
import { LINE_Y, YARD } from './scene';

/** The posts of the line, m (x). */
export const POSTS: readonly [number, number] = [-0.35, 4.35];

/** A vertical gradient from `top` to `bottom` (CSS colours) as a 1 x 256 texture. */
function gradient(stops: readonly [number, string][]): Texture {
  const c = document.createElement('canvas');
  c.width = 1;
  c.height = 256;
  const g = c.getContext('2d')!;
  const grad = g.createLinearGradient(0, 0, 0, 256);
  for (const [at, color] of stops) grad.addColorStop(at, color);
  g.fillStyle = grad;
  g.fillRect(0, 0, 1, 256);
  return Texture.from(c);
}

interface Streak {
  x: number;
  y: number;
  age: number;
  life: number;
}
interface Leaf {
  x: number;
  y: number;
  vx: number;
  vy: number;
  spin: number;
  angle: number;
  color: number;
}

/** The yard: `back` goes behind the sheet, `front` over it; call `update` every frame. */
export class Yard {
  readonly back = new Container({ label: 'yard' });
  readonly front = new Container({ label: 'wind' });
  private readonly sky = new Sprite(
    gradient([
      [0, '#3f7cc4'],
      [0.55, '#8fc0e8'],
      [1, '#e9f2f4'],
    ]),
  );
  private readonly scenery = new Graphics({ label: 'scenery' });
  private readonly grass = new Graphics({ label: 'grass' });
  private readonly air = new Graphics({ label: 'air' });
  private readonly streaks: Streak[] = [];
  private readonly leaves: Leaf[] = [];
  private readonly rand = seededRandom(7);
  private readonly wind = new Float64Array(3);
  private sceneryKey = '';
  /** Streaks drawn in the last frame (tests). */
  streaksDrawn = 0;

  /** The sky and the scenery, drawn into one texture when the view changes (one quad a frame, not their many shapes). */
  private readonly still = new Container({ label: 'still' });

  constructor() {
    this.still.addChild(this.sky, this.scenery);
    this.still.cacheAsTexture(true);
    this.back.addChild(this.still, this.grass);
    this.front.addChild(this.air);
    for (let i = 0; i < 40; i++) this.streaks.push({ x: 0, y: 0, age: 0, life: 0 });
    for (let i = 0; i < 40; i++) this.respawnStreak(this.streaks[i]!, true);
    const colors = [0xd9822b, 0xc8553d, 0xe0b43a, 0x8a9a3b];
    for (let i = 0; i < 7; i++) {
      this.leaves.push({ x: 0, y: 0, vx: 0, vy: 0, spin: 0, angle: 0, color: colors[i % colors.length]! });
      this.respawnLeaf(this.leaves[i]!, true);
    }
  }

  private respawnStreak(s: Streak, anywhere: boolean): void {
    s.x = anywhere ? YARD.minX + this.rand() * (YARD.maxX - YARD.minX) : YARD.minX - 0.5 + this.rand() * 0.5;
    s.y = 0.2 + this.rand() * (LINE_Y + 1.2);
    s.age = 0;
    s.life = 1 + this.rand() * 1.6;
  }

  private respawnLeaf(l: Leaf, anywhere: boolean): void {
    l.x = anywhere ? YARD.minX + this.rand() * (YARD.maxX - YARD.minX) : YARD.minX + this.rand() * 0.5;
    l.y = 2.5 + this.rand() * 3.5;
    l.vx = 0;
    l.vy = 0;
    l.spin = (this.rand() - 0.5) * 8;
    l.angle = this.rand() * 6;
  }

  /**
   * Draws the yard for `world` through `camera` and moves the streaks and leaves on by `dt` s (0
   * while paused) in the world's wind. `screenW` and `screenH` are the canvas' size, px.
   */
  update(world: PhysicsWorld, camera: Camera, dt: number, screenW: number, screenH: number): void {
    const key = `${screenW}x${screenH}:${camera.toScreenX(0).toFixed(2)},${camera.toScreenY(0).toFixed(2)},${camera.toScreenLength(1).toFixed(3)}`;
    if (key !== this.sceneryKey) {
      this.sceneryKey = key;
      this.sky.width = screenW;
      this.sky.height = Math.max(1, camera.toScreenY(0));
      this.drawScenery(camera, screenW, screenH);
      this.still.updateCacheTexture();
    }
    this.drawGrass(world, camera);
    this.moveAir(world, dt);
    this.drawAir(world, camera);
  }

  /** The still scenery: hills, lawn, walls, posts and the line (redrawn when the view changes). */
  private drawScenery(cam: Camera, W: number, H: number): void {
    const g = this.scenery;
    g.clear();
    const X = (x: number) => cam.toScreenX(x),
      Y = (y: number) => cam.toScreenY(y),
      S = (l: number) => cam.toScreenLength(l);
    const ground = Y(0);
    // Far hills, two layers.
    const hills = (base: number, amp: number, seed: number, color: number): void => {
      const r = seededRandom(seed);
      g.moveTo(0, ground);
      const phase = r() * 6;
      for (let x = 0; x <= W + 20; x += 20) {
        const wx = cam.toWorldX(x);
        g.lineTo(x, Y(base + amp * (0.6 * Math.sin(wx * 0.45 + phase) + 0.4 * Math.sin(wx * 1.1 + 2 * phase))));
      }
      g.lineTo(W, ground).closePath().fill({ color });
    };
    hills(1.6, 0.5, 3, 0xa9c7b5);
    hills(0.9, 0.35, 5, 0x7fa88a);
    // A hedge behind the lawn.
    g.rect(0, Y(0.55), W, ground - Y(0.55)).fill({ color: 0x4f7d4a });
    for (let x = -20; x < W + 20; x += S(0.35)) g.circle(x, Y(0.55), S(0.22)).fill({ color: 0x4f7d4a });
    // The lawn.
    g.rect(0, ground, W, H - ground).fill({ color: 0x6ea24a });
    g.rect(0, ground, W, Math.max(2, S(0.06))).fill({ color: 0x8dbd5c });
    for (let y = ground + S(0.25); y < H; y += S(0.3)) g.rect(0, y, W, Math.max(1, S(0.03))).fill({ color: 0x649644, alpha: 0.7 });
    // The house on the left: plaster, a window, a drainpipe.
    const left = X(YARD.minX);
    if (left > 0) {
      g.rect(0, 0, left, H).fill({ color: 0xe7d3b5 });
      for (let y = Y(YARD.maxY); y < ground; y += S(0.3)) g.rect(0, y, left, 1).fill({ color: 0xcdb691, alpha: 0.6 });
      g.rect(left - S(0.12), 0, S(0.12), ground).fill({ color: 0xc9b28c });
      const wx0 = Math.max(4, left - S(0.75)),
        wy0 = Y(3.6);
      if (left - wx0 > S(0.2)) {
        g.rect(wx0, wy0, left - S(0.2) - wx0, S(1.1))
          .fill({ color: 0x5b7ea3 })
          .stroke({ width: Math.max(2, S(0.06)), color: 0xffffff });
        g.moveTo((wx0 + left - S(0.2)) / 2, wy0)
          .lineTo((wx0 + left - S(0.2)) / 2, wy0 + S(1.1))
          .stroke({ width: Math.max(1, S(0.04)), color: 0xffffff });
      }
      g.rect(left, 0, Math.max(2, S(0.05)), ground).fill({ color: 0x8c7a5e });
      // On a wide screen, the back door and another window.
      if (left > S(2.4)) {
        const dx = left - S(2.1),
          dw = S(0.9),
          dh = S(2.1);
        g.rect(dx, ground - dh, dw, dh)
          .fill({ color: 0x3f6e8c })
          .stroke({ width: Math.max(2, S(0.05)), color: 0xffffff });
        g.circle(dx + dw * 0.82, ground - dh * 0.48, S(0.04)).fill({ color: 0xc8a64a });
        g.rect(dx + S(0.12), ground - dh + S(0.15), dw - S(0.24), S(0.5)).fill({ color: 0x9cc3dc });
      }
    }
    // The brick wall on the right.
    const right = X(YARD.maxX);
    if (right < W) {
      g.rect(right, 0, W - right, H).fill({ color: 0xa4553f });
      const bh = S(0.16),
        bw = S(0.42);
      let row = 0;
      for (let y = ground; y > -bh; y -= bh, row++) {
        g.rect(right, y, W - right, Math.max(1, S(0.015))).fill({ color: 0xd8c3a5, alpha: 0.8 });
        for (let x = right + (row % 2 ? bw / 2 : 0); x < W; x += bw)
          g.rect(x, y - bh, Math.max(1, S(0.015)), bh).fill({ color: 0xd8c3a5, alpha: 0.8 });
      }
      g.rect(right - Math.max(2, S(0.05)), 0, Math.max(2, S(0.05)), ground).fill({ color: 0x6e3426 });
      // Ivy up the wall's edge, and on a wide screen a wooden gate in it.
      const ivy = seededRandom(11);
      for (let k = 0; k < 40; k++) {
        const y = ground - S(3.2) * ivy() ** 1.5,
          x = right + S(0.35) * ivy() ** 2;
        g.ellipse(x, y, S(0.09), S(0.06)).fill({ color: ivy() < 0.5 ? 0x3f7a35 : 0x56953f });
      }
      if (W - right > S(1.8)) {
        const gx = right + S(0.7),
          gw = S(1),
          gh = S(1.9);
        g.rect(gx, ground - gh, gw, gh)
          .fill({ color: 0x7a5230 })
          .stroke({ width: 2, color: 0x4a2f18 });
        for (let k = 1; k < 5; k++) g.rect(gx + (gw * k) / 5 - 1, ground - gh, 2, gh).fill({ color: 0x5d3d22 });
        g.circle(gx + gw * 0.85, ground - gh * 0.5, S(0.04)).fill({ color: 0xc8a64a });
      }
    }
    // Posts and the line between them.
    const top = LINE_Y + 0.15;
    for (const px of POSTS) {
      g.rect(X(px) - S(0.06), Y(top + 0.05), S(0.12), ground - Y(top + 0.05)).fill({ color: 0x7a5a3a });
      g.rect(X(px) - S(0.06), Y(top + 0.05), S(0.04), ground - Y(top + 0.05)).fill({ color: 0x93724f });
    }
    g.moveTo(X(POSTS[0]), Y(top))
      .quadraticCurveTo(X((POSTS[0] + POSTS[1]) / 2), Y(LINE_Y - 0.1), X(POSTS[1]), Y(top))
      .stroke({ width: Math.max(1.5, S(0.025)), color: 0x3b3b3b });
  }

  /** Grass blades along the lawn's edge, bent by the wind at their tips. */
  private drawGrass(world: PhysicsWorld, cam: Camera): void {
    const g = this.grass;
    g.clear();
    const Y0 = cam.toScreenY(0),
      len = cam.toScreenLength(0.16);
    const w = this.wind;
    for (let x = YARD.minX + 0.05; x < YARD.maxX; x += 0.11) {
      windAt(world, x, 0.3, 0, world.time, w);
      const bend = Math.max(-1, Math.min(1, w[0]! / 6));
      const sx = cam.toScreenX(x + 0.03 * Math.sin(x * 17));
      const h = len * (0.7 + 0.3 * Math.sin(x * 31));
      // Two straight pieces, the upper one bent further (a curve would be cut into many on every frame).
      g.moveTo(sx, Y0 + 1)
        .lineTo(sx + bend * h * 0.2, Y0 - h * 0.55)
        .lineTo(sx + bend * h * 0.8, Y0 - h * (1 - 0.35 * Math.abs(bend)));
    }
    g.stroke({ width: Math.max(1, cam.toScreenLength(0.02)), color: 0x4e8a34 });
  }

  /** Moves the streaks with the wind, and the leaves as light flat things blown about and falling. */
  private moveAir(world: PhysicsWorld, dt: number): void {
    if (dt <= 0) return;
    const w = this.wind;
    for (const s of this.streaks) {
      windAt(world, s.x, s.y, 0, world.time, w);
      s.x += w[0]! * dt;
      s.y += w[1]! * dt;
      s.age += dt;
      // Blown past the right wall: a new one comes in on the left; faded out: a new one anywhere.
      if (s.x > YARD.maxX) this.respawnStreak(s, false);
      else if (s.age > s.life || s.x < YARD.minX - 1) this.respawnStreak(s, true);
    }
    for (const l of this.leaves) {
      windAt(world, l.x, l.y, 0, world.time, w);
      // Drag toward the wind at a rate of 2 /s, falling at about 0.6 m/s in still air.
      l.vx += (w[0]! - l.vx) * Math.min(1, 2 * dt);
      l.vy += (w[1]! - 0.6 - l.vy) * Math.min(1, 2 * dt);
      l.x += l.vx * dt;
      l.y += l.vy * dt;
      l.angle += l.spin * dt * (0.3 + Math.min(2, Math.abs(l.vx) / 2));
      if (l.y < 0.04) {
        l.y = 0.04;
        l.vy = 0;
        l.vx *= 0.5;
      }
      if (l.x > YARD.maxX - 0.05 || (l.y <= 0.04 && this.rand() < dt * 0.15)) this.respawnLeaf(l, false);
    }
  }

  private drawAir(world: PhysicsWorld, cam: Camera): void {
    const g = this.air;
    g.clear();
    const w = this.wind;
    let drawn = 0;
    for (const s of this.streaks) {
      windAt(world, s.x, s.y, 0, world.time, w);
      const speed = Math.hypot(w[0]!, w[1]!);
      if (speed < 0.4) continue;
      // A streak shows 0.25 s of the air's travel; it fades in and out over its life.
      const fade = Math.sin((Math.PI * s.age) / s.life);
      const alpha = Math.min(0.55, 0.1 * speed) * fade;
      if (alpha < 0.02) continue;
      const x0 = cam.toScreenX(s.x),
        y0 = cam.toScreenY(s.y),
        x1 = cam.toScreenX(s.x - 0.25 * w[0]!),
        y1 = cam.toScreenY(s.y - 0.25 * w[1]!);
      g.moveTo(x0, y0)
        .lineTo(x1, y1)
        .stroke({ width: Math.max(1, cam.toScreenLength(0.025)), color: 0xffffff, alpha, cap: 'round' });
      drawn++;
    }
    this.streaksDrawn = drawn;
    const r = cam.toScreenLength(0.07);
    for (const l of this.leaves) {
      const x = cam.toScreenX(l.x),
        y = cam.toScreenY(l.y);
      const c = Math.cos(l.angle),
        sn = Math.sin(l.angle);
      // A leaf: an ellipse turned by its angle, squashed as it spins (seen edge-on part of the time).
      const squash = 0.35 + 0.65 * Math.abs(Math.cos(l.angle * 0.7));
      const pts: number[] = [];
      for (let k = 0; k < 10; k++) {
        const a = (2 * Math.PI * k) / 10;
        const ex = r * Math.cos(a),
          ey = r * 0.45 * squash * Math.sin(a);
        pts.push(x + ex * c - ey * sn, y + ex * sn + ey * c);
      }
      g.poly(pts).fill({ color: l.color });
    }
  }

  destroy(): void {
    this.back.destroy({ children: true });
    this.front.destroy({ children: true });
  }
}
