import type { Page } from 'playwright-core';

/**
 * One finger on a touch screen, through the DevTools protocol (real touch events, as a phone sends
 * them): down at the first point (CSS px), moved through the others, held `ms` at the last, `during`
 * run while it is still down, then lifted.
 */
export async function touchPath(page: Page, points: Array<[number, number]>, ms: number, during?: () => Promise<void>): Promise<void> {
  const cdp = await page.context().newCDPSession(page);
  const at = ([x, y]: [number, number]) => [{ x, y, id: 1 }];
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(points[0]!) });
  for (const p of points.slice(1)) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(p) });
  await page.waitForTimeout(ms);
  await during?.();
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await cdp.detach();
}
