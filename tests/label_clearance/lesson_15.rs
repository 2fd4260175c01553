//! Lesson 15: its figures' labels keep clear of what they name (see main.rs).

use super::*;

#[test]
fn lesson_15_dragged_particle_is_named_off_the_water() {
    // Figure 2 at its page camera (lessons/15-fluids/lesson.js), both canvases, the dragged
    // particle in the water (the page's start and deeper), at its surface, above it and in a
    // corner: its name is shown where the figure put it, 2 px off every line and dot (the
    // support circle, the lines to the neighbours, the arrows), over none of the particles, and
    // within 60 px of the support circle and within the page's leader distance of its anchor
    // or, deep in the water, just above its surface, at most 160 px to the side (in a corner the
    // wall keeps it off the middle). As on the page, the figure places the name for the view of
    // the frame before (set_view).
    use inbetween::figures::fluid::DensityFigure;
    let view = [0.8, 0.5, 0.0, 2.6, 0.0, 0.0];
    let mut failures = Vec::new();
    for (x, y) in [(0.8, 0.2), (0.8, 0.05), (0.3, 0.3), (0.318, 0.79), (1.55, 0.02), (0.05, 0.4)] {
        for size in CANVASES {
            let mut f = DensityFigure::new();
            f.set_probe(x, y).unwrap();
            let (frame, camera) = drawn!(&mut f, view, size);
            let name = format!("15 density, particle at ({x}, {y})");
            let view_proj = camera.projection(size.x / size.y) * camera.view();
            let check = || {
                let placed = layout(&frame, &camera, size);
                assert_eq!(placed.len(), 1, "{name}");
                assert_shown_clear_by(&name, &frame, &camera, size, &[0], 2.0);
                let (l, b, p) = &placed[0];
                let r = Rect { min: p.top_left, size: b.size };
                for q in frame.points.iter().filter_map(|q| {
                    project_to_canvas(view_proj, size, Vec3::from(q.center))
                }) {
                    assert!(
                        !(q.cmpgt(r.min).all() && q.cmplt(r.max()).all()),
                        "{name} on {size}: {:?} at {} over a particle at {q}",
                        l.text,
                        p.top_left
                    );
                }
                let probe = f.probe_position();
                let c = project_to_canvas(view_proj, size, probe).unwrap();
                let h = f.h();
                let rim = project_to_canvas(view_proj, size, probe + h * Vec3::Y).unwrap();
                let gap = r.nearest(c).distance(c) - rim.distance(c);
                // Deep in the water, the nearest place off it: just above the surface.
                let surface = frame
                    .points
                    .iter()
                    .filter_map(|q| project_to_canvas(view_proj, size, Vec3::from(q.center)))
                    .map(|q| q.y)
                    .fold(f32::MAX, f32::min);
                let bottom = r.max().y;
                let over_surface = (surface - 30.0..=surface).contains(&bottom)
                    && (r.nearest(c).x - c.x).abs() <= 160.0;
                assert!(
                    gap <= 60.0 || over_surface,
                    "{name} on {size}: the name {gap} px off the circle, its bottom at {bottom}, \
                     the water's top at {surface}"
                );
                // The page draws a leader to the anchor from a name that ends more than
                // LEADER_PX from it: a name beside the circle is anchored at its edge and needs
                // none (one stepped up over the water's surface gets its leader to the circle).
                let label = &frame.labels[0];
                let anchor = project_to_canvas(view_proj, size, label.anchor).unwrap();
                let off = r.nearest(anchor).distance(anchor);
                assert!(
                    off <= inbetween::draw::layout::LEADER_PX || over_surface,
                    "{name} on {size}: the name {off} px from its anchor, {gap} px off the circle"
                );
            };
            failures.extend(failure_of(check));
        }
    }
    assert_none_failed(&failures);
}
