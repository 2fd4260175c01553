// A uniform grid built on the GPU every step (Hoetzlein 2014, "Fast fixed-radius nearest
// neighbours: interactive million-particle fluids"), prefixed by grid_common.wgsl. Five passes,
// in order: `clear` the cell counts; `count` the points per cell with atomics, keeping each
// point's rank within its cell (the atomicAdd's old value); `scan_blocks`, an exclusive prefix
// sum of the counts in blocks of 512 cells (one workgroup each), and `scan_sums` of the blocks'
// totals (one workgroup, 512 at a time), then `add_sums` adds each block's offset: `cells[c]` is
// then where cell c's run starts in `sorted` and `cells[cell count]` is the number of points;
// `scatter` writes each point's index at its cell's start plus its rank. Within a cell the order
// is the atomics' (not the CPU's increasing index), so only the cells' sets are the CPU's.
@group(0) @binding(0) var<uniform> grid: GridParams;
@group(0) @binding(1) var<storage, read> points: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read_write> cells: array<atomic<u32>>;  // cell count + 1
@group(0) @binding(3) var<storage, read_write> block_sums: array<u32>;
@group(0) @binding(4) var<storage, read_write> rank: array<u32>;
@group(0) @binding(5) var<storage, read_write> sorted: array<u32>;

const WG: u32 = 256u;
const BLOCK: u32 = 512u;
var<workgroup> scratch: array<u32, 256>;

fn point_cell(i: u32) -> u32 {
    return grid_index(grid, grid_coords(grid, points[i * grid.counts.y].xyz));
}

@compute @workgroup_size(256)
fn clear(@builtin(global_invocation_id) gid: vec3<u32>) {
    if (gid.x < grid.dims.w) { atomicStore(&cells[gid.x], 0u); }
}

@compute @workgroup_size(256)
fn count(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i < grid.counts.x) { rank[i] = atomicAdd(&cells[point_cell(i)], 1u); }
}

// The sum of the pairs (a, b) of the threads before this one in the workgroup (Hillis and
// Steele's scan over the 256 pair sums); afterwards scratch[WG - 1] holds the workgroup's total.
// Every thread of the workgroup must call it (it has barriers).
fn scan_pairs(lid: u32, a: u32, b: u32) -> u32 {
    scratch[lid] = a + b;
    workgroupBarrier();
    for (var off = 1u; off < WG; off *= 2u) {
        let add = select(0u, scratch[max(lid, off) - off], lid >= off);
        workgroupBarrier();
        scratch[lid] += add;
        workgroupBarrier();
    }
    return scratch[lid] - a - b;
}

@compute @workgroup_size(256)
fn scan_blocks(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_id) lid: vec3<u32>) {
    let n = grid.dims.w;
    let c = wid.x * BLOCK + 2u * lid.x;
    var a = 0u;
    var b = 0u;
    if (c < n) { a = atomicLoad(&cells[c]); }
    if (c + 1u < n) { b = atomicLoad(&cells[c + 1u]); }
    let before = scan_pairs(lid.x, a, b);
    if (c < n) { atomicStore(&cells[c], before); }
    if (c + 1u < n) { atomicStore(&cells[c + 1u], before + a); }
    if (lid.x == WG - 1u) { block_sums[wid.x] = before + a + b; }
}

@compute @workgroup_size(256)
fn scan_sums(@builtin(local_invocation_id) lid: vec3<u32>) {
    let blocks = grid.counts.z;
    var carry = 0u;
    for (var start = 0u; start < blocks; start += BLOCK) {
        let k = start + 2u * lid.x;
        var a = 0u;
        var b = 0u;
        if (k < blocks) { a = block_sums[k]; }
        if (k + 1u < blocks) { b = block_sums[k + 1u]; }
        let before = carry + scan_pairs(lid.x, a, b);
        if (k < blocks) { block_sums[k] = before; }
        if (k + 1u < blocks) { block_sums[k + 1u] = before + a; }
        carry += scratch[WG - 1u];
        workgroupBarrier();
    }
    if (lid.x == 0u) { atomicStore(&cells[grid.dims.w], carry); }
}

@compute @workgroup_size(256)
fn add_sums(@builtin(global_invocation_id) gid: vec3<u32>) {
    if (gid.x < grid.dims.w) { atomicAdd(&cells[gid.x], block_sums[gid.x / BLOCK]); }
}

@compute @workgroup_size(256)
fn scatter(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if (i < grid.counts.x) { sorted[atomicLoad(&cells[point_cell(i)]) + rank[i]] = i; }
}
