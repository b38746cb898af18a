/**
 * Where a forecast tag ("Jupiter on day 427", "probe on day 427") goes on the solar system's map,
 * DOM-free so Node tests check it: the first of its places beside its point that is clear of the
 * tags already placed and of the names and dots; else the first of those places, or one stacked
 * under or over a tag already placed, that is clear of the tags; so two tags never overlap (the
 * names, placed after the tags, keep clear of them). Every place is moved inside the view first.
 */

/** A box on the screen: left, top, right, bottom, px. */
export type TagBox = readonly [number, number, number, number];

/** The view a tag is placed in: its size (px) and the least gap between a tag and its edges (px). */
export interface TagView {
  w: number;
  h: number;
  margin: number;
}

/**
 * The top-left corner (whole px) for a tag `tw` x `th` px among `places` (top-left corners, in order of
 * preference), each moved inside `view` (`view.margin` from its edges): the first clear of every box
 * in `tags` (the tags placed this frame) for which `free` (the names' and dots' test: true when the
 * box x0, y0, x1, y1 lies clear of them) is true; else the first of `places`, or of the places
 * stacked `gap` px under or over each of `tags` (centred on `cx`, the tag's point), clear of
 * `tags`; null when none is.
 * @throws RangeError on a tag size, gap or margin that is negative or not finite.
 */
export function tagPlace(
  places: readonly (readonly [number, number])[],
  tw: number,
  th: number,
  cx: number,
  view: TagView,
  tags: readonly TagBox[],
  free: (x0: number, y0: number, x1: number, y1: number) => boolean,
  gap: number,
): [number, number] | null {
  for (const [name, v] of [
    ['tw', tw],
    ['th', th],
    ['gap', gap],
    ['margin', view.margin],
  ] as const)
    if (!(v >= 0 && Number.isFinite(v))) throw new RangeError(`tagPlace: ${name} must be finite and >= 0, got ${v}`);
  const all: (readonly [number, number])[] = [...places];
  for (const b of tags) all.push([cx - tw / 2, b[3] + gap], [cx - tw / 2, b[1] - gap - th]);
  let fallback: [number, number] | null = null;
  for (let k = 0; k < all.length; k++) {
    // In whole pixels, as the tag is shown.
    const x = Math.round(Math.max(view.margin, Math.min(view.w - tw - view.margin, all[k]![0]))),
      y = Math.round(Math.max(view.margin, Math.min(view.h - th - view.margin, all[k]![1])));
    if (tags.some((b) => x < b[2] && x + tw > b[0] && y < b[3] && y + th > b[1])) continue;
    if (k < places.length && free(x, y, x + tw, y + th)) return [x, y];
    fallback ??= [x, y];
  }
  return fallback;
}
