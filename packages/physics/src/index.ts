/**
 * @bitphysics/physics: components, systems, the staged step, collisions, diagnostics and scenes.
 * Everything is SI (m, kg, s, rad, N), y up, angles counter-clockwise.
 */
export { createPhysicsWorld, registerForceLaw, addComponentIfMissing, MAX_CAPACITY } from './world';
export type { PhysicsWorld, PhysicsWorldContext, PhysicsWorldOptions, StageTimings } from './world';
export { createComponents, DEFAULT_MATERIAL, DEFAULT_RADIUS } from './components';
export type { Components, Vec3Store } from './components';
export {
  createEntity, addBody, addParticle, addSegment, setBoundary, clearBoundary, removeBody,
  setMass, setMaterial, setRadius, setPosition, setVelocity, applyImpulse,
} from './bodies';
export type { BodyOptions, ParticleOptions, SegmentOptions, BoundaryOptions, MaterialOptions } from './bodies';
export { STAGES, SUBSTEP_STAGES, PIPELINE } from './pipeline/stages';
export type { StageName, System } from './pipeline/stages';
export { step, stepMany, evaluateForces, addSystem, removeSystem } from './pipeline/step';
export type { AddSystemOptions } from './pipeline/step';
export { createFixedStepLoop } from './pipeline/loop';
export type { FixedStepLoop, FixedStepLoopOptions, FrameResult } from './pipeline/loop';
export { INTEGRATOR_NAMES } from './integrators/names';
export type { IntegratorName } from './integrators/names';
export { INTEGRATORS, integrateSystem } from './integrators/integrate';
export type { Integrator } from './integrators/integrate';
export { clearForcesSystem } from './forces/clear';
export { linearDragSystem, quadraticDragSystem } from './forces/drag';
export { broadphaseSystem, BodyType, PairKind } from './collision/broadphase';
export { narrowphaseSystem, currentSeparation } from './collision/narrowphase';
export { contactSolverSystem } from './collision/solver';
export { ContactKind } from './collision/contacts';
export type { ContactBuffer } from './collision/contacts';
export type { CollisionState, CollisionSettings, Boundary } from './collision/state';
export {
  kineticEnergy, gravitationalPotentialEnergy, contactSpringEnergy, totalEnergy, linearMomentum, contactCount, stageTimings,
} from './diagnostics/energy';
export { NonFiniteStateError } from './errors';
export { Rng } from './rng';
export * from './scenes/index';
