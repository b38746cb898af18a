// `npm start`: builds every game with esbuild, serves the gallery on http://127.0.0.1:8080/ (PORT
// overrides the port), prints the address and rebuilds on change. Tests import startServer().
//
// The site is built into memory and served from there by a plain node:http server: a request never
// waits for a build. While watching, esbuild rebuilds incrementally when a source changes and the
// new output replaces the old one only when the build has finished (a failed build keeps serving
// the last good one and prints its errors); a new game folder restarts the build with it included.

import { existsSync, mkdirSync, readFileSync, renameSync, rmSync, statSync, watch as watchDir, writeFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join, normalize, relative, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import * as esbuild from 'esbuild';
import { gameFolders, readRegistry, root, siteDir, siteOptions } from './build.mjs';
import { buildDocs, docsDir } from './docs.mjs';

/** Content types by file extension. */
const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.svg': 'image/svg+xml',
  '.ico': 'image/x-icon',
  '.txt': 'text/plain; charset=utf-8',
  '.woff2': 'font/woff2',
};

/**
 * Directories served as they are on disk, besides the built site: URL prefix (starting and ending
 * with '/') -> directory. A request under a prefix is answered from its directory ('/x/' -> x/index.html).
 * @type {Record<string, string>}
 */
export const staticRoutes = { '/docs/': docsDir };

/**
 * The API reference's build, while `npm start` makes it in the background: a page under /docs/ that
 * is not there yet is answered with a page saying so (and reloading itself every 3 s) instead of a
 * 404, and with the error if the build failed. `since` is the build's start (ms, Date.now()).
 * @type {{ building: boolean, since: number, error: string | null }}
 */
export const docsBuild = { building: false, since: 0, error: null };

/** The page /docs/ shows while its build runs (or after it failed). */
function docsPendingPage() {
  const seconds = Math.round((Date.now() - docsBuild.since) / 1000);
  const body = docsBuild.error
    ? `<h1>The API reference failed to build</h1><pre>${docsBuild.error.replace(/[<&]/g, (c) => (c === '<' ? '&lt;' : '&amp;'))}</pre><p>Run <code>npm run docs</code> to see the whole output.</p>`
    : `<h1>The API reference is being built</h1><p>Started ${seconds} s ago (TypeDoc takes about 10 s on a quiet machine). This page reloads itself; the gallery is at <a href="/">/</a>.</p>`;
  const refresh = docsBuild.error ? '' : '<meta http-equiv="refresh" content="3">';
  return `<!doctype html><html lang="en"><head><meta charset="utf-8">${refresh}<title>bitphysics API reference</title><style>body{font:16px system-ui,sans-serif;margin:3em;background:#10141c;color:#e8ecf1}a{color:#8ecbff}pre{white-space:pre-wrap}</style></head><body>${body}</body></html>`;
}

/** Where `startServer({ watch: false, cache: true })` keeps its last build between runs (the browser tests). */
export const cacheDir = join(root, 'dist', 'site-cache');

/**
 * The files of the build cached in `dir`, if every input it was built from is unchanged since (no
 * input modified after the build started, none missing) and the game folders are the same; else null.
 * @returns {Map<string, Uint8Array> | null}
 */
function readCache(dir) {
  const stampFile = join(dir, 'stamp.json');
  if (!existsSync(stampFile)) return null;
  try {
    const stamp = JSON.parse(readFileSync(stampFile, 'utf8'));
    if (stamp.folders !== gameFolders().join(',')) return null;
    for (const input of stamp.inputs) if (statSync(resolve(root, input)).mtimeMs > stamp.startedAt) return null;
    const files = new Map();
    for (const path of stamp.outputs) files.set(path, readFileSync(join(dir, 'site', path)));
    return files;
  } catch {
    return null;
  }
}

/**
 * Writes `files` and their inputs (esbuild metafile) to the cache `dir`: into a fresh folder first,
 * then swapped in, so a reader never sees half a cache. A cache that cannot be written is skipped
 * (the next run builds again).
 */
function writeCache(dir, files, metafile, startedAt) {
  const fresh = `${dir}.new-${process.pid}`;
  const old = `${dir}.old-${process.pid}`;
  try {
    rmSync(fresh, { recursive: true, force: true });
    for (const [path, contents] of files) {
      const file = join(fresh, 'site', path);
      mkdirSync(resolve(file, '..'), { recursive: true });
      writeFileSync(file, contents);
    }
    const inputs = Object.keys(metafile?.inputs ?? {}).map((p) => relative(root, resolve(p)));
    writeFileSync(
      join(fresh, 'stamp.json'),
      JSON.stringify({ startedAt, folders: gameFolders().join(','), inputs, outputs: [...files.keys()] }),
    );
    if (existsSync(dir)) renameSync(dir, old);
    renameSync(fresh, dir);
  } catch {
    // Another writer got there first, or the disk is full: no cache this time.
  } finally {
    rmSync(fresh, { recursive: true, force: true });
    rmSync(old, { recursive: true, force: true });
  }
}

/** Methods the server answers; any other gets 405 with an Allow header listing these. */
const METHODS = ['GET', 'HEAD'];

/**
 * Whether a request's Host header names this server: localhost, 127.0.0.1, [::1] or the address it
 * is bound to, with the port it listens on (no port: 80). Anything else is refused, so a page of
 * another site cannot reach the server through a DNS name rebound to 127.0.0.1 (DNS rebinding).
 * @param {string | undefined} header the Host header
 * @param {string} boundHost the address the server listens on
 * @param {number} port the port it listens on
 */
export function isOwnHost(header, boundHost, port) {
  if (typeof header !== 'string') return false;
  const match = /^(\[[0-9a-fA-F:.]+\]|[^:[\]]+)(?::(\d{1,5}))?$/.exec(header.trim());
  if (match === null) return false;
  const name = match[1].toLowerCase();
  const given = match[2] === undefined ? 80 : Number(match[2]);
  const bound = boundHost.includes(':') ? `[${boundHost.toLowerCase()}]` : boundHost.toLowerCase();
  return given === port && ['localhost', '127.0.0.1', '[::1]', bound].includes(name);
}

/**
 * Whether `file` (an absolute, normalised path) is inside directory `dir` (or is it): compared with a
 * trailing separator, so a sibling whose name starts with the directory's ('docs-old' beside 'docs')
 * is not inside.
 */
export function isInside(file, dir) {
  const base = resolve(dir);
  return file === base || file.startsWith(base.endsWith(sep) ? base : base + sep);
}

/**
 * Serves the site from memory: builds it once, then (with `watch`, the default) rebuilds on change.
 * Answers GET and HEAD only (405 with `Allow: GET, HEAD` otherwise), requests whose Host is this
 * server only (421 otherwise: `isOwnHost`), 400 for a path with malformed %-encoding, and serves a
 * static route (`staticRoutes`) only from inside its directory (403 otherwise: `isInside`).
 * @param {{ port?: number, host?: string, watch?: boolean, cache?: boolean, log?: (line: string) => void, site?: Map<string, Uint8Array> }} options
 *   port 0 picks a free one; `log` receives build errors and rebuild notes (default console.error).
 *   `cache` (only without watch; default false): reuse the build in `cacheDir` when none of its
 *   inputs changed since, else build and store it there. Callers that share the cache must not
 *   run at the same time (the browser tests hold a lock, test/browser/chromium.mjs). `site`: serve
 *   these files (path relative to the site root -> contents) instead of building (tests of the HTTP
 *   layer; `watch` and `cache` are then ignored).
 * @returns {Promise<{ url: string, stop: () => Promise<void>, builds: () => number }>} url ends with
 *   '/'; `builds()` counts finished builds (first included), for tests that wait for a rebuild.
 * @throws Error if the first build fails without `watch` (its esbuild errors), or the port cannot be bound.
 */
export async function startServer({
  port = 8080,
  host = '127.0.0.1',
  watch = true,
  cache = false,
  log = (line) => console.error(line),
  site = undefined,
} = {}) {
  if (site !== undefined) {
    watch = false;
    cache = false;
  }
  /** Built files: path relative to the site root ('lab-orbits/main.js') -> contents. */
  let files = new Map();
  let builds = 0;
  /** esbuild's metafile of the last good build (for the cache). */
  let metafile = null;
  let ctx = null;
  let folders = '';
  /** Errors of the last build, when it failed ('' after a good one). */
  let failure = '';

  /** Keeps a finished build's output (only a build without errors replaces the served files). */
  const collect = {
    name: 'bitphysics-serve-memory',
    setup(build) {
      build.onEnd((result) => {
        if (result.errors.length > 0) {
          failure = result.errors
            .slice(0, 10)
            .map((e) => (e.location ? `${e.location.file}:${e.location.line}: ${e.text}` : e.text))
            .join('\n');
          log(`build failed${builds > 0 ? ' (still serving the last good build)' : ''}:\n${failure}`);
          return;
        }
        failure = '';
        const next = new Map();
        for (const file of result.outputFiles ?? []) next.set(relative(siteDir, file.path).split(sep).join('/'), file.contents);
        files = next;
        metafile = result.metafile ?? null;
        if (builds > 0) log(`rebuilt ${next.size} files`);
        builds++;
      });
    },
  };

  /**
   * (Re)creates the esbuild context for the current game folders and builds once. A failed build
   * throws without `watch`; with it, the server starts anyway (pages answer 503 with the errors
   * until a change fixes the build).
   */
  const createContext = async () => {
    folders = gameFolders().join(',');
    const next = await esbuild.context({ ...siteOptions(), write: false, metafile: cache, plugins: [collect], logLevel: 'silent' });
    const result = await next.rebuild().catch((error) => error);
    if (result instanceof Error && !watch) {
      await next.dispose();
      throw new Error(`startServer: the site does not build: ${result.message}`);
    }
    if (watch) await next.watch();
    const old = ctx;
    ctx = next;
    await old?.dispose();
  };
  const cached = site ?? (cache && !watch ? readCache(cacheDir) : null);
  if (cached) {
    files = cached;
    builds = 1;
  } else {
    const startedAt = Date.now();
    await createContext();
    if (cache && !watch && builds > 0) writeCache(cacheDir, files, metafile, startedAt);
    if (!watch) {
      await ctx.dispose();
      ctx = null;
    }
  }

  // A new or removed game folder changes the entry points: rebuild the context (esbuild's watch only
  // follows files it already builds). game.json is read per request of registry.json.
  let dirWatcher = null;
  let restarting = Promise.resolve();
  if (watch) {
    dirWatcher = watchDir(join(root, 'games'), () => {
      restarting = restarting.then(async () => {
        try {
          if (gameFolders().join(',') === folders) return;
          const cached = cache && !watch ? readCache(cacheDir) : null;
          if (cached) {
            files = cached;
            builds = 1;
          } else {
            const startedAt = Date.now();
            await createContext();
            if (cache && !watch && builds > 0) writeCache(cacheDir, files, metafile, startedAt);
            if (!watch) {
              await ctx.dispose();
              ctx = null;
            }
          }
          log(`game folders changed: now ${gameFolders().length}`);
        } catch (error) {
          log(String(error));
        }
      });
    });
  }

  // Cross-origin isolation (COOP same-origin + COEP require-corp) makes SharedArrayBuffer available
  // to the pages, which worlds made with `threads > 1` need; every resource of the site is same-origin.
  const send = (res, status, type, body) => {
    res.writeHead(status, {
      'content-type': type,
      'cache-control': 'no-cache',
      'cross-origin-opener-policy': 'same-origin',
      'cross-origin-embedder-policy': 'require-corp',
    });
    res.end(body);
  };

  /** The contents for site path `path` ('' is the root), or undefined. */
  const lookup = (path) => {
    // The gallery's list, read from the games' game.json now, of the games this build holds (a
    // folder that appeared since waits for its build).
    if (path === 'registry.json')
      return Buffer.from(
        JSON.stringify(
          readRegistry().filter((e) => files.has(`${e.folder}/index.html`)),
          null,
          2,
        ),
      );
    return files.get(path);
  };

  const server = createServer((req, res) => {
    try {
      if (!METHODS.includes(req.method ?? '')) {
        res.writeHead(405, { allow: METHODS.join(', '), 'content-type': TYPES['.txt'] });
        res.end(`method not allowed: ${req.method}`);
        return;
      }
      const listening = server.address();
      if (!isOwnHost(req.headers.host, host, typeof listening === 'object' && listening ? listening.port : port)) {
        send(res, 421, TYPES['.txt'], 'misdirected request: this server answers only for its own address (localhost)');
        return;
      }
      const url = new URL(req.url ?? '/', 'http://localhost');
      let pathname;
      try {
        pathname = decodeURIComponent(url.pathname);
      } catch {
        send(res, 400, TYPES['.txt'], `bad request: malformed %-encoding in ${url.pathname}`);
        return;
      }
      for (const [prefix, dir] of Object.entries(staticRoutes)) {
        if (pathname === prefix.slice(0, -1)) {
          res.writeHead(301, { location: prefix + url.search });
          res.end();
          return;
        }
        if (!pathname.startsWith(prefix)) continue;
        const file = normalize(join(dir, pathname.slice(prefix.length)));
        if (!isInside(file, dir)) {
          send(res, 403, TYPES['.txt'], 'forbidden');
          return;
        }
        const target = existsSync(file) && statSync(file).isDirectory() ? join(file, 'index.html') : file;
        if (!existsSync(target)) {
          if (prefix === '/docs/' && (docsBuild.building || docsBuild.error))
            send(res, docsBuild.error ? 500 : 200, TYPES['.html'], docsPendingPage());
          else send(res, 404, TYPES['.txt'], `not found: ${pathname}`);
          return;
        }
        send(res, 200, TYPES[extname(target)] ?? 'application/octet-stream', readFileSync(target));
        return;
      }
      let path = pathname.replace(/^\/+/, '');
      if (path === '' || path.endsWith('/')) path += 'index.html';
      const body = lookup(path);
      if (body === undefined && lookup(`${path}/index.html`) !== undefined) {
        res.writeHead(301, { location: `${pathname}/${url.search}` });
        res.end();
        return;
      }
      if (body === undefined && builds === 0 && failure) {
        send(res, 503, TYPES['.txt'], `The site does not build yet:\n${failure}`);
        return;
      }
      if (body === undefined) {
        send(res, 404, TYPES['.txt'], `not found: ${pathname}`);
        return;
      }
      send(res, 200, TYPES[extname(path)] ?? 'application/octet-stream', body);
    } catch (error) {
      send(res, 500, TYPES['.txt'], String(error));
    }
  });
  await new Promise((resolveListen, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => resolveListen(undefined));
  });
  const address = server.address();
  const actual = typeof address === 'object' && address ? address.port : port;
  return {
    url: `http://${host}:${actual}/`,
    builds: () => builds,
    stop: async () => {
      dirWatcher?.close();
      await restarting;
      const closed = new Promise((r) => server.close(() => r(undefined)));
      server.closeAllConnections();
      await closed;
      await ctx?.dispose();
    },
  };
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const port = process.env.PORT ? Number(process.env.PORT) : 8080;
  if (!Number.isInteger(port) || port < 0 || port > 65535) {
    console.error(`PORT must be an integer in [0, 65535], got ${process.env.PORT}`);
    process.exit(1);
  }
  // The API reference (npm run docs) at /docs/: built once in the background if it is not there
  // yet, started before the gallery's build so both run at once; /docs/ says so meanwhile.
  const docsReady = existsSync(join(docsDir, 'index.html'));
  let docs = Promise.resolve();
  if (!docsReady) {
    docsBuild.building = true;
    docsBuild.since = Date.now();
    docs = buildDocs({ quiet: true, background: true }).then(
      () => undefined,
      (error) => {
        docsBuild.error = error instanceof Error ? error.message : String(error);
      },
    );
  }
  const { url } = await startServer({ port });
  console.log(`bitphysics gallery: ${url}  (rebuilds on change; Ctrl+C to stop)`);
  if (docsReady) console.log(`API reference: ${url}docs/  (npm run docs rebuilds it)`);
  else {
    console.log(`API reference: ${url}docs/ (being built; the page says when it is ready)`);
    docs.then(() => {
      docsBuild.building = false;
      if (docsBuild.error) console.error(`API reference failed: ${docsBuild.error}`);
      else console.log(`API reference: ${url}docs/ ready`);
    });
  }
}
