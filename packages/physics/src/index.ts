/**
 * @bitphysics/physics: components, systems, the staged step, collisions, diagnostics and scenes.
 * Everything is SI (m, kg, s, rad, N), y up, angles counter-clockwise.
 */
export { createPhysicsWorld } from './create-world.js';
export { registerForceLaw, addComponentIfMissing, disposeWorld, threadsReady, MAX_CAPACITY, MAX_TIME_STEP } from './world.js';
export { MIN_PARALLEL_PER_THREAD } from './threads/parallel.js';
export type { PhysicsWorld, PhysicsWorldContext, PhysicsWorldOptions, StageTimings } from './world.js';
export { createComponents, DEFAULT_MATERIAL, DEFAULT_RADIUS, LAZY_COMPONENTS, LAZY_GROUPS, materializeStore, materializeGroup, storesAllocatedWith } from './components.js';
export type { Components, Vec3Store } from './components.js';
export {
  createEntity, addBody, addParticle, addSegment, setBoundary, clearBoundary, removeBody,
  setMass, setMaterial, setRadius, setPosition, setVelocity, applyImpulse, setGravity, setTimeStep,
  setAngularVelocity, setOrientation,
} from './bodies.js';
export type { BodyOptions, ParticleOptions, SegmentOptions, BoundaryOptions, MaterialOptions } from './bodies.js';
/**
 * Entity handles: the API hands out and accepts handles (slot + generation * 2^25); stores are indexed
 * by slot. Index stores with slotOf(e); query() gives slots; handleOf turns a slot into a handle.
 */
export { slotOf, handleOf, isAlive, resolveEntity, SLOT_RANGE } from './handles.js';
export type { EntityKind } from './handles.js';
export {
  inertiaOfSolidSphere, inertiaOfSphericalShell, inertiaOfSolidBox, inertiaOfSolidCylinder, inertiaOfDisc, inertiaOfRectangle,
  setInertia, applyForceAtPoint, applyImpulseAtPoint, spinAngularMomentum, spinKineticEnergy, setAngularDamping, addPlane,
} from './rigid.js';
export type { PlaneOptions } from './rigid.js';
export { rotateVector, rotateVectorInverse, rotateFrom, rotateInPlace } from './math/quaternion.js';
export { eulerAcceleration } from './integrators/euler-equations.js';
export { angularDampingSystem } from './forces/angular-damping.js';
export { STAGES, SUBSTEP_STAGES, PIPELINE } from './pipeline/stages.js';
export type { StageName, System } from './pipeline/stages.js';
export { step, stepMany, evaluateForces, addSystem, removeSystem } from './pipeline/step.js';
export type { AddSystemOptions } from './pipeline/step.js';
export { createFixedStepLoop } from './pipeline/loop.js';
export type { FixedStepLoop, FixedStepLoopOptions, FrameResult } from './pipeline/loop.js';
export { INTEGRATOR_NAMES, INTEGRATOR_ORDER } from './integrators/names.js';
export type { IntegratorName } from './integrators/names.js';
export { INTEGRATORS, integrateSystem } from './integrators/integrate.js';
export type { Integrator } from './integrators/integrate.js';
export { clearForcesSystem } from './forces/clear.js';
export { linearDragSystem, quadraticDragSystem } from './forces/drag.js';
export { broadphaseSystem, BodyType, PairKind } from './collision/broadphase.js';
export { narrowphaseSystem, currentSeparation } from './collision/narrowphase.js';
export { contactSolverSystem } from './collision/solver.js';
export { CONTACT_LENGTH_UNIT, MAX_AUTO_SUBSTEPS, contactLength, solverSubstepsFor } from './collision/contact-scale.js';
export { shapeCollisionSystem } from './collision/shape-collision.js';
export { rayCast, rayCastAll, overlapPoint, overlapAABB } from './collision/shape-queries.js';
export type { RayHit } from './collision/shape-queries.js';
export type { ManifoldBuffer, ContactEvents, EventList, ShapeCollisionState } from './collision/manifolds.js';
export { collideShapes, collideHalfPlane, collideCircles, createManifold, segmentFractions } from './collision/manifold.js';
export type { Manifold } from './collision/manifold.js';
export { addShape, addBox, setShapeFilter, shapesOf, updateMassFromShapes } from './shapes/api.js';
export type { ShapeOptions, BoxOptions } from './shapes/api.js';
export { ShapeKind, MAX_POLYGON_VERTICES, makeBox, makeCapsule, makeCircle, makePolygon } from './shapes/geometry.js';
export type { ConvexGeometry } from './shapes/geometry.js';
export { shapeMassProperties } from './shapes/mass.js';
export type { MassProperties } from './shapes/mass.js';
export type { ShapeStore } from './shapes/store.js';
export { addShape3D, updateMassFromShapes3D, shapes3DOfBody, hullOfShape3D } from './shapes3d/api.js';
export type { Shape3DOptions } from './shapes3d/api.js';
export { quickhull, MAX_HULL_VERTICES, MAX_HULL_INPUT } from './shapes3d/hull.js';
export type { Hull } from './shapes3d/hull.js';
export { sphereMass, boxMass, capsuleMass, cylinderMass, hullMass, hullVolume, principalAxes } from './shapes3d/mass.js';
export type { MassProperties3D } from './shapes3d/mass.js';
export { Shape3DKind, shapes3DOf } from './shapes3d/store.js';
export type { Shape3DStore } from './shapes3d/store.js';
export { rayCast3D, rayCastAll3D, overlapPoint3D, overlapAABB3D } from './collision/shape3d-queries.js';
export type { RayHit3D } from './collision/shape3d-queries.js';
export { addTriangleMesh3D, addHeightField3D } from './collision/mesh3d.js';
export type { TriangleMeshOptions, HeightFieldOptions, Mesh3D } from './collision/mesh3d.js';
export { contactEvents3D } from './collision/manifold3d-solver.js';
export type { ContactEvents3D, EventList3D } from './collision/manifolds3d-state.js';
export { forEachContact3D } from './collision/contacts3d-view.js';
export { meshesOf } from './collision/mesh3d.js';
export type { Contact3DView } from './collision/contacts3d-view.js';
export { addBallJoint3D, addHingeJoint3D, addFixedJoint3D, addDistanceJoint3D, addSliderJoint3D, removeJoint3D, joint3DBreaks } from './joints3d/api.js';
export { setBallJoint3DCone, setDistanceJoint3DLength, setDistanceJoint3DSpring, setJoint3DBreak, setJoint3DLimits, setJoint3DMotor } from './joints3d/api.js';
export type { Joint3DBaseOptions, BallJoint3DOptions, HingeJoint3DOptions, FixedJoint3DOptions, DistanceJoint3DOptions, SliderJoint3DOptions } from './joints3d/api.js';
export { Joint3DType, Joint3DFlag, joints3DOf } from './joints3d/store.js';
export type { Joint3DStore } from './joints3d/store.js';
export { sleepSystem, wakeSystem, wakeBody, wakeAll, isSleeping } from './collision/sleep.js';
export type { SleepState } from './collision/state.js';
export { ContactKind, forEachContact } from './collision/contacts.js';
export type { ContactView } from './collision/contacts.js';
export type { ContactBuffer } from './collision/contacts.js';
export type { CollisionState, CollisionSettings, Boundary } from './collision/state.js';
export {
  kineticEnergy, gravitationalPotentialEnergy, newtonianPotentialEnergy, springPotentialEnergy, electricPotentialEnergy,
  centralPotentialEnergy, potentialEnergy, contactSpringEnergy, totalEnergy, linearMomentum, angularMomentum,
  contactCount, stageTimings,
} from './diagnostics/energy.js';
export { createRecorder } from './diagnostics/recorder.js';
export type { Recorder, RecorderOptions, Quantity } from './diagnostics/recorder.js';
export {
  setGravityScale, enableMutualGravity, setAttractor, setCharge, addElectricField, addMagneticField, setCentralForce,
  setDrag, setLift, setBuoyancy, addFluidRegion, addSpring, setDrivingForce, setRandomForce, setThrust, setVortex,
  setElectricField, setMagneticField, setFluidRegion, setSpring,
} from './forces/api.js';
export { vortexSystem } from './forces/vortex.js';
export {
  addEmitter, setEmitter, burst, emitNow, setEmitterEnabled, setEmitterRate, onParticleDeath, onParticleBirth, particlesExpired, particleLook, lifetimeSystem, emitterSystem,
  EmitterShape, CapacityPolicy, MAX_EMITTER_RATE, maxSpawnsPerStep,
} from './particles/emitter.js';
export type { EmitterOptions, EmittedParticleOptions, ParticleBirthHook, ParticleDeathHook, ParticleLook } from './particles/emitter.js';
export { addParticles } from './particles/bulk.js';
export type { BulkParticleOptions } from './particles/bulk.js';
export type { FieldOptions, BuoyancyOptions, SpringOptions, SpringSettings, FluidRegionOptions } from './forces/api.js';
export { G_SI, COULOMB_SI, MAX_WIND_MODES } from './forces/settings.js';
export { setGravitation, setElectrostatics, setWind, windAt } from './forces/configure.js';
export type { ForceLawSettings, WindField, GravityMethod } from './forces/settings.js';
export type { WindOptions, GravitationOptions } from './forces/configure.js';
export type { ForceLaw } from './forces/law.js';
export { gravityScaleSystem, mutualGravitySystem, attractorSystem } from './forces/gravity.js';
export { coulombSystem, lorentzSystem, fieldsAt } from './forces/electromagnetism.js';
export { centralForceSystem } from './forces/central.js';
export { liftSystem } from './forces/drag.js';
export { buoyancySystem, submergedMeasure, BuoyancyShape } from './forces/fluid.js';
export { springSystem } from './forces/spring.js';
export { drivingForceSystem, randomForceSystem, valueNoise } from './forces/driving.js';
export { thrustSystem, burnFuelSystem } from './forces/thrust.js';
export { setBallast, setBallastTarget, ballastTrimSystem, ballastFillSystem } from './forces/ballast.js';
export type { BallastOptions } from './forces/ballast.js';
export { setBodyThrust, bodyThrustSystem } from './forces/body-thrust.js';
export {
  addLiftingSurface, setControlDeflection, liftingSurfaceSystem, liftCoefficient, dragCoefficient, removeSurfacesOf, DEFAULT_LIFT_SLOPE,
} from './forces/lifting-surface.js';
export type { LiftingSurfaceOptions } from './forces/lifting-surface.js';
export {
  buildTree, treeField, treeFields, treeFieldsSorted, worldTree, worldTreeFields, barnesHutGravity,
} from './forces/barnes-hut.js';
export {
  directField, sampleIndices, fieldErrorStats, gravityFieldError, forceErrorMedian, gravityMomentumRate,
} from './forces/gravity-accuracy.js';
export type { FieldErrorStats, GravityMomentumRate } from './forces/gravity-accuracy.js';
export type { GravityTree } from './forces/barnes-hut.js';
export { NonFiniteStateError } from './errors.js';
export { Rng } from './rng.js';
export { query, Not } from './query.js';
/**
 * bitecs' own functions for raw ECS use on a physics world (`addComponent(world, slotOf(e),
 * world.components.LinearDrag)`), re-exported so a project needs no import of its own from bitecs.
 * They take slots, not handles: pass `slotOf(handle)` (and use `isAlive(world, handle)`, not
 * entityExists, to ask whether an entity handed out by the API still exists).
 * bitecs is a peer dependency: the project and every bitphysics package share one copy.
 */
export { entityExists, hasComponent, addComponent, removeComponent, getEntityComponents } from 'bitecs';
export {
  addDistanceJoint, addRevoluteJoint, addPrismaticJoint, addWeldJoint, addWheelJoint, addMouseJoint, removeJoint, isJoint,
  setMouseTarget, setJointMotor, setJointLimits, setJointSpring, jointLength, jointAngle, jointAnchors,
} from './joints/api.js';
export type {
  JointBaseOptions, DistanceJointOptions, RevoluteJointOptions, PrismaticJointOptions, WeldJointOptions, WheelJointOptions, MouseJointOptions,
} from './joints/api.js';
export { JointType, JointFlag, JOINT_TYPE_NAMES } from './joints/store.js';
export type { JointStore, JointTypeCode } from './joints/store.js';
export type { JointState, JointSettings, JointBreakEvents } from './joints/state.js';
export { createRope } from './joints/rope.js';
export type { RopeOptions, Rope } from './joints/rope.js';
export { createCloth, clothPointIndex } from './cloth/create.js';
export { pinClothPoint } from './cloth/pin.js';
export type { ClothOptions, Cloth } from './cloth/create.js';
export { ClothLinkKind } from './cloth/store.js';
export type { ClothLinkStore } from './cloth/store.js';
export type { ClothState } from './cloth/state.js';
export { clothSystem } from './cloth/solver.js';
export * from './scenes/index.js';
/** Snapshots (save, load, rewind, rollback) and a state fingerprint for determinism checks. */
export { snapshot, restore } from './snapshot/snapshot.js';
export type { WorldSnapshot, SnapshotHeader, Encoded } from './snapshot/snapshot.js';
export { stateHash } from './snapshot/hash.js';
export { createInputRecorder, createReplayPlayer, playReplay } from './snapshot/replay.js';
export type { InputEvent, Replay, InputHandlers, ReplayOptions, InputRecorder, ReplayPlayer } from './snapshot/replay.js';
