import { describe } from '@bitphysics/physics/validate';

/**
 * Colours: parsing user input and the seeded per-entity colours. No pixi, no three.js, no DOM.
 * A colour is a 24-bit integer 0xRRGGBB (sRGB) throughout: what pixi's `tint` takes, and what
 * @bitphysics/render-three converts to three's linear working space when it writes instance colours.
 * Both renderers use these functions, so the same seed gives the same colours in 2D and 3D.
 */

/** A colour given by a user: an integer 0xRRGGBB in [0, 0xffffff], or a CSS hex string '#rgb' or '#rrggbb'. */
export type ColorInput = number | string;

/**
 * Parses a colour to 0xRRGGBB.
 * @throws TypeError if `value` is neither a number nor a string;
 * @throws RangeError if a number is not an integer in [0, 0xffffff] or a string is not '#rgb' / '#rrggbb'.
 */
export function parseColor(where: string, name: string, value: unknown): number {
  if (typeof value === 'number') {
    if (!Number.isInteger(value) || value < 0 || value > 0xffffff) {
      throw new RangeError(`${where}: ${name} must be an integer 0xRRGGBB in [0, 0xffffff], got ${describe(value)}`);
    }
    return value;
  }
  if (typeof value === 'string') {
    const m = /^#([0-9a-f]{3}|[0-9a-f]{6})$/i.exec(value.trim());
    if (!m) throw new RangeError(`${where}: ${name} must be a hex colour '#rgb' or '#rrggbb', got ${describe(value)}`);
    let hex = m[1]!;
    if (hex.length === 3) hex = hex[0]! + hex[0]! + hex[1]! + hex[1]! + hex[2]! + hex[2]!;
    return parseInt(hex, 16);
  }
  throw new TypeError(`${where}: ${name} must be a number 0xRRGGBB or a '#rrggbb' string, got ${describe(value)}`);
}

/**
 * Converts HSL to 0xRRGGBB. @param h hue, degrees (any finite value, wrapped); @param s saturation
 * in [0, 1]; @param l lightness in [0, 1]. Standard formula (CSS Color Module Level 3, section 4.2.4).
 */
export function hslToRgb(h: number, s: number, l: number): number {
  h = ((h % 360) + 360) % 360;
  const c = (1 - Math.abs(2 * l - 1)) * s;
  const hp = h / 60;
  const x = c * (1 - Math.abs((hp % 2) - 1));
  let r = 0,
    g = 0,
    b = 0;
  if (hp < 1) {
    r = c;
    g = x;
  } else if (hp < 2) {
    r = x;
    g = c;
  } else if (hp < 3) {
    g = c;
    b = x;
  } else if (hp < 4) {
    g = x;
    b = c;
  } else if (hp < 5) {
    r = x;
    b = c;
  } else {
    r = c;
    b = x;
  }
  const m = l - c / 2;
  const to8 = (v: number): number => Math.max(0, Math.min(255, Math.round((v + m) * 255)));
  return (to8(r) << 16) | (to8(g) << 8) | to8(b);
}

/** 32-bit integer hash of three integers (murmur3 finaliser mixing); the same inputs always give the same output. */
export function hash3(a: number, b: number, c: number): number {
  let h = Math.imul(a | 0, 0x9e3779b1) ^ Math.imul(b | 0, 0x85ebca77) ^ Math.imul(c | 0, 0xc2b2ae3d);
  h ^= h >>> 16;
  h = Math.imul(h, 0x85ebca6b);
  h ^= h >>> 13;
  h = Math.imul(h, 0xc2b2ae35);
  h ^= h >>> 16;
  return h >>> 0;
}

/**
 * The seeded colour of an entity: a pure function of (seed, entity id, spawn stamp), so the same
 * seeded scene always shows the same colours, and a recycled id (new spawn stamp) gets a new one.
 * With a palette, picks one of its colours; without, a saturated hue (golden-angle spread, S 0.7, L 0.6).
 */
export function seededColor(seed: number, eid: number, stamp: number, palette: readonly number[] | null): number {
  const h = hash3(seed, eid, stamp);
  if (palette && palette.length > 0) return palette[h % palette.length]!;
  return hslToRgb((h % 3600) / 10, 0.62 + ((h >>> 12) % 20) / 100, 0.55 + ((h >>> 20) % 12) / 100);
}

/**
 * Parses a renderer's `palette` option: `undefined` (no palette: seeded hues) gives null, otherwise a
 * non-empty array of colours (each a `ColorInput`) gives them as 0xRRGGBB numbers, in order.
 * @throws TypeError if `value` is not an array (or a colour is of the wrong type);
 * @throws RangeError if the array is empty or a colour is out of range (`parseColor`).
 */
export function parsePalette(where: string, name: string, value: unknown): number[] | null {
  if (value === undefined) return null;
  if (!Array.isArray(value)) throw new TypeError(`${where}: ${name} must be an array of colours, got ${describe(value)}`);
  if (value.length === 0) throw new RangeError(`${where}: ${name} must not be empty`);
  return value.map((c, i) => parseColor(where, `${name}[${i}]`, c));
}
