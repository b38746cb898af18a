import type { PhysicsWorld } from '@bitphysics/physics';
import {
  assertBoolean,
  assertFinite,
  assertInRange,
  assertInteger,
  assertKnownKeys,
  assertNonNegative,
  describe,
} from '@bitphysics/physics/validate';
import { type ColorInput, parseColor } from '@bitphysics/render-common';
import { Not as notTerm, query } from 'bitecs';
import { Container, Particle, type Texture } from 'pixi.js';
import type { Camera } from './camera.js';
import { QuadPools } from './quads.js';
import { radialAlphaTexture, sharedStreakTexture } from './textures.js';

/**
 * The point layer: draws bodies that have no collider (stars, dust, test particles in a force field)
 * as small dots, all of them with one pixi v8 `ParticleContainer` and one shared dot texture, so a
 * hundred thousand stars of an N-body galaxy cost one draw call.
 *
 * Which entities: by default every moving point mass, i.e. entities with Position, Velocity and Mass
 * that have no Ball (the ball layer draws those), no Particle (the particle layer draws those) and are
 * neither Static nor Kinematic. Or give `entities`, a function returning the ids to draw each frame
 * (a scene's star list, say). Ids it returns must be live entities of the world.
 *
 * Per point and frame, from the physics component stores (nothing is cached per entity):
 * - position: PreviousPosition + (Position - PreviousPosition) alpha, m, to CSS px through the camera;
 * - colour: one colour for all (`colorBy: 'uniform'`), or a palette gradient indexed by the body's
 *   speed |v| (m/s, `'speed'`) or its distance from `centre` (m, `'radius'`), mapped linearly from
 *   `range` onto the palette (values outside the range take the end colours). The gradient is a
 *   256-entry lookup table built when the colouring changes, so a frame does one table read a point;
 * - size: `size` CSS px across for every point (screen-sized dots: stars stay visible when zoomed out).
 *
 * Optional trails: one streak quad per point from its position back along its velocity over
 * `trails.duration` s (the distance it covers at its current speed), fading towards the tail, in a
 * second ParticleContainer under the dots. One quad a point: memory bounded by the point count, no
 * per-point history. A body moved with setPosition gets no streak across the jump (its velocity, not
 * its history, sets the streak).
 *
 * Pooling: display particles come from pools that only grow (to the most points ever shown at once);
 * each frame the shown ones fill slots 0..n-1 and the container's list is cut to n. Off-screen points
 * are skipped when `cull` is on. Once the pools have grown, a frame allocates nothing.
 *
 * The layer reads; it never writes physics state.
 *
 * @example
 * const stars = new PointLayer({ entities: () => handles.stars, colorBy: 'speed', range: [0, 40], size: 2 });
 * renderer.root.addChild(stars.container);
 * each frame: stars.render(world, renderer.camera, loop.alpha);
 */

/** Options of point trails (`PointLayerOptions.trails`). Unknown fields are rejected. */
export interface PointTrailOptions {
  /** How far back a streak reaches, s, in (0, 2]: the distance |v| duration. Default 0.1 s. */
  duration?: number;
  /** Streak width, CSS px, in (0, 64]. Default: the dot size. */
  width?: number;
  /** Opacity of the streak's head relative to the dot's, in (0, 1]; it fades to 0 at the tail. Default 0.5. */
  alpha?: number;
  /** Streaks shorter than this, CSS px (>= 0), are not drawn. Default 1. */
  minLength?: number;
}

/** How points are coloured: one colour, or a palette gradient by speed (m/s) or by distance from a centre (m). */
export type PointColorBy = 'uniform' | 'speed' | 'radius';

/** The colouring fields of `PointLayerOptions` (also what `setColoring` takes). */
export interface PointColoring {
  /** What picks a point's colour. Default 'uniform'. */
  colorBy?: PointColorBy;
  /** The colour of every point when `colorBy` is 'uniform': 0xRRGGBB or '#rrggbb'. Default 0xffffff. */
  color?: ColorInput;
  /**
   * The values mapped onto the palette's first and last stop: m/s for 'speed', m for 'radius';
   * finite, [low, high] with high > low. Default [0, 10].
   */
  range?: readonly [number, number];
  /** Where distances are measured from for 'radius', m (x, y). Default [0, 0]. */
  centre?: readonly [number, number];
  /** Gradient stops, evenly spaced from low to high, at least 2 colours. Default `DEFAULT_POINT_PALETTE`. */
  palette?: readonly ColorInput[];
}

/** Options of `new PointLayer`. Every field optional; unknown fields are rejected. */
export interface PointLayerOptions extends PointColoring {
  /**
   * The entities to draw this frame, called once per `render`: return a live array or typed array of
   * live entity ids (e.g. a scene's `stars`); do not allocate a new one every frame. Default: every
   * moving point mass (Position, Velocity, Mass; no Ball, Particle, Static or Kinematic).
   */
  entities?: (world: PhysicsWorld) => ArrayLike<number>;
  /** Dot diameter, CSS px, in (0, 64]. Default 2. */
  size?: number;
  /** Opacity of every dot, in [0, 1]. Default 1. */
  alpha?: number;
  /** 'add' (additive: dense regions glow; star fields) or 'normal' (alpha blending). Default 'add'. */
  blend?: 'normal' | 'add';
  /** Skip points outside the screen. Default true. */
  cull?: boolean;
  /** Streak trails: `true` for defaults, options, or `false` (default) for none. */
  trails?: boolean | PointTrailOptions;
  /** Edge of the shared dot texture, px, integer in [8, 256]. Default 16 (mipmapped). */
  textureSize?: number;
}

/** Fully resolved trail options. */
export type ResolvedPointTrailOptions = Required<PointTrailOptions>;

/** Fully resolved layer options (colours as 0xRRGGBB numbers). */
export interface ResolvedPointLayerOptions {
  entities: ((world: PhysicsWorld) => ArrayLike<number>) | null;
  size: number;
  alpha: number;
  blend: 'normal' | 'add';
  cull: boolean;
  trails: ResolvedPointTrailOptions | null;
  textureSize: number;
  colorBy: PointColorBy;
  color: number;
  range: [number, number];
  centre: [number, number];
  palette: number[];
}

/** What the layer drew in its last `render` (one object, updated in place). */
export interface PointLayerStats {
  /** Entities the layer was given (or found) to draw, integer >= 0. */
  points: number;
  /** Dots drawn (on screen). */
  drawn: number;
  /** Streaks drawn. */
  trails: number;
  /** Display particles ever created (dots plus streaks). */
  pooled: number;
  /** Milliseconds the last `render` took on the CPU (the GPU upload happens later, in `app.render()`). */
  cpuMs: number;
  /** Frames rendered since creation. */
  frames: number;
}

/** The default gradient: deep blue, blue-white, white, warm yellow, orange (slow to fast, or inner to outer). */
export const DEFAULT_POINT_PALETTE: readonly number[] = Object.freeze([0x3050ff, 0x9fc4ff, 0xffffff, 0xffe08a, 0xff8a3d]);

const LAYER_OPTIONS = [
  'entities',
  'size',
  'alpha',
  'blend',
  'cull',
  'trails',
  'textureSize',
  'colorBy',
  'color',
  'range',
  'centre',
  'palette',
] as const;
const COLORING_OPTIONS = ['colorBy', 'color', 'range', 'centre', 'palette'] as const;
const TRAIL_OPTIONS = ['duration', 'width', 'alpha', 'minLength'] as const;

/**
 * Checks trail options and fills in defaults (`size` is the dot size, the default width).
 * @throws TypeError on unknown options or wrong types; RangeError naming the option and value when out of range.
 */
export function resolvePointTrailOptions(where: string, options: PointTrailOptions, size: number): ResolvedPointTrailOptions {
  assertKnownKeys(where, options, TRAIL_OPTIONS);
  const duration = options.duration ?? 0.1;
  assertInRange(where, 'trails.duration', duration, 0, 2);
  if (duration === 0) throw new RangeError(`${where}: trails.duration must be in (0, 2] s, got 0`);
  const width = options.width ?? size;
  assertInRange(where, 'trails.width', width, 0, 64);
  if (width === 0) throw new RangeError(`${where}: trails.width must be in (0, 64] px, got 0`);
  const alpha = options.alpha ?? 0.5;
  assertInRange(where, 'trails.alpha', alpha, 0, 1);
  if (alpha === 0) throw new RangeError(`${where}: trails.alpha must be in (0, 1], got 0`);
  const minLength = options.minLength ?? 1;
  assertNonNegative(where, 'trails.minLength', minLength);
  return { duration, width, alpha, minLength };
}

function resolveColoring(
  where: string,
  options: PointColoring,
  base: Pick<ResolvedPointLayerOptions, 'colorBy' | 'color' | 'range' | 'centre' | 'palette'>,
): Pick<ResolvedPointLayerOptions, 'colorBy' | 'color' | 'range' | 'centre' | 'palette'> {
  const colorBy = options.colorBy ?? base.colorBy;
  if (colorBy !== 'uniform' && colorBy !== 'speed' && colorBy !== 'radius') {
    throw new RangeError(`${where}: colorBy must be 'uniform', 'speed' or 'radius', got ${describe(colorBy)}`);
  }
  const color = options.color !== undefined ? parseColor(where, 'color', options.color) : base.color;
  let range = base.range;
  if (options.range !== undefined) {
    const r = options.range;
    if (!Array.isArray(r) || r.length !== 2) throw new TypeError(`${where}: range must be [low, high], got ${describe(r)}`);
    assertFinite(where, 'range[0]', r[0]);
    assertFinite(where, 'range[1]', r[1]);
    if (!(r[1] > r[0])) throw new RangeError(`${where}: range must have high > low, got ${describe(r)}`);
    range = [r[0], r[1]];
  }
  let centre = base.centre;
  if (options.centre !== undefined) {
    const c = options.centre;
    if (!Array.isArray(c) || c.length !== 2) throw new TypeError(`${where}: centre must be [x, y] in m, got ${describe(c)}`);
    assertFinite(where, 'centre[0]', c[0]);
    assertFinite(where, 'centre[1]', c[1]);
    centre = [c[0], c[1]];
  }
  let palette = base.palette;
  if (options.palette !== undefined) {
    if (!Array.isArray(options.palette))
      throw new TypeError(`${where}: palette must be an array of colours, got ${describe(options.palette)}`);
    if (options.palette.length < 2) throw new RangeError(`${where}: palette needs at least 2 colours, got ${options.palette.length}`);
    palette = options.palette.map((c, i) => parseColor(where, `palette[${i}]`, c));
  }
  return { colorBy, color, range, centre, palette };
}

/**
 * Checks layer options and fills in defaults.
 * @throws TypeError on unknown options or wrong types (entities not a function, a malformed range or
 *   centre, a colour of the wrong type); RangeError naming the option and value when out of range.
 */
export function resolvePointLayerOptions(where: string, options: PointLayerOptions = {}): ResolvedPointLayerOptions {
  assertKnownKeys(where, options, LAYER_OPTIONS);
  const entities = options.entities ?? null;
  if (entities !== null && typeof entities !== 'function')
    throw new TypeError(`${where}: entities must be a function (world) => ids, got ${describe(entities)}`);
  const size = options.size ?? 2;
  assertInRange(where, 'size', size, 0, 64);
  if (size === 0) throw new RangeError(`${where}: size must be in (0, 64] px, got 0`);
  const alpha = options.alpha ?? 1;
  assertInRange(where, 'alpha', alpha, 0, 1);
  const blend = options.blend ?? 'add';
  if (blend !== 'normal' && blend !== 'add') throw new RangeError(`${where}: blend must be 'normal' or 'add', got ${describe(blend)}`);
  const cull = options.cull ?? true;
  assertBoolean(where, 'cull', cull);
  const textureSize = options.textureSize ?? 16;
  assertInteger(where, 'textureSize', textureSize, 8, 256);
  const t = options.trails ?? false;
  if (typeof t !== 'boolean' && (t === null || typeof t !== 'object')) {
    throw new TypeError(`${where}: trails must be a boolean or an options object, got ${describe(t)}`);
  }
  const trails = t === false ? null : resolvePointTrailOptions(where, t === true ? {} : t, size);
  const coloring = resolveColoring(where, options, {
    colorBy: 'uniform',
    color: 0xffffff,
    range: [0, 10],
    centre: [0, 0],
    palette: [...DEFAULT_POINT_PALETTE],
  });
  return { entities, size, alpha, blend, cull, trails, textureSize, ...coloring };
}

/**
 * Creates the dot texture: a white disc, opaque out to 45% of its radius, then falling smoothly to 0
 * at the edge (a crisp core with an antialiased rim; tint multiplies it). Mipmapped.
 * @param size edge, px, integer in [8, 256].
 * @throws TypeError | RangeError on a bad size; Error if there is no 2D canvas.
 */
export function createPointTexture(size = 16): Texture {
  const where = 'createPointTexture';
  assertInteger(where, 'size', size, 8, 256);
  return radialAlphaTexture(where, size, [
    [0, 1],
    [0.45, 1],
    [0.7, 0.45],
    [1, 0],
  ]);
}

/**
 * Shared dot textures, one per size, made on first use and kept (a few kilobytes; see particles.ts for
 * why they are never destroyed). The streak texture is shared with the particle layer (`sharedStreakTexture`).
 */
const dotTextures = new Map<number, Texture>();

function dotTexture(size: number): Texture {
  let t = dotTextures.get(size);
  if (!t) {
    t = createPointTexture(size);
    dotTextures.set(size, t);
  }
  return t;
}

/** Size of the LUT a gradient is sampled into. */
const LUT_SIZE = 256;

/**
 * Draws point masses of a world as dots. See the file comment for what is drawn and how. Add
 * `container` to a stage (e.g. `renderer.root`), call `render` each frame before `app.render()`.
 */
export class PointLayer {
  /** Parent of the streak container (below) and the dot container; add it to a stage. */
  readonly container = new Container({ label: 'points' });
  /** Statistics of the last `render` (updated in place). */
  readonly stats: PointLayerStats = { points: 0, drawn: 0, trails: 0, pooled: 0, cpuMs: 0, frames: 0 };
  private opts: ResolvedPointLayerOptions;
  private readonly texture: Texture;
  /** The dot and streak containers and their pools. */
  private readonly quads: QuadPools;
  /** Gradient as pixi colours (0xBBGGRR), LUT_SIZE entries. */
  private readonly lut = new Uint32Array(LUT_SIZE);
  private terms: object[] = [];
  private termsOf: object | null = null;
  private destroyed = false;

  /**
   * @throws TypeError | RangeError on bad options (see `resolvePointLayerOptions`); Error if there is
   *   no 2D canvas for the textures.
   */
  constructor(options: PointLayerOptions = {}) {
    this.opts = resolvePointLayerOptions('PointLayer', options);
    this.texture = dotTexture(this.opts.textureSize);
    this.quads = new QuadPools(this.container, { main: 'point-dots', streaks: 'point-trails' }, this.texture, false, this.opts.blend);
    this.buildLut();
    if (this.opts.trails) this.quads.showStreaks(true);
  }

  /** The options in use (resolved; colours as numbers). */
  get options(): Readonly<ResolvedPointLayerOptions> {
    return this.opts;
  }

  /** Whether streak trails are drawn. */
  get trailsEnabled(): boolean {
    return this.opts.trails !== null;
  }

  /**
   * Changes how points are coloured; omitted fields keep their value.
   * @throws TypeError | RangeError on bad values (see `PointColoring`).
   */
  setColoring(coloring: PointColoring): void {
    this.assertAlive('setColoring');
    assertKnownKeys('PointLayer.setColoring', coloring, COLORING_OPTIONS);
    Object.assign(this.opts, resolveColoring('PointLayer.setColoring', coloring, this.opts));
    this.buildLut();
  }

  /** Sets the dot diameter, CSS px, in (0, 64]. @throws RangeError otherwise. */
  setSize(size: number): void {
    this.assertAlive('setSize');
    assertInRange('PointLayer.setSize', 'size', size, 0, 64);
    if (size === 0) throw new RangeError('PointLayer.setSize: size must be in (0, 64] px, got 0');
    this.opts.size = size;
    const s = size / this.opts.textureSize;
    const dotPool = this.quads.mainPool;
    for (let i = 0; i < dotPool.length; i++) {
      const p = dotPool[i]!;
      p.scaleX = s;
      p.scaleY = s;
    }
    this.quads.main.update();
  }

  /** Sets the opacity of every dot, in [0, 1]. @throws RangeError otherwise. */
  setAlpha(alpha: number): void {
    this.assertAlive('setAlpha');
    assertInRange('PointLayer.setAlpha', 'alpha', alpha, 0, 1);
    this.opts.alpha = alpha;
  }

  /** Switches between additive ('add') and alpha ('normal') blending. @throws RangeError on another value. */
  setBlend(blend: 'normal' | 'add'): void {
    this.assertAlive('setBlend');
    if (blend !== 'normal' && blend !== 'add')
      throw new RangeError(`PointLayer.setBlend: blend must be 'normal' or 'add', got ${describe(blend)}`);
    this.opts.blend = blend;
    this.quads.setBlend(blend);
  }

  /**
   * Turns streak trails on (`true` or options) or off (`false`).
   * @throws TypeError | RangeError on bad options.
   */
  setTrails(options: boolean | PointTrailOptions): void {
    this.assertAlive('setTrails');
    if (typeof options !== 'boolean' && (options === null || typeof options !== 'object')) {
      throw new TypeError(`PointLayer.setTrails: options must be a boolean or an options object, got ${describe(options)}`);
    }
    this.opts.trails =
      options === false ? null : resolvePointTrailOptions('PointLayer.setTrails', options === true ? {} : options, this.opts.size);
    this.quads.showStreaks(this.opts.trails !== null);
  }

  /**
   * Places every point of `world` for interpolation factor `alpha` (0: the state at the start of the
   * last step, 1: the current state) through `camera`. Call once per frame before the stage is rendered.
   * @param alpha in [0, 1]; the fixed-step loop's alpha, or 1 while paused.
   * @throws RangeError if alpha is outside [0, 1] or NaN; Error after `destroy`.
   */
  render(world: PhysicsWorld, camera: Camera, alpha: number): void {
    if (!(alpha >= 0 && alpha <= 1)) throw new RangeError(`PointLayer.render: alpha must be in [0, 1], got ${describe(alpha)}`);
    this.assertAlive('render');
    const t0 = performance.now();
    const o = this.opts;
    const c = world.components;
    let ents: ArrayLike<number>;
    if (o.entities !== null) {
      ents = o.entities(world);
    } else {
      if (this.termsOf !== c) {
        this.termsOf = c;
        this.terms = [c.Position, c.Velocity, c.Mass, notTerm(c.Ball), notTerm(c.Particle), notTerm(c.Static), notTerm(c.Kinematic)];
      }
      ents = query(world, this.terms);
    }
    const px = c.Position.x,
      py = c.Position.y,
      ox = c.PreviousPosition.x,
      oy = c.PreviousPosition.y;
    const vx = c.Velocity.x,
      vy = c.Velocity.y;
    const ppm = camera.pixelsPerMeter,
      x0 = camera.originX,
      y0 = camera.originY;
    const width = camera.width,
      height = camera.height;
    const half = o.size * 0.5;
    const a8 = Math.round(o.alpha * 255);
    const cull = o.cull;
    const mode = o.colorBy === 'speed' ? 1 : o.colorBy === 'radius' ? 2 : 0;
    const lut = this.lut;
    const low = o.range[0],
      scale = (LUT_SIZE - 1) / (o.range[1] - o.range[0]);
    const cx = o.centre[0],
      cy = o.centre[1];
    const uniform = ((a8 << 24) | lut[0]!) >>> 0;
    const trails = o.trails;
    const trailT = trails ? trails.duration * ppm : 0;
    const trailMin = trails ? trails.minLength : 0;
    const trailA = trails ? Math.round(a8 * trails.alpha) : 0;
    const streakTexture = sharedStreakTexture();
    const sw = trails ? 1 / streakTexture.width : 0,
      sh = trails ? trails.width / streakTexture.height : 0;
    const dotScale = o.size / o.textureSize;
    const dotPool = this.quads.mainPool,
      streakPool = this.quads.streakPool;
    let n = 0,
      k = 0;
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      const ax = ox[e]!,
        ay = oy[e]!;
      const wx = ax + (px[e]! - ax) * alpha,
        wy = ay + (py[e]! - ay) * alpha;
      const x = x0 + wx * ppm,
        y = y0 - wy * ppm;
      let len = 0,
        svx = 0,
        svy = 0,
        speed = -1;
      if (trails !== null) {
        svx = vx[e]!;
        svy = vy[e]!;
        speed = Math.sqrt(svx * svx + svy * svy);
        len = speed * trailT;
      }
      if (cull) {
        const m = half + len;
        if (x < -m || x > width + m || y < -m || y > height + m) continue;
      }
      let color = uniform;
      if (mode !== 0) {
        let v: number;
        if (mode === 1) {
          if (speed < 0) {
            const ux = vx[e]!,
              uy = vy[e]!;
            speed = Math.sqrt(ux * ux + uy * uy);
          }
          v = speed;
        } else {
          const dx = wx - cx,
            dy = wy - cy;
          v = Math.sqrt(dx * dx + dy * dy);
        }
        let j = (v - low) * scale;
        j = j > 0 ? (j < LUT_SIZE - 1 ? j | 0 : LUT_SIZE - 1) : 0;
        color = ((a8 << 24) | lut[j]!) >>> 0;
      }
      let p = dotPool[n];
      if (p === undefined) {
        p = new Particle({ texture: this.texture, anchorX: 0.5, anchorY: 0.5, scaleX: dotScale, scaleY: dotScale });
        dotPool.push(p);
      }
      n++;
      p.x = x;
      p.y = y;
      p.color = color;
      if (trails !== null && len >= trailMin && trailA > 0) {
        let q = streakPool[k];
        if (q === undefined) {
          q = new Particle({ texture: streakTexture, anchorX: 1, anchorY: 0.5 });
          streakPool.push(q);
        }
        k++;
        q.x = x;
        q.y = y;
        q.scaleX = len * sw;
        q.scaleY = sh;
        q.rotation = Math.atan2(-svy, svx);
        q.color = ((trailA << 24) | (color & 0xffffff)) >>> 0;
      }
    }
    this.quads.commit(n, trails !== null ? k : 0);
    const st = this.stats;
    st.points = ents.length;
    st.drawn = n;
    st.trails = trails !== null ? k : 0;
    st.pooled = this.quads.pooled;
    st.frames++;
    st.cpuMs = performance.now() - t0;
  }

  /** Frees the display particles and the containers (the shared textures stay). Methods throw Error afterwards. */
  destroy(): void {
    if (this.destroyed) return;
    this.destroyed = true;
    this.quads.destroy();
  }

  /** Samples the palette (or the uniform colour) into the LUT as pixi's 0xBBGGRR. */
  private buildLut(): void {
    const o = this.opts;
    const lut = this.lut;
    if (o.colorBy === 'uniform') {
      lut.fill(bgr(o.color));
      return;
    }
    const stops = o.palette;
    const segments = stops.length - 1;
    for (let i = 0; i < LUT_SIZE; i++) {
      const t = (i / (LUT_SIZE - 1)) * segments;
      const s = Math.min(segments - 1, Math.floor(t));
      const f = t - s;
      const a = stops[s]!,
        b = stops[s + 1]!;
      const r = Math.round(((a >> 16) & 255) + (((b >> 16) & 255) - ((a >> 16) & 255)) * f);
      const g = Math.round(((a >> 8) & 255) + (((b >> 8) & 255) - ((a >> 8) & 255)) * f);
      const bl = Math.round((a & 255) + ((b & 255) - (a & 255)) * f);
      lut[i] = (bl << 16) | (g << 8) | r;
    }
  }

  private assertAlive(where: string): void {
    if (this.destroyed) throw new Error(`PointLayer.${where}: the layer was destroyed`);
  }
}

/** 0xRRGGBB to pixi's 0xBBGGRR. */
function bgr(rgb: number): number {
  return ((rgb & 255) << 16) | (rgb & 0xff00) | ((rgb >> 16) & 255);
}
