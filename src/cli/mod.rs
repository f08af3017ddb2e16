//! The `yinset` command line: Boolean operations, queries, pictures and format
//! conversion over yin2 text, WKT and GeoJSON files, exact by default, float mode with `--eps`;
//! and the same on 3D sets from OBJ, STL, OFF and PLY files, exactly.

mod args;
mod axioms;
mod decode;
mod encode;
mod error;
mod format;
mod info;
mod input;
mod locate;
mod ops;
mod output;
mod picture;
mod progress;
mod set;

pub use args::{Cli, Command};
pub use error::CliError;

use crate::num::Float;
use crate::yin2::YinSet2;
use crate::yin3::YinSet3;
use args::{Eps, ReadOpts};
use clap::Parser;
use format::{Dimension, Format};
use input::{name, one_stdin, read_text};
use ops::{operate, Op};
use output::{write_bytes, write_text};
use set::Set;
use std::path::Path;
use std::process::ExitCode;

/// The exact number type of the command (GMP rationals with the `gmp` feature).
#[cfg(feature = "gmp")]
type Exact = crate::num::GmpRational;
/// The exact number type of the command (GMP rationals with the `gmp` feature).
#[cfg(not(feature = "gmp"))]
type Exact = crate::num::Rational;

/// Parse the process's arguments, run, report any error on stderr; the exit status.
pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let _ = e.print();
            return ExitCode::from(e.exit_code().clamp(0, 255) as u8);
        }
    };
    match run(&cli.command.unwrap_or(Command::Demo)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("yinset: error: {e}");
            e.exit_code()
        }
    }
}

/// Run one subcommand: on 2D or 3D sets as its inputs' formats say; exact unless it was given
/// `--eps` (a value, or `auto` for the default tolerance).
pub fn run(command: &Command) -> Result<(), CliError> {
    let no_options = ReadOpts::default();
    let read = command.read_opts().unwrap_or(&no_options);
    match (dimension(command, read)?, read.eps.map(Eps::tolerance)) {
        (Dimension::Two, None) => run_in::<YinSet2<Exact>>(command, ()),
        (Dimension::Two, Some(tol)) => run_in::<YinSet2<Float>>(command, tol),
        (Dimension::Three, None) => run_in::<YinSet3<Exact>>(command, ()),
        (Dimension::Three, Some(tol)) => run_in::<YinSet3<Float>>(command, tol),
    }
}

/// The dimension of the sets `command` reads, by their formats (`--from`, else the file
/// extensions; standard input follows the other inputs): an error if they mix 2D and 3D, or if
/// 3D sets meet an option or subcommand of 2D only.
fn dimension(command: &Command, read: &ReadOpts) -> Result<Dimension, CliError> {
    let declared: Vec<(&Path, Format)> = command
        .set_inputs()
        .into_iter()
        .filter_map(|p| Some((p, Format::declared(p, read.from)?)))
        .collect();
    let of = |d: Dimension| declared.iter().find(|(_, f)| f.dimension() == d);
    match (of(Dimension::Two), of(Dimension::Three)) {
        (Some((a, fa)), Some((b, fb))) => Err(CliError::Usage(format!(
            "conflicting inputs: {} is a 2D set ({}) but {} is a 3D set ({}); \
             the operands must have one dimension",
            name(a),
            fa.name(),
            name(b),
            fb.name()
        ))),
        (_, Some(_)) if read.fill.is_some() => Err(CliError::Usage(
            "--fill takes 2D rings as polygon soup; the faces of a 3D mesh must bound a 3D set \
             as given"
                .to_string(),
        )),
        (_, Some(_)) => Ok(Dimension::Three),
        (_, None) => Ok(Dimension::Two),
    }
}

/// Run one subcommand on sets of kind `S`, with number context `ctx`.
fn run_in<S: Set>(command: &Command, ctx: S::Ctx) -> Result<(), CliError> {
    let binary = |op, b: &args::Binary| operate::<S>(op, &[&b.a, &b.b], &b.read, &b.write, ctx);
    let unary = |op, u: &args::Unary| operate::<S>(op, &[&u.input], &u.read, &u.write, ctx);
    match command {
        Command::Demo => {
            let report = crate::demo::run().map_err(|source| CliError::Invalid {
                name: "a demonstration shape".to_string(),
                source,
                note: String::new(),
            })?;
            write_text(None, &report)
        }
        Command::Meet(b) => binary(Op::Meet, b),
        Command::Join(b) => binary(Op::Join, b),
        Command::Difference(b) => binary(Op::Difference, b),
        Command::Xor(b) => binary(Op::Xor, b),
        Command::Complement(u) => unary(Op::Complement, u),
        Command::Convert(u) => unary(Op::Convert, u),
        Command::Info(s) => {
            let set = S::load(&s.input, &s.read, ctx)?;
            write_text(None, &format!("{:#}\n", set.info()))
        }
        Command::Validate(s) => {
            let set = S::load(&s.input, &s.read, ctx)?;
            let summary = set.describe();
            write_text(
                None,
                &format!("{} is a Yin set: {summary}\n", name(&s.input)),
            )
        }
        Command::Locate(l) => {
            one_stdin([l.set.as_path(), l.points.as_path()])?;
            let set = S::load(&l.set, &l.read, ctx)?;
            let text = read_text(&l.points, &l.read)?;
            let words = set.locate_text(&text).map_err(|source| CliError::Parse {
                name: name(&l.points),
                source,
            })?;
            write_text(None, &words)
        }
        Command::Render(r) => {
            one_stdin(r.inputs.iter().map(|p| p.as_path()))?;
            let sets = r
                .inputs
                .iter()
                .map(|p| S::load(p, &r.read, ctx))
                .collect::<Result<Vec<_>, _>>()?;
            let labels: Vec<String> = r.inputs.iter().map(|p| label(p)).collect();
            let layers: Vec<(&str, _)> = labels.iter().map(String::as_str).zip(&sets).collect();
            write_bytes(r.output.as_deref(), &S::render(&layers, r)?)
        }
        Command::Axioms(a) => axioms::run::<Exact>(a.n, a.seed),
    }
}

/// The legend label of an input: its file name.
fn label(path: &Path) -> String {
    match path.file_name() {
        Some(f) if !format::is_std(path) => f.to_string_lossy().into_owned(),
        _ => "standard input".to_string(),
    }
}
