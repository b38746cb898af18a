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

export type { ColorInput } from '@bitphysics/render-common';
export { hash3, hslToRgb, parseColor, seededColor } from '@bitphysics/render-common';
export type { VectorArrowOptions } from './arrow.js';
export { VectorArrow } from './arrow.js';
export type { InstanceBookListener } from './book.js';
export { InstanceBook, MAX_GROUPS } from './book.js';
export type { FrameOptions, OrbitOptions } from './camera.js';
export { createOrbitControls, frameBox } from './camera.js';
export type { DebugCounts, DebugFrame, DebugOptions, ResolvedDebugOptions } from './debug.js';
export { DebugLayer, resolveDebugOptions } from './debug.js';
export type { DrawnPositions, SegmentSink } from './debug-scenery.js';
export {
  drawEmitters,
  drawFields,
  drawJoints,
  drawJoints3D,
  drawPlanes,
  drawSprings,
  SCENERY_PALETTE,
  SceneryColor,
} from './debug-scenery.js';
export type { BodyDrag3DOptions } from './drag.js';
export { BodyDrag3D } from './drag.js';
export type { BoundaryStyle, EnvironmentStyle } from './environment.js';
export { EnvironmentLayer } from './environment.js';
export type { GroupKind } from './groups.js';
export { InstanceGroup } from './groups.js';
export type { LightOptions, ResolvedLightOptions } from './lights.js';
export { createLights, LightRig, resolveLightOptions } from './lights.js';
export type { NumberArray } from './math.js';
export { composeInto, equivalentBoxEdges, hexToLinear, rotateBack, rotateInto, slerpInto } from './math.js';
export type { BodyShape, PickResult, Renderer3DStats, WorldRenderer3DOptions } from './renderer.js';
export { WorldRenderer3D } from './renderer.js';
export type { ShapeCounts, ShapeFrame } from './shapes.js';
export { CAPSULE_RATIO_STEP, CYLINDER_SEGMENTS, hullGeometry, ShapeLayer3D } from './shapes.js';
export type { ResolvedTrailOptions, TrailOptions } from './trails.js';
export { MAX_TRAIL_POINTS, resolveTrailOptions, TrailLayer } from './trails.js';
