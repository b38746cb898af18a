/**
 * The API reference (`npm run docs`, TypeDoc in tools/docs) holds every exported name with its docs.
 * TypeDoc runs once here, writing only its JSON model to a temp file (not the HTML site, which
 * `npm run docs` writes to dist/docs), with its `notDocumented`
 * validation as an error (so an exported function, class, interface, property or type without a
 * docstring fails). Then, independently of TypeDoc's own check, every name each package exports at
 * run time (as esbuild's bundler reads its entry) must appear in that package's module of the
 * reference, and every name there must carry a comment (or re-export a commented declaration).
 */
import { execFile } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { promisify } from 'node:util';
import * as esbuild from 'esbuild';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { repoRoot } from '../browser/chromium.mjs';

const run = promisify(execFile);

interface Reflection {
  id: number;
  name: string;
  kind: number;
  target?: number;
  comment?: { summary?: unknown[] };
  signatures?: Reflection[];
  getSignature?: Reflection;
  children?: Reflection[];
}

/** TypeDoc's kind of a re-export ("Reference"). */
const REFERENCE = 4194304;

let dir = '';
let modules = new Map<string, Reflection>();
const byId = new Map<number, Reflection>();

beforeAll(async () => {
  dir = mkdtempSync(join(tmpdir(), 'bitphysics-docs-'));
  const tools = join(repoRoot, 'tools', 'docs');
  const json = join(dir, 'api.json');
  // tools/docs/typedoc.json without its `out`: with `out` set TypeDoc renders the HTML site as well as
  // the JSON (a fifth of its run, and it overwrote dist/docs). Its paths are made absolute, since
  // TypeDoc reads an options file's paths from the file's folder.
  const options = JSON.parse(readFileSync(join(tools, 'typedoc.json'), 'utf8')) as {
    out?: string;
    tsconfig: string;
    entryPoints: string[];
  };
  delete options.out;
  options.tsconfig = resolve(tools, options.tsconfig);
  options.entryPoints = options.entryPoints.map((e) => resolve(tools, e));
  writeFileSync(join(dir, 'typedoc.json'), JSON.stringify(options));
  await run(
    process.execPath,
    [
      join(tools, 'node_modules', 'typedoc', 'bin', 'typedoc'),
      '--options',
      join(dir, 'typedoc.json'),
      '--json',
      json,
      '--treatValidationWarningsAsErrors',
      // `npm test` type-checks the packages before this runs; TypeDoc's own type-check took half its time.
      '--skipErrorChecking',
    ],
    { cwd: tools },
  ).catch((error: { stdout?: string; stderr?: string }) => {
    throw new Error(`typedoc failed:\n${error.stdout ?? ''}${error.stderr ?? ''}`);
  });
  const project = JSON.parse(readFileSync(json, 'utf8')) as Reflection;
  const walk = (r: Reflection): void => {
    byId.set(r.id, r);
    for (const c of r.children ?? []) walk(c);
  };
  walk(project);
  modules = new Map((project.children ?? []).map((m) => [m.name, m]));
}, 240_000);

afterAll(() => {
  if (dir) rmSync(dir, { recursive: true, force: true });
});

/** Whether `r` (or what it re-exports) carries a docstring. */
function documented(r: Reflection, depth = 0): boolean {
  if (r.kind === REFERENCE && r.target !== undefined && depth < 5) {
    const target = byId.get(r.target);
    return target !== undefined && documented(target, depth + 1);
  }
  const has = (x?: Reflection) => (x?.comment?.summary?.length ?? 0) > 0;
  return has(r) || (r.signatures ?? []).some(has) || has(r.getSignature);
}

/** Each package export and its source entry. */
const PACKAGES: [string, string][] = [
  ['@bitphysics/physics', 'packages/physics/src/index.ts'],
  ['@bitphysics/physics/validate', 'packages/physics/src/validation/validate.ts'],
  ['@bitphysics/render-common', 'packages/render-common/src/index.ts'],
  ['@bitphysics/render-pixi', 'packages/render-pixi/src/index.ts'],
  ['@bitphysics/render-three', 'packages/render-three/src/index.ts'],
];

/** The names `entry` exports at run time, as esbuild's bundler sees them (other packages external). */
async function runtimeExports(entry: string): Promise<string[]> {
  const result = await esbuild.build({
    entryPoints: [join(repoRoot, entry)],
    bundle: true,
    write: false,
    metafile: true,
    format: 'esm',
    platform: 'neutral',
    packages: 'external',
    outdir: dir,
    logLevel: 'silent',
  });
  return Object.values(result.metafile.outputs).flatMap((o) => o.exports);
}

describe('the API reference', () => {
  for (const [name, entry] of PACKAGES) {
    it(`documents every run-time export of ${name}`, async () => {
      const exported = await runtimeExports(entry);
      expect(exported.length).toBeGreaterThan(0);
      const reflection = modules.get(name);
      expect(reflection, `module ${name} in the reference`).toBeDefined();
      const children = new Map((reflection!.children ?? []).map((c) => [c.name, c]));
      const missing = exported.filter((key) => !children.has(key));
      const undocumented = [...children.values()].filter((c) => !documented(c)).map((c) => c.name);
      expect(missing).toEqual([]);
      expect(undocumented).toEqual([]);
    });
  }
});
