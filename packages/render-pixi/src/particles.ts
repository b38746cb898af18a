import type { PhysicsWorld } from '@bitphysics/physics';
import {
  assertBoolean,
  assertInRange,
  assertInteger,
  assertKnownKeys,
  assertNonNegative,
  assertPositive,
  describe,
} from '@bitphysics/physics/validate';
import { query } from 'bitecs';
import { Container, Particle, type Texture } from 'pixi.js';
import type { Camera } from './camera.js';
import { QuadPools } from './quads.js';
import { radialAlphaTexture, STREAK_H, STREAK_W, sharedStreakTexture } from './textures.js';

/**
 * The particle layer: draws every entity that has Particle and Position (emitted sparks, smoke,
 * exhaust; no Ball needed) with one pixi v8 `ParticleContainer` and one shared soft round texture.
 *
 * Per particle and frame, from the physics component stores (nothing is cached per entity):
 * - position: PreviousPosition + (Position - PreviousPosition) alpha, m, to CSS px through the camera;
 * - look: `Particle` colour / size / alpha at birth and death, interpolated linearly in
 *   age / duration (the same rule as `particleLook` in @bitphysics/physics), the age taken at the
 *   interpolated time too (age - (1 - alpha) dt), so fades are as smooth as the motion;
 * - size: the look's size (m) is the diameter of the soft disc's quad, times `sizeScale`, times the
 *   camera's px/m. Below `minPixelSize` px the quad is kept at that size and its alpha scaled down by
 *   size / minPixelSize (a sub-pixel spark dims instead of vanishing or flickering).
 *
 * Optional trails: one streak quad per particle from its interpolated position back along its
 * velocity over the last `trails.duration` s (at most its age), fading from the head to the tail, in
 * a second ParticleContainer under the sparks. One quad a particle, so memory is bounded by the
 * particle count and there is no per-particle history.
 *
 * Pooling: display particles live in a pool that only grows (up to the most particles ever shown at
 * once); each frame the shown ones are written into slots 0..n-1 in query order and the container's
 * list is cut to n. Off-screen and invisible (alpha 0, size 0) particles are skipped. A frame
 * allocates nothing once the pool has grown to the live count (pixi's vertex buffer grows by 1.5x
 * the same way).
 *
 * The layer reads; it never writes physics state.
 *
 * @example
 * const layer = new ParticleLayer({ blend: 'add', trails: { duration: 0.06 } });
 * app.stage.addChild(layer.container);
 * layer.bind(world);
 * each frame: layer.render(world, camera, loop.alpha); app.render();
 * // or through the world renderer: new WorldRenderer(world, { app, particles: { blend: 'add' } })
 */

/** Options of the particle trails (`ParticleLayerOptions.trails`). Unknown fields are rejected. */
export interface ParticleTrailOptions {
  /**
   * How far back a streak reaches, s, in (0, 2]: it covers the distance |v| duration the particle
   * travelled at its current velocity (at most its age, so a newborn has no tail). Default 0.08 s.
   */
  duration?: number;
  /** Streak width relative to the particle's drawn diameter, in (0, 4]. Default 0.6. */
  width?: number;
  /** Opacity of the streak's head relative to the particle's alpha, in (0, 1]; it fades to 0 at the tail. Default 0.6. */
  alpha?: number;
  /** Streaks shorter than this, CSS px (>= 0), are not drawn. Default 1. */
  minLength?: number;
}

/** Options of `new ParticleLayer` (and `WorldRendererOptions.particles`). Every field optional; unknown fields are rejected. */
export interface ParticleLayerOptions {
  /** 'add' (additive: overlapping sparks glow brighter; fire, fireworks) or 'normal' (alpha blending; smoke, dust). Default 'normal'. */
  blend?: 'normal' | 'add';
  /** Edge of the shared soft round texture, px, integer in [8, 512]. Default 64 (mipmapped). */
  textureSize?: number;
  /** Smallest drawn diameter, CSS px, >= 0; smaller particles are drawn at it with alpha scaled by size / minPixelSize. Default 1.5. */
  minPixelSize?: number;
  /** Multiplies every particle's size (m) before drawing, > 0. Default 1. */
  sizeScale?: number;
  /** Multiplies every particle's alpha, in [0, 1]. Default 1. */
  alphaScale?: number;
  /** Skip particles whose quad lies outside the screen. Default true. */
  cull?: boolean;
  /** Trails: `true` for defaults, options, or `false` (default) for none. */
  trails?: boolean | ParticleTrailOptions;
  /**
   * Which particles this layer draws, decided once per particle (per entity id and spawn stamp) when
   * it is first seen: e.g. `(w, e) => w.components.Particle.emitter[e] === smoke` to give smoke and
   * fire their own layers with different blending. Default: every particle.
   */
  include?: (world: PhysicsWorld, eid: number) => boolean;
}

/** Fully resolved particle trail options. */
export type ResolvedParticleTrailOptions = Required<ParticleTrailOptions>;

/** Fully resolved layer options (trails null when off, include null for all). */
export interface ResolvedParticleLayerOptions {
  blend: 'normal' | 'add';
  textureSize: number;
  minPixelSize: number;
  sizeScale: number;
  alphaScale: number;
  cull: boolean;
  trails: ResolvedParticleTrailOptions | null;
  include: ((world: PhysicsWorld, eid: number) => boolean) | null;
}

/** What the layer drew in its last `render` (one object, updated in place). */
export interface ParticleLayerStats {
  /** Particles in the world that this layer draws (after `include`), integer >= 0. */
  particles: number;
  /** Particles drawn (on screen and visible). */
  drawn: number;
  /** Trail streaks drawn. */
  trails: number;
  /** Display particles ever created (pool size: sparks plus streaks). */
  pooled: number;
  /** Milliseconds the last `render` took on the CPU (reading stores, writing display particles); the GPU upload happens later in `app.render()`. */
  cpuMs: number;
  /** Frames rendered since creation. */
  frames: number;
}

const LAYER_OPTIONS = ['blend', 'textureSize', 'minPixelSize', 'sizeScale', 'alphaScale', 'cull', 'trails', 'include'] as const;
const TRAIL_OPTIONS = ['duration', 'width', 'alpha', 'minLength'] as const;

/**
 * Checks trail options and fills in defaults.
 * @throws TypeError on unknown options or wrong types; RangeError naming the option and value when out of range.
 */
export function resolveParticleTrailOptions(where: string, options: ParticleTrailOptions = {}): ResolvedParticleTrailOptions {
  assertKnownKeys(where, options, TRAIL_OPTIONS);
  const duration = options.duration ?? 0.08;
  assertInRange(where, 'trails.duration', duration, 0, 2);
  if (duration === 0) throw new RangeError(`${where}: trails.duration must be in (0, 2], got 0`);
  const width = options.width ?? 0.6;
  assertInRange(where, 'trails.width', width, 0, 4);
  if (width === 0) throw new RangeError(`${where}: trails.width must be in (0, 4], got 0`);
  const alpha = options.alpha ?? 0.6;
  assertInRange(where, 'trails.alpha', alpha, 0, 1);
  if (alpha === 0) throw new RangeError(`${where}: trails.alpha must be in (0, 1], got 0`);
  const minLength = options.minLength ?? 1;
  assertNonNegative(where, 'trails.minLength', minLength);
  return { duration, width, alpha, minLength };
}

/**
 * Checks layer options and fills in defaults.
 * @throws TypeError on unknown options or wrong types (include not a function); RangeError naming
 *   the option and value when out of range.
 */
export function resolveParticleLayerOptions(where: string, options: ParticleLayerOptions = {}): ResolvedParticleLayerOptions {
  assertKnownKeys(where, options, LAYER_OPTIONS);
  const blend = options.blend ?? 'normal';
  if (blend !== 'normal' && blend !== 'add') throw new RangeError(`${where}: blend must be 'normal' or 'add', got ${describe(blend)}`);
  const textureSize = options.textureSize ?? 64;
  assertInteger(where, 'textureSize', textureSize, 8, 512);
  const minPixelSize = options.minPixelSize ?? 1.5;
  assertNonNegative(where, 'minPixelSize', minPixelSize);
  const sizeScale = options.sizeScale ?? 1;
  assertPositive(where, 'sizeScale', sizeScale);
  const alphaScale = options.alphaScale ?? 1;
  assertInRange(where, 'alphaScale', alphaScale, 0, 1);
  const cull = options.cull ?? true;
  assertBoolean(where, 'cull', cull);
  const t = options.trails ?? false;
  if (typeof t !== 'boolean' && (t === null || typeof t !== 'object')) {
    throw new TypeError(`${where}: trails must be a boolean or an options object, got ${describe(t)}`);
  }
  const trails = t === false ? null : resolveParticleTrailOptions(where, t === true ? {} : t);
  const include = options.include ?? null;
  if (include !== null && typeof include !== 'function')
    throw new TypeError(`${where}: include must be a function (world, eid) => boolean, got ${describe(include)}`);
  return { blend, textureSize, minPixelSize, sizeScale, alphaScale, cull, trails, include };
}

/**
 * Creates the shared soft round particle texture: a white disc whose opacity falls smoothly from 1 at
 * the centre to 0 at the edge (a glow; tint multiplies it). Mipmapped, so any drawn size stays smooth.
 * @param size edge, px, integer in [8, 512].
 * @throws TypeError | RangeError on a bad size; Error if there is no 2D canvas.
 */
export function createSoftParticleTexture(size = 64): Texture {
  const where = 'createSoftParticleTexture';
  assertInteger(where, 'size', size, 8, 512);
  // A smooth bump close to (1 - r^2)^2: bright core, soft rim, exactly 0 at the edge.
  return radialAlphaTexture(where, size, [
    [0, 1],
    [0.2, 0.92],
    [0.4, 0.7],
    [0.6, 0.41],
    [0.8, 0.13],
    [1, 0],
  ]);
}

/**
 * The soft textures every layer shares, one per size (made on first use, never destroyed: a few
 * kilobytes, and a texture destroyed while pixi's particle shader still has it bound makes pixi warn).
 * The streak texture is shared the same way (`sharedStreakTexture` in textures.ts).
 */
const sharedSoft = new Map<number, Texture>();

function softTexture(size: number): Texture {
  let t = sharedSoft.get(size);
  if (!t) {
    t = createSoftParticleTexture(size);
    sharedSoft.set(size, t);
  }
  return t;
}

/**
 * Draws the particles of a world. See the file comment for what is drawn and how. Use it directly
 * (add `container` to a stage, `bind`, `render` each frame) or through `WorldRenderer`'s
 * `particles` option.
 */
export class ParticleLayer {
  /** Parent of the trail container (below) and the spark container; add it to a stage. */
  readonly container = new Container({ label: 'particles' });
  /** Statistics of the last `render` (updated in place). */
  readonly stats: ParticleLayerStats = { particles: 0, drawn: 0, trails: 0, pooled: 0, cpuMs: 0, frames: 0 };
  private opts: ResolvedParticleLayerOptions;
  private readonly texture: Texture;
  /** The spark and streak containers and their pools. */
  private readonly quads: QuadPools;
  private terms: object[] = [];
  private capacity = -1;
  /** Per entity (only with `include`): spawn stamp the decision was made for, and the decision (1 draw). */
  private includeStamp = new Uint32Array(0);
  private includeValue = new Uint8Array(0);
  private destroyed = false;

  /**
   * @throws TypeError | RangeError on bad options (see `resolveParticleLayerOptions`); Error if there
   *   is no 2D canvas for the textures.
   */
  constructor(options: ParticleLayerOptions = {}) {
    this.opts = resolveParticleLayerOptions('ParticleLayer', options);
    this.texture = softTexture(this.opts.textureSize);
    this.quads = new QuadPools(
      this.container,
      { main: 'particle-sparks', streaks: 'particle-trails' },
      this.texture,
      true,
      this.opts.blend,
    );
    if (this.opts.trails) this.quads.showStreaks(true);
  }

  /** The options in use (resolved). */
  get options(): Readonly<ResolvedParticleLayerOptions> {
    return this.opts;
  }

  /** Whether trails are drawn. */
  get trailsEnabled(): boolean {
    return this.opts.trails !== null;
  }

  /**
   * Binds to `world`: sizes the per-entity `include` cache to its capacity and forgets decisions
   * made for another world. Call before the first `render` of a world (WorldRenderer does).
   * @throws TypeError if `world` is not a physics world; Error after `destroy`.
   */
  bind(world: PhysicsWorld): void {
    this.assertAlive('bind');
    if (world === null || typeof world !== 'object' || typeof world.capacity !== 'number' || !(world.spawnStamp instanceof Uint32Array)) {
      throw new TypeError(`ParticleLayer.bind: world must be a physics world from createPhysicsWorld, got ${describe(world)}`);
    }
    const c = world.components;
    this.terms = [c.Particle, c.Position];
    if (this.opts.include) {
      if (this.capacity !== world.capacity) {
        this.includeStamp = new Uint32Array(world.capacity + 1);
        this.includeValue = new Uint8Array(world.capacity + 1);
      } else {
        this.includeStamp.fill(0);
      }
    }
    this.capacity = world.capacity;
  }

  /**
   * Switches between additive ('add') and alpha ('normal') blending.
   * @throws RangeError on another value.
   */
  setBlend(blend: 'normal' | 'add'): void {
    if (blend !== 'normal' && blend !== 'add')
      throw new RangeError(`ParticleLayer.setBlend: blend must be 'normal' or 'add', got ${describe(blend)}`);
    this.opts.blend = blend;
    this.quads.setBlend(blend);
  }

  /**
   * Turns trails on (`true` or options) or off (`false`).
   * @throws TypeError | RangeError on bad options.
   */
  setTrails(options: boolean | ParticleTrailOptions): void {
    this.assertAlive('setTrails');
    if (typeof options !== 'boolean' && (options === null || typeof options !== 'object')) {
      throw new TypeError(`ParticleLayer.setTrails: options must be a boolean or an options object, got ${describe(options)}`);
    }
    this.opts.trails = options === false ? null : resolveParticleTrailOptions('ParticleLayer.setTrails', options === true ? {} : options);
    this.quads.showStreaks(this.opts.trails !== null);
  }

  /**
   * Places every particle of `world` for interpolation factor `alpha` (0: the state at the start of
   * the last step, 1: the current state) through `camera`. Call once per frame before the stage is
   * rendered. Binds to `world` first if it is not the world last bound (by capacity).
   * @param alpha in [0, 1]; the fixed-step loop's alpha, or 1 while paused.
   * @throws RangeError if alpha is outside [0, 1] or NaN; Error after `destroy`.
   */
  render(world: PhysicsWorld, camera: Camera, alpha: number): void {
    if (!(alpha >= 0 && alpha <= 1)) throw new RangeError(`ParticleLayer.render: alpha must be in [0, 1], got ${describe(alpha)}`);
    this.assertAlive('render');
    const t0 = performance.now();
    if (this.terms.length === 0 || this.terms[0] !== world.components.Particle || this.capacity !== world.capacity) this.bind(world);
    const o = this.opts;
    const c = world.components;
    const ents = query(world, this.terms);
    const px = c.Position.x,
      py = c.Position.y,
      ox = c.PreviousPosition.x,
      oy = c.PreviousPosition.y;
    const vx = c.Velocity.x,
      vy = c.Velocity.y;
    const age = c.Lifetime.age,
      duration = c.Lifetime.duration;
    const P = c.Particle;
    const cs = P.colorStart,
      ce = P.colorEnd,
      ss = P.sizeStart,
      se = P.sizeEnd,
      as = P.alphaStart,
      ae = P.alphaEnd;
    const ppm = camera.pixelsPerMeter,
      x0 = camera.originX,
      y0 = camera.originY;
    const width = camera.width,
      height = camera.height;
    const back = (1 - alpha) * world.dt;
    const sizePx = ppm * o.sizeScale;
    const minPx = o.minPixelSize;
    const alphaScale = o.alphaScale * 255;
    const texScale = 1 / o.textureSize;
    const cull = o.cull;
    const trails = o.trails;
    const trailT = trails ? trails.duration : 0,
      trailW = trails ? trails.width / STREAK_H : 0;
    const trailA = trails ? trails.alpha : 0,
      trailMin = trails ? trails.minLength : 0;
    const include = o.include;
    const spawn = world.spawnStamp,
      incStamp = this.includeStamp,
      incValue = this.includeValue;
    const sparkPool = this.quads.mainPool,
      streakPool = this.quads.streakPool;
    const streakTexture = trails !== null ? sharedStreakTexture() : null;
    let n = 0,
      k = 0,
      shown = 0;
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      if (include !== null) {
        if (incStamp[e] !== spawn[e]) {
          incStamp[e] = spawn[e]!;
          incValue[e] = include(world, e) ? 1 : 0;
        }
        if (incValue[e] === 0) continue;
      }
      shown++;
      const d = duration[e]!;
      const a0 = age[e]! - back;
      let t = d > 0 ? a0 / d : 1;
      t = t < 0 ? 0 : t > 1 ? 1 : t;
      let a = (as[e]! + (ae[e]! - as[e]!) * t) * alphaScale;
      if (!(a > 0)) continue;
      let size = (ss[e]! + (se[e]! - ss[e]!) * t) * sizePx;
      if (!(size > 0)) continue;
      if (size < minPx) {
        a *= size / minPx;
        size = minPx;
      }
      const ax = ox[e]!,
        ay = oy[e]!;
      const x = x0 + (ax + (px[e]! - ax) * alpha) * ppm;
      const y = y0 - (ay + (py[e]! - ay) * alpha) * ppm;
      // Streak length, px: |v| min(duration, shown age).
      let len = 0;
      let svx = 0,
        svy = 0;
      if (trails !== null) {
        svx = vx[e]!;
        svy = vy[e]!;
        const span = a0 < trailT ? (a0 > 0 ? a0 : 0) : trailT;
        len = Math.sqrt(svx * svx + svy * svy) * span * ppm;
      }
      const r = size * 0.5;
      if (cull) {
        const m = r + len;
        if (x < -m || x > width + m || y < -m || y > height + m) continue;
      }
      const c0 = cs[e]!,
        c1 = ce[e]!;
      let bgr: number;
      if (c0 === c1) {
        bgr = ((c0 & 255) << 16) | (c0 & 0xff00) | ((c0 >> 16) & 255);
      } else {
        const r0 = (c0 >> 16) & 255,
          g0 = (c0 >> 8) & 255,
          b0 = c0 & 255;
        const rr = (r0 + (((c1 >> 16) & 255) - r0) * t + 0.5) | 0;
        const gg = (g0 + (((c1 >> 8) & 255) - g0) * t + 0.5) | 0;
        const bb = (b0 + ((c1 & 255) - b0) * t + 0.5) | 0;
        bgr = (bb << 16) | (gg << 8) | rr;
      }
      const a8 = a >= 255 ? 255 : (a + 0.5) | 0;
      let p = sparkPool[n];
      if (p === undefined) {
        p = this.newParticle(this.texture, 0.5);
        sparkPool.push(p);
      }
      n++;
      p.x = x;
      p.y = y;
      const s = size * texScale;
      p.scaleX = s;
      p.scaleY = s;
      p.color = ((a8 << 24) | bgr) >>> 0;
      if (trails !== null && len >= trailMin) {
        const ta = (a8 * trailA + 0.5) | 0;
        if (ta > 0) {
          let q = streakPool[k];
          if (q === undefined) {
            q = this.newParticle(streakTexture!, 1);
            streakPool.push(q);
          }
          k++;
          q.x = x;
          q.y = y;
          q.scaleX = len / STREAK_W;
          q.scaleY = size * trailW;
          q.rotation = Math.atan2(-svy, svx);
          q.color = ((ta << 24) | bgr) >>> 0;
        }
      }
    }
    this.quads.commit(n, trails !== null ? k : 0);
    const st = this.stats;
    st.particles = shown;
    st.drawn = n;
    st.trails = trails !== null ? k : 0;
    st.pooled = this.quads.pooled;
    st.frames++;
    st.cpuMs = performance.now() - t0;
  }

  /**
   * Frees the display particles and the containers (the shared textures stay for other layers). The
   * layer cannot be used afterwards (methods throw Error).
   */
  destroy(): void {
    if (this.destroyed) return;
    this.destroyed = true;
    this.quads.destroy();
  }

  private newParticle(texture: Texture, anchorX: number): Particle {
    return new Particle({ texture, anchorX, anchorY: 0.5 });
  }

  private assertAlive(where: string): void {
    if (this.destroyed) throw new Error(`ParticleLayer.${where}: the layer was destroyed`);
  }
}
