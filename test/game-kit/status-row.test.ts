// createStatusRow (packages/game-kit/src/status-row.ts) on a minimal stand-in for the DOM (./fake-dom.ts): the three
// lines in order with their data-hud names, role 'status', the style added once, and the DOM written
// only when the lines or the done mark change.
import { describe, expect, it } from 'vitest';
import { createStatusRow } from '../../packages/game-kit/src/status-row';
import { FakeDocument } from './fake-dom';

function setup() {
  const doc = new FakeDocument();
  const parent = doc.createElement('div');
  const row = createStatusRow({ name: 'hoop', parent: parent as unknown as HTMLElement });
  return { doc, parent, row, el: parent.children[0]! };
}

describe('createStatusRow', () => {
  it('appends a role=status row named by data-hud with goal, numbers and hint lines, in that order', () => {
    const { parent, row, el } = setup();
    expect(parent.children).toHaveLength(1);
    expect(row.element).toBe(el as unknown as HTMLElement);
    expect(el.attributes.get('role')).toBe('status');
    expect(el.dataset.hud).toBe('hoop');
    expect(el.children.map((c) => c.dataset.hud)).toEqual(['goal', 'numbers', 'hint']);
    row.set({ goal: 'Throw!', numbers: 'Baskets 0', hint: 'Drag to throw' });
    expect(el.children.map((c) => c.textContent)).toEqual(['Throw!', 'Baskets 0', 'Drag to throw']);
    expect(el.classes.has('bp-done')).toBe(false);
  });
  it('writes only on a change; done turns the goal green (class bp-done); the style is added once', () => {
    const { doc, parent, row, el } = setup();
    const lines = { goal: 'Time!', numbers: 'Baskets 3', hint: 'Play again' };
    expect(row.set(lines)).toBe(true);
    const writes = doc.writes;
    expect(row.set({ ...lines })).toBe(false);
    expect(doc.writes).toBe(writes);
    expect(row.set(lines, true)).toBe(true);
    expect(el.classes.has('bp-done')).toBe(true);
    expect(row.set({ ...lines, numbers: 'Baskets 4' }, true)).toBe(true);
    expect(row.numbers.textContent).toBe('Baskets 4');
    createStatusRow({ name: 'second', parent: parent as unknown as HTMLElement });
    expect(doc.head.children.filter((c) => c.tagName === 'style')).toHaveLength(1);
  });
  it('rejects an empty name, naming the function', () => {
    expect(() => createStatusRow({ name: '', parent: setup().parent as unknown as HTMLElement })).toThrow(/createStatusRow: name/);
  });
});
