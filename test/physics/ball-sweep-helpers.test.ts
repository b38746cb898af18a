import { describe, expect, test } from 'vitest';
import * as FINISH from '../../packages/physics/src/solver/slots/finish-bodies.js';
import * as GATHER from '../../packages/physics/src/solver/slots/gather-fill.js';
import { lowerSupportBall, relaxOrderInto, SUPPORT_COS } from '../../packages/physics/src/solver/support.js';

// The pieces the 2D and 3D ball sweeps (solver/ball-sweeps.ts) and the solver's stages
// (solver/stages-threads.ts motionArrays) share, against what each is documented to do.

describe('relaxOrderInto: the ball sweeps row order', () => {
  const n = 7;
  const ia = Int32Array.from([0, 3, 0, 5, 2, 0, 4]);
  const first = Uint8Array.from([1, 0, 0, 0, 0, 1, 0]);

  test('relaxing: the marked rows, then the rows between two balls, then the rows against static bodies', () => {
    const out = new Int32Array(2 * n).fill(-1);
    const count = relaxOrderInto(first, ia, n, out);
    const rows = [...Array(n).keys()];
    const expected = [...rows.filter((i) => first[i] === 1), ...rows.filter((i) => ia[i] !== 0), ...rows.filter((i) => ia[i] === 0)];
    expect(count).toBe(n + 2);
    expect([...out.subarray(0, count)]).toEqual(expected);
    expect(out[count]).toBe(-1);
  });
});

describe('lowerSupportBall: which ball of a support row may be held', () => {
  const up = SUPPORT_COS + 0.2;
  test('a frictionless row near vertical: the lower ball, A when n points up from A, else B', () => {
    expect(lowerSupportBall(up, 0, 1, 1)).toBe(1);
    expect(lowerSupportBall(-up, 0, 1, 1)).toBe(2);
  });
  test('a row within SUPPORT_COS of horizontal is no support row', () => {
    expect(lowerSupportBall(SUPPORT_COS - 0.1, 0, 1, 1)).toBe(0);
    expect(lowerSupportBall(-(SUPPORT_COS - 0.1), 0, 1, 1)).toBe(0);
    expect(lowerSupportBall(Number.NaN, 0, 1, 1)).toBe(0);
  });
  test('with friction, only when the upper ball is at least four times as heavy', () => {
    // Inverse masses: A 1/kg (1 kg), B 0.1/kg (10 kg) above A.
    expect(lowerSupportBall(up, 0.3, 1, 0.1)).toBe(1);
    expect(lowerSupportBall(up, 0.3, 1, 0.5)).toBe(0);
    // B below, A above and heavier.
    expect(lowerSupportBall(-up, 0.3, 0.1, 1)).toBe(2);
    expect(lowerSupportBall(-up, 0.3, 0.5, 1)).toBe(0);
  });
});

test('the gather and finish slot modules keep the body motion arrays in the order motionArrays writes them', () => {
  for (const S of [GATHER, FINISH]) {
    expect([S.PY, S.VX, S.VY, S.WZ].map((v) => v - S.PX)).toEqual([1, 2, 3, 4]);
    expect([S.VZ, S.WX, S.WY].map((v) => v - S.PZ)).toEqual([1, 2, 3]);
  }
});
