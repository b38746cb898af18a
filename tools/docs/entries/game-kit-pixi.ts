/**
 * A 2D game page on pixi.js 8 and @bitphysics/render-pixi, on the game shell.
 *
 * @packageDocumentation
 * @module @bitphysics/game-kit/pixi
 */
export * from '../../../packages/game-kit/src/pixi.js';
