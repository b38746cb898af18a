import { UsageError } from './errors.js';
import type { SceneParam } from './scenes/types.js';

/**
 * Parses and checks the value of a scene parameter flag: a finite decimal number (underscores allowed
 * as digit separators), an integer if the parameter says so, within [min, max] (min excluded when
 * `exclusiveMin`). Returns the number.
 * @throws UsageError naming the flag (`--<name>`), the value given and the accepted range.
 */
export function parseParamValue(name: string, text: string, param: SceneParam): number {
  const flag = `--${name}`;
  const cleaned = text.trim().replace(/(\d)_(?=\d)/g, '$1');
  const value = Number(cleaned);
  if (cleaned === '' || !Number.isFinite(value)) throw new UsageError(`${flag} must be a finite number, got ${JSON.stringify(text)}`);
  if (param.integer && !Number.isInteger(value)) throw new UsageError(`${flag} must be an integer, got ${JSON.stringify(text)}`);
  const low = param.exclusiveMin ? value <= param.min : value < param.min;
  if (low || (param.max !== undefined && value > param.max)) {
    throw new UsageError(`${flag} must be ${paramRange(param)}, got ${JSON.stringify(text)}`);
  }
  return value;
}

/** The accepted range of a parameter in words: "> 0", ">= 1 and <= 10000", "an integer >= 1". */
export function paramRange(param: SceneParam): string {
  const parts = [`${param.exclusiveMin ? '>' : '>='} ${param.min}`];
  if (param.max !== undefined) parts.push(`<= ${param.max}`);
  return `${param.integer ? 'an integer ' : ''}${parts.join(' and ')}`;
}

/** One line of help for a parameter: its flag, what it is, its default and range. */
export function describeParam(name: string, param: SceneParam): string {
  return `--${name} <${param.integer ? 'n' : 'x'}>: ${param.description} (default ${param.default}; ${paramRange(param)})`;
}
