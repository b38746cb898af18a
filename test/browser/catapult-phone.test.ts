/**
 * Catapult on a phone held upright (390 x 844, touch), what a stranger found unfinished there (issue
 * 34): the castle out of sight while aiming and for the first seconds of a throw, a full pull that
 * needed a drag to the screen's edge, and a settings menu whose gravity slider changed a level under
 * way. Here: a new level opens on its castle and pans to the catapult; the castle's inset stays from
 * the throw until the castle is in view; half the screen's width of thumb drag is a full pull; the
 * physics knobs sit in a closed folder and apply by starting the level again.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { OPENING_FRAMES } from '../../games/catapult/camera';
import { PULL } from '../../games/catapult/scene';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';
import { touchPath } from './touch';

/** What these checks read of the catapult page's `window.game`. */
interface Game {
  paused: boolean;
  reset(): void;
  params: { level: number };
  cameraShot(): string;
  cameraSettled(): boolean;
  closeUp(): { box: [number, number, number, number] } | null;
  level(): { castleMinX: number; castleMaxX: number; castleTop: number };
  levelEnded(): boolean;
  lastVerdict(): string;
  shots(): number[];
  fire(dx: number, dy: number): number;
  fullPullPx(): number;
  lastLaunch(): [number, number];
  aimShown(): { power: number; angle: number };
  aimLabelAt(): { box: { x: number; y: number; w: number; h: number }; band: number[] };
  world: { gravity: Float64Array | number[] };
  renderer: { camera: { toScreenX(x: number): number; toScreenY(y: number): number; width: number; height: number } };
  panel: {
    gui: {
      controllersRecursive(): {
        property: string;
        parent: { _title: string; _closed: boolean; root: unknown; parent: unknown };
        setValue(v: number): void;
        _callOnFinishChange(): void;
      }[];
    };
  };
}

let h: Harness;
let p: GamePage;
beforeAll(async () => {
  h = await Harness.start();
  p = await h.openGame('catapult', { query: { level: 1 }, viewport: { width: 390, height: 844 }, touch: true });
}, START_TIMEOUT_MS);
afterAll(async () => {
  await h?.close();
});

/** Starts `level` afresh (its reset), unpaused. */
async function startLevel(level: number): Promise<void> {
  await p.page.evaluate((lv) => {
    const w = window.game as unknown as Game;
    w.paused = false;
    w.params.level = lv;
    w.reset();
  }, level);
}

/**
 * Runs frames until the camera rests on the aim view (the catapult close, the castle's inset
 * showing); returns how many, and on how many of them the camera said it was at rest on the
 * castle's view (tests aim once it is at rest: during the opening it is not).
 */
async function toAimView(): Promise<{ frames: number; restOnCastle: number }> {
  return await p.runUntil(
    (a: { frames: number; restOnCastle: number }) => {
      a.frames++;
      const w = window.game as unknown as Game;
      if (w.cameraShot() === 'castle' && w.cameraSettled()) a.restOnCastle++;
      return w.cameraShot() === 'aim' && w.cameraSettled() && w.closeUp() !== null ? a : null;
    },
    { frames: 0, restOnCastle: 0 },
    { maxFrames: 600 },
  );
}

/** Where the castle (its ends) and the catapult's arm (x = 1 m) are across the canvas, px, and its width. */
const across = () =>
  p.page.evaluate(() => {
    const w = window.game as unknown as Game;
    const cam = w.renderer.camera,
      lv = w.level();
    return { castle: [cam.toScreenX(lv.castleMinX), cam.toScreenX(lv.castleMaxX)], catapult: cam.toScreenX(1), W: cam.width };
  });

describe('catapult on a phone held upright (390 x 844, touch)', () => {
  it('a new level opens on its whole castle, large, then pans to the catapult; a retry opens on the catapult; a touch ends the opening', async () => {
    // Level 3 (the farthest castle), new to the page: its first frame shows the castle whole and
    // large (./camera uprightOpeningView: 26 px a metre; the catapult and the castle together drew
    // it at 11 px a metre, a thin strip low on the screen under 60 % of sky), the ground half-way
    // up as in the aim view (to a pixel), so the camera then pans level across to the catapult.
    await startLevel(3);
    await p.runFrames(1);
    expect(await p.page.evaluate(() => (window.game as unknown as Game).cameraShot())).toBe('castle');
    const first = await across();
    expect([first.castle[0]! >= 0, first.castle[1]! <= first.W], JSON.stringify(first)).toEqual([true, true]);
    const look = await p.page.evaluate(() => {
      const cam = (window.game as unknown as Game).renderer.camera;
      return { ground: cam.toScreenY(0) / cam.height, perM: cam.toScreenX(1) - cam.toScreenX(0) };
    });
    expect(Math.abs(look.ground - 0.5) * 788, JSON.stringify(look)).toBeLessThan(1);
    expect(look.perM, JSON.stringify(look)).toBeGreaterThan(20);
    // Held, then the pan to the catapult: at rest on the aim view after the opening's frames and the
    // easing (a tenth of the way a step, a frame a step here: about 60 frames to within 1 cm), the castle off the screen
    // and its inset showing.
    const { frames, restOnCastle } = await toAimView();
    expect(frames).toBeGreaterThan(OPENING_FRAMES - 2);
    expect(frames).toBeLessThan(OPENING_FRAMES + 150);
    expect(restOnCastle).toBe(0);
    const rest = await across();
    expect([rest.catapult > 0 && rest.catapult < rest.W, rest.castle[0]! > rest.W], JSON.stringify(rest)).toEqual([true, true]);
    // The same level again: no opening (the player knows where the castle is).
    await startLevel(3);
    await p.runFrames(1);
    expect(await p.page.evaluate(() => (window.game as unknown as Game).cameraShot())).toBe('aim');
    // A new level, and a finger down during its opening: the camera heads for the catapult at once.
    await startLevel(4);
    await p.runFrames(1);
    expect(await p.page.evaluate(() => (window.game as unknown as Game).cameraShot())).toBe('castle');
    const cdp = await p.page.context().newCDPSession(p.page);
    const box = (await p.page.locator('canvas').boundingBox())!;
    const at = [{ x: box.x + 200, y: box.y + 400, id: 1 }];
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at });
    await p.runFrames(1, { unpause: false });
    expect(await p.page.evaluate(() => (window.game as unknown as Game).cameraShot())).toBe('aim');
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await cdp.detach();
    expect(p.errors).toEqual([]);
  });

  it("a full pull is a thumb's drag: half the screen's width (195 px) reads 100 % and throws at full speed", async () => {
    await startLevel(1);
    await toAimView();
    const full = await p.page.evaluate(() => (window.game as unknown as Game).fullPullPx());
    // It was 0.9 of the width (351 px): a drag to the screen's edge.
    expect(full).toBeLessThanOrEqual(0.55 * 390);
    expect(full).toBeGreaterThanOrEqual(150);
    // From 60 % across and half-way down, 196 px (1 px over the full pull: the aim counts to a
    // pixel) down and back at 30 degrees: the thumb ends 170 px to the left, on the screen.
    const box = (await p.page.locator('canvas').boundingBox())!;
    const x0 = box.x + 0.6 * box.width,
      y0 = box.y + 0.5 * box.height,
      len = 196;
    const path: Array<[number, number]> = [];
    for (let i = 0; i <= 8; i++) path.push([x0 - (len * Math.cos(Math.PI / 6) * i) / 8, y0 + (len * Math.sin(Math.PI / 6) * i) / 8]);
    expect(path[8]![0]).toBeGreaterThan(box.x + 20);
    let shown = { power: 0, angle: 0, text: '' };
    // The most of the pull's band (press to finger) inside the castle's inset, px, over the pull.
    let overlap = 0;
    await touchPath(p.page, path, 150, async () => {
      shown = await p.page.evaluate(() => ({
        ...(window.game as unknown as Game).aimShown(),
        text: document.querySelector('[data-hud="aim"]')?.textContent ?? '',
      }));
      const inside = await p.page.evaluate(() => {
        const w = window.game as unknown as Game;
        const c = w.closeUp(),
          [x0, y0, x1, y1] = w.aimLabelAt().band as [number, number, number, number];
        if (!c) return 0;
        const [bx, by, bw, bh] = c.box;
        let n = 0;
        for (let i = 0; i <= 100; i++) {
          const x = x0 + ((x1 - x0) * i) / 100,
            y = y0 + ((y1 - y0) * i) / 100;
          if (x >= bx && x <= bx + bw && y >= by && y <= by + bh) n++;
        }
        return (n / 101) * Math.hypot(x1 - x0, y1 - y0);
      });
      overlap = Math.max(overlap, inside);
    });
    // The inset stands clear of the pull (./pull insetBesidePull; to the 1 % of the band sampled): the
    // band ran 170 px through the inset and over its label.
    expect(overlap).toBeLessThanOrEqual(2);
    // The readout says full power (1 % of 21 m/s is 0.2 m/s: the tolerance of one pixel's rounding).
    expect(shown.power, JSON.stringify(shown)).toBeGreaterThanOrEqual(0.99);
    expect(shown.text, JSON.stringify(shown)).toMatch(/\b(99|100) %/);
    expect(Math.abs(shown.angle - 30), JSON.stringify(shown)).toBeLessThan(1.5);
    await p.waitFor(() => (window.game as unknown as Game).shots().length === 1, null);
    const v = await p.page.evaluate(() => (window.game as unknown as Game).lastLaunch());
    expect(Math.hypot(v[0], v[1])).toBeGreaterThan(0.98 * 21);
  });

  it('levels 1 and 2 aim close (the catapult 190 px wide or more); the power and angle sit over the press on both', async () => {
    const seen: Array<{ catapult: number; press: number[]; box: { x: number; y: number; w: number; h: number } }> = [];
    for (const level of [1, 2]) {
      await startLevel(level);
      await toAimView();
      // The catapult with its stones, x -3.0 to 1.1 m, across the canvas, px.
      const catapult = await p.page.evaluate(() => {
        const cam = (window.game as unknown as Game).renderer.camera;
        return cam.toScreenX(1.1) - cam.toScreenX(-3.0);
      });
      // The same pull on both levels: from 60 % across and half-way down, 100 px down and back.
      const box = (await p.page.locator('canvas').boundingBox())!;
      const x0 = box.x + 0.6 * box.width,
        y0 = box.y + 0.5 * box.height;
      const path: Array<[number, number]> = [];
      for (let i = 0; i <= 4; i++) path.push([x0 - 20 * i, y0 + 12 * i]);
      await touchPath(p.page, path, 100, async () => {
        const at = await p.page.evaluate(() => (window.game as unknown as Game).aimLabelAt());
        seen.push({ catapult, press: at.band.slice(0, 2), box: at.box });
      });
    }
    const at = JSON.stringify(seen);
    // 197 px at 48 px a metre (camera.ts AIM_CLOSE_PX_PER_M_MAX); it was 173 and 148 px, a small
    // figure at the foot of a tall sky.
    for (const s of seen) expect(s.catapult, at).toBeGreaterThanOrEqual(190);
    // The numbers and bar over the press, their foot 10 to 60 px above it, across its x, and at the
    // same height over it on both levels (to a pixel: the label's lines differ, its foot does not).
    // They sat over the catapult on level 1 and under the ground on level 2.
    const foot = seen.map((s) => s.press[1]! - (s.box.y + s.box.h));
    for (const [k, s] of seen.entries()) {
      expect(foot[k], at).toBeGreaterThanOrEqual(10);
      expect(foot[k], at).toBeLessThanOrEqual(60);
      expect(s.box.x <= s.press[0]! && s.press[0]! <= s.box.x + s.box.w, at).toBe(true);
    }
    expect(Math.abs(foot[0]! - foot[1]!), at).toBeLessThanOrEqual(1);
    expect(p.errors).toEqual([]);
  });

  it("the castle's inset shows on every frame from the throw until the castle is on the screen; on a 15 fps page the camera reaches the castle with the stone (level 3, the farthest castle)", async () => {
    await startLevel(3);
    await toAimView();
    // A throw at 40 degrees at 80 % of a full pull (past the catapult's view, towards the castle).
    const pull = 0.8 * PULL.max,
      th = (40 * Math.PI) / 180;
    await p.page.evaluate(([dx, dy]) => (window.game as unknown as Game).fire(dx, dy), [
      -pull * Math.cos(th),
      -pull * Math.sin(th),
    ] as const);
    // Each frame until the verdict, frames of 4 steps (a page drawing 15 frames a second): where the
    // castle is not wholly on the canvas, the inset shows; and at the first frame the stone is within
    // 0.5 m of the castle's front, the front is well on the canvas (issue 34: the camera eased a tenth a
    // frame whatever the steps, and a slow page's stone hit the castle while the view was still on
    // the field: the hit seen only in the inset).
    const seen = await p.runUntil(
      (a: { frames: number; away: number; missing: number; reached: number; front: number }) => {
        const w = window.game as unknown as Game & { positionOf(h: number): [number, number] };
        const cam = w.renderer.camera,
          lv = w.level();
        a.frames++;
        const away = cam.toScreenX(lv.castleMinX) < 0 || cam.toScreenX(lv.castleMaxX) > cam.width;
        if (away && !w.levelEnded()) {
          a.away++;
          if (w.closeUp() === null) a.missing++;
        }
        const shot = w.shots()[0];
        if (a.reached === 0 && shot !== undefined && w.positionOf(shot)[0] >= lv.castleMinX - 0.5) {
          a.reached = a.frames;
          a.front = cam.toScreenX(lv.castleMinX);
        }
        return w.lastVerdict() !== '' ? a : null;
      },
      { frames: 0, away: 0, missing: 0, reached: 0, front: Number.NaN },
      { maxFrames: 300, seconds: 4 / 60 },
    );
    // The castle was off the screen for part of the flight (the check ran), and the inset never went.
    expect(seen.away, JSON.stringify(seen)).toBeGreaterThan(3);
    expect(seen.missing, JSON.stringify(seen)).toBe(0);
    // The stone reached the castle, and its front was then in the canvas's left two thirds (260 of
    // 390 px: the castle behind it in view; 190 px here, 378 px eased a tenth a frame). Followed
    // exactly, the stone sits 30 % across (117 px) and the front 0.5 m on (137 px); the 260 px
    // allow 3 m of lag at 40 px a metre.
    expect(seen.reached, JSON.stringify(seen)).toBeGreaterThan(0);
    expect(seen.front >= 0 && seen.front <= 260, JSON.stringify(seen)).toBe(true);
    expect(p.errors).toEqual([]);
  });

  it('the physics knobs sit in a closed folder saying they restart the level; gravity moved mid-flight changes nothing until let go, then restarts the level with it', async () => {
    await startLevel(1);
    await toAimView();
    const folder = await p.page.evaluate(() => {
      const c = (window.game as unknown as Game).panel.gui.controllersRecursive().filter((c) => c.property === 'gravity')[0]!;
      return { title: c.parent._title, closed: c.parent._closed, nested: c.parent.parent !== undefined };
    });
    expect(folder).toEqual({ title: 'Advanced (restarts level)', closed: true, nested: true });
    // A throw in flight, and the gravity slider dragged to 20 m/s² (not yet let go).
    await p.page.evaluate(() => {
      const w = window.game as unknown as Game;
      w.fire(-2, -1.5);
      w.panel.gui
        .controllersRecursive()
        .filter((c) => c.property === 'gravity')[0]!
        .setValue(20);
    });
    await p.runFrames(5);
    const mid = await p.page.evaluate(() => {
      const w = window.game as unknown as Game;
      return { g: w.world.gravity[1]!, shots: w.shots().length };
    });
    expect(mid).toEqual({ g: -9.81, shots: 1 });
    // Let go: the level starts again under the new gravity (no stone thrown, every shot back).
    await p.page.evaluate(() =>
      (window.game as unknown as Game).panel.gui
        .controllersRecursive()
        .filter((c) => c.property === 'gravity')[0]!
        ._callOnFinishChange(),
    );
    const after = await p.page.evaluate(() => {
      const w = window.game as unknown as Game;
      return { g: w.world.gravity[1]!, shots: w.shots().length };
    });
    expect(after).toEqual({ g: -20, shots: 0 });
    // Back to Earth's for the page's other checks.
    await p.page.evaluate(() => {
      const c = (window.game as unknown as Game).panel.gui.controllersRecursive().filter((c) => c.property === 'gravity')[0]!;
      c.setValue(9.81);
      c._callOnFinishChange();
    });
    expect(p.errors).toEqual([]);
  });
});
