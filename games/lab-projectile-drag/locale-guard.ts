/**
 * Import this module before anything that imports uPlot (games/shared/plot.ts).
 *
 * uPlot builds `new Intl.NumberFormat(navigator.language)` when its module is evaluated. Chromium
 * started with a POSIX locale (LANG=C.UTF-8, as in the headless test containers) reports
 * navigator.language as 'en-US@posix', which Intl rejects with "RangeError: Invalid language tag",
 * so the whole page fails to load. When (and only when) the browser's language tag is one Intl
 * rejects, this shadows navigator.language with 'en-US' for the page.
 * Proper fix: pass `locale: 'en-US'` to the browser contexts of the test harness and the
 * thumbnail script, and/or guard the tag in games/shared/plot.ts (reported).
 */
function languageTagIsValid(tag: string): boolean {
  try {
    new Intl.NumberFormat(tag);
    return true;
  } catch {
    return false;
  }
}

if (typeof navigator !== 'undefined' && !languageTagIsValid(navigator.language)) {
  Object.defineProperty(navigator, 'language', { value: 'en-US', configurable: true });
}

export {};
