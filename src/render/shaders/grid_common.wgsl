// A GPU uniform grid's layout and its cells (prefixed to grid.wgsl and to the kernels that search
// it, such as boids.wgsl): the same cells as GridLayout::cell_of in src/figures/gpu.rs.
struct GridParams {
    origin: vec4<f32>,    // xyz: the corner of cell (0, 0, 0), metres
    inv_size: vec4<f32>,  // xyz: 1 / the cells' size along x, y, z
    dims: vec4<u32>,      // cells along x, y, z; w: cells in all
    counts: vec4<u32>,    // points, vec4s per point, prefix-sum blocks, unused
};

// The cell of p, clamped into the grid (a NaN coordinate gives 0 on its axis, as on the CPU).
fn grid_coords(g: GridParams, p: vec3<f32>) -> vec3<u32> {
    let f = (p - g.origin.xyz) * g.inv_size.xyz;
    let top = vec3<f32>(g.dims.xyz - vec3<u32>(1u));
    return vec3<u32>(min(select(vec3<f32>(0.0), f, f >= vec3<f32>(0.0)), top));
}

fn grid_index(g: GridParams, c: vec3<u32>) -> u32 {
    return c.x + g.dims.x * (c.y + g.dims.y * c.z);
}
