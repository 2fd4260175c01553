// Every lesson page in a browser without WebGPU or WebGL2, and forcing WebGPU where there is none
// (see lessons.mjs): the page must say so.
import { lessonTests } from './lessons.mjs';

lessonTests({ extras: true });
