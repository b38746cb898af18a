import { addBody, createPhysicsWorld, kineticEnergy, Rng, setBoundary, step } from '@bitphysics/physics';
import { sig } from '../scenes/format.js';
import type { BenchStudy, StudyResult, StudyRunOptions } from './types.js';

/**
 * The elastic gas study (`--scene elastic-gas`): the book's molecules (Ramtal and Dobre ch. 11) as a
 * long run. `count` discs of radius 0.1 m and unit mass, all at 1 m/s in random directions on a
 * jittered grid, 12 % area fraction, e = 1, no friction, no gravity, in a 3:2 box with e = 1 walls.
 * Every collision is an exact pairwise exchange, so the kinetic energy should stay where it started:
 * the study prints its drift (E_end - E_0) / E_0 at a tenth, half and the end of `steps`, and the
 * median step time. The budget: within 1 % over 20,000 steps of 500 balls (the defaults) and
 * over 10,000 steps of 5,000 (`--count 5000 --steps 10000`). The unit suite runs 500 steps of it.
 */
export const elasticGasStudy: BenchStudy = {
  name: 'elastic-gas',
  description: 'elastic gas of discs (e = 1, no friction, no gravity) in a box: kinetic energy drift over a long run',
  defaultCount: 500,
  maxCount: 100_000,
  defaults: { steps: 20_000, warmup: 0 },
  run(options: StudyRunOptions): StudyResult {
    const count = options.count,
      r = 0.1;
    const world = createPhysicsWorld({ dimensions: 2, capacity: count + 8, gravity: [0, 0], sleep: false, seed: options.seed });
    const height = Math.sqrt((count * Math.PI * r * r) / 0.12 / 1.5),
      width = 1.5 * height;
    setBoundary(world, { min: [0, 0], max: [width, height], restitution: 1, friction: 0 });
    const cols = Math.ceil(Math.sqrt(count * 1.5)),
      rows = Math.ceil(count / cols);
    const dx = width / cols,
      dy = height / rows;
    const rng = new Rng(options.seed);
    for (let i = 0; i < count; i++) {
      const x = ((i % cols) + 0.5) * dx + rng.range(-0.2, 0.2) * (dx - 2 * r);
      const y = (Math.floor(i / cols) + 0.5) * dy + rng.range(-0.2, 0.2) * (dy - 2 * r);
      const a = rng.range(0, 2 * Math.PI);
      addBody(world, { position: [x, y], velocity: [Math.cos(a), Math.sin(a)], radius: r, mass: 1, restitution: 1, friction: 0 });
    }
    const k0 = kineticEnergy(world);
    const marks = [Math.max(1, Math.round(options.steps / 10)), Math.max(1, Math.round(options.steps / 2)), options.steps];
    const drift: number[] = [];
    const times: number[] = [];
    options.onProgress?.(`${options.steps} steps of ${count} discs`);
    for (let s = 1; s <= options.steps; s++) {
      const t = performance.now();
      step(world);
      times.push(performance.now() - t);
      if (marks.includes(s) && drift.length < marks.length) drift.push(kineticEnergy(world) / k0 - 1);
    }
    while (drift.length < marks.length) drift.push(kineticEnergy(world) / k0 - 1);
    times.sort((a, b) => a - b);
    const median = times[Math.floor(times.length / 2)]!;
    const pct = (v: number): string => `${(100 * v).toFixed(4)}%`;
    return {
      records: [{ count, steps: options.steps, driftTenth: drift[0], driftHalf: drift[1], drift: drift[2], medianMs: median }],
      header: ['discs', 'steps', `drift @${marks[0]}`, `drift @${marks[1]}`, `drift @${marks[2]}`, 'median ms'],
      rows: [[String(count), String(options.steps), pct(drift[0]!), pct(drift[1]!), pct(drift[2]!), String(sig(median))]],
      notes: ['drift: (E_end - E_0) / E_0 of the kinetic energy; budget 1 % (20,000 steps of 500 discs, 10,000 of 5,000).'],
    };
  },
};
