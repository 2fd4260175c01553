//! Orderings by an `f32` key, through one sort compiled once.
//!
//! Every `sort_by` with a closure of its own compiles a whole sort (its quicksort, merge and
//! small-sort routines: about 4.5 KB of wasm each). The crate's orderings by a float key share
//! [`sort_desc`] instead: the sprites' depth sort and the figures' small orderings (labels'
//! sides, arrows by length, neighbours by distance, skin weights) are one sort in the module.

/// Sorts `pairs` of `(key, index)` by key, largest first, under `f32::total_cmp` (NaN keys with
/// the sign bit clear go first, as if infinitely large); pairs with equal keys keep their order
/// (a stable sort). For smallest first, sort the negated keys: negation reverses `total_cmp`'s
/// order exactly.
pub fn sort_desc(pairs: &mut [(f32, u32)]) {
    pairs.sort_by(|a, b| b.0.total_cmp(&a.0));
}

/// The indices `0..keys.len()` ordered by their key, largest first (`descending`) or smallest
/// first, equal keys in index order: [`sort_desc`] on `(key, index)` pairs.
pub fn order_by(keys: impl IntoIterator<Item = f32>, descending: bool) -> Vec<usize> {
    let mut pairs: Vec<(f32, u32)> = keys
        .into_iter()
        .enumerate()
        .map(|(i, k)| (if descending { k } else { -k }, i as u32))
        .collect();
    sort_desc(&mut pairs);
    pairs.into_iter().map(|(_, i)| i as usize).collect()
}

/// Sorts `values` smallest first under `f32::total_cmp`: [`sort_desc`] on the negated values
/// (a `sort_by(f32::total_cmp)` of its own would compile a second sort).
pub fn sort_ascending(values: &mut [f32]) {
    let mut pairs: Vec<(f32, u32)> = values.iter().map(|&x| (-x, 0)).collect();
    sort_desc(&mut pairs);
    for (v, (k, _)) in values.iter_mut().zip(pairs) {
        *v = -k;
    }
}
