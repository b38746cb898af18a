/**
 * Runs a game's fixed steps in the page faster than real time, for the browser cases that would
 * otherwise wait seconds of game time at the software renderer's frame rate: `window.game.step()`
 * (the N key's single step, the same step a frame runs) in a loop inside one evaluation, until a
 * predicate holds. Inputs already given through the browser (keys held, a finger down) apply to
 * those steps as they do to a frame's; only the waiting is shortened.
 */
import type { GamePage } from './harness';

/** Options of `stepUntil`. */
export interface StepUntilOptions {
  /** Most game time to step, s of `window.game.world.time` (> 0). Default 30. */
  seconds?: number;
  /** Let the game run on afterwards (unpause). Default true; false leaves it paused, as the steps do. */
  resume?: boolean;
  /** Animation frames to wait for afterwards (the HUD and the sprites are drawn from the state on each frame). Default 2. */
  frames?: number;
}

/**
 * Steps the game in the page (paused, as the N key does) until `until(arg)` (run in the page; a
 * function of this file's own, passed as its source) returns a truthy value, at most `seconds` of
 * game time; then, unless `resume` is false, lets it run on, waits for `frames` animation frames and
 * returns that value.
 * @throws Error naming the page and the predicate if it does not hold within `seconds` of game time.
 */
export async function stepUntil<A, R>(
  g: GamePage,
  until: (arg: A) => R,
  arg: A,
  { seconds = 30, resume = true, frames = 2 }: StepUntilOptions = {},
): Promise<Exclude<R, null | undefined | false | 0 | ''>> {
  const got = await g.evaluate(
    ([src, a, seconds, resume]) => {
      const game = window.game as unknown as { paused: boolean; step(): void; world: { time: number } };
      // biome-ignore lint/security/noGlobalEval: the predicate is the calling test's own function, passed as its source
      const test = eval(`(${src})`) as (a: unknown) => unknown;
      const end = game.world.time + seconds;
      game.paused = true;
      let value = test(a);
      while (!value && game.world.time < end) {
        game.step();
        value = test(a);
      }
      if (resume) game.paused = false;
      return { ok: !!value, value: value as unknown };
    },
    [until.toString(), arg as unknown, seconds, resume] as const,
    `stepping the game until ${until.toString().slice(0, 80)}`,
  );
  if (!got.ok) throw new Error(`${g.page.url()}: ${until.toString()} did not hold within ${seconds} s of game time; ${g.describe()}`);
  if (frames > 0) await g.frames(frames);
  return got.value as Exclude<R, null | undefined | false | 0 | ''>;
}

/** Runs `n` (>= 0) steps of the game in the page (it is left paused, as the N key leaves it), then waits for `frames` (default 2) animation frames. */
export async function stepN(g: GamePage, n: number, frames = 2): Promise<void> {
  await g.evaluate(
    (count) => {
      const game = window.game as unknown as { step(): void };
      for (let i = 0; i < count; i++) game.step();
    },
    n,
    `stepping the game ${n} times`,
  );
  if (frames > 0) await g.frames(frames);
}
