/**
 * The balloon and parachute lab's two scenes (Ramtal and Dobre ch. 7: upthrust, drag, terminal
 * velocity, wind). Pure, deterministic builders (no DOM, no pixi), shared by the page and the tests.
 *
 * Parachute: a parachutist of mass m jumps from rest and falls with quadratic drag F = -k |v - u| (v - u)
 * against the wind u (setWind: mean wind plus optional Kraichnan turbulence). Opening the chute raises
 * k from k_closed to k_open over the opening time (a game rule: the QuadraticDrag coefficient is
 * ramped each step). Terminal speeds sqrt(m g / k) before and after. The air is taken at sea-level
 * density throughout (k constant), as the book does.
 *
 * Balloon: a helium balloon rises in an atmosphere whose density falls with height,
 * rho(y) = rho0 exp(-y / H) (isothermal atmosphere, scale height H; scaled down from Earth's 8.4 km so
 * the flight fits a lab). The physically right composition is buoyancy, not a negative gravity scale:
 * the upthrust is the weight of the air the balloon displaces (Archimedes), so it depends on the air's
 * density where the balloon is, and the balloon stops rising where its mean density equals the air's.
 * A gravity scale of -s would give a constant upward force at every height: the balloon would rise
 * forever (and its inertia, the air's effect on it and the way lift depends on the envelope volume
 * would all be wrong). The atmosphere is a stack of FluidRegions (each "below y = surface", so the
 * densities add up): layer k adds rho(mid_k) - rho(mid_{k+1}), which makes the total density in layer
 * k equal rho at its middle; a balloon straddling layers is buoyed by each in proportion to the area
 * inside it. Air drag on the balloon is the QuadraticDrag law against the wind (so the balloon drifts
 * with it); the Buoyancy drag coefficient is left 0 because it would be counted once per layer.
 * An optional tether is a one-sided spring (a rope) to a ground anchor.
 *
 * 2D world: a disc is a cylinder 1 m deep seen end on, so its "volume" is pi r^2 x 1 m and areal
 * densities (kg/m^2) read as kg/m^3.
 */
import {
  addBody,
  addFluidRegion,
  addSpring,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  removeBody,
  setBoundary,
  setBuoyancy,
  setWind,
  slotOf,
} from '@bitphysics/physics';

/** The two scenes. */
export type SceneName = 'parachute' | 'balloon';
/** Scene names, in menu order. */
export const SCENES: readonly SceneName[] = ['parachute', 'balloon'];

/** Standard gravity, m/s^2. */
export const G = 9.81;
/** Sea-level air density, kg/m^3 (ISA). */
export const RHO_AIR = 1.225;
/** Helium density at sea level, kg/m^3 (0 C, 1 atm: 0.1786). */
export const RHO_HELIUM = 0.1786;

/** Options of both scenes; each scene reads its own. Every field optional. */
export interface BalloonParachuteOptions {
  /** Parachutist (with gear) mass, kg, in [30, 200]. Default 85. */
  jumperMass?: number;
  /** Jump altitude, m, in [100, 5000]. Default 1200. */
  jumpAltitude?: number;
  /** Drag coefficient k = rho C_d A / 2 with the chute closed (belly to earth), kg/m, in [0.01, 5]. Default 0.27. */
  kClosed?: number;
  /** Drag coefficient with the chute open, kg/m, in [1, 200]. Default 30. */
  kOpen?: number;
  /** Mean wind along x, m/s, in [-30, 30]. Default 0 (still air, where the exact fall applies). */
  wind?: number;
  /** Turbulence: RMS gust speed per component, m/s, in [0, 10]. Default 0. */
  turbulence?: number;
  /** Balloon radius, m, in [0.3, 3]. Default 1. */
  balloonRadius?: number;
  /** Envelope and payload mass (without the helium), kg, in [0.01, 50]. Default 1.2. */
  envelopeMass?: number;
  /** Atmosphere scale height H, m, in [20, 1000]. Default 120. */
  scaleHeight?: number;
  /** Balloon tethered to the ground. Default false. */
  tethered?: boolean;
  /** Tether length, m, in [2, 500]. Default 25. */
  tetherLength?: number;
}

/** Resolved options. */
export type BalloonParachuteParams = Required<BalloonParachuteOptions>;

const RANGES: Record<Exclude<keyof BalloonParachuteOptions, 'tethered'>, [number, number, number]> = {
  jumperMass: [30, 200, 85],
  jumpAltitude: [100, 5000, 1200],
  kClosed: [0.01, 5, 0.27],
  kOpen: [1, 200, 30],
  wind: [-30, 30, 0],
  turbulence: [0, 10, 0],
  balloonRadius: [0.3, 3, 1],
  envelopeMass: [0.01, 50, 1.2],
  scaleHeight: [20, 1000, 120],
  tetherLength: [2, 500, 25],
};

/** The accepted range [min, max] of a numeric option (for panels and URL parameters). */
export function rangeOf(name: keyof typeof RANGES): [number, number] {
  const r = RANGES[name];
  return [r[0], r[1]];
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option or a non-boolean `tethered`; RangeError naming the option and value when out of range.
 */
export function resolveOptions(options: BalloonParachuteOptions = {}): BalloonParachuteParams {
  const known = [...Object.keys(RANGES), 'tethered'];
  for (const k of Object.keys(options)) {
    if (!known.includes(k)) throw new TypeError(`lab-balloon-parachute: unknown option ${JSON.stringify(k)}; known: ${known.join(', ')}`);
  }
  const out: Record<string, number | boolean> = {};
  for (const [k, [lo, hi, d]] of Object.entries(RANGES)) {
    const v = (options as Record<string, unknown>)[k] ?? d;
    if (!(typeof v === 'number' && v >= lo && v <= hi))
      throw new RangeError(`lab-balloon-parachute: ${k} must be in [${lo}, ${hi}], got ${String(v)}`);
    out[k] = v;
  }
  const tethered = options.tethered ?? false;
  if (typeof tethered !== 'boolean') throw new TypeError(`lab-balloon-parachute: tethered must be a boolean, got ${String(tethered)}`);
  out.tethered = tethered;
  return out as unknown as BalloonParachuteParams;
}

/**
 * Height of the top of the atmosphere in the balloon scene, m: 3 scale heights (the highest
 * equilibrium the option ranges allow is below 2 H; above the top there is no air).
 */
export function atmosphereTop(scaleHeight: number): number {
  return 3 * scaleHeight;
}

/** World options: 2D, gravity (0, -9.81), room for the atmosphere's layers in the balloon scene. */
export function worldOptions(scene: SceneName, options: BalloonParachuteOptions = {}): PhysicsWorldOptions {
  const p = resolveOptions(options);
  const capacity = scene === 'balloon' ? layerCount(p.scaleHeight, p.balloonRadius) + 16 : 16;
  return { dimensions: 2, capacity, gravity: [0, -G] };
}

/** Most layers of the staircase atmosphere. */
const MAX_LAYERS = 600;

/**
 * Layer thickness of the staircase atmosphere, m: half the balloon's radius (so the balloon always
 * straddles several layers and its upthrust changes smoothly with height), at most H / 20, and no
 * thinner than the top / MAX_LAYERS.
 */
function layerThickness(scaleHeight: number, radius: number): number {
  return Math.max(Math.min(scaleHeight / 20, radius / 2), atmosphereTop(scaleHeight) / MAX_LAYERS);
}

function layerCount(scaleHeight: number, radius: number): number {
  return Math.ceil(atmosphereTop(scaleHeight) / layerThickness(scaleHeight, radius));
}

/** What the parachute scene's builder returns. */
export interface ParachuteHandles {
  readonly scene: 'parachute';
  /** The parachutist (a ball of radius 0.4 m for landing). */
  jumper: number;
  /** Simulated time the chute was pulled, s (NaN while closed). */
  openedAt: number;
  params: BalloonParachuteParams;
}

/** What the balloon scene's builder returns. */
export interface BalloonHandles {
  readonly scene: 'balloon';
  /** The balloon. */
  balloon: number;
  /** The tether spring entity, or 0 when free. */
  tether: number;
  /** Ground anchor of the tether, m. */
  anchor: [number, number];
  /** The FluidRegion entities of the atmosphere, bottom first. */
  layers: number[];
  params: BalloonParachuteParams;
}

/** Either scene's handles. */
export type Handles = ParachuteHandles | BalloonHandles;

/** Radius of the parachutist's collider, m. */
export const JUMPER_RADIUS = 0.4;

/** Applies the mean wind and turbulence of `p` to the world (setWind replaces the whole field). */
export function applyWind(world: PhysicsWorld, p: BalloonParachuteParams): void {
  setWind(world, {
    velocity: [p.wind, 0],
    ...(p.turbulence > 0 ? { turbulence: { intensity: p.turbulence, lengthScale: 40, timeScale: 4, seed: 7, modes: 16 } } : {}),
  });
}

/**
 * Builds the parachute scene: the ground (the boundary's floor), the parachutist at rest at the jump
 * altitude with the chute closed, and the wind. @throws TypeError | RangeError on bad options.
 */
export function buildParachute(world: PhysicsWorld, options: BalloonParachuteOptions = {}): ParachuteHandles {
  const p = resolveOptions(options);
  setBoundary(world, { min: [-10_000, 0], max: [10_000, 6000], restitution: 0, friction: 0.8 });
  const jumper = addBody(world, {
    position: [0, p.jumpAltitude],
    radius: JUMPER_RADIUS,
    mass: p.jumperMass,
    quadraticDrag: p.kClosed,
    rotates: false,
    friction: 0.8,
  });
  applyWind(world, p);
  return { scene: 'parachute', jumper, openedAt: Number.NaN, params: p };
}

/** Sea-level-referenced air density of the balloon scene at height y, kg/m^3: rho0 exp(-y / H). */
export function airDensity(y: number, scaleHeight: number): number {
  return RHO_AIR * Math.exp(-y / scaleHeight);
}

/** Mass of the balloon, kg: the helium in pi r^2 (x 1 m) plus the envelope and payload. */
export function balloonMass(p: BalloonParachuteParams): number {
  return RHO_HELIUM * Math.PI * p.balloonRadius ** 2 + p.envelopeMass;
}

/** Quadratic drag coefficient of the balloon in sea-level air, kg/m: rho0 C_d (2 r x 1 m) / 2, C_d = 0.47 (sphere). */
export function balloonDrag(p: BalloonParachuteParams): number {
  return 0.5 * RHO_AIR * 0.47 * 2 * p.balloonRadius;
}

/**
 * Builds the balloon scene: ground, the staircase atmosphere up to `atmosphereTop`, the balloon at rest
 * on its launch point just above the ground, the wind, and the tether if asked for.
 * @throws TypeError | RangeError on bad options.
 */
export function buildBalloon(world: PhysicsWorld, options: BalloonParachuteOptions = {}): BalloonHandles {
  const p = resolveOptions(options);
  const H = p.scaleHeight,
    r = p.balloonRadius;
  const top = atmosphereTop(H);
  setBoundary(world, { min: [-20_000, 0], max: [20_000, top + 10 * r], restitution: 0.2, friction: 0.5 });
  const dz = layerThickness(H, r);
  const n = layerCount(H, r);
  const layers: number[] = [];
  for (let k = 0; k < n; k++) {
    // Layer k spans [k dz, (k + 1) dz]; the regions' densities add up to rho at the layer's middle.
    const here = airDensity((k + 0.5) * dz, H);
    const above = k + 1 < n ? airDensity((k + 1.5) * dz, H) : 0;
    layers.push(addFluidRegion(world, { surface: (k + 1) * dz, density: here - above }));
  }
  const balloon = addBody(world, {
    position: [0, r + 0.05],
    radius: r,
    mass: balloonMass(p),
    quadraticDrag: balloonDrag(p),
    rotates: false,
    restitution: 0.2,
  });
  setBuoyancy(world, balloon, { shape: 'ball', radius: r, dragCoefficient: 0 });
  applyWind(world, p);
  const h: BalloonHandles = { scene: 'balloon', balloon, tether: 0, anchor: [0, 0], layers, params: p };
  if (p.tethered) setTether(world, h, true);
  return h;
}

/**
 * Ties the balloon to the ground anchor below where it was launched with a rope of `params.tetherLength`
 * (a one-sided spring, stiff and damped) or cuts it.
 */
export function setTether(world: PhysicsWorld, h: BalloonHandles, on: boolean): void {
  h.params.tethered = on;
  if (!on) {
    if (h.tether !== 0) removeBody(world, h.tether);
    h.tether = 0;
    return;
  }
  if (h.tether !== 0) return;
  const m = world.components.Mass.value[slotOf(h.balloon)]!;
  // Rope: natural frequency about 3 Hz for the balloon's mass, critically damped along the rope.
  const w = 2 * Math.PI * 3;
  h.tether = addSpring(world, {
    anchor: h.anchor,
    b: h.balloon,
    stiffness: m * w * w,
    damping: 2 * m * w,
    restLength: h.params.tetherLength,
    oneSided: true,
  });
}

/**
 * Pulls the ripcord at the current time (no-op if already open). @returns whether it opened now.
 */
export function openChute(world: PhysicsWorld, h: ParachuteHandles): boolean {
  if (!Number.isNaN(h.openedAt)) return false;
  h.openedAt = world.time;
  return true;
}

/**
 * The game rule of the chute: sets the jumper's QuadraticDrag coefficient for the coming step, rising
 * linearly from k_closed to k_open over `openingTime` s after the ripcord is pulled (0: at once).
 * Also pulls the ripcord when the jumper passes below `autoOpenAltitude` m (an automatic activation
 * device; 0 turns it off).
 */
export function updateChute(world: PhysicsWorld, h: ParachuteHandles, openingTime: number, autoOpenAltitude: number): void {
  const e = h.jumper;
  if (Number.isNaN(h.openedAt) && autoOpenAltitude > 0 && world.components.Position.y[slotOf(e)]! < autoOpenAltitude) openChute(world, h);
  const p = h.params;
  let k = p.kClosed;
  if (!Number.isNaN(h.openedAt)) {
    const f = openingTime > 0 ? Math.min(1, (world.time - h.openedAt) / openingTime) : 1;
    k = p.kClosed + (p.kOpen - p.kClosed) * f;
  }
  world.components.QuadraticDrag.k[slotOf(e)] = k;
}

/**
 * Terminal speed of a body of mass m under gravity g with quadratic drag k in still air, m/s:
 * v_t = sqrt(m g / k) (drag balances weight). Source: Ramtal and Dobre ch. 7, "terminal velocity".
 */
export function terminalSpeed(mass: number, k: number, g = G): number {
  return Math.sqrt((mass * g) / k);
}

/**
 * Exact speed of a fall from rest with quadratic drag in still air, m/s: v(t) = v_t tanh(g t / v_t).
 * Source: Taylor, Classical Mechanics (2005), eq. 2.57.
 */
export function fallSpeedFromRest(t: number, vt: number, g = G): number {
  return vt * Math.tanh((g * t) / vt);
}

/** 2 I_1(a) / a, the mean of exp(-eta / H) over a disc of radius r with a = r / H (power series; a <= 3 here). */
function discMeanOfExp(a: number): number {
  let term = 1,
    sum = 1;
  const q = (a * a) / 4;
  for (let k = 1; k < 40; k++) {
    term *= q / (k * (k + 1));
    sum += term;
    if (term < 1e-17 * sum) break;
  }
  return sum;
}

/**
 * Exact equilibrium height of the balloon's centre, m, in the exponential atmosphere: where the
 * upthrust g rho0 e^(-y/H) pi r^2 <e^(-eta/H)> equals the weight m g, i.e.
 * y* = H ln(rho0 pi r^2 <e^(-eta/H)> / m), with <e^(-eta/H)> = 2 I_1(r/H) / (r/H) the mean of the
 * density profile over the disc (Abramowitz and Stegun 9.6.10 for I_1). NaN if it cannot lift off.
 * Source: Ramtal and Dobre ch. 7 (upthrust); the isothermal atmosphere, e.g. Wallace and Hobbs,
 * Atmospheric Science, eq. 3.30.
 */
export function equilibriumAltitude(p: BalloonParachuteParams): number {
  const r = p.balloonRadius,
    H = p.scaleHeight;
  const lift = RHO_AIR * Math.PI * r * r * discMeanOfExp(r / H);
  const m = balloonMass(p);
  if (!(lift > m * Math.exp(r / H))) return Number.NaN; // not even the bottom layer can float it off the ground
  return H * Math.log(lift / m);
}
