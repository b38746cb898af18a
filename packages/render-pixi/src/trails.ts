import type { PhysicsWorld } from '@bitphysics/physics';
import { assertInRange, assertInteger, assertKnownKeys } from '@bitphysics/physics/validate';
import { CanvasSource, Container, MeshRope, type PointData, Texture } from 'pixi.js';
import type { BallLayer, BallLayerListener } from './balls.js';
import type { Camera } from './camera.js';
import { canvas2d } from './textures.js';

/** Options of the trail layer (`WorldRendererOptions.trails`, `WorldRenderer.setTrails`). Unknown fields are rejected. */
export interface TrailOptions {
  /**
   * Positions kept per trail (one per rendered frame in which the world stepped), integer in
   * [2, 1024]. Default 30 (half a second at 60 Hz). Up to 48 the trails of all balls are drawn in
   * one batched draw call; longer trails cost a draw call each.
   */
  length?: number;
  /**
   * Most entities that get a trail at once, integer in [1, 100_000]. Balls beyond it have none (the
   * first ones shown get one; a slot frees when its ball goes). Bounds memory (about
   * maxEntities x length x 40 bytes, allocated once) and drawing cost. Default 256.
   */
  maxEntities?: number;
  /** Line width, CSS px, integer in [1, 64]. Default 2. */
  width?: number;
  /** Opacity of the newest end of a trail, in (0, 1]; it fades linearly to 0 at the oldest end. Default 0.55. */
  alpha?: number;
}

/** Fully resolved trail options. */
export type ResolvedTrailOptions = Required<TrailOptions>;

const TRAIL_OPTIONS = ['length', 'maxEntities', 'width', 'alpha'] as const;

/** Checks trail options and fills in defaults. @throws TypeError | RangeError naming the bad option and value. */
export function resolveTrailOptions(where: string, options: TrailOptions = {}): ResolvedTrailOptions {
  assertKnownKeys(where, options, TRAIL_OPTIONS);
  const length = options.length ?? 30;
  assertInteger(where, 'trails.length', length, 2, 1024);
  const maxEntities = options.maxEntities ?? 256;
  assertInteger(where, 'trails.maxEntities', maxEntities, 1, 100_000);
  const width = options.width ?? 2;
  assertInteger(where, 'trails.width', width, 1, 64);
  const alpha = options.alpha ?? 0.55;
  assertInRange(where, 'trails.alpha', alpha, Number.MIN_VALUE, 1);
  if (alpha === 0) throw new RangeError(`${where}: trails.alpha must be in (0, 1], got 0`);
  return { length, maxEntities, width, alpha };
}

/**
 * A white texture whose opacity rises linearly from 0 (left) to `alpha` (right); its height is the
 * rope width (pixi's MeshRope takes its thickness from the texture height).
 */
function createFadeTexture(width: number, alpha: number): Texture {
  const w = 64;
  const { canvas, ctx } = canvas2d('TrailLayer', w, width);
  const gradient = ctx.createLinearGradient(0, 0, w, 0);
  gradient.addColorStop(0, 'rgba(255,255,255,0)');
  gradient.addColorStop(1, `rgba(255,255,255,${alpha})`);
  ctx.fillStyle = gradient;
  ctx.fillRect(0, 0, w, width);
  return new Texture({ source: new CanvasSource({ resource: canvas, scaleMode: 'linear' }) });
}

/**
 * Trails: a fading polyline through each ball's recent positions (m, kept in a ring buffer per trail
 * slot), ending at the ball's interpolated position. Each trail is a pixi `MeshRope` along a fade
 * texture, tinted with the ball's colour. Everything is allocated once for `maxEntities` slots;
 * a frame only rewrites point coordinates (no allocation).
 */
export class TrailLayer implements BallLayerListener {
  /** Parent of the trail meshes; sits under the balls. */
  readonly container = new Container({ label: 'trails' });
  /** The options in use. */
  readonly options: ResolvedTrailOptions;
  private slotOf: Int32Array;
  private readonly free: Int32Array;
  private freeCount: number;
  private readonly history: Float64Array;
  private readonly head: Int32Array;
  private readonly filled: Int32Array;
  private readonly ropes: MeshRope[] = [];
  /** Per slot: tint last given to its rope (0xRRGGBB), -1 = none. */
  private tints = new Float64Array(0);
  private readonly ropePoints: PointData[][] = [];
  private readonly texture: Texture;
  private world: PhysicsWorld | null = null;

  /** @param options resolved options (see `resolveTrailOptions`). @param capacity the world's capacity. */
  constructor(options: ResolvedTrailOptions, capacity: number) {
    this.options = options;
    const m = options.maxEntities;
    this.slotOf = new Int32Array(capacity + 1);
    this.free = new Int32Array(m);
    this.freeCount = 0;
    this.history = new Float64Array(m * options.length * 2);
    this.head = new Int32Array(m);
    this.filled = new Int32Array(m);
    this.texture = createFadeTexture(options.width, options.alpha);
    this.tints = new Float64Array(m).fill(-1);
    this.resetSlots();
  }

  /** Binds to `world` (its capacity sizes the per-entity table) and drops every trail. */
  bind(world: PhysicsWorld): void {
    this.world = world;
    if (this.slotOf.length !== world.capacity + 1) this.slotOf = new Int32Array(world.capacity + 1);
    else this.slotOf.fill(0);
    this.resetSlots();
  }

  /** Number of trails in use. */
  get active(): number {
    return this.options.maxEntities - this.freeCount;
  }

  /** BallLayerListener: gives `eid` a trail slot if one is free, starting at its current position. */
  added(eid: number): void {
    if (this.freeCount === 0 || !this.world) return;
    const s = this.free[--this.freeCount]!;
    this.slotOf[eid] = s + 1;
    this.head[s] = 0;
    this.filled[s] = 0;
    const P = this.world.components.Position;
    this.push(s, P.x[eid]!, P.y[eid]!);
  }

  /** BallLayerListener: frees the trail slot of `eid`. */
  removed(eid: number): void {
    const s = this.slotOf[eid]! - 1;
    if (s < 0) return;
    this.slotOf[eid] = 0;
    this.free[this.freeCount++] = s;
    const rope = this.ropes[s];
    if (rope) rope.visible = false;
  }

  /** Appends every trailed ball's current Position (m) to its trail; call once per frame in which the world stepped. */
  record(world: PhysicsWorld, balls: BallLayer): void {
    const px = world.components.Position.x,
      py = world.components.Position.y;
    const eids = balls.eids,
      slotOf = this.slotOf;
    for (let i = 0; i < balls.count; i++) {
      const e = eids[i]!;
      const s = slotOf[e]! - 1;
      if (s >= 0) this.push(s, px[e]!, py[e]!);
    }
  }

  /** Places every trail: history oldest to newest, then the ball's interpolated position for `alpha`. */
  draw(world: PhysicsWorld, balls: BallLayer, camera: Camera, alpha: number): void {
    const L = this.options.length;
    const hist = this.history;
    const c = world.components;
    const px = c.Position.x,
      py = c.Position.y,
      ox = c.PreviousPosition.x,
      oy = c.PreviousPosition.y;
    const ppm = camera.pixelsPerMeter,
      x0 = camera.originX,
      y0 = camera.originY;
    const eids = balls.eids,
      slotOf = this.slotOf;
    for (let i = 0; i < balls.count; i++) {
      const e = eids[i]!;
      const s = slotOf[e]! - 1;
      if (s < 0) continue;
      const rope = this.rope(s);
      rope.visible = true;
      const color = balls.shownColor(e);
      if (this.tints[s] !== color) {
        this.tints[s] = color;
        rope.tint = color;
      }
      const pts = this.ropePoints[s]!;
      const n = this.filled[s]!;
      const start = (this.head[s]! - n + L) % L; // oldest stored point
      const pad = L - n; // unfilled history collapses onto the oldest point (zero-length, transparent end)
      for (let j = 0; j < L; j++) {
        const k = j < pad ? 0 : j - pad;
        const a = s * L * 2 + ((start + k) % L) * 2;
        const p = pts[j]!;
        p.x = x0 + hist[a]! * ppm;
        p.y = y0 - hist[a + 1]! * ppm;
      }
      const last = pts[L]!;
      last.x = x0 + (ox[e]! + (px[e]! - ox[e]!) * alpha) * ppm;
      last.y = y0 - (oy[e]! + (py[e]! - oy[e]!) * alpha) * ppm;
    }
  }

  /** Releases the meshes and the fade texture. */
  destroy(): void {
    this.container.destroy({ children: true });
    this.texture.destroy(true);
  }

  private resetSlots(): void {
    const m = this.options.maxEntities;
    for (let i = 0; i < m; i++) this.free[i] = m - 1 - i;
    this.freeCount = m;
    for (const rope of this.ropes) rope.visible = false;
  }

  /** The rope of slot `s`, created on first use (and kept for reuse). */
  private rope(s: number): MeshRope {
    let rope = this.ropes[s];
    if (!rope) {
      for (let k = this.ropes.length; k <= s; k++) {
        const points: PointData[] = [];
        for (let j = 0; j <= this.options.length; j++) points.push({ x: 0, y: 0 });
        const r = new MeshRope({ texture: this.texture, points });
        r.visible = false;
        this.ropes.push(r);
        this.ropePoints.push(points);
        this.container.addChild(r);
      }
      rope = this.ropes[s]!;
    }
    return rope;
  }

  private push(s: number, x: number, y: number): void {
    const L = this.options.length;
    const h = this.head[s]!;
    const a = (s * L + h) * 2;
    this.history[a] = x;
    this.history[a + 1] = y;
    this.head[s] = (h + 1) % L;
    if (this.filled[s]! < L) this.filled[s] = this.filled[s]! + 1;
  }
}
