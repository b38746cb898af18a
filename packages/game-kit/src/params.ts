/** Reading game settings from the page's URL query (`?count=20&debug`). DOM-free apart from the default `search`. */

/** Options of `numberParam`. */
export interface NumberParamOptions {
  /** Value when the parameter is absent. */
  default: number;
  /** Smallest accepted value. */
  min: number;
  /** Largest accepted value. */
  max: number;
  /** Accept integers only. Default false. */
  integer?: boolean;
}

function currentSearch(): string {
  return typeof location === 'undefined' ? '' : location.search;
}

/**
 * The number in query parameter `name`, or `options.default` if absent.
 * @param search the query string to read; default `location.search`.
 * @throws RangeError naming the parameter and its text if it is not a number in [min, max]
 *   (or not an integer when `integer` is set).
 */
export function numberParam(name: string, options: NumberParamOptions, search: string = currentSearch()): number {
  const text = new URLSearchParams(search).get(name);
  if (text === null || text === '') return options.default;
  const value = Number(text);
  if (!Number.isFinite(value) || value < options.min || value > options.max || (options.integer && !Number.isInteger(value))) {
    throw new RangeError(
      `URL parameter ${name} must be ${options.integer ? 'an integer' : 'a number'} in [${options.min}, ${options.max}], got ${JSON.stringify(text)}`,
    );
  }
  return value;
}

/**
 * The `seed` query parameter: an integer in [-2^31, 2^32 - 1] (any signed or unsigned 32-bit seed),
 * or `fallback` when absent. The seed every seeded scene of the gallery takes from its URL.
 * @throws RangeError as `numberParam` does, naming `seed` and its text.
 */
export function seedParam(fallback = 1, search: string = currentSearch()): number {
  return numberParam('seed', { default: fallback, min: -2147483648, max: 4294967295, integer: true }, search);
}

/**
 * Whether flag `name` is set: present with no value, or '1', 'true', 'yes', 'on'; '0', 'false',
 * 'no', 'off' or absent mean false.
 * @throws RangeError naming the parameter if its value is anything else.
 */
export function flagParam(name: string, search: string = currentSearch()): boolean {
  const params = new URLSearchParams(search);
  if (!params.has(name)) return false;
  const text = (params.get(name) ?? '').toLowerCase();
  if (text === '' || text === '1' || text === 'true' || text === 'yes' || text === 'on') return true;
  if (text === '0' || text === 'false' || text === 'no' || text === 'off') return false;
  throw new RangeError(`URL parameter ${name} must be a flag (1/0, true/false, yes/no, on/off), got ${JSON.stringify(text)}`);
}

/**
 * The value of query parameter `name` if it is one of `choices`, else `fallback` when absent.
 * @throws RangeError naming the parameter, its value and the choices if it is present but not one of them.
 */
export function choiceParam<T extends string>(name: string, choices: readonly T[], fallback: T, search: string = currentSearch()): T {
  const text = new URLSearchParams(search).get(name);
  if (text === null || text === '') return fallback;
  if (!(choices as readonly string[]).includes(text)) {
    throw new RangeError(`URL parameter ${name} must be one of ${choices.join(', ')}, got ${JSON.stringify(text)}`);
  }
  return text as T;
}
