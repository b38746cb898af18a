/**
 * Catapult in headless Chromium: the page draws and lists its controls; a mouse drag back from the
 * cup and release throws a projectile that flies; a throw at the castle raises the score; a throw
 * that overshoots or falls short says by how much, with an arrow to where it went; P pauses. On a
 * phone, upright and sideways, the views and the card saying how to play fit, and touch throws.
 */
import type { Locator } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { FIRST_PREVIEW_SHARE, LEVEL_COUNT, levelName } from '../../games/catapult/scene';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';
import { checkPageContract } from './page-contract';
import { touchPath } from './touch';

interface Cam {
  toScreenX(x: number): number;
  toScreenY(y: number): number;
}
interface CatapultGame {
  paused: boolean;
  reset(): void;
  advance(n: number): void;
  shots(): number[];
  shotsLeft(): number;
  fire(dx: number, dy: number): number;
  tally(): { fallen: number; broken: number; score: number };
  level(): { castleMinX: number; castleMaxX: number; castleTop: number };
  params: { level: number };
  campaign: { scores: number[]; stars: number[] };
  levelEnded(): boolean;
  lastVerdict(): string;
  panel: { gui: { controllersRecursive(): { property: string; $input?: HTMLInputElement }[] } };
  renderer: { camera: Cam };
  world: { steps: number; components: { Position: { x: Float64Array; y: Float64Array } } };
}

let h: Harness;
let g: GamePage;
beforeAll(async () => {
  h = await Harness.start();
  g = await h.openGame('catapult', { query: { level: 1 } });
}, START_TIMEOUT_MS);
afterAll(async () => {
  await h?.close();
});

/**
 * Waits until the miss's hint shows (1 s of frames after the throw's verdict, the hint risen) and
 * checks its box lies clear of the castle (its front to its far end, the ground to its top), the
 * rock behind it and the catapult with its stones (x -3.0 to 1.1 m, y 0 to 2 m), on screen. Returns
 * the hint's words.
 */
/**
 * How a test runs a throw to its verdict: at once, three steps a frame drawn (the verdict is decided
 * in a frame, ./main.ts), not at the software renderer's pace.
 */
const VERDICT_RUN = { seconds: 1 / 20 };

async function expectHintOffScene(p: GamePage, tag: string): Promise<string> {
  // The flight run at once (VERDICT_RUN), then a second of frames to frame and label it.
  await p.runUntil(() => (window.game as unknown as CatapultGame).lastVerdict() !== '', null, VERDICT_RUN);
  await p.runFrames(60);
  const r = await p.page.evaluate(() => {
    const w = window.game as unknown as CatapultGame & {
      verdictShown(): string;
      wordBoxes(): { verdict: number[] | null };
    };
    const cam = w.renderer.camera,
      lv = w.level();
    const box = (x0: number, y0: number, x1: number, y1: number) => [
      cam.toScreenX(x0),
      cam.toScreenY(y1),
      cam.toScreenX(x1),
      cam.toScreenY(y0),
    ];
    return {
      shown: w.verdictShown(),
      verdict: w.wordBoxes().verdict,
      castle: box(lv.castleMinX, 0, lv.castleMaxX, lv.castleTop),
      // The rock: 1.9 m past the castle's far end, 1 m wide, 2.8 m tall (games/catapult/scene.ts ROCK).
      rock: box(lv.castleMaxX + 1.9, 0, lv.castleMaxX + 2.9, 2.8),
      catapult: box(-3.0, 0, 1.1, 2),
    };
  });
  expect(r.shown, tag).not.toBe('');
  const [a0, a1, a2, a3] = r.verdict! as [number, number, number, number];
  for (const name of ['castle', 'rock', 'catapult'] as const) {
    const [b0, b1, b2, b3] = r[name] as [number, number, number, number];
    expect(a2 <= b0 || b2 <= a0 || a3 <= b1 || b3 <= a1, `${tag}: "${r.shown}" over the ${name}: ${JSON.stringify(r)}`).toBe(true);
  }
  return r.shown;
}

const screen = (x: number, y: number) =>
  g.page.evaluate(
    ([x, y]) => {
      const cam = (window.game as unknown as CatapultGame).renderer.camera;
      const box = document.querySelector('canvas')!.getBoundingClientRect();
      return { x: box.left + cam.toScreenX(x), y: box.top + cam.toScreenY(y) };
    },
    [x, y] as const,
  );

/** What the phone page's checks below read of `window.game`. */
type PhoneGame = {
  cameraSettled(): boolean;
  bannerSize(): { width: number; height: number; fontSize: number };
  level(): { castleMinX: number; castleMaxX: number; castleTop: number };
  positionOf(b: number): [number, number];
  fire(dx: number, dy: number): number;
  shots(): number[];
  renderer: { camera: { toScreenX(x: number): number; toScreenY(y: number): number; width: number; height: number } };
};

/**
 * Puts the page's game on `level` afresh (its reset), first setting `paused` if given and, with
 * `clearCampaign`, the campaign's scores and stars back to 0.
 */
async function startLevel(p: GamePage, level: number, o: { paused?: boolean; clearCampaign?: boolean } = {}): Promise<void> {
  await p.page.evaluate(
    ([lv, paused, clear]) => {
      const w = window.game as unknown as CatapultGame;
      if (clear) {
        w.campaign.scores.fill(0);
        w.campaign.stars.fill(0);
      }
      if (paused !== null) w.paused = paused;
      w.params.level = lv;
      w.reset();
    },
    [level, o.paused ?? null, o.clearCampaign ?? false] as const,
  );
}

/**
 * On a phone (390 x 844, touch) page of level 1 before its first touch: upright, the level opens
 * close on the catapult (a large stone), the castle off the screen with an arrow at the edge saying
 * how far it is and its inset in the earth under the ground (no look button); the banner fits and a
 * card says how to play; on every level the same;
 * sideways (844 x 390) the whole field is in view and the card lies clear of the castle; back
 * upright. Returns the card and the canvas' box seen sideways.
 */
async function phoneBeforeTouch(p: GamePage): Promise<{ hint: Locator; box: DOMRect }> {
  // The catapult with its mound and the stones stacked behind it spans x = -3.0 to 1.1 m, y = 0 to 2 m
  // (see drawCatapult, drawMound and drawAmmo in games/catapult); the castle from its front to its far
  // end and its top. `shot` is the view the camera heads for (games/catapult/camera.ts).
  const framing = () =>
    p.page.evaluate(() => {
      const w = window.game as unknown as PhoneGame & { cameraShot(): string };
      const cam = w.renderer.camera,
        lv = w.level();
      const [left, right, top, bottom] = [cam.toScreenX(-3.0), cam.toScreenX(1.1), cam.toScreenY(2), cam.toScreenY(0)];
      const castle = [cam.toScreenX(lv.castleMinX), cam.toScreenX(lv.castleMaxX), cam.toScreenY(lv.castleTop)];
      const canvasTop = document.querySelector('canvas')!.getBoundingClientRect().top;
      // (The card goes 9 s after the page loads or at the first press: NaN once gone.)
      const card = document.querySelector('[data-hud="touch-hint"]');
      const hintTop = card ? card.getBoundingClientRect().top - canvasTop : Number.NaN;
      const perM = cam.toScreenX(1) - cam.toScreenX(0);
      const g = window.game as unknown as {
        closeUp(): { box: number[] } | null;
        castleMarker(): { text: string; box: number[] } | null;
        params: { level: number };
      };
      return {
        level: g.params.level,
        shot: w.cameraShot(),
        left,
        right,
        top,
        bottom,
        castle,
        perM,
        W: cam.width,
        H: cam.height,
        banner: w.bannerSize(),
        hintTop,
        inset: g.closeUp()?.box ?? null,
        marker: g.castleMarker(),
      };
    });
  type Framing = Awaited<ReturnType<typeof framing>>;
  // The aim view close on the catapult (issue 34: the whole field fitted to 390 px drew it 12 to 21 px
  // a metre, a stone 8 to 12 px, a thin band under a tall empty sky): the catapult whole on the
  // canvas (x -3.0 to 1.1 m, y 0 to 2 m) and a 0.6 m stone 20 px across or more (camera.ts
  // AIM_PX_PER_M: 21.6 px at least); the castle wholly off the screen to the right. With `settled`
  // (the camera at rest) the castle shows: its inset on the canvas under the ground, and its arrow at
  // the right edge with a label saying how far it is, on the canvas.
  const expectAimLayout = (f: Framing, settled: boolean) => {
    const at = JSON.stringify(f);
    expect([f.left >= 0, f.right <= f.W, f.top >= 0, f.bottom <= f.H], at).toEqual([true, true, true, true]);
    expect(0.6 * f.perM, at).toBeGreaterThanOrEqual(20);
    expect(f.castle[0], at).toBeGreaterThan(f.W);
    if (!settled) return;
    const [ix, iy, iw, ih] = f.inset ?? [Number.NaN, 0, 0, 0];
    expect([ix >= 0, iy > f.bottom, ix + iw <= f.W, iy + ih <= f.H], at).toEqual([true, true, true, true]);
    expect(f.marker?.text, at).toMatch(/^castle \d+ m$/);
    const [mx0, my0, mx1, my1] = f.marker!.box as [number, number, number, number];
    expect([mx0 >= 0, my0 >= 0, mx1 <= f.W, my1 <= f.bottom], at).toEqual([true, true, true, true]);
  };
  // The level played again from its start opens on where the player shoots from and what at: the
  // catapult whole and the castle's inset in the first frame drawn after the start (an opening held
  // on the castle alone showed a stranger a target with no catapult until they dragged; a level new
  // to the page shows its castle and pans to the catapult, catapult-phone.test.ts).
  await p.page.evaluate(async () => {
    (window.game as unknown as CatapultGame).reset();
    await new Promise(requestAnimationFrame);
    await new Promise(requestAnimationFrame);
  });
  const first = await framing();
  expect(first.shot).toBe('aim');
  expectAimLayout(first, false);
  await p.waitFor(() => {
    const w = window.game as unknown as { cameraShot(): string; cameraSettled(): boolean };
    return w.cameraShot() === 'aim' && w.cameraSettled();
  }, null);
  const opening = await framing();
  expectAimLayout(opening, true);
  // The ground is above the card saying how to play (the card lies on the earth, not over the
  // catapult), and the scene uses the screen's middle: the ground within 5 % of the screen's height
  // of half-way down (at 89 % the scene sat in the bottom fifth under 70 % of empty sky, at 62 % under
  // 489 px of mostly empty sky; camera.ts UPRIGHT_GROUND_CLOSE).
  expect(opening.bottom).toBeLessThan(opening.hintTop);
  expect(opening.bottom / opening.H).toBeGreaterThan(0.45);
  expect(opening.bottom / opening.H).toBeLessThan(0.55);
  // The level and the star rule: two lines of text, narrower than the canvas (a line is about 1.3 x
  // the type size and the outline adds 4 px: two lines 2.9 x, three 4.2 x; bound 3.5 x). (Four lines
  // with what "down" means were too many for a stranger; the card saying how to play tells it.)
  expect(opening.banner.height).toBeLessThan(3.5 * opening.banner.fontSize);
  expect(await p.page.locator('[data-hud="touch-hint"]').textContent()).toContain('leaning 30°');
  expect(opening.banner.width).toBeLessThanOrEqual(opening.W);
  await expectSunClear(p);
  // The castle's inset lies between the ground and the card saying how to play (while it shows).
  if (!Number.isNaN(opening.hintTop))
    expect(opening.inset![1]! + opening.inset![3]!, JSON.stringify(opening)).toBeLessThanOrEqual(opening.hintTop);
  // Until the first throw a line in the sky says how to throw (the card goes at the first touch and
  // the legend is behind the menu button): one line (under 2 x its type size tall), on the canvas,
  // under the banner and wholly over the castle's top and the catapult's (2 m) in the aim view.
  const howTo = await p.page.evaluate(() => {
    const el = document.querySelector<HTMLElement>('[data-hud="how-to"]')!;
    const r = el.getBoundingClientRect(),
      c = document.querySelector('canvas')!.getBoundingClientRect();
    return {
      text: el.textContent,
      left: r.left - c.left,
      right: r.right - c.left,
      top: r.top - c.top,
      bottom: r.bottom - c.top,
      height: r.height,
      font: Number.parseFloat(getComputedStyle(el).fontSize),
      opacity: getComputedStyle(el).opacity,
      bannerBottom: (window.game as unknown as { bannerPanel(): { panel: number[] } | null }).bannerPanel()!.panel[3]!,
    };
  });
  expect(howTo.text).toBe('Drag back anywhere, let go to throw');
  expect(howTo.opacity).toBe('1');
  expect(howTo.height, JSON.stringify(howTo)).toBeLessThan(2 * howTo.font + 14);
  expect([howTo.left >= 0, howTo.right <= opening.W], JSON.stringify(howTo)).toEqual([true, true]);
  expect(howTo.top, JSON.stringify(howTo)).toBeGreaterThan(howTo.bannerBottom);
  expect(howTo.bottom, JSON.stringify(howTo)).toBeLessThan(Math.min(opening.castle[2]!, opening.top));
  // The legend is behind the menu button on a phone: a card over the scene says how to play until
  // the first touch.
  const hint = p.page.locator('[data-hud="touch-hint"]');
  expect(await hint.textContent()).toMatch(/^Drag\s*pull back/);
  // Sideways (844 x 390): the whole field in view, and the card lies on the earth under the ground
  // line, not over the castle's foot (the field fitted to the castle's height put it there).
  await p.page.setViewportSize({ width: 844, height: 390 });
  await p.waitFor(() => {
    const w = window.game as unknown as PhoneGame;
    return w.renderer.camera.width > 600 && w.cameraSettled();
  }, null);
  const box = await p.page.evaluate(() => document.querySelector('canvas')!.getBoundingClientRect().toJSON() as DOMRect);
  const castle = await p.page.evaluate(() => (window.game as unknown as PhoneGame).level());
  const foot = await p.worldToPage(castle.castleMinX, 0);
  for (const at of [await p.worldToPage(-3, 0), foot, await p.worldToPage(castle.castleMaxX, castle.castleTop)]) {
    expect(at.x).toBeGreaterThan(box.left);
    expect(at.x).toBeLessThan(box.right);
    expect(at.y).toBeLessThan(box.bottom);
  }
  expect((await hint.boundingBox())!.y).toBeGreaterThanOrEqual(foot.y);
  await p.page.setViewportSize({ width: 390, height: 844 });
  await p.waitFor(() => {
    const w = window.game as unknown as PhoneGame;
    return w.renderer.camera.width < 600 && w.cameraSettled();
  }, null);
  // Back upright the camera frames the catapult and the whole castle again (a view of the catapult
  // large cut a stranger's target off at the edge while aiming).
  await p.page.evaluate(() => (window.game as unknown as { jumpCamera(): void }).jumpCamera());
  await p.waitFor(() => {
    const w = window.game as unknown as { cameraShot(): string; cameraSettled(): boolean };
    return w.cameraShot() === 'aim' && w.cameraSettled();
  }, null);
  const aim = await framing();
  expectAimLayout(aim, true);
  expect(aim.perM).toBeCloseTo(opening.perM, 1);
  // Every level opens the same way (levels 3 and 9, the farthest castle and the widest, drew a stone
  // 8 px across in the whole field's view).
  for (let level = 2; level <= 9; level++) {
    await startLevel(p, level);
    // (Each opening's look at the castle, 40 frames, is catapult-phone.test.ts's; here the aim view.)
    await p.page.evaluate(() => {
      const w = window.game as unknown as { jumpCamera(): void; endOpening(): void };
      w.endOpening();
      w.jumpCamera();
    });
    await p.waitFor(() => {
      const w = window.game as unknown as { cameraShot(): string; cameraSettled(): boolean; closeUp(): unknown };
      return w.cameraShot() === 'aim' && w.cameraSettled() && w.closeUp() !== null;
    }, null);
    const f = await framing();
    expect(f.level).toBe(level);
    expectAimLayout(f, true);
  }
  await startLevel(p, 1);
  // The castle shows close in the earth on every level here, so no look button repeats it (an
  // upright tablet, where the field draws the castle large enough, has one: see its own test).
  expect(await p.page.locator('[data-hud="look"]').count()).toBe(0);
  return { hint, box };
}

/** The sun's disc wholly under the banner's panel (a phone's banner of four to six lines covered it). */
async function expectSunClear(p: GamePage): Promise<void> {
  const { sun, panel } = await p.page.evaluate(() => {
    const w = window.game as unknown as { sunAt(): number[]; bannerPanel(): { panel: number[] } | null };
    return { sun: w.sunAt(), panel: w.bannerPanel()!.panel };
  });
  expect(sun[1]! - sun[2]!, JSON.stringify({ sun, panel })).toBeGreaterThan(panel[3]!);
}

/**
 * On the phone page after `phoneBeforeTouch` (the level played again from its start): the camera
 * follows a stone to a large tower, a drag from anywhere throws, and the next-level (or try-again)
 * button goes on when the level is over.
 */
async function phoneThrows(p: GamePage, hint: Locator, box: DOMRect): Promise<void> {
  // A throw at the castle's front at 14 m/s, the low angle (sin 2 theta = g R / v^2). Each frame
  // while it flies the stone is inside the canvas's width (the camera follows it), and when it gets
  // there the tower is over 210 px tall on the screen (the shot view fitted to the castle, the rock
  // and 2.5 m either side drew it 179 px tall).
  const flight = await p.page.evaluate(async () => {
    const w = window.game as unknown as PhoneGame;
    const cam = w.renderer.camera;
    const lv = w.level();
    const R = lv.castleMinX + 0.5,
      v = 14,
      th = 0.5 * Math.asin((9.81 * R) / (v * v)),
      d = v / 7;
    const ball = w.fire(-d * Math.cos(th), -d * Math.sin(th));
    let outside = 0,
      frames = 0;
    const t0 = performance.now();
    while (performance.now() - t0 < 5000) {
      await new Promise(requestAnimationFrame);
      const x = w.positionOf(ball)[0];
      if (x > lv.castleMinX - 0.3) break;
      frames++;
      const sx = cam.toScreenX(x);
      if (sx < 0 || sx > cam.width) outside++;
    }
    return { frames, outside };
  });
  expect(flight.frames).toBeGreaterThan(3);
  expect(flight.outside).toBe(0);
  // Once the camera is at rest on the shot view, the rock past the castle and room past it are in view too.
  const tower = await p.waitFor(() => {
    const w = window.game as unknown as PhoneGame & { shotView(): boolean; closeUp(): unknown };
    if (!w.shotView() || !w.cameraSettled()) return null;
    const cam = w.renderer.camera,
      lv = w.level();
    return {
      closeUp: w.closeUp(),
      height: cam.toScreenY(0) - cam.toScreenY(lv.castleTop),
      perMetre: cam.toScreenY(0) - cam.toScreenY(1),
      rock: cam.toScreenX(lv.castleMaxX + 2.9),
      width: cam.width,
    };
  }, null);
  // The shot view's zoom: over 30 px a metre (level 1's old 6 m watchtower drew 210 px tall; its
  // low tower of 2 m drew 70 px at 34 px a metre, and its castle, the hut now 5.5 m behind the
  // tower, not 3.3, is 2.2 m wider: 31 px a metre with 0.8 m before it and 1 m past the rock).
  expect(tower.perMetre).toBeGreaterThan(30);
  // (The close-up is hidden there: the view is as close.)
  expect(tower.closeUp).toBeNull();
  expect(tower.height).toBeGreaterThan(2 * 30);
  expect(tower.rock).toBeLessThan(tower.width - 30);
  // A touch drag starting mid-screen, far from the cup (at the left edge there is no room to pull back), throws.
  // Level 1's low tower falls to the shot above, which ends the level: the drag plays it again.
  const thrown = await p.page.evaluate(() => {
    const game = window.game as unknown as { shots(): number[]; reset(): void };
    game.reset();
    return game.shots().length;
  });
  const start = { x: box.left + 390 / 2, y: box.top + (844 - box.top) / 2 };
  await touchPath(
    p.page,
    [
      [start.x, start.y],
      [start.x - 40, start.y + 20],
      [start.x - 80, start.y + 40],
    ],
    50,
  );
  await p.waitFor((n) => (window.game as unknown as { shots(): number[] }).shots().length === n + 1, thrown);
  await hint.waitFor({ state: 'detached', timeout: 3000 });
  // After the throw the camera follows it (the shot view).
  await p.waitFor(() => (window.game as unknown as { shotView(): boolean }).shotView(), null);
  // Spend the remaining shots and let 4 s pass: the level is over.
  await p.page.evaluate(() => {
    const game = window.game as unknown as { shotsLeft(): number; fire(dx: number, dy: number): number; advance(n: number): void };
    while (game.shotsLeft() > 0) game.fire(-2, -1);
    game.advance(260);
  });
  // The button reads 'Level 2 ▶' when the shots brought down half the castle and 'Try again ↺' when
  // not: the first shot is a real touch drag, whose throw depends on the frame timing.
  const next = p.page.getByRole('button', { name: /^(Level 2 ▶|Try again ↺)$/ });
  await next.waitFor({ state: 'visible', timeout: 5000 });
  const cleared = (await next.textContent())?.startsWith('Level 2') === true;
  // With the button, the banner gives the level's result (no shots left to count).
  const said = await p.page.evaluate(() => (window.game as unknown as { bannerText(): string }).bannerText());
  expect(said).toMatch(cleared ? /^Level 1 cleared/ : /^Level 1 not cleared/);
  expect(said).not.toMatch(/shots? left/);
  await next.tap();
  if (cleared) await p.waitFor(() => (window.game as unknown as { params: { level: number } }).params.level === 2, null);
  else await p.waitFor(() => (window.game as unknown as { shotsLeft(): number }).shotsLeft() === 3, null);
}

/**
 * With the frame pacer drawing nothing (a GPU too busy to finish a frame), a drag on `p` that throws
 * at `power` (0 to 1) and `deg` degrees above level: the arc preview's dots (in the page) follow every
 * move at once, its last dot sits at the end the game reports; released, the stone first touches
 * something within 0.3 m of that end (issue 34: a stranger's preview ended at the first tower, and
 * the stone flew to the far one). `touch` drags with a finger (CDP touch events), else the mouse.
 * @returns the preview's end and how many of its dots showed in the phone's close-up.
 */
async function previewMatchesThrow(
  p: GamePage,
  power: number,
  deg: number,
  touch: boolean,
): Promise<{ end: [number, number]; closeDots: number; past: number }> {
  type W = CatapultGame & {
    pacer: { mayDraw(): boolean };
    fullPullPx(): number;
    cameraSettled(): boolean;
    firstTouch(): [number, number, number, number] | null;
    aimShown(): { power: number; angle: number; dots: number; closeDots: number; reach: number; end: [number, number] };
  };
  // (On a phone, the camera at rest on the aim view: it does not move under the finger.)
  await p.page.evaluate(() => (window.game as unknown as { jumpCamera(): void }).jumpCamera());
  await p.waitFor(() => {
    const w = window.game as unknown as W & { cameraShot(): string };
    return w.cameraSettled() && !w.levelEnded() && w.shotsLeft() > 0 && (w.cameraShot() === 'aim' || innerWidth >= 600);
  }, null);
  const box = (await p.page.locator('canvas').boundingBox())!;
  const full = await p.page.evaluate(() => (window.game as unknown as W).fullPullPx());
  await p.page.evaluate(() => {
    const w = window.game as unknown as W;
    (window as unknown as { keptMayDraw: () => boolean }).keptMayDraw = w.pacer.mayDraw;
    w.pacer.mayDraw = () => false;
  });
  const from = { x: box.x + box.width * 0.7, y: box.y + box.height * 0.45 };
  const a = (deg * Math.PI) / 180;
  const cdp = touch ? await p.page.context().newCDPSession(p.page) : null;
  const point = (x: number, y: number) => [{ x, y, id: 1 }];
  if (cdp) await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: point(from.x, from.y) });
  else {
    await p.page.mouse.move(from.x, from.y);
    await p.page.mouse.down();
  }
  let shown = { power: 0, angle: 0, dots: 0, closeDots: 0, reach: 0, end: [0, 0] as [number, number] };
  let past = 0;
  // Two pulls, the second the throw: the arc's end moves with the pull, no frame drawn.
  for (const k of [0.6, 1]) {
    const len = k * power * full;
    const to = { x: from.x - len * Math.cos(a), y: from.y + len * Math.sin(a) };
    if (cdp) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: point(to.x, to.y) });
    else await p.page.mouse.move(to.x, to.y);
    const before = shown.end[0];
    // The aim and the arc's dots on the page read together (the camera may ease between two reads).
    const seen = await p.waitFor(
      ([want, before]) => {
        const s = (window.game as unknown as W).aimShown();
        if (Math.abs(s.power - want) >= 0.01 || s.end[0] === before) return null;
        const cam = (window.game as unknown as W).renderer.camera;
        const dots = [...document.querySelectorAll('[data-hud="aim-arc"] circle')].filter((c) => c.getAttribute('display') !== 'none');
        const last = dots[dots.length - 1];
        const past = [...document.querySelectorAll('[data-hud="aim-arc-past"] circle')].filter((c) => c.getAttribute('display') !== 'none');
        const dot = {
          past: past.length,
          count: dots.length,
          dx: Number(last?.getAttribute('cx')) - cam.toScreenX(s.end[0]),
          dy: Number(last?.getAttribute('cy')) - cam.toScreenY(s.end[1]),
        };
        return { s, dot };
      },
      [k * power, before] as const,
    );
    shown = seen.s;
    // The arc's last dot on the page is the end the game reports (canvas px, to a pixel).
    const dot = seen.dot;
    expect(dot.count).toBe(shown.dots);
    expect(dot.count).toBeGreaterThan(4);
    expect(Math.hypot(dot.dx, dot.dy)).toBeLessThan(1);
    past = dot.past;
  }
  if (cdp) {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await cdp.detach();
  } else await p.page.mouse.up();
  await p.page.evaluate(() => {
    (window.game as unknown as W).pacer.mayDraw = (window as unknown as { keptMayDraw: () => boolean }).keptMayDraw;
  });
  // The flight to its first touch stepped in the page, not waited for in real time.
  const seg = await p.runUntil(() => (window.game as unknown as W).firstTouch(), null, { draw: false });
  await p.frames(2);
  // The preview's end against the segment of the step in which the stone first touched anything.
  const [x0, y0, x1, y1] = seg;
  const [ex, ey] = shown.end;
  const u = Math.max(0, Math.min(1, ((ex - x0) * (x1 - x0) + (ey - y0) * (y1 - y0)) / Math.max(1e-12, (x1 - x0) ** 2 + (y1 - y0) ** 2)));
  expect(Math.hypot(x0 + u * (x1 - x0) - ex, y0 + u * (y1 - y0) - ey), JSON.stringify({ seg, end: shown.end })).toBeLessThanOrEqual(0.3);
  return { end: shown.end, closeDots: shown.closeDots, past };
}

describe('catapult', () => {
  it('draws, shows its controls and panel', async () => {
    expect(await g.canvasColors()).toBeGreaterThan(4);
    const legend = await g.page.locator('.bp-legend').textContent();
    for (const key of ['P', 'R', 'L', 'Drag']) expect(legend).toContain(key);
    expect(await g.page.locator('.lil-gui').count()).toBeGreaterThan(0);
    // The view was framed for one canvas size since load: the panel is in place before the first
    // frame (made after it, it narrowed the canvas from 1060 to 735 px and the scene jumped twice).
    const sizes = await g.page.evaluate(() => (window.game as unknown as { sizesFramed(): string[] }).sizesFramed());
    const canvas = await g.page.evaluate(() => document.querySelector('canvas')!.getBoundingClientRect().toJSON() as DOMRect);
    expect(sizes).toEqual([`${canvas.width}x${canvas.height}`]);
    // The panel sits in the left column under the controls, so the scene has the rest of the width
    // (800 - 220 px here; a right-hand panel column left it 255 px).
    expect(await g.page.locator('.bp-info .lil-gui.lil-root').count()).toBe(1);
    expect(canvas.width).toBe(800 - 220);
    // The weld slider's label leaves its slider room ("joint strength (N, rebuilds)" squeezed it).
    expect(await g.page.locator('.lil-gui').getByText('weld strength (N)', { exact: true }).count()).toBe(1);
    expect(g.errors).toEqual([]);
  });

  it('left alone before the first throw (a page in the background for minutes), no piece moves and nothing scores', async () => {
    const r = await g.page.evaluate(() => {
      const w = window.game as unknown as Omit<CatapultGame, 'level'> & {
        positionOf(h: number): [number, number];
        level(): { pieces: Array<{ body: number; startX: number; startY: number }> };
        total(): number;
      };
      w.paused = true;
      w.reset();
      // Two minutes of steps with no throw.
      w.advance(60 * 120);
      let moved = 0;
      for (const p of w.level().pieces) {
        const [x, y] = w.positionOf(p.body);
        moved = Math.max(moved, Math.hypot(x - p.startX, y - p.startY));
      }
      const out = { tally: w.tally(), moved, total: w.total(), shotsLeft: w.shotsLeft() };
      w.reset();
      w.paused = false;
      return out;
    });
    expect(r.tally).toEqual({ fallen: 0, broken: 0, score: 0 });
    expect(r.total).toBe(0);
    expect(r.moved).toBeLessThan(0.01);
    expect(r.shotsLeft).toBeGreaterThan(0);
  });

  it('left alone after a throw that came down short, no level scores by itself: two minutes on, no piece has moved', async () => {
    // Kept awake, levels 4, 5, 6, 8 and 9 scored 100 to 675 in two minutes with no throw (their
    // crown stones rolled off): the castle now sleeps about a second after its build and stays put.
    // Bound: 1 mm from where each piece stood at the throw (a sleeping piece does not move at all).
    const r = await g.page.evaluate(() => {
      const w = window.game as unknown as Omit<CatapultGame, 'level'> & {
        positionOf(h: number): [number, number];
        level(): { pieces: Array<{ body: number }> };
        total(): number;
      };
      w.paused = true;
      const out: Array<{ level: number; tally: { fallen: number; broken: number; score: number }; moved: number }> = [];
      for (const level of [1, 4, 5, 6, 8, 9]) {
        w.params.level = level;
        w.reset();
        w.advance(60);
        const at = w.level().pieces.map((p) => w.positionOf(p.body));
        // 7 m/s at 15 degrees: down 5.2 m out, short of every castle.
        const a = (15 * Math.PI) / 180;
        w.fire(-Math.cos(a), -Math.sin(a));
        w.advance(60 * 120);
        let moved = 0;
        w.level().pieces.forEach((p, k) => {
          const [x, y] = w.positionOf(p.body);
          moved = Math.max(moved, Math.hypot(x - at[k]![0], y - at[k]![1]));
        });
        out.push({ level, tally: w.tally(), moved });
      }
      w.params.level = 1;
      w.reset();
      w.paused = false;
      return out;
    });
    for (const l of r) {
      expect(l.tally, `level ${l.level}`).toEqual({ fallen: 0, broken: 0, score: 0 });
      expect(l.moved, `level ${l.level}`).toBeLessThan(1e-3);
    }
    expect(g.errors).toEqual([]);
  });

  it('with the frame pacer drawing nothing (a GPU too busy to finish a frame), a pause, a resume and a reset are each drawn at once', async () => {
    // game-kit's startPixiGame forces the first frame after a pause or resume and after a new world:
    // a paused scene does not change, so before, a pause on a busy GPU left the old picture (no
    // "Paused") until the pacer let a frame through, seconds later under software WebGL and load.
    type Paced = { pacer: { drawn: number; mayDraw(): boolean }; paused: boolean; reset(): void };
    const drawn = () => g.page.evaluate(() => (window.game as unknown as Paced).pacer.drawn);
    await g.page.evaluate(() => {
      const w = window.game as unknown as Paced;
      (window as unknown as { keptMayDraw: () => boolean }).keptMayDraw = w.pacer.mayDraw;
      w.pacer.mayDraw = () => false;
    });
    await g.frames(3);
    const start = await drawn();
    await g.frames(3);
    expect(await drawn()).toBe(start);
    await g.page.keyboard.press('p');
    await g.frames(3);
    expect(await g.page.evaluate(() => (window.game as unknown as Paced).paused)).toBe(true);
    expect(await drawn()).toBe(start + 1);
    await g.page.keyboard.press('p');
    await g.frames(3);
    expect(await drawn()).toBe(start + 2);
    await g.page.evaluate(() => (window.game as unknown as Paced).reset());
    await g.frames(3);
    expect(await drawn()).toBe(start + 3);
    // A throw while no frame is drawn: the readout does not run ahead of the canvas's banner (it
    // said 'score 50' beside the banner's 'Score 0'); once a frame is drawn it follows.
    const shotsRow = g.page.locator('[data-readout="1"]');
    expect(await shotsRow.textContent()).toBe('3');
    await g.page.evaluate(() => (window.game as unknown as CatapultGame).fire(-1, -1));
    await g.frames(3);
    expect(await drawn()).toBe(start + 3);
    expect(await shotsRow.textContent()).toBe('3');
    // The level's end while no frame is drawn: the next-level (or try-again) button does not go on
    // over a canvas still showing the level under way (a stranger saw "Level 2 ▶" under a banner
    // saying "1 shot left" for 5 s); once a frame is drawn, the button and the result go on together.
    await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame & { advance(n: number): void; paused: boolean };
      while (w.shotsLeft() > 0) w.fire(-1, -1);
      // (Steps pause; running again before the next frame, no pause or resume forces a frame.)
      w.advance(300);
      w.paused = false;
    });
    await g.frames(3);
    expect(await drawn()).toBe(start + 3);
    expect(await g.page.evaluate(() => (window.game as unknown as CatapultGame).levelEnded())).toBe(true);
    const next = g.page.getByRole('button', { name: /^(Level 2 ▶|Try again ↺)$/ });
    expect(await next.count()).toBe(0);
    await g.page.evaluate(() => {
      const w = window.game as unknown as Paced;
      w.pacer.mayDraw = (window as unknown as { keptMayDraw: () => boolean }).keptMayDraw;
      w.paused = false;
    });
    await g.waitFor(() => document.querySelector('[data-readout="1"]')?.textContent === '0', null);
    await next.waitFor({ state: 'visible' });
    const banner = await g.page.evaluate(() => (window.game as unknown as { bannerText(): string }).bannerText());
    expect(banner).toMatch(/^Level 1 (not )?cleared/);
    expect(banner).not.toMatch(/shots? left/);
    expect(g.errors).toEqual([]);
  });

  it('with the frame pacer drawing nothing, the aim (numbers, power bar, band) follows every move of the mouse at once', async () => {
    // Issue 34: the aim's numbers were drawn on the canvas, and the kit's frame pacer draws no frame
    // while the GPU has two unfinished (software WebGL, for a whole quick drag): a stranger read
    // "6 %" at the release of a 59 % throw. They are in the page now, set on every pointer move.
    type W = CatapultGame & { pacer: { mayDraw(): boolean }; fullPullPx(): number; cameraSettled(): boolean; aimLabel(): string };
    await startLevel(g, 1);
    await g.waitFor(() => {
      const w = window.game as unknown as W;
      return w.cameraSettled() && w.shotsLeft() === 3 && !w.levelEnded();
    }, null);
    const box = (await g.page.locator('canvas').boundingBox())!;
    const full = await g.page.evaluate(() => (window.game as unknown as W).fullPullPx());
    await g.page.evaluate(() => {
      const w = window.game as unknown as W;
      (window as unknown as { keptMayDraw: () => boolean }).keptMayDraw = w.pacer.mayDraw;
      w.pacer.mayDraw = () => false;
    });
    const from = { x: box.x + box.width * 0.6, y: box.y + box.height * 0.3 };
    await g.page.mouse.move(from.x, from.y);
    await g.page.mouse.down();
    // Down and to the left at 30 degrees: a throw up and to the right at 30 degrees.
    for (const len of [0.15 * full, 0.4 * full, 0.7 * full, 0.25 * full]) {
      const to = { x: from.x - len * Math.cos(Math.PI / 6), y: from.y + len * Math.sin(Math.PI / 6) };
      await g.page.mouse.move(to.x, to.y);
      const want = Math.round((100 * len) / full);
      const shown = await g.waitFor((want) => {
        const text = document.querySelector('[data-hud="aim"]')?.textContent ?? '';
        const m = /(\d+) %\s+(\d+)°$/.exec(text);
        const band = document.querySelector('[data-hud="aim-band"] line:last-of-type');
        return m && Math.abs(Number(m[1]) - want) <= 1
          ? { power: Number(m[1]), angle: Number(m[2]), x2: Number(band?.getAttribute('x2')), y2: Number(band?.getAttribute('y2')) }
          : null;
      }, want);
      expect(Math.abs(shown.angle - 30)).toBeLessThanOrEqual(1);
      // The band ends at the mouse (canvas px), to a pixel.
      expect(Math.abs(shown.x2 - (to.x - box.x))).toBeLessThan(1.5);
      expect(Math.abs(shown.y2 - (to.y - box.y))).toBeLessThan(1.5);
      expect(await g.page.evaluate(() => (window.game as unknown as W).aimLabel())).toMatch(new RegExp(`${shown.power} %`));
    }
    await g.page.mouse.up();
    await g.waitFor(() => (window.game as unknown as W).shots().length === 1, null);
    // The release takes the aim away at once, drawn frame or not.
    expect(await g.page.locator('[data-hud="aim"]').isVisible()).toBe(false);
    expect(await g.page.locator('[data-hud="aim-band"]').isVisible()).toBe(false);
    expect(await g.page.evaluate(() => (window.game as unknown as W).aimLabel())).toBe('');
    await g.page.evaluate(() => {
      (window.game as unknown as W).pacer.mayDraw = (window as unknown as { keptMayDraw: () => boolean }).keptMayDraw;
    });
    expect(g.errors).toEqual([]);
  });

  it('a drag back from the cup and release throws a projectile that flies', async () => {
    // A fresh level (a retry of this test starts from the same state), aimed at once the camera is at rest.
    await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame;
      w.paused = false;
      w.reset();
    });
    await g.waitFor(() => (window.game as unknown as { cameraSettled(): boolean }).cameraSettled(), null);
    // The game measures a pull in screen pixels (aimPxPerM a metre), not in the scene's metres, so a
    // throw takes the same hand movement at any zoom: a pull of (-1.2, -1.6) m, 2 m long, is a drag
    // of 2 aimPxPerM px down and to the left of where it starts (the cup).
    const from = await screen(0, 1.5);
    const perM = await g.page.evaluate(() => (window.game as unknown as { aimPxPerM(): number }).aimPxPerM());
    const pull = [-1.2, -1.6] as const;
    const to = { x: from.x + pull[0] * perM, y: from.y - pull[1] * perM };
    const before = await g.page.evaluate(() => (window.game as unknown as CatapultGame).shotsLeft());
    await g.page.mouse.move(from.x, from.y);
    await g.page.mouse.down();
    await g.page.mouse.move(to.x, to.y, { steps: 6 });
    // The catapult's arm follows the pull: back past cocked (pi rad) by up to 15 degrees at a full pull.
    await g.waitFor(() => (window.game as unknown as { armAngle(): number }).armAngle() > Math.PI + 0.05, null);
    await g.page.mouse.up();
    // Paused at once, so the flight checked below starts where the throw is now.
    const thrown = await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame & { lastLaunch(): [number, number] };
      w.paused = true;
      return { shots: w.shots(), left: w.shotsLeft(), v: w.lastLaunch() };
    });
    // One drag, one throw.
    expect(thrown.shots.length).toBe(1);
    expect(thrown.left).toBe(before - 1);
    // Thrown the other way at PULL.gain (7 /s) x the pull: (8.4, 11.2) m/s. Tolerance 0.3 m/s: the
    // mouse lands on whole or fractional pixels, 1 px of drag being 7 / aimPxPerM (<= 0.09) m/s.
    expect(Math.abs(thrown.v[0] - -7 * pull[0])).toBeLessThan(0.3);
    expect(Math.abs(thrown.v[1] - -7 * pull[1])).toBeLessThan(0.3);
    // It flies: 20 steps (1/3 s) later it is 2.8 m further on (8.4 m/s x 1/3 s; it is in the air
    // for 2.4 s, far longer than the page runs between the release and the pause).
    const moved = await g.page.evaluate((b) => {
      const w = window.game as unknown as CatapultGame & { positionOf(h: number): [number, number] };
      const x0 = w.positionOf(b)[0];
      w.advance(20);
      return w.positionOf(b)[0] - x0;
    }, thrown.shots[0]!);
    expect(moved).toBeGreaterThan(2);
    // The arm swings forward to its crossbar (80 degrees) on the throw.
    await g.page.evaluate(() => {
      (window.game as unknown as CatapultGame).paused = false;
    });
    await g.waitFor(() => (window.game as unknown as { armAngle(): number }).armAngle() < Math.PI / 2, null);
    // A release with no move before it (a busy browser merges or drops the moves just before a
    // release) throws from where the pointer came up, not from the last move the page saw.
    await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame;
      w.reset();
      w.paused = false;
    });
    await g.waitFor(() => (window.game as unknown as { cameraSettled(): boolean }).cameraSettled(), null);
    const cdp = await g.page.context().newCDPSession(g.page);
    const press = { button: 'left', clickCount: 1 } as const;
    await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: from.x, y: from.y, ...press });
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: to.x, y: to.y, ...press });
    await cdp.detach();
    const flick = await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame & { lastLaunch(): [number, number] };
      return { shots: w.shots().length, v: w.lastLaunch() };
    });
    expect(flick.shots).toBe(1);
    expect(Math.abs(flick.v[0] - -7 * pull[0])).toBeLessThan(0.3);
    expect(Math.abs(flick.v[1] - -7 * pull[1])).toBeLessThan(0.3);
    expect(g.errors).toEqual([]);
  });

  it('a throw at the castle raises the score', async () => {
    const t = await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame;
      w.paused = true;
      w.reset();
      w.advance(30);
      const before = w.tally().score;
      // Aim the low angle at the castle's front: sin(2 theta) = g R / v^2 at v = 20 m/s (pull 20 / 7 m).
      const R = w.level().castleMinX + 0.5,
        v = 20,
        th = 0.5 * Math.asin((9.81 * R) / (v * v)),
        d = v / 7;
      w.fire(-d * Math.cos(th), -d * Math.sin(th));
      w.advance(300);
      return {
        before,
        after: w.tally().score,
        fallen: w.tally().fallen,
        share: (w as unknown as { downShare(): number }).downShare(),
      };
    });
    expect(t.before).toBe(0);
    expect(t.after).toBeGreaterThan(0);
    // The hit shows: debris flies and popups rise over what fell, 100 points a piece (FALL_POINTS),
    // pieces that fell near each other sharing one popup: fewer popups than pieces, and no two
    // overlapping on the screen (three "+100" side by side read as "+10000").
    type Shown = { bits: number; popups: number; points: number; boxes: number[][] };
    const shown = await g.waitFor(() => {
      const e = (window.game as unknown as { effects(): Shown }).effects();
      return e.popups > 0 ? e : null;
    }, null);
    expect(shown.bits).toBeGreaterThan(0);
    expect(shown.points).toBe(100 * t.fallen);
    expect(shown.popups).toBeLessThan(t.fallen);
    const overlaps = (a: number[], b: number[]) => a[0]! < b[2]! && b[0]! < a[2]! && a[1]! < b[3]! && b[1]! < a[3]!;
    for (const [i, a] of shown.boxes.entries())
      for (const b of shown.boxes.slice(i + 1)) expect(overlaps(a, b), JSON.stringify(shown.boxes)).toBe(false);
    // The next frame says what the throw earned, over the scene.
    await g.runUntil(() => (window.game as unknown as CatapultGame).lastVerdict() !== '', null, VERDICT_RUN);
    expect(await g.page.evaluate(() => (window.game as unknown as CatapultGame).lastVerdict())).toBe(`+${t.after}`);
    // That throw brought down over half the castle with two shots left: the level is cleared and the
    // player may move on at once; the level then counts its score, with 150 a shot left only for
    // three stars (paid on any clear, it made moving on worth more than throwing for more stars).
    // (The share is of the pieces that count: a bottom row lying flat on the ground cannot fall and
    // does not.)
    expect(t.share).toBeGreaterThanOrEqual(0.5);
    // Enter moves on as the button does (before, only L or the button did), and the banner says so:
    // cleared early, beside the stars; with three stars the level has ended, in its summary.
    const three = t.share >= 0.95;
    const next = g.page.getByRole('button', { name: /Level 2/ });
    await next.waitFor({ state: 'visible' });
    const said = await g.page.evaluate(() => (window.game as unknown as { bannerText(): string }).bannerText());
    expect(said).toContain(three ? 'Enter, L or the button below: next level' : 'or press Enter: next level');
    // In a player's words: pieces knocked down of how many, and what another throw is for (a stranger
    // could not parse "9 down (darker), 4 welds broke" nor "Throw for ★ or move on").
    expect(said).toContain(three ? 'pieces knocked down' : 'Throw again for more stars');
    expect(said).not.toMatch(/weld|darker|move on|Throw for ★/);
    // Once the verdict has been read (VERDICT_READ, 2.5 s of game time after it), the camera is back
    // on the whole field, the catapult on the screen for the next throw (resting on the castle left
    // the catapult off the screen until the next drag): its arm (x = 0 to 1.1 m) at least 20 px in.
    // (With three stars the level has ended and its wreck stays in view.)
    await g.page.evaluate(() => (window.game as unknown as CatapultGame).advance(200));
    const back = await g.waitFor(() => {
      const w = window.game as unknown as { cameraSettled(): boolean; renderer: { camera: Cam & { width: number } } };
      const cam = w.renderer.camera;
      return w.cameraSettled() ? { left: cam.toScreenX(0), right: cam.toScreenX(1.1), W: cam.width } : null;
    }, null);
    if (!three) expect([back.left > 20, back.right < back.W - 20], JSON.stringify(back)).toEqual([true, true]);
    await g.page.keyboard.press('Enter');
    await g.waitFor(() => (window.game as unknown as CatapultGame).params.level === 2, null);
    const campaign = await g.page.evaluate(() => (window.game as unknown as CatapultGame).campaign);
    expect(campaign.stars[0]).toBeGreaterThan(0);
    expect(campaign.stars[0] === 3).toBe(three);
    expect(campaign.scores[0]).toBe(t.after + (three ? 2 * 150 : 0));
    // Back to a new campaign at level 1 for the next test.
    await startLevel(g, 1, { clearCampaign: true });
    expect(g.errors).toEqual([]);
  });

  it('a full pull overshoots: an arrow at the edge points where it went and the verdict says by how much', async () => {
    await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame;
      w.paused = false;
      w.reset();
      w.fire(-3 * Math.SQRT1_2, -3 * Math.SQRT1_2);
    });
    await g.runUntil(() => (window.game as unknown as CatapultGame).lastVerdict() !== '', null, VERDICT_RUN);
    const verdict = await g.page.evaluate(() => (window.game as unknown as CatapultGame).lastVerdict());
    // 21 m/s at 45 degrees comes down 46 m out, about 32 m past the castle (at 11-15 m).
    const long = /^Long by (\d+) m: pull less, or aim lower$/.exec(verdict);
    expect(long, verdict).not.toBeNull();
    expect(Number(long![1])).toBeGreaterThan(20);
    const off = await g.page.evaluate(() => (window.game as unknown as { offscreen(): string }).offscreen());
    expect(off).toMatch(/^\d+ m past ▸$/);
    // The marker's label says the verdict's distance (a stranger saw "Long by 11 m" beside "14 m past").
    expect(off).toBe(`${long![1]} m past ▸`);
    // The marker sits above the castle, not over it.
    const marker = await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame & { offscreenY(): number };
      return { y: w.offscreenY(), castle: w.renderer.camera.toScreenY(w.level().castleTop) };
    });
    expect(marker.y).toBeLessThan(marker.castle);
    // The verdict and the marker's label do not overlap (a stranger saw "Long by 6 m: pull less"
    // run into "12 m past ▸" at the right edge).
    const words = await g.page.evaluate(() =>
      (window.game as unknown as { wordBoxes(): { verdict: number[] | null; offscreen: number[] | null } }).wordBoxes(),
    );
    expect(words.verdict).not.toBeNull();
    expect(words.offscreen).not.toBeNull();
    const [a0, a1, a2, a3] = words.verdict!,
      [b0, b1, b2, b3] = words.offscreen!;
    expect(a2 <= b0! || b2! <= a0! || a3! <= b1! || b3! <= a1!, JSON.stringify(words)).toBe(true);
    // Nor does the hint lie on the castle, the rock or the catapult (a stranger's "Long by 8 m" sat on the castle).
    expect(await expectHintOffScene(g, 'level 1, a full pull')).toBe(verdict);
    // A miss's hint stays up (it faded after 2.5 s and a stranger's later misses showed none):
    // 6 s on it still shows.
    await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame;
      w.paused = true;
      w.advance(360);
      w.paused = false;
    });
    await g.frames(2);
    expect(await g.page.evaluate(() => (window.game as unknown as { verdictShown(): string }).verdictShown())).toBe(verdict);
    // A new aim drops the last throw's marker but keeps its trail (a guide for the next throw); a
    // press without a pull throws nothing. A press anywhere on the scene starts an aim.
    const trail = await g.page.evaluate(() => (window.game as unknown as { trailDots(): number }).trailDots());
    expect(trail).toBeGreaterThan(5);
    const box = (await g.page.locator('canvas').boundingBox())!;
    await g.page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await g.page.mouse.down();
    await g.waitFor(() => (window.game as unknown as { offscreen(): string }).offscreen() === '', null);
    expect(await g.page.evaluate(() => (window.game as unknown as { trailDots(): number }).trailDots())).toBeGreaterThanOrEqual(trail);
    // While aiming, the hint over the scene goes and the last throw's numbers say what it did.
    await g.page.mouse.move(box.x + box.width / 2 - 30, box.y + box.height / 2 + 20, { steps: 3 });
    await g.waitFor(() => (window.game as unknown as { aimLabel(): string }).aimLabel() !== '', null);
    const aiming = await g.page.evaluate(() => {
      const w = window.game as unknown as { aimLabel(): string; verdictShown(): string };
      return { label: w.aimLabel(), verdict: w.verdictShown() };
    });
    expect(aiming.label).toMatch(new RegExp(`^last \\d+ % {2}\\d+°: long ${long![1]} m\n`));
    expect(aiming.verdict).toBe('');
    await g.page.mouse.move(box.x + box.width / 2, box.y + box.height / 2, { steps: 3 });
    await g.page.mouse.up();
    // Paused (P): an overlay says so and a drag throws nothing.
    await g.page.keyboard.press('p');
    await g.waitFor(() => (window.game as unknown as { pauseShown(): boolean }).pauseShown(), null);
    const before = await g.page.evaluate(() => (window.game as unknown as CatapultGame).shotsLeft());
    await g.page.mouse.down();
    await g.page.mouse.move(box.x + box.width / 2 - 150, box.y + box.height / 2 + 80, { steps: 6 });
    await g.page.mouse.up();
    expect(await g.page.evaluate(() => (window.game as unknown as CatapultGame).shotsLeft())).toBe(before);
    await g.page.keyboard.press('p');
    await g.waitFor(() => !(window.game as unknown as { pauseShown(): boolean }).pauseShown(), null);
    expect(g.errors).toEqual([]);
  });

  it('level 6 (a fort on a hill): a throw past the castle is long, and the marker past the edge says the same distance', async () => {
    // Four throws over the hill fort at 80 to 100 % power, 40 to 50 degrees (one that bounced on the
    // fort's hill and flew on read "No damage: throw harder" beside "17 m past").
    for (const [power, angle] of [
      [0.8, 40],
      [0.9, 50],
      [1, 40],
      [1, 50],
    ] as const) {
      await g.page.evaluate(
        ([power, angle]) => {
          const w = window.game as unknown as CatapultGame;
          w.paused = false;
          w.params.level = 6;
          w.reset();
          const th = (angle * Math.PI) / 180;
          w.fire(-3 * power * Math.cos(th), -3 * power * Math.sin(th));
        },
        [power, angle],
      );
      await g.runUntil(() => (window.game as unknown as CatapultGame).lastVerdict() !== '', null, VERDICT_RUN);
      // (The marker is drawn in the frame that decides the verdict.)
      const said = await g.page.evaluate(() => {
        const w = window.game as unknown as CatapultGame & { offscreen(): string; verdictShown(): string };
        return { verdict: w.lastVerdict(), shown: w.verdictShown(), off: w.offscreen() };
      });
      const long = /^Long by (\d+) m: pull less, or aim lower$/.exec(said.verdict);
      expect(long, JSON.stringify({ power, angle, ...said })).not.toBeNull();
      if (said.off !== '') expect(said.off).toBe(`${long![1]} m past ▸`);
    }
    await startLevel(g, 1);
    expect(g.errors).toEqual([]);
  });

  it('a throw over the castle that comes down on the rock and bounces back onto it is long, not "throw harder"', async () => {
    // Levels 1 and 2: these throws fly over the castle, first touch the rock behind it, then fall back
    // onto a piece (they read "Hit a wooden post, nothing fell: throw harder", the wrong way).
    for (const [level, power, angle] of [
      [1, 0.7, 30],
      // (Level 2's lookout behind the keep: a throw at 0.6 to 0.62 lands on it; 0.64 to 0.66 clears it to the rock.)
      [2, 0.65, 40],
    ] as const) {
      await g.page.evaluate(
        ([level, power, angle]) => {
          const w = window.game as unknown as CatapultGame;
          w.paused = false;
          w.params.level = level;
          w.reset();
          const th = (angle * Math.PI) / 180;
          w.fire(-3 * power * Math.cos(th), -3 * power * Math.sin(th));
        },
        [level, power, angle],
      );
      await g.runUntil(() => (window.game as unknown as CatapultGame).lastVerdict() !== '', null, VERDICT_RUN);
      const said = await g.page.evaluate(() => {
        const w = window.game as unknown as CatapultGame & { firstTouch(): number[] | null };
        return { verdict: w.lastVerdict(), first: w.firstTouch(), castleMaxX: w.level().castleMaxX };
      });
      // The stone's first touch was past the castle's far end (on the rock), independent of the verdict.
      expect(said.first![2]!, JSON.stringify(said)).toBeGreaterThan(said.castleMaxX + 0.3);
      expect(said.verdict, JSON.stringify({ level, power, angle, ...said })).toMatch(/^Long by \d+ m: pull less, or aim lower$/);
    }
    await startLevel(g, 1);
    expect(g.errors).toEqual([]);
  });

  it('a level cleared throws confetti that comes to rest on the ground, not in the earth under it', async () => {
    // Level 5: a tower in a pit (the ground's height changes under the confetti). On a phone the
    // confetti fell on through the earth (it had no floor).
    await startLevel(g, 5, { paused: false });
    await g.waitFor(() => !(window.game as unknown as CatapultGame).levelEnded(), null);
    // Every drawn frame the lowest bit over the ground, from the level's end until the bits are gone.
    await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame & {
        debrisOverGround(): number;
        effects(): { bits: number };
      };
      const box = window as unknown as { lowestBit: number; bitsSeen: number };
      box.lowestBit = Number.POSITIVE_INFINITY;
      box.bitsSeen = 0;
      const sample = (): void => {
        box.lowestBit = Math.min(box.lowestBit, w.debrisOverGround());
        box.bitsSeen = Math.max(box.bitsSeen, w.effects().bits);
        if (box.bitsSeen === 0 || w.effects().bits > 0) requestAnimationFrame(sample);
      };
      requestAnimationFrame(sample);
      w.fire(-1, -1);
      for (const piece of (w as unknown as { level(): { pieces: { down: boolean }[] } }).level().pieces) piece.down = true;
    });
    await g.waitFor(
      () => {
        const box = window as unknown as { lowestBit: number; bitsSeen: number };
        return box.bitsSeen >= 40 && (window.game as unknown as { effects(): { bits: number } }).effects().bits === 0;
      },
      null,
      60_000,
    );
    const lowest = await g.page.evaluate(() => (window as unknown as { lowestBit: number }).lowestBit);
    expect(lowest).toBeGreaterThanOrEqual(0);
    expect(lowest).toBeLessThan(0.05);
    await startLevel(g, 1, { clearCampaign: true });
    expect(g.errors).toEqual([]);
  });

  it('a low throw that comes down short says by how much it fell short, not where it topped out', async () => {
    // 7 m/s at 5 degrees comes down about 4.3 m out (drag-free), 2.3 to 3.3 m short of level 1's
    // castle (at 6.6 to 7.6 m). The verdict took where the throw first went down under the castle's
    // top: for a throw that never rose over it, its top, 0.4 m out ("Short by 7 m").
    await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame;
      w.paused = false;
      w.params.level = 1;
      w.reset();
      const a = (5 * Math.PI) / 180;
      w.fire((-7 / 7) * Math.cos(a), (-7 / 7) * Math.sin(a));
    });
    await g.runUntil(() => (window.game as unknown as CatapultGame).lastVerdict() !== '', null, VERDICT_RUN);
    const verdict = await g.page.evaluate(() => (window.game as unknown as CatapultGame).lastVerdict());
    expect(verdict).toMatch(/^Short by [2-4] m: pull further back$/);
    expect(g.errors).toEqual([]);
  });

  it("desktop 1280 x 800 and phone 390 x 844: a miss's hint lies clear of the castle, the rock and the catapult (long, short and a glance off level 4's tall bridge)", async () => {
    // Level 4's bridge is 5.6 m tall: a hint put 2.2 m over where the stone came down lay across it.
    // Throws (pull dx, dy, m; 3 m is a full pull) long over it, short of it, and low into its foot.
    const pulls: [number, number][] = [
      [-2.0, -1.6],
      [-1.0, -0.9],
      [-1.5, -0.35],
    ];
    for (const size of [
      { viewport: { width: 1280, height: 800 }, touch: false },
      { viewport: { width: 390, height: 844 }, touch: true },
    ]) {
      const p = await h.openGame('catapult', { query: { level: 4 }, ...size });
      for (const [dx, dy] of pulls) {
        await p.page.evaluate(
          ([dx, dy]) => {
            const w = window.game as unknown as CatapultGame;
            w.paused = false;
            w.reset();
            w.fire(dx, dy);
          },
          [dx, dy] as const,
        );
        const said = await expectHintOffScene(p, `${size.viewport.width} px, pull (${dx}, ${dy})`);
        // A miss, or a hit's points (those rise from the place hit and go).
        expect(said).toMatch(/^(Long by|Short by|Hit |No damage|\+\d+)/);
      }
      expect(p.errors).toEqual([]);
      await p.close();
    }
  }, 240_000);

  it('one level score everywhere, the star rule shown, and a retry (R) takes its points out of Total', async () => {
    type W = CatapultGame & { shownScore(): number; total(): number; bannerText(): string };
    await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame;
      w.paused = true;
      w.params.level = 1;
      w.reset();
      w.paused = false;
    });
    await g.waitFor(() => (window.game as unknown as { bannerText(): string }).bannerText().includes('★★★\u00a095\u00a0%'), null);
    // The shots still to throw, said as such ("shots 3" read as shots thrown).
    expect(await g.page.evaluate(() => (window.game as unknown as W).bannerText())).toMatch(/Total 0 {2}3 shots left/);
    // Level 1's caption is two lines: the level and its shots, then the star rule (it was three on a
    // desktop, four on a phone, with what counts as down: that is in the controls' help now).
    expect((await g.page.evaluate(() => (window.game as unknown as W).bannerText())).split('\n')).toHaveLength(2);
    expect(await g.page.locator('.bp-legend').textContent()).toContain('leaning 30°');
    await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame;
      w.paused = true;
      w.advance(30);
      const R = w.level().castleMinX + 0.5,
        th = 0.5 * Math.asin((9.81 * R) / 400),
        d = 20 / 7;
      w.fire(-d * Math.cos(th), -d * Math.sin(th));
      w.advance(300);
      while (w.shotsLeft() > 0) w.fire(0, -1.5);
      w.advance(60 * 9);
      w.paused = false;
    });
    await g.waitFor(() => (window.game as unknown as CatapultGame).levelEnded(), null);
    await g.waitFor(() => (window.game as unknown as W).shownScore() > 0, null);
    const end = await g.page.evaluate(() => {
      const w = window.game as unknown as W;
      return { shown: w.shownScore(), recorded: w.campaign.scores[0], total: w.total(), banner: w.bannerText() };
    });
    expect(end.shown).toBe(end.recorded);
    expect(end.total).toBe(end.recorded);
    expect(end.banner).toContain(`Score ${end.shown}`);
    expect(end.banner).toMatch(/★★★\s95\s%/);
    expect(await g.page.locator('[data-readout="2"]').textContent()).toBe(String(end.shown));
    // The level over, a drag aims nothing: no pull band, power bar or arc where no throw follows
    // (a stranger's drag after "Level 1 cleared" drew them, and the release threw nothing).
    const canvas = (await g.page.locator('canvas').boundingBox())!;
    await g.page.mouse.move(canvas.x + canvas.width / 2, canvas.y + canvas.height / 2);
    await g.page.mouse.down();
    await g.page.mouse.move(canvas.x + canvas.width / 2 - 120, canvas.y + canvas.height / 2 + 60, { steps: 4 });
    await g.frames(2);
    const dragged = await g.page.evaluate(() => {
      const w = window.game as unknown as W & { aimLabel(): string; aimShown(): { dots: number } };
      return { label: w.aimLabel(), dots: w.aimShown().dots };
    });
    await g.page.mouse.up();
    expect(dragged).toEqual({ label: '', dots: 0 });
    // R: the level again, and Total back to its value at the level's start (0).
    await g.page.keyboard.press('r');
    await g.waitFor(() => !(window.game as unknown as CatapultGame).levelEnded(), null);
    const after = await g.page.evaluate(() => {
      const w = window.game as unknown as W;
      return { total: w.total(), score: w.campaign.scores[0] };
    });
    expect(after).toEqual({ total: 0, score: 0 });
    expect(g.errors).toEqual([]);
  });

  it('a level where under half the pieces fell is not cleared: the button plays it again; L moves the level slider', async () => {
    // Every shot thrown straight up, away from the castle: nothing falls, so the level is over once
    // the shots are spent and 4 s passed, not cleared (the pass mark is half the pieces).
    await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame;
      w.paused = true;
      w.reset();
      w.advance(10);
      while (w.shotsLeft() > 0) w.fire(0, -1.5);
      w.advance(60 * 9);
      w.paused = false;
    });
    await g.waitFor(() => (window.game as unknown as CatapultGame).levelEnded(), null);
    const state = await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame;
      return { fallen: w.tally().fallen, stars: w.campaign.stars[0], level: w.params.level, verdict: w.lastVerdict() };
    });
    // A throw that came down short of the castle says so, and by how much (thrown straight up from
    // x = 0, level 1's castle front is 6.6 to 7.6 m away).
    expect(state).toMatchObject({ fallen: 0, stars: 0, level: 1 });
    expect(state.verdict).toMatch(/^Short by [6-8] m: pull further back$/);
    const again = g.page.getByRole('button', { name: /Try again/ });
    // Its tooltip says the same as its label (it was created as 'Next level ▶').
    expect(await again.getAttribute('title')).toBe('Try again ↺');
    // Not upright, the button is in the sky under the banner, over the castle's top: at the foot of
    // the canvas it sat over the wreck (the strip of ground under a wide view is thin).
    const place = await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame & { bannerPanel(): { panel: number[] } | null };
      const top = document.querySelector('canvas')!.getBoundingClientRect().top;
      return { castleTop: top + w.renderer.camera.toScreenY(w.level().castleTop), bannerBottom: top + w.bannerPanel()!.panel[3]! };
    });
    const button = (await again.boundingBox())!;
    expect(button.y).toBeGreaterThan(place.bannerBottom);
    expect(button.y + button.height).toBeLessThan(place.castleTop);
    await again.click();
    await g.waitFor(() => !(window.game as unknown as CatapultGame).levelEnded(), null);
    expect(await g.page.evaluate(() => (window.game as unknown as CatapultGame).params.level)).toBe(1);
    // L: the next level, and the panel's level slider shows it (it stayed at 1).
    await g.page.keyboard.press('l');
    await g.waitFor(() => (window.game as unknown as CatapultGame).params.level === 2, null);
    const shown = await g.page.evaluate(
      () => (window.game as unknown as CatapultGame).panel.gui.controllersRecursive().find((c) => c.property === 'level')?.$input?.value,
    );
    expect(shown).toBe('2');
    expect(g.errors).toEqual([]);
  });
  it('the end screen after skipped levels names them instead of claiming every castle fell', async () => {
    // L on a level not yet cleared moves on without counting it (levels 1 to 8 here), as a stranger
    // did; each level's name shows in the banner before its first throw.
    await startLevel(g, 1, { clearCampaign: true });
    const banner = () => g.page.evaluate(() => (window.game as unknown as CatapultGame & { bannerText(): string }).bannerText());
    await g.frames(2);
    expect(await banner()).toContain(`Level 1: ${levelName(0)}`);
    for (let n = 2; n <= LEVEL_COUNT; n++) {
      await g.page.keyboard.press('l');
      await g.waitFor((n) => (window.game as unknown as CatapultGame).params.level === n, n);
      await g.frames(2);
      expect(await banner()).toContain(`Level ${n}: ${levelName(n - 1)}`);
    }
    // The last level cleared: one throw, then every piece marked as fallen (the tally keeps a piece's fall).
    await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame;
      w.paused = true;
      w.advance(10);
      w.fire(0, -1.5);
      for (const p of (w.level() as unknown as { pieces: { down: boolean }[] }).pieces) p.down = true;
      w.advance(60 * 5);
      w.paused = false;
    });
    await g.waitFor(() => (window.game as unknown as CatapultGame).levelEnded(), null);
    const end = await g.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame & { bannerText(): string };
      return { text: w.bannerText(), stars: [...w.campaign.stars] };
    });
    expect(end.stars).toEqual([...new Array(LEVEL_COUNT - 1).fill(0), 3]);
    expect(end.text).not.toContain(`All ${LEVEL_COUNT} castles down`);
    const skipped = Array.from({ length: LEVEL_COUNT - 1 }, (_, i) => i + 1).join(', ');
    expect(end.text).toContain(`1 of ${LEVEL_COUNT} castles down (levels ${skipped} not cleared)`);
    expect(end.text).toContain(`Stars 3 / ${3 * LEVEL_COUNT}`);
    expect(g.errors).toEqual([]);
  });

  it('desktop 1280 x 800: a full pull is a long drag (a 200 px drag throws at about half power), and the aim shows its power, angle and a short arc, half-way to the castle', async () => {
    // The file's page is done with (no case from here on uses it): closed so that it does not keep
    // running beside the pages this case and the next open.
    await g.close();
    // The stranger's complaint: a 190 px drag was already full power (21 m/s), so aiming was fiddly.
    const d = await h.openGame('catapult', { query: { level: 1 }, viewport: { width: 1280, height: 800 }, locale: 'de-DE' });
    await checkPageContract(d, 'catapult', 'desktop');
    type W = CatapultGame & {
      cameraSettled(): boolean;
      fullPullPx(): number;
      aimPxPerM(): number;
      lastLaunch(): [number, number];
      aimShown(): { power: number; angle: number; dots: number; reach: number };
    };
    await d.waitFor(() => (window.game as unknown as W).cameraSettled(), null);
    const canvas = (await d.page.locator('canvas').boundingBox())!;
    const full = await d.page.evaluate(() => (window.game as unknown as W).fullPullPx());
    // A full pull: a third of the canvas's diagonal, capped at 380 px (it was 165 px).
    expect(full).toBeGreaterThanOrEqual(Math.min(380, 0.3 * Math.hypot(canvas.width, canvas.height)));
    expect(full).toBeGreaterThan(300);
    // A 200 px drag down and to the left at 45 degrees, from the middle of the scene.
    const from = { x: canvas.x + canvas.width * 0.6, y: canvas.y + canvas.height * 0.4 };
    const len = 200,
      to = { x: from.x - len * Math.SQRT1_2, y: from.y + len * Math.SQRT1_2 };
    await d.page.mouse.move(from.x, from.y);
    await d.page.mouse.down();
    await d.page.mouse.move(to.x, to.y, { steps: 8 });
    const shown = await d.waitFor(() => {
      const a = (window.game as unknown as W).aimShown();
      return a.dots > 0 && a.power > 0.3 ? a : null;
    }, null);
    const castle = await d.page.evaluate(() => (window.game as unknown as W).level().castleMinX);
    // The full and half pull's marks are arcs by the pull's end, each under 0.65 of a full pull across (a circle's 2)
    // and clear of the banner's panel (whole circles, 760 px across, crossed the banner and the
    // clouds); the aim's numbers at least 12 px from the canvas' left edge (at 4 px they read as
    // jammed against the sidebar).
    const marks = await d.page.evaluate(() => {
      const w = window.game as unknown as { bannerPanel(): { panel: number[] }; aimLabelAt(): { box: { x: number } } };
      const c = document.querySelector('canvas')!.getBoundingClientRect();
      const arcs = ['aim-ring', 'aim-ring-half'].map((k) => {
        const r = document.querySelector(`[data-hud="${k}"]`)!.getBoundingClientRect();
        return [r.left - c.left, r.top - c.top, r.right - c.left, r.bottom - c.top];
      });
      return { arcs, panel: w.bannerPanel().panel, labelX: w.aimLabelAt().box.x };
    });
    for (const a of marks.arcs) {
      expect(Math.hypot(a[2]! - a[0]!, a[3]! - a[1]!), JSON.stringify(marks)).toBeLessThan(0.65 * full);
      const apart = a[2]! < marks.panel[0]! || a[0]! > marks.panel[2]! || a[3]! < marks.panel[1]! || a[1]! > marks.panel[3]!;
      expect(apart, JSON.stringify(marks)).toBe(true);
    }
    expect(marks.labelX).toBeGreaterThanOrEqual(12);
    // Power 200 px / full pull (0.53 at 380 px), to 0.02; the angle 45 degrees, to 1 degree.
    expect(Math.abs(shown.power - len / full)).toBeLessThan(0.02);
    expect(shown.power).toBeLessThan(0.7);
    expect(Math.abs(shown.angle - 45)).toBeLessThan(1);
    await d.page.mouse.up();
    const v = await d.page.evaluate(() => (window.game as unknown as W).lastLaunch());
    // The preview is a short aiming arc (issue 34: drawn into the castle, the dots played the game
    // for a stranger): it ends FIRST_PREVIEW_SHARE of the way from the cup (x = 0) to the castle's
    // front (to 1 mm: the cut is interpolated on the flight), well short of where the drag-free
    // flight from the cup (0, 1.5 m) brings the stone (radius 0.3 m) down to the grass.
    expect(shown.dots).toBeGreaterThan(4);
    const grav = 9.81,
      rise = 1.5 - 0.3;
    const land = (v[0] * (v[1] + Math.sqrt(v[1] * v[1] + 2 * grav * rise))) / grav;
    expect(Math.abs(shown.reach - FIRST_PREVIEW_SHARE * castle)).toBeLessThan(1e-3);
    expect(shown.reach).toBeLessThan(land - 3);
    // 7 /s x 200 px / aimPxPerM: about 11 m/s, not the 21 m/s the 190 px drag threw before. Tolerance 0.3 m/s (pixel rounding).
    const perM = await d.page.evaluate(() => (window.game as unknown as W).aimPxPerM());
    expect(Math.abs(Math.hypot(v[0], v[1]) - (7 * len) / perM)).toBeLessThan(0.3);
    expect(Math.hypot(v[0], v[1])).toBeLessThan(0.7 * 21);
    // The aim's overlay goes with the release.
    await d.waitFor(() => (window.game as unknown as W).aimShown().dots === 0, null);
    expect(d.errors).toEqual([]);
    await d.close();
  });

  it('desktop 1280 x 800: the arc preview follows the mouse with no frame drawn and ends where the stone first touches (level 2: the bank, then the keep); after a throw the camera frames the castle', async () => {
    // (guide=full: past the first level the page draws only the flight's start, previewLimit.)
    const d = await h.openGame('catapult', { query: { level: 2, guide: 'full' }, viewport: { width: 1280, height: 800 } });
    await d.waitFor(() => (window.game as unknown as { cameraSettled(): boolean }).cameraSettled(), null);
    const aimPerM = await d.page.evaluate(() => {
      const cam = (window.game as unknown as CatapultGame).renderer.camera;
      return cam.toScreenX(1) - cam.toScreenX(0);
    });
    // Low and under half power: the stone meets the earth bank's face, 0.75 m up its 1.2 m (the
    // preview ended 0.3 m past it); then the stranger's 58 % at 40 degrees.
    const bank = await previewMatchesThrow(d, 0.45, 15, false);
    const lv = await d.page.evaluate(
      () => (window.game as unknown as { level(): { terrain: { kind: string; minX: number }[] } }).level().terrain,
    );
    const hill = lv.find((t) => t.kind === 'hill')!;
    expect(Math.abs(bank.end[0] + 0.3 - hill.minX)).toBeLessThan(0.05);
    // Past the bank, faint dots show where the throw was headed (issue 34: the preview stopped at
    // the first touch, and the player could not see where a blocked throw would go).
    expect(bank.past).toBeGreaterThan(0);
    await previewMatchesThrow(d, 0.58, 40, false);
    // After the throw the camera frames the castle (the whole field fitted to the width drew it as a
    // strip under 80 % of sky): at least 1.4 x the aim view's pixels a metre, the sky over the
    // castle's top under 65 % of the canvas.
    type V = {
      shotView(): boolean;
      cameraSettled(): boolean;
      renderer: { camera: Cam & { height: number } };
      level(): { castleTop: number };
    };
    const framed = await d.waitFor(() => {
      const w = window.game as unknown as V;
      const cam = w.renderer.camera;
      return w.shotView() && w.cameraSettled()
        ? { perM: cam.toScreenX(1) - cam.toScreenX(0), sky: cam.toScreenY(w.level().castleTop) / cam.height }
        : null;
    }, null);
    expect(framed.perM).toBeGreaterThanOrEqual(1.4 * aimPerM);
    expect(framed.sky).toBeLessThan(0.65);
    expect(d.errors).toEqual([]);
    await d.close();
  });

  it('phone 390 x 844 (touch): the arc preview follows the finger with no frame drawn and ends where the stone first touches', async () => {
    // (guide=full: the page draws only the flight's start, previewLimit.)
    const p = await h.openGame('catapult', { query: { level: 1, guide: 'full' }, viewport: { width: 390, height: 844 }, touch: true });
    await previewMatchesThrow(p, 0.5, 30, true);
    expect(p.errors).toEqual([]);
    await p.close();
  });

  it('upright tablet 768 x 1024 (touch): the look button says in words what it shows, shows the castle close and goes back', async () => {
    const p = await h.openGame('catapult', { query: { level: 1 }, viewport: { width: 768, height: 1024 }, touch: true });
    type T = { cameraShot(): string; cameraSettled(): boolean; renderer: { camera: Cam } };
    const settled = (shot: string) =>
      p.waitFor((s) => {
        const w = window.game as unknown as T;
        return w.cameraShot() === s && w.cameraSettled() ? w.renderer.camera.toScreenX(1) - w.renderer.camera.toScreenX(0) : null;
      }, shot);
    const aimPerM = await settled('aim');
    // 768 px over the aim view's 18.6 m: about 41 px a metre, so the field shows the castle and no close-up.
    expect(await p.page.evaluate(() => (window.game as unknown as { closeUp(): unknown }).closeUp())).toBeNull();
    const look = p.page.locator('[data-hud="look"] button');
    expect(await look.textContent()).toMatch(/zoom to castle/i);
    await look.tap();
    const lookedPerM = await settled('castle');
    expect(lookedPerM).toBeGreaterThan(1.25 * aimPerM);
    expect(await look.textContent()).toMatch(/back to catapult/i);
    await look.tap();
    expect(await settled('aim')).toBeCloseTo(aimPerM, 1);
    expect(p.errors).toEqual([]);
    await p.close();
  });

  it('phone 390 x 844 (touch): upright every level opens close on the catapult, the castle in an inset and an arrow with its distance; sideways the whole field; the card and the how-to line; the pull is long and the release throws; played again, the camera follows the stone to a large tower, a drag from anywhere throws and the next-level (or try-again) button goes on', async () => {
    const p = await h.openGame('catapult', { query: { level: 1 }, viewport: { width: 390, height: 844 }, touch: true });
    // Before the first touch: the start view upright and sideways, and the card saying how to play.
    const { hint, box: sideways } = await phoneBeforeTouch(p);
    type W = CatapultGame & {
      cameraSettled(): boolean;
      fullPullPx(): number;
      lastLaunch(): [number, number];
      aimShown(): { power: number; angle: number; dots: number; reach: number };
      renderer: { camera: Cam & { width: number; height: number } };
    };
    await p.waitFor(() => (window.game as unknown as W).cameraSettled(), null);
    // Where the catapult (its mound and arm: x -1.2 to 1 m, y 0 to 2 m) and the castle are on the canvas.
    const where = () =>
      p.page.evaluate(() => {
        const w = window.game as unknown as W;
        const cam = w.renderer.camera,
          lv = w.level();
        return {
          catapult: [cam.toScreenX(-1.2), cam.toScreenX(1), cam.toScreenY(2), cam.toScreenY(0)],
          castle: [cam.toScreenX(lv.castleMinX), cam.toScreenX(lv.castleMaxX), cam.toScreenY(lv.castleTop), cam.toScreenY(0)],
          W: cam.width,
          H: cam.height,
        };
      });
    const inside = (r: number[], W: number, H: number) => r[0]! >= 0 && r[1]! <= W && r[2]! >= 0 && r[3]! <= H;
    // Before the first throw (the opening over) the view holds the catapult, the castle off the
    // screen to its right, and the castle's inset in the earth under it.
    type Close = { closeUp(): { box: [number, number, number, number] } | null };
    const rest = await where();
    const ahead = (f: typeof rest) => f.castle[0]! > f.W;
    expect(inside(rest.catapult, rest.W, rest.H)).toBe(true);
    expect(ahead(rest)).toBe(true);
    const restClose = (await p.page.evaluate(() => (window.game as unknown as Close).closeUp()))!;
    expect(restClose).not.toBeNull();
    // In the earth: its top under the ground line (12 px gap in main.ts drawCloseUp; 1 px rounding).
    expect(restClose.box[1]).toBeGreaterThanOrEqual(rest.castle[3]! + 11);
    const full = await p.page.evaluate(() => (window.game as unknown as W).fullPullPx());
    // A full pull: half the phone's width, a thumb's drag (at 0.9 of it, 351 px, a stranger had to
    // drag to the screen's edge; catapult-phone.test.ts pulls it whole).
    expect(full).toBeCloseTo(0.5 * 390, 0);
    const box = (await p.page.locator('canvas').boundingBox())!;
    // From the screen's middle: the finger ends by the catapult, where the aim's numbers go unless
    // the band is there (a stranger's pull put its knob on them).
    const start = { x: box.x + 0.49 * box.width, y: box.y + 0.53 * box.height };
    const cdp = await p.page.context().newCDPSession(p.page);
    const touch = (x: number, y: number) => [{ x, y, id: 1 }];
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: touch(start.x, start.y) });
    // 85 px down and to the left (30 degrees below level): under two thirds of full power.
    const len = 85,
      end = { x: start.x - len * Math.cos(Math.PI / 6), y: start.y + len * Math.sin(Math.PI / 6) };
    for (let i = 1; i <= 6; i++)
      await cdp.send('Input.dispatchTouchEvent', {
        type: 'touchMove',
        touchPoints: touch(start.x + ((end.x - start.x) * i) / 6, start.y + ((end.y - start.y) * i) / 6),
      });
    // While the finger is down the catapult stays on the canvas and the castle's inset stays too
    // (a stranger aimed at a keep cut off at the edge), the band over it, clear of the aim's numbers,
    // and none of the preview's dots in it: the short aiming arc (scene FIRST_PREVIEW_SHARE) ends
    // half-way to the castle's front, so where this throw (about 9 m/s at 30 degrees, down about 9 m
    // out) comes down is the player's judgement (issue 34: the whole flight drawn into the castle's
    // inset played the game for a stranger).
    await p.waitFor(() => (window.game as unknown as W).cameraSettled(), null);
    const aiming = await where();
    expect(inside(aiming.catapult, aiming.W, aiming.H)).toBe(true);
    expect(ahead(aiming)).toBe(true);
    expect(await p.page.evaluate(() => (window.game as unknown as Close).closeUp())).not.toBeNull();
    expect(await p.page.evaluate(() => (window.game as unknown as { aimShown(): { closeDots: number } }).aimShown().closeDots)).toBe(0);
    // The aim's numbers and bar at least 9 px (the knob's radius) from the band, on 400 points of it,
    // and on the canvas.
    const label = await p.page.evaluate(() =>
      (window.game as unknown as { aimLabelAt(): { box: { x: number; y: number; w: number; h: number }; band: number[] } }).aimLabelAt(),
    );
    const [bx0, by0, bx1, by1] = label.band as [number, number, number, number];
    const { x: lx, y: ly, w: lw, h: lh } = label.box;
    let gap = Number.POSITIVE_INFINITY;
    for (let i = 0; i <= 400; i++) {
      const [qx, qy] = [bx0 + ((bx1 - bx0) * i) / 400, by0 + ((by1 - by0) * i) / 400];
      gap = Math.min(gap, Math.hypot(Math.max(lx - qx, 0, qx - lx - lw), Math.max(ly - qy, 0, qy - ly - lh)));
    }
    expect(gap, JSON.stringify(label)).toBeGreaterThanOrEqual(9);
    expect([lx >= 0, ly >= 0, lx + lw <= aiming.W, ly + lh <= aiming.H], JSON.stringify(label)).toEqual([true, true, true, true]);
    const aimClose = (await p.page.evaluate(() => (window.game as unknown as Close).closeUp()))!;
    const [cx, cy, cw, ch] = aimClose.box;
    const overlaps = lx < cx + cw && cx < lx + lw && ly < cy + ch && cy < ly + lh;
    expect(overlaps, JSON.stringify({ label: label.box, close: aimClose.box })).toBe(false);
    const shown = await p.page.evaluate(() => (window.game as unknown as W).aimShown());
    expect(Math.abs(shown.power - len / full)).toBeLessThan(0.02);
    expect(shown.power).toBeLessThan(0.65);
    expect(Math.abs(shown.angle - 30)).toBeLessThan(1.5);
    expect(shown.dots).toBeGreaterThan(4);
    // The how-to line stays through the first touch and the pull, and goes with the throw.
    const howTo = p.page.locator('[data-hud="how-to"]');
    expect(await howTo.evaluate((el) => getComputedStyle(el).opacity)).toBe('1');
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await cdp.detach();
    await p.waitFor(() => (window.game as unknown as W).shots().length === 1, null);
    await howTo.waitFor({ state: 'detached', timeout: 3000 });
    // The first touch took the card away.
    await hint.waitFor({ state: 'detached', timeout: 3000 });
    const v = await p.page.evaluate(() => (window.game as unknown as W).lastLaunch());
    expect(Math.hypot(v[0], v[1])).toBeLessThan(0.65 * 21);
    expect(Math.hypot(v[0], v[1])).toBeGreaterThan(0.3 * 21);
    // The level over (every piece marked fallen): the view holds the wreck, not the catapult (a
    // stranger's result screen showed the catapult under five lines of text), and the banner has a
    // dark panel behind it: white type over black at opacity a over the palest sky (white) is
    // 1.05 / (L + 0.05) to 1, L the luminance of sRGB 1 - a: at least 4.5 (WCAG AA).
    await p.page.evaluate(() => {
      for (const piece of (window.game as unknown as { level(): { pieces: { down: boolean }[] } }).level().pieces) piece.down = true;
    });
    // The camera eases there: waited on (the wait fails the test at its time limit) until the castle
    // is in view and the catapult out of it, not until the camera is at rest.
    await p.waitFor(() => {
      const w = window.game as unknown as W;
      const cam = w.renderer.camera,
        lv = w.level();
      return w.levelEnded() && cam.toScreenX(lv.castleMinX) >= 0 && cam.toScreenX(lv.castleMaxX) <= cam.width && cam.toScreenX(1) < 0;
    }, null);
    const ended = await where();
    expect(inside(ended.castle, ended.W, ended.H)).toBe(true);
    expect(ended.catapult[1]).toBeLessThan(0);
    const panel = await p.page.evaluate(() =>
      (window.game as unknown as { bannerPanel(): { panel: number[]; alpha: number; text: number[] } | null }).bannerPanel(),
    );
    expect(panel).not.toBeNull();
    const [px0, py0, px1, py1] = panel!.panel,
      [tx0, ty0, tx1, ty1] = panel!.text;
    expect([px0! <= tx0!, py0! <= ty0!, px1! >= tx1!, py1! >= ty1!]).toEqual([true, true, true, true]);
    const c = 1 - panel!.alpha,
      lum = c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
    expect(1.05 / (lum + 0.05)).toBeGreaterThanOrEqual(4.5);
    // The result in three lines at most (a line 1.17 x the type size and the outline 4 px: three
    // 3.8 x, four 4.9 x; it was six) and the sun clear of it.
    const result = await p.page.evaluate(() => (window.game as unknown as PhoneGame).bannerSize());
    expect(result.height).toBeLessThan(4.5 * result.fontSize);
    await expectSunClear(p);
    // The level played again from its start, the camera at rest on the aim view: a stone followed
    // to the tower, a drag from anywhere throws, the next-level (or try-again) button.
    await p.page.evaluate(() => {
      const w = window.game as unknown as CatapultGame & { jumpCamera(): void };
      w.reset();
      w.jumpCamera();
    });
    await p.waitFor(() => {
      const w = window.game as unknown as W & { cameraShot(): string };
      return !w.levelEnded() && w.shots().length === 0 && w.cameraShot() === 'aim' && w.cameraSettled();
    }, null);
    await phoneThrows(p, hint, sideways);
    // The menu drawer over the scene pauses the game (a stone flew and a castle fell under it), and
    // closing it plays on.
    const menu = p.page.getByRole('button', { name: 'information and controls' });
    await p.page.evaluate(() => {
      (window.game as unknown as CatapultGame).paused = false;
    });
    await menu.tap();
    await p.waitFor(() => (window.game as unknown as CatapultGame).paused, null);
    await menu.tap();
    await p.waitFor(() => !(window.game as unknown as CatapultGame).paused, null);
    expect(p.errors).toEqual([]);
    await p.close();
  });
});
