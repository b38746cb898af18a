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
  /**
   * The ring's bearing from the way the aircraft flies, rad, + to the right, in [-pi, pi], and its
   * elevation above the flight path, rad, + above: what to do is read from these, not from the
   * screen, whose up is the aircraft's in the cockpit view (banked, the screen's down is partly sideways).
   */
  bearing: number;
  elevation: number;
  /** Whether the page is used by touch (the stick, not the keys, is named). */
  touch: boolean;
}

/** The label for an out-of-view ring and the arrow at its edge ('▶', '◀', '▲' or '▼'). */
export interface OffScreenLabel {
  text: string;
  arrow: '▶' | '◀' | '▲' | '▼';
}

/**
/** Bearing off the way flown, rad (15 degrees), from which an out-of-view ring is turned to rather than climbed or dived to. */
export const TURN_BEARING = (15 * Math.PI) / 180;

/**
 * The label of an out-of-view ring `r`: the arrow towards the screen edge its direction meets (a
 * ring behind: the side it lies, never up or down), and what to do, from its bearing and elevation:
 * "turn right" / "turn left" when it lies behind or TURN_BEARING or more to the side (the way to it
 * is a turn), else "climb" / "dive". On a keyboard the key is named ("hold →").
 * @throws RangeError on a ring number that is not an integer >= 1, a half size that is not finite
 * and > 0, or a bearing or elevation that is not finite.
 */
export function offScreenLabel(r: OffScreenRing): OffScreenLabel {
  if (!(Number.isInteger(r.ring) && r.ring >= 1)) throw new RangeError(`offScreenLabel: ring must be an integer >= 1, got ${r.ring}`);
  if (!(r.halfW > 0 && r.halfH > 0 && Number.isFinite(r.halfW * r.halfH)))
    throw new RangeError(`offScreenLabel: halfW and halfH must be finite and > 0, got ${r.halfW}, ${r.halfH}`);
  if (!(Number.isFinite(r.bearing) && Number.isFinite(r.elevation)))
    throw new RangeError(`offScreenLabel: bearing and elevation must be finite (rad), got ${r.bearing}, ${r.elevation}`);
  const sideways = r.behind || Math.abs(r.dx) * r.halfH > Math.abs(r.dy) * r.halfW;
  const arrow: OffScreenLabel['arrow'] = sideways ? (r.dx >= 0 ? '▶' : '◀') : r.dy < 0 ? '▲' : '▼';
  let act: string;
  if (r.behind || Math.abs(r.bearing) >= TURN_BEARING) {
    const right = r.bearing >= 0;
    act = `turn ${right ? 'right' : 'left'}${r.touch ? '' : ` (hold ${right ? '→' : '←'})`}`;
  } else {
    const up = r.elevation >= 0;
    act = `${up ? 'climb' : 'dive'}${r.touch ? '' : ` (hold ${up ? '↑' : '↓'})`}`;
  }
  const text = `ring ${r.ring}${r.behind ? ' behind' : ''} · ${r.distance} · ${act}`;
  return { text: arrow === '▶' ? `${text} ▶` : `${arrow} ${text}`, arrow };
}
