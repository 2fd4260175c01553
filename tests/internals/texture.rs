use inbetween::texture::*;

#[test]
fn atlas_frames_tile_the_texture_row_by_row() {
    let a = Atlas {
        columns: 4,
        rows: 2,
    };
    assert_eq!(a.frame(0).to_array(), [0.0, 0.0, 0.25, 0.5]);
    assert_eq!(a.frame(5).to_array(), [0.25, 0.5, 0.5, 1.0]);
    assert_eq!(a.frame(8), a.frame(0));
    assert_eq!(a.frame_at(0.0), a.frame(0));
    assert_eq!(a.frame_at(1.0), a.frame(7));
    assert_eq!(a.frame_at(0.5), a.frame(4));
    assert_eq!(a.frame_at(f32::NAN), a.frame(0));
}

#[test]
fn rgba_sizes_are_checked() {
    assert!(validate_rgba(2, 3, &[0; 24]).is_ok());
    assert!(validate_rgba(2, 3, &[0; 23]).is_err());
    assert!(validate_rgba(0, 3, &[]).is_err());
    assert!(validate_rgba(MAX_TEXTURE_SIDE + 1, 1, &[0; 4 * 2049]).is_err());
}
