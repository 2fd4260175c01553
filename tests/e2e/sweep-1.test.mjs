// The lesson pages end to end, on both backends (see lessons.mjs): the first of two files that share
// them. Their names sort after every other e2e file's, so that `node --test` starts them last and
// the two finish together (they take the pages as they go).
import { lessonTests } from './lessons.mjs';

lessonTests({ part: 0, parts: 2 });
