// Lesson pages end to end (see lessons.mjs): { backends: ['webgl2'], part: 1, parts: 2 }.
import { lessonTests } from './lessons.mjs';

lessonTests({ backends: ['webgl2'], part: 1, parts: 2 });
