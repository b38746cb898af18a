/**
 * Import this module before anything that calls `Intl` with the browser's language: ./plot.ts
 * imports it before uPlot, and every page gets it first through ./page-errors.ts.
 *
 * uPlot builds `new Intl.NumberFormat(navigator.language)` when its module is evaluated. Chromium
 * started with a POSIX locale (LANG=C.UTF-8, as in headless containers) reports navigator.language
 * as 'en-US@posix', which Intl rejects with "RangeError: Invalid language tag", so a page that loads
 * uPlot would fail before it starts. When (and only when) the browser's language tag is one Intl
 * rejects, this shadows navigator.language (and navigator.languages) with the tag cut at its first
 * '@' or '.' ('en-US@posix' -> 'en-US'), or 'en-US' if that is still rejected.
 */

/** Whether `tag` is a language tag Intl accepts. */
export function languageTagIsValid(tag: string): boolean {
  try {
    new Intl.NumberFormat(tag);
    return true;
  } catch {
    return false;
  }
}

/** `tag` if Intl accepts it, else the part before '@' or '.' if Intl accepts that, else 'en-US'. */
export function usableLanguageTag(tag: string): string {
  if (languageTagIsValid(tag)) return tag;
  const base = tag.split(/[@.]/)[0] ?? '';
  return base && languageTagIsValid(base) ? base : 'en-US';
}

if (typeof navigator !== 'undefined' && !languageTagIsValid(navigator.language)) {
  const language = usableLanguageTag(navigator.language);
  const languages = Array.from(navigator.languages ?? [], usableLanguageTag);
  Object.defineProperty(navigator, 'language', { value: language, configurable: true });
  Object.defineProperty(navigator, 'languages', { value: Object.freeze(languages.length ? languages : [language]), configurable: true });
}
