/**
 * The one argument check render-three keeps for itself. Every other check (assertFinite,
 * assertPositive, assertInteger, assertKnownKeys, describe, ...) comes from
 * `@bitphysics/physics/validate`, with the same rules and wording as the physics package.
 *
 * This `assertVector` is looser than physics' own: it takes any array-like object with a numeric
 * `length` (the renderer's vector options are typed `ArrayLike<number>`), where physics takes only
 * arrays and typed arrays; and a non-finite element's message names the element alone.
 */
import { assertFinite, describe } from '@bitphysics/physics/validate';

/**
 * Throws unless `value` is an array-like object (array, typed array, or any object with a numeric
 * `length`) of `length` finite numbers.
 * @throws TypeError unless `value` is an array-like of `length` numbers; RangeError if one is not finite.
 */
export function assertVector(where: string, name: string, value: unknown, length: number): asserts value is ArrayLike<number> {
  const v = value as ArrayLike<unknown> | null;
  if (v === null || typeof v !== 'object' || typeof v.length !== 'number' || v.length !== length) {
    throw new TypeError(`${where}: ${name} must be an array of ${length} numbers, got ${describe(value)}`);
  }
  for (let i = 0; i < length; i++) assertFinite(where, `${name}[${i}]`, v[i]);
}
