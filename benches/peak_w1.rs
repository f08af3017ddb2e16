//! Peak memory of W1 at n = 10^6 (issue 8, item 5): being written.

fn main() {}
