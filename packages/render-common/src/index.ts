/**
 * @bitphysics/render-common: the parts of bitphysics' renderers that need neither pixi.js, three.js
 * nor the DOM, shared by @bitphysics/render-pixi and @bitphysics/render-three (which re-export what
 * their users need, so most code never imports this package directly).
 *
 * Entry points: `parseColor` (user colour input to 0xRRGGBB), `seededColor` (the per-entity colour
 * of a seeded scene), `hslToRgb`, `hash3`, `parsePalette` (a renderer's palette option);
 * `assertLiveEntity` (the renderers' check of an entity id argument); `resolveOptions` (a table-driven check of an options object, used by both debug layers).
 */

export type { ColorInput } from './colors.js';
export { hash3, hslToRgb, parseColor, parsePalette, seededColor } from './colors.js';
export { assertLiveEntity, entitySlot } from './entities.js';
export type { OptionRule, OptionRules } from './options.js';
export { resolveOptions } from './options.js';
