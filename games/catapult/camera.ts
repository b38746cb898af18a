/**
 * Catapult: the camera's decisions, with no DOM: which view the camera heads for (the shot), and on
 * an upright phone the rectangle of each view. The page (main.ts) eases the camera to the view.
 *
 * The views: 'overview' (the catapult, the field and the whole castle: the aim view on a wide
 * screen), 'aim' (on an upright phone: the catapult close, with the castle shown in an inset and an
 * arrow at the screen's edge, or where the screen is wide enough the catapult and the whole castle),
 * 'follow' (from the aim view to the castle as the stone crosses the field) and 'castle' (the castle
 * and the rock behind it, close: a phone's look button, a new level's opening look on a phone, and a
 * finished level's wreck).
 *
 * On a desktop the views are `wideViews`: the whole field (the catapult and the castle) for the
 * level's start until its first throw and while the player pulls, the castle close between throws.
 *
 * Upright, a view fitted to the catapult and the castle draws them small (12 to 21 px a metre at
 * 390 px wide: a stone 7 to 12 px, the field a thin band under a tall sky); there the aim view is
 * close on the catapult (`uprightAimView`, AIM_PX_PER_M or closer) and the page shows the castle in
 * the earth under the ground while the player aims (`aimCloseUp`).
 */

import { LAUNCH, ROCK } from './scene';

/** A view the camera heads for. */
export type CameraShot = 'overview' | 'aim' | 'follow' | 'castle';

/** What the camera's choice depends on. */
export interface CameraInput {
  /** Whether the screen is an upright phone's (narrow and taller than wide). */
  upright: boolean;
  /** Whether the player asked to look at the castle (the phone's look button). */
  peeking: boolean;
  /** Whether a throw is being shown (in flight, or its verdict not yet read). */
  shotView: boolean;
  /** Whether the level is over after at least one throw (its result showing). */
  wreck: boolean;
  /** Whether the castle's view is closer than the aim view on this screen (always upright). */
  zoomsIn: boolean;
  /**
   * Whether a level's opening look at the castle is under way (`OPENING_FRAMES`: upright where the
   * aim view is close on the catapult, from a level's first frame until the player touches).
   */
  opening: boolean;
}

/**
 * Upright where the aim view is close on the catapult (`aimCloseUp`), a new level opens on its
 * castle, large (`uprightOpeningView`; the shot is 'castle'), for this many frames (1 s at 60 frames a
 * second), and the camera then pans across the field to the catapult: the player sees what they
 * shoot at and, in the pan, how far it lies from the catapult, before the castle goes to the inset
 * while they aim. (Opened on the catapult and the castle together, a 390 px phone drew the scene as
 * a thin strip low on the screen under 60 % of sky, 11 to 18 px a metre.) A touch ends it
 * at once.
 */
export const OPENING_FRAMES = 60;

/**
 * Upright, the castle's view stays this long after a throw's verdict, s, before the camera goes back
 * to the catapult: what the stone set off is still falling when the verdict shows (a tower can take
 * longer than 2.5 s to come down).
 */
export const UPRIGHT_WATCH = 4.5;

/**
 * The view the camera heads for: the castle's view for a finished level's wreck (where it is
 * closer), the following view while a throw shows, and otherwise, upright, the castle's view while
 * the player looks at the castle or a new level opens on it (`OPENING_FRAMES`), else the aim view. Not
 * upright the aim view is the overview (the whole field fits a wide screen).
 */
export function cameraShot(s: CameraInput): CameraShot {
  if (s.wreck && s.zoomsIn) return 'castle';
  if (s.shotView && s.zoomsIn) return 'follow';
  if (!s.upright) return 'overview';
  if (s.peeking || s.opening) return 'castle';
  return 'aim';
}

/** A view rectangle, m (x right, y up). */
export interface View {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

/** What of a level the upright views frame, m. */
export interface Field {
  /** The castle's near and far ends and its top, m. */
  castleMinX: number;
  castleMaxX: number;
  castleTop: number;
  /** The lowest surface (0 for flat ground, a pit's floor below it), m (<= 0). */
  floor: number;
  /**
   * How far the aim preview's dots reach, m (scene previewLimit: Infinity where they show the whole
   * flight); the close aim view keeps them in view (`uprightAimView`). Default Infinity.
   */
  previewTo?: number;
}

/**
 * On a screen taller than wide (an upright phone or tablet), where the lowest surface sits: this
 * fraction of the screen's height from the bottom, so the catapult, the flight and the castle use
 * the screen's lower middle, with the banner in the sky over them and a strip of earth under them
 * for the card saying how to play and the next-level button. At 0.11 the scene sat in the bottom
 * fifth under 70 % of empty sky; at 0.5 the bottom 40 % read as plain earth.
 */
export const UPRIGHT_GROUND = 0.28;

/**
 * The same where the aim view is close on the catapult and the castle's inset shows in the earth
 * while aiming (`aimCloseUp`): the screen's middle. The inset fills the earth, so more earth draws a
 * tall castle's inset larger (a 390 x 844 phone's 788 px canvas has 394 px of earth under the
 * ground: levels 4 to 8's insets 202 to 261 px tall, 166 px at 0.38), and the sky over the ground
 * (8 to 11 m at 48 to 36 px a metre) holds a throw at the castle across the whole aim view. At 0.38
 * the catapult sat under 62 % of mostly empty sky; a throw that rises higher is followed by a view
 * that rises with it.
 */
export const UPRIGHT_GROUND_CLOSE = 0.5;

/** Where the lowest surface sits on an upright screen for field `f`: UPRIGHT_GROUND_CLOSE where the close-up shows (`aimCloseUp`), else UPRIGHT_GROUND. */
export function uprightGround(f: Field, width: number, height: number): number {
  return aimCloseUp(f, width, height) ? UPRIGHT_GROUND_CLOSE : UPRIGHT_GROUND;
}

/** The upright aim view's left edge, m: just behind the catapult's stacked stones (4 at most, to x = -3.0 m). */
export const AIM_LEFT = LAUNCH.x - 3.2;

/** Room past the castle's far end in the upright aim view, m: a stone rolling off its back end stays in view. */
export const AIM_PAST = 0.8;

/** The right face of the rock behind a castle whose far end is at castleMaxX, m. */
export const rockRight = (castleMaxX: number): number => castleMaxX + ROCK.gap + 2 * ROCK.hx;

/**
 * An upright screen's view of the span [minX, maxX], m, fitted to the screen's width (`width` x
 * `height` px), the field's lowest surface `ground` of the way up the screen (default
 * `uprightGround`).
 * @throws RangeError if the span is empty or the screen's size not positive.
 */
export function uprightView(f: Field, minX: number, maxX: number, width: number, height: number, ground?: number): View {
  if (!(maxX > minX)) throw new RangeError(`uprightView: maxX must exceed minX (${minX} m), got ${maxX}`);
  if (!(width > 0 && height > 0)) throw new RangeError(`uprightView: the screen must be > 0 px each way, got ${width} x ${height}`);
  ground ??= uprightGround(f, width, height);
  const h = ((maxX - minX) * height) / width;
  const minY = f.floor - ground * h;
  return { minX, minY, maxX, maxY: minY + h };
}

/**
 * Upright, the view of the whole field: from just behind the catapult's stones (AIM_LEFT) to just
 * past the castle's far end (AIM_PAST). The aim view where it draws AIM_CLOSE_PX_PER_M or more (an
 * upright tablet), else too small (`aimCloseUp`).
 */
export function uprightFieldView(f: Field, width: number, height: number): View {
  return uprightView(f, AIM_LEFT, f.castleMaxX + AIM_PAST, width, height);
}

/**
 * Upright, the aim view's least scale where the whole field is too small on the screen (`aimCloseUp`),
 * px a metre: a 0.6 m stone 22 px across (7 to 12 px in the field's view on a 390 px phone), the
 * catapult with its stones 148 px wide, and the preview's start on every level after the first (to
 * 40 % of the way to the castle, at most 7 m) inside the view's 10.8 m.
 */
export const AIM_PX_PER_M = 36;

/**
 * Upright, the close aim view's scale where the preview's dots (`Field.previewTo`) and the castle's
 * front allow it, px a metre: a 0.6 m stone 29 px across, the catapult with its stones (4.1 m) 197 px
 * wide on a 390 px phone, 8.1 m of the field across (at AIM_PX_PER_M the catapult was a small figure
 * at the foot of a tall empty sky).
 */
export const AIM_CLOSE_PX_PER_M_MAX = 48;

/** Room past the preview's dots' end in the close aim view, m. */
export const AIM_PREVIEW_ROOM = 0.5;

/** Upright, the close aim view's right edge stays this far short of the castle's front, m: the castle is wholly off the screen, shown by its inset and its arrow at the edge rather than cut by the edge. */
export const AIM_SHORT = 1;

/**
 * Upright, the aim view: where the field's view (`uprightFieldView`) draws the castle small
 * (`aimCloseUp`: every level on a phone), close on the catapult: from AIM_LEFT, AIM_CLOSE_PX_PER_M_MAX
 * px a metre, or farther out where the preview's dots (`Field.previewTo`, a finite reach) need it, to
 * AIM_PREVIEW_ROOM past them, but no farther than AIM_PX_PER_M, and closer where that would reach
 * within AIM_SHORT of the castle's front; the page shows the castle in an inset under the ground and
 * an arrow with its distance at the screen's edge. Else (an upright tablet) the field's view, the
 * catapult and the whole castle.
 * @throws RangeError if the screen's size is not positive.
 */
export function uprightAimView(f: Field, width: number, height: number): View {
  if (!aimCloseUp(f, width, height)) return uprightFieldView(f, width, height);
  const to = f.previewTo ?? Number.POSITIVE_INFINITY;
  const reach = Number.isFinite(to) ? to + AIM_PREVIEW_ROOM - AIM_LEFT : 0;
  const span = Math.min(Math.max(width / AIM_CLOSE_PX_PER_M_MAX, reach), width / AIM_PX_PER_M);
  const right = Math.min(AIM_LEFT + span, f.castleMinX - AIM_SHORT);
  return uprightView(f, AIM_LEFT, Math.max(right, LAUNCH.x + 2), width, height);
}

/**
 * Upright, a level's opening look (`OPENING_FRAMES`): the castle's view (`uprightCastleView`), the
 * castle and the rock behind it as large as the screen's width allows (19 to 38 px a metre on a 390 px
 * phone, 1.5 to 2.5 times the scale of a view holding the catapult too), the ground where the
 * aim view has it, so the camera then pans level across the field to the catapult.
 * @throws RangeError if the screen's size is not positive.
 */
export function uprightOpeningView(f: Field, width: number, height: number): View {
  return uprightCastleView(f, width, height);
}

/** The share of the way to its target the camera eases in one frame at one physics step a frame. */
export const CAMERA_EASE = 0.1;

/**
 * The share of the way to its target the camera eases in a frame drawn `steps` physics steps after
 * the last (at least one: a paused page still eases a tenth a frame): 1 - (1 - CAMERA_EASE)^steps, so
 * a page drawing a frame every 4 steps (15 frames a second) follows a stone as closely, in game
 * time, as one drawing every step. Eased a tenth a frame whatever the steps, such a page's camera
 * lagged a 1 s throw by four times as far, and the stone reached the castle while the view was
 * still on the field (the hit seen only in the inset).
 */
export function easeShare(steps: number): number {
  return 1 - (1 - CAMERA_EASE) ** Math.max(1, steps);
}

/** Upright, the castle's view: the castle, the rock behind it and room for debris (0.8 m before, 1 m past the rock). */
export function uprightCastleView(f: Field, width: number, height: number): View {
  return uprightView(f, f.castleMinX - 0.8, rockRight(f.castleMaxX) + 1, width, height);
}

/**
 * Upright, a field's view (`uprightFieldView`) drawing fewer screen pixels a metre than this gives way
 * to the close aim view (`uprightAimView`) with the castle's inset in the earth under the ground. At
 * 14 to 18 px a metre (a far or wide castle on a 390 px screen) planks are 3 px thick, panes a few
 * pixels and a stone 8 to 11 px; at 21 to 22 px a metre (levels 1 and 2) a stall is about 25 px tall
 * on a 844 px screen, a thin strip between the sky and the earth. So every level on a phone held
 * upright aims close, and an upright tablet (24 px a metre or more) keeps the whole field.
 */
export const AIM_CLOSE_PX_PER_M = 24;

/**
 * Whether an upright screen (`width` x `height` px) aims close on the catapult and shows the castle's
 * inset in the earth while the player aims at field `f`: when its field's view (`uprightFieldView`)
 * draws fewer than AIM_CLOSE_PX_PER_M pixels a metre.
 * @throws RangeError as `uprightView` (the screen's size not positive).
 */
export function aimCloseUp(f: Field, width: number, height: number): boolean {
  if (!(width > 0 && height > 0)) throw new RangeError(`aimCloseUp: the screen must be > 0 px each way, got ${width} x ${height}`);
  // The field's view's width (uprightFieldView's span), fitted to the screen's width.
  return width / (f.castleMaxX + AIM_PAST - AIM_LEFT) < AIM_CLOSE_PX_PER_M;
}

/**
 * On a wide screen (a desktop), the play area the camera fits: from the view's foot (`minY`, under the
 * ground) to PLAY_SKY m over the castle's top, and at least to PLAY_TOP m (room over a low castle for
 * the arcs that come down on it). The whole field fitted to a desktop's width drew the castle and the
 * catapult in the bottom fifth of the screen under empty sky.
 */
export const PLAY_SKY = 3;
export const PLAY_TOP = 7;
/** The highest a wide field view's lowest surface sits: this share of the screen's height from the bottom. */
export const FIELD_GROUND = 0.2;
/** Room before the castle's near end and past the rock in the wide castle view, m. */
const CASTLE_BEFORE = 1.2,
  CASTLE_PAST = 0.4;

/** The views of a wide screen (see `wideViews`). */
export interface WideViews {
  /** The catapult and the whole castle: until the level's first throw and while a pull is under way, so the player sees what they aim at. */
  field: View;
  /** The castle and the rock behind it, close: at rest between throws, a throw's end and a finished level's wreck. */
  castle: View;
}

/**
 * A wide screen's (`width` x `height` px, not an upright phone's) views of field `f`, each with its
 * foot at `minY` (m, under the lowest surface) and the screen's aspect:
 * - field: from AIM_LEFT (the catapult and its stones) to AIM_PAST past the castle's far end, fitted
 *   to the screen's width (no lower than the play area: PLAY_SKY over the castle, PLAY_TOP at least);
 * - castle: the castle and the rock, from CASTLE_BEFORE before it to CASTLE_PAST past the rock,
 *   fitted to the play area's height, or zoomed out as far as holding them needs.
 * A view taller than the play area puts half its extra height under `minY` (earth), its lowest
 * surface no higher than FIELD_GROUND of the way up, and the rest over the play area (sky).
 * @throws RangeError if the screen's size is not positive.
 */
export function wideViews(f: Field, width: number, height: number, minY: number): WideViews {
  if (!(width > 0 && height > 0)) throw new RangeError(`wideViews: the screen must be > 0 px each way, got ${width} x ${height}`);
  const aspect = height / width;
  const playW = (Math.max(f.castleTop + PLAY_SKY, PLAY_TOP) - minY) / aspect;
  const playH = playW * aspect;
  // A view wider than the play area's is taller than it: half the extra height goes under the ground
  // (earth), so long as the lowest surface stays under FIELD_GROUND of the way up the screen, and the
  // rest to sky, rather than all of it to sky.
  const view = (x0: number, w: number): View => {
    const h = w * aspect;
    const foot = Math.min(minY, Math.max(minY - (h - playH) / 2, f.floor - FIELD_GROUND * h));
    return { minX: x0, minY: foot, maxX: x0 + w, maxY: foot + h };
  };
  const fieldW = Math.max(playW, f.castleMaxX + AIM_PAST - AIM_LEFT);
  const c0 = f.castleMinX - CASTLE_BEFORE,
    c1 = rockRight(f.castleMaxX) + CASTLE_PAST;
  const cw = Math.max(playW, c1 - c0);
  return { field: view(AIM_LEFT, fieldW), castle: view((c0 + c1 - cw) / 2, cw) };
}

/**
 * Upright, the scale of the view that follows a stone in flight, px a metre: a 0.6 m stone 24 px
 * across. Fitted to the whole field a 390 px phone draws 12 to 19 px a metre (a stone 7 to 11 px),
 * and the castle's view 19 to 38.
 */
export const FOLLOW_PX_PER_M = 40;

/**
 * Upright, the view that follows a stone in flight at (x, y), m: FOLLOW_PX_PER_M (or the castle's
 * view's scale where that is closer), the stone a fifth of the view's width left of its middle so
 * what it flies at shows ahead of it, kept between AIM_LEFT and 1 m past the rock, the lowest
 * surface where the other upright views put it and the whole view raised where the stone would
 * otherwise be within 15 % of its top.
 * @throws RangeError if the screen's size is not positive.
 */
export function uprightFollowView(f: Field, x: number, y: number, width: number, height: number): View {
  if (!(width > 0 && height > 0)) throw new RangeError(`uprightFollowView: the screen must be > 0 px each way, got ${width} x ${height}`);
  const right = rockRight(f.castleMaxX) + 1;
  const castle = uprightCastleView(f, width, height);
  const w = Math.min(width / FOLLOW_PX_PER_M, castle.maxX - castle.minX);
  const minX = Math.min(Math.max(x - 0.3 * w, AIM_LEFT), right - w);
  const v = uprightView(f, minX, minX + w, width, height, uprightGround(f, width, height));
  const lift = Math.max(0, y - (v.maxY - 0.15 * (v.maxY - v.minY)));
  return { minX: v.minX, minY: v.minY + lift, maxX: v.maxX, maxY: v.maxY + lift };
}
