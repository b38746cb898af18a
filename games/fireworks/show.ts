/**
 * The fireworks show, DOM-free (runs in Node for tests): scene building, launching shells, bursts
 * whose size grows with how long the button was held, secondary bursts (generations) and the
 * auto-show. The page (main.ts) adds input, the panel and the renderer.
 *
 * Physics (all SI, y up):
 * - A shell is a body (1 kg) launched from the ground and timed to burst at the target `FUSE` (1.2 s)
 *   after launch, so a tap answers quickly whatever the height. A target low enough for a drag-free
 *   parabola to peak there within FUSE (h <= g FUSE^2 / 2, 7.1 m: lower than any target) gets that parabola: v_y =
 *   sqrt(2 g h), fuse T = v_y / g, v_x = dx / T (Ramtal and Dobre ch. 4, projectiles). A higher one
 *   is launched faster and slowed by linear air drag F = -c m v (Ramtal and Dobre ch. 7), c chosen
 *   so that the apex comes at FUSE, as a real shell decelerates to its apex (`shellFlight`; c is
 *   capped at `SHELL_DRAG_MAX`, above which the shell bursts still rising). With g = 0 it flies
 *   straight to the target in FUSE. At the first step where its age reaches the fuse it bursts and
 *   is removed. An emitter attached to it sheds a glittering tail.
 * - A burst spawns `sparks x burstScale(hold)` sparks of one random colour at the shell's position,
 *   passing on its velocity. Its size follows the sky (`reach`: sky width / BURST_REFERENCE_WIDTH,
 *   so a burst covers the same fraction of a wide desktop sky as of a phone's) and the hold
 *   (`burstSize`: the cube root of burstScale, so the largest burst, with 3 times the stars, is
 *   1.44 times as wide and a little denser, and still fits the sky): for a size factor R the stars leave R times faster under 1 / R times the drag, which makes the whole
 *   drag-dominated burst R times larger (x(t) = ln(1 + k v0 t / m) m / k scales with v0 at fixed
 *   k v0). Sparks fall under gravity with quadratic drag F = -k |v| v (mass 1 g; terminal speed
 *   sqrt(m g / k), 14 m/s at the default k), and fade and shrink over their lifetime (the look over
 *   life of the physics emitters).
 * - Generations: with `generations` >= 2 every spark bursts into crackles when it dies, and with 3
 *   the crackles burst once more (the emitters' onDeath with a generation limit, Ramtal and Dobre
 *   ch. 12).
 * - Capacity: the world holds `capacity` entities (default 60,000: 50,000 live sparks with room to
 *   spare) and every emitter recycles the oldest particle when it is full, so nothing ever throws and
 *   the count never exceeds the capacity. Room for `MAX_SHELLS` shells is reserved with empty
 *   placeholder entities (a shell takes a placeholder's place when launched and gives it back when it
 *   bursts), so a full world of sparks never stops a launch and a shell in flight is never recycled.
 *
 * Everything random comes from seeded generators: the same seed and the same launches give the same show.
 */
import {
  addBody,
  addEmitter,
  createEntity,
  createPhysicsWorld,
  emitNow,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  Rng,
  removeBody,
  setGravity,
  slotOf,
  step,
} from '@bitphysics/physics';
import { GOLD, RECIPE_NAMES, RECIPES, type RecipeName, type ShellRecipe } from './recipes';

/** Width and height of the sky, m. The ground is y = 0. */
export const SKY = Object.freeze({ width: 120, height: 70 });

/** Mass of a spark, kg (1 g): the drag coefficient k is per spark of this mass. */
export const SPARK_MASS = 1e-3;

/**
 * Launch speed of the sparks of a normal-size burst (burstScale 1) in a BURST_REFERENCE_WIDTH sky,
 * m/s: uniform in [SPEED_MIN, 1] x this (x `reach` in another sky).
 */
export const BURST_SPEED = 16;

/** Slowest spark of a burst as a fraction of the fastest (a filled disc with a bright rim, like a peony shell seen from the side). */
export const SPEED_MIN = 0.3;

/** Crackles per dying spark (generation 2), and per dying crackle (generation 3). */
export const CRACKLES = Object.freeze({ first: 4, second: 3 });

/** Bursts remembered for the page's flash (show.flashes). */
export const FLASHES = 16;

/** Most shells in flight at once; further launches are refused until one bursts. */
export const MAX_SHELLS = 64;

/**
 * Most burst sparks spawned in one step. A bigger burst spawns the rest at the same point in the next
 * steps (2,000 sparks a step: a 12,000-spark burst takes 0.1 s), so a huge burst costs several
 * frames a little instead of one frame a lot (each spawn costs the physics tens of microseconds).
 */
export const BURST_SPARKS_PER_STEP = 2000;

/**
 * Time from launch to burst of a shell aimed higher than g FUSE^2 / 2 (7.1 m), s: a tap bursts this
 * long after it at every height the show aims at (targets start 12 m up). 1.2 s, so a tap answers
 * quickly (2 s feels slow); a real shell's climb is slower still, but a game's tap must answer.
 */
export const FUSE = 1.2;

/**
 * Largest linear drag rate c = k / m of a shell, 1/s: enough for a 400 m apex in FUSE at 9.81 m/s^2
 * (a 160 m sky needs 5); beyond it (a weak gravity) the shell bursts at the target still rising.
 * Kept well below the engine's stiff limit (c dt < 0.25; 0.1 at 60 steps a second) so the drag
 * stays an explicit force the launch can solve for.
 */
export const SHELL_DRAG_MAX = 6;

/**
 * Width of the sky, m, in which a burst has its nominal size (BURST_SPEED, the drag option): a
 * phone held upright, 64 m across. A sky w wide scales every burst by w / this (`FireworksShow.reach`).
 */
export const BURST_REFERENCE_WIDTH = 64;

/** How long the auto-show waits after a player's launch, s, so the player's shells are the only ones in the sky. */
export const PLAYER_PAUSE = 8;

/** Longest hold that still makes the burst bigger, s. */
export const MAX_HOLD = 1.5;

/** The burst colours, 0xRRGGBB: the spark's colour at birth; it fades towards a darker shade of it. */
export const PALETTE: readonly number[] = Object.freeze([
  0xff4d40, 0xff9f1c, 0xffe14d, 0x4cff7a, 0x4de1ff, 0x6b8cff, 0xc77dff, 0xff5cc8, 0xffffff,
]);

/** Options of the show. Every field optional. */
export interface FireworksOptions {
  /** Seed of the show (colours, auto-show, spark directions). Any finite number. Default 1. */
  seed?: number;
  /** Magnitude of gravity, m/s^2, in [0, 30] (pointing down). Default 9.81. */
  gravity?: number;
  /** Quadratic drag coefficient of a spark, kg/m, in [0, 1e-3] (for its 1 g mass). Default 5e-5. */
  drag?: number;
  /** Sparks of a normal-size burst (a click), integer in [10, 10_000]; a long hold makes up to 3 times as many. Default 300. */
  sparks?: number;
  /** Generations of sparks: 1 (sparks only), 2 (sparks burst into crackles) or 3 (crackles burst again). Default 2. */
  generations?: number;
  /** Launch shells on its own, following `PROGRAMME`. Default false. */
  autoShow?: boolean;
  /** Shells launched at once when the show starts (0 for a dark sky), integer in [0, 16]. Default 3. */
  opening?: number;
  /** Most entities alive at once, integer in [1000, 2_000_000]. Default 60_000 (50,000 live sparks). */
  capacity?: number;
  /**
   * Width and height of the sky, m, each in [30, 400]: where shells are aimed and launched from (a
   * portrait screen takes a narrower, taller sky). Default `SKY` (120 x 70).
   */
  sky?: { readonly width: number; readonly height: number };
}

/** Resolved options. */
export type FireworksParams = Required<Omit<FireworksOptions, 'sky'>> & {
  readonly sky: { readonly width: number; readonly height: number };
};

/** The emitters of the show (entity ids). */
export interface FireworksEmitters {
  /** One spark emitter per palette colour (generation 1). */
  sparks: number[];
  /** Crackles of the second generation, one per palette colour (a paler shade of it). */
  crackles: number[];
  /** Crackles of the third generation (white-gold, shared). */
  crackle2: number;
}

/** The running show: its parameters, emitters, shells in flight and auto-show clock. */
export interface FireworksShow {
  /** The parameters in use (change them with the setters below so the world follows). */
  readonly params: FireworksParams;
  readonly emitters: FireworksEmitters;
  /** Generator of launch points, colours and the auto-show (seeded from `params.seed`). */
  readonly rng: Rng;
  /** Shells in flight: entity handle (a Float64Array: handles exceed 2^31 once slots are reused often), world time of its burst (s), burst scale and colour index, entries 0..shellCount-1. */
  readonly shellIds: Float64Array;
  readonly shellBurstTime: Float64Array;
  readonly shellScale: Float64Array;
  readonly shellColor: Int32Array;
  /** Recipe of each shell in flight, an index into RECIPE_NAMES. */
  readonly shellRecipe: Int32Array;
  shellCount: number;
  /** Emitters of the recipes other than 'crackle', by `${recipe name}:${colour}` (0xRRGGBB as a number). */
  readonly recipeEmitters: Map<string, number>;
  /** Emitters of recipe stars' own bursts (onDeath), by the same keys, with the drag factor of each. */
  readonly recipeDrag: Map<number, number>;
  /** Index of the auto-show's next act in PROGRAMME. */
  act: number;
  /** Seconds until the auto-show's next launch. */
  autoTimer: number;
  /** Seconds the auto-show still waits after a player's launch (`pauseAutoShow`); 0 when not waiting. */
  autoPause: number;
  /**
   * Size factor of every burst for this sky: sky width / BURST_REFERENCE_WIDTH (1 on a phone, 1.875
   * in the 120 m desktop sky). Star speeds are multiplied and star drag divided by it.
   */
  readonly reach: number;
  /** Shells launched and burst since the start. */
  launched: number;
  bursts: number;
  /**
   * The newest bursts, for the page's flash: x, y (m), the world time of the burst (s) and its scale,
   * four numbers each, at most FLASHES of them (oldest overwritten); `flashCount` counts all ever made.
   */
  readonly flashes: Float64Array;
  flashCount: number;
  /** Placeholder entities holding room for shells not in flight (MAX_SHELLS - shellCount of them). */
  readonly placeholders: number[];
  /**
   * Bursts still spawning (see BURST_SPARKS_PER_STEP), entries 0..pendingCount-1: position (m),
   * velocity passed on (m/s), emitter, sparks left, slowest and fastest star speed (m/s), star drag (kg/m).
   */
  readonly pending: Float64Array;
  pendingCount: number;
}

/** Fields of a pending burst in `FireworksShow.pending`: x, y, vx, vy, emitter, stars left, slowest and fastest speed (m/s), drag (kg/m). */
const PEND = 9;

/**
 * One act of the auto-show: `count` shells of `recipe` (a salvo when more than one) then a pause of
 * `pause` s before the next act.
 */
export interface ShowAct {
  readonly recipe: RecipeName;
  readonly count: number;
  readonly pause: number;
}

/**
 * The auto-show's programme, played in order and then again: single shells of each kind, pairs and
 * salvos, a finale of everything. About 25 s a round. Launch points and holds are drawn from the
 * show's seeded generator.
 */
export const PROGRAMME: readonly ShowAct[] = Object.freeze(
  [
    { recipe: 'peony', count: 1, pause: 1.1 },
    { recipe: 'chrysanthemum', count: 1, pause: 1.3 },
    { recipe: 'willow', count: 2, pause: 2.2 },
    { recipe: 'ring', count: 1, pause: 1 },
    { recipe: 'crossette', count: 2, pause: 1.6 },
    { recipe: 'palm', count: 1, pause: 1.6 },
    { recipe: 'strobe', count: 1, pause: 1.4 },
    { recipe: 'crackle', count: 1, pause: 1.4 },
    { recipe: 'peony', count: 3, pause: 1.8 },
    { recipe: 'chrysanthemum', count: 2, pause: 1.6 },
    { recipe: 'ring', count: 2, pause: 1.4 },
    { recipe: 'willow', count: 3, pause: 2.6 },
    { recipe: 'crossette', count: 3, pause: 1.4 },
    { recipe: 'strobe', count: 2, pause: 1.2 },
    { recipe: 'palm', count: 3, pause: 3.5 },
  ].map((a) => Object.freeze(a as ShowAct)),
);

function check(cond: boolean, message: string): void {
  if (!cond) throw new RangeError(`fireworks: ${message}`);
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolveFireworksOptions(options: FireworksOptions = {}): FireworksParams {
  const known = ['seed', 'gravity', 'drag', 'sparks', 'generations', 'autoShow', 'opening', 'capacity', 'sky'];
  for (const k of Object.keys(options)) {
    if (!known.includes(k)) throw new TypeError(`fireworks: unknown option ${JSON.stringify(k)}; known options are ${known.join(', ')}`);
  }
  const p: FireworksParams = {
    seed: options.seed ?? 1,
    gravity: options.gravity ?? 9.81,
    drag: options.drag ?? 5e-5,
    sparks: options.sparks ?? 300,
    generations: options.generations ?? 2,
    autoShow: options.autoShow ?? false,
    opening: options.opening ?? 3,
    capacity: options.capacity ?? 60_000,
    sky: Object.freeze({ width: options.sky?.width ?? SKY.width, height: options.sky?.height ?? SKY.height }),
  };
  check(Number.isFinite(p.seed), `seed must be finite, got ${p.seed}`);
  checkGravity(p.gravity);
  checkDrag(p.drag);
  checkSparks(p.sparks);
  checkGenerations(p.generations);
  check(typeof p.autoShow === 'boolean', `autoShow must be a boolean, got ${String(p.autoShow)}`);
  check(Number.isInteger(p.opening) && p.opening >= 0 && p.opening <= 16, `opening must be an integer in [0, 16], got ${p.opening}`);
  check(
    Number.isInteger(p.capacity) && p.capacity >= 1000 && p.capacity <= 2_000_000,
    `capacity must be an integer in [1000, 2000000], got ${p.capacity}`,
  );
  for (const side of ['width', 'height'] as const) {
    const v = p.sky[side];
    check(typeof v === 'number' && v >= 30 && v <= 400, `sky.${side} must be in [30, 400] m, got ${String(v)}`);
  }
  return p;
}

function checkGravity(g: number): void {
  check(g >= 0 && g <= 30, `gravity must be in [0, 30] m/s^2, got ${g}`);
}
function checkDrag(k: number): void {
  check(k >= 0 && k <= 1e-3, `drag must be in [0, 0.001] kg/m, got ${k}`);
}
function checkSparks(n: number): void {
  check(Number.isInteger(n) && n >= 10 && n <= 10_000, `sparks must be an integer in [10, 10000], got ${n}`);
}
function checkGenerations(g: number): void {
  check(g === 1 || g === 2 || g === 3, `generations must be 1, 2 or 3, got ${g}`);
}

/** World options for the show: 2D, the capacity, gravity, seed. @throws like `resolveFireworksOptions`. */
export function fireworksWorldOptions(options: FireworksOptions = {}): PhysicsWorldOptions {
  const p = resolveFireworksOptions(options);
  return { dimensions: 2, capacity: p.capacity, gravity: [0, -p.gravity], seed: p.seed };
}

/**
 * How much bigger a burst is for a button held `holdSeconds`: 1 for a click, rising linearly to 3 at
 * `MAX_HOLD` (1.5 s) and staying there. The burst has burstScale x `sparks` sparks and is
 * `burstSize(burstScale)` times as large.
 * @throws RangeError if holdSeconds is negative or not finite.
 */
export function burstScale(holdSeconds: number): number {
  check(Number.isFinite(holdSeconds) && holdSeconds >= 0, `burstScale: holdSeconds must be a finite number >= 0, got ${holdSeconds}`);
  return 1 + 2 * Math.min(1, holdSeconds / MAX_HOLD);
}

/**
 * The size factor of a burst of scale `scale` (>= 1, from `burstScale`): scale^(1/3), 1 for a click
 * and 1.44 at the longest hold. Its stars leave this many times faster under 1 / this times the drag
 * (see the file's header). @throws RangeError unless scale is finite and >= 1.
 */
export function burstSize(scale: number): number {
  check(Number.isFinite(scale) && scale >= 1, `burstSize: scale must be a finite number >= 1, got ${scale}`);
  return Math.cbrt(scale);
}

/** Mixes two 0xRRGGBB colours per channel: a (f = 0) to b (f = 1). */
function mix(a: number, b: number, f: number): number {
  const ch = (s: number) => Math.round(((a >> s) & 255) + (((b >> s) & 255) - ((a >> s) & 255)) * f);
  return (ch(16) << 16) | (ch(8) << 8) | ch(0);
}

/** Multiplies each channel of a 0xRRGGBB colour by f in [0, 1]. */
function shade(color: number, f: number): number {
  const r = Math.round(((color >> 16) & 255) * f),
    g = Math.round(((color >> 8) & 255) * f),
    b = Math.round((color & 255) * f);
  return (r << 16) | (g << 8) | b;
}

/**
 * Builds the show's emitters into `world` (a fresh 2D world, ideally from `fireworksWorldOptions`)
 * and launches the opening salvo.
 * @throws TypeError | RangeError on bad options or a 3D world.
 */
export function buildFireworks(world: PhysicsWorld, options: FireworksOptions = {}): FireworksShow {
  const p = resolveFireworksOptions(options);
  check(world.dimensions === 2, `needs a 2D world, got dimensions ${world.dimensions}`);
  const policy = 'recycle-oldest' as const;
  // The crackles scale with the sky like the bursts they come from (see `reach`).
  const reach = p.sky.width / BURST_REFERENCE_WIDTH;
  const crackle2 = addEmitter(world, {
    speed: [1.5 * reach, 4 * reach],
    lifetime: [0.3, 0.6],
    inheritVelocity: 1,
    policy,
    particle: {
      mass: SPARK_MASS,
      quadraticDrag: p.drag / reach,
      colorStart: 0xffffff,
      colorEnd: 0xffa040,
      sizeStart: 0.8,
      sizeEnd: 0.2,
      alphaStart: 1,
      alphaEnd: 0,
    },
  });
  const crackles = PALETTE.map((color) =>
    addEmitter(world, {
      speed: [2 * reach, 5 * reach],
      lifetime: [0.35, 0.7],
      inheritVelocity: 1,
      policy,
      particle: {
        mass: SPARK_MASS,
        quadraticDrag: p.drag / reach,
        colorStart: mix(color, 0xffffff, 0.55),
        colorEnd: shade(color, 0.6),
        sizeStart: 0.9,
        sizeEnd: 0.25,
        alphaStart: 1,
        alphaEnd: 0,
      },
      onDeath: { emitter: crackle2, count: CRACKLES.second, maxGeneration: p.generations - 1 },
    }),
  );
  const sparks = PALETTE.map((color, i) =>
    addEmitter(world, {
      // Speeds and drag here are nominal: each burst sets its own (emitPending).
      speed: [SPEED_MIN * BURST_SPEED, BURST_SPEED],
      // A spherical shell seen from the side (RECIPES.crackle.sphere).
      projectSphere: true,
      lifetime: [1.4, 2.4],
      inheritVelocity: 1,
      policy,
      particle: {
        mass: SPARK_MASS,
        quadraticDrag: p.drag,
        colorStart: color,
        colorEnd: shade(color, 0.55),
        sizeStart: RECIPES.crackle.size[0],
        sizeEnd: RECIPES.crackle.size[1],
        alphaStart: 1,
        alphaEnd: 0,
      },
      onDeath: { emitter: crackles[i]!, count: CRACKLES.first, maxGeneration: p.generations - 1 },
    }),
  );
  const placeholders: number[] = [];
  for (let i = 0; i < MAX_SHELLS; i++) placeholders.push(createEntity(world));
  const show: FireworksShow = {
    params: p,
    emitters: { sparks, crackles, crackle2 },
    rng: new Rng(p.seed),
    shellIds: new Float64Array(MAX_SHELLS),
    shellBurstTime: new Float64Array(MAX_SHELLS),
    shellScale: new Float64Array(MAX_SHELLS),
    shellColor: new Int32Array(MAX_SHELLS),
    shellRecipe: new Int32Array(MAX_SHELLS),
    shellCount: 0,
    recipeEmitters: new Map(),
    recipeDrag: new Map(),
    act: 0,
    autoTimer: 0.5,
    autoPause: 0,
    reach,
    launched: 0,
    bursts: 0,
    flashes: new Float64Array(4 * FLASHES),
    flashCount: 0,
    placeholders,
    pending: new Float64Array(PEND * MAX_SHELLS),
    pendingCount: 0,
  };
  for (const name of RECIPE_NAMES) {
    if (name === 'crackle') continue;
    for (let c = 0; c < PALETTE.length; c++) recipeEmitter(world, show, RECIPES[name], c);
  }
  for (let i = 0; i < p.opening; i++) {
    const x = p.sky.width * (0.25 + 0.5 * (p.opening === 1 ? 0.5 : i / (p.opening - 1)));
    launchShell(world, show, x, show.rng.range(0.55, 0.8) * p.sky.height, show.rng.range(0, MAX_HOLD));
  }
  return show;
}

/**
 * Creates a world and builds the show in it: `{ world, show }`.
 * @throws like `buildFireworks`.
 */
export function createFireworks(options: FireworksOptions = {}): { world: PhysicsWorld; show: FireworksShow } {
  const world = createPhysicsWorld(fireworksWorldOptions(options));
  return { world, show: buildFireworks(world, options) };
}

/**
 * Launches a shell from the ground towards (targetX, targetY), m, where it bursts FUSE (1.2 s) later
 * at the apex of its flight, or sooner for a low target (see `shellFlight`). The target is clamped
 * into the show's sky, `params.sky`: x in [4, width - 4], y in [12, height - 3]. The launch point is
 * on the ground between the middle of the sky and the target, jittered. The burst's size follows
 * `burstScale(holdSeconds)`; its colour is drawn from the palette; what it does is `recipe`
 * (./recipes.ts; default 'crackle', the book's stars that burst into stars).
 * @returns the shell's entity id, or 0 if `MAX_SHELLS` shells are already in flight.
 * @throws RangeError on non-finite coordinates, a negative hold or an unknown recipe.
 */
export function launchShell(
  world: PhysicsWorld,
  show: FireworksShow,
  targetX: number,
  targetY: number,
  holdSeconds = 0,
  recipe: RecipeName = 'crackle',
): number {
  check(Number.isFinite(targetX) && Number.isFinite(targetY), `launchShell: target must be finite, got (${targetX}, ${targetY})`);
  const recipeIndex = RECIPE_NAMES.indexOf(recipe);
  check(recipeIndex >= 0, `launchShell: recipe must be one of ${RECIPE_NAMES.join(', ')}, got ${String(recipe)}`);
  const scale = burstScale(holdSeconds);
  if (show.shellCount >= MAX_SHELLS) return 0;
  const rng = show.rng;
  const sky = show.params.sky;
  const tx = Math.min(sky.width - 4, Math.max(4, targetX));
  const ty = Math.min(sky.height - 3, Math.max(12, targetY));
  const x0 = Math.min(sky.width - 2, Math.max(2, 0.5 * sky.width + 0.5 * (tx - 0.5 * sky.width) + rng.range(-4, 4)));
  const y0 = 0.5;
  const flight = shellFlight(-world.gravity[1]!, ty - y0, world.dt / world.substeps);
  const vx = (tx - x0) * flight.perMetreX,
    vy = flight.vy;
  const color = rng.int(0, PALETTE.length - 1);
  // Take a placeholder's room (so a world full of sparks still has room for the shell).
  removeBody(world, show.placeholders.pop()!);
  const id = addBody(world, {
    position: [x0, y0],
    velocity: [vx, vy],
    mass: 1,
    ...(flight.drag > 0 ? { linearDrag: flight.drag } : {}),
  });
  addEmitter(world, {
    attachTo: id,
    rate: 90,
    speed: [0.3, 2],
    lifetime: [0.4, 0.9],
    inheritVelocity: 0.15,
    policy: 'recycle-oldest',
    particle: {
      mass: SPARK_MASS,
      quadraticDrag: show.params.drag,
      colorStart: 0xffd890,
      colorEnd: 0xff5a10,
      sizeStart: 0.8,
      sizeEnd: 0.2,
      alphaStart: 1,
      alphaEnd: 0,
    },
  });
  const i = show.shellCount++;
  show.shellIds[i] = id;
  show.shellBurstTime[i] = world.time + flight.fuse;
  show.shellScale[i] = scale;
  show.shellColor[i] = color;
  show.shellRecipe[i] = recipeIndex;
  show.launched++;
  return id;
}

/** How a shell flies to a target: see `shellFlight`. */
export interface ShellFlight {
  /** Time from launch to burst, s. */
  fuse: number;
  /** Vertical launch speed, m/s. */
  vy: number;
  /** Horizontal launch speed per metre of horizontal distance to the target, 1/s. */
  perMetreX: number;
  /** Linear drag coefficient of the 1 kg shell, N s/m (= its decay rate c, 1/s); 0 for none. */
  drag: number;
}

/**
 * The flight of a shell climbing `height` m (> 0) under gravity `g` m/s^2 in steps of `h` s: it
 * reaches the height after `fuse` s, at its apex when it can.
 *
 * - g = 0: a straight line in FUSE, no drag.
 * - height <= g FUSE^2 / 2: the drag-free parabola peaking there, fuse sqrt(2 height / g) (the
 *   integrator follows a drag-free body's parabola exactly).
 * - higher: linear drag c (F = -c m v) and a launch speed that make the apex come after N = FUSE / h
 *   steps at the height. It is solved on the integrator's own recursion (semi-implicit Euler with
 *   the drag as a force, v' = (1 - c h) v - g h, y' = y + h v'), whose closed form with r = 1 - c h
 *   is v_N = r^N (v0 + g / c) - g / c and y_N = v0 A - (g / c)(N h - A), A = r (1 - r^N) / c: so the
 *   burst lands on the target to rounding, not to the time step's error. v_N = 0 gives v0; the
 *   apex height grows with c, found by bisection. If even SHELL_DRAG_MAX does not reach the height,
 *   the shell keeps that drag and is launched to reach it after N steps still rising.
 *   The horizontal motion has the same decay and no gravity: x_N = vx0 A.
 * @throws RangeError unless g >= 0, height > 0 and h > 0 are finite.
 */
export function shellFlight(g: number, height: number, h: number): ShellFlight {
  check(Number.isFinite(g) && g >= 0, `shellFlight: g must be finite and >= 0, got ${g}`);
  check(Number.isFinite(height) && height > 0, `shellFlight: height must be finite and > 0, got ${height}`);
  check(Number.isFinite(h) && h > 0, `shellFlight: h must be finite and > 0, got ${h}`);
  if (g <= 1e-6) return { fuse: FUSE, vy: height / FUSE, perMetreX: 1 / FUSE, drag: 0 };
  if (height <= 0.5 * g * FUSE * FUSE) {
    const vy = Math.sqrt(2 * g * height);
    return { fuse: vy / g, vy, perMetreX: g / vy, drag: 0 };
  }
  const n = Math.max(1, Math.round(FUSE / h));
  // A(c), the distance per m/s of launch speed after n steps, and the apex height for drag c.
  const perSpeed = (c: number): number => ((1 - c * h) * (1 - (1 - c * h) ** n)) / c;
  const apexHeight = (c: number): number => {
    const a = perSpeed(c);
    return (g / c) * ((1 - c * h) ** -n - 1) * a - (g / c) * (n * h - a);
  };
  let c = SHELL_DRAG_MAX;
  if (apexHeight(SHELL_DRAG_MAX) > height) {
    let lo = 1e-3,
      hi = SHELL_DRAG_MAX;
    for (let i = 0; i < 60; i++) {
      const mid = 0.5 * (lo + hi);
      if (apexHeight(mid) < height) lo = mid;
      else hi = mid;
    }
    c = 0.5 * (lo + hi);
  }
  const a = perSpeed(c);
  return { fuse: n * h, vy: (height + (g / c) * (n * h - a)) / a, perMetreX: 1 / a, drag: c };
}

/** Removes shell entry i (swap with the last). */
function dropShell(show: FireworksShow, i: number): void {
  const last = --show.shellCount;
  show.shellIds[i] = show.shellIds[last]!;
  show.shellBurstTime[i] = show.shellBurstTime[last]!;
  show.shellScale[i] = show.shellScale[last]!;
  show.shellColor[i] = show.shellColor[last]!;
  show.shellRecipe[i] = show.shellRecipe[last]!;
}

/** The colour a star burst of `burst` takes for a shell of palette colour `color`. */
function burstColor(burst: 'same' | 'white' | 'gold', color: number): number {
  return burst === 'same' ? mix(color, 0xffffff, 0.3) : burst === 'white' ? 0xffffff : GOLD;
}

/**
 * The emitter of `recipe`'s stars in palette colour `colorIndex` (or the recipe's own colour), with
 * its chain of onDeath emitters (innermost first: a star's burst is an emitter of the physics package
 * too; their speeds and drag follow the show's `reach`). `buildFireworks` makes them all up front,
 * so a full world never refuses one; later calls return the same emitter.
 * @throws RangeError (from addEmitter) if called for a new one in a full world.
 */
export function recipeEmitter(world: PhysicsWorld, show: FireworksShow, recipe: ShellRecipe, colorIndex: number): number {
  const base = recipe.color ?? PALETTE[colorIndex]!;
  const key = `${recipe.name}:${base}`;
  const known = show.recipeEmitters.get(key);
  if (known !== undefined) return known;
  const policy = 'recycle-oldest' as const;
  const drag = show.params.drag;
  const reach = show.reach;
  let onDeath: { emitter: number; count: number; maxGeneration: number } | undefined;
  const b = recipe.onDeath;
  if (b) {
    const levels = b.generations === 'show' ? 1 : b.generations;
    const c = burstColor(b.color, base);
    let inner: number | null = null;
    for (let level = levels; level >= 1; level--) {
      const em: number = addEmitter(world, {
        speed: [b.speed[0] * reach, b.speed[1] * reach],
        lifetime: [b.lifetime[0], b.lifetime[1]],
        inheritVelocity: 1,
        policy,
        particle: {
          mass: SPARK_MASS,
          quadraticDrag: (drag * recipe.drag) / reach,
          colorStart: c,
          colorEnd: shade(c, 0.6),
          sizeStart: b.size,
          sizeEnd: b.size * 0.3,
          alphaStart: 1,
          alphaEnd: 0,
        },
        ...(inner !== null ? { onDeath: { emitter: inner, count: b.count, maxGeneration: 16 } } : {}),
      });
      show.recipeDrag.set(em, recipe.drag / reach);
      inner = em;
    }
    onDeath = { emitter: inner!, count: b.count, maxGeneration: 16 };
  }
  // Speeds and drag of the burst's own stars are nominal: each burst sets its own (emitPending).
  const em = addEmitter(world, {
    speed: [recipe.speed[0] * BURST_SPEED, recipe.speed[1] * BURST_SPEED],
    projectSphere: recipe.sphere,
    lifetime: [recipe.lifetime[0], recipe.lifetime[1]],
    inheritVelocity: 1,
    policy,
    particle: {
      mass: SPARK_MASS,
      quadraticDrag: drag * recipe.drag,
      colorStart: base,
      colorEnd: recipe.fade === 'gold' ? shade(GOLD, 0.7) : shade(base, 0.55),
      sizeStart: recipe.size[0],
      sizeEnd: recipe.size[1],
      alphaStart: 1,
      alphaEnd: 0,
    },
    ...(onDeath ? { onDeath } : {}),
  });
  show.recipeDrag.set(em, recipe.drag);
  show.recipeEmitters.set(key, em);
  return em;
}

const burstPos = [0, 0],
  burstVel = [0, 0];

/**
 * Bursts every shell whose fuse has burnt: `sparks x scale` sparks of its colour at its position,
 * passing on its velocity, launched at R = reach x burstSize(scale) times the normal speeds under 1 / R
 * times the drag (a burst R times larger, see the file's header); the shell is removed and its
 * room given back to a placeholder. At most BURST_SPARKS_PER_STEP sparks are spawned a step; the
 * rest of a big burst follows in the next steps. Called by `stepFireworks` after each step.
 */
export function burstShells(world: PhysicsWorld, show: FireworksShow): void {
  const c = world.components;
  const now = world.time + 1e-9;
  const Q = show.pending;
  for (let i = show.shellCount - 1; i >= 0; i--) {
    const e = show.shellIds[i]!;
    if (now < show.shellBurstTime[i]!) continue;
    const scale = show.shellScale[i]!;
    if (show.pendingCount < MAX_SHELLS) {
      const o = PEND * show.pendingCount++;
      const recipe: ShellRecipe = RECIPES[RECIPE_NAMES[show.shellRecipe[i]!]!];
      const colorIndex = show.shellColor[i]!;
      const crackle = recipe.name === 'crackle';
      const s = show.reach * burstSize(scale);
      Q[o] = c.Position.x[slotOf(e)]!;
      Q[o + 1] = c.Position.y[slotOf(e)]!;
      Q[o + 2] = c.Velocity.x[slotOf(e)]!;
      Q[o + 3] = c.Velocity.y[slotOf(e)]!;
      Q[o + 4] = crackle ? show.emitters.sparks[colorIndex]! : recipeEmitter(world, show, recipe, colorIndex);
      Q[o + 5] = Math.max(1, Math.round(show.params.sparks * scale * recipe.stars));
      Q[o + 6] = (crackle ? SPEED_MIN : recipe.speed[0]) * BURST_SPEED * s;
      Q[o + 7] = (crackle ? 1 : recipe.speed[1]) * BURST_SPEED * s;
      Q[o + 8] = (show.params.drag * (crackle ? 1 : recipe.drag)) / s;
    }
    const f = 4 * (show.flashCount++ % FLASHES);
    show.flashes[f] = c.Position.x[slotOf(e)]!;
    show.flashes[f + 1] = c.Position.y[slotOf(e)]!;
    show.flashes[f + 2] = world.time;
    show.flashes[f + 3] = scale;
    removeBody(world, e);
    dropShell(show, i);
    show.placeholders.push(createEntity(world));
    show.bursts++;
  }
  emitPending(world, show);
}

/** Spawns up to BURST_SPARKS_PER_STEP sparks of the pending bursts, oldest first. */
function emitPending(world: PhysicsWorld, show: FireworksShow): void {
  const E = world.components.Emitter;
  const Q = show.pending;
  let budget = BURST_SPARKS_PER_STEP;
  while (show.pendingCount > 0 && budget > 0) {
    const em = Q[4]!;
    const n = Math.min(Q[5]!, budget);
    E.speedMin[slotOf(em)] = Q[6]!;
    E.speedMax[slotOf(em)] = Q[7]!;
    // This burst's drag for its stars only: the emitter keeps the show's nominal drag.
    const nominal = E.quadraticDrag[slotOf(em)]!;
    E.quadraticDrag[slotOf(em)] = Q[8]!;
    burstPos[0] = Q[0]!;
    burstPos[1] = Q[1]!;
    burstVel[0] = Q[2]!;
    burstVel[1] = Q[3]!;
    emitNow(world, em, n, burstPos, burstVel);
    E.quadraticDrag[slotOf(em)] = nominal;
    budget -= n;
    Q[5] = Q[5]! - n;
    if (Q[5] === 0) {
      // Drop the head entry (at most MAX_SHELLS entries of PEND numbers: a short copy).
      Q.copyWithin(0, PEND, PEND * show.pendingCount);
      show.pendingCount--;
    }
  }
}

/**
 * The auto-show: plays `PROGRAMME` act by act (a salvo spreads its shells across the sky), then
 * again; launch points and holds come from the show's generator. It waits while `autoPause` runs
 * down (after a player's launch), its own clock stopped. Called by `stepFireworks` before each step
 * while `params.autoShow` is on.
 */
export function autoShow(world: PhysicsWorld, show: FireworksShow): void {
  if (show.autoPause > 0) {
    show.autoPause = Math.max(0, show.autoPause - world.dt);
    return;
  }
  show.autoTimer -= world.dt;
  if (show.autoTimer > 0) return;
  const rng = show.rng;
  const act = PROGRAMME[show.act % PROGRAMME.length]!;
  show.act++;
  for (let k = 0; k < act.count; k++) {
    const lane = act.count === 1 ? rng.range(0.2, 0.8) : ((k + 0.5) / act.count) * 0.76 + 0.12 + rng.range(-0.04, 0.04);
    const sky = show.params.sky;
    launchShell(world, show, lane * sky.width, rng.range(0.5, 0.88) * sky.height, rng.range(0, MAX_HOLD), act.recipe);
  }
  show.autoTimer = act.pause;
}

/** One step of the show: the auto-show (if on), the physics step, then the shells' bursts. @throws what `step` throws. */
export function stepFireworks(world: PhysicsWorld, show: FireworksShow): void {
  if (show.params.autoShow) autoShow(world, show);
  step(world);
  burstShells(world, show);
}

/** Sets gravity, m/s^2 in [0, 30] (down). @throws RangeError out of range. */
export function setShowGravity(world: PhysicsWorld, show: FireworksShow, g: number): void {
  checkGravity(g);
  show.params.gravity = g;
  setGravity(world, [0, -g]);
}

/**
 * Sets the sparks' quadratic drag coefficient, kg/m in [0, 1e-3] (nominal: stars get it divided by
 * their burst's size factor, see `burstShells`): for sparks, crackles and tails born from now on.
 * @throws RangeError out of range.
 */
export function setShowDrag(world: PhysicsWorld, show: FireworksShow, k: number): void {
  checkDrag(k);
  show.params.drag = k;
  const E = world.components.Emitter;
  for (const em of show.emitters.sparks) E.quadraticDrag[slotOf(em)] = k;
  for (const em of [...show.emitters.crackles, show.emitters.crackle2]) E.quadraticDrag[slotOf(em)] = k / show.reach;
  for (const [em, factor] of show.recipeDrag) E.quadraticDrag[slotOf(em)] = k * factor;
  // The shells' tails (emitters attached to the shells).
  for (let i = 0; i < show.shellCount; i++) E.quadraticDrag[slotOf(show.shellIds[i]!)] = k;
}

/** Sets the sparks of a normal-size burst, integer in [10, 10_000]. @throws RangeError out of range. */
export function setShowSparks(show: FireworksShow, n: number): void {
  checkSparks(n);
  show.params.sparks = n;
}

/**
 * Sets the generations (1, 2 or 3): the limit the spark and crackle emitters burst up to on death.
 * @throws RangeError unless 1, 2 or 3.
 */
export function setShowGenerations(world: PhysicsWorld, show: FireworksShow, g: number): void {
  checkGenerations(g);
  show.params.generations = g;
  const E = world.components.Emitter;
  for (const em of [...show.emitters.sparks, ...show.emitters.crackles]) E.maxGeneration[slotOf(em)] = g - 1;
}

/** Turns the auto-show on or off (its clock restarts at 0.3 s and a player's pause is cleared: asked for, it starts now). */
export function setAutoShow(show: FireworksShow, on: boolean): void {
  show.params.autoShow = on;
  show.autoTimer = 0.3;
  show.autoPause = 0;
}

/**
 * Holds the auto-show for `seconds` (default PLAYER_PAUSE, 8 s) from now, so a player's shells are
 * the only new ones in the sky; it then resumes where it was, if it is on. Call it on each launch a
 * player makes. @throws RangeError unless seconds is finite and >= 0.
 */
export function pauseAutoShow(show: FireworksShow, seconds = PLAYER_PAUSE): void {
  check(Number.isFinite(seconds) && seconds >= 0, `pauseAutoShow: seconds must be finite and >= 0, got ${seconds}`);
  show.autoPause = seconds;
}
