/**
 * Catapult: the distance marks on the ground, every DISTANCE_STEP metres out from the catapult to
 * short of the castle ("5 m", "10 m", ...). The camera frames each level at its own scale (level 2's
 * far keep drew the field at 34 px a metre on a desktop, level 3 at 48), so a pull remembered as a
 * length on the screen did not carry from one level to the next; the marks say how far the castle
 * stands in metres, the unit a miss's hint uses ("Short by 3 m").
 */

import { LAUNCH, type Level, surfaceAt } from './scene';

/** Metres between two distance marks. */
export const DISTANCE_STEP = 5;

/** A distance mark: where it stands, m from the world's origin, and what it says. */
export interface DistanceMark {
  x: number;
  label: string;
}

/**
 * The distance marks of level `lv`: every DISTANCE_STEP m from the catapult (LAUNCH.x) while at
 * least 1 m short of the castle's near end, each on flat ground only (not on a hill, in a pit or off
 * the ground), so no mark lies under the castle or its wreck.
 */
export function distanceMarks(lv: Pick<Level, 'terrain' | 'castleMinX'>): DistanceMark[] {
  const marks: DistanceMark[] = [];
  for (let d = DISTANCE_STEP; LAUNCH.x + d <= lv.castleMinX - 1; d += DISTANCE_STEP) {
    const x = LAUNCH.x + d;
    if (surfaceAt(lv, x) === 0 && surfaceAt(lv, x - 0.5) === 0 && surfaceAt(lv, x + 0.5) === 0) marks.push({ x, label: `${d} m` });
  }
  return marks;
}
