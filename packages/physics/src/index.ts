/**
 * @bitphysics/physics: components, systems, the staged step, collisions, diagnostics and scenes.
 * Everything is SI (m, kg, s, rad, N), y up, angles counter-clockwise.
 */
export { createPhysicsWorld, registerForceLaw, addComponentIfMissing, MAX_CAPACITY } from './world';
export type { PhysicsWorld, PhysicsWorldContext, PhysicsWorldOptions, StageTimings } from './world';
export { createComponents, DEFAULT_MATERIAL, DEFAULT_RADIUS, LAZY_COMPONENTS, materializeStore } from './components';
export type { Components, Vec3Store } from './components';
export {
  createEntity, addBody, addParticle, addSegment, setBoundary, clearBoundary, removeBody,
  setMass, setMaterial, setRadius, setPosition, setVelocity, applyImpulse, setGravity, setTimeStep,
  setAngularVelocity, setOrientation,
} from './bodies';
export type { BodyOptions, ParticleOptions, SegmentOptions, BoundaryOptions, MaterialOptions } from './bodies';
export {
  inertiaOfSolidSphere, inertiaOfSphericalShell, inertiaOfSolidBox, inertiaOfSolidCylinder, inertiaOfDisc, inertiaOfRectangle,
  setInertia, applyForceAtPoint, applyImpulseAtPoint, spinAngularMomentum, spinKineticEnergy, setAngularDamping, addPlane,
} from './rigid';
export type { PlaneOptions } from './rigid';
export { rotateVector, rotateVectorInverse, rotateFrom, rotateInPlace } from './math/quaternion';
export { eulerAcceleration } from './integrators/euler-equations';
export { angularDampingSystem } from './forces/angular-damping';
export { STAGES, SUBSTEP_STAGES, PIPELINE } from './pipeline/stages';
export type { StageName, System } from './pipeline/stages';
export { step, stepMany, evaluateForces, addSystem, removeSystem } from './pipeline/step';
export type { AddSystemOptions } from './pipeline/step';
export { createFixedStepLoop } from './pipeline/loop';
export type { FixedStepLoop, FixedStepLoopOptions, FrameResult } from './pipeline/loop';
export { INTEGRATOR_NAMES, INTEGRATOR_ORDER } from './integrators/names';
export type { IntegratorName } from './integrators/names';
export { INTEGRATORS, integrateSystem } from './integrators/integrate';
export type { Integrator } from './integrators/integrate';
export { clearForcesSystem } from './forces/clear';
export { linearDragSystem, quadraticDragSystem } from './forces/drag';
export { broadphaseSystem, BodyType, PairKind } from './collision/broadphase';
export { narrowphaseSystem, currentSeparation } from './collision/narrowphase';
export { contactSolverSystem } from './collision/solver';
export { sleepSystem, wakeSystem, wakeBody, wakeAll, wakeIsland, isSleeping } from './collision/sleep';
export type { SleepState } from './collision/state';
export { ContactKind } from './collision/contacts';
export type { ContactBuffer } from './collision/contacts';
export type { CollisionState, CollisionSettings, Boundary } from './collision/state';
export {
  kineticEnergy, gravitationalPotentialEnergy, newtonianPotentialEnergy, springPotentialEnergy, electricPotentialEnergy,
  centralPotentialEnergy, potentialEnergy, contactSpringEnergy, totalEnergy, linearMomentum, angularMomentum,
  contactCount, stageTimings,
} from './diagnostics/energy';
export { createRecorder } from './diagnostics/recorder';
export type { Recorder, RecorderOptions, Quantity } from './diagnostics/recorder';
export {
  setGravityScale, enableMutualGravity, setAttractor, setCharge, addElectricField, addMagneticField, setCentralForce,
  setDrag, setLift, setBuoyancy, addFluidRegion, addSpring, setDrivingForce, setRandomForce, setThrust, setVortex,
} from './forces/api';
export { vortexSystem } from './forces/vortex';
export {
  addEmitter, setEmitter, burst, emitNow, setEmitterEnabled, setEmitterRate, onParticleDeath, particleLook, lifetimeSystem, emitterSystem,
  EmitterShape, CapacityPolicy,
} from './particles/emitter';
export type { EmitterOptions, EmittedParticleOptions, ParticleDeathHook, ParticleLook } from './particles/emitter';
export type { FieldOptions, BuoyancyOptions, SpringOptions } from './forces/api';
export {
  G_SI, COULOMB_SI, MAX_WIND_MODES, setGravitation, setElectrostatics, setWind, windAt,
} from './forces/settings';
export type { ForceLawSettings, WindField, WindOptions, GravitationOptions, GravityMethod } from './forces/settings';
export type { ForceLaw } from './forces/law';
export { gravityScaleSystem, mutualGravitySystem, attractorSystem } from './forces/gravity';
export { coulombSystem, lorentzSystem, fieldsAt } from './forces/electromagnetism';
export { centralForceSystem } from './forces/central';
export { liftSystem } from './forces/drag';
export { buoyancySystem, submergedMeasure, BuoyancyShape } from './forces/fluid';
export { springSystem } from './forces/spring';
export { drivingForceSystem, randomForceSystem, valueNoise } from './forces/driving';
export { thrustSystem, burnFuelSystem } from './forces/thrust';
export {
  buildTree, treeField, treeFields, treeFieldsSorted, worldTree, worldTreeFields, barnesHutGravity,
} from './forces/barnes-hut';
export {
  directField, sampleIndices, fieldErrorStats, gravityFieldError, forceErrorMedian, gravityMomentumRate,
} from './forces/gravity-accuracy';
export type { FieldErrorStats, GravityMomentumRate } from './forces/gravity-accuracy';
export type { GravityTree } from './forces/barnes-hut';
export { NonFiniteStateError } from './errors';
export { Rng } from './rng';
export { query, Not } from './query';
/** Whether an entity id is alive in the world (bitecs' entityExists). */
export { entityExists, hasComponent } from 'bitecs';
export * from './scenes/index';
