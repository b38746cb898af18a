/**
 * Catapult: the camera's decisions, with no DOM: which view the camera heads for (the shot), and on
 * an upright phone how wide the aim view is. The page (main.ts) turns a shot into a rectangle for the
 * screen and eases to it.
 *
 * The views: 'overview' (the catapult, the field and the whole castle), 'aim' (on an upright phone:
 * the catapult large enough to aim with a finger, the castle's front in view when it is near),
 * 'follow' (from the aim view to the castle as the stone crosses the field) and 'castle' (the castle,
 * the rock behind it and room for debris).
 */

/** A view the camera heads for. */
export type CameraShot = 'overview' | 'aim' | 'follow' | 'castle';

/** What the camera's choice depends on. */
export interface CameraInput {
  /** Whether the screen is an upright phone's (narrow and taller than wide). */
  upright: boolean;
  /** World time since the level (or its replay) started, s (>= 0). */
  sinceStart: number;
  /** Whether a finger or the mouse has gone down on the scene since the level started. */
  touched: boolean;
  /** Whether the player asked to look at the castle (the phone's look button). */
  peeking: boolean;
  /** Whether a throw is being shown (in flight, or its verdict not yet read). */
  shotView: boolean;
  /** Whether the level is over after at least one throw (its result showing). */
  wreck: boolean;
  /** Whether the castle's view is closer than the aim view on this screen (always upright). */
  zoomsIn: boolean;
}

/**
 * Upright, the level opens on the overview for this long, s, so a player sees what to knock down
 * before the camera closes in on the catapult (a first touch closes in at once).
 */
export const INTRO_HOLD = 1.8;

/**
 * Upright, the castle's view stays this long after a throw's verdict, s, before the camera goes back
 * to the catapult: what the stone set off is still falling when the verdict shows (a tower can take
 * longer than 2.5 s to come down), and the castle is off the screen from the aim view.
 */
export const UPRIGHT_WATCH = 4.5;

/**
 * Upright, the aim view shows at least this many screen pixels a metre: the catapult (4 m across with
 * its stones) about 120 px wide on a 390 px phone, its cup a target for a finger; a wide level's
 * whole field fitted to that width would be half that (level 9's, 14 px a metre).
 */
export const AIM_PX_PER_M = 28;

/**
 * The view the camera heads for: the castle's view for a finished level's wreck (where it is
 * closer), the following view while a throw shows, and otherwise, upright, the overview at the
 * level's start (INTRO_HOLD, until the first touch) or while the player looks at the castle, else
 * the aim view. Not upright the aim view is the overview (the whole field fits a wide screen).
 * @throws RangeError if sinceStart is negative or not finite.
 */
export function cameraShot(s: CameraInput): CameraShot {
  if (!(Number.isFinite(s.sinceStart) && s.sinceStart >= 0))
    throw new RangeError(`cameraShot: sinceStart must be a finite time >= 0 s, got ${s.sinceStart}`);
  if (s.wreck && s.zoomsIn) return 'castle';
  if (s.shotView && s.zoomsIn) return 'follow';
  if (!s.upright) return 'overview';
  if (s.peeking) return 'overview';
  if (!s.touched && s.sinceStart < INTRO_HOLD) return 'overview';
  return 'aim';
}

/**
 * Upright, the aim view's span [minX, maxX], m: from `left` (just behind the catapult's stones) as
 * wide as the overview's span [left, overviewMaxX] where that shows at least AIM_PX_PER_M on a screen
 * `width` px wide, else narrowed to that scale (the castle off the screen to the right).
 * @throws RangeError if width is not positive or the overview's span is empty.
 */
export function uprightAimSpan(left: number, overviewMaxX: number, width: number): [number, number] {
  if (!(width > 0)) throw new RangeError(`uprightAimSpan: width must be > 0 px, got ${width}`);
  if (!(overviewMaxX > left)) throw new RangeError(`uprightAimSpan: overviewMaxX must exceed left (${left} m), got ${overviewMaxX}`);
  return [left, Math.min(overviewMaxX, left + width / AIM_PX_PER_M)];
}
