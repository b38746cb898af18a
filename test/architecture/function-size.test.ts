// No function body of the physics package is over 150 lines (issue 32): a longer one is split into
// named phases. The functions still over it are listed below with the length they may not pass; the
// list only shrinks. A top-level function is counted from its `function` line to the first line after
// it that is a lone `}` at the start of a line (the formatter's layout of every such function here).

import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, it } from 'vitest';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
const MAX_LINES = 150;

/**
 * The functions over MAX_LINES, with the most lines each may have: hot loops and thread kernels whose
 * split into calls needs a quiet machine to show it costs no speed, and those other work is splitting.
 */
const LEFT: Readonly<Record<string, number>> = {
  'forces/barnes-hut/walk-kernel.ts barnesHutWalk': 513,
  'solver/manifold-solve-3d.ts solveManifolds3D': 337,
  'solver/ball-sweeps.ts solve3D': 161,
};

function sources(dir: string): string[] {
  const out: string[] = [];
  for (const name of readdirSync(dir)) {
    const p = join(dir, name);
    if (statSync(p).isDirectory()) out.push(...sources(p));
    else if (p.endsWith('.ts')) out.push(p);
  }
  return out;
}

/** Each top-level function of `text` with its length in lines (from its `function` line to its closing `}`). */
function functions(text: string): Array<{ name: string; lines: number }> {
  const out: Array<{ name: string; lines: number }> = [];
  const lines = text.split('\n');
  for (let i = 0; i < lines.length; i++) {
    const m = /^(?:export )?(?:async )?function\*? ?([A-Za-z0-9_$]+)/.exec(lines[i]!);
    if (!m) continue;
    let j = i + 1;
    while (j < lines.length && lines[j] !== '}') j++;
    out.push({ name: m[1]!, lines: j - i });
    i = j;
  }
  return out;
}

it(`no function of packages/physics is over ${MAX_LINES} lines but those listed, and none of those grows`, () => {
  const base = join(root, 'packages/physics/src');
  const over: string[] = [];
  const seen = new Map<string, number>();
  for (const file of sources(base)) {
    for (const f of functions(readFileSync(file, 'utf8'))) {
      const key = `${relative(base, file)} ${f.name}`;
      const limit = LEFT[key] ?? MAX_LINES;
      if (key in LEFT) seen.set(key, f.lines);
      if (f.lines > limit) over.push(`${key}: ${f.lines} lines (at most ${limit})`);
    }
  }
  expect(over, `split these into named phases:\n${over.join('\n')}`).toEqual([]);
  // A listed function that is gone or now short enough is taken off the list.
  const stale = Object.keys(LEFT).filter((k) => (seen.get(k) ?? 0) <= MAX_LINES);
  expect(stale, 'take these off LEFT (split or gone)').toEqual([]);
});
