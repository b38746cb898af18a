/**
 * Catapult, the rules (no DOM, no pixi; they run in Node and in tests): seeded castle levels of
 * posts, planks and round stones glued by breakable weld joints, the launch from a pull, the
 * drag-free predicted arc, and the score.
 *
 * Units: metres, seconds, kilograms. The ground's top is y = 0 from x = GROUND.minX to GROUND.maxX;
 * the catapult throws from LAUNCH. Score: FALL_POINTS for every castle piece that fell (its centre
 * more than FALL_DROP below where it started, or off the ground's end) and BREAK_POINTS for every
 * weld joint that broke.
 */
import {
  addBody,
  addBox,
  addSystem,
  addWeldJoint,
  isAlive,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  Rng,
  slotOf,
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
/** Drop (m) below its start past which a castle piece counts as fallen. */
export const FALL_DROP = 0.6;
/** Points for a fallen piece and for a broken joint. */
export const FALL_POINTS = 100;
export const BREAK_POINTS = 25;
/** Number of levels. */
export const LEVEL_COUNT = 5;

/**
 * Each level's castle: towers side by side, storeys in each, where the first tower stands (m, give
 * or take 1 m from the seed) and the shots the player has. Each level asks a little more than the
 * one before. The castle stands 11 to 12 m out, so the catapult and the castle share the screen at a
 * scale where a piece reads (a 1.2 m post about 55 px tall on a 1060 px wide view).
 */
const LEVEL_TOWERS = [1, 2, 2, 3, 4],
  LEVEL_STOREYS = [3, 2, 3, 3, 4],
  LEVEL_X0 = [12, 12, 12, 11.5, 11],
  LEVEL_SHOTS = [3, 3, 3, 4, 5];

/** Options of a level. */
export interface LevelOptions {
  /** Level index, integer in [0, LEVEL_COUNT). */
  level: number;
  /** Seed of the castle's variations. */
  seed: number;
  /** Gravity, m/s^2 downwards, > 0. */
  gravity: number;
  /** Force past which a weld joint breaks, N, > 0 (torque limit: this x 0.25 m). */
  jointStrength: number;
}

/** One castle piece: its body and where it started. */
export interface Piece {
  body: number;
  startX: number;
  startY: number;
  kind: 'post' | 'plank' | 'block' | 'stone';
  /** Half width and half height of a box, m; a stone's radius twice. */
  half: [number, number];
  /** Whether the piece has counted as fallen: once it has, it stays fallen (set by `tally`). */
  down?: boolean;
}

/** What a level holds. */
export interface Level {
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
  /** The ground's and the catapult mound's handles (0 before a level is built). */
  ground: number;
  mound: number;
  /**
   * A static rock past the castle (its handle, 0 before a level is built) that stops debris sliding
   * out of the view; its right face is at `castleMaxX + ROCK.gap + 2 ROCK.hx`.
   */
  rock: number;
}

/** The rock behind the castle: its gap from the castle's right end, half width and half height, m. */
export const ROCK = { gap: 1.9, hx: 0.5, hy: 1.4 } as const;

/** The world options: 2D, 4 contact substeps, room for the castle and shots. */
export function worldOptions(o: { gravity: number }): PhysicsWorldOptions {
  return { dimensions: 2, capacity: 1000, gravity: [0, -o.gravity], sleep: false };
}

/**
 * Builds level `o.level` into an empty `world`: the ground and a castle of seeded towers.
 * Level 0: one tower of three storeys; 1: two towers of two storeys joined by a bridge plank; 2: two
 * towers of three storeys, two stones on each; 3: three towers; 4: a fortress of four towers of four
 * storeys, heavier stones.
 * @throws RangeError if level is not an integer in [0, LEVEL_COUNT).
 */
export function buildLevel(world: PhysicsWorld, o: LevelOptions): Level {
  if (!Number.isInteger(o.level) || o.level < 0 || o.level >= LEVEL_COUNT) {
    throw new RangeError(`buildLevel: level must be an integer in [0, ${LEVEL_COUNT}), got ${o.level}`);
  }
  const ground = addBox(world, {
    position: [(GROUND.minX + GROUND.maxX) / 2, -0.5],
    halfExtents: [(GROUND.maxX - GROUND.minX) / 2, 0.5],
    static: true,
    friction: 0.9,
  });
  // The catapult's mound (static, under the catapult): 0.3 m high, from 1.2 m behind the cup to 0.6 m past it.
  const mound = addBox(world, { position: [LAUNCH.x - 0.3, 0.15], halfExtents: [0.9, 0.15], static: true, friction: 0.9 });
  const rng = new Rng(o.seed * 7919 + o.level);
  const lv: Level = {
    pieces: [],
    joints: [],
    jointBodies: [],
    shots: LEVEL_SHOTS[o.level]!,
    castleMinX: Infinity,
    castleMaxX: -Infinity,
    castleTop: 0,
    ground,
    mound,
    rock: 0,
  };
  const towers = LEVEL_TOWERS[o.level]!,
    storeys = LEVEL_STOREYS[o.level]!;
  const x0 = LEVEL_X0[o.level]! + rng.range(-1, 1);
  const span = 2.4; // width of a storey: two posts under a plank
  const weld = (a: number, b: number, anchor: [number, number]): void => {
    lv.joints.push(addWeldJoint(world, { a, b, anchor, breakForce: o.jointStrength, breakTorque: o.jointStrength * 0.25 }));
    lv.jointBodies.push([a, b]);
  };
  const piece = (body: number, kind: Piece['kind'], half: [number, number]): number => {
    const P = world.components.Position,
      s = slotOf(body);
    lv.pieces.push({ body, startX: P.x[s]!, startY: P.y[s]!, kind, half });
    return body;
  };
  // Round bodies slowed on the grass by `rollingResistance`: handle, radius (m) pairs.
  const rolling: number[] = [];
  thrown.set(world, rolling);
  const POST = { hx: 0.15, hy: 0.6 },
    PLANK = { hx: span / 2 + 0.2, hy: 0.12 };
  for (let t = 0; t < towers; t++) {
    const cx = x0 + t * (span + 1.2);
    let y = 0,
      below: number[] = [];
    for (let s = 0; s < storeys; s++) {
      const base = y;
      const posts: number[] = [];
      for (const side of [-1, 1]) {
        const px = cx + side * (span / 2 - POST.hx);
        const post = piece(
          addBox(world, { position: [px, y + POST.hy], halfExtents: [POST.hx, POST.hy], density: 2, friction: 0.7 }),
          'post',
          [POST.hx, POST.hy],
        );
        posts.push(post);
        // Glue the post to the plank under it.
        if (below.length) weld(below[0]!, post, [px, y]);
      }
      y += 2 * POST.hy;
      const plank = piece(
        addBox(world, { position: [cx, y + PLANK.hy], halfExtents: [PLANK.hx, PLANK.hy], density: 2, friction: 0.7 }),
        'plank',
        [PLANK.hx, PLANK.hy],
      );
      for (const post of posts) weld(post, plank, [world.components.Position.x[slotOf(post)]!, y]);
      y += 2 * PLANK.hy;
      below = [plank];
      // A block in the middle of some storeys, from the seed.
      if (s > 0 && rng.next() < 0.5)
        piece(addBox(world, { position: [cx, base + 0.31], halfExtents: [0.3, 0.3], density: 1.5, friction: 0.7 }), 'block', [0.3, 0.3]);
    }
    // Crown: a stone (or two) on the top plank.
    const stones = o.level >= 2 ? 2 : 1;
    for (let k = 0; k < stones; k++) {
      const r = 0.3 + 0.04 * o.level;
      const stone = piece(
        addBody(world, {
          position: [cx + (stones === 1 ? 0 : (k - 0.5) * 1.1), y + r + 0.01],
          radius: r,
          mass: 2 + o.level,
          friction: 0.8,
          restitution: 0.1,
        }),
        'stone',
        [r, r],
      );
      rolling.push(stone, r);
    }
    lv.castleMinX = Math.min(lv.castleMinX, cx - span / 2 - 0.2);
    lv.castleMaxX = Math.max(lv.castleMaxX, cx + span / 2 + 0.2);
    lv.castleTop = Math.max(lv.castleTop, y + 0.6);
    // A bridge plank between neighbouring towers' roofs, welded to both.
    if (t > 0) {
      const prevRoof = lv.pieces.filter((p) => p.kind === 'plank' && Math.abs(p.startY - (y - PLANK.hy)) < 1e-6);
      const a = prevRoof[prevRoof.length - 2],
        b = prevRoof[prevRoof.length - 1];
      if (a && b) {
        const mid = (a.startX + b.startX) / 2;
        const bridge = piece(
          addBox(world, { position: [mid, y + 0.12], halfExtents: [0.75, 0.12], density: 2, friction: 0.7 }),
          'plank',
          [0.75, 0.12],
        );
        weld(a.body, bridge, [mid - 0.6, y]);
        weld(b.body, bridge, [mid + 0.6, y]);
      }
    }
  }
  addSystem(world, 'forces', rollingResistance(rolling));
  lv.rock = addBox(world, {
    position: [lv.castleMaxX + ROCK.gap + ROCK.hx, ROCK.hy],
    halfExtents: [ROCK.hx, ROCK.hy],
    static: true,
    friction: 0.9,
  });
  return lv;
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

/** The round bodies of each world that the grass slows: handle, radius (m) pairs (`buildLevel` and `launch` add them). */
const thrown = new WeakMap<PhysicsWorld, number[]>();

/**
 * A forces-stage system: each round body of `list` (handle, radius pairs: the projectiles and the
 * castle's crown stones) touching the ground (its bottom within 3 cm of y = 0, on the ground's
 * length) gets a force against its motion of ROLL_RESISTANCE x its weight and a torque against its
 * spin of as much at its rim, each capped so that it stops the body within the substep rather than
 * turn it back. A stone knocked off the castle so stops near it instead of rolling back to the catapult.
 */
function rollingResistance(list: number[]): (w: PhysicsWorld) => void {
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
      if (c.Position.y[s]! - r > 0.03 || x < GROUND.minX || x > GROUND.maxX) continue;
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

/** Whether a piece has fallen: dropped FALL_DROP below its start, off the ground's end, or removed. */
export function hasFallen(world: PhysicsWorld, p: Piece): boolean {
  if (!isAlive(world, p.body)) return true;
  const s = slotOf(p.body),
    P = world.components.Position;
  const x = P.x[s]!,
    y = P.y[s]!;
  return y < p.startY - FALL_DROP || x < GROUND.minX || x > GROUND.maxX || y < -1;
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
