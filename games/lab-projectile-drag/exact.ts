/**
 * Exact solutions the projectile lab compares the simulation against. These are the only physics
 * formulas of the lab outside the physics package, and they are only drawn and plotted, never fed
 * back into the simulation.
 */

/** A launch: position (m), velocity (m/s), gravity g (m/s^2, downwards, > 0). */
export interface Launch {
  x0: number;
  y0: number;
  vx0: number;
  vy0: number;
  g: number;
}

/** State at time t: position (m) and velocity (m/s). Written in place by the functions below. */
export interface KinematicState {
  x: number;
  y: number;
  vx: number;
  vy: number;
}

/**
 * No drag (uniform gravity): x = x0 + vx0 t, y = y0 + vy0 t - g t^2 / 2, vy = vy0 - g t.
 * Source: Ramtal and Dobre ch. 4 (constant acceleration); Taylor, Classical Mechanics (2005) sect. 1.7.
 * @param t time since launch, s (>= 0).
 */
export function noDragState(l: Launch, t: number, out: KinematicState): KinematicState {
  out.x = l.x0 + l.vx0 * t;
  out.y = l.y0 + l.vy0 * t - 0.5 * l.g * t * t;
  out.vx = l.vx0;
  out.vy = l.vy0 - l.g * t;
  return out;
}

/**
 * Linear drag F = -k v with gravity: m dv/dt = -k v - m g y_hat. With tau = m / k and the terminal
 * speed v_t = m g / k, each component is a first-order linear ODE whose solution is
 *   vx = vx0 e^(-t/tau),                 x = x0 + vx0 tau (1 - e^(-t/tau)) = x0 + (m vx0 / k)(1 - e^(-k t / m)),
 *   vy = -v_t + (vy0 + v_t) e^(-t/tau),  y = y0 - v_t t + (vy0 + v_t) tau (1 - e^(-t/tau)).
 * (Integrate dvy/dt = -(vy + v_t) / tau to get vy, then vy once more for y.)
 * Source: Taylor, Classical Mechanics (2005) sect. 2.2-2.3, eqs. 2.33-2.37; Ramtal and Dobre ch. 7 (drag).
 * @param m mass, kg (> 0). @param k linear drag coefficient, N s/m (> 0; k = 0 falls back to no drag).
 */
export function linearDragState(l: Launch, m: number, k: number, t: number, out: KinematicState): KinematicState {
  if (!(k > 0)) return noDragState(l, t, out);
  const tau = m / k;
  const vt = l.g * tau;
  const e = Math.exp(-t / tau);
  // 1 - e^(-t/tau), accurate for small t/tau too.
  const oneMinusE = -Math.expm1(-t / tau);
  out.x = l.x0 + l.vx0 * tau * oneMinusE;
  out.vx = l.vx0 * e;
  out.y = l.y0 - vt * t + (l.vy0 + vt) * tau * oneMinusE;
  out.vy = -vt + (l.vy0 + vt) * e;
  return out;
}

/**
 * Terminal speed under linear drag, m/s: the speed at which k v = m g, v_t = m g / k (Infinity for k = 0).
 * Source: Taylor, Classical Mechanics (2005) eq. 2.29; Ramtal and Dobre ch. 7.
 */
export function linearTerminalSpeed(m: number, g: number, k: number): number {
  return k > 0 ? (m * g) / k : Infinity;
}

/**
 * Terminal speed under quadratic drag, m/s: k v^2 = m g, v_t = sqrt(m g / k) (Infinity for k = 0).
 * Quadratic drag in two dimensions has no closed-form trajectory; the terminal speed is what the lab
 * compares against. Source: Taylor, Classical Mechanics (2005) eq. 2.53; Ramtal and Dobre ch. 7.
 */
export function quadraticTerminalSpeed(m: number, g: number, k: number): number {
  return k > 0 ? Math.sqrt((m * g) / k) : Infinity;
}
