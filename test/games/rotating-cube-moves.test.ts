/** The room's round move count in the status row and a reached pad's result words (games/rotating-cube/round-moves.ts). */
import { describe, expect, it } from 'vitest';
import { padResultText, roundMovesText } from '../../games/rotating-cube/round-moves';
import { PAR_SLACK } from '../../games/rotating-cube/scene';

describe('roundMovesText', () => {
  it('names the round and the stars still in reach: par + 2 for three, par + 8 for two, then one', () => {
    expect(PAR_SLACK).toEqual([2, 8]);
    expect(roundMovesText(1, 3)).toBe('round: 1 of 5 moves for ★★★');
    expect(roundMovesText(5, 3)).toBe('round: 5 of 5 moves for ★★★');
    expect(roundMovesText(6, 3)).toBe('round: 6 of 11 moves for ★★☆');
    expect(roundMovesText(12, 3)).toBe('round: 12 moves ★☆☆');
    expect(roundMovesText(3, 3, true)).toBe('round 3/5 ★★★');
    expect(roundMovesText(12, 3, true)).toBe('round 12 ★☆☆');
  });
  it('throws on a count that is not a whole number >= 0', () => {
    expect(() => roundMovesText(-1, 3)).toThrow(/roundMovesText: moves must be an integer >= 0, got -1/);
    expect(() => roundMovesText(1, 2.5)).toThrow(/par must be an integer >= 0, got 2.5/);
  });
});

describe('padResultText', () => {
  it('one label for any optimal solution: a pad done in its best 1 move and one done in its best 2 both read "Perfect!"', () => {
    // A player read "Perfect!" for pad 1 (best 1, done in 1) and only "on par" for pad 2 (best 2, done in 2).
    expect(padResultText(1, 1)).toBe(' · Perfect!');
    expect(padResultText(2, 2)).toBe(padResultText(1, 1));
    expect(padResultText(0, 0)).toBe(' · Perfect!');
    expect(padResultText(4, 2)).toBe(' · 4 moves, best 2');
    expect(padResultText(3, 1)).toBe(' · 3 moves, best 1');
  });
  it('throws on a count that is not a whole number >= 0', () => {
    expect(() => padResultText(-1, 2)).toThrow(/padResultText: moves must be an integer >= 0, got -1/);
    expect(() => padResultText(1, 0.5)).toThrow(/par must be an integer >= 0, got 0.5/);
  });
});
