/**
 * What the next ring's label says when the ring is out of view: which way it lies and how to turn
 * to it ("turn right", with the key on a keyboard), so a player who has lost the ring off the edge
 * of the screen, or behind them, is told how to find it again rather than shown a small arrow.
 * Headless (no DOM), tested in node (test/games/flight-simulator-pacing.test.ts).
 */

/** Where an out-of-view ring lies, as the page projects it. */
export interface OffScreenRing {
  /** The ring's number as the player reads it (1-based). */
  ring: number;
  /** Its distance as the page writes it ("637 m", "1.2 km"). */
  distance: string;
  /**
   * Its direction from the scene's centre on the screen, px (x right, y down), already turned round
   * for a ring behind the camera (whose projection is mirrored).
   */
  dx: number;
  dy: number;
  /** Half the scene's width and height, px (> 0): the arrow points at the edge the direction meets. */
  halfW: number;
  halfH: number;
  /** Whether the ring is behind the camera. */
  behind: boolean;
  /** Whether the page is used by touch (the stick, not the keys, is named). */
  touch: boolean;
}

/** The label for an out-of-view ring and the arrow at its edge ('▶', '◀', '▲' or '▼'). */
export interface OffScreenLabel {
  text: string;
  arrow: '▶' | '◀' | '▲' | '▼';
}

/**
 * The label of an out-of-view ring `r`: the arrow towards the edge its direction meets, and what to
 * do: "turn right" / "turn left" for a ring to the side or behind (a ring behind is always turned
 * to, never climbed to: the way back is a turn), "climb" / "dive" for one above or below ahead. On a
 * keyboard the key is named ("hold →").
 * @throws RangeError on a ring number that is not an integer >= 1, or a half size that is not finite and > 0.
 */
export function offScreenLabel(r: OffScreenRing): OffScreenLabel {
  if (!(Number.isInteger(r.ring) && r.ring >= 1)) throw new RangeError(`offScreenLabel: ring must be an integer >= 1, got ${r.ring}`);
  if (!(r.halfW > 0 && r.halfH > 0 && Number.isFinite(r.halfW * r.halfH)))
    throw new RangeError(`offScreenLabel: halfW and halfH must be finite and > 0, got ${r.halfW}, ${r.halfH}`);
  const sideways = r.behind || Math.abs(r.dx) * r.halfH > Math.abs(r.dy) * r.halfW;
  const name = `ring ${r.ring}${r.behind ? ' behind' : ''} · ${r.distance}`;
  if (sideways) {
    const right = r.dx >= 0;
    const act = `turn ${right ? 'right' : 'left'}${r.touch ? '' : ` (hold ${right ? '→' : '←'})`}`;
    return right ? { text: `${name} · ${act} ▶`, arrow: '▶' } : { text: `◀ ${name} · ${act}`, arrow: '◀' };
  }
  const up = r.dy < 0;
  const act = `${up ? 'climb' : 'dive'}${r.touch ? '' : ` (hold ${up ? '↑' : '↓'})`}`;
  return up ? { text: `▲ ${name} · ${act}`, arrow: '▲' } : { text: `▼ ${name} · ${act}`, arrow: '▼' };
}
