import './devloop.js';
// The lesson index: one card per lesson, grouped by part, from the catalog the build writes.
const catalog = await (await fetch('catalog.json')).json();
const root = document.getElementById('gallery');
const parts = [...new Set(catalog.map((l) => l.part))];
for (const part of parts) {
  const heading = document.createElement('h2');
  heading.textContent = part;
  const grid = document.createElement('div');
  grid.className = 'gallery';
  for (const lesson of catalog.filter((l) => l.part === part).sort((a, b) => a.order - b.order)) {
    const card = document.createElement('a');
    card.className = 'card';
    card.href = `${lesson.folder}/`;
    const image = lesson.hasThumbnail ? `<img alt="" src="${lesson.folder}/${lesson.thumbnail}">` : '<img alt="">';
    card.innerHTML = `${image}<div class="text"><h3></h3><p></p></div>`;
    card.querySelector('h3').textContent = lesson.title;
    card.querySelector('p').textContent = lesson.summary;
    grid.append(card);
  }
  root.append(heading, grid);
}
document.body.dataset.ready = '1';
