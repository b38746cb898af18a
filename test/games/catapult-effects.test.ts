// Chips and confetti of the catapult's effects come to rest on the ground, never in the earth: a
// level with a pit (level 5) has ground steps that a bit flying sideways meets as a wall.
import { describe, expect, it } from 'vitest';

// pixi.js reads `navigator` as it loads (effects.ts imports its Container and Text): a bare one for Node.
(globalThis as { navigator?: unknown }).navigator ??= { userAgent: 'node' };
const { Container } = await import('pixi.js');
const { Effects } = await import('../../games/catapult/effects');

describe('catapult effects', () => {
  it('confetti thrown over a pit lies on its floor or the ground beside it, never under them, at frames of 1/60 to 1/4 s', () => {
    // A pit 1.5 m deep from x = 0 to 2 m; the burst over its middle, 1 m up, throws bits up to
    // 7 m/s sideways, so some fly into the pit's walls. Before a bit's sideways move was checked
    // against the ground ahead of it, bits at a long frame ended up to 1.5 m inside the wall.
    for (const dt of [1 / 60, 1 / 10, 1 / 4]) {
      const fx = new Effects(new Container());
      fx.surface = (x) => (x > 0 && x < 2 ? -1.5 : 0);
      fx.burst('confetti', 1, 1, 60, 7);
      fx.burst('stone', 1, -0.5, 30, 7);
      let lowest = Number.POSITIVE_INFINITY;
      for (let t = 0; t < 8; t += dt) {
        fx.update(dt, 9.81);
        lowest = Math.min(lowest, fx.lowestOverGround());
      }
      // At rest 0.02 m over the ground (effects.ts); bits that landed have that margin, none less than 0.
      expect(lowest, `frame ${dt} s`).toBeGreaterThanOrEqual(0);
    }
  });

  it('a score popup is drawn in type of at least 22 px (its digits, about 0.7 em, some 15 px tall or more on the screen)', () => {
    // The stage is drawn 1:1 in CSS px, so the type size is the size on the screen; 18 px type drew
    // digits a stranger measured at 6 to 13 px. Exact: a style value, no tolerance needed.
    const layer = new Container();
    const fx = new Effects(layer);
    fx.popup(0, 0, '+450');
    const text = layer.children[0] as unknown as { style: { fontSize: number } };
    expect(text.style.fontSize).toBeGreaterThanOrEqual(22);
  });
});
