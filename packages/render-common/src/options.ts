import { assertBoolean, assertInteger, assertKnownKeys, assertPositive } from '@bitphysics/physics/validate';

/**
 * How one option of a renderer's options object is checked and what it defaults to:
 * a boolean; a number > 0 (`positive`); or an integer in [min, max] (`integer`).
 */
export type OptionRule =
  | { readonly kind: 'boolean'; readonly default: boolean }
  | { readonly kind: 'positive'; readonly default: number }
  | { readonly kind: 'integer'; readonly default: number; readonly min: number; readonly max: number };

/** One rule per option of T (every field of T must be listed). */
export type OptionRules<T> = { readonly [K in keyof Required<T>]: OptionRule };

/**
 * Checks an options object against `rules` and fills in each rule's default: unknown fields are
 * rejected, and each given value must meet its rule. Errors name `where` and the option as
 * `<prefix><name>` (e.g. `WorldRenderer.setDebug: debug.maxArrows must be ...`).
 * Used by both renderers' debug layers.
 * @returns a new object holding every option (`Required<T>`).
 * @throws TypeError on an unknown field or a value of the wrong type; RangeError on a value out of range.
 */
export function resolveOptions<T extends object>(where: string, prefix: string, options: T, rules: OptionRules<T>): Required<T> {
  const names = Object.keys(rules) as (keyof T & string)[];
  assertKnownKeys(where, options as Record<string, unknown>, names);
  const out: Record<string, unknown> = {};
  for (const name of names) {
    const rule = rules[name] as OptionRule;
    const given = (options as Record<string, unknown>)[name];
    const value = given === undefined ? rule.default : given;
    const param = prefix + name;
    if (rule.kind === 'boolean') assertBoolean(where, param, value);
    else if (rule.kind === 'positive') assertPositive(where, param, value);
    else assertInteger(where, param, value, rule.min, rule.max);
    out[name] = value;
  }
  return out as Required<T>;
}
