//! The course module's own bindings (built with the feature `course-module`): the grader of the
//! page's "Check my exercises" panel and the answers of the quizzes' numeric questions.
//!
//! The page loads two wasm modules (see `scripts/build`): the figures module (the figures, the
//! renderer, the cores) and the course module (the cores, the exercises, these bindings and
//! [`super::sandbox`]'s `runExercise`; no renderer). Student code runs in instances of the course
//! module only: the sandbox of `www/lesson.js` and the grading worker of `www/grade-worker.js`.
//! Keeping the graders (their cases, checks and messages) out of the figures module keeps the
//! module every page needs first small.

use crate::exercises::grade::{self, Known, KnownFailure, Report, Status};
use crate::exercises::run;
use wasm_bindgen::prelude::*;

#[wasm_bindgen]
extern "C" {
    /// `__inbetweenGradeCase(exercise, case)`: the grading worker's watchdog hears of each case.
    #[wasm_bindgen(catch, js_name = __inbetweenGradeCase)]
    fn grade_case(exercise: &str, case: u32) -> Result<JsValue, JsValue>;
}

/// The lessons whose exercises the page can grade (their folder names), in course order.
#[wasm_bindgen(js_name = gradedLessons)]
pub fn graded_lessons() -> Vec<String> {
    grade::LESSONS.iter().map(|l| l.id.to_string()).collect()
}

/// Grades the exercises of `lesson` (a folder name from [`graded_lessons`]) in this instance, for
/// the page's "Check my exercises" panel, which runs it in a worker (`www/grade-worker.js`).
/// `known` lists the failures earlier runs met (`[{ exercise, case, kind: "panicked", message,
/// location }]` or `kind: "stopped", seconds`): those rows are replayed, not run again. With
/// `watch` true, `__inbetweenGradeCase(exercise, case)` hears of each case before it runs.
/// Returns `{ rows: [{ exercise, verdict, text, … }], table }`, `table` being what
/// `scripts/grade` prints for the same reports. Cap: `known` holds at most [`MAX_KNOWN`] entries
/// (a run meets at most one failure per exercise), checked before any is read.
#[wasm_bindgen(js_name = gradeLesson)]
pub fn grade_lesson(lesson: JsValue, known: JsValue, watch: JsValue) -> Result<JsValue, JsError> {
    let id = super::string("lesson", &lesson)?;
    let lesson = grade::LESSONS
        .iter()
        .find(|l| l.id == id)
        .ok_or_else(|| JsError::new(&format!("lesson {id:?} has no exercises to grade")))?;
    let known = known_failures(&known)?;
    let watch = super::boolean("watch", &watch)?;
    let on_case: Option<grade::OnCase> = watch.then_some(|exercise, case| {
        let _ = grade_case(exercise, case as u32);
    });
    let reports = grade::grade_lesson_with(lesson, known, on_case);
    let rows = js_sys::Array::new();
    for report in &reports {
        rows.push(&row(report));
    }
    let out = js_sys::Object::new();
    set(&out, "rows", &rows);
    set(&out, "table", &grade::table(&reports).into());
    Ok(out.into())
}

/// The answer to a quiz's numeric question, computed by the core that `name` picks
/// ([`run::quiz_answer`]).
#[wasm_bindgen(js_name = quizAnswer)]
pub fn quiz_answer(name: JsValue, args: &[f32]) -> Result<f32, JsError> {
    let name = super::string("name", &name)?;
    run::quiz_answer(&name, args).map_err(|e| JsError::new(&e))
}

fn set(object: &js_sys::Object, key: &str, value: &JsValue) {
    let _ = js_sys::Reflect::set(object, &JsValue::from_str(key), value);
}

/// One report as a plain object: the verdict's fields by name, and `text`, its line in the table.
fn row(report: &Report) -> JsValue {
    let o = js_sys::Object::new();
    set(&o, "lesson", &report.lesson.into());
    set(&o, "exercise", &report.exercise.into());
    set(&o, "text", &report.status.to_string().into());
    let input = |pairs: &[(&str, String)]| -> JsValue {
        let list = js_sys::Array::new();
        for (name, value) in pairs {
            list.push(&js_sys::Array::of2(&(*name).into(), &value.into()));
        }
        list.into()
    };
    let verdict = match &report.status {
        Status::Passed { cases } => {
            set(&o, "cases", &(*cases as f64).into());
            "passed"
        }
        Status::NotDone => "not-done",
        Status::Wrong {
            case,
            what,
            input: i,
            list,
            expected,
            actual,
        } => {
            set(&o, "case", &(*case as f64).into());
            set(&o, "what", &what.into());
            set(&o, "input", &input(i));
            if let Some(list) = list {
                set(&o, "list", &list.into());
            }
            set(&o, "expected", &expected.into());
            set(&o, "actual", &actual.into());
            "wrong"
        }
        Status::Panicked {
            case,
            what,
            input: i,
            message,
            location,
        } => {
            set(&o, "case", &(*case as f64).into());
            set(&o, "what", &what.into());
            set(&o, "input", &input(i));
            set(&o, "message", &message.into());
            if let Some(at) = location {
                set(&o, "location", &at.into());
            }
            "panicked"
        }
        Status::Stopped {
            case,
            what,
            input: i,
            seconds,
        } => {
            set(&o, "case", &(*case as f64).into());
            set(&o, "what", &what.into());
            set(&o, "input", &input(i));
            set(&o, "seconds", &(*seconds as f64).into());
            "stopped"
        }
    };
    set(&o, "verdict", &verdict.into());
    o.into()
}

/// The most known failures [`grade_lesson`] takes: far more than a lesson has exercises (each
/// run adds at most one per exercise), so the replay's work stays small.
pub const MAX_KNOWN: usize = 1000;

/// `known` as the grader's [`Known`] failures; every field is checked before any is used.
fn known_failures(known: &JsValue) -> Result<Vec<Known>, JsError> {
    if known.is_undefined() || known.is_null() {
        return Ok(Vec::new());
    }
    if !js_sys::Array::is_array(known) {
        return Err(JsError::new(
            "known must be an array of { exercise, case, kind, … }",
        ));
    }
    let known = js_sys::Array::from(known);
    if known.length() as usize > MAX_KNOWN {
        return Err(JsError::new(&format!(
            "known may hold at most {MAX_KNOWN} failures, got {}",
            known.length()
        )));
    }
    let mut out = Vec::new();
    for (i, item) in known.iter().enumerate() {
        let field = |key: &str| {
            js_sys::Reflect::get(&item, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED)
        };
        let exercise = super::string(&format!("known[{i}].exercise"), &field("exercise"))?;
        let case_value = field("case").as_f64().unwrap_or(f64::NAN);
        let case = super::whole_in(&format!("known[{i}].case"), case_value, 1, super::MAX_WHOLE)?;
        let kind = super::string(&format!("known[{i}].kind"), &field("kind"))?;
        let failure = match kind.as_str() {
            "panicked" => KnownFailure::Panicked {
                message: super::string(&format!("known[{i}].message"), &field("message"))?,
                location: field("location").as_string(),
            },
            "stopped" => {
                let seconds = field("seconds").as_f64().unwrap_or(f64::NAN) as f32;
                let seconds =
                    super::in_range(&format!("known[{i}].seconds"), seconds, 0.001, 3600.0)?;
                KnownFailure::Stopped { seconds }
            }
            other => {
                return Err(JsError::new(&format!(
                    "known[{i}].kind must be \"panicked\" or \"stopped\", got {other:?}"
                )))
            }
        };
        out.push(Known {
            exercise,
            case,
            failure,
        });
    }
    Ok(out)
}
