// `node scripts/black-hole-taps.mjs [--fps 60,10] [--ms 40,60,120,200,250,400,800]`: black hole's arrow presses as the
// page turns them into thrust (games/black-hole/press-timing.ts), against the rule before it (a press let go within
// 250 ms and 9 steps thrust 9 steps, any other let go at the step count of its release). The pacer runs fixed steps of
// 1/60 s in a burst at each frame (frames every 1000/fps ms), and a press begins and ends between frames, at 20 phases
// across a frame. Per frame rate and press length: the steps thrust and the speed the ship gains from rest (the
// engine's ramp, ./rules.ts `rampThrust`, full thrust 6 m/s^2), min-max over the phases.
import { importSource } from './build.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
};
const m = await importSource(
  'black-hole-taps',
  "export { rampThrust } from './games/black-hole/rules.ts'; export * from './games/black-hole/press-timing.ts';",
);
const fpsList = arg('--fps', '60,10').split(',').map(Number);
const msList = arg('--ms', '40,60,120,200,250,400,800').split(',').map(Number);
const dt = 1 / 60,
  full = 6,
  PHASES = 20;
/** Steps the pacer has run at wall time t ms, frames every f ms. */
const stepsAt = (t, f) => Math.floor((Math.floor(t / f) * f) / (1000 * dt) + 1e-9);
/** Speed gained from rest, m/s, by thrust held for n steps (then the engine dies away). */
function speed(n) {
  const vec = [0, 0];
  let v = 0;
  for (let i = 0; i < n + 60; i++) {
    m.rampThrust(vec, i < n ? full : 0, 0, full, dt);
    v += vec[0] * dt;
  }
  return v;
}
const rules = {
  before: (press, ms, now) => (ms < 250 && now < press + 9 ? press + 9 : now),
  after: (press, ms, now) => m.releaseStep(press, ms, now, dt),
};
for (const fps of fpsList) {
  const f = 1000 / fps;
  console.log(`${fps} frames a second (${f.toFixed(1)} ms a frame):`);
  for (const ms of msList) {
    const parts = [];
    for (const [name, rule] of Object.entries(rules)) {
      const steps = [];
      for (let k = 0; k < PHASES; k++) {
        const t0 = 1000 + (k / PHASES) * f;
        const press = stepsAt(t0, f);
        steps.push(rule(press, ms, stepsAt(t0 + ms, f)) - press);
      }
      const vs = steps.map(speed);
      parts.push(
        `${name} ${Math.min(...steps)}-${Math.max(...steps)} steps, ${Math.min(...vs).toFixed(2)}-${Math.max(...vs).toFixed(2)} m/s`,
      );
    }
    console.log(`  ${String(ms).padStart(4)} ms: ${parts.join(' | ')}`);
  }
}
