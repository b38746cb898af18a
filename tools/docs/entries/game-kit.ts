/**
 * The game shell (fixed-step loop, keys, HUD, lil-gui panel, URL parameters, touch controls, sound and the error box) for game pages of your own.
 *
 * @packageDocumentation
 * @module @bitphysics/game-kit
 */
export * from '../../../packages/game-kit/src/index.js';
