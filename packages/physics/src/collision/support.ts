/**
 * Support rows of the 2D ball contacts' relax sweep (solver.ts, solve2D, and the coloured solve of a
 * threaded world, contact-colors-kernel.ts, which repeats the same test inline): shock propagation
 * (Guendelman, Bridson and Fedkiw, "Nonconvex rigid bodies with stacking", SIGGRAPH 2003), limited to
 * the relax sweep of frictionless rows and to row updates that take energy out.
 *
 * Each soft substep solves the contacts with one Gauss-Seidel sweep with bias (which pushes overlaps
 * out), then one relax sweep without bias that should take the push-out velocity away again. Along a
 * tall chain of contacts one relax sweep cannot: relaxing the row under a ball only moves that ball's
 * velocity into the ball below, so the push-out of a 60-layer column stays in it as kinetic energy.
 * With the stiff contacts of issue 13 (frequency f up to 0.6 of the substep rate, contact-scale.ts)
 * a column whose rows have no friction to damp them boiled: 120 frictionless balls of 2 cm zigzagging
 * between walls 5 radii apart kept their fastest ball at 5 to 11 sqrt(g r) for as long as they ran,
 * 0.5 m balls at 1 sqrt(g r), and 120 balls stacked straight up in a tube threw balls at 28 sqrt(g r);
 * the exact equilibrium of the zigzag column grew unstable above f h_s ~ 0.27 (the code before issue 13
 * ran at f h_s 0.25, seven times softer at 2 cm, and settled). Rows with friction settle at f h_s 0.6
 * (their tangent rows damp the column), and are left as they were.
 *
 * In the relax sweep, a row between two dynamic balls with no friction (bound 0) whose normal is within
 * acos(SUPPORT_COS) of gravity (one ball rests on the other) is solved with the lower ball held
 * (inverse mass 0, `holdsLower`) when that only slows the ball above: when the lower ball's speed along
 * the normal is at most the upper one's, so making the upper ball move with the lower one along the
 * normal cannot raise its kinetic energy, and the lower ball is not touched. One sweep then clears the
 * push-out speed of a whole column. Otherwise (and always in the sweep with bias, and for the impact
 * stage and restitution) both masses count, so momentum is exchanged as it should be.
 * Measured (fastest ball over the last 100 of 400 steps, sqrt(g r), sleep off): 120 balls zigzagging,
 * 2 cm 3.89 -> 0.0024, 0.5 m 1.10 -> 0.0034 (the code before issue 13: 0.038 and 0.127); 60 balls of
 * 2 cm in a tube, 300 steps: 4.04 -> 0.0001 (test/physics/support-rows.test.ts); on 2 threads with
 * the coloured solve, 6.88 -> 0.0022 and 3.30 -> 0.0002. Not everything: the
 * same 120 balls put exactly touching in their ideal lattice (pairs on the walls, one ball between)
 * came to rest from one start (0.007) but kept swaying at 0.2 to 0.46 sqrt(g r) in place from another
 * (the rows with the walls are horizontal, not support rows; the code before issue 13: at rest).
 *
 * The trade-off: in such a row the relax sweep does not conserve momentum (the ball above is stopped
 * against the ball below as if that one were immovable). The relax sweep exists to remove speed the
 * bias added, so this changes only how that speed is removed, never adds energy.
 */

/**
 * Smallest |n . g| / |g| (dimensionless, 0..1) for which a frictionless row between two dynamic balls
 * is a support row: 0.3, rows within 72.5 degrees of vertical (a zigzag column's rows lean 41 degrees
 * from horizontal, |n . g| / |g| = 0.66; a row side by side, like a Newton's cradle's, is 0 and never one).
 */
export const SUPPORT_COS = 0.3;

/**
 * Whether the relax sweep holds the lower ball of a support row: its normal speed |v_lower . n| (m/s,
 * >= 0) is at most the upper ball's |v_upper . n| (m/s, >= 0), so moving the upper ball to the lower
 * one's normal velocity does not raise its kinetic energy.
 */
export function holdsLower(speedLower: number, speedUpper: number): boolean {
  return speedLower <= speedUpper;
}

/**
 * Writes the unit vector along `g` (m/s^2, 2 or 3 components; the first two used), or (0, 0) for no
 * gravity, into out[at] and out[at + 1] (no array made: the solvers ask once a step).
 */
export function downwardInto(g: ArrayLike<number>, out: Float64Array, at: number): void {
  const gx = g[0]!,
    gy = g[1]!;
  const l = Math.sqrt(gx * gx + gy * gy);
  if (l > 0) {
    out[at] = gx / l;
    out[at + 1] = gy / l;
  } else {
    out[at] = 0;
    out[at + 1] = 0;
  }
}
