/**
 * @bitphysics/render-three: draws a 3D bitphysics world with three.js.
 *
 * The renderer only reads component stores (Position, PreviousPosition, Orientation, AngularVelocity,
 * Ball, Mass, Inertia, InertiaTensor, Velocity, Plane, Segment), the boundary box and the contact
 * cache; it computes no physics, and the physics package never imports three.js. It owns the
 * conversion from SI metres to scene units (`unitsPerMeter`); y is up in both.
 *
 * Entry points: `WorldRenderer3D` (everything: instanced bodies and 3D shapes, scenery, lights, trails,
 * debug, picking through the physics' ray cast), `BodyDrag3D` (drag bodies with the pointer), `createOrbitControls` and `frameBox` (camera), `VectorArrow` (solid arrows for a few
 * physical vectors), `createLights`; and the three.js-free parts: `InstanceBook` (entity to
 * instance bookkeeping), the interpolation maths, colours.
 */
export { WorldRenderer3D } from './renderer.js';
export type { WorldRenderer3DOptions, BodyShape, Renderer3DStats, PickResult } from './renderer.js';
export { InstanceBook, MAX_GROUPS } from './book.js';
export type { InstanceBookListener } from './book.js';
export { InstanceGroup } from './groups.js';
export type { GroupKind } from './groups.js';
export { TrailLayer, resolveTrailOptions, MAX_TRAIL_POINTS } from './trails.js';
export type { TrailOptions, ResolvedTrailOptions } from './trails.js';
export { DebugLayer, resolveDebugOptions } from './debug.js';
export type { DebugOptions, ResolvedDebugOptions, DebugFrame, DebugCounts } from './debug.js';
export { ShapeLayer3D, hullGeometry, CYLINDER_SEGMENTS, CAPSULE_RATIO_STEP } from './shapes.js';
export type { ShapeCounts, ShapeFrame } from './shapes.js';
export { BodyDrag3D } from './drag.js';
export type { BodyDrag3DOptions } from './drag.js';
export { SceneryColor, SCENERY_PALETTE, drawSprings, drawJoints, drawJoints3D, drawPlanes, drawFields, drawEmitters } from './debug-scenery.js';
export type { SegmentSink, DrawnPositions } from './debug-scenery.js';
export { EnvironmentLayer } from './environment.js';
export type { BoundaryStyle, EnvironmentStyle } from './environment.js';
export { LightRig, createLights, resolveLightOptions } from './lights.js';
export type { LightOptions, ResolvedLightOptions } from './lights.js';
export { VectorArrow } from './arrow.js';
export type { VectorArrowOptions } from './arrow.js';
export { createOrbitControls, frameBox } from './camera.js';
export type { OrbitOptions, FrameOptions } from './camera.js';
export { slerpInto, rotateBack, composeInto, rotateInto, equivalentBoxEdges, hexToLinear } from './math.js';
export type { NumberArray } from './math.js';
export { parseColor, seededColor, hslToRgb, hash3 } from '@bitphysics/render-common';
export type { ColorInput } from '@bitphysics/render-common';
