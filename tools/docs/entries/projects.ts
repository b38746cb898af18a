/**
 * The closing projects of the book on bitphysics: the aircraft, the submarine and the solar system from real ephemerides.
 *
 * @packageDocumentation
 * @module @bitphysics/projects
 */
export * from '../../../packages/projects/src/index.js';
