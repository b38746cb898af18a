/**
 * Argument checks for the API boundary. Every public entry point validates its input with
 * these so that a bad value is reported where it enters, naming the parameter and the value,
 * instead of spreading through the world as NaN.
 *
 * Conventions: a value of the wrong type throws `TypeError`; a value of the right type outside
 * its valid range throws `RangeError`. Messages read `<where>: <param> must be <rule>, got <value>`.
 */

/**
 * Formats a value for an error message: numbers as written, strings quoted, arrays element by element, other objects as JSON.
 * @category Utilities
 */
export function describe(value: unknown): string {
  if (typeof value === 'number') return Object.is(value, -0) ? '-0' : String(value);
  if (typeof value === 'string') return JSON.stringify(value);
  if (typeof value === 'bigint') return `${value}n`;
  if (value === undefined) return 'undefined';
  if (value === null) return 'null';
  if (typeof value === 'function') return 'a function';
  if (Array.isArray(value)) {
    // Element by element, so NaN, Infinity, -0 and undefined show as such (JSON writes null or 0).
    let text = '[';
    // A nested array is written as JSON (no recursion, so an array that holds itself cannot loop).
    for (let i = 0; i < value.length && text.length <= 80; i++) {
      const v: unknown = value[i];
      text += (i > 0 ? ',' : '') + (Array.isArray(v) ? json(v) : describe(v));
    }
    text += ']';
    return text.length > 80 ? `${text.slice(0, 77)}...` : text;
  }
  return json(value);
}

/** `value` as JSON cut to 80 characters, or its `Object.prototype.toString` if it has none. */
function json(value: unknown): string {
  try {
    const text = JSON.stringify(value);
    if (text === undefined) return String(value); // a symbol, or an object whose toJSON gives undefined
    return text.length > 80 ? `${text.slice(0, 77)}...` : text;
  } catch {
    return Object.prototype.toString.call(value);
  }
}

/**
 * Throws unless `value` is a finite number.
 * @throws TypeError if not a number; RangeError if NaN or infinite.
 * @category Utilities
 */
export function assertFinite(where: string, param: string, value: unknown): asserts value is number {
  if (typeof value !== 'number') {
    throw new TypeError(`${where}: ${param} must be a number, got ${describe(value)}`);
  }
  if (!Number.isFinite(value)) {
    throw new RangeError(`${where}: ${param} must be finite, got ${describe(value)}`);
  }
}

/**
 * Throws unless `value` is a finite number > 0. @throws TypeError | RangeError
 * @category Utilities
 */
export function assertPositive(where: string, param: string, value: unknown): asserts value is number {
  assertFinite(where, param, value);
  if (!(value > 0)) throw new RangeError(`${where}: ${param} must be > 0, got ${describe(value)}`);
}

/**
 * Throws unless `value` is a finite number >= 0. @throws TypeError | RangeError
 * @category Utilities
 */
export function assertNonNegative(where: string, param: string, value: unknown): asserts value is number {
  assertFinite(where, param, value);
  if (!(value >= 0)) throw new RangeError(`${where}: ${param} must be >= 0, got ${describe(value)}`);
}

/**
 * Throws unless `value` is a finite number in the closed interval [min, max]. @throws TypeError | RangeError
 * @category Utilities
 */
export function assertInRange(where: string, param: string, value: unknown, min: number, max: number): asserts value is number {
  assertFinite(where, param, value);
  if (!(value >= min && value <= max)) {
    throw new RangeError(`${where}: ${param} must be in [${min}, ${max}], got ${describe(value)}`);
  }
}

/**
 * Throws unless `value` is an integer in [min, max]. @throws TypeError | RangeError
 * @category Utilities
 */
export function assertInteger(where: string, param: string, value: unknown, min: number, max: number): asserts value is number {
  assertFinite(where, param, value);
  if (!Number.isInteger(value)) throw new RangeError(`${where}: ${param} must be an integer, got ${describe(value)}`);
  if (value < min || value > max) {
    throw new RangeError(`${where}: ${param} must be an integer in [${min}, ${max}], got ${describe(value)}`);
  }
}

/**
 * An option's number: `value`, or `fallback` where it is undefined or null, once `assert` (one of the
 * checks above: assertFinite, assertPositive, assertNonNegative, or assertInRange and assertInteger
 * with `min` and `max`) has passed it. @throws as `assert`.
 * @category Utilities
 */
export function optionOr(
  where: string,
  param: string,
  value: unknown,
  fallback: number,
  assert: (where: string, param: string, value: unknown, min: number, max: number) => void,
  min = -Infinity,
  max = Infinity,
): number {
  const v = value ?? fallback;
  assert(where, param, v, min, max);
  // Each assert throws unless v is a finite number.
  return v as number;
}

/**
 * Throws unless `value` is a boolean (`true` or `false`, not truthy or falsy). @throws TypeError
 * @category Utilities
 */
export function assertBoolean(where: string, param: string, value: unknown): asserts value is boolean {
  if (typeof value !== 'boolean') throw new TypeError(`${where}: ${param} must be a boolean, got ${describe(value)}`);
}

/**
 * The unit vector along `value`, which must be an array (or typed array) of `length` (2 or 3) finite
 * numbers, not all zero: (x, y, z) / |(x, y, z)| with z = 0 when `length` is 2 and |v| = Math.hypot(x, y, z).
 * @returns [x, y, z], dimensionless, |v| = 1 to rounding.
 * @throws TypeError | RangeError as `assertVector`; RangeError naming `where`, `param` and the value if it is zero.
 */
export function unitVector(where: string, param: string, value: unknown, length: number): [number, number, number] {
  assertVector(where, param, value, length);
  const x = value[0]!,
    y = value[1]!,
    z = length === 3 ? value[2]! : 0;
  const n = Math.hypot(x, y, z);
  if (!(n > 0)) throw new RangeError(`${where}: ${param} must not be zero, got ${describe(value)}`);
  return [x / n, y / n, z / n];
}

/**
 * Throws unless `value` is an array (or typed array) of `length` finite numbers.
 * @throws TypeError if not array-like of numbers or of the wrong length; RangeError if an element is not finite.
 * @category Utilities
 */
export function assertVector(where: string, param: string, value: unknown, length: number): asserts value is ArrayLike<number> {
  const ok = Array.isArray(value) || ArrayBuffer.isView(value);
  if (!ok || (value as ArrayLike<unknown>).length !== length) {
    throw new TypeError(`${where}: ${param} must be an array of ${length} numbers, got ${describe(value)}`);
  }
  const arr = value as ArrayLike<unknown>;
  for (let i = 0; i < length; i++) {
    const v = arr[i];
    if (typeof v !== 'number') {
      throw new TypeError(`${where}: ${param}[${i}] must be a number, got ${describe(v)}`);
    }
    if (!Number.isFinite(v)) {
      throw new RangeError(`${where}: ${param}[${i}] must be finite, got ${describe(v)} (in ${describe(value)})`);
    }
  }
}

/**
 * Throws a TypeError naming the first key of `options` that is not in `known`, or whose value is null
 * (an option is omitted, never null, to get its default; `nullable` lists the keys whose documented
 * meaning includes null, such as a joint's `a: null` for the world). Catches misspelt options
 * (`restituion`) that would otherwise be silently ignored. `options` undefined passes (all defaults).
 * @throws TypeError if `options` is not a plain object, has an unknown key or a null value.
 * @category Utilities
 */
export function assertKnownKeys(where: string, options: unknown, known: readonly string[], nullable: readonly string[] = []): void {
  if (options === undefined) return;
  assertOptions(where, options, known, 'options', nullable);
}

/**
 * Throws unless `options` is a plain object whose keys are all in `known` and whose values are not
 * `null` (an option is omitted, never null, to get its default). Functions whose options object is
 * optional give it a default (`options = {}`) before calling this, so a missing object means "all
 * defaults" there and is refused everywhere else with the same message as a wrong one.
 * @param param how the object is named in messages: 'options', or a nested option such as 'particle'.
 * @param nullable keys whose documented meaning includes null (a joint's `a: null` is the world).
 * @throws TypeError `<where>: <param> must be an object, got <value>`; `<where>: unknown option "<key>"...`;
 *   `<where>: <key> must be a value (omit it for the default), got null`.
 * @category Utilities
 */
export function assertOptions(
  where: string,
  options: unknown,
  known: readonly string[],
  param = 'options',
  nullable: readonly string[] = [],
): void {
  if (options === null || typeof options !== 'object' || Array.isArray(options) || ArrayBuffer.isView(options)) {
    throw new TypeError(`${where}: ${param} must be an object, got ${describe(options)}`);
  }
  const prefix = param === 'options' ? '' : `${param}.`;
  for (const key of Object.keys(options)) {
    if (!known.includes(key)) {
      throw new TypeError(
        `${where}: unknown option ${JSON.stringify(prefix + key)}; known options${prefix ? ` of ${param}` : ''} are ${known.join(', ')}`,
      );
    }
    if ((options as Record<string, unknown>)[key] === null && !nullable.includes(key)) {
      throw new TypeError(`${where}: ${prefix}${key} must be a value (omit it for the default), got null`);
    }
  }
}

/**
 * Throws unless `value` is undefined (omitted) or a boolean. @throws TypeError `<where>: <param> must be a boolean, got <value>`
 * @category Utilities
 */
export function assertOptionalBoolean(where: string, param: string, value: unknown): asserts value is boolean | undefined {
  if (value !== undefined) assertBoolean(where, param, value);
}

/**
 * Throws unless `value` is one of the strings `choices` (own names only: 'toString' is not a choice).
 * @throws RangeError `<where>: <param> must be one of 'a', 'b', got <value>`.
 * @category Utilities
 */
export function assertOneOf<T extends string>(where: string, param: string, value: unknown, choices: readonly T[]): asserts value is T {
  if (typeof value !== 'string' || !(choices as readonly string[]).includes(value)) {
    throw new RangeError(`${where}: ${param} must be one of ${choices.map((c) => `'${c}'`).join(', ')}, got ${describe(value)}`);
  }
}
