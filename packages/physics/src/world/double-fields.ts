/**
 * Double-represented number fields from an object's creation on.
 *
 * V8 stores a number field that has held only small integers (such as a start value of 0) as a small
 * integer, and the first fraction written to it changes the object's layout: its hidden class is
 * replaced (the old one deprecated), and every optimised function compiled against the old one is
 * thrown away and compiled again. For a field such as `world.time`, written with a fraction in a
 * world's first step, that happened while the first step ran, to the code of every stage that reads
 * the world. Written with a fraction once where the object is made, before anything is compiled
 * against it, the field holds doubles from the start and keeps its layout.
 */

/**
 * Writes 0.5 into each of `keys` of `target`, then the field's value back, so that V8 represents the
 * fields as doubles from here on (see the top of double-fields.ts). The values are unchanged.
 * @param target - An object whose `keys` hold numbers.
 * @param keys - The number fields to widen.
 */
export function widenToDoubles<T extends object>(target: T, keys: readonly (keyof T & string)[]): void {
  const o = target as Record<string, number>;
  for (const k of keys) {
    const v = o[k]!;
    o[k] = 0.5;
    o[k] = v;
  }
}
