/**
 * The room's "how close" indicator: the fewest moves left to win the lit pad from where the cube rests
 * (scene.ts `padMovePar`, a shortest route over the grid model) and whether the last move brought the
 * cube closer or took it farther, so a pad whose face rule takes planning (the last ones, across their
 * tiles) reads on screen as hot or cold instead of on paper. Pure (no DOM, no three.js).
 */

/** Which way the count went with the last change: 'closer' (fewer moves left), 'farther' (more), or '' (the same, or no count before). */
export type ToGoTrend = 'closer' | 'farther' | '';

/**
 * Follows the moves left on the lit pad: `update` with each new count read while the cube rests; a
 * count that differs from the last gives the trend. `reset` when a new pad lights (or a new round).
 */
export class ToGoMeter {
  /** The moves left at the last count, >= 0, or -1 before any (or when no route reaches the pad). */
  toGo = -1;
  /** The trend of the last change of the count. */
  trend: ToGoTrend = '';
  /** Forgets the count and the trend. */
  reset(): void {
    this.toGo = -1;
    this.trend = '';
  }
  /**
   * Takes a new count of the moves left (an integer >= 0; -1 when no route reaches the pad, which
   * forgets the count). @returns whether the count changed.
   * @throws RangeError if `movesLeft` is not an integer >= -1.
   */
  update(movesLeft: number): boolean {
    if (!Number.isInteger(movesLeft) || movesLeft < -1)
      throw new RangeError(`ToGoMeter.update: movesLeft must be an integer >= -1, got ${movesLeft}`);
    if (movesLeft === this.toGo) return false;
    this.trend = this.toGo < 0 || movesLeft < 0 ? '' : movesLeft < this.toGo ? 'closer' : 'farther';
    this.toGo = movesLeft;
    return true;
  }
  /**
   * The indicator in words (no arrows: on a phone ▲ and ▼ are the roll buttons), worded as the best
   * case, not a budget: "best: 3 more moves · closer", "best: 1 more move", or '' with no count;
   * `short` (a phone's narrow status row): "best 3 more, closer".
   */
  text(short = false): string {
    if (this.toGo < 0) return '';
    const moves = short ? `best ${this.toGo} more` : `best: ${this.toGo} more move${this.toGo === 1 ? '' : 's'}`;
    return this.trend === '' ? moves : `${moves}${short ? ',' : ' ·'} ${this.trend}`;
  }
}
