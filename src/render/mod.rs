//! Output: the files of a map ([`map_files`]).

pub mod map_files;
