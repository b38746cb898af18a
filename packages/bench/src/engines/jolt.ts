import { boxPile3DLayout, pyramid3DLayout, spheresInBoxLayout } from '@bitphysics/physics';
import { asleepSteps } from '../scenes/box-pile-3d.js';
import { boxWalls3d } from './box-walls.js';
import { optimizedWasm } from './rapier2d.js';
import type { BodySnapshot, EngineAdapter, EngineInstance, SceneRunOptions } from './types.js';

type JoltModule = Awaited<ReturnType<typeof import('jolt-physics/wasm-compat').default>>;

let jolt: Promise<JoltModule> | undefined;

/**
 * Loads and initialises jolt-physics' single-threaded WASM build (`jolt-physics/wasm-compat`, the
 * WASM inlined) once, with V8's baseline WASM compiler turned off first (`optimizedWasm`, as for
 * Rapier), and steps one tiny world so the optimizing compiler has compiled what a step runs before
 * any timing.
 */
export function loadJolt(): Promise<JoltModule> {
  jolt ??= (async () => {
    optimizedWasm();
    const init = (await import('jolt-physics/wasm-compat')).default;
    const J = await init();
    const scene = makeSystem(J, 4);
    addBox(J, scene, [0, 2, 0], [0.5, 0.5, 0.5], 1, 0.5, 0, J.EMotionType_Dynamic, MOVING);
    addBox(J, scene, [0, -1, 0], [5, 1, 5], 1, 0.5, 0, J.EMotionType_Static, NON_MOVING);
    for (let i = 0; i < 5; i++) scene.jolt.Step(1 / 60, 1);
    J.destroy(scene.jolt);
    return J;
  })();
  return jolt;
}

/** Object layers: static walls and ground, and moving bodies (they collide with both). */
const NON_MOVING = 0;
const MOVING = 1;

interface JoltScene {
  readonly jolt: InstanceType<JoltModule['JoltInterface']>;
  readonly bodies: InstanceType<JoltModule['BodyInterface']>;
}

/**
 * A physics system with the two object layers in two broadphase layers (Jolt's usual set-up), room
 * for `maxBodies` bodies and 4 body pairs and contact constraints a body (Jolt's defaults, 65,536
 * and 10,240, at least): a settled pile of cubes has about 3 touching pairs a body. Jolt reserves the
 * contact constraints in its fixed temporary allocator every step, so 16 a body aborted a pile of
 * 5,000 cubes. Gravity is left at Jolt's default until the scene sets it.
 */
function makeSystem(J: JoltModule, maxBodies: number): JoltScene {
  const settings = new J.JoltSettings();
  settings.mMaxBodies = maxBodies + 16;
  settings.mMaxBodyPairs = Math.max(65_536, 4 * maxBodies);
  settings.mMaxContactConstraints = Math.max(10_240, 4 * maxBodies);
  const pairs = new J.ObjectLayerPairFilterTable(2);
  pairs.EnableCollision(NON_MOVING, MOVING);
  pairs.EnableCollision(MOVING, MOVING);
  const layers = new J.BroadPhaseLayerInterfaceTable(2, 2);
  layers.MapObjectToBroadPhaseLayer(NON_MOVING, new J.BroadPhaseLayer(0));
  layers.MapObjectToBroadPhaseLayer(MOVING, new J.BroadPhaseLayer(1));
  settings.mObjectLayerPairFilter = pairs;
  settings.mBroadPhaseLayerInterface = layers;
  settings.mObjectVsBroadPhaseLayerFilter = new J.ObjectVsBroadPhaseLayerFilterTable(layers, 2, pairs, 2);
  const joltInterface = new J.JoltInterface(settings);
  J.destroy(settings);
  return { jolt: joltInterface, bodies: joltInterface.GetPhysicsSystem().GetBodyInterface() };
}

/**
 * Adds a box body of half extents `half` (m) at `centre`, of mass `mass` (kg; ignored for a static
 * body), friction and restitution, and returns its body id's index and sequence number packed as Jolt
 * keeps them (`BodyID.GetIndexAndSequenceNumber`). The box's convex radius is Jolt's default 0.05 m,
 * or its smallest half extent if less.
 */
function addBox(
  J: JoltModule,
  scene: JoltScene,
  centre: readonly [number, number, number],
  half: readonly [number, number, number],
  mass: number,
  friction: number,
  restitution: number,
  motion: number,
  layer: number,
): InstanceType<JoltModule['BodyID']> {
  const extent = new J.Vec3(half[0], half[1], half[2]);
  const shape = new J.BoxShape(extent, Math.min(0.05, half[0], half[1], half[2]), undefined);
  J.destroy(extent);
  shape.SetDensity(mass / (8 * half[0] * half[1] * half[2]));
  return addBody(J, scene, shape, centre, friction, restitution, motion, layer);
}

function addBody(
  J: JoltModule,
  scene: JoltScene,
  shape: InstanceType<JoltModule['Shape']>,
  centre: readonly [number, number, number],
  friction: number,
  restitution: number,
  motion: number,
  layer: number,
): InstanceType<JoltModule['BodyID']> {
  const position = new J.RVec3(centre[0], centre[1], centre[2]);
  const rotation = new J.Quat(0, 0, 0, 1);
  const settings = new J.BodyCreationSettings(shape, position, rotation, motion, layer);
  settings.mFriction = friction;
  settings.mRestitution = restitution;
  const body = scene.bodies.CreateBody(settings);
  const id = body.GetID();
  scene.bodies.AddBody(id, motion === J.EMotionType_Static ? J.EActivation_DontActivate : J.EActivation_Activate);
  J.destroy(settings);
  J.destroy(position);
  J.destroy(rotation);
  return id;
}

/**
 * Jolt Physics (jolt-physics, C++ compiled to WASM, the single-threaded `wasm-compat` build): the 3D
 * scenes with the layouts of `spheresInBoxLayout`, `boxPile3DLayout` and `pyramid3DLayout`. One dynamic
 * body a sphere or a cube (mass, radius or half extent, friction and restitution from the layout;
 * cubes with Jolt's default convex radius 0.05 m), walls as static boxes (six slabs around the box,
 * or the pyramid's ground slab whose top is y = 0), gravity from the layout, `Step(1/60, 1)` (one
 * collision step a frame), every other setting at Jolt's default (10 velocity and 2 position solver
 * iterations, sleeping allowed, friction combined as the geometric mean and restitution as the
 * larger). The broadphase is optimised once after the scene is built, as Jolt recommends. Contacts are
 * not counted (Jolt reports them only through a contact listener, which would be timed).
 */
export const joltEngine: EngineAdapter = {
  name: 'jolt',
  description: "Jolt Physics (jolt-physics, C++ compiled to WASM, single-threaded), Jolt's default solver settings",
  async prepare(): Promise<void> {
    await loadJolt();
  },
  supports(scene: string): boolean {
    return scene === 'spheres-in-box' || scene === 'box-pile-3d' || scene === 'pyramid-3d';
  },
  async create(options: SceneRunOptions): Promise<EngineInstance> {
    if (!this.supports(options.scene)) throw new RangeError(`jolt: does not support scene "${options.scene}"`);
    const J = await loadJolt();
    const spheres = options.scene === 'spheres-in-box';
    const layout = spheres
      ? spheresInBoxLayout({ count: options.count, seed: options.seed })
      : options.scene === 'box-pile-3d'
        ? boxPile3DLayout({ count: options.count, seed: options.seed })
        : pyramid3DLayout({ count: options.count });
    const n = layout.count;
    let scene: JoltScene | undefined = makeSystem(J, n + 8);
    const s = scene;
    const system = s.jolt.GetPhysicsSystem();
    const g = new J.Vec3(layout.gravity[0], layout.gravity[1], layout.gravity[2]);
    system.SetGravity(g);
    J.destroy(g);
    const walls =
      'min' in layout
        ? boxWalls3d(layout.min, layout.max)
        : [{ cx: 0, cy: -0.5, cz: 0, hx: (layout.base * layout.pitch) / 2 + 10, hy: 0.5, hz: (layout.base * layout.pitch) / 2 + 10 }];
    for (const b of walls) {
      addBox(J, s, [b.cx, b.cy, b.cz], [b.hx, b.hy, b.hz], 1, layout.friction, layout.restitution, J.EMotionType_Static, NON_MOVING);
    }
    const ids = new Array<InstanceType<JoltModule['BodyID']>>(n);
    const p = layout.positions;
    for (let i = 0; i < n; i++) {
      const centre = [p[3 * i]!, p[3 * i + 1]!, p[3 * i + 2]!] as const;
      if ('radius' in layout) {
        const shape = new J.SphereShape(layout.radius, undefined);
        shape.SetDensity(layout.mass / ((4 / 3) * Math.PI * layout.radius ** 3));
        ids[i] = addBody(J, s, shape, centre, layout.friction, layout.restitution, J.EMotionType_Dynamic, MOVING);
      } else {
        const h = layout.half;
        ids[i] = addBox(J, s, centre, [h, h, h], layout.mass, layout.friction, layout.restitution, J.EMotionType_Dynamic, MOVING);
      }
    }
    system.OptimizeBroadPhase();
    const settings = system.GetPhysicsSettings();
    const notes = [
      `jolt (jolt-physics wasm-compat, single-threaded): dt 1/60 s, 1 collision step, ${settings.mNumVelocitySteps} velocity and ` +
        `${settings.mNumPositionSteps} position iterations, sleeping allowed (defaults); friction combine: geometric mean, ` +
        'restitution: max (defaults); contacts not counted; WASM compiled optimized up front (V8 --no-liftoff)',
    ];
    const bodies = s.bodies;
    const sleep = asleepSteps(n);
    let steps = 0;
    const asleep = (): number => {
      let count = 0;
      for (let i = 0; i < n; i++) if (!bodies.IsActive(ids[i]!)) count++;
      return count;
    };
    return {
      engine: 'jolt',
      notes,
      step(): void {
        s.jolt.Step(1 / 60, 1);
        steps++;
      },
      afterStep(): void {
        if (!spheres) sleep.record(asleep(), steps);
      },
      stats() {
        return { bodies: n, contacts: null, extra: { sleeping: asleep(), ...(spheres ? {} : sleep.fields()) } };
      },
      snapshot(): BodySnapshot {
        const positions = new Float64Array(3 * n),
          orientations = new Float64Array(4 * n);
        for (let i = 0; i < n; i++) {
          const t = bodies.GetPosition(ids[i]!);
          positions[3 * i] = t.GetX();
          positions[3 * i + 1] = t.GetY();
          positions[3 * i + 2] = t.GetZ();
          const q = bodies.GetRotation(ids[i]!);
          orientations[4 * i] = q.GetX();
          orientations[4 * i + 1] = q.GetY();
          orientations[4 * i + 2] = q.GetZ();
          orientations[4 * i + 3] = q.GetW();
        }
        return spheres
          ? { dimensions: 3, count: n, positions, radius: (layout as { radius: number }).radius }
          : { dimensions: 3, count: n, positions, orientations };
      },
      dispose(): void {
        if (scene === undefined) return;
        J.destroy(scene.jolt);
        scene = undefined;
      },
    };
  },
};
