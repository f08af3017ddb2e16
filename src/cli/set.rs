//! The two kinds of sets the command works on, 2D (`YinSet2`: yin2, WKT, GeoJSON) and 3D
//! (`YinSet3`: OBJ, STL, OFF, PLY), behind one interface, so that each subcommand has one
//! generic path.

use super::args::{ReadOpts, RenderArgs};
use super::encode::{encode, encode3};
use super::error::CliError;
use super::format::{Dimension, Format};
use super::input::{load, load3};
use super::{info, locate, picture};
use crate::io::{NumberStyle, ParseError};
use crate::num::Num;
use crate::yin2::YinSet2;
use crate::yin3::{Yin3Error, YinSet3};
use serde_json::Value;
use std::path::Path;

/// A kind of Yin set of the command line: its Boolean algebra, how it is read and written, and
/// what the reporting subcommands say about it.
pub trait Set: Clone {
    /// The number context (the tolerance in float mode).
    type Ctx: Copy;
    /// The dimension of the space the sets live in.
    const DIMENSION: Dimension;
    /// The set in `path`, read as `opts` say, with number context `ctx`.
    fn load(path: &Path, opts: &ReadOpts, ctx: Self::Ctx) -> Result<Self, CliError>;
    /// The file of the set in `format`, coordinates of the OGC formats in `style`.
    fn encode(&self, format: Format, style: NumberStyle) -> Result<Vec<u8>, CliError>;
    /// A ∧ B (an error only where the kernel's `try_` operation gives one: 3D float mode).
    fn meet(&self, other: &Self) -> Result<Self, CliError>;
    /// A ∨ B.
    fn join(&self, other: &Self) -> Result<Self, CliError>;
    /// A ∧ B′.
    fn difference(&self, other: &Self) -> Result<Self, CliError>;
    /// (A ∧ B′) ∨ (A′ ∧ B).
    fn symmetric_difference(&self, other: &Self) -> Result<Self, CliError>;
    /// A′.
    fn complement(&self) -> Self;
    /// The number of boundary vertices (large inputs show progress).
    fn size(&self) -> usize;
    /// The JSON report of `info`.
    fn info(&self) -> Value;
    /// The one-line summary of `validate`.
    fn describe(&self) -> String;
    /// The answer of `locate` for the points in `text`, one line per line of `text`.
    fn locate_text(&self, text: &str) -> Result<String, ParseError>;
    /// The picture of labelled sets that `render` asks for.
    fn render(layers: &[(&str, &Self)], args: &RenderArgs) -> Result<Vec<u8>, CliError>;
}

/// The Boolean algebra of a `Set` impl: the kernel's operations `$g` (each result lifted into
/// a `Result` by `$lift`) as the operations `$f`, and its complement.
macro_rules! algebra {
    ($set:ident, $lift:expr, $($f:ident: $g:ident),*) => {
        $(fn $f(&self, other: &Self) -> Result<Self, CliError> {
            $lift($set::$g(self, other))
        })*
        fn complement(&self) -> Self {
            $set::complement(self)
        }
    };
}

/// A 3D float-mode failure as the command's error.
fn float3_failure<N: Num>(r: Result<YinSet3<N>, Yin3Error>) -> Result<YinSet3<N>, CliError> {
    r.map_err(|e| CliError::Operation(e.to_string()))
}

impl<N: Num> Set for YinSet2<N> {
    type Ctx = N::Ctx;
    const DIMENSION: Dimension = Dimension::Two;
    algebra!(YinSet2, Ok, meet: meet, join: join, difference: difference,
        symmetric_difference: symmetric_difference);

    fn load(path: &Path, opts: &ReadOpts, ctx: N::Ctx) -> Result<Self, CliError> {
        load(path, opts, ctx)
    }
    fn encode(&self, format: Format, style: NumberStyle) -> Result<Vec<u8>, CliError> {
        encode(self, format, style)
    }
    fn size(&self) -> usize {
        self.curves().iter().map(|c| c.len()).sum()
    }
    fn info(&self) -> Value {
        info::report(self)
    }
    fn describe(&self) -> String {
        info::summary(self)
    }
    fn locate_text(&self, text: &str) -> Result<String, ParseError> {
        Ok(locate::aligned(&locate::read_points(text)?, |p| {
            self.locate(p)
        }))
    }
    fn render(layers: &[(&str, &Self)], args: &RenderArgs) -> Result<Vec<u8>, CliError> {
        picture::render2(layers, args)
    }
}

impl<N: Num> Set for YinSet3<N> {
    type Ctx = N::Ctx;
    const DIMENSION: Dimension = Dimension::Three;
    algebra!(YinSet3, float3_failure, meet: try_meet, join: try_join,
        difference: try_difference, symmetric_difference: try_symmetric_difference);

    fn load(path: &Path, opts: &ReadOpts, ctx: N::Ctx) -> Result<Self, CliError> {
        load3(path, opts, ctx)
    }
    fn encode(&self, format: Format, _: NumberStyle) -> Result<Vec<u8>, CliError> {
        encode3(self, format)
    }
    fn size(&self) -> usize {
        self.vertices().len()
    }
    fn info(&self) -> Value {
        info::report3(self)
    }
    fn describe(&self) -> String {
        crate::demo::describe3(self)
    }
    fn locate_text(&self, text: &str) -> Result<String, ParseError> {
        Ok(locate::aligned(&locate::read_points3(text)?, |p| {
            self.locate(p)
        }))
    }
    fn render(layers: &[(&str, &Self)], args: &RenderArgs) -> Result<Vec<u8>, CliError> {
        picture::render3(layers, args)
    }
}
