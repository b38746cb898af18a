/**
 * Draws a 3D world with three.js: instanced meshes interpolated between steps; trails, lights, a debug layer, orbit controls and picking.
 *
 * @packageDocumentation
 * @module @bitphysics/render-three
 */
export * from '../../../packages/render-three/src/index.js';
