// The folders of packages/physics/src form layers (docs/architecture.md): a module imports modules of
// its own folder or of folders below it. This test lists the folder-to-folder imports (type-only ones
// too) that run back up the order below, and fails on any that is not one of the four known ones, so a
// new arrow back up is a decision made in this file, not an accident.

import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, normalize, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const src = resolve(dirname(fileURLToPath(import.meta.url)), '../../packages/physics/src');

/** The folders, bottom first; the files at the top of src (index.ts, create-world.ts) are above all. */
const ORDER = [
  'threads',
  'validation',
  'math',
  'world',
  'shapes',
  'forces',
  'integrators',
  'collision',
  'islands',
  'bodies',
  'cloth',
  'solver',
  'particles',
  'joints',
  'scenes',
  'diagnostics',
  'step',
  'snapshot',
  '(root)',
];

/**
 * The arrows back up that are left, and why each is there:
 * - collision -> islands: the collide stage wakes the sleeping islands a moving body reaches;
 * - collision -> joints, collision -> solver: the install modules (install-3d.ts, install-balls.ts)
 *   wire a feature's collide, solver and joint rows together when it is first used;
 * - world -> collision: the world's type names its collision state (collision/state.ts).
 */
const KNOWN_BACK = ['collision -> islands', 'collision -> joints', 'collision -> solver', 'world -> collision'];

function sources(dir: string): string[] {
  const out: string[] = [];
  for (const name of readdirSync(dir)) {
    const p = join(dir, name);
    if (statSync(p).isDirectory()) out.push(...sources(p));
    else if (p.endsWith('.ts') && !p.endsWith('.d.ts')) out.push(p);
  }
  return out;
}

const folderOf = (file: string): string => {
  const parts = relative(src, file).split(/[\\/]/);
  return parts.length > 1 ? parts[0]! : '(root)';
};

/** Each folder-to-folder import as 'a -> b', with one importing file as an example. */
function folderArrows(): Map<string, string> {
  const arrows = new Map<string, string>();
  for (const file of sources(src)) {
    const text = readFileSync(file, 'utf8');
    for (const m of text.matchAll(/^\s*(?:import|export)\s[^;]*?from\s+['"](\.[^'"]+)['"]/gms)) {
      const target = normalize(join(dirname(file), m[1]!));
      const a = folderOf(file),
        b = folderOf(target);
      if (a !== b && !arrows.has(`${a} -> ${b}`)) arrows.set(`${a} -> ${b}`, relative(src, file));
    }
  }
  return arrows;
}

describe('folder layers of packages/physics/src', () => {
  const arrows = folderArrows();

  it('every folder is in the order', () => {
    const folders = new Set([...arrows.keys()].flatMap((k) => k.split(' -> ')));
    expect([...folders].filter((f) => !ORDER.includes(f))).toEqual([]);
  });

  it('no import runs back up the order but the four known ones', () => {
    const back = [...arrows.keys()].filter((k) => {
      const [a, b] = k.split(' -> ') as [string, string];
      return ORDER.indexOf(a) < ORDER.indexOf(b);
    });
    expect(back.sort().map((k) => `${k} (${arrows.get(k)})`)).toEqual(
      KNOWN_BACK.filter((k) => arrows.has(k)).map((k) => `${k} (${arrows.get(k)})`),
    );
  });

  it('the check sees an arrow back up (a self-check on a made-up import)', () => {
    const made = new Map(arrows);
    made.set('math -> step', 'math/made-up.ts');
    const back = [...made.keys()].filter((k) => {
      const [a, b] = k.split(' -> ') as [string, string];
      return ORDER.indexOf(a) < ORDER.indexOf(b);
    });
    expect(back).toContain('math -> step');
  });
});
