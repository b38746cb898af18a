/**
 * The flight simulator's bank after a let-go (projects and phone-controls cases): every drawn frame's
 * bank is recorded with the game time and the keys' bank input, and what the wings did from the
 * release on is read back.
 */
import type { GamePage } from './harness';

type Flying = { world: { time: number }; instruments(): { roll: number }; keyInput(): { roll: number } };

/** Starts recording [game time s, bank deg, keys' bank input] once a drawn frame into `window.bankLog`. */
export async function recordBank(g: GamePage): Promise<void> {
  await g.page.evaluate(() => {
    const w = window.game as unknown as Flying;
    const log: [number, number, number][] = [];
    (window as unknown as { bankLog: typeof log }).bankLog = log;
    const rec = () => {
      log.push([w.world.time, w.instruments().roll, w.keyInput().roll]);
      requestAnimationFrame(rec);
    };
    requestAnimationFrame(rec);
  });
}

/**
 * Call right after the bank input is let go (recordBank running): waits until the wings are within
 * 3 degrees of level and returns how many degrees further than at the release they rolled meanwhile
 * (`rolledOn`) and how long they took to level (`levelIn`, s of game time, to where the bank crossed
 * 3 degrees between two recorded frames). For a key, the release
 * is the last recorded frame before the keys' input began to fall: the page applies a let-go key on
 * its next frame, and on a loaded machine that frame steps the game up to 4 steps (67 ms, 5 degrees
 * of roll) after the test's own reading. A stick has no ramp: its release is the test's reading.
 */
export async function afterRelease(g: GamePage): Promise<{ rolledOn: number; levelIn: number }> {
  const read = await g.page.evaluate(() => {
    const w = window.game as unknown as Flying;
    return { time: w.world.time, bank: w.instruments().roll };
  });
  const levelAt = await g.waitFor(
    (t0) => (window as unknown as { bankLog: [number, number, number][] }).bankLog.find(([t, b]) => t > t0 && Math.abs(b) < 3)?.[0] ?? null,
    read.time,
    60_000,
  );
  const log = await g.page.evaluate(() => (window as unknown as { bankLog: [number, number, number][] }).bankLog.slice());
  const fall = log.findIndex(([, , k], i) => i > 0 && Math.abs(k) < Math.abs(log[i - 1]![2]));
  const release = fall > 0 && log[fall - 1]![0] <= read.time + 0.5 ? { time: log[fall - 1]![0], bank: log[fall - 1]![1] } : read;
  const after = log.filter(([t]) => t >= release.time && t <= levelAt).map(([, b]) => b);
  // The wings came level between the last frame still past 3 degrees and the first within: the
  // crossing is put on the straight line between the two, not at the later frame (on a loaded
  // machine a frame steps up to 9 steps, 0.15 s, and the later frame alone read late by that much).
  const at = log.findIndex(([t]) => t === levelAt);
  let levelTime = levelAt;
  if (at > 0 && log[at - 1]![0] >= release.time) {
    const [t0, b0] = log[at - 1]!,
      [t1, b1] = log[at]!;
    if (Math.abs(b0) > Math.abs(b1)) levelTime = t0 + ((t1 - t0) * (Math.abs(b0) - 3)) / (Math.abs(b0) - Math.abs(b1));
  }
  return { rolledOn: Math.max(...after.map(Math.abs)) - Math.abs(release.bank), levelIn: levelTime - release.time };
}
