/**
 * The rope lab's levels and world, headless (no DOM, no Pixi), shared by the page and its tests.
 *
 * A level: a ball hangs from one to three ropes pinned to a beam; a basket stands on the floor; three
 * stars float in the air. Cut the ropes (cut.ts) so that the ball falls into the basket, catching the
 * stars on its way. Each rope is createRope's chain of point masses joined by distance joints that only
 * pull (rope links), pinned at its top; the ball (a dynamic ball body) hangs from its last point by one
 * more rope link. The links have a small radius, so a cut rope drapes over the basket and the floor.
 *
 * The ball is in the basket once its centre is inside the basket's walls and below their tops while it
 * is almost still (RopeGame.update); it is lost once it rests anywhere else, rolls on the floor
 * outside the basket, has been down on the floor outside it for LANDED_LOST s, has been free for FREE_LOST s, or leaves the level.
 */
import {
  addBody,
  addBox,
  addDistanceJoint,
  createPhysicsWorld,
  createRope,
  isAlive,
  type PhysicsWorld,
  type Rope,
  removeJoint,
  slotOf,
} from '@bitphysics/physics';

/** One level. Lengths in m, y up, the floor's top at y = 0. */
export interface Level {
  /** A name for the level's banner. */
  readonly name: string;
  /** The hint shown at the level's start. */
  readonly hint: string;
  /** Where each rope is pinned, m. */
  readonly anchors: readonly (readonly [number, number])[];
  /** Where the ball starts, m (the ropes are laid straight from their anchors to it). */
  readonly ball: readonly [number, number];
  /** Centre of the basket's floor, m (x, and y of its bottom's top). */
  readonly basket: readonly [number, number];
  /** Inner width of the basket, m. */
  readonly basketWidth: number;
  /** Height of the basket's walls, m. */
  readonly basketDepth: number;
  /** The three stars, m. */
  readonly stars: readonly (readonly [number, number])[];
  /** Walls in the way: centre and half extents, m. */
  readonly blocks?: readonly { readonly at: readonly [number, number]; readonly half: readonly [number, number] }[];
  /** What the camera frames, m (the level is drawn as large as it fits). */
  readonly view: { readonly minX: number; readonly minY: number; readonly maxX: number; readonly maxY: number };
  /** Half the room's width, m: its side walls' inner faces are this far from x = 0. Default ROOM_HALF_WIDTH. */
  readonly room?: number;
  /** The level's gravity as a share of the lab's (RopeSceneParams.gravity), default 1: the Moon's is 0.165. */
  readonly gravityScale?: number;
}

/** Radius of the ball, m. */
export const BALL_RADIUS = 0.28;
/** Mass of the ball, kg. */
export const BALL_MASS = 1;
/** The ball's linear drag coefficient k, N s/m (F = -k v, physics' linearDrag). */
export const BALL_DRAG = 0.02;
/** Thickness of the basket's walls and floor, m. */
export const WALL = 0.1;
/** Half the room's width of LEVELS, m (`Level.room`): its side walls' inner faces are this far from x = 0. */
export const ROOM_HALF_WIDTH = 2.7;
/** Half the room's width of level `level`, m. */
export function roomHalfWidth(level: Level): number {
  return level.room ?? ROOM_HALF_WIDTH;
}
/** Restitution of the room's side walls. */
export const WALL_RESTITUTION = 0.3;
/** Restitution of the ball. */
export const BALL_RESTITUTION = 0.25;
/** Restitution of the ball's contact with a side wall: the larger of the two (the engine's rule). */
export const SIDE_RESTITUTION = Math.max(WALL_RESTITUTION, BALL_RESTITUTION);
/** How close the ball's centre must come to a star to catch it, m. */
export const STAR_REACH = BALL_RADIUS + 0.22;

const VIEW = { minX: -2.9, minY: -0.35, maxX: 2.9, maxY: 9.1 } as const;

/** The levels, in order: each adds one idea. */
export const LEVELS: readonly Level[] = Object.freeze([
  {
    name: 'Let go',
    hint: 'Swipe across the rope to cut it. Cut when the stars and the basket light up.',
    anchors: [[0, 8.4]],
    ball: [-2, 6.7],
    // The basket stands under the right end of the swing, where the ball slows, stops and turns
    // back (as in the wide room's first level): a cut on the way up to that end or at it drops the
    // ball in, from 0.6 to 2.06 s, and the three stars hang along the drop from there (3 stars 1.0 to
    // 1.88 s; scripts/lab-rope-cuts.mjs 1; test/games/lab-rope.test.ts), so a cut at the far end
    // lands. A basket left of that end (x = 1) would be won only after the ball turned back, with
    // the stars zigzagging, and a cut at the far end would miss right and one a little later left.
    basket: [1.75, 0],
    basketWidth: 1.3,
    basketDepth: 0.75,
    stars: [
      [2.0, 5.3],
      [2.03, 4.0],
      [2.06, 2.7],
    ],
    view: VIEW,
  },
  {
    name: 'Two ropes',
    hint: 'Two ropes: which goes first? Then wait for the swing to cut the other.',
    anchors: [
      [-2.2, 8.4],
      [1, 8.4],
    ],
    ball: [-0.6, 6.3],
    basket: [1.9, 0],
    basketWidth: 1.1,
    basketDepth: 0.75,
    stars: [
      [0.5, 5.3],
      [2.25, 4.3],
      [1.95, 2.2],
    ],
    view: VIEW,
  },
  {
    name: 'Over the wall',
    hint: 'Cut on the upswing to throw the ball over the wall.',
    anchors: [[-1.1, 8.6]],
    ball: [-2.6, 6.9],
    basket: [2.05, 0],
    basketWidth: 1.1,
    basketDepth: 0.7,
    stars: [
      [0.55, 5.7],
      [1.85, 3.7],
      [2.05, 1.3],
    ],
    blocks: [{ at: [0.75, 1.5], half: [0.12, 1.5] }],
    view: VIEW,
  },
  {
    name: 'Three ropes',
    hint: 'Three ropes: cut them in the right order, at the right time.',
    anchors: [
      [-2.3, 8.5],
      [0, 8.8],
      [2.3, 8.5],
    ],
    ball: [0.2, 6.4],
    basket: [-1.9, 0],
    basketWidth: 1.1,
    basketDepth: 0.75,
    stars: [
      [-0.6, 5.15],
      [-2.25, 5.05],
      [-2.05, 2.6],
    ],
    view: VIEW,
  },
  {
    name: 'Push',
    hint: 'Drag the ball to push it into a swing, then cut.',
    anchors: [[-0.6, 8.6]],
    ball: [-0.6, 5.8],
    // Pushed at 5 m/s, a cut as the ball swings back up to the right lobs it onto the raised basket,
    // which reaches the right wall (won 3.55-4.3 s, 3 stars 3.85-4.1 s; scripts/lab-rope-cuts.mjs 5).
    basket: [2.05, 2.6],
    basketWidth: 1.2,
    basketDepth: 0.6,
    stars: [
      [0.95, 7.0],
      [-2.35, 5.6],
      [2.05, 3.6],
    ],
    blocks: [{ at: [2.05, 1.2], half: [0.65, 1.3] }],
    view: VIEW,
  },
  {
    name: 'Moon',
    hint: 'On the Moon the ball floats: watch the glow and cut when the stars light up.',
    anchors: [[-1.0, 8.4]],
    ball: [-2.5, 7.2],
    // A sixth of the Earth's gravity: the swing takes 7 s, and a cut on the way up to its right
    // end drifts onto the high basket (won 1.6-3.2 s).
    gravityScale: 0.165,
    basket: [1.75, 3.0],
    basketWidth: 1.2,
    basketDepth: 0.6,
    stars: [
      [0.95, 6.7],
      [1.15, 5.3],
      [2.05, 4.2],
    ],
    blocks: [{ at: [1.75, 1.5], half: [0.7, 1.5] }],
    view: VIEW,
  },
  {
    name: 'Window',
    hint: 'Throw the ball through the window in the wall.',
    anchors: [[-1.0, 8.4]],
    ball: [-2.4, 6.2],
    // A cut on the way up to the swing's right end throws the ball through the gap between the
    // walls (won 0.9-1.55 s); earlier it strikes the low wall, later the high one or drops short.
    basket: [1.95, 0],
    basketWidth: 1.2,
    basketDepth: 0.75,
    stars: [
      [0.55, 5.1],
      [1.95, 3.5],
      [2.25, 1.4],
    ],
    blocks: [
      { at: [1.0, 1.9], half: [0.12, 1.9] },
      { at: [1.0, 7.35], half: [0.12, 1.15] },
    ],
    view: VIEW,
  },
  {
    name: 'Off the wall',
    hint: 'The basket hides behind a wall: bounce the ball off the side of the room.',
    anchors: [[-0.6, 8.4]],
    ball: [-2.5, 7.2],
    // A cut as the ball swings up to the right throws it at the room's right wall, and it drops off
    // the wall into the basket behind the tall one (won 0.8-1.55 s).
    basket: [2.05, 0],
    basketWidth: 1.1,
    basketDepth: 0.75,
    stars: [
      [1.95, 5.8],
      [2.05, 3.6],
      [2.05, 1.4],
    ],
    blocks: [{ at: [1.25, 1.8], half: [0.12, 1.8] }],
    view: VIEW,
  },
]);

/** Half the room's width of WIDE_LEVELS, m. */
export const WIDE_ROOM_HALF_WIDTH = 5.2;
const WIDE_VIEW = { minX: -5.4, minY: -0.35, maxX: 5.4, maxY: 7.0 } as const;

/**
 * The levels for a screen wider than tall: the same eight ideas in a room twice as wide and 2 m
 * lower (10.4 x 7 m), so a desktop window draws them large (94 px a metre at 1280 x 800, the room
 * 1010 px wide; LEVELS' upright room, drawn as large as the window's height allows, would be 415 px
 * wide). Laid out with the ball's flights measured like LEVELS' (test/games/lab-rope.test.ts):
 * each cut's outcome the same wherever along its rope it is made, and no star caught by the
 * untouched swing.
 */
export const WIDE_LEVELS: readonly Level[] = Object.freeze([
  {
    name: 'Let go',
    hint: LEVELS[0]!.hint,
    anchors: [[-1.2, 6.3]],
    ball: [-4.2, 4.8],
    // A wide basket from under the right end of the swing, where the ball slows, stops and turns
    // back, to the room's right wall: a cut on the upswing throws the ball far right (off the wall
    // and down into the basket), one at the top drops it in, one just after the turn too. Won by a
    // cut anywhere from 1.04 s (the ball rising past the bottom) to 2.48 s, with no gap (scripts/
    // lab-rope-cuts.mjs --wide 1): a first level learnt by trying, not by a frame's timing. The three
    // stars hang along the drop from the very top (3 stars 2.04-2.24 s), the rising throws catch one
    // or two. (A basket under the swing's end alone, 1.5 m wide, was won only 2.0-2.56 s: a stranger
    // cutting on the upswing missed four times.)
    basket: [3.0, 0],
    basketWidth: 4.2,
    basketDepth: 0.75,
    stars: [
      [2.35, 3.4],
      [2.95, 3.2],
      [3.15, 2.6],
    ],
    view: WIDE_VIEW,
    room: WIDE_ROOM_HALF_WIDTH,
  },
  {
    name: 'Two ropes',
    hint: LEVELS[1]!.hint,
    anchors: [
      [-3.6, 6.3],
      [0.6, 6.3],
    ],
    ball: [-1.6, 4.5],
    // The left rope first (its swing on the right rope takes the first star), then the right one as
    // the ball swings up to the right: a 1.5 m basket under the throws of that upswing and its top
    // (a cut 0.5 s in, then the right rope 1.45-2.4 s in wins; 3 stars 1.6-2.05 s; scripts/
    // lab-rope-cuts.mjs --wide 2). The other way round never wins.
    basket: [3.45, 0],
    basketWidth: 1.5,
    basketDepth: 0.75,
    stars: [
      [-1.15, 3.4],
      [1.55, 3.3],
      [3.55, 1.4],
    ],
    view: WIDE_VIEW,
    room: WIDE_ROOM_HALF_WIDTH,
  },
  {
    name: 'Over the wall',
    hint: LEVELS[2]!.hint,
    anchors: [[-1.6, 6.3]],
    ball: [-4.4, 5.6],
    // The swing carries the ball over a 2.4 m wall to the right end of its swing; a cut as it rises
    // past the wall throws it on, one at the top drops it, both into the wide basket behind the wall
    // (won 1.7-2.75 s; scripts/lab-rope-cuts.mjs --wide 3). A cut before the ball is over the wall
    // strikes it or falls short. The three stars hang along the one high throw, cut just as the
    // ball rises past the wall (3 stars 1.7-1.79 s).
    basket: [1.7, 0],
    basketWidth: 3.0,
    basketDepth: 0.7,
    stars: [
      [1.05, 3.3],
      [0.95, 2.3],
      [0.85, 1.3],
    ],
    blocks: [{ at: [-0.3, 1.2], half: [0.12, 1.2] }],
    view: WIDE_VIEW,
    room: WIDE_ROOM_HALF_WIDTH,
  },
  {
    name: 'Three ropes',
    hint: LEVELS[3]!.hint,
    anchors: [
      [-2.0, 6.3],
      [0.4, 6.5],
      [3.6, 6.3],
    ],
    ball: [0.6, 4.7],
    // The right and middle ropes (either first), then the left one as the ball swings out to the
    // left wall or at the top of that swing: the basket stands against the left wall, and a ball
    // thrown at the wall drops off it into the basket (won 2.15-3.3 s after cuts at 1.0 and 1.3 s;
    // scripts/lab-rope-cuts.mjs --wide 4). The swing takes the first two stars, the drop from the
    // top of the swing the third (3 stars 3.25-3.3 s). The left rope cut before the right one never wins.
    basket: [-4.45, 0],
    basketWidth: 1.3,
    basketDepth: 0.75,
    stars: [
      [-0.15, 4.4],
      [-4.6, 4.0],
      [-2.35, 2.3],
    ],
    view: WIDE_VIEW,
    room: WIDE_ROOM_HALF_WIDTH,
  },
  {
    name: 'Push',
    hint: LEVELS[4]!.hint,
    anchors: [[-1.6, 6.3]],
    ball: [-1.6, 3.0],
    // Pushed at 5 m/s, a cut as it swings back up to the right, or at the top of that swing, lobs or
    // drops it onto the raised basket, which stands under the top of the swing (won 4.1-5.0 s;
    // scripts/lab-rope-cuts.mjs --wide 5); the push's swing takes the first two stars, the drop
    // the third. Untouched, it only hangs.
    basket: [0.45, 1.2],
    basketWidth: 0.85,
    basketDepth: 0.6,
    stars: [
      [0.35, 3.95],
      [-3.55, 3.62],
      [0.45, 3.0],
    ],
    blocks: [{ at: [0.45, 0.6], half: [0.55, 0.6] }],
    view: WIDE_VIEW,
    room: WIDE_ROOM_HALF_WIDTH,
  },
  {
    name: 'Moon',
    hint: LEVELS[5]!.hint,
    anchors: [[-2.8, 6.3]],
    ball: [-4.8, 5.0],
    // A sixth of the Earth's gravity: a cut as the ball drifts up to the right end of its slow
    // swing floats it onto the high basket (won 2.15-4.05 s).
    gravityScale: 0.165,
    basket: [-0.2, 2.4],
    basketWidth: 1.5,
    basketDepth: 0.6,
    stars: [
      [-0.25, 4.7],
      [-0.55, 3.9],
      [0.25, 3.6],
    ],
    blocks: [{ at: [-0.2, 1.2], half: [0.85, 1.2] }],
    view: WIDE_VIEW,
    room: WIDE_ROOM_HALF_WIDTH,
  },
  {
    name: 'Window',
    hint: LEVELS[6]!.hint,
    anchors: [[-2.2, 6.3]],
    ball: [-4.6, 5.0],
    // A cut as the ball rises from the bottom of its swing throws it through the gap between the
    // walls into the basket behind (won 1.1-1.7 s).
    basket: [2.55, 0],
    basketWidth: 2.5,
    basketDepth: 0.75,
    stars: [
      [0.75, 3.7],
      [1.25, 3.2],
      [1.55, 2.6],
    ],
    blocks: [
      { at: [0.8, 1.0], half: [0.12, 1.0] },
      { at: [0.8, 5.7], half: [0.12, 0.7] },
    ],
    view: WIDE_VIEW,
    room: WIDE_ROOM_HALF_WIDTH,
  },
  {
    name: 'Off the wall',
    hint: LEVELS[7]!.hint,
    anchors: [[-0.5, 6.3]],
    ball: [-3.5, 5.3],
    // A cut as the ball swings up to the right throws it over the tall wall at the room's right
    // wall, and it drops off it into the basket between the two (won 1.3-1.9 s).
    basket: [4.2, 0],
    basketWidth: 1.8,
    basketDepth: 0.75,
    stars: [
      [3.95, 3.05],
      [4.4, 2.3],
      [4.55, 1.3],
    ],
    blocks: [{ at: [3.0, 1.2], half: [0.12, 1.2] }],
    view: WIDE_VIEW,
    room: WIDE_ROOM_HALF_WIDTH,
  },
]);

/**
 * The flight of a ball let go now: its centre's path from (x, y) at velocity (vx, vy) (m, m/s) under
 * gravity `g` (m/s^2, downward, >= 0) and linear drag of rate `c` = k / m (1/s, >= 0), sampled every
 * `dt` s (> 0) until it would touch the floor, a block or the basket (its walls, rim or floor: a ball
 * that reaches the opening ends there), or after `maxTime` s. The exact solution of
 * m dv/dt = -m g y^ - k v (Ramtal and Dobre ch. 7, linear drag), from a start (x0, y0, u, w) s ago:
 * x = x0 + u (1 - e^(-c s)) / c, y = y0 + (w + g / c)(1 - e^(-c s)) / c - g s / c,
 * the drag-free parabola x0 + u s, y0 + w s - g s^2 / 2 as c -> 0 (used for c < 1e-9). At the room's
 * side walls it bounces (up to twice): the across-speed reversed and scaled by SIDE_RESTITUTION (the
 * contact's restitution, the larger of the wall's and the ball's), the path going on from there.
 * Writes x, y pairs into `out` (cleared first; the start point included). @returns whether the path
 * ends in the basket's opening (its centre over the basket's floor, between its walls).
 * @throws RangeError (naming predictFlight) on a negative or non-finite g or c, or dt not > 0.
 */
export function predictFlight(
  level: Level,
  x: number,
  y: number,
  vx: number,
  vy: number,
  g: number,
  c: number,
  out: number[],
  dt = 0.04,
  maxTime = 4,
): boolean {
  if (!(Number.isFinite(g) && g >= 0)) throw new RangeError(`predictFlight: g must be a finite number >= 0, got ${g}`);
  if (!(Number.isFinite(c) && c >= 0)) throw new RangeError(`predictFlight: c must be a finite number >= 0, got ${c}`);
  if (!(dt > 0)) throw new RangeError(`predictFlight: dt must be > 0, got ${dt}`);
  out.length = 0;
  out.push(x, y);
  const r = BALL_RADIUS,
    room = roomHalfWidth(level);
  const [bx, by] = level.basket,
    half = level.basketWidth / 2;
  // The flight's start: place, velocity and time (moved on at each bounce off a side wall).
  let x0 = x,
    y0 = y,
    u = vx,
    w = vy,
    t0 = 0,
    bounces = 0;
  for (let t = dt; t <= maxTime + 1e-9; t += dt) {
    const s = t - t0;
    let px: number, py: number, pvx: number, pvy: number;
    if (c < 1e-9) {
      px = x0 + u * s;
      py = y0 + w * s - 0.5 * g * s * s;
      pvx = u;
      pvy = w - g * s;
    } else {
      const decay = Math.exp(-c * s),
        e = (1 - decay) / c;
      px = x0 + u * e;
      py = y0 + (w + g / c) * e - (g * s) / c;
      pvx = u * decay;
      pvy = (w + g / c) * decay - g / c;
    }
    if (Math.abs(px) > room - r && bounces < 2 && py >= r) {
      // Off the side wall: on from the wall's face, the across-speed reversed and damped.
      px = Math.sign(px) * (room - r);
      x0 = px;
      y0 = py;
      u = -SIDE_RESTITUTION * pvx;
      w = pvy;
      t0 = t;
      bounces++;
    }
    // The basket's opening: between its walls, below a ball resting on its rim.
    const opening = Math.abs(px - bx) < half && py < by + level.basketDepth + r && py > by;
    const hit =
      py < r ||
      Math.abs(px) > room - r ||
      (Math.abs(px - bx) < half + WALL + r && py < by + level.basketDepth + r && !opening) ||
      (level.blocks ?? []).some((b) => {
        // The ball against the block's box: the distance from its centre to the box, round corners too.
        const dx = Math.max(0, Math.abs(px - b.at[0]) - b.half[0]),
          dy = Math.max(0, Math.abs(py - b.at[1]) - b.half[1]);
        return dx * dx + dy * dy < r * r;
      });
    out.push(px, py);
    if (opening) return true;
    if (hit) return false;
  }
  return false;
}

/**
 * Whether the path `path` (x, y pairs, m; predictFlight's) passes within STAR_REACH of the point
 * (sx, sy): measured to each straight piece between its points, not to the points alone (sampled
 * every 0.04 s, a throw's points lie 0.2 m apart).
 */
export function pathReaches(path: readonly number[], sx: number, sy: number): boolean {
  for (let i = 0; i + 1 < path.length; i += 2) {
    const ax = path[i]!,
      ay = path[i + 1]!;
    const bx = i + 3 < path.length ? path[i + 2]! : ax,
      by = i + 3 < path.length ? path[i + 3]! : ay;
    const dx = bx - ax,
      dy = by - ay,
      l2 = dx * dx + dy * dy;
    const u = l2 > 0 ? Math.max(0, Math.min(1, ((sx - ax) * dx + (sy - ay) * dy) / l2)) : 0;
    if (Math.hypot(ax + u * dx - sx, ay + u * dy - sy) < STAR_REACH) return true;
  }
  return false;
}

/** The lab's settings that shape its world. */
export interface RopeSceneParams {
  /** Rope links a metre of rope, in [2, 40]. */
  linksPerMetre: number;
  /** Mass of a metre of rope, kg, > 0. */
  ropeMass: number;
  /** Mass of the ball, kg, > 0. */
  ballMass: number;
  /** Gravity, m/s^2, >= 0. */
  gravity: number;
  /** Whether the links only pull (rope) or also push (rods). */
  slack: boolean;
}

/** The lab's defaults. */
export const DEFAULTS: Readonly<RopeSceneParams> = Object.freeze({
  linksPerMetre: 8,
  ropeMass: 0.08,
  ballMass: BALL_MASS,
  gravity: 9.81,
  slack: true,
});

/** One rope of the level: its bodies and links in order from the anchor to the ball. */
export interface RopePiece {
  /** Where it is pinned, m. */
  readonly anchor: readonly [number, number];
  /** createRope's rope. */
  readonly rope: Rope;
  /** The link from its last body to the ball. */
  readonly ballLink: number;
  /** Its links in order: rope.joints then ballLink. */
  readonly links: readonly number[];
  /** Its bodies in order (rope.bodies). */
  readonly bodies: readonly number[];
}

/** What `createRopeScene` made. */
export interface RopeScene {
  world: PhysicsWorld;
  level: Level;
  ball: number;
  ropes: RopePiece[];
}

/**
 * Builds level `index` (0-based) of `levels` (LEVELS, or WIDE_LEVELS for a wide screen): the floor,
 * the room's side walls, the basket, the blocks, the ball and its ropes.
 * @throws RangeError on a level index outside `levels`.
 */
export function createRopeScene(index: number, p: RopeSceneParams, levels: readonly Level[] = LEVELS): RopeScene {
  const level = levels[index];
  if (!level) throw new RangeError(`createRopeScene: level must be an integer in [0, ${levels.length - 1}], got ${index}`);
  const world = createPhysicsWorld({ gravity: [0, -p.gravity * (level.gravityScale ?? 1)], capacity: 2000 });
  addBox(world, { position: [0, -0.25], halfExtents: [20, 0.25], static: true, friction: 0.6 });
  // The room's side walls: their inner faces at x = -room and +room.
  const room = roomHalfWidth(level);
  for (const side of [-1, 1])
    addBox(world, { position: [side * (room + 1), 10], halfExtents: [1, 10], static: true, friction: 0.3, restitution: WALL_RESTITUTION });
  const [bx, by] = level.basket,
    half = level.basketWidth / 2;
  // The basket: a floor and two walls, static, of soft wicker (little bounce).
  addBox(world, { position: [bx, by + WALL / 2], halfExtents: [half + WALL, WALL / 2], static: true, friction: 0.8, restitution: 0.05 });
  for (const side of [-1, 1])
    addBox(world, {
      position: [bx + side * (half + WALL / 2), by + level.basketDepth / 2],
      halfExtents: [WALL / 2, level.basketDepth / 2],
      static: true,
      friction: 0.8,
      restitution: 0.05,
    });
  for (const b of level.blocks ?? []) addBox(world, { position: b.at, halfExtents: b.half, static: true, friction: 0.5 });
  const [x, y] = level.ball;
  const ball = addBody(world, {
    position: [x, y],
    mass: p.ballMass,
    radius: BALL_RADIUS,
    restitution: BALL_RESTITUTION,
    friction: 0.5,
    linearDrag: BALL_DRAG,
  });
  const ropes: RopePiece[] = [];
  for (const anchor of level.anchors) {
    const dx = x - anchor[0],
      dy = y - anchor[1],
      d = Math.hypot(dx, dy);
    // The rope runs from the anchor to the ball's surface; its last link joins the ball's centre.
    const length = d - BALL_RADIUS;
    const end: [number, number] = [anchor[0] + (dx / d) * length, anchor[1] + (dy / d) * length];
    const segments = Math.max(4, Math.round(length * p.linksPerMetre));
    const rope = createRope(world, {
      start: anchor,
      end,
      segments,
      mass: p.ropeMass * length,
      slack: p.slack,
      drag: 0.004,
      radius: 0.035,
    });
    const last = rope.bodies[rope.bodies.length - 1]!;
    const ballLink = addDistanceJoint(world, { a: last, b: ball, ...(p.slack ? { minLength: 0 } : {}) });
    ropes.push({ anchor, rope, ballLink, links: [...rope.joints, ballLink], bodies: Array.from(rope.bodies) });
  }
  return { world, level, ball, ropes };
}

/**
 * Cuts rope `rope` of a scene at its link `link` (one of `rope.links`) and frees the ball from the
 * piece below the cut: that loose end falls on its own, the ball flies on alone. A loose end left on
 * the ball (up to 2.5 m of rope, a fifth of the ball's mass, whipping and catching on the walls) would
 * make where a swipe crossed the rope decide the throw, not when: on level 3 a cut near the pin 1.0 s
 * in would fall short of the wall and one near the ball clear it. Freed, the ball's flight follows from the
 * time of the cut alone (the same outcome for a cut at a tenth, half and nine tenths of the rope at
 * every time tried, levels 1 to 5; see test/games/lab-rope.test.ts).
 * @throws RangeError (naming cutRope) when `link` is not one of the rope's links.
 */
export function cutRope(world: PhysicsWorld, rope: RopePiece, link: number): void {
  if (!rope.links.includes(link)) throw new RangeError(`cutRope: link must be one of the rope's links, got ${link}`);
  if (isAlive(world, link)) removeJoint(world, link);
  if (isAlive(world, rope.ballLink)) removeJoint(world, rope.ballLink);
}

/**
 * Seconds the free ball may roll on the floor outside the basket before the try is lost: rolling at
 * 0.45 m/s between the walls, a ball can take 14 s to come to rest, too long to wait for the miss.
 */
export const FLOOR_LOST = 0.5;
/**
 * Seconds after the free ball first comes down to the floor outside the basket (its centre within
 * LOW_REACH of it: on the floor, or on a cut rope lying there) before the try is lost, however it
 * bounces or jiggles since: a bounce off the floor rises under 0.6 m, too little to clear a basket
 * wall, so nothing brings it back in. Bounces reset FLOOR_LOST's count, and a ball lying on a
 * rope piece never settled under it: a miss sat on the floor 3 s before its card showed.
 */
export const LANDED_LOST = 1.2;
/** How far above lying on the floor the ball's centre may be and still count as down (a rope piece under it), m. */
export const LOW_REACH = 0.12;
/**
 * Time constant, s, of the basket's lining: a free ball in the basket's opening loses its speed as
 * exp(-t / NET_TIME). A ball dropping in fast across the basket struck its far wall's top and
 * bounced out over it (level 1, a cut 1.94 s in, between cuts at 1.9 and 2.0 s that won): whether a
 * throw won turned on a few centimetres at the rim. Lined, one that drops into the opening stays.
 */
export const NET_TIME = 0.08;
/** Seconds the ball may be free (no rope holding it) before a try that is not won is lost, whatever it does. */
export const FREE_LOST = 8;

/** Where a level stands. */
export type Outcome = 'playing' | 'won' | 'lost';

/**
 * The rules of a level on its scene: the stars caught, whether the ball is in the basket (won) or lost.
 * Call `update` after every step.
 */
export class RopeGame {
  /** Which stars are caught. */
  readonly caught: boolean[];
  outcome: Outcome = 'playing';
  /** Seconds the ball has been almost still (speed under 0.25 m/s). */
  private still = 0;
  /** Seconds the free ball has lain on the floor outside the basket, and been free at all. */
  private floored = 0;
  private free = 0;
  /** Seconds since the free ball first came down to the floor outside the basket; NaN until it has. */
  private landed = Number.NaN;

  constructor(readonly scene: RopeScene) {
    this.caught = scene.level.stars.map(() => false);
  }

  /** Stars caught. */
  stars(): number {
    return this.caught.filter(Boolean).length;
  }

  /** Ropes that still hold the ball (every link from the anchor to the ball alive). */
  holding(): number {
    const w = this.scene.world;
    return this.scene.ropes.filter((r) => r.links.every((l) => isAlive(w, l))).length;
  }

  /**
   * Catches the stars the ball touches and decides the outcome. @returns the indices of the stars
   * caught in this call (usually none).
   */
  update(): number[] {
    const { world, ball, level } = this.scene;
    const e = slotOf(ball);
    const P = world.components.Position,
      V = world.components.Velocity;
    const x = P.x[e]!,
      y = P.y[e]!;
    const [bx, by] = level.basket;
    const fresh: number[] = [];
    if (this.outcome !== 'playing') return fresh;
    level.stars.forEach(([sx, sy], i) => {
      if (!this.caught[i] && Math.hypot(x - sx, y - sy) < STAR_REACH) {
        this.caught[i] = true;
        fresh.push(i);
      }
    });
    const speed = Math.hypot(V.x[e]!, V.y[e]!);
    this.still = speed < 0.25 ? this.still + world.dt : 0;
    const inside = Math.abs(x - bx) < level.basketWidth / 2 && y > by && y < by + level.basketDepth + BALL_RADIUS;
    // A ball come to rest on the basket's rim (its centre over a wall's top) counts as in: whether
    // it stayed there or rolled off outside turned on a centimetre.
    const onRim =
      Math.abs(x - bx) < level.basketWidth / 2 + WALL + 0.02 &&
      y > by + level.basketDepth &&
      y < by + level.basketDepth + BALL_RADIUS + 0.08;
    const free = this.holding() === 0;
    this.free = free ? this.free + world.dt : 0;
    // The basket's soft lining: a free ball in its opening (over its floor, no higher than a ball
    // over its rim) is slowed hard, so one that drops in stays in (see NET_TIME).
    if (free && inside) {
      const k = Math.exp(-world.dt / NET_TIME);
      V.x[e] = V.x[e]! * k;
      V.y[e] = V.y[e]! * k;
    }
    // On the floor outside the basket (its walls stand up from the floor): nothing brings it back in.
    this.floored = free && !inside && !onRim && y < BALL_RADIUS + 0.03 ? this.floored + world.dt : 0;
    if (!Number.isNaN(this.landed)) this.landed += world.dt;
    else if (free && !inside && !onRim && y < BALL_RADIUS + LOW_REACH) this.landed = 0;
    if ((inside || onRim) && this.still > 0.3) this.outcome = 'won';
    else if (
      free &&
      (this.still > 0.6 ||
        this.floored > FLOOR_LOST ||
        this.landed > LANDED_LOST ||
        this.free > FREE_LOST ||
        y < -2 ||
        x < level.view.minX - 3 ||
        x > level.view.maxX + 3)
    )
      this.outcome = 'lost';
    return fresh;
  }
}
