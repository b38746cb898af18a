/**
 * The dev server's HTTP layer (scripts/serve.mjs, `npm start`), served from a small in-memory site
 * (no build) on a free port: methods, Host, %-encoding and the static routes' containment. The
 * reference is HTTP itself (RFC 9110: 405 with Allow, 400 for a malformed request target, 421 for a
 * request aimed at another server) and the rule that only the docs folder is served under /docs/.
 */

import { mkdirSync, mkdtempSync, writeFileSync } from 'node:fs';
import { request } from 'node:http';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

interface DevServer {
  url: string;
  stop(): Promise<void>;
}
interface ServeModule {
  startServer(o: { port: number; site: Map<string, Uint8Array>; log: (line: string) => void }): Promise<DevServer>;
  staticRoutes: Record<string, string>;
  docsBuild: { building: boolean; since: number; error: string | null };
}

const serve = (await import(pathToFileURL(join(__dirname, '../../scripts/serve.mjs')).href)) as ServeModule;

/** One raw request (node:http: any method, any Host header); resolves with status, headers and body. */
function send(
  url: string,
  method: string,
  path: string,
  host?: string,
): Promise<{ status: number; headers: Record<string, unknown>; body: string }> {
  const u = new URL(url);
  return new Promise((resolve, reject) => {
    const req = request({ host: u.hostname, port: u.port, method, path, headers: host === undefined ? {} : { host } }, (res) => {
      let body = '';
      res.setEncoding('utf8');
      res.on('data', (d) => {
        body += d;
      });
      res.on('end', () => resolve({ status: res.statusCode ?? 0, headers: res.headers, body }));
    });
    req.on('error', reject);
    req.end();
  });
}

describe('dev server HTTP layer', () => {
  let server: DevServer;
  let port: string;
  const oldRoutes = { ...serve.staticRoutes };
  beforeAll(async () => {
    // A docs folder with siblings whose names start with its own.
    const dir = mkdtempSync(join(tmpdir(), 'bitphysics-serve-'));
    for (const name of ['docs', 'docs-old', 'docsx']) {
      mkdirSync(join(dir, name));
      writeFileSync(join(dir, name, 'page.txt'), `${name} page`);
    }
    serve.staticRoutes['/docs/'] = join(dir, 'docs');
    const site = new Map<string, Uint8Array>([
      ['index.html', Buffer.from('<!doctype html><title>gallery</title>')],
      ['lab/index.html', Buffer.from('<!doctype html><title>lab</title>')],
    ]);
    server = await serve.startServer({ port: 0, site, log: () => undefined });
    port = new URL(server.url).port;
  });
  afterAll(async () => {
    await server?.stop();
    Object.assign(serve.staticRoutes, oldRoutes);
  });

  it('serves GET and HEAD; PUT, DELETE, TRACE, POST and others get 405 with Allow: GET, HEAD', async () => {
    expect((await send(server.url, 'GET', '/')).status).toBe(200);
    const head = await send(server.url, 'HEAD', '/lab/');
    expect(head.status).toBe(200);
    expect(head.body).toBe('');
    for (const method of ['PUT', 'DELETE', 'TRACE', 'POST', 'PATCH', 'OPTIONS']) {
      const res = await send(server.url, method, '/');
      expect(res.status, method).toBe(405);
      expect(res.headers.allow, method).toBe('GET, HEAD');
    }
  });

  it('answers 400 to malformed %-encoding (it was a 500)', async () => {
    for (const path of ['/%E0%A4%A', '/%', '/lab/%zz', '/docs/%C0']) {
      const res = await send(server.url, 'GET', path);
      expect(res.status, path).toBe(400);
    }
    // Well-formed encoding still works.
    expect((await send(server.url, 'GET', '/%6cab/')).status).toBe(200);
  });

  it('refuses a foreign Host (DNS rebinding) with 421; accepts localhost, 127.0.0.1 and [::1] with its port', async () => {
    for (const host of [`localhost:${port}`, `127.0.0.1:${port}`, `[::1]:${port}`, `LOCALHOST:${port}`]) {
      expect((await send(server.url, 'GET', '/', host)).status, host).toBe(200);
    }
    for (const host of [
      `evil.example:${port}`,
      'evil.example',
      `127.0.0.1.evil.example:${port}`,
      `localhost:${Number(port) + 1}`,
      'localhost',
      `user@localhost:${port}`,
    ]) {
      const res = await send(server.url, 'GET', '/', host);
      expect(res.status, host).toBe(421);
      expect(res.body, host).not.toContain('gallery');
    }
  });

  it('serves /docs/ from the docs folder only: its siblings docs-old and docsx are not reachable', async () => {
    const ok = await send(server.url, 'GET', '/docs/page.txt');
    expect(ok.status).toBe(200);
    expect(ok.body).toBe('docs page');
    // Out of the folder by an encoded slash: into a sibling whose name starts with "docs", or above it.
    for (const path of ['/docs/..%2Fdocs-old/page.txt', '/docs/..%2Fdocsx/page.txt', '/docs/..%2F..%2Fetc/passwd']) {
      const res = await send(server.url, 'GET', path);
      expect(res.status, path).toBe(403);
      expect(res.body, path).not.toContain('page');
    }
    // Sibling prefixes are not the docs route at all.
    for (const path of ['/docs-old/page.txt', '/docsx/page.txt', '/docsx']) {
      const res = await send(server.url, 'GET', path);
      expect(res.status, path).toBe(404);
      expect(res.body, path).not.toContain('docs-old page');
    }
  });

  it('while npm start builds the API reference, /docs/ says so and reloads itself; a failed build shows its error', async () => {
    expect((await send(server.url, 'GET', '/docs/index.html')).status).toBe(404); // no build running: missing is missing
    serve.docsBuild.building = true;
    serve.docsBuild.since = Date.now() - 4000;
    try {
      const pending = await send(server.url, 'GET', '/docs/index.html');
      expect(pending.status).toBe(200);
      expect(pending.body).toContain('The API reference is being built');
      expect(pending.body).toContain('<meta http-equiv="refresh" content="3">');
      // A page that is there is served as it is meanwhile.
      expect((await send(server.url, 'GET', '/docs/page.txt')).body).toBe('docs page');
      serve.docsBuild.building = false;
      serve.docsBuild.error = 'typedoc exited with 1\nsrc/x.ts: <undocumented>';
      const failed = await send(server.url, 'GET', '/docs/index.html');
      expect(failed.status).toBe(500);
      expect(failed.body).toContain('failed to build');
      expect(failed.body).toContain('&lt;undocumented>');
    } finally {
      serve.docsBuild.building = false;
      serve.docsBuild.error = null;
    }
  });
});
