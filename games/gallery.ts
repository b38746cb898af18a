/**
 * The gallery page: reads registry.json (written by the build from each game's game.json) and lists
 * the pages by category, the games first, each as a card with a screenshot of it in play, its title
 * and one sentence of what you can do there (./gallery-cards; else the first line of its summary).
 * The first games are shown larger. DOM only.
 */
import { CARD_LINES, SECTIONS } from './gallery-cards';

interface Entry {
  folder: string;
  title: string;
  summary: string;
  category: string;
}

/** Games shown as large cards at the top of their section. */
const FEATURED = 3;

/**
 * Fills the bands round a screenshot not of the card's 16:10 shape (the card shows it whole:
 * object-fit contain, gallery.css) with its own edge colours: the mean of its top row above it and
 * of its bottom row below (left and right columns beside a narrow one), so they read as more sky or
 * ground rather than bars. A screenshot of 16:10 is left as it is.
 */
function matchEdges(img: HTMLImageElement): void {
  const w = img.naturalWidth,
    h = img.naturalHeight;
  if (!(w > 0 && h > 0) || Math.abs(w / h - 1.6) < 0.02) return;
  const c = document.createElement('canvas');
  c.width = w;
  c.height = h;
  const g = c.getContext('2d', { willReadFrequently: true });
  if (!g) return;
  g.drawImage(img, 0, 0);
  const wide = w / h > 1.6;
  const mean = (x: number, y: number, cw: number, ch: number): string => {
    const d = g.getImageData(x, y, cw, ch).data;
    let r = 0,
      gr = 0,
      b = 0;
    for (let k = 0; k < d.length; k += 4) {
      r += d[k]!;
      gr += d[k + 1]!;
      b += d[k + 2]!;
    }
    const n = d.length / 4;
    return `rgb(${Math.round(r / n)}, ${Math.round(gr / n)}, ${Math.round(b / n)})`;
  };
  const [first, last] = wide ? [mean(0, 0, w, 2), mean(0, h - 2, w, 2)] : [mean(0, 0, 2, h), mean(w - 2, 0, 2, h)];
  img.style.background = `linear-gradient(${wide ? 'to bottom' : 'to right'}, ${first} 50%, ${last} 50%)`;
}

/** A card linking to `e`: screenshot, title, one line. */
function card(e: Entry, featured: boolean): HTMLAnchorElement {
  const a = document.createElement('a');
  a.className = featured ? 'card featured' : 'card';
  a.href = `./${e.folder}/`;
  a.dataset.folder = e.folder;
  const img = document.createElement('img');
  img.src = `./${e.folder}/thumbnail.png`;
  img.alt = `${e.title}: screenshot`;
  img.loading = featured ? 'eager' : 'lazy';
  img.addEventListener('load', () => matchEdges(img), { once: true });
  const text = document.createElement('div');
  text.className = 'text';
  const title = document.createElement('h3');
  title.textContent = e.title;
  const line = document.createElement('p');
  line.textContent = CARD_LINES[e.folder] ?? e.summary.split('\n')[0] ?? '';
  text.append(title, line);
  a.append(img, text);
  return a;
}

async function main(): Promise<void> {
  const root = document.getElementById('gallery');
  if (!root) throw new Error('gallery: #gallery element missing');
  const response = await fetch('./registry.json');
  if (!response.ok) throw new Error(`gallery: registry.json answered ${response.status}`);
  const entries = (await response.json()) as Entry[];
  const byCategory = new Map<string, Entry[]>();
  for (const e of entries) {
    const list = byCategory.get(e.category) ?? [];
    list.push(e);
    byCategory.set(e.category, list);
  }
  for (const [category, list] of byCategory) {
    const section = document.createElement('section');
    section.dataset.category = category;
    const heading = document.createElement('h2');
    const about = SECTIONS[category];
    heading.textContent = about?.title ?? category;
    section.append(heading);
    if (about) {
      const line = document.createElement('p');
      line.className = 'section-line';
      line.textContent = about.line;
      section.append(line);
    }
    const games = category === 'Games';
    if (games) {
      const top = document.createElement('div');
      top.className = 'grid featured-grid';
      for (const e of list.slice(0, FEATURED)) top.append(card(e, true));
      section.append(top);
    }
    const grid = document.createElement('div');
    grid.className = 'grid';
    for (const e of games ? list.slice(FEATURED) : list) grid.append(card(e, false));
    section.append(grid);
    root.append(section);
  }
  document.body.dataset.ready = 'true';
}

main().catch((error: unknown) => {
  console.error(error);
});
