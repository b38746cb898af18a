/**
 * What the two renderers share and that needs neither pixi.js, three.js nor the DOM: colour parsing, seeded colours, palette and entity-id checks.
 *
 * @packageDocumentation
 * @module @bitphysics/render-common
 */
export * from '../../../packages/render-common/src/index.js';
