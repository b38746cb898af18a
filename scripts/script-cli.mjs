// The command line and a revision's checkout shared by the scripts that time the physics against a git
// revision (scripts/ab.mjs, scripts/first-steps.mjs).
import { execFileSync } from 'node:child_process';
import { rmSync, symlinkSync } from 'node:fs';
import { join } from 'node:path';
import { parseArgs } from 'node:util';
import { root } from './build.mjs';

/**
 * Parses this process's arguments for script `name` (node:util parseArgs with positionals). A bad
 * flag prints `name: <message>` and `usage` to stderr and exits with code 2.
 * @param {string} name - The script's name, the first word of its messages.
 * @param {string} usageLine - The usage line printed after a message.
 * @param {Record<string, { type: 'string' | 'boolean', default?: string | boolean }>} options - parseArgs' options.
 * @returns {{ values: Record<string, any>, positionals: string[], usage: (message: string) => never, integer: (flag: string, text: string, min: number) => number }}
 *   the values and positionals, `usage` (exit 2 with a message) and `integer` (a flag's text as an integer >= min, else usage).
 */
export function scriptCli(name, usageLine, options) {
  const usage = (message) => {
    console.error(`${name}: ${message}\nusage: ${usageLine}`);
    process.exit(2);
  };
  let parsed;
  try {
    parsed = parseArgs({ allowPositionals: true, options });
  } catch (e) {
    usage(e.message);
  }
  const integer = (flag, text, min) => {
    const v = Number(text);
    if (!Number.isInteger(v) || v < min) usage(`--${flag} must be an integer >= ${min}, got ${text}`);
    return v;
  };
  return { values: parsed.values, positionals: parsed.positionals, usage, integer };
}

/**
 * Checks git revision `rev` of this repository out into `temp`/tree (a detached worktree) whose
 * sources resolve their packages (bitecs) from this tree's node_modules. A revision git cannot check
 * out removes `temp` and calls `usage` (which exits).
 * @param {string} rev - A git revision.
 * @param {string} temp - A scratch folder of the caller's.
 * @param {(message: string) => never} usage - scriptCli's usage.
 * @returns {string} the worktree's path; remove it with removeCheckout.
 */
export function checkOut(rev, temp, usage) {
  const base = join(temp, 'tree');
  try {
    execFileSync('git', ['-C', root, 'worktree', 'add', '--detach', '--quiet', base, rev], { stdio: ['ignore', 'ignore', 'inherit'] });
  } catch {
    rmSync(temp, { recursive: true, force: true });
    usage(`cannot check out ${rev}`);
  }
  try {
    symlinkSync(join(root, 'node_modules'), join(base, 'node_modules'), 'dir');
  } catch (e) {
    removeCheckout(base);
    throw e;
  }
  return base;
}

/**
 * Removes a worktree made by checkOut.
 * @param {string} base - checkOut's result.
 */
export function removeCheckout(base) {
  execFileSync('git', ['-C', root, 'worktree', 'remove', '--force', base], { stdio: 'ignore' });
}
