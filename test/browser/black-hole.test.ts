/**
 * Black hole in headless Chromium, level 1: the opening line says what reaching the line is worth;
 * the level's title shows until the first thrust; holding ↑ flies into the hole across the path,
 * which plays the swallow effect and says so; the next thrust clears that message; flying at a side
 * edge warns before the ship leaves the field; two arrows held thrust diagonally (keys, and two
 * fingers on the pad). A clear shows its points rising from the line; between
 * levels the field is empty and the next-level button, over the field, leaves the start pad, the ship
 * and the thrust buttons clear, and a tap on it starts level 2, whose wall is drawn inside the field
 * (desktop and phone); on a phone, after the game a tap on the scene plays again from the level lost.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';
import { checkPageContract } from './page-contract';
import { decodePng } from './png';
import { sharedPage } from './shared-page';

interface BlackHolePage {
  bh: { falls: number; message: string };
  levelBanner(): string;
  swallowing(): boolean;
  edgeWarning(): boolean;
  pathEnd(): 'clear' | 'falls' | 'lost';
  pathLabel(): string;
  pathShade(): 'warn' | 'clear' | 'open' | '';
  ghostHoles(): boolean;
  deathEffect(): { count: number; text: string; flashPeak: number; shown: boolean; caption: string };
  pathPoints(): number;
  engineGauge(): number;
}

/**
 * In the page: the holes whose drawing (disc and glow, `holeExtents`, m) the level's title box
 * (`levelBannerBox`, canvas px) overlaps, and how many holes there are. Run by `page.evaluate`.
 */
function bannerOverHoles(): { hits: number; holes: number; text: string } {
  type Cam = { toScreenX(x: number): number; toScreenY(y: number): number };
  const w = window.game as unknown as {
    renderer: { camera: Cam };
    levelBanner(): string;
    levelBannerBox(): number[];
    holeExtents(): number[][];
  };
  const cam = w.renderer.camera;
  const [l, t, r, b] = w.levelBannerBox();
  const hits = w
    .holeExtents()
    .filter(([x0, x1, y0, y1]) => cam.toScreenX(x1!) > l! && cam.toScreenX(x0!) < r! && cam.toScreenY(y0!) > t! && cam.toScreenY(y1!) < b!);
  return { hits: hits.length, holes: w.holeExtents().length, text: w.levelBanner() };
}

let h: Harness;
let g: GamePage;
beforeAll(async () => {
  h = await Harness.start();
  g = await h.openGame('black-hole', { query: { level: 1 } });
}, START_TIMEOUT_MS);
afterAll(async () => {
  await h?.close();
});

describe('black hole', () => {
  it('labels the score; a fall spirals the ship in; the next thrust clears the message; the edge warns', async () => {
    expect(await g.page.locator('[data-hud="numbers"]').textContent()).toContain('Score 0');
    expect(await g.page.locator('[data-hud="message"]').textContent()).toBe(
      'Level 1: fly through the gold ring, then reach the green line for 100 points, more if fast. Practice: falling in costs no life here.',
    );
    // The level's title shows over the field until the first thrust, with what the line is worth.
    expect(await g.page.evaluate(() => (window.game as unknown as BlackHolePage).levelBanner())).toBe(
      'Level 1\nthrough the gold ring, then steer round the hole\n100 points at the line',
    );
    // The predicted path shows from the pad before the first thrust (the path holding ↑ would take;
    // it showed only once the ship moved), and the legend says what its colours mean.
    await g.waitFor(() => {
      const w = window.game as unknown as { padPath(): boolean; pathPoints(): number };
      return w.padPath() && w.pathPoints() > 10;
    }, null);
    expect(await g.page.evaluate(() => document.body.textContent)).toContain(
      'predicted path on / off (red: falls in or lost, blue: reaches the line, grey: undecided)',
    );
    // The title covers none of the holes (it was printed under the finish line, over the holes and a
    // wall's gap): it sits in the open field below them.
    const banner = await g.page.evaluate(bannerOverHoles);
    expect(banner).toMatchObject({ hits: 0, holes: 1 });
    // The path from the pad runs into the hole across the climb: its end says so in words by a cross.
    await g.waitFor(() => (window.game as unknown as BlackHolePage).pathLabel() === 'falls in', null);
    expect(await g.page.evaluate(() => (window.game as unknown as BlackHolePage).pathEnd())).toBe('falls');
    await g.page.keyboard.down('ArrowUp');
    await g.waitFor(() => (window.game as unknown as BlackHolePage).levelBanner() === '', null);
    // The engine gauge round the ship shows how far the thrust has built up while ↑ is held.
    await g.waitFor(() => (window.game as unknown as BlackHolePage).engineGauge() > 0, null);
    // The climb into the hole, ↑ held, stepped in the page (the fall starts the swallow in its step).
    await g.runUntil(() => (window.game as unknown as BlackHolePage).swallowing(), null, { draw: false });
    await g.frames(2);
    await g.page.keyboard.up('ArrowUp');
    expect(await g.page.evaluate(() => (window.game as unknown as BlackHolePage).bh.falls)).toBe(1);
    expect(await g.page.locator('[data-hud="message"]').textContent()).toMatch(/^Swallowed/);
    // The fall flashes the field red and says so over it (it had no feedback but the spiral and the
    // status line): on level 1, practice, that it cost no life (elsewhere, the lives left).
    const death = await g.waitFor(() => {
      const d = (window.game as unknown as BlackHolePage).deathEffect();
      return d.flashPeak > 0 ? d : null;
    }, null);
    expect(death.count).toBe(1);
    // While the ship spirals in, a caption at the hole says what happened (the words in the field's
    // top band, far from where the eye was, were the only words).
    expect(await g.waitFor(() => (window.game as unknown as BlackHolePage).deathEffect().caption, null)).toBe('Swallowed!');
    // The words stay while the new ship waits parked for the player's thrust: in the ready beat after
    // the respawn (a press then is dropped) they say to wait, then how to fly on (read when the flash
    // was first seen: on a loaded machine that may be after the beat).
    expect(death.text).toMatch(/^Swallowed!\nPractice: no life lost\n(Get ready…|(Press|Tap) ↑, ← or → to fly on)$/);
    // While the words of the fall show, the path's label is not drawn under them.
    const shown = await g.waitFor(() => {
      const w = window.game as unknown as BlackHolePage;
      return w.deathEffect().shown ? { label: w.pathLabel(), path: w.pathPoints() } : null;
    }, null);
    expect(shown.path).toBeGreaterThan(0);
    expect(shown.label).toBe('');
    // The new ship waits with its engine off: no gauge.
    expect(await g.page.evaluate(() => (window.game as unknown as BlackHolePage).engineGauge())).toBe(0);
    const go = await g.waitFor(() => {
      const w = window.game as unknown as BlackHolePage & { readyLeft(): number };
      return w.readyLeft() === 0 && w.deathEffect().shown && !w.deathEffect().text.endsWith('Get ready…') ? w.deathEffect().text : null;
    }, null);
    expect(go).toMatch(/^Swallowed!\nPractice: no life lost\n(Press|Tap) ↑, ← or → to fly on$/);
    await g.page.keyboard.down('ArrowLeft');
    await g.waitFor(() => !(window.game as unknown as BlackHolePage).bh.message.startsWith('Swallowed'), null);
    // Paused as soon as the edge warns, so the ship cannot leave the field meanwhile: ↑ pressed
    // with ← still held thrusts up and left at once and both arrows of the pad light up (before, the
    // last key pressed was the only thrust); letting ← go leaves ↑, and ↑ then none.
    await g.waitFor(() => {
      const w = window.game as unknown as BlackHolePage & { paused: boolean };
      if (w.edgeWarning()) w.paused = true;
      return w.paused;
    }, null);
    // The path with ← held runs off the field's edge: drawn as lost (red, a cross at the edge), not blue.
    await g.waitFor(() => (window.game as unknown as BlackHolePage).pathEnd() === 'lost', null);
    expect(await g.page.evaluate(() => (window.game as unknown as BlackHolePage).pathLabel())).toBe('lost');
    const thrust = () => g.page.evaluate(() => (window.game as unknown as { bh: { thrust: string } }).bh.thrust);
    await g.page.keyboard.down('ArrowUp');
    expect(await thrust()).toBe('up-left');
    await g.waitFor(() => document.querySelectorAll('.bh-pad button.on').length === 2, null);
    await g.page.keyboard.up('ArrowLeft');
    expect(await thrust()).toBe('up');
    await g.page.keyboard.up('ArrowUp');
    expect(await thrust()).toBe('none');
    await g.page.evaluate(() => {
      (window.game as unknown as { paused: boolean }).paused = false;
    });
    expect(g.errors).toEqual([]);
  });

  it('a path that runs its length mid-field, short of a hole straight ahead, is grey, not blue', async () => {
    type Bh = BlackHolePage & {
      paused: boolean;
      reset(): void;
      bh: { ship: number; holes: number[]; lineY: number; world: { components: Record<string, { x: Float64Array; y: Float64Array }> } };
      level: { parked: boolean };
      pathPoints(): number;
      padPath(): boolean;
    };
    // The ship put 9 m straight below level 1's first hole, creeping up at 0.2 m/s: 3 s of path stop
    // well short of the hole and of the line, so whether it clears is not decided yet.
    await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.reset();
      w.paused = true;
      const c = w.bh.world.components,
        s = w.bh.ship % 2 ** 25,
        hole = w.bh.holes[0]! % 2 ** 25;
      c.Position!.x[s] = c.PreviousPosition!.x[s] = c.Position!.x[hole]!;
      c.Position!.y[s] = c.PreviousPosition!.y[s] = c.Position!.y[hole]! - 9;
      c.Velocity!.x[s] = 0;
      c.Velocity!.y[s] = 0.2;
      w.level.parked = false;
    });
    const drawn = await g.waitFor(() => {
      const w = window.game as unknown as Bh;
      return !w.padPath() && w.pathPoints() > 100 ? { shade: w.pathShade(), end: w.pathEnd(), label: w.pathLabel() } : null;
    }, null);
    expect(drawn).toEqual({ shade: 'open', end: 'clear', label: '' });
    await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.reset();
      w.paused = false;
    });
    expect(g.errors).toEqual([]);
  });
});

describe('black hole, words off the holes and the continue panel', () => {
  it("the path's words, the edge warning and the caption of a fall cover no hole, nor the continue panel after the last life", async () => {
    // The issue this answers: "predicted path, next 3 s" was drawn over level 1's hole, the edge
    // warning over the hole the path was about to fall into, and a fading "Swallowed!" over the
    // game-over panel. Paused and set up by hand, so nothing depends on the machine's speed.
    type Cam = { toScreenX(x: number): number; toScreenY(y: number): number };
    type Bh = {
      paused: boolean;
      reset(): void;
      step(): void;
      renderer: { camera: Cam };
      bh: {
        ship: number;
        holes: number[];
        lives: number;
        over: boolean;
        parked: boolean;
        holeRadius: number[];
        field: { width: number; height: number };
        world: { components: Record<string, { x: Float64Array; y: Float64Array }> };
      };
      level: { parked: boolean; spec: { practice: boolean } };
      holeExtents(): number[][];
      textBox(name: string): number[];
      pathHint(): string;
      pathEnd(): string;
      edgeWarning(): boolean;
      swallowing(): boolean;
      renewPathHint(): void;
    };
    const frames = (n: number) => g.frames(n);
    /** In the page: the ship (and, given, hole 0) put at places, m, paused; the ship's velocity, m/s. */
    const put = (ship: number[], hole?: number[]) =>
      g.page.evaluate(
        ([ship, hole]) => {
          const w = window.game as unknown as Bh;
          w.paused = true;
          const c = w.bh.world.components,
            s = w.bh.ship % 2 ** 25,
            k = w.bh.holes[0]! % 2 ** 25;
          if (hole) [c.Position!.x[k], c.Position!.y[k]] = [hole[0]!, hole[1]!];
          c.Position!.x[s] = c.PreviousPosition!.x[s] = ship[0]!;
          c.Position!.y[s] = c.PreviousPosition!.y[s] = ship[1]!;
          c.Velocity!.x[s] = ship[2]!;
          c.Velocity!.y[s] = ship[3]!;
          w.level.parked = w.bh.parked = false;
        },
        [ship, hole] as const,
      );
    /** In the page: how many holes' drawings (`holeExtents`) the text's box overlaps, or -1 when it is not shown. */
    const overHoles = (name: string) =>
      g.page.evaluate((name) => {
        const w = window.game as unknown as Bh;
        const shown =
          name === 'edge' ? w.edgeWarning() : name === 'pathHint' ? w.pathHint() !== '' && w.pathEnd() === 'clear' : w.swallowing();
        if (!shown) return -1;
        const cam = w.renderer.camera;
        const [l, t, r, b] = w.textBox(name);
        return w
          .holeExtents()
          .filter(
            ([x0, x1, y0, y1]) => cam.toScreenX(x1!) > l! && cam.toScreenX(x0!) < r! && cam.toScreenY(y0!) > t! && cam.toScreenY(y1!) < b!,
          ).length;
      }, name);
    const hole = await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.reset();
      // The path's words show the first times only: earlier tests on this page may have used them up.
      w.renewPathHint();
      const c = w.bh.world.components,
        k = w.bh.holes[0]! % 2 ** 25;
      return [c.Position!.x[k]!, c.Position!.y[k]!, w.bh.field.width, w.bh.field.height];
    });
    const [hx, hy, W, H] = hole as [number, number, number, number];
    // The ship down and to the left of the hole, drifting up and away: the grey path runs on to end
    // just left of and below the hole, where its words, to the right of its end, lay over the hole.
    const shown: string[] = [];
    for (const [dx, dy] of [
      [-3.5, -4],
      [-4, -4],
      [-4, -3],
    ]) {
      await put([hx + dx!, hy + dy!, -0.8, 0.8]);
      await frames(3);
      const n = await overHoles('pathHint');
      if (n >= 0) shown.push(`${dx},${dy}: ${n}`);
    }
    expect(shown.length, 'the path hint shown').toBeGreaterThan(0);
    expect(
      shown.filter((t) => !t.endsWith(': 0')),
      'the path hint over a hole',
    ).toEqual([]);
    // The hole where the edge warning is put first (a quarter of the way down, mid-field), the ship
    // at the left edge: the warning goes elsewhere.
    await put([1.2, 6, 0, 0.5], [W / 2, 0.75 * H - 0.3]);
    await frames(3);
    expect(await overHoles('edge'), 'the edge warning over a hole (-1: not shown)').toBe(0);
    // The last life lost (not practice) into a hole high up, whose caption above it stood where the
    // continue panel first showed: the caption keeps off the panel in every frame of the swallow.
    await put([W / 2, 0.45 * H - 3, 0, 3], [W / 2, 0.45 * H]);
    const over = await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.level.spec = { ...w.level.spec, practice: false };
      w.bh.lives = 1;
      for (let i = 0; i < 120 && !w.bh.over; i++) w.step();
      return w.bh.over;
    });
    expect(over).toBe(true);
    const hits: string[] = [];
    for (let i = 0; i < 6; i++) {
      await frames(1);
      const seen = await g.page.evaluate(() => {
        const w = window.game as unknown as Bh;
        if (!w.swallowing()) return null;
        const bar = document.querySelector<HTMLElement>('.bp-touchbar.bp-action');
        const c = document.querySelector('canvas')!.getBoundingClientRect();
        const [l, t, r, b] = w.textBox('swallow');
        const covered = Array.from(bar?.children ?? [])
          .map((e) => e.getBoundingClientRect())
          .filter((e) => e.height > 0 && e.left - c.left < r! && e.right - c.left > l! && e.top - c.top < b! && e.bottom - c.top > t!);
        return covered.length;
      });
      if (seen === null) break;
      if (seen > 0) hits.push(`frame ${i}: ${seen}`);
    }
    expect(hits, 'the caption of the last fall over the continue panel').toEqual([]);
    await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.reset();
      w.paused = false;
    });
    expect(g.errors).toEqual([]);
  });
});

describe('black hole, the coach by a near ring', () => {
  it('with the ring 1.3 m away the coach says tap, and a tap of what it names flies through the ring', async () => {
    // The issue this answers: "Hold → and ↑ to fly through it" showed with the ring some 40 px away,
    // and → held half a second flew the ship past the ring, off the top.
    type Bh = {
      paused: boolean;
      reset(): void;
      step(): void;
      coach(): string;
      readyLeft(): number;
      bh: {
        ship: number;
        holes: number[];
        parked: boolean;
        field: { width: number };
        world: { components: Record<string, { x: Float64Array; y: Float64Array }> };
      };
      level: { parked: boolean; rings: number[][]; ringsTaken: number };
    };
    /** In the page: the ship at rest `dx`, `dy` m from level 1's ring (towards the middle), unpaused (the coach shows only then). */
    const put = (dx: number, dy: number) =>
      g.page.evaluate(
        ([dx, dy]) => {
          const w = window.game as unknown as Bh;
          const c = w.bh.world.components,
            s = w.bh.ship % 2 ** 25,
            [rx, ry] = w.level.rings[0]!;
          c.Position!.x[s] = c.PreviousPosition!.x[s] = rx! + dx!;
          c.Position!.y[s] = c.PreviousPosition!.y[s] = ry! + dy!;
          c.Velocity!.x[s] = c.Velocity!.y[s] = 0;
          // The hole far off in a lower corner across from the ring, so its pull does not move the ship
          // while the frames run (the coach reads its path only unpaused): what it says holds for the
          // ship at rest there, however slow the frames.
          const k = w.bh.holes[0]! % 2 ** 25;
          c.Position!.x[k] = rx! < w.bh.field.width / 2 ? w.bh.field.width - 2 : 2;
          c.Position!.y[k] = 3;
          w.level.parked = w.bh.parked = false;
          w.level.ringsTaken = 0;
          w.paused = false;
        },
        [dx, dy],
      );
    const coach = () => g.waitFor(() => (window.game as unknown as Bh).coach(), null);
    // A new game, its ready moment (no thrust for a second of the wall clock after a restart) over.
    await g.page.evaluate(() => (window.game as unknown as Bh).reset());
    await g.frames(2);
    await g.waitFor(() => (window.game as unknown as Bh).readyLeft() === 0, null);
    const side = await g.page.evaluate(() => {
      const w = window.game as unknown as Bh & { bh: { field: { width: number } } };
      return w.level.rings[0]![0]! < w.bh.field.width / 2 ? 1 : -1;
    });
    await put(side * 0.5, -1.2);
    await g.frames(2);
    const near = await coach();
    expect(near).toMatch(/^Gold ring first!\nTap (↑|[←→]( and ↑)?) to fly through it\.$/);
    // Do as it says: the arrows it names, pressed and let go at once (a tap: TAP_STEPS of thrust),
    // then 3 s of steps: the ship flies through the ring.
    const taken = await g.page.evaluate((words) => {
      const w = window.game as unknown as Bh;
      w.paused = true;
      // Back where the coach read the path (the holes' pull moved it meanwhile), at rest.
      const c = w.bh.world.components,
        s = w.bh.ship % 2 ** 25,
        [rx, ry] = w.level.rings[0]!;
      c.Position!.x[s] = c.PreviousPosition!.x[s] = rx! + (rx! < w.bh.field.width / 2 ? 0.5 : -0.5);
      c.Position!.y[s] = c.PreviousPosition!.y[s] = ry! - 1.2;
      c.Velocity!.x[s] = c.Velocity!.y[s] = 0;
      const keys: Record<string, string> = { '←': 'ArrowLeft', '→': 'ArrowRight', '↑': 'ArrowUp' };
      const named = [...words.split('\n')[1]!].filter((c) => c in keys).map((c) => keys[c]!);
      // Down and up in one task, unpaused (paused, a key let go lets go at once), then paused again.
      w.paused = false;
      for (const key of named) window.dispatchEvent(new KeyboardEvent('keydown', { key, code: key }));
      for (const key of named) window.dispatchEvent(new KeyboardEvent('keyup', { key, code: key }));
      w.paused = true;
      for (let i = 0; i < 180 && w.level.ringsTaken === 0; i++) w.step();
      return w.level.ringsTaken;
    }, near);
    expect(taken, near).toBe(1);
    // Far below the ring: held arrows (a tap would not reach it within the 3 s the coach looks ahead).
    await put(side * 4, -9);
    await g.frames(2);
    expect(await coach()).toMatch(/^Gold ring first!\nHold /);
    await g.page.evaluate(() => (window.game as unknown as Bh).reset());
    expect(g.errors).toEqual([]);
  });
});

describe('black hole, the replay clock and the paused path words', () => {
  it("the replay's clock is the attempt's game time: the wait on the pad it skips is not counted", async () => {
    type Bh = BlackHolePage & {
      paused: boolean;
      reset(): void;
      step(): void;
      replayClock(): number;
      replay: { player: unknown; play(): void };
      level: { parked: boolean; time: number; attemptStart: number };
    };
    // Paused, stepped by hand: 2 s parked on the pad, ↑ pressed for 0.5 s, 0.5 s more of flight.
    const run = await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.reset();
      w.paused = true;
      for (let i = 0; i < 120; i++) w.step();
      window.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowUp', code: 'ArrowUp' }));
      for (let i = 0; i < 30; i++) w.step();
      window.dispatchEvent(new KeyboardEvent('keyup', { key: 'ArrowUp', code: 'ArrowUp' }));
      for (let i = 0; i < 30; i++) w.step();
      const live = w.level.time - w.level.attemptStart;
      // The replay of it, stepped to its end: its clock at lift-off and at the end.
      w.replay.play();
      let atLiftOff = -1,
        last = -1;
      for (let i = 0; i < 400 && w.replay.player; i++) {
        w.step();
        if (w.replay.player) last = w.replayClock();
        if (atLiftOff < 0 && !w.level.parked) atLiftOff = w.replayClock();
      }
      return { live, atLiftOff, last, done: w.replay.player === null };
    });
    expect(run.done).toBe(true);
    // The attempt flew 1 s (60 steps of 1/60 s); counted with the skipped wait it showed 3 s and more.
    expect(run.live).toBeCloseTo(1, 6);
    expect(run.atLiftOff).toBeLessThan(0.05);
    expect(Math.abs(run.last - run.live)).toBeLessThanOrEqual(1 / 60 + 1e-9);
    await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.reset();
      w.paused = false;
    });
    expect(g.errors).toEqual([]);
  });

  it('paused, the words of a path that reaches the line stand clear of "Paused" (in the status row, above the field)', async () => {
    type Bh = BlackHolePage & {
      paused: boolean;
      reset(): void;
      pathHint(): string;
      textBox(name: string): number[];
      pauseWordsBox(): number[];
      pauseOverlay(): { visible: boolean; words: boolean };
      renderer: { camera: { toScreenY(y: number): number } };
      bh: { ship: number; lineY: number; world: { components: Record<string, { x: Float64Array; y: Float64Array }> } };
      level: { parked: boolean; ringsTaken: number; rings: unknown[] };
    };
    // The ship 6 m under the line, flying up at 4 m/s, right of the middle: its path reaches the line
    // in the band above the line, where "Paused" was drawn (the words by its end were drawn over it).
    await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.reset();
      const c = w.bh.world.components,
        s = w.bh.ship % 2 ** 25;
      c.Position!.x[s] = c.PreviousPosition!.x[s] = 22;
      c.Position!.y[s] = c.PreviousPosition!.y[s] = w.bh.lineY - 6;
      c.Velocity!.x[s] = 0;
      c.Velocity!.y[s] = 4;
      w.level.parked = false;
      // The ring taken: the line counts, so the path reaches it.
      w.level.ringsTaken = w.level.rings.length;
      w.paused = true;
    });
    const boxes = await g.waitFor(() => {
      const w = window.game as unknown as Bh;
      const o = w.pauseOverlay();
      return o.visible && o.words && w.pathHint() !== ''
        ? { hint: w.textBox('pathHint'), pause: w.pauseWordsBox(), line: w.renderer.camera.toScreenY(w.bh.lineY), text: w.pathHint() }
        : null;
    }, null);
    expect(boxes.text).toBe('predicted path: reaches the line');
    const [l, t, r, b] = boxes.hint;
    const [pl, pt, pr, pb] = boxes.pause;
    expect(l! < pr! && pl! < r! && t! < pb! && pt! < b!, JSON.stringify(boxes)).toBe(false);
    // The settings panel opened (it lay over the field's top right corner, over the line and the path
    // there): the field is drawn left of it, and fills the stage again when it closes. 1 px for rounding.
    type Fit = { renderer: { camera: { toScreenX(x: number): number } }; bh: { field: { width: number } } };
    // The field's right edge and the panel's left edge (0 wide: closed), px in the page.
    const edges = (): { right: number; side: number; open: boolean } => {
      const w = window.game as unknown as Fit,
        side = document.querySelector('.bp-side')!.getBoundingClientRect();
      const right = document.querySelector('canvas')!.getBoundingClientRect().left + w.renderer.camera.toScreenX(w.bh.field.width);
      return { right, side: side.left, open: side.width > 0 };
    };
    const before = await g.page.evaluate(edges);
    expect(before.open).toBe(false);
    await g.page.getByRole('button', { name: 'parameters and charts' }).click();
    const beside = await g.waitFor(() => {
      const w = window.game as unknown as Fit,
        side = document.querySelector('.bp-side')!.getBoundingClientRect();
      const right = document.querySelector('canvas')!.getBoundingClientRect().left + w.renderer.camera.toScreenX(w.bh.field.width);
      return side.width > 0 && right <= side.left + 1 ? { right, side: side.left } : null;
    }, null);
    expect(beside.right).toBeLessThan(before.right);
    await g.page.getByRole('button', { name: 'parameters and charts' }).click();
    // The panel closes at once; the field is fitted to the stage again by the next frame's resize, so
    // wait for that frame rather than reading the edge in the same frame the panel closed.
    const back = await g.waitFor((wanted: number) => {
      const w = window.game as unknown as Fit,
        side = document.querySelector('.bp-side')!.getBoundingClientRect();
      const right = document.querySelector('canvas')!.getBoundingClientRect().left + w.renderer.camera.toScreenX(w.bh.field.width);
      return side.width === 0 && Math.abs(right - wanted) < 1 ? { right } : null;
    }, before.right);
    expect(Math.abs(back.right - before.right)).toBeLessThan(1);
    await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.reset();
      w.paused = false;
    });
    expect(g.errors).toEqual([]);
  });
});

describe('black hole, the ready moment', () => {
  it('after a fall the new ship waits out a ready beat of the wall clock, however many steps a slow frame runs meanwhile; an arrow pressed in it never thrusts, a fresh press after it does', async () => {
    type Bh = BlackHolePage & {
      paused: boolean;
      reset(): void;
      step(): void;
      readyLeft(): number;
      bh: { ship: number; holes: number[]; thrust: string; world: { components: Record<string, { x: Float64Array; y: Float64Array }> } };
      level: { parked: boolean };
    };
    // In one task (no wall-clock time to speak of passes): the ship put on level 1's first hole falls
    // in; then 120 steps (2 s of game time, as a burst of catch-up steps after a slow frame would
    // run), and ← pressed. The ship still waits (by steps, the moment of 60 steps was over).
    const early = await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.reset();
      w.paused = true;
      const c = w.bh.world.components,
        s = w.bh.ship % 2 ** 25,
        hole = w.bh.holes[0]! % 2 ** 25;
      const falls = w.bh.falls;
      c.Position!.x[s] = c.PreviousPosition!.x[s] = c.Position!.x[hole]!;
      c.Position!.y[s] = c.PreviousPosition!.y[s] = c.Position!.y[hole]!;
      w.level.parked = false;
      for (let i = 0; i < 600 && w.bh.falls === falls; i++) w.step();
      const fell = w.bh.falls > falls;
      for (let i = 0; i < 120; i++) w.step();
      window.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowLeft' }));
      return { fell, left: w.readyLeft(), thrust: w.bh.thrust };
    });
    expect(early.fell).toBe(true);
    expect(early.left).toBeGreaterThan(0);
    expect(early.thrust).toBe('none');
    // Running again: the beat ends, and the arrow pressed in it (an "ok" after the fall, still held)
    // does not launch the ship, for 30 steps after (it did, at the beat's first step after).
    await g.page.evaluate(() => {
      (window.game as unknown as Bh).paused = false;
    });
    await g.waitFor(() => (window.game as unknown as Bh).readyLeft() === 0, null);
    await g.runFrames(30, { draw: false });
    const held = await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      return { thrust: w.bh.thrust, parked: w.level.parked };
    });
    expect(held).toEqual({ thrust: 'none', parked: true });
    // A fresh press after the beat thrusts at once.
    const fresh = await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      window.dispatchEvent(new KeyboardEvent('keyup', { key: 'ArrowLeft' }));
      window.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowLeft' }));
      w.step();
      const thrust = w.bh.thrust;
      window.dispatchEvent(new KeyboardEvent('keyup', { key: 'ArrowLeft' }));
      w.reset();
      return thrust;
    });
    expect(fresh).toBe('left');
    expect(g.errors).toEqual([]);
  });
});

describe('black hole, the start pad', () => {
  it('↓ held on the pad leaves the ship parked there: no "Off the field", no reset, for 2.5 s of game time', async () => {
    // A stranger's first key was ↓: the ship flew off the field's foot in under 1 s.
    type Bh = {
      reset(): void;
      bh: {
        ship: number;
        resets: number;
        message: string;
        start: number[];
        world: { steps: number; components: Record<string, { y: Float64Array }> };
      };
      level: { parked: boolean };
    };
    // A page of its own: keys the other cases pressed on the shared one must not steer this ship.
    const p = await h.openGame('black-hole', { query: { level: 1 } });
    const before = await p.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      return { resets: w.bh.resets, steps: w.bh.world.steps };
    });
    await p.page.keyboard.down('ArrowDown');
    // The ready moment (1 s) and then 1.5 s of ↓ held, at 60 steps a second.
    await p.waitFor((n) => (window.game as unknown as Bh).bh.world.steps >= n, before.steps + 150, 30_000);
    const after = await p.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      return {
        resets: w.bh.resets,
        message: w.bh.message,
        parked: w.level.parked,
        dy: w.bh.world.components.Position!.y[w.bh.ship % 2 ** 25]! - w.bh.start[1]!,
      };
    });
    await p.page.keyboard.up('ArrowDown');
    expect(after.message).not.toMatch(/Off the field/);
    expect([after.resets, after.parked, after.dy]).toEqual([before.resets, true, 0]);
    expect(p.errors).toEqual([]);
    await p.close();
  });
});

describe('black hole, between levels', () => {
  it('a cleared level takes its holes off the field (drawn dimmed) while the ship waits; Enter lays out the next', async () => {
    type Bh = BlackHolePage & {
      paused: boolean;
      reset(): void;
      step(): void;
      ship(): number[];
      scorePop(): string;
      bh: { ship: number; lineY: number; holes: number[]; world: { components: { Position: { y: Float64Array } } } };
      level: { waiting: boolean; spec: { level: number; holes: number }; summary: { points: number } | null };
    };
    // A fall on level 1 first (the ship put on its hole), then the ship put just over the green line:
    // the next step clears level 1.
    const cleared = await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.reset();
      w.paused = true;
      const c = w.bh.world.components as unknown as Record<string, { x: Float64Array; y: Float64Array }>,
        s = w.bh.ship % 2 ** 25,
        hole = w.bh.holes[0]! % 2 ** 25;
      c.Position!.x[s] = c.PreviousPosition!.x[s] = c.Position!.x[hole]!;
      c.Position!.y[s] = c.PreviousPosition!.y[s] = c.Position!.y[hole]!;
      (w.level as unknown as { parked: boolean }).parked = false;
      for (let i = 0; i < 600 && (w.bh as unknown as { falls: number }).falls === 0; i++) w.step();
      (w.level as unknown as { ringsTaken: number }).ringsTaken = 1;
      w.bh.world.components.Position.y[w.bh.ship % 2 ** 25] = w.bh.lineY + 0.3;
      w.step();
      const during = { waiting: w.level.waiting, next: w.level.spec.level, holes: w.bh.holes.length, y: w.ship()[1]! };
      for (let i = 0; i < 30; i++) w.step();
      return { during, later: w.bh.holes.length, line: w.bh.lineY };
    });
    // Waiting on level 2: no live hole on the field (before, level 2's holes were laid out at once, round
    // the frozen ship), the ship at rest where it crossed, at or past the line (it was put back at
    // the start, which looked as if it fell back below the line it had reached).
    expect(cleared.during).toMatchObject({ waiting: true, next: 2, holes: 0 });
    expect(cleared.during.y).toBeGreaterThanOrEqual(cleared.line);
    expect(cleared.later).toBe(0);
    // The points the clear made rise from the line (they were only in the status row's numbers).
    const pop = await g.waitFor(() => (window.game as unknown as Bh).scorePop(), null);
    expect(pop).toBe(`+${await g.page.evaluate(() => (window.game as unknown as Bh).level.summary!.points)}`);
    // The cleared level's holes stay on the field, dimmed, under the summary (an empty field round the
    // ship looked like a glitch); no live hole is on it meanwhile.
    expect(await g.waitFor(() => (window.game as unknown as Bh).ghostHoles() || null, null)).toBe(true);
    expect(await g.page.evaluate(() => (window.game as unknown as Bh).bh.holes.length)).toBe(0);
    await g.page.evaluate(() => {
      (window.game as unknown as Bh).paused = false;
    });
    await g.page.keyboard.press('Enter');
    const begun = await g.waitFor(() => {
      const w = window.game as unknown as Bh;
      return w.level.waiting ? null : { holes: w.bh.holes.length, level: w.level.spec.level };
    }, null);
    // Level 2: a wall of holes across the field (how many depends on the field's width).
    expect(begun.level).toBe(2);
    expect(begun.holes).toBeGreaterThan(5);
    // Its title shows in the open field under the wall, over none of its holes (it covered the gap).
    const wallBanner = await g.waitFor(() => {
      const w = window.game as unknown as { holeExtents(): number[][]; levelBanner(): string; bh: { holes: number[] } };
      return w.holeExtents().length === w.bh.holes.length && w.levelBanner().startsWith('Level 2') ? true : null;
    }, null);
    expect(wallBanner).toBe(true);
    // The fall on level 1 is history: no "Swallowed! Practice: no life lost" over level 2's title.
    await g.frames(2);
    expect(await g.page.evaluate(() => (window.game as unknown as BlackHolePage).deathEffect().shown), 'fall words on level 2').toBe(false);
    expect(await g.page.evaluate(() => (window.game as unknown as Bh).ghostHoles())).toBe(false);
    expect(await g.page.evaluate(bannerOverHoles)).toMatchObject({ hits: 0, holes: begun.holes });
    // The last life lost on level 2 (the ship put into a hole): the button and Enter go on from level 2
    // with three lives and a score of 0, not back to level 1.
    const over = await g.page.evaluate(() => {
      const w = window.game as unknown as Bh & {
        bh: { lives: number; over: boolean; world: { components: { Position: { x: Float64Array } } } };
      };
      w.paused = true;
      w.bh.lives = 1;
      (w.level as unknown as { parked: boolean }).parked = false;
      const P = w.bh.world.components.Position,
        s = w.bh.ship % 2 ** 25,
        hole = w.bh.holes[0]! % 2 ** 25;
      P.x[s] = P.x[hole]!;
      w.bh.world.components.Position.y[s] = w.bh.world.components.Position.y[hole]!;
      w.step();
      w.paused = false;
      return w.bh.over;
    });
    expect(over).toBe(true);
    await g.page.getByRole('button', { name: 'Continue from level 2 ↺' }).waitFor({ state: 'visible', timeout: 10_000 });
    // Paused over the game-over card: one message, the card's (the pause's words are not drawn over it).
    type Words = { paused: boolean; pauseOverlay(): { visible: boolean; words: boolean } };
    await g.page.evaluate(() => {
      (window.game as unknown as Words).paused = true;
    });
    const pausedOver = await g.waitFor(() => {
      const o = (window.game as unknown as Words).pauseOverlay();
      return o.visible ? o : null;
    }, null);
    expect(pausedOver.words, 'pause words over the game-over card').toBe(false);
    await g.page.evaluate(() => {
      (window.game as unknown as Words).paused = false;
    });
    // The button covers no hole of the wall left on the field (it sat on the middle of the field, over
    // a hole): its box is clear of every hole's horizon, 1.5 radii round (the photon ring and disc).
    const covered = await g.waitFor(() => {
      type Cam = { toScreenX(x: number): number; toScreenY(y: number): number; toScreenLength(l: number): number };
      const w = window.game as unknown as {
        renderer: { camera: Cam };
        bh: { holes: number[]; holeRadius: number[]; world: { components: { Position: { x: Float64Array; y: Float64Array } } } };
      };
      const button = [...document.querySelectorAll('button')].find((b) => b.textContent === 'Continue from level 2 ↺');
      if (!button) return null;
      const b = button.getBoundingClientRect(),
        c = document.querySelector('canvas')!.getBoundingClientRect(),
        cam = w.renderer.camera,
        P = w.bh.world.components.Position;
      const hits = w.bh.holes.filter((h, i) => {
        const x = c.left + cam.toScreenX(P.x[h % 2 ** 25]!),
          y = c.top + cam.toScreenY(P.y[h % 2 ** 25]!),
          r = 1.5 * cam.toScreenLength(w.bh.holeRadius[i]!);
        return x + r > b.left && x - r < b.right && y + r > b.top && y - r < b.bottom;
      });
      return { hits: hits.length, holes: w.bh.holes.length };
    }, null);
    expect(covered.holes).toBeGreaterThan(5);
    expect(covered.hits).toBe(0);
    expect(await g.page.locator('[data-hud="message"]').textContent()).toContain('Enter: continue from level 2 (score resets to 0).');
    // The game-over card above the button keeps the final score and the best (the score went to 0
    // with no record of it); the best is the page's, at least the final score.
    const card = await g.page.evaluate(() => {
      const w = window.game as unknown as { overCard(): string; best: number; bh: { score: number } };
      return { text: w.overCard(), best: w.best, score: w.bh.score };
    });
    expect(card.score).toBeGreaterThan(0);
    expect(card.best).toBeGreaterThanOrEqual(card.score);
    // And says what Continue does: the score does not carry over (it was reset with no word of it).
    expect(card.text).toMatch(
      new RegExp(
        `^Game over\nFinal score ${card.score}\n(Best ${card.best}|New best! \\(was \\d+\\))\nContinue: level 2 again, score resets to 0$`,
      ),
    );
    await g.page.keyboard.press('Enter');
    const again = await g.waitFor(() => {
      const w = window.game as unknown as Bh & { bh: { lives: number; over: boolean; score: number } };
      return w.bh.over ? null : { level: w.level.spec.level, lives: w.bh.lives, score: w.bh.score };
    }, null);
    expect(again).toEqual({ level: 2, lives: 3, score: 0 });
    expect(await g.page.evaluate(() => (window.game as unknown as { overCard(): string }).overCard())).toBe('');
    expect(g.errors).toEqual([]);
  });
  it('paused, the next level begun: its holes are drawn in the next frame, even with the frame pacer skipping every frame', async () => {
    type Cam = { toScreenX(x: number): number; toScreenY(y: number): number; toScreenLength(l: number): number };
    type Bh = {
      paused: boolean;
      reset(): void;
      step(): void;
      advance(): void;
      renderer: { camera: Cam };
      pacer: { drawn: number; mayDraw(): boolean };
      bh: {
        ship: number;
        lineY: number;
        holes: number[];
        holeRadius: number[];
        world: { components: { Position: { x: Float64Array; y: Float64Array } } };
      };
      level: { waiting: boolean };
    };
    // Level 1 cleared while paused; then the pacer refuses every frame (a GPU far behind), so only a
    // frame the game asks for is drawn.
    const drawnBefore = await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.reset();
      w.paused = true;
      (w.level as unknown as { ringsTaken: number }).ringsTaken = 1;
      w.bh.world.components.Position.y[w.bh.ship % 2 ** 25] = w.bh.lineY + 0.3;
      w.step();
      (window as unknown as { keptMayDraw: () => boolean }).keptMayDraw = w.pacer.mayDraw;
      w.pacer.mayDraw = () => false;
      return w.pacer.drawn;
    });
    expect(await g.page.evaluate(() => (window.game as unknown as Bh).level.waiting)).toBe(true);
    // The frame of the clear (the emptied field) is drawn.
    await g.waitFor((n) => (window.game as unknown as Bh).pacer.drawn > n, drawnBefore);
    // The canvas as it shows the empty field, before the level begins.
    const before = decodePng(await g.page.screenshot());
    const { holes, drawnAtBegin } = await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.advance();
      const cam = w.renderer.camera,
        c = document.querySelector('canvas')!.getBoundingClientRect(),
        P = w.bh.world.components.Position;
      return {
        drawnAtBegin: w.pacer.drawn,
        holes: w.bh.holes.map((h, i) => ({
          x: c.left + cam.toScreenX(P.x[h % 2 ** 25]!),
          y: c.top + cam.toScreenY(P.y[h % 2 ** 25]!),
          r: cam.toScreenLength(w.bh.holeRadius[i]!),
        })),
      };
    });
    expect(holes.length).toBeGreaterThan(5);
    await g.waitFor((n) => (window.game as unknown as Bh).pacer.drawn > n, drawnAtBegin);
    const after = decodePng(await g.page.screenshot());
    expect([after.width, after.channels]).toEqual([before.width, before.channels]);
    // The square round the first hole's centre, 2 radii each way.
    const hole = holes[0]!;
    const half = Math.max(6, Math.round(2 * hole.r));
    let diff = 0,
      n = 0;
    for (let y = Math.round(hole.y) - half; y < Math.round(hole.y) + half; y++) {
      for (let x = Math.round(hole.x) - half; x < Math.round(hole.x) + half; x++) {
        if (x < 0 || y < 0 || x >= before.width || y >= before.height) continue;
        const o = (y * before.width + x) * before.channels;
        for (let k = 0; k < 3; k++) diff += Math.abs(before.data[o + k]! - after.data[o + k]!);
        n += 3;
      }
    }
    diff /= n;
    // Mean difference per colour channel, 0 to 255: the hole's glow, ring and disc over the dark field.
    expect(diff).toBeGreaterThan(8);
    await g.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.pacer.mayDraw = (window as unknown as { keptMayDraw: () => boolean }).keptMayDraw;
      w.paused = false;
    });
    expect(g.errors).toEqual([]);
  });
  // The thrust pad cases below open pages of their own; this page would otherwise keep running
  // (stepping and drawing on the shared software GPU) beside them until the file ends.
  afterAll(async () => {
    await g?.close();
  });
});

describe.each([
  { device: 'desktop', viewport: { width: 1280, height: 800 }, touch: false },
  { device: 'phone', viewport: { width: 390, height: 844 }, touch: true },
] as const)('black hole thrust pad ($device)', ({ device, viewport, touch }) => {
  it('a finger (or the mouse) held on ↑ and slid onto → turns the thrust right; lifting it stops; the ship is drawn at least 26 px; the next-level button leaves the pad and the ship clear and starts level 2; on a phone ↑ held thrusts up and after the game a tap on the scene plays again', async () => {
    const p = await h.openGame('black-hole', { viewport, touch, query: { level: 1 }, ...(touch ? { locale: 'en-US@posix' } : {}) });
    if (touch) await checkPageContract(p, 'black-hole', 'phone');
    // Where the field stands: it stays there as the status line changes (level 1's opening line took
    // three lines on a phone, the lines after it two, and the field moved 10 px each time).
    const field = () =>
      p.page.evaluate(() => {
        const m = document.querySelector<HTMLElement>('[data-hud="message"]')!;
        const lines = m.offsetHeight / Number.parseFloat(getComputedStyle(m).lineHeight);
        return { top: document.querySelector('canvas')!.getBoundingClientRect().top, lines, text: m.textContent };
      });
    const field0 = await field();
    expect(field0.lines, field0.text ?? '').toBeLessThan(2.5);
    if (touch) {
      // The touch hint at the start lies clear of the ship waiting at the start and of level 1's holes
      // (each with its glow, 3 radii round): at the stage's foot it covered the ship.
      const overlaps = await p.page.evaluate(() => {
        type Cam = { toScreenX(x: number): number; toScreenY(y: number): number; toScreenLength(l: number): number };
        const w = window.game as unknown as {
          renderer: { camera: Cam };
          bh: { holes: number[]; holeRadius: number[]; world: { components: { Position: { x: Float64Array; y: Float64Array } } } };
          ship(): number[];
        };
        const cam = w.renderer.camera;
        const c = document.querySelector('canvas')!.getBoundingClientRect();
        // The kit's card goes after 9 s or at a touch: on a slow load it may be gone, and a card of
        // its class and text, put where the kit puts it, stands in for it (the page's style places both).
        let card = document.querySelector<HTMLElement>('[data-hud="touch-hint"]');
        if (!card) {
          card = document.createElement('div');
          card.className = 'bp-touch-hint';
          card.innerHTML = '<div><b>hold ↑ to fly, tap ← →</b><span>thumb between two: both</span></div>';
          document.querySelector('.bp-stage')!.append(card);
        }
        const hint = card.getBoundingClientRect();
        const hits = (name: string, x: number, y: number, px: number) => {
          const sx = c.left + cam.toScreenX(x),
            sy = c.top + cam.toScreenY(y);
          return sx + px > hint.left && sx - px < hint.right && sy + px > hint.top && sy - px < hint.bottom ? [name] : [];
        };
        const [x, y] = w.ship();
        const P = w.bh.world.components.Position;
        return [
          ...hits('ship', x!, y!, Math.max(16, cam.toScreenLength(0.8))),
          ...w.bh.holes.flatMap((h, i) =>
            hits(`hole ${i}`, P.x[h % 2 ** 25]!, P.y[h % 2 ** 25]!, cam.toScreenLength(3 * w.bh.holeRadius[i]!)),
          ),
        ];
      });
      expect(overlaps).toEqual([]);
      // The level's title is compact (at most two lines of 13 px or more) and lies between the field's
      // top edge and the finish line, off the ship's path up from the pad: four lines of 26 px
      // centred on the field sat right over it. 1 px of slack for the text's rounding.
      const title = await p.waitFor(() => {
        type Cam = { toScreenY(y: number): number };
        const w = window.game as unknown as {
          renderer: { camera: Cam };
          bh: { lineY: number; field: { height: number } };
          levelBanner(): string;
          levelBannerBox(): number[];
        };
        const text = w.levelBanner();
        if (!text) return null;
        const [, top, , bottom] = w.levelBannerBox();
        const cam = w.renderer.camera;
        return { text, top: top!, bottom: bottom!, fieldTop: cam.toScreenY(w.bh.field.height), line: cam.toScreenY(w.bh.lineY) };
      }, null);
      expect(title.text.split('\n').length, title.text).toBeLessThanOrEqual(2);
      expect(title.top, title.text).toBeGreaterThanOrEqual(title.fieldTop - 1);
      expect(title.bottom, title.text).toBeLessThanOrEqual(title.line + 1);
      expect((title.bottom - title.top) / title.text.split('\n').length, title.text).toBeGreaterThanOrEqual(13);
    }
    type Bh = { bh: { thrust: string }; shipPx(): number };
    if (touch) {
      // On the phone first: a finger held 0.4 s on ↑ thrusts the ship up; after the game a tap on the
      // scene plays again from the level lost (level 1 here), and a big button over the scene says so.
      const upBox = (await p.page.getByRole('button', { name: 'thrust up', exact: true }).boundingBox())!;
      const tap = await p.page.context().newCDPSession(p.page);
      const at = [{ x: upBox.x + upBox.width / 2, y: upBox.y + upBox.height / 2, id: 1 }];
      await tap.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at });
      await p.page.waitForTimeout(400);
      await tap.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
      await tap.detach();
      expect(await p.page.evaluate(() => (window.game as unknown as { ship(): number[] }).ship()[3])).toBeGreaterThan(0.2);
      await p.page.evaluate(() => {
        const game = window.game as unknown as { bh: { over: boolean; message: string } };
        game.bh.over = true;
        game.bh.message = 'Swallowed! Game over with 0 points. Press Enter or R to play again.';
      });
      await p.waitFor(
        () => document.querySelector('[data-hud="message"]')?.textContent?.includes('Tap to continue from level 1 (score resets to 0).'),
        null,
      );
      await p.page.getByRole('button', { name: 'Continue from level 1 ↺' }).waitFor({ state: 'visible', timeout: 5000 });
      await p.clickCanvas(0.5, 0.5);
      await p.waitFor(() => !(window.game as unknown as { bh: { over: boolean } }).bh.over, null);
      await p.page.getByRole('button', { name: 'Continue from level 1 ↺' }).waitFor({ state: 'detached', timeout: 5000 });
    }
    const centre = async (name: string): Promise<[number, number]> => {
      const b = (await p.page.getByRole('button', { name, exact: true }).boundingBox())!;
      return [b.x + b.width / 2, b.y + b.height / 2];
    };
    const up = await centre('thrust up'),
      right = await centre('thrust right');
    if (touch) {
      // The phone's pad is a d-pad: ↑ straight above ↓ in the middle column, ← and → either side
      // spanning both rows, every button at least 44 x 44 px, the pad below the scene (not over it).
      const box = async (d: string) => (await p.page.getByRole('button', { name: `thrust ${d}`, exact: true }).boundingBox())!;
      const [l, u, dn, r] = [await box('left'), await box('up'), await box('down'), await box('right')];
      const canvas = (await p.page.locator('canvas').first().boundingBox())!;
      for (const [name, b] of [
        ['left', l],
        ['up', u],
        ['down', dn],
        ['right', r],
      ] as const) {
        expect(b.width, `${name} width`).toBeGreaterThanOrEqual(44);
        expect(b.height, `${name} height`).toBeGreaterThanOrEqual(44);
        expect(b.y, `${name} below the scene`).toBeGreaterThanOrEqual(canvas.y + canvas.height - 1);
      }
      expect(Math.abs(u.x - dn.x)).toBeLessThan(1);
      expect(dn.y).toBeGreaterThanOrEqual(u.y + u.height);
      expect(l.x + l.width).toBeLessThanOrEqual(u.x);
      expect(r.x).toBeGreaterThanOrEqual(u.x + u.width);
      expect(l.y).toBeLessThanOrEqual(u.y + 1);
      expect(l.y + l.height).toBeGreaterThanOrEqual(dn.y + dn.height - 1);
      expect(r.y).toBeLessThanOrEqual(u.y + 1);
    }
    const thrust = () => p.page.evaluate(() => (window.game as unknown as Bh).bh.thrust);
    const cdp = touch ? await p.page.context().newCDPSession(p.page) : null;
    const finger = async (type: 'touchStart' | 'touchMove', [x, y]: [number, number]) =>
      cdp!.send('Input.dispatchTouchEvent', { type, touchPoints: [{ x, y, id: 1 }] });
    if (cdp) await finger('touchStart', up);
    else {
      await p.page.mouse.move(...up);
      await p.page.mouse.down();
    }
    await p.waitFor(() => (window.game as unknown as Bh).bh.thrust === 'up', null);
    // Slid onto → without lifting: the thrust follows the arrow under it (before, the ↑ button kept
    // the pointer and thrust up until the finger lifted). On the desktop's row the straight slide
    // crosses ↓; on the phone's d-pad it never does, and on the seam of ↑ and → it thrusts up-right.
    const path: [number, number][] = [0.25, 0.5, 0.75, 1].map((f) => [up[0] + f * (right[0] - up[0]), up[1] + f * (right[1] - up[1])]);
    const seen: string[] = [];
    for (const at of path) {
      if (cdp) await finger('touchMove', at);
      else await p.page.mouse.move(...at);
      seen.push(await thrust());
    }
    if (touch) {
      expect(seen, 'thrusts on the way from ↑ to →').not.toContain('down');
      expect(seen, 'thrusts on the way from ↑ to →').toContain('up-right');
    }
    const slid = await p
      .waitFor(() => {
        const t = (window.game as unknown as Bh).bh.thrust;
        return t === 'right' ? t : null;
      }, null)
      .catch(async () => thrust());
    expect(slid, `${device}: thrust after sliding onto →`).toBe('right');
    if (cdp) {
      // A second finger on ↑ while the first stays on → thrusts up and right at once.
      await cdp.send('Input.dispatchTouchEvent', {
        type: 'touchStart',
        touchPoints: [
          { x: right[0], y: right[1], id: 1 },
          { x: up[0], y: up[1], id: 2 },
        ],
      });
      await p.waitFor(() => (window.game as unknown as Bh).bh.thrust === 'up-right', null);
    }
    if (cdp) {
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
      await cdp.detach();
    } else await p.page.mouse.up();
    await p.waitFor(() => (window.game as unknown as Bh).bh.thrust === 'none', null);
    expect(await p.page.evaluate(() => (window.game as unknown as Bh).shipPx())).toBeGreaterThanOrEqual(26);
    // A cleared level: the "Level 2" button shows over the field, clear of the start pad (drawn 2.4 m
    // wide at 0.9 m up), of the ship waiting on it (shipPx tall) and of the thrust buttons.
    await p.page.evaluate(() => {
      const w = window.game as unknown as {
        bh: { ship: number; lineY: number; world: { components: { Position: { y: Float64Array } } } };
        level: { ringsTaken: number; rings: unknown[] };
      };
      // The ring counted as flown through (the line counts only after it), then the ship over the line.
      w.level.ringsTaken = w.level.rings.length;
      w.bh.world.components.Position.y[w.bh.ship % 2 ** 25] = w.bh.lineY + 0.3;
    });
    const next = p.page.getByRole('button', { name: 'Level 2 ▶' });
    await next.waitFor({ state: 'visible', timeout: 10_000 });
    const b = (await next.boundingBox())!;
    const { start, px } = await p.page.evaluate(() => {
      const w = window.game as unknown as { bh: { start: number[] }; shipPx(): number };
      return { start: w.bh.start, px: w.shipPx() };
    });
    const padL = await p.worldToPage(start[0]! - 1.2, 0.9),
      padR = await p.worldToPage(start[0]! + 1.2, 0.9),
      ship = await p.worldToPage(start[0]!, start[1]!);
    type Box = { x: number; y: number; width: number; height: number };
    const boxes: [string, Box][] = [
      ['start pad', { x: padL.x, y: padL.y - 2, width: padR.x - padL.x, height: 5 }],
      ['ship', { x: ship.x - px / 2, y: ship.y - px / 2, width: px, height: px }],
    ];
    for (const d of ['left', 'up', 'down', 'right'])
      boxes.push([`${d} button`, (await p.page.getByRole('button', { name: `thrust ${d}`, exact: true }).boundingBox())!]);
    for (const [name, o] of boxes) {
      const overlap = b.x < o.x + o.width && o.x < b.x + b.width && b.y < o.y + o.height && o.y < b.y + b.height;
      expect(overlap, `${device}: the Level 2 button over the ${name}`).toBe(false);
    }
    // Level 2's wall reaches from edge to edge, and every hole, its disc and its glow stay inside the
    // field (on a phone a hole of the wall stood half past the edge and discs were cut off by it).
    // A tap on the phone (a click on the desktop) starts level 2.
    if (touch) await next.tap();
    else await next.click();
    const wall = await p.waitFor(() => {
      const w = window.game as unknown as {
        level: { waiting: boolean };
        bh: { holes: number[]; field: { width: number; height: number } };
      };
      const e = (window.game as unknown as { holeExtents(): number[][] }).holeExtents();
      return !w.level.waiting && e.length === w.bh.holes.length && e.length > 0 ? { e, field: w.bh.field } : null;
    }, null);
    expect(await p.page.evaluate(() => (window.game as unknown as { level: { spec: { level: number } } }).level.spec.level)).toBe(2);
    expect(wall.e.length).toBeGreaterThan(5);
    const field2 = await field();
    expect(field2.top, `${device}: the field's top, level 2 (${field2.text})`).toBeCloseTo(field0.top, 1);
    // Level 2's title and the path's words cover no part of the gold ring (or its halo): the title sat
    // on it, centred in the open field, where the ring was on the desktop and on a phone.
    const overRing = await p.waitFor(() => {
      const w = window.game as unknown as { ringBoxes(): number[][]; levelBanner(): string; levelBannerBox(): number[] };
      type Page = { pathLabel(): string; pathHint(): string; pathPoints(): number; textBox(n: string): number[] };
      const q = window.game as unknown as Page;
      // The pad's path is drawn (1.5 s of it on level 2: it may stop short of the wall, with no label).
      if (!w.levelBanner().startsWith('Level 2') || q.pathPoints() === 0) return null;
      const boxes: [string, number[]][] = [['title', w.levelBannerBox()]];
      if (q.pathLabel()) boxes.push(['path label', q.textBox('pathLabel')]);
      if (q.pathHint()) boxes.push(['path hint', q.textBox('pathHint')]);
      const rings = w.ringBoxes();
      const hits = boxes
        .filter(([, [l, t, r, b]]) => rings.some(([L, T, R, B]) => l! < R! && L! < r! && t! < B! && T! < b!))
        .map(([n]) => n);
      return { rings: rings.length, hits };
    }, null);
    expect(overRing, `${device}: words over the ring`).toEqual({ rings: 1, hits: [] });
    for (const [left, right, bottom, top] of wall.e) {
      expect(left, `${device}: a hole's left`).toBeGreaterThanOrEqual(0);
      expect(right, `${device}: a hole's right`).toBeLessThanOrEqual(wall.field.width);
      expect(bottom).toBeGreaterThanOrEqual(0);
      expect(top).toBeLessThanOrEqual(wall.field.height);
    }
    // The phone's menu drawer is opaque: the level banner over the field does not show through it.
    // Opened, it pauses the game (it covers the field); closed, the game goes on.
    if (touch) {
      const paused = () => p.page.evaluate(() => (window.game as unknown as { paused: boolean }).paused);
      expect(await paused()).toBe(false);
      await p.page.locator('.bp-drawer-button:not(.bp-side-button)').click();
      const bg = await p.page.evaluate(() => getComputedStyle(document.querySelector('.bp-info')!).backgroundColor);
      expect(bg).toBe('rgb(16, 20, 28)');
      await p.waitFor(() => (window.game as unknown as { paused: boolean }).paused, null);
      await p.page.locator('.bp-drawer-button:not(.bp-side-button)').click();
      await p.waitFor(() => !(window.game as unknown as { paused: boolean }).paused, null);
      // A pause the player made stays when the menu closes.
      await p.page
        .getByRole('button', { name: /^pause/i })
        .first()
        .click();
      expect(await paused()).toBe(true);
      await p.page.locator('.bp-drawer-button:not(.bp-side-button)').click();
      await p.page.locator('.bp-drawer-button:not(.bp-side-button)').click();
      await p.frames(2);
      expect(await paused()).toBe(true);
    }
    expect(p.errors).toEqual([]);
    await p.close();
  });
});

describe.each([
  { device: 'desktop', viewport: { width: 1280, height: 800 }, touch: false },
  { device: 'phone', viewport: { width: 390, height: 844 }, touch: true },
] as const)('black hole pause and touch card; taps, the paused path, path and replay buttons ($device)', ({ device, viewport, touch }) => {
  // One page for both cases (reset between), the pause's first: it reads the page's own touch card.
  const page = sharedPage(() => h, 'black-hole', { viewport, touch, query: { level: 1 } });

  it('pausing dims the field and says how to resume; on a phone the touch card names the seam and never covers the finish line', async () => {
    const p = page();
    type Pause = { pauseOverlay(): { visible: boolean; text: string }; paused: boolean };
    if (touch) {
      // The card of gestures (and the legend in the drawer) says, in a player's words, that a thumb
      // on the seam of two arrows holds both ("seam of two: diagonal" read as cryptic).
      expect(await p.page.locator('.bp-legend').textContent()).toContain('thumb between two: both');
      // The finish line's screen rect (the dashed line across the field, 2 px either side of it) and
      // the card's box: apart. The kit's card goes after 9 s or at a touch; a stand-in of its class
      // with a longer text (two lines at this width, which do not fit above the line) is checked too.
      const overlap = () =>
        p.page.evaluate(() => {
          type Cam = { toScreenX(x: number): number; toScreenY(y: number): number };
          const w = window.game as unknown as { renderer: { camera: Cam }; bh: { lineY: number; field: { width: number } } };
          const cam = w.renderer.camera;
          const c = document.querySelector('canvas')!.getBoundingClientRect();
          const line = {
            left: c.left + cam.toScreenX(0),
            right: c.left + cam.toScreenX(w.bh.field.width),
            top: c.top + cam.toScreenY(w.bh.lineY) - 2,
            bottom: c.top + cam.toScreenY(w.bh.lineY) + 2,
          };
          const card = document.querySelector('[data-hud="touch-hint"]');
          if (!card) return null;
          const r = card.getBoundingClientRect();
          return r.left < line.right && line.left < r.right && r.top < line.bottom && line.top < r.bottom;
        });
      const real = await overlap();
      if (real !== null) expect(real, 'the touch card over the finish line').toBe(false);
      await p.page.evaluate(() => {
        document.querySelector('[data-hud="touch-hint"]')?.remove();
        const card = document.createElement('div');
        card.className = 'bp-touch-hint';
        card.dataset.hud = 'touch-hint';
        card.innerHTML = '<div><b>hold, slide ← ↑ → ↓</b><span>thrust (two at once, or a finger on the seam of two: diagonal)</span></div>';
        document.querySelector('.bp-stage')!.append(card);
      });
      expect(await p.page.locator('[data-hud="touch-hint"]').evaluate((e) => e.getBoundingClientRect().height)).toBeGreaterThan(40);
      await p.waitFor(() => {
        const card = document.querySelector<HTMLElement>('[data-hud="touch-hint"]');
        return card !== null && card.style.top !== '' && card.style.top !== '6px';
      }, null);
      expect(await overlap(), 'a two-line card over the finish line').toBe(false);
    }
    // Paused from the toolbar (a tap on the phone, P on the desktop): the overlay shows and says how
    // to resume; resumed, it goes.
    if (touch) await p.page.getByRole('button', { name: 'pause / resume (P)', exact: true }).tap();
    else await p.page.keyboard.press('p');
    const shown = await p.waitFor(() => {
      const o = (window.game as unknown as Pause).pauseOverlay();
      return o.visible ? o.text : null;
    }, null);
    expect(shown, device).toBe(touch ? 'Paused\n▶ to resume' : 'Paused\nP to resume');
    // Paused, the predicted path stays drawn (the pad's, before the first thrust), and the words cover
    // none of its dots nor the ship nor the finish line: they stand in one line in the status row, above
    // the field's top (in the band above the line they lay over a path's top), at least 14 px tall.
    const paused = await p.waitFor(() => {
      type Cam = { toScreenY(y: number): number };
      const w = window.game as unknown as Pause & {
        pathPoints(): number;
        pauseWordsBox(): number[];
        dotsIn(...box: number[]): number;
        renderer: { camera: Cam };
        bh: { lineY: number; field: { height: number } };
      };
      const box = w.pauseWordsBox();
      const cam = w.renderer.camera;
      return w.pauseOverlay().visible && box[2]! > box[0]!
        ? { points: w.pathPoints(), covered: w.dotsIn(...box), box, band: [cam.toScreenY(w.bh.field.height), cam.toScreenY(w.bh.lineY)] }
        : null;
    }, null);
    expect(paused.points, device).toBeGreaterThan(0);
    expect(paused.covered, device).toBe(0);
    expect(paused.box[3]!, device).toBeLessThanOrEqual(paused.band[0]!);
    expect(paused.box[3]! - paused.box[1]!, device).toBeGreaterThanOrEqual(14);
    await p.page.evaluate(() => {
      (window.game as unknown as Pause).paused = false;
    });
    await p.waitFor(() => !(window.game as unknown as Pause).pauseOverlay().visible, null);
    // The stand-in card goes (the next case on this page finds the page's own, or none).
    await p.page.evaluate(() => document.querySelector('[data-hud="touch-hint"]')?.remove());
    expect(p.errors).toEqual([]);
  });

  it('a tap thrusts exactly 13 steps, its arrow unlit once let go; paused, arrows do not redraw the path; Path and Replay (F, V) work; the legend names real controls', async () => {
    const p = page();
    type Bh = {
      paused: boolean;
      step(): void;
      reset(): void;
      params: { path: boolean };
      replay: { player: unknown };
      pathPoints(): number;
      pathTip(): number[];
      bh: { ship: number; thrust: string; world: { components: Record<string, { x: Float64Array; y: Float64Array }> } };
      level: { parked: boolean };
    };
    // The legend names the on-screen controls, not "the big button".
    const legend = await p.page.locator('.bp-legend').textContent();
    expect(legend).not.toContain('big button');
    if (touch) expect(legend).toContain('Level ▶ / Continue ↺');
    // A tap of ↑ (a finger's tap, or a key pressed and let go at once) thrusts for exactly 13 steps
    // (TAP_STEPS) of the game: the run's recording (V replays it) holds the thrust 'up' and, 13 steps
    // later, 'none' (a finger's tap thrust for no step at all; a key's for as many steps as the frames
    // between).
    const upBox = (await p.page.getByRole('button', { name: 'thrust up', exact: true }).boundingBox())!;
    if (touch) await p.page.touchscreen.tap(upBox.x + upBox.width / 2, upBox.y + upBox.height / 2);
    // The key's down and up in one task of the page, so no frame runs between them: sent as two
    // protocol events on a loaded machine, the press could last longer than a tap by the wall clock,
    // and a press thrusts as long as it lasts.
    else
      await p.page.evaluate(() => {
        for (const type of ['keydown', 'keyup']) window.dispatchEvent(new KeyboardEvent(type, { key: 'ArrowUp', code: 'ArrowUp' }));
      });
    // Let go, ↑ is not lit while the tap's thrust runs on (lit, and paused so, it looked stuck).
    const tail = await p.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.paused = true;
      return w.bh.thrust;
    });
    await p.frames(2);
    const lit = await p.page.evaluate(() => [
      (window.game as unknown as Bh).bh.thrust,
      document.querySelectorAll('.bh-pad button.on').length,
    ]);
    if (tail === 'up') expect(lit, 'thrust and arrows lit, paused in a tap').toEqual(['up', 0]);
    await p.page.evaluate(() => {
      (window.game as unknown as Bh).paused = false;
    });
    type Events = { replay: { recorder: { replay: { events: { step: number; name: string; args: unknown[] }[] } } } };
    const thrusts = await p.waitFor(() => {
      const events = (window.game as unknown as Events).replay.recorder.replay.events.filter((e) => e.name === 'thrust');
      return events.length >= 2 ? events.map((e) => [e.step, e.args[0]]) : null;
    }, null);
    expect(thrusts.map((t) => t[1])).toEqual(['up', 'none']);
    expect(thrusts[1]![0]! as number, device).toBe((thrusts[0]![0]! as number) + 13);
    await p.page.evaluate(() => {
      (window.game as unknown as Bh).paused = true;
    });
    // Path off and on, and the replay of the run so far (the tap; it waits while paused): the buttons on a
    // phone; on the desktop F, then the buttons (Path and Replay show there too: the keys alone were missed).
    const act = async (key: string, name: string, click = false) => {
      if (touch) await p.page.getByRole('button', { name, exact: true }).tap();
      else if (click) await p.page.getByRole('button', { name, exact: true }).click();
      else await p.page.keyboard.press(key);
    };
    await act('f', 'predicted path on / off (F)');
    await p.waitFor(() => !(window.game as unknown as Bh).params.path, null);
    await act('f', 'predicted path on / off (F)', true);
    await p.waitFor(() => (window.game as unknown as Bh).params.path, null);
    await act('v', 'replay the run (V)', true);
    await p.waitFor(() => (window.game as unknown as Bh).replay.player !== null, null);
    // The ship mid-field, moving: paused, the path is the course at the pause; an arrow held (or a
    // thrust set) while paused does not redraw it; resumed, the thrust bends it.
    await p.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      w.reset();
      const c = w.bh.world.components,
        s = w.bh.ship % 2 ** 25;
      c.Position!.x[s] = c.PreviousPosition!.x[s] = 6;
      c.Position!.y[s] = c.PreviousPosition!.y[s] = 5;
      c.Velocity!.x[s] = 0;
      c.Velocity!.y[s] = 1;
      w.level.parked = false;
    });
    const tip = async () => {
      await p.frames(3);
      return p.page.evaluate(() => (window.game as unknown as Bh).pathTip());
    };
    const before = await tip();
    expect(before.length).toBe(2);
    await p.page.evaluate(() => {
      (window.game as unknown as Bh).bh.thrust = 'right';
    });
    expect(await tip()).toEqual(before);
    await p.page.evaluate(() => {
      (window.game as unknown as Bh).paused = false;
    });
    await p.waitFor((b) => {
      const t = (window.game as unknown as Bh).pathTip();
      return t.length === 2 && Math.abs(t[0]! - b[0]!) > 0.5;
    }, before);
    if (touch)
      for (const name of ['predicted path on / off (F)', 'replay the run (V)']) {
        const b = (await p.page.getByRole('button', { name, exact: true }).boundingBox())!;
        expect(b.width, name).toBeGreaterThanOrEqual(44);
        expect(b.height, name).toBeGreaterThanOrEqual(44);
        expect(b.x + b.width, name).toBeLessThanOrEqual(390);
      }
    expect(p.errors).toEqual([]);
  });
});

/**
 * In the page: a naive player of level 1 who does what the coach beside the ship says (the arrows it
 * names, and no others: held, or for "Tap" pressed and let go at once, at most every half second), read every frame, with the keys (desktop) or fingers on the pad's arrows
 * (phone: one synthetic touch pointer per arrow, at its button's centre). After a fall or an exit
 * the page forgets what was held, so it lifts everything and presses again. It plays until the level
 * is cleared or 60 s of game time pass, and reports how it went on `window.naivePlayer`.
 */
function playAsCoachSays(touch: boolean): void {
  type Game = {
    coach(): string;
    bh: { falls: number; lives: number; over: boolean; resets: number; world: { steps: number } };
    level: { waiting: boolean; spec: { level: number } };
  };
  const w = window.game as unknown as Game;
  const KEYS: Record<string, string> = { '←': 'ArrowLeft', '→': 'ArrowRight', '↑': 'ArrowUp', '↓': 'ArrowDown' };
  const DIRS: Record<string, string> = { '←': 'left', '→': 'right', '↑': 'up', '↓': 'down' };
  const held = new Map<string, number>();
  let nextPointer = 100;
  const button = (a: string) => document.querySelector<HTMLElement>(`.bh-pad button[data-dir="${DIRS[a]}"]`)!;
  const touchEvent = (type: string, a: string, id: number) => {
    const r = button(a).getBoundingClientRect();
    const init = { pointerId: id, pointerType: 'touch', isPrimary: false, bubbles: true, cancelable: true };
    button(a).dispatchEvent(new PointerEvent(type, { ...init, clientX: r.left + r.width / 2, clientY: r.top + r.height / 2 }));
  };
  const down = (a: string) => {
    const id = nextPointer++;
    held.set(a, id);
    if (touch) touchEvent('pointerdown', a, id);
    else window.dispatchEvent(new KeyboardEvent('keydown', { key: KEYS[a], bubbles: true }));
  };
  const up = (a: string) => {
    const id = held.get(a)!;
    held.delete(a);
    if (touch) touchEvent('pointerup', a, id);
    else window.dispatchEvent(new KeyboardEvent('keyup', { key: KEYS[a], bubbles: true }));
  };
  const start = w.bh.world.steps;
  let resets = w.bh.resets,
    lastTap = -Infinity;
  const said = new Set<string>();
  const report = (cleared: boolean) => {
    for (const a of [...held.keys()]) up(a);
    (window as unknown as { naivePlayer: unknown }).naivePlayer = {
      cleared,
      falls: w.bh.falls,
      lives: w.bh.lives,
      seconds: (w.bh.world.steps - start) / 60,
      said: [...said],
    };
  };
  const frame = () => {
    if (w.level.waiting) return report(true);
    if (w.bh.over || w.bh.world.steps - start > 3600) return report(false);
    if (w.bh.resets !== resets) {
      // A fall or an exit: the page let go of everything held.
      resets = w.bh.resets;
      for (const a of [...held.keys()]) up(a);
    }
    const coach = w.coach();
    if (/\nTap /.test(coach)) {
      // "Tap ...": the arrows it names pressed and let go at once, at most every half second.
      said.add(coach);
      for (const a of [...held.keys()]) up(a);
      if (w.bh.world.steps - lastTap >= 30) {
        lastTap = w.bh.world.steps;
        const taps = [...coach].filter((c) => c in KEYS);
        for (const a of taps) down(a);
        for (const a of taps) up(a);
      }
    } else if (coach !== '') {
      said.add(coach);
      const want = [...coach].filter((c) => c in KEYS);
      for (const a of [...held.keys()]) if (!want.includes(a)) up(a);
      for (const a of want) if (!held.has(a)) down(a);
    }
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
}

describe.each([
  { device: 'desktop', viewport: { width: 1280, height: 800 }, touch: false },
  { device: 'phone', viewport: { width: 390, height: 844 }, touch: true },
] as const)('black hole level 1, a newcomer ($device)', ({ viewport, touch }) => {
  it('a naive player who holds what the coach beside the ship says clears level 1 with its lives', async () => {
    // The issue this answers: a stranger lost three lives on level 1 in 30 s without seeing how to
    // get through, and a drawn "way through" that depended on exact timing led one into a hole. The
    // coach reads the path of the moment, so it holds whatever the player's timing.
    // One layout a size (seed 1 on the desktop, 2 on the phone): each run plays in real time, some
    // 7 s of a 2-core CI machine's browser lane a seed.
    for (const seed of touch ? [2] : [1]) {
      const p = await h.openGame('black-hole', { viewport, touch, query: { level: 1, seed } });
      // On the pad, before the first thrust, it says how to start and what the dots are.
      expect(await p.waitFor(() => (window.game as unknown as { coach(): string }).coach(), null)).toBe(
        'Hold ↑ to fly.\nThe dots show your way.',
      );
      await p.page.evaluate(playAsCoachSays, touch);
      const result = await p.waitFor(
        () =>
          (window as unknown as { naivePlayer?: { cleared: boolean; falls: number; lives: number; seconds: number; said: string[] } })
            .naivePlayer,
        null,
        120_000,
      );
      // Cleared, with every life, at most one fall on the way (measured: none, on 20 seeds of
      // scripts/black-hole-levels.mjs's rules at reaction lags of 0.3 and 0.5 s).
      expect(result, `seed ${seed}: ${JSON.stringify(result)}`).toMatchObject({ cleared: true, lives: 3 });
      expect(result.falls, `seed ${seed}: ${JSON.stringify(result)}`).toBeLessThanOrEqual(1);
      // It was told to steer round the hole (the straight climb runs into it).
      expect(
        result.said.some((s) => /^Red: you'd fall in!\nHold [←→] and ↑ to steer round\.$/.test(s)),
        JSON.stringify(result.said),
      ).toBe(true);
      expect(p.errors).toEqual([]);
      await p.close();
    }
  }, 300_000);
});

describe('black hole, a phone played with keys', () => {
  it('a clear fades the touch card, which lay over the "+N" rising under the finish line', async () => {
    // A phone with a keyboard: no touch on the stage ever fades the card (it stays 9 s), and on a
    // phone the card sits just under the finish line, where the clear's points show.
    const p = await h.openGame('black-hole', { viewport: { width: 390, height: 844 }, touch: true, query: { level: 1 } });
    type Bh = {
      bh: { ship: number; lineY: number; world: { components: Record<string, { y: Float64Array; x: Float64Array }> } };
      level: { parked: boolean; waiting: boolean; ringsTaken: number; rings: unknown[] };
    };
    const shown = await p.waitFor(() => {
      const card = document.querySelector('[data-hud="touch-hint"]');
      return card && !card.classList.contains('bp-gone') ? true : null;
    }, null);
    expect(shown).toBe(true);
    // The ship put just under the line, climbing: the next step clears level 1.
    await p.page.evaluate(() => {
      const w = window.game as unknown as Bh;
      const c = w.bh.world.components,
        s = w.bh.ship % 2 ** 25;
      w.level.parked = false;
      // The ring counted as flown through: the line counts only after it.
      w.level.ringsTaken = w.level.rings.length;
      c.Position!.y[s] = c.PreviousPosition!.y[s] = w.bh.lineY - 0.3;
      c.Velocity!.x[s] = 0;
      c.Velocity!.y[s] = 4;
    });
    await p.waitFor(() => (window.game as unknown as Bh).level.waiting, null);
    // Gone (or fading) within a second of the clear, well before its own 9 s are up.
    await p.waitFor(
      () => {
        const card = document.querySelector('[data-hud="touch-hint"]');
        return !card || card.classList.contains('bp-gone');
      },
      null,
      1000,
    );
    expect(p.errors).toEqual([]);
    await p.close();
  });
});

describe('black hole on a phone (390 x 844, touch)', () => {
  it("one thumb on the seam of ← and ↑ until the ship flies left at 4.5 m/s, then slid onto ↑: the narrow field's gentler sideways thrust and soft side wall keep the ship in the field", async () => {
    // Played on the phone's 20 x 30 m field: flown on with ↑ alone from there, at full sideways thrust
    // and without the soft side walls it left the field ("Off the field") on every layout of level 1,
    // seeds 1 to 8 (games/black-hole/rules.ts SOFT_WALL and `sideScale`).
    type PhoneBh = { bh: { thrust: string; message: string; falls: number }; level: { waiting: boolean }; ship(): number[] };
    const p = await h.openGame('black-hole', { viewport: { width: 390, height: 844 }, touch: true, query: { level: 1 } });
    const box = async (name: string) => (await p.page.getByRole('button', { name, exact: true }).boundingBox())!;
    const up = await box('thrust up'),
      left = await box('thrust left');
    const upMid: [number, number] = [up.x + up.width / 2, up.y + up.height / 2];
    // The seam: midway between ← and ↑, within the pad's PAD_SEAM of both.
    const seam: [number, number] = [(left.x + left.width + up.x) / 2, up.y + up.height / 2];
    const cdp = await p.page.context().newCDPSession(p.page);
    const finger = (type: 'touchStart' | 'touchMove', [x, y]: [number, number]) =>
      cdp.send('Input.dispatchTouchEvent', { type, touchPoints: [{ x, y, id: 1 }] });
    // The ring counted as flown through, so the line ends the flight (this checks the side wall).
    await p.page.evaluate(() => {
      const run = (window.game as unknown as { level: { ringsTaken: number; rings: unknown[] } }).level;
      run.ringsTaken = run.rings.length;
    });
    await finger('touchStart', seam);
    await p.waitFor(() => (window.game as unknown as PhoneBh).bh.thrust === 'up-left', null);
    // The least x the ship reaches, m, sampled every frame from here on; the game paused in the first
    // frame that finds the ship flying left at 4.5 m/s (some 1.5 s of the diagonal), so the thumb
    // slides onto ↑ then, however slow the machine.
    await p.page.evaluate(() => {
      const w = window.game as unknown as PhoneBh & { paused: boolean };
      const track = { minX: Infinity, stopped: false };
      (window as unknown as { track: typeof track }).track = track;
      const each = () => {
        const [x, , vx] = w.ship();
        track.minX = Math.min(track.minX, x!);
        if (!track.stopped && vx! <= -4.5) [track.stopped, w.paused] = [true, true];
        requestAnimationFrame(each);
      };
      requestAnimationFrame(each);
    });
    await p.waitFor(() => (window as unknown as { track: { stopped: boolean } }).track.stopped || null, null);
    await finger('touchMove', upMid);
    await p.waitFor(() => (window.game as unknown as PhoneBh).bh.thrust === 'up', null);
    await p.page.evaluate(() => {
      (window.game as unknown as { paused: boolean }).paused = false;
    });
    // Until the level is cleared, the ship falls in, or it is lost.
    const end = await p.waitFor(() => {
      const w = window.game as unknown as PhoneBh;
      if (w.level.waiting) return 'cleared';
      if (w.bh.message.startsWith('Lost')) return 'lost';
      return w.bh.falls > 0 ? 'fell' : null;
    }, null);
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    const minX = await p.page.evaluate(() => (window as unknown as { track: { minX: number } }).track.minX);
    expect(end).not.toBe('lost');
    expect(minX).toBeGreaterThan(0);
    // It did fly towards the edge (into the soft wall, the last 3 m), not straight up.
    expect(minX).toBeLessThan(3);
    expect(p.errors).toEqual([]);
    await cdp.detach();
    await p.close();
  });
});

describe('black hole, a stranger on a phone (issue 34)', () => {
  type Phone = {
    bh: {
      thrust: string;
      message: string;
      lives: number;
      over: boolean;
      falls: number;
      resets: number;
      holes: number[];
      holeRadius: number[];
      field: { width: number; height: number };
      start: number[];
      lineY: number;
      world: { steps: number; components: Record<string, { x: Float64Array; y: Float64Array }> };
    };
    level: { waiting: boolean; parked: boolean; spec: { level: number } } | null;
    ship(): number[];
    coach(): string;
    pathHint(): string;
    pathShade(): string;
    textBox(name: string): number[];
    holeExtents(): number[][];
    advance(): void;
    renderer: { camera: { toScreenX(x: number): number; toScreenY(y: number): number } };
  };

  // One phone page (390 x 844, touch, level 1) for the cases below, reset and unpaused before each:
  // each lifts every finger before it ends, and a reset starts no ready beat (main.ts sets one only
  // after a fall or a loss), so each starts as a fresh page does.
  describe('one phone page at level 1', () => {
    const phonePage = sharedPage(() => h, 'black-hole', { viewport: { width: 390, height: 844 }, touch: true, query: { level: 1 } });

    it('a 1 s touch hold of → flies the ship aside and the soft wall stops it 2 m inside the field; a 0.5 s hold still moves it 1 m', async () => {
      // The stranger lost six lives learning that a 0.9-1 s hold carried the ship to the edge. A side
      // arrow alone builds at most 3 m/s on the phone's field (games/black-hole/rules.ts
      // NARROW_SIDE_SPEED), which the soft wall (its last 3 m) stops 2.4 m from the edge in the rules
      // (test/games/black-hole-rules.test.ts); before, 1 s of it stopped 1.5 m from the edge, 2 s left the field.
      const p = phonePage();
      const right = (await p.page.getByRole('button', { name: 'thrust right', exact: true }).boundingBox())!;
      const cdp = await p.page.context().newCDPSession(p.page);
      const at = { x: right.x + right.width / 2, y: right.y + right.height / 2, id: 1 };
      /** What a flight did: the ship's greatest x (m), and whether it was lost (a reset or "Lost"). */
      type Track = { steps: number; resets: number; x0: number; maxX: number; lost: boolean; hold: number };
      const fly = async (ms: number) => {
        const start = await p.page.evaluate(() => {
          const w = window.game as unknown as Phone;
          return { steps: w.bh.world.steps, resets: w.bh.resets, x0: w.ship()[0]! };
        });
        const track: Track = { ...start, maxX: start.x0, lost: false, hold: Math.round((ms / 1000) * 60) };
        /** Follows the flight one step: the greatest x and a loss; the track once `steps` steps have passed since the press. */
        const follow = (t: Track & { until: number }) => {
          const w = window.game as unknown as Phone;
          t.maxX = Math.max(t.maxX, w.ship()[0]!);
          if (w.bh.resets !== t.resets || w.bh.message.startsWith('Lost')) t.lost = true;
          return w.bh.world.steps - t.steps >= t.until || t.lost ? t : null;
        };
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [at] });
        // Held for `ms` of game time (60 steps a second), stepped at once (not the wall clock: on a
        // loaded machine a second of it carried less game time, and the ship flew less far).
        const held = await p.runUntil(follow, { ...track, until: track.hold }, { draw: false });
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
        // 7 s of game time after the press: long enough to reach the wall and turn.
        const t = await p.runUntil(follow, { ...held, until: 7 * 60 + 1 }, { draw: false });
        return p.page.evaluate(
          (t) => ({ edge: (window.game as unknown as Phone).bh.field.width - t.maxX, travel: t.maxX - t.x0, lost: t.lost }),
          t,
        );
      };
      const long = await fly(1000);
      expect(long.lost, JSON.stringify(long)).toBe(false);
      expect(long.edge, JSON.stringify(long)).toBeGreaterThan(2);
      // It did fly aside into the wall's band, not nowhere.
      expect(long.travel, JSON.stringify(long)).toBeGreaterThan(4);
      await p.page.evaluate(() => (window.game as unknown as { reset(): void }).reset());
      await p.runFrames(2);
      const nudge = await fly(500);
      expect(nudge.lost, JSON.stringify(nudge)).toBe(false);
      expect(nudge.travel, JSON.stringify(nudge)).toBeGreaterThan(1);
      expect(p.errors).toEqual([]);
      await cdp.detach();
    }, 120_000);

    it('a retry meets the same layout: level 2 continued after a game over has the holes it had when reached from level 1', async () => {
      const p = phonePage();
      const holes = () =>
        p.page.evaluate(() => {
          const w = window.game as unknown as Phone;
          const P = w.bh.world.components.Position!;
          return w.bh.holes.map((e, i) =>
            [P.x[e % 2 ** 25]!, P.y[e % 2 ** 25]!, w.bh.holeRadius[i]!].map((v) => Math.round(v * 1e6) / 1e6),
          );
        });
      // Level 1 cleared: the ship put just under the line, flying up.
      await p.page.evaluate(() => {
        const w = window.game as unknown as Phone;
        const c = w.bh.world.components,
          s = (w as unknown as { bh: { ship: number } }).bh.ship % 2 ** 25;
        w.level!.parked = false;
        (w.level as unknown as { ringsTaken: number }).ringsTaken = 1;
        c.Position!.y[s] = c.PreviousPosition!.y[s] = w.bh.lineY - 0.05;
        c.Velocity!.y[s] = 3;
      });
      await p.waitFor(() => (window.game as unknown as Phone).level!.waiting, null);
      await p.page.evaluate(() => (window.game as unknown as Phone).advance());
      await p.waitFor(() => !(window.game as unknown as Phone).level!.waiting, null);
      const reached = await holes();
      expect(reached.length).toBeGreaterThan(5);
      // Three falls: the ship put on a hole, each time once the ready moment is over.
      for (let fall = 0; fall < 3; fall++) {
        await p.waitFor(() => (window.game as unknown as { readyLeft(): number }).readyLeft() === 0, null);
        const falls = await p.page.evaluate(() => {
          const w = window.game as unknown as Phone;
          const c = w.bh.world.components,
            s = (w as unknown as { bh: { ship: number } }).bh.ship % 2 ** 25,
            hole = w.bh.holes[0]! % 2 ** 25;
          w.level!.parked = false;
          c.Position!.x[s] = c.PreviousPosition!.x[s] = c.Position!.x[hole]!;
          c.Position!.y[s] = c.PreviousPosition!.y[s] = c.Position!.y[hole]!;
          return w.bh.falls;
        });
        await p.waitFor((n) => (window.game as unknown as Phone).bh.falls > n, falls);
        // The holes stay as they were after each fall.
        expect(await holes()).toEqual(reached);
      }
      expect(await p.page.evaluate(() => (window.game as unknown as Phone).bh.over)).toBe(true);
      // Continue from level 2 (a new world): the same holes.
      await p.page.evaluate(() => (window.game as unknown as Phone).advance());
      await p.waitFor(() => {
        const w = window.game as unknown as Phone;
        return !w.bh.over && w.level!.spec.level === 2 && w.bh.holes.length > 0;
      }, null);
      expect(await holes()).toEqual(reached);
      expect(p.errors).toEqual([]);
    }, 120_000);

    type Two = { bh: { thrust: string }; paused: boolean };
    /** The arrows lit on the pad now. */
    const lit = (): string[] => [...document.querySelectorAll<HTMLElement>('.bh-pad button.on')].map((b) => b.dataset.dir!).sort();
    for (const side of ['right', 'left'] as const)
      it(`finger 1 on ↑, finger 2 on ${side === 'right' ? '→' : '←'}: lifting finger 2 leaves ↑ held and lit, lifting finger 1 leaves ${side}`, async () => {
        const p = phonePage();
        const mid = async (d: string) => {
          const b = (await p.page.getByRole('button', { name: `thrust ${d}`, exact: true }).boundingBox())!;
          return { x: b.x + b.width / 2, y: b.y + b.height / 2 };
        };
        const f1 = { ...(await mid('up')), id: 1 },
          f2 = { ...(await mid(side)), id: 2 };
        // What the browser says each lift was, read from its own touchend events (independent of the game).
        await p.page.evaluate(() => {
          const ends: { changed: number[]; still: number[] }[] = [];
          (window as unknown as { ends: typeof ends }).ends = ends;
          window.addEventListener('touchend', (e) =>
            ends.push({ changed: [...e.changedTouches].map((t) => t.identifier), still: [...e.touches].map((t) => t.identifier) }),
          );
        });
        const ends = () => p.page.evaluate(() => (window as unknown as { ends: { changed: number[]; still: number[] }[] }).ends);
        const cdp = await p.page.context().newCDPSession(p.page);
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [f1] });
        await p.waitFor(() => (window.game as unknown as Two).bh.thrust === 'up', null);
        // Paused, so the ship stays on the field while the fingers come and go (the pad works paused).
        await p.page.evaluate(() => {
          (window.game as unknown as Two).paused = true;
        });
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [f1, f2] });
        await p.waitFor((s) => (window.game as unknown as Two).bh.thrust === `up-${s}`, side);
        await p.page.waitForTimeout(200);
        // Lifting finger 2 only (CDP's touchEnd lifts the points it lists; finger 1 stays down).
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [f2] });
        await p.waitFor(() => (window as unknown as { ends: unknown[] }).ends.length === 1 || null, null);
        expect(await ends()).toEqual([{ changed: [2], still: [1] }]);
        await p.waitFor(() => (window.game as unknown as Two).bh.thrust === 'up', null, 3000).catch(() => {});
        expect(await p.page.evaluate(() => (window.game as unknown as Two).bh.thrust)).toBe('up');
        expect(await p.page.evaluate(lit)).toEqual(['up']);
        // Finger 2 back on the side arrow, then finger 1 lifted: the side arrow alone is held and lit.
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [f1, f2] });
        await p.waitFor((s) => (window.game as unknown as Two).bh.thrust === `up-${s}`, side);
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [f1] });
        await p.waitFor(() => (window as unknown as { ends: unknown[] }).ends.length === 2 || null, null);
        expect((await ends())[1]).toEqual({ changed: [1], still: [2] });
        await p.waitFor((s) => (window.game as unknown as Two).bh.thrust === s, side, 3000).catch(() => {});
        expect(await p.page.evaluate(() => (window.game as unknown as Two).bh.thrust)).toBe(side);
        expect(await p.page.evaluate(lit)).toEqual([side]);
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
        await p.waitFor(() => (window.game as unknown as Two).bh.thrust === 'none', null);
        expect(await p.page.evaluate(lit)).toEqual([]);
        expect(p.errors).toEqual([]);
        await cdp.detach();
      }, 120_000);
  });

  it('level 1 on the pad: the card and the coach both say hold ↑ to fly, and the coach is clear of the hole; in flight the dots are named', async () => {
    for (const touch of [true, false]) {
      const viewport = touch ? { width: 390, height: 844 } : { width: 1280, height: 800 };
      const p = await h.openGame('black-hole', { viewport, touch, query: { level: 1 } });
      const coach = await p.waitFor(() => (window.game as unknown as Phone).coach(), null);
      expect(coach).toMatch(/^Hold ↑ to fly\./);
      const card = await p.page.evaluate(() => document.querySelector('[data-hud="touch-hint"]')?.textContent ?? '');
      // The card's words for this device (the kit shows it on a touch screen).
      if (touch) expect(card).toMatch(/^hold ↑ to fly, tap ← →/);
      if (touch) expect(card).not.toMatch(/nudge/);
      // In one line (it fits above the finish line).
      if (touch)
        expect(await p.page.evaluate(() => document.querySelector<HTMLElement>('[data-hud="touch-hint"]')!.offsetHeight)).toBeLessThan(40);
      // The coach's box keeps off every hole's drawing (disc, ring and glow).
      const hits = await p.page.evaluate(() => {
        const w = window.game as unknown as Phone;
        const cam = w.renderer.camera;
        const [l, t, r, b] = w.textBox('coach');
        return w
          .holeExtents()
          .filter(
            ([x0, x1, y0, y1]) => cam.toScreenX(x1!) > l! && cam.toScreenX(x0!) < r! && cam.toScreenY(y0!) > t! && cam.toScreenY(y1!) < b!,
          ).length;
      });
      expect(hits).toBe(0);
      // A tap of ↑: the path then runs on, grey, and the words by its end say what it is.
      await p.page.keyboard.down('ArrowUp');
      await p.page.waitForTimeout(200);
      await p.page.keyboard.up('ArrowUp');
      const hint = await p.waitFor(() => {
        const w = window.game as unknown as Phone;
        return w.pathShade() === 'open' && w.pathHint();
      }, null);
      expect(hint).toBe('predicted path, next 3 s');
      expect(p.errors).toEqual([]);
      await p.close();
    }
  }, 120_000);

  it('the classic game (?holes=3): ↓ held on the pad leaves the ship there, never off the field', async () => {
    const p = await h.openGame('black-hole', { viewport: { width: 390, height: 844 }, touch: true, query: { holes: 3 } });
    const down = (await p.page.getByRole('button', { name: 'thrust down', exact: true }).boundingBox())!;
    const start = await p.page.evaluate(() => {
      const w = window.game as unknown as Phone;
      return { steps: w.bh.world.steps, resets: w.bh.resets, start: w.bh.start };
    });
    const cdp = await p.page.context().newCDPSession(p.page);
    await cdp.send('Input.dispatchTouchEvent', {
      type: 'touchStart',
      touchPoints: [{ x: down.x + down.width / 2, y: down.y + down.height / 2, id: 1 }],
    });
    // 2 s of game time held (it left the bottom in 0.7 s before).
    await p.waitFor((n) => (window.game as unknown as Phone).bh.world.steps - n > 120, start.steps);
    const seen = await p.page.evaluate(() => {
      const w = window.game as unknown as Phone;
      return { resets: w.bh.resets, ship: w.ship().slice(0, 2), message: w.bh.message };
    });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    expect(seen.resets, JSON.stringify(seen)).toBe(start.resets);
    expect(seen.ship).toEqual(start.start);
    expect(seen.message).not.toMatch(/Lost/);
    expect(p.errors).toEqual([]);
    await cdp.detach();
    await p.close();
  }, 120_000);
});

describe('black hole, the replay of a level (issue 34)', () => {
  it('V after clearing level 2 replays level 2 (not the run from level 1); leaving it shows level 2’s dimmed holes and the Level 3 button again, where the Level 2 button stood', async () => {
    type Rp = {
      paused: boolean;
      step(): void;
      advance(): void;
      ghostExtents(): number[][];
      bh: { ship: number; lineY: number; holes: number[]; world: { components: Record<string, { x: Float64Array; y: Float64Array }> } };
      level: { waiting: boolean; parked: boolean; spec: { level: number }; ringsTaken: number; rings: unknown[] };
      replay: { player: unknown };
    };
    const p = await h.openGame('black-hole', { viewport: { width: 1280, height: 800 }, query: { level: 1 } });
    /** Flies ↑ for 20 steps (recorded input), then counts the ring taken and puts the ship over the line: the next steps clear the level. */
    const clear = () =>
      p.page.evaluate(() => {
        const w = window.game as unknown as Rp;
        w.paused = true;
        const levelHoles = w.bh.holes.length;
        window.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowUp' }));
        for (let i = 0; i < 20; i++) w.step();
        window.dispatchEvent(new KeyboardEvent('keyup', { key: 'ArrowUp' }));
        w.level.ringsTaken = w.level.rings.length;
        w.bh.world.components.Position!.y[w.bh.ship % 2 ** 25] = w.bh.lineY + 0.3;
        for (let i = 0; i < 40 && !w.level.waiting; i++) w.step();
        return { waiting: w.level.waiting, next: w.level.spec.level, levelHoles };
      });
    expect(await clear()).toMatchObject({ waiting: true, next: 2, levelHoles: 1 });
    // The next-level button stands in one place at every level's end (it moved with the dimmed holes).
    const button = async (name: string) => {
      const b = p.page.getByRole('button', { name });
      await b.waitFor({ state: 'visible' });
      await p.frames(3);
      return (await b.boundingBox())!;
    };
    const after1 = await button('Level 2 ▶');
    await p.page.evaluate(() => (window.game as unknown as Rp).advance());
    const two = await clear();
    expect(two).toMatchObject({ waiting: true, next: 3 });
    expect(two.levelHoles).toBeGreaterThan(5);
    await p.frames(2);
    const ghosts = await p.page.evaluate(() => (window.game as unknown as Rp).ghostExtents());
    expect(ghosts.length).toBe(two.levelHoles);
    const after2 = await button('Level 3 ▶');
    expect(Math.abs(after2.y - after1.y)).toBeLessThan(1);
    expect(Math.abs(after2.x - after1.x)).toBeLessThan(1);
    await p.page.keyboard.press('v');
    // The replay starts at level 2's start: level 2's wall of holes, not level 1's one hole.
    const first = await p.waitFor(() => {
      const w = window.game as unknown as Rp;
      return w.replay.player ? { level: w.level.spec.level, holes: w.bh.holes.length, waiting: w.level.waiting } : null;
    }, null);
    expect(first).toEqual({ level: 2, holes: two.levelHoles, waiting: false });
    // Left while it plays (paused, the game stays where it is: the clears were made by moving the
    // ship, not by recorded inputs, so the replay played to its end would not clear level 2).
    await p.page.keyboard.press('a');
    await p.waitFor(() => (window.game as unknown as Rp).replay.player === null || null, null);
    await p.frames(3);
    // Back where the run was: level 3 next, its button shown, level 2's holes dimmed where they were.
    expect(
      await p.page.evaluate(() => [(window.game as unknown as Rp).level.waiting, (window.game as unknown as Rp).level.spec.level]),
    ).toEqual([true, 3]);
    expect(await p.page.evaluate(() => (window.game as unknown as Rp).ghostExtents())).toEqual(ghosts);
    expect(Math.abs((await button('Level 3 ▶')).y - after1.y)).toBeLessThan(1);
    expect(p.errors).toEqual([]);
    await p.close();
  }, 120_000);
});
