//! What every lesson page's text must say, read from `lessons/*/index.html` natively.

use std::fs;
use std::path::Path;

/// A lesson with exercises tells the student both ways to grade them: the terminal command for
/// its own lesson (`./scripts/grade 12`, which `scripts/grade` takes as a lesson's number) and
/// the page's own "Check my exercises" button, which grades them without leaving the page.
#[test]
fn your_turn_names_the_lessons_grade_command_and_the_pages_button() {
    let lessons = Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons");
    let mut checked = 0;
    for entry in fs::read_dir(&lessons).expect("lessons/") {
        let dir = entry.expect("a lesson folder").path();
        let Ok(html) = fs::read_to_string(dir.join("index.html")) else { continue };
        if !html.contains("src/exercises/") {
            continue;
        }
        let folder = dir.file_name().unwrap().to_string_lossy().into_owned();
        let number = folder.split('-').next().unwrap();
        let command = format!("<code>./scripts/grade {number}</code>");
        assert!(html.contains(&command), "{folder}: its text never names {command}");
        assert!(
            html.contains("<em>Check my exercises</em>"),
            "{folder}: its text never points to the Check my exercises button"
        );
        checked += 1;
    }
    assert!(checked >= 15, "only {checked} lessons with exercises found");
}
