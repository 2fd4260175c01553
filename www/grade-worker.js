// The "Check my exercises" panel's worker: grades one lesson's exercises in its own instance of
// the course module (src/web/course.rs, gradeLesson), off the page's thread, so that the
// page can stop an exercise that never returns by ending this worker (www/course.js).
//
// Messages in:  { module }                  the compiled module, once, first
//               { lesson, known, quiet }    grade; `known`: failures earlier workers met;
//                                           `quiet`: no console lines (the page's own check)
// Messages out: { kind: 'ready' }
//               { kind: 'case', exercise, case }       a case is about to run (the watchdog)
//               { kind: 'panic', message }             the student's code panicked; a trap follows
//               { kind: 'done', rows, table }
//               { kind: 'trapped', message }            the module trapped (after a panic)
//               { kind: 'error', message }              anything else that went wrong
import init, { gradeLesson } from '../pkg/course.js';

// The Rust panic hook (installed when the module starts) hands the message here before the trap.
globalThis.__inbetweenPanic = (message) => {
  postMessage({ kind: 'panic', message });
  return true;
};
// The grader calls this before each case (gradeLesson's `watch`).
globalThis.__inbetweenGradeCase = (exercise, c) => {
  postMessage({ kind: 'case', exercise, case: c });
};

let ready = null;
onmessage = async ({ data }) => {
  if (data.module) {
    ready = init({ module_or_path: data.module });
    try {
      await ready;
      postMessage({ kind: 'ready' });
    } catch (e) {
      postMessage({ kind: 'error', message: `could not start the grader: ${e?.message ?? e}` });
    }
    return;
  }
  // The check the page runs before its figures call an exercise (www/course.js,
  // checkExercises) reports in the figures' notes: the grader's console lines would be noise.
  if (data.quiet) console.error = () => {};
  try {
    await ready;
    const { rows, table } = gradeLesson(data.lesson, data.known ?? [], true);
    postMessage({ kind: 'done', rows, table });
  } catch (e) {
    const trapped = e instanceof WebAssembly.RuntimeError;
    postMessage({ kind: trapped ? 'trapped' : 'error', message: String(e?.message ?? e) });
  }
};
