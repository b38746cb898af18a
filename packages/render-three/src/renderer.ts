import { entityExists, handleOf, isAlive, type PhysicsWorld, rayCast3D, shapes3DOf, slotOf } from '@bitphysics/physics';
import {
  assertBoolean,
  assertFinite,
  assertInRange,
  assertInteger,
  assertKnownKeys,
  assertNonNegative,
  assertPositive,
  describe,
} from '@bitphysics/physics/validate';
import { type ColorInput, entitySlot, parseColor, parsePalette, seededColor } from '@bitphysics/render-common';
import { hasComponent, query } from 'bitecs';
import {
  BoxGeometry,
  BufferGeometry,
  type Camera,
  Group,
  type Intersection,
  type Material,
  Matrix3,
  Matrix4,
  MeshStandardMaterial,
  type Object3D,
  Raycaster,
  SphereGeometry,
  Vector2,
  Vector3,
} from 'three';
import { InstanceBook, type InstanceBookListener } from './book.js';
import { type DebugCounts, type DebugFrame, DebugLayer, type DebugOptions, resolveDebugOptions } from './debug.js';
import { type BoundaryStyle, EnvironmentLayer } from './environment.js';
import { type GroupKind, InstanceGroup } from './groups.js';
import { type LightOptions, LightRig, resolveLightOptions } from './lights.js';
import { composeInto, equivalentBoxEdges, hexToLinear, rotateBack, slerpInto } from './math.js';
import { type ShapeCounts, type ShapeFrame, ShapeLayer3D } from './shapes.js';
import { resolveTrailOptions, TrailLayer, type TrailOptions } from './trails.js';
import { assertVector } from './validate.js';

/** Options of `new WorldRenderer3D`. Every field is optional; unknown fields are rejected. */
export interface WorldRenderer3DOptions {
  /** An object (usually the three.js `Scene`) the renderer's `root` is added to. Without it, add `root` yourself. */
  scene?: Object3D;
  /**
   * Scene units per metre, > 0. Default 1 (one three.js unit is one metre). Planetary scenes use a
   * small factor (1e-7: one unit is 10 000 km) so float32 GPU coordinates keep their precision.
   * The renderer owns this conversion; nothing else in the framework converts units.
   */
  unitsPerMeter?: number;
  /** Segments around the shared ball sphere, integer in [4, 128] (rings: two thirds of it). Default 24. */
  sphereSegments?: number;
  /** Material of balls (instance colours tint it). Default: a MeshStandardMaterial, roughness 0.35. */
  ballMaterial?: Material;
  /** Material of boxes (bodies without a ball). Default: a MeshStandardMaterial, roughness 0.5. */
  boxMaterial?: Material;
  /**
   * Draw bodies that have an orientation but no ball as boxes: the solid box with the body's mass
   * and principal moments (edges from `equivalentBoxEdges`), or a cube of `boxSize` when the body has
   * no inertia. Default true.
   */
  bodies?: boolean;
  /** Edge of the cube drawn for a body without inertia or ball, m, > 0. Default 0.2 m. */
  boxSize?: number;
  /** Seed of the per-entity colours, a finite number. Default 1. */
  colorSeed?: number;
  /** Colours the seeded colours are picked from (0xRRGGBB or '#rrggbb'); default: free hues. Non-empty if given. */
  palette?: readonly ColorInput[];
  /** Bodies cast and receive shadows (the lights must cast them too). Default true. */
  shadows?: boolean;
  /** A light rig (hemisphere + shadow-casting sun): `true` for defaults, options, or `false` for none. Default true. */
  lights?: boolean | LightOptions;
  /**
   * Box (m) the sun's shadow camera covers when the world has no boundary: { min, max } 3-vectors.
   * Default min (-10, -10, -10), max (10, 10, 10). With a boundary the shadows follow the boundary.
   */
  shadowBounds?: { min: ArrayLike<number>; max: ArrayLike<number> };
  /** How the boundary box is drawn. Default 'glass'. */
  boundary?: BoundaryStyle;
  /** Edge colour of the boundary box. Default 0x8fb3d9. */
  boundaryColor?: ColorInput;
  /** Tint of the glass walls. Default 0x9cc9ff. */
  glassColor?: ColorInput;
  /** Opacity of the glass walls, [0, 1]. Default 0.12. */
  glassOpacity?: number;
  /** Colour of the boundary's floor, of planes and of static triangle meshes and height fields. Default 0x39404f. */
  floorColor?: ColorInput;
  /** Colour of static segments. Default 0x8d99ae. */
  segmentColor?: ColorInput;
  /** Edge of the square drawn for each infinite plane, m, >= 0 (0: three times the boundary, or 40 m). Default 0. */
  planeSize?: number;
  /** Trails: `true` for defaults, an options object, or `false` (default) for none. */
  trails?: boolean | TrailOptions;
  /** Debug layer: `true` for defaults, an options object, or `false` (default) for none. */
  debug?: boolean | DebugOptions;
  /** Instances each group makes room for at first, integer in [1, 16_777_216] (groups double as needed). Default 64. */
  initialInstances?: number;
}

const RENDERER_OPTIONS = [
  'scene',
  'unitsPerMeter',
  'sphereSegments',
  'ballMaterial',
  'boxMaterial',
  'bodies',
  'boxSize',
  'colorSeed',
  'palette',
  'shadows',
  'lights',
  'shadowBounds',
  'boundary',
  'boundaryColor',
  'glassColor',
  'glassOpacity',
  'floorColor',
  'segmentColor',
  'planeSize',
  'trails',
  'debug',
  'initialInstances',
] as const;

/**
 * A user-chosen look for one entity (`WorldRenderer3D.setShape`). Entities with the same geometry
 * and material share one instanced mesh (one draw call).
 */
export interface BodyShape {
  /** The geometry, in metres when `scale` is a number or vector, or a unit shape for 'radius' / 'inertia'. */
  geometry: BufferGeometry;
  /** The material. Default: the renderer's ball material for balls, its box material otherwise. */
  material?: Material;
  /**
   * Scale of the geometry: a number or (x, y, z) factors; `'radius'` (uniform, the ball's radius in
   * m: for unit spheres; an entity without a Ball falls back to 'inertia'); `'inertia'` (the body's
   * equivalent-inertia box edges in m: for unit cubes). Default 'radius' for balls, 'inertia' for
   * other bodies.
   */
  scale?: number | ArrayLike<number> | 'radius' | 'inertia';
  /**
   * Instance tint (multiplies the material's colour and texture). Default: white when a `material`
   * is given (so a textured material shows as is), else the entity's colour. The entity's colour
   * (`setColor`, seeded) still colours its trail.
   */
  color?: ColorInput;
}

/** What the renderer drew in its last frame (one object, updated in place by `render`). */
export interface Renderer3DStats {
  /** Entities shown, over every group. */
  instances: number;
  /** Entities in the ball group. */
  balls: number;
  /** Entities in the box group. */
  boxes: number;
  /** Entities in user-shape groups. */
  custom: number;
  /** Bodies drawn by their 3D shapes (`addShape3D`), and the shapes drawn, by kind (see shapes.ts). */
  shaped: number;
  shapes: ShapeCounts;
  /** Instanced meshes with at least one instance (each is one draw call, plus one per shadow map). */
  meshes: number;
  /** Trails in use (0 when trails are off). */
  trails: number;
  /** Contacts drawn by the debug layer (0 when it is off). */
  contacts: number;
  /** Arrows drawn by the debug layer (0 when it is off). */
  arrows: number;
  /** Springs, joints, planes, field regions and emitters drawn by the debug layer (all 0 when it is off). */
  scenery: DebugCounts;
  /** Frames rendered since creation. */
  frames: number;
}

/** Where `pick` hit an entity. */
export interface PickResult {
  /** The entity hit: its handle, for the physics API (index stores with slotOf). */
  eid: number;
  /**
   * Hit point in physics world coordinates (the renderer's root frame, scene units / unitsPerMeter), m.
   * For a body with a collider it is where the physics has the body now (`rayCast3D`; at most one step
   * from where the last `render` drew it); for a body drawn without a collider it is on its mesh as
   * drawn by the last `render`. See `pick`.
   */
  point: [number, number, number];
  /** Unit outward surface normal at the hit point, in the physics world frame (the renderer's root frame, as `point`, whether the physics' or three.js' ray cast found it). */
  normal: [number, number, number];
  /** Distance from the camera to the hit point, scene units. */
  distance: number;
}

const SCALE_RADIUS = 1;
const SCALE_FIXED = 0;

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
  if (w.dimensions !== 3) throw new RangeError(`${where}: world must be 3D (dimensions 3), got dimensions ${describe(w.dimensions)}`);
}

function isMaterial(value: unknown): value is Material {
  return value !== null && typeof value === 'object' && (value as { isMaterial?: unknown }).isMaterial === true;
}

function isGeometry(value: unknown): value is BufferGeometry {
  return value !== null && typeof value === 'object' && (value as { isBufferGeometry?: unknown }).isBufferGeometry === true;
}

/**
 * The 3D renderer: follows one physics world and draws it with three.js.
 *
 * - Every body with Position and Ball is an instance of one shared sphere `InstancedMesh`, scaled by
 *   its radius; every body with an Orientation and no ball is an instance of one shared box mesh,
 *   scaled to its equivalent-inertia box; `setShape` gives an entity its own geometry and material
 *   (entities sharing both share a mesh). So 10 000 bodies are a handful of draw calls.
 * - A body with 3D shapes (`addShape3D`: sphere, box, capsule, cylinder, hull, compounds) is drawn by
 *   its shapes instead (`ShapeLayer3D`, shapes.ts: instanced per kind and size class, hulls as their
 *   own geometry), each at the body's interpolated pose composed with its placement.
 * - Instances come and go with their entities (swap-remove, see `InstanceBook`); recycled ids are
 *   detected by the world's spawn stamps.
 * - Each frame every instance matrix is written from the state at interpolation factor alpha:
 *   positions lerp from PreviousPosition to Position; orientations slerp between the orientation at
 *   the start and at the end of the last step. Physics keeps no previous orientation, so the renderer
 *   keeps a two-entry history per entity, shifted each frame in which one step ran; when several ran
 *   since the last frame, the start-of-step orientation is recovered by turning back by the angular
 *   velocity over one step (`rotateBack`).
 * - Scenery: the boundary box (glass), infinite planes, static segments; a light rig with shadows;
 *   optional trails and a debug layer (axes, velocity arrows, contacts of the last step, springs,
 *   joints, plane normals, field regions, emitters).
 * - Metres become scene units through `unitsPerMeter`; y is up in both.
 *
 * The hot path (`render`) allocates nothing per entity: matrices and colours are written straight
 * into the instanced meshes' Float32Arrays; per-entity state lives in typed arrays of capacity + 1
 * (about 230 bytes per entity of the world's capacity, allocated once per world size, plus 76 bytes
 * per instance in the meshes).
 *
 * @example
 * const renderer = new WorldRenderer3D(world, { scene, trails: true });
 * each frame: renderer.render(alpha); webgl.render(scene, camera);
 */
export class WorldRenderer3D {
  /** Parent of everything the renderer draws. */
  readonly root = new Group();
  /** Statistics of the last frame (updated in place). */
  readonly stats: Renderer3DStats = {
    instances: 0,
    balls: 0,
    boxes: 0,
    custom: 0,
    shaped: 0,
    shapes: { spheres: 0, boxes: 0, capsules: 0, cylinders: 0, hulls: 0, meshes: 0, triangleMeshes: 0 },
    meshes: 0,
    trails: 0,
    contacts: 0,
    arrows: 0,
    scenery: { springs: 0, joints: 0, planes: 0, fields: 0, emitters: 0 },
    frames: 0,
  };
  /** The light rig, or null when `lights` is false. */
  readonly lights: LightRig | null;
  /** Scene units per metre. */
  readonly unitsPerMeter: number;
  private worldRef: PhysicsWorld;
  private book: InstanceBook;
  private readonly groups: InstanceGroup[] = [];
  private readonly groupIndex = new Map<BufferGeometry, Map<Material, number>>();
  private readonly ballGroup: number;
  private readonly boxGroup: number;
  /** The hidden group of bodies drawn by their 3D shapes (it carries their interpolated poses). */
  private readonly shapedGroup: number;
  private readonly shapes: ShapeLayer3D;
  private readonly shapeFrame: ShapeFrame;
  private readonly instanceRoot = new Group();
  private readonly env: EnvironmentLayer;
  private trails: TrailLayer | null = null;
  private debug: DebugLayer | null = null;
  private readonly owned: Array<{ dispose(): void }> = [];
  private readonly ballMaterial: Material;
  private readonly boxMaterial: Material;
  private readonly drawBodies: boolean;
  private readonly boxSize: number;
  private readonly shadows: boolean;
  private readonly colorSeed: number;
  private readonly palette: number[] | null;
  private readonly shadowMin = new Float64Array(3);
  private readonly shadowMax = new Float64Array(3);
  private readonly boxSeen = new Float64Array(7);
  private lastSteps = -1;
  private terms: { balls: object[]; bodies: object[] } = { balls: [], bodies: [] };
  private destroyed = false;
  /** True while an entity moves between groups (its trail stays). */
  private regrouping = false;
  private readonly listener: InstanceBookListener;
  private readonly edgesScratch = new Float64Array(3);
  /** What the debug layer reads each frame (one object, refilled: no allocation per frame). */
  private readonly debugFrame: DebugFrame;
  // Per-entity state, capacity + 1 long (see allocate).
  private cap = 0;
  private oriented = new Uint8Array(0);
  private qPrev = new Float64Array(0);
  private qCur = new Float64Array(0);
  private drawnPos = new Float64Array(0);
  private drawnQuat = new Float64Array(0);
  private scaleMode = new Uint8Array(0);
  private fixedScale = new Float64Array(0);
  private size = new Float64Array(0);
  private entityColor = new Uint32Array(0);
  private tint = new Int32Array(0);
  private userColor = new Uint32Array(0);
  private userStamp = new Uint32Array(0);
  private shapeGroup = new Int32Array(0);
  private shapeStamp = new Uint32Array(0);
  private shapeScaleMode = new Int8Array(0);
  private shapeScale = new Float64Array(0);
  private shapeTint = new Int32Array(0);
  // Picking scratch (allocated once).
  private readonly raycaster = new Raycaster();
  private readonly ndc = new Vector2();
  private readonly hits: Intersection[] = [];
  private readonly m4 = new Matrix4();
  private readonly m3 = new Matrix3();
  private readonly v3 = new Vector3();

  /**
   * @param world a 3D physics world (createPhysicsWorld with dimensions 3).
   * @throws TypeError if `world` is not a physics world, on an unknown option or a value of the wrong type.
   * @throws RangeError if the world is not 3D, on a scale, size or count out of range, an empty
   *   palette, a bad colour, or a bad boundary style.
   */
  constructor(world: PhysicsWorld, options: WorldRenderer3DOptions = {}) {
    const where = 'WorldRenderer3D';
    checkWorld(where, world);
    assertKnownKeys(where, options, RENDERER_OPTIONS);
    const scene = options.scene;
    if (scene !== undefined && (scene === null || typeof scene !== 'object' || (scene as { isObject3D?: unknown }).isObject3D !== true)) {
      throw new TypeError(`${where}: scene must be a three.js Object3D (a Scene), got ${describe(scene)}`);
    }
    const unitsPerMeter = options.unitsPerMeter ?? 1;
    assertPositive(where, 'unitsPerMeter', unitsPerMeter);
    const segments = options.sphereSegments ?? 24;
    assertInteger(where, 'sphereSegments', segments, 4, 128);
    if (options.ballMaterial !== undefined && !isMaterial(options.ballMaterial))
      throw new TypeError(`${where}: ballMaterial must be a three.js Material, got ${describe(options.ballMaterial)}`);
    if (options.boxMaterial !== undefined && !isMaterial(options.boxMaterial))
      throw new TypeError(`${where}: boxMaterial must be a three.js Material, got ${describe(options.boxMaterial)}`);
    const bodies = options.bodies ?? true;
    assertBoolean(where, 'bodies', bodies);
    const boxSize = options.boxSize ?? 0.2;
    assertPositive(where, 'boxSize', boxSize);
    const colorSeed = options.colorSeed ?? 1;
    assertFinite(where, 'colorSeed', colorSeed);
    const palette = parsePalette(where, 'palette', options.palette);
    const shadows = options.shadows ?? true;
    assertBoolean(where, 'shadows', shadows);
    const lightOptions =
      options.lights === undefined || options.lights === true
        ? resolveLightOptions(where, {})
        : options.lights === false
          ? null
          : resolveLightOptions(where, options.lights);
    if (options.shadowBounds !== undefined) {
      const b = options.shadowBounds;
      if (b === null || typeof b !== 'object') throw new TypeError(`${where}: shadowBounds must be { min, max }, got ${describe(b)}`);
      assertKnownKeys(where, b, ['min', 'max']);
      assertVector(where, 'shadowBounds.min', b.min, 3);
      assertVector(where, 'shadowBounds.max', b.max, 3);
      for (let i = 0; i < 3; i++) {
        if (!(b.max[i]! > b.min[i]!))
          throw new RangeError(`${where}: shadowBounds.max[${i}] must be > shadowBounds.min[${i}], got ${describe(b)}`);
        this.shadowMin[i] = b.min[i]!;
        this.shadowMax[i] = b.max[i]!;
      }
    } else {
      this.shadowMin.fill(-10);
      this.shadowMax.fill(10);
    }
    const boundary = options.boundary ?? 'glass';
    if (boundary !== 'glass' && boundary !== 'edges' && boundary !== 'none') {
      throw new RangeError(`${where}: boundary must be 'glass', 'edges' or 'none', got ${describe(boundary)}`);
    }
    const glassOpacity = options.glassOpacity ?? 0.12;
    assertInRange(where, 'glassOpacity', glassOpacity, 0, 1);
    const planeSize = options.planeSize ?? 0;
    assertNonNegative(where, 'planeSize', planeSize);
    const initial = options.initialInstances ?? 64;
    assertInteger(where, 'initialInstances', initial, 1, 16_777_216);
    const envStyle = {
      boundary,
      boundaryColor: parseColor(where, 'boundaryColor', options.boundaryColor ?? 0x8fb3d9),
      glassColor: parseColor(where, 'glassColor', options.glassColor ?? 0x9cc9ff),
      glassOpacity,
      floorColor: parseColor(where, 'floorColor', options.floorColor ?? 0x39404f),
      segmentColor: parseColor(where, 'segmentColor', options.segmentColor ?? 0x8d99ae),
      planeSize,
      shadows,
    };
    const trailOptions =
      options.trails === undefined || options.trails === false
        ? null
        : resolveTrailOptions(where, options.trails === true ? {} : options.trails);
    const debugOptions =
      options.debug === undefined || options.debug === false
        ? null
        : resolveDebugOptions(where, options.debug === true ? {} : options.debug);

    this.unitsPerMeter = unitsPerMeter;
    this.drawBodies = bodies;
    this.boxSize = boxSize;
    this.shadows = shadows;
    this.colorSeed = colorSeed;
    this.palette = palette;
    this.root.name = 'bitphysics-world';
    this.instanceRoot.name = 'instances';
    this.env = new EnvironmentLayer(envStyle);
    this.root.add(this.env.object, this.instanceRoot);
    this.lights = lightOptions ? new LightRig(lightOptions) : null;
    if (this.lights) this.root.add(this.lights.object);

    const sphere = new SphereGeometry(1, segments, Math.max(3, Math.ceil((segments * 2) / 3)));
    const box = new BoxGeometry(1, 1, 1);
    this.owned.push(sphere, box);
    this.ballMaterial = options.ballMaterial ?? this.own(new MeshStandardMaterial({ roughness: 0.35, metalness: 0.05 }));
    this.boxMaterial = options.boxMaterial ?? this.own(new MeshStandardMaterial({ roughness: 0.5, metalness: 0.1 }));

    this.worldRef = world;
    this.book = new InstanceBook(world.capacity);
    this.debugFrame = {
      book: this.book,
      drawnPosition: this.drawnPos,
      drawnOrientation: this.drawnQuat,
      size: this.size,
      scale: unitsPerMeter,
    };
    this.listener = {
      added: (g, i, e) => this.onAdded(g, i, e),
      moved: (g, _from, to, e) => this.writeTint(g, to, e),
      removed: (_g, e) => {
        if (!this.regrouping) this.trails?.removed(e);
      },
    };
    this.book.listener = this.listener;
    this.ballGroup = this.groupFor(sphere, this.ballMaterial, 'ball', initial);
    this.boxGroup = this.groupFor(box, this.boxMaterial, 'box', initial);
    this.shapedGroup = this.groupFor(this.own(new BufferGeometry()), this.boxMaterial, 'shapes', initial);
    this.shapes = new ShapeLayer3D(world.capacity, this.boxMaterial, sphere, shadows, envStyle.floorColor);
    this.root.add(this.shapes.object);
    this.shapeFrame = {
      bodies: this.book.eids(this.shapedGroup),
      count: 0,
      drawnPosition: this.drawnPos,
      drawnOrientation: this.drawnQuat,
      scale: unitsPerMeter,
      colorOf: (shape, b) => this.shapeColor(shape, b),
    };
    this.allocate(world.capacity);
    this.bindWorld(world);
    if (trailOptions) this.installTrails(trailOptions);
    if (debugOptions) this.installDebug(debugOptions);
    if (scene) scene.add(this.root);
  }

  /** The world being drawn. Change it with `setWorld`. */
  get world(): PhysicsWorld {
    return this.worldRef;
  }

  /**
   * Draws a new world from now on (after a reset or a rebuilt scene): every instance of the old one
   * is dropped; user colours, shapes and trails start empty.
   * @throws TypeError | RangeError if `world` is not a 3D physics world.
   */
  setWorld(world: PhysicsWorld): void {
    checkWorld('WorldRenderer3D.setWorld', world);
    this.assertAlive('setWorld');
    this.book.clear();
    if (world.capacity !== this.cap) {
      this.book = new InstanceBook(world.capacity);
      this.book.listener = this.listener;
      for (let g = 0; g < this.groups.length; g++) this.book.addGroup(this.groups[g]!.capacity);
      this.allocate(world.capacity);
    } else {
      this.userStamp.fill(0);
      this.shapeStamp.fill(0);
    }
    for (const group of this.groups) group.commit(0);
    this.shapes.reset(world.capacity);
    this.worldRef = world;
    this.bindWorld(world);
  }

  /**
   * Places every instance for the state at interpolation factor `alpha` (0: the start of the last
   * step, 1: the current state). Call once per frame, then render the scene.
   * @param alpha in [0, 1]: `FixedStepLoop.advance(...).alpha`, or 1 while paused.
   * @throws RangeError if alpha is outside [0, 1] or NaN; Error if the renderer was destroyed.
   */
  render(alpha: number): void {
    if (!(alpha >= 0 && alpha <= 1)) throw new RangeError(`WorldRenderer3D.render: alpha must be in [0, 1], got ${describe(alpha)}`);
    this.assertAlive('render');
    const world = this.worldRef;
    const k = this.unitsPerMeter;
    this.env.update(world, k);
    this.fitLights(world);
    this.sync(world);
    const steps = world.steps;
    const delta = this.lastSteps < 0 ? 0 : steps - this.lastSteps;
    this.lastSteps = steps;
    const c = world.components;
    const px = c.Position.x,
      py = c.Position.y,
      pz = c.Position.z;
    const ox = c.PreviousPosition.x,
      oy = c.PreviousPosition.y,
      oz = c.PreviousPosition.z;
    const Ox = c.Orientation.x,
      Oy = c.Orientation.y,
      Oz = c.Orientation.z,
      Ow = c.Orientation.w;
    const wx = c.AngularVelocity.x,
      wy = c.AngularVelocity.y,
      wz = c.AngularVelocity.z;
    const radius = c.Ball.radius;
    const h = world.dt;
    const oriented = this.oriented,
      qp = this.qPrev,
      qc = this.qCur,
      dp = this.drawnPos,
      dq = this.drawnQuat;
    const mode = this.scaleMode,
      fixed = this.fixedScale,
      size = this.size;
    const book = this.book;
    let meshes = 0;
    for (let g = 0; g < this.groups.length; g++) {
      const group = this.groups[g]!;
      const n = book.count(g);
      if (n > 0 && !group.hidden) meshes++;
      const eids = book.eids(g);
      const m = group.matrices;
      for (let i = 0; i < n; i++) {
        const e = eids[i]!;
        const q4 = 4 * e,
          p3 = 3 * e;
        if (oriented[e] === 1) {
          const x = Ox[e]!,
            y = Oy[e]!,
            z = Oz[e]!,
            w = Ow[e]!;
          if (delta === 1) {
            qp[q4] = qc[q4]!;
            qp[q4 + 1] = qc[q4 + 1]!;
            qp[q4 + 2] = qc[q4 + 2]!;
            qp[q4 + 3] = qc[q4 + 3]!;
            qc[q4] = x;
            qc[q4 + 1] = y;
            qc[q4 + 2] = z;
            qc[q4 + 3] = w;
          } else if (delta > 1) {
            qc[q4] = x;
            qc[q4 + 1] = y;
            qc[q4 + 2] = z;
            qc[q4 + 3] = w;
            rotateBack(x, y, z, w, wx[e]!, wy[e]!, wz[e]!, h, qp, q4);
          } else if (x !== qc[q4] || y !== qc[q4 + 1] || z !== qc[q4 + 2] || w !== qc[q4 + 3]) {
            // Changed without a step (set by hand): show it as is, no interpolation.
            qp[q4] = x;
            qp[q4 + 1] = y;
            qp[q4 + 2] = z;
            qp[q4 + 3] = w;
            qc[q4] = x;
            qc[q4 + 1] = y;
            qc[q4 + 2] = z;
            qc[q4 + 3] = w;
          }
          slerpInto(qp[q4]!, qp[q4 + 1]!, qp[q4 + 2]!, qp[q4 + 3]!, qc[q4]!, qc[q4 + 1]!, qc[q4 + 2]!, qc[q4 + 3]!, alpha, dq, q4);
        }
        const ax = ox[e]!,
          ay = oy[e]!,
          az = oz[e]!;
        const x = ax + (px[e]! - ax) * alpha,
          y = ay + (py[e]! - ay) * alpha,
          z = az + (pz[e]! - az) * alpha;
        dp[p3] = x;
        dp[p3 + 1] = y;
        dp[p3 + 2] = z;
        let sx: number, sy: number, sz: number;
        if (mode[e] === SCALE_RADIUS) {
          const r = radius[e]!;
          size[e] = r;
          sx = sy = sz = r * k;
        } else {
          sx = fixed[p3]! * k;
          sy = fixed[p3 + 1]! * k;
          sz = fixed[p3 + 2]! * k;
        }
        composeInto(m, 16 * i, x * k, y * k, z * k, dq[q4]!, dq[q4 + 1]!, dq[q4 + 2]!, dq[q4 + 3]!, sx, sy, sz);
      }
      group.commit(n);
    }
    const sf = this.shapeFrame;
    sf.bodies = book.eids(this.shapedGroup);
    sf.count = book.count(this.shapedGroup);
    sf.drawnPosition = dp;
    sf.drawnOrientation = dq;
    sf.scale = k;
    this.shapes.draw(world, sf);
    meshes += this.shapes.counts.meshes;
    const trails = this.trails;
    if (trails) {
      if (delta > 0) trails.record(world);
      trails.draw(world, alpha, k, this.entityColor);
    }
    const debug = this.debug;
    if (debug) {
      const f = this.debugFrame;
      f.book = book;
      f.drawnPosition = dp;
      f.drawnOrientation = dq;
      f.size = size;
      f.scale = k;
      debug.draw(world, f);
    }
    const s = this.stats;
    s.instances = book.total;
    s.balls = book.count(this.ballGroup);
    s.boxes = book.count(this.boxGroup);
    s.shaped = book.count(this.shapedGroup);
    s.custom = s.instances - s.balls - s.boxes - s.shaped;
    const sc3 = this.shapes.counts,
      ss = s.shapes;
    ss.spheres = sc3.spheres;
    ss.boxes = sc3.boxes;
    ss.capsules = sc3.capsules;
    ss.cylinders = sc3.cylinders;
    ss.hulls = sc3.hulls;
    ss.meshes = sc3.meshes;
    ss.triangleMeshes = sc3.triangleMeshes;
    s.meshes = meshes;
    s.trails = trails ? trails.count : 0;
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
   * Gives entity `eid` its own look: a geometry, an optional material, scale and tint (see
   * `BodyShape`); `null` returns it to the default look (its 3D shapes, else a sphere or a box). A body with
   * 3D shapes given a user shape is drawn by that shape instead of its shapes. The shape holds until the entity
   * is removed (a recycled id starts with the default again). Entities sharing geometry and material
   * share one instanced mesh. May be called before the entity is first drawn.
   * @throws RangeError if `eid` is not a live entity; TypeError if geometry or material are not three.js
   *   ones; TypeError | RangeError on a bad scale or colour.
   */
  setShape(entity: number, shape: BodyShape | null): void {
    const where = 'WorldRenderer3D.setShape';
    const eid = this.entitySlot(where, entity);
    const stamp = this.worldRef.spawnStamp[eid]!;
    if (shape === null) {
      this.shapeStamp[eid] = 0;
    } else {
      if (shape === undefined || typeof shape !== 'object')
        throw new TypeError(`${where}: shape must be { geometry, material?, scale?, color? } or null, got ${describe(shape)}`);
      assertKnownKeys(where, shape, ['geometry', 'material', 'scale', 'color']);
      if (!isGeometry(shape.geometry))
        throw new TypeError(`${where}: geometry must be a three.js BufferGeometry, got ${describe(shape.geometry)}`);
      if (shape.material !== undefined && !isMaterial(shape.material))
        throw new TypeError(`${where}: material must be a three.js Material, got ${describe(shape.material)}`);
      const s = shape.scale;
      let scaleMode = -1; // -1 default by kind, 0 fixed, 1 radius, 2 inertia
      const o = 3 * eid;
      if (s === 'radius') scaleMode = 1;
      else if (s === 'inertia') scaleMode = 2;
      else if (typeof s === 'number') {
        assertPositive(where, 'scale', s);
        scaleMode = 0;
        this.shapeScale[o] = s;
        this.shapeScale[o + 1] = s;
        this.shapeScale[o + 2] = s;
      } else if (s !== undefined) {
        assertVector(where, 'scale', s, 3);
        for (let i = 0; i < 3; i++) assertPositive(where, `scale[${i}]`, s[i]);
        scaleMode = 0;
        this.shapeScale[o] = s[0]!;
        this.shapeScale[o + 1] = s[1]!;
        this.shapeScale[o + 2] = s[2]!;
      }
      const tint = shape.color !== undefined ? parseColor(where, 'color', shape.color) : shape.material !== undefined ? 0xffffff : -1;
      const isBall = hasComponent(this.worldRef, eid, this.worldRef.components.Ball);
      const material = shape.material ?? (isBall ? this.ballMaterial : this.boxMaterial);
      this.shapeGroup[eid] = this.groupFor(shape.geometry, material, 'custom', 4) + 1;
      this.shapeScaleMode[eid] = scaleMode;
      this.shapeTint[eid] = tint;
      this.shapeStamp[eid] = stamp;
    }
    this.regroup(eid);
  }

  /**
   * Re-reads how entity `eid` is drawn (its group and scale: after a Ball was added or removed, or
   * mass or inertia changed a box's size) at the next render.
   * @throws RangeError if `eid` is not a live entity.
   */
  refresh(entity: number): void {
    const eid = this.entitySlot('WorldRenderer3D.refresh', entity);
    this.regroup(eid);
  }

  /**
   * Gives entity `eid` a colour of its own (its instance tint unless its shape sets one, and its
   * trail). It keeps it until removed. May be called before the entity is first drawn. `eid` may be
   * a body (its colour fills its 3D shapes that have none of their own) or a shape as `addShape3D`
   * returns it (that shape alone).
   * @param color 0xRRGGBB integer or '#rgb' / '#rrggbb'.
   * @throws RangeError if `eid` is not a live entity or the colour is out of range; TypeError if the
   *   colour is neither a number nor a string.
   */
  setColor(entity: number, color: ColorInput): void {
    const where = 'WorldRenderer3D.setColor';
    const eid = this.entitySlot(where, entity);
    const value = parseColor(where, 'color', color);
    this.userColor[eid] = value;
    this.userStamp[eid] = this.worldRef.spawnStamp[eid]!;
    this.recolor(eid);
  }

  /** Returns entity `eid` to its seeded colour. @throws RangeError if `eid` is not a live entity. */
  clearColor(entity: number): void {
    const eid = this.entitySlot('WorldRenderer3D.clearColor', entity);
    this.userStamp[eid] = 0;
    this.recolor(eid);
  }

  /**
   * The colour of entity `eid`, 0xRRGGBB: its user colour if set, else its seeded colour (a pure
   * function of colorSeed, the id and its spawn stamp; the same as render-pixi's).
   * @throws RangeError if `eid` is not a live entity.
   */
  colorOf(entity: number): number {
    const eid = this.entitySlot('WorldRenderer3D.colorOf', entity);
    return this.computeColor(eid);
  }

  /**
   * Where entity `eid` was drawn by the last `render`: its interpolated centre in world coordinates,
   * m, written into `out` (allocated if omitted). @returns `out`, or null if the entity is not shown.
   * @throws RangeError if `eid` is not an integer.
   */
  drawnPosition(entity: number, out: number[] | Float64Array = [0, 0, 0]): number[] | Float64Array | null {
    if (!Number.isInteger(entity)) throw new RangeError(`WorldRenderer3D.drawnPosition: eid must be an integer, got ${describe(entity)}`);
    const eid = this.shownSlot(entity);
    if (eid === 0) return null;
    out[0] = this.drawnPos[3 * eid]!;
    out[1] = this.drawnPos[3 * eid + 1]!;
    out[2] = this.drawnPos[3 * eid + 2]!;
    return out;
  }

  /**
   * The orientation entity `eid` was drawn with by the last `render` (x, y, z, w), written into `out`.
   * @returns `out`, or null if the entity is not shown. @throws RangeError if `eid` is not an integer.
   */
  drawnOrientation(entity: number, out: number[] | Float64Array = [0, 0, 0, 1]): number[] | Float64Array | null {
    if (!Number.isInteger(entity))
      throw new RangeError(`WorldRenderer3D.drawnOrientation: eid must be an integer, got ${describe(entity)}`);
    const eid = this.shownSlot(entity);
    if (eid === 0) return null;
    for (let i = 0; i < 4; i++) out[i] = this.drawnQuat[4 * eid + i]!;
    return out;
  }

  /** Whether entity `eid` (a handle) is drawn now (has an instance); false for a removed entity. */
  isShown(eid: number): boolean {
    return this.shownSlot(eid) !== 0;
  }

  /**
   * The entity under a screen point: casts a ray from `camera` through (ndcX, ndcY) (normalised
   * device coordinates, -1..1, y up). Bodies with colliders (3D shapes, balls) and the static world
   * (planes, meshes, static shapes) are hit by a ray cast through the physics (`rayCast3D`, where the
   * bodies are now: at most one step from where they were drawn); bodies drawn without a collider (a
   * plain rigid body's inertia box, user shapes on such bodies) by three.js' ray cast against the
   * instanced meshes as drawn by the last `render`. The nearer hit wins; a hit on the static world
   * with no body (a plane, a mesh) hides what is behind it and returns null.
   * @returns the nearest hit, or null. Allocates a little (call it on clicks, not per frame).
   * @throws RangeError if ndcX or ndcY is not finite.
   */
  pick(ndcX: number, ndcY: number, camera: Camera): PickResult | null {
    const where = 'WorldRenderer3D.pick';
    assertFinite(where, 'ndcX', ndcX);
    assertFinite(where, 'ndcY', ndcY);
    this.assertAlive('pick');
    this.ndc.set(ndcX, ndcY);
    this.raycaster.setFromCamera(this.ndc, camera);
    this.root.updateMatrixWorld();
    const k = this.unitsPerMeter;
    const world = this.worldRef;
    // The physics ray, in metres in the renderer's root frame.
    const ray = this.raycaster.ray;
    const o = this.v3.copy(ray.origin);
    this.root.worldToLocal(o);
    const ox = o.x / k,
      oy = o.y / k,
      oz = o.z / k;
    const farDistance = (camera as { far?: number }).far ?? 1000; // scene units: the physics segment's length in the scene
    const far = this.v3.copy(ray.origin).addScaledVector(ray.direction, farDistance);
    this.root.worldToLocal(far);
    const tx = far.x / k - ox,
      ty = far.y / k - oy,
      tz = far.z / k - oz;
    const rayLength = Math.hypot(tx, ty, tz);
    let physics: PickResult | null = null;
    let physicsDistance = Infinity;
    let blocked = false;
    if (rayLength > 0) {
      const hit = rayCast3D(world, [ox, oy, oz], [tx, ty, tz]);
      if (hit) {
        physicsDistance = hit.fraction * farDistance; // scene units, whatever the root's scale
        if (hit.body === 0) blocked = true;
        else physics = { eid: hit.body, point: [hit.x, hit.y, hit.z], normal: [hit.nx, hit.ny, hit.nz], distance: physicsDistance };
      }
    }
    const hits = this.hits;
    hits.length = 0;
    for (let g = 0; g < this.groups.length; g++) {
      const group = this.groups[g]!;
      if (this.book.count(g) === 0 || group.hidden || g === this.ballGroup) continue;
      group.mesh.computeBoundingSphere();
      group.mesh.raycast(this.raycaster, hits);
    }
    let best: Intersection | null = null;
    for (const hit of hits) if (hit.instanceId !== undefined && (!best || hit.distance < best.distance)) best = hit;
    hits.length = 0;
    if (!best || best.distance >= physicsDistance) return blocked ? null : physics;
    const gi = this.groups.findIndex((gr) => gr.mesh === best!.object);
    if (gi < 0) return null;
    const eid = this.book.eids(gi)[best.instanceId!]!;
    const normal: [number, number, number] = [0, 1, 0];
    if (best.normal) {
      this.groups[gi]!.mesh.getMatrixAt(best.instanceId!, this.m4);
      this.m4.premultiply(this.groups[gi]!.mesh.matrixWorld);
      this.m3.getNormalMatrix(this.m4);
      const n = this.v3.copy(best.normal).applyMatrix3(this.m3).normalize();
      // That is the scene's frame; the result's is the physics' (the root's): n_root ~ M_root^T n_scene
      // (a normal transforms by the inverse transpose; root.matrixWorld maps root to scene).
      n.applyMatrix3(this.m3.setFromMatrix4(this.root.matrixWorld).transpose()).normalize();
      normal[0] = n.x;
      normal[1] = n.y;
      normal[2] = n.z;
    }
    // Hits are in scene coordinates; the renderer's root may sit anywhere in the scene.
    const local = this.v3.copy(best.point);
    this.root.worldToLocal(local);
    if (!entityExists(world, eid)) return null; // removed since the last render
    return { eid: handleOf(world, eid), point: [local.x / k, local.y / k, local.z / k], normal, distance: best.distance };
  }

  /**
   * Turns trails on (`true` or options) or off (`false`). Turning them on starts every trail empty.
   * @throws TypeError | RangeError on bad options (named with their value).
   */
  setTrails(options: boolean | TrailOptions): void {
    this.assertAlive('setTrails');
    const resolved = options === false ? null : resolveTrailOptions('WorldRenderer3D.setTrails', options === true ? {} : options);
    if (this.trails) {
      this.trails.destroy();
      this.trails = null;
    }
    if (resolved) this.installTrails(resolved);
  }

  /** Whether trails are on. */
  get trailsEnabled(): boolean {
    return this.trails !== null;
  }

  /** Whether entity `eid` has a trail now. */
  hasTrail(eid: number): boolean {
    return this.trails !== null && isAlive(this.worldRef, eid) && this.trails.has(slotOf(eid));
  }

  /**
   * Turns the debug layer on (`true` or options) or off (`false`).
   * @throws TypeError | RangeError on bad options (named with their value).
   */
  setDebug(options: boolean | DebugOptions): void {
    this.assertAlive('setDebug');
    const resolved = options === false ? null : resolveDebugOptions('WorldRenderer3D.setDebug', options === true ? {} : options);
    if (this.debug) {
      this.debug.destroy();
      this.debug = null;
    }
    if (resolved) this.installDebug(resolved);
  }

  /** Whether the debug layer is on. */
  get debugEnabled(): boolean {
    return this.debug !== null;
  }

  /** Turns shadow casting and receiving of every instanced mesh on or off. @throws TypeError unless a boolean. */
  setShadows(on: boolean): void {
    assertBoolean('WorldRenderer3D.setShadows', 'on', on);
    for (const g of this.groups) g.setShadows(on);
    this.shapes.setShadows(on);
  }

  /**
   * Removes `root` from its parent and frees every mesh, geometry and material the renderer made
   * (not user geometries and materials). Methods throw Error afterwards.
   */
  destroy(): void {
    if (this.destroyed) return;
    this.destroyed = true;
    this.root.removeFromParent();
    this.trails?.destroy();
    this.debug?.destroy();
    this.env.destroy();
    this.lights?.dispose();
    for (const g of this.groups) g.dispose();
    this.shapes.destroy();
    for (const d of this.owned) d.dispose();
  }

  // ---- internals -------------------------------------------------------------------------------

  private own<T extends { dispose(): void }>(thing: T): T {
    this.owned.push(thing);
    return thing;
  }

  /** The group drawing (geometry, material), created on first use. */
  private groupFor(geometry: BufferGeometry, material: Material, kind: GroupKind, initial: number): number {
    let byMaterial = this.groupIndex.get(geometry);
    if (!byMaterial) {
      byMaterial = new Map();
      this.groupIndex.set(geometry, byMaterial);
    }
    const known = byMaterial.get(material);
    if (known !== undefined) return known;
    const g = this.book.addGroup(initial);
    const group = new InstanceGroup(this.instanceRoot, geometry, material, kind, `instances-${kind}-${g}`, initial, this.shadows);
    this.groups.push(group);
    byMaterial.set(material, g);
    return g;
  }

  private allocate(capacity: number): void {
    const n = capacity + 1;
    this.cap = capacity;
    this.oriented = new Uint8Array(n);
    this.qPrev = new Float64Array(4 * n);
    this.qCur = new Float64Array(4 * n);
    this.drawnPos = new Float64Array(3 * n);
    this.drawnQuat = new Float64Array(4 * n);
    for (let e = 0; e < n; e++) this.drawnQuat[4 * e + 3] = 1;
    this.scaleMode = new Uint8Array(n);
    this.fixedScale = new Float64Array(3 * n);
    this.size = new Float64Array(n);
    this.entityColor = new Uint32Array(n);
    this.tint = new Int32Array(n);
    this.userColor = new Uint32Array(n);
    this.userStamp = new Uint32Array(n);
    this.shapeGroup = new Int32Array(n);
    this.shapeStamp = new Uint32Array(n);
    this.shapeScaleMode = new Int8Array(n);
    this.shapeScale = new Float64Array(3 * n);
    this.shapeTint = new Int32Array(n);
  }

  private bindWorld(world: PhysicsWorld): void {
    const c = world.components;
    this.terms = { balls: [c.Position, c.Ball], bodies: [c.Position, c.Orientation] };
    this.env.bind(world);
    this.trails?.reset(world.capacity);
    this.lastSteps = -1;
    this.boxSeen[0] = -1;
  }

  /**
   * Re-chooses the group and scale of a shown entity now (after setShape / refresh), keeping its
   * trail; an entity not shown yet gets its look when the next render first shows it.
   */
  private regroup(eid: number): void {
    const world = this.worldRef;
    if (!this.book.has(eid)) return;
    this.regrouping = true;
    try {
      const g = this.classify(world, eid);
      if (g >= 0) {
        this.book.add(eid, g, world.spawnStamp[eid]!);
        return;
      }
    } finally {
      this.regrouping = false;
    }
    this.book.remove(eid);
  }

  /** Brings the shown set in line with the world (adds new entities, drops removed and recycled ones). */
  private sync(world: PhysicsWorld): void {
    const book = this.book;
    const spawn = world.spawnStamp;
    const s3 = world.dimensions === 3 ? shapes3DOf(world) : undefined;
    const first = s3 !== undefined ? s3.first : null,
      shaped = this.shapedGroup,
      userStamp = this.shapeStamp;
    book.beginPass();
    for (let pass = 0; pass < 2; pass++) {
      const ents = query(world, pass === 0 ? this.terms.balls : this.terms.bodies);
      for (let i = 0; i < ents.length; i++) {
        const e = ents[i]!;
        if (book.has(e)) {
          // A body given its first 3D shape after it was first drawn moves to the shapes (unless the user chose its look).
          if (
            book.stampOf[e] === spawn[e] &&
            (first === null || first[e] === 0 || book.groupOf(e) === shaped || userStamp[e] === spawn[e])
          ) {
            book.mark(e);
            continue;
          }
          book.remove(e);
        }
        const g = this.classify(world, e);
        if (g >= 0) book.add(e, g, spawn[e]!);
      }
    }
    book.sweep();
  }

  /** The group entity `e` belongs in, or -1 if it is not drawn; fills its scale and orientation state. */
  private classify(world: PhysicsWorld, e: number): number {
    const c = world.components;
    const ball = hasComponent(world, e, c.Ball);
    const userShape = this.shapeStamp[e] === world.spawnStamp[e] && this.shapeGroup[e]! > 0;
    let g: number;
    const s3 = world.dimensions === 3 ? shapes3DOf(world) : undefined;
    const shaped = !userShape && s3 !== undefined && s3.first[e]! !== 0;
    if (userShape) g = this.shapeGroup[e]! - 1;
    else if (shaped) g = this.shapedGroup;
    else if (ball) g = this.ballGroup;
    else if (this.drawBodies) g = this.boxGroup;
    else return -1;
    // Scale: radius for balls, the equivalent box otherwise, unless the user shape says otherwise.
    const want = userShape ? this.shapeScaleMode[e]! : -1;
    const o = 3 * e;
    if (shaped) {
      // Bodies drawn by their shapes: the group only carries the pose; size is the shapes' reach from the centre.
      this.scaleMode[e] = SCALE_FIXED;
      this.fixedScale[o] = this.fixedScale[o + 1] = this.fixedScale[o + 2] = 1;
      let reach = 0;
      for (let sh = s3.first[e]!; sh !== 0; sh = s3.next[sh]!)
        reach = Math.max(reach, Math.hypot(s3.px[sh]!, s3.py[sh]!, s3.pz[sh]!) + s3.reach[sh]!);
      this.size[e] = reach;
    } else if (want === 0) {
      this.scaleMode[e] = SCALE_FIXED;
      this.fixedScale[o] = this.shapeScale[o]!;
      this.fixedScale[o + 1] = this.shapeScale[o + 1]!;
      this.fixedScale[o + 2] = this.shapeScale[o + 2]!;
      this.size[e] = 0.5 * Math.max(this.shapeScale[o]!, this.shapeScale[o + 1]!, this.shapeScale[o + 2]!);
    } else if ((want === 1 || want === -1) && ball) {
      this.scaleMode[e] = SCALE_RADIUS;
      this.size[e] = c.Ball.radius[e]!;
    } else {
      this.scaleMode[e] = SCALE_FIXED;
      this.boxEdges(world, e, this.edgesScratch);
      const ed = this.edgesScratch;
      this.fixedScale[o] = ed[0]!;
      this.fixedScale[o + 1] = ed[1]!;
      this.fixedScale[o + 2] = ed[2]!;
      this.size[e] = 0.5 * Math.max(ed[0]!, ed[1]!, ed[2]!);
    }
    const q4 = 4 * e;
    if (hasComponent(world, e, c.Orientation)) {
      this.oriented[e] = 1;
      const O = c.Orientation;
      this.qPrev[q4] = this.qCur[q4] = this.drawnQuat[q4] = O.x[e]!;
      this.qPrev[q4 + 1] = this.qCur[q4 + 1] = this.drawnQuat[q4 + 1] = O.y[e]!;
      this.qPrev[q4 + 2] = this.qCur[q4 + 2] = this.drawnQuat[q4 + 2] = O.z[e]!;
      this.qPrev[q4 + 3] = this.qCur[q4 + 3] = this.drawnQuat[q4 + 3] = O.w[e]!;
    } else {
      this.oriented[e] = 0;
      this.drawnQuat[q4] = 0;
      this.drawnQuat[q4 + 1] = 0;
      this.drawnQuat[q4 + 2] = 0;
      this.drawnQuat[q4 + 3] = 1;
    }
    return g;
  }

  /** Edges (m) of the box drawn for a body without a ball: its equivalent-inertia box, else a `boxSize` cube. */
  private boxEdges(world: PhysicsWorld, e: number, out: Float64Array): void {
    const c = world.components;
    const mass = c.Mass.value[e]!;
    if (hasComponent(world, e, c.InertiaTensor)) {
      const T = c.InertiaTensor;
      if (equivalentBoxEdges(mass, T.x[e]!, T.y[e]!, T.z[e]!, out)) return;
    } else if (hasComponent(world, e, c.Inertia)) {
      const I = c.Inertia.value[e]!;
      if (equivalentBoxEdges(mass, I, I, I, out)) return;
    }
    out[0] = out[1] = out[2] = this.boxSize;
  }

  private onAdded(g: number, i: number, e: number): void {
    const group = this.groups[g]!;
    group.ensure(i + 1);
    this.entityColor[e] = this.computeColor(e);
    const userShape = this.shapeStamp[e] === this.worldRef.spawnStamp[e] && this.shapeGroup[e]! > 0;
    this.tint[e] = userShape ? this.shapeTint[e]! : -1;
    this.writeTint(g, i, e);
    this.trails?.added(this.worldRef, e);
  }

  /** Writes entity e's instance tint at instance i of group g. */
  private writeTint(g: number, i: number, e: number): void {
    const t = this.tint[e]!;
    const hex = t >= 0 ? t : this.entityColor[e]!;
    const group = this.groups[g]!;
    hexToLinear(hex, group.colors, 3 * i);
    group.colorsChanged();
  }

  /** A shape's colour: the user colour set on the shape itself, else its body's colour (user or seeded). */
  private shapeColor(shape: number, body: number): number {
    const st = this.worldRef.spawnStamp[shape]!;
    if (shape !== body && this.userStamp[shape] === st && st !== 0) return this.userColor[shape]!;
    return this.entityColor[body]!;
  }

  private computeColor(e: number): number {
    const st = this.worldRef.spawnStamp[e]!;
    if (this.userStamp[e] === st && st !== 0) return this.userColor[e]!;
    return seededColor(this.colorSeed, e, st, this.palette);
  }

  private recolor(e: number): void {
    this.shapes.recolor();
    if (!this.book.has(e)) return;
    this.entityColor[e] = this.computeColor(e);
    this.writeTint(this.book.groupOf(e), this.book.indexOf[e]!, e);
  }

  private installTrails(options: ReturnType<typeof resolveTrailOptions>): void {
    const trails = new TrailLayer(options, this.worldRef.capacity);
    this.trails = trails;
    this.root.add(trails.object);
    // Entities already shown get a trail too.
    for (let g = 0; g < this.groups.length; g++) {
      const eids = this.book.eids(g);
      for (let i = 0; i < this.book.count(g); i++) trails.added(this.worldRef, eids[i]!);
    }
  }

  private installDebug(options: ReturnType<typeof resolveDebugOptions>): void {
    const debug = new DebugLayer(options);
    this.debug = debug;
    this.root.add(debug.object);
  }

  /** Aims the sun's shadow camera at the boundary box when it changes (or at shadowBounds without one). */
  private fitLights(world: PhysicsWorld): void {
    const lights = this.lights;
    if (!lights) return;
    const box = world.collision.boundary;
    const seen = this.boxSeen;
    const on = box.enabled ? 1 : 0;
    if (
      seen[0] === on &&
      seen[1] === box.min[0] &&
      seen[2] === box.min[1] &&
      seen[3] === box.min[2] &&
      seen[4] === box.max[0] &&
      seen[5] === box.max[1] &&
      seen[6] === box.max[2]
    )
      return;
    seen[0] = on;
    seen[1] = box.min[0]!;
    seen[2] = box.min[1]!;
    seen[3] = box.min[2]!;
    seen[4] = box.max[0]!;
    seen[5] = box.max[1]!;
    seen[6] = box.max[2]!;
    const k = this.unitsPerMeter;
    const min = box.enabled ? box.min : this.shadowMin,
      max = box.enabled ? box.max : this.shadowMax;
    lights.fit(min[0]! * k, min[1]! * k, min[2]! * k, max[0]! * k, max[1]! * k, max[2]! * k);
  }

  private assertAlive(where: string): void {
    if (this.destroyed) throw new Error(`WorldRenderer3D.${where}: the renderer was destroyed`);
  }

  /** The slot of entity handle `entity` (per-entity methods take handles; the instance books index by slot). */
  private entitySlot(where: string, entity: number): number {
    this.assertAlive(where.slice(where.indexOf('.') + 1));
    return entitySlot(where, this.worldRef, entity);
  }

  /** The slot of entity handle `entity` if it is alive and drawn now, else 0 (a stale handle never finds the slot's new entity). */
  private shownSlot(entity: number): number {
    if (!isAlive(this.worldRef, entity)) return 0;
    const slot = slotOf(entity);
    return this.book.has(slot) ? slot : 0;
  }
}
