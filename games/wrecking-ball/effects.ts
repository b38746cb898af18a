/**
 * Wrecking ball, the effects of a hit (drawing only, no physics): dust that billows where something
 * strikes the ground or the ball strikes a piece, chips in the piece's colour that fly and fall, and
 * score popups that rise over what fell, one for each group of pieces that fell together
 * (`ScoreTally`). Dust and chips are the points of one `Points` object (one draw call: as a sprite
 * each, a collapse drew up to 160 more), popups sprites; all sized in the scene's metres, from fixed pools.
 */
import {
  BufferAttribute,
  BufferGeometry,
  type Camera,
  CanvasTexture,
  Color,
  DynamicDrawUsage,
  type Object3D,
  Points,
  ShaderMaterial,
  Sprite,
  SpriteMaterial,
  SRGBColorSpace,
  Vector2,
  Vector3,
} from 'three';

/**
 * Sprites in each pool: dust puffs and chips share one, popups have their own. At most POPUPS
 * popups show at once (a new one takes the oldest's sprite): with one a falling piece, a tower's
 * collapse stacked five or six labels into one unreadable pile on a phone.
 */
const BITS = 160,
  POPUPS = 4;

/** The part of a popup's sprite its text covers, across (LABEL_W) and up (LABEL_H). */
const LABEL_W = 0.7,
  LABEL_H = 0.7;

/** Gap left between two stacked popup labels, in normalised device coordinates (0.004: 1.6 px of an 800 px screen). */
const CLEARANCE = 0.004;

/** Seconds a dust puff lives; a chip lives CHIP_LIFE; a popup POPUP_LIFE. */
const DUST_LIFE = 1.4,
  CHIP_LIFE = 1.2,
  POPUP_LIFE = 1.2;

/**
 * The bits' shaders: each point a square `size` m across at its distance (`pxPerM` px a metre at
 * 1 m from the camera), in its colour; dust (kind 0) a soft round puff (opaque at its middle, 0.55
 * halfway out, clear at its rim), a chip (kind 1) a solid square; `alpha` fades it.
 */
const BIT_VERTEX = `
uniform float pxPerM;
attribute float size;
attribute float alpha;
attribute float kind;
attribute vec3 tint;
varying vec3 vTint;
varying float vAlpha;
varying float vKind;
void main() {
  vTint = tint;
  vAlpha = alpha;
  vKind = kind;
  vec4 mv = modelViewMatrix * vec4(position, 1.0);
  gl_Position = projectionMatrix * mv;
  gl_PointSize = alpha > 0.0 ? size * pxPerM / max(0.01, -mv.z) : 0.0;
}`;
const BIT_FRAGMENT = `
varying vec3 vTint;
varying float vAlpha;
varying float vKind;
void main() {
  float r = 2.0 * length(gl_PointCoord - vec2(0.5));
  float a = vKind > 0.5 ? 1.0 : (r < 0.5 ? mix(1.0, 0.55, 2.0 * r) : mix(0.55, 0.0, clamp(2.0 * r - 1.0, 0.0, 1.0)));
  if (a * vAlpha <= 0.0) discard;
  gl_FragColor = vec4(vTint, a * vAlpha);
  #include <colorspace_fragment>
}`;

/** A popup's label drawn in bold yellow with a dark outline, on a clear canvas. */
function labelTexture(text: string): CanvasTexture {
  const c = document.createElement('canvas');
  c.width = 160;
  c.height = 64;
  const g = c.getContext('2d')!;
  g.font = 'bold 40px sans-serif';
  g.textAlign = 'center';
  g.textBaseline = 'middle';
  g.lineWidth = 8;
  g.strokeStyle = '#1a1208';
  g.strokeText(text, 80, 34);
  g.fillStyle = '#ffe066';
  g.fillText(text, 80, 34);
  const t = new CanvasTexture(c);
  t.colorSpace = SRGBColorSpace;
  return t;
}

/** One bit in flight: its place (m), velocity (m/s), age and life (s, life 0: not in flight), size (m) and whether it is dust. */
interface Bit {
  x: number;
  y: number;
  z: number;
  vx: number;
  vy: number;
  vz: number;
  age: number;
  life: number;
  size: number;
  dust: boolean;
}

/** The effects layer: add `root` to the scene, call `update` once a frame. */
export class SiteEffects {
  private readonly bits: Bit[] = [];
  /** The bits drawn: one point each (place, tint, size, alpha, kind), written by `update`. */
  private readonly points: Points;
  private readonly place = new Float32Array(3 * BITS);
  private readonly tint = new Float32Array(3 * BITS);
  private readonly size = new Float32Array(BITS);
  private readonly alpha = new Float32Array(BITS);
  private readonly kind = new Float32Array(BITS);
  private readonly color = new Color();
  /** Whether a bit showed at the last update (its buffers need one more upload to hide it). */
  private drawn = false;
  /**
   * The popups' sprites: `age` s since shown, `y0` the height it rose from and `lift` m it was raised
   * by to clear the labels shown before it (never lowered, so a stacked label does not jump back),
   * `seq` the order it was shown in; `sx`, `sy`, `hw`, `hh` its label's centre and half size on the
   * screen this frame (normalised device coordinates).
   */
  private readonly popups: Array<{
    sprite: Sprite;
    age: number;
    y0: number;
    lift: number;
    seq: number;
    sx: number;
    sy: number;
    hw: number;
    hh: number;
  }> = [];
  /** Popups shown so far (their `seq`). */
  private shownPopups = 0;
  /** The visible popups, oldest first (reused each frame). */
  private readonly stack: Array<(typeof this.popups)[number]> = [];
  private readonly at = new Vector3();
  private readonly up = new Vector3();
  private readonly labels = new Map<string, CanvasTexture>();
  private next = 0;
  private nextPopup = 0;
  private seed = 9;

  /**
   * `root` is the object the sprites are added to (the scene); `popupScale` (> 0, default 1) sizes
   * the popups (an upright phone, whose view of the site is about half as large, draws them larger).
   * @throws RangeError on a popupScale that is not > 0.
   */
  constructor(
    root: Object3D,
    private readonly popupScale = 1,
  ) {
    if (!(popupScale > 0 && Number.isFinite(popupScale))) throw new RangeError(`SiteEffects: popupScale must be > 0, got ${popupScale}`);
    const geometry = new BufferGeometry();
    const attributes: Array<[string, Float32Array, number]> = [
      ['position', this.place, 3],
      ['tint', this.tint, 3],
      ['size', this.size, 1],
      ['alpha', this.alpha, 1],
      ['kind', this.kind, 1],
    ];
    for (const [name, array, n] of attributes) geometry.setAttribute(name, new BufferAttribute(array, n).setUsage(DynamicDrawUsage));
    const material = new ShaderMaterial({
      uniforms: { pxPerM: { value: 500 } },
      vertexShader: BIT_VERTEX,
      fragmentShader: BIT_FRAGMENT,
      transparent: true,
      depthWrite: false,
    });
    this.points = new Points(geometry, material);
    this.points.frustumCulled = false;
    this.points.visible = false;
    // Pixels a metre at 1 m, for this frame's camera and drawing buffer (a perspective camera's fov).
    const buffer = new Vector2();
    this.points.onBeforeRender = (renderer, _scene, camera) => {
      renderer.getDrawingBufferSize(buffer);
      const fov = (camera as { fov?: number }).fov ?? 50;
      material.uniforms.pxPerM!.value = buffer.y / (2 * Math.tan((fov * Math.PI) / 360));
    };
    root.add(this.points);
    for (let i = 0; i < BITS; i++) this.bits.push({ x: 0, y: 0, z: 0, vx: 0, vy: 0, vz: 0, age: 0, life: 0, size: 0, dust: true });
    for (let i = 0; i < POPUPS; i++) {
      const sprite = new Sprite(new SpriteMaterial({ transparent: true, depthTest: false, depthWrite: false }));
      sprite.visible = false;
      sprite.renderOrder = 10;
      root.add(sprite);
      this.popups.push({ sprite, age: 0, y0: 0, lift: 0, seq: 0, sx: 0, sy: 0, hw: 0, hh: 0 });
    }
  }

  private rand(): number {
    this.seed = (this.seed * 1103515245 + 12345) >>> 0;
    return this.seed / 2 ** 32;
  }

  /**
   * Dust: `count` puffs at (x, y, z), m, spreading at up to `speed` m/s, in `color` (0xRRGGBB);
   * and `chips` chips of `chipColor` thrown up and out, falling under gravity.
   */
  burst(x: number, y: number, z: number, count: number, speed: number, color = 0xc9b393, chips = 0, chipColor = 0x888888): void {
    for (let i = 0; i < count + chips; i++) {
      const k = this.next;
      const b = this.bits[k]!;
      this.next = (this.next + 1) % BITS;
      const dust = i < count;
      const a = this.rand() * 2 * Math.PI;
      const v = speed * (dust ? 0.3 + 0.5 * this.rand() : 0.5 + 0.8 * this.rand());
      b.vx = v * Math.cos(a);
      b.vz = v * Math.sin(a);
      b.vy = dust ? 0.3 + 0.6 * this.rand() : 2 + 3 * this.rand();
      b.age = 0;
      b.life = dust ? DUST_LIFE * (0.6 + 0.4 * this.rand()) : CHIP_LIFE * (0.6 + 0.4 * this.rand());
      b.size = dust ? 0.5 + 0.5 * this.rand() : 0.1 + 0.1 * this.rand();
      b.dust = dust;
      b.x = x + (this.rand() - 0.5) * 0.4;
      b.y = y + (this.rand() - 0.5) * 0.3;
      b.z = z + (this.rand() - 0.5) * 0.4;
      this.color.setHex(dust ? color : chipColor);
      this.tint[3 * k] = this.color.r;
      this.tint[3 * k + 1] = this.color.g;
      this.tint[3 * k + 2] = this.color.b;
      this.kind[k] = dust ? 0 : 1;
    }
  }

  /** A popup (e.g. "+40") rising from (x, y, z), m. */
  popup(x: number, y: number, z: number, text: string): void {
    let map = this.labels.get(text);
    if (!map) {
      map = labelTexture(text);
      this.labels.set(text, map);
    }
    const p = this.popups[this.nextPopup]!;
    this.nextPopup = (this.nextPopup + 1) % POPUPS;
    p.sprite.material.map = map;
    p.sprite.material.needsUpdate = true;
    p.sprite.position.set(x, y, z);
    p.y0 = y;
    p.age = 0;
    p.lift = 0;
    p.seq = this.shownPopups++;
    p.sprite.visible = true;
  }

  /**
   * Advances every bit and popup by `dt` s. With `camera` (the view they are drawn in), labels that
   * would overlap on the screen are stacked: each is raised over those shown before it.
   */
  update(dt: number, camera?: Camera): void {
    let shown = 0;
    for (let i = 0; i < BITS; i++) {
      const b = this.bits[i]!;
      if (b.life > 0) b.age += dt;
      if (b.life > 0 && b.age >= b.life) b.life = 0;
      if (b.life <= 0) {
        this.alpha[i] = 0;
        continue;
      }
      shown++;
      const t = b.age / b.life;
      if (b.dust) {
        const damp = Math.exp(-2.5 * dt);
        b.vx *= damp;
        b.vz *= damp;
        b.vy = b.vy * damp + 0.2 * dt;
        this.size[i] = b.size * (0.7 + 1.8 * t);
        this.alpha[i] = 0.6 * (1 - t);
      } else {
        b.vy -= 9.81 * dt;
        if (b.y + b.vy * dt < 0.05) b.vx = b.vy = b.vz = 0;
        this.size[i] = b.size;
        this.alpha[i] = Math.min(1, 3 * (1 - t));
      }
      b.x += b.vx * dt;
      b.y += b.vy * dt;
      b.z += b.vz * dt;
      this.place[3 * i] = b.x;
      this.place[3 * i + 1] = b.y;
      this.place[3 * i + 2] = b.z;
    }
    this.points.visible = shown > 0;
    if (shown > 0 || this.drawn) for (const a of Object.values(this.points.geometry.attributes)) (a as BufferAttribute).needsUpdate = true;
    this.drawn = shown > 0;
    for (const p of this.popups) {
      if (!p.sprite.visible) continue;
      p.age += dt;
      if (p.age >= POPUP_LIFE) {
        p.sprite.visible = false;
        continue;
      }
      const t = p.age / POPUP_LIFE;
      p.sprite.position.y = p.y0 + p.lift + 1.6 * this.popupScale * (1 - (1 - t) * (1 - t));
      p.sprite.scale.set(3, 1.2, 1).multiplyScalar(this.popupScale * (t < 0.15 ? 0.6 + (0.4 * t) / 0.15 : 1));
      p.sprite.material.opacity = t < 0.7 ? 1 : (1 - t) / 0.3;
    }
    if (camera) this.unstack(camera);
  }

  /**
   * Raises each visible popup, oldest first, until its label's box on the screen (the text's part of
   * the sprite: LABEL_W of its width, LABEL_H of its height) clears the boxes of those before it.
   */
  private unstack(camera: Camera): void {
    const stack = this.stack;
    stack.length = 0;
    for (const p of this.popups) if (p.sprite.visible) stack.push(p);
    if (stack.length < 2) return;
    stack.sort((a, b) => a.seq - b.seq);
    this.up.setFromMatrixColumn(camera.matrixWorld, 1).normalize();
    for (let i = 0; i < stack.length; i++) {
      const p = stack[i]!;
      this.screenBox(p, camera);
      // Each rise clears one earlier label with CLEARANCE to spare (a label raised farther from the camera
      // draws a little smaller, so a rise to the exact edge can leave a sliver of overlap); at most two
      // rises per label shown (the 1e-3 margin ignores what is left then).
      for (let j = 0, rises = 0; j < i && rises < 2 * stack.length; j++) {
        const q = stack[j]!;
        if (Math.abs(p.sx - q.sx) >= p.hw + q.hw - 1e-3 || Math.abs(p.sy - q.sy) >= p.hh + q.hh - 1e-3 || p.hh <= 0) continue;
        rises++;
        // Screen height to rise by, as metres at the label's distance (its full height is scale.y m).
        const rise = ((q.sy + q.hh + p.hh + CLEARANCE - p.sy) / (2 * p.hh)) * p.sprite.scale.y * LABEL_H;
        p.lift += rise;
        p.sprite.position.y += rise;
        this.screenBox(p, camera);
        j = -1; // it moved: check it against every earlier label again
      }
    }
  }

  /** Popup `p`'s label centre and half size on the screen of `camera`, normalised device coordinates. */
  private screenBox(p: (typeof this.popups)[number], camera: Camera): void {
    const c = this.at.copy(p.sprite.position).project(camera);
    p.sx = c.x;
    p.sy = c.y;
    const top = this.at
      .copy(p.sprite.position)
      .addScaledVector(this.up, 0.5 * p.sprite.scale.y)
      .project(camera);
    p.hh = Math.abs(top.y - p.sy) * LABEL_H;
    const aspect = (camera as { aspect?: number }).aspect ?? 1;
    p.hw = ((p.hh / LABEL_H) * (p.sprite.scale.x / p.sprite.scale.y) * LABEL_W) / aspect;
  }

  /** Bits and popups showing now (tests). */
  counts(): { bits: number; popups: number } {
    return { bits: this.bits.filter((b) => b.life > 0).length, popups: this.popups.filter((p) => p.sprite.visible).length };
  }

  /**
   * The visible popups' label boxes on the screen as last stacked (tests): centre (sx, sy) and half
   * size (hw, hh) in normalised device coordinates, oldest first; all 0 until stacked with another.
   */
  popupBoxes(): Array<{ sx: number; sy: number; hw: number; hh: number }> {
    return this.popups
      .filter((p) => p.sprite.visible)
      .sort((a, b) => a.seq - b.seq)
      .map(({ sx, sy, hw, hh }) => ({ sx, sy, hw, hh }));
  }

  /** Hides everything (a new level). */
  clear(): void {
    for (const b of this.bits) b.life = 0;
    this.alpha.fill(0);
    this.points.visible = false;
    for (const p of this.popups) p.sprite.visible = false;
  }
}

/** Seconds after a tally's first fall that it collects falls for, before its popup shows. */
export const TALLY_TIME = 0.5;
/** Metres across the ground from a tally's first fall within which a fall joins it. */
export const TALLY_REACH = 3;

/** One group of falls being summed (see `ScoreTally`). */
export interface Tally {
  /** Where its popup rises from, m: over the highest piece that fell in it. */
  x: number;
  y: number;
  z: number;
  /** The points of its falls, summed. */
  points: number;
  /** How many pieces fell in it. */
  pieces: number;
  /** World time of its first fall, s. */
  time: number;
}

/**
 * Sums the points of pieces that fall together into one popup: a fall within TALLY_REACH m across
 * the ground of a tally opened less than TALLY_TIME s before joins it; any other opens a new one. A
 * tally is due (its popup shows) TALLY_TIME s after it opened. Pure bookkeeping, no drawing.
 */
export class ScoreTally {
  private readonly open: Tally[] = [];

  /**
   * Adds a fall of `points` at (x, y, z), m, at world time `time`, s.
   * @throws RangeError on a non-finite place or time, or negative points.
   */
  add(x: number, y: number, z: number, points: number, time: number): void {
    if (![x, y, z, time].every(Number.isFinite))
      throw new RangeError(`ScoreTally.add: place and time must be finite, got ${[x, y, z, time]}`);
    if (!(points >= 0)) throw new RangeError(`ScoreTally.add: points must be >= 0, got ${points}`);
    const t = this.open.find((q) => time - q.time < TALLY_TIME && Math.hypot(q.x - x, q.z - z) < TALLY_REACH);
    if (t === undefined) {
      this.open.push({ x, y, z, points, pieces: 1, time });
      return;
    }
    t.points += points;
    t.pieces++;
    if (y > t.y) t.y = y;
  }

  /** The tallies due at world time `time`, s (each returned once), oldest first. */
  due(time: number): Tally[] {
    const out: Tally[] = [];
    for (let i = 0; i < this.open.length; ) {
      if (time - this.open[i]!.time >= TALLY_TIME) out.push(...this.open.splice(i, 1));
      else i++;
    }
    return out;
  }

  /** Forgets every open tally (a new level). */
  clear(): void {
    this.open.length = 0;
  }
}
