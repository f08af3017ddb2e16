//! The command line's grammar: subcommands and their options (clap derive).

use super::format::Format;
use crate::io::scene3::View;
use crate::num::Tolerance;
use crate::yin2::FillRule;
use clap::{Args, Parser, Subcommand, ValueEnum};
use std::path::{Path, PathBuf};

/// Boolean algebra of 2D and 3D Yin sets, exact on rationals (float mode with --eps).
#[derive(Parser, Debug)]
#[command(
    name = "yinset",
    version,
    about,
    after_help = "With no subcommand, runs the built-in demonstration.\n\
                  Inputs are yin2 text, WKT or GeoJSON (2D sets) or OBJ, STL, OFF or PLY (3D \
                  sets), chosen by --from or the file extension (.txt/.yin2, .wkt, \
                  .geojson/.json; .obj, .stl, .off, .ply); `-` is standard input or output.\n\
                  Exit status: 0 success, 1 bad input or failed checks, 2 wrong usage."
)]
pub struct Cli {
    /// What to do (default: the demonstration).
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Run the built-in demonstration (what `yinset` alone does).
    Demo,
    /// Intersection A ∧ B.
    Meet(Binary),
    /// Regularized union A ∨ B.
    Join(Binary),
    /// Complement A′: the interior of what A leaves out.
    Complement(Unary),
    /// Difference A ∧ B′.
    Difference(Binary),
    /// Symmetric difference (A ∧ B′) ∨ (A′ ∧ B).
    Xor(Binary),
    /// Say for each point (`x y`, or `x y z` in 3D, per line) whether it is inside, outside or
    /// on the boundary.
    Locate(LocateArgs),
    /// Print Betti numbers, curves (surfaces), Hasse diagram, area (volume) and bounding box as
    /// JSON.
    Info(Single),
    /// Draw one or more sets: 2D sets as SVG or PNG; 3D sets as PNG or an interactive HTML page.
    Render(RenderArgs),
    /// Check that the input is a Yin set's boundary, explaining why not.
    Validate(Single),
    /// Rewrite a set in another format (canonical form, through the Yin set).
    Convert(Unary),
    /// Check Boolean-algebra laws with == on random exact Yin sets (a smoke test of the build).
    Axioms(AxiomsArgs),
}

/// How inputs are read.
#[derive(Args, Debug, Clone)]
pub struct ReadOpts {
    /// Input format of every input (default: from the file extension; for standard input, WKB
    /// hex if it is all hex digits, else yin2, or OBJ if the other inputs are 3D); an input
    /// file whose extension names another format is an error. A .wkb file or --from wkb of hex
    /// digits is read as wkb-hex.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub from: Option<Format>,
    /// Read the rings as polygon soup and take the region they cover under this rule.
    #[arg(long, value_enum, value_name = "RULE")]
    pub fill: Option<FillArg>,
    /// Float mode with tolerance E > 0, or `auto` for the default tolerance: 10⁻¹⁰ times the
    /// larger side of the input's bounding box, raised to the finest that its coordinates allow,
    /// rounded down to a power of two (default: exact rational arithmetic).
    #[arg(long, value_name = "E|auto", value_parser = parse_eps, allow_hyphen_values = true)]
    pub eps: Option<Eps>,
    /// Drop the points and lines of WKT, GeoJSON and WKB inputs (such as a FeatureCollection's
    /// Points) instead of rejecting them; only the polygons are read.
    #[arg(long)]
    pub polygonal_only: bool,
    /// Refuse a number with more than N digits in a row (exact numbers of many digits are
    /// slow to read and to compute with).
    #[arg(long, value_name = "N", default_value_t = DEFAULT_MAX_DIGITS)]
    pub max_digits: usize,
    /// Refuse an input larger than N bytes, before reading it whole.
    #[arg(long, value_name = "N", default_value_t = DEFAULT_MAX_BYTES)]
    pub max_bytes: u64,
}

/// The default of `--max-digits`: far more than any exact result of decimal inputs needs.
pub const DEFAULT_MAX_DIGITS: usize = 10_000;

/// The default of `--max-bytes`: 1 GiB.
pub const DEFAULT_MAX_BYTES: u64 = 1 << 30;

impl Default for ReadOpts {
    /// The options' defaults on the command line.
    fn default() -> Self {
        ReadOpts {
            from: None,
            fill: None,
            eps: None,
            polygonal_only: false,
            max_digits: DEFAULT_MAX_DIGITS,
            max_bytes: DEFAULT_MAX_BYTES,
        }
    }
}

/// Where and how a resulting set is written.
#[derive(Args, Debug, Clone, Default)]
pub struct WriteOpts {
    /// Output file (`-` or absent: standard output); its extension picks the format.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// Output format (default: from the --output extension, else yin2 for 2D sets, obj for 3D;
    /// stl-binary writes binary STL).
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub to: Option<Format>,
    /// Write WKT and GeoJSON coordinates exactly (decimals where they terminate, else `p/q` in
    /// WKT and an error in GeoJSON) instead of the shortest decimals of the nearest f64s, which
    /// other GIS tools read; yin2 and OBJ are always exact. WKB holds f64s: with --exact, a
    /// coordinate that is not one is an error instead of rounded.
    #[arg(long)]
    pub exact: bool,
}

/// The tolerance of float mode that `--eps` asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Eps {
    /// `auto`: the default tolerance, chosen from each input's extent (`Tolerance::default()`).
    Auto,
    /// A given ε > 0.
    Value(f64),
}

impl Eps {
    /// The kernel's tolerance.
    pub fn tolerance(self) -> Tolerance {
        match self {
            Eps::Auto => Tolerance::default(),
            Eps::Value(eps) => Tolerance::new(eps),
        }
    }
}

/// A fill rule for polygon soup.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum FillArg {
    /// Points of non-zero winding number.
    Nonzero,
    /// Points inside an odd number of rings.
    Evenodd,
}

/// Two input sets, one output set.
#[derive(Args, Debug)]
pub struct Binary {
    /// The first operand (`-`: standard input).
    pub a: PathBuf,
    /// The second operand (`-`: standard input).
    pub b: PathBuf,
    #[command(flatten)]
    pub read: ReadOpts,
    #[command(flatten)]
    pub write: WriteOpts,
}

/// One input set, one output set.
#[derive(Args, Debug)]
pub struct Unary {
    /// The input set (`-`: standard input).
    pub input: PathBuf,
    #[command(flatten)]
    pub read: ReadOpts,
    #[command(flatten)]
    pub write: WriteOpts,
}

/// One input set, a report on standard output.
#[derive(Args, Debug)]
pub struct Single {
    /// The input set (`-`: standard input).
    pub input: PathBuf,
    #[command(flatten)]
    pub read: ReadOpts,
}

/// A set and the points to locate in it.
#[derive(Args, Debug)]
pub struct LocateArgs {
    /// The set (`-`: standard input).
    pub set: PathBuf,
    /// Points, one `x y` per line (default `-`: standard input).
    #[arg(default_value = "-")]
    pub points: PathBuf,
    #[command(flatten)]
    pub read: ReadOpts,
}

/// Sets to draw and where.
#[derive(Args, Debug)]
pub struct RenderArgs {
    /// The sets (`-`: standard input): 2D sets drawn in order, later ones on top; 3D sets drawn
    /// together.
    #[arg(required = true)]
    pub inputs: Vec<PathBuf>,
    /// The picture: FILE.svg or FILE.png (2D sets; the PNG's legend in an 8×8 bitmap font; `-`
    /// or absent: SVG on standard output), FILE.png or FILE.html (3D sets).
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// 3D only: the view direction, azimuth (about the z axis, from the x axis) and elevation
    /// in degrees [default: -60,25].
    #[arg(long, value_name = "AZIMUTH,ELEVATION", allow_hyphen_values = true)]
    pub view: Option<View>,
    /// 3D PNG only: the width and height of the picture in pixels [default: 800].
    #[arg(long, value_name = "PIXELS", value_parser = clap::value_parser!(u32).range(16..=8192))]
    pub size: Option<u32>,
    #[command(flatten)]
    pub read: ReadOpts,
}

/// How many random checks, from which seed.
#[derive(Args, Debug)]
pub struct AxiomsArgs {
    /// Number of random triples (A, B, C); every law is checked on each.
    #[arg(default_value_t = 100)]
    pub n: u64,
    /// Seed of the random generator (the same seed gives the same sets).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
}

impl FillArg {
    /// The kernel's fill rule.
    pub fn rule(self) -> FillRule {
        match self {
            FillArg::Nonzero => FillRule::NonZero,
            FillArg::Evenodd => FillRule::EvenOdd,
        }
    }
}

/// Parse `--eps`: `auto`, or a finite number greater than zero.
fn parse_eps(text: &str) -> Result<Eps, String> {
    if text == "auto" {
        return Ok(Eps::Auto);
    }
    match text.parse::<f64>() {
        Ok(eps) if eps.is_finite() && eps > 0.0 => Ok(Eps::Value(eps)),
        Ok(_) => Err(
            "the tolerance must be a finite number greater than 0, or auto for the default"
                .to_string(),
        ),
        Err(e) => Err(format!("not a number or auto: {e}")),
    }
}

impl Command {
    /// The read options of a subcommand that reads sets.
    pub fn read_opts(&self) -> Option<&ReadOpts> {
        match self {
            Command::Meet(b) | Command::Join(b) | Command::Difference(b) | Command::Xor(b) => {
                Some(&b.read)
            }
            Command::Complement(u) | Command::Convert(u) => Some(&u.read),
            Command::Info(s) | Command::Validate(s) => Some(&s.read),
            Command::Locate(l) => Some(&l.read),
            Command::Render(r) => Some(&r.read),
            Command::Demo | Command::Axioms(_) => None,
        }
    }

    /// The sets a subcommand reads (not the points of `locate`).
    pub fn set_inputs(&self) -> Vec<&Path> {
        match self {
            Command::Meet(b) | Command::Join(b) | Command::Difference(b) | Command::Xor(b) => {
                vec![&b.a, &b.b]
            }
            Command::Complement(u) | Command::Convert(u) => vec![&u.input],
            Command::Info(s) | Command::Validate(s) => vec![&s.input],
            Command::Locate(l) => vec![&l.set],
            Command::Render(r) => r.inputs.iter().map(PathBuf::as_path).collect(),
            Command::Demo | Command::Axioms(_) => Vec::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn grammar_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn eps_must_be_positive_and_finite_or_auto() {
        assert_eq!(parse_eps("1e-9"), Ok(Eps::Value(1e-9)));
        assert_eq!(parse_eps("auto"), Ok(Eps::Auto));
        assert_eq!(Eps::Auto.tolerance(), Tolerance::default());
        assert_eq!(Eps::Value(0.5).tolerance().eps(), 0.5);
        for bad in ["0", "-1", "inf", "NaN", "x", "Auto", ""] {
            assert!(parse_eps(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn options_follow_their_subcommand() {
        let cli = Cli::try_parse_from([
            "yinset", "meet", "a.wkt", "-", "--eps", "0.5", "--to", "geojson",
        ])
        .unwrap();
        let Some(Command::Meet(b)) = cli.command else {
            panic!("not meet")
        };
        assert_eq!(
            (b.read.eps, b.write.to),
            (Some(Eps::Value(0.5)), Some(Format::Geojson))
        );
        assert!(Cli::try_parse_from(["yinset", "axioms", "5", "--eps", "1"]).is_err());
        assert!(Cli::try_parse_from(["yinset", "info", "a", "--to", "wkt"]).is_err());
        assert!(Cli::try_parse_from(["yinset"]).unwrap().command.is_none());
    }
}
