//! The grader: runs each exercise on many inputs and compares it with the reference core.
//!
//! It is plain Rust, so the same code grades natively (`tests/grader.rs`) and in headless Chromium
//! (`tests/web_grader.rs`). Inputs come from a fixed-seed generator, so a failure reproduces.

use super::Answer;
pub use crate::fixtures::Rng;
use glam::Mat4;
use std::fmt::{self, Debug};

/// The outcome of grading one exercise.
#[derive(Clone, Debug, PartialEq)]
pub enum Status {
    /// Every case matched the reference.
    Passed { cases: usize },
    /// The exercise still returns `Err(NotDone)`.
    NotDone,
    /// The first case whose answer differs from the reference.
    Wrong {
        /// The case's number, counting from 1 (as a student counts them).
        case: usize,
        /// What the case is meant to test ("keys with a·b < 0: the short arc").
        what: String,
        /// The case's arguments, each with the exercise's name for it: `("t", "0.5")`.
        input: Vec<(&'static str, String)>,
        /// For a list answer, where it is wrong: "index 17 first, 3 of 34 elements in all:
        /// expected …, actual …", or "the length: expected 34 elements, actual 33". `None` for
        /// an answer that is no list.
        list: Option<String>,
        /// The reference's answer; a long list shows the elements round the first wrong one.
        expected: String,
        /// The exercise's answer, shown as `expected` is.
        actual: String,
    },
    /// The exercise panicked (caught natively only: a wasm panic aborts the module).
    Panicked {
        /// The case's number, counting from 1.
        case: usize,
        what: String,
        input: Vec<(&'static str, String)>,
        message: String,
        /// Where it panicked, `file:line:column` (as the browser's report gives it).
        location: Option<String>,
    },
    /// The exercise gave no answer within the page's time limit (an endless loop, most likely).
    /// Only the page reports this: natively the grader would wait for ever.
    Stopped {
        /// The case's number, counting from 1.
        case: usize,
        what: String,
        input: Vec<(&'static str, String)>,
        /// The time limit it ran into, in seconds.
        seconds: f32,
    },
}

/// One row of the grade table.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    pub lesson: &'static str,
    pub exercise: &'static str,
    /// The names of the exercise's arguments, in the order of its signature (inputs only: an
    /// output slice the exercise fills is not an argument of a case).
    pub args: Vec<&'static str>,
    pub status: Status,
}

impl Report {
    pub fn passed(&self) -> bool {
        matches!(self.status, Status::Passed { .. })
    }
    pub fn not_done(&self) -> bool {
        self.status == Status::NotDone
    }
}

/// Where the grader's inputs come from: each lesson's generator starts from this seed mixed with
/// the lesson's id, so a lesson graded alone meets the very cases it meets in the whole table.
const SEED: u64 = 0x1b_e7_7e_e2;

/// A lesson's exercises: the lesson's id (its folder under `lessons/`), the exercise file that
/// holds them (`src/exercises/<file>.rs`) and the function that grades them.
pub struct Lesson {
    pub id: &'static str,
    pub file: &'static str,
    grade: fn(&mut Rng) -> Vec<Report>,
}

/// Every lesson with exercises, in course order. A new exercise file registers its lesson here.
pub const LESSONS: &[Lesson] = &[
    lesson("00-triangles-to-pixels", "raster", super::raster::grade),
    lesson("01-transforms", "transforms", super::transforms::grade),
    lesson("02-keyframes", "curves", super::curves::grade),
    lesson(
        "02b-expressive-animation",
        "expressive",
        super::expressive::grade,
    ),
    lesson(
        "03-rotations",
        "rotations",
        super::rotations::grade_rotations,
    ),
    lesson(
        "04-rigid-motions",
        "rotations",
        super::rotations::grade_rigid_motions,
    ),
    lesson("05-noise", "noise", super::noise::grade),
    lesson("06-skeletons", "skeleton", super::skeleton::grade),
    lesson("07-inverse-kinematics", "ik", super::ik::grade),
    lesson("08-blending", "blending", super::blending::grade),
    lesson("09-skinning", "skinning", super::skinning::grade),
    lesson(
        "10-blend-shapes",
        "blend_shapes",
        super::blend_shapes::grade,
    ),
    lesson("11-particles", "particles", super::particles::grade),
    lesson("12-boids", "boids", super::boids::grade),
    lesson("13-cloth", "cloth", super::cloth::grade),
    lesson("14-rigid-bodies", "rigid_body", super::rigid_body::grade),
    lesson("15-fluids", "fluid", super::fluid::grade),
];

/// A lesson of the grader: its id, its exercises' file and the function that grades them.
pub const fn lesson(
    id: &'static str,
    file: &'static str,
    grade: fn(&mut Rng) -> Vec<Report>,
) -> Lesson {
    Lesson { id, file, grade }
}

impl Lesson {
    /// Grades this lesson's exercises, with its own generator (see [`SEED`]).
    pub fn grade(&self) -> Vec<Report> {
        // FNV-1a of the id: a fixed, platform-independent hash (std's hasher may change).
        let hash = self.id.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
            (h ^ b as u64).wrapping_mul(0x0100_0000_01b3)
        });
        (self.grade)(&mut Rng::new(SEED ^ hash))
    }

    /// The number before the first `-` ("02b"), and the name after it ("expressive-animation").
    fn number_and_name(&self) -> (&'static str, &'static str) {
        self.id.split_once('-').unwrap_or((self.id, ""))
    }
}

/// Grades every exercise of every lesson.
pub fn grade_all() -> Vec<Report> {
    LESSONS.iter().flat_map(Lesson::grade).collect()
}

/// The lessons that `selector` names, for `scripts/grade LESSON`. A selector is a lesson's id
/// (`03-rotations`), its number (`03`, `3`, `2b`), its name (`rotations`), an exercise file's
/// name (`curves`: every lesson in that file) or the start of a name, at least three letters long
/// (`rigid`). The first of these kinds that matches anything decides, so `rotations` is lesson 03
/// alone although `rotations.rs` also holds lesson 04's exercises. An empty or blank selector
/// selects every lesson. A selector that matches nothing gets a message listing the lessons.
pub fn select_lessons(selector: &str) -> Result<Vec<&'static Lesson>, String> {
    let wanted = selector.trim().to_lowercase();
    if wanted.is_empty() {
        return Ok(LESSONS.iter().collect());
    }
    let number = |l: &Lesson| {
        let (n, _) = l.number_and_name();
        n == wanted || n.trim_start_matches('0') == wanted.trim_start_matches('0')
    };
    let kinds: [&dyn Fn(&Lesson) -> bool; 4] = [
        &|l| l.id == wanted || number(l) || l.number_and_name().1 == wanted,
        &|l| l.file == wanted,
        &|l| wanted.chars().count() >= 3 && l.number_and_name().1.starts_with(&wanted),
        &|l| wanted.chars().count() >= 3 && l.file.starts_with(&wanted),
    ];
    for matches in kinds {
        let found: Vec<&Lesson> = LESSONS.iter().filter(|l| matches(l)).collect();
        if !found.is_empty() {
            return Ok(found);
        }
    }
    let list: Vec<String> = LESSONS
        .iter()
        .map(|l| format!("  {:<26} (src/exercises/{}.rs)", l.id, l.file))
        .collect();
    Err(format!(
        "no lesson with exercises matches \"{}\". Name one by its number, its name or its \
         exercise file, e.g. `scripts/grade 03` or `scripts/grade rotations`; the lessons with \
         exercises are:\n{}",
        selector.trim(),
        list.join("\n")
    ))
}

/// Grades the lessons that `selector` names (see [`select_lessons`]).
pub fn grade_selected(selector: &str) -> Result<Vec<Report>, String> {
    Ok(select_lessons(selector)?
        .into_iter()
        .flat_map(Lesson::grade)
        .collect())
}

/// A failure that an earlier run in the page met and could not survive: a panic ends a wasm
/// module, and an endless loop has to be stopped from outside. The page grades again in a fresh
/// module with these known, so the exercise gets its row without running again and the others are
/// graded on the very same inputs (no case depends on an answer).
#[derive(Clone, Debug, PartialEq)]
pub struct Known {
    pub exercise: String,
    /// The case it happened at, counting from 1.
    pub case: usize,
    pub failure: KnownFailure,
}

#[derive(Clone, Debug, PartialEq)]
pub enum KnownFailure {
    Panicked {
        message: String,
        location: Option<String>,
    },
    Stopped {
        seconds: f32,
    },
}

/// Called with the exercise's name and the case's number before each case runs.
pub type OnCase = fn(exercise: &str, case: usize);

thread_local! {
    static KNOWN: std::cell::RefCell<Vec<Known>> = const { std::cell::RefCell::new(Vec::new()) };
    static ON_CASE: std::cell::Cell<Option<OnCase>> = const { std::cell::Cell::new(None) };
}

/// Grades `lesson` as [`Lesson::grade`] does, with the failures `known` from earlier runs
/// replayed instead of run, and `on_case` told of each case as it starts (the page's watchdog
/// uses it to say which case ran too long).
pub fn grade_lesson_with(
    lesson: &Lesson,
    known: Vec<Known>,
    on_case: Option<OnCase>,
) -> Vec<Report> {
    KNOWN.set(known);
    ON_CASE.set(on_case);
    let reports = lesson.grade();
    KNOWN.set(Vec::new());
    ON_CASE.set(None);
    reports
}

/// The row of an exercise whose failure is known (see [`Known`]), if it is.
fn replayed<I: Args<N>, const N: usize>(
    exercise: &'static str,
    args: [&'static str; N],
    cases: &[(&str, I)],
) -> Option<Status> {
    let known = KNOWN.with_borrow(|all| all.iter().find(|k| k.exercise == exercise).cloned())?;
    let (what, input) = cases.get(known.case.checked_sub(1)?)?;
    let (what, input) = (what.to_string(), named(args, input));
    let case = known.case;
    Some(match known.failure {
        KnownFailure::Panicked { message, location } => Status::Panicked {
            case,
            what,
            input,
            message,
            location,
        },
        KnownFailure::Stopped { seconds } => Status::Stopped {
            case,
            what,
            input,
            seconds,
        },
    })
}

/// The `student-bugs` build's mistakes (or, in a build with debug assertions, those of
/// [`super::with_student_bugs`]), in the grader as in the figures (see `run::student_bugs`):
/// slerp panics, the Rodrigues matrix comes out transposed, the middle
/// vertex normal is reversed, and in the browser `polar_step` never returns (the page's time limit must stop it; natively it is left
/// alone, since nothing could stop it there).
#[cfg(any(feature = "student-bugs", debug_assertions))]
fn planted_mistakes<O: 'static>(exercise: &str, answer: Answer<O>) -> Answer<O> {
    use std::any::Any;
    if !super::student_bugs_on() {
        return answer;
    }
    let mut answer = answer;
    match exercise {
        "slerp" => {
            let _ = super::run::student_bugs("slerp", &[0.0; 9]);
        }
        "rodrigues_matrix" => {
            if let Some(Ok(m)) = (&mut answer as &mut dyn Any).downcast_mut::<Answer<glam::Mat3>>()
            {
                *m = m.transpose();
            }
        }
        "vertex_normals" => {
            let normals = (&mut answer as &mut dyn Any).downcast_mut::<Answer<Vec<glam::Vec3>>>();
            if let Some(Ok(normals)) = normals {
                super::run::reverse_middle_normal(normals);
            }
        }
        #[cfg(target_arch = "wasm32")]
        "polar_step" => loop {
            std::hint::black_box(&answer);
        },
        _ => {}
    }
    answer
}

#[cfg(not(any(feature = "student-bugs", debug_assertions)))]
fn planted_mistakes<O>(_exercise: &str, answer: Answer<O>) -> Answer<O> {
    answer
}

/// What a case of random inputs is said to test.
pub const RANDOM: &str = "random input";

/// A case's input split into the exercise's arguments, so that a report can name each one
/// (`x = Vec3(…), k = 50.0`). Implemented for tuples of up to eight arguments and for the
/// single values that exercises take alone; `N` is the number of arguments, so a list of names of
/// another length does not compile.
pub trait Args<const N: usize> {
    /// Each argument as `{:?}` shows it.
    fn shown(&self) -> [String; N];
}

macro_rules! tuple_args {
    ($n:literal: $($t:ident $i:tt),+) => {
        impl<$($t: Debug),+> Args<$n> for ($($t,)+) {
            fn shown(&self) -> [String; $n] {
                [$(format!("{:?}", self.$i)),+]
            }
        }
    };
}
tuple_args!(1: A 0);
tuple_args!(2: A 0, B 1);
tuple_args!(3: A 0, B 1, C 2);
tuple_args!(4: A 0, B 1, C 2, D 3);
tuple_args!(5: A 0, B 1, C 2, D 3, E 4);
tuple_args!(6: A 0, B 1, C 2, D 3, E 4, F 5);
tuple_args!(7: A 0, B 1, C 2, D 3, E 4, F 5, G 6);
tuple_args!(8: A 0, B 1, C 2, D 3, E 4, F 5, G 6, H 7);

macro_rules! single_args {
    ($($t:ty),+) => {
        $(impl Args<1> for $t {
            fn shown(&self) -> [String; 1] {
                [format!("{self:?}")]
            }
        })+
    };
}
single_args!(
    f32,
    i32,
    u32,
    usize,
    glam::Vec2,
    glam::Vec3,
    glam::Quat,
    glam::Mat3,
    Mat4
);

/// Pairs each argument with its name.
fn named<I: Args<N>, const N: usize>(
    names: [&'static str; N],
    input: &I,
) -> Vec<(&'static str, String)> {
    names.into_iter().zip(input.shown()).collect()
}

/// Runs `student` and `reference` on each input; the first disagreement (by `close`) fails.
/// `args` names the exercise's arguments, in the order of the input tuple. Every case counts as
/// [`RANDOM`]; [`check_cases`] says what each edge case tests.
pub fn check<I: Args<N>, O: Debug + 'static, const N: usize>(
    lesson: &'static str,
    exercise: &'static str,
    args: [&'static str; N],
    inputs: &[I],
    student: impl Fn(&I) -> Answer<O>,
    reference: impl Fn(&I) -> O,
    close: impl Fn(&O, &O) -> bool,
) -> Report {
    let cases: Vec<(&str, &I)> = inputs.iter().map(|i| (RANDOM, i)).collect();
    check_cases(
        lesson,
        exercise,
        args,
        &cases,
        |i| student(i),
        |i| reference(i),
        close,
    )
}

/// References to arguments show as the arguments (so [`check`] can pass its inputs by reference).
impl<I: Args<N>, const N: usize> Args<N> for &I {
    fn shown(&self) -> [String; N] {
        (*self).shown()
    }
}

/// Like [`check`], with each input paired with what it tests, e.g.
/// `("keys with a·b < 0: the short arc", input)`, so that a wrong answer says what it got wrong.
pub fn check_cases<I: Args<N>, O: Debug + 'static, const N: usize>(
    lesson: &'static str,
    exercise: &'static str,
    args: [&'static str; N],
    cases: &[(&str, I)],
    student: impl Fn(&I) -> Answer<O>,
    reference: impl Fn(&I) -> O,
    close: impl Fn(&O, &O) -> bool,
) -> Report {
    grade_cases(lesson, exercise, args, cases, student, reference, |e, a| {
        (!close(e, a)).then(|| (None, format!("{e:?}"), format!("{a:?}")))
    })
}

/// Like [`check_cases`], for an exercise whose answer is a list: `close` compares two elements,
/// and the lists match when they have the same length and every element is close. A wrong answer
/// names its first wrong element (its index, both values) and how many are wrong, or says that
/// the lengths differ; a long list shows the elements round the first wrong one (see
/// [`Status::Wrong`]).
pub fn check_list_cases<I: Args<N>, T: Debug + 'static, const N: usize>(
    lesson: &'static str,
    exercise: &'static str,
    args: [&'static str; N],
    cases: &[(&str, I)],
    student: impl Fn(&I) -> Answer<Vec<T>>,
    reference: impl Fn(&I) -> Vec<T>,
    close: impl Fn(&T, &T) -> bool,
) -> Report {
    grade_cases(lesson, exercise, args, cases, student, reference, |e, a| {
        let wrong: Vec<usize> = (0..e.len().min(a.len()))
            .filter(|&i| !close(&e[i], &a[i]))
            .collect();
        let (at, list) = if e.len() != a.len() {
            let at = wrong.first().copied().unwrap_or(e.len().min(a.len()));
            let list = format!(
                "the length: expected {} elements, actual {}",
                e.len(),
                a.len()
            );
            (at, list)
        } else {
            let &at = wrong.first()?;
            let list = format!(
                "index {at} first, {} of {} elements in all: expected {:?}, actual {:?}",
                wrong.len(),
                e.len(),
                e[at],
                a[at]
            );
            (at, list)
        };
        Some((Some(list), shown_round(e, at), shown_round(a, at)))
    })
}

/// A list as `{:?}` shows it or, when it is long, the few elements round index `at` with how many
/// are left out before and after them: `[… 15 before, Vec3(…), …, … 14 after]`.
fn shown_round<T: Debug>(list: &[T], at: usize) -> String {
    const SHOWN: usize = 5;
    if list.len() <= SHOWN + 2 {
        return format!("{list:?}");
    }
    let start = at.saturating_sub(SHOWN / 2).min(list.len() - SHOWN);
    let end = start + SHOWN;
    let mut parts: Vec<String> = list[start..end].iter().map(|x| format!("{x:?}")).collect();
    if start > 0 {
        parts.insert(0, format!("… {start} before"));
    }
    if end < list.len() {
        parts.push(format!("… {} after", list.len() - end));
    }
    format!("[{}]", parts.join(", "))
}

/// What [`check_cases`] and [`check_list_cases`] share: runs each case, and `wrong` compares the
/// reference's answer with the exercise's, giving `None` when they match, else what
/// [`Status::Wrong`] shows (`list`, `expected`, `actual`).
#[allow(clippy::type_complexity)]
fn grade_cases<I: Args<N>, O: 'static, const N: usize>(
    lesson: &'static str,
    exercise: &'static str,
    args: [&'static str; N],
    cases: &[(&str, I)],
    student: impl Fn(&I) -> Answer<O>,
    reference: impl Fn(&I) -> O,
    wrong: impl Fn(&O, &O) -> Option<(Option<String>, String, String)>,
) -> Report {
    let status = (|| {
        if let Some(status) = replayed(exercise, args, cases) {
            return status;
        }
        // Numbered from 1: "WRONG at case 1" is the first case a student would count.
        for (case, (what, input)) in (1..).zip(cases) {
            let context = || format!("exercise {exercise} ({lesson}), case {case} ({what})");
            if let Some(on_case) = ON_CASE.get() {
                on_case(exercise, case);
            }
            let answer = match run_caught(context, || planted_mistakes(exercise, student(input))) {
                Ok(answer) => answer,
                Err(Caught { message, location }) => {
                    return Status::Panicked {
                        case,
                        what: what.to_string(),
                        input: named(args, input),
                        message,
                        location,
                    };
                }
            };
            let Ok(actual) = answer else {
                return Status::NotDone;
            };
            if let Some((list, expected, actual)) = wrong(&reference(input), &actual) {
                return Status::Wrong {
                    case,
                    what: what.to_string(),
                    input: named(args, input),
                    list,
                    expected,
                    actual,
                };
            }
        }
        Status::Passed { cases: cases.len() }
    })();
    Report {
        lesson,
        exercise,
        args: args.to_vec(),
        status,
    }
}

/// A caught panic: its message and where it happened.
struct Caught {
    message: String,
    location: Option<String>,
}

/// Runs `f`, catching a panic. `catch_unwind` gives only the payload (the message); the location
/// is known only to the panic hook, so while `f` runs a hook records it for this thread (and
/// prints nothing: the report says it all), handing other threads' panics to the hook that was
/// there. That very hook is put back afterwards (not wrapped, so grading many cases does not
/// chain hooks). Hooks are global: one grading call at a time swaps them, so parallel tests put
/// the right one back.
#[cfg(not(target_arch = "wasm32"))]
fn run_caught<T>(_context: impl Fn() -> String, f: impl FnOnce() -> T) -> Result<T, Caught> {
    use std::panic::{self, PanicHookInfo};
    use std::sync::{Arc, Mutex};
    type Hook = Box<dyn Fn(&PanicHookInfo<'_>) + Send + Sync + 'static>;
    static SWAPPING: Mutex<()> = Mutex::new(());
    let _one_at_a_time = SWAPPING.lock().unwrap_or_else(|e| e.into_inner());
    let previous: Arc<Mutex<Option<Hook>>> = Arc::new(Mutex::new(Some(panic::take_hook())));
    let location = Arc::new(Mutex::new(None::<String>));
    let (seen, chained) = (location.clone(), previous.clone());
    let grading = std::thread::current().id();
    panic::set_hook(Box::new(move |info| {
        if std::thread::current().id() == grading {
            let at = info
                .location()
                .map(|l| format!("{}:{}:{}", l.file(), l.line(), l.column()));
            *seen.lock().unwrap_or_else(|e| e.into_inner()) = at;
        } else if let Some(hook) = chained.lock().unwrap_or_else(|e| e.into_inner()).as_ref() {
            hook(info);
        }
    }));
    let result = panic::catch_unwind(panic::AssertUnwindSafe(f));
    // Dropping the grading hook drops its handle on `previous`.
    drop(panic::take_hook());
    let hook = previous.lock().unwrap_or_else(|e| e.into_inner()).take();
    if let Some(hook) = hook {
        panic::set_hook(hook);
    }
    result.map_err(|payload| Caught {
        message: payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "panic".to_string()),
        location: location.lock().unwrap_or_else(|e| e.into_inner()).take(),
    })
}

/// In wasm a panic cannot be caught: it ends the module. While the student's code runs, a panic
/// hook first says, in one line, which exercise and case panicked and what to do, then hands over
/// to the hook that was there (the test runner's).
#[cfg(target_arch = "wasm32")]
fn run_caught<T>(context: impl Fn() -> String, f: impl FnOnce() -> T) -> Result<T, Caught> {
    use std::panic::PanicHookInfo;
    use std::sync::{Arc, Mutex};
    type Hook = Box<dyn Fn(&PanicHookInfo<'_>) + Send + Sync + 'static>;
    let previous: Arc<Mutex<Option<Hook>>> = Arc::new(Mutex::new(Some(std::panic::take_hook())));
    let context = context();
    let chained = previous.clone();
    std::panic::set_hook(Box::new(move |info| {
        let message = format!(
            "Your {context} panicked: {info}\nA WebAssembly module cannot continue after a panic: \
             the page's Check my exercises panel grades the rest in a fresh module, `scripts/grade \
             --browser` stops here, and `scripts/grade` (native) reports it as PANICKED and grades \
             the other exercises."
        );
        web_sys::console::error_1(&message.into());
        if let Some(hook) = chained.lock().unwrap_or_else(|e| e.into_inner()).as_ref() {
            hook(info);
        }
    }));
    let answer = f();
    // Put back the very hook that was there (see the native `run_caught`).
    drop(std::panic::take_hook());
    let hook = previous.lock().unwrap_or_else(|e| e.into_inner()).take();
    if let Some(hook) = hook {
        std::panic::set_hook(hook);
    }
    Ok(answer)
}

/// Element-wise comparison with a tolerance scaled by the larger magnitude.
pub fn mat4_close(a: &Mat4, b: &Mat4, eps: f32) -> bool {
    a.to_cols_array()
        .iter()
        .zip(b.to_cols_array().iter())
        .all(|(x, y)| (x - y).abs() <= eps * (1.0 + x.abs().max(y.abs())))
}

/// The grade table, one row per exercise, then a summary line.
pub fn table(reports: &[Report]) -> String {
    let mut out = String::new();
    let w_lesson = reports
        .iter()
        .map(|r| r.lesson.len())
        .max()
        .unwrap_or(0)
        .max(6);
    let w_ex = reports
        .iter()
        .map(|r| r.exercise.len())
        .max()
        .unwrap_or(0)
        .max(8);
    out += &format!("{:<w_lesson$}  {:<w_ex$}  status\n", "lesson", "exercise");
    out += &format!("{}\n", "-".repeat(w_lesson + w_ex + 30));
    for r in reports {
        out += &format!(
            "{:<w_lesson$}  {:<w_ex$}  {}\n",
            r.lesson, r.exercise, r.status
        );
    }
    let count = |f: fn(&Status) -> bool| reports.iter().filter(|r| f(&r.status)).count();
    let passed = count(|s| matches!(s, Status::Passed { .. }));
    let todo = count(|s| *s == Status::NotDone);
    // A panic and a stop are counted apart from wrong answers (as the page's summary does),
    // and named only when there are any.
    let panicked = count(|s| matches!(s, Status::Panicked { .. }));
    let stopped = count(|s| matches!(s, Status::Stopped { .. }));
    let wrong = reports.len() - passed - todo - panicked - stopped;
    let mut line = format!("{passed} passed, {todo} not yet implemented, {wrong} wrong");
    for (n, what) in [(panicked, "panicked"), (stopped, "stopped")] {
        if n > 0 {
            line += &format!(", {n} {what}");
        }
    }
    out += &format!("\n{line}, of {}\n", reports.len());
    out
}

impl fmt::Display for Status {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Status::Passed { cases } => write!(f, "passed ({cases} cases)"),
            Status::NotDone => write!(f, "not yet implemented"),
            Status::Wrong { case, what, input, list, expected, actual } => write!(
                f,
                "WRONG at case {case} ({what})\n      input:    {}{}\n      expected: {expected}\n      actual:   {actual}",
                show_input(input),
                list.as_ref().map_or(String::new(), |l| format!("\n      wrong:    {l}"))
            ),
            Status::Stopped { case, what, input, seconds } => write!(
                f,
                "STOPPED at case {case} ({what}): no answer within {seconds} s (an endless loop?)\n      input:    {}",
                show_input(input)
            ),
            Status::Panicked { case, what, input, message, location } => write!(
                f,
                "PANICKED at case {case} ({what}): {message}{}\n      input:    {}",
                location.as_ref().map_or(String::new(), |at| format!(" ({at})")),
                show_input(input)
            ),
        }
    }
}

/// A case's arguments as `name = value`, on one line when they fit in about a terminal's width,
/// otherwise one per line, each under the first.
fn show_input(input: &[(&str, String)]) -> String {
    let parts: Vec<String> = input
        .iter()
        .map(|(name, value)| format!("{name} = {value}"))
        .collect();
    let one_line = parts.join(", ");
    if one_line.chars().count() <= 80 {
        one_line
    } else {
        parts.join(&format!("\n{:16}", ""))
    }
}
