/**
 * How much a ring near the camera fades: a ring whose outer edge spans most of the view is drawn
 * faint, so the ring the aircraft flies through (and the one just flown through, still between the
 * chase camera and the aircraft) does not cover the scene. On a phone the chase camera sits 110 m
 * behind, where an unfaded ring would fill the screen at each pass. The flight-path marker and the
 * ring's outline still say where it is. Headless (no DOM), tested in node
 * (test/games/flight-simulator-pacing.test.ts).
 */

/**
 * The ring's share of the view at which it starts to fade and at which it is faintest: its outer
 * radius over the half width of the view's narrower side at its distance (1: it touches the edges).
 */
export const NEAR_FADE = Object.freeze({ from: 0.55, to: 1, least: 0.15 });

/**
 * The opacity factor, in [NEAR_FADE.least, 1], of a ring of outer radius `radius` (m, > 0) whose
 * centre is `distance` m from the camera, seen with a view whose narrower side spans `tanHalf` (the
 * tangent of half its angle, > 0): its share s = radius / (distance tanHalf) of the view; 1 up to
 * NEAR_FADE.from, NEAR_FADE.least from NEAR_FADE.to on (and for a ring at or behind the camera's
 * place), smoothstep between.
 * @throws RangeError on a radius or tanHalf that is not finite and > 0, or a distance that is negative or not finite.
 */
export function nearFade(radius: number, distance: number, tanHalf: number): number {
  if (!(radius > 0 && Number.isFinite(radius) && tanHalf > 0 && Number.isFinite(tanHalf)))
    throw new RangeError(`nearFade: radius and tanHalf must be finite and > 0, got ${radius}, ${tanHalf}`);
  if (!(distance >= 0 && Number.isFinite(distance))) throw new RangeError(`nearFade: distance must be finite and >= 0, got ${distance}`);
  const { from, to, least } = NEAR_FADE;
  if (distance === 0) return least;
  const share = radius / (distance * tanHalf);
  const u = Math.min(1, Math.max(0, (share - from) / (to - from)));
  return 1 - (1 - least) * u * u * (3 - 2 * u);
}
