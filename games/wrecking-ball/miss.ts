/**
 * Wrecking ball: the words for a swing that brought nothing down ("Missed: ..." and a hint), from
 * where the ball came nearest the block it was aimed at. Pure (no DOM, no world), so node tests
 * can check it; the page (./main) tracks the nearest pass while the swing runs.
 */

/** Where the ball came nearest its target during a swing (world frame, m; y up). */
export interface NearestPass {
  /** The ball's centre at its nearest. */
  ball: readonly [number, number, number];
  /** The target's centre then. */
  target: readonly [number, number, number];
  /** The target's half extents (x, y, z), m (its height above its centre is `half[1]`). */
  half: readonly [number, number, number];
  /** The ball's radius, m. */
  radius: number;
  /** The swing's direction across the ground, rad (atan2 of z over x, as ./scene SwingRequest). */
  direction: number;
  /** The camera's right across the ground, a unit (x, z) vector, so "left" and "right" read as on the screen. */
  right: readonly [number, number];
}

/** Gap, m, between the ball's surface and the target's box under which the ball counts as touching it. */
export const TOUCH_GAP = 0.08;

/**
 * The status line's words for a swing that brought nothing down, with a hint at what to change:
 * the ball touched the block (swing harder), passed over it (lower the hook), stopped short of it
 * (pull farther) or passed beside it (which side as seen on the screen; drag straight back from it).
 * `name` is the target's name ('the wall'); `downKey` the control that lowers the hook ('Down', 'E').
 */
export function missWords(pass: NearestPass, name: string, downKey: string): string {
  const [bx, by, bz] = pass.ball;
  const [tx, ty, tz] = pass.target;
  const [hx, hy, hz] = pass.half;
  // Gap between the ball's surface and the target's box (its axes taken as the world's: a bound
  // within the box's half diagonal, enough to tell a touch from a pass by).
  const gx = Math.max(0, Math.abs(bx - tx) - hx),
    gy = Math.max(0, Math.abs(by - ty) - hy),
    gz = Math.max(0, Math.abs(bz - tz) - hz);
  const gap = Math.hypot(gx, gy, gz) - pass.radius;
  if (gap < TOUCH_GAP) return `Missed: the ball touched ${name} but nothing fell. Pull farther for a harder swing`;
  const over = by - pass.radius - (ty + hy);
  const ux = Math.cos(pass.direction),
    uz = Math.sin(pass.direction);
  // The target from the ball, along the swing and across it.
  const dx = tx - bx,
    dz = tz - bz;
  const along = dx * ux + dz * uz,
    across = -dx * uz + dz * ux;
  if (over > 0 && over >= Math.abs(across) - hx - pass.radius)
    return `Missed: the ball passed ${over.toFixed(1)} m over ${name}. Lower the hook (${downKey}) or aim at a lower block`;
  if (along > Math.abs(across))
    return `Missed: the ball stopped ${Math.max(0, along - hx - pass.radius).toFixed(1)} m short of ${name}. Pull farther for a longer swing`;
  // Beside: which side of the target the ball went, as seen on the screen.
  const side = -(dx * pass.right[0] + dz * pass.right[1]) > 0 ? 'right' : 'left';
  return `Missed: the ball passed ${Math.max(0, gap).toFixed(1)} m to the ${side} of ${name}. Drag straight back from it, away from where it should fall`;
}
