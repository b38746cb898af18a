/**
 * The gallery page: reads registry.json (written by the build from each game's game.json) and lists
 * the games, the Games category first. A summary's first line says what a player does; a second
 * line, if any (after a newline), names the physics and is shown smaller beneath it.
 */

interface Entry {
  folder: string;
  title: string;
  summary: string;
  category: string;
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
    const heading = document.createElement('h2');
    heading.textContent = category;
    const grid = document.createElement('div');
    grid.className = 'grid';
    for (const e of list) {
      const card = document.createElement('a');
      card.className = 'card';
      card.href = `./${e.folder}/`;
      card.dataset.folder = e.folder;
      const img = document.createElement('img');
      img.src = `./${e.folder}/thumbnail.png`;
      img.alt = `${e.title}: screenshot`;
      img.loading = 'lazy';
      const text = document.createElement('div');
      text.className = 'text';
      const title = document.createElement('h3');
      title.textContent = e.title;
      const [play, ...physics] = e.summary.split('\n');
      const summary = document.createElement('p');
      summary.textContent = play ?? '';
      text.append(title, summary);
      if (physics.length > 0) {
        const more = document.createElement('p');
        more.className = 'physics';
        more.textContent = physics.join(' ');
        text.append(more);
      }
      card.append(img, text);
      grid.append(card);
    }
    root.append(heading, grid);
  }
  document.body.dataset.ready = 'true';
}

main().catch((error: unknown) => {
  console.error(error);
});
