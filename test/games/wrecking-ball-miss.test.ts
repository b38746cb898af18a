/**
 * Wrecking ball, the words of a miss (games/wrecking-ball/miss.ts): a swing that brings nothing down
 * says "Missed: ..." and what to change, from where the ball came nearest its target. The target
 * here is a 1 x 1 x 1 m block centred 0.5 m up at the origin; the ball (radius 0.5 m) swings along
 * +x (direction 0); the camera's right across the ground is +z unless a case turns it. Each case
 * puts the ball where the words are unambiguous (0.5 m or more from any boundary between cases).
 */
import { describe, expect, it } from 'vitest';
import { missWords, type NearestPass } from '../../games/wrecking-ball/miss';

function pass(ball: [number, number, number], right: [number, number] = [0, 1]): NearestPass {
  return { ball, target: [0, 0.5, 0], half: [0.5, 0.5, 0.5], radius: 0.5, direction: 0, right };
}

describe('wrecking ball miss words', () => {
  it('a ball that touched the block but toppled nothing: swing harder', () => {
    expect(missWords(pass([-1.02, 0.5, 0]), 'the wall', 'Down')).toMatch(/^Missed: the ball touched the wall.*Pull farther/);
  });
  it('a ball that passed over the block: lower the hook, naming the control', () => {
    const w = missWords(pass([0, 2.5, 0]), 'the wall', 'Down');
    expect(w).toMatch(/^Missed: the ball passed 1\.0 m over the wall/);
    expect(w).toContain('Lower the hook (Down)');
  });
  it('a ball that stopped before the block: pull farther', () => {
    expect(missWords(pass([-3, 0.6, 0.2]), 'the tower', 'E')).toMatch(/^Missed: the ball stopped 2\.0 m short of the tower/);
  });
  it('a ball that went beside the block: the side as on the screen', () => {
    // Swinging along +x past the block at z = +2 (1.0 m gap): with the camera's right along +z the
    // ball went right of it; with the camera turned round (right along -z), left.
    expect(missWords(pass([0, 0.5, 2]), 'the crate', 'E')).toMatch(/^Missed: the ball passed 1\.0 m to the right of the crate\. Drag/);
    expect(missWords(pass([0, 0.5, 2], [0, -1]), 'the crate', 'E')).toMatch(/to the left of the crate/);
  });
});
