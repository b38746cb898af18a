import type { PhysicsWorld } from '@bitphysics/physics';
import { assertInRange, assertInteger, assertKnownKeys, assertNonNegative } from '@bitphysics/physics/validate';
import { BufferAttribute, BufferGeometry, DynamicDrawUsage, LineBasicMaterial, LineSegments } from 'three';
import { hexToLinear } from './math.js';

/** Options of the trail layer (`WorldRenderer3DOptions.trails`, `WorldRenderer3D.setTrails`). Unknown fields are rejected. */
export interface TrailOptions {
  /**
   * Points kept per trail, integer in [2, 8192]. Default 60 (one second at 60 Hz when `spacing` is 0).
   * A point is recorded once per rendered frame in which the world stepped (and, with `spacing`,
   * only after the body moved far enough).
   */
  length?: number;
  /**
   * Most entities with a trail at once, integer in [1, 100_000]: the first ones shown get one, and a
   * trail frees when its entity goes. length x maxEntities must not exceed 4_194_304 points. Memory,
   * allocated once: about 120 bytes a point. Default 256.
   */
  maxEntities?: number;
  /** Opacity of the newest end of a trail, in (0, 1]; it fades linearly to 0 at the oldest end. Default 0.6. */
  alpha?: number;
  /**
   * Least distance, m (>= 0), a body moves from its last recorded point before the next is recorded.
   * 0 (default) records every stepped frame. A spacing makes a trail cover a distance instead of a
   * time (an orbit of the Moon in a few hundred points, whatever the time scale).
   */
  spacing?: number;
}

/** Fully resolved trail options. */
export type ResolvedTrailOptions = Required<TrailOptions>;

const TRAIL_OPTIONS = ['length', 'maxEntities', 'alpha', 'spacing'] as const;

/** Most trail points (length x maxEntities) a trail layer may hold. */
export const MAX_TRAIL_POINTS = 4_194_304;

/** Checks trail options and fills in defaults. @throws TypeError | RangeError naming the bad option and value. */
export function resolveTrailOptions(where: string, options: TrailOptions = {}): ResolvedTrailOptions {
  assertKnownKeys(where, options, TRAIL_OPTIONS);
  const length = options.length ?? 60;
  assertInteger(where, 'trails.length', length, 2, 8192);
  const maxEntities = options.maxEntities ?? 256;
  assertInteger(where, 'trails.maxEntities', maxEntities, 1, 100_000);
  if (length * maxEntities > MAX_TRAIL_POINTS) {
    throw new RangeError(`${where}: trails.length x trails.maxEntities must be <= ${MAX_TRAIL_POINTS}, got ${length} x ${maxEntities}`);
  }
  const alpha = options.alpha ?? 0.6;
  assertInRange(where, 'trails.alpha', alpha, 0, 1);
  if (alpha === 0) throw new RangeError(`${where}: trails.alpha must be in (0, 1], got 0`);
  const spacing = options.spacing ?? 0;
  assertNonNegative(where, 'trails.spacing', spacing);
  return { length, maxEntities, alpha, spacing };
}

/**
 * Trails: a fading polyline through each trailed entity's recent positions (m, a ring buffer per
 * trail), ending at the entity's interpolated position. Every trail is part of one `LineSegments`
 * with per-vertex RGBA (the alpha fades from 0 at the oldest point to `alpha` at the newest), so all
 * trails are one draw call. Trails are a dense list (swap-remove), so the drawn range is exactly the
 * trails in use. Everything is allocated once; a frame rewrites vertex positions only.
 * Lines are one pixel wide (WebGL ignores line widths).
 */
export class TrailLayer {
  /** The line object; the renderer adds it to its root. */
  readonly object: LineSegments;
  /** The options in use. */
  readonly options: ResolvedTrailOptions;
  private readonly geometry = new BufferGeometry();
  private readonly material: LineBasicMaterial;
  private readonly positions: Float32Array;
  private readonly colors: Float32Array;
  private readonly positionAttr: BufferAttribute;
  private readonly colorAttr: BufferAttribute;
  /** Per entity: trail slot + 1 (0 = none). */
  private slotOf: Int32Array;
  /** Per slot: owner entity, ring head, points filled, colour shown (-1 = none yet). */
  private readonly owner: Int32Array;
  private readonly head: Int32Array;
  private readonly filled: Int32Array;
  private readonly shownColor: Float64Array;
  /** Per slot: `length` points, xyz, m. */
  private readonly history: Float64Array;
  private active = 0;
  private readonly scratch = new Float64Array(3);

  /** @param options resolved options (see `resolveTrailOptions`). @param capacity the world's capacity. */
  constructor(options: ResolvedTrailOptions, capacity: number) {
    this.options = options;
    const m = options.maxEntities,
      L = options.length;
    this.slotOf = new Int32Array(capacity + 1);
    this.owner = new Int32Array(m);
    this.head = new Int32Array(m);
    this.filled = new Int32Array(m);
    this.shownColor = new Float64Array(m).fill(-1);
    this.history = new Float64Array(m * L * 3);
    this.positions = new Float32Array(m * L * 2 * 3);
    this.colors = new Float32Array(m * L * 2 * 4);
    this.positionAttr = new BufferAttribute(this.positions, 3);
    this.positionAttr.setUsage(DynamicDrawUsage);
    this.colorAttr = new BufferAttribute(this.colors, 4);
    this.colorAttr.setUsage(DynamicDrawUsage);
    this.geometry.setAttribute('position', this.positionAttr);
    this.geometry.setAttribute('color', this.colorAttr);
    this.geometry.setDrawRange(0, 0);
    this.material = new LineBasicMaterial({ vertexColors: true, transparent: true, depthWrite: false });
    this.object = new LineSegments(this.geometry, this.material);
    this.object.name = 'trails';
    this.object.frustumCulled = false;
    this.object.renderOrder = 1;
  }

  /** Trails in use. */
  get count(): number {
    return this.active;
  }

  /** Whether entity `eid` has a trail. */
  has(eid: number): boolean {
    return eid > 0 && eid < this.slotOf.length && this.slotOf[eid] !== 0;
  }

  /** Drops every trail and sizes the per-entity table for a world of `capacity` entities. */
  reset(capacity: number): void {
    if (this.slotOf.length !== capacity + 1) this.slotOf = new Int32Array(capacity + 1);
    else this.slotOf.fill(0);
    this.active = 0;
    this.shownColor.fill(-1);
    this.geometry.setDrawRange(0, 0);
  }

  /** Gives `eid` a trail starting at its current position (if a slot is free). */
  added(world: PhysicsWorld, eid: number): void {
    if (this.active >= this.options.maxEntities || this.slotOf[eid] !== 0) return;
    const s = this.active++;
    this.slotOf[eid] = s + 1;
    this.owner[s] = eid;
    this.head[s] = 0;
    this.filled[s] = 0;
    this.shownColor[s] = -1;
    const P = world.components.Position;
    this.push(s, P.x[eid]!, P.y[eid]!, P.z[eid]!);
  }

  /** Frees the trail of `eid` (the last trail moves into its slot). */
  removed(eid: number): void {
    const s = this.slotOf[eid]! - 1;
    if (s < 0) return;
    this.slotOf[eid] = 0;
    const last = --this.active;
    if (s !== last) {
      const L = this.options.length;
      const moved = this.owner[last]!;
      this.owner[s] = moved;
      this.slotOf[moved] = s + 1;
      this.head[s] = this.head[last]!;
      this.filled[s] = this.filled[last]!;
      this.shownColor[s] = this.shownColor[last]!;
      this.history.copyWithin(s * L * 3, last * L * 3, (last + 1) * L * 3);
      this.colors.copyWithin(s * L * 8, last * L * 8, (last + 1) * L * 8);
      this.colorAttr.needsUpdate = true;
    }
  }

  /** Appends every trailed entity's Position (m) to its trail (honouring `spacing`); call once per frame in which the world stepped. */
  record(world: PhysicsWorld): void {
    const P = world.components.Position;
    const px = P.x,
      py = P.y,
      pz = P.z;
    const L = this.options.length,
      sp2 = this.options.spacing * this.options.spacing;
    const hist = this.history;
    for (let s = 0; s < this.active; s++) {
      const e = this.owner[s]!;
      const x = px[e]!,
        y = py[e]!,
        z = pz[e]!;
      if (sp2 > 0) {
        const a = (s * L + ((this.head[s]! - 1 + L) % L)) * 3;
        const dx = x - hist[a]!,
          dy = y - hist[a + 1]!,
          dz = z - hist[a + 2]!;
        if (dx * dx + dy * dy + dz * dz < sp2) continue;
      }
      this.push(s, x, y, z);
    }
  }

  /**
   * Writes every trail's vertices for the frame: history oldest to newest, then the entity's
   * interpolated position for `alpha`; `colors[eid]` is each entity's colour (0xRRGGBB).
   * @param scale scene units per metre.
   */
  draw(world: PhysicsWorld, alpha: number, scale: number, colors: Uint32Array): void {
    const c = world.components;
    const px = c.Position.x,
      py = c.Position.y,
      pz = c.Position.z;
    const ox = c.PreviousPosition.x,
      oy = c.PreviousPosition.y,
      oz = c.PreviousPosition.z;
    const L = this.options.length;
    const hist = this.history,
      pos = this.positions;
    let colorsDirty = false;
    for (let s = 0; s < this.active; s++) {
      const e = this.owner[s]!;
      const color = colors[e]!;
      if (this.shownColor[s] !== color) {
        this.shownColor[s] = color;
        this.writeColors(s, color);
        colorsDirty = true;
      }
      const n = this.filled[s]!;
      const start = (this.head[s]! - n + L) % L;
      const pad = L - n;
      const base = s * L * 6;
      // Point j (0..L-1) of the trail: unfilled history collapses onto the oldest stored point.
      let prevX = 0,
        prevY = 0,
        prevZ = 0;
      for (let j = 0; j <= L; j++) {
        let x: number, y: number, z: number;
        if (j < L) {
          const k = j < pad ? 0 : j - pad;
          const a = (s * L + ((start + k) % L)) * 3;
          x = hist[a]! * scale;
          y = hist[a + 1]! * scale;
          z = hist[a + 2]! * scale;
        } else {
          x = (ox[e]! + (px[e]! - ox[e]!) * alpha) * scale;
          y = (oy[e]! + (py[e]! - oy[e]!) * alpha) * scale;
          z = (oz[e]! + (pz[e]! - oz[e]!) * alpha) * scale;
        }
        if (j > 0) {
          // Segment j - 1 runs from point j - 1 to point j.
          const v = base + (j - 1) * 6;
          pos[v] = prevX;
          pos[v + 1] = prevY;
          pos[v + 2] = prevZ;
          pos[v + 3] = x;
          pos[v + 4] = y;
          pos[v + 5] = z;
        }
        prevX = x;
        prevY = y;
        prevZ = z;
      }
    }
    const used = this.active * L * 2;
    this.geometry.setDrawRange(0, used);
    if (used > 0) {
      this.positionAttr.clearUpdateRanges();
      this.positionAttr.addUpdateRange(0, used * 3);
      this.positionAttr.needsUpdate = true;
    }
    if (colorsDirty) this.colorAttr.needsUpdate = true;
  }

  /** Frees the geometry and material. */
  destroy(): void {
    this.object.removeFromParent();
    this.geometry.dispose();
    this.material.dispose();
  }

  private writeColors(s: number, color: number): void {
    const L = this.options.length,
      a = this.options.alpha;
    const rgb = this.scratch;
    hexToLinear(color, rgb, 0);
    const col = this.colors;
    for (let j = 0; j < L; j++) {
      const v = (s * L + j) * 8;
      col[v] = rgb[0]!;
      col[v + 1] = rgb[1]!;
      col[v + 2] = rgb[2]!;
      col[v + 3] = (a * j) / L;
      col[v + 4] = rgb[0]!;
      col[v + 5] = rgb[1]!;
      col[v + 6] = rgb[2]!;
      col[v + 7] = (a * (j + 1)) / L;
    }
  }

  private push(s: number, x: number, y: number, z: number): void {
    const L = this.options.length;
    const h = this.head[s]!;
    const a = (s * L + h) * 3;
    this.history[a] = x;
    this.history[a + 1] = y;
    this.history[a + 2] = z;
    this.head[s] = (h + 1) % L;
    if (this.filled[s]! < L) this.filled[s] = this.filled[s]! + 1;
  }
}
