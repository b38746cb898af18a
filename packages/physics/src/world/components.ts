/**
 * Component stores. Every physical quantity is a bitecs 0.4 component: a plain object of typed
 * arrays indexed by entity id (`Position.x[eid]`). Stores are made per world with the world's
 * capacity, so two worlds never share data; they live on `world.components`.
 *
 * Rules that hold for every store here:
 * - Length is capacity + 1 because bitecs entity ids start at 1 (index 0 is never a body; the
 *   contact solver uses it to mean "the static world").
 * - Physical quantities are Float64Array, SI units, y up, angles counter-clockwise.
 * - In a 2D world the z fields exist and stay 0; 2D rotation uses the z component of angular
 *   quantities (rotation about the axis out of the screen).
 * - When a component is added to an entity its fields are reset to the defaults documented
 *   below (bitecs recycles ids and leaves old data behind, so nothing is inherited).
 *
 * Memory: stores a world never uses are never allocated. Only Position, Velocity and
 * PreviousPosition get their arrays when the world is made (every entity that moves has them; in a
 * world made with `interpolation: false` and one thread, where bare particles never write their
 * previous position, PreviousPosition waits for the body group too and starts as a copy of Position,
 * so a world of bare particles holds 48 bytes of stores an entity); every
 * other store starts with empty (length 0) arrays and gets them, zero-filled, the first time its
 * component is added to any entity (createPhysicsWorld installs the onAdd hook, before the hooks that
 * write defaults). Stores are allocated by group (`LAZY_GROUPS`): the first body component (Mass,
 * Force, Ball, Angle, ...) allocates the whole body group and the collision state's per-entity scratch,
 * because code that reads one of them for an entity reads the others too; the first particle component
 * or emitter allocates Lifetime and Particle. A world of a million bare 2D particles thus holds 72
 * bytes of stores an entity (48 without interpolation), plus 4 of spawn stamp and bitecs' bookkeeping
 * made lean in world/lean-ecs.ts (about 40 more), instead of about 700 in all.
 *
 * Rules this gives to code that reads stores:
 * - Pull a store's arrays from `world.components` when you use them (once a step or a call, into
 *   locals), never earlier: an array taken before the store's first use stays empty. Renderers, the
 *   thread pool's shared arrays, snapshot/restore and the emitters all take them per call.
 * - Read a store only for entities that have its component (its query), or check the array's length:
 *   reading an unallocated store gives undefined. Writing to one is silently dropped, so code that
 *   makes entities without `addComponent` (bulk paths) calls `materializeGroup` first.
 * - The store object keeps its identity; only its arrays are replaced, once. In a world with threads > 1
 *   they are made on SharedArrayBuffer.
 */

import { type ClothLinkStore, createClothLinkStore } from './cloth-store.js';
import { createJointStore, type JointStore } from './joint-store-2d.js';

import { createEmptyShapeStore, type ShapeStore } from './shape-store-2d.js';

/**
 * A 3-vector store: one Float64Array a component.
 * @category Bodies
 */
export interface Vec3Store {
  /** x component, per entity. */
  x: Float64Array;
  /** y component, per entity (y is up). */
  y: Float64Array;
  /** z component, per entity (0 in a 2D world). */
  z: Float64Array;
}

/**
 * A uniform field oscillating in time, per field entity: F(t) = F0 + A cos(omega t + phase), in the
 * field's unit (ElectricField V/m, MagneticField T); x, y, z hold F0.
 * @category Forces
 */
export interface OscillatingField extends Vec3Store {
  /** Amplitude A, x component. */
  ampX: Float64Array;
  /** Amplitude A, y component. */
  ampY: Float64Array;
  /** Amplitude A, z component. */
  ampZ: Float64Array;
  /** Angular frequency omega, rad/s. */
  omega: Float64Array;
  /** Phase, rad. */
  phase: Float64Array;
}

/**
 * What a particle looks like at birth and at death (an emitter's for the particles it makes, a
 * particle's own), interpolated linearly in age / duration by renderers.
 * @category Particles
 */
export interface ParticleLooks {
  /** Colour at birth, 0xRRGGBB. */
  colorStart: Uint32Array;
  /** Colour at death, 0xRRGGBB. */
  colorEnd: Uint32Array;
  /** Size at birth, m. */
  sizeStart: Float64Array;
  /** Size at death, m. */
  sizeEnd: Float64Array;
  /** Alpha at birth, 0..1. */
  alphaStart: Float64Array;
  /** Alpha at death, 0..1. */
  alphaEnd: Float64Array;
}

function vec3(n: number): Vec3Store {
  return { x: new Float64Array(n), y: new Float64Array(n), z: new Float64Array(n) };
}

/** Empty ParticleLooks arrays (a store's group allocates them, materializeGroup). */
function looks(): ParticleLooks {
  const z = (): Float64Array => new Float64Array(0);
  return { colorStart: new Uint32Array(0), colorEnd: new Uint32Array(0), sizeStart: z(), sizeEnd: z(), alphaStart: z(), alphaEnd: z() };
}

/**
 * The stores of one world; see each field for meaning, unit and default.
 * @category Bodies
 */
export interface Components {
  /** Position of the body's centre of mass, m. Default (0, 0, 0). */
  Position: Vec3Store;
  /** Linear velocity of the centre of mass, m/s. Default 0. */
  Velocity: Vec3Store;
  /**
   * Position at the start of the most recent step, m. Written by the integrate stage for every
   * moving body; read by the collision stage (contacts are found where bodies were, as Box2D
   * does, and solved speculatively) and by renderers to interpolate between steps.
   */
  PreviousPosition: Vec3Store;
  /**
   * Force accumulator, N. Cleared at stage 2 of every step and summed by the force laws of
   * stage 3. Only bodies with this component feel force laws; adding any force-law component
   * adds it automatically. A body without it still feels the world's uniform gravity.
   */
  Force: Vec3Store;
  /**
   * Mass: `value` in kg (> 0 for dynamic bodies) and `inv` = 1 / value in 1/kg; `inv` = 0 means
   * infinite mass (static or kinematic). Default 1 kg. Write both through `setMass` so they stay
   * consistent; the solver reads only `inv`.
   */
  Mass: { value: Float64Array; inv: Float64Array };
  /**
   * Round collision shape: a circle in a 2D world, a sphere in a 3D world (Rapier's "ball").
   * `radius` in m, > 0. Default 0.5 m. Make balls with `addBody({ radius })`, `setRadius`, an emitter's
   * `particle.radius` or a rope's `radius`: these install the balls' collisions in the world the first
   * time (collision/install-balls.ts). An entity given this component with `addComponent` alone needs
   * `installBalls(world)`; `step` throws until it is called.
   */
  Ball: { radius: Float64Array };
  /**
   * Static line segment from (ax, ay, az) to (bx, by, bz), m: an inclined wall or floor that
   * bodies collide with, end points included (a body hitting an end point bounces off the point).
   * `radius` thickens it into a capsule, m, >= 0 (default 0). Segments never move.
   */
  Segment: {
    ax: Float64Array;
    ay: Float64Array;
    az: Float64Array;
    bx: Float64Array;
    by: Float64Array;
    bz: Float64Array;
    radius: Float64Array;
  };
  /**
   * Surface material for contacts. `restitution` in [0, 1] (ratio of separating to approaching
   * normal speed; default 0); `friction` the kinetic Coulomb coefficient mu_k >= 0 (default 0.6);
   * `staticFriction` mu_s >= 0 used while a contact sticks (default equal to friction).
   * A pair combines as Box2D does: restitution = max(e_a, e_b), friction = sqrt(mu_a mu_b).
   */
  Material: { restitution: Float64Array; friction: Float64Array; staticFriction: Float64Array };
  /** Tag: the body never moves and has infinite mass (walls, pegs). */
  Static: object;
  /** Tag: the body moves with its velocity, ignores forces, and has infinite mass in contacts. */
  Kinematic: object;
  /**
   * Tag: the body is asleep: at rest in a resting island, skipped by integration and the contact
   * solver until something wakes it (see islands/sleep.ts). Added and removed by the engine.
   */
  Sleeping: object;
  /**
   * Linear (viscous, Stokes) drag F = -k v, with `k` in N s/m = kg/s, >= 0.
   * Source: Ramtal and Dobre, ch. 7 (drag); Stokes' law for small Reynolds numbers.
   */
  LinearDrag: { k: Float64Array };
  /**
   * Quadratic (form) drag F = -k |v| v, with `k` in N s^2/m^2 = kg/m, >= 0
   * (k = rho C_d A / 2 for a fluid of density rho, drag coefficient C_d and frontal area A).
   * Source: Ramtal and Dobre, ch. 7; any fluid-mechanics text for the drag equation.
   */
  QuadraticDrag: { k: Float64Array };
  /**
   * Per-body scale of the world's uniform gravity, dimensionless (1 = normal, 0 = floats, -1 = falls
   * up). Default 1. A force law: the body gets a force accumulator.
   */
  GravityScale: { value: Float64Array };
  /** Tag: the body takes part in mutual Newtonian gravity with every other tagged body (its mass is `Mass.value`). */
  MutualGravity: object;
  /**
   * A Newtonian attractor of `mass` kg that pulls every dynamic body with a force accumulator:
   * F = -G M m r / (r^2 + eps^2)^(3/2), r from the attractor, eps = `softening` (m, >= 0). The
   * attractor itself can be static (a sun, a black hole) or move. Source: Ramtal and Dobre ch. 6.
   */
  Attractor: { mass: Float64Array; softening: Float64Array };
  /** Electric charge, C. Charged bodies repel or attract in pairs (Coulomb) and feel electric and magnetic fields. Default 0. */
  Charge: { value: Float64Array };
  /**
   * A uniform electric field, V/m, filling the world: E(t) = E0 + A cos(omega t + phase), with E0 =
   * (x, y, z), A = (ampX, ampY, ampZ), `omega` rad/s, `phase` rad. Charged bodies feel q E.
   */
  ElectricField: OscillatingField;
  /**
   * A uniform magnetic field, T: B(t) = B0 + A cos(omega t + phase), fields as ElectricField. In a 2D
   * world only z is used (B out of the screen). Charged bodies feel the Lorentz force q v x B.
   */
  MagneticField: OscillatingField;
  /**
   * General central force about the point (cx, cy, cz): F = k r^(n-1) r_hat, r the distance from the
   * centre. k < 0 attracts. n = 2 is Hooke's law (k = -stiffness), n = -1 inverse-square gravity
   * (k = -G M m). Units of k: N / m^(n-1). Source: Ramtal and Dobre ch. 6, "central forces".
   */
  CentralForce: { cx: Float64Array; cy: Float64Array; cz: Float64Array; k: Float64Array; n: Float64Array };
  /**
   * Lift perpendicular to the velocity relative to the air: F = k |v_rel| (axis x v_rel), with `k`
   * in kg/m (k = rho C_L A / 2) and `axis` the unit span axis (default z: in 2D the lift points to
   * the left of the motion). Source: Ramtal and Dobre ch. 7, "lift".
   */
  Lift: { k: Float64Array; axisX: Float64Array; axisY: Float64Array; axisZ: Float64Array };
  /**
   * Buoyancy and fluid drag for a body in a FluidRegion: `shape` 0 = ball of radius `radius` (circle
   * in 2D: area per unit depth), 1 = box of half extents (halfX, halfY, halfZ) (2D: rectangle). The
   * fluid pushes up with rho g V_submerged and drags with -f k |v_rel| v_rel, f the submerged fraction
   * and `dragCoefficient` k in kg/m. Source: Ramtal and Dobre ch. 7, "upthrust".
   */
  Buoyancy: {
    shape: Float64Array;
    radius: Float64Array;
    halfX: Float64Array;
    halfY: Float64Array;
    halfZ: Float64Array;
    dragCoefficient: Float64Array;
  };
  /**
   * A body of fluid below the horizontal surface y = `surface` (m), of `density` kg/m^3 (2D: kg/m^2),
   * optionally limited to x in [minX, maxX] and z in [minZ, maxZ] (defaults: unlimited).
   */
  FluidRegion: {
    surface: Float64Array;
    density: Float64Array;
    minX: Float64Array;
    maxX: Float64Array;
    minZ: Float64Array;
    maxZ: Float64Array;
  };
  /**
   * A spring between bodies `a` and `b` (entity ids), or between body `b` and the fixed anchor
   * (anchorX, anchorY, anchorZ) when `a` is 0. Hooke: F = -stiffness (L - restLength) along the
   * spring, plus damping -damping (relative velocity along the spring). `oneSided` 1 makes a bungee
   * (pulls only while stretched). Units: stiffness N/m, damping N s/m, lengths m. The spring is its
   * own entity; removing either body removes it. Source: Ramtal and Dobre ch. 8.
   */
  Spring: {
    a: Int32Array;
    b: Int32Array;
    restLength: Float64Array;
    stiffness: Float64Array;
    damping: Float64Array;
    oneSided: Uint8Array;
    anchorX: Float64Array;
    anchorY: Float64Array;
    anchorZ: Float64Array;
  };
  /**
   * Periodic driving force F = F0 cos(omega t + phase), F0 = (x, y, z) in N, omega rad/s, phase rad.
   * Source: Ramtal and Dobre ch. 8, "forced oscillations".
   */
  DrivingForce: { x: Float64Array; y: Float64Array; z: Float64Array; omega: Float64Array; phase: Float64Array };
  /**
   * Seeded random driving force: a smooth random vector of magnitude up to `magnitude` N whose
   * direction and size change over `correlationTime` s (value noise, a pure function of time and
   * `seed`, so every integrator sees the same force at the same time).
   */
  RandomForce: { magnitude: Float64Array; correlationTime: Float64Array; seed: Float64Array };
  /**
   * Rocket thrust with burning fuel: while `fuel` (kg) lasts, a force ve mdot along the unit
   * direction (dirX, dirY, dirZ) (world frame), with `exhaustVelocity` ve (m/s) and `massFlowRate`
   * mdot (kg/s); the body's mass drops by mdot per second and `fuel` with it. Source: Ramtal and
   * Dobre ch. 6, "rockets"; Tsiolkovsky's equation dv = ve ln(m0 / m1).
   */
  Thrust: {
    exhaustVelocity: Float64Array;
    massFlowRate: Float64Array;
    fuel: Float64Array;
    dirX: Float64Array;
    dirY: Float64Array;
    dirZ: Float64Array;
  };
  /**
   * A swirl about an axis through (cx, cy, cz): tangential force F = k r^(n-1) (axis x r_hat), r the
   * distance from the axis, `k` in N / m^(n-1) (positive: counter-clockwise about the axis), axis unit
   * (default z, the only axis that makes sense in 2D). Particles in a whirlpool or tornado.
   */
  Vortex: {
    cx: Float64Array;
    cy: Float64Array;
    cz: Float64Array;
    axisX: Float64Array;
    axisY: Float64Array;
    axisZ: Float64Array;
    k: Float64Array;
    n: Float64Array;
  };
  /**
   * A particle emitter on an entity with Position (and Velocity, to pass some of it on). See
   * particles/emitter.ts and `addEmitter` for every field; all units SI (rates per second, speeds
   * m/s, angles rad, lifetimes s).
   */
  Emitter: {
    rate: Float64Array;
    carry: Float64Array;
    pendingBurst: Float64Array;
    enabled: Uint8Array;
    shape: Uint8Array;
    size: Float64Array;
    sizeY: Float64Array;
    sizeZ: Float64Array;
    dirX: Float64Array;
    dirY: Float64Array;
    dirZ: Float64Array;
    spread: Float64Array;
    projectSphere: Uint8Array;
    speedMin: Float64Array;
    speedMax: Float64Array;
    lifeMin: Float64Array;
    lifeMax: Float64Array;
    inherit: Float64Array;
    mass: Float64Array;
    linearDrag: Float64Array;
    quadraticDrag: Float64Array;
    gravityScale: Float64Array;
    radius: Float64Array;
    deathEmitter: Int32Array;
    deathCount: Float64Array;
    maxGeneration: Float64Array;
    policy: Uint8Array;
    spawned: Float64Array;
    dropped: Float64Array;
  } & ParticleLooks;
  /** Age and lifetime of a particle, s: it is removed when `age` reaches `duration`. */
  Lifetime: { age: Float64Array; duration: Float64Array };
  /**
   * What a particle looks like over its life, for renderers: colour (0xRRGGBB), size (m) and alpha
   * (0..1) at birth and at death, interpolated linearly in age / duration; `emitter` that made it and
   * that emitter's spawn stamp (so a recycled emitter id is not mistaken for it); `generation` (0 for
   * emitted, +1 for each burst on death).
   */
  Particle: {
    emitter: Int32Array;
    emitterStamp: Uint32Array;
    generation: Float64Array;
  } & ParticleLooks;
  /** Rotation angle in a 2D world, rad, counter-clockwise. Default 0. */
  Angle: { value: Float64Array };
  /**
   * Unit quaternion orientation in a 3D world (x, y, z, w), rotating body frame to world frame.
   * Default identity (0, 0, 0, 1).
   */
  Orientation: { x: Float64Array; y: Float64Array; z: Float64Array; w: Float64Array };
  /** Angular velocity, rad/s, world frame. In 2D only z is used (counter-clockwise positive). Default 0. */
  AngularVelocity: Vec3Store;
  /** Torque accumulator, N m, world frame; cleared with Force. In 2D only z is used. */
  Torque: Vec3Store;
  /**
   * Scalar moment of inertia about the centre of mass: `value` in kg m^2, `inv` in 1/(kg m^2),
   * `inv` = 0 locks rotation. For a ball: solid disc m r^2 / 2 in 2D, solid sphere 2 m r^2 / 5 in 3D.
   * Default 0 (no rotation) until set by `addBody` or `setInertia`.
   */
  Inertia: { value: Float64Array; inv: Float64Array };
  /**
   * Principal moments of inertia in the body frame, kg m^2 (x, y, z), and their inverses (invX...,
   * 1/(kg m^2); 0 locks rotation about that axis). The body frame's axes are the principal axes; the
   * world-frame tensor is I_w = R diag(x, y, z) R^T with R from `Orientation`. 3D only. A body with
   * this component turns by Euler's equations I dw/dt = tau - w x I w (its `Inertia` is not used).
   */
  InertiaTensor: { x: Float64Array; y: Float64Array; z: Float64Array; invX: Float64Array; invY: Float64Array; invZ: Float64Array };
  /** Angular damping: torque -k w, with `k` in N m s (>= 0). A torque law. */
  AngularDamping: { k: Float64Array };
  /**
   * Static infinite plane n . x = d with unit normal (nx, ny, nz) pointing out of the solid side (m for
   * d): balls stay on the side n points to. In 2D it is an infinite line (nz = 0). Collides like a
   * segment; its Material gives restitution and friction.
   */
  Plane: { nx: Float64Array; ny: Float64Array; nz: Float64Array; d: Float64Array };
  /**
   * A convex collision shape of a 2D body: circle, capsule, box or polygon of up to 8 vertices, rounded
   * by a radius (shapes/geometry-2d.ts; added with `addShape` or `addBox`). The first shape of a body lives
   * on the body's own entity (`body` is then the entity itself); each further shape of a compound body
   * is its own entity holding its `body`, like a spring holds its two ends, and is removed with the
   * body. The Material of the entity a shape lives on is the shape's material. Fields, units and
   * defaults: see ShapeStore. Arrays are allocated when the world's first shape is added.
   */
  Shape: ShapeStore;
  /**
   * Ballast tanks of a submarine (forces/ballast.ts, `setBallast`): a fore and an aft tank of
   * `capacity` kg of water each, `fore` and `aft` their fill fractions in [0, 1] moving towards
   * `foreTarget` / `aftTarget` at `rate` (fraction/s); the body's mass is `dryMass` + capacity
   * (fore + aft). In 2D the tanks sit `arm` m fore and aft of the centre of mass along the hull, and
   * the hull has the metacentric height `metacentricHeight` m (its centre of buoyancy above its
   * centre of mass), which give the trim torques.
   */
  Ballast: {
    dryMass: Float64Array;
    capacity: Float64Array;
    fore: Float64Array;
    aft: Float64Array;
    foreTarget: Float64Array;
    aftTarget: Float64Array;
    rate: Float64Array;
    arm: Float64Array;
    metacentricHeight: Float64Array;
  };
  /**
   * A force fixed in the body frame, N (x, y, z; z unused in 2D), applied at the centre of mass and
   * turned with the body (`Orientation` in 3D, `Angle` in 2D): a propeller, a jet, a ship's screw.
   * Set with `setBodyThrust` (forces/body-thrust.ts).
   */
  BodyThrust: { x: Float64Array; y: Float64Array; z: Float64Array };
  /**
   * A lifting surface (wing half, tailplane, fin) of a rigid 3D body (forces/lifting-surface.ts,
   * `addLiftingSurface`): its own entity holding the `body` (entity id), the point `offset` (m, body
   * frame) where its force acts, its unit `normal` (body frame; the chord is the body's x axis made
   * perpendicular to it),
   * `area` m^2, lift slope `liftSlope` (1/rad), `stallAngle` rad, zero-lift drag `dragZero`, induced
   * drag factor `inducedDrag`, and a control surface: `deflection` rad times `controlPower` (1/rad).
   * Air density `airDensity` kg/m^3.
   */
  LiftingSurface: {
    body: Int32Array;
    offsetX: Float64Array;
    offsetY: Float64Array;
    offsetZ: Float64Array;
    normalX: Float64Array;
    normalY: Float64Array;
    normalZ: Float64Array;
    area: Float64Array;
    liftSlope: Float64Array;
    stallAngle: Float64Array;
    dragZero: Float64Array;
    inducedDrag: Float64Array;
    deflection: Float64Array;
    controlPower: Float64Array;
    airDensity: Float64Array;
  };
  /**
   * A joint between two 2D bodies (its own entity: see world/joint-store-2d.ts for every field and
   * joints/distance-joint.ts for addDistanceJoint, revolute-joint.ts for addRevoluteJoint, ...). Removing either body removes it.
   */
  Joint: JointStore;
  /** A link of a cloth between two point bodies (its own entity: see world/cloth-store.ts; `createCloth` makes them). */
  ClothLink: ClothLinkStore;
}

/**
 * The body group: the stores of anything more than a bare particle (forces, mass, rotation, a round
 * shape, a material). Its first use also allocates the collision state's per-entity scratch.
 * @category Bodies
 */
export const BODY_STORES: ReadonlyArray<keyof Components> = [
  'Force',
  'Torque',
  'Mass',
  'Inertia',
  'AngularVelocity',
  'Angle',
  'Orientation',
  'Ball',
  'Material',
];

/**
 * Stores allocated together, on the first use of any of them (see the module docstring). Each group
 * holds the stores that code reads side by side for the same entities: a body's mass, inertia, spin,
 * orientation, shape radius and material; a particle's lifetime and look. Every other lazy store is a
 * group of its own.
 * @category Bodies
 */
export const LAZY_GROUPS: ReadonlyArray<ReadonlyArray<keyof Components>> = [
  BODY_STORES,
  ['Lifetime', 'Particle'],
  ['Segment'],
  ['LinearDrag'],
  ['QuadraticDrag'],
  ['GravityScale'],
  ['Attractor'],
  ['Charge'],
  ['ElectricField'],
  ['MagneticField'],
  ['CentralForce'],
  ['Lift'],
  ['Buoyancy'],
  ['FluidRegion'],
  ['Spring'],
  ['DrivingForce'],
  ['RandomForce'],
  ['Thrust'],
  ['Vortex'],
  ['Emitter'],
  ['InertiaTensor'],
  ['AngularDamping'],
  ['Plane'],
  ['Ballast'],
  ['LiftingSurface'],
  ['BodyThrust'],
  ['Joint'],
  ['ClothLink'],
];

/**
 * Every lazily allocated component (the union of LAZY_GROUPS), in group order.
 * @category Bodies
 */
export const LAZY_COMPONENTS: ReadonlyArray<keyof Components> = LAZY_GROUPS.flat();

/**
 * The stores a component's first use allocates: its own group, and for `Emitter` the particle group too
 * (an emitter's particles are written by bulk spawn paths that may bypass per-component hooks).
 * Empty for a component that is always allocated (Position, Velocity, PreviousPosition, tags, Shape).
 * @category Bodies
 */
export function storesAllocatedWith(name: keyof Components): ReadonlyArray<keyof Components> {
  const own = LAZY_GROUPS.find((g) => g.includes(name)) ?? [];
  return name === 'Emitter' ? [...own, 'Lifetime', 'Particle'] : own;
}

type TypedArray = Float64Array | Int32Array | Uint32Array | Uint8Array;

/**
 * Gives every array of `store` room for `capacity` entities if it has none yet (see LAZY_GROUPS): the
 * store object keeps its identity, only its empty arrays are replaced by zero-filled ones, on a
 * SharedArrayBuffer if `shared` (a world with threads > 1). @returns whether it allocated anything.
 * @category Bodies
 */
export function materializeStore(store: object, capacity: number, shared = false): boolean {
  const rec = store as Record<string, TypedArray>;
  let made = false;
  for (const key of Object.keys(rec)) {
    const arr = rec[key]!;
    if (ArrayBuffer.isView(arr) && arr.length < capacity + 1) {
      const Ctor = arr.constructor as { new (n: number): TypedArray; new (b: ArrayBufferLike): TypedArray; BYTES_PER_ELEMENT: number };
      rec[key] = shared ? new Ctor(new SharedArrayBuffer((capacity + 1) * Ctor.BYTES_PER_ELEMENT)) : new Ctor(capacity + 1);
      made = true;
    }
  }
  return made;
}

/**
 * Allocates the stores that the first use of component `name` needs (`storesAllocatedWith(name)`) in
 * `components` if they are still empty. @returns whether anything was allocated.
 * @category Bodies
 */
export function materializeGroup(components: Components, name: keyof Components, capacity: number, shared = false): boolean {
  let made = false;
  for (const member of storesAllocatedWith(name)) if (materializeStore(components[member], capacity, shared)) made = true;
  return made;
}

/**
 * Makes the stores of a world with room for `capacity` entities (ids 1..capacity): Position, Velocity
 * and PreviousPosition allocated, every store of LAZY_GROUPS empty until `materializeGroup` gives it
 * its arrays (createPhysicsWorld does on the first use of the store's group), Shape empty until the
 * first shape. @param capacity integer >= 1 (checked by createPhysicsWorld).
 * @param previousPosition false: PreviousPosition starts empty too (createPhysicsWorld passes it for a
 *   world made with `interpolation: false` and one thread, which allocates it with the body group; see
 *   the module docstring). Default true.
 * @category Bodies
 */
export function createComponents(capacity: number, previousPosition = true): Components {
  const n = capacity + 1;
  const z = (): Float64Array => new Float64Array(0);
  return {
    Position: vec3(n),
    Velocity: vec3(n),
    PreviousPosition: vec3(previousPosition ? n : 0),
    Force: vec3(0),
    Mass: { value: z(), inv: z() },
    Ball: { radius: z() },
    Segment: { ax: z(), ay: z(), az: z(), bx: z(), by: z(), bz: z(), radius: z() },
    Material: { restitution: z(), friction: z(), staticFriction: z() },
    Static: {},
    Kinematic: {},
    Sleeping: {},
    LinearDrag: { k: z() },
    QuadraticDrag: { k: z() },
    GravityScale: { value: z() },
    MutualGravity: {},
    Attractor: { mass: z(), softening: z() },
    Charge: { value: z() },
    ElectricField: { x: z(), y: z(), z: z(), ampX: z(), ampY: z(), ampZ: z(), omega: z(), phase: z() },
    MagneticField: { x: z(), y: z(), z: z(), ampX: z(), ampY: z(), ampZ: z(), omega: z(), phase: z() },
    CentralForce: { cx: z(), cy: z(), cz: z(), k: z(), n: z() },
    Lift: { k: z(), axisX: z(), axisY: z(), axisZ: z() },
    Buoyancy: { shape: z(), radius: z(), halfX: z(), halfY: z(), halfZ: z(), dragCoefficient: z() },
    FluidRegion: { surface: z(), density: z(), minX: z(), maxX: z(), minZ: z(), maxZ: z() },
    Spring: {
      a: new Int32Array(0),
      b: new Int32Array(0),
      restLength: z(),
      stiffness: z(),
      damping: z(),
      oneSided: new Uint8Array(0),
      anchorX: z(),
      anchorY: z(),
      anchorZ: z(),
    },
    DrivingForce: { x: z(), y: z(), z: z(), omega: z(), phase: z() },
    RandomForce: { magnitude: z(), correlationTime: z(), seed: z() },
    Thrust: { exhaustVelocity: z(), massFlowRate: z(), fuel: z(), dirX: z(), dirY: z(), dirZ: z() },
    Vortex: { cx: z(), cy: z(), cz: z(), axisX: z(), axisY: z(), axisZ: z(), k: z(), n: z() },
    Emitter: {
      rate: z(),
      carry: z(),
      pendingBurst: z(),
      enabled: new Uint8Array(0),
      shape: new Uint8Array(0),
      size: z(),
      sizeY: z(),
      sizeZ: z(),
      dirX: z(),
      dirY: z(),
      dirZ: z(),
      spread: z(),
      projectSphere: new Uint8Array(0),
      speedMin: z(),
      speedMax: z(),
      lifeMin: z(),
      lifeMax: z(),
      inherit: z(),
      mass: z(),
      linearDrag: z(),
      quadraticDrag: z(),
      gravityScale: z(),
      radius: z(),
      ...looks(),
      deathEmitter: new Int32Array(0),
      deathCount: z(),
      maxGeneration: z(),
      policy: new Uint8Array(0),
      spawned: z(),
      dropped: z(),
    },
    Lifetime: { age: z(), duration: z() },
    Particle: {
      emitter: new Int32Array(0),
      emitterStamp: new Uint32Array(0),
      generation: z(),
      ...looks(),
    },
    Angle: { value: z() },
    Orientation: { x: z(), y: z(), z: z(), w: z() },
    AngularVelocity: vec3(0),
    Torque: vec3(0),
    Inertia: { value: z(), inv: z() },
    InertiaTensor: { x: z(), y: z(), z: z(), invX: z(), invY: z(), invZ: z() },
    AngularDamping: { k: z() },
    Plane: { nx: z(), ny: z(), nz: z(), d: z() },
    Shape: createEmptyShapeStore(),
    Ballast: {
      dryMass: z(),
      capacity: z(),
      fore: z(),
      aft: z(),
      foreTarget: z(),
      aftTarget: z(),
      rate: z(),
      arm: z(),
      metacentricHeight: z(),
    },
    BodyThrust: { x: z(), y: z(), z: z() },
    LiftingSurface: {
      body: new Int32Array(0),
      offsetX: z(),
      offsetY: z(),
      offsetZ: z(),
      normalX: z(),
      normalY: z(),
      normalZ: z(),
      area: z(),
      liftSlope: z(),
      stallAngle: z(),
      dragZero: z(),
      inducedDrag: z(),
      deflection: z(),
      controlPower: z(),
      airDensity: z(),
    },
    Joint: createJointStore(),
    ClothLink: createClothLinkStore(),
  };
}

/**
 * Default material values, documented on `Components.Material`.
 * @category Bodies
 */
export const DEFAULT_MATERIAL = Object.freeze({ restitution: 0, friction: 0.6 });

/**
 * Default ball radius in m, documented on `Components.Ball`.
 * @category Bodies
 */
export const DEFAULT_RADIUS = 0.5;
