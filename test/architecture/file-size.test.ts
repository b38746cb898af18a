// A file holds one concept (issue 32): no source file of the physics package is over 800 lines. A file
// that grows past it is split by concept (its declarations moved, not rewritten), as
// snapshot/, particles/emitter*.ts and forces/barnes-hut/ were.

import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, it } from 'vitest';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
const MAX_LINES = 800;

function sources(dir: string): string[] {
  const out: string[] = [];
  for (const name of readdirSync(dir)) {
    const p = join(dir, name);
    if (statSync(p).isDirectory()) out.push(...sources(p));
    else if (p.endsWith('.ts')) out.push(p);
  }
  return out;
}

/** Lines of a file as `wc -l` counts them (newline characters). */
function lineCount(path: string): number {
  let n = 0;
  for (const ch of readFileSync(path, 'utf8')) if (ch === '\n') n++;
  return n;
}

it(`no source file of packages/physics is over ${MAX_LINES} lines`, () => {
  const files = sources(join(root, 'packages/physics/src'));
  expect(files.length).toBeGreaterThan(100);
  const over = files
    .map((f) => ({ file: relative(root, f), lines: lineCount(f) }))
    .filter((f) => f.lines > MAX_LINES)
    .map((f) => `${f.file}: ${f.lines} lines`);
  expect(over, `split these by concept:\n${over.join('\n')}`).toEqual([]);
});
