//! The benchmarks' package has no library of its own: `impact.rs` is its one benchmark
//! (`make bench`).
