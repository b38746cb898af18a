/**
 * Draws a 2D world with pixi.js 8: SI metres (y up) to CSS pixels (y down) through its Camera; interpolated between steps; trails, particles and a debug layer.
 *
 * @packageDocumentation
 * @module @bitphysics/render-pixi
 */
export * from '../../../packages/render-pixi/src/index.js';
