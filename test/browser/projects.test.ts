/**
 * The book's simulation projects in headless Chromium: input changes each game (the solar system's
 * keys aim and launch the probe, its rate key speeds up its clock and its error table reads the
 * ephemeris; the submarine's keys drive the screw and flood the tanks; the flight simulator's keys
 * open the throttle and pull the nose up, its ring label stays clear of the path marker and its
 * cockpit view has an instrument panel that reads the instruments).
 */

import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { lowContrastText } from './contrast-check';
import { pausedShade, resumedShade } from './dom-pause';
import { afterRelease, recordBank } from './flight-bank';
import { type GamePage, Harness } from './harness';
import { checkPageContract } from './page-contract';

interface Game {
  paused: boolean;
  // biome-ignore lint/suspicious/noExplicitAny: the page's stores are read loosely here
  world: { time: number; components: any };
  step(): void;
}

/**
 * Puts the flight simulator's aircraft at ring 1's centre plus (dx, dz), m (the course's first ring
 * lies along +x), before the first input starts the flight.
 */
async function placeBeforeRing1(g: GamePage, dx: number, dz: number): Promise<void> {
  await g.page.evaluate(
    ([ox, oz]) => {
      const w = window.game as unknown as Game & { aircraftBody(): number; rings(): { x: number; y: number; z: number }[] };
      const r = w.rings()[0]!,
        c = w.world.components,
        e = w.aircraftBody();
      c.Position.x[e] = r.x + ox!;
      c.Position.y[e] = r.y;
      c.Position.z[e] = r.z + oz!;
    },
    [dx, dz],
  );
}

describe('projects', () => {
  let h: Harness;
  beforeAll(async () => {
    h = await Harness.start();
  });
  afterAll(async () => {
    await h?.close();
  });

  it('solar-system: the status states the goal and the forecast’s verdict; H a hint of what to change and watch, again on H; paused, the keys turn and speed up the launch; Space launches the probe, ↑ in flight burns and the forecast follows; ] raises the rate; the error table starts at the ephemeris', async () => {
    // ?verdict=1: the forecast's verdict from the start (players get it after a failed try; the reload case reads the map).
    const g = await h.openGame('solar-system', { viewport: { width: 1280, height: 800 }, locale: 'de-DE', query: { rate: 0, verdict: 1 } });
    await checkPageContract(g, 'solar-system', 'desktop');
    type Mission = {
      number: number;
      target: string;
      phase: string;
      aim: { angle: number; speed: number };
      plan: { hit: boolean; distance: number; time: number; current: boolean; shown: boolean };
      flight: { state: string; elapsed: number; fuelUsed: number; burns: number } | null;
    };
    type Solar = { mission(): Mission; params: { rate: number } };
    // The forecast for the aim now, drawn: the status line's words change with the map's (a stranger
    // read "day 371" in the line over tags still saying "day 366").
    const current = () =>
      g.waitFor(() => {
        const p = (window.game as unknown as Solar).mission().plan;
        return p.current && p.shown;
      }, null);
    await current();
    const m0 = await g.page.evaluate(() => (window.game as unknown as Solar).mission());
    expect([m0.number, m0.target, m0.phase]).toEqual([1, 'Mars', 'aim']);
    // The first mission starts short: the arrow points the right way but the launch is too slow. The
    // goal is stated above the scene; the line gives the forecast's verdict (the flight flown ahead,
    // games/solar-system/forecast.ts), not what to press; H shows that.
    expect(m0.plan.hit).toBe(false);
    expect(await g.page.locator('[data-hud="goal"]').textContent()).toBe('Mission 1/7: fly to Mars · ★★★ ≤ 3.3 km/s');
    const numbers = (await g.page.locator('[data-hud="plan"]').textContent()) ?? '';
    expect(numbers).toMatch(
      /^Launch \d+\.\d km\/s along the Earth’s path → ✗ goes out only to \d\.\d\d AU from the Sun; Mars will be at \d\.\d\d AU$/,
    );
    expect(numbers).not.toMatch(/press|tap|more speed/);
    expect(await g.page.locator('[data-hud="hint"]').textContent()).toBe('');
    // The header has one height (main.ts STATUS_ROW): the stage's top and height stay as they were
    // through the hint (it grew the header by a line, and one frame drew the canvas black), a longer
    // line and the flight (the header grew from 107 to 146 px over the first missions, each time
    // moving the map down). To the pixel.
    const stageBox = () =>
      g.page.evaluate(() => {
        const r = document.querySelector('canvas')!.getBoundingClientRect();
        return [Math.round(r.top), Math.round(r.height)];
      });
    const boxBefore = await stageBox();
    // The hint says which way to change and what to watch, not how many presses (counting presses
    // to a green line was the whole game): a faster launch.
    await g.press('h');
    await g.waitFor(
      () => /^A faster launch \(↑\) flies farther out/.test(document.querySelector('[data-hud="hint"]')?.textContent ?? ''),
      null,
    );
    expect(await g.page.locator('[data-hud="hint"]').textContent()).not.toMatch(/\d+ times|twice|once/);
    expect(await stageBox()).toEqual(boxBefore);
    // Nor does a longer plan or hint move it (mission 2's hint took five lines on a phone): the
    // header's height does not follow its words. (Set here, and put back by the next update.)
    await g.page.evaluate(() => {
      for (const hud of ['plan', 'hint']) document.querySelector(`[data-hud="${hud}"]`)!.textContent = 'a longer line of words '.repeat(12);
    });
    await g.frames(1);
    expect(await stageBox()).toEqual(boxBefore);
    // The legend lists the few controls a mission needs (with the kit's P, N, R): 16 lines were too
    // many to learn; the rest are named in the panel.
    expect(await g.page.locator('.bp-legend > div').count()).toBe(9);
    expect(await g.page.locator('[data-hud="more-keys"]').textContent()).toMatch(/^More keys: Enter .* 1 2 3 views; D distances; E sizes/);
    // Up 6 times (2.8 km/s): still short. H again keeps the hint (it hid it) and works it out again.
    for (let i = 0; i < 6; i++) await g.press('ArrowUp');
    await current();
    expect(await g.page.evaluate(() => (window.game as unknown as Solar).mission().plan.hit)).toBe(false);
    await g.press('h');
    await g.waitFor(() => /^A faster launch/.test(document.querySelector('[data-hud="hint"]')?.textContent ?? ''), null);
    // Paused (P), the aim still moves the forecast: up twice more. It arrives, and the line says so
    // with the stars this speed earns: the forecast is the flight (the white dot is inside the ring
    // drawn at the real zone; the case below checks the two agree); the hint says what to look at.
    await g.press('p');
    for (let i = 0; i < 2; i++) await g.press('ArrowUp');
    await current();
    const m1 = await g.page.evaluate(() => (window.game as unknown as Solar).mission());
    expect(m1.aim.speed).toBeCloseTo(m0.aim.speed + 0.8, 9);
    expect(m1.plan.hit).toBe(true);
    const judged = (await g.page.locator('[data-hud="plan"]').textContent()) ?? '';
    expect(judged).toMatch(/ → ✓ meets Mars on day \d+ · ★★★$/);
    expect(await g.page.locator('[data-hud="plan"]').getAttribute('class')).toBe('ss-line ok');
    expect(await stageBox()).toEqual(boxBefore);
    await g.waitFor(
      () => /^Look where the dots end: .* press Space\.$/.test(document.querySelector('[data-hud="hint"]')?.textContent ?? ''),
      null,
    );
    // The ring where Mars will be and the probe's place then are named on the map.
    await g.frames(2);
    const tags = await g.page.evaluate(() =>
      ['target-then', 'probe-then'].map((n) => {
        const el = document.querySelector<HTMLElement>(`[data-tag="${n}"]`);
        return el && el.style.display !== 'none' ? el.textContent : null;
      }),
    );
    expect(tags).toEqual(['Mars at arrival', 'probe then']);
    // The preview draws the forecast to the arrival: the probe's dots (every 4th point and the last),
    // Mars's own dots to the meeting, and the white dot of the probe then (hit or miss: the player judges).
    await g.frames(2);
    type Preview = { dots: number; shownPoints: number; probeThen: boolean; track: boolean; pointsToTime: number; points: number };
    const preview = await g.page.evaluate(() => (window.game as unknown as { preview(): Preview }).preview());
    expect(preview.probeThen).toBe(true);
    expect(preview.track).toBe(true);
    expect(preview.shownPoints).toBe(preview.points);
    expect(preview.dots).toBe(Math.ceil(preview.shownPoints / 4) + 1);
    // Turning: → turns the arrow by 2 degrees (clockwise, outwards), and the forecast follows.
    await g.press('ArrowRight');
    const m2 = await g.page.evaluate(() => (window.game as unknown as Solar).mission());
    expect(m2.aim.angle).toBeCloseTo(m0.aim.angle + 2, 9);
    await current();
    expect(await g.page.evaluate(() => (window.game as unknown as Solar).mission().plan.time)).not.toBe(m1.plan.time);
    await g.press('ArrowLeft');
    await current();
    await g.press('p');
    const before = await g.page.evaluate(() => (window.game as unknown as Solar).params.rate);
    await g.press(']');
    expect(await g.page.evaluate(() => (window.game as unknown as Solar).params.rate)).toBeGreaterThan(before);
    // Time runs at the rate now, and the line says how fast; paused (P), it says paused, not the
    // rate (it said "11 days a second" with nothing moving); P again and the rate is back.
    const dateLine = () => g.page.locator('[data-hud="date"]').textContent();
    await g.waitFor(() => /days a second/.test(document.querySelector('[data-hud="date"]')?.textContent ?? ''), null);
    await g.press('p');
    await g.waitFor(() => / · paused · /.test(document.querySelector('[data-hud="date"]')?.textContent ?? ''), null);
    expect(await dateLine()).not.toMatch(/days a second/);
    await g.press('p');
    await g.waitFor(() => /days a second/.test(document.querySelector('[data-hud="date"]')?.textContent ?? ''), null);
    // Time waits again while aiming (the forecast is for the moment of the launch).
    await g.page.evaluate(() => (window.game as unknown as { setRate(days: number): void }).setRate(0));
    const errors = await g.page.evaluate(() => (window.game as unknown as { errors(): Record<string, number> }).errors());
    // A few simulated days in: every planet still within 1e-3 of the ephemeris (the one-year floor is 2.9e-3 for Mercury).
    for (const e of Object.values(errors)) expect(e).toBeLessThan(1e-3);
    // The comparison is there, folded.
    expect(await g.page.locator('details[data-hud="ephemeris"]').getAttribute('open')).toBeNull();
    await current();
    const launched = await g.page.evaluate(() => (window.game as unknown as Solar).mission().plan);
    expect(launched.hit).toBe(true);
    await g.press('Space');
    const flying = await g.waitFor(() => {
      const m = (window.game as unknown as Solar).mission();
      return m.phase === 'flight' && m.flight!.elapsed > 5 ? m : null;
    }, null);
    expect(flying.flight!.state).toBe('flying');
    // In flight the line gives the forecast of the course (the launch's: the same day) and the fuel.
    expect(flying.plan.time).toBe(launched.time);
    expect(await g.page.locator('[data-hud="plan"]').textContent()).toMatch(
      /^Day \d+ · \d\.\d\d AU to Mars · ✓ arrives on day \d+ · fuel 1\.00 km\/s$/,
    );
    // The header keeps its height in flight (one line fewer than aiming moved the canvas 17 px).
    expect(await stageBox()).toEqual(boxBefore);
    // ↑ is a burn along the motion: the fuel goes down by 0.05 km/s and the forecast follows it.
    await g.press('p');
    await g.press('ArrowUp');
    const burnt = await g.waitFor(() => {
      const m = (window.game as unknown as Solar).mission();
      return m.flight!.burns === 1 && m.plan.current ? m : null;
    }, null);
    expect(burnt.flight!.fuelUsed).toBeCloseTo(0.05, 9);
    // The course before the burn is kept to show dim beside the new one (for 4 s of the clock, so
    // not read here whether it shows: the count of its dots is set at the burn, none before one).
    expect(
      await g.page.evaluate(() => (window.game as unknown as { burnLook(): { ghostDots: number } }).burnLook().ghostDots),
    ).toBeGreaterThan(10);
    expect(burnt.plan.hit ? burnt.plan.time : burnt.plan.distance).not.toBe(burnt.plan.hit ? launched.time : launched.distance);
    await g.waitFor(() => document.querySelector('[data-hud="plan"]')?.textContent?.endsWith('fuel 0.95 km/s'), null);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('solar-system: the ring "at arrival" is the real zone and the line the real verdict: the white dot is inside the ring exactly when the line says ✓, and a ✓ launch arrives', async () => {
    const g = await h.openGame('solar-system', { viewport: { width: 1280, height: 800 }, query: { rate: 0, verdict: 1 } });
    type Plan = { hit: boolean; distance: number; current: boolean; shown: boolean; key: string };
    type Ghost = { key: string; visible: boolean; ring: [number, number][]; dot: [number, number] };
    type Solar = {
      mission(): { phase: string; plan: Plan; flight: { burns: number } | null };
      ghost(): Ghost;
      startMission(i: number): void;
      waitForWindow(): void;
      setAim(angle: number, speed: number): void;
      launch(): void;
      finishFlight(): string;
      params: { rate: number };
    };
    await g.page.evaluate(() => (window.game as unknown as Solar).startMission(1));
    await g.page.evaluate(() => (window.game as unknown as Solar).waitForWindow());
    // At the window (tens of days on) time waits again for the aim.
    await g.waitFor(
      () => {
        const key = (window.game as unknown as Solar).mission().plan.key;
        const line = document.querySelector('[data-hud="date"]')?.textContent ?? '';
        return Number(key.slice(key.indexOf('|') + 1)) > 30 && /launch window for Venus/.test(line) ? true : null;
      },
      null,
      60_000,
    );
    // Where the dot is against the drawn ring: inside (ray crossing) and its distance to the ring's line, px.
    const against = (ring: [number, number][], [x, y]: [number, number]) => {
      let inside = false,
        edge = Infinity;
      for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
        const [xi, yi] = ring[i]!,
          [xj, yj] = ring[j]!;
        if (yi > y !== yj > y && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
        const dx = xj - xi,
          dy = yj - yi;
        const t = Math.max(0, Math.min(1, ((x - xi) * dx + (y - yi) * dy) / (dx * dx + dy * dy)));
        edge = Math.min(edge, Math.hypot(xi + t * dx - x, yi + t * dy - y));
      }
      return { inside, edge };
    };
    let hits = 0,
      nearMisses = 0,
      hitAim: [number, number] | null = null;
    // Launches round the window (hits) and off it by up to 30 degrees and 1 km/s (misses, some near).
    for (const angle of [150, 160, 170, 176, 180])
      for (const speed of [2.2, 2.7, 3.2]) {
        await g.page.evaluate(([a, s]) => (window.game as unknown as Solar).setAim(a!, s!), [angle, speed]);
        // The line is read once a frame showing this forecast is drawn: it changes with the map.
        const seen = await g.waitFor(
          (head) => {
            const game = window.game as unknown as Solar;
            const plan = game.mission().plan;
            const ghost = game.ghost();
            const line = document.querySelector('[data-hud="plan"]')?.textContent ?? '';
            return plan.current && plan.shown && ghost.key === plan.key && line.startsWith(head) ? { plan, ghost, line } : null;
          },
          `Launch ${speed.toFixed(1)} km/s ${angle === 180 ? 'against' : `${angle}°`}`,
        );
        const where = against(seen.ghost.ring, seen.ghost.dot);
        const what = `${angle}° ${speed} km/s: closest ${seen.plan.distance} AU, dot ${JSON.stringify(where)}, ${seen.line}`;
        // The line's verdict is the forecast's.
        expect(/ → ✓ meets Venus on day \d+/.test(seen.line), what).toBe(seen.plan.hit);
        // A hit ends at the zone's edge (the first step inside): the dot on the ring or inside it. A
        // miss never comes inside the zone: the dot is outside the ring or on it.
        if (seen.plan.hit) {
          hits++;
          hitAim ??= [angle, speed];
          expect(where.inside || where.edge < 2, what).toBe(true);
        } else {
          if (seen.plan.distance < 0.14) nearMisses++;
          expect(!where.inside || where.edge < 2, what).toBe(true);
        }
      }
    expect(hits).toBeGreaterThan(0);
    expect(nearMisses).toBeGreaterThan(0);
    // And the ✓ holds: the launch arrives.
    await g.page.evaluate(([a, s]) => (window.game as unknown as Solar).setAim(a!, s!), hitAim!);
    await g.waitFor(() => (window.game as unknown as Solar).mission().plan.current || null, null);
    await g.page.evaluate(() => (window.game as unknown as Solar).launch());
    expect(await g.page.evaluate(() => (window.game as unknown as Solar).finishFlight())).toBe('arrived');
    // The result card hides the map under it: its ground is opaque (the planets' names showed through).
    const ground = await g.waitFor(() => {
      const card = document.querySelector<HTMLElement>('.ss-card');
      return card && !card.hidden ? getComputedStyle(card).backgroundColor : null;
    }, null);
    expect(ground).toMatch(/^rgb\(\d+, \d+, \d+\)$/);
    // In flight a burn holds time still for a moment, so the taps of a hint's "Press ↓ 4 times now"
    // all act at the moment it was worked out for (time ran on at a fifth of its rate and the hint
    // then asked for more burns than the fuel allowed).
    await g.page.evaluate(() => (window.game as unknown as Solar).startMission(1));
    await g.page.evaluate(([a, s]) => (window.game as unknown as Solar).setAim(a!, s!), hitAim!);
    await g.waitFor(() => (window.game as unknown as Solar).mission().plan.current || null, null);
    await g.page.evaluate(() => (window.game as unknown as Solar).launch());
    type Rate = { rate(): { days: number; sinceBurn: number } };
    await g.waitFor(() => (window.game as unknown as Rate).rate().days > 0 || null, null);
    await g.press('ArrowDown');
    const held = await g.waitFor(() => {
      const game = window.game as unknown as Solar & Rate;
      return game.mission().flight?.burns === 1 ? game.rate() : null;
    }, null);
    // Read in the same moment as the burn count; only meaningful within the hold (800 ms).
    expect(held.sinceBurn >= 800 || held.days === 0, JSON.stringify(held)).toBe(true);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('solar-system: a reload goes on at the mission last started, or at the next not yet flown once it has stars; ?mission= picks one', async () => {
    const g = await h.openGame('solar-system', { viewport: { width: 1280, height: 800 }, query: { rate: 0 } });
    type Solar = { mission(): { number: number; phase: string }; startMission(index: number): void };
    const number = () => g.page.evaluate(() => (window.game as unknown as Solar).mission().number);
    const startSpeed = await g.page.evaluate(
      () => (window.game as unknown as { mission(): { aim: { speed: number } } }).mission().aim.speed,
    );
    // A first visit (no storage) starts at mission 1, its line reading the launch's path (without the
    // ring at arrival) and its verdict: ✗, short of Mars's orbit.
    expect(await number()).toBe(1);
    await g.waitFor(
      () =>
        / → ✗ goes out only to \d\.\d\d AU from the Sun, short of Mars’s orbit$/.test(
          document.querySelector('[data-hud="plan"]')?.textContent ?? '',
        ),
      null,
    );
    // Faster, a step at a time: once the line reads the new speed, the map's tags give the same day
    // as the line (a stranger read "day 371" in the line over tags saying "day 366"), and the line
    // says which way the probe crosses Mars's orbit then, and when it crosses it again (the day
    // picked switched between the two, 222 to 341, and read as random).
    type Aiming = { mission(): { aim: { speed: number }; plan: { shown: boolean } } };
    let crossings = 0;
    for (let i = 0; i < 8; i++) {
      const speed = await g.page.evaluate(() => (window.game as unknown as Aiming).mission().aim.speed);
      await g.press('ArrowUp');
      const seen = await g.waitFor(
        (head) => {
          const line = document.querySelector('[data-hud="plan"]')?.textContent ?? '';
          // The new aim's words (until its forecast is drawn the line reads "head …").
          if (!line.startsWith(head) || line.endsWith(' …') || !(window.game as unknown as Aiming).mission().plan.shown) return null;
          const tag = (n: string) => {
            const el = document.querySelector<HTMLElement>(`[data-tag="${n}"]`);
            return el && el.style.display !== 'none' ? el.textContent : null;
          };
          return { line, tags: [tag('target-then'), tag('probe-then')] };
        },
        `Launch ${(speed + 0.1).toFixed(1)} km/s`,
      );
      const day = seen.line.match(/is at Mars’s orbit on day (\d+) (going out|coming in)/)?.[1];
      if (!day) continue;
      crossings++;
      // And the line's verdict on that meeting (a stranger read "Will Mars be there?" with no answer).
      expect(seen.line).toMatch(
        /\. (✓ Mars will be there · ★|✗ Mars (gets there \d+ days? later|passed there \d+ days? before)|✗ misses Mars: closest)/,
      );
      expect(seen.tags, seen.line).toEqual([`Mars on day ${day}`, `probe on day ${day}`]);
      // Every crossing named with its way; in order of day they alternate, out first: a path from
      // the Earth, inside Mars's orbit, crosses it going out before it can come back in.
      const named = [...seen.line.matchAll(/day (\d+) (going out|coming in)/g)].map((c) => [Number(c[1]), c[2]] as const);
      const ways = named.sort((a, b) => a[0] - b[0]).map((c) => c[1]);
      if (named.length > 1) expect(seen.line).toContain('Mars farther then)');
      expect(ways, seen.line).toEqual(ways.map((_, k) => (k % 2 === 0 ? 'going out' : 'coming in')));
    }
    expect(crossings).toBeGreaterThan(3);
    // Wait held: time runs and the tags still name the day the line gives (a stranger holding W on
    // the Venus mission lost "Venus on day N", the guidance the wait is for, while time ran).
    type Running = { rate(): { days: number } };
    const lineBefore = (await g.page.locator('[data-hud="plan"]').textContent()) ?? '';
    await g.page.keyboard.down('w');
    const waited = await g.waitFor((before) => {
      // Time runs and the line names a new day (a forecast from a later launch day is drawn).
      if ((window.game as unknown as Running).rate().days <= 0) return null;
      const line = document.querySelector('[data-hud="plan"]')?.textContent ?? '';
      const day = line.match(/is at Mars’s orbit on day (\d+)/)?.[1];
      if (!day || day === before.match(/is at Mars’s orbit on day (\d+)/)?.[1]) return null;
      const tag = (n: string) => document.querySelector<HTMLElement>(`[data-tag="${n}"]`);
      const shown = ['target-then', 'probe-then'].map((n) => (tag(n)?.style.display === 'none' ? null : tag(n)?.textContent));
      // The tags follow at the next frame drawn.
      return shown[0] === `Mars on day ${day}` ? { line, shown, day } : null;
    }, lineBefore);
    await g.page.keyboard.up('w');
    expect(waited.shown, waited.line).toEqual([`Mars on day ${waited.day}`, `probe on day ${waited.day}`]);
    // A press reads in the line at once, in the same task (it waited for the next frame, and a
    // stranger's fourth press showed 2.4 km/s over a page already at 2.6); its words "…" until the
    // new aim's forecast is drawn, never the last aim's day under the new speed.
    const pressed = await g.page.evaluate(() => {
      const speed = (window.game as unknown as Aiming).mission().aim.speed;
      for (const type of ['keydown', 'keyup']) document.body.dispatchEvent(new KeyboardEvent(type, { key: 'ArrowUp', bubbles: true }));
      return { speed, line: document.querySelector('[data-hud="plan"]')?.textContent ?? '' };
    });
    expect(pressed.line).toBe(`Launch ${(pressed.speed + 0.1).toFixed(1)} km/s along the Earth’s path → …`);
    // R restarts the mission: its first day (the wait undone) and its starting launch speed (it kept
    // the last speed, where a player expected a reset; T keeps it).
    await g.press('r');
    const restarted = await g.waitFor(() => {
      const game = window.game as unknown as Aiming & { world: { time: number } };
      return game.world.time === 0 ? game.mission().aim.speed : null;
    }, null);
    expect(restarted).toBe(startSpeed);
    // Mission 4 started, then the page reloaded: mission 4 again (it went back to mission 1).
    await g.page.evaluate(() => (window.game as unknown as Solar).startMission(3));
    await g.page.reload();
    await g.waitFor(() => (window.game as unknown as Solar | undefined)?.mission?.().phase === 'aim', null);
    expect(await number()).toBe(4);
    // Mission 4 flown (stars kept) with 5 flown before: the reload goes on at 6, the next not flown.
    await g.page.evaluate(() => localStorage.setItem('bitphysics.solar-system.stars', JSON.stringify([3, 2, 0, 1, 2, 0, 0])));
    await g.page.reload();
    await g.waitFor(() => (window.game as unknown as Solar | undefined)?.mission?.().phase === 'aim', null);
    expect(await number()).toBe(6);
    // Every mission flown: the one last started (6).
    await g.page.evaluate(() => localStorage.setItem('bitphysics.solar-system.stars', JSON.stringify([3, 2, 1, 1, 2, 1, 3])));
    await g.page.reload();
    await g.waitFor(() => (window.game as unknown as Solar | undefined)?.mission?.().phase === 'aim', null);
    expect(await number()).toBe(6);
    // ?mission= wins over the storage.
    await g.page.goto(`${g.page.url().split('?')[0]}?rate=0&mission=2`);
    await g.waitFor(() => (window.game as unknown as Solar | undefined)?.mission?.().phase === 'aim', null);
    expect(await number()).toBe(2);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('solar-system: orbit lines; 2 frames all eight planets, 1 the inner four; labels by their dots never overlap', async () => {
    const g = await h.openGame('solar-system', { viewport: { width: 1280, height: 800 }, query: { rate: 0 } });
    type Solar = { orbitCount(): number; planetsInView(): string[]; shownLabels(): number };
    expect(await g.page.evaluate(() => (window.game as unknown as Solar).orbitCount())).toBe(8);
    await g.press('2');
    await g.waitFor(() => (window.game as unknown as Solar).planetsInView().length === 8, null);
    // Every body shows as a dot at least 6 px wide or is drawn at least 3 px in radius (the exaggerated
    // spheres of the small planets are a pixel or two at this scale), and every name shows beside its
    // body, no two labels' boxes intersecting. The labels move only in frames that are drawn (the
    // frame pacer skips some while the GPU is behind): wait for two.
    const drawn = await g.page.evaluate(() => (window.game as unknown as { pacer: { drawn: number } }).pacer.drawn);
    await g.waitFor((d) => (window.game as unknown as { pacer: { drawn: number } }).pacer.drawn >= d + 2, drawn);
    type Marker = { x: number; y: number; radius: number; dot: boolean; visible: boolean };
    const report = await g.page.evaluate(() => {
      const markers = (window.game as unknown as { markers(): Record<string, Marker> }).markers();
      const labels = [...document.querySelectorAll<HTMLElement>('[data-label]')].filter((el) => el.style.display !== 'none');
      const boxes = labels.map((el) => el.getBoundingClientRect());
      let overlaps = 0;
      for (let i = 0; i < boxes.length; i++)
        for (let j = i + 1; j < boxes.length; j++) {
          const a = boxes[i]!,
            b = boxes[j]!;
          if (a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom) overlaps++;
        }
      // How far each name's box is from its body's rim, px.
      const stage = document.querySelector('.bp-stage')!.getBoundingClientRect();
      let farthest = 0;
      for (const [i, el] of labels.entries()) {
        const m = markers[el.dataset.label!]!,
          b = boxes[i]!;
        const dx = Math.max(b.left - stage.left - m.x, m.x - (b.right - stage.left), 0),
          dy = Math.max(b.top - stage.top - m.y, m.y - (b.bottom - stage.top), 0);
        farthest = Math.max(farthest, Math.hypot(dx, dy) - m.radius);
      }
      const seen = Object.entries(markers).filter(([name, m]) => name !== 'probe' && m.visible && (m.dot || m.radius >= 3));
      return { overlaps, shown: labels.length, farthest, seen: seen.length };
    });
    expect(report.seen).toBe(9);
    expect(report.overlaps).toBe(0);
    // Nine names fit; a name may wait a frame while two bodies pass each other.
    expect(report.shown).toBeGreaterThanOrEqual(8);
    // Beside its body: the gap is a few pixels, never a row or more away.
    expect(report.farthest).toBeLessThan(16);
    await g.press('1');
    await g.waitFor(() => !(window.game as unknown as Solar).planetsInView().includes('Neptune'), null);
    const inner = await g.page.evaluate(() => (window.game as unknown as Solar).planetsInView());
    for (const p of ['Mercury', 'Venus', 'Earth', 'Mars']) expect(inner).toContain(p);
    // A won mission: on the start date (time waits while aiming) 3.0 km/s along the Earth's path
    // arrives at Mars (the first case's launch). Flown to its end at once, it shows the result card:
    // 3 stars (3.0 <= 3.3 km/s) and the score's budget part, 1000 x the Hohmann speed over 3.0 km/s:
    // v_E (sqrt(2 r / (1 + r)) - 1) = 29.78 x 0.0989 = 2.945 km/s at r = 1.524 AU, so 982 (975..990
    // allows for the constants' rounding). Its Next mission button starts mission 2, Venus.
    type Flow = {
      setAim(a: number, s: number): void;
      launch(): void;
      finishFlight(): string;
      mission(): {
        number: number;
        target: string;
        phase: string;
        aim: { angle: number };
        plan: { hit: boolean; current: boolean; time: number };
      };
    };
    // A click on Mars itself does not aim the launch at Mars (24 degrees outwards from the Earth, a
    // course no transfer flies): it turns the arrow along the Earth's path and says why.
    await g.page.evaluate(() => (window.game as unknown as Flow).setAim(30, 3));
    await g.press('3');
    // The markers are where the last drawn frame put them, and the view eases to its new zoom: click
    // where Mars is once two drawn frames in a row show it in the same place.
    const marsAt = () =>
      g.page.evaluate(() => {
        const game = window.game as unknown as { markers(): Record<string, Marker>; pacer: { drawn: number } };
        const m = game.markers().Mars!;
        const stage = document.querySelector('.bp-stage')!.getBoundingClientRect();
        return { x: stage.left + m.x, y: stage.top + m.y, drawn: game.pacer.drawn };
      });
    let mars = await marsAt();
    for (let tries = 0; tries < 100; tries++) {
      await g.waitFor((d) => (window.game as unknown as { pacer: { drawn: number } }).pacer.drawn > d, mars.drawn);
      const next = await marsAt();
      const still = Math.hypot(next.x - mars.x, next.y - mars.y) < 0.5;
      mars = next;
      if (still) break;
    }
    await g.page.mouse.click(mars.x, mars.y);
    expect((await g.page.evaluate(() => (window.game as unknown as Flow).mission())).aim.angle).toBe(0);
    expect(await g.page.locator('[data-hud="brief"]').textContent()).toMatch(/^A probe does not fly straight at Mars/);
    await g.page.evaluate(() => (window.game as unknown as Flow).setAim(0, 3));
    const aimed = await g.waitFor(() => {
      const m = (window.game as unknown as Flow).mission();
      return m.plan.current ? m : null;
    }, null);
    expect(aimed.plan.hit).toBe(true);
    // The forecast is the flight flown ahead: the card's flight days are the forecast's, within a day.
    // (The line promised the score before the launch; it no longer says whether it arrives.)
    // Abort takes Launch's place in the bar: a tap on it in the flight's first 48 ticks (0.8 s) does
    // nothing, so a double tap on Launch does not end the flight it began (it did: back to aiming).
    const kept = await g.page.evaluate(() => {
      (window.game as unknown as Flow).launch();
      document.querySelector<HTMLElement>('.ss-pad button[data-pad="abort"]')!.click();
      return (window.game as unknown as Flow).mission().phase;
    });
    expect(kept).toBe('flight');
    // The arrival gets its moment before the card: "Mars reached!" and the three stars over the scene.
    const ended = await g.page.evaluate(() => {
      const state = (window.game as unknown as Flow).finishFlight();
      const banner = document.querySelector<HTMLElement>('[data-hud="arrival-banner"]')!;
      const card = document.querySelector<HTMLElement>('[data-hud="result-card"]')!;
      // The banner keeps clear of the Sun's name (it hid all but "Su").
      const b = banner.getBoundingClientRect(),
        sun = document.querySelector<HTMLElement>('[data-label="Sun"]')!.getBoundingClientRect();
      const clear = b.bottom <= sun.top || b.top >= sun.bottom;
      return { state, banner: banner.hidden ? null : banner.textContent, card: card.hidden, clear };
    });
    expect(ended).toEqual({ state: 'arrived', banner: 'Mars reached!★★★', card: true, clear: true });
    const card = g.page.locator('[data-hud="result-card"]');
    await card.waitFor({ state: 'visible' });
    expect(await card.locator('h2').textContent()).toBe('Mars reached!');
    expect(await card.locator('.bp-result-stars span:not(.off)').count()).toBe(3);
    const scored = Number.parseInt((await card.locator('.ss-card-score').textContent()) ?? '', 10);
    expect(scored).toBeGreaterThan(0);
    const days = Number(/Flight (\d+) days/.exec((await card.locator('.ss-card-parts').textContent()) ?? '')?.[1]);
    expect(Math.abs(days - aimed.plan.time)).toBeLessThanOrEqual(1);
    const budget = Number(await card.locator('.ss-card-parts b').first().textContent());
    expect(budget).toBeGreaterThanOrEqual(975);
    expect(budget).toBeLessThanOrEqual(990);
    // At desktop size too, the card lists the missions with their stars, as on a phone (a stranger
    // who looked during the banner took the desktop for a banner alone); each is a button that flies it.
    const chips = await card.locator('.ss-card-map > button').allTextContents();
    expect(chips.map((c) => c.replace(/ [★–]+$/, ''))).toEqual([
      '1 Mars',
      '2 Venus',
      '3 Jupiter',
      '4 Mercury',
      '5 Saturn',
      '6 Uranus',
      '7 Neptune',
    ]);
    expect(chips[0]).toBe('1 Mars ★★★');
    // The card's text over the scene is legible (WCAG AA, 4.5:1).
    expect((await lowContrastText(g.page)).filter((t) => /reached|points|arrival|Speed|Flight|Next|Try|Mars|★/.test(t.text))).toEqual([]);
    await card.getByRole('button', { name: 'next mission (Enter)' }).click();
    await card.waitFor({ state: 'hidden' });
    const next = await g.page.evaluate(() => (window.game as unknown as Flow).mission());
    expect([next.number, next.target, next.phase]).toEqual([2, 'Venus', 'aim']);
    expect(await g.page.locator('[data-hud="goal"]').textContent()).toMatch(/^Mission 2\/7: fly to Venus · /);
    // Wait held speeds up with the days it has run, to 4 times its start, slows to 15 days a second
    // within 60 days of the next launch window and stands at it 1.5 s (90 ticks) whatever the aim
    // (./wait-pace.ts; it raced past the windows for years with the aim off), then runs on while
    // held. Stepped by hand: 10 ticks at the start, 10 after 100 days, then on until it slows.
    await g.page.evaluate(() => {
      (window.game as unknown as { paused: boolean }).paused = true;
    });
    await g.page.keyboard.down('w');
    const held = await g.page.evaluate(() => {
      const w = window.game as unknown as {
        step(): void;
        world: { time: number };
        rate(): { days: number };
        heliocentric(name: string): number[];
      };
      const ten = (): number => {
        const t = w.world.time;
        for (let k = 0; k < 10; k++) w.step();
        return w.world.time - t;
      };
      const first = ten();
      const t0 = w.world.time;
      for (let k = 0; k < 2000 && w.world.time - t0 < 100; k++) w.step();
      const later = ten();
      for (let k = 0; k < 5000 && w.rate().days > 15; k++) w.step();
      const slowAt = w.world.time;
      const slow = ten();
      const slowRate = w.rate().days;
      // On to the window, and Venus's lead on the Earth there.
      for (let k = 0; k < 2000 && w.rate().days > 0; k++) w.step();
      const stopAt = w.world.time;
      const [vx, , vz] = w.heliocentric('Venus'),
        [ex, , ez] = w.heliocentric('Earth');
      const lead = Math.atan2(vz!, vx!) - Math.atan2(ez!, ex!);
      return { first, later, slowAt, slow, slowRate, stopAt, lead };
    });
    // Standing there, the date line names the window (the page draws while paused).
    await g.waitFor(() => /launch window for Venus/.test(document.querySelector('[data-hud="date"]')?.textContent ?? ''), null);
    // The ticks it stands there, and the days it runs in 10 ticks after.
    const stand = await g.page.evaluate((stopAt) => {
      const w = window.game as unknown as { step(): void; world: { time: number } };
      let standing = 0;
      for (let k = 0; k < 500; k++) {
        w.step();
        if (w.world.time !== stopAt) break;
        standing++;
      }
      const t = w.world.time;
      for (let k = 0; k < 10; k++) w.step();
      return { standing, after: w.world.time - t };
    }, held.stopAt);
    // 40 days a second, 10 ticks of 1/60 s: 6.7 days, and a little more as the ramp starts (+1 day).
    expect(held.first).toBeGreaterThan(6);
    expect(held.first).toBeLessThan(8.7);
    // 100 days on: 4 times it (the cap), 26.7 days, within a step (at most a day).
    expect(held.later).toBeGreaterThan(25.6);
    expect(held.later).toBeLessThan(27.8);
    // Near the window: 15 days a second, 2.5 days in 10 ticks (within a step).
    expect(held.slowRate).toBe(15);
    expect(held.slow).toBeGreaterThan(1.4);
    expect(held.slow).toBeLessThan(3.6);
    // It stops at the window, 60 days after the slowing began (within a tick's days, 2.7), for 90
    // ticks (a tick either way for the steps' rounding), then runs on slowly (at most 15 days a second).
    expect(Math.abs(held.stopAt - held.slowAt - 60)).toBeLessThan(4);
    expect(Math.abs(stand.standing - 90)).toBeLessThanOrEqual(2);
    expect(stand.after).toBeGreaterThan(0);
    expect(stand.after).toBeLessThan(3.6);
    await g.page.keyboard.up('w');
    // At the window Venus leads the Earth by the Hohmann transfer's angle, 54 degrees (within 6: the
    // page's window is worked out on circular orbits at their mean pace; the windows' period, 583.9
    // days, is checked by the node tests, test/games/solar-system-wait.test.ts).
    const lead = (((held.lead * 180) / Math.PI + 540) % 360) - 180;
    expect(Math.abs(Math.abs(lead) - 54)).toBeLessThan(6);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('submarine: D drives the screw ahead, S floods the tanks', async () => {
    const g = await h.openGame('submarine', { viewport: { width: 1280, height: 800 } });
    // At the start the camera frames the hull and the first beacon, which lies close ahead, at a
    // zoom that keeps the hull large; the label says it lies ahead and how far down.
    type Pointer = { index: number; dy: number; onScreen: boolean; visible: boolean; text: string; zoom: number };
    const aim = await g.waitFor(() => {
      const p = (window.game as unknown as { beaconPointer(): Pointer }).beaconPointer();
      return p.onScreen ? p : null;
    }, null);
    expect(aim.index).toBe(0);
    expect(aim.visible).toBe(true);
    expect(aim.zoom).toBeGreaterThan(5); // px/m: the 12 m hull at least 60 px long
    // Named by its letter (the first beacon is A), the target held until collected.
    expect(aim.text).toBe(`target A: ${aim.text.match(/\d+ m ahead/)![0]}, ${Math.abs(aim.dy).toFixed(0)} m down`);
    // The goal and the clock are stated above the scene.
    // (Level, beacons collected of the course's, the clock and par: "L1 · ◯ 0/6 · 0:00 · par 2:20",
    // not "0:00/2:20", which read as a time limit.)
    expect(await g.page.locator('[data-hud="goal"]').textContent()).toMatch(/^L1 · ◯ 0\/6 · 0:\d\d · par \d:\d\d$/);
    const x0 = await g.page.evaluate(() => {
      const w = window.game as unknown as Game & { hull(): number };
      return w.world.components.Position.x[w.hull()] as number;
    });
    await g.page.keyboard.down('d');
    await g.page.keyboard.down('s');
    // Held until the controls have moved (simulated time, not a wall-clock wait: the game's frames
    // run at once, GamePage.runUntil, at most 30 s of game time).
    const s = await g.runUntil(
      (start) => {
        const w = window.game as unknown as Game & { hull(): number; state: { throttle: number; fill: number } };
        const r = { throttle: w.state.throttle, fill: w.state.fill, x: w.world.components.Position.x[w.hull()] as number };
        return r.throttle > 0.3 && r.fill > 0.1 && r.x > start ? r : null;
      },
      x0,
      { maxFrames: 1800 },
    );
    await g.page.keyboard.up('d');
    await g.page.keyboard.up('s');
    expect(s.throttle).toBeGreaterThan(0.3);
    expect(s.fill).toBeGreaterThan(0.1);
    expect(s.x).toBeGreaterThan(x0);
    // Let go, the screw winds down to stop (it stayed at full ahead, which read as a stuck key) and
    // never backs on its own: the boat coasts on, slowed by the water's drag (a player brakes with
    // Astern); the coasting itself is test/games/submarine-helm.test.ts's.
    const letGo = await g.runUntil(
      () => {
        const w = window.game as unknown as Game & { hull(): number; state: { throttle: number } };
        return w.state.throttle === 0 ? { vx: w.world.components.Velocity.x[w.hull()] as number } : null;
      },
      null,
      { maxFrames: 1800 },
    );
    expect(letGo.vx).toBeGreaterThan(0);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('submarine: a mine costs a hit and throws the hull; a third scrape ends the run; the last beacon shows the stars', async () => {
    const g = await h.openGame('submarine', { query: { waves: 0, beacons: 2 } });
    type Sub = {
      world: { components: { Position: { x: Float64Array; y: Float64Array }; Velocity: { x: Float64Array; y: Float64Array } } };
      hull(): number;
      handles(): { beacons: Float64Array; seabed: { x0: number; dx: number; y: Float64Array } };
      state: { hits: number; spared: number; over: string; collected: number; minesHit: number; time: number; par: number };
      mines(): { x: number; y: number; live: boolean }[];
      endText(): string;
    };
    // The hull put at rest with its deck 0.5 m under the first mine (within its 2.4 m reach): the
    // mine goes off, costs a hit and its blast (440 kN s) throws the light hull (80 t, tanks empty)
    // down at about 5.5 m/s, where its buoyancy alone would only lift it. The game is paused there
    // and its frames of 1/60 s run at once (GamePage.runUntil), the fastest sinking speed seen kept
    // after each (a loaded machine's frames of many steps each could pass the blast's peak by).
    const mine = await g.page.evaluate(() => {
      const w = window.game as unknown as Sub & { paused: boolean };
      w.paused = true;
      const m = w.mines()[0]!;
      const c = w.world.components;
      c.Position.x[w.hull()] = m.x;
      c.Position.y[w.hull()] = m.y - 3.5;
      c.Velocity.x[w.hull()] = 0;
      c.Velocity.y[w.hull()] = 0;
      return m;
    });
    expect(mine.live).toBe(true);
    const blast = await g.runUntil(
      (seen) => {
        const w = window.game as unknown as Sub;
        seen.vy = Math.min(seen.vy, w.world.components.Velocity.y[w.hull()]!);
        return w.state.minesHit === 1 && seen.vy < -3 ? { hits: w.state.hits, live: w.mines()[0]!.live } : null;
      },
      { vy: 0 },
      { maxFrames: 600 },
    );
    expect(blast.hits).toBe(1);
    expect(blast.live).toBe(false);
    // Two scrapes already; the hull put into the seabed under it, coming down at 4 m/s (over the
    // 1.5 m/s an impact needs, games/submarine/seabed.ts), makes the third.
    await g.page.evaluate(() => {
      const w = window.game as unknown as Sub;
      const bed = w.handles().seabed;
      Object.assign(w.state, { hits: 2, spared: 0 });
      w.world.components.Position.x[w.hull()] = bed.x0 + 20 * bed.dx;
      w.world.components.Position.y[w.hull()] = bed.y[20]! + 1.4;
      w.world.components.Velocity.y[w.hull()] = -4;
    });
    await g.runUntil(() => (window.game as unknown as Sub).state.over === 'sunk', null, { maxFrames: 600 });
    await g.page.evaluate(() => {
      (window.game as unknown as { paused: boolean }).paused = false;
    });
    const again = g.page.getByRole('button', { name: 'Try again ↺', exact: true });
    await again.waitFor({ state: 'visible' });
    expect(await g.page.evaluate(() => (window.game as unknown as Sub).endText())).toContain('Hull breached!');
    await again.click();
    await g.waitFor(() => (window.game as unknown as Sub).state.over === '', null);
    expect(await g.page.evaluate(() => (window.game as unknown as Sub).state.hits)).toBe(0);
    // Both beacons collected inside par with the hull unhurt: the run is won with three stars.
    for (const i of [0, 1]) {
      await g.page.evaluate((i) => {
        const w = window.game as unknown as Sub;
        const b = w.handles().beacons;
        w.world.components.Position.x[w.hull()] = b[2 * i]! - 3;
        w.world.components.Position.y[w.hull()] = b[2 * i + 1]!;
      }, i);
      await g.runUntil((n) => (window.game as unknown as Sub).state.collected === n, i + 1, { maxFrames: 600 });
    }
    await g.runUntil(() => (window.game as unknown as Sub).state.over === 'won', null, { maxFrames: 600 });
    // Won on level 1 of 3: the card's button goes on to level 2.
    await g.page.getByRole('button', { name: 'Next level 2 ▶', exact: true }).waitFor({ state: 'visible' });
    const won = await g.page.evaluate(() => (window.game as unknown as Sub).state);
    expect(won.time).toBeLessThan(won.par);
    expect(await g.page.evaluate(() => (window.game as unknown as Sub).endText())).toMatch(
      /^LEVEL 1 OF 3All 2 beacons!★★★✓\u00a0all\u00a02\u00a0beacons · ✓\u00a00:\d\d\u00a0\(par\u00a0\d:\d\d\) · ✓\u00a0hull\u00a03\/3/,
    );
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('submarine: collecting a beacon spreads rings from it and shows "Beacon 1 of 6" for 2 s', async () => {
    const g = await h.openGame('submarine', { query: { waves: 0 } });
    type Sub = {
      world: { time: number; components: { Position: { x: Float64Array; y: Float64Array } } };
      hull(): number;
      handles(): { beacons: Float64Array };
      state: { collected: number };
      pickupEffect(): { count: number; banner: string; alpha: number };
    };
    expect(await g.page.evaluate(() => (window.game as unknown as Sub).pickupEffect().count)).toBe(0);
    // The hull put 3 m from the first beacon (the game collects within 7 m).
    const t0 = await g.page.evaluate(() => {
      const w = window.game as unknown as Sub;
      const c = w.world.components,
        e = w.hull(),
        b = w.handles().beacons;
      c.Position.x[e] = b[0]! - 3;
      c.Position.y[e] = b[1]!;
      return w.world.time;
    });
    const fx = await g.waitFor(() => {
      const w = window.game as unknown as Sub;
      return w.state.collected === 1 ? w.pickupEffect() : null;
    }, null);
    expect(fx.count).toBe(1);
    expect(fx.banner).toBe('Beacon 1 of 6\nnext: B');
    // Gone after PICKUP_LIFE (2 s) of game time (the frames run at once, 6 steps each, as at 10 frames a second).
    await g.runUntil((start) => (window.game as unknown as Sub).world.time > start + 2.5, t0, { seconds: 0.1 });
    await g.frames(2);
    const after = await g.page.evaluate(() => (window.game as unknown as Sub).pickupEffect());
    expect(after.count).toBe(0);
    expect(after.banner).toBe('');
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('flight-simulator: the ring label sits clear of the path marker; the cockpit view has a canopy and an instrument panel whose gauges read the instruments and whose attitude indicator follows the bank; the ring label stays in view', async () => {
    const g = await h.openGame('flight-simulator');
    type Pointer = { index: number; inView: boolean; text: string; box: number[]; ring: number[] };
    type Panel = {
      visible: boolean;
      panelTop: number;
      gauges: { name: string; value: number }[];
      attitude: number[];
    };
    type Att = {
      attitude(): { pitch: number; roll: number; visible: boolean };
      ringPointer(): Pointer;
      pathMarker(): { visible: boolean; x: number; y: number };
      cockpit(): Panel;
      instruments(): { speed: number; altitude: number; heading: number };
    };
    // The next ring is pointed at, with its distance, and the goal is stated above the scene.
    const pointer = await g.page.evaluate(() => (window.game as unknown as Att).ringPointer());
    expect(pointer.index).toBe(0);
    expect(pointer.text).toMatch(/^(. )?ring 1 · \d+(\.\d)? k?m( .)?$/);
    expect(await g.page.locator('[data-hud="ring-pointer"]').isVisible()).toBe(true);
    // The goal above the scene gives ring 1's distance as its label does (it said 2.0 km after a reset, the label 520 m).
    const distance = pointer.text.match(/\d+(\.\d)? k?m/)![0];
    // It names the course first (course n of the 1000 that Next course goes through is seed n; the page's seed is 1).
    expect(await g.page.locator('[data-hud="goal"]').textContent()).toMatch(
      new RegExp(`^Course 1 of 1000 · Fly through ring 1 of 10 · ${distance} · `),
    );
    // The label is clear of the flight-path marker (34 x 20 px round its point) in the ring: it sat
    // 30 px under the ring's centre, over the marker's crosshair.
    const aim = await g.waitFor(() => {
      const w = window.game as unknown as Att;
      const m = w.pathMarker(),
        p = w.ringPointer();
      return m.visible && p.inView ? { m, box: p.box, ring: p.ring } : null;
    }, null);
    const [lx, ly, lw, lh] = aim.box as [number, number, number, number];
    const overlaps = lx < aim.m.x + 17 && aim.m.x - 17 < lx + lw && ly < aim.m.y + 10 && aim.m.y - 10 < ly + lh;
    expect(overlaps, `label ${aim.box} marker ${aim.m.x}, ${aim.m.y}`).toBe(false);
    // Nor does it cover the ring it labels, a few hundred metres off and small on the screen: its box
    // stays outside the ring's outer edge (the pulsing halo's; the label sat over it, 8 px in at 470 m).
    const [cx, cy, rr] = aim.ring as [number, number, number];
    expect(rr).toBeLessThan(150);
    const gap = Math.hypot(Math.max(Math.abs(lx + lw / 2 - cx) - lw / 2, 0), Math.max(Math.abs(ly + lh / 2 - cy) - lh / 2, 0)) - rr;
    expect(gap, `label ${aim.box} ring ${aim.ring}`).toBeGreaterThanOrEqual(0);
    expect(await g.page.evaluate(() => (window.game as unknown as Att).attitude().visible)).toBe(false);
    await g.press('c');
    await g.waitFor(() => (window.game as unknown as Att).attitude().visible, null);
    expect(await g.page.locator('canvas[aria-label="attitude indicator"]').isVisible()).toBe(true);
    // The cockpit: the panel across the stage's lower part, its gauges reading the instruments, the
    // attitude indicator inside the panel (there was only the indicator, over the sky).
    expect(await g.page.locator('canvas[aria-label="cockpit instruments"]').isVisible()).toBe(true);
    const panel = await g.page.evaluate(() => {
      const w = window.game as unknown as Att;
      return { ...w.cockpit(), i: w.instruments(), h: document.querySelector('canvas')!.clientHeight };
    });
    expect(panel.visible).toBe(true);
    expect(panel.panelTop).toBeGreaterThan(0.55 * panel.h);
    expect(panel.attitude[1]!).toBeGreaterThanOrEqual(panel.panelTop - 30);
    const gauge = (name: string) => panel.gauges.find((x) => x.name === name)!.value;
    expect(gauge('speed')).toBeCloseTo(panel.i.speed, -1);
    expect(gauge('altitude')).toBeCloseTo(panel.i.altitude, -1);
    expect(panel.gauges.map((x) => x.name)).toEqual(expect.arrayContaining(['speed', 'altitude', 'heading', 'throttle']));
    // Seen from the cockpit no bead of the guide lies in front of the next ring, within its radius
    // (77 m with the halo) of the line of sight to it: the chain from the aircraft to the ring lay
    // on that line, and its nearest bead (5 m across, 50 m off) covered a ring 2 km off whole. The
    // chain on from the ring to the one after is still drawn.
    const sight = await g.page.evaluate(() => {
      const w = window.game as unknown as Att & {
        guideBeads(): [number, number, number][];
        rings(): { x: number; y: number; z: number }[];
        aircraftBody(): number;
        world: { components: { Position: { x: Float64Array; y: Float64Array; z: Float64Array } } };
      };
      const P = w.world.components.Position,
        e = w.aircraftBody();
      const a = [P.x[e]!, P.y[e]!, P.z[e]!],
        r = w.rings()[0]!;
      const to = [r.x - a[0]!, r.y - a[1]!, r.z - a[2]!],
        d = Math.hypot(to[0]!, to[1]!, to[2]!);
      // Each bead's angle off the line of sight to the ring's centre, against the ring's angular radius.
      return w.guideBeads().map((b) => {
        const v = [b[0] - a[0]!, b[1] - a[1]!, b[2] - a[2]!],
          dv = Math.hypot(v[0]!, v[1]!, v[2]!);
        const cos = (v[0]! * to[0]! + v[1]! * to[1]! + v[2]! * to[2]!) / (dv * d);
        return { nearer: dv < d, off: Math.acos(Math.min(1, cos)), ring: Math.atan(77 / d) };
      });
    });
    expect(sight.length).toBeGreaterThan(0);
    const inFront = sight.filter((b) => b.nearer && b.off < b.ring);
    expect(inFront, JSON.stringify(inFront.slice(0, 3))).toEqual([]);
    // Banking left: the indicator's roll goes negative (the instruments' sign), by more than 5 degrees.
    await g.page.keyboard.down('ArrowLeft');
    await g.waitFor(() => (window.game as unknown as Att).attitude().roll < -5, null, 30_000);
    // Held on until the ring is off to the side: its label sits at the scene's edge, wholly inside
    // it (it ran past the right edge); the canvas is the stage, so its size bounds the label.
    const edge = await g.waitFor(
      () => {
        const p = (window.game as unknown as Att).ringPointer();
        return p.inView ? null : p;
      },
      null,
      60_000,
    );
    await g.page.keyboard.up('ArrowLeft');
    const stage = await g.page.evaluate(() => {
      const c = document.querySelector('canvas')!;
      return [c.clientWidth, c.clientHeight];
    });
    expect(edge.box[0]!).toBeGreaterThanOrEqual(0);
    expect(edge.box[1]!).toBeGreaterThanOrEqual(0);
    expect(edge.box[0]! + edge.box[2]!).toBeLessThanOrEqual(stage[0]!);
    expect(edge.box[1]! + edge.box[3]!).toBeLessThanOrEqual(stage[1]!);
    // Turned on left past it (it may first drop under the panel), the ring lies to the right: the
    // label says to turn right and names the key.
    await g.page.keyboard.down('ArrowLeft');
    const side = await g.waitFor(
      () => {
        const p = (window.game as unknown as Att).ringPointer();
        return !p.inView && !p.text.includes('under the panel') ? p.text : null;
      },
      null,
      60_000,
    );
    await g.page.keyboard.up('ArrowLeft');
    // (The arrow points where it is on the screen: banked in the cockpit, right may be the bottom edge.)
    expect(side).toMatch(/^([▲▼] )?ring 1 (behind )?· \d+(\.\d)? k?m · turn right \(hold →\)( ▶)?$/);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('flight-simulator: X opens the throttle and Z closes it (no Ctrl), up climbs, E yaws right; the wing reads its AoA', async () => {
    const g = await h.openGame('flight-simulator');
    type Flight = Game & {
      state: { throttle: number; elevator: number };
      instruments(): { pitch: number; speed: number; heading: number; aoa: number; roll: number };
    };
    const before = await g.page.evaluate(() => {
      const w = window.game as unknown as Flight;
      return { throttle: w.state.throttle, pitch: w.instruments().pitch, aoa: w.instruments().aoa };
    });
    // Level at the trim speed, the wing meets the air at its 3 degree incidence (the body's AoA is 0).
    expect(before.aoa).toBeGreaterThan(2);
    expect(before.aoa).toBeLessThan(4);
    await g.page.keyboard.down('x');
    await g.page.keyboard.down('ArrowUp');
    // Held until the nose has come up (simulated time, not a wall-clock wait, which a loaded machine
    // fills with few frames: the game's frames run at once, GamePage.runUntil, as its pause has them).
    const during = await g.runUntil(
      (b) => {
        const w = window.game as unknown as Flight;
        const r = { throttle: w.state.throttle, elevator: w.state.elevator, pitch: w.instruments().pitch };
        return r.throttle > b.throttle + 0.1 && r.elevator > 0.3 && r.pitch > b.pitch + 1 ? r : null;
      },
      before,
      { unpause: false, maxFrames: 1800 },
    );
    await g.page.keyboard.up('ArrowUp');
    await g.page.keyboard.up('x');
    expect(during.pitch).toBeGreaterThan(before.pitch + 1); // degrees: the nose came up
    // Z closes the throttle; Ctrl (a browser modifier: Ctrl+W closes the tab) leaves it alone.
    const opened = await g.page.evaluate(() => (window.game as unknown as Flight).state.throttle);
    await g.page.keyboard.down('Control');
    const t0 = await g.page.evaluate(() => (window.game as unknown as Flight).world.time);
    await g.runUntil((t) => ((window.game as unknown as Flight).world.time > t + 0.5 ? true : null), t0, {
      unpause: false,
      maxFrames: 1800,
    });
    await g.page.keyboard.up('Control');
    expect(await g.page.evaluate(() => (window.game as unknown as Flight).state.throttle)).toBeCloseTo(opened, 6);
    await g.page.keyboard.down('z');
    await g.runUntil((o) => ((window.game as unknown as Flight).state.throttle < o - 0.1 ? true : null), opened, {
      unpause: false,
      maxFrames: 1800,
    });
    await g.page.keyboard.up('z');
    // A held bank: the chase camera stays at its distance behind (its offset's length) in the turn.
    await g.page.keyboard.down('d');
    const t1 = await g.page.evaluate(() => (window.game as unknown as Flight).world.time);
    let far = 0;
    await g.waitFor(
      (t) => {
        const w = window.game as unknown as Flight & { chaseDistance(): number; chaseOffset(): [number, number] };
        const o = (window as unknown as { farthest?: number }).farthest ?? 0;
        (window as unknown as { farthest?: number }).farthest = Math.max(o, Math.abs(w.chaseDistance() - Math.hypot(...w.chaseOffset())));
        return w.world.time > t + 4 && Math.abs(w.instruments().roll) > 40 ? true : null;
      },
      t1,
      30_000,
    );
    far = await g.page.evaluate(() => (window as unknown as { farthest?: number }).farthest ?? -1);
    await g.page.keyboard.up('d');
    expect(far).toBeGreaterThanOrEqual(0);
    expect(far).toBeLessThan(0.5); // m
    // Right rudder (E) swings the nose right.
    await g.press('r');
    // After the reset the goal and ring 1's label give the same distance (the goal kept the old place's).
    const agree = await g.waitFor(() => {
      const w = window.game as unknown as { ringPointer(): { index: number; text: string }; world: { time: number } };
      const p = w.ringPointer(),
        goal = document.querySelector('[data-hud="goal"]')?.textContent ?? '';
      // An undrawn frame hides the label (text '') until a drawn one places ring 1's.
      return w.world.time === 0 && p.index === 0 && p.text !== '' ? { label: p.text, goal } : null;
    }, null);
    expect(agree.goal).toContain(` · ${agree.label.match(/\d+(\.\d)? k?m/)![0]} · `);
    const h0 = await g.page.evaluate(() => (window.game as unknown as Flight).instruments().heading);
    await g.page.keyboard.down('e');
    const turned = await g.runUntil(
      (start) => {
        const d = (((window.game as unknown as Flight).instruments().heading - start + 540) % 360) - 180;
        return d > 3 ? d : null;
      },
      h0,
      { unpause: false, maxFrames: 1800 },
    );
    await g.page.keyboard.up('e');
    expect(turned).toBeGreaterThan(3);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('flight-simulator at 1280x800: trees, villages and clouds at three heights; the path marker sits in ring 1; a tap of up is a small ramped input, held dive takes the marker out of the ring', async () => {
    const g = await h.openGame('flight-simulator', { viewport: { width: 1280, height: 800 }, locale: 'de-DE' });
    await checkPageContract(g, 'flight-simulator', 'desktop');
    type Flight = Game & {
      scenery(): { trees: number; houses: number; puffs: number; cloudLow: number; cloudHigh: number };
      pathMarker(): { visible: boolean; inside: boolean; offset: number; x: number; y: number };
      keyInput(): { pitch: number; roll: number };
    };
    const scene = await g.waitFor(() => {
      const s = (window.game as unknown as Flight).scenery();
      return s.trees > 0 ? s : null;
    }, null);
    expect(scene.trees).toBeGreaterThan(300);
    expect(scene.houses).toBeGreaterThan(20);
    // Clouds below, at and above the start's 900 m.
    expect(scene.cloudLow).toBeLessThan(800);
    expect(scene.cloudHigh).toBeGreaterThan(1400);
    // The aircraft starts on course for ring 1: the marker is drawn and inside it.
    const start = await g.waitFor(() => {
      const m = (window.game as unknown as Flight).pathMarker();
      return m.visible ? m : null;
    }, null);
    expect(start.inside).toBe(true);
    expect(await g.page.locator('[data-hud="path-marker"]').isVisible()).toBe(true);
    // The flight waits for the pilot, the tip saying how to start (a stranger read the tips while it flew on).
    const waiting = await g.page.evaluate(() => {
      const w = window.game as unknown as Flight & { tip(): string };
      return { paused: w.paused, time: w.world.time, tip: w.tip(), wait: document.querySelector('[data-hud="tip-wait"]')?.textContent };
    });
    expect(waiting).toMatchObject({ paused: true, time: 0, wait: 'Press an arrow key to start.' });
    expect(waiting.tip).toMatch(/^Fly through the yellow rings\. The marker ⊕ shows where you will pass/);
    // A tap: the key's input grows from small (KEY_RAMP: full after 0.4 s held), not to full at once, then falls back to 0.
    await g.page.keyboard.down('ArrowUp');
    const tapped = await g.runUntil(
      () => {
        const w = window.game as unknown as Flight & { world: { time: number } };
        const k = w.keyInput().pitch;
        return k > 0 ? { k, t: w.world.time } : null;
      },
      null,
      { unpause: false, maxFrames: 600 },
    );
    await g.page.keyboard.up('ArrowUp');
    // At the first frame that saw the key: no more than KEY_RAMP's growth over the game time flown
    // since the press started the flight ((0.25 + 0.25) e^(4 t) - 0.25; on a loaded machine that
    // first frame may be 0.15 s long, 0.66 of full stick), and short of full stick.
    expect(tapped.k).toBeLessThanOrEqual(0.5 * Math.exp(4 * tapped.t) - 0.25 + 1e-9);
    expect(tapped.k).toBeLessThan(1);
    expect(await g.page.evaluate(() => (window.game as unknown as Flight).paused)).toBe(false);
    await g.runUntil(() => (window.game as unknown as Flight).keyInput().pitch === 0, null, { unpause: false, maxFrames: 600 });
    // Down held: the path dives, so the marker drops below the ring's centre and out of the ring.
    await g.page.keyboard.down('ArrowDown');
    const dived = await g.waitFor(
      (y0) => {
        const m = (window.game as unknown as Flight).pathMarker();
        return m.visible && !m.inside && m.y > y0 + 10 ? m : null;
      },
      start.y,
      60_000,
    );
    await g.page.keyboard.up('ArrowDown');
    expect(dived.offset).toBeGreaterThan(65); // the ring's radius
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('flight-simulator at 1280x800: each lesson tip names the ways its ring lies from the aircraft when it shows; a bank moves the path marker its way at once, never the other; P dims the scene with "Paused"', async () => {
    const g = await h.openGame('flight-simulator', { viewport: { width: 1280, height: 800 }, query: { rings: 5 } });
    type Store = { x: Float64Array; y: Float64Array; z: Float64Array };
    type Flight = Game & {
      aircraftBody(): number;
      rings(): { x: number; y: number; z: number; nx: number; ny: number; nz: number }[];
      tip(): string;
      pathMarker(): { visible: boolean; x: number; y: number; drawnAt: number };
      ringPointer(): { ring: number[] };
      keyInput(): { roll: number };
      world: {
        time: number;
        components: { Position: Store; Velocity: Store; AngularVelocity: Store; Orientation: Store & { w: Float64Array } };
      };
    };
    // The flight waits at the start: no pause overlay then (the tip says it waits).
    await g.waitFor(() => (window.game as unknown as Flight).tip() !== '', null);
    expect(await g.page.locator('[data-hud="paused"]').isVisible()).toBe(false);
    // For each lesson ring (2 to 4): put 60 m before the ring before it, on its line but flying
    // `yaw` degrees to its right and `climb` degrees up, so the lesson ring lies off the way it was
    // laid; when it becomes next, its tip must name the ways it lies from the aircraft then.
    const poses: [number, number][] = [
      [-12, 0],
      [10, -4],
      [0, 4],
    ];
    for (let k = 1; k <= 3; k++) {
      const [yaw, climb] = poses[k - 1]!;
      await g.page.evaluate(
        ([k, yaw, climb]) => {
          const w = window.game as unknown as Flight;
          const r = w.rings()[k - 1]!,
            c = w.world.components,
            e = w.aircraftBody();
          const speed = Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!, c.Velocity.z[e]!);
          const heading = Math.atan2(r.nz, r.nx) + (yaw * Math.PI) / 180,
            path = (climb * Math.PI) / 180;
          c.Position.x[e] = r.x - 60 * r.nx;
          c.Position.y[e] = r.y - 60 * r.ny;
          c.Position.z[e] = r.z - 60 * r.nz;
          c.Velocity.x[e] = speed * Math.cos(path) * Math.cos(heading);
          c.Velocity.y[e] = speed * Math.sin(path);
          c.Velocity.z[e] = speed * Math.cos(path) * Math.sin(heading);
          c.AngularVelocity.x[e] = c.AngularVelocity.y[e] = c.AngularVelocity.z[e] = 0;
          // Nose along the velocity: a turn of -heading about y, then of path about the body's z.
          const a = -heading / 2,
            b = path / 2;
          c.Orientation.x[e] = Math.sin(a) * Math.sin(b);
          c.Orientation.y[e] = Math.sin(a) * Math.cos(b);
          c.Orientation.z[e] = Math.cos(a) * Math.sin(b);
          c.Orientation.w[e] = Math.cos(a) * Math.cos(b);
        },
        [k, yaw, climb] as const,
      );
      // Space goes on from the wait (the start's, or ring 2's) without steering; the game's frames
      // run at once (GamePage.runUntil), as its pause has them (ring 2's tip pauses it).
      await g.page.keyboard.press('Space');
      const seen = await g.runUntil(
        (k) => {
          const w = window.game as unknown as Flight;
          if (!w.tip().startsWith(`Ring ${k + 1} `)) return null;
          // Where the ring lies from the aircraft, worked out here: across the line flown (right +)
          // and above it, m at the ring's distance.
          const r = w.rings()[k]!,
            c = w.world.components,
            e = w.aircraftBody();
          const dx = r.x - c.Position.x[e]!,
            dy = r.y - c.Position.y[e]!,
            dz = r.z - c.Position.z[e]!;
          const vx = c.Velocity.x[e]!,
            vy = c.Velocity.y[e]!,
            vz = c.Velocity.z[e]!;
          const v = Math.hypot(vx, vy, vz),
            vh = Math.hypot(vx, vz);
          const right = (dz * vx - dx * vz) / vh;
          // Above the line along the velocity: the part of (dx, dy, dz) along the velocity's "up"
          // (-vy vx, vh^2, -vy vz) / (v vh).
          const up = (-vy * vx * dx + vh * vh * dy - vy * vz * dz) / (v * vh);
          return { tip: w.tip(), wait: document.querySelector('[data-hud="tip-wait"]')?.textContent ?? '', right, up, paused: w.paused };
        },
        k,
        { unpause: false, maxFrames: 1800 },
      );
      // Only the first lesson (ring 2: a plane turns by banking) waits while its tip is read; the
      // tips of rings 3 and 4 show while the flight goes on (a stranger found a pause at every
      // lesson ring broke the flow).
      expect(seen.paused, `ring ${k + 1}`).toBe(k === 1);
      const r3 = 65 / 3; // a third of the ring's radius: nearer the line flown, no way is named
      const words = seen.tip.split(/[:.]/)[0]!;
      const message = `${seen.tip} (ring ${seen.right.toFixed(0)} m right, ${seen.up.toFixed(0)} m up)`;
      if (Math.abs(seen.right) > 1.2 * r3) {
        expect(words, message).toContain(seen.right > 0 ? 'to the right' : 'to the left');
        expect(words, message).not.toContain(seen.right > 0 ? 'left' : 'right');
      } else if (Math.abs(seen.right) < 0.8 * r3) expect(words, message).not.toMatch(/left|right/);
      if (Math.abs(seen.up) > 1.2 * r3) {
        expect(words, message).toContain(seen.up > 0 ? 'higher' : 'lower');
        expect(words, message).not.toContain(seen.up > 0 ? 'lower' : 'higher');
      } else if (Math.abs(seen.up) < 0.8 * r3) expect(words, message).not.toMatch(/higher|lower/);
      // The key that goes on is one the tip asks for.
      const key = seen.wait.match(/press (.) to fly on/)?.[1];
      if (key) expect(seen.tip, message).toContain(key);
    }
    // A bank held from level flight: the path marker moves on the screen the way of the bank, 10 px
    // within 1 s of game time, never the other way first (it slid 34 px the wrong way first, as the
    // chase camera swung with the bank). The flight is paused and stepped 2 steps (1/30 s) at a time,
    // each time up to a drawn frame that placed the marker for that moment: the chase camera eases by
    // game time, so this is the flight at 30 frames a second whatever the load (flown in real time on
    // a loaded machine, the software GPU drew a frame every 0.3 s or less, and a frame the pacer does
    // not draw leaves the marker where it was).
    type Row = { t: number; x: number; k: number };
    /**
     * Steps the paused flight 2 steps at a time, recording the marker on a drawn frame after each:
     * `sign` 0, two records (the base); else until the marker is 10 px the way `sign` from `x0` (what
     * is checked below) or the game time is 1.2 s past `t0`.
     */
    const sample = (sign: number, x0 = 0, t0 = 0) =>
      g.evaluate(
        async ([sign, x0, t0]) => {
          const w = window.game as unknown as Flight;
          const log: Row[] = [];
          for (let n = 0; n < 90; n++) {
            w.step();
            w.step();
            let m = w.pathMarker();
            for (let f = 0; !(m.visible && m.drawnAt === w.world.time); f++) {
              if (f > 1200) throw new Error(`no frame drew the path marker at ${w.world.time} s`);
              await new Promise<number>((r) => requestAnimationFrame(r));
              m = w.pathMarker();
            }
            log.push({ t: w.world.time, x: m.x, k: w.keyInput().roll });
            if (sign === 0 ? log.length >= 2 : sign! * (m.x - x0!) >= 10 || w.world.time - t0! > 1.2) break;
          }
          return log;
        },
        [sign, x0, t0],
        'stepping the flight and reading the path marker',
        120_000,
      );
    for (const key of ['ArrowRight', 'ArrowLeft']) {
      await g.press('r');
      await g.page.keyboard.press('Space');
      await g.runUntil(() => (window.game as unknown as Flight).world.time > 1 && !(window.game as unknown as Flight).paused, null, {
        unpause: false,
        maxFrames: 600,
      });
      await g.page.evaluate(() => {
        (window.game as unknown as Flight).paused = true;
      });
      const sign = key === 'ArrowRight' ? 1 : -1;
      const before = await sample(0);
      await g.page.keyboard.down(key);
      const held = await sample(sign, before[1]!.x, before[1]!.t);
      await g.page.keyboard.up(key);
      const log = [...before, ...held];
      const i0 = log.findIndex((r) => r.k !== 0);
      expect(i0).toBeGreaterThan(0);
      const base = log[i0 - 1]!;
      const after = log.slice(i0);
      // The frames before the marker has gone 10 px the bank's way: none of them the other way. Later,
      // with the key held, the chase camera turning after the aircraft brings the marker back toward
      // the screen's middle (the place straight ahead, where a let-go turn now ends).
      const trace = `${key}: ${after.map((r) => `${(r.t - base.t).toFixed(2)}:${(r.x - base.x).toFixed(0)}:${r.k.toFixed(2)}`).join(' ')}`;
      const m = after.findIndex((r) => sign * (r.x - base.x) >= 10);
      expect(m, trace).toBeGreaterThanOrEqual(0);
      expect(after[m]!.t - base.t, trace).toBeLessThan(1);
      expect(Math.max(0, ...after.slice(0, m).map((r) => -sign * (r.x - base.x))), trace).toBeLessThan(5);
    }
    await g.page.evaluate(() => {
      (window.game as unknown as Flight).paused = false;
    });
    // P pauses: the scene dims over the whole stage, "Paused" and how to resume low in it (under the aircraft); P again resumes.
    await g.page.keyboard.press('p');
    const shade = await pausedShade(g);
    expect(shade.text.replace(/\s+/g, ' ')).toBe('Paused P to resume');
    for (let k = 0; k < 4; k++) expect(Math.abs(shade.box[k]! - shade.stage[k]!)).toBeLessThan(2);
    await g.page.keyboard.press('p');
    await resumedShade(g);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('flight-simulator: a ring flown through counts with a banner; a missed one comes round again at no cost, missed again it costs a star and 10 s, said at once; the ground ends the flight with a Try again button', async () => {
    const g = await h.openGame('flight-simulator', { query: { rings: 3 } });
    type Flight = Game & {
      aircraftBody(): number;
      rings(): { x: number; y: number; z: number; nx: number; nz: number; status: string }[];
      state: { score: number; missed: number; again: number; phase: string };
      banner(): { text: string };
    };
    // The aircraft put 150 m before ring 1, on its line (the course's first ring lies along +x).
    await placeBeforeRing1(g, -150, 0);
    // The flight waits for the pilot: Space starts it. The game's frames run at once (GamePage.runUntil),
    // as its pause has them, until what is waited for.
    await g.page.keyboard.press('Space');
    const passed = await g.runUntil(
      () => {
        const w = window.game as unknown as Flight;
        return w.state.score === 1 ? { status: w.rings()[0]!.status, banner: w.banner().text } : null;
      },
      null,
      { unpause: false, maxFrames: 600 },
    );
    expect(passed.status).toBe('passed');
    expect(passed.banner).toBe('Ring 1 ✓');
    // The ring flown through fades out and goes (it lay on as a big green arc across the chase view,
    // and over the whole wait for ring 2's tip, which follows at once).
    await g.waitFor(() => (window.game as unknown as Flight & { ringOpacity(): number[] }).ringOpacity()[0] === 0, null);
    expect(await g.page.evaluate(() => (window.game as unknown as Flight & { ringOpacity(): number[] }).ringOpacity()[1])).toBe(1);
    // Ring 2, the first turn, comes with a tip over the scene in plain words: which side it is on
    // (the side the course lays it, from the aircraft's heading), that a plane turns by tipping its
    // wings, and the key for it.
    const tip = await g.runUntil(
      () => {
        const w = window.game as unknown as Flight & { tip(): string };
        const r = w.rings()[1]!,
          c = w.world.components,
          e = w.aircraftBody();
        const right = (r.x - c.Position.x[e]!) * -c.Velocity.z[e]! + (r.z - c.Position.z[e]!) * c.Velocity.x[e]! > 0;
        return w.tip() ? { text: w.tip(), side: right ? 'right' : 'left' } : null;
      },
      null,
      { unpause: false, maxFrames: 600 },
    );
    expect(tip.text).toBe(
      `Ring 2 is to the ${tip.side}. A plane turns by tipping its wings (banking): hold ${tip.side === 'right' ? '→' : '←'} and it leans and turns ${tip.side}; let go to fly straight.`,
    );
    expect(await g.page.locator('[data-hud="tip"]').isVisible()).toBe(true);
    // The flight waits while the lesson's tip is read, and says how to go on.
    expect(await g.page.evaluate(() => (window.game as unknown as Flight).paused)).toBe(true);
    expect(await g.page.locator('[data-hud="tip-wait"]').textContent()).toBe(
      `Paused: press ${tip.side === 'right' ? '→' : '←'} to fly on.`,
    );
    // Then put 150 m before ring 2 but 100 m above its centre (its radius is 55 m): a miss, counted
    // once, with its banner.
    await g.page.evaluate(() => {
      const w = window.game as unknown as Flight;
      const r = w.rings()[1]!,
        c = w.world.components,
        e = w.aircraftBody();
      c.Position.x[e] = r.x - 150 * r.nx;
      c.Position.y[e] = r.y + 100;
      c.Position.z[e] = r.z - 150 * r.nz;
    });
    await g.page.keyboard.press('Space');
    const first = await g.runUntil(
      () => {
        const w = window.game as unknown as Flight;
        if (w.state.again === 0) return null;
        // Held there while the aircraft is put before the ring again.
        w.paused = true;
        return { missed: w.state.missed, status: w.rings()[1]!.status, banner: w.banner().text };
      },
      null,
      { unpause: false, maxFrames: 600 },
    );
    // A first miss costs nothing yet: the ring comes round again to be scored (second-try.ts; a
    // stranger who came back for a ring saw +10 s for it all the same and took it for a miss).
    expect(first).toEqual({ missed: 0, status: 'ahead', banner: 'Missed ring 2 · fly it again to score it' });
    // The goal line names the second try, with no penalty on the clock; the readout counts rings,
    // none missed yet: passed, missed and to go add up to the 3 rings.
    await g.frames(1);
    const goal = await g.page.locator('[data-hud="goal"]').textContent();
    expect(goal).toMatch(/Fly through ring 2 of 3 \(second try\) · /);
    expect(goal).not.toMatch(/\+10 s/);
    expect(await g.page.locator('[data-hud="readout"]').textContent()).toMatch(/ · rings: 1 passed · 2 to go$/);
    // Missed on its second try too (put 150 m before it as it is laid now, 100 m above): for good.
    await g.page.evaluate(() => {
      const w = window.game as unknown as Flight;
      const r = w.rings()[1]!,
        c = w.world.components,
        e = w.aircraftBody();
      const across = Math.hypot(r.nx, r.nz);
      c.Position.x[e] = r.x - (150 * r.nx) / across;
      c.Position.y[e] = r.y + 100;
      c.Position.z[e] = r.z - (150 * r.nz) / across;
      w.paused = false;
    });
    const missed = await g.runUntil(
      () => {
        const w = window.game as unknown as Flight;
        return w.rings()[1]!.status === 'missed' ? { missed: w.state.missed, banner: w.banner().text } : null;
      },
      null,
      { unpause: false, maxFrames: 600 },
    );
    // The miss for good costs a star and 10 s (20 s, with a star for every miss, left a stranger nothing
    // to play for after three misses: ./course.ts courseStars), said at
    // once in the banner; the goal line above the scene adds the time and shows the stars left.
    expect(missed).toEqual({ missed: 1, banner: 'Missed ring 2 · −1 ★ · +10 s' });
    await g.frames(1);
    expect(await g.page.locator('[data-hud="readout"]').textContent()).toMatch(/ · rings: 1 passed · 1 missed · 1 to go$/);
    // Ring 3, laid for a climb or a dive, seen from 100 m above ring 2: its tip names the ways it
    // lies from the aircraft now (lower, from up here), not the way it was laid.
    const tip3 = await g.runUntil(
      () => {
        const w = window.game as unknown as Flight & { tip(): string };
        const r = w.rings()[2]!,
          c = w.world.components,
          e = w.aircraftBody();
        return w.tip().startsWith('Ring 3') ? { text: w.tip(), below: r.y < c.Position.y[e]! - 60 } : null;
      },
      null,
      { unpause: false, maxFrames: 600 },
    );
    expect(tip3.below).toBe(true);
    expect(tip3.text).toMatch(
      /^Ring 3 is (.* and )?(a little |far )?lower: hold (↓ to dive|← to bank and ↓ to dive|→ to bank and ↓ to dive)/,
    );
    await g.waitFor(() => document.querySelector('[data-hud="goal"]')?.textContent?.match(/\(\+10 s\) · ★★☆$/), null);
    // No red glow round the scene (a stranger took it for a warning he could not name): the banner
    // and the goal line say the miss.
    expect(await g.page.evaluate(() => document.querySelector('[data-hud="miss-flash"]'))).toBeNull();
    await g.page.evaluate(() => {
      const w = window.game as unknown as Flight;
      w.world.components.Position.y[w.aircraftBody()] = 1; // below every hill and the sea
    });
    await g.page.keyboard.press('Space'); // harmless: ring 3's tip does not wait
    // The readouts give the crash's values as soon as the goal line says so, and keep them (they ran
    // on after "Crashed", 166 -> 170 m/s and 309 -> 245 m: they were refreshed every 6th drawn frame).
    const atCrash = await g.waitFor(
      () =>
        document.querySelector('[data-hud="goal"]')?.textContent?.startsWith('Crashed')
          ? document.querySelector('[data-hud="readout"]')!.textContent
          : null,
      null,
    );
    const crashAlt = Number(atCrash.match(/alt (-?\d+) m/)?.[1]);
    expect(Math.abs(crashAlt), atCrash).toBeLessThan(10); // put at 1 m, it crashes within a step
    await g.frames(30);
    expect(await g.page.locator('[data-hud="readout"]').textContent()).toBe(atCrash);
    await g.waitFor(() => (window.game as unknown as Flight).state.phase === 'crashed', null);
    const again = g.page.getByRole('button', { name: 'Try again ↺', exact: true });
    await again.waitFor({ state: 'visible' });
    expect(await g.page.locator('[data-hud="end"]').textContent()).toContain('Crashed!');
    // Paused with the end card up, the card stays clear and bright: no dimming and no "Paused" over
    // it (a stranger saw "Paused / P to resume" under a dimmed "Course 1 over").
    await g.page.evaluate(() => {
      (window.game as unknown as Flight).paused = true;
    });
    await g.frames(3);
    expect(await g.page.locator('[data-hud="paused"]').isVisible()).toBe(false);
    expect(await again.isVisible()).toBe(true);
    await again.click();
    await g.waitFor(() => (window.game as unknown as Flight).state.phase === 'flying', null);
    expect(await g.page.evaluate(() => (window.game as unknown as Flight).state.score)).toBe(0);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('flight-simulator: a ring whose path marker sits on its drawn tube (67 m off its centre) shows it orange, a wing through the tube, not green; flown on, it is still passed, not missed', async () => {
    const g = await h.openGame('flight-simulator', { viewport: { width: 1280, height: 800 }, query: { rings: 3 } });
    type Flight = Game & {
      rings(): { status: string }[];
      state: { missed: number; score: number };
      pathMarker(): { visible: boolean; inside: boolean; offset: number; drawnAt: number };
      banner(): { text: string };
    };
    // Put 400 m before ring 1 and 67 m to its side: flying on along +x, the aircraft's centre
    // crosses the ring's plane on its tube (drawn from 59 to 71 m), where a stranger's marker sat.
    await placeBeforeRing1(g, -400, 67);
    await g.page.keyboard.press('Space');
    // The marker, drawn after the move, sits on the tube: orange, not green (green only where the
    // whole aircraft goes through: ./course.ts clearThrough, 50 m; green here, a stranger let go and
    // missed), so the coach says which way to steer rather than "let go".
    const shown = await g.waitFor(() => {
      const w = window.game as unknown as Flight;
      const m = w.pathMarker();
      return m.visible && m.drawnAt > 0 && m.offset > 65
        ? { ...m, colour: document.querySelector<HTMLElement>('[data-hud="path-marker"]')!.style.color }
        : null;
    }, null);
    expect(shown.offset).toBeLessThan(71);
    expect(shown.inside).toBe(false);
    expect(shown.colour).toBe('rgb(255, 154, 74)');
    // And the ring counts it all the same (its centre inside PASS_RADIUS, 71 m): passed, with its banner, no miss (the game's frames run at once,
    // GamePage.runUntil, as its pause has them).
    const done = await g.runUntil(
      () => {
        const w = window.game as unknown as Flight;
        const r = w.rings()[0]!;
        return r.status === 'ahead' ? null : { status: r.status, missed: w.state.missed, score: w.state.score, banner: w.banner().text };
      },
      null,
      { unpause: false, maxFrames: 3600 },
    );
    expect(done).toEqual({ status: 'passed', missed: 0, score: 1, banner: 'Ring 1 ✓' });
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('flight-simulator: a ring flown past to the side, beyond the miss range, is left behind: a first miss, laid ahead for a second try; left behind again before it is reached, laid ahead again with no further miss', async () => {
    const g = await h.openGame('flight-simulator', { viewport: { width: 1280, height: 800 }, query: { rings: 3 } });
    type Flight = Game & {
      aircraftBody(): number;
      rings(): { x: number; y: number; z: number; status: string }[];
      state: { missed: number; again: number; score: number };
      behindFor(): number;
      banner(): { text: string };
      tip(): string;
    };
    // Before the first input the flight waits (no step runs): the aircraft is put 800 m to the right
    // of ring 1 (+z; past MISS_RANGE, 600 m, so crossing its plane there counts nothing) and 100 m
    // short of its plane, flying on along +x as it starts. A stranger flew past a ring far to the
    // side and took about a minute to come round to it.
    await placeBeforeRing1(g, -100, 800);
    await g.page.keyboard.press('Space');
    // Past its plane the ring falls behind; 1.5 s of game time later (LEFT_BEHIND_TIME) it is
    // missed, said at once, and counted once. The game's frames run at once (GamePage.runUntil), as
    // its pause has them.
    const ring1 = await g.page.evaluate(() => (window.game as unknown as Flight).rings()[0]!.x);
    const missed = await g.runUntil(
      (x0) => {
        const w = window.game as unknown as Flight;
        const r = w.rings()[0]!,
          c = w.world.components,
          e = w.aircraftBody();
        if (w.state.again === 0) return null;
        // Held there while it is read and the aircraft moved.
        w.paused = true;
        return { status: r.status, missed: w.state.missed, score: w.state.score, past: c.Position.x[e]! - x0, banner: w.banner().text };
      },
      ring1,
      { unpause: false, maxFrames: 3600 },
    );
    // A first miss: no time, no star, and the ring comes round again to be scored (second-try.ts).
    expect(missed).toMatchObject({ status: 'ahead', missed: 0, score: 0, banner: 'Missed ring 1 · fly it again to score it' });
    // Counted when it had fallen behind: flown on past its plane, at 110 to 170 m/s for 1.5 s at least.
    expect(missed.past).toBeGreaterThan(150);
    // The course moved on: ring 1, for its second try, now lies ahead of the aircraft (along +x,
    // within 30 degrees), 600 to 1,000 m off (laid 800 m ahead: ./course.ts RECOVERY_DISTANCE).
    const next = await g.page.evaluate(() => {
      const w = window.game as unknown as Flight;
      const r = w.rings()[0]!,
        c = w.world.components,
        e = w.aircraftBody();
      const dx = r.x - c.Position.x[e]!,
        dz = r.z - c.Position.z[e]!;
      return { status: r.status, distance: Math.hypot(dx, r.y - c.Position.y[e]!, dz), bearing: (Math.atan2(dz, dx) * 180) / Math.PI };
    });
    expect(next.status).toBe('ahead');
    expect(next.distance).toBeGreaterThan(600);
    expect(next.distance).toBeLessThan(1000);
    expect(Math.abs(next.bearing)).toBeLessThan(30);
    // Ring 1, laid ahead after the miss, left behind too before it was reached (the pilot still
    // turning away, over-correcting: put 300 m past it and 800 m to its side): it is laid ahead
    // again, said at once, with no further miss (a newcomer holding a bank key lost a star every
    // 6 s as each new ring fell behind the turn).
    await g.page.evaluate(() => {
      const w = window.game as unknown as Flight;
      const r = w.rings()[0]! as unknown as { x: number; y: number; z: number; nx: number; nz: number },
        c = w.world.components,
        e = w.aircraftBody();
      const across = Math.hypot(r.nx, r.nz);
      c.Position.x[e] = r.x + (300 * r.nx) / across - (800 * r.nz) / across;
      c.Position.z[e] = r.z + (300 * r.nz) / across + (800 * r.nx) / across;
      c.Position.y[e] = r.y;
    });
    const before = await g.page.evaluate(() => ({ ...(window.game as unknown as Flight).rings()[0]! }));
    await g.page.evaluate(() => {
      (window.game as unknown as Flight).paused = false;
    });
    const again = await g.runUntil(
      (before) => {
        const w = window.game as unknown as Flight;
        const r = w.rings()[0]!,
          c = w.world.components,
          e = w.aircraftBody();
        if (r.x === before.x && r.z === before.z && w.state.missed === 0) return null;
        const dx = r.x - c.Position.x[e]!,
          dz = r.z - c.Position.z[e]!,
          vx = c.Velocity.x[e]!,
          vz = c.Velocity.z[e]!;
        return {
          missed: w.state.missed,
          tries: w.state.again,
          status: r.status,
          banner: w.banner().text,
          tip: w.tip(),
          distance: Math.hypot(dx, r.y - c.Position.y[e]!, dz),
          // The angle between the way flown and the line to the ring, degrees.
          off: (Math.acos((dx * vx + dz * vz) / (Math.hypot(dx, dz) * Math.hypot(vx, vz))) * 180) / Math.PI,
        };
      },
      before,
      { unpause: false, maxFrames: 3600 },
    );
    expect(again).toMatchObject({ missed: 0, tries: 1, status: 'ahead' });
    // The banner and ring 1's tip, read in the same frame, say the same of where ring 1 is (the
    // banner said "just ahead of you" while the tip said "to the left and far higher").
    const where = /^Ring 1 is now (?:just ahead of you|ahead: (.+))$/.exec(again.banner);
    expect(where, again.banner).not.toBeNull();
    if (again.tip) expect(again.tip).toMatch(`Ring 1 is ${where![1] ?? 'straight ahead'}`);
    expect(again.distance).toBeGreaterThan(600);
    expect(again.distance).toBeLessThan(1000);
    expect(again.off).toBeLessThan(30);
    expect(g.errors).toEqual([]);
    await g.close();
  });
  it('flight-simulator: every figure agrees at every frame (the readout with the banner, the goal line and the engine note); after a miss the next ring faces the aircraft; ← let go, the wings stop rolling and level', async () => {
    const g = await h.openGame('flight-simulator', { viewport: { width: 1280, height: 800 }, query: { rings: 3 } });
    type Flight = Game & {
      aircraftBody(): number;
      rings(): { x: number; y: number; z: number; nx: number; ny: number; nz: number; status: string }[];
      state: { score: number; missed: number; throttle: number };
      banner(): { text: string };
      instruments(): { roll: number };
    };
    // Every frame, what the scene's messages and the status rows say is checked against each other
    // (a stranger saw "+60 s ☆☆☆" with "missed 1", "Ring 1 ✓" with "rings 0/10", "Engine 66 %" with
    // "throttle 43 %": the readout was refreshed every 6th drawn frame). The checks run after every
    // animation frame and after every frame run at once by GamePage.runUntil (window.hudFrame, called
    // by the waits below), which run the game's frames as its pause has them.
    type HudFrame = { hudFrame(): void };
    await g.page.evaluate(() => {
      const hud = { bad: [] as string[], seen: [] as string[], frames: 0, warningAt: '' };
      (window as unknown as { hud: typeof hud }).hud = hud;
      const text = (n: string) => {
        const el = document.querySelector<HTMLElement>(`[data-hud="${n}"]`);
        return el && el.style.display !== 'none' ? (el.textContent ?? '') : '';
      };
      const check = () => {
        hud.frames++;
        const read = text('readout'),
          goal = text('goal'),
          banner = text('banner'),
          note = text('throttle-note');
        const rings = Number(read.match(/(\d+) passed/)?.[1] ?? Number.NaN),
          missed = Number(read.match(/(\d+) missed/)?.[1] ?? 0),
          toGo = Number(read.match(/(\d+) to go/)?.[1] ?? Number.NaN),
          throttle = Number(read.match(/throttle (\d+)%/)?.[1] ?? Number.NaN);
        const said = `${goal} | ${read} | ${banner} | ${note}`;
        const stars = (goal.match(/★/g) ?? []).length;
        // The readout counts rings: passed, missed for good and to go, adding up to the course's (a
        // stranger read "Ring 4 ✓" over "rings 3/10 · missed 2", the misses counted with a second
        // try's first one). The clock's penalty and the stars count the misses for good (10 s each;
        // a first miss gives the ring a second try at no cost: second-try.ts).
        const st = (window.game as unknown as { state: { missed: number; again: number } }).state;
        const forGood = st.missed;
        if (read && missed !== forGood) hud.bad.push(`missed: ${said}`);
        if (read && rings + missed + toGo !== (window.game as unknown as { rings(): unknown[] }).rings().length)
          hud.bad.push(`rings do not add up: ${said}`);
        if (goal.includes('★') || goal.includes('☆')) {
          if (stars !== 3 - Math.ceil(forGood / 2)) hud.bad.push(`stars: ${said}`);
          if (Number(goal.match(/\(\+(\d+) s\)/)?.[1] ?? 0) !== 10 * forGood) hud.bad.push(`penalty: ${said}`);
        }
        const next = goal.match(/ring (\d+) of/)?.[1];
        if (next && Number(next) !== rings + forGood + 1) hud.bad.push(`next ring: ${said}`);
        const passed = banner.match(/^Ring (\d+) ✓/)?.[1];
        if (passed) {
          hud.seen.push('pass');
          if (rings < 1 || Number(passed) > rings + missed) hud.bad.push(`pass: ${said}`);
        }
        if (banner.startsWith('Missed')) {
          hud.seen.push('miss');
          if (banner.includes('fly it again') ? st.again < 1 : missed < 1) hud.bad.push(`miss: ${said}`);
        }
        if (note) {
          hud.seen.push('note');
          if (Number(note.match(/(\d+) %/)?.[1]) !== throttle) hud.bad.push(`engine: ${said}`);
        }
        // The height above the ground: in the readout beside the sea-level altitude, the same figure
        // as the side panel's, and the two apart by the ground's height (the sea at 60 m, the hills
        // up to 700 m: a stranger read "alt 108 m" as clear of hills that reach 700 m).
        const agl = Number(read.match(/· (\d+) m above ground ·/)?.[1] ?? Number.NaN),
          alt = Number(read.match(/alt (-?\d+) m/)?.[1] ?? Number.NaN),
          panelAgl = Number(text('instruments').match(/(\d+) m above ground/)?.[1] ?? Number.NaN);
        if (read && !(agl >= 0)) hud.bad.push(`no height above ground: ${said}`);
        if (read && agl !== panelAgl) hud.bad.push(`above ground ${agl} in the readout, ${panelAgl} in the panel`);
        if (agl > 0 && !(alt - agl >= 59 && alt - agl <= 760)) hud.bad.push(`ground at ${alt - agl} m: ${said}`);
        // The ring label keeps off the aircraft (its box on the screen in the chase view; a stranger
        // read "ring 9 · 671 m" over the tail): both as of the last drawn frame.
        const shown = window.game as unknown as { ringPointer(): { inView: boolean; box: number[] }; planeFade(): { box: number[] } };
        const lp = shown.ringPointer(),
          pb = shown.planeFade().box as [number, number, number, number];
        const [bx, by, bw, bh] = lp.box as [number, number, number, number];
        if (lp.inView && pb[2] > 0 && bx < pb[0] + pb[2] && pb[0] < bx + bw && by < pb[1] + pb[3] && pb[1] < by + bh)
          hud.bad.push(`ring label [${lp.box.map(Math.round)}] over the aircraft [${pb.map(Math.round)}]`);
        // The warning, while it shows, stays in one place and nothing over the scene overlaps it.
        // It blinks (hidden every other third of a second): a frame in its hidden phase counts too,
        // its box is the same, so a loaded machine drawing a few frames before the crash still sees it.
        const warning = document.querySelector<HTMLElement>('[data-hud="warning"]')!;
        if (warning.style.display !== 'none') {
          hud.seen.push('warning');
          const w = warning.getBoundingClientRect();
          const at = `${Math.round(w.left)},${Math.round(w.top)}`;
          hud.warningAt ||= at;
          if (at !== hud.warningAt) hud.bad.push(`the warning moved from ${hud.warningAt} to ${at}`);
          for (const n of ['ring-pointer', 'banner', 'throttle-note', 'tip', 'end']) {
            const el = document.querySelector<HTMLElement>(`[data-hud="${n}"]`);
            if (!el || el.style.display === 'none') continue;
            const o = el.getBoundingClientRect();
            if (o.left < w.right && w.left < o.right && o.top < w.bottom && w.top < o.bottom)
              hud.bad.push(`${n} over the warning: ${said}`);
          }
        }
      };
      (window as unknown as { hudFrame: () => void }).hudFrame = check;
      const frame = () => {
        check();
        requestAnimationFrame(frame);
      };
      requestAnimationFrame(frame);
    });
    /** Puts the aircraft `back` m before ring `ring` on its line, `up` m above its centre and `side` m to its right. */
    const place = (ring: number, back: number, up: number, side: number) =>
      g.page.evaluate(
        ([ring, back, up, side]) => {
          const w = window.game as unknown as Flight;
          const r = w.rings()[ring]!,
            c = w.world.components,
            e = w.aircraftBody();
          const across = Math.hypot(r.nx, r.nz);
          c.Position.x[e] = r.x - back! * r.nx - (side! * r.nz) / across;
          c.Position.y[e] = r.y + up!;
          c.Position.z[e] = r.z - back! * r.nz + (side! * r.nx) / across;
        },
        [ring, back, up, side],
      );
    await place(0, 150, 0, 0);
    await g.page.keyboard.press('Space'); // the flight waits for the pilot
    await g.runUntil(
      () => {
        (window as unknown as HudFrame).hudFrame();
        return (window.game as unknown as Flight).banner().text === 'Ring 1 ✓';
      },
      null,
      { unpause: false },
    );
    // Faster: the engine's note and the readout say the same figure.
    await g.page.keyboard.press('x');
    await g.runUntil(
      () => {
        (window as unknown as HudFrame).hudFrame();
        return (window as unknown as { hud: { seen: string[] } }).hud.seen.includes('note') || null;
      },
      null,
      { unpause: false },
    );
    // Ring 2 missed 250 m to its right and 100 m above (the lesson's tip waits: Space goes on): ring 2,
    // laid ahead for its second try, faces the aircraft (a ring laid on the line from the missed
    // ring's centre was seen 15 degrees off its way through).
    await place(1, 150, 100, 250);
    await g.page.keyboard.press('Space');
    const missed = await g.runUntil(
      () => {
        (window as unknown as HudFrame).hudFrame();
        const w = window.game as unknown as Flight;
        if (!w.banner().text.startsWith('Missed ring 2')) return null;
        const r = w.rings()[1]!,
          c = w.world.components,
          e = w.aircraftBody();
        const dx = r.x - c.Position.x[e]!,
          dy = r.y - c.Position.y[e]!,
          dz = r.z - c.Position.z[e]!;
        // How squarely ring 3 faces the aircraft: the cosine between its way through and the line to it.
        return { facing: (dx * r.nx + dy * r.ny + dz * r.nz) / Math.hypot(dx, dy, dz) };
      },
      null,
      { unpause: false },
    );
    expect(missed.facing).toBeGreaterThan(0.995);
    const hud = await g.runUntil(
      () => {
        (window as unknown as HudFrame).hudFrame();
        const h = (window as unknown as { hud: { bad: string[]; seen: string[]; frames: number } }).hud;
        return h.seen.includes('miss') ? h : null;
      },
      null,
      { unpause: false },
    );
    expect(hud.bad.slice(0, 5)).toEqual([]);
    expect(new Set(hud.seen)).toEqual(new Set(['pass', 'note', 'miss']));
    // ← held until the aircraft banks 30 degrees, then let go: from the release the wings roll at
    // most 5 degrees further (they rolled on 8 degrees when the bank asked for stayed ahead of the
    // aircraft's) and come level within 1.3 s of game time. Every frame's bank is recorded. Let go
    // while still rolling in at up to 78 degrees a second, the ailerons take a moment to reverse: the
    // roll-on measured 4.0-4.2 degrees on a quiet machine, more than the 4 a let-go at rest allows
    // (test/games/flight-simulator-assist.test.ts).
    await recordBank(g);
    await g.page.keyboard.down('ArrowLeft');
    await g.runUntil(
      () => {
        (window as unknown as HudFrame).hudFrame();
        return (window.game as unknown as Flight).instruments().roll < -30 || null;
      },
      null,
      { unpause: false },
    );
    await g.page.keyboard.up('ArrowLeft');
    const { rolledOn, levelIn, trace } = await afterRelease(g);
    expect(rolledOn, trace).toBeLessThan(5);
    expect(levelIn, trace).toBeLessThan(1.3);
    // 500 m before ring 3, 60 m over the ground, sinking and ↓ held to dive: "PULL UP" shows (the
    // checks above run on every frame it shows).
    await place(2, 500, 0, 0);
    await g.page.evaluate(() => {
      const w = window.game as unknown as Flight;
      const c = w.world.components,
        e = w.aircraftBody();
      c.Position.y[e] = c.Position.y[e]! - (w.instruments() as unknown as { agl: number }).agl + 60;
      c.Velocity.y[e] = -12;
    });
    await g.page.keyboard.down('ArrowDown');
    const warned = await g.runUntil(
      () => {
        (window as unknown as HudFrame).hudFrame();
        const h = (window as unknown as { hud: { bad: string[]; seen: string[]; frames: number } }).hud;
        return h.seen.includes('warning') ? h : null;
      },
      null,
      { unpause: false },
    );
    await g.page.keyboard.up('ArrowDown');
    expect(warned.bad.slice(0, 5)).toEqual([]);
    expect(new Set(warned.seen)).toEqual(new Set(['pass', 'note', 'miss', 'warning']));
    expect(g.errors).toEqual([]);
    await g.close();
    // A long case (two rings, a let-go and a dive): 23 s on a quiet machine, 50 s and more under load.
  }, 180_000);
});
