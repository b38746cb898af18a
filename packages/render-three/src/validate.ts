/**
 * Argument checks at the renderer's API boundary (no three.js, no DOM: safe to import anywhere).
 * The same rules and wording as @bitphysics/render-pixi's checks.
 *
 * Conventions, the same as @bitphysics/physics: a value of the wrong type throws `TypeError`, a value
 * of the right type outside its valid range throws `RangeError`; messages read
 * `<where>: <option> must be <rule>, got <value>`.
 */

/** Formats a value for an error message: numbers as written, strings quoted, objects as short JSON. */
export function describe(value: unknown): string {
  if (typeof value === 'number') return Object.is(value, -0) ? '-0' : String(value);
  if (typeof value === 'string') return JSON.stringify(value);
  if (value === undefined) return 'undefined';
  if (value === null) return 'null';
  if (typeof value === 'function') return 'a function';
  if (typeof value === 'bigint') return `${value}n`;
  try {
    const text = JSON.stringify(value);
    if (text === undefined) return String(value);
    return text.length > 80 ? `${text.slice(0, 77)}...` : text;
  } catch {
    return Object.prototype.toString.call(value);
  }
}

/** @throws TypeError if `value` is not a number; RangeError if it is NaN or infinite. */
export function assertFinite(where: string, name: string, value: unknown): asserts value is number {
  if (typeof value !== 'number') throw new TypeError(`${where}: ${name} must be a number, got ${describe(value)}`);
  if (!Number.isFinite(value)) throw new RangeError(`${where}: ${name} must be finite, got ${describe(value)}`);
}

/** @throws TypeError if not a number; RangeError unless finite and > 0. */
export function assertPositive(where: string, name: string, value: unknown): asserts value is number {
  assertFinite(where, name, value);
  if (!(value > 0)) throw new RangeError(`${where}: ${name} must be > 0, got ${describe(value)}`);
}

/** @throws TypeError if not a number; RangeError unless finite and >= 0. */
export function assertNonNegative(where: string, name: string, value: unknown): asserts value is number {
  assertFinite(where, name, value);
  if (!(value >= 0)) throw new RangeError(`${where}: ${name} must be >= 0, got ${describe(value)}`);
}

/** @throws TypeError if not a number; RangeError unless finite and in [min, max]. */
export function assertInRange(where: string, name: string, value: unknown, min: number, max: number): asserts value is number {
  assertFinite(where, name, value);
  if (!(value >= min && value <= max)) throw new RangeError(`${where}: ${name} must be in [${min}, ${max}], got ${describe(value)}`);
}

/** @throws TypeError if not a number; RangeError unless an integer in [min, max]. */
export function assertInteger(where: string, name: string, value: unknown, min: number, max: number): asserts value is number {
  assertFinite(where, name, value);
  if (!Number.isInteger(value) || value < min || value > max) {
    throw new RangeError(`${where}: ${name} must be an integer in [${min}, ${max}], got ${describe(value)}`);
  }
}

/** @throws TypeError unless `value` is a boolean. */
export function assertBoolean(where: string, name: string, value: unknown): asserts value is boolean {
  if (typeof value !== 'boolean') throw new TypeError(`${where}: ${name} must be a boolean, got ${describe(value)}`);
}

/**
 * Throws a TypeError naming the first key of `options` not in `known` (catches misspelt options).
 * `undefined` passes (no options given).
 * @throws TypeError if `options` is not a plain object or has an unknown key.
 */
export function assertKnownKeys(where: string, options: unknown, known: readonly string[]): void {
  if (options === undefined) return;
  if (options === null || typeof options !== 'object' || Array.isArray(options)) {
    throw new TypeError(`${where}: options must be an object, got ${describe(options)}`);
  }
  for (const key of Object.keys(options)) {
    if (!known.includes(key)) {
      throw new TypeError(`${where}: unknown option ${JSON.stringify(key)}; known options are ${known.join(', ')}`);
    }
  }
}

/**
 * @throws TypeError unless `value` is an array-like of `length` numbers; RangeError if one is not finite.
 */
export function assertVector(where: string, name: string, value: unknown, length: number): asserts value is ArrayLike<number> {
  const v = value as ArrayLike<unknown> | null;
  if (v === null || typeof v !== 'object' || typeof v.length !== 'number' || v.length !== length) {
    throw new TypeError(`${where}: ${name} must be an array of ${length} numbers, got ${describe(value)}`);
  }
  for (let i = 0; i < length; i++) assertFinite(where, `${name}[${i}]`, v[i]);
}
