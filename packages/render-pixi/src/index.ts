/**
 * @bitphysics/render-pixi: draws a 2D bitphysics world with pixi.js 8.
 *
 * The renderer only reads component stores (Position, PreviousPosition, Ball, Angle, Velocity,
 * Segment, Particle, Lifetime), the boundary box and the contact cache; it computes no physics. It
 * owns the conversion from SI metres (y up) to CSS pixels (y down): see `Camera`.
 *
 * Entry points: `WorldRenderer` (everything), `ParticleLayer` (emitted particles: sparks, smoke;
 * also the renderer's `particles` option), `Camera` (metres <-> pixels, no pixi inside),
 * `createBallTexture` (the shared circle texture), colour helpers.
 */
export { WorldRenderer } from './renderer.js';
export type { WorldRendererOptions, RendererStats } from './renderer.js';
export { Camera, assertWorldRect } from './camera.js';
export type { CameraOptions, WorldRect, Point2 } from './camera.js';
export type { BallMode } from './balls.js';
export { createBallTexture, ballTextureDiameter, createStreakTexture } from './textures.js';
export type { BallTextureOptions } from './textures.js';
export { parseColor, seededColor, hslToRgb } from '@bitphysics/render-common';
export type { ColorInput } from '@bitphysics/render-common';
export { resolveTrailOptions } from './trails.js';
export type { TrailOptions } from './trails.js';
export {
  ParticleLayer, createSoftParticleTexture, resolveParticleLayerOptions, resolveParticleTrailOptions,
} from './particles.js';
export type {
  ParticleLayerOptions, ParticleTrailOptions, ParticleLayerStats, ResolvedParticleLayerOptions, ResolvedParticleTrailOptions,
} from './particles.js';
export { resolveDebugOptions } from './debug.js';
export type { DebugOptions, DebugCounts } from './debug.js';
export { SCENERY_COLORS, drawSprings, drawJoints, drawPlanes, drawFields, drawEmitters } from './debug-scenery.js';
export * from './points.js';
export { RopeLayer } from './rope.js';
export type { RopeLayerOptions } from './rope.js';
export { ClothLayer } from './cloth.js';
export type { ClothLayerOptions, ClothGrid } from './cloth.js';
