/**
 * The particle labs of Ramtal and Dobre ch. 12 (galaxy, wormhole, splash, smoke, fire, sparks,
 * attractors) in headless Chromium, with small counts. For each lab: the page loads without errors,
 * draws a non-blank canvas, lists its controls and shows its readout and panel; an input (click, drag,
 * mouse move, key or panel value) changes the state read through window.game; and the particle
 * counts behave as they must (smoke and fire settle to a steady count near rate x mean lifetime, a
 * splash makes droplets that are all gone a few lifetimes later). Measurements run the lab's own
 * step with `advance(n)` while the page is paused, so they do not depend on the frame rate.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';
import { type ContractRun, checkPageContract, contractOptions } from './page-contract';

/** What every particle lab puts on window.game, loosely typed (each test casts what it reads). */
type Lab = Record<string, unknown> & {
  paused: boolean;
  reset(): void;
  advance(n: number): void;
  stats(): { entities: number; steps: number; fps: number };
  world: {
    time: number;
    steps: number;
    dt: number;
    laws: { openingAngle: number; gravitySoftening: number; gravityMethod: string; wind: { velocity: Float64Array } };
    components: Record<string, Record<string, ArrayLike<number>>>;
  };
  renderer: {
    camera: { toScreenX(x: number): number; toScreenY(y: number): number; toWorldX(x: number): number; toWorldY(y: number): number };
  };
};

let h: Harness;
beforeAll(async () => {
  h = await Harness.start();
}, START_TIMEOUT_MS);
afterAll(async () => {
  await h?.close();
});

/** Opens a lab and checks what every lab shows: a drawn canvas, the legend keys, the readout, the panel, no errors. */
/** Opens a lab and checks it is drawn, its legend and panels; with `run`, as that run of the page contract, which it checks first. */
async function openLab(folder: string, query: Record<string, string | number>, keys: string[], run?: ContractRun): Promise<GamePage> {
  const g = await h.openGame(folder, { query, ...(run ? contractOptions(run) : {}) });
  if (run) await checkPageContract(g, folder, run);
  expect(await g.canvasColors()).toBeGreaterThan(16);
  const legend = await g.page.locator('.bp-legend').textContent();
  for (const key of ['P', 'N', 'R', ...keys]) expect(legend).toContain(key);
  expect(await g.page.locator('[data-lab="info"]').count()).toBe(1);
  expect(await g.page.locator('.lil-gui').count()).toBeGreaterThan(0);
  expect(g.errors).toEqual([]);
  return g;
}

/** Pauses the lab and starts it over from a fresh world (step 0). */
async function pauseAndReset(g: GamePage): Promise<void> {
  await g.page.evaluate(() => {
    const w = window.game as unknown as Lab;
    w.paused = true;
    w.reset();
  });
}

/** Types `value` into the lil-gui number field labelled `name` and commits it (Enter). */
async function setNumber(g: GamePage, name: string, value: number): Promise<void> {
  const input = g.page.getByLabel(name, { exact: true });
  await input.fill(String(value));
  await input.press('Enter');
}

/** Screen position (page px) of world point (x, y), m. */
async function pageXY(g: GamePage, x: number, y: number): Promise<{ x: number; y: number }> {
  const box = await g.canvasBox();
  const s = await g.page.evaluate(
    ([wx, wy]) => {
      const cam = (window.game as unknown as Lab).renderer.camera;
      return { x: cam.toScreenX(wx!), y: cam.toScreenY(wy!) };
    },
    [x, y],
  );
  return { x: box.x + s.x, y: box.y + s.y };
}

describe('lab-galaxy', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab('lab-galaxy', { count: 3000 }, ['Wheel', 'Drag', 'C']);
  });
  afterAll(async () => {
    await g?.close();
  });

  it('times its steps, and pausing stops the stars', async () => {
    await g.waitFor(() => (window.game as unknown as { timer: { count: number } }).timer.count >= 3, null, 20_000);
    const timing = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & {
        timer: { mean: number; count: number };
        starCount(): number;
        points: { stats: { points: number } };
      };
      return { mean: w.timer.mean, stars: w.starCount(), drawn: w.points.stats.points };
    });
    expect(timing.stars).toBe(3000);
    expect(timing.drawn).toBe(3000);
    expect(timing.mean).toBeGreaterThan(0);
    await g.press('p');
    const before = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab;
      return { steps: w.world.steps, x: Array.from(w.world.components.Position!.x!).slice(1, 40) };
    });
    await g.frames(4);
    const after = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab;
      return { paused: w.paused, steps: w.world.steps, x: Array.from(w.world.components.Position!.x!).slice(1, 40) };
    });
    expect(after.paused).toBe(true);
    expect(after.steps).toBe(before.steps);
    expect(after.x).toEqual(before.x);
    // One step moves them.
    await g.press('n');
    const stepped = await g.page.evaluate(() => Array.from((window.game as unknown as Lab).world.components.Position!.x!).slice(1, 40));
    expect(stepped).not.toEqual(before.x);
  });

  it('takes the opening angle, softening and time scale from the panel, rebuilds by star count, and colours by radius on C', async () => {
    await setNumber(g, 'opening angle θ', 1);
    await setNumber(g, 'softening ε (m)', 0.5);
    await setNumber(g, 'time scale', 2);
    const laws = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab;
      return { theta: w.world.laws.openingAngle, eps: w.world.laws.gravitySoftening, dt: w.world.dt };
    });
    expect(laws.theta).toBe(1);
    expect(laws.eps).toBe(0.5);
    expect(laws.dt).toBeCloseTo(2 / 60, 12);
    await setNumber(g, 'stars (rebuilds)', 2000);
    await g.press('c');
    const rebuilt = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & {
        starCount(): number;
        params: { color: string };
        points: { options: { colorBy: string } };
      };
      w.advance(2);
      return {
        stars: w.starCount(),
        steps: w.world.steps,
        theta: w.world.laws.openingAngle,
        color: w.params.color,
        colorBy: w.points.options.colorBy,
      };
    });
    expect(rebuilt.stars).toBe(2000);
    expect(rebuilt.theta).toBe(1);
    expect(rebuilt.color).toBe('radius');
    expect(rebuilt.colorBy).toBe('radius');
    expect(g.errors).toEqual([]);
  });
});

describe('lab-wormhole', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab('lab-wormhole', { count: 300 }, ['Drag', 'Click', 'T']);
  });
  afterAll(async () => {
    await g?.close();
  });

  it('moves stars that cross the horizon to the white hole with the same speed and an outward velocity', async () => {
    await pauseAndReset(g);
    const jump = await g.page.evaluate(() => {
      type Hole = {
        teleports: number;
        last: { speedIn: number; speedOut: number; x: number; y: number; step: number };
        settings: { horizon: number };
        whiteHole: number;
        ids: Uint32Array;
      };
      const w = window.game as unknown as Lab & { hole: Hole };
      for (let i = 0; i < 900 && w.hole.teleports === 0; i++) w.advance(1);
      const hole = w.hole,
        P = w.world.components.Position!,
        V = w.world.components.Velocity!;
      const wx = P.x![hole.whiteHole % 2 ** 25]!,
        wy = P.y![hole.whiteHole % 2 ** 25]!;
      // The star that just came out: the one sitting at the exit point.
      let star = 0;
      for (const e of hole.ids) if (e !== 0 && P.x![e % 2 ** 25] === hole.last.x && P.y![e % 2 ** 25] === hole.last.y) star = e;
      const vr = star ? V.x![star % 2 ** 25]! * (hole.last.x - wx) + V.y![star % 2 ** 25]! * (hole.last.y - wy) : Number.NaN;
      return {
        teleports: hole.teleports,
        ...hole.last,
        horizon: hole.settings.horizon,
        exitR: Math.hypot(hole.last.x - wx, hole.last.y - wy),
        star,
        vr,
        steps: w.world.steps,
      };
    });
    expect(jump.teleports).toBeGreaterThan(0);
    expect(jump.step).toBe(jump.steps);
    expect(jump.speedOut).toBeCloseTo(jump.speedIn, 9);
    expect(jump.exitR).toBeCloseTo(jump.horizon, 9);
    expect(jump.star).toBeGreaterThan(0);
    // Reflected about the radial direction: the star leaves the white hole outwards.
    expect(jump.vr).toBeGreaterThan(0);
  });

  it("adds stars on a click and moves the white hole (and every star's push centre) on a drag", async () => {
    const before = await g.page.evaluate(() => (window.game as unknown as Lab & { hole: { count: number } }).hole.count);
    const empty = await pageXY(g, 0, -7);
    await g.page.mouse.click(empty.x, empty.y);
    const added = await g.page.evaluate(() => (window.game as unknown as Lab & { hole: { count: number } }).hole.count);
    expect(added).toBe(before + 40);
    const from = await pageXY(g, 6, 0),
      to = await pageXY(g, 8, -4);
    const m = g.page.mouse;
    await m.move(from.x, from.y);
    await m.down();
    await m.move(to.x, to.y, { steps: 6 });
    await m.up();
    const moved = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & { hole: { whiteHole: number; ids: Uint32Array } };
      const P = w.world.components.Position!,
        C = w.world.components.CentralForce!;
      const star = w.hole.ids[0]!;
      return {
        x: P.x![w.hole.whiteHole % 2 ** 25]!,
        y: P.y![w.hole.whiteHole % 2 ** 25]!,
        cx: C.cx![star % 2 ** 25]!,
        cy: C.cy![star % 2 ** 25]!,
      };
    });
    expect(moved.x).toBeCloseTo(8, 1);
    expect(moved.y).toBeCloseTo(-4, 1);
    expect(moved.cx).toBe(moved.x);
    expect(moved.cy).toBe(moved.y);
    expect(g.errors).toEqual([]);
  });
});

describe('lab-splash', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab('lab-splash', { rain: 0 }, ['Click']);
  });
  afterAll(async () => {
    await g?.close();
  });

  it('a drop hitting the ground bursts into droplets that are all gone a few lifetimes later', async () => {
    await pauseAndReset(g);
    const run = await g.page.evaluate(() => {
      type S = { groundImpacts: number; waterImpacts: number; last: { surface: string; speed: number; droplets: number } };
      const w = window.game as unknown as Lab & {
        splash: S;
        splashCount(): number;
        dropCount(): number;
        drop(x: number, y: number): number;
      };
      const before = w.splashCount();
      w.drop(3, 3);
      const dropsInAir = w.dropCount();
      let steps = 0;
      while (w.splash.groundImpacts === 0 && steps < 240) {
        w.advance(1);
        steps++;
      }
      const justAfter = w.splashCount();
      const droplets = w.splash.last.droplets,
        speed = w.splash.last.speed,
        surface = w.splash.last.surface;
      w.advance(30);
      const peakLater = w.splashCount();
      w.advance(150);
      return { before, dropsInAir, steps, justAfter, droplets, speed, surface, peakLater, end: w.splashCount(), dropsLeft: w.dropCount() };
    });
    expect(run.before).toBe(0);
    expect(run.dropsInAir).toBe(1);
    expect(run.steps).toBeLessThan(240);
    expect(run.surface).toBe('ground');
    expect(run.speed).toBeGreaterThan(3);
    expect(run.droplets).toBeGreaterThan(5);
    expect(run.justAfter).toBe(run.droplets);
    expect(run.peakLater).toBeGreaterThan(0);
    expect(run.end).toBe(0);
    expect(run.dropsLeft).toBe(0);
  });

  it('a drop into the pool makes a crown and a ripple; a click drops a drop; the panel sets the rain', async () => {
    const water = await g.page.evaluate(() => {
      type S = { waterImpacts: number; absorbed: number; rippleT: Float64Array };
      const w = window.game as unknown as Lab & { splash: S; splashCount(): number; drop(x: number, y: number): number };
      w.drop(-2.5, 2);
      let steps = 0;
      while (w.splash.waterImpacts === 0 && steps < 240) {
        w.advance(1);
        steps++;
      }
      const crown = w.splashCount();
      w.advance(150);
      return {
        impacts: w.splash.waterImpacts,
        crown,
        absorbed: w.splash.absorbed,
        ripples: Array.from(w.splash.rippleT).filter((t) => t > 0).length,
        end: w.splashCount(),
      };
    });
    expect(water.impacts).toBe(1);
    expect(water.crown).toBeGreaterThan(5);
    expect(water.ripples).toBe(1);
    expect(water.absorbed).toBeGreaterThan(0);
    expect(water.end).toBe(0);
    const sky = await pageXY(g, 2, 4);
    await g.page.mouse.click(sky.x, sky.y);
    expect(await g.page.evaluate(() => (window.game as unknown as Lab & { dropCount(): number }).dropCount())).toBe(1);
    await setNumber(g, 'rain (drops/s)', 12);
    const rate = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & { splash: { rain: number } };
      return w.world.components.Emitter!.rate![w.splash.rain % 2 ** 25];
    });
    expect(rate).toBe(12);
    expect(g.errors).toEqual([]);
  });
});

describe('lab-smoke', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab('lab-smoke', {}, ['Click'], 'desktop');
  });
  afterAll(async () => {
    await g?.close();
  });

  it('settles to a steady puff count near rate x mean lifetime, which follows the rate set in the panel', async () => {
    await pauseAndReset(g);
    const count = () =>
      g.page.evaluate((n) => {
        const w = window.game as unknown as Lab & { particleCount(): number };
        w.advance(n);
        return w.particleCount();
      }, 0);
    const advance = (n: number) => g.page.evaluate((k) => (window.game as unknown as Lab).advance(k), n);
    await advance(120);
    const early = await count();
    await advance(480);
    const c1 = await count();
    await advance(120);
    const c2 = await count();
    // Puffs live 4 to 6 s at 120 per second: 600 on average once the first ones expire.
    expect(early).toBeGreaterThan(200);
    expect(early).toBeLessThan(260);
    expect(c1).toBeGreaterThan(500);
    expect(c1).toBeLessThan(700);
    expect(Math.abs(c2 - c1) / c1).toBeLessThan(0.12);
    await setNumber(g, 'rate (puffs/s)', 300);
    const rate = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & { smoke: { emitter: number } };
      return w.world.components.Emitter!.rate![w.smoke.emitter % 2 ** 25];
    });
    expect(rate).toBe(300);
    await advance(600);
    const c3 = await count();
    expect(c3).toBeGreaterThan(1250);
    expect(c3).toBeLessThan(1750);
  });

  it('blows the smoke downwind and moves the chimney on a click', async () => {
    await setNumber(g, 'wind (m/s)', 5);
    const drift = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & { smoke: { source: [number, number] }; puffCentroid(): number[] };
      const x0 = w.puffCentroid()[0]!;
      w.advance(240);
      return { wind: w.world.laws.wind.velocity[0], x0, meanX: w.puffCentroid()[0]!, sourceX: w.smoke.source[0] };
    });
    expect(drift.wind).toBe(5);
    // 4 s of a 5 m/s wind: the puffs (which relax to the air in 0.5 s) end up well downwind of where they were.
    expect(drift.meanX).toBeGreaterThan(drift.sourceX + 3);
    expect(drift.meanX).toBeGreaterThan(drift.x0 + 3);
    const target = await pageXY(g, 8, 2);
    await g.page.mouse.click(target.x, target.y);
    const source = await g.page.evaluate(() =>
      (window.game as unknown as Lab & { smoke: { source: [number, number] } }).smoke.source.slice(),
    );
    expect(source[0]).toBeCloseTo(8, 1);
    expect(source[1]).toBeCloseTo(2, 1);
    expect(g.errors).toEqual([]);
  });
});

describe('lab-fire', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab('lab-fire', {}, ['Click'], 'desktop');
  });
  afterAll(async () => {
    await g?.close();
  });

  it('reaches a steady count that scales with the intensity, flames turning into glow', async () => {
    await pauseAndReset(g);
    const at = (n: number) =>
      g.page.evaluate((k) => {
        const w = window.game as unknown as Lab & {
          particleCount(e?: number): number;
          fire: { flames: number; glow: number; sparks: number; smoke: number };
        };
        w.advance(k);
        const f = w.fire;
        return {
          all: w.particleCount(),
          flames: w.particleCount(f.flames),
          glow: w.particleCount(f.glow),
          sparks: w.particleCount(f.sparks),
          smoke: w.particleCount(f.smoke),
        };
      }, n);
    const c1 = await at(240);
    const c2 = await at(60);
    // 500 flames/s (flicker 0.7-1.3) x 0.375 s + as many glows x 0.5 s + 14 sparks/s x 1.3 s + 30 smoke/s x 2.75 s = about 540.
    expect(c1.all).toBeGreaterThan(380);
    expect(c1.all).toBeLessThan(700);
    expect(Math.abs(c2.all - c1.all) / c1.all).toBeLessThan(0.25);
    expect(c1.flames).toBeGreaterThan(100);
    expect(c1.glow).toBeGreaterThan(100);
    expect(c1.sparks).toBeGreaterThan(0);
    expect(c1.smoke).toBeGreaterThan(40);
    await setNumber(g, 'intensity', 2);
    const rates = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & { fire: { sparks: number; settings: { intensity: number } } };
      return { intensity: w.fire.settings.intensity, sparks: w.world.components.Emitter!.rate![w.fire.sparks % 2 ** 25] };
    });
    expect(rates.intensity).toBe(2);
    expect(rates.sparks).toBe(28);
    const c3 = await at(240);
    expect(c3.all / c1.all).toBeGreaterThan(1.6);
    expect(c3.all / c1.all).toBeLessThan(2.4);
    expect(g.errors).toEqual([]);
  });
});

describe('lab-sparks', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab('lab-sparks', {}, ['Mouse', 'Space', 'W'], 'desktop');
  });
  afterAll(async () => {
    await g?.close();
  });

  it('sparks bounce off the floor and settle to a steady count; Space stops them', async () => {
    await pauseAndReset(g);
    const run = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & { particleCount(): number; sparks: { bounces: number; on: boolean } };
      w.advance(180);
      const c1 = w.particleCount(),
        b1 = w.sparks.bounces;
      w.advance(60);
      return { c1, c2: w.particleCount(), b1, b2: w.sparks.bounces };
    });
    // 400 sparks/s living 0.6 to 1.4 s: 400 on average.
    expect(run.c1).toBeGreaterThan(330);
    expect(run.c1).toBeLessThan(470);
    expect(Math.abs(run.c2 - run.c1) / run.c1).toBeLessThan(0.15);
    expect(run.b1).toBeGreaterThan(0);
    expect(run.b2).toBeGreaterThan(run.b1);
    await g.press('Space');
    const off = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & { particleCount(): number; sparks: { on: boolean; emitter: number } };
      w.advance(90);
      return { on: w.sparks.on, enabled: w.world.components.Emitter!.enabled![w.sparks.emitter % 2 ** 25], count: w.particleCount() };
    });
    expect(off.on).toBe(false);
    expect(off.enabled).toBe(0);
    expect(off.count).toBe(0);
    await g.press('Space');
  });

  it('the mouse moves the tool and new sparks start there; the panel turns the cone', async () => {
    // (Clear of the panel in the top right corner, which would take the pointer events.)
    const target = await pageXY(g, 2, 1.5);
    await g.page.mouse.move(target.x, target.y);
    const moved = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & { sparks: { at: [number, number]; emitter: number } };
      const P = w.world.components.Position!;
      return { at: w.sparks.at.slice(), ex: P.x![w.sparks.emitter % 2 ** 25]!, ey: P.y![w.sparks.emitter % 2 ** 25]! };
    });
    expect(moved.at[0]).toBeCloseTo(2, 1);
    expect(moved.at[1]).toBeCloseTo(1.5, 1);
    expect(moved.ex).toBe(moved.at[0]);
    expect(moved.ey).toBe(moved.at[1]);
    await setNumber(g, 'direction (°)', 90);
    const dir = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & { sparks: { emitter: number } };
      const E = w.world.components.Emitter!;
      return { x: E.dirX![w.sparks.emitter % 2 ** 25]!, y: E.dirY![w.sparks.emitter % 2 ** 25]! };
    });
    expect(dir.x).toBeCloseTo(0, 9);
    expect(dir.y).toBeCloseTo(1, 9);
    expect(g.errors).toEqual([]);
  });
});

describe('lab-attractors', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab('lab-attractors', { count: 500 }, ['Click', 'Drag', 'Right-click', 'V', 'T']);
  });
  afterAll(async () => {
    await g?.close();
  });

  const ids = () => g.page.evaluate(() => (window.game as unknown as Lab & { attractorIds(): number[] }).attractorIds());

  it('click adds an attractor, shift-click and right-click remove one, drag moves one', async () => {
    await pauseAndReset(g);
    const start = await ids();
    expect(start.length).toBe(3);
    const spot = await pageXY(g, -1.5, -1);
    await g.page.mouse.click(spot.x, spot.y);
    const added = await ids();
    expect(added.length).toBe(4);
    const pos = await g.page.evaluate((e) => {
      const P = (window.game as unknown as Lab).world.components.Position!;
      return { x: P.x![e % 2 ** 25]!, y: P.y![e % 2 ** 25]! };
    }, added[3]!);
    expect(pos.x).toBeCloseTo(-1.5, 1);
    expect(pos.y).toBeCloseTo(-1, 1);
    await g.page.keyboard.down('Shift');
    await g.page.mouse.click(spot.x, spot.y);
    await g.page.keyboard.up('Shift');
    expect((await ids()).length).toBe(3);
    const first = await pageXY(g, -5, 0.5);
    await g.page.mouse.click(first.x, first.y, { button: 'right' });
    const left = await ids();
    expect(left.length).toBe(2);
    const from = await pageXY(g, 1.5, 2.5),
      to = await pageXY(g, -6, 3);
    const m = g.page.mouse;
    await m.move(from.x, from.y);
    await m.down();
    await m.move(to.x, to.y, { steps: 6 });
    await m.up();
    const dragged = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & { attractorIds(): number[] };
      const P = w.world.components.Position!;
      return w.attractorIds().map((e) => [P.x![e % 2 ** 25]!, P.y![e % 2 ** 25]!]);
    });
    expect(dragged.length).toBe(2);
    expect(dragged.some(([x, y]) => Math.abs(x! + 6) < 0.1 && Math.abs(y! - 3) < 0.1)).toBe(true);
  });

  it("the panel sets the attractors' mass and softening, V turns the vortex on, and the particles respond", async () => {
    await setNumber(g, 'attractor G M (m³/s²)', 100);
    await setNumber(g, 'softening (m)', 1);
    await g.press('v');
    const state = await g.page.evaluate(() => {
      const w = window.game as unknown as Lab & {
        attractorIds(): number[];
        field: { particles: Uint32Array };
        params: { vortex: boolean; vortexStrength: number };
      };
      const A = w.world.components.Attractor!,
        Vx = w.world.components.Vortex!;
      const p = w.field.particles[0]!;
      const P = w.world.components.Position!,
        V = w.world.components.Velocity!;
      // Mean angular momentum about the vortex centre per kg, m^2/s: the swirl's torque k_v r drives it up.
      const spin = (): number => {
        let L = 0;
        for (const e of w.field.particles) L += P.x![e % 2 ** 25]! * V.y![e % 2 ** 25]! - P.y![e % 2 ** 25]! * V.x![e % 2 ** 25]!;
        return L / w.field.particles.length;
      };
      const L0 = spin();
      w.advance(120);
      return {
        masses: w.attractorIds().map((e) => A.mass![e % 2 ** 25]),
        soft: w.attractorIds().map((e) => A.softening![e % 2 ** 25]),
        vortex: w.params.vortex,
        k: Vx.k![p % 2 ** 25],
        strength: w.params.vortexStrength,
        L0,
        L1: spin(),
      };
    });
    expect(state.masses.every((m) => m === 100)).toBe(true);
    expect(state.soft.every((s) => s === 1)).toBe(true);
    expect(state.vortex).toBe(true);
    expect(state.k).toBe(state.strength);
    expect(state.strength).toBeGreaterThan(0);
    expect(state.L1 - state.L0).toBeGreaterThan(5);
    expect(g.errors).toEqual([]);
  });
});
