// Lesson pages end to end (see lessons.mjs): { backends: ['webgpu'], extras: true }.
import { lessonTests } from './lessons.mjs';

lessonTests({ backends: ['webgpu'], extras: true });
