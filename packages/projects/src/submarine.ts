import {
  addBody,
  addFluidRegion,
  addSystem,
  inertiaOfRectangle,
  type PhysicsWorld,
  Rng,
  type SceneDefinition,
  setAngularDamping,
  setBallast,
  setBodyThrust,
  setBuoyancy,
  setInertia,
  slotOf,
} from '@bitphysics/physics';
import { assertFinite, assertInteger, assertKnownKeys } from '@bitphysics/physics/validate';

/**
 * The book's submarine (Ramtal and Dobre ch. 16) grown up, in SI units, 2D (x along the sea, y up,
 * the water's surface at y = 0): a 12 m x 3 m hull of 3 m beam, so the water is 2D with the density
 * of sea water times the beam (1025 kg/m^3 x 3 m). Its buoyancy is Archimedes' (the `Buoyancy` law
 * on a box), its drag quadratic and scaled by the submerged fraction, two ballast tanks flood and
 * blow (the `Ballast` law: mass, trim), a screw pushes along the hull (`BodyThrust`), two vertical
 * thrusters fore and aft push across it (`setSubmarineThrusters`), and the hull turns with angular
 * damping. A seeded seabed and beacons to collect make it a game.
 */
export const SUBMARINE = Object.freeze({
  /** Hull length and height, m. */
  length: 12,
  height: 3,
  /** Hull beam (width across), m: the 2D water density is the sea's times this. */
  beam: 3,
  /** Sea water, kg/m^3. */
  seaWaterDensity: 1025,
  /** Mass with empty tanks, kg. */
  dryMass: 80_000,
  /** Water each of the two tanks holds, kg. */
  tankCapacity: 20_000,
  /**
   * Tank fill rate, fraction per second: 1 s from empty to full, flooding or blowing. The tanks are
   * open to the sea at the bottom and vented at the top, so flooding is as fast as the air leaves:
   * through a vent of area A it escapes at v = sqrt(2 dp / rho_air) (Bernoulli) with dp = rho g h
   * the head of water over the tank's air, Q = C_d A v. With h = 1.5 m (dp = 15 kPa, v = 158 m/s),
   * C_d = 0.6 and A = 0.2 m^2 (one 50 cm vent a tank) Q = 19 m^3/s: a 19.5 m^3 tank (20 t of sea
   * water) in about 1 s. Blowing at 150 m (16 bar, air of 19.4 kg/m^3) needs 19.5 m^3/s of air,
   * 380 kg/s, which a 200 bar bank passes through 80 cm^2 of pipe at choked flow
   * (m' = 0.0404 A p0 / sqrt(T0), Anderson, Modern Compressible Flow, ch. 5). Real boats are slower (a WWII fleet boat got under in
   * 30 to 60 s) because their tanks hold hundreds of tonnes and their vents are sized for that.
   */
  fillRate: 1,
  /** Distance of each tank from the centre along the hull, m. */
  tankArm: 4,
  /** Height of the centre of buoyancy above the centre of mass, m. */
  metacentricHeight: 1.5,
  /**
   * Quadratic drag coefficient of the fully submerged hull, kg/m: F = k v^2 (k = 1/2 rho C_d A with
   * A = 9 m^2 across the hull and C_d = 0.52, a blunt hull with its fin and planes). The water slows
   * the boat quickly when the screw stops: from 12.9 m/s to half that in m / (k v) = 3.6 s.
   */
  dragCoefficient: 2400,
  /**
   * Largest screw thrust, N: against the drag k v^2 of the submerged hull it drives the boat at up to
   * sqrt(F / k) = 12.9 m/s (25 knots), about 5.2 MW of thrust power.
   */
  maxThrust: 400_000,
  /** Rotational damping of the hull in water, N m s. */
  angularDamping: 1.5e6,
  /**
   * Largest push of each of the two vertical thrusters, N (up or down, across the hull). A ducted
   * thruster of diameter D (m) and power P (kW) gives T (kN) = (D P)^(2/3) at zero speed (Wartsila,
   * Encyclopedia of Ship Technology, "bollard pull"): 300 kN is a 2 m thruster of 2.6 MW (half the
   * screw's power), enough to take the 110 t boat from a hover to 5 m/s in about a second. Nordenfelt
   * dived his boats of 1885-7 with such vertical "sinking screws" (BR 3043, The Development of HM
   * Submarines, ch. 18); small submersibles hover and change depth with them today.
   */
  thrusterForce: 300_000,
  /** Distance of each vertical thruster from the centre along the hull, m (fore at +, aft at -). */
  thrusterArm: 4.5,
});

/** Sea water per unit depth of the 2D world, kg/m^2. */
export const SUBMARINE_WATER_DENSITY = SUBMARINE.seaWaterDensity * SUBMARINE.beam;

/**
 * The tank fill (both tanks alike) at which the fully submerged hull is neutrally buoyant, by
 * Archimedes: dryMass + 2 capacity f = rho V, f = (rho L H - dryMass) / (2 capacity) (0.7675).
 */
export const SUBMARINE_NEUTRAL_FILL =
  (SUBMARINE_WATER_DENSITY * SUBMARINE.length * SUBMARINE.height - SUBMARINE.dryMass) / (2 * SUBMARINE.tankCapacity);

/** Options of the `submarine` scene. */
export interface SubmarineOptions {
  /** Beacons to collect, integer in [0, 64]. Default 6. */
  count?: number;
  /** Seed of the seabed and beacons; any finite number. Default 1. */
  seed?: number;
  /** Initial tank fill (both tanks), in [0, 1]. Default 0 (floating on the surface). */
  fill?: number;
  /** Initial centre of the hull, m (x, y). Default floating at x = 0. */
  position?: readonly [number, number];
}

/** What `submarine.build` returns. */
export interface SubmarineHandles {
  /** The hull (entity). */
  readonly hull: number;
  /** The sea (FluidRegion entity; its `surface` is y of the water line, m). */
  readonly sea: number;
  /** The seabed: heights y (m, negative) every `dx` m from x = `x0`. */
  readonly seabed: { readonly x0: number; readonly dx: number; readonly y: Float64Array };
  /** Beacons to collect: (x, y) pairs, m. */
  readonly beacons: Float64Array;
  /**
   * Push of the vertical thrusters now, N: [fore, aft], each across the hull (along its own y axis,
   * positive up when level) at +-`SUBMARINE.thrusterArm`. Set it with `setSubmarineThrusters`.
   */
  readonly thrusters: Float64Array;
}

/**
 * Sets the push of the submarine's vertical thrusters, N: `fore` and `aft` each in
 * [-SUBMARINE.thrusterForce, SUBMARINE.thrusterForce], positive up across the hull. Equal pushes
 * heave the hull; unequal ones also pitch it (torque arm (fore - aft)).
 * @throws RangeError on a value that is not finite or is past the thrusters' limit.
 */
export function setSubmarineThrusters(handles: SubmarineHandles, fore: number, aft: number): void {
  const where = 'setSubmarineThrusters';
  const T = SUBMARINE.thrusterForce;
  assertFinite(where, 'fore', fore);
  assertFinite(where, 'aft', aft);
  if (Math.abs(fore) > T || Math.abs(aft) > T)
    throw new RangeError(`${where}: fore and aft must be within +-${T} N, got ${fore} and ${aft}`);
  handles.thrusters[0] = fore;
  handles.thrusters[1] = aft;
}

/**
 * The force law of the vertical thrusters of `hull` (a 2D body with an angle): each pushes along the
 * hull's own y axis, n = (-sin(theta), cos(theta)), at its point +-arm along the hull, so the hull
 * gets F = (fore + aft) n and the torque tau = arm (fore - aft) (r x n with r = +-arm (cos, sin)).
 * Position-only: it reads the angle, so every integrator stage sees the thrust of its own state.
 */
function thrusterLaw(hull: number, thrusters: Float64Array): (world: PhysicsWorld) => void {
  const law = (world: PhysicsWorld): void => {
    const fore = thrusters[0]!,
      aft = thrusters[1]!;
    if (fore === 0 && aft === 0) return;
    const c = world.components,
      e = slotOf(hull);
    const a = c.Angle.value[e]!,
      f = fore + aft;
    c.Force.x[e] = c.Force.x[e]! - f * Math.sin(a);
    c.Force.y[e] = c.Force.y[e]! + f * Math.cos(a);
    c.Torque.z[e] = c.Torque.z[e]! + SUBMARINE.thrusterArm * (fore - aft);
  };
  return law;
}

/** Seabed height at x, m, by linear interpolation of `seabed` (clamped at its ends). */
export function seabedHeight(seabed: SubmarineHandles['seabed'], x: number): number {
  const t = (x - seabed.x0) / seabed.dx;
  const n = seabed.y.length;
  if (t <= 0) return seabed.y[0]!;
  if (t >= n - 1) return seabed.y[n - 1]!;
  const i = Math.floor(t),
    f = t - i;
  return seabed.y[i]! * (1 - f) + seabed.y[i + 1]! * f;
}

/**
 * `submarine`: the hull floating at x = 0 (or where asked), the sea (y < 0), a seeded seabed from
 * x = -100 to 1,100 m between 40 and 150 m deep, and `count` beacons between it and the surface
 * (the first 55 to 75 m ahead and 15 to 28 m down, the others from x = 100 to 1,000 m).
 */
export const submarine: SceneDefinition<SubmarineOptions, SubmarineHandles> = {
  name: 'submarine',
  description: 'A submarine with buoyancy, ballast tanks, thrust and drag in a sea with a seabed and beacons (SI, 2D)',
  defaultCount: 6,
  worldOptions() {
    return { dimensions: 2, capacity: 16, gravity: [0, -9.81], dt: 1 / 60, sleep: false };
  },
  build(world: PhysicsWorld, options: SubmarineOptions = {}) {
    const where = 'submarine.build';
    assertKnownKeys(where, options, ['count', 'seed', 'fill', 'position']);
    if (world.dimensions !== 2) throw new RangeError(`${where}: needs a 2D world, got dimensions ${world.dimensions}`);
    const count = options.count ?? 6;
    assertInteger(where, 'count', count, 0, 64);
    const seed = options.seed ?? 1;
    assertFinite(where, 'seed', seed);
    const fill = options.fill ?? 0;
    assertFinite(where, 'fill', fill);
    if (fill < 0 || fill > 1) throw new RangeError(`${where}: fill must be in [0, 1], got ${fill}`);
    const S = SUBMARINE;
    const mass = S.dryMass + 2 * S.tankCapacity * fill;
    // Floating draft d from rho L d = m (a box), capped at the hull's height.
    const draft = Math.min(S.height, mass / (SUBMARINE_WATER_DENSITY * S.length));
    const position = options.position ?? [0, S.height / 2 - draft];
    if (!Array.isArray(position) || position.length !== 2)
      throw new TypeError(`${where}: position must be [x, y], got ${String(position)}`);
    assertFinite(where, 'position[0]', position[0]);
    assertFinite(where, 'position[1]', position[1]);
    if (world.capacity - world.entityIndex.aliveCount < 2) throw new RangeError(`${where}: the world needs room for 2 more entities`);

    const sea = addFluidRegion(world, { surface: 0, density: SUBMARINE_WATER_DENSITY });
    const hull = addBody(world, { position: [position[0], position[1]], mass });
    setInertia(world, hull, inertiaOfRectangle(mass, S.length, S.height));
    setBuoyancy(world, hull, { shape: 'box', halfExtents: [S.length / 2, S.height / 2], dragCoefficient: S.dragCoefficient });
    setBallast(world, hull, {
      dryMass: S.dryMass,
      capacity: S.tankCapacity,
      fill,
      rate: S.fillRate,
      arm: S.tankArm,
      metacentricHeight: S.metacentricHeight,
    });
    setBodyThrust(world, hull, [0, 0]);
    setAngularDamping(world, hull, S.angularDamping);
    const thrusters = new Float64Array(2);
    addSystem(world, 'forces', thrusterLaw(hull, thrusters));

    const rng = new Rng(seed);
    const x0 = -100,
      dx = 5,
      n = 241;
    const y = new Float64Array(n);
    // Seabed: a mean depth of 90 m with three seeded sine ridges and a little roughness, in [-150, -40].
    const waves = [0, 1, 2].map((k) => ({ a: rng.range(8, 22) / (k + 1), l: rng.range(120, 320) / (k + 1), p: rng.range(0, 2 * Math.PI) }));
    for (let i = 0; i < n; i++) {
      const x = x0 + i * dx;
      let h = -90;
      for (const w of waves) h += w.a * Math.sin((2 * Math.PI * x) / w.l + w.p);
      h += rng.range(-1.5, 1.5);
      y[i] = Math.max(-150, Math.min(-40, h));
    }
    const seabed = { x0, dx, y };
    // The first beacon close and shallow (55 to 75 m ahead, 15 to 28 m down: in view from the
    // start, an easy first catch); the others spread over x = 100 to 1,000 m, each between 8 m
    // over the seabed and 10 m under the surface.
    const beacons = new Float64Array(2 * count);
    for (let i = 0; i < count; i++) {
      const bx = i === 0 ? rng.range(55, 75) : 100 + (i - 1 + rng.range(0.1, 0.9)) * (900 / Math.max(1, count - 1));
      const floor = seabedHeight(seabed, bx);
      beacons[2 * i] = bx;
      beacons[2 * i + 1] = i === 0 ? Math.max(floor + 8, rng.range(-28, -15)) : rng.range(floor + 8, -10);
    }
    return { hull, sea, seabed, beacons, thrusters };
  },
};
