// Builds the gallery of games (dist/site), the bench CLI (packages/bench/dist) and the packages'
// ESM bundles (packages/*/dist). Run directly (`npm run build`) or import the functions.

import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import * as esbuild from 'esbuild';

export const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
export const siteDir = join(root, 'dist', 'site');

/** Workspace packages resolve to their TypeScript sources under this condition. */
const conditions = ['bitphysics-source'];

/**
 * The module `contents` (TypeScript, resolved from the repository root, e.g. "export * from
 * './games/catapult/solve.ts';") bundled for Node with the workspace packages from their sources,
 * and imported: how the scripts that play a game headless load its rules. The bundle is written to a
 * temporary folder named after `name` and removed once imported (it imports nothing further).
 * @param {string} name @param {string} contents @returns {Promise<any>} the module's exports
 */
export async function importSource(name, contents) {
  const dir = mkdtempSync(join(tmpdir(), `${name}-`));
  try {
    const outfile = join(dir, 'bundle.mjs');
    await esbuild.build({
      stdin: { contents, resolveDir: root, loader: 'ts' },
      bundle: true,
      format: 'esm',
      platform: 'node',
      outfile,
      conditions,
      logLevel: 'error',
    });
    return await import(pathToFileURL(outfile).href);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

/** Every game folder: games/<name>/ holding main.ts and index.html. @param {string} games the games folder (default games/). */
export function gameFolders(games = join(root, 'games')) {
  // Dirent types, not a stat per name: a file that vanishes between the listing and a stat (an
  // editor's temp file) must not throw while `npm start` watches this folder.
  return readdirSync(games, { withFileTypes: true })
    .filter((entry) => entry.isDirectory())
    .map((entry) => entry.name)
    .filter((name) => existsSync(join(games, name, 'main.ts')) && existsSync(join(games, name, 'index.html')))
    .sort();
}

/**
 * The gallery's registry: each game folder's game.json ({ title, summary, category, order }) plus its
 * folder name, sorted by category order then `order`. Written to dist/site/registry.json.
 * @throws Error naming the folder if a game.json is missing or lacks a title or summary.
 */
export function readRegistry(games = join(root, 'games')) {
  const categories = ['Games', 'Labs', 'Benchmarks'];
  const entries = gameFolders(games).map((folder) => {
    const file = join(games, folder, 'game.json');
    if (!existsSync(file)) throw new Error(`games/${folder}/game.json is missing`);
    const meta = JSON.parse(readFileSync(file, 'utf8'));
    if (typeof meta.title !== 'string' || typeof meta.summary !== 'string') {
      throw new Error(`games/${folder}/game.json needs a title and a summary`);
    }
    const category = meta.category ?? 'Labs';
    if (!categories.includes(category)) throw new Error(`games/${folder}/game.json: category must be one of ${categories.join(', ')}`);
    return { folder, title: meta.title, summary: meta.summary, category, order: meta.order ?? 100 };
  });
  entries.sort(
    (a, b) => categories.indexOf(a.category) - categories.indexOf(b.category) || a.order - b.order || a.title.localeCompare(b.title),
  );
  return entries;
}

/** Writes dist/site/registry.json. */
export function writeRegistry() {
  mkdirSync(siteDir, { recursive: true });
  writeFileSync(join(siteDir, 'registry.json'), JSON.stringify(readRegistry(), null, 2));
}

/**
 * esbuild options for the site: every game's main.ts bundled, every page and picture copied. The
 * pages' scripts are minified and split (`splitting`): code two pages share (pixi.js, three, bitecs,
 * the physics, the game kit) goes into chunks under chunks/ that the browser loads once and caches for
 * every page, so a page's own script is small. Source maps keep stack traces readable.
 */
export function siteOptions({ minify = true } = {}) {
  const games = join(root, 'games');
  const entryPoints = [join(games, 'index.html'), join(games, 'gallery.ts'), join(games, 'gallery.css')];
  for (const name of gameFolders()) {
    entryPoints.push(join(games, name, 'main.ts'), join(games, name, 'index.html'));
    for (const file of readdirSync(join(games, name))) {
      if (/\.(png|jpg|svg|css)$/.test(file)) entryPoints.push(join(games, name, file));
    }
  }
  return {
    entryPoints: entryPoints.filter((p) => existsSync(p)),
    outbase: games,
    outdir: siteDir,
    bundle: true,
    format: 'esm',
    platform: 'browser',
    target: 'es2022',
    conditions,
    sourcemap: true,
    minify,
    splitting: true,
    chunkNames: 'chunks/[name]-[hash]',
    loader: { '.html': 'copy', '.png': 'copy', '.jpg': 'copy', '.svg': 'copy' },
    // Runs first on every page: the locale guard and the error box for anything thrown (also at import time).
    inject: [join(root, 'packages', 'game-kit', 'src', 'page-errors.ts')],
    logLevel: 'warning',
  };
}

/** Builds the site once into dist/site. */
export async function buildSite(options = {}) {
  rmSync(siteDir, { recursive: true, force: true });
  mkdirSync(siteDir, { recursive: true });
  await esbuild.build(siteOptions(options));
  writeRegistry();
  return siteDir;
}

/** Builds the bench CLI into packages/bench/dist/cli.js and its peer engines' worker thread into dist/engine-thread.js (workspace code bundled, peers external). */
export async function buildBench() {
  await esbuild.build({
    // The CLI, and the worker thread each peer engine runs in (isolation/engine-thread.ts), side by side.
    entryPoints: {
      cli: join(root, 'packages', 'bench', 'src', 'cli.ts'),
      'engine-thread': join(root, 'packages', 'bench', 'src', 'isolation', 'engine-thread.ts'),
    },
    outdir: join(root, 'packages', 'bench', 'dist'),
    bundle: true,
    format: 'esm',
    platform: 'node',
    target: 'node20',
    conditions,
    external: ['@dimforge/*', 'matter-js', 'cli-progress', 'bitecs'],
    // As a page or a user's bundler ships the engine (minified), and as the packages' dist/ holds it:
    // constants folded into the code that uses them. V8 does not fold a module-level constant (a row
    // offset imported from a layout file) into optimised code; folded, the 2D joint rows run about
    // 20% faster. Names are kept.
    minifySyntax: true,
    sourcemap: true,
    banner: { js: '#!/usr/bin/env node' },
    logLevel: 'warning',
  });
}

/**
 * Whether the TypeScript module `file` holds only numeric constants (`export const A = 0, B = 1;`
 * and comments): a layout of offsets, safe to copy into every module that imports it.
 */
export function isConstantModule(file) {
  if (!file.endsWith('.ts') || !existsSync(file)) return false;
  const code = readFileSync(file, 'utf8')
    .replace(/\/\*[\s\S]*?\*\//g, '')
    .replace(/\/\/.*$/gm, '')
    .trim();
  const declaration = /^export const [A-Za-z_$][\w$]* = -?\d+(\.\d+)?(,\s*[A-Za-z_$][\w$]* = -?\d+(\.\d+)?)*;$/;
  const statements = code.split(/;\s*/).filter((x) => x.length > 0);
  return statements.length > 0 && statements.every((x) => declaration.test(`${x.trim()};`));
}

/**
 * An esbuild plugin for the per-module package build: every import stays an import of the module as
 * written, except a relative import of a constant module (isConstantModule), which is bundled in so
 * minifySyntax folds its constants into the code that reads them. In Node, a hot loop reading offsets
 * imported from another module ran 20 to 25% slower than with the numbers written in.
 */
export function inlineConstantModules() {
  return {
    name: 'inline-constant-modules',
    setup(build) {
      build.onResolve({ filter: /.*/ }, (args) => {
        if (args.kind === 'entry-point') return undefined;
        if (args.path.startsWith('.')) {
          const target = resolve(args.resolveDir, args.path).replace(/\.js$/, '.ts');
          if (isConstantModule(target)) return { path: target };
        }
        return { path: args.path, external: true };
      });
    },
  };
}

/** The library packages whose ESM bundles `buildPackages` writes, dependencies before dependants. */
export const libraryPackages = ['physics', 'projects', 'render-common', 'render-pixi', 'render-three', 'game-kit'];

/**
 * Builds each library package into its dist/ (emptied first): one ES module a source file
 * (src/a/b.ts -> dist/a/b.js, transpiled by esbuild, imports kept; the `exports` map's `default`
 * files are among them),
 * and the declarations with their maps (each src/ file gets a dist/ .d.ts and .d.ts.map, by tsc with
 * the package's tsconfig.build.json). Declarations are compiled without the `bitphysics-source`
 * condition, so a package's imports of another resolve to that package's dist/ declarations, as
 * they will for a user: hence dependencies first.
 * @param {{ names?: string[] }} options which packages (default: every library package).
 * @throws Error with tsc's output if a package's declarations do not compile.
 */
export async function buildPackages({ names = libraryPackages } = {}) {
  for (const name of names) {
    const dir = join(root, 'packages', name);
    const manifest = join(dir, 'package.json');
    if (!existsSync(manifest)) continue;
    rmSync(join(dir, 'dist'), { recursive: true, force: true });
    // One JS module a source file (transpiled, not bundled): the package's module graph stays as
    // written, so a user's bundler keeps only what the user's code reaches (tree shaking across
    // files, with "sideEffects": false), and each module, with its state, exists once whichever
    // entries of the `exports` map a page imports.
    const sources = readdirSync(join(dir, 'src'), { recursive: true })
      .map(String)
      .filter((f) => f.endsWith('.ts') && !f.endsWith('.d.ts'))
      .map((f) => join(dir, 'src', f));
    // Each module on its own, its imports kept, except the constant modules it imports (layout
    // offsets): those are copied in and folded (minifySyntax), since V8 does not fold an imported
    // constant into optimised code (see inlineConstantModules).
    await esbuild.build({
      entryPoints: sources,
      outdir: join(dir, 'dist'),
      outbase: join(dir, 'src'),
      bundle: true,
      minifySyntax: true,
      plugins: [inlineConstantModules()],
      format: 'esm',
      platform: 'neutral',
      target: 'es2022',
      sourcemap: true,
      logLevel: 'warning',
    });
    buildDeclarations(dir);
  }
}

/**
 * Writes the .d.ts and .d.ts.map files of the package in `dir` with the workspace's tsc.
 * @throws Error with tsc's diagnostics if the package does not type-check.
 */
function buildDeclarations(dir) {
  const config = join(dir, 'tsconfig.build.json');
  if (!existsSync(config)) return;
  try {
    // --singleThreaded: the same output for less CPU than tsc's parallel checkers, which each resolve
    // the shared declarations again.
    execFileSync(process.execPath, [join(root, 'node_modules', 'typescript', 'bin', 'tsc'), '-p', config, '--singleThreaded'], {
      cwd: root,
      encoding: 'utf8',
      stdio: 'pipe',
    });
  } catch (error) {
    throw new Error(`declarations of ${dir} failed:\n${error.stdout ?? ''}${error.stderr ?? ''}`);
  }
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const benchOnly = process.argv.includes('--bench-only');
  if (benchOnly) {
    await buildBench();
  } else {
    await buildPackages();
    await buildBench();
    await buildSite({ minify: true });
    console.log(`built ${gameFolders().length} games into ${siteDir}`);
  }
}
