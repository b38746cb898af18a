/**
 * The flight simulator's bank after a let-go (projects and phone-controls cases): every drawn frame's
 * bank is recorded with the game time, and what the wings did from the release on is read back.
 */
import type { GamePage } from './harness';

type Flying = { world: { time: number }; instruments(): { roll: number } };

/** Starts recording [game time s, bank deg] once a drawn frame into `window.bankLog`. */
export async function recordBank(g: GamePage): Promise<void> {
  await g.page.evaluate(() => {
    const w = window.game as unknown as Flying;
    const log: [number, number][] = [];
    (window as unknown as { bankLog: typeof log }).bankLog = log;
    const rec = () => {
      log.push([w.world.time, w.instruments().roll]);
      requestAnimationFrame(rec);
    };
    requestAnimationFrame(rec);
  });
}

/**
 * Call right after the bank input is let go (recordBank running): waits until the wings are within
 * 3 degrees of level and returns how many degrees further than at the release they rolled meanwhile
 * (`rolledOn`) and how long they took to level (`levelIn`, s of game time).
 */
export async function afterRelease(g: GamePage): Promise<{ rolledOn: number; levelIn: number }> {
  const release = await g.page.evaluate(() => {
    const w = window.game as unknown as Flying;
    return { time: w.world.time, bank: w.instruments().roll };
  });
  const levelAt = await g.waitFor(
    (t0) => (window as unknown as { bankLog: [number, number][] }).bankLog.find(([t, b]) => t > t0 && Math.abs(b) < 3)?.[0] ?? null,
    release.time,
    60_000,
  );
  const after = await g.page.evaluate(
    ([t0, t1]) => (window as unknown as { bankLog: [number, number][] }).bankLog.filter(([t]) => t >= t0! && t <= t1!).map(([, b]) => b),
    [release.time, levelAt],
  );
  return { rolledOn: Math.max(...after.map(Math.abs)) - Math.abs(release.bank), levelIn: levelAt - release.time };
}
