/**
 * Shell recipes: what a firework shell does when it bursts, as data the show (./show.ts) turns into
 * emitters of the physics package (`addEmitter` for the stars, its `onDeath` for stars that burst
 * again) and one `emitNow` burst. Each recipe is a small object you can copy and change:
 *
 *     const myShell: ShellRecipe = { ...RECIPES.peony, name: 'slow peony', speed: [0.2, 0.6] };
 *
 * Speeds are fractions of the burst speed (./show.ts `BURST_SPEED`, 16 m/s for a normal burst),
 * star counts fractions of the show's `sparks` option, lifetimes in seconds, drag a factor on the
 * show's quadratic drag (heavier drag: the stars slow sooner and droop, as willow stars do). The
 * names are the pyrotechnic ones; what they look like in the sky:
 *
 * - peony: a sphere of coloured stars that fade, seen from the side (a disc brightest at its rim:
 *   `sphere`);
 * - chrysanthemum: the same with longer-lived stars whose fading tails turn gold (its "petals");
 * - willow: slow, long-burning gold stars under heavy drag that droop like branches;
 * - palm: a few big, fast comets, each shedding glitter as it dies;
 * - crossette: a few stars that each split into four after half a second;
 * - ring: every star at the same speed in the sky's plane, so the burst is a flat ring;
 * - strobe: short white flashes that flash again where they die, for a while (a chain of onDeath);
 * - crackle: the book's rule (Ramtal and Dobre ch. 12): every star bursts into smaller stars when it
 *   dies, up to the show's `generations`.
 */

/** Stars a dying star bursts into (the emitter's `onDeath`). */
export interface StarBurst {
  /** Stars per dying star, integer >= 1. */
  count: number;
  /** Their launch speed range, m/s (absolute, not a fraction). */
  speed: readonly [number, number];
  /** Their lifetime range, s. */
  lifetime: readonly [number, number];
  /** Their colour: the shell's, white, or gold. */
  color: 'same' | 'white' | 'gold';
  /** Their size at birth, m (drawn size). */
  size: number;
  /** Generations of bursts after the first, integer >= 1 ('crackle' follows the show's setting instead). */
  generations: number | 'show';
}

/** One kind of shell. */
export interface ShellRecipe {
  /** Name shown in the panel. */
  readonly name: string;
  /** Stars of a normal burst as a fraction of the show's `sparks`, in (0, 2]. */
  readonly stars: number;
  /** Launch speed range as fractions of the burst speed; min = max makes a ring (unless `sphere`). */
  readonly speed: readonly [number, number];
  /**
   * Whether the stars leave as a spherical shell seen from the side (addEmitter's projectSphere):
   * only the part of each star's speed across the line of sight shows, so a burst fills a disc that
   * is brightest at its rim, as a real shell looks; false keeps a flat ring. (Crackle's stars come
   * from the show's spark emitters, which are spheres: its flag says so, the show does not read it.)
   */
  readonly sphere: boolean;
  /** Star lifetime range, s. */
  readonly lifetime: readonly [number, number];
  /** Factor on the show's quadratic drag, >= 0. */
  readonly drag: number;
  /** Star size at birth and at death, m. */
  readonly size: readonly [number, number];
  /** Colour the stars fade towards: a darker shade of theirs, or gold. */
  readonly fade: 'shade' | 'gold';
  /** Fixed star colour (0xRRGGBB) instead of the shell's palette colour, or null. */
  readonly color: number | null;
  /** What a dying star bursts into, or null. */
  readonly onDeath: StarBurst | null;
}

/** Gold of willows, palms and glitter, 0xRRGGBB. */
export const GOLD = 0xffc25a;

/** The recipes, by name. */
export const RECIPES = Object.freeze({
  peony: {
    name: 'peony',
    stars: 1,
    speed: [0.8, 1],
    sphere: true,
    lifetime: [1.4, 2.2],
    drag: 1,
    size: [1.1, 0.4],
    fade: 'shade',
    color: null,
    onDeath: null,
  },
  chrysanthemum: {
    name: 'chrysanthemum',
    stars: 1.2,
    speed: [0.7, 0.85],
    sphere: true,
    lifetime: [2.2, 3],
    drag: 1.2,
    size: [1, 0.35],
    fade: 'gold',
    color: null,
    onDeath: { count: 1, speed: [0, 1], lifetime: [0.3, 0.6], color: 'gold', size: 0.5, generations: 1 },
  },
  willow: {
    name: 'willow',
    stars: 1.1,
    speed: [0.75, 0.9],
    sphere: true,
    lifetime: [3.5, 5],
    drag: 4,
    size: [1.2, 0.45],
    fade: 'gold',
    color: GOLD,
    onDeath: null,
  },
  palm: {
    name: 'palm',
    stars: 0.15,
    speed: [0.58, 0.7],
    sphere: true,
    lifetime: [1.4, 1.9],
    drag: 0.6,
    size: [2.4, 0.9],
    fade: 'gold',
    color: null,
    onDeath: { count: 6, speed: [1, 3], lifetime: [0.4, 0.9], color: 'gold', size: 0.6, generations: 1 },
  },
  crossette: {
    name: 'crossette',
    stars: 0.35,
    speed: [0.7, 0.85],
    sphere: true,
    lifetime: [0.6, 0.8],
    drag: 0.5,
    size: [1.6, 1.2],
    fade: 'shade',
    color: null,
    onDeath: { count: 4, speed: [6, 8], lifetime: [0.9, 1.3], color: 'same', size: 1.2, generations: 1 },
  },
  ring: {
    name: 'ring',
    stars: 1,
    speed: [1, 1],
    sphere: false,
    lifetime: [1.5, 1.9],
    drag: 1,
    size: [1.1, 0.45],
    fade: 'shade',
    color: null,
    onDeath: null,
  },
  strobe: {
    name: 'strobe',
    stars: 1.2,
    speed: [0.6, 0.85],
    sphere: true,
    lifetime: [0.15, 0.3],
    drag: 2,
    size: [1.1, 0.2],
    fade: 'shade',
    color: 0xffffff,
    onDeath: { count: 1, speed: [0, 0.4], lifetime: [0.15, 0.35], color: 'white', size: 1.1, generations: 5 },
  },
  crackle: {
    name: 'crackle',
    stars: 1,
    speed: [0.3, 1],
    sphere: true,
    lifetime: [1.4, 2.4],
    drag: 1,
    size: [1.1, 0.4],
    fade: 'shade',
    color: null,
    onDeath: { count: 4, speed: [2, 5], lifetime: [0.35, 0.7], color: 'same', size: 0.9, generations: 'show' },
  },
} satisfies Record<string, ShellRecipe>);

/** A recipe's name. */
export type RecipeName = keyof typeof RECIPES;

/** Every recipe name, in the panel's order. */
export const RECIPE_NAMES = Object.freeze(Object.keys(RECIPES) as RecipeName[]);
