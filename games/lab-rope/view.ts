/**
 * Draws a level of the rope lab: the room (a papered wall, a floor of boards, brick side walls and the
 * beam the ropes hang from), the basket and the blocks, the stars, the ropes and the ball.
 *
 * A rope is drawn as a thick twisted cord: a smooth curve (uniform Catmull-Rom) through its points, in
 * a dark outline, a hemp body, short diagonal strokes for the twist of its strands and a light edge.
 * Where a link is gone (a cut), the curve ends there, so a cut rope is two ropes, and each cut end is
 * drawn frayed. Drawing only.
 */
import { isAlive, type PhysicsWorld, slotOf } from '@bitphysics/physics';
import type { Camera } from '@bitphysics/render-pixi';
import { Container, Graphics, Sprite, Texture } from 'pixi.js';
import { CUT_END_TRIM, trimPolyline } from './cut';
import { BALL_RADIUS, type Level, type RopePiece, roomHalfWidth, WALL } from './scene';

/** Rope thickness, m (drawn at least 4 px). */
export const ROPE_WIDTH = 0.085;

/** A vertical gradient (CSS colours at stops in [0, 1]) as a 1 x 256 texture. */
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

/** A glossy red ball, 128 px, drawn with radial gradients. */
function ballTexture(): Texture {
  const s = 128;
  const c = document.createElement('canvas');
  c.width = s;
  c.height = s;
  const g = c.getContext('2d')!;
  const body = g.createRadialGradient(s * 0.38, s * 0.34, s * 0.05, s * 0.5, s * 0.5, s * 0.5);
  body.addColorStop(0, '#ff8a7a');
  body.addColorStop(0.45, '#e2403a');
  body.addColorStop(1, '#8e1c22');
  g.fillStyle = body;
  g.beginPath();
  g.arc(s / 2, s / 2, s / 2 - 1, 0, 2 * Math.PI);
  g.fill();
  // A band round it, and a highlight.
  g.strokeStyle = 'rgba(255, 236, 200, 0.75)';
  g.lineWidth = s * 0.07;
  g.beginPath();
  g.ellipse(s / 2, s / 2, s * 0.46, s * 0.16, -0.5, 0, 2 * Math.PI);
  g.stroke();
  const hi = g.createRadialGradient(s * 0.34, s * 0.3, 0, s * 0.34, s * 0.3, s * 0.2);
  hi.addColorStop(0, 'rgba(255,255,255,0.9)');
  hi.addColorStop(1, 'rgba(255,255,255,0)');
  g.fillStyle = hi;
  g.fillRect(0, 0, s, s);
  return Texture.from(c);
}

/** The smooth curve through points (x, y interleaved, screen px): `steps` points a span, uniform Catmull-Rom. */
function smooth(pts: number[], steps: number): number[] {
  const n = pts.length / 2;
  if (n < 2) return pts.slice();
  const out: number[] = [pts[0]!, pts[1]!];
  for (let i = 0; i + 1 < n; i++) {
    const i0 = Math.max(0, i - 1),
      i3 = Math.min(n - 1, i + 2);
    for (let k = 1; k <= steps; k++) {
      const t = k / steps,
        t2 = t * t,
        t3 = t2 * t;
      for (let d = 0; d < 2; d++) {
        const p0 = pts[2 * i0 + d]!,
          p1 = pts[2 * i + d]!,
          p2 = pts[2 * (i + 1) + d]!,
          p3 = pts[2 * i3 + d]!;
        out.push(0.5 * (2 * p1 + (p2 - p0) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t2 + (3 * p1 - p0 - 3 * p2 + p3) * t3));
      }
    }
  }
  return out;
}

/** How long a caught star's pop lasts, s: it swells, spins and fades in a widening ring. */
export const STAR_POP_S = 0.5;

/** The level's drawing: `container` goes into the scene; call `update` every frame. */
export class RopeView {
  readonly container = new Container({ label: 'rope level' });
  /** Rope pieces drawn in the last frame (one a whole rope; a cut adds one). */
  pieces = 0;
  private readonly wall = new Sprite(
    gradient([
      [0, '#1d2b44'],
      [1, '#3e5878'],
    ]),
  );
  private readonly room = new Graphics({ label: 'room' });
  private readonly cords = new Graphics({ label: 'ropes' });
  private readonly shadow = new Graphics({ label: 'shadow' });
  private readonly ballSprite = Object.assign(new Sprite(ballTexture()), { label: 'ball' });
  private readonly front = new Graphics({ label: 'front' });
  /**
   * The basket's front, drawn over the ball: a ball in the basket shows through the wicker below
   * the rim instead of sitting on top of the whole basket drawn behind it (on the win screen it read
   * as resting on the rim).
   */
  private readonly basketFront = new Graphics({ label: 'basket front' });
  /** The basket front's box as last drawn: x, y, width, height, px. */
  readonly frontBox = [0, 0, 0, 0];
  private roomKey = '';

  /** The wall and the room, drawn into one texture when the view changes (one quad a frame, not their many shapes). */
  private readonly still = new Container({ label: 'still' });

  constructor() {
    this.ballSprite.anchor.set(0.5);
    this.still.addChild(this.wall, this.room);
    this.still.cacheAsTexture(true);
    this.container.addChild(this.still, this.shadow, this.cords, this.ballSprite, this.basketFront, this.front);
  }

  /**
   * Draws `level` with its ropes and ball at interpolation factor `alpha`; `caught` says which stars
   * are gone, `time` (s) turns the stars. `W` x `H` is the canvas, px. `caughtAt` (s, on `time`'s
   * clock; NaN while not caught) times each caught star's pop (STAR_POP_S). A star `lit` (the cue
   * to cut: a cut now would fly the ball through it) glows bright in a pulsing ring.
   */
  update(
    world: PhysicsWorld,
    level: Level,
    ropes: readonly RopePiece[],
    ball: number,
    caught: readonly boolean[],
    cam: Camera,
    alpha: number,
    time: number,
    W: number,
    H: number,
    caughtAt: readonly number[] = [],
    lit: readonly boolean[] = [],
  ): void {
    const key = `${level.name}:${W}x${H}:${cam.toScreenX(0).toFixed(2)},${cam.toScreenY(0).toFixed(2)},${cam.toScreenLength(1).toFixed(4)}`;
    if (key !== this.roomKey) {
      this.roomKey = key;
      this.wall.width = W;
      this.wall.height = H;
      this.drawRoom(level, cam, W, H);
      this.still.updateCacheTexture();
    }
    const P = world.components.Position,
      O = world.components.PreviousPosition;
    const X = (e: number) => cam.toScreenX(O.x[e]! + (P.x[e]! - O.x[e]!) * alpha),
      Y = (e: number) => cam.toScreenY(O.y[e]! + (P.y[e]! - O.y[e]!) * alpha);
    // Ropes.
    const g = this.cords;
    g.clear();
    this.pieces = 0;
    const be = slotOf(ball);
    const bx = X(be),
      by = Y(be);
    const width = Math.max(4, cam.toScreenLength(ROPE_WIDTH));
    for (const rope of ropes) {
      // Points: the anchor, the bodies, the ball; link k joins point k and k + 1.
      const xs: number[] = [cam.toScreenX(rope.anchor[0]), cam.toScreenY(rope.anchor[1])];
      const pieces: { pts: number[]; cutStart: boolean; cutEnd: boolean }[] = [];
      let cutStart = false;
      for (let k = 0; k < rope.links.length; k++) {
        const next = k < rope.bodies.length ? slotOf(rope.bodies[k]!) : be;
        const nx = k < rope.bodies.length ? X(next) : bx,
          ny = k < rope.bodies.length ? Y(next) : by;
        if (!isAlive(world, rope.links[k]!)) {
          pieces.push({ pts: xs.splice(0), cutStart, cutEnd: true });
          cutStart = true;
        }
        // The ball's link ends at the ball's surface, not its centre.
        if (k === rope.links.length - 1) {
          const px = xs.length >= 2 ? xs[xs.length - 2]! : nx,
            py = xs.length >= 2 ? xs[xs.length - 1]! : ny;
          const d = Math.hypot(nx - px, ny - py),
            r = cam.toScreenLength(BALL_RADIUS) * 0.85;
          if (d > r && xs.length >= 2) xs.push(nx - ((nx - px) / d) * r, ny - ((ny - py) / d) * r);
        } else xs.push(nx, ny);
      }
      pieces.push({ pts: xs, cutStart, cutEnd: false });
      // A cut end is drawn short of its body (CUT_END_TRIM), so the cut shows as a gap at once.
      const trim = CUT_END_TRIM * width;
      for (const piece of pieces)
        if (piece.pts.length >= 4)
          this.drawCord(trimPolyline(piece.pts, piece.cutStart ? trim : 0, piece.cutEnd ? trim : 0), width, piece.cutStart, piece.cutEnd);
    }
    // Ball, and its shadow on the floor: wider and fainter the higher it is.
    const r = cam.toScreenLength(BALL_RADIUS);
    const height = Math.max(0, O.y[be]! + (P.y[be]! - O.y[be]!) * alpha - BALL_RADIUS);
    this.shadow.clear();
    this.shadow
      .ellipse(bx, cam.toScreenY(0) - 1, r * (1 + 0.15 * height), r * 0.25 * (1 + 0.05 * height))
      .fill({ color: 0x000000, alpha: 0.35 * Math.exp(-height / 3) });
    this.ballSprite.position.set(bx, by);
    this.ballSprite.width = 2 * r;
    this.ballSprite.height = 2 * r;
    this.ballSprite.rotation = world.components.Angle.value[be]! * -1;
    this.drawBasketFront(level, cam);
    // Stars, turning and pulsing; a caught one pops (grows, spins and fades in a widening ring),
    // then is gone.
    const f = this.front;
    f.clear();
    this.popping = 0;
    level.stars.forEach(([sx, sy], i) => {
      const x = cam.toScreenX(sx),
        y = cam.toScreenY(sy);
      let R = cam.toScreenLength(0.22) * (1 + 0.08 * Math.sin(3 * time + i)),
        a0 = 0.4 * Math.sin(time + i),
        opacity = 1;
      if (caught[i]) {
        const u = (time - (caughtAt[i] ?? Number.NaN)) / STAR_POP_S;
        if (!(u >= 0 && u < 1)) return;
        this.popping++;
        // The ring widens from the star to three times its size; the star swells to twice and fades.
        f.circle(x, y, R * (1 + 2 * u)).stroke({ width: Math.max(2, R * 0.25 * (1 - u)), color: 0xffe27a, alpha: 1 - u });
        R *= 1 + u;
        a0 += 4 * u;
        opacity = 1 - u * u;
      } else if (lit[i]) {
        // Lit: a bright halo and a ring that beats, seen from across the room.
        const beat = 0.5 + 0.5 * Math.sin(8 * time);
        f.circle(x, y, R * 1.6).fill({ color: 0xffe27a, alpha: 0.22 });
        f.circle(x, y, R * (1.9 + 0.3 * beat)).stroke({ width: Math.max(3, R * 0.28), color: 0xffd23f, alpha: 0.95 });
        f.circle(x, y, R * (2.5 + 0.5 * beat)).stroke({ width: Math.max(2, R * 0.12), color: 0xffe27a, alpha: 0.5 * (1 - beat) });
        R *= 1.25;
      } else f.circle(x, y, R * 1.6).fill({ color: 0xffe27a, alpha: 0.18 });
      const pts: number[] = [];
      for (let k = 0; k < 10; k++) {
        const a = -Math.PI / 2 + (Math.PI * k) / 5 + a0;
        const rr = k % 2 ? R * 0.45 : R;
        pts.push(x + rr * Math.cos(a), y + rr * Math.sin(a));
      }
      f.poly(pts)
        .fill({ color: 0xffd23f, alpha: opacity })
        .stroke({ width: Math.max(1.5, R * 0.12), color: 0xb07a00, alpha: opacity });
    });
  }
  /** Caught stars drawn popping in the last frame. */
  popping = 0;

  /**
   * The basket's front over the ball: the wicker see-through (a ball inside shows dimmed behind it),
   * its weave and the rim band solid, on the room's basket (drawRoom) in the same place.
   */
  private drawBasketFront(level: Level, cam: Camera): void {
    const g = this.basketFront;
    g.clear();
    const X = (x: number) => cam.toScreenX(x),
      Y = (y: number) => cam.toScreenY(y),
      S = (l: number) => cam.toScreenLength(l);
    const [bx, by] = level.basket,
      half = level.basketWidth / 2 + WALL;
    const l = X(bx - half),
      r = X(bx + half),
      t = Y(by + level.basketDepth),
      b = Y(by);
    g.poly([l, t, r, t, r - S(0.06), b, l + S(0.06), b])
      .fill({ color: 0xb9853f, alpha: 0.55 })
      .stroke({ width: 2, color: 0x6e4a1c });
    for (let y = t + S(0.12); y < b; y += S(0.12)) g.moveTo(l + S(0.03), y).lineTo(r - S(0.03), y);
    g.stroke({ width: Math.max(1, S(0.025)), color: 0x8a5f26, alpha: 0.8 });
    g.rect(l - S(0.03), t - S(0.05), r - l + S(0.06), S(0.1)).fill({ color: 0x8a5f26 });
    this.frontBox[0] = l - S(0.03);
    this.frontBox[1] = t - S(0.05);
    this.frontBox[2] = r - l + S(0.06);
    this.frontBox[3] = b - t + S(0.05);
  }

  /** A twisted cord through `pts` (screen px), frayed at an end that was cut. */
  private drawCord(pts: number[], width: number, frayStart: boolean, frayEnd: boolean): void {
    const g = this.cords;
    const c = smooth(pts, 4);
    this.pieces++;
    const path = (): void => {
      g.moveTo(c[0]!, c[1]!);
      for (let i = 2; i < c.length; i += 2) g.lineTo(c[i]!, c[i + 1]!);
    };
    path();
    g.stroke({ width: width + 2.5, color: 0x4a3218, cap: 'round', join: 'round' });
    path();
    g.stroke({ width, color: 0xc9a064, cap: 'round', join: 'round' });
    // The twist: a short diagonal stroke every 1.3 widths along the cord.
    const step = width * 1.3;
    let carry = 0;
    for (let i = 2; i < c.length; i += 2) {
      const x0 = c[i - 2]!,
        y0 = c[i - 1]!,
        dx = c[i]! - x0,
        dy = c[i + 1]! - y0,
        len = Math.hypot(dx, dy);
      if (len === 0) continue;
      const ux = dx / len,
        uy = dy / len;
      let s = step - carry;
      while (s <= len) {
        const x = x0 + ux * s,
          y = y0 + uy * s,
          h = width * 0.42;
        g.moveTo(x - uy * h - ux * h * 0.6, y + ux * h - uy * h * 0.6).lineTo(x + uy * h + ux * h * 0.6, y - ux * h + uy * h * 0.6);
        s += step;
      }
      carry = len - (s - step);
    }
    g.stroke({ width: Math.max(1, width * 0.2), color: 0x7c5a2c, cap: 'round' });
    // A light edge along one side.
    g.moveTo(c[0]!, c[1]!);
    for (let i = 2; i < c.length; i += 2) g.lineTo(c[i]! - width * 0.18, c[i + 1]! - width * 0.18);
    g.stroke({ width: Math.max(1, width * 0.18), color: 0xf0d49c, alpha: 0.7, cap: 'round' });
    if (frayStart) this.fray(c[0]!, c[1]!, c[0]! - c[2]!, c[1]! - c[3]!, width);
    if (frayEnd) {
      const n = c.length;
      this.fray(c[n - 2]!, c[n - 1]!, c[n - 2]! - c[n - 4]!, c[n - 1]! - c[n - 3]!, width);
    }
  }

  /** Loose fibres at a cut end (x, y), spreading along direction (dx, dy). */
  private fray(x: number, y: number, dx: number, dy: number, width: number): void {
    const len = Math.hypot(dx, dy) || 1;
    const ux = dx / len,
      uy = dy / len;
    const g = this.cords;
    for (const a of [-0.6, -0.2, 0.25, 0.65]) {
      const c = Math.cos(a),
        s = Math.sin(a);
      const fx = ux * c - uy * s,
        fy = ux * s + uy * c;
      g.moveTo(x, y).lineTo(x + fx * width * 1.1, y + fy * width * 1.1);
    }
    g.stroke({ width: Math.max(1, width * 0.25), color: 0xd9b67c, cap: 'round' });
  }

  /** The still room: wallpaper, floor, walls, beam and hooks, basket and blocks. */
  private drawRoom(level: Level, cam: Camera, W: number, H: number): void {
    const g = this.room;
    g.clear();
    const X = (x: number) => cam.toScreenX(x),
      Y = (y: number) => cam.toScreenY(y),
      S = (l: number) => cam.toScreenLength(l);
    // Wallpaper stripes.
    const room = roomHalfWidth(level);
    for (let x = -room - 1.5; x <= room + 1.5; x += 0.5) g.rect(X(x), 0, Math.max(1, S(0.16)), H).fill({ color: 0xffffff, alpha: 0.035 });
    // A level on the Moon (low gravity): a large pale moon, its craters, on the wallpaper's top
    // right, under the beam, so the level does not look like any other.
    if ((level.gravityScale ?? 1) < 0.5) {
      const top = Math.max(...level.anchors.map((a) => a[1]));
      const mx = X(room - 0.75),
        my = Y(top - 0.75),
        mr = S(0.45);
      g.circle(mx, my, mr * 1.5).fill({ color: 0xf3ecc8, alpha: 0.08 });
      g.circle(mx, my, mr).fill({ color: 0xe8e1bd, alpha: 0.55 });
      for (const [cx, cy, cr] of [
        [-0.3, -0.2, 0.22],
        [0.35, 0.15, 0.16],
        [-0.05, 0.45, 0.12],
      ] as const)
        g.circle(mx + cx * mr, my + cy * mr, cr * mr).fill({ color: 0xb9b294, alpha: 0.45 });
    }
    // The floor: boards.
    const floor = Y(0);
    g.rect(0, floor, W, H - floor).fill({ color: 0x6b4a2f });
    g.rect(0, floor, W, Math.max(2, S(0.05))).fill({ color: 0x9a6e45 });
    for (let y = floor + S(0.22); y < H; y += S(0.22)) g.rect(0, y, W, 1).fill({ color: 0x4a321e, alpha: 0.8 });
    // Side walls: brick.
    for (const side of [-1, 1]) {
      const inner = X(side * room);
      const x0 = side < 0 ? 0 : inner,
        x1 = side < 0 ? inner : W;
      if (x1 <= x0) continue;
      g.rect(x0, 0, x1 - x0, floor).fill({ color: 0x7d3f2e });
      const bh = S(0.18),
        bw = S(0.45);
      let row = 0;
      for (let y = floor; y > -bh; y -= bh, row++) {
        g.rect(x0, y, x1 - x0, 1).fill({ color: 0x4b2219 });
        for (let x = (side < 0 ? inner : inner) + (row % 2 ? bw / 2 : 0) * side; side < 0 ? x > x0 : x < x1; x += side * bw)
          g.rect(x, y - bh, 1, bh).fill({ color: 0x4b2219 });
      }
      g.rect(side < 0 ? inner - 3 : inner, 0, 3, floor).fill({ color: 0x3a1a12, alpha: 0.6 });
      // On a wide screen the walls show more: a window onto the night in each, the moon in the left one.
      if (x1 - x0 > S(1.8)) {
        const w = S(1.1),
          h = S(1.6),
          wx = (x0 + x1) / 2 - w / 2,
          wy = Y(6.6);
        g.rect(wx - S(0.08), wy - S(0.08), w + S(0.16), h + S(0.16)).fill({ color: 0x5a3b22 });
        g.rect(wx, wy, w, h).fill({ color: 0x14284a });
        for (let k = 0; k < 6; k++)
          g.circle(wx + w * ((k * 0.37 + 0.13) % 1), wy + h * ((k * 0.61 + 0.2) % 1), Math.max(1, S(0.02))).fill({ color: 0xffffff });
        if (side < 0) g.circle(wx + w * 0.68, wy + h * 0.28, S(0.16)).fill({ color: 0xf3ecc8 });
        g.rect(wx + w / 2 - S(0.03), wy, S(0.06), h).fill({ color: 0x5a3b22 });
        g.rect(wx, wy + h / 2 - S(0.03), w, S(0.06)).fill({ color: 0x5a3b22 });
      }
    }
    // The beam the ropes hang from, and a brass ring at each anchor.
    const top = Math.max(...level.anchors.map((a) => a[1]));
    g.rect(X(-room), Y(top + 0.45), X(room) - X(-room), S(0.35)).fill({ color: 0x5a3b22 });
    g.rect(X(-room), Y(top + 0.45), X(room) - X(-room), Math.max(2, S(0.06))).fill({ color: 0x7b5433 });
    for (const [ax, ay] of level.anchors) {
      g.rect(X(ax) - S(0.03), Y(top + 0.1), S(0.06), Y(ay) - Y(top + 0.1)).fill({ color: 0x8d8d8d });
      g.circle(X(ax), Y(ay), S(0.09)).stroke({ width: Math.max(2, S(0.04)), color: 0xd4a537 });
    }
    // Blocks: stone.
    for (const b of level.blocks ?? []) {
      const x0 = X(b.at[0] - b.half[0]),
        y0 = Y(b.at[1] + b.half[1]);
      g.rect(x0, y0, S(2 * b.half[0]), S(2 * b.half[1]))
        .fill({ color: 0x8a8f98 })
        .stroke({ width: 2, color: 0x4d525a });
      for (let y = y0 + S(0.3); y < Y(b.at[1] - b.half[1]); y += S(0.3)) g.rect(x0, y, S(2 * b.half[0]), 1).fill({ color: 0x5d626b });
    }
    // The basket: wicker, open at the top.
    const [bx, by] = level.basket,
      half = level.basketWidth / 2 + WALL,
      depth = level.basketDepth;
    const l = X(bx - half),
      r = X(bx + half),
      t = Y(by + depth),
      b = Y(by);
    // The open mouth, seen a little from above: a dark inside behind a back rim, its lower half hidden
    // by the basket's side drawn over it (drawn side-on alone, a wide basket read as a shut crate).
    const mouth = Math.min(S(0.3), (b - t) * 0.45);
    g.ellipse((l + r) / 2, t, (r - l) / 2 + S(0.02), mouth)
      .fill({ color: 0x3a2610 })
      .stroke({ width: Math.max(2, S(0.05)), color: 0x8a5f26 });
    g.poly([l, t, r, t, r - S(0.06), b, l + S(0.06), b])
      .fill({ color: 0xb9853f })
      .stroke({ width: 2, color: 0x6e4a1c });
    for (let y = t + S(0.12); y < b; y += S(0.12)) g.moveTo(l + S(0.03), y).lineTo(r - S(0.03), y);
    g.stroke({ width: Math.max(1, S(0.025)), color: 0x8a5f26 });
    for (let x = l + S(0.1); x < r; x += S(0.14)) g.moveTo(x, t).lineTo(x, b);
    g.stroke({ width: Math.max(1, S(0.018)), color: 0xd9a65a, alpha: 0.6 });
    g.rect(l - S(0.03), t - S(0.05), r - l + S(0.06), S(0.1)).fill({ color: 0x8a5f26 });
  }

  destroy(): void {
    this.container.destroy({ children: true });
  }
}
