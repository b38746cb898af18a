// createHud (packages/game-kit/src/hud.ts) on a minimal stand-in for the DOM (./fake-dom.ts): the
// readout shows the frame rate and the pause line; the body and step counts sit in a closed
// "physics details" fold (Hud.details), named by their data-hud lines.
import { afterEach, describe, expect, it, vi } from 'vitest';
import { createHud } from '../../packages/game-kit/src/hud';
import { FakeDocument, type FakeElement } from './fake-dom';

afterEach(() => {
  vi.unstubAllGlobals();
});

describe('createHud', () => {
  it('keeps fps and the pause line in view and puts bodies and steps in a closed "physics details" fold', () => {
    const doc = new FakeDocument();
    vi.stubGlobal('document', doc);
    const parent = doc.createElement('div');
    const hud = createHud({ title: 'Test', controls: [], parent: parent as unknown as HTMLElement });
    hud.update(59.6, 12, 500, true);
    const readout = hud.readout as unknown as FakeElement;
    const top = readout.children.map((c) => c.dataset.hud ?? c.tagName);
    expect(top).toEqual(['h1', 'fps', 'status', 'physics']);
    const details = hud.details as unknown as FakeElement;
    expect(details).toBe(readout.children[3]);
    expect(details.tagName).toBe('details');
    // Closed: no open attribute or property set.
    expect(details.attributes.has('open')).toBe(false);
    expect((details as unknown as { open?: boolean }).open ?? false).toBe(false);
    expect(details.children.map((c) => c.tagName)).toEqual(['summary', 'div', 'div']);
    expect(details.children[0]!.textContent).toBe('physics details');
    expect(details.children.slice(1).map((c) => [c.dataset.hud, c.textContent])).toEqual([
      ['bodies', '12 bodies'],
      ['steps', 'step 500'],
    ]);
    expect(readout.children[1]!.textContent).toBe('60 fps');
    expect(readout.children[2]!.textContent).toBe('paused');
  });

  it('shows a dash, not "0 fps", before the frame rate is measured', () => {
    const doc = new FakeDocument();
    vi.stubGlobal('document', doc);
    const hud = createHud({ title: 'Test', controls: [], parent: doc.createElement('div') as unknown as HTMLElement });
    const fps = (hud.readout as unknown as FakeElement).children[1]!;
    expect(fps.textContent).toBe('– fps');
    hud.update(30.2, 0, 1, false);
    expect(fps.textContent).toBe('30 fps');
  });
});
