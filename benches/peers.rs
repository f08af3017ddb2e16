//! Criterion benches of yinset against its peers (issue 8): being written.

fn main() {}
