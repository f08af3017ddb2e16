//! Values grouped by small integer keys in two passes of counting (a counting sort): the
//! vertex-to-edge tables of the pasting map and the sweeps, the cells of a grid.

/// Values grouped by key `0..keys`, each group in the order the values came.
pub(crate) struct Buckets {
    /// The values of key k are `values[start[k]..start[k + 1]]`.
    start: Vec<usize>,
    values: Vec<usize>,
}

impl Buckets {
    /// The `(key, value)` pairs of `items` (keys below `keys`) grouped by key.
    pub(crate) fn new(keys: usize, items: impl Iterator<Item = (usize, usize)> + Clone) -> Buckets {
        let mut start = vec![0; keys + 1];
        for (k, _) in items.clone() {
            start[k + 1] += 1;
        }
        for k in 1..start.len() {
            start[k] += start[k - 1];
        }
        let mut values = vec![0; start[keys]];
        // Each start moves up to the next key's as its values are placed, then back down one.
        for (k, v) in items {
            values[start[k]] = v;
            start[k] += 1;
        }
        start.rotate_right(1);
        start[0] = 0;
        Buckets { start, values }
    }

    /// The values of key `k`, in the order they came.
    pub(crate) fn get(&self, k: usize) -> &[usize] {
        &self.values[self.start[k]..self.start[k + 1]]
    }

    /// The values of the keys `keys`, key after key.
    pub(crate) fn range(&self, keys: std::ops::RangeInclusive<usize>) -> &[usize] {
        &self.values[self.start[*keys.start()]..self.start[keys.end() + 1]]
    }

    /// All values, key after key.
    pub(crate) fn all(&self) -> &[usize] {
        &self.values
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// Each group holds exactly the values of its key, in the order they came (a stable
        /// sort by key), against filtering the items key by key.
        #[test]
        fn buckets_are_the_values_of_each_key_in_order(
            items in proptest::collection::vec((0usize..6, 0usize..100), 0..40),
        ) {
            let b = Buckets::new(6, items.iter().copied());
            let mut sorted = items.clone();
            sorted.sort_by_key(|&(k, _)| k);
            let want: Vec<usize> = sorted.iter().map(|&(_, v)| v).collect();
            prop_assert_eq!(b.all(), &want[..]);
            for k in 0..6 {
                let of_k: Vec<usize> = items.iter().filter(|i| i.0 == k).map(|i| i.1).collect();
                prop_assert_eq!(b.get(k), &of_k[..]);
            }
            prop_assert_eq!(b.range(1..=3), &want[b.get(0).len()..items.iter().filter(|i| i.0 <= 3).count()]);
        }
    }
}
