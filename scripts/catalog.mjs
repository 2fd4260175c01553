// Writes dist/lessons/catalog.json (the gallery's list, from each lesson's meta.json) and copies
// the source files that lessons show into dist/source/ (into $INBETWEEN_DIST instead of dist/ when
// set, as scripts/build does).
import { readdirSync, readFileSync, writeFileSync, mkdirSync, copyFileSync, existsSync } from 'node:fs';
import { dirname, join } from 'node:path';

const dist = process.env.INBETWEEN_DIST ?? 'dist';
const catalog = [];
for (const folder of readdirSync('lessons').sort()) {
  const metaPath = join('lessons', folder, 'meta.json');
  if (!existsSync(metaPath)) continue;
  const meta = JSON.parse(readFileSync(metaPath, 'utf8'));
  for (const key of ['title', 'summary', 'part', 'order']) {
    if (meta[key] === undefined) throw new Error(`${metaPath} lacks "${key}"`);
  }
  // A lesson without a thumbnail yet (THUMBNAILS=1 node --test tests/e2e/ makes one) gets a placeholder.
  const hasThumbnail = Boolean(meta.thumbnail) && existsSync(join('lessons', folder, meta.thumbnail));
  catalog.push({ folder, ...meta, hasThumbnail });
  for (const { path } of meta.sources ?? []) {
    if (!existsSync(path)) throw new Error(`${metaPath} lists ${path}, which does not exist`);
    mkdirSync(dirname(join(dist, 'source', path)), { recursive: true });
    copyFileSync(path, join(dist, 'source', path));
  }
}
// The gallery lists lessons by their `order` (fractional orders slot a lesson between two others).
catalog.sort((a, b) => a.order - b.order);
writeFileSync(join(dist, 'lessons', 'catalog.json'), JSON.stringify(catalog, null, 2));
