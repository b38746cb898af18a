// `npm run new-game -- <folder outside the repository>`: scaffolds a standalone game project there
// (see newProject). scripts/new-game.mjs calls it when its argument is a path, not a game name.
import { copyFileSync, existsSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { basename, join, relative, resolve } from 'node:path';
import { root } from './build.mjs';
import { templateDir, titleOf } from './new-game.mjs';
import { packPackages } from './pack.mjs';

/** The standalone project's own files (build, serve, tsconfig, README, .gitignore). */
export const projectTemplateDir = join(root, 'scripts', 'templates', 'project');

/**
 * Copies packed packages into a project's vendor folder.
 * @param {{ name: string, file: string }[]} tarballs `packPackages`' result.
 * @param {string} vendor the folder to copy them into (created if missing).
 * @returns {{ name: string, file: string }[]} each package's name and the path of its copy.
 */
function copyTarballs(tarballs, vendor) {
  mkdirSync(vendor, { recursive: true });
  return tarballs.map((t) => {
    const file = join(vendor, basename(t.file));
    copyFileSync(t.file, file);
    return { name: t.name, file };
  });
}

/** Versions the project pins for what the bitphysics packages expect beside them. */
function workspaceVersion(name) {
  return JSON.parse(readFileSync(join(root, 'node_modules', name, 'package.json'), 'utf8')).version;
}

/**
 * Scaffolds a standalone 2D game project in `dir` (which must not exist, or be empty, and lie
 * outside this repository): the bitphysics packages built and packed into `dir/vendor/` and named
 * as `file:` dependencies, pixi.js, bitecs, esbuild and TypeScript from the registry; the game
 * template's scene and page (`src/scene.ts`, `src/main.ts`, `src/index.html`) on
 * `@bitphysics/game-kit`; `npm start` (esbuild's serve API), `npm run build` and `npm run typecheck`.
 * After `npm install` in `dir`, `npm start` serves the game. Packing builds the packages first (a
 * few seconds).
 * @param {string} dir the project folder (absolute or relative to the current directory).
 * @param {{ title?: string, tarballs?: { name: string, file: string }[] }} options the game's title
 *   (default from the folder's name); `tarballs`: the packages already packed by `packPackages`
 *   (scripts/pack.mjs), copied into `vendor/` instead of building and packing them again (for a
 *   program that makes several projects from one build, such as the packaging tests).
 * @returns {Promise<{ dir: string, files: string[] }>} the folder and every file written.
 * @throws Error if `dir` is inside the repository or is a non-empty folder; TypeError on a bad title.
 */
export async function newProject(dir, { title = undefined, tarballs: packed = undefined } = {}) {
  const target = resolve(dir);
  const inside = relative(root, target);
  if (!inside.startsWith('..') && !inside.startsWith('/')) {
    throw new Error(`new-game: ${target} is inside the bitphysics repository; give a folder outside it (or a plain name for games/)`);
  }
  if (existsSync(target) && readdirSync(target).length > 0) throw new Error(`new-game: ${target} exists and is not empty`);
  const name =
    basename(target)
      .toLowerCase()
      .replace(/[^a-z0-9-]+/g, '-')
      .replace(/^-+|-+$/g, '') || 'my-game';
  const gameTitle = title ?? titleOf(name);
  if (typeof gameTitle !== 'string' || gameTitle.trim() === '' || /[<>"`\\]/.test(gameTitle)) {
    throw new TypeError(`new-game: title must be non-empty text without < > " \` or \\, got ${JSON.stringify(gameTitle)}`);
  }
  const fill = (text) => text.replaceAll('__NAME__', name).replaceAll('__TITLE__', gameTitle.replaceAll("'", '’'));
  mkdirSync(join(target, 'src'), { recursive: true });
  const files = [];
  const write = (file, text) => {
    writeFileSync(join(target, file), text);
    files.push(join(target, file));
  };

  const vendor = join(target, 'vendor');
  const tarballs = packed === undefined ? await packPackages({ destination: vendor }) : copyTarballs(packed, vendor);
  const dependencies = {};
  for (const t of tarballs) {
    if (t.name === '@bitphysics/render-three') {
      rmSync(t.file); // a 2D game: no three.js
      continue;
    }
    files.push(t.file);
    dependencies[t.name] = `file:vendor/${basename(t.file)}`;
  }
  dependencies.bitecs = workspaceVersion('bitecs');
  dependencies['pixi.js'] = `^${workspaceVersion('pixi.js')}`;
  write(
    'package.json',
    `${JSON.stringify(
      {
        name,
        version: '0.1.0',
        private: true,
        type: 'module',
        description: `${gameTitle}: a 2D physics game made with bitphysics`,
        scripts: { start: 'node serve.mjs', build: 'node build.mjs', typecheck: 'tsc -p tsconfig.json' },
        dependencies,
        devDependencies: { esbuild: `^${workspaceVersion('esbuild')}`, typescript: `^${workspaceVersion('typescript')}` },
      },
      null,
      2,
    )}\n`,
  );
  for (const file of readdirSync(projectTemplateDir)) {
    write(file === 'gitignore' ? '.gitignore' : file, fill(readFileSync(join(projectTemplateDir, file), 'utf8')));
  }
  // The game itself: the repository's game template, with the error box loaded first.
  write('src/scene.ts', fill(readFileSync(join(templateDir, 'scene.ts'), 'utf8')));
  const main = fill(readFileSync(join(templateDir, 'main.ts'), 'utf8')).replace(
    /\nimport /,
    "\n// First: the locale guard and the error box that shows anything thrown instead of a blank page.\nimport '@bitphysics/game-kit/page-errors';\nimport ",
  );
  write('src/main.ts', main.replace(`(\`npm run new-game -- ${name}\`)`, '(`npm run new-game -- <folder>` in the bitphysics repository)'));
  write('src/index.html', fill(readFileSync(join(templateDir, 'index.html'), 'utf8')));
  return { dir: target, files };
}
