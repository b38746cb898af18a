// createDomResultCard (packages/game-kit/src/dom-result-card.ts) on a stand-in DOM (./fake-dom.ts):
// what a shown card holds and in which order, its buttons and key shortcut, focus, the ✕, removal,
// the errors on bad input, and, from its style sheet, 44 px touch targets and text contrast of at
// least 4.5:1 (WCAG 2 relative luminance, computed here) on its ground.
import { describe, expect, it } from 'vitest';
import { createDomResultCard, type DomResultCardContent, type DomResultCardOptions } from '../../packages/game-kit/src/dom-result-card';
import { FakeDocument, type FakeElement } from './fake-dom';

function setup(options: Partial<DomResultCardOptions> = {}) {
  const doc = new FakeDocument();
  const stage = doc.createElement('div');
  const card = createDomResultCard(stage as unknown as HTMLElement, { name: 'end', ...options });
  const el = card.element as unknown as FakeElement;
  const buttons = () => el.findAll((e) => e.tagName === 'button' && !e.classes.has('bp-result-close'));
  return { doc, stage, card, el, buttons };
}

/** A won round: 2 of 3 stars, a big line, three lines (one empty), Retry (R, bound by the game) and Next (Enter). */
function content(runs: string[], extra: Partial<DomResultCardContent> = {}): DomResultCardContent {
  return {
    title: 'All 5 pads!',
    stars: { earned: 2, outOf: 3 },
    big: '9 moves',
    lines: ['par 8', '', { text: 'New best!', className: 'record', strong: true }],
    buttons: [
      { label: 'Same pads', keyHint: 'R', action: 'retry', onPress: () => runs.push('retry') },
      { label: 'New pads', keyHint: 'Enter', key: 'Enter', action: 'next', primary: true, onPress: () => runs.push('next') },
    ],
    ...extra,
  };
}

describe('createDomResultCard', () => {
  it('adds a hidden dialog named by data-hud; shown, it holds the title, stars, big line, lines and buttons in order', () => {
    const { stage, card, el, buttons } = setup({ className: 'ss-card', passThrough: true, ariaLabel: 'flight result' });
    expect(stage.children).toEqual([el]);
    expect([el.dataset.hud, el.getAttribute('role'), el.getAttribute('aria-label'), el.hidden, card.shown]).toEqual([
      'end',
      'dialog',
      'flight result',
      true,
      false,
    ]);
    expect([...el.classes]).toEqual(['bp-result', 'bp-pass', 'ss-card']);
    card.show(content([]));
    expect(card.shown).toBe(true);
    expect(el.children.map((c) => [c.tagName, c.className])).toEqual([
      ['h2', ''],
      ['div', 'bp-result-stars'],
      ['div', 'bp-result-big'],
      ['div', 'bp-result-line'],
      ['div', 'bp-result-line bp-strong record'],
      ['div', 'bp-result-buttons'],
    ]);
    expect(el.children.slice(0, 5).map((c) => c.textContent)).toEqual(['All 5 pads!', '★★☆', '9 moves', 'par 8', 'New best!']);
    expect(el.children[1]!.children.map((s) => s.className)).toEqual(['', '', 'off']);
    expect(buttons().map((b) => [b.textContent, b.dataset.action, b.className, b.type])).toEqual([
      ['Same padsR', 'retry', '', 'button'],
      ['New padsEnter', 'next', 'bp-primary', 'button'],
    ]);
  });

  it('places a Node line as it is, and marks a lost round', () => {
    const { doc, card, el } = setup();
    const table = doc.createElement('table');
    card.show({ title: 'Missed Mars', lost: true, lines: ['near', table as unknown as Node] });
    expect(el.children[2]).toBe(table);
    expect(el.classes.has('bp-lost')).toBe(true);
    expect(el.findAll((e) => e.tagName === 'button')).toEqual([]);
  });

  it('a button runs its handler on a press; Enter runs Next once while shown, not hidden, not with Ctrl, not a repeat', () => {
    const { doc, card, buttons } = setup();
    const runs: string[] = [];
    card.show(content(runs));
    buttons()[0]!.fire('click', { detail: 0 });
    expect(buttons()[1]!.fire('pointerdown').stopped).toBe(true);
    const enter = doc.defaultView.fire('keydown', { key: 'Enter' });
    expect(enter).toEqual({ stopped: true, prevented: true });
    doc.defaultView.fire('keydown', { key: 'Enter', ctrlKey: true });
    doc.defaultView.fire('keydown', { key: 'Enter', repeat: true });
    expect(doc.defaultView.fire('keydown', { key: 'r' }).prevented).toBe(false);
    card.hide();
    doc.defaultView.fire('keydown', { key: 'Enter' });
    expect(runs).toEqual(['retry', 'next']);
  });

  it('the same words again are not written again, and the handlers last given run', () => {
    const { doc, card, buttons } = setup();
    const first: string[] = [],
      second: string[] = [];
    card.show(content(first));
    const writes = doc.writes;
    const before = buttons()[1];
    card.show(content(second));
    expect(doc.writes).toBe(writes);
    expect(buttons()[1]).toBe(before);
    buttons()[1]!.fire('click', { detail: 0 });
    expect([first, second]).toEqual([[], ['next']]);
  });

  it('focusOnShow focuses the primary button and gives focus back on hide; without it a focused button is blurred on hide', () => {
    const focusing = setup({ focusOnShow: true });
    const before = focusing.doc.createElement('canvas');
    before.focus();
    focusing.card.show(content([]));
    expect(focusing.doc.activeElement).toBe(focusing.buttons()[1]);
    focusing.card.hide();
    expect(focusing.doc.activeElement).toBe(before);
    const plain = setup();
    plain.card.show(content([]));
    expect(plain.doc.activeElement).toBe(plain.doc.body);
    plain.buttons()[0]!.focus();
    plain.card.hide();
    expect(plain.doc.activeElement).toBe(plain.doc.body);
  });

  it('the ✕ hides the card and then runs onClose', () => {
    const closed: boolean[] = [];
    const { card, el } = setup({ close: { ariaLabel: 'hide the result', onClose: () => closed.push(card.shown) } });
    card.show(content([]));
    const x = el.findAll((e) => e.classes.has('bp-result-close'))[0]!;
    expect([x.textContent, x.getAttribute('aria-label')]).toEqual(['✕', 'hide the result']);
    x.fire('click', { detail: 0 });
    expect([card.shown, closed]).toEqual([false, [false]]);
  });

  it('destroy removes the element and its key listener', () => {
    const { doc, stage, card } = setup();
    expect(doc.defaultView.listenerCount('keydown')).toBe(1);
    card.destroy();
    expect([stage.children.length, doc.defaultView.listenerCount('keydown')]).toEqual([0, 0]);
  });

  it('throws on bad input, naming the function, the parameter and the value', () => {
    const doc = new FakeDocument();
    const stage = doc.createElement('div') as unknown as HTMLElement;
    expect(() => createDomResultCard({} as HTMLElement, { name: 'x' })).toThrow(/createDomResultCard: parent .*\[object Object\]/);
    expect(() => createDomResultCard(stage, { name: '' })).toThrow(/createDomResultCard: options.name .*got $/);
    expect(() => createDomResultCard(stage, { name: 'x', titleSize: 60 })).toThrow(/createDomResultCard: options.titleSize .*got 60/);
    const card = createDomResultCard(stage, { name: 'x' });
    expect(() => card.show({ title: '' })).toThrow(/show: content.title .*got $/);
    expect(() => card.show({ title: 'T', stars: { earned: 4, outOf: 3 } })).toThrow(/show: content.stars .*got 4 of 3/);
    expect(() => card.show({ title: 'T', buttons: [{ label: '', onPress: () => {} }] })).toThrow(/show: a button's label .*got $/);
    expect(() => card.show({ title: 'T', buttons: [{ label: 'Go' } as never] })).toThrow(
      /show: button 'Go' needs an onPress function, got undefined/,
    );
  });

  it('its style sheet gives buttons 44 x 44 px and every text colour 4.5:1 or more on its ground', () => {
    const { doc } = setup();
    const css = doc.getElementById('bp-result-style')!.textContent;
    const button = /\.bp-result button \{([^}]*)\}/.exec(css)![1]!;
    expect(button).toMatch(/min-width: 44px/);
    expect(button).toMatch(/min-height: 44px/);
    /** WCAG 2 relative luminance of #rrggbb. */
    const luminance = (hex: string): number => {
      const [r, g, b] = [1, 3, 5].map((i) => {
        const c = Number.parseInt(hex.slice(i, i + 2), 16) / 255;
        return c <= 0.03928 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
      });
      return 0.2126 * r! + 0.7152 * g! + 0.0722 * b!;
    };
    const contrast = (a: string, b: string): number => {
      const [hi, lo] = [luminance(a), luminance(b)].sort((x, y) => y - x);
      return (hi! + 0.05) / (lo! + 0.05);
    };
    expect(css).toMatch(/background: rgb\(10, 14, 24\)/);
    const ground = '#0a0e18';
    // Text colours in the sheet (not border or background colours), and the defaults given as variables.
    const colours = [...css.matchAll(/(?<![-\w])color: (#[0-9a-f]{6})/g)].map((m) => m[1]!);
    expect(colours.length).toBeGreaterThanOrEqual(6);
    for (const c of [...colours, '#ffd166', '#ff8a7a']) expect(contrast(c, ground), c).toBeGreaterThanOrEqual(4.5);
    // The secondary button's white on its own ground, the primary's near-black on the default gold.
    expect(contrast('#ffffff', '#1d2738')).toBeGreaterThanOrEqual(4.5);
    expect(contrast('#1a1206', '#ffd166')).toBeGreaterThanOrEqual(4.5);
  });
});
