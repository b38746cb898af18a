/** Rounds to `digits` decimal places (keeps JSON lines short). Non-finite values pass through. */
export function round(value: number, digits: number): number {
  if (!Number.isFinite(value)) return value;
  const f = 10 ** digits;
  return Math.round(value * f) / f;
}

/** Rounds to `digits` significant digits. Zero and non-finite values pass through. */
export function sig(value: number, digits = 4): number {
  return Number.isFinite(value) && value !== 0 ? Number(value.toPrecision(digits)) : value;
}
