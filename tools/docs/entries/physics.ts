/**
 * Components, systems, the staged step, collisions, particles, diagnostics and scenes on bitecs. Everything is SI (m, kg, s, rad, N), y up, angles counter-clockwise. No DOM, no timers.
 *
 * @packageDocumentation
 * @module @bitphysics/physics
 */
export * from '../../../packages/physics/src/index.js';
