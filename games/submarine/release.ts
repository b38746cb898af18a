/**
 * What a let-go of Dive or Rise holds: the depth order line as the player last saw it drawn. The
 * helm's order (./helm.ts `HelmState.holdY`) runs on with every step the key is held, but on a
 * loaded machine the page draws only some frames (the frame pacer skips those the GPU has no room
 * for) and a key let go on seeing the line at a depth reaches the page a frame or more later: the
 * order has run on past the line the player let go at, and the boat stops metres beyond it. The
 * hint says "let go: stop at the line", so the line seen is the one held. Headless, tested in node.
 */

/**
 * The order a let-go holds, as the hull's y, m (negative under water): `shown` (the order as last
 * drawn) when the helm's `holdY` has run past it the way the boat was ordered (`mode` 'diving':
 * down, 'rising': up), else `holdY` (it never runs the order on; NaN `shown` leaves `holdY`).
 * @throws RangeError when `holdY` is not a number or `mode` is not 'diving' or 'rising'.
 */
export function releasedOrder(holdY: number, shown: number, mode: string): number {
  if (typeof holdY !== 'number') throw new RangeError(`releasedOrder: holdY must be a number, got ${holdY}`);
  if (mode !== 'diving' && mode !== 'rising') throw new RangeError(`releasedOrder: mode must be 'diving' or 'rising', got ${mode}`);
  if (Number.isNaN(shown) || Number.isNaN(holdY)) return holdY;
  return mode === 'diving' ? Math.max(holdY, shown) : Math.min(holdY, shown);
}

/** The order as last drawn: `note` it each frame as it is drawn from, read `shown` at a let-go. */
export interface ShownOrder {
  /**
   * Notes the order a frame is being drawn from (m, NaN for none) and how many frames had been put
   * on the screen before it (the frame pacer's `drawn`): a frame the pacer skips is never shown.
   */
  note(order: number, drawn: number): void;
  /** The order on the last frame put on the screen, given the frames put on it so far (`drawn`); NaN before any. */
  shown(drawn: number): number;
}

/** A new `ShownOrder` with nothing drawn yet. */
export function createShownOrder(): ShownOrder {
  let value = Number.NaN,
    pending = Number.NaN,
    at = -1;
  const settle = (drawn: number) => {
    // The frame noted last was put on the screen once the count has passed the one before it.
    if (at >= 0 && drawn > at) {
      value = pending;
      at = -1;
    }
  };
  return {
    note(order, drawn) {
      settle(drawn);
      pending = order;
      at = drawn;
    },
    shown(drawn) {
      settle(drawn);
      return value;
    },
  };
}
