/**
 * Dragging bodies with the pointer through a mouse joint (2D).
 *
 * @packageDocumentation
 * @module @bitphysics/game-kit/drag
 */
export * from '../../../packages/game-kit/src/drag.js';
