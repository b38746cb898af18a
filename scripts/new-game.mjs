// `npm run new-game -- <folder> [--title "Title"]`: a path (with a slash, e.g. ../my-game or
// /tmp/my-game) scaffolds a standalone project there, outside this repository (scripts/new-project.mjs).
// `npm run new-game -- <name> [--title "Title"]`: scaffolds games/<name>/ from scripts/templates/game
// (scene.ts: a pure seeded scene builder; main.ts: the page on the shared shell with a lil-gui panel,
// pause, FPS, window.game and the ready flag; index.html; game.json; a placeholder thumbnail.png)
// and its browser test test/browser/<name>.test.ts. The new game builds, appears in the gallery and
// passes its test as generated. Tests import newGame().
import { existsSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { deflateSync } from 'node:zlib';
import { root } from './build.mjs';
import { newProject } from './new-project.mjs';

/** Where the template's files are. */
export const templateDir = join(root, 'scripts', 'templates', 'game');

/** A game folder name: lower-case letters and digits in dash-separated words, 2 to 40 characters. */
const NAME = /^[a-z][a-z0-9]*(-[a-z0-9]+)*$/;

/** 'my-new-game' -> 'My new game'. */
export function titleOf(name) {
  const words = name.split('-').join(' ');
  return words.charAt(0).toUpperCase() + words.slice(1);
}

/**
 * Scaffolds a game.
 * @param {string} name folder name (see NAME), not taken yet.
 * @param {{ title?: string, gamesDir?: string, testDir?: string }} options title (default from the
 *   name), where the game folder goes (default games/) and its test (default test/browser/).
 * @returns {{ dir: string, test: string, files: string[] }} the game folder, the test file and every file written.
 * @throws TypeError if name is not a valid folder name; Error if the folder or test already exists.
 */
export function newGame(name, { title = undefined, gamesDir = join(root, 'games'), testDir = join(root, 'test', 'browser') } = {}) {
  if (typeof name !== 'string' || !NAME.test(name) || name.length < 2 || name.length > 40) {
    throw new TypeError(
      `new-game: name must be lower-case words joined by dashes (e.g. my-game), 2 to 40 characters, got ${JSON.stringify(name)}`,
    );
  }
  if (name === 'shared') throw new Error('new-game: "shared" is the games\' shared folder');
  const dir = join(gamesDir, name);
  const test = join(testDir, `${name}.test.ts`);
  if (existsSync(dir)) throw new Error(`new-game: ${dir} already exists`);
  if (existsSync(test)) throw new Error(`new-game: ${test} already exists`);
  const gameTitle = title ?? titleOf(name);
  if (typeof gameTitle !== 'string' || gameTitle.trim() === '' || /[<>"`\\]/.test(gameTitle)) {
    throw new TypeError(`new-game: title must be non-empty text without < > " \` or \\, got ${JSON.stringify(gameTitle)}`);
  }
  const fill = (text) => text.replaceAll('__NAME__', name).replaceAll('__TITLE__', gameTitle.replaceAll("'", '’'));
  mkdirSync(dir, { recursive: true });
  const files = [];
  for (const file of readdirSync(templateDir)) {
    const text = fill(readFileSync(join(templateDir, file), 'utf8'));
    const target = file === 'game.test.ts' ? test : join(dir, file);
    mkdirSync(resolve(target, '..'), { recursive: true });
    writeFileSync(target, text);
    files.push(target);
  }
  const thumbnail = join(dir, 'thumbnail.png');
  writeFileSync(thumbnail, placeholderPng(320, 200));
  files.push(thumbnail);
  return { dir, test, files };
}

/** Removes what `newGame` wrote. */
export function removeGame({ dir, test }) {
  rmSync(dir, { recursive: true, force: true });
  rmSync(test, { force: true });
}

/**
 * A placeholder thumbnail: `width` x `height` px, the gallery's dark background with a lighter
 * ball and floor (replace it with a screenshot: `npm run thumbnails`). An 8-bit RGB PNG (PNG spec, ISO/IEC 15948).
 */
export function placeholderPng(width, height) {
  const raw = Buffer.alloc((width * 3 + 1) * height);
  for (let y = 0; y < height; y++) {
    raw[y * (width * 3 + 1)] = 0; // filter: none
    for (let x = 0; x < width; x++) {
      const inBall = (x - width / 2) ** 2 + (y - height / 2) ** 2 < (height / 6) ** 2;
      const floor = y > height * 0.85;
      const [r, g, b] = inBall ? [108, 182, 255] : floor ? [60, 68, 84] : [16, 20, 28];
      const o = y * (width * 3 + 1) + 1 + x * 3;
      raw[o] = r;
      raw[o + 1] = g;
      raw[o + 2] = b;
    }
  }
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header[8] = 8;
  header[9] = 2;
  header[10] = 0;
  header[11] = 0;
  header[12] = 0;
  return Buffer.concat([
    Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
    chunk('IHDR', header),
    chunk('IDAT', deflateSync(raw)),
    chunk('IEND', Buffer.alloc(0)),
  ]);
}

/** A PNG chunk: length, type, data, CRC-32 of type and data. */
function chunk(type, data) {
  const out = Buffer.alloc(12 + data.length);
  out.writeUInt32BE(data.length, 0);
  out.write(type, 4, 'ascii');
  data.copy(out, 8);
  out.writeUInt32BE(crc32(out.subarray(4, 8 + data.length)), 8 + data.length);
  return out;
}

/** CRC-32 (IEEE 802.3 polynomial, reflected), as PNG uses. */
function crc32(bytes) {
  let c = 0xffffffff;
  for (let i = 0; i < bytes.length; i++) {
    c ^= bytes[i];
    for (let k = 0; k < 8; k++) c = (c >>> 1) ^ (0xedb88320 & -(c & 1));
  }
  return (c ^ 0xffffffff) >>> 0;
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const args = process.argv.slice(2);
  const titleAt = args.indexOf('--title');
  const title = titleAt >= 0 ? args[titleAt + 1] : undefined;
  const names = args.filter((a, i) => !a.startsWith('--') && (titleAt < 0 || i !== titleAt + 1));
  if (names.length !== 1) {
    console.error(
      'usage: npm run new-game -- <folder> [--title "Title"]   (a path outside this repository: a standalone project)\n' +
        '       npm run new-game -- <name> [--title "Title"]     (lower-case words joined by dashes: games/<name>)',
    );
    process.exit(2);
  }
  const arg = names[0];
  try {
    if (/[\\/]/.test(arg)) {
      const { dir } = await newProject(arg, { title });
      console.log(`wrote a standalone game project in ${dir}\n\nnext:\n  cd ${dir}\n  npm install\n  npm start`);
    } else {
      const { dir, test, files } = newGame(arg, { title });
      for (const f of files) console.log(`wrote ${f.slice(root.length + 1)}`);
      console.log(
        `\nnext: npm start, then open /${arg}/; edit ${dir.slice(root.length + 1)}/scene.ts and main.ts; npx vitest run ${test.slice(root.length + 1)}`,
      );
    }
  } catch (error) {
    console.error(error instanceof Error ? error.message : error);
    process.exit(1);
  }
}
