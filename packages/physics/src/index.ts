/**
 * @bitphysics/physics: components, systems, the staged step, collisions, diagnostics and scenes.
 * Everything is SI (m, kg, s, rad, N), y up, angles counter-clockwise.
 */

/**
 * bitecs' own functions for raw ECS use on a physics world (`addComponent(world, slotOf(e),
 * world.components.LinearDrag)`), re-exported so a project needs no import of its own from bitecs.
 * They take slots, not handles: pass `slotOf(handle)` (and use `isAlive(world, handle)`, not
 * entityExists, to ask whether an entity handed out by the API still exists).
 * bitecs is a peer dependency: the project and every bitphysics package share one copy.
 */
export { addComponent, entityExists, getEntityComponents, hasComponent, removeComponent } from 'bitecs';
export type { BodyOptions, BoundaryOptions, MaterialOptions, ParticleOptions, SegmentOptions } from './bodies/api.js';
export {
  addBody,
  addParticle,
  addSegment,
  applyImpulse,
  clearBoundary,
  createEntity,
  removeBody,
  setAngularVelocity,
  setBoundary,
  setGravity,
  setMass,
  setMaterial,
  setOrientation,
  setPosition,
  setRadius,
  setTimeStep,
  setVelocity,
} from './bodies/api.js';
export type { PlaneOptions } from './bodies/rigid.js';
export {
  addPlane,
  applyForceAtPoint,
  applyImpulseAtPoint,
  inertiaOfDisc,
  inertiaOfRectangle,
  inertiaOfSolidBox,
  inertiaOfSolidCylinder,
  inertiaOfSolidSphere,
  inertiaOfSphericalShell,
  setAngularDamping,
  setInertia,
  spinAngularMomentum,
  spinKineticEnergy,
} from './bodies/rigid.js';
export type { BoxOptions, ShapeOptions } from './bodies/shapes-2d.js';
export { addBox, addShape, setShapeFilter, shapesOf, updateMassFromShapes } from './bodies/shapes-2d.js';
export type { Shape3DOptions } from './bodies/shapes-3d.js';
export { addShape3D, hullOfShape3D, shapes3DOfBody, updateMassFromShapes3D } from './bodies/shapes-3d.js';
export type { Cloth, ClothOptions } from './cloth/create.js';
export { clothPointIndex, createCloth } from './cloth/create.js';
export type { ClothPinOptions } from './cloth/pin.js';
export { pinClothPoint } from './cloth/pin.js';
export { clothSystem } from './cloth/solver.js';
export { BodyType, broadphaseSystem, PairKind } from './collision/broadphase/grid.js';
export type { ContactEventList, ContactEventLists } from './collision/contact-events.js';
export { contactEvents, contactEvents3D, HIT_SPEED } from './collision/contact-events.js';
export type { ContactView, ContactView as Contact3DView } from './collision/contact-view.js';
export { forEachContact, forEachContact3D } from './collision/contact-view.js';
export type { ContactBuffer } from './collision/contacts.js';
export { ContactKind } from './collision/contacts.js';
export { installBalls } from './collision/install-balls.js';
export type { ManifoldBuffer, ShapeCollisionState } from './collision/manifolds-2d.js';
export { currentSeparation, narrowphaseSystem } from './collision/narrowphase/balls.js';
export type { Manifold } from './collision/narrowphase/manifold-2d.js';
export { collideCircles, collideHalfPlane, collideShapes, createManifold, segmentFractions } from './collision/narrowphase/manifold-2d.js';
export type { RayHit } from './collision/queries-2d.js';
export { overlapAABB, overlapPoint, rayCast, rayCastAll } from './collision/queries-2d.js';
export type { RayHit3D } from './collision/queries-3d.js';
export { overlapAABB3D, overlapPoint3D, rayCast3D, rayCastAll3D } from './collision/queries-3d.js';
export { shapeCollisionSystem } from './collision/shapes-2d.js';
export type { Boundary, CollisionSettings, CollisionState, SleepState } from './collision/state.js';
export { createPhysicsWorld } from './create-world.js';
export {
  angularMomentum,
  centralPotentialEnergy,
  contactCount,
  contactSpringEnergy,
  electricPotentialEnergy,
  gravitationalPotentialEnergy,
  kineticEnergy,
  linearMomentum,
  newtonianPotentialEnergy,
  potentialEnergy,
  springPotentialEnergy,
  stageTimings,
  totalEnergy,
} from './diagnostics/energy.js';
export type { Quantity, Recorder, RecorderOptions } from './diagnostics/recorder.js';
export { createRecorder } from './diagnostics/recorder.js';
export { angularDampingSystem } from './forces/angular-damping.js';
export type { BuoyancyOptions, FieldOptions, FluidRegionOptions, SpringOptions, SpringSettings } from './forces/api.js';
export {
  addElectricField,
  addFluidRegion,
  addMagneticField,
  addSpring,
  enableMutualGravity,
  setAttractor,
  setBuoyancy,
  setCentralForce,
  setCharge,
  setDrag,
  setDrivingForce,
  setElectricField,
  setFluidRegion,
  setGravityScale,
  setLift,
  setMagneticField,
  setRandomForce,
  setSpring,
  setThrust,
  setVortex,
} from './forces/api.js';
export type { BallastOptions } from './forces/ballast.js';
export { ballastFillSystem, ballastTrimSystem, setBallast, setBallastTarget } from './forces/ballast.js';
export { barnesHutGravity, treeField, treeFields, treeFieldsSorted, worldTreeFields } from './forces/barnes-hut/tree.js';
export { buildTree } from './forces/barnes-hut/tree-build.js';
export type { GravityTree } from './forces/barnes-hut/tree-store.js';
export { worldTree } from './forces/barnes-hut/tree-store.js';
export { bodyThrustSystem, setBodyThrust } from './forces/body-thrust.js';
export { centralForceSystem } from './forces/central.js';
export { clearForcesSystem } from './forces/clear.js';
export type { GravitationOptions, WindOptions } from './forces/configure.js';
export { setElectrostatics, setGravitation, setWind, windAt } from './forces/configure.js';
export { liftSystem, linearDragSystem, quadraticDragSystem } from './forces/drag.js';
export { drivingForceSystem, randomForceSystem, valueNoise } from './forces/driving.js';
export { coulombSystem, fieldsAt, lorentzSystem } from './forces/electromagnetism.js';
export { evaluateForces } from './forces/evaluate.js';
export { BuoyancyShape, buoyancySystem, submergedMeasure } from './forces/fluid.js';
export { attractorSystem, gravityScaleSystem, mutualGravitySystem } from './forces/gravity.js';
export type { FieldErrorStats, GravityMomentumRate } from './forces/gravity-accuracy.js';
export {
  directField,
  fieldErrorStats,
  forceErrorMedian,
  gravityFieldError,
  gravityMomentumRate,
  sampleIndices,
} from './forces/gravity-accuracy.js';
export type { ForceLaw } from './forces/law.js';
export type { LiftingSurfaceOptions } from './forces/lifting-surface.js';
export {
  addLiftingSurface,
  DEFAULT_LIFT_SLOPE,
  dragCoefficient,
  liftCoefficient,
  liftingSurfaceSystem,
  removeSurfacesOf,
  setControlDeflection,
} from './forces/lifting-surface.js';
export { springSystem } from './forces/spring.js';
export { burnFuelSystem, thrustSystem } from './forces/thrust.js';
export { vortexSystem } from './forces/vortex.js';
export { eulerAcceleration } from './integrators/euler-equations.js';
export type { Integrator } from './integrators/integrate.js';
export { INTEGRATORS, integrateSystem } from './integrators/integrate.js';
export { isSleeping, sleepSystem, wakeAll, wakeBody, wakeSystem } from './islands/sleep.js';
export {
  isJoint,
  jointAnchors,
  jointAngle,
  jointLength,
  removeJoint,
  setJointLimits,
  setJointMotor,
  setJointSpring,
} from './joints/api-2d.js';
export { joint3DBreaks, removeJoint3D, setJoint3DBreak, setJoint3DLimits, setJoint3DMotor } from './joints/api-3d.js';
export type { BallJoint3DOptions } from './joints/ball-joint-3d.js';
export { addBallJoint3D, setBallJoint3DCone } from './joints/ball-joint-3d.js';
export type { DistanceJointOptions } from './joints/distance-joint.js';
export { addDistanceJoint } from './joints/distance-joint.js';
export type { DistanceJoint3DOptions } from './joints/distance-joint-3d.js';
export { addDistanceJoint3D, setDistanceJoint3DLength, setDistanceJoint3DSpring } from './joints/distance-joint-3d.js';
export type { FixedJoint3DOptions } from './joints/fixed-joint-3d.js';
export { addFixedJoint3D } from './joints/fixed-joint-3d.js';
export type { HingeJoint3DOptions } from './joints/hinge-joint-3d.js';
export { addHingeJoint3D } from './joints/hinge-joint-3d.js';
export type { Joint3DBaseOptions } from './joints/joint-3d.js';
export type { JointBaseOptions } from './joints/joint-base.js';
export type { MouseJointOptions } from './joints/mouse-joint.js';
export { addMouseJoint, setMouseTarget } from './joints/mouse-joint.js';
export type { PrismaticJointOptions } from './joints/prismatic-joint.js';
export { addPrismaticJoint } from './joints/prismatic-joint.js';
export type { RevoluteJointOptions } from './joints/revolute-joint.js';
export { addRevoluteJoint } from './joints/revolute-joint.js';
export type { Rope, RopeOptions } from './joints/rope.js';
export { createRope } from './joints/rope.js';
export type { SliderJoint3DOptions } from './joints/slider-joint-3d.js';
export { addSliderJoint3D } from './joints/slider-joint-3d.js';
export type { Joint3DStore } from './joints/store-3d.js';
export { Joint3DFlag, Joint3DType, joints3DOf } from './joints/store-3d.js';
export type { WeldJointOptions } from './joints/weld-joint.js';
export { addWeldJoint } from './joints/weld-joint.js';
export type { WheelJointOptions } from './joints/wheel-joint.js';
export { addWheelJoint } from './joints/wheel-joint.js';
export { rotateFrom, rotateInPlace, rotateVector, rotateVectorInverse } from './math/quaternion.js';
export { Rng } from './math/rng.js';
export type { BulkParticleOptions } from './particles/bulk.js';
export { addParticles } from './particles/bulk.js';
export type { ParticleLook } from './particles/emitter.js';
export {
  addEmitter,
  burst,
  emitNow,
  onParticleBirth,
  onParticleDeath,
  particleLook,
  particlesExpired,
  setEmitter,
  setEmitterEnabled,
  setEmitterRate,
} from './particles/emitter.js';
export type { EmittedParticleOptions, EmitterOptions, ParticleBirthHook, ParticleDeathHook } from './particles/emitter-options.js';
export { CapacityPolicy, EmitterShape, MAX_EMITTER_RATE, maxSpawnsPerStep } from './particles/emitter-options.js';
export { emitterSystem, lifetimeSystem } from './particles/emitter-systems.js';
export * from './scenes/index.js';
export type { ConvexGeometry } from './shapes/geometry-2d.js';
export { MAX_POLYGON_VERTICES, makeBox, makeCapsule, makeCircle, makePolygon, ShapeKind } from './shapes/geometry-2d.js';
export type { Hull } from './shapes/hull-3d.js';
export { MAX_HULL_INPUT, MAX_HULL_VERTICES, quickhull } from './shapes/hull-3d.js';
export type { MassProperties } from './shapes/mass-2d.js';
export { shapeMassProperties } from './shapes/mass-2d.js';
export type { MassProperties3D } from './shapes/mass-3d.js';
export { boxMass, capsuleMass, cylinderMass, hullMass, hullVolume, principalAxes, sphereMass } from './shapes/mass-3d.js';
export type { HeightFieldOptions, Mesh3D, TriangleMeshOptions } from './shapes/mesh-3d.js';
export { addHeightField3D, addTriangleMesh3D, MAX_HEIGHT_FIELD_POINTS, meshesOf } from './shapes/mesh-3d.js';
export type { Shape3DStore } from './shapes/store-3d.js';
export { Shape3DKind, shapes3DOf } from './shapes/store-3d.js';
export type { Encoded, SnapshotHeader, WorldSnapshot } from './snapshot/format.js';
export { stateHash } from './snapshot/hash.js';
export type { InputEvent, InputHandlers, InputRecorder, Replay, ReplayOptions, ReplayPlayer } from './snapshot/replay.js';
export { createInputRecorder, createReplayPlayer, playReplay } from './snapshot/replay.js';
/** Snapshots (save, load, rewind, rollback) and a state fingerprint for determinism checks. */
export { restore, snapshot } from './snapshot/snapshot.js';
export { CONTACT_LENGTH_UNIT, contactLength, MAX_AUTO_SUBSTEPS, solverSubstepsFor } from './solver/contact-scale.js';
export { contactSolverSystem } from './solver/contact-solver.js';
export { enableThreads } from './step/enable-threads.js';
export type { FixedStepLoop, FixedStepLoopOptions, FrameResult } from './step/loop.js';
export { createFixedStepLoop } from './step/loop.js';
export type { StageName, System } from './step/stages.js';
export { PIPELINE, STAGES, SUBSTEP_STAGES } from './step/stages.js';
export type { AddSystemOptions } from './step/step.js';
export { addSystem, removeSystem, step, stepMany } from './step/step.js';
export { MIN_PARALLEL_PER_THREAD } from './threads/parallel.js';
export { WARM_UP_PILE_BALLS, WARM_UP_STEPS, type WarmUpOptions, warmUp } from './warm-up.js';
export type { ClothState } from './world/cloth-state.js';
export type { ClothLinkStore } from './world/cloth-store.js';
export { ClothLinkKind } from './world/cloth-store.js';
export type { Components, OscillatingField, ParticleLooks, Vec3Store } from './world/components.js';
export {
  createComponents,
  DEFAULT_MATERIAL,
  DEFAULT_RADIUS,
  LAZY_COMPONENTS,
  LAZY_GROUPS,
  materializeGroup,
  materializeStore,
  storesAllocatedWith,
} from './world/components.js';
export { NonFiniteStateError } from './world/errors.js';
export type { ForceLawSettings, GravityMethod, WindField } from './world/force-settings.js';
export { COULOMB_SI, G_SI, MAX_WIND_MODES } from './world/force-settings.js';
export type { EntityKind } from './world/handles.js';
/**
 * Entity handles: the API hands out and accepts handles (slot + generation * 2^25); stores are indexed
 * by slot. Index stores with slotOf(e); query() gives slots; handleOf turns a slot into a handle.
 */
export { handleOf, isAlive, resolveEntity, SLOT_RANGE, slotOf } from './world/handles.js';
export type { IntegratorName } from './world/integrator-names.js';
export { INTEGRATOR_NAMES, INTEGRATOR_ORDER } from './world/integrator-names.js';
export type { JointBreakEvents, JointSettings, JointState } from './world/joint-state-2d.js';
export type { JointStore, JointTypeCode } from './world/joint-store-2d.js';
export { JOINT_TYPE_NAMES, JointFlag, JointType } from './world/joint-store-2d.js';
export type { PhysicsWorld, PhysicsWorldContext, PhysicsWorldOptions, StageTimings } from './world/options.js';
export { addComponentIfMissing, disposeWorld, MAX_CAPACITY, MAX_TIME_STEP, registerForceLaw, threadsReady } from './world/options.js';
export { Not, query } from './world/query.js';
export type { ShapeStore } from './world/shape-store-2d.js';
