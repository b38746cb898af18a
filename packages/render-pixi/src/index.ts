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
export { WorldRenderer } from './renderer';
export type { WorldRendererOptions, RendererStats } from './renderer';
export { Camera, assertWorldRect } from './camera';
export type { CameraOptions, WorldRect, Point2 } from './camera';
export type { BallMode } from './balls';
export { createBallTexture, ballTextureDiameter, createStreakTexture } from './textures';
export type { BallTextureOptions } from './textures';
export { parseColor, seededColor, hslToRgb } from '@bitphysics/render-common';
export type { ColorInput } from '@bitphysics/render-common';
export { resolveTrailOptions } from './trails';
export type { TrailOptions } from './trails';
export {
  ParticleLayer, createSoftParticleTexture, resolveParticleLayerOptions, resolveParticleTrailOptions,
} from './particles';
export type {
  ParticleLayerOptions, ParticleTrailOptions, ParticleLayerStats, ResolvedParticleLayerOptions, ResolvedParticleTrailOptions,
} from './particles';
export { resolveDebugOptions } from './debug';
export type { DebugOptions } from './debug';
export * from './points';
