/**
 * lab-molecules (games/lab-molecules/scene.ts), headless: the theory curve the page draws is the 2D
 * Maxwell-Boltzmann density, and the lab's elastic gas, built and measured as the page does it
 * (buildGas, measureSpeeds), relaxes from one common speed into that distribution at the measured
 * temperature.
 */

import { createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { buildGas, gasWorldOptions, MOLECULE_MASS, maxwellBoltzmann2D, measureSpeeds } from '../../games/lab-molecules/scene';

/** Composite Simpson integral of f over [a, b] with n (even) intervals. */
function simpson(f: (x: number) => number, a: number, b: number, n: number): number {
  const h = (b - a) / n;
  let s = f(a) + f(b);
  for (let i = 1; i < n; i++) s += (i % 2 === 1 ? 4 : 2) * f(a + i * h);
  return (s * h) / 3;
}

describe('maxwellBoltzmann2D', () => {
  it('is a density (integral 1), peaks at sqrt(kT / m) and has mean speed sqrt(pi kT / (2 m))', () => {
    // Simpson with 4,000 intervals on [0, 12 sqrt(kT/m)] (the tail beyond holds exp(-72)): error
    // ~1e-12, so 1e-9 is loose yet far below any wrong factor.
    for (const [kT, m] of [
      [0.5, 1],
      [2, 1],
      [0.3, 2.5],
      [1e-3, 0.01],
    ] as const) {
      const vp = Math.sqrt(kT / m),
        top = 12 * vp;
      const f = (v: number): number => maxwellBoltzmann2D(v, kT, m);
      expect(simpson(f, 0, top, 4000)).toBeCloseTo(1, 9);
      expect(simpson((v) => v * f(v), 0, top, 4000) / Math.sqrt((Math.PI * kT) / (2 * m))).toBeCloseTo(1, 9);
      // Cumulative below v_p: 1 - exp(-1/2).
      expect(simpson(f, 0, vp, 2000)).toBeCloseTo(1 - Math.exp(-0.5), 9);
      // Peak: f'(v_p) = 0, so f falls on both sides, and f(v_p) = sqrt(m / kT) exp(-1/2).
      expect(f(vp)).toBeCloseTo(Math.sqrt(m / kT) * Math.exp(-0.5), 9);
      expect(f(vp * (1 - 1e-4))).toBeLessThan(f(vp));
      expect(f(vp * (1 + 1e-4))).toBeLessThan(f(vp));
    }
    expect(maxwellBoltzmann2D(0, 1)).toBe(0);
    expect(() => maxwellBoltzmann2D(-1, 1)).toThrow(/maxwellBoltzmann2D: v/);
    expect(() => maxwellBoltzmann2D(1, 0)).toThrow(/maxwellBoltzmann2D: kT/);
    expect(() => maxwellBoltzmann2D(1, 1, Number.NaN)).toThrow(/maxwellBoltzmann2D: m/);
  });
});

describe('lab-molecules gas', () => {
  it('relaxes into the 2D Maxwell-Boltzmann speed distribution at the measured kT', () => {
    // The page's gas: 400 discs, all at 1 m/s. Relaxation takes ~180 steps here (a disc meets another
    // about once a second, 60 steps); snapshots at steps 300, 360, ..., 600 are pooled.
    const world = createPhysicsWorld(gasWorldOptions({}));
    const gas = buildGas(world, {});
    const N = gas.molecules.length,
      BINS = 24;
    const counts = new Float64Array(BINS);
    // At the start every speed is v0: mean speed / sqrt(pi kT / 2m) = 2 / sqrt(pi) = 1.128 and no
    // molecule is below v_p = v0 / sqrt(2): the test must see that change.
    const m0 = measureSpeeds(world, gas.molecules, counts);
    expect(m0.kT).toBeCloseTo(0.5 * MOLECULE_MASS * 1 * 1, 12);
    const V = world.components.Velocity;
    let sumRatio = 0,
      sumBelow = 0,
      sumM4 = 0,
      snaps = 0,
      worstChi2 = 0,
      dof = 0;
    for (let i = 1; i <= 600; i++) {
      step(world);
      if (i < 300 || i % 60 !== 0) continue;
      const { kT, binWidth } = measureSpeeds(world, gas.molecules, counts);
      expect(kT / m0.kT).toBeCloseTo(1, 2); // elastic: temperature kept (issue 13 asks 1 % over 20,000 steps)
      const vp = Math.sqrt(kT / MOLECULE_MASS);
      let sv = 0,
        sv4 = 0,
        below = 0;
      for (const e of gas.molecules) {
        const sl = slotOf(e),
          v = Math.hypot(V.x[sl]!, V.y[sl]!);
        sv += v;
        sv4 += v ** 4;
        if (v < vp) below++;
      }
      sumRatio += sv / N / Math.sqrt((Math.PI * kT) / (2 * MOLECULE_MASS));
      sumBelow += below / N;
      sumM4 += sv4 / N / ((2 * kT) / MOLECULE_MASS) ** 2;
      // Chi-square of the page's histogram against the bin integrals of the law, N [F(a) - F(b)],
      // F(v) = exp(-m v^2 / 2kT); bins expecting under 5 merged into one tail bin.
      const F = (v: number): number => Math.exp((-MOLECULE_MASS * v * v) / (2 * kT));
      let chi2 = 0,
        tailObs = 0,
        tailExp = N * F(BINS * binWidth),
        k = 0;
      for (; k < BINS; k++) {
        const e = N * (F(k * binWidth) - F((k + 1) * binWidth));
        if (e < 5) break;
        chi2 += (counts[k]! - e) ** 2 / e;
      }
      dof = k; // k bins plus the tail, less one for the fixed total
      for (let j = k; j < BINS; j++) {
        tailObs += counts[j]!;
        tailExp += N * (F(j * binWidth) - F((j + 1) * binWidth));
      }
      tailObs += N - counts.reduce((a, b) => a + b, 0);
      chi2 += (tailObs - tailExp) ** 2 / tailExp;
      worstChi2 = Math.max(worstChi2, chi2);
      snaps++;
    }
    // Tolerances: 4 standard errors of ONE snapshot of N = 400 independent Maxwell-Boltzmann speeds
    // (the pooled mean of correlated snapshots varies no more than one snapshot does).
    // - <v> / sqrt(pi <v^2> / 4): delta method on the Rayleigh moments, SE = 0.152 / sqrt(N) = 0.0076
    //   (a 20,000-sample Monte Carlo agrees: 0.0076); bound 0.030, against 0.128 at the start.
    // - fraction below v_p: binomial SE sqrt(p (1 - p) / N) = 0.024 (an upper bound: v_p from the
    //   same sample lowers it to 0.019); bound 0.098, against 0.39 at the start.
    // - <v^4> / (2 kT / m)^2 = 2 (1 at the start): SE (Monte Carlo) 0.099; bound 0.4.
    expect(snaps).toBe(6);
    expect(Math.abs(sumRatio / snaps - 1)).toBeLessThan(0.03);
    expect(Math.abs(sumBelow / snaps - (1 - Math.exp(-0.5)))).toBeLessThan(0.098);
    expect(Math.abs(sumM4 / snaps - 2)).toBeLessThan(0.4);
    // Each snapshot's histogram: chi-square below the p = 1e-4 point for its degrees of freedom
    // (Wilson-Hilferty, z = 3.72): the page's bars follow the page's curve.
    const crit = dof * (1 - 2 / (9 * dof) + 3.72 * Math.sqrt(2 / (9 * dof))) ** 3;
    expect(worstChi2).toBeLessThan(crit);
  });

  it('measureSpeeds rejects an empty gas or histogram', () => {
    const world = createPhysicsWorld(gasWorldOptions({ count: 10 }));
    const gas = buildGas(world, { count: 10 });
    expect(() => measureSpeeds(world, [], new Float64Array(4))).toThrow(/measureSpeeds: molecules/);
    expect(() => measureSpeeds(world, gas.molecules, new Float64Array(0))).toThrow(/measureSpeeds: counts/);
  });
});
