/**
 * A 3D game page on three.js and @bitphysics/render-three, on the game shell.
 *
 * @packageDocumentation
 * @module @bitphysics/game-kit/three
 */
export * from '../../../packages/game-kit/src/three.js';
