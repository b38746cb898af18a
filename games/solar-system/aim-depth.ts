/**
 * How centred a launch is on its target, from the second mission on: the two-body (Kepler) closest
 * approach of the aim's path to the target's centre, over the mission's arrival ring (`aimRings`),
 * not stopped at the ring's edge as the flight and its forecast are (an arrival's forecast closest
 * approach is always just under one ring, so it could not tell a launch that grazes the ring from
 * one that runs through its middle). Three stars from mission 2 want both a cheap launch and one
 * within STAR_RINGS (`skillStars`); the line before a launch that arrives shows the stars it earns
 * (./meeting-words.ts forecastWords), so an arrival off the centre reads "✓ … · ★★" and the player
 * can centre it. DOM-free, for Node tests.
 */

import type { PhysicsWorld } from '@bitphysics/physics';
import type { SolarSystemHandles } from '@bitphysics/projects';
import { type Aim, createFlightPlan, type Mission, planFlight, starsFor } from './missions';

/**
 * The centredness three stars want from the second mission on: the aim's path, flown on past the
 * ring's edge, comes within this share of the ring's radius of the target's centre. Half a ring:
 * of 30 random launches within 15 days of a window (scripts/solar-system-stars.mjs) three stars went
 * to 9 -> 6 on Venus, 5 -> 3 on Jupiter, 2 -> 0 on Mercury, and a search of three windows each
 * found a cheap launch within 0.2 rings on Venus and Jupiter and on two of Mercury's three.
 */
export const STAR_RINGS = 0.5;

const depthPlan = createFlightPlan();

/**
 * The closest approach (two-body, the probe's and the target's Kepler motions about the Sun, see
 * ./missions.ts planFlight) of launching `aim` now on `mission`, not stopped at the arrival ring,
 * over the ring's radius (>= 0; 0.3: through the ring's inner third). @throws RangeError as planFlight.
 */
export function aimRings(world: PhysicsWorld, handles: SolarSystemHandles, mission: Mission, aim: Aim): number {
  // A ring too small to enter: the plan runs to the closest approach rather than stopping at the ring.
  planFlight(world, handles, { ...mission, zone: 1e-12 }, aim, depthPlan);
  return depthPlan.distance / mission.zone;
}

/**
 * The stars an arrival earns on mission `index` (0-based in MISSIONS) of `mission`: its speed
 * budget's (`starsFor` of `spent`, the launch plus the burns, km/s), and from the second mission on
 * at most two unless the launch's own aim was centred (`rings`, its `aimRings` at the launch, at
 * most STAR_RINGS) and no burn was needed (`burns` 0): three stars for an arrival worked out before
 * the launch, not for any launch that happens to reach the ring. The first mission is the lesson:
 * its speed budget alone. @throws RangeError on a NaN rings.
 */
export function skillStars(index: number, mission: Mission, spent: number, rings: number, burns: number): 1 | 2 | 3 {
  if (Number.isNaN(rings)) throw new RangeError('skillStars: rings must be a number, got NaN');
  const s = starsFor(mission, spent);
  if (index === 0 || s < 3) return s;
  return rings <= STAR_RINGS && burns === 0 ? 3 : 2;
}
