//! The `yinset` command line (issue 6): Boolean operations, queries, pictures and format
//! conversion over yin2 text, WKT and GeoJSON files, exact by default, float mode with `--eps`.

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
mod progress;

pub use args::{Cli, Command};
pub use error::CliError;

use crate::io::svg::write_svg;
use crate::num::{Float, Num, Tolerance};
use clap::Parser;
use input::{load, name, one_stdin, read_text};
use ops::{operate, Op};
use output::write_text;
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

/// Run one subcommand: exact unless it was given `--eps`.
pub fn run(command: &Command) -> Result<(), CliError> {
    match command.read_opts().and_then(|r| r.eps) {
        None => run_in::<Exact>(command, ()),
        Some(eps) => run_in::<Float>(command, Tolerance::new(eps)),
    }
}

/// Run one subcommand with numbers `N` in context `ctx`.
fn run_in<N: Num>(command: &Command, ctx: N::Ctx) -> Result<(), CliError> {
    let binary = |op, b: &args::Binary| operate::<N>(op, &[&b.a, &b.b], &b.read, &b.write, ctx);
    let unary = |op, u: &args::Unary| operate::<N>(op, &[&u.input], &u.read, &u.write, ctx);
    match command {
        Command::Demo => {
            let report = crate::demo::run().map_err(|source| CliError::Invalid {
                name: "a demonstration shape".to_string(),
                source: Box::new(source),
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
            let set = load::<N>(&s.input, &s.read, ctx)?;
            write_text(None, &format!("{:#}\n", info::report(&set)))
        }
        Command::Validate(s) => {
            let set = load::<N>(&s.input, &s.read, ctx)?;
            let summary = crate::demo::describe(&set);
            write_text(
                None,
                &format!("{} is a Yin set: {summary}\n", name(&s.input)),
            )
        }
        Command::Locate(l) => {
            one_stdin([l.set.as_path(), l.points.as_path()])?;
            let set = load::<N>(&l.set, &l.read, ctx)?;
            let text = read_text(&l.points)?;
            let points = locate::read_points::<N>(&text).map_err(|source| CliError::Parse {
                name: name(&l.points),
                source,
            })?;
            write_text(None, &locate::classify(&set, &points))
        }
        Command::Render(r) => {
            one_stdin(r.inputs.iter().map(|p| p.as_path()))?;
            let sets = r
                .inputs
                .iter()
                .map(|p| load::<N>(p, &r.read, ctx))
                .collect::<Result<Vec<_>, _>>()?;
            let labels: Vec<String> = r.inputs.iter().map(|p| label(p)).collect();
            let layers: Vec<(&str, _)> = labels.iter().map(String::as_str).zip(&sets).collect();
            write_text(r.output.as_deref(), &write_svg(&layers))
        }
        Command::Axioms(a) => axioms::run::<N>(a.n, a.seed),
    }
}

/// The legend label of an input: its file name.
fn label(path: &Path) -> String {
    match path.file_name() {
        Some(f) if !format::is_std(path) => f.to_string_lossy().into_owned(),
        _ => "standard input".to_string(),
    }
}
