/**
 * Catapult, the effects of a hit (drawing only, no physics): dust that puffs where something lands,
 * splinters of wood, shards of glass and chips of stone that fly and fall, score popups that rise
 * over a piece as it falls, and a camera shake that dies away. Positions are in the scene's metres,
 * so the effects move with the camera; sizes of dust and chips are in metres too.
 */
import type { Camera } from '@bitphysics/render-pixi';
import { type Container, Graphics, Text } from 'pixi.js';

/** What a burst throws out: grey-brown dust, wood splinters, glass shards, stone chips or confetti (a level cleared). */
export type DebrisKind = 'dust' | 'wood' | 'glass' | 'stone' | 'confetti';

/** Colours of each kind's bits (picked in turn). */
const COLORS: Record<DebrisKind, readonly number[]> = {
  dust: [0xcbb89a, 0xb39f80, 0xd9cbb2],
  wood: [0xc08a4e, 0x9a6232, 0xe0b27a],
  glass: [0xd6f3ff, 0xa8dcef, 0xffffff],
  stone: [0x8b929c, 0x6f757e, 0xb3b8bf],
  confetti: [0xffd166, 0xef476f, 0x06d6a0, 0x118ab2, 0xffffff],
};

/** Most bits alive at once (a new burst replaces the oldest past it). */
const MAX_BITS = 400;

/** Seconds a dust puff lives; a splinter, shard or chip lives up to CHIP_LIFE. */
const DUST_LIFE = 0.9,
  CHIP_LIFE = 1.6;

/**
 * The bits in flight (structure of arrays): position and velocity (m, m/s), spin (rad, rad/s), size
 * (m), age and life (s), colour and kind (`dust`: 1 dust, 2 confetti, 0 a chip).
 */
class Bits {
  readonly x = new Float64Array(MAX_BITS);
  readonly y = new Float64Array(MAX_BITS);
  readonly vx = new Float64Array(MAX_BITS);
  readonly vy = new Float64Array(MAX_BITS);
  readonly a = new Float64Array(MAX_BITS);
  readonly w = new Float64Array(MAX_BITS);
  readonly size = new Float64Array(MAX_BITS);
  readonly age = new Float64Array(MAX_BITS);
  readonly life = new Float64Array(MAX_BITS);
  readonly color = new Uint32Array(MAX_BITS);
  readonly dust = new Uint8Array(MAX_BITS);
  count = 0;
  /** Index of the next slot to overwrite once full (the oldest). */
  next = 0;
}

/** A score popup: its text object, where it started (m), its age (s), its points (NaN for a label that is not "+N") and colour. */
interface Popup {
  text: Text;
  x: number;
  y: number;
  age: number;
  points: number;
  color: number;
}

/** How long a popup shows, s, and how far it rises, m. */
const POPUP_LIFE = 1.1,
  POPUP_RISE = 1.4;
/** A popup takes in the points of another near it while under this share of its life (before it fades). */
const MERGE_AGE = 0.6;
/**
 * A popup's type size, px on the screen (the stage is drawn 1:1 in CSS px): its digits, about 0.7 em,
 * stand some 17 px tall at both a desktop and a phone size (at 18 px they were 6 to 13 px tall and
 * hard to read over the scene). Two popups one line (`near` / 2, 40 px in main.ts) apart still clear.
 */
export const POPUP_FONT = 24;
/** The share of POPUP_RISE a popup has risen at `t` of its life (0 to 1): fast, then slowing. */
const rise = (t: number): number => 1 - (1 - t) * (1 - t);

/** The effects layer: add `graphics` and `popups` to the stage, call `update` once a frame and `draw` after. */
export class Effects {
  /** Dust, splinters, shards and chips. */
  readonly graphics = new Graphics({ label: 'debris' });
  /** The score popups' texts. */
  readonly popups: Container;
  private readonly bits = new Bits();
  private readonly live: Popup[] = [];
  private readonly spare: Text[] = [];
  private shakePx = 0;
  private seed = 1;
  /**
   * The ground's height (m) at x (m), where falling chips and confetti come to rest: 0 (flat
   * ground) unless the game sets its level's surface.
   */
  surface: (x: number) => number = () => 0;

  /** `popups` is the container the popup texts go in (over the scene). */
  constructor(popups: Container) {
    this.popups = popups;
  }

  /** A pseudo-random number in [0, 1) (a fixed sequence, so runs look alike). */
  private rand(): number {
    this.seed = (this.seed * 1103515245 + 12345) >>> 0;
    return this.seed / 2 ** 32;
  }

  /**
   * Throws out `count` bits of `kind` from (x, y), m, at up to `speed` m/s, mostly upward and along
   * (nx, ny) (a unit direction, the side they fly out of); dust also puffs a few grains, slower.
   */
  burst(kind: DebrisKind, x: number, y: number, count: number, speed: number, nx = 0, ny = 1): void {
    const b = this.bits,
      colors = COLORS[kind];
    for (let i = 0; i < count; i++) {
      let k: number;
      if (b.count < MAX_BITS) k = b.count++;
      else {
        k = b.next;
        b.next = (b.next + 1) % MAX_BITS;
      }
      const dust = kind === 'dust',
        confetti = kind === 'confetti';
      const ang = Math.atan2(ny, nx) + (this.rand() - 0.5) * (dust || confetti ? 2.6 : 2.0);
      const v = speed * (dust ? 0.25 + 0.35 * this.rand() : 0.35 + 0.65 * this.rand());
      b.x[k] = x + (this.rand() - 0.5) * 0.2;
      b.y[k] = y + (this.rand() - 0.5) * 0.2;
      b.vx[k] = v * Math.cos(ang);
      b.vy[k] = v * Math.sin(ang) + (dust ? 0.3 : 0);
      b.a[k] = this.rand() * Math.PI;
      b.w[k] = (this.rand() - 0.5) * 20;
      b.size[k] = dust ? 0.18 + 0.22 * this.rand() : kind === 'wood' || confetti ? 0.07 + 0.09 * this.rand() : 0.04 + 0.06 * this.rand();
      b.age[k] = 0;
      b.life[k] = dust ? DUST_LIFE * (0.6 + 0.4 * this.rand()) : CHIP_LIFE * (confetti ? 1.6 : 1) * (0.5 + 0.5 * this.rand());
      b.color[k] = colors[i % colors.length]!;
      b.dust[k] = dust ? 1 : confetti ? 2 : 0;
    }
  }

  /**
   * The least height (m) of any chip, splinter or bit of confetti over the surface under it (see
   * `surface`; negative when one is under the ground), Infinity when there is none (dust, which
   * drifts, is not counted).
   */
  lowestOverGround(): number {
    const b = this.bits;
    let low = Number.POSITIVE_INFINITY;
    for (let k = 0; k < b.count; k++) if (b.dust[k] !== 1) low = Math.min(low, b.y[k]! - this.surface(b.x[k]!));
    return low;
  }

  /**
   * A score popup ("+100") rising from (x, y), m, in `color` (0xRRGGBB). Popups must each read:
   * a "+N" within `near` m (horizontally, and 2 `near` vertically) of a young "+M" popup in the same
   * colour (under MERGE_AGE of its life) is added to it ("+M+N", its rise and pop starting again),
   * and any other popup that would overlap a live one starts one line (`near` / 2 m) above the
   * highest of them. `near` is about a popup's width in metres on the screen (default 1.5 m).
   * @throws RangeError if near is not a finite length > 0.
   */
  popup(x: number, y: number, label: string, color = 0xffe066, near = 1.5): void {
    if (!(Number.isFinite(near) && near > 0)) throw new RangeError(`Effects.popup: near must be a finite length > 0 m, got ${near}`);
    const m = /^\+(\d+)$/.exec(label);
    const points = m ? Number(m[1]) : Number.NaN;
    const close = this.live.filter((p) => Math.abs(p.x - x) < near && Math.abs(p.y - y) < 2 * near);
    if (!Number.isNaN(points)) {
      const mate = close.find((p) => !Number.isNaN(p.points) && p.age < MERGE_AGE * POPUP_LIFE && p.color === color);
      if (mate) {
        // It pops again from where it is drawn now, and rises on from there.
        mate.points += points;
        mate.text.text = `+${mate.points}`;
        mate.y += POPUP_RISE * rise(mate.age / POPUP_LIFE);
        mate.age = 0;
        return;
      }
    }
    // Over the highest popup near by (where it is drawn now), so the two do not overlap.
    for (const p of close) y = Math.max(y, p.y + POPUP_RISE * rise(p.age / POPUP_LIFE) + near / 2);
    const text =
      this.spare.pop() ??
      new Text({
        text: '',
        style: {
          fill: 0xffffff,
          fontSize: POPUP_FONT,
          fontFamily: 'sans-serif',
          fontWeight: 'bold',
          stroke: { color: 0x000000, width: 5, join: 'round' },
        },
      });
    text.anchor.set(0.5);
    text.text = label;
    text.style.fill = color;
    text.visible = true;
    this.popups.addChild(text);
    this.live.push({ text, x, y, age: 0, points, color });
  }

  /** Shakes the camera by up to `px` screen pixels (the larger of this and the shake already running). */
  shake(px: number): void {
    this.shakePx = Math.max(this.shakePx, Math.min(px, 14));
  }

  /** The camera's shake offset now, screen px: [dx, dy]. */
  shakeOffset(): [number, number] {
    const s = this.shakePx;
    if (s < 0.3) return [0, 0];
    return [(this.rand() - 0.5) * 2 * s, (this.rand() - 0.5) * 2 * s];
  }

  /** Advances the bits, popups and shake by `dt` s under gravity `g` (m/s^2, downward). */
  update(dt: number, g: number): void {
    const b = this.bits;
    for (let k = 0; k < b.count; k++) {
      b.age[k] = b.age[k]! + dt;
      if (b.dust[k] === 1) {
        // Dust drifts up and slows (air drag).
        const damp = Math.exp(-3 * dt);
        b.vx[k] = b.vx[k]! * damp;
        b.vy[k] = b.vy[k]! * damp + 0.4 * dt;
      } else {
        if (b.dust[k] === 2) {
          // Confetti flutters down: strong drag, a slow fall.
          const damp = Math.exp(-2.5 * dt);
          b.vx[k] = b.vx[k]! * damp;
          b.vy[k] = (b.vy[k]! - g * dt) * damp;
        } else b.vy[k] = b.vy[k]! - g * dt;
        // One flying sideways into a step of the ground (a pit's wall, a hill's side) stops
        // against it and drops, not passing into the earth beyond.
        if (b.vx[k] !== 0 && b.y[k]! < this.surface(b.x[k]! + b.vx[k]! * dt)) b.vx[k] = 0;
        // A chip or a bit of confetti that reaches the ground where it is going (a hill's top, a
        // pit's floor or its lip) lies there, not falling on through the earth on a phone's screen.
        if (b.y[k]! + b.vy[k]! * dt < this.surface(b.x[k]! + b.vx[k]! * dt) + 0.02) {
          b.vy[k] = 0;
          b.vx[k] = 0;
          b.w[k] = 0;
        }
      }
      b.x[k] = b.x[k]! + b.vx[k]! * dt;
      b.y[k] = b.y[k]! + b.vy[k]! * dt;
      b.a[k] = b.a[k]! + b.w[k]! * dt;
    }
    // Drop the dead bits (swap with the last).
    for (let k = 0; k < b.count; ) {
      if (b.age[k]! < b.life[k]!) {
        k++;
        continue;
      }
      const last = --b.count;
      for (const arr of [b.x, b.y, b.vx, b.vy, b.a, b.w, b.size, b.age, b.life, b.color, b.dust]) arr[k] = arr[last]!;
      if (b.next >= b.count) b.next = 0;
    }
    for (let i = this.live.length - 1; i >= 0; i--) {
      const p = this.live[i]!;
      p.age += dt;
      if (p.age < POPUP_LIFE) continue;
      p.text.visible = false;
      this.popups.removeChild(p.text);
      this.spare.push(p.text);
      this.live.splice(i, 1);
    }
    this.shakePx *= Math.exp(-9 * dt);
  }

  /** Draws the bits and places the popups for camera `cam`. */
  draw(cam: Camera): void {
    const g = this.graphics,
      b = this.bits;
    g.clear();
    for (let k = 0; k < b.count; k++) {
      const t = b.age[k]! / b.life[k]!;
      const x = cam.toScreenX(b.x[k]!),
        y = cam.toScreenY(b.y[k]!);
      if (b.dust[k] === 1) {
        const r = cam.toScreenLength(b.size[k]! * (0.6 + 1.4 * t));
        g.circle(x, y, r).fill({ color: b.color[k]!, alpha: 0.55 * (1 - t) });
        continue;
      }
      const s = Math.max(1.5, cam.toScreenLength(b.size[k]!));
      const c = Math.cos(b.a[k]!),
        sn = Math.sin(b.a[k]!);
      // A splinter is a thin sliver, a shard or chip a small triangle.
      const alpha = Math.min(1, 3 * (1 - t));
      g.poly([
        x + c * s,
        y + sn * s,
        x - c * s + sn * 0.35 * s,
        y - sn * s - c * 0.35 * s,
        x - c * 0.6 * s - sn * 0.4 * s,
        y - sn * 0.6 * s + c * 0.4 * s,
      ]).fill({
        color: b.color[k]!,
        alpha,
      });
    }
    for (const p of this.live) {
      const t = p.age / POPUP_LIFE;
      p.text.x = cam.toScreenX(p.x);
      p.text.y = cam.toScreenY(p.y + POPUP_RISE * rise(t));
      p.text.alpha = t < 0.7 ? 1 : (1 - t) / 0.3;
      p.text.scale.set(t < 0.15 ? 0.6 + (0.4 * t) / 0.15 : 1);
    }
  }

  /** Bits in flight now (tests). */
  get bitCount(): number {
    return this.bits.count;
  }

  /** Popups showing now (tests). */
  get popupCount(): number {
    return this.live.length;
  }

  /** The points the "+N" popups showing now add up to (tests). */
  get popupPoints(): number {
    return this.live.reduce((a, p) => a + (Number.isNaN(p.points) ? 0 : p.points), 0);
  }

  /** The popups' boxes where they were last drawn, screen px [left, top, right, bottom] (tests). */
  popupBoxes(): number[][] {
    return this.live.map((p) => {
      const w = p.text.width / 2,
        h = p.text.height / 2;
      return [p.text.x - w, p.text.y - h, p.text.x + w, p.text.y + h];
    });
  }

  /** Clears every bit, popup and shake (a new level). */
  clear(): void {
    this.bits.count = 0;
    this.bits.next = 0;
    for (const p of this.live) {
      p.text.visible = false;
      this.popups.removeChild(p.text);
      this.spare.push(p.text);
    }
    this.live.length = 0;
    this.shakePx = 0;
  }
}
