import { assertFinite, assertInteger, assertKnownKeys, optionOr } from '../validation/validate.js';

/**
 * The options every scene takes, checked: `options` holds no key outside `keys`, `count` (default
 * `defaultCount`) is an integer in [min, max] and `seed` (default 1) is finite.
 * @throws TypeError | RangeError naming the scene `where`.
 * @category Scenes
 */
export function countAndSeed(
  where: string,
  options: { count?: number; seed?: number },
  keys: readonly string[],
  defaultCount: number,
  min: number,
  max: number,
): { count: number; seed: number } {
  assertKnownKeys(where, options, keys);
  const count = optionOr(where, 'count', options.count, defaultCount, assertInteger, min, max);
  const seed = optionOr(where, 'seed', options.seed, 1, assertFinite);
  return { count, seed };
}
