pub mod intersect;
