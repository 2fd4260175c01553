//! Figure logic for this lesson (see `figures`): moved here from `web/curves.rs`.
