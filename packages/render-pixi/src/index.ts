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

export type { ColorInput } from '@bitphysics/render-common';
export { hslToRgb, parseColor, seededColor } from '@bitphysics/render-common';
export type { BallMode } from './balls.js';
export type { CameraOptions, Point2, WorldRect } from './camera.js';
export { assertWorldRect, Camera } from './camera.js';
export type { ClothGrid, ClothLayerOptions } from './cloth.js';
export { ClothLayer } from './cloth.js';
export type { DebugCounts, DebugOptions } from './debug.js';
export { resolveDebugOptions } from './debug.js';
export { drawEmitters, drawFields, drawJoints, drawPlanes, drawSprings, SCENERY_COLORS } from './debug-scenery.js';
export type {
  ParticleLayerOptions,
  ParticleLayerStats,
  ParticleTrailOptions,
  ResolvedParticleLayerOptions,
  ResolvedParticleTrailOptions,
} from './particles.js';
export {
  createSoftParticleTexture,
  ParticleLayer,
  resolveParticleLayerOptions,
  resolveParticleTrailOptions,
} from './particles.js';
export * from './points.js';
export type { RendererStats, WorldRendererOptions } from './renderer.js';
export { WorldRenderer } from './renderer.js';
export type { RopeLayerOptions } from './rope.js';
export { RopeLayer } from './rope.js';
export type { BallTextureOptions } from './textures.js';
export { ballTextureDiameter, createBallTexture, createStreakTexture } from './textures.js';
export type { TrailOptions } from './trails.js';
export { resolveTrailOptions } from './trails.js';
