import { isAlive, type PhysicsWorld, slotOf } from '@bitphysics/physics';
import {
  assertBoolean,
  assertFinite,
  assertInteger,
  assertKnownKeys,
  assertNonNegative,
  assertPositive,
  describe,
} from '@bitphysics/physics/validate';
import { type ColorInput, entitySlot, parseColor, parsePalette } from '@bitphysics/render-common';
import { query } from 'bitecs';
import { type Application, Container, type Texture } from 'pixi.js';
import { BallLayer, type BallMode } from './balls.js';
import { assertWorldRect, Camera, type Point2, type WorldRect } from './camera.js';
import { type DebugCounts, DebugLayer, type DebugOptions, resolveDebugOptions } from './debug.js';
import { ParticleLayer, type ParticleLayerOptions, resolveParticleLayerOptions } from './particles.js';
import { ShapeLayer } from './shapes.js';
import { createBallTexture } from './textures.js';
import { resolveTrailOptions, TrailLayer, type TrailOptions } from './trails.js';
import { WallLayer } from './walls.js';

/** Options of `new WorldRenderer`. Every field is optional; unknown fields are rejected. */
export interface WorldRendererOptions {
  /**
   * A pixi Application to attach to: the renderer's `root` is added to `app.stage`, the screen size
   * is taken from `app.screen`, and the camera follows every resize of `app.renderer`.
   * Without it, add `root` to a stage yourself and call `resize`.
   */
  app?: Application;
  /** Screen width, CSS px, > 0, when no `app` is given. Default 800. */
  width?: number;
  /** Screen height, CSS px, > 0, when no `app` is given. Default 600. */
  height?: number;
  /**
   * Fixed scale, px/m, > 0. When given (and `view` is not), the world origin starts at the
   * bottom-left corner of the screen and the scale never changes on its own.
   */
  pixelsPerMeter?: number;
  /**
   * What the camera keeps in view, refitted on every resize: a world rectangle in m, or
   * `'boundary'` to fit the world's boundary box (`setBoundary`), following it when it changes.
   * Default `'boundary'` unless `pixelsPerMeter` is given. With `'boundary'` and no boundary set the
   * camera uses a fixed 50 px/m until one is.
   */
  view?: WorldRect | 'boundary';
  /** Margin kept free around the fitted view, CSS px, >= 0. Default 16. */
  padding?: number;
  /**
   * Ball drawing path: `'sprites'`, `'particles'` (pixi v8 ParticleContainer + Particle, one shared
   * texture; for thousands of balls) or `'auto'`: particles from `particleThreshold` balls on,
   * sprites again below 80% of it. Default `'auto'`.
   */
  balls?: BallMode | 'auto';
  /** Ball count at which `'auto'` switches to particles, integer in [1, 16_777_216]. Default 1000. */
  particleThreshold?: number;
  /** Turn balls that have an Angle component and draw the rotation mark on them. Default true. */
  rotation?: boolean;
  /** Seed of the per-entity colours, a finite number. Default 1. */
  colorSeed?: number;
  /** Colours the seeded colours are picked from (0xRRGGBB or '#rrggbb'); default: free hues. Non-empty if given. */
  palette?: readonly ColorInput[];
  /** Colour of static segments. Default 0x8d99ae. */
  segmentColor?: ColorInput;
  /** Colour of the boundary box outline. Default 0x5c677d. */
  boundaryColor?: ColorInput;
  /** Trails: `true` for defaults, an options object, or `false` (default) for none. */
  trails?: boolean | TrailOptions;
  /** Debug overlay: `true` for defaults, an options object, or `false` (default) for none. */
  debug?: boolean | DebugOptions;
  /** Edge of the shared ball texture, px, integer in [8, 1024]. Default 128. */
  textureSize?: number;
  /**
   * Particle layer (entities with Particle and Position, see `ParticleLayer`), drawn above the
   * trails and below the balls: `true` for defaults, layer options, or `false` (default) for none.
   * Particles that also have a Ball (emitted with a collider radius) are drawn by the ball layer too.
   */
  particles?: boolean | ParticleLayerOptions;
}

const RENDERER_OPTIONS = [
  'app',
  'width',
  'height',
  'pixelsPerMeter',
  'view',
  'padding',
  'balls',
  'particleThreshold',
  'rotation',
  'colorSeed',
  'palette',
  'segmentColor',
  'boundaryColor',
  'trails',
  'debug',
  'textureSize',
  'particles',
] as const;

/** What the renderer drew in its last frame (one object, updated in place by `render`). */
export interface RendererStats {
  /** Balls shown. */
  balls: number;
  /** The ball path in use. */
  mode: BallMode;
  /** Static segments drawn. */
  segments: number;
  /** Contacts drawn by the debug layer (0 when it is off). */
  contacts: number;
  /** Velocity arrows drawn by the debug layer (0 when it is off). */
  arrows: number;
  /** Springs, joints, planes, field regions and emitters drawn by the debug layer (all 0 when it is off). */
  scenery: DebugCounts;
  /** Frames rendered since creation. */
  frames: number;
}

/** Validates particle layer options up front (before anything is allocated); returns them as given. */
function particleLayerOptions(where: string, options: true | ParticleLayerOptions): ParticleLayerOptions {
  if (options === true) return {};
  if (options === null || typeof options !== 'object')
    throw new TypeError(`${where}: particles must be a boolean or an options object, got ${describe(options)}`);
  resolveParticleLayerOptions(where, options);
  return options;
}

function checkWorld(where: string, world: unknown): asserts world is PhysicsWorld {
  const w = world as Partial<PhysicsWorld> | null;
  if (
    w === null ||
    typeof w !== 'object' ||
    typeof w.capacity !== 'number' ||
    typeof w.components !== 'object' ||
    !(w.spawnStamp instanceof Uint32Array)
  ) {
    throw new TypeError(`${where}: world must be a physics world from createPhysicsWorld, got ${describe(world)}`);
  }
  if (w.dimensions !== 2) throw new RangeError(`${where}: world must be 2D (dimensions 2), got dimensions ${describe(w.dimensions)}`);
}

/**
 * The 2D renderer: follows one physics world and draws it with pixi.js 8.
 *
 * - Balls (entities with Position and Ball) gain a display object when they appear and lose it when
 *   they are removed; every frame they are placed at PreviousPosition + (Position -
 *   PreviousPosition) alpha, with alpha from the fixed-step loop, and turned by their Angle.
 * - Shapes of 2D bodies (`addBox`, `addShape`: boxes, polygons, capsules, circles) are drawn filled
 *   with their colour and outlined, at their bodies' interpolated poses; sensors as outlines only.
 * - Static segments and the boundary box are drawn as walls; joints, springs and planes are drawn by
 *   the debug layer (`debug: true`).
 * - Metres become CSS pixels through `camera` (scale `pixelsPerMeter`, y flipped); nothing else in
 *   the framework converts units.
 * - Optional trails and a debug overlay (velocities, contacts, wall outlines, springs, joints, planes,
 *   field regions, emitters).
 *
 * Layers, bottom to top: walls, trails, particles (optional), balls, debug. The hot path (`render`) allocates nothing per
 * entity; trails and debug rebuild pixi Graphics, whose cost is bounded by their options.
 *
 * @example
 * const renderer = new WorldRenderer(world, { app, view: 'boundary', trails: true });
 * loop: const { alpha } = fixedLoop.advance(dt); renderer.render(alpha); app.render();
 */
export class WorldRenderer {
  /** Parent of every layer; add it to a stage (done for you when `app` is given). */
  readonly root = new Container({ label: 'bitphysics-world' });
  /** The camera: metres to pixels, y flipped, fitted view. */
  readonly camera: Camera;
  /** Statistics of the last frame (updated in place). */
  readonly stats: RendererStats = {
    balls: 0,
    mode: 'sprites',
    segments: 0,
    contacts: 0,
    arrows: 0,
    scenery: { springs: 0, joints: 0, planes: 0, fields: 0, emitters: 0 },
    frames: 0,
  };
  private worldRef: PhysicsWorld;
  private readonly texture: Texture;
  private readonly balls: BallLayer;
  /** An entity's user colour or -1 (the ball layer keeps the user colours of every entity), for the shape layer. */
  private readonly userColorOf = (world: PhysicsWorld, slot: number): number => this.balls.userColorOf(world, slot);
  private readonly walls: WallLayer;
  private readonly shapes: ShapeLayer;
  private readonly trailHolder = new Container({ label: 'trail-holder' });
  private readonly debugHolder = new Container({ label: 'debug-holder' });
  private trails: TrailLayer | null = null;
  private debug: DebugLayer | null = null;
  private particleLayer: ParticleLayer | null = null;
  private readonly particleHolder = new Container({ label: 'particle-holder' });
  private readonly ballMode: BallMode | 'auto';
  private readonly threshold: number;
  private readonly fitBoundary: boolean;
  private readonly boxSeen = new Float64Array(5);
  private lastSteps = -1;
  private ballTerms: object[] = [];
  private readonly app: Application | null;
  private readonly onResize: ((width: number, height: number) => void) | null = null;
  private destroyed = false;

  /**
   * @param world a 2D physics world (createPhysicsWorld with dimensions 2).
   * @throws TypeError if `world` is not a physics world, on an unknown option or a value of the wrong type.
   * @throws RangeError if the world is not 2D, on a size, scale or threshold out of range, a bad view
   *   rectangle, an empty palette, or a bad colour.
   */
  constructor(world: PhysicsWorld, options: WorldRendererOptions = {}) {
    const where = 'WorldRenderer';
    checkWorld(where, world);
    assertKnownKeys(where, options, RENDERER_OPTIONS);
    const app = options.app ?? null;
    if (app !== null && (typeof app !== 'object' || !('stage' in app) || !('renderer' in app))) {
      throw new TypeError(`${where}: app must be an initialised pixi Application, got ${describe(app)}`);
    }
    let width = options.width ?? 800;
    let height = options.height ?? 600;
    assertPositive(where, 'width', width);
    assertPositive(where, 'height', height);
    if (app) {
      width = Math.max(1, app.screen.width);
      height = Math.max(1, app.screen.height);
    }
    if (options.pixelsPerMeter !== undefined) assertPositive(where, 'pixelsPerMeter', options.pixelsPerMeter);
    const padding = options.padding ?? 16;
    assertNonNegative(where, 'padding', padding);
    const view = options.view ?? (options.pixelsPerMeter === undefined ? 'boundary' : undefined);
    if (view !== undefined && view !== 'boundary') assertWorldRect(where, 'view', view);
    const mode = options.balls ?? 'auto';
    if (mode !== 'sprites' && mode !== 'particles' && mode !== 'auto') {
      throw new RangeError(`${where}: balls must be 'sprites', 'particles' or 'auto', got ${describe(mode)}`);
    }
    const threshold = options.particleThreshold ?? 1000;
    assertInteger(where, 'particleThreshold', threshold, 1, 16_777_216);
    const rotation = options.rotation ?? true;
    assertBoolean(where, 'rotation', rotation);
    const colorSeed = options.colorSeed ?? 1;
    assertFinite(where, 'colorSeed', colorSeed);
    const palette = parsePalette(where, 'palette', options.palette);
    const segmentColor = parseColor(where, 'segmentColor', options.segmentColor ?? 0x8d99ae);
    const boundaryColor = parseColor(where, 'boundaryColor', options.boundaryColor ?? 0x5c677d);
    const textureSize = options.textureSize ?? 128;
    assertInteger(where, 'textureSize', textureSize, 8, 1024);
    // Validate optional layers before anything is allocated.
    const trailOptions =
      options.trails === undefined || options.trails === false
        ? null
        : resolveTrailOptions(where, options.trails === true ? {} : options.trails);
    const debugOptions =
      options.debug === undefined || options.debug === false
        ? null
        : resolveDebugOptions(where, options.debug === true ? {} : options.debug);
    const particleOptions =
      options.particles === undefined || options.particles === false ? null : particleLayerOptions(where, options.particles);

    this.camera = new Camera({
      width,
      height,
      padding,
      ...(options.pixelsPerMeter !== undefined ? { pixelsPerMeter: options.pixelsPerMeter } : {}),
      ...(view !== undefined && view !== 'boundary' ? { view } : {}),
    });
    this.fitBoundary = view === 'boundary';
    this.boxSeen[0] = -1;
    this.ballMode = mode;
    this.threshold = threshold;
    this.worldRef = world;
    this.texture = createBallTexture({ size: textureSize, mark: rotation });
    this.balls = new BallLayer(this.texture, mode === 'particles' ? 'particles' : 'sprites', rotation, colorSeed, palette);
    this.walls = new WallLayer(segmentColor, boundaryColor);
    this.shapes = new ShapeLayer(colorSeed, palette);
    this.root.addChild(
      this.walls.graphics,
      this.shapes.graphics,
      this.trailHolder,
      this.particleHolder,
      this.balls.container,
      this.debugHolder,
    );
    if (particleOptions) this.installParticles(particleOptions);
    this.bindWorld(world);
    if (trailOptions) this.installTrails(trailOptions);
    if (debugOptions) this.installDebug(debugOptions);

    this.app = app;
    if (app) {
      app.stage.addChild(this.root);
      this.onResize = (w: number, h: number) => {
        if (w > 0 && h > 0) this.camera.resize(w, h);
      };
      app.renderer.on('resize', this.onResize);
    }
  }

  /** The world being drawn. Change it with `setWorld`. */
  get world(): PhysicsWorld {
    return this.worldRef;
  }

  /** The ball path in use now (`'auto'` resolves to one of the two each frame). */
  get mode(): BallMode {
    return this.balls.mode;
  }

  /**
   * Draws a new world from now on (after a reset or a rebuilt scene): every display object of the
   * old one is dropped; user colours and trails start empty.
   * @throws TypeError | RangeError if `world` is not a 2D physics world.
   */
  setWorld(world: PhysicsWorld): void {
    checkWorld('WorldRenderer.setWorld', world);
    this.assertAlive('setWorld');
    this.worldRef = world;
    this.bindWorld(world);
  }

  /**
   * Updates every display object for the state at interpolation factor `alpha` (0 shows the state at
   * the start of the last step, 1 the current state). Call once per frame, then render the stage.
   * @param alpha in [0, 1]; `FixedStepLoop.advance(...).alpha`, or 1 while paused.
   * @throws RangeError if alpha is outside [0, 1] or NaN; Error if the renderer was destroyed.
   */
  render(alpha: number): void {
    if (!(alpha >= 0 && alpha <= 1)) throw new RangeError(`WorldRenderer.render: alpha must be in [0, 1], got ${describe(alpha)}`);
    this.assertAlive('render');
    const world = this.worldRef;
    if (this.fitBoundary) this.followBoundary(world);
    if (this.ballMode === 'auto') this.chooseMode(world);
    const balls = this.balls;
    balls.sync(world);
    const stepped = world.steps !== this.lastSteps;
    this.lastSteps = world.steps;
    this.walls.update(world, this.camera);
    this.shapes.update(world, this.camera, alpha, this.userColorOf);
    const trails = this.trails;
    if (trails) {
      if (stepped) trails.record(world, balls);
      trails.draw(world, balls, this.camera, alpha);
    }
    balls.update(world, this.camera, alpha, stepped);
    this.particleLayer?.render(world, this.camera, alpha);
    const debug = this.debug;
    if (debug) debug.draw(world, balls, this.camera, alpha);
    const s = this.stats;
    s.balls = balls.count;
    s.mode = balls.mode;
    s.segments = this.walls.segments;
    s.contacts = debug ? debug.contactsDrawn : 0;
    s.arrows = debug ? debug.arrowsDrawn : 0;
    const sc = s.scenery,
      dd = debug?.drawn;
    sc.springs = dd ? dd.springs : 0;
    sc.joints = dd ? dd.joints : 0;
    sc.planes = dd ? dd.planes : 0;
    sc.fields = dd ? dd.fields : 0;
    sc.emitters = dd ? dd.emitters : 0;
    s.frames++;
  }

  /**
   * Sets the screen size in CSS px (not needed when an `app` was given: it follows the app).
   * @throws TypeError | RangeError unless both are finite numbers > 0.
   */
  resize(width: number, height: number): void {
    this.camera.resize(width, height);
  }

  /**
   * Where ball `eid` (its handle, as the physics API returns it) was drawn in the last `render`, CSS px
   * from the canvas' top-left corner (for labels that follow a ball, hit tests, tests), written into
   * `out` (allocated if omitted).
   * @returns `out`, or null if the entity has no display object (not a ball, not rendered yet, or
   *   removed: a removed ball's handle never reports the entity that reuses its slot).
   * @throws RangeError if `eid` is not an integer.
   */
  drawnPosition(eid: number, out: Point2 = { x: 0, y: 0 }): Point2 | null {
    if (!Number.isInteger(eid)) throw new RangeError(`WorldRenderer.drawnPosition: eid must be an integer, got ${describe(eid)}`);
    if (!isAlive(this.worldRef, eid)) return null;
    return this.balls.drawnAt(slotOf(eid), out) ? out : null;
  }

  /**
   * Gives entity `eid` a colour of its own (it keeps it until removed; a recycled id starts with a
   * seeded colour again). May be called before the entity is first drawn. `eid` may be a ball, a
   * shape (as `addShape` returns it) or a body: a body's colour fills its shapes that have none of
   * their own.
   * @param color 0xRRGGBB integer or '#rgb' / '#rrggbb'.
   * @throws RangeError if `eid` is not a live entity of the world or the colour is out of range;
   *   TypeError if the colour is neither a number nor a string.
   */
  setColor(eid: number, color: ColorInput): void {
    const slot = this.entitySlot('WorldRenderer.setColor', eid);
    const value = parseColor('WorldRenderer.setColor', 'color', color);
    this.balls.setUserColor(this.worldRef, slot, value);
  }

  /** Returns entity `eid` to its seeded colour. @throws RangeError if `eid` is not a live entity. */
  clearColor(eid: number): void {
    this.balls.clearUserColor(this.worldRef, this.entitySlot('WorldRenderer.clearColor', eid));
  }

  /**
   * The colour of entity `eid`, 0xRRGGBB: its user colour if set, else its seeded colour (a pure
   * function of colorSeed, the id and its spawn stamp).
   * @throws RangeError if `eid` is not a live entity.
   */
  colorOf(eid: number): number {
    return this.balls.colorOf(this.worldRef, this.entitySlot('WorldRenderer.colorOf', eid));
  }

  /**
   * Turns trails on (`true` or options) or off (`false`). Turning them on starts every trail empty.
   * @throws TypeError | RangeError on bad options (named with their value).
   */
  setTrails(options: boolean | TrailOptions): void {
    this.assertAlive('setTrails');
    const resolved = options === false ? null : resolveTrailOptions('WorldRenderer.setTrails', options === true ? {} : options);
    if (this.trails) {
      this.balls.listener = null;
      this.trailHolder.removeChildren();
      this.trails.destroy();
      this.trails = null;
    }
    if (resolved) this.installTrails(resolved);
  }

  /** Whether trails are on. */
  get trailsEnabled(): boolean {
    return this.trails !== null;
  }

  /**
   * Turns the debug overlay on (`true` or options) or off (`false`).
   * @throws TypeError | RangeError on bad options (named with their value).
   */
  setDebug(options: boolean | DebugOptions): void {
    this.assertAlive('setDebug');
    const resolved = options === false ? null : resolveDebugOptions('WorldRenderer.setDebug', options === true ? {} : options);
    if (this.debug) {
      this.debugHolder.removeChildren();
      this.debug.destroy();
      this.debug = null;
    }
    if (resolved) this.installDebug(resolved);
  }

  /**
   * The particle layer, or null when particles are off. Its `stats` say how many particles were drawn;
   * `setBlend` and `setTrails` change it in place.
   */
  get particles(): ParticleLayer | null {
    return this.particleLayer;
  }

  /**
   * Turns the particle layer on (`true` or options, replacing the current layer) or off (`false`).
   * @throws TypeError | RangeError on bad options (named with their value); Error after `destroy`.
   */
  setParticles(options: boolean | ParticleLayerOptions): void {
    this.assertAlive('setParticles');
    const resolved = options === false ? null : particleLayerOptions('WorldRenderer.setParticles', options);
    if (this.particleLayer) {
      this.particleLayer.destroy();
      this.particleLayer = null;
    }
    if (resolved) {
      this.installParticles(resolved);
      this.particleLayer!.bind(this.worldRef);
    }
  }

  /** Whether the debug overlay is on. */
  get debugEnabled(): boolean {
    return this.debug !== null;
  }

  /**
   * Removes `root` from its parent, stops following the app's resizes and frees every display
   * object and the shared texture. The renderer cannot be used afterwards (methods throw Error).
   */
  destroy(): void {
    if (this.destroyed) return;
    this.destroyed = true;
    if (this.app && this.onResize) this.app.renderer.off('resize', this.onResize);
    this.root.parent?.removeChild(this.root);
    this.trails?.destroy();
    this.debug?.destroy();
    this.particleLayer?.destroy();
    this.balls.destroy();
    this.walls.destroy();
    this.shapes.destroy();
    this.root.destroy({ children: true });
    this.texture.destroy(true);
  }

  private bindWorld(world: PhysicsWorld): void {
    this.ballTerms = [world.components.Position, world.components.Ball];
    this.balls.bind(world);
    this.walls.bind(world);
    this.trails?.bind(world);
    this.particleLayer?.bind(world);
    this.lastSteps = -1;
    this.boxSeen[0] = -1;
  }

  private installTrails(options: ReturnType<typeof resolveTrailOptions>): void {
    const trails = new TrailLayer(options, this.worldRef.capacity);
    trails.bind(this.worldRef);
    this.trails = trails;
    this.trailHolder.addChild(trails.container);
    this.balls.listener = trails;
    // Balls already shown get a trail too.
    for (let i = 0; i < this.balls.count; i++) trails.added(this.balls.eids[i]!);
  }

  private installParticles(options: ParticleLayerOptions): void {
    const layer = new ParticleLayer(options);
    this.particleLayer = layer;
    this.particleHolder.addChild(layer.container);
  }

  private installDebug(options: ReturnType<typeof resolveDebugOptions>): void {
    const debug = new DebugLayer(options);
    this.debug = debug;
    this.debugHolder.addChild(debug.graphics);
  }

  private followBoundary(world: PhysicsWorld): void {
    const box = world.collision.boundary;
    const seen = this.boxSeen;
    const enabled = box.enabled ? 1 : 0;
    if (seen[0] === enabled && seen[1] === box.min[0] && seen[2] === box.min[1] && seen[3] === box.max[0] && seen[4] === box.max[1]) return;
    seen[0] = enabled;
    seen[1] = box.min[0]!;
    seen[2] = box.min[1]!;
    seen[3] = box.max[0]!;
    seen[4] = box.max[1]!;
    if (box.enabled) this.camera.fit({ minX: box.min[0]!, minY: box.min[1]!, maxX: box.max[0]!, maxY: box.max[1]! });
  }

  private chooseMode(world: PhysicsWorld): void {
    // query() returns bitecs' cached result for these terms (the same list BallLayer.sync reads).
    const n = query(world, this.ballTerms).length;
    const mode = this.balls.mode;
    if (mode === 'sprites' && n >= this.threshold) this.balls.setMode('particles');
    else if (mode === 'particles' && n < this.threshold * 0.8) this.balls.setMode('sprites');
  }

  private assertAlive(where: string): void {
    if (this.destroyed) throw new Error(`WorldRenderer.${where}: the renderer was destroyed`);
  }

  /** The slot of entity handle `eid` (per-entity methods take handles; the layers index by slot). */
  private entitySlot(where: string, eid: number): number {
    this.assertAlive(where.replace(/^WorldRenderer\./, ''));
    return entitySlot(where, this.worldRef, eid);
  }
}
