/**
 * Catapult, the rules (no DOM, no pixi; they run in Node and in tests): seeded castle levels of
 * wooden posts and planks, glass, stone blocks and round stones glued by breakable weld joints, on
 * flat ground, a hill or by a pit; the launch from a pull, the drag-free predicted arc, and the score.
 *
 * Units: metres, seconds, kilograms. The ground's top is y = 0 from x = GROUND.minX to GROUND.maxX
 * (a level's hill or pit changes it there: `Level.terrain`); the catapult throws from LAUNCH.
 * Score: FALL_POINTS for every castle piece that is down (`hasFallen`, measured from where the piece
 * came to rest once the new castle settled: dropped more than DROP_SHARE of its height, knocked
 * KNOCK_DISTANCE aside, a box tipped past TIP_ANGLE, or off the ground's end) and BREAK_POINTS for
 * every weld joint that broke.
 */
import {
  addBody,
  addBox,
  addSystem,
  addWeldJoint,
  isAlive,
  isSleeping,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  Rng,
  removeBody,
  slotOf,
  step,
} from '@bitphysics/physics';

/** Where the projectile leaves the catapult (its cup), m. */
export const LAUNCH = { x: 0, y: 1.5 } as const;
/**
 * The ground: a static slab whose top is y = 0, from minX to maxX, m. It reaches 12 m behind the
 * catapult so that a view letterboxed to the castle's height (wider than the field) still has grass
 * at its left edge.
 */
export const GROUND = { minX: -12, maxX: 34 } as const;
/**
 * Longest pull, m, and launch speed per metre of pull, 1/s: the top speed is 3 x 7 = 21 m/s, which
 * carries a stone 45 m at 45 degrees (the farthest castle ends at about 28 m); a higher gain would
 * send ordinary pulls past the castle.
 */
export const PULL = { max: 3, gain: 7 } as const;
/** Projectile radius, m. */
export const PROJECTILE_RADIUS = 0.3;
/**
 * Rolling resistance of the grass: a projectile or a crown stone on the ground is slowed by
 * ROLL_RESISTANCE x its weight (and its spin by as much at its rim), so a stone that lands short
 * thuds and stops instead of rolling on into the castle (a ball rolling without slipping on flat
 * ground never slows).
 */
export const ROLL_RESISTANCE = 1.2;
/**
 * A castle piece is down when its centre has dropped more than DROP_SHARE of its height (as built:
 * twice its half height, a stone's diameter) below where it came to rest, and at least DROP_MIN m: a
 * stall whose posts buckle drops its roof plank a few tenths of a metre, which a player sees as
 * fallen, while settling moves a piece by millimetres.
 */
export const DROP_SHARE = 0.35;
export const DROP_MIN = 0.15;
/**
 * A castle piece is also down when its centre is KNOCK_DISTANCE (m) from where it came to rest (a
 * stone block pushed off its row, a post on the ground shoved aside, a crown stone rolled off its
 * roof), or a box has turned past TIP_ANGLE (rad, 30 degrees) from its resting angle: a post leaning
 * that far reads as falling over, and one leaning less can still stand.
 */
export const KNOCK_DISTANCE = 0.8;
export const TIP_ANGLE = Math.PI / 6;
/** Longest settling of a new castle before its resting poses are taken (`settleLevel`), s. */
export const SETTLE_TIME = 3;
/** Points for a fallen piece and for a broken joint. */
export const FALL_POINTS = 100;
export const BREAK_POINTS = 25;
/** Options of a level. */
export interface LevelOptions {
  /** Level index, integer in [0, LEVEL_COUNT) (0-based: level 1 on the page is 0). */
  level: number;
  /** Seed of the castle's variations. */
  seed: number;
  /** Gravity, m/s^2 downwards, > 0. */
  gravity: number;
  /** Force past which a weld joint breaks, N, > 0 (torque limit: this x 0.25 m). */
  jointStrength: number;
}

/** One castle piece: its body and where it came to rest once its castle settled (`settleLevel`). */
export interface Piece {
  body: number;
  /** Centre (m) and angle (rad) at rest: as built until the castle has settled, then where it settled. */
  startX: number;
  startY: number;
  startAngle: number;
  /** Wood ('post', 'plank'), glass ('block': blocks and panes), stone ('brick': a block; 'stone': round). */
  kind: 'post' | 'plank' | 'block' | 'brick' | 'stone';
  /** Half width and half height of a box, m; a stone's radius twice. */
  half: [number, number];
  /** Whether the piece has counted as fallen: once it has, it stays fallen (set by `tally`). */
  down?: boolean;
}

/** A static box of the ground's shape: the ground's slabs, a hill, a pit's floor (m). */
export interface Terrain {
  body: number;
  kind: 'ground' | 'hill' | 'pit';
  minX: number;
  maxX: number;
  minY: number;
  maxY: number;
}

/** What a level holds. */
export interface Level {
  /** The level's name, as the player sees it. */
  name: string;
  /** Castle pieces. */
  pieces: Piece[];
  /** Weld joints built (handles). */
  joints: number[];
  /** The two bodies each weld joint holds together, in the order of `joints`. */
  jointBodies: Array<[number, number]>;
  /** Shots the player has at the start. */
  shots: number;
  /** Left and right end of the castle, m (for aiming and framing). */
  castleMinX: number;
  castleMaxX: number;
  /** Height of the castle's top, m (for framing). */
  castleTop: number;
  /** The ground's handle (its slab under the catapult; 0 before a level is built). */
  ground: number;
  /** The ground's shape: its slabs, and a hill or a pit's floor where the level has one. */
  terrain: Terrain[];
  /** The catapult mound's handle (0 before a level is built). */
  mound: number;
  /**
   * A static rock past the castle (its handle, 0 before a level is built) that stops debris sliding
   * out of the view; its right face is at `castleMaxX + ROCK.gap + 2 ROCK.hx`.
   */
  rock: number;
}

/** The rock behind the castle: its gap from the castle's right end, half width and half height, m. */
export const ROCK = { gap: 1.9, hx: 0.5, hy: 1.4 } as const;

/**
 * The world options: 2D, room for the castle and shots, resting islands asleep (the default). A
 * castle left alone falls asleep within about a second of its build and stays where it stands
 * until something hits it: kept awake, its round stones, neutral on their planks, would roll off
 * (0.2 to 6 m in two minutes, as in planck.js and Rapier kept awake) and score by themselves.
 */
export function worldOptions(o: { gravity: number }): PhysicsWorldOptions {
  return { dimensions: 2, capacity: 1000, gravity: [0, -o.gravity] };
}

/** A post (wood, or a glass pane) of a storey, half extents (m). */
const POST = { hx: 0.15, hy: 0.6 } as const;
/** Width of a tower's storey (two posts under a plank), m. */
const SPAN = 2.4;
/** A storey's floor plank, half extents (m): the storey's width and 0.2 m over each side. */
const PLANK = { hx: SPAN / 2 + 0.2, hy: 0.12 } as const;
/** From one tower's middle to the next one's, m (room for a bridge plank between their roofs). */
const TOWER_PITCH = SPAN + 1.2;
/**
 * The fortress's (level 9's) extra room between each outer tower and the bridged pair, m, on top of
 * TOWER_PITCH: room for an earth bank between them.
 */
const FORT_GAP = 0.8;
/** Height of the fortress's earth banks either side of its keep, m (half its towers' height). */
const FORT_BANK = 2.5;
/** A stone block, half extents (m). */
const BRICK = { hx: 0.4, hy: 0.25 } as const;
/** A glass pane (a post of glass), half extents (m). */
const PANE = { hx: 0.12, hy: 0.6 } as const;
/** Width of a bay of a hall (from one pane to the next), m. */
const BAY = 2.2;

/** Areal density (kg/m^2) and friction of each kind of box piece: wood, glass, stone. */
const MATERIAL: Record<Exclude<Piece['kind'], 'stone'>, { density: number; friction: number }> = {
  post: { density: 2, friction: 0.7 },
  plank: { density: 2, friction: 0.7 },
  block: { density: 1.5, friction: 0.7 },
  brick: { density: 5, friction: 0.8 },
};

/** What a level's builder works with (see LEVELS). */
interface Builder {
  world: PhysicsWorld;
  lv: Level;
  rng: Rng;
  /** Level index, 0-based. */
  level: number;
  /** A box piece of `kind` centred at (x, y), half extents (hx, hy), m. @returns its body. */
  box(kind: Exclude<Piece['kind'], 'stone'>, x: number, y: number, hx: number, hy: number): number;
  /** A round stone of radius r (m) and mass (kg) centred at (x, y). @returns its body. */
  stone(x: number, y: number, r: number, mass: number): number;
  /** Welds bodies a and b at `anchor` (m), breaking at the level's joint strength. */
  weld(a: number, b: number, anchor: [number, number]): void;
}

/** A tower's roof: its plank's body, its middle x and the height of its top, m. */
interface Roof {
  body: number;
  x: number;
  y: number;
}

/** Options of `tower`. */
interface TowerOptions {
  /** Crown stones on the roof: 1 (in the middle) or 2. Default 1. */
  stones?: number;
  /** Crown stones' mass, kg. Default 2 + level / 2. */
  stoneMass?: number;
  /**
   * Glass blocks inside: 'seeded' puts one in each storey above the first with chance 1/2 (from the
   * level's seed), a number n in the n storeys above the first. Default 'seeded'.
   */
  blocks?: 'seeded' | number;
  /** The posts: wood ('post') or glass panes ('block'). Default 'post'. */
  post?: 'post' | 'block';
  /** Storey width, m. Default SPAN. */
  span?: number;
  /** A body the first storey's posts are welded to (the deck it stands on), or 0. Default 0. */
  on?: number;
}

/**
 * A tower of `storeys` storeys standing at x = cx on the surface at height `base` (m): each storey two
 * posts under a plank, each post welded to the plank under it and to the plank over it; crown stones
 * on the roof. @returns its roof.
 */
function tower(b: Builder, cx: number, base: number, storeys: number, o: TowerOptions = {}): Roof {
  const span = o.span ?? SPAN;
  const post = o.post === 'block' ? PANE : POST;
  const plankHx = span / 2 + 0.2;
  let y = base,
    below = o.on ?? 0,
    roof = 0;
  for (let s = 0; s < storeys; s++) {
    const storeyBase = y;
    const posts: number[] = [];
    for (const side of [-1, 1]) {
      const px = cx + side * (span / 2 - POST.hx);
      const p = b.box(o.post ?? 'post', px, y + post.hy, post.hx, post.hy);
      posts.push(p);
      if (below) b.weld(below, p, [px, y]);
    }
    y += 2 * post.hy;
    roof = b.box('plank', cx, y + PLANK.hy, plankHx, PLANK.hy);
    for (const p of posts) b.weld(p, roof, [b.world.components.Position.x[slotOf(p)]!, y]);
    y += 2 * PLANK.hy;
    below = roof;
    const blocks = o.blocks ?? 'seeded';
    if (s > 0 && (blocks === 'seeded' ? b.rng.next() < 0.5 : s <= blocks)) b.box('block', cx, storeyBase + 0.3, 0.3, 0.3);
  }
  const stones = o.stones ?? 1;
  const r = 0.3 + 0.02 * b.level;
  for (let k = 0; k < stones; k++) b.stone(cx + (stones === 1 ? 0 : (k - 0.5) * 1.1), y + r, r, o.stoneMass ?? 2 + 0.5 * b.level);
  return { body: roof, x: cx, y };
}

/**
 * A bridge plank between two roofs of the same height, welded to both; it lies on the roofs' inner
 * 0.55 m (a crown stone must stay out of there). @returns the middle of its top (x, y), m.
 */
function bridge(b: Builder, a: Roof, c: Roof): [number, number] {
  const mid = (a.x + c.x) / 2;
  const half = (c.x - a.x) / 2 - SPAN / 2 + 0.35;
  const body = b.box('plank', mid, a.y + PLANK.hy, half, PLANK.hy);
  b.weld(a.body, body, [mid - half + 0.15, a.y]);
  b.weld(c.body, body, [mid + half - 0.15, a.y]);
  return [mid, a.y + 2 * PLANK.hy];
}

/**
 * A block of stone blocks `cols` wide and `rows` high centred at x = cx on the surface at height
 * `base`, laid in bond (every other row shifted half a block, with half blocks at its ends; one block
 * wide, a plain column), not glued. @returns the height of its top, m.
 */
function brickBlock(b: Builder, cx: number, base: number, cols: number, rows: number, brick: { hx: number; hy: number }): number {
  const w = 2 * brick.hx;
  const left = cx - (cols * w) / 2;
  for (let r = 0; r < rows; r++) {
    const y = base + brick.hy + r * 2 * brick.hy;
    // One block wide: a plain column.
    if (r % 2 === 0 || cols === 1) for (let c = 0; c < cols; c++) b.box('brick', left + (c + 0.5) * w, y, brick.hx - 0.005, brick.hy);
    else {
      b.box('brick', left + w / 4, y, brick.hx / 2 - 0.005, brick.hy);
      for (let c = 0; c < cols - 1; c++) b.box('brick', left + (c + 1) * w, y, brick.hx - 0.005, brick.hy);
      b.box('brick', left + cols * w - w / 4, y, brick.hx / 2 - 0.005, brick.hy);
    }
  }
  return base + rows * 2 * brick.hy;
}

/**
 * A hall of glass panes (or wooden posts) under wooden beams at x0 (its left pane) on the surface at
 * height `base`: `bays` bays of BAY m, `floors` floors; each beam welded to the panes under it and
 * the panes of the floor above to the beam they stand on. Crown stones stand in the upper floor's
 * outer bays, glass blocks on the roof over the middle bay.
 */
function hall(b: Builder, x0: number, base: number, bays: number, floors: number, post: 'pane' | 'post'): void {
  const p = post === 'pane' ? PANE : POST;
  const kind = post === 'pane' ? 'block' : 'post';
  let y = base,
    beams: number[] = [];
  for (let f = 0; f < floors; f++) {
    const panes: number[] = [];
    for (let i = 0; i <= bays; i++) {
      const px = x0 + i * BAY;
      const pane = b.box(kind, px, y + p.hy, p.hx, p.hy);
      panes.push(pane);
      const under = beams[Math.min(i, bays - 1)];
      if (under !== undefined) b.weld(under, pane, [px, y]);
    }
    y += 2 * p.hy;
    const next: number[] = [];
    for (let i = 0; i < bays; i++) {
      const beam = b.box('plank', x0 + (i + 0.5) * BAY, y + PLANK.hy, BAY / 2 - 0.005, PLANK.hy);
      b.weld(panes[i]!, beam, [x0 + i * BAY, y]);
      b.weld(panes[i + 1]!, beam, [x0 + (i + 1) * BAY, y]);
      next.push(beam);
    }
    beams = next;
    y += 2 * PLANK.hy;
    if (f === floors - 2) {
      const r = 0.3 + 0.02 * b.level;
      b.stone(x0 + 0.5 * BAY, y + r, r, 2 + 0.5 * b.level);
      b.stone(x0 + (bays - 0.5) * BAY, y + r, r, 2 + 0.5 * b.level);
    }
  }
  const mid = x0 + (bays / 2) * BAY;
  b.box('block', mid - 0.35, y + 0.3, 0.3, 0.3);
  b.box('block', mid + 0.35, y + 0.3, 0.3, 0.3);
}

/** A static hill (an earth box) from minX to maxX, `height` m high, on the ground. */
function hill(b: Builder, minX: number, maxX: number, height: number): void {
  terrain(b, 'hill', minX, maxX, 0, height);
}

/**
 * A pit from minX to maxX, `depth` m deep: the level's ground is made again as a slab either side of
 * it (the left one is `Level.ground`) and the pit's floor.
 */
function pit(b: Builder, minX: number, maxX: number, depth: number): void {
  removeBody(b.world, b.lv.ground);
  b.lv.terrain = b.lv.terrain.filter((t) => t.body !== b.lv.ground);
  b.lv.ground = terrain(b, 'ground', GROUND.minX, minX, -1, 0);
  terrain(b, 'ground', maxX, GROUND.maxX, -1, 0);
  terrain(b, 'pit', minX, maxX, -depth - 1, -depth);
}

/** A static earth box of `kind` over [minX, maxX] x [minY, maxY], m, listed in `Level.terrain`. @returns its body. */
function terrain(b: Builder, kind: Terrain['kind'], minX: number, maxX: number, minY: number, maxY: number): number {
  const body = addBox(b.world, {
    position: [(minX + maxX) / 2, (minY + maxY) / 2],
    halfExtents: [(maxX - minX) / 2, (maxY - minY) / 2],
    static: true,
    friction: 0.9,
  });
  b.lv.terrain.push({ body, kind, minX, maxX, minY, maxY });
  return body;
}

/** The height of the surface (the top of the highest terrain box) at x, m; -Infinity off the ground. */
export function surfaceAt(lv: Pick<Level, 'terrain'>, x: number): number {
  let top = Number.NEGATIVE_INFINITY;
  for (const t of lv.terrain) if (x >= t.minX && x <= t.maxX) top = Math.max(top, t.maxY);
  return top;
}

/**
 * The levels, in order: each a castle of its own shape and materials (a name shown to the player,
 * the shots it allows, and its builder): one wooden tower, a keep of wood and stone, two towers joined
 * by a bridge, a deck on stone piers, a tower down in a pit, a fort on a hill, a hall of glass,
 * three towers, and a fortress. They come in the order of how hard they measured (the share of
 * single throws over a grid of angles and powers that clear them), so each asks a little more than
 * the one before. The castles stand 7 to 26 m out, so the catapult and the castle share the screen
 * at a scale where a piece reads (a 1.2 m post about 40 px tall on a 1060 px wide view). The first
 * three ask for different throws (games/catapult/solve.ts, `node scripts/catapult-levels.mjs --grid`):
 * two market stalls, stones on low tables, one near by and one behind it (a low, flat throw brings
 * both down for three stars), a low keep behind a low earth rampart (a flat throw skims over it, a
 * lob drops onto the keep) with a lookout behind it, and
 * twin towers far off behind a taller rampart with a lookout behind them (three stars take two
 * aimed throws); one blind throw does not clear all three.
 */
const LEVELS: ReadonlyArray<{ name: string; shots: number; build: (b: Builder) => void }> = [
  {
    // Named for what it shows: two low tables with stones on them.
    name: 'Market stalls',
    // A low stall near by and a wider one 5.5 m behind it: a throw at either clears the level, and three
    // stars take both, each aimed (a careless pull toppled both at 3.3 m apart); a hard, flat throw
    // meant for a farther castle flies over them.
    shots: 3,
    build: (b) => {
      const x = 8.5 + b.rng.range(-0.5, 0.5);
      tower(b, x, 0, 1, { stones: 2 });
      tower(b, x + 5.5, 0, 1, { stones: 1, span: 1.6 });
    },
  },
  {
    name: 'Stone keep',
    // A low wooden keep on a plinth of stone blocks, crowned with a stone battlement, behind a low
    // earth rampart (1.2 m high, 4.2 m in front): a flat throw skims over it into the keep, a lob
    // drops onto it; the second level asks for a little more than the first, not for one power in
    // twenty at each angle (as a rampart 2 m high 3 m in front would). A lookout 4 m behind the keep
    // makes three stars a matter of aim (the keep alone: 32 of the 33 single throws over the --grid
    // that cleared it earned three stars; with the lookout 8 of 31).
    shots: 3,
    build: (b) => {
      const x = 12.5 + b.rng.range(-0.5, 0.5);
      hill(b, x - 5.4, x - 4.2, 1.2);
      const top = brickBlock(b, x, 0, 4, 1, BRICK);
      const roof = tower(b, x, top, 1, { stones: 0, blocks: 0 });
      brickBlock(b, x, roof.y, 3, 1, BRICK);
      tower(b, x + 4, 0, 1, { stones: 1, span: 1.4 });
    },
  },
  {
    name: 'Twin towers',
    // Far off (19 m), behind a rampart 1.3 m high: a long throw. A lookout stands 4.2 m behind the
    // bridged pair, out of reach of what the pair drops, so three stars take a throw at each (with
    // the pair alone, 8 of 195 single throws over the --grid earned three stars; with it, none).
    shots: 3,
    build: (b) => {
      const x0 = 19 + b.rng.range(-0.5, 0.5);
      hill(b, x0 - 4.4, x0 - 2.8, 1.3);
      const first = tower(b, x0, 0, 2, { stones: 1 });
      const second = tower(b, x0 + TOWER_PITCH, 0, 2, { stones: 1 });
      bridge(b, first, second);
      tower(b, x0 + TOWER_PITCH + 4.2, 0, 1, { stones: 1, span: 1.4 });
    },
  },
  {
    name: 'Stone bridge',
    // A wooden deck on two stone piers, glass and a stone out in the middle of its span, a lookout
    // over each pier.
    shots: 4,
    build: (b) => {
      const x = 12 + b.rng.range(-0.5, 0.5);
      const span = 5.2;
      const top = brickBlock(b, x, 0, 1, 4, BRICK);
      brickBlock(b, x + span, 0, 1, 4, BRICK);
      // The deck: one long plank on a post on each pier, welded to both.
      const deckY = top + 2 * POST.hy;
      const postL = b.box('post', x, top + POST.hy, POST.hx, POST.hy);
      const postR = b.box('post', x + span, top + POST.hy, POST.hx, POST.hy);
      const mid = x + span / 2;
      const deck = b.box('plank', mid, deckY + PLANK.hy, span / 2 + 0.9, PLANK.hy);
      b.weld(postL, deck, [x, deckY]);
      b.weld(postR, deck, [x + span, deckY]);
      const on = deckY + 2 * PLANK.hy;
      b.box('block', mid - 0.7, on + 0.3, 0.3, 0.3);
      b.box('block', mid + 0.7, on + 0.3, 0.3, 0.3);
      b.stone(mid, on + 0.35, 0.35, 3);
      tower(b, x, on, 1, { stones: 1, span: 1.4, on: deck });
      tower(b, x + span, on, 1, { stones: 1, span: 1.4, on: deck });
    },
  },
  {
    name: 'The pit',
    // A tower standing in a pit 1.6 m deep: its lower storeys are behind the pit's wall, so throw
    // high and drop onto it; the stone wall on the far rim holds the stones.
    shots: 4,
    build: (b) => {
      const x = 13.5 + b.rng.range(-0.5, 0.5);
      const depth = 1.6;
      pit(b, x - 2.2, x + 2.2, depth);
      tower(b, x, -depth, 3, { stones: 2, blocks: 2 });
      const wallX = x + 3.4;
      const top = brickBlock(b, wallX, 0, 2, 3, BRICK);
      b.stone(wallX, top + 0.35, 0.35, 3);
    },
  },
  {
    name: 'Hill fort',
    // A fort on a hill 2 m high: the hill's face stops a low throw; what is knocked off falls far.
    shots: 4,
    build: (b) => {
      const x = 12.5 + b.rng.range(-0.5, 0.5);
      const H = 2;
      hill(b, x - 0.6, x + 6.4, H);
      // A palisade of posts at the hill's front edge, a two-storey tower behind it and stones at the back.
      for (let k = 0; k < 3; k++) b.box('post', x + 0.2 + 0.34 * k, H + POST.hy, POST.hx, POST.hy);
      tower(b, x + 2.6, H, 2, { stones: 1, blocks: 1 });
      b.box('block', x + 4.7, H + 0.3, 0.3, 0.3);
      b.box('block', x + 4.7, H + 0.9, 0.3, 0.3);
      b.stone(x + 5.6, H + 0.35, 0.35, 3);
    },
  },
  {
    name: 'Glass house',
    // A long hall of glass panes under wooden beams, two floors, its stones on the upper floor.
    shots: 4,
    build: (b) => {
      const x0 = 12 + b.rng.range(-0.5, 0.5);
      hall(b, x0, 0, 3, 2, 'pane');
    },
  },
  {
    name: 'Three towers',
    // Wood, then glass, then wood on a stone base, joined by bridges.
    shots: 4,
    build: (b) => {
      const x0 = 11.5 + b.rng.range(-1, 1);
      const a = tower(b, x0, 0, 3, { stones: 1, blocks: 1 });
      const c = tower(b, x0 + TOWER_PITCH, 0, 3, { stones: 1, post: 'block' });
      bridge(b, a, c);
      const top = brickBlock(b, x0 + 2 * TOWER_PITCH, 0, 4, 2, BRICK);
      tower(b, x0 + 2 * TOWER_PITCH, top, 2, { stones: 1, blocks: 1 });
    },
  },
  {
    name: 'Fortress',
    // Four towers of four storeys, the outer two on stone bases, bridged; heavy stones on top. The
    // bridged pair (the keep) stands behind earth banks FORT_BANK m high, one between it and each
    // outer tower (FORT_GAP further out to make room): a tower knocked over falls on a bank, not on
    // the next tower, so no single throw brings half the fortress down (with the towers one pitch
    // apart one lob at 30 degrees and 80 % power would) and clearing it takes throws at each tower.
    shots: 5,
    build: (b) => {
      const x0 = 11 + b.rng.range(-1, 1);
      // The banks fill the room between an outer tower's stone base (BASE_HALF either side of its
      // middle) and the keep's planks (SPAN / 2 + 0.2), less 0.1 m either side.
      const BASE_HALF = 4 * BRICK.hx;
      const bank = TOWER_PITCH + FORT_GAP - BASE_HALF - (SPAN / 2 + 0.2) - 0.2;
      let last: Roof | null = null;
      for (let t = 0; t < 4; t++) {
        const cx = x0 + t * TOWER_PITCH + (t === 0 ? -FORT_GAP : t === 3 ? FORT_GAP : 0);
        if (t === 0) hill(b, cx + BASE_HALF + 0.1, cx + BASE_HALF + 0.1 + bank, FORT_BANK);
        if (t === 3) hill(b, cx - BASE_HALF - 0.1 - bank, cx - BASE_HALF - 0.1, FORT_BANK);
        const base = t === 0 || t === 3 ? brickBlock(b, cx, 0, 4, 2, BRICK) : 0;
        // The middle two (on the ground, four storeys) are bridged: one stone each, in the middle,
        // and one on the bridge (a pair's inner stone, 0.46 m in radius, would stand on the
        // bridge's end, overlapping it, and be pushed off as the level starts).
        const roof = tower(b, cx, base, base > 0 ? 3 : 4, { stones: base > 0 ? 2 : 1, blocks: 1, stoneMass: 5 });
        if (last && Math.abs(last.y - roof.y) < 1e-6) {
          const [mx, my] = bridge(b, last, roof);
          const r = 0.3 + 0.02 * b.level;
          b.stone(mx, my + r, r, 5);
        }
        last = roof;
      }
    },
  },
];

/** Number of levels. */
export const LEVEL_COUNT = LEVELS.length;

/** The name of level `level` (0-based), as the player sees it. @throws RangeError out of [0, LEVEL_COUNT). */
export function levelName(level: number): string {
  const spec = LEVELS[level];
  if (!Number.isInteger(level) || spec === undefined)
    throw new RangeError(`levelName: level must be an integer in [0, ${LEVEL_COUNT}), got ${level}`);
  return spec.name;
}

/**
 * Builds level `o.level` into an empty `world`: the ground (its slabs, and a hill or a pit where the
 * level has one), the catapult's mound, the level's castle (LEVELS: towers, a hall, a bridge, stone
 * blocks; seeded variations) and a rock past it.
 * @throws RangeError if level is not an integer in [0, LEVEL_COUNT).
 */
export function buildLevel(world: PhysicsWorld, o: LevelOptions): Level {
  if (!Number.isInteger(o.level) || o.level < 0 || o.level >= LEVEL_COUNT) {
    throw new RangeError(`buildLevel: level must be an integer in [0, ${LEVEL_COUNT}), got ${o.level}`);
  }
  const spec = LEVELS[o.level]!;
  const lv: Level = {
    name: spec.name,
    pieces: [],
    joints: [],
    jointBodies: [],
    shots: spec.shots,
    castleMinX: Infinity,
    castleMaxX: -Infinity,
    castleTop: 0,
    ground: 0,
    terrain: [],
    mound: 0,
    rock: 0,
  };
  // Round bodies slowed on the ground by `rollingResistance`: handle, radius (m) pairs.
  const rolling: number[] = [];
  thrown.set(world, rolling);
  const b: Builder = {
    world,
    lv,
    rng: new Rng(o.seed * 7919 + o.level),
    level: o.level,
    box(kind, x, y, hx, hy) {
      const m = MATERIAL[kind];
      const body = addBox(world, { position: [x, y], halfExtents: [hx, hy], density: m.density, friction: m.friction });
      return piece(body, kind, [hx, hy], x, y);
    },
    stone(x, y, r, mass) {
      const body = addBody(world, { position: [x, y], radius: r, mass, friction: 0.8, restitution: 0.1 });
      rolling.push(body, r);
      return piece(body, 'stone', [r, r], x, y);
    },
    weld(a, c, anchor) {
      lv.joints.push(addWeldJoint(world, { a, b: c, anchor, breakForce: o.jointStrength, breakTorque: o.jointStrength * 0.25 }));
      lv.jointBodies.push([a, c]);
    },
  };
  const piece = (body: number, kind: Piece['kind'], half: [number, number], x: number, y: number): number => {
    lv.pieces.push({ body, startX: x, startY: y, startAngle: 0, kind, half });
    lv.castleMinX = Math.min(lv.castleMinX, x - half[0]);
    lv.castleMaxX = Math.max(lv.castleMaxX, x + half[0]);
    lv.castleTop = Math.max(lv.castleTop, y + half[1]);
    return body;
  };
  lv.ground = terrain(b, 'ground', GROUND.minX, GROUND.maxX, -1, 0);
  // The catapult's mound (static, under the catapult): 0.3 m high, from 1.2 m behind the cup to 0.6 m past it.
  lv.mound = addBox(world, { position: [LAUNCH.x - 0.3, 0.15], halfExtents: [0.9, 0.15], static: true, friction: 0.9 });
  spec.build(b);
  addSystem(world, 'forces', rollingResistance(rolling, lv));
  lv.rock = addBox(world, {
    position: [lv.castleMaxX + ROCK.gap + ROCK.hx, surfaceAt(lv, lv.castleMaxX + ROCK.gap + ROCK.hx) + ROCK.hy],
    halfExtents: [ROCK.hx, ROCK.hy],
    static: true,
    friction: 0.9,
  });
  settleLevel(world, lv);
  return lv;
}

/**
 * Lets the castle of `lv`, just built in `world`, settle under its own weight: steps the world until
 * every piece is asleep (a castle sleeps about a second after its build) or SETTLE_TIME s have
 * passed, then takes each piece's pose as its resting one (`Piece.startX`, `startY`, `startAngle`),
 * from which `hasFallen` measures. A piece only settling is so never counted down. `buildLevel` calls it.
 */
export function settleLevel(world: PhysicsWorld, lv: Level): void {
  const steps = Math.ceil(SETTLE_TIME / world.dt);
  for (let i = 0; i < steps && !lv.pieces.every((p) => !isAlive(world, p.body) || isSleeping(world, p.body)); i++) step(world);
  const P = world.components.Position,
    A = world.components.Angle.value;
  for (const p of lv.pieces) {
    if (!isAlive(world, p.body)) continue;
    const s = slotOf(p.body);
    p.startX = P.x[s]!;
    p.startY = P.y[s]!;
    p.startAngle = A[s]!;
  }
}

/**
 * Launch velocity for a pull: the pointer dragged back from the cup by (dx, dy), m, throws the
 * other way at speed PULL.gain x |pull| (the pull capped at PULL.max). @returns [vx, vy], m/s.
 */
export function launchVelocity(dx: number, dy: number): [number, number] {
  const d = Math.hypot(dx, dy);
  if (!(d > 0)) return [0, 0];
  const k = (PULL.gain * Math.min(d, PULL.max)) / d;
  return [-dx * k, -dy * k];
}

/** The pull (dx, dy), m, that throws at `speed` (m/s, at most PULL.gain x PULL.max) and `angle` (rad above the +x axis). */
export function pullFor(speed: number, angle: number): [number, number] {
  const d = speed / PULL.gain;
  return [-d * Math.cos(angle), -d * Math.sin(angle)];
}

/**
 * Launch angle (rad, the low one, <= pi/4) that carries a drag-free projectile a horizontal `range`
 * (m) back to its launch height at `speed` (m/s) under gravity g: sin(2 theta) = g R / v^2.
 * @returns NaN if the range is out of reach (g R > v^2).
 */
export function angleForRange(range: number, speed: number, g: number): number {
  const s = (g * range) / (speed * speed);
  return s > 1 ? Number.NaN : 0.5 * Math.asin(s);
}

/**
 * The drag-free predicted path from (x0, y0) at (vx, vy) under g: `count` points [x, y] every `dt`
 * seconds (x = x0 + vx t, y = y0 + vy t - g t^2 / 2), stopping below the ground (y < 0).
 */
export function predictArc(x0: number, y0: number, vx: number, vy: number, g: number, count = 40, dt = 0.06): Array<[number, number]> {
  const out: Array<[number, number]> = [];
  for (let i = 0; i < count; i++) {
    const t = i * dt,
      y = y0 + vy * t - 0.5 * g * t * t;
    out.push([x0 + vx * t, y]);
    if (y < 0) break;
  }
  return out;
}

/**
 * Whether a stone of radius `r` (m) centred at (x, y), m, touches what stands in `world` now: the
 * ground (a hill's top, a pit's floor: `surfaceAt`), the rock past the castle, or a castle piece (a
 * box in its own turned frame, a round stone as a circle). Below the deepest surface less 5 m counts
 * as touching (the stone has left the field).
 */
function stoneTouches(world: PhysicsWorld, lv: Level, x: number, y: number, r: number): boolean {
  if (y < Math.min(0, ...lv.terrain.map((t) => t.maxY)) - 5) return true;
  // Each slab of the ground, a hill, a pit's floor: a box (a stone meets a hill's or a pit's side
  // face before it is over the box).
  for (const t of lv.terrain) {
    const ox = Math.max(0, t.minX - x, x - t.maxX),
      oy = Math.max(0, t.minY - y, y - t.maxY);
    if (ox * ox + oy * oy <= r * r) return true;
  }
  const rockX = lv.castleMaxX + ROCK.gap + ROCK.hx;
  if (lv.rock && Math.abs(x - rockX) <= ROCK.hx + r && y - r <= surfaceAt(lv, rockX) + 2 * ROCK.hy) return true;
  const P = world.components.Position,
    A = world.components.Angle.value;
  for (const p of lv.pieces) {
    if (!isAlive(world, p.body)) continue;
    const s = slotOf(p.body);
    const dx = x - P.x[s]!,
      dy = y - P.y[s]!;
    if (p.kind === 'stone') {
      if (Math.hypot(dx, dy) <= p.half[0] + r) return true;
      continue;
    }
    const c = Math.cos(A[s]!),
      sn = Math.sin(A[s]!);
    const lx = c * dx + sn * dy,
      ly = -sn * dx + c * dy;
    // The distance from the box (0 inside it) against the radius: a stone passing a corner diagonally
    // does not touch it (a square test widened by r on both axes would stop the preview short there).
    const ox = Math.max(0, Math.abs(lx) - p.half[0]),
      oy = Math.max(0, Math.abs(ly) - p.half[1]);
    if (ox * ox + oy * oy <= r * r) return true;
  }
  return false;
}

/** Step of the preview's flight (`previewFlight`), s: at most 0.25 m of flight at the fastest throw, so it does not step over a piece's corner. */
export const PREVIEW_DT = 0.01;

/**
 * The drag-free flight of a thrown stone (radius PROJECTILE_RADIUS) from LAUNCH at (vx, vy), m/s,
 * under gravity `g` (m/s^2 down, > 0), against what stands in `world` now (the level `lv` built in
 * it): x, y pairs (m) every PREVIEW_DT s, the last one the point where the stone first touches the
 * ground, the rock or a castle piece (found to within a millimetre between two steps), or where it
 * is after `maxTime` s. This is the engine's flight: a thrown stone feels only gravity until it
 * touches something (no air drag), so the game's aim preview and the stone agree (the browser and
 * headless tests compare the two). `r` is the stone's radius, m (PROJECTILE_RADIUS unless given;
 * the tests widen and narrow it to tell a grazing throw, which may or may not touch, from a clear hit).
 * @throws Error if g, maxTime or r is not a positive number.
 */
export function previewFlight(
  world: PhysicsWorld,
  lv: Level,
  vx: number,
  vy: number,
  g: number,
  maxTime = 6,
  r = PROJECTILE_RADIUS,
): number[] {
  if (!(g > 0)) throw new Error(`previewFlight: g must be > 0 m/s^2, got ${g}`);
  if (!(maxTime > 0)) throw new Error(`previewFlight: maxTime must be > 0 s, got ${maxTime}`);
  if (!(r > 0)) throw new Error(`previewFlight: r must be > 0 m, got ${r}`);
  const at = (t: number): [number, number] => [LAUNCH.x + vx * t, LAUNCH.y + vy * t - 0.5 * g * t * t];
  const out: number[] = [LAUNCH.x, LAUNCH.y];
  const steps = Math.ceil(maxTime / PREVIEW_DT);
  for (let i = 1; i <= steps; i++) {
    const [x, y] = at(i * PREVIEW_DT);
    if (!stoneTouches(world, lv, x, y, r)) {
      out.push(x, y);
      continue;
    }
    // Between the last free point and this one: halve the interval down to under a millimetre.
    let lo = (i - 1) * PREVIEW_DT,
      hi = i * PREVIEW_DT;
    const speed = Math.hypot(vx, vy) + g * hi;
    while ((hi - lo) * speed > 1e-3) {
      const mid = (lo + hi) / 2;
      const [mx, my] = at(mid);
      if (stoneTouches(world, lv, mx, my, r)) hi = mid;
      else lo = mid;
    }
    out.push(...at(hi));
    return out;
  }
  return out;
}

/**
 * The flight past the preview's end, for a faint guide (the game's aim draws it as hollow dots): the
 * drag-free path of a stone (radius PROJECTILE_RADIUS) thrown from LAUNCH at (vx, vy), m/s, under
 * gravity `g` (m/s^2 down, > 0), from time `t0` (s, >= 0; the time of the first touch) on, as if
 * nothing stood in its way but the level's ground (its slabs, a pit's floor, and the top of a hill or
 * bank the stone comes down on from above; it passes through a bank's side face and the castle):
 * x, y pairs (m) every PREVIEW_DT s, the last one where the stone's bottom comes down to that ground
 * (found to within a millimetre between two steps), past the ground's ends, or `extra` s after t0.
 * A throw blocked by a bank or a piece so shows where it was headed, and never goes into the earth
 * of a hill it falls onto; the stone itself stops or bounces at the first touch.
 * @throws Error if g or extra is not a positive number, or t0 is not a number >= 0.
 */
export function flightPast(lv: Pick<Level, 'terrain'>, vx: number, vy: number, g: number, t0: number, extra = 2): number[] {
  if (!(g > 0)) throw new Error(`flightPast: g must be > 0 m/s^2, got ${g}`);
  if (!(t0 >= 0)) throw new Error(`flightPast: t0 must be >= 0 s, got ${t0}`);
  if (!(extra > 0)) throw new Error(`flightPast: extra must be > 0 s, got ${extra}`);
  const xAt = (t: number): number => LAUNCH.x + vx * t,
    yAt = (t: number): number => LAUNCH.y + vy * t - 0.5 * g * t * t;
  // Down on the ground at time t (falling, its bottom at or under the ground below it), for a stone
  // whose bottom was at `from` (m) a step before: a hill counts only if that was over its top.
  const down = (t: number, from: number): boolean => vy - g * t < 0 && yAt(t) - PROJECTILE_RADIUS <= groundAt(lv, xAt(t), from);
  const out: number[] = [];
  const steps = Math.ceil(extra / PREVIEW_DT);
  for (let i = 0; i <= steps; i++) {
    const t = t0 + i * PREVIEW_DT;
    const x = xAt(t);
    if (x < GROUND.minX || x > GROUND.maxX) break;
    // (Once past the start, which may be on the ground already.)
    const from = yAt(t - PREVIEW_DT) - PROJECTILE_RADIUS;
    if (i > 0 && down(t, from)) {
      // Between the last point in the air and this one: halve the interval down to under a millimetre.
      let lo = t - PREVIEW_DT,
        hi = t;
      const speed = Math.hypot(vx, vy) + g * hi;
      while ((hi - lo) * speed > 1e-3) {
        const mid = (lo + hi) / 2;
        if (down(mid, from)) hi = mid;
        else lo = mid;
      }
      out.push(xAt(hi), yAt(hi));
      break;
    }
    out.push(x, yAt(t));
  }
  return out;
}

/**
 * Share of the way from the catapult (LAUNCH.x) to the castle's front (Level.castleMinX) that the
 * aim preview draws on every level after the first: the start of the flight, its angle and how it
 * begins to bend, but not where it comes down. The whole flight to its first touch made the second
 * level a throw aimed along the dots (two in three throws whose dots ended on level 2's keep
 * cleared it); the last throw's trail and its numbers still guide the next.
 */
export const SHORT_PREVIEW_SHARE = 0.4;

/**
 * The same on the first level: a little more of the rise, to learn the throw, but still not where it
 * comes down. The whole flight there drew the dots into the castle and a stranger took three stars
 * on the first two levels with three throws (issue 34: "the aim aid plays the game for you").
 */
export const FIRST_PREVIEW_SHARE = 0.5;

/**
 * Help for a player who keeps missing: from MISSES_FOR_MORE throws at a level that brought nothing
 * down (counted over its tries, since the level was entered) the preview reaches HELP_PREVIEW_SHARE
 * of the way to the castle's front (most of the fall, not the landing), and from MISSES_FOR_FULL the
 * whole flight to its first touch. A level holds 3 throws: the first try's misses bring the longer
 * arc, a failed try and one more the whole flight.
 */
export const MISSES_FOR_MORE = 2;
export const MISSES_FOR_FULL = 4;
export const HELP_PREVIEW_SHARE = 0.75;

/**
 * The share of the way from LAUNCH.x to the castle's front that the aim preview draws on level
 * `level` (0-based) after `misses` throws there that brought nothing down: FIRST_PREVIEW_SHARE on the
 * first level, SHORT_PREVIEW_SHARE on the others, HELP_PREVIEW_SHARE from MISSES_FOR_MORE misses
 * and Infinity (the whole flight) from MISSES_FOR_FULL.
 * @throws RangeError if level is not an integer in [0, LEVEL_COUNT) or misses not an integer >= 0.
 */
export function previewShare(level: number, misses = 0): number {
  if (!Number.isInteger(level) || level < 0 || level >= LEVEL_COUNT)
    throw new RangeError(`previewShare: level must be an integer in [0, ${LEVEL_COUNT}), got ${level}`);
  if (!Number.isInteger(misses) || misses < 0) throw new RangeError(`previewShare: misses must be an integer >= 0, got ${misses}`);
  if (misses >= MISSES_FOR_FULL) return Number.POSITIVE_INFINITY;
  if (misses >= MISSES_FOR_MORE) return HELP_PREVIEW_SHARE;
  return level === 0 ? FIRST_PREVIEW_SHARE : SHORT_PREVIEW_SHARE;
}

/**
 * The farthest x (m) the aim preview draws on level `level` (0-based) of `lv` after `misses` throws
 * there that brought nothing down (`previewShare`): that share of the way from LAUNCH.x to
 * `lv.castleMinX`, or Infinity (the whole flight to its first touch, previewFlight) when `full`
 * (the page's guide=full) or after MISSES_FOR_FULL misses.
 * @throws RangeError as `previewShare`.
 */
export function previewLimit(level: number, lv: Pick<Level, 'castleMinX'>, full = false, misses = 0): number {
  const share = previewShare(level, misses);
  return full ? Number.POSITIVE_INFINITY : LAUNCH.x + share * (lv.castleMinX - LAUNCH.x);
}

/**
 * `arc` (x, y pairs, m, x increasing, as previewFlight gives) cut at x = `limit` (m): the points
 * before it and one on the line between the two either side of it; `arc` itself (the same array)
 * when it ends at or before `limit`.
 */
export function cutArc(arc: number[], limit: number): number[] {
  for (let i = 2; i < arc.length; i += 2) {
    const x = arc[i]!;
    if (x <= limit) continue;
    const x0 = arc[i - 2]!,
      y0 = arc[i - 1]!;
    const k = x > x0 ? (limit - x0) / (x - x0) : 0;
    return [...arc.slice(0, i), limit, y0 + k * (arc[i + 1]! - y0)];
  }
  return arc;
}

/**
 * The height of the ground under x, m, for a stone whose bottom is at `from` (m): the top of the
 * ground's slabs or a pit's floor, and of a hill only if `from` is at or over the hill's top (less a
 * centimetre: a stone that went into a hill's side face passes through it); -Infinity off the ground.
 */
function groundAt(lv: Pick<Level, 'terrain'>, x: number, from: number): number {
  let top = Number.NEGATIVE_INFINITY;
  for (const t of lv.terrain) if (x >= t.minX && x <= t.maxX && (t.kind !== 'hill' || from >= t.maxY - 0.01)) top = Math.max(top, t.maxY);
  return top;
}

/** The round bodies of each world that the grass slows: handle, radius (m) pairs (`buildLevel` and `launch` add them). */
const thrown = new WeakMap<PhysicsWorld, number[]>();

/**
 * The round bodies the grass slows in `world` (handle, radius pairs; `launch` adds each throw): a
 * tool that restores a snapshot of the world sets its length back to what it was at the snapshot,
 * so the throws made since are not slowed twice when their handles are used again.
 * @throws Error if no level was built in `world`.
 */
export function rollingBodies(world: PhysicsWorld): number[] {
  const list = thrown.get(world);
  if (list === undefined) throw new Error('rollingBodies: no level was built in this world (buildLevel)');
  return list;
}

/**
 * A forces-stage system: each round body of `list` (handle, radius pairs: the projectiles and the
 * castle's crown stones) touching the ground (its bottom within 3 cm of the level's surface under
 * it, `surfaceAt`: the ground, a hill's top or a pit's floor) gets a force against its motion of ROLL_RESISTANCE x its weight and a torque against its
 * spin of as much at its rim, each capped so that it stops the body within the substep rather than
 * turn it back. A stone knocked off the castle so stops near it instead of rolling back to the catapult.
 */
function rollingResistance(list: number[], lv: Pick<Level, 'terrain'>): (w: PhysicsWorld) => void {
  return (w) => {
    const c = w.components,
      h = w.dt / w.substeps,
      g = Math.abs(w.gravity[1]!);
    for (let i = 0; i < list.length; i += 2) {
      const b = list[i]!,
        r = list[i + 1]!;
      if (!isAlive(w, b)) continue;
      const s = slotOf(b);
      const x = c.Position.x[s]!;
      if (c.Position.y[s]! - r - surfaceAt(lv, x) > 0.03) continue;
      const m = c.Mass.value[s]!,
        f = ROLL_RESISTANCE * m * g;
      const vx = c.Velocity.x[s]!,
        w0 = c.AngularVelocity.z[s]!;
      c.Force.x[s] = c.Force.x[s]! - Math.sign(vx) * Math.min(f, (m * Math.abs(vx)) / h);
      c.Torque.z[s] = c.Torque.z[s]! - Math.sign(w0) * Math.min(f * r, (c.Inertia.value[s]! * Math.abs(w0)) / h);
    }
  };
}

/** Adds a projectile at the cup with velocity (vx, vy), m/s, and mass (kg, > 0). @returns its handle. */
export function launch(world: PhysicsWorld, vx: number, vy: number, mass: number): number {
  const b = addBody(world, {
    position: [LAUNCH.x, LAUNCH.y],
    velocity: [vx, vy],
    radius: PROJECTILE_RADIUS,
    mass,
    friction: 0.6,
    restitution: 0.2,
  });
  thrown.get(world)?.push(b, PROJECTILE_RADIUS);
  return b;
}

/** A tally of the level: pieces fallen, joints broken (counted by `countBreaks`), score. */
export interface Tally {
  fallen: number;
  broken: number;
  score: number;
}

/**
 * Whether a piece is down, as a player sees it, measured from where it came to rest (`settleLevel`):
 * its centre dropped more than DROP_SHARE of its height (and at least DROP_MIN m), moved
 * KNOCK_DISTANCE from there, a box (not a round stone) turned past TIP_ANGLE from its resting angle,
 * off the ground's end (past its ends, or 3 m down: below every level's surface, the deepest pit's
 * floor being 1.6 m down), or removed.
 */
export function hasFallen(world: PhysicsWorld, p: Piece): boolean {
  if (!isAlive(world, p.body)) return true;
  const s = slotOf(p.body),
    P = world.components.Position;
  const x = P.x[s]!,
    y = P.y[s]!;
  const drop = Math.max(DROP_MIN, DROP_SHARE * 2 * p.half[1]);
  if (y < p.startY - drop || x < GROUND.minX || x > GROUND.maxX || y < -3) return true;
  if (Math.hypot(x - p.startX, y - p.startY) > KNOCK_DISTANCE) return true;
  if (p.kind === 'stone') return false;
  // The turn from its resting angle, wrapped into [0, pi].
  const a = Math.abs((world.components.Angle.value[s]! - p.startAngle) % (2 * Math.PI));
  return Math.min(a, 2 * Math.PI - a) > TIP_ANGLE;
}

/**
 * Whether piece `p` counts toward its level's share of pieces down (the stars and the clear): every
 * piece but one lying flat where the level's ground (a hill's top, a pit's floor) holds it at the
 * start, a box at least as wide as it is tall (a bottom row's block or plank): it can neither drop
 * nor tip, and counted it would keep three stars out of reach however the castle above it is
 * brought down. A post standing on the ground counts (it tips over).
 */
export function countsTowardStars(lv: Pick<Level, 'terrain'>, p: Piece): boolean {
  const onGround = p.startY - p.half[1] - surfaceAt(lv, p.startX) < 0.05;
  return !(onGround && p.half[0] >= p.half[1]);
}

/**
 * The pieces of `lv` that count toward its share (`countsTowardStars`): how many there are (`of`)
 * and how many of them are marked down by the last `tally` (`down`).
 */
export function countedDown(lv: Level): { down: number; of: number } {
  let down = 0,
    of = 0;
  for (const p of lv.pieces)
    if (countsTowardStars(lv, p)) {
      of++;
      if (p.down) down++;
    }
  return { down, of };
}

/**
 * The tally now. `fallen` counts the pieces that have fallen at any call so far (marked `down` on the
 * piece), so it never decreases; `broken` is the count of weld joints of the level no longer alive
 * (broken ones are removed by the solver). Score = FALL_POINTS x fallen + BREAK_POINTS x broken.
 */
export function tally(world: PhysicsWorld, lv: Level): Tally {
  let fallen = 0,
    broken = 0;
  // A piece that fell and then bounced or was knocked back up stays counted: the score never drops.
  for (const p of lv.pieces) {
    if (!p.down && hasFallen(world, p)) p.down = true;
    if (p.down) fallen++;
  }
  for (const j of lv.joints) if (!isAlive(world, j)) broken++;
  return { fallen, broken, score: fallen * FALL_POINTS + broken * BREAK_POINTS };
}
