//! Files and standard input → Yin sets: read, decode, validate (or fill), with located errors;
//! 2D sets from yin2, WKT, GeoJSON and WKB, 3D sets from OBJ, STL, OFF and PLY.

use super::args::{FillArg, ReadOpts};
use super::decode::{decode, decode_mesh, decode_wkb, locate_faces, Decoded, Rings};
use super::error::CliError;
use super::format::{is_std, Dimension, Format};
use super::progress;
use crate::io::mesh::Mesh;
use crate::io::{check_digit_runs, ParseError};
use crate::kernel::Point;
use crate::num::{Num, Rational};
use crate::yin2::{YinError, YinSet2};
use crate::yin3::{Yin3Error, YinSet3};
use std::io::Read;
use std::path::Path;

/// The hint for standard input that begins as binary WKB does but is read as yin2.
const WKB_HINT: &str =
    " (standard input is read as yin2 or WKB hex, and this looks like binary WKB: give --from wkb)";

/// How `path` is named in messages.
pub fn name(path: &Path) -> String {
    if is_std(path) {
        "standard input".to_string()
    } else {
        format!("`{}`", path.display())
    }
}

/// Reject more than one of `paths` reading standard input.
pub fn one_stdin<'a>(paths: impl IntoIterator<Item = &'a Path>) -> Result<(), CliError> {
    if paths.into_iter().filter(|p| is_std(p)).count() > 1 {
        return Err(CliError::Usage(
            "conflicting inputs: standard input (`-`) can be read only once".to_string(),
        ));
    }
    Ok(())
}

/// The text of `path` (`-`: standard input), refused as [`read_bytes`] does, if it is not
/// UTF-8, or if a number has more than `opts.max_digits` digits in a row.
pub fn read_text(path: &Path, opts: &ReadOpts) -> Result<String, CliError> {
    text_of(path, read_bytes(path, opts)?, opts)
}

/// The text of `bytes` read from `path`, refused as [`read_text`] says.
fn text_of(path: &Path, bytes: Vec<u8>, opts: &ReadOpts) -> Result<String, CliError> {
    let text = String::from_utf8(bytes).map_err(|e| CliError::Read {
        name: name(path),
        source: std::io::Error::new(std::io::ErrorKind::InvalidData, e),
    })?;
    check_digit_runs(&text, opts.max_digits).map_err(|source| parse_error(path, source))?;
    Ok(text)
}

/// The bytes of `path` (`-`: standard input), refused if longer than `opts.max_bytes` (a file
/// by its length before reading it, standard input once the limit is passed).
pub fn read_bytes(path: &Path, opts: &ReadOpts) -> Result<Vec<u8>, CliError> {
    let limit = opts.max_bytes;
    let too_large = || CliError::TooLarge {
        name: name(path),
        limit,
    };
    let read_error = |source| CliError::Read {
        name: name(path),
        source,
    };
    let source: Box<dyn Read> = if is_std(path) {
        Box::new(std::io::stdin())
    } else {
        let file = std::fs::File::open(path).map_err(read_error)?;
        if file.metadata().map_err(read_error)?.len() > limit {
            return Err(too_large());
        }
        Box::new(file)
    };
    let mut bytes = Vec::new();
    source
        .take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(read_error)?;
    if bytes.len() as u64 > limit {
        return Err(too_large());
    }
    Ok(bytes)
}

/// The Yin set in `path`, read as `opts` say, with number context `ctx`.
pub fn load<N: Num>(path: &Path, opts: &ReadOpts, ctx: N::Ctx) -> Result<YinSet2<N>, CliError> {
    let declared = Format::of_input(path, opts.from, Dimension::Two)?;
    let bytes = read_bytes(path, opts)?;
    let format = declared.sniffed(&bytes, path, opts.from);
    if let Format::Wkb | Format::WkbHex = format {
        let hex = format == Format::WkbHex;
        let rings =
            decode_wkb(&bytes, hex, opts.polygonal_only).map_err(|source| CliError::Wkb {
                name: name(path),
                format: format.name(),
                source,
            })?;
        return from_rings(path, rings, opts, ctx);
    }
    let guessed = is_std(path) && opts.from.is_none();
    let wkb_hint = guessed && crate::io::wkb::looks_binary(&bytes);
    let text = text_of(path, bytes, opts).map_err(|e| match e {
        CliError::Read { name, source } if wkb_hint => CliError::Read {
            name,
            source: std::io::Error::new(source.kind(), format!("{source}{WKB_HINT}")),
        },
        other => other,
    })?;
    let rings = match decode::<N>(&text, format, opts.polygonal_only) {
        Ok(Decoded::Full) => return Ok(YinSet2::full().with_ctx(ctx)),
        Ok(Decoded::Boundary(rings)) => rings,
        Err(mut source) => {
            if wkb_hint {
                source.message += WKB_HINT;
            } else if guessed && looks_like_obj(&text) {
                source.message += " (standard input is read as yin2: for OBJ give --from obj)";
            }
            return Err(parse_error(path, source));
        }
    };
    from_rings(path, rings, opts, ctx).map_err(|e| match N::EXACT {
        true => e,
        false => with_rounding_note(e, &text, format, opts),
    })
}

/// `e` with a note where float mode refused rings for a repeated vertex or too few vertices
/// that only rounding made: the vertices differ in the input read exactly and coincide once
/// rounded to the nearest `f64`s.
fn with_rounding_note(e: CliError, text: &str, format: Format, opts: &ReadOpts) -> CliError {
    let CliError::Invalid { name, source, note } = e else {
        return e;
    };
    let exact = match decode::<Rational>(text, format, opts.polygonal_only) {
        Ok(Decoded::Boundary(rings)) => rings.rings,
        _ => Vec::new(),
    };
    let distinct = |curve: usize| {
        let ring = exact.get(curve)?;
        let mut points: Vec<&Point<Rational>> = ring.iter().collect();
        points.sort();
        points.dedup();
        Some(points.len())
    };
    let merged = match source.downcast_ref::<YinError>() {
        Some(YinError::RepeatedVertex { curve, vertex, .. }) => {
            exact.get(*curve).is_some_and(|ring| {
                let before = (vertex + ring.len() - 1) % ring.len();
                ring.get(*vertex).is_some_and(|p| p != &ring[before])
            })
        }
        Some(YinError::TooFewVertices { curve, count }) => {
            distinct(*curve).is_some_and(|n| n > *count)
        }
        _ => false,
    };
    let note = match merged {
        true => format!(
            "{note}; its vertices there differ in the input but coincide once rounded to the \
             nearest f64s, as float mode reads coordinates: read it exactly (without --eps)"
        ),
        false => note,
    };
    CliError::Invalid { name, source, note }
}

/// The Yin set bounded by `rings` read from `path` (or covered by them, under `opts.fill`).
fn from_rings<N: Num>(
    path: &Path,
    rings: Rings<N>,
    opts: &ReadOpts,
    ctx: N::Ctx,
) -> Result<YinSet2<N>, CliError> {
    if rings.rings.is_empty() {
        return Ok(YinSet2::empty().with_ctx(ctx));
    }
    let message = || format!("reading {}", name(path));
    progress::while_working(message, rings.vertices(), || {
        build(path, rings, opts.fill, ctx)
    })
}

/// The 3D Yin set in the mesh file `path`, with number context `ctx`: 0̂ if it has no faces,
/// 1̂ if it is OBJ's whole-space comment line.
pub fn load3<N: Num>(path: &Path, opts: &ReadOpts, ctx: N::Ctx) -> Result<YinSet3<N>, CliError> {
    let format = Format::of_input(path, opts.from, Dimension::Three)?;
    let bytes = read_bytes(path, opts)?;
    if let Ok(text) = std::str::from_utf8(&bytes) {
        check_digit_runs(text, opts.max_digits).map_err(|source| parse_error(path, source))?;
    }
    let mesh = match decode_mesh::<N>(&bytes, format) {
        Ok(Decoded::Full) => return Ok(YinSet3::full()),
        Ok(Decoded::Boundary(mesh)) => mesh,
        Err(source) => {
            return Err(CliError::Mesh {
                name: name(path),
                source,
            })
        }
    };
    let Mesh {
        vertices,
        faces,
        face_lines,
    } = mesh;
    if faces.is_empty() {
        return Ok(YinSet3::empty());
    }
    let message = || format!("reading {}", name(path));
    progress::while_working(message, vertices.len(), || {
        YinSet3::from_triangles_with(vertices, faces, ctx)
    })
    .map_err(|source| match source {
        Yin3Error::ToleranceTooFine { representable, .. } => CliError::Tolerance {
            name: name(path),
            hint: coarser_eps(representable.get()),
            source: Box::new(source),
        },
        _ => CliError::Invalid {
            name: name(path),
            note: locate_faces(&source, &face_lines),
            source: Box::new(source),
        },
    })
}

/// What to give instead of an ε too fine for the coordinates, `representable` the finest that
/// fits them.
fn coarser_eps(representable: f64) -> String {
    format!("; give --eps {representable:e} or more, or --eps auto for the default tolerance")
}

/// The error of malformed text in `path`.
fn parse_error(path: &Path, source: ParseError) -> CliError {
    CliError::Parse {
        name: name(path),
        source,
    }
}

/// True if `text` has OBJ vertex or face lines.
fn looks_like_obj(text: &str) -> bool {
    text.lines()
        .any(|l| l.starts_with("v ") || l.starts_with("f "))
}

/// The Yin set bounded by `rings`, or covered by them under `fill`.
fn build<N: Num>(
    path: &Path,
    rings: Rings<N>,
    fill: Option<FillArg>,
    ctx: N::Ctx,
) -> Result<YinSet2<N>, CliError> {
    let Rings { rings, origins } = rings;
    let built = match fill {
        None => YinSet2::from_curves_with(rings, ctx),
        Some(rule) => YinSet2::from_rings_filled_with(rings, rule.rule(), ctx),
    };
    built.map_err(|source| {
        // Float mode's refusals of ε are about the tolerance, not the rings.
        let hint = match &source {
            YinError::ToleranceTooFine { representable, .. } => {
                Some(coarser_eps(representable.get()))
            }
            YinError::CollapsedOnGrid { .. } => Some(String::new()),
            _ => None,
        };
        if let Some(hint) = hint {
            return CliError::Tolerance {
                name: name(path),
                source: Box::new(source),
                hint,
            };
        }
        let hint = if fill.is_none() {
            "; to take the region the rings cover instead, give --fill nonzero or --fill evenodd"
        } else {
            ""
        };
        CliError::Invalid {
            name: name(path),
            note: format!("{}{hint}", origins.locate_error(&source)),
            source: Box::new(source),
        }
    })
}
