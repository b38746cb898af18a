import type { PhysicsWorld } from '@bitphysics/physics';
import { seededColor } from '@bitphysics/render-common';
import { hasComponent, Not, query } from 'bitecs';
import { Container, Particle, ParticleContainer, Sprite, type Texture } from 'pixi.js';
import type { Camera, Point2 } from './camera.js';
import { ballTextureDiameter } from './textures.js';

/**
 * How balls are drawn:
 * - `'sprites'`: one pixi `Sprite` per ball (pooled). Each is an ordinary display object (filters,
 *   masks, hit tests work); fine up to about a thousand balls.
 * - `'particles'`: one pixi v8 `Particle` per ball inside a single `ParticleContainer` that shares
 *   one circle texture (tint per particle, scale from radius). Positions and rotations are
 *   uploaded each frame, scale and tint only when they change. For thousands of balls.
 */
export type BallMode = 'sprites' | 'particles';

/** Told when the ball layer starts or stops showing an entity (trails keep per-entity history). */
export interface BallLayerListener {
  /** Entity `eid` gained a display object. */
  added(eid: number): void;
  /** Entity `eid` lost its display object (removed from the world, or its id recycled). */
  removed(eid: number): void;
}

/**
 * The balls of one world: tracks every entity with Position and Ball, gives each a display object
 * while it exists, and moves them every frame (interpolated between PreviousPosition and Position).
 * Internal to the renderer; `WorldRenderer` owns one.
 *
 * Per-entity state lives in typed arrays of capacity + 1 indexed by entity id; the shown entities
 * are a dense list (`eids[0..count-1]`) parallel to the display objects. Nothing is allocated per
 * entity per frame: display objects come from pools and are reused.
 */
export class BallLayer {
  /** Parent of the sprite container and the particle container; add it to the stage. */
  readonly container = new Container({ label: 'balls' });
  /** Dense list of the entity ids shown, entries 0..count-1. */
  eids: Int32Array;
  /** Number of balls shown. */
  count = 0;
  /** The path in use; change with `setMode`. */
  mode: BallMode;
  /** Receives added/removed notifications (the trail layer), or null. */
  listener: BallLayerListener | null = null;
  /** Seed of the per-entity colours. */
  colorSeed: number;
  /** Palette the seeded colours are picked from, or null for free hues. */
  palette: readonly number[] | null;

  private readonly spriteContainer = new Container({ label: 'ball-sprites' });
  private readonly particleContainer: ParticleContainer<Particle>;
  private sprites: Sprite[] = [];
  private readonly spritePool: Sprite[] = [];
  private readonly particlePool: Particle[] = [];
  private readonly texture: Texture;
  private readonly textureDiameter: number;
  private readonly rotate: boolean;
  private terms: object[] = [];
  private capacity = 0;
  /** Per entity: dense index + 1, 0 when not shown. */
  private slot = new Int32Array(1);
  /** Per entity: the spawn stamp it had when it was first shown (detects recycled ids). */
  private stamp = new Uint32Array(1);
  /** Per entity: the sync pass that last saw it. */
  private seen = new Uint32Array(1);
  /** Per entity: radius (m) the display scale was computed from. */
  private radiusShown = new Float64Array(1);
  /** Per entity: 1 if it has an Angle component (checked when first shown). */
  private hasAngle = new Uint8Array(1);
  /** Per entity: Angle at the step before the last one seen, and at the last one, rad. */
  private anglePrev = new Float64Array(1);
  private angleCur = new Float64Array(1);
  /** Per entity: colour shown (0xRRGGBB). */
  private colorShown = new Uint32Array(1);
  /** Per entity: user colour, valid while userStamp matches the entity's spawn stamp. */
  private userColor = new Uint32Array(1);
  private userStamp = new Uint32Array(1);
  private pass = 0;
  private cameraVersion = -1;
  private particlesDirty = false;

  /**
   * @param texture the shared ball texture (see `createBallTexture`).
   * @param mode the initial path. @param rotate whether balls with Angle are turned.
   * @param colorSeed seed of the seeded colours. @param palette optional palette (0xRRGGBB values).
   */
  constructor(texture: Texture, mode: BallMode, rotate: boolean, colorSeed: number, palette: readonly number[] | null) {
    this.texture = texture;
    this.textureDiameter = ballTextureDiameter(texture);
    this.mode = mode;
    this.rotate = rotate;
    this.colorSeed = colorSeed;
    this.palette = palette;
    this.eids = new Int32Array(1);
    this.particleContainer = new ParticleContainer<Particle>({
      label: 'ball-particles',
      texture,
      dynamicProperties: { position: true, rotation: rotate, vertex: false, uvs: false, color: false },
    });
    this.container.addChild(this.spriteContainer, this.particleContainer);
  }

  /** Binds to `world` (sizes the per-entity arrays to its capacity) and forgets every ball shown. */
  bind(world: PhysicsWorld): void {
    this.clear();
    const n = world.capacity + 1;
    const c = world.components;
    // Particles that collide have a Ball too, but the particle layer draws them.
    this.terms = [c.Position, c.Ball, Not(c.Particle)];
    if (n !== this.capacity + 1) {
      this.capacity = world.capacity;
      this.eids = new Int32Array(world.capacity);
      this.slot = new Int32Array(n);
      this.stamp = new Uint32Array(n);
      this.seen = new Uint32Array(n);
      this.radiusShown = new Float64Array(n);
      this.hasAngle = new Uint8Array(n);
      this.anglePrev = new Float64Array(n);
      this.angleCur = new Float64Array(n);
      this.colorShown = new Uint32Array(n);
      this.userColor = new Uint32Array(n);
      this.userStamp = new Uint32Array(n);
    } else {
      this.slot.fill(0);
      this.seen.fill(0);
      this.userStamp.fill(0);
    }
    this.pass = 0;
  }

  /** Removes every display object (they go back to the pools). */
  clear(): void {
    for (let i = this.count - 1; i >= 0; i--) this.removeAt(i);
    this.count = 0;
  }

  /**
   * Switches between the sprite and the particle path, moving every shown ball over (tracking,
   * colours and trails are kept).
   */
  setMode(mode: BallMode): void {
    if (mode === this.mode) return;
    const n = this.count;
    // Release the views of the old path.
    if (this.mode === 'sprites') {
      for (let i = 0; i < n; i++) this.releaseSprite(this.sprites[i]!);
      this.sprites.length = 0;
    } else {
      const list = this.particleContainer.particleChildren;
      for (let i = 0; i < list.length; i++) this.particlePool.push(list[i]!);
      list.length = 0;
      this.particleContainer.update();
    }
    this.mode = mode;
    for (let i = 0; i < n; i++) {
      const e = this.eids[i]!;
      this.pushView(this.colorShown[e]!);
    }
    this.cameraVersion = -1;
  }

  /** Whether entity `eid` is shown now. */
  has(eid: number): boolean {
    return eid > 0 && eid <= this.capacity && this.slot[eid] !== 0;
  }

  /**
   * Sets a user colour for `eid` (valid until the entity is removed; a recycled id starts seeded
   * again) and applies it at once if the entity is shown. The caller validates `eid` and `color`.
   */
  setUserColor(world: PhysicsWorld, eid: number, color: number): void {
    this.userColor[eid] = color;
    this.userStamp[eid] = world.spawnStamp[eid]!;
    const s = this.slot[eid]!;
    if (s !== 0 && this.stamp[eid] === world.spawnStamp[eid]) this.applyColor(s - 1, eid, color);
  }

  /** Drops the user colour of `eid`; a shown entity returns to its seeded colour. */
  clearUserColor(world: PhysicsWorld, eid: number): void {
    this.userStamp[eid] = 0;
    const s = this.slot[eid]!;
    if (s !== 0) this.applyColor(s - 1, eid, seededColor(this.colorSeed, eid, world.spawnStamp[eid]!, this.palette));
  }

  /** The user colour (0xRRGGBB) of entity `eid` if one is set for its current life, else -1. */
  userColorOf(world: PhysicsWorld, eid: number): number {
    const st = world.spawnStamp[eid]!;
    return this.userStamp[eid] === st && st !== 0 ? this.userColor[eid]! : -1;
  }

  /** The colour (0xRRGGBB) entity `eid` has or would have when shown: its user colour or its seeded colour. */
  colorOf(world: PhysicsWorld, eid: number): number {
    const st = world.spawnStamp[eid]!;
    if (this.userStamp[eid] === st && st !== 0) return this.userColor[eid]!;
    return seededColor(this.colorSeed, eid, st, this.palette);
  }

  /**
   * Where entity `eid` was drawn by the last `update`, CSS px, written into `out`; false (and `out`
   * untouched) if it is not shown.
   */
  drawnAt(eid: number, out: Point2): boolean {
    if (!this.has(eid)) return false;
    const i = this.slot[eid]! - 1;
    if (this.mode === 'sprites') {
      const sp = this.sprites[i]!;
      out.x = sp.position.x;
      out.y = sp.position.y;
    } else {
      const p = this.particleContainer.particleChildren[i]!;
      out.x = p.x;
      out.y = p.y;
    }
    return true;
  }

  /** The colour (0xRRGGBB) shown for entity `eid` right now; meaningful only while `has(eid)`. */
  shownColor(eid: number): number {
    return this.colorShown[eid]!;
  }

  /** Recomputes every seeded colour (after the seed or palette changed). */
  recolor(world: PhysicsWorld): void {
    for (let i = 0; i < this.count; i++) {
      const e = this.eids[i]!;
      this.applyColor(i, e, this.colorOf(world, e));
    }
  }

  /**
   * Brings the shown set in line with the world: entities with Position and Ball that appeared
   * gain a display object, those removed (or whose id was recycled) lose theirs.
   */
  sync(world: PhysicsWorld): void {
    const ents = query(world, this.terms);
    const pass = ++this.pass;
    const slot = this.slot,
      stamp = this.stamp,
      seen = this.seen,
      spawn = world.spawnStamp;
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      const s = slot[e]!;
      if (s === 0) {
        this.add(world, e);
      } else if (stamp[e] !== spawn[e]) {
        this.removeAt(s - 1);
        this.add(world, e);
      }
      seen[e] = pass;
    }
    const eids = this.eids;
    for (let i = this.count - 1; i >= 0; i--) {
      if (seen[eids[i]!] !== pass) this.removeAt(i);
    }
  }

  /**
   * Moves every display object to its entity's interpolated position:
   * p = PreviousPosition + (Position - PreviousPosition) alpha, then to pixels through the camera.
   * @param alpha interpolation factor in [0, 1] (the caller validates it).
   * @param stepped whether the world advanced since the last call (rotation history is shifted).
   */
  update(world: PhysicsWorld, camera: Camera, alpha: number, stepped: boolean): void {
    const c = world.components;
    const px = c.Position.x,
      py = c.Position.y,
      ox = c.PreviousPosition.x,
      oy = c.PreviousPosition.y;
    const radius = c.Ball.radius,
      angle = c.Angle.value;
    const ppm = camera.pixelsPerMeter,
      x0 = camera.originX,
      y0 = camera.originY;
    const rescale = camera.version !== this.cameraVersion;
    this.cameraVersion = camera.version;
    const k = (2 * ppm) / this.textureDiameter;
    const eids = this.eids,
      n = this.count;
    const shown = this.radiusShown,
      hasAngle = this.hasAngle,
      aPrev = this.anglePrev,
      aCur = this.angleCur;
    const rotate = this.rotate;
    if (this.mode === 'sprites') {
      const sprites = this.sprites;
      for (let i = 0; i < n; i++) {
        const e = eids[i]!;
        const sp = sprites[i]!;
        const ax = ox[e]!,
          ay = oy[e]!;
        sp.position.set(x0 + (ax + (px[e]! - ax) * alpha) * ppm, y0 - (ay + (py[e]! - ay) * alpha) * ppm);
        const r = radius[e]!;
        if (rescale || r !== shown[e]) {
          shown[e] = r;
          sp.scale.set(r * k);
        }
        if (rotate && hasAngle[e] === 1) {
          if (stepped) {
            aPrev[e] = aCur[e]!;
            aCur[e] = angle[e]!;
          }
          const a0 = aPrev[e]!;
          sp.rotation = -(a0 + (aCur[e]! - a0) * alpha);
        }
      }
    } else {
      const list = this.particleContainer.particleChildren;
      let dirty = this.particlesDirty;
      for (let i = 0; i < n; i++) {
        const e = eids[i]!;
        const p = list[i]!;
        const ax = ox[e]!,
          ay = oy[e]!;
        p.x = x0 + (ax + (px[e]! - ax) * alpha) * ppm;
        p.y = y0 - (ay + (py[e]! - ay) * alpha) * ppm;
        const r = radius[e]!;
        if (rescale || r !== shown[e]) {
          shown[e] = r;
          const s = r * k;
          p.scaleX = s;
          p.scaleY = s;
          dirty = true;
        }
        if (rotate && hasAngle[e] === 1) {
          if (stepped) {
            aPrev[e] = aCur[e]!;
            aCur[e] = angle[e]!;
          }
          const a0 = aPrev[e]!;
          p.rotation = -(a0 + (aCur[e]! - a0) * alpha);
        }
      }
      if (dirty) this.particleContainer.update();
      this.particlesDirty = false;
    }
  }

  /** Releases the pools' display objects and the containers. The shared texture is not destroyed. */
  destroy(): void {
    this.clear();
    this.container.destroy({ children: true });
    this.spritePool.length = 0;
    this.particlePool.length = 0;
  }

  private add(world: PhysicsWorld, e: number): void {
    const i = this.count++;
    this.eids[i] = e;
    this.slot[e] = i + 1;
    this.stamp[e] = world.spawnStamp[e]!;
    this.radiusShown[e] = -1;
    const c = world.components;
    const withAngle = hasComponent(world, e, c.Angle);
    this.hasAngle[e] = withAngle ? 1 : 0;
    const a = withAngle ? c.Angle.value[e]! : 0;
    this.anglePrev[e] = a;
    this.angleCur[e] = a;
    const color = this.colorOf(world, e);
    this.colorShown[e] = color;
    this.pushView(color);
    this.listener?.added(e);
  }

  /** Appends a display object of the current path with `color` at dense index count - 1. */
  private pushView(color: number): void {
    if (this.mode === 'sprites') {
      let sp = this.spritePool.pop();
      if (!sp) {
        sp = new Sprite({ texture: this.texture, anchor: 0.5 });
        this.spriteContainer.addChild(sp);
      }
      sp.visible = true;
      sp.tint = color;
      sp.rotation = 0;
      this.sprites.push(sp);
    } else {
      let p = this.particlePool.pop();
      if (!p) p = new Particle({ texture: this.texture, anchorX: 0.5, anchorY: 0.5 });
      p.tint = color;
      p.rotation = 0;
      this.particleContainer.particleChildren.push(p);
      this.particlesDirty = true;
    }
  }

  /** Swap-removes dense entry i (the last entry moves into i). */
  private removeAt(i: number): void {
    const last = this.count - 1;
    const e = this.eids[i]!;
    const moved = this.eids[last]!;
    this.eids[i] = moved;
    this.slot[moved] = i + 1;
    this.slot[e] = 0;
    this.count = last;
    if (this.mode === 'sprites') {
      const list = this.sprites;
      const sp = list[i]!;
      list[i] = list[last]!;
      list.length = last;
      this.releaseSprite(sp);
    } else {
      const list = this.particleContainer.particleChildren;
      const p = list[i]!;
      list[i] = list[last]!;
      list.length = last;
      this.particlePool.push(p);
      this.particlesDirty = true;
      this.particleContainer.update();
    }
    this.listener?.removed(e);
  }

  private releaseSprite(sp: Sprite): void {
    sp.visible = false;
    this.spritePool.push(sp);
  }

  private applyColor(i: number, e: number, color: number): void {
    this.colorShown[e] = color;
    if (this.mode === 'sprites') {
      this.sprites[i]!.tint = color;
    } else {
      this.particleContainer.particleChildren[i]!.tint = color;
      this.particleContainer.update();
    }
  }
}
