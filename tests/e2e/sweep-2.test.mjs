// The lesson pages end to end, on both backends (see lessons.mjs): the second of two files that
// share them (see sweep-1.test.mjs).
import { lessonTests } from './lessons.mjs';

lessonTests({ part: 1, parts: 2 });
