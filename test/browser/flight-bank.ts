/**
 * The flight simulator's bank after a let-go (projects and phone-controls cases): every step's bank
 * is recorded with the game time and the keys' and the stick's bank inputs (the page's
 * `window.game.traceBank`), and what the wings did from the release on is read back, to the step,
 * whatever the frame rate.
 */
import type { GamePage } from './harness';

/** One step: [game time s, bank degrees, keys' bank input, stick's bank input]. */
type Row = [number, number, number, number];
type Flying = { traceBank(on: boolean): Row[] | null };

/** Starts recording every step's bank and bank inputs into `window.bankLog` (the page's `traceBank`). */
export async function recordBank(g: GamePage): Promise<void> {
  await g.page.evaluate(() => {
    (window as unknown as { bankLog: Row[] | null }).bankLog = (window.game as unknown as Flying).traceBank(true);
  });
}

/**
 * Call after the bank input is let go (recordBank running): waits until the wings are within 3
 * degrees of level after the release and returns how many degrees further than at the release they
 * rolled meanwhile (`rolledOn`) and how long they took to level (`levelIn`, s of game time, to where
 * the bank crossed 3 degrees between two steps), and those steps (`trace`: time from the release s,
 * bank degrees, bank input) for a failure's message. The release is the last step before the bank input
 * (keys' and stick's) began to fall: a key let go ramps its input down from the step the page gives
 * its release to (a frame's steps share the frame's span of the clock), the stick drops to 0 there.
 * Stops the recording.
 */
export async function afterRelease(g: GamePage): Promise<{ rolledOn: number; levelIn: number; trace: string }> {
  const seen = await g.waitFor(
    () => {
      const log = (window as unknown as { bankLog: Row[] }).bankLog;
      const input = (r: Row) => Math.abs(r[2] + r[3]);
      const fall = log.findIndex((r, i) => i > 0 && input(r) < input(log[i - 1]!));
      if (fall < 0) return null;
      const level = log.findIndex((r, i) => i >= fall && Math.abs(r[1]) < 3);
      return level < 0 ? null : log.slice(fall - 1, level + 1);
    },
    null,
    60_000,
  );
  await g.page.evaluate(() => (window.game as unknown as Flying).traceBank(false));
  const release = seen[0]!;
  const [t0, b0] = seen[seen.length - 2]!,
    [t1, b1] = seen[seen.length - 1]!;
  // The wings came level between the last step still past 3 degrees and the first within: the
  // crossing is put on the straight line between the two.
  const levelTime = Math.abs(b0) > Math.abs(b1) ? t0 + ((t1 - t0) * (Math.abs(b0) - 3)) / (Math.abs(b0) - Math.abs(b1)) : t1;
  const trace = seen.map(([t, b, k, s]) => `${(t - release[0]).toFixed(3)}:${b.toFixed(1)}:${(k + s).toFixed(2)}`).join(' ');
  return { rolledOn: Math.max(...seen.map((r) => Math.abs(r[1]))) - Math.abs(release[1]), levelIn: levelTime - release[0], trace };
}
