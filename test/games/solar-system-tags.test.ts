/**
 * Solar system's forecast tags on the map (games/solar-system/tag-place.ts), headless: where the
 * target's tag and the probe's meet (the probe's forecast end at the target's place then, zoomed on
 * Jupiter, or on a phone's small map), the second tag never lies over the first.
 */
import { describe, expect, it } from 'vitest';
import { type TagBox, tagPlace } from '../../games/solar-system/tag-place';

/** Whether boxes a and b (left, top, right, bottom) overlap. */
const overlap = (a: TagBox, b: TagBox) => a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
/** The places the page tries for a tag `tw` x `th` px by point (sx, sy), `off` px under it first (main.ts placeTag). */
const placesBy = (sx: number, sy: number, tw: number, th: number, off: number): [number, number][] => [
  [sx - tw / 2, sy + off],
  [sx - tw / 2, sy - off - th],
  [sx + Math.max(8, off * 0.7), sy - th / 2],
  [sx - Math.max(8, off * 0.7) - tw, sy - th / 2],
];

describe('solar system forecast tags (tag-place.ts)', () => {
  // A phone's map, 390 x 570 px; tags 16 px tall, 6 px from the edges.
  const view = { w: 390, h: 570, margin: 6 };
  it('a second tag by the same point, every place crowded by names, is stacked clear of the first', () => {
    // "Jupiter on day 427" (126 px) placed under its point (200, 100); "probe on day 427" (116 px)
    // for a point 3 px away, with names all round (free is false everywhere): the page kept its
    // first place, over the first tag (116 x 13 px of it).
    const first: TagBox = [137, 112, 263, 128];
    const crowded = () => false;
    const at = tagPlace(placesBy(203, 103, 116, 16, 12), 116, 16, 203, view, [first], crowded, 2);
    expect(at).not.toBeNull();
    const [x, y] = at!;
    expect(overlap([x, y, x + 116, y + 16], first)).toBe(false);
    // Over its point (the first place clear of the tag), not far off.
    expect([x, y]).toEqual([145, 75]);
  });
  it('stacks under or over the first tag where none of its own places clears it', () => {
    // The first tag wide across the view's top; the second's point at the top edge, right of it:
    // its places are all pulled onto the first, so it goes under the first, 2 px from it.
    const first: TagBox = [6, 6, 384, 22];
    const at = tagPlace(placesBy(300, 8, 100, 16, 4), 100, 16, 300, view, [first], () => true, 2);
    expect(at).toEqual([250, 24]);
  });
  it('takes the first place clear of tags, names and dots, kept inside the view', () => {
    expect(tagPlace(placesBy(200, 300, 80, 16, 12), 80, 16, 200, view, [], () => true, 2)).toEqual([160, 312]);
    // At the right edge the place is moved in to 6 px from it.
    expect(tagPlace(placesBy(380, 300, 80, 16, 12), 80, 16, 380, view, [], () => true, 2)).toEqual([304, 312]);
  });
  it('throws on a negative size, gap or margin', () => {
    expect(() => tagPlace([], -1, 16, 0, view, [], () => true, 2)).toThrow(/tagPlace: tw/);
    expect(() => tagPlace([], 10, 16, 0, { ...view, margin: -1 }, [], () => true, 2)).toThrow(/tagPlace: margin/);
  });
});
