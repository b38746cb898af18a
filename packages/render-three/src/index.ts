/**
 * @bitphysics/render-three: draws a 3D bitphysics world with three.js.
 *
 * The renderer only reads component stores (Position, PreviousPosition, Orientation, AngularVelocity,
 * Ball, Mass, Inertia, InertiaTensor, Velocity, Plane, Segment), the boundary box and the contact
 * cache; it computes no physics, and the physics package never imports three.js. It owns the
 * conversion from SI metres to scene units (`unitsPerMeter`); y is up in both.
 *
 * Entry points: `WorldRenderer3D` (everything: instanced bodies, scenery, lights, trails, debug,
 * picking), `createOrbitControls` and `frameBox` (camera), `VectorArrow` (solid arrows for a few
 * physical vectors), `createLights`; and the three.js-free parts: `InstanceBook` (entity to
 * instance bookkeeping), the interpolation maths, colours.
 */
export { WorldRenderer3D } from './renderer';
export type { WorldRenderer3DOptions, BodyShape, Renderer3DStats, PickResult } from './renderer';
export { InstanceBook, MAX_GROUPS } from './book';
export type { InstanceBookListener } from './book';
export { InstanceGroup } from './groups';
export type { GroupKind } from './groups';
export { TrailLayer, resolveTrailOptions, MAX_TRAIL_POINTS } from './trails';
export type { TrailOptions, ResolvedTrailOptions } from './trails';
export { DebugLayer, resolveDebugOptions } from './debug';
export type { DebugOptions, ResolvedDebugOptions, DebugFrame } from './debug';
export { EnvironmentLayer } from './environment';
export type { BoundaryStyle, EnvironmentStyle } from './environment';
export { LightRig, createLights, resolveLightOptions } from './lights';
export type { LightOptions, ResolvedLightOptions } from './lights';
export { VectorArrow } from './arrow';
export type { VectorArrowOptions } from './arrow';
export { createOrbitControls, frameBox } from './camera';
export type { OrbitOptions, FrameOptions } from './camera';
export { slerpInto, rotateBack, composeInto, rotateInto, equivalentBoxEdges, hexToLinear } from './math';
export type { NumberArray } from './math';
export { parseColor, seededColor, hslToRgb, hash3 } from '@bitphysics/render-common';
export type { ColorInput } from '@bitphysics/render-common';
