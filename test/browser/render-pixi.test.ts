/**
 * @bitphysics/render-pixi: the pixi-free parts (camera, colours) in Node, the renderer itself in
 * headless Chromium, hosted by the bouncing-balls page (window.game.renderer is a WorldRenderer).
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { choiceParam, flagParam, numberParam } from '../../packages/game-kit/src/params';
import { parseColor, seededColor } from '../../packages/render-common/src/colors';
import { Camera } from '../../packages/render-pixi/src/camera';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';

describe('Camera (metres to pixels)', () => {
  it('fits a view centred with padding and flips y', () => {
    const cam = new Camera({ width: 800, height: 600, padding: 10, view: { minX: 0, minY: 0, maxX: 16, maxY: 10 } });
    // Limited by width: (800 - 20) / 16 = 48.75 px/m; height used (10 m) = 487.5 px < 580.
    expect(cam.pixelsPerMeter).toBeCloseTo(48.75, 12);
    expect(cam.toScreenX(0)).toBeCloseTo(10, 9);
    expect(cam.toScreenX(16)).toBeCloseTo(790, 9);
    expect(cam.toScreenY(5)).toBeCloseTo(300, 9); // view centre at screen centre
    expect(cam.toScreenY(10)).toBeLessThan(cam.toScreenY(0)); // y up in the world is up on screen
    const p = cam.screenToWorld(cam.toScreenX(3.25), cam.toScreenY(7.5));
    expect(p.x).toBeCloseTo(3.25, 12);
    expect(p.y).toBeCloseTo(7.5, 12);
  });

  it('refits on resize and bumps its version', () => {
    const cam = new Camera({ width: 800, height: 600, padding: 0, view: { minX: -1, minY: -1, maxX: 1, maxY: 1 } });
    const v = cam.version;
    cam.resize(300, 900);
    expect(cam.version).toBeGreaterThan(v);
    expect(cam.pixelsPerMeter).toBeCloseTo(150, 12);
    expect(cam.toScreenY(0)).toBeCloseTo(450, 12);
  });

  it('keeps the screen centre when switching to a fixed scale', () => {
    const cam = new Camera({ width: 400, height: 400, pixelsPerMeter: 20 });
    expect(cam.toScreenX(0)).toBeCloseTo(0, 12); // default: world origin at the bottom-left corner
    expect(cam.toScreenY(0)).toBeCloseTo(400, 12);
    const cx = cam.toWorldX(200),
      cy = cam.toWorldY(200);
    cam.setPixelsPerMeter(80);
    expect(cam.toWorldX(200)).toBeCloseTo(cx, 12);
    expect(cam.toWorldY(200)).toBeCloseTo(cy, 12);
  });

  it('rejects bad input naming the option and the value', () => {
    expect(() => new Camera({ pixelsPerMeter: 0 })).toThrow(RangeError);
    expect(() => new Camera({ pixelsPerMeter: 0 })).toThrow(/pixelsPerMeter must be > 0, got 0/);
    expect(() => new Camera({ width: Number.NaN })).toThrow(/width must be finite, got NaN/);
    expect(() => new Camera({ view: { minX: 0, minY: 0, maxX: 0, maxY: 1 } })).toThrow(/view must have maxX > minX/);
    expect(() => new Camera({ zoom: 2 } as never)).toThrow(TypeError);
    expect(() => new Camera({ padding: '5' } as never)).toThrow(/padding must be a number, got "5"/);
    expect(() => new Camera().resize(-1, 10)).toThrow(/width must be > 0, got -1/);
  });
});

describe('colours and URL parameters', () => {
  it('parses colours and rejects bad ones', () => {
    expect(parseColor('t', 'c', '#ff8000')).toBe(0xff8000);
    expect(parseColor('t', 'c', '#f80')).toBe(0xff8800);
    expect(parseColor('t', 'c', 0x123456)).toBe(0x123456);
    expect(() => parseColor('t', 'c', 'red')).toThrow(RangeError);
    expect(() => parseColor('t', 'c', 0x1000000)).toThrow(/c must be an integer 0xRRGGBB/);
    expect(() => parseColor('t', 'c', null)).toThrow(TypeError);
  });

  it('seeds colours deterministically per (seed, id, spawn stamp)', () => {
    expect(seededColor(1, 5, 1, null)).toBe(seededColor(1, 5, 1, null));
    const distinct = new Set(Array.from({ length: 50 }, (_, i) => seededColor(1, i + 1, 1, null)));
    expect(distinct.size).toBeGreaterThan(40);
    expect(seededColor(1, 5, 2, null)).not.toBe(seededColor(1, 5, 1, null));
    expect([0x111111, 0x222222]).toContain(seededColor(7, 3, 1, [0x111111, 0x222222]));
  });

  it('reads URL parameters with clear errors', () => {
    expect(numberParam('count', { default: 40, min: 1, max: 100, integer: true }, '?count=8')).toBe(8);
    expect(numberParam('count', { default: 40, min: 1, max: 100 }, '')).toBe(40);
    expect(() => numberParam('count', { default: 40, min: 1, max: 100, integer: true }, '?count=2.5')).toThrow(
      /count must be an integer in \[1, 100\], got "2.5"/,
    );
    expect(() => numberParam('count', { default: 40, min: 1, max: 100 }, '?count=abc')).toThrow(RangeError);
    expect(flagParam('debug', '?debug')).toBe(true);
    expect(flagParam('debug', '?debug=0')).toBe(false);
    expect(() => flagParam('debug', '?debug=maybe')).toThrow(RangeError);
    expect(choiceParam('mode', ['a', 'b'] as const, 'a', '?mode=b')).toBe('b');
    expect(() => choiceParam('mode', ['a', 'b'] as const, 'a', '?mode=c')).toThrow(/mode must be one of a, b, got "c"/);
  });
});

/** What the renderer tests read from window.game on the bouncing-balls page. */
interface Host {
  paused: boolean;
  world: {
    steps: number;
    collision: { boundary: { min: Float64Array; max: Float64Array } };
    components: Record<string, Record<string, Float64Array>>;
  };
  ballIds(): number[];
  spawn(x: number, y: number, vx?: number, vy?: number): number;
  remove(eid: number): void;
  step(): void;
  reset(): void;
  renderer: {
    constructor: new (world: unknown, options?: unknown) => unknown;
    stats: { balls: number; mode: string; contacts: number; arrows: number; segments: number };
    mode: string;
    camera: { width: number; height: number; pixelsPerMeter: number; toScreenX(x: number): number; toScreenY(y: number): number };
    render(alpha: number): void;
    drawnPosition(eid: number): { x: number; y: number } | null;
    setColor(eid: number, color: unknown): void;
    clearColor(eid: number): void;
    colorOf(eid: number): number;
    setTrails(options: unknown): void;
    setDebug(options: unknown): void;
    trailsEnabled: boolean;
  };
}

describe('WorldRenderer in the browser', () => {
  let h: Harness;
  let g: GamePage;
  beforeAll(async () => {
    h = await Harness.start();
    g = await h.openGame('bouncing-balls', { query: { count: 8, trails: 0 } });
  }, START_TIMEOUT_MS);
  afterAll(async () => {
    await h?.close();
  });

  it('rejects bad options and arguments with RangeError/TypeError naming them', async () => {
    const results = await g.page.evaluate(() => {
      const game = window.game as unknown as Host;
      const R = game.renderer.constructor;
      const attempt = (f: () => unknown): string => {
        try {
          f();
          return 'no error';
        } catch (e) {
          return `${(e as Error).name}: ${(e as Error).message}`;
        }
      };
      const w = game.world;
      const id = game.ballIds()[0]!;
      return [
        attempt(() => new R(w, { pixelsPerMeter: -1 })),
        attempt(() => new R(w, { balls: 'quads' })),
        attempt(() => new R(w, { trails: { length: 1 } })),
        attempt(() => new R(w, { debug: { velocityScale: 'x' } })),
        attempt(() => new R(w, { colour: 1 })),
        attempt(() => new R(w, { palette: [] })),
        attempt(() => new R(w, { segmentColor: '#12' })),
        attempt(() => new R({}, {})),
        attempt(() => game.renderer.render(2)),
        attempt(() => game.renderer.setColor(999_999, 0xff0000)),
        attempt(() => game.renderer.setColor(id, 'red')),
        attempt(() => game.renderer.setTrails({ width: 0 })),
      ];
    });
    expect(results[0]).toMatch(/^RangeError: .*pixelsPerMeter must be > 0, got -1/);
    expect(results[1]).toMatch(/^RangeError: .*balls must be 'sprites', 'particles' or 'auto', got "quads"/);
    expect(results[2]).toMatch(/^RangeError: .*trails\.length must be an integer in \[2, 1024\], got 1/);
    expect(results[3]).toMatch(/^TypeError: .*debug\.velocityScale must be a number, got "x"/);
    expect(results[4]).toMatch(/^TypeError: .*unknown option "colour"/);
    expect(results[5]).toMatch(/^RangeError: .*palette must not be empty/);
    expect(results[6]).toMatch(/^RangeError: .*segmentColor must be a hex colour/);
    expect(results[7]).toMatch(/^TypeError: .*world must be a physics world/);
    expect(results[8]).toMatch(/^RangeError: .*alpha must be in \[0, 1\], got 2/);
    expect(results[9]).toMatch(/^RangeError: .*eid must be an entity of this world .*got 999999/);
    expect(results[10]).toMatch(/^RangeError: .*color must be a hex colour/);
    expect(results[11]).toMatch(/^RangeError: .*trails\.width must be an integer in \[1, 64\], got 0/);
  });

  it('interpolates between PreviousPosition and Position with alpha, y flipped', async () => {
    const r = await g.page.evaluate(() => {
      const game = window.game as unknown as Host;
      game.paused = true;
      const e = game.spawn(4, 8, 3, 0);
      game.step(); // one step: PreviousPosition is the start of it, Position the end
      const P = game.world.components.Position!,
        O = game.world.components.PreviousPosition!;
      const cam = game.renderer.camera;
      const at = (alpha: number) => {
        game.renderer.render(alpha);
        const p = game.renderer.drawnPosition(e)!;
        return [p.x, p.y];
      };
      return {
        a0: at(0),
        a1: at(1),
        ah: at(0.5),
        prev: [cam.toScreenX(O.x![e]!), cam.toScreenY(O.y![e]!)],
        cur: [cam.toScreenX(P.x![e]!), cam.toScreenY(P.y![e]!)],
        moved: P.x![e]! - O.x![e]!,
        fell: P.y![e]! - O.y![e]!,
      };
    });
    expect(r.moved).toBeGreaterThan(0);
    expect(r.fell).toBeLessThan(0);
    expect(r.a0[0]).toBeCloseTo(r.prev[0]!, 6);
    expect(r.a0[1]).toBeCloseTo(r.prev[1]!, 6);
    expect(r.a1[0]).toBeCloseTo(r.cur[0]!, 6);
    expect(r.a1[1]).toBeCloseTo(r.cur[1]!, 6);
    expect(r.ah[0]).toBeCloseTo((r.prev[0]! + r.cur[0]!) / 2, 6);
    expect(r.a1[1]).toBeGreaterThan(r.a0[1]); // falling in the world is moving down the screen
  });

  it('gives entities display objects as they come and takes them away as they go', async () => {
    await g.page.evaluate(() => {
      (window.game as unknown as Host).paused = true;
    });
    const n0 = await g.waitFor(() => {
      const game = window.game as unknown as Host;
      return game.renderer.stats.balls === game.ballIds().length && game.renderer.stats.balls;
    }, null);
    const added = await g.page.evaluate(() => (window.game as unknown as Host).spawn(12, 8));
    await g.waitFor((n) => (window.game as unknown as Host).renderer.stats.balls === n + 1, n0);
    expect(await g.page.evaluate((e) => (window.game as unknown as Host).renderer.drawnPosition(e) !== null, added)).toBe(true);
    await g.page.evaluate((e) => (window.game as unknown as Host).remove(e), added);
    await g.waitFor((n) => (window.game as unknown as Host).renderer.stats.balls === n, n0);
    expect(await g.page.evaluate((e) => (window.game as unknown as Host).renderer.drawnPosition(e), added)).toBeNull();
    expect(g.errors).toEqual([]);
  });

  it("never draws a new entity with a removed one's state: the old handle is refused, the slot's new ball has its own", async () => {
    const r = await g.page.evaluate(() => {
      const game = window.game as unknown as Host;
      game.paused = true;
      const old = game.spawn(3, 9);
      game.renderer.setColor(old, 0xff0000);
      game.renderer.render(1);
      game.remove(old);
      const fresh = game.spawn(15, 4); // bitecs reuses the slot at once
      game.renderer.render(1);
      const slot = fresh % 2 ** 25; // slotOf, in the page
      const P = game.world.components.Position!,
        cam = game.renderer.camera;
      let refused = '';
      try {
        game.renderer.setColor(old, 0x00ff00);
      } catch (e) {
        refused = String(e);
      }
      const p = game.renderer.drawnPosition(fresh)!;
      return {
        sameSlot: old % 2 ** 25 === slot,
        differ: fresh !== old,
        refused,
        oldDrawn: game.renderer.drawnPosition(old),
        freshColor: game.renderer.colorOf(fresh),
        drawn: [p.x, p.y],
        expected: [cam.toScreenX(P.x![slot]!), cam.toScreenY(P.y![slot]!)],
      };
    });
    expect(r.sameSlot).toBe(true);
    expect(r.differ).toBe(true);
    expect(r.refused).toMatch(/RangeError: WorldRenderer.setColor: eid refers to a removed entity/);
    expect(r.oldDrawn).toBeNull();
    expect(r.freshColor).not.toBe(0xff0000); // the user colour of the removed ball does not carry over
    expect(r.drawn[0]).toBeCloseTo(r.expected[0]!, 6);
    expect(r.drawn[1]).toBeCloseTo(r.expected[1]!, 6);
    expect(g.errors).toEqual([]);
  });

  it('keeps seeded colours deterministic and lets users set and clear their own', async () => {
    const r = await g.page.evaluate(() => {
      const game = window.game as unknown as Host;
      game.reset();
      // A ball the page leaves in its seeded colour (it colours the gold ball and the steel ones): the
      // first after ball 0 whose colour stays when its user colour is cleared.
      const plain = (): number =>
        game
          .ballIds()
          .slice(1)
          .find((e) => {
            const c = game.renderer.colorOf(e);
            game.renderer.clearColor(e);
            return game.renderer.colorOf(e) === c;
          })!;
      const id = plain();
      const seeded = game.renderer.colorOf(id);
      game.renderer.setColor(id, '#ff0000');
      const user = game.renderer.colorOf(id);
      game.renderer.clearColor(id);
      const back = game.renderer.colorOf(id);
      game.renderer.setColor(id, 0x00ff00);
      game.reset(); // a new world: user colours are forgotten, seeded ones come back identical
      return { seeded, user, back, afterReset: game.renderer.colorOf(plain()) };
    });
    expect(r.user).toBe(0xff0000);
    expect(r.back).toBe(r.seeded);
    expect(r.afterReset).toBe(r.seeded);
  });

  it('draws the debug overlay (contacts, arrows) and trails on demand', async () => {
    await g.page.evaluate(() => {
      const game = window.game as unknown as Host;
      game.renderer.setDebug(true);
      game.renderer.setTrails({ length: 20 });
      // The page's heap starts at rest (asleep: no arrows): balls thrown down onto it move and touch.
      for (const x of [4, 8, 12]) game.spawn(x, 8, 0, -5);
      game.paused = false;
    });
    const s = await g.waitFor(
      () => {
        const st = (window.game as unknown as Host).renderer.stats;
        return st.contacts > 0 && st.arrows > 0 ? { ...st } : null;
      },
      null,
      30_000,
    );
    expect(s.segments).toBe(5); // the scene's three inclined walls and the hoop's backboard and rim
    expect(await g.page.evaluate(() => (window.game as unknown as Host).renderer.trailsEnabled)).toBe(true);
    expect(await g.canvasColors()).toBeGreaterThan(16);
    await g.page.evaluate(() => {
      const game = window.game as unknown as Host;
      game.renderer.setDebug(false);
      game.renderer.setTrails(false);
    });
    await g.waitFor(() => (window.game as unknown as Host).renderer.stats.contacts === 0, null);
    expect(g.errors).toEqual([]);
  });

  it('keeps the boundary in view when the window is resized', async () => {
    await g.page.setViewportSize({ width: 420, height: 640 });
    // The canvas fills the layout's stage: at 420 px the whole width, under the toolbar.
    await g.waitFor(() => (window.game as unknown as Host).renderer.camera.width === 420, null);
    const canvas = await g.canvasBox();
    const r = await g.page.evaluate(() => {
      const game = window.game as unknown as Host;
      const cam = game.renderer.camera,
        box = game.world.collision.boundary;
      return {
        x0: cam.toScreenX(box.min[0]!),
        x1: cam.toScreenX(box.max[0]!),
        yTop: cam.toScreenY(box.max[1]!),
        yBottom: cam.toScreenY(box.min[1]!),
        w: cam.width,
        h: cam.height,
      };
    });
    expect(r.h).toBe(canvas.height);
    // The canvas fills the stage: the window less the toolbar and the game's status row (its goal,
    // score and hint take two or three lines at this width).
    const stage = (await g.page.locator('.bp-stage').boundingBox())!;
    expect(canvas.height).toBeCloseTo(stage.height, 0);
    expect(canvas.height).toBeGreaterThan(480);
    expect(r.x0).toBeGreaterThanOrEqual(0);
    expect(r.x1).toBeLessThanOrEqual(r.w);
    expect(r.yTop).toBeGreaterThanOrEqual(0);
    expect(r.yBottom).toBeLessThanOrEqual(r.h);
    expect(r.x1 - r.x0).toBeGreaterThan(r.w * 0.8); // fitted, not just inside
    await g.page.setViewportSize({ width: 800, height: 500 });
  });

  it('fills a shape with the colour set on its body (catapult page)', async () => {
    // The cases from here on open pages of their own: the bouncing-balls page of the cases above is
    // closed (an open game page keeps stepping and drawing on the one software GPU every page shares).
    await g.close();
    // The catapult's castle pieces are boxes (addBox: the body is its own shape). Each colour set on a
    // piece must fill it: the pixel at its centre is dominated by that channel (the fill is drawn at
    // alpha 0.85 over the dark background, so the set channel reads above 180 and the others below 100).
    const c = await h.openGame('catapult', { query: { level: 1 }, viewport: { width: 1280, height: 800 } });
    const read = (color: number) =>
      c.page.evaluate(async (color: number) => {
        const game = window.game as unknown as {
          paused: boolean;
          level(): { pieces: { body: number; kind: string }[] };
          positionOf(h: number): [number, number];
          renderer: Host['renderer'];
          pacer: { drawn: number };
          app: { canvas: HTMLCanvasElement };
        };
        // Running, not paused: paused, the page dims the scene under its 'Paused' overlay. The castle
        // stands at rest, so the post stays where it is drawn.
        game.paused = false;
        // A post: 0.3 m x 1.2 m, about 10 px wide on a 1280 px page, so its centre is fill, not outline.
        const piece = game.level().pieces.find((p) => p.kind === 'post')!;
        game.renderer.setColor(piece.body, color);
        const reported = game.renderer.colorOf(piece.body);
        // Two drawn frames, then copy the canvas in the next animation frame (before it is cleared).
        const start = game.pacer.drawn;
        while (game.pacer.drawn < start + 2) await new Promise((r) => requestAnimationFrame(r));
        const canvas = game.app.canvas;
        const copy = new OffscreenCanvas(canvas.width, canvas.height).getContext('2d')!;
        copy.drawImage(canvas, 0, 0);
        const [x, y] = game.positionOf(piece.body);
        const scale = canvas.width / canvas.getBoundingClientRect().width;
        const px = Math.round(game.renderer.camera.toScreenX(x) * scale),
          py = Math.round(game.renderer.camera.toScreenY(y) * scale);
        const [r, g, b] = copy.getImageData(px, py, 1, 1).data;
        return { reported, rgb: [r!, g!, b!] };
      }, color);
    const green = await read(0x00ff00);
    expect(green.reported).toBe(0x00ff00);
    expect(green.rgb[1]).toBeGreaterThan(180);
    expect(green.rgb[0]).toBeLessThan(100);
    expect(green.rgb[2]).toBeLessThan(100);
    const blue = await read(0x0000ff);
    expect(blue.rgb[2]).toBeGreaterThan(180);
    expect(blue.rgb[0]).toBeLessThan(100);
    expect(blue.rgb[1]).toBeLessThan(100);
    expect(c.errors).toEqual([]);
  });

  it('uses the ParticleContainer path from 1000 balls on (auto) or when asked', async () => {
    const big = await h.openGame('bouncing-balls', { query: { count: 1200, trails: 0 } });
    const s = await big.waitFor(
      () => {
        const st = (window.game as unknown as Host).renderer.stats;
        return st.balls === 1200 ? { ...st } : null;
      },
      null,
      30_000,
    );
    expect(s.mode).toBe('particles');
    expect(await big.canvasColors()).toBeGreaterThan(16);
    expect(big.errors).toEqual([]);
    await big.close();
    const small = await h.openGame('bouncing-balls', { query: { count: 8, mode: 'particles' } });
    expect(await small.page.evaluate(() => (window.game as unknown as Host).renderer.mode)).toBe('particles');
    expect(await small.canvasColors()).toBeGreaterThan(16);
    expect(small.errors).toEqual([]);
    await small.close();
  });
});
