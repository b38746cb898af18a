/**
 * Newtonian gravitational constant G, m^3 kg^-1 s^-2 (CODATA 2018).
 * @category Forces
 */
export const G_SI = 6.6743e-11;
/**
 * Coulomb constant k = 1 / (4 pi eps0), N m^2 C^-2 (CODATA 2018).
 * @category Forces
 */
export const COULOMB_SI = 8.9875517923e9;

/**
 * How mutual gravity is summed: every pair ('direct', O(N^2)) or by a Barnes-Hut tree ('barnes-hut').
 * @category Forces
 */
export type GravityMethod = 'direct' | 'barnes-hut';

/**
 * World-wide constants and fields the force laws read. Change with the setters below.
 * @category Forces
 */
export interface ForceLawSettings {
  /** G, m^3 kg^-1 s^-2; default the SI value. Games often use scaled units (see setGravitation). */
  gravitationalConstant: number;
  /** Plummer softening length eps of mutual gravity, m (>= 0): the pair force is G m m r / (r^2 + eps^2)^(3/2). */
  gravitySoftening: number;
  /** Summation of mutual gravity. */
  gravityMethod: GravityMethod;
  /**
   * Barnes-Hut opening angle theta (> 0): two cells of radii r_A, r_B whose centres of mass are R apart
   * interact as wholes (by their multipole expansions) when (r_A + r_B) / R < min(theta, 1); smaller is
   * more accurate and slower (see forces/barnes-hut/tree.ts).
   */
  openingAngle: number;
  /** Coulomb constant, N m^2 C^-2. */
  coulombConstant: number;
  /** Softening of the Coulomb force, m (>= 0). */
  electricSoftening: number;
  /** The wind field drag and lift are measured against. */
  readonly wind: WindField;
}

/**
 * The wind (the velocity of the air, m/s) at a point and time:
 * u(x, t) = u0 + A cos(omega t + phase) + turbulence(x, t), where the turbulence is a sum of random
 * Fourier modes (Kraichnan, Phys. Fluids 13, 1970) with divergence-free directions, seeded, with
 * root-mean-square speed `intensity` (per component), wavelengths around `lengthScale` and
 * frequencies around 1 / `timeScale`. A pure function of position and time.
 * @category Forces
 */
export interface WindField {
  /** Mean wind u0, m/s. */
  readonly velocity: Float64Array;
  /** Gust amplitude A, m/s. */
  readonly gust: Float64Array;
  /** Gust angular frequency omega, rad/s, and phase, rad. */
  gustOmega: number;
  gustPhase: number;
  /** Turbulence: number of modes in use (0 = none), and per mode: wave vector (3), frequency, phase, unit amplitude direction (3). */
  modes: number;
  readonly modeData: Float64Array;
  /** RMS turbulent speed per component, m/s. */
  intensity: number;
}

/**
 * Turbulence modes the wind field can hold.
 * @category Forces
 */
export const MAX_WIND_MODES = 32;

/**
 * Default settings: SI constants, direct gravity, no softening, no wind.
 * @category Forces
 */
export function createForceLawSettings(): ForceLawSettings {
  return {
    gravitationalConstant: G_SI,
    gravitySoftening: 0,
    gravityMethod: 'direct',
    openingAngle: 0.5,
    coulombConstant: COULOMB_SI,
    electricSoftening: 0,
    wind: {
      velocity: new Float64Array(3),
      gust: new Float64Array(3),
      gustOmega: 0,
      gustPhase: 0,
      modes: 0,
      modeData: new Float64Array(MAX_WIND_MODES * 8),
      intensity: 0,
    },
  };
}
